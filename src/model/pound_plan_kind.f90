!> The building in plan as a building kind (pound_plan_building): its outline, centre of mass,
!> rotational inertias and planes, described in the listing and written to /model/<b>/.
module pound_plan_kind
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str, counted, fixed_cell, plain_real
   use pound_model_sink, only: model_sink, text_lines
   use pound_structure, only: structure_model
   use pound_building_kind, only: building_kind
   use pound_plan_geometry, only: plane_x
   use pound_plan_building, only: plan_data
   implicit none
   private

   public :: plan_kind

   !> A building in plan's data for the writers.
   type, extends(building_kind) :: plan_kind
      !> Floor masses, rotational inertias, the planes' storey stiffnesses, P-Delta loads.
      type(plan_data) :: plan
   contains
      procedure :: describe => plan_describe
      procedure :: write_data => plan_write_data
   end type plan_kind

contains

   !> Outline, centre of mass, the floors (height, mass, rotational inertia, P-Delta loads)
   !> and the planes table.
   subroutine plan_describe(kind, m, lines)
      !> The building kind.
      class(plan_kind), intent(in) :: kind
      !> Its structural model.
      type(structure_model), intent(in) :: m
      !> The lines.
      type(text_lines), intent(inout) :: lines
      character(len=256) :: buf
      character(len=:), allocatable :: text
      integer :: j, p, np

      np = size(m%plan%plane_direction)
      call lines%add('')
      call lines%add('  Building '//m%name//' (plan): '//counted(kind%n_storeys, 'storey')//', '// &
                     counted(np, 'plane')//', '//str(m%n)//' DOFs (u_x, u_y, theta a floor), P-Delta '// &
                     trim(merge('on ', 'off', kind%p_delta)))
      call lines%add('  outline Lx x Ly = '//plain_real(m%plan%lx)//' x '//plain_real(m%plan%ly)// &
                     ' m, edge y = 0 at site y = '//plain_real(m%plan%y0)//' m, centre of mass (xm, ym) = ('// &
                     plain_real(m%plan%xm)//', '//plain_real(m%plan%ym)//') m')
      call lines%add('  storey    h [m]    mass [t]   I [t m2]      W [kN]     R [kN m2]')
      do j = 1, kind%n_storeys
         write (buf, '(2x,i6,a9,a12,es11.4,2es13.5)') j, fixed_cell(kind%height(j), 9, 3, .true.), &
            fixed_cell(kind%plan%floor_mass(j), 12, 4, .true.), kind%plan%rot_inertia(j), &
            kind%plan%storey_load(j), kind%plan%storey_load_rot(j)
         call lines%add(trim(buf))
      end do
      call lines%add('  plane  dir  position [m]  storey stiffness k [kN/m], storey 1 first')
      do p = 1, np
         write (buf, '(2x,i5,a5,a14)') p, trim(merge('x', 'y', m%plan%plane_direction(p) == plane_x)), &
            fixed_cell(m%plan%plane_position(p), 14, 3)
         text = trim(buf)//' '
         do j = 1, kind%n_storeys
            write (buf, '(es12.4)') kind%plan%plane_stiffness(j, p)
            text = text//trim(buf)
         end do
         call lines%add(text)
      end do
   end subroutine plan_describe

   !> plan_size, plan_origin_y, mass_centre, rot_inertia, plane_direction, plane_position,
   !> plane_stiffness (h5py (n_planes, n_storeys)), storey_load, storey_load_rot.
   subroutine plan_write_data(kind, m, sink, error)
      !> The building kind.
      class(plan_kind), intent(in) :: kind
      !> Its structural model.
      type(structure_model), intent(in) :: m
      !> Where to write.
      class(model_sink), intent(inout) :: sink
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: np

      np = size(m%plan%plane_direction)
      call sink%reals('plan_size', [m%plan%lx, m%plan%ly], 'm', error)
      if (allocated(error)) return
      call sink%reals('plan_origin_y', [m%plan%y0], 'm', error)
      if (allocated(error)) return
      call sink%reals('mass_centre', [m%plan%xm, m%plan%ym], 'm', error)
      if (allocated(error)) return
      call sink%reals('rot_inertia', kind%plan%rot_inertia, 't m^2', error)
      if (allocated(error)) return
      call sink%int_table('plane_direction', reshape(m%plan%plane_direction, [1, np]), '1', &
                          'direction of each plane in deck order (1: x, 2: y)', error)
      if (allocated(error)) return
      call sink%reals('plane_position', m%plan%plane_position, 'm', error)
      if (allocated(error)) return
      call sink%real_table('plane_stiffness', kind%plan%plane_stiffness, 'kN/m', &
                           'storey 1 .. n_storeys; one row per plane in deck order', error)
      if (allocated(error)) return
      call sink%reals('storey_load', kind%plan%storey_load, 'kN', error)
      if (allocated(error)) return
      call sink%reals('storey_load_rot', kind%plan%storey_load_rot, 'kN m^2', error)
   end subroutine plan_write_data

end module pound_plan_kind
