!> Input deck reader: Fortran namelist groups `&analysis`, `&ground`, `&building` and `&contact`.
!>
!> The deck is read into memory once (kept in `deck%text` for the echo; any line ends, a
!> UTF-8 byte-order mark dropped, pipes read to their end), then scanned: every group must
!> start with `&name` and end with `/` (or `&end`), text between groups must be blank or a
!> `!` comment, and every assignment is checked before gfortran reads the group: known
!> variable, subscript in range, each value of the variable's type (real, integer, logical,
!> character) on its own line, repeat counts >= 1, no more values than the variable holds,
!> no variable or element given twice, no real of magnitude 1e300 or more (so the `unset_real`
!> marker cannot come from the deck). Each group occurrence is then read on its own (from a
!> one-record internal file holding just that group), so the order of the groups does not
!> matter and memory stays proportional to the deck. Raw inputs must also lie in the
!> plausible ranges of `bounds` (README: Input bounds).
!>
!> * `&analysis` and `&ground` exactly once, `&building` once per building, left to right.
!> * `&contact` zero or more times (none: the buildings are uncoupled).
!> * `&sweep` at most once, with at least one `&contact`: gap_from, gap_to (m), n_gaps, and
!>   optionally target_lambda (%) and target_quantities (default 'u a_abs drift storey_shear').
!> * Per-storey arrays need exactly `n_storeys` values, storey/floor 1 at the bottom;
!>   use the namelist repeat count for equal values: `height = 8*3.0`.
!>
!> `&contact` declares unilateral constraints (pairs of facing floors) between two buildings:
!>
!>     &contact
!>        left = 'A'                 ! building on the left (its displacement to the right closes the gaps)
!>        right = 'B'                ! building on the right
!>        floors_left = 1, 2, 3      ! floor of `left` in each pair
!>        floors_right = 1, 2, 3     ! facing floor of `right` in each pair (floors at different heights allowed)
!>        gap = 3*0.001              ! initial gap of each pair (m): one value per pair, or a single value for all
!>        law = 'elastic'            ! constraint law, see below
!>        stiffness = 1.0e6          ! joint stiffness k0 (kN/m), > 0
!>        dashpot = 0.0              ! joint dashpot c (kN s/m), >= 0, default 0
!>        dashpot_rate = 'backward_euler'  ! or 'trapezoidal'
!>     /
!>
!> `left`, `right` (building names, any case, distinct), `floors_left`, `floors_right` (same
!> count, 1..`max_pairs` pairs, each floor in 1..n_storeys of its building), `gap` (>= 0) and
!> `law` are required. The same floor pair may appear more than once. Laws and their variables:
!> 'elastic' (stiffness), 'elastic_plastic' (stiffness, yield_force), 'bilinear' (stiffness,
!> yield_force, second_slope < stiffness), 'piecewise' (envelope_d, envelope_r: points after the
!> origin), 'parabola_cubic' (peak_penetration, fracture_penetration, peak_force or stiffness,
!> n_segments = 8); see pound_contact_law (envelope rules: pound_envelope_rules). A variable the chosen
!> law does not use is an error.
!>
!> Every value is validated and resolved (masses from load coefficients, storey stiffness
!> from columns, default gravity loads, record path relative to the deck's directory).
!> The first error found is reported in one message of the form
!> `deck.nml:14: &building #2 (B): n_columns(5) = 0, must be >= 1`
!> (line of the variable's assignment, or of the group start when the variable is missing).
module pound_deck
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_text_file, only: read_whole_file
   use pound_strings, only: str, number_end, decimal_exponent, shorten, short_real
   use pound_config, only: deck_type, analysis_config, ground_config, building_config, &
                           contact_config, sweep_config, n_history_quantities, history_names, g_accel
   use pound_envelope_rules, only: check_piecewise_envelope, max_law_points
   implicit none
   private

   public :: read_deck, max_storeys, max_name_length, max_pairs

   !> Largest number of storeys a `&building` may have.
   integer, parameter :: max_storeys = 20000
   !> Longest building name (it is used as an HDF5 group name).
   integer, parameter :: max_name_length = 64
   !> Largest number of floor pairs in one `&contact`.
   integer, parameter :: max_pairs = 1000

   !> Marks namelist values the deck did not give.
   real(dp), parameter :: unset_real = -huge(1.0_dp)
   !> Marks namelist integers the deck did not give.
   integer, parameter :: unset_int = -huge(1)

   !> Largest number of columns in one storey.
   integer, parameter :: max_columns = 100000

   !> Largest number of time steps t_end/dt.
   integer, parameter :: max_steps = 1000000000

   !> Lengths of the character buffers the namelist reads into.
   integer, parameter :: title_len = 1024, path_len = 4096, word_len = 256

   character(len=*), parameter :: lf = achar(10), cr = achar(13), tab = achar(9)
   !> UTF-8 byte-order mark, dropped from the start of a deck.
   character(len=*), parameter :: bom = char(239)//char(187)//char(191)
   !> Characters that end a value or name in a group.
   character(len=*), parameter :: word_stops = ' ,/=!&'//tab//"'"//'"'
   !> Token kinds of a group's body.
   integer, parameter :: tok_word = 1, tok_quoted = 2, tok_equals = 3, tok_comma = 4

   character(len=*), parameter :: known_groups(5) = &
      [character(len=8) :: 'analysis', 'ground', 'building', 'contact', 'sweep']
   character(len=*), parameter :: analysis_vars(5) = &
      [character(len=12) :: 'title', 'dt', 't_end', 'output_every', 'history']
   character(len=*), parameter :: ground_vars(7) = &
      [character(len=6) :: 'kind', 'x0', 'a', 'b', 'file', 'format', 'scale']
   character(len=*), parameter :: building_vars(15) = &
      [character(len=14) :: 'name', 'n_storeys', 'height', 'mass', 'load_coeff', 'ref_floor_load', &
      'stiffness', 'n_columns', 'e_modulus', 'inertia', 'column_ends', 'damping_ratio', &
      'damping_modes', 'p_delta', 'gravity_load']
   character(len=*), parameter :: sweep_vars(5) = &
      [character(len=17) :: 'gap_from', 'gap_to', 'n_gaps', 'target_lambda', 'target_quantities']
   character(len=*), parameter :: contact_vars(17) = &
      [character(len=20) :: 'left', 'right', 'floors_left', 'floors_right', 'gap', 'law', &
      'stiffness', 'dashpot', 'dashpot_rate', 'yield_force', 'second_slope', 'envelope_d', 'envelope_r', &
      'peak_force', 'peak_penetration', 'fracture_penetration', 'n_segments']
   !> Constraint laws, as written in the deck.
   character(len=*), parameter :: law_names = &
      "'elastic', 'elastic_plastic', 'bilinear', 'piecewise' or 'parabola_cubic'"
   !> Largest number of envelope points of a `piecewise` law.
   integer, parameter :: max_envelope_points = max_law_points
   !> Largest number of chords per curved branch of `parabola_cubic`.
   integer, parameter :: max_segments = 64

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

   !> Where a message points: deck, group occurrence and its label.
   type :: site
      !> Deck path as given.
      character(len=:), allocatable :: path
      !> Group label, e.g. `&building #2 (B)`.
      character(len=:), allocatable :: label
      !> The group occurrence (for the line of a variable).
      type(group_ref) :: group
   end type site

   !> Plausible engineering range of a deck variable (README: Input bounds).
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
   type(bound_t), parameter :: bounds(27) = [ &
      bound_t('analysis:dt', 1.0e-7_dp, 1.0_dp, 's', .false.), &
      bound_t('analysis:t_end', 0.0_dp, 1.0e4_dp, 's', .false.), &
      bound_t('ground:x0', 1.0e-9_dp, 10.0_dp, 'm', .true.), &
      bound_t('ground:a', 0.0_dp, 1.0e3_dp, '1/s', .false.), &
      bound_t('ground:b', 1.0e-3_dp, 1.0e4_dp, 'rad/s', .false.), &
      bound_t('ground:scale', 1.0e-6_dp, 1.0e3_dp, '', .true.), &
      bound_t('building:height', 0.1_dp, 1.0e3_dp, 'm', .false.), &
      bound_t('building:mass', 1.0e-6_dp, 1.0e9_dp, 't', .false.), &
      bound_t('building:load_coeff', 1.0e-3_dp, 1.0e3_dp, '', .false.), &
      bound_t('building:ref_floor_load', 1.0e-2_dp, 1.0e8_dp, 'kN', .false.), &
      bound_t('building:stiffness', 1.0e-3_dp, 1.0e12_dp, 'kN/m', .false.), &
      bound_t('building:e_modulus', 1.0e2_dp, 1.0e10_dp, 'kN/m^2', .false.), &
      bound_t('building:inertia', 1.0e-12_dp, 1.0e4_dp, 'm^4', .false.), &
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
      bound_t('sweep:target_lambda', 0.0_dp, 1.0e6_dp, '%', .false.)]

contains

   !> Read, validate and resolve the deck at `path`.
   !>
   !> On error `deck` is left in its default state and `error%message` names the deck file,
   !> the line, the group (occurrence and building name when known), the variable and the rule.
   subroutine read_deck(path, deck, error)
      !> Deck file; record files are resolved relative to its directory.
      character(len=*), intent(in) :: path
      !> The validated deck (untouched defaults on error).
      type(deck_type), intent(out) :: deck
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(deck_type) :: d
      character(len=:), allocatable :: text

      call load_deck(path, text, error)
      if (allocated(error)) return
      call parse_deck(path, text, d, error)
      if (allocated(error)) return
      deck = d
   end subroutine read_deck

   !> Scan, read, validate and resolve the deck whose file text is `text`.
   subroutine parse_deck(path, text, d, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The resolved deck.
      type(deck_type), intent(out) :: d
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(group_ref), allocatable :: groups(:)
      integer :: n_groups, i, k, nb, ia, ig

      d%path = path
      d%text = text
      call scan_groups(path, text, groups, n_groups, error)
      if (allocated(error)) return

      call find_single(path, groups(1:n_groups), 'analysis', &
                       'title, dt, t_end, output_every, history', ia, error)
      if (allocated(error)) return
      call find_single(path, groups(1:n_groups), 'ground', &
                       "kind = 'pulse' or 'record' and its parameters", ig, error)
      if (allocated(error)) return
      nb = count([(groups(i)%name == 'building', i=1, n_groups)])
      if (nb == 0) then
         call fatal_error(error, path//': no &building group; give one &building per '// &
                          'building, left to right')
         return
      end if

      call read_analysis(path, text, groups(ia), d%analysis, error)
      if (allocated(error)) return
      call read_ground(path, text, groups(ig), d%ground, error)
      if (allocated(error)) return
      allocate (d%buildings(nb))
      k = 0
      do i = 1, n_groups
         if (groups(i)%name /= 'building') cycle
         k = k + 1
         call read_building(path, text, groups(i), d%buildings(1:k - 1), d%buildings(k), error)
         if (allocated(error)) return
      end do
      allocate (d%contacts(count([(groups(i)%name == 'contact', i=1, n_groups)])))
      k = 0
      do i = 1, n_groups
         if (groups(i)%name /= 'contact') cycle
         k = k + 1
         call read_contact(path, text, groups(i), d%buildings, d%contacts(k), error)
         if (allocated(error)) return
      end do
      k = count([(groups(i)%name == 'sweep', i=1, n_groups)])
      if (k == 0) return
      call find_single(path, groups(1:n_groups), 'sweep', 'gap_from, gap_to, n_gaps', i, error)
      if (allocated(error)) return
      call read_sweep(path, text, groups(i), size(d%contacts), d%sweep, error)
   end subroutine parse_deck

   !> Read the whole deck file; its text with LF line ends, without a UTF-8 byte-order mark
   !> and without the final newline.
   subroutine load_deck(path, text, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text.
      character(len=:), allocatable, intent(out) :: text
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: raw

      call read_whole_file(path, 'deck', raw, error)
      if (allocated(error)) return
      call normalize_text(raw, text)
   end subroutine load_deck

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
                                '&ground, &building, &contact, &sweep')
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
                             "'; groups start with &name and end with /, comments start with !")
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
                                " is not closed with '/' before line "//str(line))
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
                                ': a character value opened with '//c//' is not closed')
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
                          " is not closed with '/'")
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
      integer, allocatable :: starts(:), eqs(:), owner(:, :)
      character(len=:), allocatable :: label, left, right, designator, vname, why
      character :: vtype
      integer :: na, k, m, neq, first, last, vsize, lo, hi_lim, line, i, rep, tline, iv
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
                  if (vname == 'right') right = why
               end if
            end if
            k = neq + 1
         else if (na == 0) then
            call fatal_error(error, path//':'//str(toks%t(4, k))//': '//label//": expected "// &
                             "'name = value', found '"//token_text(text, toks, k)//"'")
            return
         else
            k = k + 1
         end if
      end do
      starts(na + 1) = toks%n + 1
      if (g%name == 'building' .and. len(left) > 0) label = label//' ('//printable(left)//')'
      if (g%name == 'contact' .and. len(left) > 0 .and. len(right) > 0) &
         label = label//' ('//printable(left)//', '//printable(right)//')'

      ! Pass 2: each assignment. owner(e, iv): line that gave element e of variable iv.
      select case (g%name)
      case ('building')
         k = max_storeys
      case ('contact')
         k = max(max_pairs, max_envelope_points)
      case default
         k = 2
      end select
      allocate (owner(k, size(contact_vars)), source=0)
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
                             printable(vname)//"'; known: "//variable_list(g%name))
            return
         end if
         call variable_type(g%name, vname, vtype, vsize)
         lo = 1
         hi_lim = max(vsize, 1)
         if (i > 0) then
            call parse_subscript(designator(i:), vname, vsize, lo, hi_lim, why)
            if (len(why) > 0) then
               call fatal_error(error, path//':'//str(line)//': '//label//': '//why)
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
                                ": unexpected '='; write "//vname//' = value')
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
                                   ' = '//shorten(printable(token_text(text, toks, k)))//': '//why)
                  return
               end if
               positions = positions + rep
               seen = .true.
            end select
         end do
         hi = lo + positions - 1
         if (vsize == 0 .and. positions > 1) then
            call fatal_error(error, path//':'//str(line)//': '//label//': '//vname//' has '// &
                             str(int(min(positions, int(huge(1), int64))))//' values, takes one')
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
            call fatal_error(error, path//':'//str(line)//': '//label//': '//why)
            return
         end if
         iv = variable_index(g%name, vname)
         do k = lo, int(hi)
            if (owner(k, iv) == 0) cycle
            if (vsize > 0) then
               why = vname//'('//str(k)//') is given twice (also on line '// &
                     str(owner(k, iv))//'); give each value once per group'
            else
               why = vname//' is given twice (also on line '//str(owner(k, iv))// &
                     '); give each variable once per group'
            end if
            call fatal_error(error, path//':'//str(line)//': '//label//': '//why)
            return
         end do
         owner(lo:int(hi), iv) = line
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
   !> values it stands for (repeat count), `null` when it is `r*` alone (r null values).
   pure subroutine value_problem(t, vtype, rep, null, why)
      !> The token as written.
      character(len=*), intent(in) :: t
      !> Variable type.
      character, intent(in) :: vtype
      !> Number of values the token stands for.
      integer, intent(out) :: rep
      !> Whether it stands for null values (the variable keeps its default).
      logical, intent(out) :: null
      !> Empty when the token fits; otherwise the rule broken.
      character(len=:), allocatable, intent(out) :: why
      character(len=:), allocatable :: v, r
      integer :: star, k

      rep = 1
      null = .false.
      why = ''
      do k = 1, len(t)
         if (iachar(t(k:k)) < 32 .or. iachar(t(k:k)) == 127) then
            if (iachar(t(k:k)) == 0) then
               why = 'contains a NUL byte (character code 0) at character '//str(k)// &
                     '; a deck is plain text'
            else
               why = 'contains the control character code '//str(iachar(t(k:k)))// &
                     ' at character '//str(k)//'; a deck is plain text'
            end if
            return
         end if
      end do
      v = t
      star = 0
      if (t(1:1) /= "'" .and. t(1:1) /= '"') star = index(t, '*')
      if (star > 0) then
         r = t(1:star - 1)
         if (len(r) > 0 .and. verify(r, '0123456789') == 0) then
            if (len(r) - verify(r, '0') + 1 > 9 .and. verify(r, '0') > 0) then
               why = 'repeat count '//r//' is too large'
               return
            end if
            read (r, *) rep
            if (rep == 0) then
               why = 'repeat count 0, must be >= 1 (r*value stands for r equal values)'
               return
            end if
            v = t(star + 1:)
            if (len(v) == 0) then
               null = .true.
               return
            end if
         end if
      end if
      select case (vtype)
      case ('r')
         if (v(1:1) == "'" .or. v(1:1) == '"' .or. star > 0 .and. len(v) == len(t)) then
            why = 'expected a real number'
         else if (number_end(v) == len(v)) then
            if (decimal_exponent(v) >= 300) then
               why = 'out of range, the magnitude of a deck value must be below 1e300'
            end if
         else if (.not. is_special_real(v)) then
            why = 'expected a real number'
         end if
      case ('i')
         call integer_problem(v, why)
      case ('l')
         select case (lower(v))
         case ('t', 'f', '.t', '.f', '.t.', '.f.', 'true', 'false', '.true.', '.false.')
         case default
            why = 'expected a logical: .true. or .false.'
         end select
      end select
   end subroutine value_problem

   !> What is wrong with `v` as a deck integer: '' when it is one in -999999999..2147483647.
   pure subroutine integer_problem(v, why)
      !> The value as written (repeat count removed).
      character(len=*), intent(in) :: v
      !> Empty when `v` fits.
      character(len=:), allocatable, intent(out) :: why
      character(len=:), allocatable :: digits
      integer :: b

      why = ''
      b = 1
      if (v(1:1) == '+' .or. v(1:1) == '-') b = 2
      if (len(v) < b .or. verify(v(b:), '0123456789') /= 0) then
         why = 'expected an integer'
         return
      end if
      digits = v(b:)
      if (verify(digits, '0') == 0) return
      digits = digits(verify(digits, '0'):)
      if (v(1:1) == '-') then
         if (len(digits) > 9) why = 'integer out of range, must be >= -999999999'
      else if (len(digits) > 10 .or. (len(digits) == 10 .and. digits > '2147483647')) then
         why = 'integer out of range, must be <= 2147483647'
      end if
   end subroutine integer_problem

   !> Whether `v` spells an IEEE special value the namelist read accepts (Inf, Infinity,
   !> NaN, with an optional sign); the range checks then refuse it by name.
   pure logical function is_special_real(v)
      !> The value as written.
      character(len=*), intent(in) :: v
      character(len=:), allocatable :: s

      s = lower(v)
      if (s(1:1) == '+' .or. s(1:1) == '-') s = s(2:)
      is_special_real = s == 'inf' .or. s == 'infinity' .or. s == 'nan'
   end function is_special_real

   !> Type ('r', 'i', 'l', 'c') and number of elements (0: scalar) of variable `name` of
   !> group `group`.
   pure subroutine variable_type(group, name, vtype, vsize)
      !> Group name and variable name, lower case.
      character(len=*), intent(in) :: group, name
      !> Type letter.
      character, intent(out) :: vtype
      !> Number of elements, 0 for a scalar.
      integer, intent(out) :: vsize

      vsize = 0
      select case (name)
      case ('title', 'history', 'kind', 'file', 'format', 'name', 'column_ends', 'left', 'right', &
            'law', 'dashpot_rate', 'target_quantities')
         vtype = 'c'
      case ('output_every', 'n_storeys', 'n_segments', 'n_gaps')
         vtype = 'i'
      case ('n_columns')
         vtype = 'i'
         vsize = max_storeys
      case ('damping_modes')
         vtype = 'i'
         vsize = 2
      case ('floors_left', 'floors_right')
         vtype = 'i'
         vsize = max_pairs
      case ('p_delta')
         vtype = 'l'
      case ('height', 'mass', 'load_coeff', 'e_modulus', 'inertia', 'gravity_load')
         vtype = 'r'
         vsize = max_storeys
      case ('gap')
         vtype = 'r'
         vsize = max_pairs
      case ('envelope_d', 'envelope_r')
         vtype = 'r'
         vsize = max_envelope_points
      case ('stiffness')
         vtype = 'r'
         if (group == 'building') vsize = max_storeys
      case default
         vtype = 'r'
      end select
   end subroutine variable_type

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

   !> Whether `name` is a variable of group `group` (groups read elsewhere accept anything).
   pure logical function known_variable(group, name)
      !> Group name and variable name, lower case.
      character(len=*), intent(in) :: group, name

      known_variable = variable_index(group, name) > 0
   end function known_variable

   !> Position of variable `name` in the list of group `group` (0: not a variable of it).
   pure integer function variable_index(group, name) result(k)
      !> Group name and variable name, lower case.
      character(len=*), intent(in) :: group, name

      select case (group)
      case ('analysis')
         k = findloc_name(analysis_vars, name)
      case ('ground')
         k = findloc_name(ground_vars, name)
      case ('building')
         k = findloc_name(building_vars, name)
      case ('contact')
         k = findloc_name(contact_vars, name)
      case ('sweep')
         k = findloc_name(sweep_vars, name)
      case default
         k = 0
      end select
   end function variable_index

   !> The variables of `group`, comma separated.
   pure function variable_list(group) result(list)
      !> Group name, lower case.
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: list

      select case (group)
      case ('analysis')
         list = join(analysis_vars)
      case ('ground')
         list = join(ground_vars)
      case ('building')
         list = join(building_vars)
      case ('contact')
         list = join(contact_vars)
      case ('sweep')
         list = join(sweep_vars)
      case default
         list = ''
      end select
   end function variable_list

   !> Words joined by ', '.
   pure function join(words) result(s)
      !> Words to join (trailing blanks dropped).
      character(len=*), intent(in) :: words(:)
      character(len=:), allocatable :: s
      integer :: i

      s = trim(words(1))
      do i = 2, size(words)
         s = s//', '//trim(words(i))
      end do
   end function join

   !> `&name` for groups that occur once, `&name #k` for `&building` and `&contact`.
   pure function group_label(g) result(s)
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      character(len=:), allocatable :: s

      if (g%name == 'building' .or. g%name == 'contact') then
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
                             '); exactly one &'//name//' is allowed')
            return
         end if
         idx = i
      end do
      if (idx == 0) call fatal_error(error, path//': &'//name//' is missing; exactly one &'// &
                                     name//' is required ('//contents//')')
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
      integer :: i, line

      line = at%group%line1
      do i = 1, at%group%n_vars
         if (at%group%vars(i)%name == var) line = at%group%vars(i)%line
      end do
      call fatal_error(error, at%path//':'//str(line)//': '//at%label//': '//text)
   end subroutine fail

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
      call fatal_error(error, at%path//':'//str(at%group%line1)//': '//at%label//': '//trim(msg))
   end subroutine read_failed

   !> `&analysis`: title, time step, duration, history output.
   subroutine read_analysis(path, text, g, cfg, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Resolved `&analysis`.
      type(analysis_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=title_len) :: title
      character(len=path_len) :: history
      real(dp) :: dt, t_end
      integer :: output_every, ios
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      namelist /analysis/ title, dt, t_end, output_every, history

      title = ' '
      history = ' '
      dt = unset_real
      t_end = unset_real
      output_every = 1
      at = site_of(path, g)
      call group_text(text, g, buf)
      msg = ' '
      read (buf, nml=analysis, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      if (len_trim(title) == len(title)) then
         call fail(at, 'title', 'title is longer than '//str(len(title) - 1)//' characters', error)
         return
      end if
      if (len_trim(title) > 0) then
         cfg%title = trim(title)
      else
         cfg%title = base_name(path)
      end if

      call require_real(at, 'dt', dt, 'time step in s', error)
      if (allocated(error)) return
      call check_real(at, 'dt', dt, '>', 0.0_dp, error)
      if (allocated(error)) return
      call require_real(at, 't_end', t_end, 'duration in s', error)
      if (allocated(error)) return
      call check_real(at, 't_end', t_end, '>=', dt, error, 'dt = '//str(dt))
      if (allocated(error)) return
      if (t_end > dt*real(max_steps, dp)) then
         call fail(at, 't_end', 't_end/dt = '//str(t_end/dt)//' steps, must be <= '// &
                   str(max_steps), error)
         return
      end if
      if (output_every < 1) then
         call fail(at, 'output_every', 'output_every = '//str(output_every)//', must be >= 1', error)
         return
      end if
      cfg%dt = dt
      cfg%t_end = t_end
      cfg%output_every = output_every
      call parse_history(at, history, cfg%store, error)
   end subroutine read_analysis

   !> `history`: blank/comma separated quantities, 'all' or 'none'; blank means all.
   pure subroutine parse_history(at, spec, store, error, var)
      !> Where messages point.
      type(site), intent(in) :: at
      !> The `history` string.
      character(len=*), intent(in) :: spec
      !> Which quantities are stored.
      logical, intent(out) :: store(n_history_quantities)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> Variable name in messages (default 'history').
      character(len=*), intent(in), optional :: var
      character(len=:), allocatable :: s, word, v
      integer :: i, j, k

      v = 'history'
      if (present(var)) v = var
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
         k = findloc_name(history_names, word)
         if (k == 0) then
            call fail(at, v, v//": unknown quantity '"//word//"', must be one of "// &
                      join(history_names)//", 'all' or 'none'", error)
            return
         end if
         store(k) = .true.
      end do
   end subroutine parse_history

   !> Position of `word` in `names` (0 if absent).
   pure integer function findloc_name(names, word) result(k)
      !> Names to search, word to find.
      character(len=*), intent(in) :: names(:), word

      do k = 1, size(names)
         if (names(k) == word) return
      end do
      k = 0
   end function findloc_name

   !> `&ground`: a pulse or a record file.
   subroutine read_ground(path, text, g, cfg, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Resolved `&ground`.
      type(ground_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=word_len) :: kind, format
      character(len=path_len) :: file
      real(dp) :: x0, a, b, scale
      integer :: ios
      logical :: exists
      character(len=:), allocatable :: buf
      character(len=:), allocatable :: resolved
      character(len=512) :: msg
      type(site) :: at
      namelist /ground/ kind, x0, a, b, file, format, scale

      kind = ' '
      format = ' '
      file = ' '
      x0 = unset_real
      a = unset_real
      b = unset_real
      scale = unset_real
      at = site_of(path, g)
      call group_text(text, g, buf)
      msg = ' '
      read (buf, nml=ground, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      cfg%kind = lower(trim(adjustl(kind)))
      select case (cfg%kind)
      case ('')
         call fail(at, 'kind', "kind is missing, must be 'pulse' or 'record'", error)
      case ('pulse')
         if (len_trim(file) > 0) then
            call fail(at, 'file', "file applies only to kind = 'record'", error)
         else if (len_trim(format) > 0) then
            call fail(at, 'format', "format applies only to kind = 'record'", error)
         else if (is_set(scale)) then
            call fail(at, 'scale', "scale applies only to kind = 'record'", error)
         end if
         if (allocated(error)) return
         call require_real(at, 'x0', x0, 'pulse amplitude in m', error)
         if (allocated(error)) return
         call check_real(at, 'x0', x0, '/=', 0.0_dp, error)
         if (allocated(error)) return
         call require_real(at, 'a', a, 'pulse decay in 1/s', error)
         if (allocated(error)) return
         call check_real(at, 'a', a, '>=', 0.0_dp, error)
         if (allocated(error)) return
         call require_real(at, 'b', b, 'pulse circular frequency in rad/s', error)
         if (allocated(error)) return
         call check_real(at, 'b', b, '>', 0.0_dp, error)
         if (allocated(error)) return
         cfg%x0 = x0
         cfg%a = a
         cfg%b = b
         cfg%file = ''
         cfg%format = ''
      case ('record')
         if (is_set(x0)) then
            call fail(at, 'x0', "x0 applies only to kind = 'pulse'", error)
         else if (is_set(a)) then
            call fail(at, 'a', "a applies only to kind = 'pulse'", error)
         else if (is_set(b)) then
            call fail(at, 'b', "b applies only to kind = 'pulse'", error)
         end if
         if (allocated(error)) return
         if (len_trim(file) == 0) then
            call fail(at, 'file', 'file is missing (record file, relative to the deck''s '// &
                      'directory unless absolute)', error)
            return
         end if
         if (len_trim(file) == len(file)) then
            call fail(at, 'file', 'file is longer than '//str(len(file) - 1)//' characters', error)
            return
         end if
         resolved = resolve_path(path, trim(adjustl(file)))
         inquire (file=resolved, exist=exists)
         if (.not. exists) then
            call fail(at, 'file', "file = '"//trim(adjustl(file))//"': record file '"// &
                      resolved//"' does not exist", error)
            return
         end if
         cfg%file = resolved
         cfg%format = lower(trim(adjustl(format)))
         if (len(cfg%format) == 0) cfg%format = 'auto'
         select case (cfg%format)
         case ('auto', 'at2', 'columns')
         case default
            call fail(at, 'format', "format = '"//trim(adjustl(format))//"', must be 'auto', "// &
                      "'at2' or 'columns'", error)
            return
         end select
         if (.not. is_set(scale)) scale = 1.0_dp
         call check_real(at, 'scale', scale, '/=', 0.0_dp, error)
         if (allocated(error)) return
         cfg%scale = scale
      case default
         call fail(at, 'kind', "kind = '"//trim(adjustl(kind))//"', must be 'pulse' or 'record'", error)
      end select
   end subroutine read_ground

   !> `file` as given if absolute, else relative to the directory of the deck `deck_path`.
   pure function resolve_path(deck_path, file) result(resolved)
      !> Deck path and record file as given.
      character(len=*), intent(in) :: deck_path, file
      character(len=:), allocatable :: resolved
      integer :: slash

      slash = index(deck_path, '/', back=.true.)
      if (file(1:1) == '/' .or. slash == 0) then
         resolved = file
      else
         resolved = deck_path(1:slash)//file
      end if
   end function resolve_path

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

   !> `&building`: one shear building.
   subroutine read_building(path, text, g, previous, cfg, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Buildings read before this one.
      type(building_config), intent(in) :: previous(:)
      !> Resolved building.
      type(building_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=word_len) :: name, column_ends
      integer :: n_storeys, damping_modes(2)
      real(dp) :: ref_floor_load, damping_ratio
      logical :: p_delta
      real(dp), allocatable :: height(:), mass(:), load_coeff(:), stiffness(:), e_modulus(:), &
                               inertia(:), gravity_load(:)
      integer, allocatable :: n_columns(:)
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      integer :: ios, n
      namelist /building/ name, n_storeys, height, mass, load_coeff, ref_floor_load, stiffness, &
         n_columns, e_modulus, inertia, column_ends, damping_ratio, damping_modes, p_delta, &
         gravity_load

      allocate (height(max_storeys), mass(max_storeys), load_coeff(max_storeys), &
                stiffness(max_storeys), e_modulus(max_storeys), inertia(max_storeys), &
                gravity_load(max_storeys), n_columns(max_storeys))
      name = ' '
      column_ends = ' '
      n_storeys = unset_int
      damping_modes = unset_int
      ref_floor_load = unset_real
      damping_ratio = 0.05_dp
      p_delta = .false.
      height = unset_real
      mass = unset_real
      load_coeff = unset_real
      stiffness = unset_real
      e_modulus = unset_real
      inertia = unset_real
      gravity_load = unset_real
      n_columns = unset_int
      at = site_of(path, g)
      call group_text(text, g, buf)
      msg = ' '
      read (buf, nml=building, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      call check_name(at, name, previous, error)
      if (allocated(error)) return
      cfg%name = trim(adjustl(name))
      at%label = at%label//' ('//cfg%name//')'

      if (n_storeys == unset_int) then
         call fail(at, 'n_storeys', 'n_storeys is missing (number of storeys)', error)
         return
      end if
      if (n_storeys < 1 .or. n_storeys > max_storeys) then
         call fail(at, 'n_storeys', 'n_storeys = '//str(n_storeys)//', must be in 1..'// &
                   str(max_storeys), error)
         return
      end if
      n = n_storeys
      cfg%n_storeys = n

      call take_reals(at, 'height', height, n, '>', cfg%height, error)
      if (allocated(error)) return

      call resolve_masses(at, n, mass, load_coeff, ref_floor_load, cfg, error)
      if (allocated(error)) return
      call resolve_stiffness(at, n, stiffness, n_columns, e_modulus, inertia, &
                             column_ends, cfg, error)
      if (allocated(error)) return

      if (.not. ieee_is_finite(damping_ratio)) then
         call fail(at, 'damping_ratio', 'damping_ratio = '//str(damping_ratio)// &
                   ', must be a finite number', error)
         return
      end if
      if (damping_ratio < 0.0_dp .or. damping_ratio >= 1.0_dp) then
         call fail(at, 'damping_ratio', 'damping_ratio = '//str(damping_ratio)// &
                   ', must be >= 0 and < 1', error)
         return
      end if
      cfg%damping_ratio = damping_ratio
      call check_modes(at, n, damping_modes, cfg%damping_modes, error)
      if (allocated(error)) return
      cfg%p_delta = p_delta

      if (given_count(gravity_load) > 0) then
         call take_reals(at, 'gravity_load', gravity_load, n, '>=', cfg%gravity_load, error)
         if (allocated(error)) return
      end if
   end subroutine read_building

   !> Building name: given, at most `max_name_length` of letters, digits, '_', '-'; unique.
   pure subroutine check_name(at, raw, previous, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> `name` as read.
      character(len=*), intent(in) :: raw
      !> Buildings read before this one.
      type(building_config), intent(in) :: previous(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: name
      integer :: i

      name = trim(adjustl(raw))
      if (len(name) == 0) then
         call fail(at, 'name', "name is missing or blank; every building needs a unique name "// &
                   "of letters, digits, '_' and '-'", error)
         return
      end if
      if (len(name) > max_name_length) then
         call fail(at, 'name', "name = '"//name//"' is longer than "//str(max_name_length)// &
                   ' characters', error)
         return
      end if
      do i = 1, len(name)
         if (.not. (is_name_char(name(i:i)) .or. name(i:i) == '-')) then
            call fail(at, 'name', "name = '"//name//"' contains '"//name(i:i)// &
                      "', must use only letters, digits, '_' and '-'", error)
            return
         end if
      end do
      do i = 1, size(previous)
         if (lower(previous(i)%name) == lower(name)) then
            call fail(at, 'name', "name = '"//name//"' is already used by &building #"//str(i)// &
                      ' ('//previous(i)%name//'); names must be unique (ignoring case)', error)
            return
         end if
      end do
   end subroutine check_name

   !> `&contact`: unilateral constraints between facing floors of two buildings.
   subroutine read_contact(path, text, g, buildings, cfg, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> All buildings of the deck (already resolved).
      type(building_config), intent(in) :: buildings(:)
      !> Resolved contact.
      type(contact_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=word_len) :: left, right, law, dashpot_rate
      integer, allocatable :: floors_left(:), floors_right(:)
      real(dp), allocatable :: gap(:), envelope_d(:), envelope_r(:)
      real(dp) :: stiffness, dashpot, yield_force, second_slope, peak_force, peak_penetration, &
                  fracture_penetration
      integer :: n_segments
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      integer :: ios, n, k, i
      namelist /contact/ left, right, floors_left, floors_right, gap, law, stiffness, dashpot, &
         dashpot_rate, yield_force, second_slope, envelope_d, envelope_r, peak_force, peak_penetration, &
         fracture_penetration, n_segments

      ! One slot more than allowed, so that too many pairs get our message, not gfortran's.
      allocate (floors_left(max_pairs + 1), floors_right(max_pairs + 1), gap(max_pairs + 1), &
                envelope_d(max_envelope_points + 1), envelope_r(max_envelope_points + 1))
      left = ' '
      right = ' '
      law = ' '
      dashpot_rate = 'backward_euler'
      floors_left = unset_int
      floors_right = unset_int
      gap = unset_real
      envelope_d = unset_real
      envelope_r = unset_real
      stiffness = unset_real
      yield_force = unset_real
      second_slope = unset_real
      peak_force = unset_real
      peak_penetration = unset_real
      fracture_penetration = unset_real
      n_segments = unset_int
      dashpot = 0.0_dp
      at = site_of(path, g)
      call group_text(text, g, buf)
      msg = ' '
      read (buf, nml=contact, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      call find_building(at, 'left', left, 'the building on the left', buildings, cfg%left_index, error)
      if (allocated(error)) return
      call find_building(at, 'right', right, 'the building on the right', buildings, cfg%right_index, error)
      if (allocated(error)) return
      cfg%left = buildings(cfg%left_index)%name
      cfg%right = buildings(cfg%right_index)%name
      if (cfg%left_index == cfg%right_index) then
         call fail(at, 'right', "right = '"//trim(adjustl(right))//"' is the same building as left = '"// &
                   trim(adjustl(left))//"'; a contact joins two different buildings", error)
         return
      end if
      if (cfg%left_index > cfg%right_index) then
         call fail(at, 'left', "left = '"//cfg%left//"' stands right of right = '"//cfg%right// &
                   "': the buildings stand left to right in deck order ("// &
                   building_names(buildings)//"); swap left and right", error)
         return
      end if
      at%label = at%label//' ('//cfg%left//', '//cfg%right//')'

      call take_floors(at, 'floors_left', floors_left, buildings(cfg%left_index), cfg%floor_left, error)
      if (allocated(error)) return
      call take_floors(at, 'floors_right', floors_right, buildings(cfg%right_index), cfg%floor_right, error)
      if (allocated(error)) return
      n = size(cfg%floor_left)
      if (size(cfg%floor_right) /= n) then
         call fail(at, 'floors_right', 'floors_right has '//values_text(size(cfg%floor_right))// &
                   ', floors_left has '//values_text(n)//'; both need one floor per pair', error)
         return
      end if

      k = given_count(gap)
      if (k == 0) then
         call fail(at, 'gap', 'gap is missing (initial gap in m: one value per pair, or a single '// &
                   'value for all pairs)', error)
         return
      end if
      if (k /= 1 .and. k /= n) then
         call fail(at, 'gap', 'gap has '//values_text(k)//', must have 1 (for all pairs) or one '// &
                   'per pair = '//str(n), error)
         return
      end if
      do i = 1, k
         if (.not. is_set(gap(i))) then
            call fail(at, 'gap', 'gap('//str(i)//') is missing; give one value per pair', error)
            return
         end if
         if (k == 1) then
            call check_real(at, 'gap', gap(i), '>=', 0.0_dp, error)
         else
            call check_real(at, 'gap', gap(i), '>=', 0.0_dp, error, name='gap('//str(i)//')')
         end if
         if (allocated(error)) return
      end do
      if (k == 1) then
         cfg%gap = spread(gap(1), 1, n)
      else
         cfg%gap = gap(1:n)
      end if

      cfg%law = lower(trim(adjustl(law)))
      select case (cfg%law)
      case ('elastic', 'elastic_plastic', 'bilinear', 'piecewise', 'parabola_cubic')
      case ('')
         call fail(at, 'law', 'law is missing, must be '//law_names, error)
         return
      case default
         call fail(at, 'law', "law = '"//trim(adjustl(law))//"', must be "//law_names, error)
         return
      end select

      ! Variables of other laws are an error, not silently ignored.
      call unused('stiffness', is_set(stiffness), cfg%law == 'piecewise', error)
      if (allocated(error)) return
      call unused('yield_force', is_set(yield_force), &
                  cfg%law /= 'elastic_plastic' .and. cfg%law /= 'bilinear', error)
      if (allocated(error)) return
      call unused('second_slope', is_set(second_slope), cfg%law /= 'bilinear', error)
      if (allocated(error)) return
      call unused('envelope_d', given_count(envelope_d) > 0, cfg%law /= 'piecewise', error)
      if (allocated(error)) return
      call unused('envelope_r', given_count(envelope_r) > 0, cfg%law /= 'piecewise', error)
      if (allocated(error)) return
      call unused('peak_force', is_set(peak_force), cfg%law /= 'parabola_cubic', error)
      if (allocated(error)) return
      call unused('peak_penetration', is_set(peak_penetration), cfg%law /= 'parabola_cubic', error)
      if (allocated(error)) return
      call unused('fracture_penetration', is_set(fracture_penetration), cfg%law /= 'parabola_cubic', error)
      if (allocated(error)) return
      call unused('n_segments', n_segments /= unset_int, cfg%law /= 'parabola_cubic', error)
      if (allocated(error)) return

      select case (cfg%law)
      case ('elastic', 'elastic_plastic', 'bilinear')
         call require_real(at, 'stiffness', stiffness, 'joint stiffness k0 in kN/m', error)
         if (allocated(error)) return
         call check_real(at, 'stiffness', stiffness, '>', 0.0_dp, error)
         if (allocated(error)) return
         cfg%stiffness = stiffness
         if (cfg%law /= 'elastic') then
            call require_real(at, 'yield_force', yield_force, 'yield force in kN', error)
            if (allocated(error)) return
            call check_real(at, 'yield_force', yield_force, '>', 0.0_dp, error)
            if (allocated(error)) return
            cfg%yield_force = yield_force
         end if
         if (cfg%law == 'bilinear') then
            call require_real(at, 'second_slope', second_slope, 'slope after yielding in kN/m, '// &
                              '< stiffness, negative for softening', error)
            if (allocated(error)) return
            if (.not. (second_slope < stiffness .and. ieee_is_finite(second_slope))) then
               call fail(at, 'second_slope', 'second_slope = '//str(second_slope)//', must be < '// &
                         'stiffness = '//str(stiffness), error)
               return
            end if
            call check_plausible(at, 'second_slope', second_slope, 'second_slope', error)
            if (allocated(error)) return
            cfg%second_slope = second_slope
         end if
      case ('piecewise')
         call take_points(error)
         if (allocated(error)) return
      case ('parabola_cubic')
         call take_parabola_cubic(error)
         if (allocated(error)) return
      end select

      call check_real(at, 'dashpot', dashpot, '>=', 0.0_dp, error)
      if (allocated(error)) return
      cfg%dashpot = dashpot
      cfg%dashpot_rate = lower(trim(adjustl(dashpot_rate)))
      if (cfg%dashpot_rate /= 'backward_euler' .and. cfg%dashpot_rate /= 'trapezoidal') then
         call fail(at, 'dashpot_rate', "dashpot_rate = '"//trim(adjustl(dashpot_rate))// &
                   "', must be 'backward_euler' or 'trapezoidal'", error)
         return
      end if

   contains

      !> `var` was given (`given`) although the law does not use it (`not_used`).
      pure subroutine unused(var, given, not_used, error)
         character(len=*), intent(in) :: var
         logical, intent(in) :: given, not_used
         type(error_type), allocatable, intent(out) :: error

         if (given .and. not_used) then
            if (var == 'stiffness') then
               call fail(at, var, "stiffness is not used by law = 'piecewise' (k0 is the slope of "// &
                         'its first segment, envelope_r(1)/envelope_d(1))', error)
            else
               call fail(at, var, var//" is not used by law = '"//cfg%law//"'", error)
            end if
         end if
      end subroutine unused

      !> `piecewise`: the envelope points, checked by the law's own rules.
      subroutine take_points(error)
         type(error_type), allocatable, intent(out) :: error
         character(len=:), allocatable :: why
         real(dp) :: k0
         integer :: nd, nr, j

         nd = given_count(envelope_d)
         nr = given_count(envelope_r)
         if (nd < 2) then
            call fail(at, 'envelope_d', 'envelope_d has '//values_text(nd)//', needs at least 2 '// &
                      'penetrations (m) of the envelope points after the origin', error)
            return
         end if
         if (nd > max_envelope_points) then
            call fail(at, 'envelope_d', 'envelope_d has '//values_text(nd)//', must have at most '// &
                      str(max_envelope_points), error)
            return
         end if
         if (nr /= nd) then
            call fail(at, 'envelope_r', 'envelope_r has '//values_text(nr)//', envelope_d has '// &
                      values_text(nd)//'; both need one value per point', error)
            return
         end if
         do j = 1, nd
            if (.not. is_set(envelope_d(j))) then
               call fail(at, 'envelope_d', 'envelope_d('//str(j)//') is missing', error)
               return
            end if
            if (.not. is_set(envelope_r(j))) then
               call fail(at, 'envelope_r', 'envelope_r('//str(j)//') is missing', error)
               return
            end if
            call check_real(at, 'envelope_d', envelope_d(j), '>', 0.0_dp, error, name='envelope_d('//str(j)//')')
            if (allocated(error)) return
            call check_real(at, 'envelope_r', envelope_r(j), '>=', 0.0_dp, error, name='envelope_r('//str(j)//')')
            if (allocated(error)) return
         end do
         call check_piecewise_envelope(envelope_d(1:nd), envelope_r(1:nd), k0, error)
         if (allocated(error)) then
            why = error%message
            call fail(at, 'envelope_r', 'envelope points: '//why, error)
            return
         end if
         cfg%envelope_d = envelope_d(1:nd)
         cfg%envelope_r = envelope_r(1:nd)
         call check_plausible(at, 'stiffness', k0, &
                              'k0 = envelope_r(1)/envelope_d(1)', error, line_of='envelope_r')
         if (allocated(error)) return
         cfg%stiffness = k0
      end subroutine take_points

      !> `parabola_cubic`: dB, dF, and k0 or rB (k0 = 2 rB/dB), chords per branch.
      subroutine take_parabola_cubic(error)
         type(error_type), allocatable, intent(out) :: error
         real(dp) :: k0

         call require_real(at, 'peak_penetration', peak_penetration, 'penetration dB at the peak force, m', &
                           error)
         if (allocated(error)) return
         call check_real(at, 'peak_penetration', peak_penetration, '>', 0.0_dp, error)
         if (allocated(error)) return
         call require_real(at, 'fracture_penetration', fracture_penetration, &
                           'penetration dF at fracture, m', error)
         if (allocated(error)) return
         call check_real(at, 'fracture_penetration', fracture_penetration, '>', peak_penetration, error, &
                         bound_text='peak_penetration = '//str(peak_penetration))
         if (allocated(error)) return
         if (is_set(stiffness)) then
            call check_real(at, 'stiffness', stiffness, '>', 0.0_dp, error)
            if (allocated(error)) return
            k0 = stiffness
            if (is_set(peak_force)) then
               if (abs(peak_force - 0.5_dp*k0*peak_penetration) > 1.0e-9_dp*peak_force) then
                  call fail(at, 'peak_force', 'peak_force = '//str(peak_force)//' contradicts stiffness = '// &
                            str(stiffness)//' and peak_penetration = '//str(peak_penetration)// &
                            ' (the parabola needs stiffness = 2 peak_force/peak_penetration); give one '// &
                            'of stiffness and peak_force', error)
                  return
               end if
            end if
         else
            call require_real(at, 'peak_force', peak_force, 'peak force rB in kN, or give stiffness '// &
                              'k0 = 2 rB/dB', error)
            if (allocated(error)) return
            call check_real(at, 'peak_force', peak_force, '>', 0.0_dp, error)
            if (allocated(error)) return
            k0 = 2.0_dp*peak_force/peak_penetration
            call check_plausible(at, 'stiffness', k0, 'k0 = 2 peak_force/peak_penetration', error, &
                                 line_of='peak_force')
            if (allocated(error)) return
         end if
         if (n_segments == unset_int) n_segments = 8
         if (n_segments < 1 .or. n_segments > max_segments) then
            call fail(at, 'n_segments', 'n_segments = '//str(n_segments)//', must be 1..'//str(max_segments)// &
                      ' (chords per curved branch)', error)
            return
         end if
         cfg%stiffness = k0
         cfg%peak_force = 0.5_dp*k0*peak_penetration
         cfg%peak_penetration = peak_penetration
         cfg%fracture_penetration = fracture_penetration
         cfg%n_segments = n_segments
      end subroutine take_parabola_cubic

   end subroutine read_contact

   !> `&sweep`: range of seismic-joint gaps and the optional target for |lambda|.
   subroutine read_sweep(path, text, g, n_contacts, cfg, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Number of `&contact` groups in the deck.
      integer, intent(in) :: n_contacts
      !> Resolved sweep.
      type(sweep_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: gap_from, gap_to, target_lambda
      integer :: n_gaps, ios
      character(len=path_len) :: target_quantities
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      namelist /sweep/ gap_from, gap_to, n_gaps, target_lambda, target_quantities

      gap_from = unset_real
      gap_to = unset_real
      target_lambda = unset_real
      n_gaps = unset_int
      target_quantities = 'u a_abs drift storey_shear'
      at = site_of(path, g)
      call group_text(text, g, buf)
      msg = ' '
      read (buf, nml=sweep, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return
      if (n_contacts == 0) then
         call fail(at, 'gap_from', 'a sweep varies the gaps of the &contact groups, and the deck '// &
                   'has none', error)
         return
      end if
      call require_real(at, 'gap_from', gap_from, 'first gap in m', error)
      if (allocated(error)) return
      call check_real(at, 'gap_from', gap_from, '>=', 0.0_dp, error)
      if (allocated(error)) return
      call require_real(at, 'gap_to', gap_to, 'last gap in m', error)
      if (allocated(error)) return
      call check_real(at, 'gap_to', gap_to, '>', gap_from, error, 'gap_from = '//str(gap_from))
      if (allocated(error)) return
      if (n_gaps == unset_int) then
         call fail(at, 'n_gaps', 'n_gaps is missing (number of gaps from gap_from to gap_to)', error)
         return
      end if
      if (n_gaps < 2 .or. n_gaps > 10000) then
         call fail(at, 'n_gaps', 'n_gaps = '//str(n_gaps)//', must be in 2..10000', error)
         return
      end if
      if (is_set(target_lambda)) then
         call check_real(at, 'target_lambda', target_lambda, '>', 0.0_dp, error)
         if (allocated(error)) return
         cfg%target = target_lambda
      end if
      call parse_history(at, target_quantities, cfg%target_quantities, error, 'target_quantities')
      if (allocated(error)) return
      if (.not. any(cfg%target_quantities)) then
         call fail(at, 'target_quantities', "target_quantities = 'none' leaves nothing to check", error)
         return
      end if
      cfg%active = .true.
      cfg%gap_from = gap_from
      cfg%gap_to = gap_to
      cfg%n_gaps = n_gaps
   end subroutine read_sweep

   !> Index of the building named `raw` (ignoring case); error if blank or not a building.
   pure subroutine find_building(at, var, raw, what, buildings, idx, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Building name as read.
      character(len=*), intent(in) :: raw
      !> What the variable is (for the message when it is missing).
      character(len=*), intent(in) :: what
      !> All buildings of the deck.
      type(building_config), intent(in) :: buildings(:)
      !> Index of the building in `buildings` (0 on error).
      integer, intent(out) :: idx
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: name, names
      integer :: i

      idx = 0
      names = building_names(buildings)
      name = trim(adjustl(raw))
      if (len(name) == 0) then
         call fail(at, var, var//' is missing or blank (name of '//what//'; buildings: '// &
                   names//')', error)
         return
      end if
      do i = 1, size(buildings)
         if (lower(buildings(i)%name) == lower(name)) then
            idx = i
            return
         end if
      end do
      call fail(at, var, var//" = '"//name//"' is not a building of the deck; buildings: "// &
                names, error)
   end subroutine find_building

   !> The buildings' names in deck order, comma separated.
   pure function building_names(buildings) result(names)
      !> All buildings of the deck.
      type(building_config), intent(in) :: buildings(:)
      character(len=:), allocatable :: names
      integer :: i

      names = buildings(1)%name
      do i = 2, size(buildings)
         names = names//', '//buildings(i)%name
      end do
   end function building_names

   !> Floors of building `b` in each pair: 1..`max_pairs` values, none missing, each in
   !> 1..n_storeys of `b`.
   pure subroutine take_floors(at, var, raw, b, values, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Namelist array as read (`unset_int` where not given).
      integer, intent(in) :: raw(:)
      !> The building these floors belong to.
      type(building_config), intent(in) :: b
      !> The floors (unallocated on error).
      integer, allocatable, intent(out) :: values(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, i

      do k = size(raw), 1, -1
         if (raw(k) /= unset_int) exit
      end do
      if (k == 0) then
         call fail(at, var, var//' is missing (floor of building '//b%name//' in each pair, '// &
                   '1..n_storeys = '//str(b%n_storeys)//')', error)
         return
      end if
      if (k > max_pairs) then
         call fail(at, var, var//' has '//values_text(k)//', must have at most '//str(max_pairs)// &
                   ' (one per pair)', error)
         return
      end if
      do i = 1, k
         if (raw(i) == unset_int) then
            call fail(at, var, var//'('//str(i)//') is missing; give one floor per pair', error)
            return
         end if
         if (raw(i) < 1 .or. raw(i) > b%n_storeys) then
            call fail(at, var, var//'('//str(i)//') = '//str(raw(i))//', must be a floor of '// &
                      'building '//b%name//': 1..n_storeys = '//str(b%n_storeys), error)
            return
         end if
      end do
      values = raw(1:k)
   end subroutine take_floors

   !> '1 value' or 'k values'.
   pure function values_text(k) result(s)
      !> Number of values.
      integer, intent(in) :: k
      character(len=:), allocatable :: s

      if (k == 1) then
         s = '1 value'
      else
         s = str(k)//' values'
      end if
   end function values_text

   !> Floor masses as `mass`, or as `load_coeff` with `ref_floor_load` (the masses and the default
   !> gravity loads are derived by the model: pound_storey_properties).
   pure subroutine resolve_masses(at, n, mass, load_coeff, ref_floor_load, cfg, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Number of storeys.
      integer, intent(in) :: n
      !> Namelist values as read (`unset_real` where not given).
      real(dp), intent(in) :: mass(:), load_coeff(:), ref_floor_load
      !> Building being resolved.
      type(building_config), intent(inout) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      if (given_count(mass) > 0 .and. given_count(load_coeff) > 0) then
         call fail(at, 'load_coeff', 'give either mass or load_coeff (with ref_floor_load), '// &
                   'not both', error)
      else if (given_count(mass) > 0) then
         if (is_set(ref_floor_load)) then
            call fail(at, 'ref_floor_load', 'ref_floor_load applies only with load_coeff, '// &
                      'not with mass', error)
            return
         end if
         call take_reals(at, 'mass', mass, n, '>', cfg%mass, error)
         if (allocated(error)) return
         cfg%mass_source = 'mass'
      else if (given_count(load_coeff) > 0) then
         call take_reals(at, 'load_coeff', load_coeff, n, '>', cfg%load_coeff, error)
         if (allocated(error)) return
         call require_real(at, 'ref_floor_load', ref_floor_load, &
                           'floor load m0 g in kN that load_coeff multiplies', error)
         if (allocated(error)) return
         call check_real(at, 'ref_floor_load', ref_floor_load, '>', 0.0_dp, error)
         if (allocated(error)) return
         cfg%ref_floor_load = ref_floor_load
         cfg%mass_source = 'load_coeff'
      else
         call fail(at, 'mass', 'floor masses are missing: give mass (t) or load_coeff with '// &
                   'ref_floor_load (kN)', error)
      end if
   end subroutine resolve_masses

   !> Storey stiffness as `stiffness`, or the columns (rigid beams) it is derived from by the
   !> model (pound_storey_properties).
   pure subroutine resolve_stiffness(at, n, stiffness, n_columns, e_modulus, inertia, &
                                     column_ends, cfg, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Number of storeys.
      integer, intent(in) :: n
      !> Namelist arrays as read.
      real(dp), intent(in) :: stiffness(:), e_modulus(:), inertia(:)
      !> Namelist array as read (`unset_int` where not given).
      integer, intent(in) :: n_columns(:)
      !> `column_ends` as read.
      character(len=*), intent(in) :: column_ends
      !> Building being resolved.
      type(building_config), intent(inout) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: ends
      logical :: columns

      columns = given_count(e_modulus) > 0 .or. given_count(inertia) > 0 .or. &
                count(n_columns /= unset_int) > 0 .or. len_trim(column_ends) > 0
      if (given_count(stiffness) > 0 .and. columns) then
         call fail(at, 'stiffness', 'give either stiffness or the columns (n_columns, '// &
                   'e_modulus, inertia, column_ends), not both', error)
      else if (given_count(stiffness) > 0) then
         call take_reals(at, 'stiffness', stiffness, n, '>', cfg%stiffness, error)
         cfg%stiffness_source = 'stiffness'
      else if (columns) then
         call take_ints(at, 'n_columns', n_columns, n, cfg%n_columns, error)
         if (allocated(error)) return
         call take_reals(at, 'e_modulus', e_modulus, n, '>', cfg%e_modulus, error)
         if (allocated(error)) return
         call take_reals(at, 'inertia', inertia, n, '>', cfg%inertia, error)
         if (allocated(error)) return
         ends = lower(trim(adjustl(column_ends)))
         select case (ends)
         case ('', 'fixed-fixed')
            cfg%column_ends = 'fixed-fixed'
         case ('fixed-pinned')
            cfg%column_ends = 'fixed-pinned'
         case default
            call fail(at, 'column_ends', "column_ends = '"//trim(adjustl(column_ends))// &
                      "', must be 'fixed-fixed' or 'fixed-pinned'", error)
            return
         end select
         cfg%stiffness_source = 'columns'
      else
         call fail(at, 'stiffness', 'storey stiffness is missing: give stiffness (kN/m) or '// &
                   'n_columns, e_modulus (kN/m^2) and inertia (m^4)', error)
      end if
   end subroutine resolve_stiffness

   !> Rayleigh modes: default (1, 2); with one storey only mode 1, stored as (1, 1).
   pure subroutine check_modes(at, n, raw, modes, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Number of storeys.
      integer, intent(in) :: n
      !> `damping_modes` as read (`unset_int` where not given).
      integer, intent(in) :: raw(2)
      !> Modes for the Rayleigh fit.
      integer, intent(out) :: modes(2)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, given

      given = count(raw /= unset_int)
      if (raw(1) == unset_int .and. raw(2) /= unset_int) then
         call fail(at, 'damping_modes', 'damping_modes(1) is missing', error)
         return
      end if
      if (n == 1) then
         modes = 1
         do i = 1, given
            if (raw(i) /= 1) then
               call fail(at, 'damping_modes', 'damping_modes('//str(i)//') = '//str(raw(i))// &
                         ', must be 1 for a one-storey building', error)
               return
            end if
         end do
         return
      end if
      if (given == 0) then
         modes = [1, 2]
         return
      end if
      if (given == 1) then
         call fail(at, 'damping_modes', 'damping_modes has 1 value, must have 2 (two modes, '// &
                   'ascending)', error)
         return
      end if
      do i = 1, 2
         if (raw(i) < 1 .or. raw(i) > n) then
            call fail(at, 'damping_modes', 'damping_modes('//str(i)//') = '//str(raw(i))// &
                      ', must be in 1..n_storeys = '//str(n), error)
            return
         end if
      end do
      if (raw(2) <= raw(1)) then
         call fail(at, 'damping_modes', 'damping_modes = '//str(raw(1))//', '//str(raw(2))// &
                   ', must be two distinct modes in ascending order', error)
         return
      end if
      modes = raw
   end subroutine check_modes

   !> Number of values given: position of the last one that is not `unset_real`.
   pure integer function given_count(raw) result(k)
      !> Namelist array as read (`unset_real` where not given).
      real(dp), intent(in) :: raw(:)

      do k = size(raw), 1, -1
         if (is_set(raw(k))) return
      end do
      k = 0
   end function given_count

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

      do k = size(raw), 1, -1
         if (raw(k) /= unset_int) exit
      end do
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
                      'range: must be <= '//str(max_columns)//' (see the input bounds in the README)', error)
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
         call fail(at, var, var//' is missing; give n_storeys = '//str(n)//' values', error)
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
                   what//' (see the input bounds in the README)', error)
         return
      end if
      call fail(at, var, shown//' = '//str(x)//unit//', outside the plausible range: '//what// &
                ' (see the input bounds in the README)', error)
   end subroutine check_plausible

   !> Whether the deck gave `x` (it is not the `unset_real` marker; safe for NaN).
   pure logical function is_set(x)
      !> Value read.
      real(dp), intent(in) :: x

      is_set = transfer(x, 0_int64) /= transfer(unset_real, 0_int64)
   end function is_set

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

   !> Lower-case copy of `s` (ASCII).
   pure function lower(s) result(t)
      !> Text.
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: i

      t = s
      do i = 1, len(s)
         if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') t(i:i) = achar(iachar(s(i:i)) + 32)
      end do
   end function lower

end module pound_deck
