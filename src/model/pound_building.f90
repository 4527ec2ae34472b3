!> One building of a deck, whatever its model: `build_building` makes the `structure_model`
!> the analyses read and, beside it, the per-kind data the writers need (`building_model`: the
!> shear building's storey table, the frame's nodes, elements and gravity analysis). The two
!> are kept in separate arrays by the run driver, so that the analyses get a contiguous
!> array of structural models (no copy).
module pound_building
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_config, only: building_config, is_frame
   use pound_structure, only: structure_model
   use pound_shear_building, only: shear_building, build_shear_building
   use pound_frame_building, only: frame_data, build_frame_building
   implicit none
   private

   public :: building_model, build_building

   !> What the writers need of a building besides its structural model (a plain data type,
   !> written once by `build_building`).
   type :: building_model
      !> Number of storeys (= floors, = response points).
      integer :: n_storeys = 0
      !> Storey heights (m) and floor masses (t).
      real(dp), allocatable :: height(:), floor_mass(:)
      !> Whether P-Delta is modelled.
      logical :: p_delta = .false.
      !> Shear building: first-order storey stiffness k_j, geometric storey stiffness P_j/h_j
      !> (kN/m) and storey axial load P_j (kN); unallocated for a frame.
      real(dp), allocatable :: storey_stiffness(:), geometric_stiffness(:), axial_load(:)
      !> Frame: nodes, elements, gravity analysis; unallocated for a shear building.
      type(frame_data), allocatable :: frame
   end type building_model

contains

   !> Build the model of a deck entry: a shear building or a frame (`model`).
   subroutine build_building(deck_entry, m, b, error, number)
      !> Validated deck entry.
      type(building_config), intent(in) :: deck_entry
      !> The structural model.
      type(structure_model), intent(out) :: m
      !> The per-kind data.
      type(building_model), intent(out) :: b
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Occurrence of the `&building` group in the deck, for messages.
      integer, intent(in), optional :: number
      type(shear_building) :: sb
      integer :: j

      b%n_storeys = deck_entry%n_storeys
      b%height = deck_entry%height
      b%p_delta = deck_entry%p_delta
      if (is_frame(deck_entry)) then
         allocate (b%frame)
         call build_frame_building(deck_entry, m, b%frame, error, number)
         if (allocated(error)) return
         allocate (b%floor_mass(b%n_storeys))
         do j = 1, b%n_storeys
            b%floor_mass(j) = sum(b%frame%frame%node_mass(b%frame%frame%floor_node(:, j)))
         end do
      else
         call build_shear_building(deck_entry, sb, error, number)
         if (allocated(error)) return
         m = sb%structure_model
         b%floor_mass = sb%mass
         call move_alloc(sb%storey_stiffness, b%storey_stiffness)
         call move_alloc(sb%geometric_stiffness, b%geometric_stiffness)
         call move_alloc(sb%axial_load, b%axial_load)
         if (allocated(deck_entry%yield_shear)) then
            m%yield_shear = deck_entry%yield_shear
            m%hardening = deck_entry%hardening_ratio
            m%yield_height = deck_entry%height
         end if
      end if
   end subroutine build_building

end module pound_building
