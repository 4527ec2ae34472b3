!> What a deck declares, after validation: the values as given (engineering derivations such
!> as masses from load coefficients or storey stiffnesses from columns are the model's, see
!> pound_storey_properties).
!>
!> The deck reader (`pound_deck`) fills these types; the driver reads them. A `&building` is
!> the model layer's own spec type (`building_config` = `building_spec`, pound_building_spec),
!> so the builders use no deck module.
!> Units throughout: kN, m, s, t (tonne).
module pound_config
   use pound_kinds, only: dp
   use pound_quantities, only: n_history_quantities, history_names, n_target_quantities, target_names, &
                               q_column_shear, q_column_moment, q_ductility
   use pound_sweep_settings, only: sweep_config
   use pound_code_factors, only: code_factors
   use pound_building_spec, only: building_config => building_spec, is_frame
   use pound_contact_settings, only: contact_config, contact_variant
   use pound_risk_settings, only: risk_config
   implicit none
   private

   public :: analysis_config, ground_config, building_config, code_factors, contact_config, sweep_config, deck_type, &
             contact_variant, risk_config
   public :: is_frame, deck_warning_len
   ! The quantities (pound_quantities), named here too for the deck's readers.
   public :: n_history_quantities, history_names, n_target_quantities, target_names, q_column_shear, q_column_moment
   public :: q_ductility

   !> Characters kept of a deck warning (`deck_type%warnings`).
   integer, parameter :: deck_warning_len = 1024

   !> `&analysis`: title, time stepping and history output.
   type :: analysis_config
      !> Title shown in the listing, the HDF5 file and plots.
      character(len=:), allocatable :: title
      !> Time step (s).
      real(dp) :: dt = 0.0_dp
      !> End of the analysis (s): the deck's `t_end` plus `t_free`.
      real(dp) :: t_end = 0.0_dp
      !> Free vibration appended after the motion (s; the deck's `t_free`, default 0): the ground
      !> is at rest after t_end - t_free (the deck's `t_end`), and the analysis runs on to `t_end`.
      real(dp) :: t_free = 0.0_dp
      !> History output every `output_every` steps.
      integer :: output_every = 1
      !> Which history quantities are stored (same order as `history_names`).
      logical :: store(n_history_quantities) = .true.
      !> Time stepping of the coupled analysis: 'uniform' (every step dt) or 'impact' (a step in
      !> which a joint is closed or predicted to close is taken as `impact_substeps` substeps).
      character(len=8) :: stepping = 'uniform'
      !> Substeps per impact step (stepping = 'impact'); 0: chosen from the joints' contact
      !> half-periods.
      integer :: impact_substeps = 0
      !> Steps in which no joint acts (every step of the uncoupled analysis): 'newmark' (average
      !> acceleration, as every other step) or 'exact' (the exact step of the linear structure
      !> under the ground acceleration linear between its samples, mode by mode).
      character(len=8) :: free_steps = 'newmark'
      !> Where the deck sets `free_steps` ('deck.nml:4: &analysis: '; the group's start when it
      !> does not), for a refusal made once the models are built.
      character(len=:), allocatable :: free_steps_site
      !> Collapse of a building with bilinear storeys: a storey drift / height beyond this (issue 25).
      real(dp) :: collapse_drift = 0.10_dp
      !> Histories in the HDF5 file in compressed (deflate) chunks.
      logical :: compress = .false.
      !> Every DOF's displacement history of each frame building (`u_nodes` in the HDF5 file,
      !> the DOF layout in `/model/<b>/dofs`); default off.
      logical :: node_histories = .false.
      !> LCP method of the coupled steps: 'auto' (the active-set method for steps whose acting
      !> joints are all elastic, Lemke otherwise and when it fails) or 'lemke' (every step).
      character(len=8) :: lcp_solver = 'auto'
      !> Time integrator: 'newmark' (average acceleration) or 'hht' (HHT-alpha).
      character(len=8) :: integrator = 'newmark'
      !> HHT-alpha's alpha, in [-1/3, 0] (integrator = 'hht').
      real(dp) :: hht_alpha = -0.05_dp
   end type analysis_config

   !> `&ground`: one ground motion (a deck with several `&ground` groups is a suite).
   type :: ground_config
      !> Name of the motion ('ground' when the deck has one `&ground` without a name).
      character(len=:), allocatable :: name
      !> 'pulse', 'record' or 'synthetic' ('record_set' only inside the deck reader).
      character(len=:), allocatable :: kind
      !> Pulse amplitude x0 (m), decay a (1/s), circular frequency b (rad/s).
      real(dp) :: x0 = 0.0_dp, a = 0.0_dp, b = 0.0_dp
      !> Record file (resolved relative to the deck's directory).
      character(len=:), allocatable :: file
      !> `kind = 'record_set'` (before the deck reader turns it into one 'record' per file):
      !> its folder (resolved relative to the deck's directory) and shell-style pattern.
      character(len=:), allocatable :: folder, pattern
      !> Record format: 'auto', 'at2' or 'columns'.
      character(len=:), allocatable :: format
      !> Scale factor applied to the record or the synthetic motion (record values are in g).
      real(dp) :: scale = 1.0_dp
      !> Scaling of the suite: '' (the factor `scale`), 'pga' or 'sa' (to `target`).
      character(len=:), allocatable :: scale_to
      !> Target of `scale_to` (m/s^2): the PGA, or the 5 %-damped Sa at `period`.
      real(dp) :: target = 0.0_dp
      !> Period (s) of `scale_to = 'sa'`; 0: the fundamental period of the most flexible building.
      real(dp) :: period = 0.0_dp
      !> Synthetic: filter ('kanai_tajimi' or 'clough_penzien') and envelope ('jennings' or
      !> 'saragoni_hart'), see pound_synthetic_motion.
      character(len=:), allocatable :: filter, envelope
      !> Synthetic: ground filter frequency (rad/s) and damping, high-pass frequency (rad/s)
      !> and damping (Clough-Penzien).
      real(dp) :: ground_frequency = 15.0_dp, ground_damping = 0.6_dp
      real(dp) :: filter_frequency = 1.5_dp, filter_damping = 0.6_dp
      !> Synthetic: Jennings rise time t1 (s), end of plateau t2 (s), decay rate c (1/s).
      real(dp) :: rise_time = 2.0_dp, plateau_end = 10.0_dp, decay_rate = 0.3_dp
      !> Synthetic: Saragoni-Hart time of the peak (fraction of the duration) and end level.
      real(dp) :: peak_fraction = 0.2_dp, end_level = 0.05_dp
      !> Synthetic: duration (s), target PGA of the generator (m/s^2), seed.
      real(dp) :: duration = 20.0_dp, pga = 0.0_dp
      integer :: seed = 1
      !> Suite: write this motion's histories under /suite/<name>/ of the HDF5 file.
      logical :: histories = .false.
      !> Direction of the motion (degrees from +x toward +y): component 1 acts along `angle`,
      !> the second component (`file_2`) along `angle` + 90 degrees.
      real(dp) :: angle = 0.0_dp
      !> `kind = 'record'`: the second horizontal component's record file (resolved relative
      !> to the deck's directory; unallocated: none) and its scale factor (`scale_2_given`
      !> false: `scale`).
      character(len=:), allocatable :: file_2
      real(dp) :: scale_2 = 1.0_dp
      logical :: scale_2_given = .false.
   end type ground_config

   !> A whole, validated deck.
   type :: deck_type
      !> Path of the deck file as given.
      character(len=:), allocatable :: path
      !> Full text of the deck (echoed in the listing and stored in HDF5).
      character(len=:), allocatable :: text
      !> `&analysis`.
      type(analysis_config) :: analysis
      !> `&ground` (the first one when the deck has several).
      type(ground_config) :: ground
      !> Every `&ground`, in deck order: the suite (size 1 for a deck with one `&ground`).
      type(ground_config), allocatable :: motions(:)
      !> `&building` occurrences, in deck order (left to right).
      type(building_config), allocatable :: buildings(:)
      !> `&contact` occurrences (size 0 when the deck declares none).
      type(contact_config), allocatable :: contacts(:)
      !> Law-study variants (`&contact variant = 'name'`; size 0: no law study). `contacts`
      !> holds the groups without a variant, the study's base.
      type(contact_variant), allocatable :: variants(:)
      !> `&sweep` (inactive when the deck has none).
      type(sweep_config) :: sweep
      !> `&stripes` and `&hazard`: the multiple-stripe analysis and the risk-targeted joint
      !> (inactive when the deck has neither; pound_stripes).
      type(risk_config) :: risk
      !> Plausibility warnings of the deck's values (one line each, 'deck.nml:12: &group: ...',
      !> trailing blanks not part of them; unallocated: none): suspicious, not refused. (Fixed
      !> length: gfortran's intrinsic assignment of the deck mishandles deferred-length arrays.)
      character(len=deck_warning_len), allocatable :: warnings(:)
   end type deck_type

end module pound_config
