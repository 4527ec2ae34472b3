!> Checks of the values a group's reader got from its namelist: required, types, lengths,
!> rules (> 0, >= ...), the plausible ranges of `bounds` (docs/manual.md: Input bounds), and the
!> message format `deck.nml:LINE: &group #k (name): text` (`site`, `fail`).
module pound_deck_checks
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_config, only: deck_warning_len, history_names, n_history_quantities
   use pound_deck_lexer, only: group_label, group_ref, lower
   use pound_deck_variables, only: findloc_name, join, max_columns
   use pound_error, only: error_type, fatal_error, status_input
   use pound_kinds, only: dp
   use pound_strings, only: counted, short_real, str
   implicit none
   private

   !> Number of values given in a namelist array (real or integer).
   interface given_count
      module procedure given_count_real, given_count_int
   end interface given_count

   public :: check_plausible, check_real, fail, warn, site_text, given_count, is_set, parse_history, read_failed, &
             require_real, site, site_of, take_ints, take_real, take_reals, unset_int, unset_real, values_text, widen

   !> Marks namelist values the deck did not give.
   real(dp), parameter :: unset_real = -huge(1.0_dp)

   !> Marks namelist integers the deck did not give.
   integer, parameter :: unset_int = -huge(1)

   !> Where a refusal for a value outside its plausible range sends the user: the file that
   !> holds the whole table of bounds (the README only summarises it).
   character(len=*), parameter :: bounds_where = ' (see the input bounds in docs/manual.md, "Input bounds")'

   !> Where a message points: deck, group occurrence and its label.
   type :: site
      !> Deck path as given.
      character(len=:), allocatable :: path
      !> Group label, e.g. `&building #2 (B)`.
      character(len=:), allocatable :: label
      !> The group occurrence (for the line of a variable).
      type(group_ref) :: group
   end type site

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
   type(bound_t), parameter :: bounds(49) = [ &
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
      bound_t('sweep:refine_tolerance', 1.0e-9_dp, 1.0_dp, 'm', .false.)]


   !> `call widen(raw, n)`: lengthen a namelist array as read to `n` elements, the new ones
   !> unset (`unset_real`, `unset_int`).
   interface widen
      module procedure widen_real, widen_int
   end interface widen

