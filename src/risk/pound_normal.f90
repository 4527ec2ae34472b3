!> The standard normal distribution as the risk calculations need it: its distribution
!> function, the logarithms of both tails and the inverse Mills ratio, accurate far into the
!> tails (through `erfc_scaled`, so that nothing underflows before its logarithm is taken).
module pound_normal
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   implicit none
   private

   public :: normal_cdf, normal_log_cdf, normal_mills, normal_log_mass

   real(dp), parameter :: sqrt_half = 0.70710678118654752440_dp
   real(dp), parameter :: sqrt_two_pi = 2.50662827463100050242_dp
   !> |z| beyond which the tails are taken at this bound (z*z stays finite).
   real(dp), parameter :: z_clamp = 1.0e150_dp
   !> A quiet NaN as a constant (for default initialisation).
   real(dp), parameter, public :: nan_dp = transfer(int(z'7FF8000000000000', kind=int64), 1.0_dp)

contains

   !> Phi(z), the standard normal distribution function.
   elemental real(dp) function normal_cdf(z)
      !> Argument.
      real(dp), intent(in) :: z

      normal_cdf = 0.5_dp*erfc(-z*sqrt_half)
   end function normal_cdf

   !> ln Phi(z), accurate for every z (for z < 0 through erfc_scaled: no underflow).
   elemental real(dp) function normal_log_cdf(z)
      !> Argument.
      real(dp), intent(in) :: z
      real(dp) :: x

      x = max(-z_clamp, min(z_clamp, z))
      if (x < 0.0_dp) then
         normal_log_cdf = log(0.5_dp*erfc_scaled(-x*sqrt_half)) - 0.5_dp*x*x
      else
         normal_log_cdf = log(1.0_dp - 0.5_dp*erfc(x*sqrt_half))
      end if
   end function normal_log_cdf

   !> The inverse Mills ratio phi(z)/Phi(z), accurate for every z.
   elemental real(dp) function normal_mills(z)
      !> Argument.
      real(dp), intent(in) :: z
      real(dp) :: x

      x = max(-z_clamp, min(z_clamp, z))
      if (x < 0.0_dp) then
         normal_mills = 2.0_dp/(sqrt_two_pi*erfc_scaled(-x*sqrt_half))
      else
         normal_mills = exp(-0.5_dp*x*x)/(sqrt_two_pi*normal_cdf(x))
      end if
   end function normal_mills

   !> ln(Phi(b) - Phi(a)) for a < b (either may be +-huge for an open end), accurate in both
   !> tails: the smaller of the two tail masses is differenced. -huge when the mass is 0.
   elemental real(dp) function normal_log_mass(a, b)
      !> Lower and upper limits.
      real(dp), intent(in) :: a, b
      real(dp) :: r

      if (.not. (b > a)) then
         normal_log_mass = -huge(1.0_dp)
      else if (b <= 0.0_dp) then
         ! both in the lower tail: Phi(b) (1 - Phi(a)/Phi(b))
         r = exp(normal_log_cdf(a) - normal_log_cdf(b))
         normal_log_mass = normal_log_cdf(b) + log_one_minus(r)
      else if (a >= 0.0_dp) then
         ! both in the upper tail: Q(a) (1 - Q(b)/Q(a)), Q(x) = Phi(-x)
         r = exp(normal_log_cdf(-b) - normal_log_cdf(-a))
         normal_log_mass = normal_log_cdf(-a) + log_one_minus(r)
      else
         normal_log_mass = log(1.0_dp - normal_cdf(a) - normal_cdf(-b))
      end if
   end function normal_log_mass

   !> ln(1 - r) for 0 <= r <= 1 (-huge at r = 1).
   elemental real(dp) function log_one_minus(r)
      real(dp), intent(in) :: r

      if (r >= 1.0_dp) then
         log_one_minus = -huge(1.0_dp)
      else if (r < 1.0e-5_dp) then
         log_one_minus = -r*(1.0_dp + r*(0.5_dp + r/3.0_dp))
      else
         log_one_minus = log(1.0_dp - r)
      end if
   end function log_one_minus

end module pound_normal
