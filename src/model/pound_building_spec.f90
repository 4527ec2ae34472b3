!> What a building is made of, as the model builders take it (`building_spec`): the storey
!> table or the frame's lines and sections, masses or load coefficients, damping, P-Delta,
!> the storey and hinge laws, the design-code factors. The values are as given; engineering
!> derivations (masses from load coefficients, storey stiffnesses from columns) are the
!> builders' (pound_storey_properties). The deck layer fills it (`pound_config` names it
!> `building_config`); the model layer uses no deck module.
!> Units: kN, m, s, t (tonne).
module pound_building_spec
   use pound_kinds, only: dp
   use pound_code_factors, only: code_factors
   implicit none
   private

   public :: building_spec, plane_spec, is_frame, is_plan

   !> `&plane`: one lateral load-resisting plane (a frame or wall line) of a building in plan.
   type :: plane_spec
      !> The direction the plane resists: 'x' or 'y'.
      character(len=1) :: direction = 'x'
      !> Position (m, outline coordinates): y of an 'x' plane, x of a 'y' plane.
      real(dp) :: position = 0.0_dp
      !> The plane's storey stiffness (kN/m), n_storeys values.
      real(dp), allocatable :: stiffness(:)
      !> Storey law: 'elastic' (default) or 'bilinear'; for 'bilinear' the yield shear (kN) and
      !> hardening ratio of each storey (unallocated for elastic planes).
      character(len=8) :: storey_law = 'elastic'
      real(dp), allocatable :: yield_shear(:), hardening_ratio(:)
      !> Line of the `&plane` group in the deck (0: not known), for messages.
      integer :: line = 0
   end type plane_spec

   !> `&building`: one building (a shear building, or a planar frame with `model = 'frame'`).
   type :: building_spec
      !> Name used in messages, listing and HDF5 groups.
      character(len=:), allocatable :: name
      !> Number of storeys (= floors).
      integer :: n_storeys = 0
      !> Storey heights (m), storey 1 at the bottom.
      real(dp), allocatable :: height(:)
      !> Floor masses (t), when given as `mass` (unallocated when the deck gives `load_coeff`;
      !> pound_storey_properties derives them then).
      real(dp), allocatable :: mass(:)
      !> Floor load coefficients a_i of `load_coeff` (unallocated when `mass` is given).
      real(dp), allocatable :: load_coeff(:)
      !> Reference floor load m0 g (kN) that `load_coeff` multiplies.
      real(dp) :: ref_floor_load = 0.0_dp
      !> Storey lateral stiffness (kN/m), when given as `stiffness` (unallocated when the deck
      !> describes the columns; pound_storey_properties derives it then).
      real(dp), allocatable :: stiffness(:)
      !> Columns per storey, their Young's modulus (kN/m^2) and moment of inertia (m^4), when
      !> the storey stiffness is given by the columns (rigid beams).
      integer, allocatable :: n_columns(:)
      real(dp), allocatable :: e_modulus(:), inertia(:)
      !> End conditions of the columns: 'fixed-fixed' (12 E I / h^3) or 'fixed-pinned' (3 E I / h^3).
      character(len=:), allocatable :: column_ends
      !> Gravity load applied at each floor (kN), used for P-Delta, when given as
      !> `gravity_load` (unallocated otherwise: the default, the floor's weight, is derived).
      real(dp), allocatable :: gravity_load(:)
      !> Damping ratio for Rayleigh damping.
      real(dp) :: damping_ratio = 0.05_dp
      !> The two modes at which Rayleigh damping is fitted.
      integer :: damping_modes(2) = [1, 2]
      !> Second-order (P-Delta) geometric stiffness on/off.
      logical :: p_delta = .false.
      !> How masses were given: 'mass' or 'load_coeff' (for the echo).
      character(len=:), allocatable :: mass_source
      !> How stiffness was given: 'stiffness' or 'columns' (for the echo).
      character(len=:), allocatable :: stiffness_source
      !> Model: 'shear' (the default: the storey table above), 'frame' (a planar frame of
      !> column lines and floors, pound_frame_building; the variables below) or 'plan' (rigid
      !> floor diaphragms with three DOFs a floor and planes placed in plan; the plan variables
      !> at the end).
      character(len=:), allocatable :: model
      !> Frame: bay widths (m), n_bays values.
      real(dp), allocatable :: bay_width(:)
      !> Frame columns: E (kN/m^2), A (m^2), I (m^4), one value for all storeys or one per storey.
      real(dp), allocatable :: column_e(:), column_area(:), column_inertia(:)
      !> Frame beams: E (kN/m^2), A (m^2), I (m^4), one value for all floors or one per floor.
      real(dp), allocatable :: beam_e(:), beam_area(:), beam_inertia(:)
      !> Frame base of every column line: 'fixed' or 'pinned'.
      character(len=:), allocatable :: base
      !> Frame: elements per storey column (>= 1).
      integer :: column_elements = 1
      !> Frame constraints (exact, eliminated DOFs): flexurally rigid beams, rigid floor
      !> diaphragms, axially rigid columns.
      logical :: rigid_beams = .false., rigid_diaphragm = .false., rigid_columns = .false.
      !> Frame geometric stiffness of the gravity axial forces (with p_delta): 'chord' or 'consistent'.
      character(len=:), allocatable :: geometric
      !> Frame: elevations (m) of contact points between floors on the leftmost and on the
      !> rightmost column line (from the `&contact elevations` that face no floor of this
      !> building; the builder adds a column node at each); unallocated: none.
      real(dp), allocatable :: contact_z_left(:), contact_z_right(:)
      !> Design-code factors for the separation rules (`cd`, `importance`, `behaviour_factor`,
      !> `response_reduction`).
      type(code_factors) :: factors
      !> Storey law of a shear building: 'elastic' (default) or 'bilinear' (issue 25: Steel01-like
      !> kinematic hardening, pound_storey_yield).
      character(len=8) :: storey_law = 'elastic'
      !> 'bilinear': yield shear of each storey (kN) and hardening ratio r of each storey
      !> (post-yield stiffness r k); unallocated for elastic storeys.
      real(dp), allocatable :: yield_shear(:), hardening_ratio(:)
      !> Plastic hinges of a frame (issue 25, `hinge_law`): 'none' (default) or
      !> 'elastic_plastic' (rigid-plastic hinges at both ends of every element, pound_storey_yield).
      character(len=16) :: hinge_law = 'none'
      !> 'elastic_plastic': yield moment (kN m) of the columns of each storey and of the beams of
      !> each floor (n_storeys each); unallocated without hinges.
      real(dp), allocatable :: column_yield_moment(:), beam_yield_moment(:)
      !> 'elastic_plastic': kinematic hardening ratio r of the hinges of each storey's columns and
      !> floor's beams (n_storeys; 0: elastic-perfectly plastic), pound_frame_hinges.
      real(dp), allocatable :: hinge_hardening_ratio(:)
      !> Building in plan (`model = 'plan'`, pound_plan_building): outline Lx, Ly (m), site y
      !> of the outline's edge y = 0 (m), centre of mass (m, outline coordinates; default the
      !> outline's centre: `mass_centre_given` false), rotational inertia of each floor about
      !> its centre of mass (t m^2; unallocated: mass (Lx^2 + Ly^2)/12) and the planes in
      !> deck order (the `&plane` groups naming this building).
      real(dp) :: plan_size(2) = 0.0_dp, plan_origin_y = 0.0_dp, mass_centre(2) = 0.0_dp
      logical :: mass_centre_given = .false.
      real(dp), allocatable :: rot_inertia(:)
      type(plane_spec), allocatable :: planes(:)
   end type building_spec

contains

   !> Whether the building entry is a frame model (`model = 'frame'`; unset: a shear building).
   pure logical function is_frame(cfg)
      !> A building entry.
      type(building_spec), intent(in) :: cfg

      is_frame = .false.
      if (allocated(cfg%model)) is_frame = cfg%model == 'frame'
   end function is_frame

   !> Whether the building entry is a building in plan (`model = 'plan'`).
   pure logical function is_plan(cfg)
      !> A building entry.
      type(building_spec), intent(in) :: cfg

      is_plan = .false.
      if (allocated(cfg%model)) is_plan = cfg%model == 'plan'
   end function is_plan

end module pound_building_spec
