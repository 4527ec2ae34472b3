!> Code rules for the separation (seismic joint) of two adjacent buildings at one contact pair,
!> from the uncoupled peak displacements u1, u2 (m, >= 0) of the two facing points (building 1
!> on the left, its displacement to the right closes the joint), the buildings' fundamental
!> periods T1, T2 (s), damping ratios z1, z2 and their design-code factors (`code_factors`).
!>
!> The peaks are the uncoupled response-history peaks of the buildings as analysed: elastic
!> buildings' elastic peaks, yielding buildings' (bilinear storeys, plastic hinges) their own
!> inelastic peaks (`inelastic`, `peaks_label`). A facing point is a floor or a point between
!> floors (a frame's split column node, whose displacement is a DOF of the model).
!>
!> Combinations of the peaks (no factor):
!>
!> * ABS = u1 + u2 (the sum: both peaks at the same time, in opposite directions);
!> * SRSS = sqrt(u1^2 + u2^2);
!> * ec8 (legacy name, kept for the HDF5 layout): the SRSS, times 0.7 where the floor levels
!>   coincide, of the peaks, without q_d: not a code check (see `en1998`);
!> * DDC (double difference combination) = sqrt(u1^2 + u2^2 - 2 rho u1 u2), with the CQC
!>   correlation of two oscillators (Der Kiureghian 1981), r = T1/T2:
!>   rho = 8 sqrt(z1 z2) (z1 + r z2) r^1.5 / ((1 - r^2)^2 + 4 z1 z2 r (1 + r^2) + 4 (z1^2 + z2^2) r^2);
!>
!> Design-code rules, with each building's factors (n/a: the factor of either building not given):
!>
!> * ASCE 7-16 12.12.3 (Eq. 12.12-2): delta_M = Cd delta_max / Ie per building,
!>   delta_MT = sqrt(delta_M1^2 + delta_M2^2);
!> * EN 1998-1:2004 4.4.2.7(2)-(3) with 4.3.4: d = q_d d_e per building (q_d = q), the SRSS
!>   of the two, times 0.7 where the floor levels coincide;
!> * IS 1893 (Part 1):2016 7.11.3: R1 D1 + R2 D2 (the code's R (D1 + D2) with each
!>   building's own R), times 0.5 where the floor levels coincide;
!>
!> The floor levels coincide (`levels_coincide`) only where both facing points are floors and
!> their elevations above the common base differ by at most `level_tolerance` (0.01 m): a floor
!> facing a column between floors never does (EC8 4.4.2.7(3)).
!>
!> The property-line setback of each building at its facing point (ASCE 7-16 12.12.2 style,
!> `separation_setback`): its own delta_M = Cd u / Ie where `cd` is given, else its peak u
!> itself (factor 1: the response-history peak of an unreduced motion is the displacement).
!>
!> and from the histories:
!>
!> * the exact no-contact gap max_t (u1(t) - u2(t)) of the uncoupled histories (0 if the
!>   joint never closes): the smallest gap at which the buildings never touch;
!> * (held here, computed by pound_suite) the time-history threshold gap of the gap sweep.
!>
!> The formulas are pure elemental functions that assume valid arguments; `code_separation`
!> gives every rule from the peaks for one pair (usable for any run), `separation_rules`
!> checks the arguments and adds the no-contact gap. A rule that is not computed holds NaN
!> and its `*_valid` flag is false: never use its value as a number.
module pound_separation
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use pound_kinds, only: dp
   use pound_code_factors, only: code_factors
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   implicit none
   private

   public :: separation_abs, separation_srss, separation_ec8, separation_ddc, cqc_correlation
   public :: no_contact_gap, separation_t, separation_rules, code_separation, levels_coincide
   public :: separation_asce7, separation_en1998, separation_is1893, not_computed
   public :: separation_setback, peaks_label, building_setbacks

   !> The EC8 reduction factor where floor levels coincide.
   real(dp), parameter, public :: ec8_coincident_factor = 0.7_dp
   !> The IS 1893 7.11.3 reduction factor (R/2 instead of R) where floor levels coincide.
   real(dp), parameter, public :: is1893_coincident_factor = 0.5_dp
   !> Two floor levels (m above the common base) coincide when they differ by at most this
   !> (a centimetre: a level survey's precision; storey heights that differ by more are
   !> staggered floors).
   real(dp), parameter, public :: level_tolerance = 0.01_dp

   !> All rules for one pair (m; rho dimensionless).
   type :: separation_t
      !> ABS, SRSS, EC8 and DDC separations (m).
      real(dp) :: abs = 0.0_dp, srss = 0.0_dp, ec8 = 0.0_dp, ddc = 0.0_dp
      !> CQC correlation used by the DDC.
      real(dp) :: rho = 0.0_dp
      !> Design-code separations (m): ASCE 7-16 12.12.3, EN 1998-1 4.4.2.7, IS 1893 7.11.3;
      !> NaN when not computed (a factor not given), see the flags below.
      real(dp) :: asce7 = 0.0_dp, en1998 = 0.0_dp, is1893 = 0.0_dp
      !> Whether each design-code rule was computed (its factors given for both buildings).
      logical :: asce7_valid = .false., en1998_valid = .false., is1893_valid = .false.
      !> Exact no-contact gap from the histories (a run: the sweep probe's largest closing).
      real(dp) :: no_contact = 0.0_dp
      !> Whether `no_contact` was computed.
      logical :: no_contact_valid = .false.
      !> Time-history threshold gap of a suite's gap sweep (pound_suite): the smallest gap
      !> meeting the sweep's target, the same for every pair (a sweep gives every pair the same
      !> gap); -1 when not computed (no `&sweep`, no target, or no gap of the range meets it:
      !> `time_history_valid` false; the -1 is kept for the HDF5 layout, never print it).
      real(dp) :: time_history = -1.0_dp
      !> Whether `time_history` was computed.
      logical :: time_history_valid = .false.
      !> False when no rule could be computed for the pair (a facing point whose peak is not
      !> known: a suite's point between floors whose model has no such node): every rule n/a.
      logical :: computed = .true.
      !> The peaks the rules used: u1, u2 of the facing points (m; 0 when not computed).
      real(dp) :: u(2) = 0.0_dp
      !> Property-line setback of each building at its facing point (m): its own delta_M,
      !> Cd u / Ie where `cd` is given (`setback_amplified`), else u (`separation_setback`).
      real(dp) :: setback(2) = 0.0_dp
      logical :: setback_amplified(2) = .false.
      !> Whether each peak is a yielding building's inelastic peak (bilinear storeys or plastic
      !> hinges) rather than an elastic one (set by the caller, who knows the models).
      logical :: inelastic(2) = .false.
      !> Whether the facing floors' levels coincided (EC8 x 0.7, IS 1893 x 0.5 applied).
      logical :: coincide = .false.
      !> The pair's buildings (left, right; indices in deck order; 0: not set), for the
      !> per-building setbacks.
      integer :: building(2) = 0
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

   !> ASCE 7-16 12.12.3 (Eq. 12.12-1, 12.12-2): delta_MT = sqrt(delta_M1^2 + delta_M2^2) with
   !> delta_M = Cd delta_max / Ie of each building (m). Factors > 0.
   elemental function separation_asce7(u1, u2, cd1, ie1, cd2, ie2) result(s)
      !> Peak displacements (m) >= 0.
      real(dp), intent(in) :: u1, u2
      !> Deflection amplification and importance factors of building 1 and of building 2.
      real(dp), intent(in) :: cd1, ie1, cd2, ie2
      real(dp) :: s

      s = separation_srss(cd1*u1/ie1, cd2*u2/ie2)
   end function separation_asce7

   !> EN 1998-1 4.4.2.7(2)-(3): the SRSS of d = q_d d_e of each building (4.3.4), times 0.7
   !> where the floor levels coincide (m). Factors > 0.
   elemental function separation_en1998(u1, u2, q1, q2, floors_coincide) result(s)
      !> Peak displacements (m) >= 0.
      real(dp), intent(in) :: u1, u2
      !> Displacement behaviour factors q_d of building 1 and of building 2.
      real(dp), intent(in) :: q1, q2
      !> The facing floors are at the same level.
      logical, intent(in) :: floors_coincide
      real(dp) :: s

      s = separation_ec8(q1*u1, q2*u2, floors_coincide)
   end function separation_en1998

   !> IS 1893 (Part 1):2016 7.11.3: R1 D1 + R2 D2 (the code's R (D1 + D2), each building with
   !> its own R), times 0.5 (R/2) where the floor levels coincide (m). Factors > 0.
   elemental function separation_is1893(u1, u2, r1, r2, floors_coincide) result(s)
      !> Peak displacements (m) >= 0.
      real(dp), intent(in) :: u1, u2
      !> Response reduction factors of building 1 and of building 2.
      real(dp), intent(in) :: r1, r2
      !> The facing floors are at the same level.
      logical, intent(in) :: floors_coincide
      real(dp) :: s

      s = r1*u1 + r2*u2
      if (floors_coincide) s = is1893_coincident_factor*s
   end function separation_is1893

   !> Whether the facing points of a pair are floors whose levels coincide: both are floors
   !> (`floor1`, `floor2` >= 1; 0: a point between floors, which never coincides) and their
   !> levels (m above the common base) differ by at most `level_tolerance`.
   elemental logical function levels_coincide(z1, z2, floor1, floor2)
      !> The two levels (m).
      real(dp), intent(in) :: z1, z2
      !> The facing floors (0: a point between floors).
      integer, intent(in) :: floor1, floor2

      levels_coincide = floor1 >= 1 .and. floor2 >= 1 .and. abs(z1 - z2) <= level_tolerance
   end function levels_coincide

   !> Property-line setback of one building at its facing point (m), ASCE 7-16 12.12.2 style:
   !> its own delta_M = Cd u / Ie (Eq. 12.12-1) where Cd is given (> 0), else its peak u
   !> itself (the response-history peak of an unreduced motion is the displacement demand).
   elemental real(dp) function separation_setback(u, f) result(s)
      !> Peak displacement of the facing point (m) >= 0.
      real(dp), intent(in) :: u
      !> The building's design-code factors.
      type(code_factors), intent(in) :: f

      s = u
      if (f%cd > 0.0_dp .and. f%importance > 0.0_dp) s = f%cd*u/f%importance
   end function separation_setback

   !> Which peaks the rules of `sep` used, as a phrase: 'uncoupled elastic peaks' (no end
   !> inelastic), 'uncoupled peaks of the yielding buildings (inelastic)' (every end), or
   !> 'uncoupled peaks as analysed (inelastic for the yielding buildings, elastic for the
   !> others)'.
   pure function peaks_label(sep) result(text)
      !> The rules of every pair of a run (or of one pair).
      type(separation_t), intent(in) :: sep(:)
      character(len=:), allocatable :: text
      integer :: n, k

      n = 0
      do k = 1, size(sep)
         n = n + count(sep(k)%inelastic)
      end do
      if (n == 0) then
         text = 'uncoupled elastic peaks'
      else if (n == 2*size(sep)) then
         text = 'uncoupled peaks of the yielding buildings (inelastic)'
      else
         text = 'uncoupled peaks as analysed (inelastic for the yielding buildings, elastic for the others)'
      end if
   end function peaks_label

   !> The value of a rule that is not computed: a quiet NaN (never a number).
   elemental real(dp) function not_computed(x)
      !> Any real (only its kind matters).
      real(dp), intent(in) :: x

      not_computed = ieee_value(x, ieee_quiet_nan)
   end function not_computed

   !> Every rule of one pair from the peaks u1, u2 (m, >= 0) of its facing points:
   !> ABS, SRSS, the legacy ec8, DDC with its rho, the design-code rules with the two
   !> buildings' factors (a rule whose factor is not given (<= 0) is NaN and not valid), the
   !> peaks themselves and each building's setback.
   !> Periods > 0, 0 <= z < 1 (not checked here; `separation_rules` checks). The no-contact
   !> and time-history gaps are left at their defaults.
   elemental function code_separation(u1, u2, f1, f2, t1, t2, z1, z2, floors_coincide) result(sep)
      !> Peak displacements of the facing points (m).
      real(dp), intent(in) :: u1, u2
      !> Design-code factors of building 1 (left) and building 2 (right).
      type(code_factors), intent(in) :: f1, f2
      !> Fundamental periods (s).
      real(dp), intent(in) :: t1, t2
      !> Damping ratios.
      real(dp), intent(in) :: z1, z2
      !> The facing floors are at the same level.
      logical, intent(in) :: floors_coincide
      type(separation_t) :: sep

      sep%u = [u1, u2]
      sep%coincide = floors_coincide
      sep%setback = [separation_setback(u1, f1), separation_setback(u2, f2)]
      sep%setback_amplified = [f1%cd > 0.0_dp, f2%cd > 0.0_dp]
      sep%abs = separation_abs(u1, u2)
      sep%srss = separation_srss(u1, u2)
      sep%ec8 = separation_ec8(u1, u2, floors_coincide)
      sep%rho = cqc_correlation(t1, t2, z1, z2)
      sep%ddc = separation_ddc(u1, u2, t1, t2, z1, z2)
      sep%asce7_valid = f1%cd > 0.0_dp .and. f2%cd > 0.0_dp .and. f1%importance > 0.0_dp .and. &
                        f2%importance > 0.0_dp
      sep%en1998_valid = f1%behaviour_factor > 0.0_dp .and. f2%behaviour_factor > 0.0_dp
      sep%is1893_valid = f1%response_reduction > 0.0_dp .and. f2%response_reduction > 0.0_dp
      if (sep%asce7_valid) then
         sep%asce7 = separation_asce7(u1, u2, f1%cd, f1%importance, f2%cd, f2%importance)
      else
         sep%asce7 = not_computed(u1)
      end if
      if (sep%en1998_valid) then
         sep%en1998 = separation_en1998(u1, u2, f1%behaviour_factor, f2%behaviour_factor, floors_coincide)
      else
         sep%en1998 = not_computed(u1)
      end if
      if (sep%is1893_valid) then
         sep%is1893 = separation_is1893(u1, u2, f1%response_reduction, f2%response_reduction, floors_coincide)
      else
         sep%is1893 = not_computed(u1)
      end if
   end function code_separation

   !> Building ib's property-line setback (m): its largest setback over the pairs it faces
   !> (`separation_t%setback` at its end); NaN when it faces no pair whose rules were computed.
   pure real(dp) function building_setbacks(sep, ib, nb) result(setback)
      !> The rules per pair.
      type(separation_t), intent(in) :: sep(:)
      !> The building (index in deck order) and the number of buildings.
      integer, intent(in) :: ib, nb
      integer :: ip, e
      logical :: found

      setback = not_computed(0.0_dp)
      if (ib < 1 .or. ib > nb) return
      found = .false.
      do ip = 1, size(sep)
         if (.not. sep(ip)%computed) cycle
         do e = 1, 2
            if (sep(ip)%building(e) /= ib) cycle
            ! (no comparison with a NaN: it traps under -ffpe-trap=invalid)
            if (found) then
               setback = max(setback, sep(ip)%setback(e))
            else
               setback = sep(ip)%setback(e)
               found = .true.
            end if
         end do
      end do
   end function building_setbacks

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
                                    history1, history2, sep, error, factors)
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
      !> Design-code factors of building 1 and building 2 (absent: none given, the design-code
      !> rules are n/a).
      type(code_factors), intent(in), optional :: factors(2)
      type(code_factors) :: f(2)

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
      if (present(factors)) f = factors
      sep = code_separation(u1, u2, f(1), f(2), t1, t2, z1, z2, floors_coincide)
      sep%no_contact = no_contact_gap(history1, history2)
      sep%no_contact_valid = .true.
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
