!> Euler-Bernoulli beam-column element of a planar frame (3 DOFs per node).
!>
!> Global axes: X horizontal (to the right), Z vertical (up); rotations counterclockwise
!> (from X towards Z). Global node DOFs, in this order: horizontal displacement u (m),
!> vertical displacement w (m), rotation theta (rad).
!>
!> Local axes of an element from node 1 (x1, z1) to node 2 (x2, z2): x along the chord,
!> c = (x2 - x1)/L, s = (z2 - z1)/L; y is x turned by +90 degrees. Local DOFs per node:
!> axial displacement, transverse displacement, rotation, d_local = T d_global with the
!> node block [c s 0; -s c 0; 0 0 1]. A column drawn upwards (node 1 below) has local x = +Z
!> and local y = -X.
!>
!> End forces (`beam_end_forces`) are the forces the nodes exert on the element, in local
!> axes: f = k_local d_local = [N1, V1, M1, N2, V2, M2] (kN, kN, kN m), moments
!> counterclockwise. Without member loads the axial force is N = f(4) = -f(1), tension
!> positive; the shear is V = f(2) = -f(5); f(3) and f(6) are the end moments acting on the
!> element.
!>
!> Geometric stiffness, with N the axial force (tension positive, so compression gives a
!> negative G), acts on the transverse DOFs only (no axial term):
!> 'chord': (N/L) [1 -1; -1 1] on (v1, v2), the P-Delta of the chord rotation;
!> 'consistent': N/(30 L) [36 3L -36 3L; 3L 4L^2 -3L -L^2; -36 -3L 36 -3L; 3L -L^2 -3L 4L^2]
!> on (v1, theta1, v2, theta2), from the cubic Hermite shape functions.
module pound_frame_element
   use pound_kinds, only: dp
   implicit none
   private

   public :: beam_local_stiffness, beam_local_geometric, beam_transformation
   public :: beam_global_stiffness, beam_global_geometric, beam_end_forces
   public :: geometric_chord, geometric_consistent

   !> Kind of geometric stiffness: chord rotation only (P-Delta).
   integer, parameter :: geometric_chord = 1
   !> Kind of geometric stiffness: consistent (Hermite shape functions, P-delta along the member).
   integer, parameter :: geometric_consistent = 2

