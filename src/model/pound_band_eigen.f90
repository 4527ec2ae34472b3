!> A few eigenpairs of a symmetric banded generalized eigenproblem A x = mu B x with B
!> positive definite, without any dense n x n matrix.
!>
!> Eigenvalues: LAPACK dsbgvx with JOBZ = 'N' (split Cholesky factor of B, reduction to
!> tridiagonal form in band storage, bisection for the selected indices). Eigenvectors:
!> inverse iteration with a banded LU factorization (dgbtrf) of A - sigma B at the computed
!> eigenvalue, which converges in one or two steps because sigma is accurate to round-off.
!> Eigenvectors of (numerically) repeated eigenvalues are not orthogonalized against each other.
module pound_band_eigen
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_band, only: band_symv
   use pound_band_lapack, only: dsbgvx, dgbtrf, dgbtrs
   implicit none
   private

   public :: band_largest_eigenvalues, band_inverse_iteration, band_lowest_modes

contains

   !> The `m` largest eigenvalues of A x = mu B x, ascending (A symmetric, B symmetric
   !> positive definite, both in upper band storage with the same kd).
   subroutine band_largest_eigenvalues(a, b, m, mu, error)
      !> A in upper band storage (kd+1, n).
      real(dp), intent(in) :: a(:, :)
      !> B in upper band storage (kd+1, n), positive definite.
      real(dp), intent(in) :: b(:, :)
      !> Number of eigenvalues wanted, 1 <= m <= n.
      integer, intent(in) :: m
      !> The m largest eigenvalues, ascending.
      real(dp), allocatable, intent(out) :: mu(:)
      !> Set if B is not positive definite or LAPACK fails.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: aa(:, :), bb(:, :), w(:), work(:)
      real(dp) :: q(1, 1), z(1, 1)
      integer, allocatable :: iwork(:), ifail(:)
      integer :: n, kd, found, info

      n = size(a, 2)
      kd = size(a, 1) - 1
      if (m < 1 .or. m > n) then
         call fatal_error(error, 'band eigenvalues: m = '//str(m)//', must be in 1..'//str(n))
         return
      end if
      aa = a
      bb = b
      allocate (w(n), work(7*n), iwork(5*n), ifail(n))
      call dsbgvx('N', 'I', 'U', n, kd, kd, aa, kd + 1, bb, kd + 1, q, 1, 0.0_dp, 0.0_dp, &
                  n - m + 1, n, 0.0_dp, found, w, z, 1, work, iwork, ifail, info)
      if (info > n) then
         call fatal_error(error, 'band eigenvalues: the right-hand matrix is not positive definite '// &
                          '(leading minor '//str(info - n)//')')
         return
      else if (info /= 0 .or. found /= m) then
         call fatal_error(error, 'band eigenvalues: dsbgvx failed (info = '//str(info)//')')
         return
      end if
      mu = w(1:m)
   end subroutine band_largest_eigenvalues

   !> Eigenvector of A x = mu B x for the eigenvalue `sigma` (from `band_largest_eigenvalues`),
   !> by inverse iteration; normalized to |x^T B x| = 1, largest component positive.
   subroutine band_inverse_iteration(a, b, sigma, x, error)
      !> A in upper band storage (kd+1, n).
      real(dp), intent(in) :: a(:, :)
      !> B in upper band storage (kd+1, n).
      real(dp), intent(in) :: b(:, :)
      !> The eigenvalue.
      real(dp), intent(in) :: sigma
      !> The eigenvector (n).
      real(dp), allocatable, intent(out) :: x(:)
      !> Set if the shifted matrix cannot be factorized.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: lu(:, :), y(:)
      integer, allocatable :: ipiv(:)
      real(dp) :: shift, scale
      integer :: n, kd, i, j, it, try, info

      n = size(a, 2)
      kd = size(a, 1) - 1
      allocate (lu(3*kd + 1, n), ipiv(n), y(n))
      shift = sigma
      do try = 1, 4
         ! General band storage of dgbtrf: lu(2 kd + 1 + i - j, j) = (A - shift B)(i, j).
         lu = 0.0_dp
         do j = 1, n
            do i = max(1, j - kd), j
               lu(2*kd + 1 + i - j, j) = a(kd + 1 + i - j, j) - shift*b(kd + 1 + i - j, j)
               lu(2*kd + 1 + j - i, i) = lu(2*kd + 1 + i - j, j)
            end do
         end do
         call dgbtrf(n, n, kd, kd, lu, 3*kd + 1, ipiv, info)
         if (info == 0) exit
         shift = shift + 1.0e-12_dp*max(abs(sigma), tiny(1.0_dp))*real(try, dp)
      end do
      if (info /= 0) then
         call fatal_error(error, 'inverse iteration: A - sigma B is singular at sigma = '//str(sigma))
         return
      end if
      allocate (x(n))
      x = 1.0_dp
      do i = 1, n, 2
         x(i) = 0.5_dp  ! not orthogonal to any particular mode
      end do
      do it = 1, 4
         call band_symv(b, x, y)
         call dgbtrs('N', n, kd, kd, 1, lu, 3*kd + 1, ipiv, y, n, info)
         x = y/maxval(abs(y))
      end do
      call band_symv(b, x, y)
      scale = sqrt(abs(dot_product(x, y)))
      j = maxloc(abs(x), 1)
      x = sign(1.0_dp, x(j))*x/scale
   end subroutine band_inverse_iteration

   !> The `m` lowest natural frequencies and modes of (K+G) phi = omega^2 M phi, with M
   !> positive semi-definite (massless DOFs allowed) and K+G positive definite.
   !>
   !> Solved as the reciprocal problem M phi = mu (K+G) phi, mu = 1/omega^2, whose right-hand
   !> matrix K+G is positive definite as dsbgvx requires: the m largest mu give the m lowest
   !> omega; massless DOFs only add mu = 0 (infinite frequencies). Mode shapes by inverse
   !> iteration, normalized to phi^T M phi = 1.
   subroutine band_lowest_modes(kt, mb, m, omega, shapes, error)
      !> K+G in upper band storage (kd+1, n), positive definite (kN/m).
      real(dp), intent(in) :: kt(:, :)
      !> M in upper band storage (kd+1, n), positive semi-definite (t).
      real(dp), intent(in) :: mb(:, :)
      !> Number of modes wanted.
      integer, intent(in) :: m
      !> Circular frequencies (rad/s), ascending.
      real(dp), allocatable, intent(out) :: omega(:)
      !> Mode shapes (n, m), mass-normalized.
      real(dp), allocatable, intent(out) :: shapes(:, :)
      !> Set if K+G is not positive definite or fewer than m modes carry mass.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: mu(:), x(:)
      integer :: j

      call band_largest_eigenvalues(mb, kt, m, mu, error)
      if (allocated(error)) return
      if (.not. (mu(1) > 1.0e-12_dp*mu(m))) then
         call fatal_error(error, 'modes: '//str(m)//' modes requested, but fewer than that carry mass')
         return
      end if
      allocate (omega(m), shapes(size(kt, 2), m))
      do j = 1, m
         omega(j) = 1.0_dp/sqrt(mu(m + 1 - j))
         call band_inverse_iteration(kt, mb, omega(j)**2, x, error)
         if (allocated(error)) return
         shapes(:, j) = x
      end do
   end subroutine band_lowest_modes

end module pound_band_eigen
