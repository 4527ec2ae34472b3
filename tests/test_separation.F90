!> Code separation rules against hand calculations, the properties of the CQC correlation
!> and the DDC, the no-contact gap of two histories, and invalid arguments.
module test_separation
   use funit
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_separation, only: separation_abs, separation_srss, separation_ec8, &
                               separation_ddc, cqc_correlation, no_contact_gap, &
                               separation_t, separation_rules
   implicit none

   real(dp), parameter :: pi = acos(-1.0_dp)

contains

   !@test
   subroutine test_hand_calculations()
      ! u1 = 30 mm, u2 = 40 mm: ABS 70, SRSS 50, EC8 35 (coinciding floors) or 50.
      ! T1 = 0.5 s, T2 = 1 s (r = 0.5), 5 %: rho = 8 (0.05) (0.05 + 0.025) 0.5^1.5 /
      ! (0.75^2 + 4 (0.0025) 0.5 (1.25) + 4 (0.005) 0.25) = 0.0106066/0.57375 = 0.0184865;
      ! DDC = sqrt(0.0009 + 0.0016 - 2 rho 0.0012) = 49.554 mm.
      real(dp), parameter :: u1 = 0.03_dp, u2 = 0.04_dp, tol = 1.0e-15_dp
      real(dp) :: rho, ddc

#line 25 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.07_dp, separation_abs(u1, u2), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 25) )
  if (anyExceptions()) return
#line 26 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 26 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.05_dp, separation_srss(u1, u2), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 26) )
  if (anyExceptions()) return
#line 27 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 27 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.035_dp, separation_ec8(u1, u2, .true.), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 27) )
  if (anyExceptions()) return
#line 28 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 28 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.05_dp, separation_ec8(u1, u2, .false.), tolerance=tol, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 28) )
  if (anyExceptions()) return
#line 29 "/work/wt/suite-blocks/tests/test_separation.pf"
      rho = cqc_correlation(0.5_dp, 1.0_dp, 0.05_dp, 0.05_dp)
#line 30 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertRelativelyEqual(0.01848645179572674_dp, rho, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 30) )
  if (anyExceptions()) return
#line 31 "/work/wt/suite-blocks/tests/test_separation.pf"
      ddc = separation_ddc(u1, u2, 0.5_dp, 1.0_dp, 0.05_dp, 0.05_dp)
#line 32 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertRelativelyEqual(0.04955433901980992_dp, ddc, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 32) )
  if (anyExceptions()) return
#line 33 "/work/wt/suite-blocks/tests/test_separation.pf"
   end subroutine test_hand_calculations

   !@test
   subroutine test_rho_equal_periods()
      ! Equal periods and damping: rho = 1 to 1e-14, DDC = |u1 - u2|. Equal periods,
      ! damping 2 % and 8 %: rho = 2 sqrt(z1 z2)/(z1 + z2) = 0.8. Equal periods without
      ! damping: 1. One building undamped, periods apart: 0, DDC = SRSS.
      real(dp), parameter :: zetas(4) = [0.0_dp, 0.02_dp, 0.05_dp, 0.2_dp]
      real(dp) :: rho, ddc
      integer :: k

      do k = 1, size(zetas)
         rho = cqc_correlation(0.8_dp, 0.8_dp, zetas(k), zetas(k))
#line 46 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(1.0_dp, rho, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 46) )
  if (anyExceptions()) return
#line 47 "/work/wt/suite-blocks/tests/test_separation.pf"
         ddc = separation_ddc(0.05_dp, 0.02_dp, 0.8_dp, 0.8_dp, zetas(k), zetas(k))
#line 48 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.03_dp, ddc, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 48) )
  if (anyExceptions()) return
#line 49 "/work/wt/suite-blocks/tests/test_separation.pf"
      end do
      rho = cqc_correlation(1.3_dp, 1.3_dp, 0.02_dp, 0.08_dp)
#line 51 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.8_dp, rho, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 51) )
  if (anyExceptions()) return
#line 52 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 52 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.0_dp, cqc_correlation(0.5_dp, 1.3_dp, 0.0_dp, 0.05_dp), &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 52) )
  if (anyExceptions()) return
#line 53 "/work/wt/suite-blocks/tests/test_separation.pf"
      ddc = separation_ddc(0.03_dp, 0.04_dp, 0.5_dp, 1.3_dp, 0.05_dp, 0.0_dp)
#line 54 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.05_dp, ddc, tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 54) )
  if (anyExceptions()) return
