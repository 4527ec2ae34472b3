!> Physical constants of pound, each defined once.
!>
!> Units throughout: kN, m, s, t (tonne); accelerations m/s^2.
module pound_constants
   use pound_kinds, only: dp
   implicit none
   private

   public :: g_accel

   !> Acceleration of gravity (m/s^2): turns floor loads into masses (and masses into default
   !> gravity loads of shear buildings and frames), and record values in g into m/s^2, so a
   !> record of 1 g loads a floor with its own weight. Written to every results file as the
   !> root attribute `g`, which the plot scripts read.
   real(dp), parameter :: g_accel = 9.81_dp

end module pound_constants
