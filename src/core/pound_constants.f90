!> Physical constants of pound, each defined once.
!>
!> Units throughout: kN, m, s, t (tonne); accelerations m/s^2.
module pound_constants
   use pound_kinds, only: dp
   implicit none
   private

   public :: g_accel, pi, two_pi

   !> Acceleration of gravity (m/s^2): turns floor loads into masses (and masses into default
   !> gravity loads of shear buildings and frames), and record values in g into m/s^2, so a
   !> record of 1 g loads a floor with its own weight. Written to every results file as the
   !> root attribute `g`, which the plot scripts read.
   real(dp), parameter :: g_accel = 9.81_dp

   !> pi, to the last bit of a double (acos(-1), folded by the compiler).
   real(dp), parameter :: pi = acos(-1.0_dp)
   !> 2 pi (the double nearest; doubling is exact).
   real(dp), parameter :: two_pi = 2.0_dp*pi

end module pound_constants
