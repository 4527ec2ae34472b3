!> Influence coefficients of pounding on the response (eq. 7 of the seed paper).
!>
!> For a response quantity Q with absolute maxima Qc (coupled) and Qu (uncoupled):
!> lambda = (Qc - Qu) / Qu * 100 (%). Positive: pounding raises the response.
module pound_influence
   use pound_kinds, only: dp
   implicit none
   private

   public :: influence_coefficient

contains

   !> lambda = (Qc - Qu)/Qu * 100; 0 where both maxima are zero (nothing to compare) and
   !> +huge where only the uncoupled one is (pounding creates a response from nothing).
   elemental function influence_coefficient(qc, qu) result(lambda)
      !> Absolute maximum, coupled.
      real(dp), intent(in) :: qc
      !> Absolute maximum, uncoupled.
      real(dp), intent(in) :: qu
      real(dp) :: lambda

      if (qu > 0.0_dp) then
         lambda = (qc - qu)/qu*100.0_dp
      else if (qc > 0.0_dp) then
         lambda = huge(1.0_dp)
      else
         lambda = 0.0_dp
      end if
   end function influence_coefficient

end module pound_influence
