!> The progress line of long runs on standard error.
!>
!> A run is counted in integration runs: every uncoupled run, coupled run and gap of a sweep
!> (of every motion of a suite) is one, and so is every motion's run at a trial gap of a
!> suite's refinements. The program says how many it plans (`progress_start`; the
!> refinements at their most, `progress_skip` takes back those that do not run); the time-step loop reports its step every `progress_stride` steps
!> (`progress_steps`) and the end of each run (`progress_run_done`). The line
!>
!>     pound: 37/561 runs (6.6 %), 12.3 s elapsed, about 2 min 54 s left
!>
!> is rewritten in place (carriage return) at most once a second, from the first second on,
!> when standard error is a terminal, and ended by a newline when the analyses end
!> (`progress_finish`); a run of less than a second prints nothing. `--progress` forces it
!> (one line each, also when standard error is not a terminal, and always a last line),
!> `--quiet` silences it; without a terminal and without `--progress` nothing is written, so
!> that captured standard error stays as it was. Not on a terminal, each line is a line of
!> its own.
!>
!> The state is the module's own (one progress line per process); the cost in the time-step
!> loop is one integer test per step and a clock reading every `progress_stride` steps.
module pound_progress
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_posix, only: posix_isatty, posix_write
   implicit none
   private

   public :: progress_setup, progress_start, progress_steps, progress_run_done, progress_finish
   public :: progress_line, progress_stride, progress_auto, progress_on, progress_off
   public :: progress_ended, progress_runs_elsewhere, progress_skip, progress_counts

   !> Modes of `progress_setup`: on a terminal only, always (`--progress`), never (`--quiet`).
   integer, parameter :: progress_auto = 0, progress_on = 1, progress_off = 2
   !> Steps between two reports of the time-step loop.
   integer, parameter :: progress_stride = 1024
   !> Seconds between two lines, and before the first one.
   real(dp), parameter :: interval = 1.0_dp

   logical, save :: active = .false., tty = .false., forced = .false., shown = .false.
   integer, save :: total = 1, done = 0
   !> Runs planned (`progress_start`, less `progress_skip`): `total` is never less than `done`.
   integer, save :: planned = 1
   !> Runs ended in this process, counted whether the line is shown or not.
   integer, save :: ended = 0
   real(dp), save :: fraction = 0.0_dp, last = 0.0_dp
   integer(int64), save :: c0 = 0, rate = 1

