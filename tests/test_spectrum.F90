!> Response spectra: the exact step against Nigam-Jennings' closed forms, closed-form SDOF
!> responses (step load, resonance, no damping), an independent fine Newmark integration,
!> the rigid limit, scaling to targets, the period grid and invalid arguments.
module test_spectrum
   use funit
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_random, only: random_t, random_seed_stream, random_normal
   use pound_sdof, only: sdof_step_t, sdof_step
   use pound_spectrum, only: response_spectrum, pseudo_acceleration, period_grid, &
                             peak_ground_acceleration, scale_to_pga, scale_to_sa
   implicit none

   real(dp), parameter :: pi = acos(-1.0_dp)

contains

   !@test
   subroutine test_step_matches_nigam_jennings()
      ! Chopra, Dynamics of Structures, Table 5.2.1 (m = 1, k = omega^2), where the closed
      ! forms are well conditioned (omega h from 0.06 to 3).
      real(dp), parameter :: cases(3, 5) = reshape([1.0_dp, 0.05_dp, 0.01_dp, &
         0.3_dp, 0.02_dp, 0.1_dp, 2.0_dp, 0.0_dp, 0.05_dp, 0.5_dp, 0.6_dp, 0.02_dp, &
         0.05_dp, 0.2_dp, 0.02_dp], [3, 5])
      type(sdof_step_t) :: st
      real(dp) :: w, z, h, wd, ex, sn, cs, r, k, nj(2, 4), got(2, 4)
      integer :: c

      do c = 1, size(cases, 2)
         w = 2.0_dp*pi/cases(1, c)
         z = cases(2, c)
         h = cases(3, c)
         wd = w*sqrt(1.0_dp - z*z)
         ex = exp(-z*w*h)
         sn = sin(wd*h)
         cs = cos(wd*h)
         r = z/sqrt(1.0_dp - z*z)
         k = w*w
         nj(1, 1) = ex*(r*sn + cs)
         nj(1, 2) = ex*sn/wd
         nj(1, 3) = (2*z/(w*h) + ex*(((1 - 2*z*z)/(wd*h) - r)*sn &
                     - (1 + 2*z/(w*h))*cs))/k
         nj(1, 4) = (1 - 2*z/(w*h) + ex*((2*z*z - 1)/(wd*h)*sn + 2*z/(w*h)*cs))/k
         nj(2, 1) = -ex*w/sqrt(1.0_dp - z*z)*sn
         nj(2, 2) = ex*(cs - r*sn)
         nj(2, 3) = (-1/h + ex*((w/sqrt(1 - z*z) + r/h)*sn + cs/h))/k
         nj(2, 4) = (1 - ex*(r*sn + cs))/(k*h)
         st = sdof_step(w, z, h)
         got(:, 1:2) = st%a
         got(:, 3:4) = st%b
#line 52 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertEqual(nj, got, tolerance=1.0e-12_dp*maxval(abs(nj)), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 52) )
  if (anyExceptions()) return
#line 53 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 53 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(nj(1, 3), got(1, 3), tolerance=1.0e-11_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 53) )
  if (anyExceptions()) return
#line 54 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 54 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(nj(1, 4), got(1, 4), tolerance=1.0e-11_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 54) )
  if (anyExceptions()) return
#line 55 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      end do
   end subroutine test_step_matches_nigam_jennings

   !@test
   subroutine test_step_small_omega_h()
      ! omega h = 6e-6, where the closed forms lose 10 digits. Undamped, a load going
      ! linearly from p0 to p1 over h moves a body at rest by h^2 (2 p0 + p1)/6 and gives it
      ! h (p0 + p1)/2, to relative order (omega h)^2 = 4e-11; with 5 % damping to order
      ! 2 zeta omega h = 6e-7.
      type(sdof_step_t) :: st
      real(dp), parameter :: h = 1.0e-4_dp
      real(dp) :: w, tol

      w = 2.0_dp*pi/100.0_dp
      tol = 1.0e-10_dp
      st = sdof_step(w, 0.0_dp, h)
#line 71 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(h*h/3.0_dp, st%b(1, 1), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 71) )
  if (anyExceptions()) return
#line 72 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 72 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(h*h/6.0_dp, st%b(1, 2), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 72) )
  if (anyExceptions()) return
