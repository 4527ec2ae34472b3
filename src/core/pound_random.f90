!> pound's own pseudo-random numbers: the same seed gives the same stream on every machine and
!> compiler.
!>
!> * Generator: xoshiro256** (Blackman and Vigna 2018, period 2^256 - 1) on four 64-bit words,
!>   seeded from one integer by splitmix64 (Steele, Lea and Flood 2014), exactly as the
!>   reference C code does it. All arithmetic is on the bit patterns of `int64` words with
!>   operations whose result the Fortran standard defines (`ieor`, `iand`, `ior`, `ishft`,
!>   `ishftc`): sums and products modulo 2^64 are built from 32-bit (and 16-bit) halves so that
!>   no signed integer ever overflows.
!> * Uniform: u = (x >> 12 + 1/2) 2^-52 from the 52 high bits of a word: exactly representable,
!>   strictly inside (0, 1), symmetric about 1/2, bit-identical everywhere.
!> * Standard normal: Marsaglia's polar method on pairs of uniforms v = 2u - 1 (rejecting
!>   s = v1^2 + v2^2 >= 1), z = v sqrt(-2 ln(s)/s); the second value of a pair is kept for the
!>   next call. Besides IEEE arithmetic and `sqrt` (both correctly rounded) it uses only `log`,
!>   so normals agree everywhere to the last bit of the platform's `log` (1e-15 relative).
module pound_random
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   implicit none
   private

   public :: random_t, random_seed_stream, random_next, random_uniform, random_normal
   public :: splitmix64_next

   !> State of one stream. Initialise it with `random_seed_stream` before use.
   type :: random_t
      !> xoshiro256** state words.
      integer(int64) :: s(4) = 0_int64
      !> A second normal from the last polar pair is waiting in `spare`.
      logical :: has_spare = .false.
      !> The waiting normal.
      real(dp) :: spare = 0.0_dp
   end type random_t

   !> Start a stream from an integer seed of either kind (default or int64).
   interface random_seed_stream
      module procedure seed_int64, seed_default
   end interface random_seed_stream

   !> Uniform numbers in (0, 1): one, or an array filled in order.
   interface random_uniform
      module procedure uniform_scalar, uniform_array
   end interface random_uniform

   !> Standard normal numbers (mean 0, variance 1): one, or an array filled in order.
   interface random_normal
      module procedure normal_scalar, normal_array
   end interface random_normal

   !> Low 32 bits of a word.
   integer(int64), parameter :: mask32 = int(z'FFFFFFFF', int64)
   !> Low 16 bits of a word.
   integer(int64), parameter :: mask16 = int(z'FFFF', int64)
   !> splitmix64 constants.
   integer(int64), parameter :: golden = int(z'9E3779B97F4A7C15', int64)
   integer(int64), parameter :: mix1 = int(z'BF58476D1CE4E5B9', int64)
   integer(int64), parameter :: mix2 = int(z'94D049BB133111EB', int64)

