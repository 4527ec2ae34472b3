!> The rules a joint's force-penetration envelope must obey, shared by the deck reader (which
!> checks the deck's `envelope_d`, `envelope_r` before any model exists) and the contact law
!> (pound_contact_law, which builds the law from them). Pure checks only: the deck does not
!> depend on the contact step, and the two cannot disagree about what is a valid envelope.
module pound_envelope_rules
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, status_input
   use pound_strings, only: str
   implicit none
   private

   public :: max_law_points, max_segments, check_piecewise_envelope, check_law_constants

   !> Largest number of envelope points of a law.
   integer, parameter :: max_law_points = 1000
   !> Largest number of chords per curved branch of `parabola_cubic`.
   integer, parameter :: max_segments = 64

contains

   !> The points (d_i, r_i) after the origin of a piecewise-linear envelope: at least 2, at
   !> most max_law_points, d increasing, r > 0 (only the last may be 0, the fracture point),
   !> every slope below the first one k0 = r_1/d_1, which must be > 0 and finite.
   pure subroutine check_piecewise_envelope(d, r, k0, error)
      !> Penetrations of the points (m).
      real(dp), intent(in) :: d(:)
      !> Forces of the points (kN).
      real(dp), intent(in) :: r(:)
      !> The first slope k0 = r(1)/d(1) (kN/m), when the points are valid.
      real(dp), intent(out) :: k0
      !> Error state: which rule the points break.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, n
      real(dp) :: s

      k0 = 0.0_dp
      n = size(d)
      if (n < 2 .or. size(r) /= n) then
         call fatal_error(error, 'a piecewise envelope needs at least 2 points (d, r) with as many '// &
                          'forces as penetrations', status_input)
         return
      end if
      if (n > max_law_points) then
         call fatal_error(error, 'a piecewise envelope may have at most '//str(max_law_points)//' points', status_input)
         return
      end if
      if (.not. (d(1) > 0.0_dp .and. r(1) > 0.0_dp)) then
         call fatal_error(error, 'the first point must have d > 0 and r > 0 (k0 = r/d is its slope)', status_input)
         return
      end if
      k0 = r(1)/d(1)
      do i = 2, n
         if (.not. (d(i) > d(i - 1))) then
            call fatal_error(error, 'point '//str(i)//': penetrations must increase, d = '//str(d(i))// &
                             ' after '//str(d(i - 1)), status_input)
            return
         end if
         if (.not. (r(i) >= 0.0_dp) .or. (r(i) == 0.0_dp .and. i < n)) then
            call fatal_error(error, 'point '//str(i)//': force r = '//str(r(i))//' must be > 0 '// &
                             '(only the last point may have r = 0, the fracture point)', status_input)
            return
         end if
         s = (r(i) - r(i - 1))/(d(i) - d(i - 1))
         if (.not. (s < k0*(1.0_dp - 1.0e-9_dp))) then
            call fatal_error(error, 'point '//str(i)//': slope '//str(s)//' must be below the first '// &
                             'slope k0 = '//str(k0)//' (the envelope yields at point 1)', status_input)
            return
         end if
      end do
      call check_law_constants(k0, 0.0_dp, error)
   end subroutine check_piecewise_envelope

   !> Every law's constants: stiffness k0 > 0 and finite, dashpot c >= 0 and finite.
   pure subroutine check_law_constants(k0, dashpot, error)
      !> Initial stiffness k0 (kN/m).
      real(dp), intent(in) :: k0
      !> Dashpot c (kN s/m).
      real(dp), intent(in) :: dashpot
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      if (.not. (k0 > 0.0_dp .and. k0 < huge(1.0_dp))) then
         call fatal_error(error, 'stiffness k0 must be > 0 and finite, got '//str(k0), status_input)
         return
      end if
      if (.not. (dashpot >= 0.0_dp .and. dashpot < huge(1.0_dp))) then
         call fatal_error(error, 'dashpot must be >= 0 and finite, got '//str(dashpot), status_input)
      end if
   end subroutine check_law_constants

end module pound_envelope_rules
