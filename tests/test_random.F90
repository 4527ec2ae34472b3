!> pound's own generator against an independent reference (tests/reference/random_reference.py,
!> Python integers masked to 64 bits) and the moments of its uniform and normal numbers.
module test_random
   use funit
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_random, only: random_t, random_seed_stream, random_next, random_uniform, &
                           random_normal, splitmix64_next
   implicit none

   !> Sample size for the moments.
   integer, parameter :: n_big = 1000000

contains

   !@test
   subroutine test_splitmix64_published()
      ! splitmix64 from state 0: the published first outputs (Vigna's splitmix64.c).
      integer(int64) :: state, x
      integer(int64), parameter :: expected(3) = [int(z'E220A8397B1DCDAF', int64), &
         int(z'6E789E6AA1B965F4', int64), int(z'06C45D188009454F', int64)]
      integer :: i

      state = 0_int64
      do i = 1, 3
         call splitmix64_next(state, x)
#line 27 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(expected(i), x, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 27) )
  if (anyExceptions()) return
#line 28 "/work/wt/suite-blocks/tests/test_random.pf"
      end do
   end subroutine test_splitmix64_published

   !@test
   subroutine test_words_seed_42()
      ! State words and the first xoshiro256** outputs for seed 42 (reference script).
      integer(int64), parameter :: state(4) = [-4767286540954276203_int64, &
         2949826092126892291_int64, 5139283748462763858_int64, 6349198060258255764_int64]
      integer(int64), parameter :: words(5) = [1546998764402558742_int64, &
         6990951692964543102_int64, -5902157311460992607_int64, &
         -1389169964527427423_int64, -151191095644234140_int64]
      type(random_t) :: rng
      integer(int64) :: x
      integer :: i

      call random_seed_stream(rng, 42_int64)
      do i = 1, 4
#line 45 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(state(i), rng%s(i), &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 45) )
  if (anyExceptions()) return
#line 46 "/work/wt/suite-blocks/tests/test_random.pf"
      end do
      do i = 1, 5
         call random_next(rng, x)
#line 49 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(words(i), x, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 49) )
  if (anyExceptions()) return
#line 50 "/work/wt/suite-blocks/tests/test_random.pf"
      end do
   end subroutine test_words_seed_42

   !@test
   subroutine test_words_negative_seed()
      ! Seed -7 is read as its two's-complement pattern (reference script with seed -7).
      integer(int64), parameter :: words(3) = [-935278008730389822_int64, &
         -2984799092062921764_int64, 8317729841091847865_int64]
      type(random_t) :: rng
      integer(int64) :: x
      integer :: i

      call random_seed_stream(rng, -7_int64)
      do i = 1, 3
         call random_next(rng, x)
#line 65 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(words(i), x, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 65) )
  if (anyExceptions()) return
#line 66 "/work/wt/suite-blocks/tests/test_random.pf"
      end do
   end subroutine test_words_negative_seed

   !@test
   subroutine test_uniform_seed_42()
      ! Uniforms are exact: compared bit for bit.
      real(dp), parameter :: expected(5) = [0.08386297105988227_dp, 0.3789802506626686_dp, &
         0.6800434110281394_dp, 0.9246929453253877_dp, 0.9918039142821028_dp]
      type(random_t) :: rng
      real(dp) :: u(5)

      call random_seed_stream(rng, 42_int64)
      call random_uniform(rng, u)
#line 79 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(expected, u, tolerance=0.0_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 79) )
  if (anyExceptions()) return
#line 80 "/work/wt/suite-blocks/tests/test_random.pf"
   end subroutine test_uniform_seed_42

   !@test
   subroutine test_normal_seed_42()
      ! Normals use the platform's log: 1e-15 relative at most.
      real(dp), parameter :: expected(6) = [-0.7262191382447862_dp, &
         -0.21119691823196007_dp, 0.22162270150359312_dp, 0.5227716877560142_dp, &
         0.46417731016247327_dp, 0.7409788916865558_dp]
      type(random_t) :: rng
      real(dp) :: z(6)

      call random_seed_stream(rng, 42_int64)
      call random_normal(rng, z)
#line 93 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(expected, z, tolerance=1.0e-15_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 93) )
  if (anyExceptions()) return
#line 94 "/work/wt/suite-blocks/tests/test_random.pf"
   end subroutine test_normal_seed_42

   !@test
   subroutine test_array_equals_scalar_calls()
      ! An array call is the same stream as calls one by one, spare included.
      type(random_t) :: r1, r2
      real(dp) :: a(7), b(7)
      integer :: i

      call random_seed_stream(r1, 2026_int64)
      call random_seed_stream(r2, 2026_int64)
      call random_normal(r1, a)
      do i = 1, 7
         call random_normal(r2, b(i))
      end do
#line 109 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(a, b, tolerance=0.0_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 109) )
  if (anyExceptions()) return
#line 110 "/work/wt/suite-blocks/tests/test_random.pf"
      call random_uniform(r1, a)
      do i = 1, 7
         call random_uniform(r2, b(i))
      end do
#line 114 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(a, b, tolerance=0.0_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 114) )
  if (anyExceptions()) return
#line 115 "/work/wt/suite-blocks/tests/test_random.pf"
   end subroutine test_array_equals_scalar_calls

   !@test
   subroutine test_seeds_differ()
      ! Neighbouring seeds give unrelated streams; re-seeding restarts the stream.
      type(random_t) :: r1, r2
      real(dp) :: a(1000), b(1000), c(1000)
      integer :: i, same

      call random_seed_stream(r1, 1_int64)
      call random_seed_stream(r2, 2_int64)
      call random_uniform(r1, a)
      call random_uniform(r2, b)
      same = 0
      do i = 1, size(a)
         if (a(i) == b(i)) same = same + 1
      end do
#line 132 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(0, same, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 132) )
  if (anyExceptions()) return
#line 133 "/work/wt/suite-blocks/tests/test_random.pf"
#line 133 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertLessThan(abs(correlation(a, b)), 0.1_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 133) )
  if (anyExceptions()) return
#line 134 "/work/wt/suite-blocks/tests/test_random.pf"
      call random_seed_stream(r1, 1_int64)
      call random_uniform(r1, c)
#line 136 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(a, c, tolerance=0.0_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 136) )
  if (anyExceptions()) return
#line 137 "/work/wt/suite-blocks/tests/test_random.pf"
   end subroutine test_seeds_differ

   !@test
   subroutine test_uniform_moments()
      ! 1e6 uniforms: mean 1/2 (sd 2.9e-4), variance 1/12 (sd 7.5e-5), lag-one correlation
      ! 0 (sd 1e-3), all strictly inside (0, 1); tolerances about five standard deviations.
      type(random_t) :: rng
      real(dp), allocatable :: u(:)
      real(dp) :: mean, var, lag1

      allocate (u(n_big))
      call random_seed_stream(rng, 12345_int64)
      call random_uniform(rng, u)
      mean = sum(u)/n_big
      var = sum((u - mean)**2)/(n_big - 1)
      lag1 = correlation(u(1:n_big - 1), u(2:n_big))
#line 153 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(0.5_dp, mean, tolerance=1.5e-3_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 153) )
  if (anyExceptions()) return
#line 154 "/work/wt/suite-blocks/tests/test_random.pf"
#line 154 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(1.0_dp/12.0_dp, var, tolerance=4.0e-4_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 154) )
  if (anyExceptions()) return
#line 155 "/work/wt/suite-blocks/tests/test_random.pf"
#line 155 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(0.0_dp, lag1, tolerance=5.0e-3_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 155) )
  if (anyExceptions()) return
#line 156 "/work/wt/suite-blocks/tests/test_random.pf"
#line 156 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertGreaterThan(minval(u), 0.0_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 156) )
  if (anyExceptions()) return
#line 157 "/work/wt/suite-blocks/tests/test_random.pf"
#line 157 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertLessThan(maxval(u), 1.0_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 157) )
  if (anyExceptions()) return
#line 158 "/work/wt/suite-blocks/tests/test_random.pf"
#line 158 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(0.1_dp, count(u < 0.1_dp)/real(n_big, dp), tolerance=1.5e-3_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 158) )
  if (anyExceptions()) return
#line 159 "/work/wt/suite-blocks/tests/test_random.pf"
   end subroutine test_uniform_moments

   !@test
   subroutine test_normal_moments()
      ! 1e6 normals: mean 0 (sd 1e-3), variance 1 (sd 1.4e-3), skewness 0 (sd 2.4e-3),
      ! kurtosis 3 (sd 4.9e-3), P(|z| < 1) = 0.6827 (sd 4.7e-4); about five sd.
      type(random_t) :: rng
      real(dp), allocatable :: z(:)
      real(dp) :: mean, var, skew, kurt, inside

      allocate (z(n_big))
      call random_seed_stream(rng, 777_int64)
      call random_normal(rng, z)
      mean = sum(z)/n_big
      var = sum((z - mean)**2)/(n_big - 1)
      skew = sum((z - mean)**3)/n_big/var**1.5_dp
      kurt = sum((z - mean)**4)/n_big/var**2
      inside = count(abs(z) < 1.0_dp)/real(n_big, dp)
#line 177 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(0.0_dp, mean, tolerance=5.0e-3_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 177) )
  if (anyExceptions()) return
#line 178 "/work/wt/suite-blocks/tests/test_random.pf"
#line 178 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(1.0_dp, var, tolerance=7.0e-3_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 178) )
  if (anyExceptions()) return
#line 179 "/work/wt/suite-blocks/tests/test_random.pf"
#line 179 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(0.0_dp, skew, tolerance=1.2e-2_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 179) )
  if (anyExceptions()) return
#line 180 "/work/wt/suite-blocks/tests/test_random.pf"
#line 180 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(3.0_dp, kurt, tolerance=2.5e-2_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 180) )
  if (anyExceptions()) return
#line 181 "/work/wt/suite-blocks/tests/test_random.pf"
#line 181 "/work/wt/suite-blocks/tests/test_random.pf"
  call assertEqual(erf(1.0_dp/sqrt(2.0_dp)), inside, tolerance=2.5e-3_dp, &
 & location=SourceLocation( &
 & 'test_random.pf', &
 & 181) )
  if (anyExceptions()) return
#line 182 "/work/wt/suite-blocks/tests/test_random.pf"
   end subroutine test_normal_moments

   !> Sample correlation coefficient of x and y.
   pure function correlation(x, y) result(r)
      real(dp), intent(in) :: x(:), y(:)
      real(dp) :: r
      real(dp) :: mx, my

      mx = sum(x)/size(x)
      my = sum(y)/size(y)
      r = sum((x - mx)*(y - my))/sqrt(sum((x - mx)**2)*sum((y - my)**2))
   end function correlation

end module test_random

module Wraptest_random
   use FUnit
   use test_random
   implicit none
   private

contains


end module Wraptest_random

function test_random_suite() result(suite)
   use FUnit
   use test_random
   use Wraptest_random
   implicit none
   type (TestSuite) :: suite

   class (Test), allocatable :: t

   suite = TestSuite('test_random_suite')

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_splitmix64_published', &
      test_splitmix64_published))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_words_seed_42', &
      test_words_seed_42))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_words_negative_seed', &
      test_words_negative_seed))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_uniform_seed_42', &
      test_uniform_seed_42))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_normal_seed_42', &
      test_normal_seed_42))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_array_equals_scalar_calls', &
      test_array_equals_scalar_calls))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_seeds_differ', &
      test_seeds_differ))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_uniform_moments', &
      test_uniform_moments))
   call suite%addTest(t)

   if(allocated(t)) deallocate(t)
   allocate(t, source=TestMethod('test_normal_moments', &
      test_normal_moments))
   call suite%addTest(t)


end function test_random_suite

