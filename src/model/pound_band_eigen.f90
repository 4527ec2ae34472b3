!> The lowest eigenpairs of symmetric banded generalized eigenproblems without any dense
!> n x n matrix: natural modes with massless DOFs, eigenvectors at a known eigenvalue.
!>
!> Natural modes of (K+G) phi = omega^2 M phi, M positive semi-definite (massless DOFs
!> allowed), K+G positive definite: subspace iteration (Bathe) on the reciprocal problem
!> M phi = mu (K+G) phi, mu = 1/omega^2. K+G is factorized once (dpbtrf); each iteration
!> solves (K+G) Y = M X (dpbtrs) for q = max(2p, p+8) vectors (at most the DOFs with mass)
!> and makes a Rayleigh-Ritz step with the small q x q pencil (Y^T M Y, Y^T (K+G) Y), solved
!> by dsygv with the positive definite Y^T (K+G) Y on the right, so that massless directions
!> only give mu = 0 (infinite frequencies). A wanted mode is converged when its residual
!> ||(K+G) phi - omega^2 M phi|| / ||(K+G) phi|| is below 1e-10, or when the residual is
!> within 100 times its round-off floor eps || |K+G| |phi| || / ||(K+G) phi|| and the
!> eigenvalue changed by less than 1e-10 relative in the last iteration. The floor matters
!> in tall frames: (K+G) phi of a low mode is a cancellation of terms up to
!> omega_max^2/omega^2 times larger (the columns' axial stiffness against the sway), so
!> its residual cannot fall below about eps times that (4e-6 for the first mode of a
!> 1000-storey, 3-bay frame); the eigenvalue is then settled to round-off (changes of
!> 1e-15 to 1e-11 from one iteration to the next). Cost per iteration O(n kd q), linear
!> in n.
!>
!> Eigenvector at a known eigenvalue sigma of A x = mu B x: inverse iteration with a banded
!> LU factorization (dgbtrf) of A - sigma B, which converges in one or two steps because
!> sigma is accurate to round-off.
module pound_band_eigen
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_plausibility, only: buckling_hint
   use pound_band, only: band_symv
   use pound_band_lapack, only: dpbtrf, dpbtrs, dsygv, dgbtrf, dgbtrs
   implicit none
   private

   public :: band_lowest_modes, band_inverse_iteration

   !> Relative residual at which a mode is converged.
   real(dp), parameter :: residual_tol = 1.0e-10_dp
   !> A residual within this factor of its round-off floor has reached the floor.
   real(dp), parameter :: floor_factor = 100.0_dp
   !> Relative change of a settled eigenvalue in one iteration (with the residual at its floor).
   real(dp), parameter :: settled_tol = 1.0e-10_dp
   !> Iteration limit of the subspace iteration.
   integer, parameter :: max_iterations = 500

contains

   !> The `m` lowest natural frequencies and modes of (K+G) phi = omega^2 M phi.
   subroutine band_lowest_modes(kt, mb, m, omega, shapes, error)
      !> K+G in upper band storage (kd+1, n), positive definite (kN/m).
      real(dp), intent(in) :: kt(:, :)
      !> M in upper band storage (kd+1, n), positive semi-definite (t).
      real(dp), intent(in) :: mb(:, :)
      !> Number of modes wanted.
      integer, intent(in) :: m
      !> Circular frequencies (rad/s), ascending.
      real(dp), allocatable, intent(out) :: omega(:)
      !> Mode shapes (n, m), mass-normalized (phi^T M phi = 1).
      real(dp), allocatable, intent(out) :: shapes(:, :)
      !> Set if K+G is not positive definite, fewer than m modes carry mass or the
      !> iteration does not converge.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: fac(:, :), x(:, :), y(:, :), mx(:, :), kr(:, :), mr(:, :)
      real(dp), allocatable :: mu(:), work(:), ratio(:), r(:), kx(:), res(:), mu_prev(:), akt(:, :), ax(:)
      real(dp) :: res_floor
      integer :: n, kd, q, j, i, it, info, worst

      n = size(kt, 2)
      kd = size(kt, 1) - 1
      q = min(max(2*m, m + 8), count(mb(kd + 1, :) > 0.0_dp))
      if (m < 1 .or. m > q) then
         call fatal_error(error, 'modes: '//str(m)//' modes requested, but only '// &
                          str(count(mb(kd + 1, :) > 0.0_dp))//' DOFs carry mass')
         return
      end if
      fac = kt
      call dpbtrf('U', n, kd, fac, kd + 1, info)
      if (info /= 0) then
         call fatal_error(error, 'modes: K+G is not positive definite (leading minor '//str(info)//')'// &
                          buckling_hint)
         return
      end if
      ! Start vectors: the mass diagonal, then unit vectors at the largest m_ii/k_ii.
      allocate (x(n, q), y(n, q), mx(n, q), mu(q), work(max(1, 3*q*q)), r(n), kx(n), ax(n))
      allocate (res(m), mu_prev(m))
      akt = abs(kt)
      res = huge(1.0_dp)
      mu_prev = 0.0_dp
      ratio = mb(kd + 1, :)/kt(kd + 1, :)
      x = 0.0_dp
      x(:, 1) = mb(kd + 1, :)
      do j = 2, q
         i = maxloc(ratio, 1)
         x(i, j) = 1.0_dp
         ratio(i) = -1.0_dp
      end do
      do j = 1, q
         call band_symv(mb, x(:, j), mx(:, j))
      end do
      do it = 1, max_iterations
         y = mx
         call dpbtrs('U', n, kd, q, fac, kd + 1, y, n, info)
         ! Rayleigh-Ritz: Y^T (K+G) Y = Y^T M X (since (K+G) Y = M X), Y^T M Y.
         kr = matmul(transpose(y), mx)
         kr = 0.5_dp*(kr + transpose(kr))
         do j = 1, q
            call band_symv(mb, y(:, j), mx(:, j))
         end do
         mr = matmul(transpose(y), mx)
         mr = 0.5_dp*(mr + transpose(mr))
         call dsygv(1, 'V', 'U', q, mr, q, kr, q, mu, work, size(work), info)
         if (info /= 0) then
            call fatal_error(error, 'modes: Rayleigh-Ritz step failed (dsygv info = '//str(info)// &
                             '): the masses span fewer directions than the subspace')
            return
         end if
         ! Ritz vectors, largest mu (lowest omega) first; mr holds the eigenvectors.
         x = matmul(y, mr(:, q:1:-1))
         mu = mu(q:1:-1)
         do j = 1, q
            call band_symv(mb, x(:, j), mx(:, j))
         end do
         worst = 0
         do j = 1, m
            if (.not. (mu(j) > 1.0e-12_dp*mu(1))) cycle
            call band_symv(kt, x(:, j), kx)
            r = kx - mx(:, j)/mu(j)
            res(j) = norm2(r)/norm2(kx)
            if (res(j) <= residual_tol) cycle
            ! Converged too: the residual at its round-off floor and the eigenvalue settled.
            ax = abs(x(:, j))
            call band_symv(akt, ax, r)
            res_floor = epsilon(1.0_dp)*norm2(r)/norm2(kx)
            if (.not. (res(j) <= floor_factor*res_floor .and. abs(mu(j) - mu_prev(j)) <= settled_tol*mu(j))) worst = j
         end do
         if (worst == 0) exit
         mu_prev = mu(1:m)
      end do
      if (.not. (mu(m) > 1.0e-12_dp*mu(1))) then
         call fatal_error(error, 'modes: '//str(m)//' modes requested, but fewer than that carry mass')
         return
      end if
      if (worst /= 0) then
         call fatal_error(error, 'modes: subspace iteration did not converge in '//str(max_iterations)// &
                          ' iterations (mode '//str(worst)//')')
         return
      end if
      allocate (omega(m), shapes(n, m))
      do j = 1, m
         omega(j) = 1.0_dp/sqrt(mu(j))
         ! x^T (K+G) x = 1, so x^T M x = mu.
         shapes(:, j) = x(:, j)/sqrt(mu(j))
         i = maxloc(abs(shapes(:, j)), 1)
         shapes(:, j) = sign(1.0_dp, shapes(i, j))*shapes(:, j)
      end do
   end subroutine band_lowest_modes

   !> Eigenvector of A x = mu B x for the eigenvalue `sigma` by inverse iteration;
   !> normalized to |x^T B x| = 1, largest component positive.
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
      x(1:n:2) = 0.5_dp  ! not orthogonal to any particular mode
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

end module pound_band_eigen
