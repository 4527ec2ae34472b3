!> Deck text to groups and checked assignments: line ends (LF, CR LF, CR) and a UTF-8
!> byte-order mark normalised, groups found with their lines, each group's assignments
!> tokenised and checked against the table of pound_deck_variables (known variable,
!> subscript, value types, repeat counts, sizes, duplicates) before gfortran reads it.
module pound_deck_lexer
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_deck_variables, only: known_groups, known_variable, variable_list, variable_type
   use pound_error, only: error_type, fatal_error, status_input
   use pound_strings, only: decimal_exponent, number_end, shorten, str
   use pound_deck_values, only: lower, value_problem
   implicit none
   private

   public :: base_name, find_single, group_extent, group_label, group_ref, group_text, is_name_char, lower, &
             normalize_text, scan_groups

   character(len=*), parameter :: lf = achar(10), cr = achar(13), tab = achar(9)

   !> UTF-8 byte-order mark, dropped from the start of a deck.
   character(len=*), parameter :: bom = char(239)//char(187)//char(191)

   !> Characters that end a value or name in a group.
   character(len=*), parameter :: word_stops = ' ,/=!&'//tab//"'"//'"'

   !> Token kinds of a group's body.
   integer, parameter :: tok_word = 1, tok_quoted = 2, tok_equals = 3, tok_comma = 4

   !> A variable assignment seen in a group (`name =` or `name(i) =`).
   type :: var_ref
      !> Variable name, lower case.
      character(len=:), allocatable :: name
      !> Deck line of the assignment.
      integer :: line = 0
      !> Elements assigned: lo..hi (scalars 1..1; hi < lo: only null values).
      integer :: lo = 1, hi = 0
   end type var_ref

   !> Tokens of a group's body: kind, first and last position, line (one column each).
   type :: token_list
      !> Number of tokens.
      integer :: n = 0
      !> Token data, (4, capacity).
      integer, allocatable :: t(:, :)
   end type token_list

   !> One occurrence of a namelist group in the deck.
   type :: group_ref
      !> Group name, lower case.
      character(len=:), allocatable :: name
      !> 1 for the first occurrence of this group name, 2 for the second, ...
      integer :: occurrence = 0
      !> Line and position in the deck text of the `&` that opens the group.
      integer :: line1 = 0, pos1 = 0
      !> Line and position of the `/` (or `&end`) that closes the group.
      integer :: line2 = 0, pos2 = 0
      !> Number of assignments seen.
      integer :: n_vars = 0
      !> Assignments seen (first `n_vars` used).
      type(var_ref), allocatable :: vars(:)
   end type group_ref