contains

   !> Site of a group occurrence, labelled without a building name.
   pure function site_of(path, g) result(at)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      type(site) :: at

      at%path = path
      at%label = group_label(g)
      at%group = g
   end function site_of

   !> Fail with `text` at the (last) line where `var` is assigned, or the group's first line.
   pure subroutine fail(at, var, text, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      call fatal_error(error, site_text(at, var)//text, status_input)
   end subroutine fail

   !> 'deck.nml:14: &building #2 (B): ': where a message about `var` points (the line of its
   !> assignment, or of the group start when the deck does not assign it).
   pure function site_text(at, var) result(text)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      character(len=:), allocatable :: text
      integer :: i, line

      line = at%group%line1
      do i = 1, at%group%n_vars
         if (at%group%vars(i)%name == var) line = at%group%vars(i)%line
      end do
      text = at%path//':'//str(line)//': '//at%label//': '
   end function site_text

   !> Append a plausibility warning about `var` (suspicious, not refused) to `warnings`, in
   !> the form of `fail`'s messages.
   pure subroutine warn(at, var, text, warnings)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> The warning.
      character(len=*), intent(in) :: text
      !> The deck's warnings (unallocated: none yet).
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)
      character(len=deck_warning_len), allocatable :: grown(:)
      integer :: n

      n = 0
      if (allocated(warnings)) n = size(warnings)
      allocate (grown(n + 1))
      if (n > 0) grown(1:n) = warnings
      grown(n + 1) = site_text(at, var)//text
      call move_alloc(grown, warnings)
   end subroutine warn

   !> Pass on gfortran's message when the namelist read of a group failed (`ios /= 0`).
   pure subroutine read_failed(at, ios, msg, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> iostat of the read.
      integer, intent(in) :: ios
      !> iomsg of the read.
      character(len=*), intent(in) :: msg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      if (ios == 0) return
      call fatal_error(error, at%path//':'//str(at%group%line1)//': '//at%label//': '//trim(msg), status_input)
   end subroutine read_failed

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

   !> Lengthen the real namelist array `raw` to `n` elements, the new ones `unset_real`.
   pure subroutine widen_real(raw, n)
      !> Namelist array as read.
      real(dp), allocatable, intent(inout) :: raw(:)
      !> New length (>= its length).
      integer, intent(in) :: n
      real(dp), allocatable :: wide(:)

      allocate (wide(n), source=unset_real)
      wide(1:size(raw)) = raw
      call move_alloc(wide, raw)
   end subroutine widen_real

   !> Lengthen the integer namelist array `raw` to `n` elements, the new ones `unset_int`.
   pure subroutine widen_int(raw, n)
      !> Namelist array as read.
      integer, allocatable, intent(inout) :: raw(:)
      !> New length (>= its length).
      integer, intent(in) :: n
      integer, allocatable :: wide(:)

      allocate (wide(n), source=unset_int)
      wide(1:size(raw)) = raw
      call move_alloc(wide, raw)
   end subroutine widen_int

   !> Check a per-storey real array (exactly `n` values, each finite and `rule` 0); return them.
   pure subroutine take_reals(at, var, raw, n, rule, values, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Namelist array as read (`unset_real` where not given).
      real(dp), intent(in) :: raw(:)
      !> Number of storeys.
      integer, intent(in) :: n
      !> Comparison with the bound: '>', '>=' or '/='.
      character(len=*), intent(in) :: rule
      !> The `n` values (unallocated on error).
      real(dp), allocatable, intent(out) :: values(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, i

      k = given_count(raw)
      call check_length(at, var, k, n, error)
      if (allocated(error)) return
      do i = 1, n
         if (.not. is_set(raw(i))) then
            call fail(at, var, var//'('//str(i)//') is missing; give all '//str(n)// &
                      ' values', error)
            return
         end if
         call check_real(at, var, raw(i), rule, 0.0_dp, error, name=var//'('//str(i)//')')
         if (allocated(error)) return
      end do
      values = raw(1:n)
   end subroutine take_reals

   !> Check `n_columns`-like integer array: exactly `n` values, each >= 1.
   pure subroutine take_ints(at, var, raw, n, values, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Namelist array as read (`unset_int` where not given).
      integer, intent(in) :: raw(:)
      !> Number of storeys.
      integer, intent(in) :: n
      !> The `n` values (unallocated on error).
      integer, allocatable, intent(out) :: values(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, i

      k = given_count(raw)
      call check_length(at, var, k, n, error)
      if (allocated(error)) return
      do i = 1, n
         if (raw(i) == unset_int) then
            call fail(at, var, var//'('//str(i)//') is missing; give all '//str(n)// &
                      ' values', error)
            return
         end if
         if (raw(i) < 1) then
            call fail(at, var, var//'('//str(i)//') = '//str(raw(i))//', must be >= 1', error)
            return
         end if
         if (raw(i) > max_columns) then
            call fail(at, var, var//'('//str(i)//') = '//str(raw(i))//', outside the plausible '// &
                      'range: must be <= '//str(max_columns)//bounds_where, error)
            return
         end if
      end do
      values = raw(1:n)
   end subroutine take_ints

   !> A per-storey array must have exactly `n` values.
   pure subroutine check_length(at, var, k, n, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Number of values given, number needed.
      integer, intent(in) :: k, n
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      if (k == n) return
      if (k == 0) then
         call fail(at, var, var//' is missing; give '//values_text(n)//' (n_storeys = '//str(n)//')', error)
      else if (k == 1) then
         call fail(at, var, var//' has 1 value, must have n_storeys = '//str(n)// &
                   ' (repeat equal values: '//str(n)//'*value)', error)
      else
         call fail(at, var, var//' has '//str(k)//' values, must have n_storeys = '//str(n), error)
      end if
   end subroutine check_length

   !> A required real: error if the deck did not give it.
   pure subroutine require_real(at, var, x, what, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Value read.
      real(dp), intent(in) :: x
      !> What the variable is, with its unit.
      character(len=*), intent(in) :: what
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      if (.not. is_set(x)) call fail(at, var, var//' is missing ('//what//')', error)
   end subroutine require_real

   !> `x rule bound` must hold (rule: '>', '>=', '/='), and `x` must be finite.
   pure subroutine check_real(at, var, x, rule, bound, error, bound_text, name)
      !> Where messages point.
      type(site), intent(in) :: at
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
      type(site), intent(in) :: at
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
      type(site), intent(in) :: at
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
         if (bounds(k)%key == at%group%name//':'//var) exit
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

   !> `history`: blank/comma separated quantities, 'all' or 'none'; blank means all. With
   !> `names`, the words are those names (`store` as long) instead of `history_names`.
   pure subroutine parse_history(at, spec, store, error, var, names)
      !> Where messages point.
      type(site), intent(in) :: at
      !> The `history` string.
      character(len=*), intent(in) :: spec
      !> Which quantities are stored (as many as the names).
      logical, intent(out) :: store(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> Variable name in messages (default 'history').
      character(len=*), intent(in), optional :: var
      !> The quantities' names (default `history_names`).
      character(len=*), intent(in), optional :: names(:)
      character(len=:), allocatable :: s, word, v
      character(len=16), allocatable :: known(:)
      integer :: i, j, k

      v = 'history'
      if (present(var)) v = var
      if (present(names)) then
         known = names
      else
         known = history_names
      end if
      store = .true.
      s = lower(spec)
      do i = 1, len(s)
         if (s(i:i) == ',') s(i:i) = ' '
      end do
      if (len_trim(s) == 0) return
      store = .false.
      i = 1
      do
         do while (i <= len(s))
            if (s(i:i) /= ' ') exit
            i = i + 1
         end do
         if (i > len(s)) exit
         j = index(s(i:), ' ')
         if (j == 0) then
            j = len(s)
         else
            j = i + j - 2
         end if
         word = s(i:j)
         i = j + 1
         if (word == 'all' .or. word == 'none') then
            if (len_trim(adjustl(s)) /= len(word)) then
               call fail(at, v, v//" = '"//trim(adjustl(spec))//"': '"//word// &
                         "' must be the only word", error)
               return
            end if
            store = (word == 'all')
            return
         end if
         k = findloc_name(known, word)
         if (k == 0) then
            call fail(at, v, v//": unknown quantity '"//word//"', must be one of "// &
                      join(known)//", 'all' or 'none'", error)
            return
         end if
         store(k) = .true.
      end do
   end subroutine parse_history

end module pound_deck_checks
