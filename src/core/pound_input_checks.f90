!> Checks of input values that know no configuration: where a value comes from (`input_site`:
!> the file, the group's label, the line of each assignment), the message format
!> `deck.nml:LINE: &group #k (name): text` (`fail`), required values, rules (> 0, >= ...), the
!> plausible ranges of `bounds` (docs/manual.md: Input bounds) and the markers of values not
!> given. The deck (pound_deck_checks) and the joint laws (pound_law_*, which read their own
!> `&contact` variables) check through it, so that no law depends on the deck layer.
module pound_input_checks
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_error, only: error_type, fatal_error, status_input
   use pound_kinds, only: dp
   use pound_strings, only: counted, short_real, str
   implicit none
   private

   !> Number of values given in a namelist array (real or integer).
   interface given_count
      module procedure given_count_real, given_count_int
   end interface given_count

   public :: input_site, name_len, fail, take_real, site_text, require_real, check_real, check_plausible, is_set, bounds_where, &
             given_count, values_text, unset_real, unset_int

   !> Marks namelist values the deck did not give.
   real(dp), parameter :: unset_real = -huge(1.0_dp)

   !> Marks namelist integers the deck did not give.
   integer, parameter :: unset_int = -huge(1)

   !> Longest variable name `input_site` keeps.
   integer, parameter :: name_len = 64

   !> Where a message points: the file, the group occurrence's label and lines.
   type :: input_site
      !> File path as given.
      character(len=:), allocatable :: path
      !> Group label, e.g. `&building #2 (B)`.
      character(len=:), allocatable :: label
      !> Group name, lower case (the key of `bounds`).
      character(len=:), allocatable :: group_name
      !> Line of the group's start.
      integer :: line1 = 0
      !> The group's assignments, in order: variable names (lower case) and their lines (the
      !> last assignment of a name gives its line).
      character(len=name_len), allocatable :: names(:)
      integer, allocatable :: lines(:)
   end type input_site

   !> Where a refusal for a value outside its plausible range sends the user: the file that
   !> holds the whole table of bounds (the README only summarises it).
   character(len=*), parameter :: bounds_where = ' (see the input bounds in docs/manual.md, "Input bounds")'


   !> Plausible engineering range of a deck variable (docs/manual.md: Input bounds).
   type :: bound_t
      !> 'group:variable'.
      character(len=28) :: key
      !> Smallest and largest value.
      real(dp) :: lo, hi
      !> Unit, for messages.
      character(len=8) :: unit
      !> Whether the bounds apply to |x|.
      logical :: magnitude
   end type bound_t

   !> The ranges: generous enough for any real structure and record, tight enough that every
   !> value inside gives finite derived quantities (12EI/h^3, masses, periods, forces).
   type(bound_t), parameter :: bounds(56) = [ &
      bound_t('analysis:dt', 1.0e-7_dp, 1.0_dp, 's', .false.), &
      bound_t('analysis:t_end', 0.0_dp, 1.0e4_dp, 's', .false.), &
      bound_t('analysis:t_free', 0.0_dp, 1.0e4_dp, 's', .false.), &
      bound_t('ground:x0', 1.0e-9_dp, 10.0_dp, 'm', .true.), &
      bound_t('ground:a', 0.0_dp, 1.0e3_dp, '1/s', .false.), &
      bound_t('ground:b', 1.0e-3_dp, 1.0e4_dp, 'rad/s', .false.), &
      bound_t('ground:scale', 1.0e-6_dp, 1.0e3_dp, '', .true.), &
      bound_t('ground:target', 1.0e-6_dp, 1.0e3_dp, 'm/s^2', .false.), &
      bound_t('ground:target_g', 1.0e-7_dp, 1.0e2_dp, 'g', .false.), &
      bound_t('building:cd', 1.0e-3_dp, 1.0e2_dp, '', .false.), &
      bound_t('building:importance', 1.0e-3_dp, 1.0e2_dp, '', .false.), &
      bound_t('building:behaviour_factor', 1.0e-3_dp, 1.0e2_dp, '', .false.), &
      bound_t('building:response_reduction', 1.0e-3_dp, 1.0e2_dp, '', .false.), &
      bound_t('ground:period', 1.0e-3_dp, 1.0e2_dp, 's', .false.), &
      bound_t('ground:ground_frequency', 1.0e-2_dp, 1.0e3_dp, 'rad/s', .false.), &
      bound_t('ground:filter_frequency', 1.0e-3_dp, 1.0e3_dp, 'rad/s', .false.), &
      bound_t('ground:duration', 1.0e-3_dp, 1.0e4_dp, 's', .false.), &
      bound_t('ground:pga', 1.0e-6_dp, 1.0e3_dp, 'm/s^2', .false.), &
      bound_t('ground:rise_time', 1.0e-3_dp, 1.0e4_dp, 's', .false.), &
      bound_t('ground:decay_rate', 1.0e-4_dp, 1.0e3_dp, '1/s', .false.), &
      bound_t('building:height', 0.1_dp, 1.0e3_dp, 'm', .false.), &
      bound_t('building:mass', 1.0e-6_dp, 1.0e9_dp, 't', .false.), &
      bound_t('building:load_coeff', 1.0e-3_dp, 1.0e3_dp, '', .false.), &
      bound_t('building:ref_floor_load', 1.0e-2_dp, 1.0e8_dp, 'kN', .false.), &
      bound_t('building:stiffness', 1.0e-3_dp, 1.0e12_dp, 'kN/m', .false.), &
      bound_t('building:e_modulus', 1.0e2_dp, 1.0e10_dp, 'kN/m^2', .false.), &
      bound_t('building:inertia', 1.0e-12_dp, 1.0e4_dp, 'm^4', .false.), &
      bound_t('building:bay_width', 0.1_dp, 1.0e3_dp, 'm', .false.), &
      bound_t('building:column_e', 1.0e2_dp, 1.0e10_dp, 'kN/m^2', .false.), &
      bound_t('building:beam_e', 1.0e2_dp, 1.0e10_dp, 'kN/m^2', .false.), &
      bound_t('building:column_area', 1.0e-8_dp, 1.0e3_dp, 'm^2', .false.), &
      bound_t('building:beam_area', 1.0e-8_dp, 1.0e3_dp, 'm^2', .false.), &
      bound_t('building:column_inertia', 1.0e-12_dp, 1.0e4_dp, 'm^4', .false.), &
      bound_t('building:beam_inertia', 1.0e-12_dp, 1.0e4_dp, 'm^4', .false.), &
      bound_t('building:gravity_load', 0.0_dp, 1.0e10_dp, 'kN', .false.), &
      bound_t('contact:stiffness', 1.0e-3_dp, 1.0e13_dp, 'kN/m', .false.), &
      bound_t('contact:dashpot', 0.0_dp, 1.0e10_dp, 'kN s/m', .false.), &
      bound_t('contact:gap', 0.0_dp, 10.0_dp, 'm', .false.), &
      bound_t('sweep:gap_from', 0.0_dp, 10.0_dp, 'm', .false.), &
      bound_t('sweep:gap_to', 0.0_dp, 10.0_dp, 'm', .false.), &
      bound_t('contact:yield_force', 1.0e-3_dp, 1.0e10_dp, 'kN', .false.), &
      bound_t('contact:peak_force', 1.0e-3_dp, 1.0e10_dp, 'kN', .false.), &
      bound_t('contact:second_slope', 0.0_dp, 1.0e13_dp, 'kN/m', .true.), &
      bound_t('contact:envelope_d', 1.0e-9_dp, 10.0_dp, 'm', .false.), &
      bound_t('contact:peak_penetration', 1.0e-9_dp, 10.0_dp, 'm', .false.), &
      bound_t('contact:fracture_penetration', 1.0e-9_dp, 10.0_dp, 'm', .false.), &
      bound_t('contact:envelope_r', 0.0_dp, 1.0e10_dp, 'kN', .false.), &
      bound_t('sweep:target_lambda', 0.0_dp, 1.0e6_dp, '%', .false.), &
      bound_t('sweep:refine_tolerance', 1.0e-9_dp, 1.0_dp, 'm', .false.), &
      bound_t('building:plan_size', 0.1_dp, 1.0e3_dp, 'm', .false.), &
      bound_t('building:plan_origin_y', 0.0_dp, 1.0e4_dp, 'm', .true.), &
      bound_t('building:rot_inertia', 1.0e-6_dp, 1.0e15_dp, 't m^2', .false.), &
      bound_t('plane:stiffness', 1.0e-3_dp, 1.0e12_dp, 'kN/m', .false.), &
      bound_t('contact:shear_stiffness', 1.0e-3_dp, 1.0e13_dp, 'kN/m', .false.), &
      bound_t('contact:friction', 0.0_dp, 10.0_dp, '', .false.), &
      bound_t('ground:scale_2', 1.0e-6_dp, 1.0e3_dp, '', .true.)]

