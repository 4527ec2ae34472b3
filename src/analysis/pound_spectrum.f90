!> Response spectra of sampled ground accelerations, the period grid, PGA and scale factors.
!>
!> The ground acceleration a_g (m/s^2) is given at t_i = (i-1) dt and is linear between samples
!> (as the solver sees it); after the last sample the ground is at rest. The oscillator of
!> period T (s) and damping ratio zeta, u'' + 2 zeta omega u' + omega^2 u = -a_g, omega =
!> 2 pi/T, starts at rest and is advanced by the exact recurrence for piecewise-linear
!> excitation (Nigam-Jennings, `pound_sdof`), so its state is exact at every (sub)step. The
!> peak between states is taken from the cubic Hermite interpolant of (u, u') on the steps
!> where u' changes sign; the step is dt divided into enough substeps for at least
!> `points_per_period` per period, so the interpolated peak is within (2 pi/32)^4/384 =
!> 4e-6 of the exact one. The free vibration after the last sample is followed up to its
!> first extremum (the later ones are smaller). The pseudo-acceleration is
!> Sa(T) = omega^2 max_t |u(t)| (m/s^2).
module pound_spectrum
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_constants, only: two_pi
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_sdof, only: sdof_step_t, sdof_step, sdof_advance
   use pound_sort, only: sort_ascending
   implicit none
   private

   public :: response_spectrum, pseudo_acceleration, period_grid, peak_ground_acceleration
   public :: scale_to_pga, scale_to_sa
   public :: default_t_min, default_t_max, points_per_period

   !> Shortest and longest period of the default grid (s).
   real(dp), parameter :: default_t_min = 0.02_dp, default_t_max = 4.0_dp
   !> Fewest (sub)steps per oscillator period.
   integer, parameter :: points_per_period = 32
   !> Periods closer than this relative distance count as the same period in `period_grid`.
   real(dp), parameter :: same_period = 1.0e-9_dp
   !> Oscillators advanced together by `peak_displacements` (two AVX2 vectors of doubles).
   integer, parameter :: lanes = 8

contains

   !> Pseudo-acceleration spectrum Sa(T_k) = omega_k^2 max_t |u_k(t)| (m/s^2) of `accel`
   !> at the given periods, for the damping ratio zeta (0.05 for the usual 5 % spectrum).
   pure subroutine response_spectrum(accel, dt, periods, zeta, sa, error)
      !> Ground acceleration at t_i = (i-1) dt (m/s^2).
      real(dp), intent(in) :: accel(:)
      !> Sample step dt (s), > 0.
      real(dp), intent(in) :: dt
      !> Oscillator periods (s), > 0.
      real(dp), intent(in) :: periods(:)
      !> Damping ratio, 0 <= zeta < 1.
      real(dp), intent(in) :: zeta
      !> Sa at each period (m/s^2).
      real(dp), allocatable, intent(out) :: sa(:)
      !> Set for invalid arguments.
      type(error_type), allocatable, intent(out) :: error
      integer :: k

      call check_motion(accel, dt, error)
      if (allocated(error)) return
      call check_damping(zeta, error)
      if (allocated(error)) return
      do k = 1, size(periods)
         call check_period(periods(k), 'period('//str(k)//')', error)
         if (allocated(error)) return
      end do
      allocate (sa(size(periods)))
      call peak_displacements(accel, dt, periods, zeta, sa)
      do k = 1, size(periods)
         sa(k) = (two_pi/periods(k))**2*sa(k)
      end do
   end subroutine response_spectrum

   !> Sa(T) (m/s^2) at one period: `response_spectrum` for a single period.
   pure subroutine pseudo_acceleration(accel, dt, period, zeta, sa, error)
      !> Ground acceleration at t_i = (i-1) dt (m/s^2).
      real(dp), intent(in) :: accel(:)
      !> Sample step dt (s), > 0.
      real(dp), intent(in) :: dt
      !> Oscillator period T (s), > 0.
      real(dp), intent(in) :: period
      !> Damping ratio, 0 <= zeta < 1.
      real(dp), intent(in) :: zeta
      !> Sa(T) (m/s^2).
      real(dp), intent(out) :: sa
      !> Set for invalid arguments.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: s(:)

      sa = 0.0_dp
      call response_spectrum(accel, dt, [period], zeta, s, error)
      if (allocated(error)) return
      sa = s(1)
   end subroutine pseudo_acceleration

   !> Peak ground acceleration max_i |a_i| (m/s^2); the peak of the piecewise-linear motion.
   pure function peak_ground_acceleration(accel) result(pga)
      !> Ground acceleration samples (m/s^2).
      real(dp), intent(in) :: accel(:)
      real(dp) :: pga

      pga = 0.0_dp
      if (size(accel) > 0) pga = maxval(abs(accel))
   end function peak_ground_acceleration

   !> Scale factor f = target/PGA that gives the motion the peak ground acceleration `target`.
   pure subroutine scale_to_pga(accel, target, factor, error)
      !> Ground acceleration samples (m/s^2).
      real(dp), intent(in) :: accel(:)
      !> Target PGA (m/s^2), > 0.
      real(dp), intent(in) :: target
      !> Scale factor.
      real(dp), intent(out) :: factor
      !> Set for a non-positive target or a motion that is zero everywhere.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: pga

      factor = 0.0_dp
      call check_target(target, 'target PGA', error)
      if (allocated(error)) return
      pga = peak_ground_acceleration(accel)
      if (.not. (pga > 0.0_dp .and. ieee_is_finite(pga))) then
         call fatal_error(error, 'scale to PGA: the motion''s PGA is '//str(pga)// &
                          ', must be finite and > 0')
         return
      end if
      factor = target/pga
   end subroutine scale_to_pga

   !> Scale factor f = target/Sa(T) that gives the motion the pseudo-acceleration `target` at
   !> period T and damping ratio zeta (Sa is linear in the motion).
   pure subroutine scale_to_sa(accel, dt, period, zeta, target, factor, error)
      !> Ground acceleration at t_i = (i-1) dt (m/s^2).
      real(dp), intent(in) :: accel(:)
      !> Sample step dt (s), > 0.
      real(dp), intent(in) :: dt
      !> Period T (s), > 0.
      real(dp), intent(in) :: period
      !> Damping ratio, 0 <= zeta < 1.
      real(dp), intent(in) :: zeta
      !> Target Sa(T) (m/s^2), > 0.
      real(dp), intent(in) :: target
      !> Scale factor.
      real(dp), intent(out) :: factor
      !> Set for invalid arguments or Sa(T) = 0.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: sa

      factor = 0.0_dp
      call check_target(target, 'target Sa', error)
      if (allocated(error)) return
      call pseudo_acceleration(accel, dt, period, zeta, sa, error)
      if (allocated(error)) return
      if (.not. (sa > 0.0_dp .and. ieee_is_finite(sa))) then
         call fatal_error(error, 'scale to Sa: Sa('//str(period)//' s) of the motion is '// &
                          str(sa)//', must be finite and > 0')
         return
      end if
      factor = target/sa
   end subroutine scale_to_sa

   !> Period grid: n periods log-spaced from t_min to t_max (both included exactly; defaults
   !> 0.02 s and 4 s), merged with the `extra` periods (e.g. the buildings' periods), sorted
   !> ascending; periods within 1e-9 relative of the previous one are dropped.
   pure subroutine period_grid(n, extra, periods, error, t_min, t_max)
      !> Number of log-spaced periods, >= 2.
      integer, intent(in) :: n
      !> Further periods (s), > 0; may be empty.
      real(dp), intent(in) :: extra(:)
      !> The grid (s), ascending.
      real(dp), allocatable, intent(out) :: periods(:)
      !> Set for invalid arguments.
      type(error_type), allocatable, intent(out) :: error
      !> Shortest log-spaced period (s); default 0.02.
      real(dp), intent(in), optional :: t_min
      !> Longest log-spaced period (s), > t_min; default 4.
      real(dp), intent(in), optional :: t_max
      real(dp) :: lo, hi, all(n + size(extra))
      integer :: k, m

      lo = default_t_min
      hi = default_t_max
      if (present(t_min)) lo = t_min
      if (present(t_max)) hi = t_max
      if (n < 2) then
         call fatal_error(error, 'period grid: n = '//str(n)//', must be >= 2')
         return
      end if
      call check_period(lo, 't_min', error)
      if (allocated(error)) return
      call check_period(hi, 't_max', error)
      if (allocated(error)) return
      if (.not. hi > lo) then
         call fatal_error(error, 'period grid: t_max = '//str(hi)//', must be > t_min = '//str(lo))
         return
      end if
      do k = 1, size(extra)
         call check_period(extra(k), 'extra period('//str(k)//')', error)
         if (allocated(error)) return
      end do
      do k = 1, n
         all(k) = lo*(hi/lo)**(real(k - 1, dp)/real(n - 1, dp))
      end do
      all(n) = hi
      all(n + 1:) = extra
      call sort_ascending(all)
      m = 1
      do k = 2, size(all)
         if (all(k) - all(m) > same_period*all(k)) then
            m = m + 1
            all(m) = all(k)
         end if
      end do
      periods = all(1:m)
   end subroutine period_grid

   !> max_t |u(t)| (m) of the oscillators (T_k, zeta) under -accel, from rest, for every
   !> period T_k of `periods`.
   !>
   !> Consecutive periods with the same number of substeps per sample advance together, up to
   !> `lanes` at a time: the oscillators are independent, so the lanes' recurrences overlap and
   !> vectorise. Each lane performs the operations of one oscillator alone (`sdof_advance`,
   !> then `step_peak` on the steps where its velocity changes sign), so the peaks do not depend
   !> on the grouping.
   pure subroutine peak_displacements(accel, dt, periods, zeta, umax)
      real(dp), intent(in) :: accel(:), dt, periods(:), zeta
      real(dp), intent(out) :: umax(:)
      integer :: k0, k1, m

      k0 = 1
      do while (k0 <= size(periods))
         m = substeps(periods(k0))
         k1 = k0
         do while (k1 < size(periods) .and. k1 - k0 + 1 < lanes)
            if (substeps(periods(k1 + 1)) /= m) exit
            k1 = k1 + 1
         end do
         call peak_group(accel, dt, m, periods(k0:k1), zeta, umax(k0:k1))
         k0 = k1 + 1
      end do

   contains

      pure integer function substeps(period)
         real(dp), intent(in) :: period

         substeps = max(1, ceiling(points_per_period*dt/period))
      end function substeps

   end subroutine peak_displacements

   !> The peaks of up to `lanes` oscillators with the same substep count m (h = dt/m); lanes
   !> beyond size(periods) repeat the first period and are dropped.
   pure subroutine peak_group(accel, dt, m, periods, zeta, umax)
      real(dp), intent(in) :: accel(:), dt
      integer, intent(in) :: m
      real(dp), intent(in) :: periods(:), zeta
      real(dp), intent(out) :: umax(:)
      type(sdof_step_t) :: step(lanes)
      real(dp), dimension(lanes) :: a11, a12, a21, a22, b11, b12, b21, b22, u, v, u0, v0, pk, cross
      real(dp) :: h, p0, p1, pa, pb
      integer :: i, j, l, n_tail

      h = dt/m
      do l = 1, lanes
         step(l) = sdof_step(two_pi/periods(min(l, size(periods))), zeta, h)
      end do
      a11 = step%a(1, 1)
      a12 = step%a(1, 2)
      a21 = step%a(2, 1)
      a22 = step%a(2, 2)
      b11 = step%b(1, 1)
      b12 = step%b(1, 2)
      b21 = step%b(2, 1)
      b22 = step%b(2, 2)
      u = 0.0_dp
      v = 0.0_dp
      pk = 0.0_dp
      do i = 1, size(accel) - 1
         p0 = -accel(i)
         p1 = -accel(i + 1)
         pb = p0
         do j = 1, m
            pa = pb
            pb = p0 + (p1 - p0)*(real(j, dp)/m)
            ! `sdof_advance` of every lane; |u| at the step's end, and whether v changed sign.
            do l = 1, lanes
               u0(l) = u(l)
               v0(l) = v(l)
               u(l) = a11(l)*u0(l) + a12(l)*v0(l) + b11(l)*pa + b12(l)*pb
               v(l) = a21(l)*u0(l) + a22(l)*v0(l) + b21(l)*pa + b22(l)*pb
               pk(l) = max(pk(l), abs(u(l)))
               cross(l) = v0(l)*v(l)
            end do
            ! The interpolated extremum within the step, where v changed sign (`step_peak`).
            if (any(cross < 0.0_dp)) then
               do l = 1, lanes
                  if (cross(l) < 0.0_dp) pk(l) = max(pk(l), step_peak(u0(l), v0(l), u(l), v(l), h))
               end do
            end if
         end do
      end do
      ! Free vibration after the last sample, up to its first extremum.
      do l = 1, size(periods)
         n_tail = ceiling(0.5_dp*periods(l)/sqrt(1.0_dp - zeta**2)/h) + 1
         do j = 1, n_tail
            u0(l) = u(l)
            v0(l) = v(l)
            call sdof_advance(step(l), 0.0_dp, 0.0_dp, u(l), v(l))
            pk(l) = max(pk(l), step_peak(u0(l), v0(l), u(l), v(l), h))
         end do
         umax(l) = pk(l)
      end do
   end subroutine peak_group

   !> Largest |u| over a step from (u0, v0) to (u1, v1) of length h: |u1|, or, when the
   !> velocity changes sign, the extremum of the cubic Hermite interpolant of (u, u').
   pure function step_peak(u0, v0, u1, v1, h) result(peak)
      real(dp), intent(in) :: u0, v0, u1, v1, h
      real(dp) :: peak
      real(dp) :: c2, c3, a, b, c, disc, q, s

      peak = abs(u1)
      if (.not. (v0*v1 < 0.0_dp)) return
      ! H(s) = u0 + h v0 s + c2 s^2 + c3 s^3 on s in [0, 1]; H'(s) = a s^2 + b s + c has
      ! exactly one root in (0, 1) because H'(0) H'(1) < 0.
      c2 = 3.0_dp*(u1 - u0) - h*(2.0_dp*v0 + v1)
      c3 = -2.0_dp*(u1 - u0) + h*(v0 + v1)
      a = 3.0_dp*c3
      b = 2.0_dp*c2
      c = h*v0
      disc = sqrt(max(b*b - 4.0_dp*a*c, 0.0_dp))
      q = -0.5_dp*(b + sign(disc, b))
      s = -1.0_dp
      if (q /= 0.0_dp) s = c/q
      if (.not. (s > 0.0_dp .and. s < 1.0_dp) .and. a /= 0.0_dp) s = q/a
      if (s > 0.0_dp .and. s < 1.0_dp) peak = max(peak, abs(u0 + s*(h*v0 + s*(c2 + s*c3))))
   end function step_peak

   pure subroutine check_motion(accel, dt, error)
      real(dp), intent(in) :: accel(:), dt
      type(error_type), allocatable, intent(out) :: error

      if (.not. (dt > 0.0_dp .and. ieee_is_finite(dt))) then
         call fatal_error(error, 'response spectrum: dt = '//str(dt)//', must be > 0')
      else if (size(accel) < 2) then
         call fatal_error(error, 'response spectrum: '//str(size(accel))// &
                          ' acceleration samples, must be >= 2')
      else if (.not. all(ieee_is_finite(accel))) then
         call fatal_error(error, 'response spectrum: acceleration sample '// &
                          str(findloc(ieee_is_finite(accel), .false., dim=1))//' is not finite')
      end if
   end subroutine check_motion

   pure subroutine check_damping(zeta, error)
      real(dp), intent(in) :: zeta
      type(error_type), allocatable, intent(out) :: error

      if (.not. (zeta >= 0.0_dp .and. zeta < 1.0_dp)) then
         call fatal_error(error, 'response spectrum: damping ratio = '//str(zeta)// &
                          ', must be >= 0 and < 1')
      end if
   end subroutine check_damping

   pure subroutine check_period(t, name, error)
      real(dp), intent(in) :: t
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error

      if (.not. (t > 0.0_dp .and. ieee_is_finite(t))) then
         call fatal_error(error, 'response spectrum: '//name//' = '//str(t)//' s, must be > 0')
      end if
   end subroutine check_period

   pure subroutine check_target(target, name, error)
      real(dp), intent(in) :: target
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error

      if (.not. (target > 0.0_dp .and. ieee_is_finite(target))) then
         call fatal_error(error, 'scaling: '//name//' = '//str(target)//' m/s^2, must be > 0')
      end if
   end subroutine check_target

end module pound_spectrum
