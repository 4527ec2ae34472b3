!> Checks of the values a group's reader got from its namelist: lengths, the namelist's
!> arrays, `history`, warnings and gfortran's read errors. The checks that know no deck
!> (required values, rules, plausible ranges, the message format `deck.nml:LINE: &group #k
!> (name): text`) are pound_input_checks', re-exported here; a deck `site` is an `input_site`
!> that also keeps its group occurrence.
module pound_deck_checks
   use pound_config, only: deck_warning_len, history_names, n_history_quantities
   use pound_deck_lexer, only: group_label, group_ref, group_text, lower
   use pound_deck_variables, only: findloc_name, join, max_columns
   use pound_error, only: error_type, fatal_error, status_input
   use pound_kinds, only: dp
   use pound_strings, only: str
   use pound_input_checks, only: input_site, check_plausible, check_real, fail, site_text, &
                                 given_count, is_set, require_real, unset_int, unset_real, values_text, bounds_where, &
                                 take_real
   implicit none
   private

   public :: check_plausible, check_real, fail, warn, site_text, given_count, group_input, is_set, parse_history, &
             read_failed, require_real, site, site_of, take_ints, take_real, take_reals, take_sa_period, unset_int, &
             unset_real, values_text, widen

   !> Where a message points: an `input_site` and the group occurrence it was made from.
   type, extends(input_site) :: site
      !> The group occurrence (its assignments, for the readers that ask what was given).
      type(group_ref) :: group
   end type site

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

      integer :: i

      at%path = path
      at%label = group_label(g)
      at%group = g
      at%group_name = g%name
      at%line1 = g%line1
      allocate (at%names(g%n_vars), at%lines(g%n_vars))
      do i = 1, g%n_vars
         at%names(i) = g%vars(i)%name
         at%lines(i) = g%vars(i)%line
      end do
   end function site_of

   !> What a group's reader starts from: the site of the group occurrence (where its messages
   !> point), its text as one record for the namelist read, and a cleared `iomsg` buffer.
   pure subroutine group_input(path, text, g, at, buf, msg)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Where the reader's messages point.
      type(site), intent(out) :: at
      !> The group's text, one record.
      character(len=:), allocatable, intent(out) :: buf
      !> The namelist read's `iomsg`, blank.
      character(len=*), intent(out) :: msg

      at = site_of(path, g)
      call group_text(text, g, buf)
      msg = ' '
   end subroutine group_input

   !> `period` (s) of a 5 %-damped Sa: given only where the intensity measure (variable
   !> `measure_var`, value `measure`: 'sa' or 'pga') is 'sa'; when given, > 0 and stored in `dest`.
   pure subroutine take_sa_period(at, measure_var, measure, period, dest, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Name of the variable that chooses the measure (e.g. 'scale_to').
      character(len=*), intent(in) :: measure_var
      !> The measure chosen ('sa' or 'pga').
      character(len=*), intent(in) :: measure
      !> `period` as read (`unset_real`: not given).
      real(dp), intent(in) :: period
      !> Where the period goes (left alone when not given).
      real(dp), intent(inout) :: dest
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      if (.not. is_set(period)) return
      if (measure /= 'sa') then
         call fail(at, 'period', 'period applies only with '//measure_var//" = 'sa'", error)
         return
      end if
      call take_real(at, 'period', period, '>', 0.0_dp, dest, error)
   end subroutine take_sa_period

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
