!> The exponential of a small dense matrix, for the exact steps of linear oscillators
!> (`pound_sdof`: the spectra; `pound_modal_step`: exact free steps): scaling so that the
!> 1-norm is at most 1/2, the Taylor series to 18 terms (truncation below 1e-22), then
!> squaring back.
module pound_expm
   use pound_kinds, only: dp
   implicit none
   private

   public :: expm

contains

   !> exp(x) of an n x n matrix.
   pure function expm(x) result(e)
      !> The matrix.
      real(dp), intent(in) :: x(:, :)
      real(dp) :: e(size(x, 1), size(x, 1))
      real(dp) :: y(size(x, 1), size(x, 1)), term(size(x, 1), size(x, 1)), nrm
      integer :: s, k, i

      nrm = maxval(sum(abs(x), dim=1))
      s = 0
      if (nrm > 0.5_dp) s = ceiling(log(nrm/0.5_dp)/log(2.0_dp))
      y = x/2.0_dp**s
      e = 0.0_dp
      term = 0.0_dp
      do i = 1, size(x, 1)
         e(i, i) = 1.0_dp
         term(i, i) = 1.0_dp
      end do
      do k = 1, 18
         term = matmul(term, y)/real(k, dp)
         e = e + term
      end do
      do k = 1, s
         e = matmul(e, e)
      end do
   end function expm

end module pound_expm
