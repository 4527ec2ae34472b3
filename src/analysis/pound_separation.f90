!> Code rules for the separation (seismic joint) of two adjacent buildings at one contact pair,
!> from the uncoupled peak displacements u1, u2 (m, >= 0) of the two facing points (building 1
!> on the left, its displacement to the right closes the joint), the buildings' fundamental
!> periods T1, T2 (s) and damping ratios z1, z2. Applied, as given, to elastic peaks (no
!> displacement amplification factors).
!>
!> * ABS = u1 + u2 (the sum: both peaks at the same time, in opposite directions);
!> * SRSS = sqrt(u1^2 + u2^2);
!> * EC8 (Eurocode 8, 4.4.2.7): the SRSS, times 0.7 where the floor levels coincide;
!> * DDC (double difference combination) = sqrt(u1^2 + u2^2 - 2 rho u1 u2), with the CQC
!>   correlation of two oscillators (Der Kiureghian 1981), r = T1/T2:
!>   rho = 8 sqrt(z1 z2) (z1 + r z2) r^1.5 / ((1 - r^2)^2 + 4 z1 z2 r (1 + r^2) + 4 (z1^2 + z2^2) r^2);
!> * the exact no-contact gap max_t (u1(t) - u2(t)) of the uncoupled histories (0 if the
!>   joint never closes): the smallest gap at which the buildings never touch;
!> * (held here, computed by pound_suite) the time-history threshold gap of the gap sweep.
!>
!> The formulas are pure elemental functions that assume valid arguments; `separation_rules`
!> checks the arguments and returns all of them.
module pound_separation
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   implicit none
   private

   public :: separation_abs, separation_srss, separation_ec8, separation_ddc, cqc_correlation
   public :: no_contact_gap, separation_t, separation_rules

   !> The EC8 reduction factor where floor levels coincide.
   real(dp), parameter, public :: ec8_coincident_factor = 0.7_dp

   !> All rules for one pair (m; rho dimensionless).
   type :: separation_t
      !> ABS, SRSS, EC8 and DDC separations (m).
      real(dp) :: abs = 0.0_dp, srss = 0.0_dp, ec8 = 0.0_dp, ddc = 0.0_dp
      !> CQC correlation used by the DDC.
      real(dp) :: rho = 0.0_dp
      !> Exact no-contact gap from the histories.
      real(dp) :: no_contact = 0.0_dp
      !> Time-history threshold gap of a suite's gap sweep (pound_suite): the smallest gap
      !> meeting the sweep's target, the same for every pair (a sweep gives every pair the same
      !> gap); -1 when not computed (no `&sweep`, no target, or no gap of the range meets it).
      real(dp) :: time_history = -1.0_dp
   end type separation_t

