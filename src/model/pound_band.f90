!> Symmetric band matrices in LAPACK upper band storage.
!>
!> A symmetric n x n matrix A with kd super-diagonals is held in `ab(kd+1, n)` with
!> `ab(kd+1+i-j, j) = A(i, j)` for `max(1, j-kd) <= i <= j` (the `uplo = 'U'` layout of
!> dpbtrf, dpbtrs and dsbgv). A shear building has kd = 1 (tridiagonal).
module pound_band
   use pound_kinds, only: dp
   implicit none
   private

   public :: band_symv, band_to_dense, band_add_storey

contains

   !> y = A x for a symmetric band matrix A in upper band storage.
   pure subroutine band_symv(ab, x, y)
      !> Band storage of A, shape (kd+1, n).
      real(dp), intent(in) :: ab(:, :)
      !> Vector x (n).
      real(dp), intent(in) :: x(:)
      !> Result y = A x (n).
      real(dp), intent(out) :: y(:)
      integer :: n, kd, i, j
      real(dp) :: xj, yj

      n = size(ab, 2)
      kd = size(ab, 1) - 1
      do j = 1, n
         y(j) = ab(kd + 1, j)*x(j)
      end do
      ! Column j: y(j) is still its diagonal term here (the later columns add to it after), so
      ! summing it in a local in the same order gives the same numbers without a store and load
      ! of y(j) per entry.
      do j = 2, n
         xj = x(j)
         yj = y(j)
         do i = max(1, j - kd), j - 1
            y(i) = y(i) + ab(kd + 1 + i - j, j)*xj
            yj = yj + ab(kd + 1 + i - j, j)*x(i)
         end do
         y(j) = yj
      end do
   end subroutine band_symv

   !> Dense copy of a symmetric band matrix (tests, and the set-up of small dense problems:
   !> the condensation of the exact free steps and of the closed steps).
   pure function band_to_dense(ab) result(a)
      !> Band storage, shape (kd+1, n).
      real(dp), intent(in) :: ab(:, :)
      real(dp) :: a(size(ab, 2), size(ab, 2))
      integer :: n, kd, i, j

      n = size(ab, 2)
      kd = size(ab, 1) - 1
      a = 0.0_dp
      do j = 1, n
         do i = max(1, j - kd), j
            a(i, j) = ab(kd + 1 + i - j, j)
            a(j, i) = ab(kd + 1 + i - j, j)
         end do
      end do
   end function band_to_dense

   !> Add the stiffness `s` of a shear storey between floors `j-1` and `j` (floor 0 is the
   !> fixed ground) to a band matrix with kd >= 1.
   pure subroutine band_add_storey(ab, j, s)
      !> Band storage, shape (kd+1, n), kd >= 1.
      real(dp), intent(inout) :: ab(:, :)
      !> Storey number (1 = bottom storey).
      integer, intent(in) :: j
      !> Storey stiffness to add (may be negative: geometric stiffness).
      real(dp), intent(in) :: s
      integer :: kd

      kd = size(ab, 1) - 1
      ab(kd + 1, j) = ab(kd + 1, j) + s
      if (j > 1) then
         ab(kd + 1, j - 1) = ab(kd + 1, j - 1) + s
         ab(kd, j) = ab(kd, j) - s
      end if
   end subroutine band_add_storey

end module pound_band