contains

   !> `raw` with every line end made one LF: LF, CR LF, CR CR LF (a run of CRs before an LF)
   !> and a lone CR (old Mac files: each CR ends a line); a leading UTF-8 byte-order mark and
   !> the final line end are dropped.
   pure subroutine normalize_text(raw, text)
      !> The file's bytes.
      character(len=*), intent(in) :: raw
      !> The text, lines separated by LF.
      character(len=:), allocatable, intent(out) :: text
      integer :: i, j, k, n

      n = len(raw)
      allocate (character(len=n) :: text)
      i = 1
      if (n >= 3) then
         if (raw(1:3) == bom) i = 4
      end if
      j = 0
      do while (i <= n)
         if (raw(i:i) == cr) then
            k = i
            do while (k <= n)
               if (raw(k:k) /= cr) exit
               k = k + 1
            end do
            if (k <= n) then
               if (raw(k:k) == lf) then
                  ! CR...CR LF: one line end.
                  j = j + 1
                  text(j:j) = lf
                  i = k + 1
                  cycle
               end if
            end if
            ! Lone CRs: one line end each.
            text(j + 1:j + k - i) = repeat(lf, k - i)
            j = j + k - i
            i = k
            cycle
         end if
         j = j + 1
         text(j:j) = raw(i:i)
         i = i + 1
      end do
      if (j > 0) then
         if (text(j:j) == lf) j = j - 1
      end if
      text = text(1:j)
   end subroutine normalize_text

   !> Position of the LF that ends the line holding position `i` (len(text) + 1 if none).
   pure integer function line_end(text, i) result(k)
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> A position in `text`.
      integer, intent(in) :: i

      k = index(text(i:), lf)
      if (k == 0) then
         k = len(text) + 1
      else
         k = i + k - 1
      end if
   end function line_end

   !> Find the groups, their extent and their assignments; reject text outside groups,
   !> unknown groups, unclosed groups, unknown variables and values that do not fit their
   !> variable (see `scan_body`).
   pure subroutine scan_groups(path, text, groups, n_groups, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> Groups found, in deck order (first `n_groups` used).
      type(group_ref), allocatable, intent(out) :: groups(:)
      !> Number of groups found.
      integer, intent(out) :: n_groups
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(group_ref), allocatable :: tmp(:)
      character(len=:), allocatable :: gname
      character :: c
      integer :: i, j, k, line

      allocate (groups(8))
      n_groups = 0
      i = 1
      line = 1
      do while (i <= len(text))
         c = text(i:i)
         if (c == lf) then
            line = line + 1
         else if (c == '!') then
            i = line_end(text, i)
            cycle
         else if (c == '&') then
            j = name_end(text, i + 1)
            gname = lower(text(i + 1:j))
            if (.not. any(known_groups == gname) .or. len(gname) == 0) then
               call fatal_error(error, path//':'//str(line)//": unknown namelist group '&"// &
                                printable(text(i + 1:j))//"'; known groups: &analysis, "// &
                                '&ground, &building, &plane, &contact, &sweep, &stripes, &hazard', status_input)
               return
            end if
            if (n_groups == size(groups)) then
               allocate (tmp(2*size(groups)))
               tmp(1:n_groups) = groups(1:n_groups)
               call move_alloc(tmp, groups)
            end if
            n_groups = n_groups + 1
            groups(n_groups)%name = gname
            groups(n_groups)%occurrence = count([(groups(k)%name == gname, k=1, n_groups)])
            groups(n_groups)%line1 = line
            groups(n_groups)%pos1 = i
            allocate (groups(n_groups)%vars(16))
            call scan_body(path, text, j + 1, line, groups(n_groups), i, error)
            if (allocated(error)) return
            cycle
         else if (c /= ' ' .and. c /= tab) then
            call fatal_error(error, path//':'//str(line)//": text outside a namelist group: '"// &
                             printable(trim(text(i:min(line_end(text, i) - 1, i + 39))))// &
                             "'; groups start with &name and end with /, comments start with !", status_input)
            return
         end if
         i = i + 1
      end do
   end subroutine scan_groups

   !> The body of group `g` from `start` to its closing `/` or `&end`: split into tokens
   !> (names, values, quoted values, `=`, `,`), then checked by `check_assignments`.
   !> On return `next` is the position after the close and `line` its line.
   pure subroutine scan_body(path, text, start, line, g, next, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> First position after the group name.
      integer, intent(in) :: start
      !> Current line (updated).
      integer, intent(inout) :: line
      !> The group occurrence (extent and assignments filled in).
      type(group_ref), intent(inout) :: g
      !> Position after the group's close.
      integer, intent(out) :: next
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(token_list) :: toks
      character :: c
      integer :: i, j, k, n, depth, nl

      n = len(text)
      i = start
      next = n + 1
      do while (i <= n)
         c = text(i:i)
         select case (c)
         case (lf)
            line = line + 1
            i = i + 1
         case (' ', tab)
            i = i + 1
         case ('!')
            i = line_end(text, i)
         case ('/')
            g%pos2 = i
            g%line2 = line
            next = i + 1
            exit
         case ('&')
            j = name_end(text, i + 1)
            if (lower(text(i + 1:j)) /= 'end') then
               call fatal_error(error, path//':'//str(g%line1)//': '//group_label(g)// &
                                " is not closed with '/' before line "//str(line), status_input)
               return
            end if
            g%pos2 = i
            g%line2 = line
            next = j + 1
            exit
         case ('=')
            call push_token(toks, tok_equals, i, i, line)
            i = i + 1
         case (',')
            call push_token(toks, tok_comma, i, i, line)
            i = i + 1
         case ("'", '"')
            call quoted_end(text, i, j, nl)
            if (j == 0) then
               call fatal_error(error, path//':'//str(g%line1)//': '//group_label(g)// &
                                ': a character value opened with '//c//' is not closed', status_input)
               return
            end if
            call push_token(toks, tok_quoted, i, j, line)
            line = line + nl
            i = j + 1
         case default
            j = i
            depth = 0
            do while (j <= n)
               c = text(j:j)
               if (c == lf) exit
               if (c == '(') depth = depth + 1
               if (c == ')') depth = max(0, depth - 1)
               if (depth == 0 .and. index(word_stops, c) > 0) exit
               j = j + 1
            end do
            nl = 0
            if (j <= n .and. j > i) then
               ! A repeat count followed by a quoted value: 3*'text'.
               if (text(j - 1:j - 1) == '*' .and. (text(j:j) == "'" .or. text(j:j) == '"')) then
                  call quoted_end(text, j, k, nl)
                  if (k > 0) j = k + 1
               end if
            end if
            call push_token(toks, tok_word, i, j - 1, line)
            line = line + nl
            i = j
         end select
      end do
      if (next > n .and. g%pos2 == 0) then
         call fatal_error(error, path//':'//str(g%line1)//': '//group_label(g)// &
                          " is not closed with '/'", status_input)
         return
      end if
      call check_assignments(path, text, toks, g, error)
   end subroutine scan_body

   !> End `j` of the quoted value starting at `i` (0 if not closed); `nl` line ends inside.
   pure subroutine quoted_end(text, i, j, nl)
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> Position of the opening quote.
      integer, intent(in) :: i
      !> Position of the closing quote, 0 if none.
      integer, intent(out) :: j
      !> Number of line ends inside the value.
      integer, intent(out) :: nl
      integer :: k

      nl = 0
      k = i + 1
      do while (k <= len(text))
         if (text(k:k) == text(i:i)) then
            if (k < len(text)) then
               if (text(k + 1:k + 1) == text(i:i)) then
                  k = k + 2
                  cycle
               end if
            end if
            j = k
            return
         end if
         if (text(k:k) == lf) nl = nl + 1
         k = k + 1
      end do
      j = 0
   end subroutine quoted_end

   !> Append a token to `toks`.
   pure subroutine push_token(toks, kind, first, last, line)
      !> Tokens of a group.
      type(token_list), intent(inout) :: toks
      !> Token kind (`tok_word`, ...), its first and last position and its line.
      integer, intent(in) :: kind, first, last, line
      integer, allocatable :: tmp(:, :)

      if (.not. allocated(toks%t)) allocate (toks%t(4, 64))
      if (toks%n == size(toks%t, 2)) then
         allocate (tmp(4, 2*toks%n))
         tmp(:, 1:toks%n) = toks%t(:, 1:toks%n)
         call move_alloc(tmp, toks%t)
      end if
      toks%n = toks%n + 1
      toks%t(:, toks%n) = [kind, first, last, line]
   end subroutine push_token

   !> Index of the `=` when token `k` starts an assignment (`name =` or
   !> `name (subscript) =`), else 0.
   pure integer function assignment_eq(text, toks, k) result(neq)
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> Tokens of a group.
      type(token_list), intent(in) :: toks
      !> Token index.
      integer, intent(in) :: k

      neq = 0
      if (k + 1 > toks%n) return
      if (toks%t(1, k) /= tok_word) return
      if (toks%t(1, k + 1) == tok_equals) then
         neq = k + 1
      else if (k + 2 <= toks%n .and. toks%t(1, k + 1) == tok_word) then
         if (text(toks%t(2, k + 1):toks%t(2, k + 1)) /= '(') return
         if (toks%t(1, k + 2) /= tok_equals) return
         neq = k + 2
      end if
   end function assignment_eq

   !> Check every assignment of group `g` against its variable: known name, subscript in
   !> range, each value of the variable's type (real, integer, logical, character), repeat
   !> counts >= 1, no more values than the variable holds, no variable (or element) given
   !> twice. Records the assignments in `g%vars`.
   pure subroutine check_assignments(path, text, toks, g, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> Tokens of the group's body.
      type(token_list), intent(in) :: toks
      !> The group occurrence.
      type(group_ref), intent(inout) :: g
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: starts(:), eqs(:)
      character(len=:), allocatable :: label, left, right, designator, vname, why
      character :: vtype
      integer :: na, k, m, neq, first, last, vsize, lo, hi_lim, line, i, rep, tline, before
      integer(int64) :: positions, hi
      logical :: seen, null

      ! Pass 1: where the assignments start; the building's or the contact's names.
      allocate (starts(toks%n + 1), eqs(toks%n + 1))
      na = 0
      left = ''
      right = ''
      label = group_label(g)
      k = 1
      do while (k <= toks%n)
         neq = assignment_eq(text, toks, k)
         if (neq > 0) then
            na = na + 1
            starts(na) = k
            eqs(na) = neq
            if (neq + 1 <= toks%n) then
               if (toks%t(1, neq + 1) == tok_quoted) then
                  vname = lower(text(toks%t(2, k):toks%t(3, k)))
                  why = text(toks%t(2, neq + 1) + 1:toks%t(3, neq + 1) - 1)
                  if (vname == 'name' .or. vname == 'left') left = why
                  if (g%name == 'plane' .and. vname == 'building') left = why
                  if (vname == 'right') right = why
               end if
            end if
            k = neq + 1
         else if (na == 0) then
            call fatal_error(error, path//':'//str(toks%t(4, k))//': '//label//": expected "// &
                             "'name = value', found '"//token_text(text, toks, k)//"'", status_input)
            return
         else
            k = k + 1
         end if
      end do
      starts(na + 1) = toks%n + 1
      if ((g%name == 'building' .or. g%name == 'plane') .and. len(left) > 0) label = label//' ('//printable(left)//')'
      if (g%name == 'contact' .and. len(left) > 0 .and. len(right) > 0) &
         label = label//' ('//printable(left)//', '//printable(right)//')'

      ! Pass 2: each assignment, checked against the group's earlier ones (`earlier_owner`).
      do m = 1, na
         k = starts(m)
         line = toks%t(4, k)
         first = toks%t(2, k)
         last = toks%t(3, eqs(m) - 1)
         designator = text(first:last)
         i = index(designator, '(')
         if (i > 0) then
            vname = lower(trim(designator(1:i - 1)))
         else
            vname = lower(designator)
         end if
         if (.not. known_variable(g%name, vname)) then
            call fatal_error(error, path//':'//str(line)//': '//label//": unknown variable '"// &
                             printable(vname)//"'; known: "//variable_list(g%name), status_input)
            return
         end if
         call variable_type(g%name, vname, vtype, vsize)
         lo = 1
         hi_lim = max(vsize, 1)
         if (i > 0) then
            call parse_subscript(designator(i:), vname, vsize, lo, hi_lim, why)
            if (len(why) > 0) then
               call fatal_error(error, path//':'//str(line)//': '//label//': '//why, status_input)
               return
            end if
         end if
         positions = 0
         seen = .false.
         do k = eqs(m) + 1, starts(m + 1) - 1
            select case (toks%t(1, k))
            case (tok_comma)
               if (.not. seen) positions = positions + 1
               seen = .false.
            case (tok_equals)
               call fatal_error(error, path//':'//str(toks%t(4, k))//': '//label//': '//vname// &
                                ": unexpected '='; write "//vname//' = value', status_input)
               return
            case default
               tline = toks%t(4, k)
               why = ''
               if (toks%t(1, k) == tok_word) then
                  if (known_variable(g%name, lower(token_text(text, toks, k)))) &
                     why = "'=' is missing after the variable name '"//token_text(text, toks, k)//"'"
               end if
               if (len(why) == 0) call value_problem(token_text(text, toks, k), vtype, rep, null, why)
               if (len(why) > 0) then
                  if (vsize > 0) then
                     designator = vname//'('//str(int(lo + positions))//')'
                  else
                     designator = vname
                  end if
                  call fatal_error(error, path//':'//str(tline)//': '//label//': '//designator// &
                                   ' = '//shorten(printable(token_text(text, toks, k)))//': '//why, status_input)
                  return
               end if
               positions = positions + rep
               seen = .true.
            end select
         end do
         hi = lo + positions - 1
         if (vsize == 0 .and. positions > 1) then
            call fatal_error(error, path//':'//str(line)//': '//label//': '//vname//' has '// &
                             str(int(min(positions, int(huge(1), int64))))//' values, takes one', status_input)
            return
         end if
         if (hi > hi_lim) then
            if (i > 0) then
               why = vname//' from element '//str(lo)//' has '//str(int(min(positions, int(huge(1), int64))))// &
                     ' values, ending beyond element '//str(hi_lim)
            else
               why = vname//' has '//str(int(min(positions, int(huge(1), int64))))// &
                     ' values, must have at most '//str(hi_lim)
            end if
            call fatal_error(error, path//':'//str(line)//': '//label//': '//why, status_input)
            return
         end if
         call earlier_owner(g, vname, lo, int(hi), k, before)
         if (k > 0) then
            if (vsize > 0) then
               why = vname//'('//str(k)//') is given twice (also on line '// &
                     str(before)//'); give each value once per group'
            else
               why = vname//' is given twice (also on line '//str(before)// &
                     '); give each variable once per group'
            end if
            call fatal_error(error, path//':'//str(line)//': '//label//': '//why, status_input)
            return
         end if
         call add_var(g, vname, line, lo, int(hi))
      end do
   end subroutine check_assignments

   !> Text of token `k`.
   pure function token_text(text, toks, k) result(s)
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> Tokens of a group.
      type(token_list), intent(in) :: toks
      !> Token index.
      integer, intent(in) :: k
      character(len=:), allocatable :: s

      s = text(toks%t(2, k):toks%t(3, k))
   end function token_text

   !> Subscript `(i)` or `(i:j)` of array `vname` (`vsize` elements): first element `lo` and
   !> last allowed `hi`; `why` is '' or what is wrong.
   pure subroutine parse_subscript(sub, vname, vsize, lo, hi, why)
      !> Text from the `(` on.
      character(len=*), intent(in) :: sub
      !> Variable name, lower case.
      character(len=*), intent(in) :: vname
      !> Number of elements (0: scalar).
      integer, intent(in) :: vsize
      !> First element and last allowed element.
      integer, intent(inout) :: lo, hi
      !> Empty when the subscript is fine.
      character(len=:), allocatable, intent(out) :: why
      character(len=:), allocatable :: inner
      integer :: colon, e

      why = ''
      if (vsize == 0) then
         why = vname//' is not an array; write '//vname//' = value'
         return
      end if
      e = index(sub, ')', back=.true.)
      if (e == 0) e = len(sub) + 1
      inner = trim(adjustl(sub(2:e - 1)))
      colon = index(inner, ':')
      if (colon == 0) then
         call subscript_int(inner, lo, why)
         if (len(why) == 0) hi = vsize
      else
         call subscript_int(trim(adjustl(inner(1:colon - 1))), lo, why)
         if (len(why) == 0) call subscript_int(trim(adjustl(inner(colon + 1:))), hi, why)
      end if
      if (len(why) > 0) then
         why = vname//printable(sub)//': the subscript must be an integer or i:j'
         return
      end if
      if (lo < 1 .or. lo > vsize) then
         why = vname//'('//str(lo)//'): index '//str(lo)//' is out of range, must be in 1..'//str(vsize)
      else if (hi < lo .or. hi > vsize) then
         why = vname//printable(sub)//': index '//str(hi)//' is out of range, must be in '// &
               str(lo)//'..'//str(vsize)
      end if
   end subroutine parse_subscript

   !> A subscript integer (at most 9 digits, optional sign).
   pure subroutine subscript_int(s, i, why)
      !> Text of the integer.
      character(len=*), intent(in) :: s
      !> Its value.
      integer, intent(out) :: i
      !> Empty when `s` is an integer.
      character(len=:), allocatable, intent(out) :: why
      integer :: b

      why = 'bad'
      i = 0
      b = 1
      if (len(s) == 0) return
      if (s(1:1) == '-' .or. s(1:1) == '+') b = 2
      if (len(s) < b .or. len(s) - b + 1 > 9) return
      if (verify(s(b:), '0123456789') /= 0) return
      read (s, *) i
      why = ''
   end subroutine subscript_int

   !> What is wrong with value token `t` for a variable of type `vtype` ('r' real,
   !> 'i' integer, 'l' logical, 'c' character): `why` is '' when nothing; `rep` the
   !> Whether `v` spells an IEEE special value the namelist read accepts (Inf, Infinity,
   !> `s` with control characters shown as `<NUL>` or `<0xNN>`.
   pure function printable(s) result(t)
      !> Text from the deck.
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: t
      character(len=*), parameter :: hex = '0123456789ABCDEF'
      integer :: i, code

      t = ''
      do i = 1, len(s)
         code = iachar(s(i:i))
         if (code == 0) then
            t = t//'<NUL>'
         else if (code < 32 .or. code == 127) then
            t = t//'<0x'//hex(code/16 + 1:code/16 + 1)//hex(mod(code, 16) + 1:mod(code, 16) + 1)//'>'
         else
            t = t//s(i:i)
         end if
      end do
   end function printable

   !> Last position of the name starting at `from` in `line` (`from - 1` if none).
   pure integer function name_end(line, from) result(j)
      !> One deck line.
      character(len=*), intent(in) :: line
      !> First position of the name.
      integer, intent(in) :: from

      j = from - 1
      do while (j + 1 <= len(line))
         if (.not. is_name_char(line(j + 1:j + 1))) exit
         j = j + 1
      end do
   end function name_end

   !> Record an assignment of `name` on `line` in group `g`, covering elements `lo`..`hi`
   !> The highest element any assignment of group `g` gives (at least 1): the length a
   !> namelist array of the group needs to read the deck's values.
   pure integer function group_extent(g) result(n)
      !> The group occurrence, scanned.
      type(group_ref), intent(in) :: g
      integer :: j

      n = 1
      do j = 1, g%n_vars
         n = max(n, g%vars(j)%hi)
      end do
   end function group_extent

   !> The first element `k` of `lo..hi` of variable `name` that an earlier assignment of group
   !> `g` gave, and the `line` of that assignment (k = 0: none). Each element is given at most
   !> once (a second time is an error), so the earlier assignments do not overlap each other.
   pure subroutine earlier_owner(g, name, lo, hi, k, line)
      !> The group occurrence, with the assignments seen so far.
      type(group_ref), intent(in) :: g
      !> Variable name, lower case.
      character(len=*), intent(in) :: name
      !> First and last element of the new assignment (hi < lo: none).
      integer, intent(in) :: lo, hi
      !> First element given before (0: none) and the line that gave it.
      integer, intent(out) :: k, line
      integer :: j, first

      k = 0
      line = 0
      do j = 1, g%n_vars
         if (g%vars(j)%name /= name) cycle
         first = max(lo, g%vars(j)%lo)
         if (first > min(hi, g%vars(j)%hi)) cycle
         if (k == 0 .or. first < k) then
            k = first
            line = g%vars(j)%line
         end if
      end do
   end subroutine earlier_owner

   !> (scalars: 1..1; `hi < lo` when only null values were given).
   pure subroutine add_var(g, name, line, lo, hi)
      !> Group the assignment belongs to.
      type(group_ref), intent(inout) :: g
      !> Variable name, lower case.
      character(len=*), intent(in) :: name
      !> Deck line number, first and last element assigned.
      integer, intent(in) :: line, lo, hi
      type(var_ref), allocatable :: tmp(:)

      if (g%n_vars == size(g%vars)) then
         allocate (tmp(2*size(g%vars)))
         tmp(1:g%n_vars) = g%vars(1:g%n_vars)
         call move_alloc(tmp, g%vars)
      end if
      g%n_vars = g%n_vars + 1
      g%vars(g%n_vars)%name = name
      g%vars(g%n_vars)%line = line
      g%vars(g%n_vars)%lo = lo
      g%vars(g%n_vars)%hi = hi
   end subroutine add_var

   !> `&name` for groups that occur once, `&name #k` for `&building`, `&contact` and `&plane`.
   pure function group_label(g) result(s)
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      character(len=:), allocatable :: s

      if (g%name == 'building' .or. g%name == 'contact' .or. g%name == 'plane') then
         s = '&'//g%name//' #'//str(g%occurrence)
      else
         s = '&'//g%name
      end if
   end function group_label

   !> Index of the single occurrence of group `name`; error if missing or repeated.
   pure subroutine find_single(path, groups, name, contents, idx, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> All groups, in deck order.
      type(group_ref), intent(in) :: groups(:)
      !> Name to look up / record.
      character(len=*), intent(in) :: name
      !> What the group holds (for the message).
      character(len=*), intent(in) :: contents
      !> Index of the group in `groups`.
      integer, intent(out) :: idx
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer :: i

      idx = 0
      do i = 1, size(groups)
         if (groups(i)%name /= name) cycle
         if (idx /= 0) then
            call fatal_error(error, path//':'//str(groups(i)%line1)//': &'//name// &
                             ' appears again (first at line '//str(groups(idx)%line1)// &
                             '); exactly one &'//name//' is allowed', status_input)
            return
         end if
         idx = i
      end do
      if (idx == 0) call fatal_error(error, path//': &'//name//' is missing; exactly one &'// &
                                     name//' is required ('//contents//')', status_input)
   end subroutine find_single

   !> Just the text of group `g`, as a one-record internal file for a namelist read:
   !> comments blanked, line ends read as blanks (inside a quoted value: as nothing, a
   !> continued character value), tabs as blanks, closed with '/'. Its length is the group's.
   pure subroutine group_text(text, g, buf)
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Internal file with just the group's text.
      character(len=:), allocatable, intent(out) :: buf
      character :: c, quote
      integer :: i, j

      allocate (character(len=g%pos2 - g%pos1 + 1) :: buf)
      quote = ' '
      j = 0
      i = g%pos1
      do while (i < g%pos2)
         c = text(i:i)
         if (quote /= ' ') then
            if (c == lf) then
               i = i + 1
               cycle
            end if
            if (c == quote) quote = ' '
         else if (c == "'" .or. c == '"') then
            quote = c
         else if (c == '!') then
            i = line_end(text, i)
            cycle
         else if (c == lf) then
            c = ' '
         end if
         if (c == tab) c = ' '
         j = j + 1
         buf(j:j) = c
         i = i + 1
      end do
      j = j + 1
      buf(j:j) = '/'
      buf = buf(1:j)
   end subroutine group_text

   !> Letters, digits and '_'.
   pure logical function is_name_char(c)
      !> Character to classify.
      character, intent(in) :: c

      select case (c)
      case ('a':'z', 'A':'Z', '0':'9', '_')
         is_name_char = .true.
      case default
         is_name_char = .false.
      end select
   end function is_name_char

   !> File name without directory and extension: 'input/a.nml' -> 'a'.
   pure function base_name(path) result(s)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: s
      integer :: dot

      s = path(index(path, '/', back=.true.) + 1:)
      dot = index(s, '.', back=.true.)
      if (dot > 1) s = s(1:dot - 1)
   end function base_name

end module pound_deck_lexer