contains

   !> 'deck.nml:14: &building #2 (B): ': where a message about `var` points (the line of its
   !> assignment, or of the group start when the deck does not assign it).
   pure function site_text(at, var) result(text)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      character(len=:), allocatable :: text
      integer :: i, line

      line = at%line1
      if (allocated(at%names)) then
         do i = 1, size(at%names)
            if (at%names(i) == var) line = at%lines(i)
         end do
      end if
      text = at%path//':'//str(line)//': '//at%label//': '
   end function site_text

   !> Fail with `text` at the (last) line where `var` is assigned, or the group's first line.
   pure subroutine fail(at, var, text, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      call fatal_error(error, site_text(at, var)//text, status_input)
   end subroutine fail

   !> Number of values given: position of the last one that is not `unset_real`.
   pure integer function given_count_real(raw) result(k)
      !> Namelist array as read (`unset_real` where not given).
      real(dp), intent(in) :: raw(:)

      do k = size(raw), 1, -1
         if (is_set(raw(k))) return
      end do
      k = 0
   end function given_count_real

   !> Number of values given: position of the last one that is not `unset_int`.
   pure integer function given_count_int(raw) result(k)
      !> Namelist array as read (`unset_int` where not given).
      integer, intent(in) :: raw(:)

      do k = size(raw), 1, -1
         if (raw(k) /= unset_int) return
      end do
      k = 0
   end function given_count_int

   !> A required real: error if the deck did not give it; with `rule` and `bound`, the value
   !> given is also checked (`check_real`).
   pure subroutine require_real(at, var, x, what, error, rule, bound, bound_text)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Value read.
      real(dp), intent(in) :: x
      !> What the variable is, with its unit.
      character(len=*), intent(in) :: what
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> Comparison with the bound: '>', '>=' or '/=' (none: no check).
      character(len=*), intent(in), optional :: rule
      !> Bound of the rule.
      real(dp), intent(in), optional :: bound
      !> How to show the bound (default: its value).
      character(len=*), intent(in), optional :: bound_text

      if (.not. is_set(x)) then
         call fail(at, var, var//' is missing ('//what//')', error)
      else if (present(rule) .and. present(bound)) then
         call check_real(at, var, x, rule, bound, error, bound_text)
      end if
   end subroutine require_real

   !> `x rule bound` must hold (rule: '>', '>=', '/='), and `x` must be finite.
   pure subroutine check_real(at, var, x, rule, bound, error, bound_text, name)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Value read.
      real(dp), intent(in) :: x
      !> Comparison with the bound: '>', '>=' or '/='.
      character(len=*), intent(in) :: rule
      !> Bound of the rule.
      real(dp), intent(in) :: bound
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> How to show the bound (default: its value).
      character(len=*), intent(in), optional :: bound_text
      !> How to show the variable (default: `var`), e.g. 'height(3)'.
      character(len=*), intent(in), optional :: name
      character(len=:), allocatable :: shown, limit
      logical :: ok

      if (present(name)) then
         shown = name
      else
         shown = var
      end if
      if (.not. ieee_is_finite(x)) then
         call fail(at, var, shown//' = '//str(x)//', must be a finite number', error)
         return
      end if
      select case (rule)
      case ('>')
         ok = x > bound
      case ('>=')
         ok = x >= bound
      case default
         ok = x > bound .or. x < bound
      end select
      if (ok) then
         call check_plausible(at, var, x, shown, error)
         return
      end if
      if (present(bound_text)) then
         limit = bound_text
      else if (.not. (abs(bound) > 0.0_dp)) then
         limit = '0'
      else
         limit = str(bound)
      end if
      call fail(at, var, shown//' = '//str(x)//', must be '//rule//' '//limit, error)
   end subroutine check_real

   !> Take an optional value: when the deck gives `x`, check it (`check_real`) and store it
   !> in `dest`; otherwise leave `dest` (its default) alone.
   pure subroutine take_real(at, var, x, rule, bound, dest, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Value read (`unset_real`: not given).
      real(dp), intent(in) :: x
      !> Comparison with the bound: '>', '>=' or '/='.
      character(len=*), intent(in) :: rule
      !> Bound of the rule.
      real(dp), intent(in) :: bound
      !> Where the value goes.
      real(dp), intent(inout) :: dest
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      if (.not. is_set(x)) return
      call check_real(at, var, x, rule, bound, error)
      if (.not. allocated(error)) dest = x
   end subroutine take_real

   !> `x` must lie in the plausible range of `var` (if it has one, see `bounds`).
   pure subroutine check_plausible(at, var, x, shown, error, line_of)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Value read.
      real(dp), intent(in) :: x
      !> How to show the variable, e.g. 'height(3)'.
      character(len=*), intent(in) :: shown
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> Variable whose line the message names (default `var`; for derived values).
      character(len=*), intent(in), optional :: line_of
      real(dp) :: lo, hi, v
      character(len=:), allocatable :: unit, what
      logical :: magnitude
      integer :: k

      do k = 1, size(bounds)
         if (bounds(k)%key == at%group_name//':'//var) exit
      end do
      if (k > size(bounds)) return
      lo = bounds(k)%lo
      hi = bounds(k)%hi
      unit = trim(bounds(k)%unit)
      magnitude = bounds(k)%magnitude
      v = x
      what = shown
      if (magnitude) then
         v = abs(x)
         what = '|'//shown//'|'
      end if
      if (v >= lo .and. v <= hi) return
      if (len(unit) > 0) unit = ' '//unit
      what = what//' must be in '//short_real(lo)//'..'//short_real(hi)//unit
      if (present(line_of)) then
         call fail(at, line_of, shown//' = '//str(x)//unit//', outside the plausible range: '// &
                   what//bounds_where, error)
         return
      end if
      call fail(at, var, shown//' = '//str(x)//unit//', outside the plausible range: '//what// &
                bounds_where, error)
   end subroutine check_plausible

   !> Whether the deck gave `x` (it is not the `unset_real` marker; safe for NaN).
   pure logical function is_set(x)
      !> Value read.
      real(dp), intent(in) :: x

      is_set = transfer(x, 0_int64) /= transfer(unset_real, 0_int64)
   end function is_set

   !> '1 value' or 'k values'.
   pure function values_text(k) result(s)
      !> Number of values.
      integer, intent(in) :: k
      character(len=:), allocatable :: s

      s = counted(k, 'value')
   end function values_text

end module pound_input_checks