contains

   !> Start a stream from an integer seed (any value, negative ones included, read as its
   !> 64-bit two's-complement pattern): the four state words are four successive splitmix64
   !> outputs from that seed.
   pure subroutine seed_int64(rng, seed)
      !> Stream to initialise.
      type(random_t), intent(out) :: rng
      !> Seed.
      integer(int64), intent(in) :: seed
      integer(int64) :: sm
      integer :: i

      sm = seed
      do i = 1, 4
         call splitmix64_next(sm, rng%s(i))
      end do
      rng%has_spare = .false.
      rng%spare = 0.0_dp
   end subroutine seed_int64

   !> `seed_int64` for a default-kind integer seed (the same stream as int(seed, int64)).
   pure subroutine seed_default(rng, seed)
      !> Stream to initialise.
      type(random_t), intent(out) :: rng
      !> Seed.
      integer, intent(in) :: seed

      call seed_int64(rng, int(seed, int64))
   end subroutine seed_default

   !> One splitmix64 step: state += 0x9E3779B97F4A7C15, output = mix(state).
   pure subroutine splitmix64_next(state, x)
      !> splitmix64 state, advanced.
      integer(int64), intent(inout) :: state
      !> Output word.
      integer(int64), intent(out) :: x

      state = add64(state, golden)
      x = state
      x = mul64(ieor(x, ishft(x, -30)), mix1)
      x = mul64(ieor(x, ishft(x, -27)), mix2)
      x = ieor(x, ishft(x, -31))
   end subroutine splitmix64_next

   !> Next 64-bit word of the stream (xoshiro256**: rotl(s1 * 5, 7) * 9, then the state update).
   pure subroutine random_next(rng, x)
      !> Stream, advanced by one.
      type(random_t), intent(inout) :: rng
      !> Output word (its bit pattern; negative values are words with the top bit set).
      integer(int64), intent(out) :: x
      integer(int64) :: t, s1

      s1 = rng%s(2)
      t = ishftc(add64(s1, ishft(s1, 2)), 7)
      x = add64(t, ishft(t, 3))
      t = ishft(s1, 17)
      rng%s(3) = ieor(rng%s(3), rng%s(1))
      rng%s(4) = ieor(rng%s(4), rng%s(2))
      rng%s(2) = ieor(rng%s(2), rng%s(3))
      rng%s(1) = ieor(rng%s(1), rng%s(4))
      rng%s(3) = ieor(rng%s(3), t)
      rng%s(4) = ishftc(rng%s(4), 45)
   end subroutine random_next

   !> One uniform number u = (x >> 12 + 1/2) 2^-52, strictly inside (0, 1).
   pure subroutine uniform_scalar(rng, u)
      !> Stream, advanced by one.
      type(random_t), intent(inout) :: rng
      !> Uniform number.
      real(dp), intent(out) :: u
      integer(int64) :: x

      call random_next(rng, x)
      u = (real(ishft(x, -12), dp) + 0.5_dp)*2.0_dp**(-52)
   end subroutine uniform_scalar

   !> Fill `u` with uniform numbers, u(1) first.
   pure subroutine uniform_array(rng, u)
      !> Stream, advanced by size(u).
      type(random_t), intent(inout) :: rng
      !> Uniform numbers.
      real(dp), intent(out) :: u(:)
      integer :: i

      do i = 1, size(u)
         call uniform_scalar(rng, u(i))
      end do
   end subroutine uniform_array

   !> One standard normal number (polar method; every other call uses the pair's spare).
   pure subroutine normal_scalar(rng, z)
      !> Stream, advanced by a whole number of pairs of uniforms when no spare is waiting.
      type(random_t), intent(inout) :: rng
      !> Standard normal number.
      real(dp), intent(out) :: z
      real(dp) :: v1, v2, s, f

      if (rng%has_spare) then
         z = rng%spare
         rng%has_spare = .false.
         return
      end if
      do
         call uniform_scalar(rng, v1)
         call uniform_scalar(rng, v2)
         v1 = 2.0_dp*v1 - 1.0_dp
         v2 = 2.0_dp*v2 - 1.0_dp
         s = v1*v1 + v2*v2
         if (s < 1.0_dp .and. s > 0.0_dp) exit
      end do
      f = sqrt(-2.0_dp*log(s)/s)
      z = v1*f
      rng%spare = v2*f
      rng%has_spare = .true.
   end subroutine normal_scalar

   !> Fill `z` with standard normal numbers, z(1) first.
   pure subroutine normal_array(rng, z)
      !> Stream, advanced.
      type(random_t), intent(inout) :: rng
      !> Standard normal numbers.
      real(dp), intent(out) :: z(:)
      integer :: i

      do i = 1, size(z)
         call normal_scalar(rng, z(i))
      end do
   end subroutine normal_array

   !> a + b modulo 2^64 on bit patterns, from 32-bit halves (no signed overflow).
   elemental function add64(a, b) result(c)
      integer(int64), intent(in) :: a, b
      integer(int64) :: c
      integer(int64) :: lo, hi

      lo = iand(a, mask32) + iand(b, mask32)
      hi = iand(ishft(a, -32) + ishft(b, -32) + ishft(lo, -32), mask32)
      c = ior(ishft(hi, 32), iand(lo, mask32))
   end function add64

   !> a * b modulo 2^64 on bit patterns, from 32-bit halves (no signed overflow).
   elemental function mul64(a, b) result(c)
      integer(int64), intent(in) :: a, b
      integer(int64) :: c
      integer(int64) :: al, ah, bl, bh, hi, lo, top

      al = iand(a, mask32)
      ah = ishft(a, -32)
      bl = iand(b, mask32)
      bh = ishft(b, -32)
      call mul32(al, bl, hi, lo)
      top = hi + low32_product(al, bh) + low32_product(ah, bl)
      c = ior(ishft(iand(top, mask32), 32), lo)
   end function mul64

   !> Low 32 bits of x * y for 0 <= x, y < 2^32.
   elemental function low32_product(x, y) result(lo)
      integer(int64), intent(in) :: x, y
      integer(int64) :: lo
      integer(int64) :: hi

      call mul32(x, y, hi, lo)
   end function low32_product

   !> Full product x * y = hi 2^32 + lo of 0 <= x, y < 2^32, from 16-bit halves.
   pure subroutine mul32(x, y, hi, lo)
      integer(int64), intent(in) :: x, y
      integer(int64), intent(out) :: hi, lo
      integer(int64) :: x0, x1, y0, y1, p00, mid

      x0 = iand(x, mask16)
      x1 = ishft(x, -16)
      y0 = iand(y, mask16)
      y1 = ishft(y, -16)
      p00 = x0*y0
      mid = x0*y1 + x1*y0 + ishft(p00, -16)
      lo = ior(iand(p00, mask16), ishft(iand(mid, mask16), 16))
      hi = x1*y1 + ishft(mid, -16)
   end subroutine mul32

end module pound_random