#line 73 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 73 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(h/2.0_dp, st%b(2, 1), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 73) )
  if (anyExceptions()) return
#line 74 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 74 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(h/2.0_dp, st%b(2, 2), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 74) )
  if (anyExceptions()) return
#line 75 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      tol = 1.0e-6_dp
      st = sdof_step(w, 0.05_dp, h)
#line 77 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(h*h/3.0_dp, st%b(1, 1), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 77) )
  if (anyExceptions()) return
#line 78 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 78 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(h*h/6.0_dp, st%b(1, 2), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 78) )
  if (anyExceptions()) return
#line 79 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_step_small_omega_h

   !@test
   subroutine test_step_load()
      ! A constant ground acceleration a0 from t = 0: u = -(a0/w^2)(1 - e^(-z w t)(cos wd t +
      ! z/sqrt(1-z^2) sin wd t)), peak at t = pi/wd: Sa = a0 (1 + exp(-pi z/sqrt(1-z^2))).
      ! Zero damping: Sa = 2 a0, the peak falls on a step (exact). 5 %: between steps, the
      ! cubic Hermite peak is within (omega h)^4/768 = 2e-8 (T = 1 s), 1e-6 (T = 0.37 s).
      real(dp), parameter :: a0 = 1.7_dp, dt = 0.01_dp
      real(dp) :: accel(1001), expected
      real(dp), allocatable :: sa(:)
      type(error_type), allocatable :: error

      accel = a0
      call response_spectrum(accel, dt, [1.0_dp], 0.0_dp, sa, error)
#line 94 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 94) )
  if (anyExceptions()) return
#line 95 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 95 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(2.0_dp*a0, sa(1), tolerance=1.0e-12_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 95) )
  if (anyExceptions()) return
#line 96 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      call response_spectrum(accel, dt, [1.0_dp, 0.37_dp], 0.05_dp, sa, error)
#line 97 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 97) )
  if (anyExceptions()) return
#line 98 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      expected = a0*(1.0_dp + exp(-pi*0.05_dp/sqrt(1.0_dp - 0.05_dp**2)))
#line 99 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(expected, sa(1), tolerance=3.0e-8_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 99) )
  if (anyExceptions()) return
#line 100 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 100 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(expected, sa(2), tolerance=1.5e-6_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 100) )
  if (anyExceptions()) return
#line 101 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_step_load

   !@test
   subroutine test_step_load_short_period_substeps()
      ! T = 0.02 s with dt = 0.01 s: two samples per period, substeps recover the peak.
      real(dp), parameter :: a0 = -0.4_dp, dt = 0.01_dp
      real(dp) :: accel(201), expected
      real(dp), allocatable :: sa(:)
      type(error_type), allocatable :: error

      accel = a0
      call response_spectrum(accel, dt, [0.02_dp, 0.013_dp], 0.05_dp, sa, error)
#line 113 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 113) )
  if (anyExceptions()) return
#line 114 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      expected = abs(a0)*(1.0_dp + exp(-pi*0.05_dp/sqrt(1.0_dp - 0.05_dp**2)))
#line 115 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(expected, sa(1), tolerance=1.0e-5_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 115) )
  if (anyExceptions()) return
#line 116 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 116 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(expected, sa(2), tolerance=1.0e-5_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 116) )
  if (anyExceptions()) return
#line 117 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_step_load_short_period_substeps

   !@test
   subroutine test_harmonic_resonance()
      ! a_g = a0 sin(w t) at the oscillator's own frequency, 5 %: the steady state amplitude
      ! is a0/(2 z w^2), Sa = a0/(2 z). The linear interpolation between samples scales the
      ! harmonic at w by sinc^2(w dt/2); the transient has decayed to exp(-z w 60) = 7e-9.
      real(dp), parameter :: a0 = 2.0_dp, dt = 0.001_dp, z = 0.05_dp
      real(dp), allocatable :: accel(:), sa(:)
      type(error_type), allocatable :: error
      real(dp) :: w, x, expected
      integer :: i

      w = 2.0_dp*pi
      allocate (accel(60001))
      accel = [(a0*sin(w*dt*(i - 1)), i=1, size(accel))]
      call response_spectrum(accel, dt, [1.0_dp], z, sa, error)
