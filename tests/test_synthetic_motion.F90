!> Synthetic ground motions: stored values from an independent reference
!> (tests/reference/synthetic_reference.py), target PGA, zero residual velocity and
!> displacement, zero mean, seeds, envelopes, the spectrum shape of the filters, bad input.
module test_synthetic_motion
   use funit
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_synthetic_motion, only: synthetic_config, synthetic_motion, synthetic_envelope, &
                                     synthetic_filter_psd, end_velocity_displacement
   implicit none

   real(dp), parameter :: pi = acos(-1.0_dp)
   !> Indices of the stored samples.
   integer, parameter :: idx(7) = [2, 3, 4, 101, 251, 401, 501]

contains

   !> Kanai-Tajimi under Jennings' envelope, 5 s at 0.01 s, 0.3 g, seed 2026.
   function kt_case() result(cfg)
      type(synthetic_config) :: cfg

      cfg%filter = 'kanai_tajimi'
      cfg%wg = 15.0_dp
      cfg%zg = 0.6_dp
      cfg%envelope = 'jennings'
      cfg%t1 = 1.0_dp
      cfg%t2 = 3.0_dp
      cfg%c = 0.5_dp
      cfg%duration = 5.0_dp
      cfg%pga = 2.943_dp
      cfg%seed = 2026_int64
   end function kt_case

   !> Clough-Penzien under the Saragoni-Hart envelope, 5 s at 0.01 s, 1 m/s^2, seed -3.
   function cp_case() result(cfg)
      type(synthetic_config) :: cfg

      cfg%filter = 'clough_penzien'
      cfg%wg = 12.0_dp
      cfg%zg = 0.4_dp
      cfg%wf = 1.5_dp
      cfg%zf = 0.6_dp
      cfg%envelope = 'saragoni_hart'
      cfg%eps = 0.2_dp
      cfg%eta = 0.05_dp
      cfg%duration = 5.0_dp
      cfg%pga = 1.0_dp
      cfg%seed = -3_int64
   end function cp_case

   !@test
   subroutine test_stored_values_kanai_tajimi()
      ! Reference script, case kt_jennings (its peak is sample 120).
      real(dp), parameter :: ref(7) = [2.2299364825733538e-05_dp, 2.251191989961528e-05_dp, &
         0.0002450669773431526_dp, -0.8674115489168823_dp, 0.018298510627447664_dp, &
         0.15991918822888784_dp, -0.3356747873230278_dp]
      real(dp), allocatable :: a(:)
      type(error_type), allocatable :: error

      call synthetic_motion(kt_case(), 0.01_dp, a, error)
#line 62 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 62) )
  if (anyExceptions()) return
#line 63 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 63 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(501, size(a), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 63) )
  if (anyExceptions()) return
#line 64 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 64 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(0.0_dp, a(1), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 64) )
  if (anyExceptions()) return
#line 65 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 65 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(ref, a(idx), tolerance=1.0e-12_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 65) )
  if (anyExceptions()) return
#line 66 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 66 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(120, maxloc(abs(a), dim=1), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 66) )
  if (anyExceptions()) return
#line 67 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
   end subroutine test_stored_values_kanai_tajimi

   !@test
   subroutine test_stored_values_clough_penzien()
      ! Reference script, case cp_saragoni_hart (its peak is sample 191).
      real(dp), parameter :: ref(7) = [0.0021686448264346806_dp, 0.007782071018461659_dp, &
         0.009493239721476051_dp, 0.10235045040953548_dp, -0.1080646125867196_dp, &
         -0.036002434211319004_dp, -0.025655613834062847_dp]
      real(dp), allocatable :: a(:)
      type(error_type), allocatable :: error

      call synthetic_motion(cp_case(), 0.01_dp, a, error)
#line 79 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 79) )
  if (anyExceptions()) return
#line 80 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 80 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(501, size(a), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 80) )
  if (anyExceptions()) return
#line 81 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 81 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(ref, a(idx), tolerance=1.0e-12_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 81) )
  if (anyExceptions()) return
