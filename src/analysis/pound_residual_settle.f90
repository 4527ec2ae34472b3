!> Whether the residual drift of yielding buildings (bilinear storeys, plastic hinges) is read
!> after the motion has settled. The residual drift is the storey drift at the end of the
!> analysis (`t_end`, plus `t_free` of free vibration with the ground at rest when given); it
!> is the permanent set only when nothing moves any more. The rule (one warning per analysis
!> set, naming what to set):
!>
!> * the ground still shakes: the largest |a_g| of the last second of the analysis is above
!>   `ground_limit` (5 %) of the PGA; or
!> * the buildings still vibrate: the largest kinetic energy (summed over the buildings, at the
!>   output samples) in the last max(1 s, T1) of the uncoupled or the coupled analysis is above
!>   `kinetic_limit` (1 %) of its peak over the analysis (T1 the longest fundamental period of
!>   the yielding buildings; a window at least a period long sees the vibration's peaks).
!>
!> The fix proposed: `t_free` = 10 T1 (ten periods of free vibration: with 5 % damping the
!> kinetic energy falls by exp(-2 pi) = 0.2 %), at least twice the `t_free` given, rounded up
!> to whole seconds.
module pound_residual_settle
   use pound_kinds, only: dp
   use pound_strings, only: plain_real, plain_significant
   implicit none
   private

   public :: residual_warning, ground_tail_fraction, kinetic_tail_fraction

   !> The ground still shakes: |a_g| in the last second above this fraction of the PGA.
   real(dp), parameter, public :: ground_limit = 0.05_dp
   !> The buildings still vibrate: kinetic energy in the last window above this fraction of its
   !> peak.
   real(dp), parameter, public :: kinetic_limit = 0.01_dp
   !> The last window's shortest length (s).
   real(dp), parameter :: window = 1.0_dp

contains

   !> Largest |a_g| of the last second of the samples ag(0:n) (step dt), as a fraction of the
   !> largest |a_g| of all (0 for a ground at rest).
   pure real(dp) function ground_tail_fraction(ag, dt) result(fraction)
      !> Ground accelerations a_g(n dt) (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> Time step (s).
      real(dp), intent(in) :: dt
      real(dp) :: pga
      integer :: n, n0

      fraction = 0.0_dp
      n = ubound(ag, 1)
      pga = maxval(abs(ag))
      if (.not. (pga > 0.0_dp)) return
      n0 = max(0, n - nint(window/dt))
      fraction = maxval(abs(ag(n0:n)))/pga
   end function ground_tail_fraction

   !> Largest kinetic energy of the samples at times >= time(end) - span, as a fraction of the
   !> largest of all (0 when the buildings never move).
   pure real(dp) function kinetic_tail_fraction(time, kinetic, span) result(fraction)
      !> Output times (s), increasing.
      real(dp), intent(in) :: time(:)
      !> Kinetic energy at those times (kJ).
      real(dp), intent(in) :: kinetic(:)
      !> Length of the last window (s).
      real(dp), intent(in) :: span
      real(dp) :: peak, tail
      integer :: k

      fraction = 0.0_dp
      if (size(time) == 0) return
      peak = maxval(kinetic)
      if (.not. (peak > 0.0_dp)) return
      tail = 0.0_dp
      do k = size(time), 1, -1
         if (time(k) < time(size(time)) - span) exit
         tail = max(tail, kinetic(k))
      end do
      fraction = tail/peak
   end function kinetic_tail_fraction

   !> The warning of the rule above ('' when the residual drift is read at rest).
   pure function residual_warning(names, ground_fraction, kinetic_unc, kinetic_cpl, t_end, t_free, period) &
      result(text)
      !> The yielding buildings' names, e.g. 'A, B'.
      character(len=*), intent(in) :: names
      !> `ground_tail_fraction` of the run.
      real(dp), intent(in) :: ground_fraction
      !> `kinetic_tail_fraction` of the uncoupled and the coupled analysis (0: not run).
      real(dp), intent(in) :: kinetic_unc, kinetic_cpl
      !> End of the analysis and free vibration given (s).
      real(dp), intent(in) :: t_end, t_free
      !> The longest fundamental period of the yielding buildings (s).
      real(dp), intent(in) :: period
      character(len=:), allocatable :: text, why
      real(dp) :: kin, proposed

      text = ''
      kin = max(kinetic_unc, kinetic_cpl)
      if (.not. (ground_fraction > ground_limit .or. kin > kinetic_limit)) return
      if (ground_fraction > ground_limit) then
         why = 'the ground still shakes (|a_g| up to '//percent(ground_fraction)//' of the PGA in the last '// &
               plain_real(window)//' s)'
      else
         why = 'the buildings still vibrate (kinetic energy up to '//percent(kin)//' of its peak in the last '// &
               plain_significant(max(window, period), 3)//' s)'
      end if
      proposed = real(ceiling(max(10.0_dp*period, 2.0_dp*t_free, 1.0_dp)), dp)
      text = 'residual drift of '//names//' read at t = '//plain_real(t_end)//' s while '//why// &
             ': it is a drift of the vibration, not the permanent set; set &analysis t_free = '// &
             plain_real(proposed)//' (s of free vibration with the ground at rest after t_end; 10 T1 = '// &
             plain_significant(10.0_dp*period, 3)//' s)'
   end function residual_warning

   !> A fraction as a percentage with one decimal, e.g. '12.3 %'.
   pure function percent(x) result(text)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: text

      text = plain_real(real(nint(1000.0_dp*x), dp)/10.0_dp)//' %'
   end function percent

end module pound_residual_settle