contains

   !> Choose when the line is shown: `progress_auto` (standard error is a terminal),
   !> `progress_on` or `progress_off`.
   subroutine progress_setup(mode)
      !> One of progress_auto, progress_on, progress_off.
      integer, intent(in) :: mode

      tty = posix_isatty(2)
      forced = mode == progress_on
      active = forced .or. (mode == progress_auto .and. tty)
   end subroutine progress_setup

   !> Start the clock for `runs` planned integration runs.
   subroutine progress_start(runs)
      !> Number of integration runs planned (more may come: the total then grows).
      integer, intent(in) :: runs

      total = max(1, runs)
      planned = total
      done = 0
      fraction = 0.0_dp
      last = 0.0_dp
      shown = .false.
      call system_clock(c0, rate)
   end subroutine progress_start

   !> The current run is at `step` of `n_steps`.
   subroutine progress_steps(step, n_steps)
      !> Steps done.
      integer, intent(in) :: step
      !> Steps of the run.
      integer, intent(in) :: n_steps

      if (.not. active) return
      fraction = real(step, dp)/real(max(1, n_steps), dp)
      call maybe_show()
   end subroutine progress_steps

   !> One integration run has ended.
   subroutine progress_run_done()
      ended = ended + 1
      if (.not. active) return
      done = done + 1
      total = max(total, done)
      fraction = 0.0_dp
      call maybe_show()
   end subroutine progress_run_done

   !> `n` of the planned runs will not be made (a negative `n`: more will): the total shrinks
   !> (grows), never below the runs done (a suite's refinements, planned at their most before
   !> the sweep tells which of them run and how many trial gaps each takes).
   subroutine progress_skip(n)
      !> Number of runs.
      integer, intent(in) :: n

      planned = planned - n
      total = max(1, done, planned)
   end subroutine progress_skip

   !> Runs done so far and runs planned (`progress_start` less `progress_skip`) of the line
   !> (both counted only while it is active).
   subroutine progress_counts(n_done, n_planned)
      !> Runs done.
      integer, intent(out) :: n_done
      !> Runs planned.
      integer, intent(out) :: n_planned

      n_done = done
      n_planned = planned
   end subroutine progress_counts

   !> Runs ended in this process so far (the case scheduler counts each case's runs with it).
   integer function progress_ended()
      progress_ended = ended
   end function progress_ended

   !> `n` runs ended in other processes (the MPI ranks' cases, counted by the scheduler).
   subroutine progress_runs_elsewhere(n)
      !> Number of runs.
      integer, intent(in) :: n

      if (.not. active .or. n <= 0) return
      done = done + n
      total = max(total, done)
      fraction = 0.0_dp
      call maybe_show()
   end subroutine progress_runs_elsewhere

   !> The analyses have ended (`ok`: all of them; else they stopped on an error): the last
   !> line (when a line was shown, or forced) and, on a terminal, its newline; after an error
   !> only the newline, so that the message starts a line of its own.
   subroutine progress_finish(ok)
      !> Whether the analyses completed.
      logical, intent(in) :: ok

      if (.not. active) return
      active = .false.
      if (ok .and. (shown .or. forced)) then
         total = done
         fraction = 0.0_dp
         call show(elapsed())
      end if
      if (tty .and. shown) call emit(new_line('a'))
      shown = .false.
   end subroutine progress_finish

   !> The progress line for `n_done` of `n_total` runs and the `part` (0..1) of the current
   !> one, `seconds` after the start: runs, per cent, elapsed time and, once there is
   !> progress to go by, the estimated time left (elapsed x remaining / done).
   pure function progress_line(n_done, n_total, part, seconds) result(line)
      !> Runs done.
      integer, intent(in) :: n_done
      !> Runs planned.
      integer, intent(in) :: n_total
      !> Part of the current run done (0..1).
      real(dp), intent(in) :: part
      !> Seconds since the start.
      real(dp), intent(in) :: seconds
      character(len=:), allocatable :: line
      character(len=32) :: buf
      real(dp) :: f

      f = min(1.0_dp, (real(n_done, dp) + part)/real(max(1, n_total), dp))
      write (buf, '(i0,a,i0,a,f5.1,a)') n_done, '/', n_total, ' runs (', 100.0_dp*f, ' %)'
      line = 'pound: '//trim(buf)//', '//duration(seconds)//' elapsed'
      if (f > 0.0_dp .and. f < 1.0_dp) line = line//', about '//duration(seconds*(1.0_dp - f)/f)//' left'
   end function progress_line

   !> `s` seconds as '12.3 s', '2 min 54 s' or '1 h 05 min'.
   pure function duration(s) result(text)
      real(dp), intent(in) :: s
      character(len=:), allocatable :: text
      character(len=24) :: buf
      integer :: whole

      if (s < 59.95_dp) then
         write (buf, '(f4.1,a)') max(0.0_dp, s), ' s'
      else if (s < 3599.5_dp) then
         whole = nint(s)
         write (buf, '(i0,a,i0,a)') whole/60, ' min ', mod(whole, 60), ' s'
      else
         whole = nint(s/60.0_dp)
         write (buf, '(i0,a,i2.2,a)') whole/60, ' h ', mod(whole, 60), ' min'
      end if
      text = trim(adjustl(buf))
   end function duration

   !> Seconds since `progress_start`.
   real(dp) function elapsed()
      integer(int64) :: c

      call system_clock(c)
      elapsed = real(c - c0, dp)/real(rate, dp)
   end function elapsed

   !> Show the line if a second has passed since the last one (and since the start).
   subroutine maybe_show()
      real(dp) :: t

      t = elapsed()
      if (t - last < interval) return
      last = t
      call show(t)
   end subroutine maybe_show

   !> Write the line: in place on a terminal, else one line each.
   subroutine show(t)
      real(dp), intent(in) :: t

      shown = .true.
      if (tty) then
         ! Carriage return, the line, and clear what a longer line left behind.
         call emit(achar(13)//progress_line(done, total, fraction, t)//achar(27)//'[K')
      else
         call emit(progress_line(done, total, fraction, t)//new_line('a'))
      end if
   end subroutine show

   !> Write to standard error, unbuffered; a failure (closed, a reader gone) stops the line.
   subroutine emit(text)
      character(len=*), intent(in) :: text

      if (posix_write(2, text) /= 0) then
         active = .false.
         shown = .false.
      end if
   end subroutine emit

end module pound_progress
