!> Synthetic ground accelerations (`kind = 'synthetic'`): filtered white noise under a time
!> envelope, baseline-corrected and scaled to a target PGA.
!>
!> For a seed, a duration T, a step dt and the parameters of `synthetic_config`:
!>
!> 1. White noise: w_i, i = 0..n (t_i = i dt, n = floor(T/dt)), independent standard normals
!>    from pound's own generator (`pound_random`) seeded with `seed`, linear between samples.
!> 2. Kanai-Tajimi filter (ground frequency wg rad/s, damping zg): x'' + 2 zg wg x' + wg^2 x
!>    = -w(t), s(t) = x'' + w = -(2 zg wg x' + wg^2 x), power spectral density
!>    |H(w)|^2 = (wg^4 + 4 zg^2 wg^2 w^2)/((wg^2 - w^2)^2 + 4 zg^2 wg^2 w^2) times that of w.
!>    Clough-Penzien adds the high-pass y'' + 2 zf wf y' + wf^2 y = s(t), output y'', which
!>    multiplies the PSD by w^4/((wf^2 - w^2)^2 + 4 zf^2 wf^2 w^2) and removes the
!>    unbounded ground displacement of Kanai-Tajimi. Both filters start at rest and are
!>    integrated exactly for linear forcing between samples (`pound_sdof`).
!> 3. Envelope e(t) (a uniformly modulated process, a_i = e(t_i) s_i):
!>    Jennings: (t/t1)^2 for t < t1, 1 up to t2, exp(-c (t - t2)) after;
!>    Saragoni-Hart in Boore's (2003) form: e = (t/t_p)^b exp(b (1 - t/t_p)), peak 1 at
!>    t_p = eps T, e(T) = eta, b = -eps ln(eta)/(1 + eps (ln(eps) - 1)).
!> 4. Baseline correction: a <- a - (c1 + c2 t/T) e(t), c1 and c2 chosen so that the ground
!>    velocity and displacement at t = T are zero, both integrated as the solver does
!>    (average acceleration: v by the trapezoidal rule, u_{i+1} = u_i + dt v_i +
!>    dt^2 (a_i + a_{i+1})/4). The correction has the envelope's shape, so the motion still
!>    starts from zero; its mean (v(T)/T) is zero.
!> 5. Scaling to the target PGA (m/s^2): a <- a pga / max_i |a_i|, which keeps v(T) = u(T) = 0
!>    up to round-off.
module pound_synthetic_motion
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_random, only: random_t, random_seed_stream, random_normal
   use pound_sdof, only: sdof_step_t, sdof_step, sdof_advance
   implicit none
   private

   public :: synthetic_config, synthetic_motion, synthetic_envelope, synthetic_filter_psd
   public :: check_synthetic, end_velocity_displacement

   !> Parameters of a synthetic motion (defaults: Clough-Penzien firm-soil values of
   !> Der Kiureghian and Neuenhofer 1992 for the filters, Jennings' envelope).
   type :: synthetic_config
      !> 'kanai_tajimi' or 'clough_penzien'.
      character(len=16) :: filter = 'kanai_tajimi'
      !> Ground filter frequency wg (rad/s) > 0 and damping ratio zg, 0 < zg < 1.
      real(dp) :: wg = 15.0_dp, zg = 0.6_dp
      !> High-pass (Clough-Penzien) frequency wf (rad/s) > 0 and damping ratio, 0 < zf < 1.
      real(dp) :: wf = 1.5_dp, zf = 0.6_dp
      !> 'jennings' or 'saragoni_hart'.
      character(len=16) :: envelope = 'jennings'
      !> Jennings: rise time t1 (s) > 0, end of the plateau t2 (s), t1 <= t2 <= duration,
      !> decay rate c (1/s) > 0.
      real(dp) :: t1 = 2.0_dp, t2 = 10.0_dp, c = 0.3_dp
      !> Saragoni-Hart: time of the peak as a fraction of the duration, 0 < eps < 1, and the
      !> envelope at the end of the duration, 0 < eta < 1.
      real(dp) :: eps = 0.2_dp, eta = 0.05_dp
      !> Duration T (s) >= 10 dt.
      real(dp) :: duration = 20.0_dp
      !> Target peak ground acceleration (m/s^2; 0.3 g = 2.943 m/s^2) > 0.
      real(dp) :: pga = 0.0_dp
      !> Seed of the white noise (any integer).
      integer(int64) :: seed = 1_int64
   end type synthetic_config

contains

   !> The synthetic ground acceleration a(i) at t = (i-1) dt, i = 1..floor(T/dt)+1 (m/s^2).
   pure subroutine synthetic_motion(cfg, dt, accel, error)
      !> Parameters.
      type(synthetic_config), intent(in) :: cfg
      !> Sample step dt (s) > 0.
      real(dp), intent(in) :: dt
      !> Ground acceleration (m/s^2).
      real(dp), allocatable, intent(out) :: accel(:)
      !> Set when a parameter breaks its rule (message: `variable = value, rule`).
      type(error_type), allocatable, intent(out) :: error
      type(random_t) :: rng
      type(sdof_step_t) :: step
      real(dp), allocatable :: noise(:), env(:), ramp(:)
      real(dp) :: u, v, t_end, ve(3), de(3), det, c1, c2, peak
      integer :: n, i

      call check_synthetic(cfg, dt, error)
      if (allocated(error)) return
      n = floor(cfg%duration/dt + 1.0e-9_dp)
      t_end = n*dt
      allocate (noise(n + 1), accel(n + 1), env(n + 1), ramp(n + 1))
      call random_seed_stream(rng, cfg%seed)
      call random_normal(rng, noise)
      ! Kanai-Tajimi: forcing -w, output -(2 zg wg x' + wg^2 x).
      step = sdof_step(cfg%wg, cfg%zg, dt)
      u = 0.0_dp
      v = 0.0_dp
      accel(1) = 0.0_dp
      do i = 2, n + 1
         call sdof_advance(step, -noise(i - 1), -noise(i), u, v)
         accel(i) = -(2.0_dp*cfg%zg*cfg%wg*v + cfg%wg**2*u)
      end do
      if (cfg%filter == 'clough_penzien') then
         ! High-pass: forcing s, output y'' = s - 2 zf wf y' - wf^2 y.
         step = sdof_step(cfg%wf, cfg%zf, dt)
         u = 0.0_dp
         v = 0.0_dp
         noise = accel
         do i = 2, n + 1
            call sdof_advance(step, noise(i - 1), noise(i), u, v)
            accel(i) = noise(i) - (2.0_dp*cfg%zf*cfg%wf*v + cfg%wf**2*u)
         end do
      end if
      do i = 1, n + 1
         env(i) = synthetic_envelope(cfg, (i - 1)*dt)
         ramp(i) = env(i)*((i - 1)*dt/t_end)
      end do
      accel = accel*env
      ! Baseline: remove c1 e(t) + c2 e(t) t/T so that v(T) = u(T) = 0.
      call end_velocity_displacement(accel, dt, ve(1), de(1))
      call end_velocity_displacement(env, dt, ve(2), de(2))
      call end_velocity_displacement(ramp, dt, ve(3), de(3))
      det = ve(2)*de(3) - ve(3)*de(2)
      c1 = (ve(1)*de(3) - ve(3)*de(1))/det
      c2 = (ve(2)*de(1) - ve(1)*de(2))/det
      accel = accel - c1*env - c2*ramp
      peak = maxval(abs(accel))
      accel = accel*(cfg%pga/peak)
   end subroutine synthetic_motion

   !> Ground velocity and displacement at the last sample of a motion starting at rest,
   !> integrated by the average-acceleration rule (the solver's): v_{i+1} = v_i +
   !> dt (a_i + a_{i+1})/2, u_{i+1} = u_i + dt v_i + dt^2 (a_i + a_{i+1})/4.
   pure subroutine end_velocity_displacement(accel, dt, v_end, u_end)
      !> Acceleration at t = (i-1) dt (m/s^2).
      real(dp), intent(in) :: accel(:)
      !> Step (s).
      real(dp), intent(in) :: dt
      !> Velocity (m/s) and displacement (m) at the last sample.
      real(dp), intent(out) :: v_end, u_end
      real(dp) :: s
      integer :: i

      v_end = 0.0_dp
      u_end = 0.0_dp
      do i = 1, size(accel) - 1
         s = accel(i) + accel(i + 1)
         u_end = u_end + dt*v_end + 0.25_dp*dt*dt*s
         v_end = v_end + 0.5_dp*dt*s
      end do
   end subroutine end_velocity_displacement

   !> The time envelope e(t) (dimensionless, peak 1) of `cfg` at time t (s).
   pure function synthetic_envelope(cfg, t) result(e)
      !> Parameters.
      type(synthetic_config), intent(in) :: cfg
      !> Time (s) >= 0.
      real(dp), intent(in) :: t
      real(dp) :: e
      real(dp) :: b, tp

      if (cfg%envelope == 'saragoni_hart') then
         b = -cfg%eps*log(cfg%eta)/(1.0_dp + cfg%eps*(log(cfg%eps) - 1.0_dp))
         tp = cfg%eps*cfg%duration
         e = 0.0_dp
         if (t > 0.0_dp) e = exp(b*(log(t/tp) + 1.0_dp - t/tp))
      else if (t < cfg%t1) then
         e = (max(t, 0.0_dp)/cfg%t1)**2
      else if (t <= cfg%t2) then
         e = 1.0_dp
      else
         e = exp(-cfg%c*(t - cfg%t2))
      end if
   end function synthetic_envelope

   !> Filter gain |H(w)|^2 of `cfg` at circular frequency w (rad/s): Kanai-Tajimi, times
   !> the high-pass for Clough-Penzien. The stationary PSD is |H|^2 times the white noise's.
   elemental function synthetic_filter_psd(cfg, w) result(g)
      !> Parameters.
      type(synthetic_config), intent(in) :: cfg
      !> Circular frequency (rad/s).
      real(dp), intent(in) :: w
      real(dp) :: g
      real(dp) :: d

      d = 4.0_dp*(cfg%zg*cfg%wg*w)**2
      g = (cfg%wg**4 + d)/((cfg%wg**2 - w**2)**2 + d)
      if (cfg%filter == 'clough_penzien') then
         g = g*w**4/((cfg%wf**2 - w**2)**2 + 4.0_dp*(cfg%zf*cfg%wf*w)**2)
      end if
   end function synthetic_filter_psd

   !> Check every parameter; the message names the variable, its value and the rule.
   pure subroutine check_synthetic(cfg, dt, error)
      !> Parameters.
      type(synthetic_config), intent(in) :: cfg
      !> Sample step dt (s).
      real(dp), intent(in) :: dt
      !> Set for the first parameter that breaks its rule.
      type(error_type), allocatable, intent(out) :: error

      if (.not. (dt > 0.0_dp .and. ieee_is_finite(dt))) then
         call fatal_error(error, 'dt = '//str(dt)//', must be > 0')
      else if (cfg%filter /= 'kanai_tajimi' .and. cfg%filter /= 'clough_penzien') then
         call fatal_error(error, 'filter = '''//trim(cfg%filter)// &
                          ''', must be ''kanai_tajimi'' or ''clough_penzien''')
      else if (cfg%envelope /= 'jennings' .and. cfg%envelope /= 'saragoni_hart') then
         call fatal_error(error, 'envelope = '''//trim(cfg%envelope)// &
                          ''', must be ''jennings'' or ''saragoni_hart''')
      else if (.not. positive(cfg%duration) .or. cfg%duration < 10.0_dp*dt) then
         call fatal_error(error, 'duration = '//str(cfg%duration)//' s, must be >= 10 dt = '// &
                          str(10.0_dp*dt)//' s')
      else if (.not. positive(cfg%pga)) then
         call fatal_error(error, 'pga = '//str(cfg%pga)//' m/s^2, must be > 0')
      else if (.not. positive(cfg%wg)) then
         call fatal_error(error, 'wg = '//str(cfg%wg)//' rad/s, must be > 0')
      else if (.not. ratio(cfg%zg)) then
         call fatal_error(error, 'zg = '//str(cfg%zg)//', must be > 0 and < 1')
      end if
      if (allocated(error)) return
      if (cfg%filter == 'clough_penzien') then
         if (.not. positive(cfg%wf)) then
            call fatal_error(error, 'wf = '//str(cfg%wf)//' rad/s, must be > 0')
         else if (.not. ratio(cfg%zf)) then
            call fatal_error(error, 'zf = '//str(cfg%zf)//', must be > 0 and < 1')
         end if
      end if
      if (allocated(error)) return
      if (cfg%envelope == 'jennings') then
         if (.not. positive(cfg%t1)) then
            call fatal_error(error, 't1 = '//str(cfg%t1)//' s, must be > 0')
         else if (.not. (cfg%t2 >= cfg%t1 .and. cfg%t2 <= cfg%duration)) then
            call fatal_error(error, 't2 = '//str(cfg%t2)//' s, must be >= t1 = '//str(cfg%t1)// &
                             ' s and <= duration = '//str(cfg%duration)//' s')
         else if (.not. positive(cfg%c)) then
            call fatal_error(error, 'c = '//str(cfg%c)//' 1/s, must be > 0')
         end if
      else
         if (.not. ratio(cfg%eps)) then
            call fatal_error(error, 'eps = '//str(cfg%eps)//', must be > 0 and < 1')
         else if (.not. ratio(cfg%eta)) then
            call fatal_error(error, 'eta = '//str(cfg%eta)//', must be > 0 and < 1')
         end if
      end if
   end subroutine check_synthetic

   !> x is finite and > 0.
   elemental logical function positive(x)
      real(dp), intent(in) :: x

      positive = x > 0.0_dp .and. ieee_is_finite(x)
   end function positive

   !> 0 < x < 1.
   elemental logical function ratio(x)
      real(dp), intent(in) :: x

      ratio = x > 0.0_dp .and. x < 1.0_dp
   end function ratio

end module pound_synthetic_motion
