!> pfunit_lite: the assertions and the test runner behind `use funit` when the real
!> pFUnit is not installed.  Argument lists follow pFUnit 4:
!>   assertEqual(expected, actual [, tolerance] [, message] [, location])   reals
!>   assertEqual(expected, actual [, message] [, location])                 integers, strings
!>   assertRelativelyEqual(expected, actual, tolerance [, message] [, location])
!>   assertLessThan(lhs, rhs [, tolerance] [, message] [, location])        checks lhs < rhs (+ tolerance)
!>   assertTrue/assertFalse(condition [, message] [, location]), assertFail(message [, location])
!>   assertIsFinite/assertIsNaN/assertIsInfinite(x [, message] [, location])   scalars
!> Integer assertNotEqual/assertLessThan/... and logical assertEqual take message= and
!> location= by keyword only (KeywordEnforcer), as in pFUnit.
!> A scalar expected value (or lhs) is compared with every element of an array actual value.
!> Reals: actual real(real64) of rank 0..2 (not-equal and relational: rank 0..1); expected
!> real64, default real or default integer; tolerance real64 or default real.
!> Integers: default and int64.  Strings compare without leading/trailing blanks.
!>
!> The specific procedures between the GENERATED markers are written by gen_funit.py
!> (run `python3 gen_funit.py` in this directory after editing it); the rest is by hand.
module funit
   use, intrinsic :: iso_fortran_env, only: int64, real32, real64, output_unit, error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none
   private

   public :: SourceLocation, KeywordEnforcer, anyExceptions
   public :: assertEqual, assertNotEqual, assertRelativelyEqual
   public :: assertLessThan, assertLessThanOrEqual, assertGreaterThan, assertGreaterThanOrEqual
   public :: assertTrue, assertFalse, assertFail, assertAll, assertAny, assertNone, assertNotAll
   public :: assertIsFinite, assertIsNaN, assertIsInfinite
   ! Runner, called by the generated driver program.
   public :: funit_lite_procedure, funit_lite_init, funit_lite_run, funit_lite_finish

   !> Where an assertion sits in the .pf file (filled in by the preprocessor).
   type :: SourceLocation
      character(len=256) :: fileName = ''
      integer :: lineNumber = 0
   end type SourceLocation

   !> Forces keyword use of the optional arguments that follow it (never pass one).
   type, abstract :: KeywordEnforcer
   end type KeywordEnforcer

   abstract interface
      subroutine funit_lite_procedure()
      end subroutine funit_lite_procedure
   end interface

   interface
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   integer, parameter :: OP_EQ = 1, OP_NE = 2, OP_REL = 3, OP_LT = 4, OP_LE = 5, OP_GT = 6, OP_GE = 7
   integer, parameter :: CLASS_FINITE = 1, CLASS_NAN = 2, CLASS_INFINITE = 3
   real(real64), parameter :: BIG = huge(1.0_real64)/4

   ! Runner state.
   character(len=:), allocatable :: current_test     ! name of the running test
   integer :: current_failures = 0                    ! failed assertions in the running test
   character(len=:), allocatable :: selection         ! test requested on the command line
   logical :: listing = .false.
   integer :: n_run = 0, n_passed = 0, n_failed = 0

   interface assertEqual
      module procedure assert_equal_string, assert_equal_string_01, assert_equal_string_11, &
         assert_equal_logical_0, assert_equal_logical_1, assert_equal_logical_01
   end interface assertEqual

   interface assertTrue
      module procedure assert_true_0, assert_true_1
   end interface assertTrue

   interface assertFalse
      module procedure assert_false_0, assert_false_1
   end interface assertFalse

   interface assertIsFinite
      module procedure is_finite_r64_0, is_finite_r32_0
   end interface assertIsFinite

   interface assertIsNaN
      module procedure is_nan_r64_0, is_nan_r32_0
   end interface assertIsNaN

   interface assertIsInfinite
      module procedure is_infinite_r64_0, is_infinite_r32_0
   end interface assertIsInfinite

   ! BEGIN GENERATED INTERFACES (gen_funit.py)
   interface assertEqual
      module procedure eq_r8_0_r8_0, eq_r8_0_r8_0_r4, eq_r8_0_r8_0_r8, eq_r4_0_r8_0, &
         eq_r4_0_r8_0_r4, eq_r4_0_r8_0_r8, eq_i4_0_r8_0, eq_i4_0_r8_0_r4, &
         eq_i4_0_r8_0_r8, eq_r8_1_r8_1, eq_r8_1_r8_1_r4, eq_r8_1_r8_1_r8, &
         eq_r4_1_r8_1, eq_r4_1_r8_1_r4, eq_r4_1_r8_1_r8, eq_i4_1_r8_1, &
         eq_i4_1_r8_1_r4, eq_i4_1_r8_1_r8, eq_r8_0_r8_1, eq_r8_0_r8_1_r4, &
         eq_r8_0_r8_1_r8, eq_r4_0_r8_1, eq_r4_0_r8_1_r4, eq_r4_0_r8_1_r8, &
         eq_i4_0_r8_1, eq_i4_0_r8_1_r4, eq_i4_0_r8_1_r8, eq_r8_2_r8_2, &
         eq_r8_2_r8_2_r4, eq_r8_2_r8_2_r8, eq_r4_2_r8_2, eq_r4_2_r8_2_r4, &
         eq_r4_2_r8_2_r8, eq_i4_2_r8_2, eq_i4_2_r8_2_r4, eq_i4_2_r8_2_r8, &
         eq_r8_0_r8_2, eq_r8_0_r8_2_r4, eq_r8_0_r8_2_r8, eq_r4_0_r8_2, &
         eq_r4_0_r8_2_r4, eq_r4_0_r8_2_r8, eq_i4_0_r8_2, eq_i4_0_r8_2_r4, &
         eq_i4_0_r8_2_r8, eq_i4_0_i4_0, eq_i8_0_i8_0, eq_i4_0_i8_0, &
         eq_i4_1_i4_1, eq_i8_1_i8_1, eq_i4_0_i4_1, eq_i8_0_i8_1, &
         eq_i4_0_i8_1, eq_i4_2_i4_2, eq_i8_2_i8_2, eq_i4_0_i4_2, &
         eq_i8_0_i8_2, eq_i4_0_i8_2
   end interface assertEqual

   interface assertNotEqual
      module procedure ne_r8_0_r8_0, ne_r8_0_r8_0_r4, ne_r8_0_r8_0_r8, ne_r4_0_r8_0, &
         ne_r4_0_r8_0_r4, ne_r4_0_r8_0_r8, ne_i4_0_r8_0, ne_i4_0_r8_0_r4, &
         ne_i4_0_r8_0_r8, ne_r8_1_r8_1, ne_r8_1_r8_1_r4, ne_r8_1_r8_1_r8, &
         ne_r4_1_r8_1, ne_r4_1_r8_1_r4, ne_r4_1_r8_1_r8, ne_i4_1_r8_1, &
         ne_i4_1_r8_1_r4, ne_i4_1_r8_1_r8, ne_r8_0_r8_1, ne_r8_0_r8_1_r4, &
         ne_r8_0_r8_1_r8, ne_r4_0_r8_1, ne_r4_0_r8_1_r4, ne_r4_0_r8_1_r8, &
         ne_i4_0_r8_1, ne_i4_0_r8_1_r4, ne_i4_0_r8_1_r8, ne_i4_0_i4_0, &
         ne_i8_0_i8_0, ne_i4_0_i8_0, ne_i4_1_i4_1, ne_i8_1_i8_1, &
         ne_i4_0_i4_1, ne_i8_0_i8_1, ne_i4_0_i8_1
   end interface assertNotEqual

   interface assertLessThan
      module procedure lt_r8_0_r8_0, lt_r8_0_r8_0_r4, lt_r8_0_r8_0_r8, lt_r4_0_r8_0, &
         lt_r4_0_r8_0_r4, lt_r4_0_r8_0_r8, lt_i4_0_r8_0, lt_i4_0_r8_0_r4, &
         lt_i4_0_r8_0_r8, lt_r8_1_r8_1, lt_r8_1_r8_1_r4, lt_r8_1_r8_1_r8, &
         lt_r4_1_r8_1, lt_r4_1_r8_1_r4, lt_r4_1_r8_1_r8, lt_i4_1_r8_1, &
         lt_i4_1_r8_1_r4, lt_i4_1_r8_1_r8, lt_r8_0_r8_1, lt_r8_0_r8_1_r4, &
         lt_r8_0_r8_1_r8, lt_r4_0_r8_1, lt_r4_0_r8_1_r4, lt_r4_0_r8_1_r8, &
         lt_i4_0_r8_1, lt_i4_0_r8_1_r4, lt_i4_0_r8_1_r8, lt_i4_0_i4_0, &
         lt_i8_0_i8_0, lt_i4_0_i8_0, lt_i4_1_i4_1, lt_i8_1_i8_1, &
         lt_i4_0_i4_1, lt_i8_0_i8_1, lt_i4_0_i8_1
   end interface assertLessThan

   interface assertLessThanOrEqual
      module procedure le_r8_0_r8_0, le_r8_0_r8_0_r4, le_r8_0_r8_0_r8, le_r4_0_r8_0, &
         le_r4_0_r8_0_r4, le_r4_0_r8_0_r8, le_i4_0_r8_0, le_i4_0_r8_0_r4, &
         le_i4_0_r8_0_r8, le_r8_1_r8_1, le_r8_1_r8_1_r4, le_r8_1_r8_1_r8, &
         le_r4_1_r8_1, le_r4_1_r8_1_r4, le_r4_1_r8_1_r8, le_i4_1_r8_1, &
         le_i4_1_r8_1_r4, le_i4_1_r8_1_r8, le_r8_0_r8_1, le_r8_0_r8_1_r4, &
         le_r8_0_r8_1_r8, le_r4_0_r8_1, le_r4_0_r8_1_r4, le_r4_0_r8_1_r8, &
         le_i4_0_r8_1, le_i4_0_r8_1_r4, le_i4_0_r8_1_r8, le_i4_0_i4_0, &
         le_i8_0_i8_0, le_i4_0_i8_0, le_i4_1_i4_1, le_i8_1_i8_1, &
         le_i4_0_i4_1, le_i8_0_i8_1, le_i4_0_i8_1
   end interface assertLessThanOrEqual

   interface assertGreaterThan
      module procedure gt_r8_0_r8_0, gt_r8_0_r8_0_r4, gt_r8_0_r8_0_r8, gt_r4_0_r8_0, &
         gt_r4_0_r8_0_r4, gt_r4_0_r8_0_r8, gt_i4_0_r8_0, gt_i4_0_r8_0_r4, &
         gt_i4_0_r8_0_r8, gt_r8_1_r8_1, gt_r8_1_r8_1_r4, gt_r8_1_r8_1_r8, &
         gt_r4_1_r8_1, gt_r4_1_r8_1_r4, gt_r4_1_r8_1_r8, gt_i4_1_r8_1, &
         gt_i4_1_r8_1_r4, gt_i4_1_r8_1_r8, gt_r8_0_r8_1, gt_r8_0_r8_1_r4, &
         gt_r8_0_r8_1_r8, gt_r4_0_r8_1, gt_r4_0_r8_1_r4, gt_r4_0_r8_1_r8, &
         gt_i4_0_r8_1, gt_i4_0_r8_1_r4, gt_i4_0_r8_1_r8, gt_i4_0_i4_0, &
         gt_i8_0_i8_0, gt_i4_0_i8_0, gt_i4_1_i4_1, gt_i8_1_i8_1, &
         gt_i4_0_i4_1, gt_i8_0_i8_1, gt_i4_0_i8_1
   end interface assertGreaterThan

   interface assertGreaterThanOrEqual
      module procedure ge_r8_0_r8_0, ge_r8_0_r8_0_r4, ge_r8_0_r8_0_r8, ge_r4_0_r8_0, &
         ge_r4_0_r8_0_r4, ge_r4_0_r8_0_r8, ge_i4_0_r8_0, ge_i4_0_r8_0_r4, &
         ge_i4_0_r8_0_r8, ge_r8_1_r8_1, ge_r8_1_r8_1_r4, ge_r8_1_r8_1_r8, &
         ge_r4_1_r8_1, ge_r4_1_r8_1_r4, ge_r4_1_r8_1_r8, ge_i4_1_r8_1, &
         ge_i4_1_r8_1_r4, ge_i4_1_r8_1_r8, ge_r8_0_r8_1, ge_r8_0_r8_1_r4, &
         ge_r8_0_r8_1_r8, ge_r4_0_r8_1, ge_r4_0_r8_1_r4, ge_r4_0_r8_1_r8, &
         ge_i4_0_r8_1, ge_i4_0_r8_1_r4, ge_i4_0_r8_1_r8, ge_i4_0_i4_0, &
         ge_i8_0_i8_0, ge_i4_0_i8_0, ge_i4_1_i4_1, ge_i8_1_i8_1, &
         ge_i4_0_i4_1, ge_i8_0_i8_1, ge_i4_0_i8_1
   end interface assertGreaterThanOrEqual

   interface assertRelativelyEqual
      module procedure rel_r8_0_r8_0_r4, rel_r8_0_r8_0_r8, rel_r4_0_r8_0_r4, rel_r4_0_r8_0_r8, &
         rel_i4_0_r8_0_r4, rel_i4_0_r8_0_r8, rel_r8_1_r8_1_r4, rel_r8_1_r8_1_r8, &
         rel_r4_1_r8_1_r4, rel_r4_1_r8_1_r8, rel_i4_1_r8_1_r4, rel_i4_1_r8_1_r8, &
         rel_r8_0_r8_1_r4, rel_r8_0_r8_1_r8, rel_r4_0_r8_1_r4, rel_r4_0_r8_1_r8, &
         rel_i4_0_r8_1_r4, rel_i4_0_r8_1_r8, rel_r8_2_r8_2_r4, rel_r8_2_r8_2_r8, &
         rel_r4_2_r8_2_r4, rel_r4_2_r8_2_r8, rel_i4_2_r8_2_r4, rel_i4_2_r8_2_r8, &
         rel_r8_0_r8_2_r4, rel_r8_0_r8_2_r8, rel_r4_0_r8_2_r4, rel_r4_0_r8_2_r8, &
         rel_i4_0_r8_2_r4, rel_i4_0_r8_2_r8
   end interface assertRelativelyEqual
   ! END GENERATED INTERFACES