#line 55 "/work/wt/suite-blocks/tests/test_separation.pf"
   end subroutine test_rho_equal_periods

   !@test
   subroutine test_rho_symmetric_and_bounded()
      ! Swapping the buildings (r -> 1/r, damping swapped) leaves rho unchanged; 0 < rho <= 1;
      ! rho falls as the periods move apart; |u1 - u2| <= DDC <= ABS, and DDC <= SRSS
      ! (rho >= 0).
      real(dp), parameter :: t2s(6) = [0.21_dp, 0.5_dp, 0.95_dp, 1.0_dp, 1.7_dp, 4.0_dp]
      real(dp), parameter :: u1 = 0.012_dp, u2 = 0.031_dp
      real(dp) :: rho, swapped, ddc, prev
      integer :: k

      prev = 0.0_dp
      do k = 1, size(t2s)
         rho = cqc_correlation(1.0_dp, t2s(k), 0.05_dp, 0.02_dp)
         swapped = cqc_correlation(t2s(k), 1.0_dp, 0.02_dp, 0.05_dp)
#line 71 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertRelativelyEqual(rho, swapped, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 71) )
  if (anyExceptions()) return
#line 72 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 72 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertGreaterThan(rho, 0.0_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 72) )
  if (anyExceptions()) return
#line 73 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 73 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertLessThanOrEqual(rho, 1.0_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 73) )
  if (anyExceptions()) return
#line 74 "/work/wt/suite-blocks/tests/test_separation.pf"
         ddc = separation_ddc(u1, u2, 1.0_dp, t2s(k), 0.05_dp, 0.02_dp)
#line 75 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertGreaterThanOrEqual(ddc, abs(u1 - u2), &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 75) )
  if (anyExceptions()) return
#line 76 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 76 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertLessThanOrEqual(ddc, separation_abs(u1, u2), &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 76) )
  if (anyExceptions()) return
#line 77 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 77 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertLessThanOrEqual(ddc, separation_srss(u1, u2), &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 77) )
  if (anyExceptions()) return
#line 78 "/work/wt/suite-blocks/tests/test_separation.pf"
         if (t2s(k) <= 1.0_dp) then
#line 79 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertGreaterThan(rho, prev, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 79) )
  if (anyExceptions()) return
#line 80 "/work/wt/suite-blocks/tests/test_separation.pf"
         else
#line 81 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertLessThan(rho, prev, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 81) )
  if (anyExceptions()) return
#line 82 "/work/wt/suite-blocks/tests/test_separation.pf"
         end if
         prev = rho
      end do
   end subroutine test_rho_symmetric_and_bounded

   !@test
   subroutine test_no_contact_gap()
      ! u1 = 0.02 sin(2 pi t), u2 = 0.01 sin(2 pi t + pi/2) at t = k/1000: closing
      ! u1 - u2 = 0.02 sin - 0.01 cos, peak sqrt(0.02^2 + 0.01^2) = 22.36 mm. A pair that
      ! only opens (u1 - u2 < 0 always) needs no gap: 0.
      real(dp) :: t(1001), h1(1001), h2(1001)
      integer :: k

      t = [(real(k, dp)/1000.0_dp, k=0, 1000)]
      h1 = 0.02_dp*sin(2.0_dp*pi*t)
      h2 = 0.01_dp*sin(2.0_dp*pi*t + 0.5_dp*pi)
#line 98 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(sqrt(5.0e-4_dp), no_contact_gap(h1, h2), tolerance=2.0e-7_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 98) )
  if (anyExceptions()) return
#line 99 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 99 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.0_dp, no_contact_gap(-abs(h1) - 1.0e-3_dp, abs(h2)), &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 99) )
  if (anyExceptions()) return
#line 100 "/work/wt/suite-blocks/tests/test_separation.pf"
      h1(1:3) = [0.0_dp, 0.01_dp, 0.02_dp]
      h2(1:3) = [0.0_dp, -0.005_dp, 0.01_dp]
#line 102 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.015_dp, no_contact_gap(h1(1:3), h2(1:3)), &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 102) )
  if (anyExceptions()) return