#line 82 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 82 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(191, maxloc(abs(a), dim=1), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 82) )
  if (anyExceptions()) return
#line 83 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
   end subroutine test_stored_values_clough_penzien

   !@test
   subroutine test_pga_velocity_mean()
      ! Both cases and a long one: PGA met to 1e-10; velocity and displacement at the end
      ! zero to round-off (relative to the peak ground velocity and displacement); the
      ! average-acceleration mean v(T)/T zero, the plain mean below 1e-3 PGA.
      type(synthetic_config) :: cfgs(3)
      real(dp), allocatable :: a(:)
      type(error_type), allocatable :: error
      real(dp) :: v_end, u_end, pgv, pgd, tol
      integer :: k

      cfgs = [kt_case(), cp_case(), kt_case()]
      cfgs(3)%duration = 40.0_dp
      cfgs(3)%t2 = 15.0_dp
      cfgs(3)%pga = 0.5_dp*9.81_dp
      do k = 1, 3
         call synthetic_motion(cfgs(k), 0.005_dp, a, error)
#line 102 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 102) )
  if (anyExceptions()) return
#line 103 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
         tol = 1.0e-10_dp*cfgs(k)%pga
#line 104 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(cfgs(k)%pga, maxval(abs(a)), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 104) )
  if (anyExceptions()) return
#line 105 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
         call ground_peaks(a, 0.005_dp, pgv, pgd)
         call end_velocity_displacement(a, 0.005_dp, v_end, u_end)
#line 107 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertLessThan(abs(v_end), 1.0e-13_dp*pgv, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 107) )
  if (anyExceptions()) return
#line 108 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 108 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertLessThan(abs(u_end), 1.0e-12_dp*pgd, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 108) )
  if (anyExceptions()) return
#line 109 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 109 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertLessThan(abs(sum(a)/size(a)), 1.0e-3_dp*cfgs(k)%pga, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 109) )
  if (anyExceptions()) return
#line 110 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 110 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertGreaterThan(pgv, 0.0_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 110) )
  if (anyExceptions()) return
#line 111 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      end do
   end subroutine test_pga_velocity_mean

   !@test
   subroutine test_reproducible_and_seeds_differ()
      ! The same seed: the same motion to the bit; another seed: an unrelated one.
      type(synthetic_config) :: cfg
      real(dp), allocatable :: a(:), b(:), c(:)
      type(error_type), allocatable :: error
      real(dp) :: r

      cfg = kt_case()
      call synthetic_motion(cfg, 0.01_dp, a, error)
      call synthetic_motion(cfg, 0.01_dp, b, error)
#line 125 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(a, b, tolerance=0.0_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 125) )
  if (anyExceptions()) return
#line 126 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      cfg%seed = 2027_int64
      call synthetic_motion(cfg, 0.01_dp, c, error)
#line 128 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 128) )
  if (anyExceptions()) return
#line 129 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      r = sum(a*c)/sqrt(sum(a*a)*sum(c*c))
#line 130 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertLessThan(abs(r), 0.3_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 130) )
  if (anyExceptions()) return
#line 131 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 131 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertGreaterThan(maxval(abs(a - c)), 0.5_dp*cfg%pga, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 131) )
  if (anyExceptions()) return
#line 132 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
   end subroutine test_reproducible_and_seeds_differ

   !@test
   subroutine test_envelopes()
      ! Jennings: (t/t1)^2, 1, exp(-c (t - t2)). Saragoni-Hart: 1 at eps T, eta at T.
      type(synthetic_config) :: cfg
      real(dp) :: tp, e

      cfg = kt_case()
#line 141 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(0.0_dp, synthetic_envelope(cfg, 0.0_dp), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 141) )
  if (anyExceptions()) return
#line 142 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 142 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(0.25_dp, synthetic_envelope(cfg, 0.5_dp), tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 142) )
  if (anyExceptions()) return
