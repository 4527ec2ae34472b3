!> One building of a deck, whatever its model: `build_building` makes the `structure_model`
!> the analyses read and, beside it, its building kind (`building_model%kind`, a
!> `building_kind`: `shear_kind` with the storey table, `frame_kind` with the nodes, elements
!> and gravity analysis), which answers the writers. The two are kept in separate arrays by
!> the run driver, so that the analyses get a contiguous array of structural models (no copy).
module pound_building
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, status_input
   use pound_building_spec, only: building_spec, is_frame, is_plan
   use pound_structure, only: structure_model, structure_check
   use pound_shear_building, only: shear_building, build_shear_building
   use pound_frame_building, only: build_frame_building
   use pound_frame, only: frame_model
   use pound_building_kind, only: building_kind
   use pound_shear_kind, only: shear_kind
   use pound_frame_kind, only: frame_kind
   implicit none
   private

   public :: building_model, build_building, frame_of

   !> What the writers need of a building besides its structural model: its kind.
   type :: building_model
      !> The building kind (shear building, frame).
      class(building_kind), allocatable :: kind
   end type building_model

contains

   !> Build the model of a deck entry: a shear building or a frame (`model`).
   subroutine build_building(deck_entry, m, b, error, number)
      !> Validated deck entry.
      type(building_spec), intent(in) :: deck_entry
      !> The structural model.
      type(structure_model), intent(out) :: m
      !> The per-kind data.
      type(building_model), intent(out) :: b
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Occurrence of the `&building` group in the deck, for messages.
      integer, intent(in), optional :: number
      type(shear_building) :: sb
      type(shear_kind), allocatable :: shear
      type(frame_kind), allocatable :: frame
      integer :: j

      if (is_plan(deck_entry)) then
         ! The deck reads buildings in plan (pound_deck_plane); their builder is not part of this
         ! version: refused, not built as something else.
         call fatal_error(error, 'building '//deck_entry%name//": model = 'plan' (a building in plan) "// &
                          'is read from the deck but this version of pound does not build it', status_input)
         return
      end if
      if (is_frame(deck_entry)) then
         allocate (frame)
         call set_common(frame)
         call build_frame_building(deck_entry, m, frame%frame, error, number)
         if (allocated(error)) return
         allocate (frame%floor_mass(frame%n_storeys))
         associate (f => frame%frame%frame, ce => frame%frame%column_element)
            do j = 1, frame%n_storeys
               frame%floor_mass(j) = sum(f%node_mass(f%floor_node(:, j)))
            end do
            frame%participation = frame%frame%participation
            frame%effective_mass = frame%frame%effective_mass
            frame%segment_storey = f%element_group(ce)
            frame%segment_line = f%node_line(f%element_nodes(1, ce))
            frame%segment_z = reshape([(f%node_z(f%element_nodes(:, ce(j))), j=1, size(ce))], [2, size(ce)])
         end associate
         call move_alloc(frame, b%kind)
      else
         call build_shear_building(deck_entry, sb, error, number)
         if (allocated(error)) return
         allocate (shear)
         call set_common(shear)
         m = sb%structure_model
         shear%floor_mass = sb%mass
         call move_alloc(sb%storey_stiffness, shear%storey_stiffness)
         call move_alloc(sb%geometric_stiffness, shear%geometric_stiffness)
         call move_alloc(sb%axial_load, shear%axial_load)
         if (allocated(deck_entry%yield_shear)) then
            m%yield_shear = deck_entry%yield_shear
            m%hardening = deck_entry%hardening_ratio
            m%yield_height = deck_entry%height
         end if
         call move_alloc(shear, b%kind)
      end if
      ! The builders' invariants (sizes, index ranges, ground components), once per building.
      call structure_check(m, error)

   contains

      !> What every kind takes from the deck entry.
      subroutine set_common(kind)
         class(building_kind), intent(inout) :: kind

         kind%n_storeys = deck_entry%n_storeys
         kind%height = deck_entry%height
         kind%p_delta = deck_entry%p_delta
      end subroutine set_common

   end subroutine build_building

   !> The frame model (nodes, elements, DOF map) of a frame building, for checks that look
   !> inside the frame (a copy; empty for another kind).
   function frame_of(b) result(f)
      !> The building.
      type(building_model), intent(in) :: b
      type(frame_model) :: f

      select type (k => b%kind)
      type is (frame_kind)
         f = k%frame%frame
      end select
   end function frame_of

end module pound_building