contains

   ! ================================================================ runner

   !> True once an assertion of the running test has failed (pFUnit's anyExceptions).
   logical function anyExceptions()
      anyExceptions = current_failures > 0
   end function anyExceptions

   !> Read the command line: no argument runs every test, `<test>` (or `<module>.<test>`)
   !> runs one, `--list` prints the test names. `initialize` (pFUnit's EXTRA_INITIALIZE)
   !> is called before any test runs, not when listing.
   subroutine funit_lite_init(initialize)
      procedure(funit_lite_procedure), optional :: initialize
      integer :: n, length

      n = command_argument_count()
      if (n > 1) call usage_error('at most one argument expected')
      if (n == 1) then
         call get_command_argument(1, length=length)
         allocate (character(len=length) :: selection)
         call get_command_argument(1, value=selection)
         if (selection == '--list') then
            listing = .true.
            deallocate (selection)
         else if (selection == '-h' .or. selection == '--help') then
            write (output_unit, '(a)') 'usage: <test executable> [--list | <test name>]'
            call stop_with(0)
         else if (len(selection) == 0) then
            call usage_error('empty test name')
         else if (selection(1:1) == '-') then
            call usage_error('unknown option ' // selection)
         end if
      end if
      if (present(initialize) .and. .not. listing) call initialize()
   end subroutine funit_lite_init

   !> Run one test (if selected): @before, the test unless @before failed, @after.
   subroutine funit_lite_run(suite, name, test, before, after)
      character(len=*), intent(in) :: suite, name
      procedure(funit_lite_procedure) :: test
      procedure(funit_lite_procedure), optional :: before, after

      if (listing) then
         write (output_unit, '(a)') name
         return
      end if
      if (allocated(selection)) then
         if (selection /= name .and. selection /= suite // '.' // name) return
      end if
      n_run = n_run + 1
      current_test = name
      current_failures = 0
      if (present(before)) call before()
      if (current_failures == 0) call test()
      if (present(after)) call after()
      if (current_failures == 0) then
         n_passed = n_passed + 1
         write (output_unit, '(a)') '[  OK  ] ' // name
      else
         n_failed = n_failed + 1
         write (output_unit, '(a)') '[FAILED] ' // name
      end if
      flush (output_unit)
      current_test = ''
      current_failures = 0
   end subroutine funit_lite_run

   !> Print the summary and end the program: status 1 if a test failed, 2 if the
   !> requested test does not exist. `finalize` (pFUnit's EXTRA_FINALIZE) is called first.
   subroutine funit_lite_finish(finalize)
      procedure(funit_lite_procedure), optional :: finalize
      character(len=32) :: a, b

      if (listing) call stop_with(0)
      if (present(finalize)) call finalize()
      if (allocated(selection) .and. n_run == 0) then
         write (error_unit, '(a)') "pfunit_lite: no test named '" // selection // "' (try --list)"
         call stop_with(2)
      end if
      write (a, '(i0)') n_passed
      write (b, '(i0)') n_failed
      write (output_unit, '(a)') trim(a) // ' passed, ' // trim(b) // ' failed'
      if (n_failed > 0) call stop_with(1)
      call stop_with(0)
   end subroutine funit_lite_finish

   subroutine usage_error(text)
      character(len=*), intent(in) :: text

      write (error_unit, '(a)') 'pfunit_lite: ' // text
      write (error_unit, '(a)') 'usage: <test executable> [--list | <test name>]'
      call stop_with(2)
   end subroutine usage_error

   !> Exit with a status, quietly (STOP would print it and the IEEE flags).
   subroutine stop_with(status)
      integer, intent(in) :: status

      flush (output_unit)
      flush (error_unit)
      call c_exit(int(status, c_int))
   end subroutine stop_with

   ! ================================================================ failure reports

   !> First line of a failure report: "<file>:<line>: <assertion> failed in <test>".
   subroutine begin_failure(assertion, location)
      character(len=*), intent(in) :: assertion
      type(SourceLocation), optional, intent(in) :: location
      character(len=16) :: line
      character(len=:), allocatable :: where, test

      where = '<unknown location>'
      if (present(location)) then
         write (line, '(i0)') location%lineNumber
         where = trim(location%fileName) // ':' // trim(line)
      end if
      test = '<no test>'
      if (allocated(current_test)) then
         if (len(current_test) > 0) test = current_test
      end if
      write (output_unit, '(a)') where // ': ' // assertion // ' failed in ' // test
   end subroutine begin_failure

   !> One "label: value" line of a failure report.
   subroutine detail(label, value)
      character(len=*), intent(in) :: label, value

      write (output_unit, '(a12,": ",a)') label, value
   end subroutine detail

   !> Last line(s) of a failure report; counts the failure.
   subroutine end_failure(message)
      character(len=*), optional, intent(in) :: message

      if (present(message)) then
         if (len_trim(message) > 0) call detail('message', trim(message))
      end if
      flush (output_unit)
      current_failures = current_failures + 1
   end subroutine end_failure

   !> Report a failure made of a single line of text.
   subroutine fail_with(assertion, text, message, location)
      character(len=*), intent(in) :: assertion, text
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call begin_failure(assertion, location)
      if (len(text) > 0) call detail('reason', text)
      call end_failure(message)
   end subroutine fail_with

   !> Index line for array comparisons: first failing element, number of failures.
   subroutine index_detail(first, count, shp)
      integer, intent(in) :: first, count
      integer, intent(in) :: shp(:)

      if (size(shp) == 0) return
      call detail('index', index_str(first, shp) // ' is the first of ' // istr(int(count, int64)) // &
                  ' failing element(s) of ' // istr(int(product(shp), int64)) // ', shape ' // shape_str(shp))
   end subroutine index_detail

   function istr(i) result(s)
      integer(int64), intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buf

      write (buf, '(i0)') i
      s = trim(buf)
   end function istr

   function rstr(x) result(s)
      real(real64), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=48) :: buf

      write (buf, '(g0)') x
      s = trim(adjustl(buf))
   end function rstr

   function lstr(x) result(s)
      logical, intent(in) :: x
      character(len=:), allocatable :: s

      s = merge('.true. ', '.false.', x)
      s = trim(s)
   end function lstr

   !> "(i, j)" of element k (column-major) of an array of shape shp.
   function index_str(k, shp) result(s)
      integer, intent(in) :: k
      integer, intent(in) :: shp(:)
      character(len=:), allocatable :: s
      integer :: d, rest

      rest = k - 1
      s = '('
      do d = 1, size(shp)
         if (d > 1) s = s // ', '
         s = s // istr(int(mod(rest, max(shp(d), 1)) + 1, int64))
         rest = rest/max(shp(d), 1)
      end do
      s = s // ')'
   end function index_str

   function shape_str(shp) result(s)
      integer, intent(in) :: shp(:)
      character(len=:), allocatable :: s
      integer :: d

      s = '['
      do d = 1, size(shp)
         if (d > 1) s = s // ', '
         s = s // istr(int(shp(d), int64))
      end do
      s = s // ']'
   end function shape_str

   !> Same shape, or report a failure.
   logical function conformable(assertion, shape_expected, shape_actual, message, location)
      character(len=*), intent(in) :: assertion
      integer, intent(in) :: shape_expected(:), shape_actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      conformable = size(shape_expected) == size(shape_actual)
      if (conformable) conformable = all(shape_expected == shape_actual)
      if (.not. conformable) then
         call begin_failure(assertion, location)
         call detail('reason', 'arrays do not conform')
         call detail('shape 1', shape_str(shape_expected))
         call detail('shape 2', shape_str(shape_actual))
         call end_failure(message)
      end if
   end function conformable

   ! ================================================================ real comparisons

   !> a - b, or .false. in ok if it cannot be computed without a floating-point trap.
   subroutine safe_difference(a, b, d, ok)
      real(real64), intent(in) :: a, b
      real(real64), intent(out) :: d
      logical, intent(out) :: ok

      d = 0
      ok = ieee_is_finite(a) .and. ieee_is_finite(b)
      if (.not. ok) return
      if (abs(a) <= BIG .and. abs(b) <= BIG) then
         d = a - b
      else if (abs(a/2 - b/2) <= BIG) then
         d = 2*(a/2 - b/2)
      else
         ok = .false.
      end if
   end subroutine safe_difference

   !> Bitwise-equal values (also equal infinities), without comparing reals with ==.
   logical function same_value(a, b)
      real(real64), intent(in) :: a, b

      same_value = .false.
      if (ieee_is_nan(a) .or. ieee_is_nan(b)) return
      same_value = a <= b .and. a >= b
   end function same_value

   !> Does the pair (l, r) pass the comparison op?  NaN never passes.
   logical function real_ok(op, l, r, tol) result(ok)
      integer, intent(in) :: op
      real(real64), intent(in) :: l, r, tol
      real(real64) :: d
      logical :: known

      ok = .false.
      if (ieee_is_nan(l) .or. ieee_is_nan(r)) return
      select case (op)
      case (OP_EQ, OP_NE)
         ok = same_value(l, r)
         if (.not. ok) then
            call safe_difference(r, l, d, known)
            ok = known .and. abs(d) <= tol
         end if
         if (op == OP_NE) ok = .not. ok
      case (OP_REL)
         ok = same_value(l, r)
         if (.not. ok .and. .not. same_value(l, 0.0_real64)) then
            call safe_difference(r, l, d, known)
            if (known) then
               if (tol <= 1) then
                  ok = abs(d) <= tol*abs(l)
               else
                  ok = abs(d)/tol <= abs(l)
               end if
            end if
         end if
      case (OP_LT, OP_LE)
         ok = l < r
         if (op == OP_LE) ok = ok .or. same_value(l, r)
         if (.not. ok .and. tol > 0) then
            call safe_difference(l, r, d, known)
            ok = known .and. (d < tol .or. (op == OP_LE .and. d <= tol))
         end if
      case (OP_GT, OP_GE)
         ok = l > r
         if (op == OP_GE) ok = ok .or. same_value(l, r)
         if (.not. ok .and. tol > 0) then
            call safe_difference(r, l, d, known)
            ok = known .and. (d < tol .or. (op == OP_GE .and. d <= tol))
         end if
      end select
   end function real_ok

   !> Compare element by element (l and r flattened, shp the shape of the actual value,
   !> empty for scalars) and report the first failing element.
   subroutine real_compare(op, assertion, l, r, shp, tol, message, location)
      integer, intent(in) :: op
      character(len=*), intent(in) :: assertion
      real(real64), intent(in) :: l(:), r(:)
      integer, intent(in) :: shp(:)
      real(real64), intent(in) :: tol
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k, first, count
      real(real64) :: e, a, d
      logical :: known

      if (op == OP_REL) then
         do k = 1, size(l)
            if (same_value(l(k), 0.0_real64)) then
               call begin_failure(assertion, location)
               call index_detail(k, 1, shp)
               call detail('reason', 'expected value is zero: relative comparison undefined')
               call detail('actual', rstr(r(k)))
               call end_failure(message)
               return
            end if
         end do
      end if
      first = 0
      count = 0
      do k = 1, size(r)
         if (.not. real_ok(op, l(k), r(k), tol)) then
            count = count + 1
            if (first == 0) first = k
         end if
      end do
      if (count == 0) return

      e = l(first)
      a = r(first)
      call begin_failure(assertion, location)
      call index_detail(first, count, shp)
      select case (op)
      case (OP_EQ, OP_REL)
         call detail('expected', rstr(e))
         call detail('actual', rstr(a))
         call safe_difference(a, e, d, known)
         if (op == OP_EQ) then
            if (known) then
               call detail('difference', rstr(d) // '  (tolerance ' // rstr(tol) // ')')
            else
               call detail('difference', nonfinite_str(a, e) // '  (tolerance ' // rstr(tol) // ')')
            end if
         else
            if (known) then
               ! d/e cannot overflow when |e| >= 1; otherwise huge*|e| cannot either.
               if (abs(e) < 1) known = abs(d) <= huge(d)*abs(e)
            end if
            if (known) then
               call detail('rel. diff.', rstr(d/e) // '  (tolerance ' // rstr(tol) // ')')
            else
               call detail('rel. diff.', nonfinite_str(a, e) // '  (tolerance ' // rstr(tol) // ')')
            end if
         end if
      case (OP_NE)
         call detail('expected', 'a value different from ' // rstr(e) // '  (tolerance ' // rstr(tol) // ')')
         call detail('actual', rstr(a))
      case default
         call detail('lhs', rstr(e))
         call detail('rhs', rstr(a))
         call detail('expected', 'lhs ' // trim(op_str(op)) // ' rhs' // tol_str(tol))
      end select
      call end_failure(message)
   end subroutine real_compare

   !> Why a difference could not be printed.
   function nonfinite_str(a, b) result(s)
      real(real64), intent(in) :: a, b
      character(len=:), allocatable :: s

      if (ieee_is_finite(a) .and. ieee_is_finite(b)) then
         s = 'overflows'
      else
         s = 'not finite'
      end if
   end function nonfinite_str

   function op_str(op) result(s)
      integer, intent(in) :: op
      character(len=2) :: s

      select case (op)
      case (OP_LT)
         s = '< '
      case (OP_LE)
         s = '<='
      case (OP_GT)
         s = '> '
      case default
         s = '>='
      end select
   end function op_str

   function tol_str(tol) result(s)
      real(real64), intent(in) :: tol
      character(len=:), allocatable :: s

      s = ''
      if (tol > 0) s = '  (tolerance ' // rstr(tol) // ')'
   end function tol_str

   ! ================================================================ integer comparisons

   subroutine int_compare(op, assertion, l, r, shp, message, location)
      integer, intent(in) :: op
      character(len=*), intent(in) :: assertion
      integer(int64), intent(in) :: l(:), r(:)
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k, first, count
      logical :: ok
      integer(int64), parameter :: HALF = 2_int64**62

      first = 0
      count = 0
      do k = 1, size(r)
         select case (op)
         case (OP_EQ)
            ok = l(k) == r(k)
         case (OP_NE)
            ok = l(k) /= r(k)
         case (OP_LT)
            ok = l(k) < r(k)
         case (OP_LE)
            ok = l(k) <= r(k)
         case (OP_GT)
            ok = l(k) > r(k)
         case default
            ok = l(k) >= r(k)
         end select
         if (.not. ok) then
            count = count + 1
            if (first == 0) first = k
         end if
      end do
      if (count == 0) return

      call begin_failure(assertion, location)
      call index_detail(first, count, shp)
      select case (op)
      case (OP_EQ)
         call detail('expected', istr(l(first)))
         call detail('actual', istr(r(first)))
         if (abs(l(first)) <= HALF .and. abs(r(first)) <= HALF) &
            call detail('difference', istr(r(first) - l(first)))
      case (OP_NE)
         call detail('expected', 'a value different from ' // istr(l(first)))
         call detail('actual', istr(r(first)))
      case default
         call detail('lhs', istr(l(first)))
         call detail('rhs', istr(r(first)))
         call detail('expected', 'lhs ' // trim(op_str(op)) // ' rhs')
      end select
      call end_failure(message)
   end subroutine int_compare

   ! ================================================================ strings, logicals

   !> Strings are equal when they match after removing leading and trailing blanks
   !> (pFUnit's default whitespace=TRIM_ALL).
   subroutine assert_equal_string(expected, actual, message, location)
      character(len=*), intent(in) :: expected, actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      character(len=:), allocatable :: e, a
      integer :: k

      e = trim(adjustl(expected))
      a = trim(adjustl(actual))
      if (e == a .and. len(e) == len(a)) return
      call begin_failure('assertEqual', location)
      call detail('expected', '"' // e // '"')
      call detail('actual', '"' // a // '"')
      do k = 1, min(len(e), len(a))
         if (e(k:k) /= a(k:k)) exit
      end do
      call detail('difference', 'from character ' // istr(int(k, int64)) // &
                  ' (lengths ' // istr(int(len(e), int64)) // ' and ' // istr(int(len(a), int64)) // ')')
      call end_failure(message)
   end subroutine assert_equal_string

   subroutine assert_equal_string_01(expected, actual, message, location)
      character(len=*), intent(in) :: expected, actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      do k = 1, size(actual)
         call assert_equal_string(expected, actual(k), message, location)
      end do
   end subroutine assert_equal_string_01

   subroutine assert_equal_string_11(expected, actual, message, location)
      character(len=*), intent(in) :: expected(:), actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      do k = 1, size(actual)
         call assert_equal_string(expected(k), actual(k), message, location)
      end do
   end subroutine assert_equal_string_11

   subroutine logical_compare(assertion, e, a, shp, message, location)
      character(len=*), intent(in) :: assertion
      logical, intent(in) :: e(:), a(:)
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k, first, count

      first = 0
      count = 0
      do k = 1, size(a)
         if (e(k) .neqv. a(k)) then
            count = count + 1
            if (first == 0) first = k
         end if
      end do
      if (count == 0) return
      call begin_failure(assertion, location)
      call index_detail(first, count, shp)
      call detail('expected', lstr(e(first)))
      call detail('actual', lstr(a(first)))
      call end_failure(message)
   end subroutine logical_compare

   subroutine assert_equal_logical_0(expected, actual, unused, message, location)
      logical, intent(in) :: expected, actual
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call logical_compare('assertEqual', [expected], [actual], shape(actual), message, location)
   end subroutine assert_equal_logical_0

   subroutine assert_equal_logical_1(expected, actual, unused, message, location)
      logical, intent(in) :: expected(:), actual(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call logical_compare('assertEqual', expected, actual, shape(actual), message, location)
   end subroutine assert_equal_logical_1

   subroutine assert_equal_logical_01(expected, actual, unused, message, location)
      logical, intent(in) :: expected, actual(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call logical_compare('assertEqual', spread(expected, 1, size(actual)), actual, shape(actual), &
                           message, location)
   end subroutine assert_equal_logical_01

   subroutine assert_true_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call logical_compare('assertTrue', [.true.], [condition], shape(condition), message, location)
   end subroutine assert_true_0

   subroutine assert_true_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call logical_compare('assertTrue', spread(.true., 1, size(condition)), condition, shape(condition), &
                           message, location)
   end subroutine assert_true_1

   subroutine assert_false_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call logical_compare('assertFalse', [.false.], [condition], shape(condition), message, location)
   end subroutine assert_false_0

   subroutine assert_false_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call logical_compare('assertFalse', spread(.false., 1, size(condition)), condition, shape(condition), &
                           message, location)
   end subroutine assert_false_1

   subroutine assertAll(conditions, message, location)
      logical, intent(in) :: conditions(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call logical_compare('assertAll', spread(.true., 1, size(conditions)), conditions, shape(conditions), &
                           message, location)
   end subroutine assertAll

   subroutine assertNone(conditions, message, location)
      logical, intent(in) :: conditions(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call logical_compare('assertNone', spread(.false., 1, size(conditions)), conditions, shape(conditions), &
                           message, location)
   end subroutine assertNone

   subroutine assertAny(conditions, message, location)
      logical, intent(in) :: conditions(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (any(conditions)) return
      call fail_with('assertAny', 'all ' // istr(int(size(conditions), int64)) // ' elements are .false.', &
                     message, location)
   end subroutine assertAny

   subroutine assertNotAll(conditions, message, location)
      logical, intent(in) :: conditions(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. all(conditions)) return
      call fail_with('assertNotAll', 'all ' // istr(int(size(conditions), int64)) // ' elements are .true.', &
                     message, location)
   end subroutine assertNotAll

   !> Unconditional failure.
   subroutine assertFail(message, location)
      character(len=*), intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call fail_with('assertFail', '', message, location)
   end subroutine assertFail

   ! ================================================================ IEEE classes

   subroutine class_check(cls, assertion, x, shp, message, location)
      integer, intent(in) :: cls
      character(len=*), intent(in) :: assertion
      real(real64), intent(in) :: x(:)
      integer, intent(in) :: shp(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location
      integer :: k, first, count
      logical :: ok

      first = 0
      count = 0
      do k = 1, size(x)
         select case (cls)
         case (CLASS_FINITE)
            ok = ieee_is_finite(x(k))
         case (CLASS_NAN)
            ok = ieee_is_nan(x(k))
         case default  ! as pFUnit: "infinite" means "not finite", NaN included
            ok = .not. ieee_is_finite(x(k))
         end select
         if (.not. ok) then
            count = count + 1
            if (first == 0) first = k
         end if
      end do
      if (count == 0) return
      call begin_failure(assertion, location)
      call index_detail(first, count, shp)
      call detail('actual', rstr(x(first)))
      call end_failure(message)
   end subroutine class_check

   subroutine is_finite_r64_0(x, message, location)
      real(real64), intent(in) :: x
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call class_check(CLASS_FINITE, 'assertIsFinite', [x], shape(x), message, location)
   end subroutine is_finite_r64_0

   subroutine is_finite_r32_0(x, message, location)
      real(real32), intent(in) :: x
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call class_check(CLASS_FINITE, 'assertIsFinite', [real(x, real64)], shape(x), message, location)
   end subroutine is_finite_r32_0

   subroutine is_nan_r64_0(x, message, location)
      real(real64), intent(in) :: x
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call class_check(CLASS_NAN, 'assertIsNaN', [x], shape(x), message, location)
   end subroutine is_nan_r64_0

   subroutine is_nan_r32_0(x, message, location)
      real(real32), intent(in) :: x
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call class_check(CLASS_NAN, 'assertIsNaN', [real(x, real64)], shape(x), message, location)
   end subroutine is_nan_r32_0

   subroutine is_infinite_r64_0(x, message, location)
      real(real64), intent(in) :: x
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call class_check(CLASS_INFINITE, 'assertIsInfinite', [x], shape(x), message, location)
   end subroutine is_infinite_r64_0

   subroutine is_infinite_r32_0(x, message, location)
      real(real32), intent(in) :: x
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call class_check(CLASS_INFINITE, 'assertIsInfinite', [real(x, real64)], shape(x), message, location)
   end subroutine is_infinite_r32_0

   ! BEGIN GENERATED PROCEDURES (gen_funit.py)

   subroutine eq_r8_0_r8_0(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r8_0_r8_0

   subroutine eq_r8_0_r8_0_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_0_r8_0_r4

   subroutine eq_r8_0_r8_0_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_0_r8_0_r8

   subroutine eq_r4_0_r8_0(expected, actual, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r4_0_r8_0

   subroutine eq_r4_0_r8_0_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_0_r8_0_r4

   subroutine eq_r4_0_r8_0_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_0_r8_0_r8

   subroutine eq_i4_0_r8_0(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_i4_0_r8_0

   subroutine eq_i4_0_r8_0_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_0_r8_0_r4

   subroutine eq_i4_0_r8_0_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_0_r8_0_r8

   subroutine eq_r8_1_r8_1(expected, actual, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r8_1_r8_1

   subroutine eq_r8_1_r8_1_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_1_r8_1_r4

   subroutine eq_r8_1_r8_1_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_1_r8_1_r8

   subroutine eq_r4_1_r8_1(expected, actual, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r4_1_r8_1

   subroutine eq_r4_1_r8_1_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_1_r8_1_r4

   subroutine eq_r4_1_r8_1_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_1_r8_1_r8

   subroutine eq_i4_1_r8_1(expected, actual, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_i4_1_r8_1

   subroutine eq_i4_1_r8_1_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_1_r8_1_r4

   subroutine eq_i4_1_r8_1_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_1_r8_1_r8

   subroutine eq_r8_0_r8_1(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r8_0_r8_1

   subroutine eq_r8_0_r8_1_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_0_r8_1_r4

   subroutine eq_r8_0_r8_1_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_0_r8_1_r8

   subroutine eq_r4_0_r8_1(expected, actual, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r4_0_r8_1

   subroutine eq_r4_0_r8_1_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_0_r8_1_r4

   subroutine eq_r4_0_r8_1_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_0_r8_1_r8

   subroutine eq_i4_0_r8_1(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_i4_0_r8_1

   subroutine eq_i4_0_r8_1_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_0_r8_1_r4

   subroutine eq_i4_0_r8_1_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_0_r8_1_r8

   subroutine eq_r8_2_r8_2(expected, actual, message, location)
      real(real64), intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r8_2_r8_2

   subroutine eq_r8_2_r8_2_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_2_r8_2_r4

   subroutine eq_r8_2_r8_2_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_2_r8_2_r8

   subroutine eq_r4_2_r8_2(expected, actual, message, location)
      real, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r4_2_r8_2

   subroutine eq_r4_2_r8_2_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_2_r8_2_r4

   subroutine eq_r4_2_r8_2_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_2_r8_2_r8

   subroutine eq_i4_2_r8_2(expected, actual, message, location)
      integer, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_i4_2_r8_2

   subroutine eq_i4_2_r8_2_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_2_r8_2_r4

   subroutine eq_i4_2_r8_2_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_EQ, 'assertEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_2_r8_2_r8

   subroutine eq_r8_0_r8_2(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r8_0_r8_2

   subroutine eq_r8_0_r8_2_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_0_r8_2_r4

   subroutine eq_r8_0_r8_2_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r8_0_r8_2_r8

   subroutine eq_r4_0_r8_2(expected, actual, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_r4_0_r8_2

   subroutine eq_r4_0_r8_2_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_0_r8_2_r4

   subroutine eq_r4_0_r8_2_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_r4_0_r8_2_r8

   subroutine eq_i4_0_r8_2(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine eq_i4_0_r8_2

   subroutine eq_i4_0_r8_2_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_0_r8_2_r4

   subroutine eq_i4_0_r8_2_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_EQ, 'assertEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine eq_i4_0_r8_2_r8

   subroutine ne_r8_0_r8_0(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_r8_0_r8_0

   subroutine ne_r8_0_r8_0_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r8_0_r8_0_r4

   subroutine ne_r8_0_r8_0_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r8_0_r8_0_r8

   subroutine ne_r4_0_r8_0(expected, actual, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_r4_0_r8_0

   subroutine ne_r4_0_r8_0_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r4_0_r8_0_r4

   subroutine ne_r4_0_r8_0_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r4_0_r8_0_r8

   subroutine ne_i4_0_r8_0(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_i4_0_r8_0

   subroutine ne_i4_0_r8_0_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_i4_0_r8_0_r4

   subroutine ne_i4_0_r8_0_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_i4_0_r8_0_r8

   subroutine ne_r8_1_r8_1(expected, actual, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_r8_1_r8_1

   subroutine ne_r8_1_r8_1_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r8_1_r8_1_r4

   subroutine ne_r8_1_r8_1_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r8_1_r8_1_r8

   subroutine ne_r4_1_r8_1(expected, actual, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_r4_1_r8_1

   subroutine ne_r4_1_r8_1_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r4_1_r8_1_r4

   subroutine ne_r4_1_r8_1_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r4_1_r8_1_r8

   subroutine ne_i4_1_r8_1(expected, actual, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_i4_1_r8_1

   subroutine ne_i4_1_r8_1_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_i4_1_r8_1_r4

   subroutine ne_i4_1_r8_1_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_NE, 'assertNotEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_i4_1_r8_1_r8

   subroutine ne_r8_0_r8_1(expected, actual, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_r8_0_r8_1

   subroutine ne_r8_0_r8_1_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r8_0_r8_1_r4

   subroutine ne_r8_0_r8_1_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r8_0_r8_1_r8

   subroutine ne_r4_0_r8_1(expected, actual, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_r4_0_r8_1

   subroutine ne_r4_0_r8_1_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r4_0_r8_1_r4

   subroutine ne_r4_0_r8_1_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_r4_0_r8_1_r8

   subroutine ne_i4_0_r8_1(expected, actual, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), 0.0_real64, message, location)
   end subroutine ne_i4_0_r8_1

   subroutine ne_i4_0_r8_1_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_i4_0_r8_1_r4

   subroutine ne_i4_0_r8_1_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_NE, 'assertNotEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine ne_i4_0_r8_1_r8

   subroutine lt_r8_0_r8_0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_r8_0_r8_0

   subroutine lt_r8_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r8_0_r8_0_r4

   subroutine lt_r8_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r8_0_r8_0_r8

   subroutine lt_r4_0_r8_0(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_r4_0_r8_0

   subroutine lt_r4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r4_0_r8_0_r4

   subroutine lt_r4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r4_0_r8_0_r8

   subroutine lt_i4_0_r8_0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_i4_0_r8_0

   subroutine lt_i4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_i4_0_r8_0_r4

   subroutine lt_i4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_i4_0_r8_0_r8

   subroutine lt_r8_1_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_r8_1_r8_1

   subroutine lt_r8_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r8_1_r8_1_r4

   subroutine lt_r8_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r8_1_r8_1_r8

   subroutine lt_r4_1_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_r4_1_r8_1

   subroutine lt_r4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r4_1_r8_1_r4

   subroutine lt_r4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r4_1_r8_1_r8

   subroutine lt_i4_1_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_i4_1_r8_1

   subroutine lt_i4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_i4_1_r8_1_r4

   subroutine lt_i4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LT, 'assertLessThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_i4_1_r8_1_r8

   subroutine lt_r8_0_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_r8_0_r8_1

   subroutine lt_r8_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r8_0_r8_1_r4

   subroutine lt_r8_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r8_0_r8_1_r8

   subroutine lt_r4_0_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_r4_0_r8_1

   subroutine lt_r4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r4_0_r8_1_r4

   subroutine lt_r4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_r4_0_r8_1_r8

   subroutine lt_i4_0_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine lt_i4_0_r8_1

   subroutine lt_i4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_i4_0_r8_1_r4

   subroutine lt_i4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LT, 'assertLessThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine lt_i4_0_r8_1_r8

   subroutine le_r8_0_r8_0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_r8_0_r8_0

   subroutine le_r8_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r8_0_r8_0_r4

   subroutine le_r8_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r8_0_r8_0_r8

   subroutine le_r4_0_r8_0(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_r4_0_r8_0

   subroutine le_r4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r4_0_r8_0_r4

   subroutine le_r4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r4_0_r8_0_r8

   subroutine le_i4_0_r8_0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_i4_0_r8_0

   subroutine le_i4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_i4_0_r8_0_r4

   subroutine le_i4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_i4_0_r8_0_r8

   subroutine le_r8_1_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_r8_1_r8_1

   subroutine le_r8_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r8_1_r8_1_r4

   subroutine le_r8_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r8_1_r8_1_r8

   subroutine le_r4_1_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_r4_1_r8_1

   subroutine le_r4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r4_1_r8_1_r4

   subroutine le_r4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r4_1_r8_1_r8

   subroutine le_i4_1_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_i4_1_r8_1

   subroutine le_i4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_i4_1_r8_1_r4

   subroutine le_i4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_i4_1_r8_1_r8

   subroutine le_r8_0_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_r8_0_r8_1

   subroutine le_r8_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r8_0_r8_1_r4

   subroutine le_r8_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r8_0_r8_1_r8

   subroutine le_r4_0_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_r4_0_r8_1

   subroutine le_r4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r4_0_r8_1_r4

   subroutine le_r4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_r4_0_r8_1_r8

   subroutine le_i4_0_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine le_i4_0_r8_1

   subroutine le_i4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_i4_0_r8_1_r4

   subroutine le_i4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_LE, 'assertLessThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine le_i4_0_r8_1_r8

   subroutine gt_r8_0_r8_0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_r8_0_r8_0

   subroutine gt_r8_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r8_0_r8_0_r4

   subroutine gt_r8_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r8_0_r8_0_r8

   subroutine gt_r4_0_r8_0(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_r4_0_r8_0

   subroutine gt_r4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r4_0_r8_0_r4

   subroutine gt_r4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r4_0_r8_0_r8

   subroutine gt_i4_0_r8_0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_i4_0_r8_0

   subroutine gt_i4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_i4_0_r8_0_r4

   subroutine gt_i4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_i4_0_r8_0_r8

   subroutine gt_r8_1_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_r8_1_r8_1

   subroutine gt_r8_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r8_1_r8_1_r4

   subroutine gt_r8_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r8_1_r8_1_r8

   subroutine gt_r4_1_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_r4_1_r8_1

   subroutine gt_r4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r4_1_r8_1_r4

   subroutine gt_r4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r4_1_r8_1_r8

   subroutine gt_i4_1_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_i4_1_r8_1

   subroutine gt_i4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_i4_1_r8_1_r4

   subroutine gt_i4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GT, 'assertGreaterThan', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_i4_1_r8_1_r8

   subroutine gt_r8_0_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_r8_0_r8_1

   subroutine gt_r8_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r8_0_r8_1_r4

   subroutine gt_r8_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r8_0_r8_1_r8

   subroutine gt_r4_0_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_r4_0_r8_1

   subroutine gt_r4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r4_0_r8_1_r4

   subroutine gt_r4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_r4_0_r8_1_r8

   subroutine gt_i4_0_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine gt_i4_0_r8_1

   subroutine gt_i4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_i4_0_r8_1_r4

   subroutine gt_i4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GT, 'assertGreaterThan', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine gt_i4_0_r8_1_r8

   subroutine ge_r8_0_r8_0(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_r8_0_r8_0

   subroutine ge_r8_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r8_0_r8_0_r4

   subroutine ge_r8_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r8_0_r8_0_r8

   subroutine ge_r4_0_r8_0(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_r4_0_r8_0

   subroutine ge_r4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r4_0_r8_0_r4

   subroutine ge_r4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r4_0_r8_0_r8

   subroutine ge_i4_0_r8_0(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_i4_0_r8_0

   subroutine ge_i4_0_r8_0_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_i4_0_r8_0_r4

   subroutine ge_i4_0_r8_0_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real([lhs], real64), &
                        real([rhs], real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_i4_0_r8_0_r8

   subroutine ge_r8_1_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_r8_1_r8_1

   subroutine ge_r8_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r8_1_r8_1_r4

   subroutine ge_r8_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r8_1_r8_1_r8

   subroutine ge_r4_1_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_r4_1_r8_1

   subroutine ge_r4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r4_1_r8_1_r4

   subroutine ge_r4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r4_1_r8_1_r8

   subroutine ge_i4_1_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_i4_1_r8_1

   subroutine ge_i4_1_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_i4_1_r8_1_r4

   subroutine ge_i4_1_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs(:)
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        real(lhs, real64), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_i4_1_r8_1_r8

   subroutine ge_r8_0_r8_1(lhs, rhs, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_r8_0_r8_1

   subroutine ge_r8_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r8_0_r8_1_r4

   subroutine ge_r8_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real(real64), intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r8_0_r8_1_r8

   subroutine ge_r4_0_r8_1(lhs, rhs, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_r4_0_r8_1

   subroutine ge_r4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r4_0_r8_1_r4

   subroutine ge_r4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      real, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_r4_0_r8_1_r8

   subroutine ge_i4_0_r8_1(lhs, rhs, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), 0.0_real64, message, location)
   end subroutine ge_i4_0_r8_1

   subroutine ge_i4_0_r8_1_r4(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_i4_0_r8_1_r4

   subroutine ge_i4_0_r8_1_r8(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(real64), intent(in) :: rhs(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_GE, 'assertGreaterThanOrEqual', &
                        spread(real(lhs, real64), 1, size(rhs)), &
                        real(rhs, real64), &
                        shape(rhs), real(tolerance, real64), message, location)
   end subroutine ge_i4_0_r8_1_r8

   subroutine rel_r8_0_r8_0_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_0_r8_0_r4

   subroutine rel_r8_0_r8_0_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_0_r8_0_r8

   subroutine rel_r4_0_r8_0_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_0_r8_0_r4

   subroutine rel_r4_0_r8_0_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_0_r8_0_r8

   subroutine rel_i4_0_r8_0_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_0_r8_0_r4

   subroutine rel_i4_0_r8_0_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real([expected], real64), &
                        real([actual], real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_0_r8_0_r8

   subroutine rel_r8_1_r8_1_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_1_r8_1_r4

   subroutine rel_r8_1_r8_1_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_1_r8_1_r8

   subroutine rel_r4_1_r8_1_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_1_r8_1_r4

   subroutine rel_r4_1_r8_1_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_1_r8_1_r8

   subroutine rel_i4_1_r8_1_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_1_r8_1_r4

   subroutine rel_i4_1_r8_1_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:)
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(expected, real64), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_1_r8_1_r8

   subroutine rel_r8_0_r8_1_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_0_r8_1_r4

   subroutine rel_r8_0_r8_1_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_0_r8_1_r8

   subroutine rel_r4_0_r8_1_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_0_r8_1_r4

   subroutine rel_r4_0_r8_1_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_0_r8_1_r8

   subroutine rel_i4_0_r8_1_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_0_r8_1_r4

   subroutine rel_i4_0_r8_1_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(actual, real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_0_r8_1_r8

   subroutine rel_r8_2_r8_2_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_2_r8_2_r4

   subroutine rel_r8_2_r8_2_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_2_r8_2_r8

   subroutine rel_r4_2_r8_2_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_2_r8_2_r4

   subroutine rel_r4_2_r8_2_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_2_r8_2_r8

   subroutine rel_i4_2_r8_2_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_2_r8_2_r4

   subroutine rel_i4_2_r8_2_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected(:, :)
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertRelativelyEqual', shape(expected), shape(actual), message, location)) return
      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        real(reshape(expected, [size(expected)]), real64), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_2_r8_2_r8

   subroutine rel_r8_0_r8_2_r4(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_0_r8_2_r4

   subroutine rel_r8_0_r8_2_r8(expected, actual, tolerance, message, location)
      real(real64), intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r8_0_r8_2_r8

   subroutine rel_r4_0_r8_2_r4(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_0_r8_2_r4

   subroutine rel_r4_0_r8_2_r8(expected, actual, tolerance, message, location)
      real, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_r4_0_r8_2_r8

   subroutine rel_i4_0_r8_2_r4(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real, intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_0_r8_2_r4

   subroutine rel_i4_0_r8_2_r8(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(real64), intent(in) :: actual(:, :)
      real(real64), intent(in) :: tolerance
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call real_compare(OP_REL, 'assertRelativelyEqual', &
                        spread(real(expected, real64), 1, size(actual)), &
                        real(reshape(actual, [size(actual)]), real64), &
                        shape(actual), real(tolerance, real64), message, location)
   end subroutine rel_i4_0_r8_2_r8

   subroutine eq_i4_0_i4_0(expected, actual, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       int([expected], int64), &
                       int([actual], int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_0_i4_0

   subroutine eq_i8_0_i8_0(expected, actual, message, location)
      integer(int64), intent(in) :: expected
      integer(int64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       int([expected], int64), &
                       int([actual], int64), &
                       shape(actual), message, location)
   end subroutine eq_i8_0_i8_0

   subroutine eq_i4_0_i8_0(expected, actual, message, location)
      integer, intent(in) :: expected
      integer(int64), intent(in) :: actual
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       int([expected], int64), &
                       int([actual], int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_0_i8_0

   subroutine eq_i4_1_i4_1(expected, actual, message, location)
      integer, intent(in) :: expected(:)
      integer, intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call int_compare(OP_EQ, 'assertEqual', &
                       int(expected, int64), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_1_i4_1

   subroutine eq_i8_1_i8_1(expected, actual, message, location)
      integer(int64), intent(in) :: expected(:)
      integer(int64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call int_compare(OP_EQ, 'assertEqual', &
                       int(expected, int64), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine eq_i8_1_i8_1

   subroutine eq_i4_0_i4_1(expected, actual, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_0_i4_1

   subroutine eq_i8_0_i8_1(expected, actual, message, location)
      integer(int64), intent(in) :: expected
      integer(int64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine eq_i8_0_i8_1

   subroutine eq_i4_0_i8_1(expected, actual, message, location)
      integer, intent(in) :: expected
      integer(int64), intent(in) :: actual(:)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_0_i8_1

   subroutine eq_i4_2_i4_2(expected, actual, message, location)
      integer, intent(in) :: expected(:, :)
      integer, intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call int_compare(OP_EQ, 'assertEqual', &
                       int(reshape(expected, [size(expected)]), int64), &
                       int(reshape(actual, [size(actual)]), int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_2_i4_2

   subroutine eq_i8_2_i8_2(expected, actual, message, location)
      integer(int64), intent(in) :: expected(:, :)
      integer(int64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (.not. conformable('assertEqual', shape(expected), shape(actual), message, location)) return
      call int_compare(OP_EQ, 'assertEqual', &
                       int(reshape(expected, [size(expected)]), int64), &
                       int(reshape(actual, [size(actual)]), int64), &
                       shape(actual), message, location)
   end subroutine eq_i8_2_i8_2

   subroutine eq_i4_0_i4_2(expected, actual, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(reshape(actual, [size(actual)]), int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_0_i4_2

   subroutine eq_i8_0_i8_2(expected, actual, message, location)
      integer(int64), intent(in) :: expected
      integer(int64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(reshape(actual, [size(actual)]), int64), &
                       shape(actual), message, location)
   end subroutine eq_i8_0_i8_2

   subroutine eq_i4_0_i8_2(expected, actual, message, location)
      integer, intent(in) :: expected
      integer(int64), intent(in) :: actual(:, :)
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      call int_compare(OP_EQ, 'assertEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(reshape(actual, [size(actual)]), int64), &
                       shape(actual), message, location)
   end subroutine eq_i4_0_i8_2

   subroutine ne_i4_0_i4_0(expected, actual, unused, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_NE, 'assertNotEqual', &
                       int([expected], int64), &
                       int([actual], int64), &
                       shape(actual), message, location)
   end subroutine ne_i4_0_i4_0

   subroutine ne_i8_0_i8_0(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected
      integer(int64), intent(in) :: actual
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_NE, 'assertNotEqual', &
                       int([expected], int64), &
                       int([actual], int64), &
                       shape(actual), message, location)
   end subroutine ne_i8_0_i8_0

   subroutine ne_i4_0_i8_0(expected, actual, unused, message, location)
      integer, intent(in) :: expected
      integer(int64), intent(in) :: actual
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_NE, 'assertNotEqual', &
                       int([expected], int64), &
                       int([actual], int64), &
                       shape(actual), message, location)
   end subroutine ne_i4_0_i8_0

   subroutine ne_i4_1_i4_1(expected, actual, unused, message, location)
      integer, intent(in) :: expected(:)
      integer, intent(in) :: actual(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call int_compare(OP_NE, 'assertNotEqual', &
                       int(expected, int64), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine ne_i4_1_i4_1

   subroutine ne_i8_1_i8_1(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected(:)
      integer(int64), intent(in) :: actual(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertNotEqual', shape(expected), shape(actual), message, location)) return
      call int_compare(OP_NE, 'assertNotEqual', &
                       int(expected, int64), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine ne_i8_1_i8_1

   subroutine ne_i4_0_i4_1(expected, actual, unused, message, location)
      integer, intent(in) :: expected
      integer, intent(in) :: actual(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_NE, 'assertNotEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine ne_i4_0_i4_1

   subroutine ne_i8_0_i8_1(expected, actual, unused, message, location)
      integer(int64), intent(in) :: expected
      integer(int64), intent(in) :: actual(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_NE, 'assertNotEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine ne_i8_0_i8_1

   subroutine ne_i4_0_i8_1(expected, actual, unused, message, location)
      integer, intent(in) :: expected
      integer(int64), intent(in) :: actual(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_NE, 'assertNotEqual', &
                       spread(int(expected, int64), 1, size(actual)), &
                       int(actual, int64), &
                       shape(actual), message, location)
   end subroutine ne_i4_0_i8_1

   subroutine lt_i4_0_i4_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LT, 'assertLessThan', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine lt_i4_0_i4_0

   subroutine lt_i8_0_i8_0(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LT, 'assertLessThan', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine lt_i8_0_i8_0

   subroutine lt_i4_0_i8_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LT, 'assertLessThan', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine lt_i4_0_i8_0

   subroutine lt_i4_1_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs(:)
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_LT, 'assertLessThan', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine lt_i4_1_i4_1

   subroutine lt_i8_1_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:)
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertLessThan', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_LT, 'assertLessThan', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine lt_i8_1_i8_1

   subroutine lt_i4_0_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LT, 'assertLessThan', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine lt_i4_0_i4_1

   subroutine lt_i8_0_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LT, 'assertLessThan', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine lt_i8_0_i8_1

   subroutine lt_i4_0_i8_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LT, 'assertLessThan', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine lt_i4_0_i8_1

   subroutine le_i4_0_i4_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine le_i4_0_i4_0

   subroutine le_i8_0_i8_0(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine le_i8_0_i8_0

   subroutine le_i4_0_i8_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine le_i4_0_i8_0

   subroutine le_i4_1_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs(:)
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine le_i4_1_i4_1

   subroutine le_i8_1_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:)
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertLessThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine le_i8_1_i8_1

   subroutine le_i4_0_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine le_i4_0_i4_1

   subroutine le_i8_0_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine le_i8_0_i8_1

   subroutine le_i4_0_i8_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_LE, 'assertLessThanOrEqual', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine le_i4_0_i8_1

   subroutine gt_i4_0_i4_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GT, 'assertGreaterThan', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine gt_i4_0_i4_0

   subroutine gt_i8_0_i8_0(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GT, 'assertGreaterThan', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine gt_i8_0_i8_0

   subroutine gt_i4_0_i8_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GT, 'assertGreaterThan', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine gt_i4_0_i8_0

   subroutine gt_i4_1_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs(:)
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_GT, 'assertGreaterThan', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine gt_i4_1_i4_1

   subroutine gt_i8_1_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:)
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertGreaterThan', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_GT, 'assertGreaterThan', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine gt_i8_1_i8_1

   subroutine gt_i4_0_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GT, 'assertGreaterThan', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine gt_i4_0_i4_1

   subroutine gt_i8_0_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GT, 'assertGreaterThan', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine gt_i8_0_i8_1

   subroutine gt_i4_0_i8_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GT, 'assertGreaterThan', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine gt_i4_0_i8_1

   subroutine ge_i4_0_i4_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine ge_i4_0_i4_0

   subroutine ge_i8_0_i8_0(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine ge_i8_0_i8_0

   subroutine ge_i4_0_i8_0(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       int([lhs], int64), &
                       int([rhs], int64), &
                       shape(rhs), message, location)
   end subroutine ge_i4_0_i8_0

   subroutine ge_i4_1_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs(:)
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine ge_i4_1_i4_1

   subroutine ge_i8_1_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs(:)
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      if (.not. conformable('assertGreaterThanOrEqual', shape(lhs), shape(rhs), message, location)) return
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       int(lhs, int64), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine ge_i8_1_i8_1

   subroutine ge_i4_0_i4_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer, intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine ge_i4_0_i4_1

   subroutine ge_i8_0_i8_1(lhs, rhs, unused, message, location)
      integer(int64), intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine ge_i8_0_i8_1

   subroutine ge_i4_0_i8_1(lhs, rhs, unused, message, location)
      integer, intent(in) :: lhs
      integer(int64), intent(in) :: rhs(:)
      class(KeywordEnforcer), optional, intent(in) :: unused
      character(len=*), optional, intent(in) :: message
      type(SourceLocation), optional, intent(in) :: location

      if (present(unused)) continue
      call int_compare(OP_GE, 'assertGreaterThanOrEqual', &
                       spread(int(lhs, int64), 1, size(rhs)), &
                       int(rhs, int64), &
                       shape(rhs), message, location)
   end subroutine ge_i4_0_i8_1

   ! END GENERATED PROCEDURES

end module funit
