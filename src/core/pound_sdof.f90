!> Exact step of a damped linear oscillator under piecewise-linear forcing (Nigam and
!> Jennings 1969; Chopra, Dynamics of Structures, section 5.2).
!>
!> For u'' + 2 zeta omega u' + omega^2 u = p(t) (per unit mass; p in m/s^2, u in m) with p
!> linear between p_n = p(t_n) and p_{n+1} = p(t_n + h), the state x = (u, v) advances
!> exactly as
!>
!>     x_{n+1} = A x_n + B(:,1) p_n + B(:,2) p_{n+1}.
!>
!> A and B are the entries of the exponential of the 4x4 augmented matrix (Van Loan 1978) of
!> the dimensionless system in tau = omega t with state (omega u, v, p/omega, its slope),
!> evaluated by scaling and squaring with a Taylor series. They equal the closed forms of
!> Nigam and Jennings, but keep full accuracy when omega h is small, where the closed forms
!> cancel (their terms of size 2 zeta/(omega h) leave a result of size (omega h)^2), and hold
!> for any zeta >= 0.
module pound_sdof
   use pound_kinds, only: dp
   use pound_expm, only: expm
   implicit none
   private

   public :: sdof_step_t, sdof_step, sdof_advance

   !> Coefficients of one exact step of length h.
   type :: sdof_step_t
      !> Transition of the state (u, v).
      real(dp) :: a(2, 2) = 0.0_dp
      !> Columns: weights of p_n and of p_{n+1}.
      real(dp) :: b(2, 2) = 0.0_dp
   end type sdof_step_t

contains

   !> The step coefficients for circular frequency omega > 0 (rad/s), damping ratio zeta >= 0
   !> and step h > 0 (s). The caller checks the arguments.
   pure function sdof_step(omega, zeta, h) result(step)
      !> Circular frequency omega (rad/s).
      real(dp), intent(in) :: omega
      !> Damping ratio zeta.
      real(dp), intent(in) :: zeta
      !> Step h (s).
      real(dp), intent(in) :: h
      type(sdof_step_t) :: step
      real(dp) :: x(4, 4), e(4, 4), dtau

      dtau = omega*h
      x = 0.0_dp
      x(1, 2) = dtau
      x(2, 1) = -dtau
      x(2, 2) = -2.0_dp*zeta*dtau
      x(2, 3) = dtau
      x(3, 4) = dtau
      e = expm(x)
      ! Dimensionless state (omega u, v, f = p/omega, (f_{n+1} - f_n)/dtau).
      step%a(1, 1) = e(1, 1)
      step%a(1, 2) = e(1, 2)/omega
      step%a(2, 1) = e(2, 1)*omega
      step%a(2, 2) = e(2, 2)
      step%b(1, 1) = (e(1, 3) - e(1, 4)/dtau)/omega**2
      step%b(1, 2) = e(1, 4)/(dtau*omega**2)
      step%b(2, 1) = (e(2, 3) - e(2, 4)/dtau)/omega
      step%b(2, 2) = e(2, 4)/(dtau*omega)
   end function sdof_step

   !> Advance (u, v) by one step from forcing p0 at the start to p1 at the end.
   pure subroutine sdof_advance(step, p0, p1, u, v)
      !> Step coefficients.
      type(sdof_step_t), intent(in) :: step
      !> Forcing at the start and at the end of the step (m/s^2).
      real(dp), intent(in) :: p0, p1
      !> Displacement (m), advanced.
      real(dp), intent(inout) :: u
      !> Velocity (m/s), advanced.
      real(dp), intent(inout) :: v
      real(dp) :: u0

      u0 = u
      u = step%a(1, 1)*u0 + step%a(1, 2)*v + step%b(1, 1)*p0 + step%b(1, 2)*p1
      v = step%a(2, 1)*u0 + step%a(2, 2)*v + step%b(2, 1)*p0 + step%b(2, 2)*p1
   end subroutine sdof_advance

end module pound_sdof
