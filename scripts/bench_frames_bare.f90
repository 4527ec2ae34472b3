!> The bare loop of scripts/bench_frames: one Cholesky factorization of an SPD band matrix of
!> order n and half-bandwidth kd (dpbtrf), then `steps` solves with it (dpbtrs), the right-hand
!> side refreshed by one cheap pass per step. Prints the loop's wall time (s).
!>     bench_frames_bare N KD STEPS
!> Compiled by scripts/bench_frames against the build's modules (LAPACK's interfaces as pound uses them).
program bench_frames_bare
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_band_lapack, only: dpbtrf, dpbtrs
   implicit none
   real(dp), allocatable :: ab(:, :), x(:)
   character(len=32) :: arg
   integer :: n, kd, steps, info, step
   integer(int64) :: c0, c1, rate

   call get_command_argument(1, arg)
   read (arg, *) n
   call get_command_argument(2, arg)
   read (arg, *) kd
   call get_command_argument(3, arg)
   read (arg, *) steps
   allocate (ab(kd + 1, n), x(n))
   ab = -1.0_dp
   ab(kd + 1, :) = real(2*kd + 2, dp)
   call dpbtrf('U', n, kd, ab, kd + 1, info)
   if (info /= 0) error stop 'dpbtrf failed'
   x = 1.0_dp
   call system_clock(c0, rate)
   do step = 1, steps
      x = 0.5_dp*x + 1.0_dp
      call dpbtrs('U', n, kd, 1, ab, kd + 1, x, n, info)
   end do
   call system_clock(c1)
   print '(es12.5,1x,es12.5)', real(c1 - c0, dp)/real(rate, dp), sum(x)
end program bench_frames_bare
