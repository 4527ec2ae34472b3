!> Buildings in plan (`&building model = 'plan'`): the outline, the centre of mass, the
!> lateral load-resisting planes and the DOF layout of a rigid-diaphragm building, and the
!> rows of a point's displacement that contact, planes and outputs read
!> (`plan_point_row` of pound_structure, which holds the geometry as `structure_model%plan`).
!>
!> **DOF layout.** Floor j (1 = lowest) has three DOFs at its centre of mass C = (xm, ym):
!> u_x = DOF 3j-2, u_y = DOF 3j-1 and theta = DOF 3j (about z, counter-clockwise positive;
!> `plan_dof`). **Kinematics** (small rotations): a point P = (px, py) of floor j moves by
!> u_x(P) = u_x - theta (py - ym) and u_y(P) = u_y + theta (px - xm) (`plan_point_row`, pound_structure).
!> Coordinates are the outline's (0 <= px <= lx, 0 <= py <= ly); the outline's edge y = 0
!> stands at site y = y0.
module pound_plan_geometry
   use pound_kinds, only: dp
   implicit none
   private

   public :: plan_geometry, plan_dof, plane_x, plane_y
   public :: plan_ux, plan_uy, plan_theta

   !> Components of a floor's DOFs (`plan_dof`).
   integer, parameter :: plan_ux = 1, plan_uy = 2, plan_theta = 3

   !> Directions a plane resists (`plan_geometry%plane_direction`).
   integer, parameter :: plane_x = 1, plane_y = 2

   !> A building in plan: its outline, centre of mass and planes (all floors alike).
   type :: plan_geometry
      !> Outline (m): lx along site x, ly along site y.
      real(dp) :: lx = 0.0_dp, ly = 0.0_dp
      !> Site y of the outline's edge y = 0 (m).
      real(dp) :: y0 = 0.0_dp
      !> Centre of mass in outline coordinates (m).
      real(dp) :: xm = 0.0_dp, ym = 0.0_dp
      !> The planes in deck order: the direction each resists (`plane_x`, `plane_y`) and its
      !> position (m, outline coordinates: y of an x plane, x of a y plane).
      integer, allocatable :: plane_direction(:)
      real(dp), allocatable :: plane_position(:)
   end type plan_geometry

contains

   !> The DOF of component `c` (`plan_ux`, `plan_uy`, `plan_theta`) of floor j (1-based).
   pure elemental integer function plan_dof(j, c) result(dof)
      !> Floor (1 = lowest).
      integer, intent(in) :: j
      !> Component.
      integer, intent(in) :: c

      dof = 3*(j - 1) + c
   end function plan_dof
end module pound_plan_geometry