#line 134 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 134) )
  if (anyExceptions()) return
#line 135 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      x = 0.5_dp*w*dt
      expected = a0/(2.0_dp*z)*(sin(x)/x)**2
#line 137 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(expected, sa(1), tolerance=1.0e-6_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 137) )
  if (anyExceptions()) return
#line 138 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_harmonic_resonance

   !@test
   subroutine test_undamped_resonance_grows()
      ! Zero damping at resonance: u = a0/(2 w^2) (w t cos w t - sin w t); over 5 whole
      ! periods the peak is a0 5 pi / w^2 (t = 5 T), Sa = 5 pi a0, up to the interpolation.
      real(dp), parameter :: a0 = 1.0_dp, dt = 0.001_dp
      real(dp), allocatable :: accel(:), sa(:)
      type(error_type), allocatable :: error
      real(dp) :: w, x, sa_end
      integer :: i

      w = 2.0_dp*pi
      allocate (accel(5001))
      accel = [(a0*sin(w*dt*(i - 1)), i=1, size(accel))]
      call response_spectrum(accel, dt, [1.0_dp], 0.0_dp, sa, error)
#line 154 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 154) )
  if (anyExceptions()) return
#line 155 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      x = 0.5_dp*w*dt
      sa_end = 5.0_dp*pi*a0*(sin(x)/x)**2
#line 157 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(sa_end, sa(1), tolerance=1.0e-4_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 157) )
  if (anyExceptions()) return
#line 158 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_undamped_resonance_grows

   !@test
   subroutine test_against_fine_newmark()
      ! Independent integration: Newmark's average acceleration with 200 steps per sample
      ! on a random piecewise-linear motion (period error (w h)^2/12 < 1e-6).
      real(dp), parameter :: dt = 0.01_dp, periods(3) = [0.1_dp, 0.5_dp, 2.0_dp]
      real(dp), parameter :: zetas(2) = [0.05_dp, 0.0_dp]
      real(dp) :: accel(501), ref
      real(dp), allocatable :: sa(:)
      type(random_t) :: rng
      type(error_type), allocatable :: error
      integer :: iz, k

      call random_seed_stream(rng, 31_int64)
      call random_normal(rng, accel)
      accel(1) = 0.0_dp
      accel(size(accel)) = 0.0_dp
      do iz = 1, 2
         call response_spectrum(accel, dt, periods, zetas(iz), sa, error)
#line 178 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 178) )
  if (anyExceptions()) return
#line 179 "/work/wt/suite-blocks/tests/test_spectrum.pf"
         do k = 1, 3
            ref = newmark_sa(accel, dt, periods(k), zetas(iz), 200)
#line 181 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(ref, sa(k), tolerance=1.0e-4_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 181) )
  if (anyExceptions()) return
#line 182 "/work/wt/suite-blocks/tests/test_spectrum.pf"
         end do
      end do
   end subroutine test_against_fine_newmark

   !@test
   subroutine test_rigid_limit_is_pga()
      ! Sa -> PGA as T -> 0 for a smooth motion that starts at rest.
      real(dp), parameter :: dt = 0.005_dp
      real(dp) :: accel(801), pga
      real(dp), allocatable :: sa(:)
      type(error_type), allocatable :: error
      integer :: i
      real(dp) :: t

      do i = 1, size(accel)
         t = dt*(i - 1)
         accel(i) = sin(pi*t/4.0_dp)**2*(sin(3.0_dp*t) + 0.5_dp*sin(7.1_dp*t))
      end do
      pga = peak_ground_acceleration(accel)
      call response_spectrum(accel, dt, [0.01_dp, 0.002_dp], 0.05_dp, sa, error)
#line 202 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 202) )
  if (anyExceptions()) return
#line 203 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 203 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(pga, sa(1), tolerance=2.0e-3_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 203) )
  if (anyExceptions()) return
#line 204 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 204 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(pga, sa(2), tolerance=3.0e-4_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 204) )
  if (anyExceptions()) return
