!> The shear building as a building kind: its storey table (first-order and geometric storey
!> stiffness, storey axial load), described in the listing and written to /model/<b>/.
module pound_shear_kind
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: counted, fixed_cell
   use pound_model_sink, only: model_sink, text_lines
   use pound_structure, only: structure_model
   use pound_building_kind, only: building_kind
   implicit none
   private

   public :: shear_kind

   !> A shear building's storey table.
   type, extends(building_kind) :: shear_kind
      !> First-order storey stiffness k_j, geometric storey stiffness P_j/h_j (kN/m) and
      !> storey axial load P_j (kN).
      real(dp), allocatable :: storey_stiffness(:), geometric_stiffness(:), axial_load(:)
   contains
      procedure :: describe => shear_describe
      procedure :: write_data => shear_write_data
   end type shear_kind

contains

   !> Name, storeys, P-Delta and the storey table.
   subroutine shear_describe(kind, m, lines)
      !> The building kind.
      class(shear_kind), intent(in) :: kind
      !> Its structural model.
      type(structure_model), intent(in) :: m
      !> The lines.
      type(text_lines), intent(inout) :: lines
      character(len=256) :: buf
      integer :: j

      call lines%add('')
      call lines%add('  Building '//m%name//': '//counted(m%n, 'storey')//', P-Delta '// &
                     trim(merge('on ', 'off', kind%p_delta)))
      call lines%add('  storey    h [m]    mass [t]     k [kN/m]      P [kN]   P/h [kN/m]  theta=P/(hk)')
      do j = 1, m%n
         write (buf, '(2x,i6,a9,a12,es13.5,es12.4,es13.5,a14)') &
            j, fixed_cell(kind%height(j), 9, 3, .true.), fixed_cell(kind%floor_mass(j), 12, 4, .true.), &
            kind%storey_stiffness(j), kind%axial_load(j), kind%geometric_stiffness(j), &
            fixed_cell(kind%geometric_stiffness(j)/kind%storey_stiffness(j), 14, 5)
         call lines%add(trim(buf))
      end do
   end subroutine shear_describe

   !> storey_stiffness, geometric_stiffness, axial_load.
   subroutine shear_write_data(kind, m, sink, error)
      !> The building kind.
      class(shear_kind), intent(in) :: kind
      !> Its structural model.
      type(structure_model), intent(in) :: m
      !> Where to write.
      class(model_sink), intent(inout) :: sink
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call sink%reals('storey_stiffness', kind%storey_stiffness(:m%n), 'kN/m', error)
      if (allocated(error)) return
      call sink%reals('geometric_stiffness', kind%geometric_stiffness(:m%n), 'kN/m', error)
      if (allocated(error)) return
      call sink%reals('axial_load', kind%axial_load(:m%n), 'kN', error)
   end subroutine shear_write_data

end module pound_shear_kind