contains

   !> Elastic stiffness in local axes (kN/m, kN, kN m).
   pure function beam_local_stiffness(e, a, i, l) result(k)
      !> Young's modulus (kPa = kN/m^2).
      real(dp), intent(in) :: e
      !> Cross-section area (m^2).
      real(dp), intent(in) :: a
      !> Second moment of area (m^4).
      real(dp), intent(in) :: i
      !> Length (m).
      real(dp), intent(in) :: l
      real(dp) :: k(6, 6)
      real(dp) :: ea, ei

      ea = e*a/l
      ei = e*i/l**3
      k = 0.0_dp
      k(1, 1) = ea
      k(1, 4) = -ea
      k(4, 1) = -ea
      k(4, 4) = ea
      k([2, 3, 5, 6], [2, 3, 5, 6]) = ei*reshape([12.0_dp, 6.0_dp*l, -12.0_dp, 6.0_dp*l, &
                                                  6.0_dp*l, 4.0_dp*l*l, -6.0_dp*l, 2.0_dp*l*l, &
                                                  -12.0_dp, -6.0_dp*l, 12.0_dp, -6.0_dp*l, &
                                                  6.0_dp*l, 2.0_dp*l*l, -6.0_dp*l, 4.0_dp*l*l], [4, 4])
   end function beam_local_stiffness

   !> Geometric stiffness in local axes for an axial force `n` (kN, tension positive).
   pure function beam_local_geometric(n, l, kind) result(g)
      !> Axial force (kN), tension positive.
      real(dp), intent(in) :: n
      !> Length (m).
      real(dp), intent(in) :: l
      !> `geometric_chord` or `geometric_consistent`.
      integer, intent(in) :: kind
      real(dp) :: g(6, 6)

      g = 0.0_dp
      if (kind == geometric_chord) then
         g([2, 5], [2, 5]) = n/l*reshape([1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp], [2, 2])
      else
         g([2, 3, 5, 6], [2, 3, 5, 6]) = n/(30.0_dp*l)*reshape([36.0_dp, 3.0_dp*l, -36.0_dp, 3.0_dp*l, &
                                                               3.0_dp*l, 4.0_dp*l*l, -3.0_dp*l, -l*l, &
                                                               -36.0_dp, -3.0_dp*l, 36.0_dp, -3.0_dp*l, &
                                                               3.0_dp*l, -l*l, -3.0_dp*l, 4.0_dp*l*l], [4, 4])
      end if
   end function beam_local_geometric

   !> Transformation d_local = T d_global of an element from (x1, z1) to (x2, z2) (m).
   pure function beam_transformation(x1, z1, x2, z2) result(t)
      !> Coordinates of node 1 (m).
      real(dp), intent(in) :: x1, z1
      !> Coordinates of node 2 (m).
      real(dp), intent(in) :: x2, z2
      real(dp) :: t(6, 6)
      real(dp) :: l, c, s

      l = hypot(x2 - x1, z2 - z1)
      c = (x2 - x1)/l
      s = (z2 - z1)/l
      t = 0.0_dp
      t(1, 1) = c
      t(1, 2) = s
      t(2, 1) = -s
      t(2, 2) = c
      t(3, 3) = 1.0_dp
      t(4:6, 4:6) = t(1:3, 1:3)
   end function beam_transformation

   !> A local element matrix in global axes, T^T m T.
   pure function to_global(m, x1, z1, x2, z2) result(g)
      real(dp), intent(in) :: m(6, 6), x1, z1, x2, z2
      real(dp) :: g(6, 6)
      real(dp) :: t(6, 6), mt(6, 6)

      t = beam_transformation(x1, z1, x2, z2)
      mt = matmul(m, t)
      g = matmul(transpose(t), mt)
   end function to_global

   !> Elastic stiffness in global axes, T^T k T.
   pure function beam_global_stiffness(e, a, i, x1, z1, x2, z2) result(k)
      !> Young's modulus (kPa).
      real(dp), intent(in) :: e
      !> Area (m^2).
      real(dp), intent(in) :: a
      !> Second moment of area (m^4).
      real(dp), intent(in) :: i
      !> Coordinates of node 1 (m).
      real(dp), intent(in) :: x1, z1
      !> Coordinates of node 2 (m).
      real(dp), intent(in) :: x2, z2
      real(dp) :: k(6, 6)

      k = to_global(beam_local_stiffness(e, a, i, hypot(x2 - x1, z2 - z1)), x1, z1, x2, z2)
   end function beam_global_stiffness

   !> Geometric stiffness in global axes, T^T g T, for an axial force `n` (kN, tension positive).
   pure function beam_global_geometric(n, x1, z1, x2, z2, kind) result(g)
      !> Axial force (kN), tension positive.
      real(dp), intent(in) :: n
      !> Coordinates of node 1 (m).
      real(dp), intent(in) :: x1, z1
      !> Coordinates of node 2 (m).
      real(dp), intent(in) :: x2, z2
      !> `geometric_chord` or `geometric_consistent`.
      integer, intent(in) :: kind
      real(dp) :: g(6, 6)

      g = to_global(beam_local_geometric(n, hypot(x2 - x1, z2 - z1), kind), x1, z1, x2, z2)
   end function beam_global_geometric

   !> End forces in local axes, [N1, V1, M1, N2, V2, M2] (kN, kN m), from the global end
   !> displacements `d` = [u1, w1, theta1, u2, w2, theta2] (m, rad). Axial force N = f(4).
   pure function beam_end_forces(e, a, i, x1, z1, x2, z2, d) result(f)
      !> Young's modulus (kPa).
      real(dp), intent(in) :: e
      !> Area (m^2).
      real(dp), intent(in) :: a
      !> Second moment of area (m^4).
      real(dp), intent(in) :: i
      !> Coordinates of node 1 (m).
      real(dp), intent(in) :: x1, z1
      !> Coordinates of node 2 (m).
      real(dp), intent(in) :: x2, z2
      !> Global end displacements (m, rad).
      real(dp), intent(in) :: d(6)
      real(dp) :: f(6)
      real(dp) :: t(6, 6), k(6, 6), dl(6)

      t = beam_transformation(x1, z1, x2, z2)
      k = beam_local_stiffness(e, a, i, hypot(x2 - x1, z2 - z1))
      dl = matmul(t, d)
      f = matmul(k, dl)
   end function beam_end_forces

end module pound_frame_element