#line 205 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_rigid_limit_is_pga

   !@test
   subroutine test_scaling_meets_target()
      ! Scaled to a PGA and to Sa(T): the scaled motion meets its target to 1e-10.
      real(dp), parameter :: dt = 0.01_dp, target = 3.3_dp
      real(dp) :: accel(1001), f, sa
      type(random_t) :: rng
      type(error_type), allocatable :: error

      call random_seed_stream(rng, 5_int64)
      call random_normal(rng, accel)
      call scale_to_pga(accel, target, f, error)
#line 218 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 218) )
  if (anyExceptions()) return
#line 219 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      sa = peak_ground_acceleration(f*accel)
#line 220 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(target, sa, tolerance=1.0e-10_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 220) )
  if (anyExceptions()) return
#line 221 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      call scale_to_sa(accel, dt, 0.7_dp, 0.05_dp, target, f, error)
#line 222 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 222) )
  if (anyExceptions()) return
#line 223 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      call pseudo_acceleration(f*accel, dt, 0.7_dp, 0.05_dp, sa, error)
#line 224 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 224) )
  if (anyExceptions()) return
#line 225 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 225 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(target, sa, tolerance=1.0e-10_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 225) )
  if (anyExceptions()) return
#line 226 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 226 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertGreaterThan(abs(f - 1.0_dp), 0.01_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 226) )
  if (anyExceptions()) return
#line 227 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_scaling_meets_target

   !@test
   subroutine test_period_grid()
      ! 5 periods log-spaced 0.02..4 s (ratio 200^(1/4)), merged with building periods;
      ! repeats and a period within 1e-12 of a grid point are dropped.
      real(dp), allocatable :: t(:)
      type(error_type), allocatable :: error
      real(dp) :: r, extra(4)

      extra = [0.5_dp, 4.0_dp, 0.5_dp, 0.02_dp*(1.0_dp + 1.0e-12_dp)]
      call period_grid(5, extra, t, error)
#line 239 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 239) )
  if (anyExceptions()) return
#line 240 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 240 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertEqual(6, size(t), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 240) )
  if (anyExceptions()) return
#line 241 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      r = 200.0_dp**0.25_dp
#line 242 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertEqual(0.02_dp, t(1), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 242) )
  if (anyExceptions()) return
#line 243 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 243 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(0.02_dp*r, t(2), tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 243) )
  if (anyExceptions()) return
#line 244 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 244 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(0.02_dp*r*r, t(3), tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 244) )
  if (anyExceptions()) return
#line 245 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 245 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertEqual(0.5_dp, t(4), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 245) )
  if (anyExceptions()) return
#line 246 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 246 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertRelativelyEqual(0.02_dp*r**3, t(5), tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 246) )
  if (anyExceptions()) return
#line 247 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 247 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertEqual(4.0_dp, t(6), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 247) )
  if (anyExceptions()) return
#line 248 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      call period_grid(3, [real(dp) ::], t, error, t_min=0.1_dp, t_max=10.0_dp)
#line 249 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 249) )
  if (anyExceptions()) return
#line 250 "/work/wt/suite-blocks/tests/test_spectrum.pf"
#line 250 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertEqual([0.1_dp, 1.0_dp, 10.0_dp], t, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 250) )
  if (anyExceptions()) return
#line 251 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine test_period_grid

   !@test
   subroutine test_invalid_arguments()
      real(dp) :: accel(10), f, sa1
      real(dp), allocatable :: sa(:), t(:)
      type(error_type), allocatable :: error

      accel = 1.0_dp
      call response_spectrum(accel, 0.01_dp, [0.5_dp, -1.0_dp], 0.05_dp, sa, error)
      call expect_error(error, 'period(2) = -1')
      call response_spectrum(accel, 0.01_dp, [0.5_dp], 1.0_dp, sa, error)
      call expect_error(error, 'damping ratio = 1')
      call response_spectrum(accel, 0.0_dp, [0.5_dp], 0.05_dp, sa, error)
      call expect_error(error, 'dt = 0')
      call response_spectrum(accel(1:1), 0.01_dp, [0.5_dp], 0.05_dp, sa, error)
      call expect_error(error, 'must be >= 2')
      call period_grid(1, [real(dp) ::], t, error)
      call expect_error(error, 'n = 1, must be >= 2')
      call period_grid(5, [0.0_dp], t, error)
      call expect_error(error, 'extra period(1) = 0')
      call scale_to_pga(accel, -1.0_dp, f, error)
      call expect_error(error, 'target PGA = -1')
      call scale_to_pga(0.0_dp*accel, 1.0_dp, f, error)
      call expect_error(error, 'PGA is 0')
      call scale_to_sa(accel, 0.01_dp, -0.5_dp, 0.05_dp, 1.0_dp, f, error)
      call expect_error(error, 'period(1) = -0.5')
      call pseudo_acceleration(accel, 0.01_dp, 0.5_dp, -0.1_dp, sa1, error)
      call expect_error(error, 'damping ratio = -0.1')
   end subroutine test_invalid_arguments

   !> The error is set and its message contains `text`.
   subroutine expect_error(error, text)
      type(error_type), allocatable, intent(in) :: error
      character(len=*), intent(in) :: text

