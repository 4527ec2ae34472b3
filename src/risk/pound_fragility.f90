!> Lognormal fragility curves from a multiple-stripe analysis, fitted by binomial maximum
!> likelihood (Baker 2015, Earthquake Spectra 31(1)): P(outcome | im) = Phi(ln(im/theta)/beta).
!>
!> The fit is a probit regression, z = a + b (ln im - mean ln im), whose log-likelihood is
!> concave in (a, b): Newton's method with a backtracking line search reaches its maximum from
!> any start whenever it exists, and the gradient is checked to be ~0 at the end. It exists,
!> with b finite, exactly when the counts are not separated; then theta = exp(mean - a/b),
!> beta = 1/b (b > 0). Where the counts do not identify the curve the fit says why and brackets
!> the median instead:
!> - 'all zero': no stripe saw the outcome (median above the highest stripe);
!> - 'all one': every record of every stripe saw it (median below the lowest stripe);
!> - 'perfectly separated': every stripe all zero or all one, but for at most one stripe in
!>   between (beta -> 0: the median lies between the last all-zero and the first all-one stripe);
!> - 'one stripe': a single stripe with counts, some but not all of them ones;
!> - 'not increasing': the likelihood is largest for a curve that falls with the intensity
!>   (beta -> infinity with beta > 0), or for one so flat that its median is beyond e^700.
!> The bracket: bracket_lo is the highest stripe below which (and at which) every count is
!> zero (0 when the lowest stripe saw the outcome), bracket_hi the lowest stripe above which
!> (and at which) every count is one (huge(1.0_dp) when the highest stripe did not all see it).
!> Stripes with no records (n_total = 0) take no part.
module pound_fragility
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_normal, only: normal_log_cdf, normal_mills, nan_dp
   implicit none
   private

   public :: fragility_fit, fit_fragility, fragility_probability

   !> A fitted lognormal fragility, or why there is none and where its median lies.
   type, public :: fragility_fit
      !> Whether the counts identify the curve.
      logical :: identified = .false.
      !> Lognormal median theta (units of im) and dispersion beta; NaN when not identified.
      real(dp) :: median = nan_dp, beta = nan_dp
      !> '' when identified, else 'all zero', 'all one', 'perfectly separated', 'one stripe'
      !> or 'not increasing'.
      character(len=80) :: reason = ''
      !> The median's bracket when not identified (0 / huge(1.0_dp) for an open end).
      real(dp) :: bracket_lo = 0.0_dp, bracket_hi = huge(1.0_dp)
      !> When not identified: the level of the step fragility that stands for the curve in the
      !> risk integral (pound_hazard), bracket_lo, or the lowest stripe's level where bracket_lo
      !> is 0; NaN when identified.
      real(dp) :: step_level = nan_dp
      !> When not identified: whether that step's risk is only a lower bound (bracket_lo = 0:
      !> the lowest stripe saw the outcome, so the median may lie below the tested range).
      logical :: lower_bound = .false.
   end type fragility_fit

   !> Newton iterations at most, and the halvings of one line search at most.
   integer, parameter :: max_newton = 200, max_halvings = 60

