!> A building kind: what a building is besides its `structure_model` (the shear building's
!> storey table, the frame's nodes and elements). The kind answers for itself what the writers
!> need: its description for the listing (`describe`), its data for the results file
!> (`write_data`, through a `model_sink`), and as plain data its modal participation and its
!> column segments where it has them, so no writer branches on the kind. Extensions:
!> `shear_kind` (pound_shear_kind) and `frame_kind` (pound_frame_kind).
module pound_building_kind
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_model_sink, only: model_sink, text_lines
   use pound_structure, only: structure_model
   implicit none
   private

   public :: building_kind

   !> The data every kind has, and the questions every kind answers.
   type, abstract :: building_kind
      !> Number of storeys (= floors, = response points).
      integer :: n_storeys = 0
      !> Storey heights (m) and floor masses (t).
      real(dp), allocatable :: height(:), floor_mass(:)
      !> Whether P-Delta is modelled.
      logical :: p_delta = .false.
      !> Per computed mode, where the kind computes them: participation factor Gamma_n and
      !> effective mass fraction (unallocated: the mode table shows periods only).
      real(dp), allocatable :: participation(:), effective_mass(:)
      !> Column segments with member results (the rows of `structure_model%member_names`
      !> come in groups per segment), where the kind has them: storey and column line of
      !> each segment, and the heights of its ends (2, segments) (m).
      integer, allocatable :: segment_storey(:), segment_line(:)
      real(dp), allocatable :: segment_z(:, :)
   contains
      !> The listing's description of the building (storey table, geometry), before its modes.
      procedure(kind_describe), deferred :: describe
      !> The kind's own datasets in /model/<b>/ (after height and mass).
      procedure(kind_write_data), deferred :: write_data
      !> Number of column segments (0: none).
      procedure, non_overridable :: n_segments => kind_n_segments
   end type building_kind

   abstract interface
      !> Append the description's lines to `lines`.
      subroutine kind_describe(kind, m, lines)
         import :: building_kind, structure_model, text_lines
         !> The building kind.
         class(building_kind), intent(in) :: kind
         !> Its structural model.
         type(structure_model), intent(in) :: m
         !> The lines.
         type(text_lines), intent(inout) :: lines
      end subroutine kind_describe

      !> Write the kind's datasets.
      subroutine kind_write_data(kind, m, sink, error)
         import :: building_kind, structure_model, model_sink, error_type
         !> The building kind.
         class(building_kind), intent(in) :: kind
         !> Its structural model.
         type(structure_model), intent(in) :: m
         !> Where to write.
         class(model_sink), intent(inout) :: sink
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine kind_write_data
   end interface

contains

   !> Number of column segments (0: none).
   pure integer function kind_n_segments(kind) result(n)
      !> The building kind.
      class(building_kind), intent(in) :: kind

      n = 0
      if (allocated(kind%segment_storey)) n = size(kind%segment_storey)
   end function kind_n_segments

end module pound_building_kind