#line 287 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertTrue(allocated(error), message=text, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 287) )
  if (anyExceptions()) return
#line 288 "/work/wt/suite-blocks/tests/test_spectrum.pf"
      if (.not. allocated(error)) return
#line 289 "/work/wt/suite-blocks/tests/test_spectrum.pf"
  call assertTrue(index(error%message, text) > 0, message=error%message, &
 & location=SourceLocation( &
 & 'test_spectrum.pf', &
 & 289) )
  if (anyExceptions()) return
#line 290 "/work/wt/suite-blocks/tests/test_spectrum.pf"
   end subroutine expect_error

   !> Sa by Newmark's average acceleration (incremental form, Chopra Table 5.4.2) with `sub`
   !> steps per sample, followed by one period of free vibration (independent of pound_sdof).
   function newmark_sa(accel, dt, period, zeta, sub) result(sa)
      real(dp), intent(in) :: accel(:), dt, period, zeta
      integer, intent(in) :: sub
      real(dp) :: sa
      real(dp) :: w, c, h, u, v, a, kh, du, dv, da, dload, umax
      integer :: i, j

      w = 2.0_dp*pi/period
      c = 2.0_dp*zeta*w
      h = dt/sub
      kh = w*w + 2.0_dp/h*c + 4.0_dp/h**2
      u = 0.0_dp
      v = 0.0_dp
      a = -accel(1)
      umax = 0.0_dp
      do i = 1, size(accel) - 1 + ceiling(period/dt)
         dload = -(ground(i + 1) - ground(i))/sub
         do j = 1, sub
            du = (dload + (4.0_dp/h + 2.0_dp*c)*v + 2.0_dp*a)/kh
            dv = 2.0_dp/h*du - 2.0_dp*v
            da = 4.0_dp/h**2*du - 4.0_dp/h*v - 2.0_dp*a
            u = u + du
            v = v + dv
            a = a + da
            umax = max(umax, abs(u))
         end do
      end do
      sa = w*w*umax
   contains
      real(dp) function ground(k)
         integer, intent(in) :: k

         ground = 0.0_dp
         if (k <= size(accel)) ground = accel(k)
      end function ground
   end function newmark_sa

end module test_spectrum

module Wraptest_spectrum
   use FUnit
   use test_spectrum
   implicit none
   private

contains


end module Wraptest_spectrum

function test_spectrum_suite() result(suite)
   use FUnit
   use test_spectrum
   use Wraptest_spectrum
   implicit none
   type (TestSuite) :: suite

   class (Test), allocatable :: t

   suite = TestSuite('test_spectrum_suite')

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_step_matches_nigam_jennings', &
      test_step_matches_nigam_jennings))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_step_small_omega_h', &
      test_step_small_omega_h))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_step_load', &
      test_step_load))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_step_load_short_period_substeps', &
      test_step_load_short_period_substeps))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_harmonic_resonance', &
      test_harmonic_resonance))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_undamped_resonance_grows', &
      test_undamped_resonance_grows))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_against_fine_newmark', &
      test_against_fine_newmark))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_rigid_limit_is_pga', &
      test_rigid_limit_is_pga))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_scaling_meets_target', &
      test_scaling_meets_target))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_period_grid', &
      test_period_grid))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_invalid_arguments', &
      test_invalid_arguments))
   call suite%addTest(t)


end function test_spectrum_suite