contains

   !> ABS = u1 + u2 (m).
   elemental function separation_abs(u1, u2) result(s)
      !> Peak displacements (m) >= 0.
      real(dp), intent(in) :: u1, u2
      real(dp) :: s

      s = u1 + u2
   end function separation_abs

   !> SRSS = sqrt(u1^2 + u2^2) (m), without overflow or underflow (`hypot`).
   elemental function separation_srss(u1, u2) result(s)
      !> Peak displacements (m) >= 0.
      real(dp), intent(in) :: u1, u2
      real(dp) :: s

      s = hypot(u1, u2)
   end function separation_srss

   !> Eurocode 8 4.4.2.7: SRSS, times 0.7 where the floor levels of the buildings coincide.
   elemental function separation_ec8(u1, u2, floors_coincide) result(s)
      !> Peak displacements (m) >= 0.
      real(dp), intent(in) :: u1, u2
      !> The facing floors are at the same level.
      logical, intent(in) :: floors_coincide
      real(dp) :: s

      s = separation_srss(u1, u2)
      if (floors_coincide) s = ec8_coincident_factor*s
   end function separation_ec8

   !> CQC correlation rho of two oscillators, r = T1/T2 (periods in s > 0, 0 <= z < 1):
   !> 8 sqrt(z1 z2) (z1 + r z2) r^1.5 / ((1 - r^2)^2 + 4 z1 z2 r (1 + r^2) + 4 (z1^2 + z2^2) r^2).
   !> 1 for equal periods and damping, symmetric in the two buildings, 0 when either is
   !> undamped and the periods differ (0/0 for equal periods without damping: 1).
   elemental function cqc_correlation(t1, t2, z1, z2) result(rho)
      !> Fundamental periods (s).
      real(dp), intent(in) :: t1, t2
      !> Damping ratios.
      real(dp), intent(in) :: z1, z2
      real(dp) :: rho
      real(dp) :: r, den

      r = t1/t2
      den = (1.0_dp - r*r)**2 + 4.0_dp*z1*z2*r*(1.0_dp + r*r) + 4.0_dp*(z1*z1 + z2*z2)*r*r
      if (den > 0.0_dp) then
         rho = 8.0_dp*sqrt(z1*z2)*(z1 + r*z2)*r**1.5_dp/den
      else
         rho = 1.0_dp
      end if
   end function cqc_correlation

   !> DDC = sqrt(u1^2 + u2^2 - 2 rho u1 u2) (m), evaluated as sqrt((u1 - u2)^2 +
   !> 2 (1 - rho) u1 u2) so that it never takes the root of a negative rounding error; it
   !> lies between |u1 - u2| (rho = 1) and ABS (rho = -1).
   elemental function separation_ddc(u1, u2, t1, t2, z1, z2) result(s)
      !> Peak displacements (m) >= 0.
      real(dp), intent(in) :: u1, u2
      !> Fundamental periods (s) > 0.
      real(dp), intent(in) :: t1, t2
      !> Damping ratios, 0 <= z < 1.
      real(dp), intent(in) :: z1, z2
      real(dp) :: s
      real(dp) :: rho

      rho = min(cqc_correlation(t1, t2, z1, z2), 1.0_dp)
      s = sqrt((u1 - u2)**2 + 2.0_dp*(1.0_dp - rho)*u1*u2)
   end function separation_ddc

   !> Exact no-contact gap max_t (u1(t) - u2(t)) (m) of two histories sampled at the same
   !> times, 0 if the joint never closes. Both must have the same size.
   pure function no_contact_gap(u1, u2) result(gap)
      !> Displacement histories of the two facing points (m).
      real(dp), intent(in) :: u1(:), u2(:)
      real(dp) :: gap
      integer :: i

      gap = 0.0_dp
      do i = 1, min(size(u1), size(u2))
         gap = max(gap, u1(i) - u2(i))
      end do
   end function no_contact_gap

   !> Every rule for one pair, with the arguments checked: u1, u2 finite and >= 0, periods
   !> finite and > 0, 0 <= z < 1, histories of the same, non-zero length and finite.
   pure subroutine separation_rules(u1, u2, t1, t2, z1, z2, floors_coincide, &
                                    history1, history2, sep, error)
      !> Peak displacements of the facing points (m).
      real(dp), intent(in) :: u1, u2
      !> Fundamental periods of the buildings (s).
      real(dp), intent(in) :: t1, t2
      !> Damping ratios of the buildings.
      real(dp), intent(in) :: z1, z2
      !> The facing floors are at the same level (EC8 factor 0.7).
      logical, intent(in) :: floors_coincide
      !> Uncoupled displacement histories of the facing points (m), same times.
      real(dp), intent(in) :: history1(:), history2(:)
      !> The rules.
      type(separation_t), intent(out) :: sep
      !> Set for an invalid argument.
      type(error_type), allocatable, intent(out) :: error

      call check_nonnegative(u1, 'u1', error)
      if (.not. allocated(error)) call check_nonnegative(u2, 'u2', error)
      if (.not. allocated(error)) call check_period(t1, 'T1', error)
      if (.not. allocated(error)) call check_period(t2, 'T2', error)
      if (.not. allocated(error)) call check_damping(z1, 'z1', error)
      if (.not. allocated(error)) call check_damping(z2, 'z2', error)
      if (allocated(error)) return
      if (size(history1) /= size(history2) .or. size(history1) == 0) then
         call fatal_error(error, 'separation: histories of '//str(size(history1))//' and '// &
                          str(size(history2))//' samples, must be the same, non-zero length')
         return
      end if
      if (.not. (all(ieee_is_finite(history1)) .and. all(ieee_is_finite(history2)))) then
         call fatal_error(error, 'separation: a displacement history is not finite')
         return
      end if
      sep%abs = separation_abs(u1, u2)
      sep%srss = separation_srss(u1, u2)
      sep%ec8 = separation_ec8(u1, u2, floors_coincide)
      sep%rho = cqc_correlation(t1, t2, z1, z2)
      sep%ddc = separation_ddc(u1, u2, t1, t2, z1, z2)
      sep%no_contact = no_contact_gap(history1, history2)
   end subroutine separation_rules

   pure subroutine check_nonnegative(x, name, error)
      real(dp), intent(in) :: x
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error

      if (.not. (x >= 0.0_dp .and. ieee_is_finite(x))) then
         call fatal_error(error, 'separation: '//name//' = '//str(x)//' m, must be >= 0')
      end if
   end subroutine check_nonnegative

   pure subroutine check_period(x, name, error)
      real(dp), intent(in) :: x
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error

      if (.not. (x > 0.0_dp .and. ieee_is_finite(x))) then
         call fatal_error(error, 'separation: '//name//' = '//str(x)//' s, must be > 0')
      end if
   end subroutine check_period

   pure subroutine check_damping(x, name, error)
      real(dp), intent(in) :: x
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error

      if (.not. (x >= 0.0_dp .and. x < 1.0_dp)) then
         call fatal_error(error, 'separation: '//name//' = '//str(x)//', must be >= 0 and < 1')
      end if
   end subroutine check_damping

end module pound_separation