#line 143 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 143 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(1.0_dp, synthetic_envelope(cfg, 2.0_dp), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 143) )
  if (anyExceptions()) return
#line 144 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      e = synthetic_envelope(cfg, 5.0_dp)
#line 145 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(exp(-1.0_dp), e, tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 145) )
  if (anyExceptions()) return
#line 146 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      cfg = cp_case()
      tp = cfg%eps*cfg%duration
#line 148 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(0.0_dp, synthetic_envelope(cfg, 0.0_dp), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 148) )
  if (anyExceptions()) return
#line 149 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 149 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(1.0_dp, synthetic_envelope(cfg, tp), tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 149) )
  if (anyExceptions()) return
#line 150 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 150 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertLessThan(synthetic_envelope(cfg, 0.99_dp*tp), 1.0_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 150) )
  if (anyExceptions()) return
#line 151 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 151 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertLessThan(synthetic_envelope(cfg, 1.01_dp*tp), 1.0_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 151) )
  if (anyExceptions()) return
#line 152 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      e = synthetic_envelope(cfg, cfg%duration)
#line 153 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertEqual(cfg%eta, e, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 153) )
  if (anyExceptions()) return
#line 154 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
   end subroutine test_envelopes

   !@test
   subroutine test_kanai_tajimi_spectrum_shape()
      ! Nearly stationary motions (Jennings, t1 = 1 s, plateau to 99 s), 4 seeds: the
      ! periodogram averaged over seeds and 41 neighbouring frequencies (8 % scatter)
      ! follows |H|^2 of the filter within 25 % from 0.3 wg to 3 wg, and its peak lies
      ! within 10 % of the filter's, wg sqrt(sqrt(1 + 8 zg^2) - 1)/(2 zg) = 0.93 wg.
      type(synthetic_config) :: cfg
      real(dp), allocatable :: w(:), s(:), g(:)
      real(dp) :: wp, ratio
      integer :: k, kp

      cfg = stationary_case('kanai_tajimi')
      call mean_periodogram(cfg, 20, w, s)
      g = synthetic_filter_psd(cfg, w)
      ratio = sum(s)/sum(g)
      do k = 1, size(w)
         if (w(k) < 0.3_dp*cfg%wg) cycle
#line 173 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertRelativelyEqual(g(k), s(k)/ratio, tolerance=0.25_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 173) )
  if (anyExceptions()) return
#line 174 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      end do
      wp = cfg%wg*sqrt(sqrt(1.0_dp + 8.0_dp*cfg%zg**2) - 1.0_dp)/(2.0_dp*cfg%zg)
      kp = maxloc(s, dim=1)
#line 177 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertRelativelyEqual(wp, w(kp), tolerance=0.1_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 177) )
  if (anyExceptions()) return
#line 178 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 178 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertRelativelyEqual(0.93_dp*cfg%wg, wp, tolerance=0.01_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 178) )
  if (anyExceptions()) return
#line 179 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
   end subroutine test_kanai_tajimi_spectrum_shape

   !@test
   subroutine test_clough_penzien_high_pass()
      ! The same seeds through Kanai-Tajimi and Clough-Penzien: the same noise through one
      ! more filter, so the ratio of the periodograms at each frequency is the high-pass
      ! gain w^4/((wf^2 - w^2)^2 + 4 zf^2 wf^2 w^2) within 12 %, up to the normalisation
      ! (PGA scaling), from 0.6 wf (gain 0.11) to 4 wf. Below, the envelope's leakage of
      ! Kanai-Tajimi's strong low frequencies blurs the ratio.
      type(synthetic_config) :: kt, cp
      real(dp), allocatable :: w(:), s_kt(:), s_cp(:), g(:), r(:)
      logical, allocatable :: band(:)
      real(dp) :: norm
      integer :: k

      kt = stationary_case('kanai_tajimi')
      cp = stationary_case('clough_penzien')
      call mean_periodogram(kt, 0, w, s_kt)
      call mean_periodogram(cp, 0, w, s_cp)
      g = synthetic_filter_psd(cp, w)/synthetic_filter_psd(kt, w)
      r = s_cp/s_kt
      band = w >= 0.6_dp*cp%wf .and. w <= 4.0_dp*cp%wf
      norm = sum(r, mask=band)/sum(g, mask=band)
