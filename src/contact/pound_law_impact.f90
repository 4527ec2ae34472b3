!> The central impact of two free masses on a joint law, finely integrated: the realised
!> coefficient of restitution, the largest penetration, the contact duration and the peak
!> force of a law's calibration (the listing's "realised e", the impact-aware substep count
!> of a smooth law, studies of a law). One public procedure, `law_impact`, for any law that
!> has a force of its own (`joint_law%force`: the smooth laws).
!>
!> The relative motion of the two masses m1, m2 (0: rigid, infinite) is
!> m_eff x'' = -max(0, f(x, x'; v)), x(0) = 0, x'(0) = v > 0, m_eff = m1 m2/(m1 + m2), while
!> x > 0; the impact ends when x returns to 0 (or the force has vanished for good with the
!> masses separating: a clipped law lets them fly apart inside the penetration). It is
!> integrated by the classical Runge-Kutta method of order 4 with `impact_steps` steps over
!> the estimated duration (pi dmax/v, dmax from the law's elastic part and the impact's
!> kinetic energy), the end located by linear interpolation in the last step.
module pound_law_impact
   use pound_kinds, only: dp
   use pound_constants, only: pi
   use pound_joint_law, only: joint_law
   implicit none
   private

   public :: law_impact, impact_result, impact_steps, typical_impact_speed, pair_mass

   !> Runge-Kutta steps over the estimated contact duration.
   integer, parameter :: impact_steps = 20000
   !> The approach speed of the calibration impact the listing reports (m/s).
   real(dp), parameter :: typical_impact_speed = 0.5_dp

   !> What an impact did.
   type :: impact_result
      !> Realised coefficient of restitution: separation speed / approach speed.
      real(dp) :: restitution = 0.0_dp
      !> Largest penetration (m), contact duration (s), peak force (kN).
      real(dp) :: max_penetration = 0.0_dp, duration = 0.0_dp, peak_force = 0.0_dp
      !> The law has a force of its own (else nothing above is set).
      logical :: defined = .false.
   end type impact_result

contains

   !> The central impact of masses m1 and m2 (t; 0: rigid) at the approach speed v (m/s)
   !> on the joint law `law` (its force hook; the closing speed latched at the impact's
   !> start is v).
   pure function law_impact(law, m1, m2, v) result(res)
      !> The law.
      class(joint_law), intent(in) :: law
      !> Masses of the two ends (t; 0: rigid), not both 0.
      real(dp), intent(in) :: m1, m2
      !> Approach speed (m/s), > 0.
      real(dp), intent(in) :: v
      type(impact_result) :: res
      real(dp) :: meff, dmax, h, t, x, u, k1x, k1u, k2x, k2u, k3x, k3u, k4x, k4u, xn, un, f, df, dv, s
      integer :: i
      logical :: defined

      call law%force(1.0e-3_dp, 0.0_dp, v, f, df, dv, defined)
      if (.not. defined .or. .not. (v > 0.0_dp)) return
      res%defined = .true.
      meff = pair_mass(m1, m2)
      dmax = elastic_reach(law, meff, v)
      h = pi*dmax/v/real(impact_steps, dp)
      t = 0.0_dp
      x = 0.0_dp
      u = v
      do i = 1, 50*impact_steps
         k1x = u
         k1u = accel(x, u)
         k2x = u + 0.5_dp*h*k1u
         k2u = accel(x + 0.5_dp*h*k1x, k2x)
         k3x = u + 0.5_dp*h*k2u
         k3u = accel(x + 0.5_dp*h*k2x, k3x)
         k4x = u + h*k3u
         k4u = accel(x + h*k3x, k4x)
         xn = x + h/6.0_dp*(k1x + 2.0_dp*k2x + 2.0_dp*k3x + k4x)
         un = u + h/6.0_dp*(k1u + 2.0_dp*k2u + 2.0_dp*k3u + k4u)
         res%max_penetration = max(res%max_penetration, xn)
         res%peak_force = max(res%peak_force, -meff*accel(xn, un))
         if (xn <= 0.0_dp) then
            ! The masses leave each other inside the step: interpolate the crossing.
            s = x/(x - xn)
            res%duration = t + s*h
            res%restitution = -(u + s*(un - u))/v
            return
         end if
         if (un < 0.0_dp .and. accel(xn, un) == 0.0_dp .and. xn > 0.0_dp) then
            ! No force with the masses separating: a clipped law lets them fly apart; the
            ! force cannot come back while the speed is constant and negative (for the
            ! laws here; checked by one more step of free flight below).
            if (accel(xn + h*un, un) == 0.0_dp) then
               res%duration = t + h
               res%restitution = -un/v
               return
            end if
         end if
         t = t + h
         x = xn
         u = un
      end do
      res%duration = t
      res%restitution = -u/v

   contains

      pure real(dp) function accel(xx, uu)
         real(dp), intent(in) :: xx, uu
         real(dp) :: ff, a, b
         logical :: ok

         ! At x = 0 the force of x = 0+ (a Kelvin joint's c x' at the impact's start).
         accel = 0.0_dp
         if (xx < 0.0_dp) return
         call law%force(xx, uu, v, ff, a, b, ok)
         accel = -max(0.0_dp, ff)/meff
      end function accel
   end function law_impact

   !> m1 m2/(m1 + m2), a zero mass standing for a rigid (infinite) one.
   pure real(dp) function pair_mass(m1, m2) result(meff)
      !> Masses (t).
      real(dp), intent(in) :: m1, m2

      if (m1 > 0.0_dp .and. m2 > 0.0_dp) then
         meff = m1*m2/(m1 + m2)
      else
         meff = max(m1, m2)
      end if
   end function pair_mass

   !> The penetration at which the law's force at rest (d' = 0) has stored the kinetic
   !> energy m_eff v^2/2 (bisection on the trapezoidal integral): the scale of the impact.
   pure real(dp) function elastic_reach(law, meff, v) result(d)
      class(joint_law), intent(in) :: law
      real(dp), intent(in) :: meff, v
      real(dp) :: lo, hi, target
      integer :: i

      target = 0.5_dp*meff*v*v
      hi = 1.0e-6_dp
      do i = 1, 200
         if (stored(hi) >= target) exit
         hi = 2.0_dp*hi
      end do
      lo = 0.0_dp
      do i = 1, 100
         d = 0.5_dp*(lo + hi)
         if (stored(d) >= target) then
            hi = d
         else
            lo = d
         end if
      end do
      d = hi

   contains

      pure real(dp) function stored(x)
         real(dp), intent(in) :: x
         real(dp) :: f, a, b
         logical :: ok
         integer :: j
         integer, parameter :: n = 64

         stored = 0.0_dp
         do j = 1, n
            call law%force(x*(real(j, dp) - 0.5_dp)/n, 0.0_dp, v, f, a, b, ok)
            stored = stored + max(0.0_dp, f)*x/n
         end do
      end function stored
   end function elastic_reach

end module pound_law_impact