#line 103 "/work/wt/suite-blocks/tests/test_separation.pf"
   end subroutine test_no_contact_gap

   !@test
   subroutine test_separation_rules()
      ! All rules at once, with the arguments checked.
      type(separation_t) :: sep
      type(error_type), allocatable :: error
      real(dp) :: h1(3), h2(3)

      h1 = [0.0_dp, 0.02_dp, -0.01_dp]
      h2 = [0.0_dp, -0.01_dp, 0.03_dp]
      call separation_rules(0.03_dp, 0.04_dp, 0.5_dp, 1.0_dp, 0.05_dp, 0.05_dp, .true., &
                            h1, h2, sep, error)
#line 116 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertFalse(allocated(error), &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 116) )
  if (anyExceptions()) return
#line 117 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 117 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.07_dp, sep%abs, tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 117) )
  if (anyExceptions()) return
#line 118 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 118 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.05_dp, sep%srss, tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 118) )
  if (anyExceptions()) return
#line 119 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 119 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.035_dp, sep%ec8, tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 119) )
  if (anyExceptions()) return
#line 120 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 120 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertRelativelyEqual(0.01848645179572674_dp, sep%rho, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 120) )
  if (anyExceptions()) return
#line 121 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 121 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertRelativelyEqual(0.04955433901980992_dp, sep%ddc, tolerance=1.0e-14_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 121) )
  if (anyExceptions()) return
#line 122 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 122 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertEqual(0.03_dp, sep%no_contact, tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 122) )
  if (anyExceptions()) return
#line 123 "/work/wt/suite-blocks/tests/test_separation.pf"
   end subroutine test_separation_rules

   !@test
   subroutine test_invalid_arguments()
      type(separation_t) :: sep
      type(error_type), allocatable :: error
      real(dp) :: h(3)

      h = 0.0_dp
      call separation_rules(-0.01_dp, 0.04_dp, 0.5_dp, 1.0_dp, 0.05_dp, 0.05_dp, .false., &
                            h, h, sep, error)
      call expect_error(error, 'u1 = -1.0', 'm, must be >= 0')
      call separation_rules(0.01_dp, 0.04_dp, 0.5_dp, -1.0_dp, 0.05_dp, 0.05_dp, .false., &
                            h, h, sep, error)
      call expect_error(error, 'T2 = -1', 's, must be > 0')
      call separation_rules(0.01_dp, 0.04_dp, 0.5_dp, 1.0_dp, 1.0_dp, 0.05_dp, .false., &
                            h, h, sep, error)
      call expect_error(error, 'z1 = 1', 'must be >= 0 and < 1')
      call separation_rules(0.01_dp, 0.04_dp, 0.5_dp, 1.0_dp, 0.05_dp, 0.05_dp, .false., &
                            h, h(1:2), sep, error)
      call expect_error(error, 'histories of 3 and 2 samples', 'same, non-zero length')
   end subroutine test_invalid_arguments

   !> The error is set and its message contains `text` and then `rule`.
   subroutine expect_error(error, text, rule)
      type(error_type), allocatable, intent(in) :: error
      character(len=*), intent(in) :: text, rule
      integer :: at

#line 152 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertTrue(allocated(error), message=text, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 152) )
  if (anyExceptions()) return
#line 153 "/work/wt/suite-blocks/tests/test_separation.pf"
      if (.not. allocated(error)) return
      at = index(error%message, text)
#line 155 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertTrue(at > 0, message=error%message, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 155) )
  if (anyExceptions()) return
#line 156 "/work/wt/suite-blocks/tests/test_separation.pf"
#line 156 "/work/wt/suite-blocks/tests/test_separation.pf"
  call assertTrue(index(error%message(at:), rule) > 0, message=error%message, &
 & location=SourceLocation( &
 & 'test_separation.pf', &
 & 156) )
  if (anyExceptions()) return
#line 157 "/work/wt/suite-blocks/tests/test_separation.pf"
   end subroutine expect_error

end module test_separation

module Wraptest_separation
   use FUnit
   use test_separation
   implicit none
   private

contains


end module Wraptest_separation

function test_separation_suite() result(suite)
   use FUnit
   use test_separation
   use Wraptest_separation
   implicit none
   type (TestSuite) :: suite

   class (Test), allocatable :: t

   suite = TestSuite('test_separation_suite')

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_hand_calculations', &
      test_hand_calculations))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_rho_equal_periods', &
      test_rho_equal_periods))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_rho_symmetric_and_bounded', &
      test_rho_symmetric_and_bounded))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_no_contact_gap', &
      test_no_contact_gap))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_separation_rules', &
      test_separation_rules))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_invalid_arguments', &
      test_invalid_arguments))
   call suite%addTest(t)


end function test_separation_suite