#line 202 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertGreaterThan(count(band), 40, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 202) )
  if (anyExceptions()) return
#line 203 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 203 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertLessThan(g(1), 0.01_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 203) )
  if (anyExceptions()) return
#line 204 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      do k = 1, size(w)
         if (.not. band(k)) cycle
#line 206 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertRelativelyEqual(g(k), r(k)/norm, tolerance=0.12_dp, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 206) )
  if (anyExceptions()) return
#line 207 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      end do
   end subroutine test_clough_penzien_high_pass

   !@test
   subroutine test_invalid_parameters()
      type(synthetic_config) :: cfg
      real(dp), allocatable :: a(:)
      type(error_type), allocatable :: error

      cfg = kt_case()
      cfg%zg = 1.2_dp
      call synthetic_motion(cfg, 0.01_dp, a, error)
      call expect_error(error, 'zg = 1.2', 'must be > 0 and < 1')
      cfg = kt_case()
      cfg%t2 = 0.5_dp
      call synthetic_motion(cfg, 0.01_dp, a, error)
      call expect_error(error, 't2 = 0.5', 'must be >= t1 = 1')
      cfg = kt_case()
      cfg%pga = 0.0_dp
      call synthetic_motion(cfg, 0.01_dp, a, error)
      call expect_error(error, 'pga = 0', 'm/s^2, must be > 0')
      cfg = kt_case()
      cfg%filter = 'kanai'
      call synthetic_motion(cfg, 0.01_dp, a, error)
      call expect_error(error, 'filter = ''kanai''', 'must be ''kanai_tajimi''')
      cfg = cp_case()
      cfg%wf = -1.0_dp
      call synthetic_motion(cfg, 0.01_dp, a, error)
      call expect_error(error, 'wf = -1', 'rad/s, must be > 0')
      cfg = cp_case()
      cfg%eta = 1.0_dp
      call synthetic_motion(cfg, 0.01_dp, a, error)
      call expect_error(error, 'eta = 1', 'must be > 0 and < 1')
      cfg = kt_case()
      call synthetic_motion(cfg, 1.0_dp, a, error)
      call expect_error(error, 'duration = 5', 's, must be >= 10 dt')
#line 243 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertFalse(allocated(a), &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 243) )
  if (anyExceptions()) return