contains

   !> Fit a lognormal fragility to stripe counts by binomial maximum likelihood.
   subroutine fit_fragility(im, n_total, n_yes, fit, error)
      !> Intensity of each stripe, > 0, strictly ascending.
      real(dp), intent(in) :: im(:)
      !> Records of each stripe (>= 0) and how many of them showed the outcome (0..n_total).
      integer, intent(in) :: n_total(:), n_yes(:)
      !> The fit.
      type(fragility_fit), intent(out) :: fit
      !> Invalid counts or intensities; a fit that does not converge.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: x(:), n(:), y(:)
      real(dp) :: a, b, xbar, l0, l1, g(2), h(3), d(2), det, t, scale_a, scale_b
      integer :: j, it, k, first_one, last_zero, n_used
      logical :: converged

      if (size(n_total) /= size(im) .or. size(n_yes) /= size(im)) then
         call fatal_error(error, 'fit_fragility: im, n_total and n_yes differ in length')
         return
      end if
      do j = 1, size(im)
         if (.not. (im(j) > 0.0_dp) .or. im(j) > huge(1.0_dp)) then
            call fatal_error(error, 'fit_fragility: every intensity must be finite and > 0')
            return
         end if
         if (n_total(j) < 0 .or. n_yes(j) < 0 .or. n_yes(j) > n_total(j)) then
            call fatal_error(error, 'fit_fragility: counts must satisfy 0 <= n_yes <= n_total')
            return
         end if
      end do
      if (size(im) > 1) then
         if (any(.not. (im(2:) > im(:size(im) - 1)))) then
            call fatal_error(error, 'fit_fragility: the intensities must be strictly ascending')
            return
         end if
      end if
      n_used = count(n_total > 0)
      if (n_used == 0) then
         call fatal_error(error, 'fit_fragility: no stripe has any record')
         return
      end if

      ! Separation, from the counts alone: the first stripe that saw the outcome, the last
      ! that did not all see it (stripes without records skipped).
      first_one = 0
      last_zero = 0
      do j = 1, size(im)
         if (n_total(j) == 0) cycle
         if (n_yes(j) > 0 .and. first_one == 0) first_one = j
         if (n_yes(j) < n_total(j)) last_zero = j
      end do
      call set_bracket(im, n_total, first_one, last_zero, fit)
      fit%lower_bound = .not. (fit%bracket_lo > 0.0_dp)
      if (fit%lower_bound) then
         fit%step_level = im(findloc(n_total > 0, .true., dim=1))
      else
         fit%step_level = fit%bracket_lo
      end if
      if (first_one == 0) then
         fit%reason = 'all zero'
         return
      else if (last_zero == 0) then
         fit%reason = 'all one'
         return
      else if (n_used == 1) then
         fit%reason = 'one stripe'
         return
      else if (last_zero <= first_one) then
         fit%reason = 'perfectly separated'
         return
      end if

      ! Probit regression on the centred log intensities.
      allocate (x(n_used), n(n_used), y(n_used))
      k = 0
      do j = 1, size(im)
         if (n_total(j) == 0) cycle
         k = k + 1
         x(k) = log(im(j))
         n(k) = real(n_total(j), dp)
         y(k) = real(n_yes(j), dp)
      end do
      xbar = sum(n*x)/sum(n)
      x = x - xbar
      scale_a = sum(n)
      scale_b = sum(n*abs(x))
      a = 0.0_dp
      b = 0.0_dp
      converged = .false.
      l0 = log_likelihood(a, b, x, n, y)
      do it = 1, max_newton
         call derivatives(a, b, x, n, y, g, h)
         if (abs(g(1)) <= 1.0e-12_dp*scale_a .and. abs(g(2)) <= 1.0e-12_dp*scale_b) then
            converged = .true.
            exit
         end if
         ! Newton direction: solve (-H) d = g, -H = [h1 h2; h2 h3] positive definite.
         det = h(1)*h(3) - h(2)*h(2)
         if (.not. (det > 0.0_dp)) exit
         d(1) = (h(3)*g(1) - h(2)*g(2))/det
         d(2) = (h(1)*g(2) - h(2)*g(1))/det
         t = 1.0_dp
         do k = 1, max_halvings
            l1 = log_likelihood(a + t*d(1), b + t*d(2), x, n, y)
            if (l1 >= l0 + 1.0e-4_dp*t*(g(1)*d(1) + g(2)*d(2))) exit
            t = 0.5_dp*t
         end do
         if (k > max_halvings) then
            ! no ascent left in floating point: accept when the gradient is ~0
            converged = abs(g(1)) <= 1.0e-8_dp*scale_a .and. abs(g(2)) <= 1.0e-8_dp*scale_b
            exit
         end if
         a = a + t*d(1)
         b = b + t*d(2)
         l0 = l1
      end do
      if (.not. converged) then
         call derivatives(a, b, x, n, y, g, h)
         converged = abs(g(1)) <= 1.0e-8_dp*scale_a .and. abs(g(2)) <= 1.0e-8_dp*scale_b
      end if
      if (.not. converged) then
         call fatal_error(error, 'fit_fragility: the maximum-likelihood fit did not converge')
         return
      end if
      if (.not. (b > 0.0_dp) .or. abs(xbar*b - a) > 700.0_dp*b) then
         ! falling, or so flat that the median lies beyond any floating-point intensity
         fit%reason = 'not increasing'
         return
      end if
      fit%identified = .true.
      fit%reason = ''
      fit%median = exp(xbar - a/b)
      fit%beta = 1.0_dp/b
      fit%bracket_lo = 0.0_dp
      fit%bracket_hi = huge(1.0_dp)
      fit%step_level = nan_dp
      fit%lower_bound = .false.
   end subroutine fit_fragility

   !> P(outcome | im) of a fit: the lognormal where identified, else the step the risk
   !> integral uses (pound_hazard: 1 from the step level up, 0 below it).
   elemental real(dp) function fragility_probability(fit, im) result(p)
      !> The fit.
      type(fragility_fit), intent(in) :: fit
      !> Intensity (> 0).
      real(dp), intent(in) :: im

      if (fit%identified) then
         p = exp(normal_log_cdf(log(im/fit%median)/fit%beta))
      else if (im >= fit%step_level) then
         p = 1.0_dp
      else
         p = 0.0_dp
      end if
   end function fragility_probability

   !> The median's bracket from the separation indices (see the module's description).
   pure subroutine set_bracket(im, n_total, first_one, last_zero, fit)
      real(dp), intent(in) :: im(:)
      integer, intent(in) :: n_total(:), first_one, last_zero
      type(fragility_fit), intent(inout) :: fit
      integer :: j

      fit%bracket_lo = 0.0_dp
      fit%bracket_hi = huge(1.0_dp)
      ! the highest stripe with records below the first one that saw the outcome
      do j = merge(first_one - 1, size(im), first_one > 0), 1, -1
         if (n_total(j) > 0) then
            fit%bracket_lo = im(j)
            exit
         end if
      end do
      ! the lowest stripe with records above the last one that did not all see it
      do j = merge(last_zero + 1, 1, last_zero > 0), size(im)
         if (n_total(j) > 0) then
            fit%bracket_hi = im(j)
            exit
         end if
      end do
   end subroutine set_bracket

   !> Binomial log-likelihood of the probit model z = a + b x (constant terms left out).
   pure real(dp) function log_likelihood(a, b, x, n, y) result(l)
      real(dp), intent(in) :: a, b, x(:), n(:), y(:)
      real(dp) :: z
      integer :: j

      l = 0.0_dp
      do j = 1, size(x)
         z = a + b*x(j)
         if (y(j) > 0.0_dp) l = l + y(j)*normal_log_cdf(z)
         if (n(j) > y(j)) l = l + (n(j) - y(j))*normal_log_cdf(-z)
      end do
   end function log_likelihood

   !> Gradient g (d/da, d/db) and the negated Hessian h = (haa, hab, hbb) of the log-likelihood.
   pure subroutine derivatives(a, b, x, n, y, g, h)
      real(dp), intent(in) :: a, b, x(:), n(:), y(:)
      real(dp), intent(out) :: g(2), h(3)
      real(dp) :: z, lp, lm, s, w
      integer :: j

      g = 0.0_dp
      h = 0.0_dp
      do j = 1, size(x)
         z = a + b*x(j)
         lp = normal_mills(z)
         lm = normal_mills(-z)
         ! dl/dz and -d2l/dz2 (lambda' = -lambda (z + lambda))
         s = y(j)*lp - (n(j) - y(j))*lm
         w = y(j)*lp*(z + lp) + (n(j) - y(j))*lm*(lm - z)
         g = g + s*[1.0_dp, x(j)]
         h = h + w*[1.0_dp, x(j), x(j)*x(j)]
      end do
   end subroutine derivatives

end module pound_fragility
