!> The site's hazard curve and the risk integral of a fragility against it.
!>
!> The curve is given by points (im, annual rate of exceedance), im ascending, rate
!> decreasing, both > 0. Between points it is a power law (linear in log-log), and beyond both
!> ends the end segments' power laws go on.
!>
!> The mean annual frequency of an outcome is maf = integral of P(im) |d rate(im)|. Integrated
!> by parts it is the integral of rate(im) dP(im); on each log-log segment, rate = c im^-k,
!> and with the lognormal P = Phi((ln im - mu)/beta) the segment's part is exact:
!>    c exp(-k mu + k^2 beta^2/2) [Phi(z_hi + k beta) - Phi(z_lo + k beta)],
!> z = (ln im - mu)/beta at the segment's ends; summed over the segments (the end ones open)
!> it is accurate to rounding. For a single power law it is k0 theta^-k exp(k^2 beta^2/2).
!>
!> A fit that is not identified (pound_fragility) counts as a step fragility, P = 0 below a
!> level and 1 from it up, so that maf = rate(level): the level is the fit's bracket_lo (the
!> highest stripe that saw no outcome below the first that did: conservative, as the median
!> lies above it); where that is 0 (the lowest stripe saw the outcome) it is the lowest
!> stripe's level, and the maf is then a lower bound. fit_fragility sets both (step_level,
!> lower_bound).
module pound_hazard
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_normal, only: normal_log_mass, nan_dp
   use pound_fragility, only: fragility_fit
   implicit none
   private

   public :: hazard_curve, hazard_rate, fragility_maf, probability_in

   !> A hazard curve: intensities (ascending, > 0) and their annual rates of exceedance
   !> (decreasing, > 0), at least two points.
   type, public :: hazard_curve
      real(dp), allocatable :: im(:), rate(:)
   end type hazard_curve

   !> Largest exponent exp() takes without overflow, with a margin.
   real(dp), parameter :: max_exponent = 700.0_dp

contains

   !> Annual rate of exceeding `im` (log-log interpolation; log-log linear extrapolation beyond
   !> both ends). huge(1.0_dp) for im <= 0; NaN for a curve of fewer than two points.
   pure real(dp) function hazard_rate(hz, im) result(rate)
      !> The hazard curve.
      type(hazard_curve), intent(in) :: hz
      !> Intensity.
      real(dp), intent(in) :: im
      integer :: i
      real(dp) :: e

      if (size(hz%im) < 2) then
         rate = nan_dp
         return
      end if
      if (.not. (im > 0.0_dp)) then
         rate = huge(1.0_dp)
         return
      end if
      i = segment(hz, log(im))
      e = log(hz%rate(i)) - slope(hz, i)*(log(im) - log(hz%im(i)))
      rate = exp(min(e, max_exponent))
   end function hazard_rate

   !> Mean annual frequency of an outcome with fragility `fit` under hazard `hz` (see the
   !> module's description; a fit that is not identified counts as a step at its
   !> step_level). huge(1.0_dp) where it overflows.
   real(dp) function fragility_maf(fit, hz) result(maf)
      !> The fragility.
      type(fragility_fit), intent(in) :: fit
      !> The hazard curve.
      type(hazard_curve), intent(in) :: hz
      real(dp) :: mu, beta, k, c, zlo, zhi, e, terms(size(hz%im) + 1)
      integer :: i, nseg

      if (size(hz%im) < 2) then
         maf = nan_dp
         return
      end if
      if (.not. fit%identified) then
         maf = hazard_rate(hz, fit%step_level)
         return
      end if
      mu = log(fit%median)
      beta = fit%beta
      if (beta > 1.0e100_dp) then
         ! so wide that (k beta)^2 would overflow: the integral does
         maf = huge(1.0_dp)
         return
      end if
      nseg = size(hz%im) + 1
      ! segment i (1..n+1) runs from ln im(i-1) to ln im(i), open at both ends; it follows
      ! the power law of points (max(i-1,1), min(i,n)) extended
      do i = 1, nseg
         k = slope(hz, min(max(i - 1, 1), size(hz%im) - 1))
         ! rate = exp(c - k u) on the segment, through its defining point
         c = log(hz%rate(min(max(i - 1, 1), size(hz%im)))) &
             + k*log(hz%im(min(max(i - 1, 1), size(hz%im))))
         if (i == 1) then
            zlo = -huge(1.0_dp)
         else
            zlo = (log(hz%im(i - 1)) - mu)/beta + k*beta
         end if
         if (i == nseg) then
            zhi = huge(1.0_dp)
         else
            zhi = (log(hz%im(i)) - mu)/beta + k*beta
         end if
         e = c - k*mu + 0.5_dp*(k*beta)**2
         terms(i) = e + normal_log_mass(zlo, zhi)
      end do
      if (maxval(terms) > max_exponent) then
         maf = huge(1.0_dp)
      else
         maf = sum(exp(max(terms, -max_exponent)), mask=terms > -max_exponent)
      end if
   end function fragility_maf

   !> Probability of at least one occurrence in `years` of a Poisson process of rate `maf`:
   !> 1 - exp(-maf years).
   pure real(dp) function probability_in(maf, years) result(p)
      !> Mean annual frequency (>= 0).
      real(dp), intent(in) :: maf
      !> Exposure time (years, >= 0).
      real(dp), intent(in) :: years
      real(dp) :: x

      if (ieee_is_nan(maf) .or. ieee_is_nan(years)) then
         p = nan_dp
      else if (maf <= 0.0_dp .or. years <= 0.0_dp) then
         p = 0.0_dp
      else if (maf >= max_exponent/years) then
         p = 1.0_dp
      else
         x = maf*years
         if (x < 1.0e-5_dp) then
            p = x*(1.0_dp - x*(0.5_dp - x/6.0_dp))
         else
            p = 1.0_dp - exp(-x)
         end if
      end if
   end function probability_in

   !> The segment (1..n-1) whose power law holds at u = ln im: the end ones beyond the ends.
   pure integer function segment(hz, u) result(i)
      type(hazard_curve), intent(in) :: hz
      real(dp), intent(in) :: u

      do i = 1, size(hz%im) - 2
         if (u < log(hz%im(i + 1))) return
      end do
      i = size(hz%im) - 1
   end function segment

   !> Slope k of segment i: rate proportional to im^-k between points i and i+1.
   pure real(dp) function slope(hz, i) result(k)
      type(hazard_curve), intent(in) :: hz
      integer, intent(in) :: i

      k = -(log(hz%rate(i + 1)) - log(hz%rate(i)))/(log(hz%im(i + 1)) - log(hz%im(i)))
   end function slope

end module pound_hazard
