!> What `&contact` declares: the pairs of two buildings and their joint law's values as given.
!> Plain data that the deck fills (`pound_config` names the type too, as part of `deck_type`)
!> and the joint laws (`pound_law_*`, which read and check their own variables) and the pair
!> set-up (`pound_contact_pair`) read, so that no contact module depends on the deck's
!> configuration.
module pound_contact_settings
   use pound_kinds, only: dp
   implicit none
   private

   public :: contact_config, contact_variant

   !> `&contact`: unilateral constraints between facing floors of two buildings.
   !>
   !> Pair k joins floor `floor_left(k)` of building `left` with floor `floor_right(k)` of
   !> building `right`; a displacement of `left` towards `right` closes the gap. Pairs given
   !> by `elevations` join the two facing column lines at elevation `elevation(k)`: the floor
   !> there, or 0 for a point between floors (a column node of a frame).
   type :: contact_config
      !> Names of the building on the left and on the right.
      character(len=:), allocatable :: left, right
      !> Their indices in `deck%buildings`.
      integer :: left_index = 0, right_index = 0
      !> Facing floors, one entry per pair (0: a point between floors, see `elevation`).
      integer, allocatable :: floor_left(:), floor_right(:)
      !> Elevation of each pair above the common base (m) when the deck gives `elevations`;
      !> unallocated when the pairs are given by floor.
      real(dp), allocatable :: elevation(:)
      !> Initial gap of each pair (m).
      real(dp), allocatable :: gap(:)
      !> Constraint law: 'elastic', 'elastic_plastic', 'bilinear', 'piecewise' or 'parabola_cubic'.
      character(len=:), allocatable :: law
      !> Joint (initial) stiffness k0 (kN/m) and dashpot c (kN s/m).
      real(dp) :: stiffness = 0.0_dp, dashpot = 0.0_dp
      !> Coefficient of restitution the dashpot is calibrated to (0 < e < 1, elastic law
      !> only); 0: none, the dashpot is `dashpot`.
      real(dp) :: restitution = 0.0_dp
      !> Dashpot rate rule: 'backward_euler' or 'trapezoidal'.
      character(len=:), allocatable :: dashpot_rate
      !> Yield force (kN) and second slope (kN/m) of `elastic_plastic` and `bilinear`.
      real(dp) :: yield_force = 0.0_dp, second_slope = 0.0_dp
      !> Envelope points of `piecewise`: penetrations (m) and forces (kN).
      real(dp), allocatable :: envelope_d(:), envelope_r(:)
      !> `parabola_cubic`: peak force rB (kN), peak and fracture penetrations dB, dF (m),
      !> chords per curved branch.
      real(dp) :: peak_force = 0.0_dp, peak_penetration = 0.0_dp, fracture_penetration = 0.0_dp
      integer :: n_segments = 8
      !> Law-study variant the group belongs to (`&contact variant`); blank: the deck's own
      !> joints (the study's base).
      character(len=32) :: variant = ''
      !> How the stiffness was found when the deck gives none (the default's rule, for the
      !> listing); blank: given by the deck.
      character(len=:), allocatable :: stiffness_rule
      !> Coulomb friction coefficient mu between the facing facades (>= 0; 0: no friction) and
      !> the pair's tangential stiffness kt (kN/m; 0: not given, the default rule of the
      !> friction applies: `stiffness` for the linear laws). Buildings in plan only.
      real(dp) :: friction = 0.0_dp, shear_stiffness = 0.0_dp
   end type contact_config

   !> A law-study variant: the `&contact` groups of one `variant` name, the same pairs as the
   !> base with other laws (`pound_deck_study`).
   type :: contact_variant
      !> The variant's name as the deck gives it.
      character(len=32) :: name = ''
      !> Its groups, in deck order.
      type(contact_config), allocatable :: contacts(:)
   end type contact_variant

end module pound_contact_settings