#line 244 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
   end subroutine test_invalid_parameters

   !> A nearly stationary 100 s motion with the given filter (zg = 0.3, wg = 15 rad/s).
   function stationary_case(filter) result(cfg)
      character(len=*), intent(in) :: filter
      type(synthetic_config) :: cfg

      cfg%filter = filter
      cfg%wg = 15.0_dp
      cfg%zg = 0.3_dp
      cfg%wf = 2.0_dp
      cfg%zf = 0.6_dp
      cfg%envelope = 'jennings'
      cfg%t1 = 1.0_dp
      cfg%t2 = 99.0_dp
      cfg%c = 2.0_dp
      cfg%duration = 100.0_dp
      cfg%pga = 1.0_dp
   end function stationary_case

   !> Periodogram |sum a_i exp(-i w t_i) dt|^2 / T at w_k = 2 pi k/T up to 3.2 wg, averaged
   !> over seeds 1..4 and over 2 half + 1 neighbouring frequencies; w and s at the centres.
   subroutine mean_periodogram(cfg0, half, w, s)
      type(synthetic_config), intent(in) :: cfg0
      integer, intent(in) :: half
      real(dp), allocatable, intent(out) :: w(:), s(:)
      real(dp), parameter :: dt = 0.01_dp
      type(synthetic_config) :: cfg
      type(error_type), allocatable :: error
      real(dp), allocatable :: a(:), raw(:)
      complex(dp) :: x, rot, ph
      real(dp) :: t_len
      integer :: n_w, k, i, seed

      cfg = cfg0
      t_len = cfg%duration
      n_w = int(3.2_dp*cfg%wg*t_len/(2.0_dp*pi))
      allocate (raw(n_w))
      raw = 0.0_dp
      do seed = 1, 4
         cfg%seed = int(seed, int64)
         call synthetic_motion(cfg, dt, a, error)
         do k = 1, n_w
            rot = exp(cmplx(0.0_dp, -2.0_dp*pi*k/t_len*dt, dp))
            ph = (1.0_dp, 0.0_dp)
            x = (0.0_dp, 0.0_dp)
            do i = 1, size(a)
               x = x + a(i)*ph
               ph = ph*rot
            end do
            raw(k) = raw(k) + abs(x*dt)**2/t_len
         end do
      end do
      allocate (w(n_w - 2*half), s(n_w - 2*half))
      do k = 1, size(w)
         w(k) = 2.0_dp*pi*(k + half)/t_len
         s(k) = sum(raw(k:k + 2*half))/(2*half + 1)
      end do
   end subroutine mean_periodogram

   !> Peak ground velocity and displacement (average-acceleration integration).
   subroutine ground_peaks(a, dt, pgv, pgd)
      real(dp), intent(in) :: a(:), dt
      real(dp), intent(out) :: pgv, pgd
      real(dp) :: v, u
      integer :: i

      v = 0.0_dp
      u = 0.0_dp
      pgv = 0.0_dp
      pgd = 0.0_dp
      do i = 1, size(a) - 1
         u = u + dt*v + 0.25_dp*dt*dt*(a(i) + a(i + 1))
         v = v + 0.5_dp*dt*(a(i) + a(i + 1))
         pgv = max(pgv, abs(v))
         pgd = max(pgd, abs(u))
      end do
   end subroutine ground_peaks

   !> The error is set and its message contains `text` and then `rule`.
   subroutine expect_error(error, text, rule)
      type(error_type), allocatable, intent(in) :: error
      character(len=*), intent(in) :: text, rule
      integer :: at

#line 329 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertTrue(allocated(error), message=text, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 329) )
  if (anyExceptions()) return
#line 330 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
      if (.not. allocated(error)) return
      at = index(error%message, text)
#line 332 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertTrue(at > 0, message=error%message, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 332) )
  if (anyExceptions()) return
#line 333 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
#line 333 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
  call assertTrue(index(error%message(at:), rule) > 0, message=error%message, &
 & location=SourceLocation( &
 & 'test_synthetic_motion.pf', &
 & 333) )
  if (anyExceptions()) return
#line 334 "/work/wt/suite-blocks/tests/test_synthetic_motion.pf"
   end subroutine expect_error

end module test_synthetic_motion

module Wraptest_synthetic_motion
   use FUnit
   use test_synthetic_motion
   implicit none
   private

contains


end module Wraptest_synthetic_motion

function test_synthetic_motion_suite() result(suite)
   use FUnit
   use test_synthetic_motion
   use Wraptest_synthetic_motion
   implicit none
   type (TestSuite) :: suite

   class (Test), allocatable :: t

   suite = TestSuite('test_synthetic_motion_suite')

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_stored_values_kanai_tajimi', &
      test_stored_values_kanai_tajimi))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_stored_values_clough_penzien', &
      test_stored_values_clough_penzien))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_pga_velocity_mean', &
      test_pga_velocity_mean))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_reproducible_and_seeds_differ', &
      test_reproducible_and_seeds_differ))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_envelopes', &
      test_envelopes))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_kanai_tajimi_spectrum_shape', &
      test_kanai_tajimi_spectrum_shape))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_clough_penzien_high_pass', &
      test_clough_penzien_high_pass))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_invalid_parameters', &
      test_invalid_parameters))
   call suite%addTest(t)


end function test_synthetic_motion_suite

