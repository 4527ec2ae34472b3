!> Input deck reader: Fortran namelist groups `&analysis`, `&ground`, `&building`, `&plane` and `&contact`.
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
!> * `&analysis` exactly once, `&building` once per building, left to right.
!> * `&ground` once, or several times with distinct `name`s: a suite of ground motions
!>   (pound_suite), each a pulse, a record or a synthetic motion with its scaling.
!> * `&plane` once or more per building in plan (`&building model = 'plan'`), in any order:
!>   its lateral load-resisting planes (pound_deck_plane); in a deck with a building in plan
!>   every building is in plan and has a plane in each direction.
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
!> `law` are required. Instead of the floors, `elevations` (m above the common base, one per
!> pair) joins the facing column lines at that elevation: a building's floor there, or a node
!> added to a frame's facing column (refused between the floors of a shear building and above a
!> roof). The same floor pair may appear more than once. Laws and their variables:
!> 'elastic' (stiffness), 'elastic_plastic' (stiffness, yield_force), 'bilinear' (stiffness,
!> yield_force, second_slope < stiffness), 'piecewise' (envelope_d, envelope_r: points after the
!> origin), 'parabola_cubic' (peak_penetration, fracture_penetration, peak_force or stiffness,
!> n_segments = 8); see pound_contact_law (envelope rules: pound_envelope_rules). A variable the chosen
!> law does not use is an error.
!>
!> Every value is validated and kept as given (the record path resolved relative to the
!> deck's directory); masses from load coefficients, storey stiffness from columns and
!> default gravity loads are the model's (pound_storey_properties).
!>
!> One job per module: pound_deck_lexer (text to groups and checked assignments),
!> pound_deck_variables (the one table of groups and variables), pound_deck_checks (value
!> checks, plausible ranges, the message format), and one reader per group:
!> pound_deck_analysis, pound_deck_ground, pound_deck_building, pound_deck_plane,
!> pound_deck_contact, pound_deck_sweep. This module reads the file and calls them in order.
!> The first error found is reported in one message of the form
!> `deck.nml:14: &building #2 (B): n_columns(5) = 0, must be >= 1`
!> (line of the variable's assignment, or of the group start when the variable is missing).
module pound_deck
   use pound_config, only: building_config, contact_config, deck_type, is_frame
   use pound_kinds, only: dp
   use pound_building_spec, only: is_plan
   use pound_deck_checks, only: fail, site_of
   use pound_deck_analysis, only: read_analysis
   use pound_deck_building, only: read_building
   use pound_deck_contact, only: read_contact
   use pound_deck_ground, only: read_ground
   use pound_deck_plane, only: read_plane, check_plan_deck, deck_yields
   use pound_deck_lexer, only: find_single, group_ref, normalize_text, scan_groups
   use pound_deck_sweep, only: read_sweep
   use pound_deck_risk, only: read_stripes, read_hazard, check_risk
   use pound_deck_record_set, only: expand_record_sets
   use pound_deck_study, only: split_variants, check_parameter_sweep
   use pound_deck_variables, only: max_name_length, max_pairs, max_storeys
   use pound_error, only: error_type, fatal_error, status_input
   use pound_strings, only: str
   use pound_text_file, only: read_whole_file
   implicit none
   private

   public :: read_deck, max_storeys, max_name_length, max_pairs

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
      type(group_ref), allocatable :: groups(:), ground_groups(:)
      type(group_ref) :: stripes_group, hazard_group
      integer :: n_groups, i, j, k, nb, ia, ng

      d%path = path
      d%text = text
      call scan_groups(path, text, groups, n_groups, error)
      if (allocated(error)) return

      call find_single(path, groups(1:n_groups), 'analysis', &
                       'title, dt, t_end, output_every, history', ia, error)
      if (allocated(error)) return
      ng = count([(groups(i)%name == 'ground', i=1, n_groups)])
      if (ng == 0) then
         call fatal_error(error, path//': &ground is missing; at least one &ground is required '// &
                          "(kind = 'pulse', 'record', 'record_set' or 'synthetic' and its parameters)", status_input)
         return
      end if
      nb = count([(groups(i)%name == 'building', i=1, n_groups)])
      if (nb == 0) then
         call fatal_error(error, path//': no &building group; give one &building per '// &
                          'building, left to right', status_input)
         return
      end if

      call read_analysis(path, text, groups(ia), d%analysis, error)
      if (allocated(error)) return
      allocate (d%motions(ng))
      k = 0
      do i = 1, n_groups
         if (groups(i)%name /= 'ground') cycle
         k = k + 1
         call read_ground(path, text, groups(i), ng, d%motions(k), error, d%warnings)
         if (allocated(error)) return
         do j = 1, k - 1
            if (d%motions(j)%name == d%motions(k)%name) then
               call fatal_error(error, path//':'//str(groups(i)%line1)//': &ground #'//str(k)// &
                                ": name = '"//d%motions(k)%name//"' is already the name of "// &
                                '&ground #'//str(j)//'; the motions of a suite need distinct names', status_input)
               return
            end if
         end do
      end do
      d%ground = d%motions(1)
      allocate (d%buildings(nb))
      k = 0
      do i = 1, n_groups
         if (groups(i)%name /= 'building') cycle
         k = k + 1
         call read_building(path, text, groups(i), d%buildings(1:k - 1), d%buildings(k), error, d%warnings)
         if (allocated(error)) return
      end do
      ! The planes of the buildings in plan, each appended to its building in deck order.
      do i = 1, n_groups
         if (groups(i)%name /= 'plane') cycle
         call read_plane(path, text, groups(i), d%buildings, error, d%warnings)
         if (allocated(error)) return
      end do
      call check_plan_deck(path, groups(1:n_groups), d%buildings, error)
      if (allocated(error)) return
      allocate (d%contacts(count([(groups(i)%name == 'contact', i=1, n_groups)])))
      k = 0
      do i = 1, n_groups
         if (groups(i)%name /= 'contact') cycle
         k = k + 1
         call read_contact(path, text, groups(i), d%buildings, d%contacts(k), error, d%warnings)
         if (allocated(error)) return
         ! A law-study variant has the base's pairs (pound_deck_study): no points of its own.
         if (len_trim(d%contacts(k)%variant) == 0) call add_contact_points(d%contacts(k), d%buildings)
      end do
      call split_variants(path, groups(1:n_groups), d, error)
      if (allocated(error)) return
      k = count([(groups(i)%name == 'sweep', i=1, n_groups)])
      if (k > 0) then
         call find_single(path, groups(1:n_groups), 'sweep', 'gap_from, gap_to, n_gaps', i, error)
         if (allocated(error)) return
         call read_sweep(path, text, groups(i), size(d%contacts), &
                         any([(is_frame(d%buildings(k)), k=1, size(d%buildings))]), d%sweep, error, &
                         deck_yields(d%buildings))
         if (allocated(error)) return
         call check_parameter_sweep(path, groups(i), d, error)
         if (allocated(error)) return
      end if
      ! The multiple-stripe analysis (pound_deck_risk) and the record sets (one motion per file).
      allocate (ground_groups(ng))
      k = 0
      do i = 1, n_groups
         if (groups(i)%name /= 'ground') cycle
         k = k + 1
         ground_groups(k) = groups(i)
      end do
      do i = 1, n_groups
         if (groups(i)%name == 'stripes' .or. groups(i)%name == 'hazard') then
            call find_single(path, groups(1:n_groups), groups(i)%name, 'see docs/manual.md', k, error)
            if (allocated(error)) return
         end if
         if (groups(i)%name == 'stripes') then
            stripes_group = groups(i)
            call read_stripes(path, text, groups(i), d, error)
         else if (groups(i)%name == 'hazard') then
            hazard_group = groups(i)
            call read_hazard(path, text, groups(i), d%risk, error)
         end if
         if (allocated(error)) return
      end do
      call expand_record_sets(path, ground_groups, d%motions, error)
      if (allocated(error)) return
      d%ground = d%motions(1)
      call check_risk(path, d, stripes_group, hazard_group, ground_groups, size(d%motions), error)
      if (allocated(error)) return
      call check_plan_suite(path, d, ground_groups, stripes_group, error)
   end subroutine parse_deck

   !> Buildings in plan run one ground motion: a suite (several `&ground`, a record set, a
   !> synthetic motion, `scale_to`) and `&stripes` are refused, because their statistics and
   !> separation rules are per floor pair, not per contact point.
   pure subroutine check_plan_suite(path, d, ground_groups, stripes_group, error)
      !> Deck path as given.
      character(len=*), intent(in) :: path
      !> The deck.
      type(deck_type), intent(in) :: d
      !> The `&ground` groups and the `&stripes` group (line 0: none).
      type(group_ref), intent(in) :: ground_groups(:), stripes_group
      !> Unallocated on success; otherwise the problem.
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: why = ' does not take buildings in plan (model = ''plan'') yet: its '// &
         'statistics and separation rules are per floor pair, not per contact point. Run each motion in a deck '// &
         'of its own (one &ground, scaled by scale)'
      integer :: k

      if (.not. any([(is_plan(d%buildings(k)), k=1, size(d%buildings))])) return
      if (stripes_group%line1 > 0) then
         call fail(site_of(path, stripes_group), 'stripes', '&stripes'//why, error)
      else if (size(d%motions) > 1) then
         call fail(site_of(path, ground_groups(min(2, size(ground_groups)))), 'kind', 'a suite of '//str(size(d%motions))// &
                   ' motions (several &ground or a record set)'//why, error)
      else if (d%ground%kind == 'synthetic') then
         call fail(site_of(path, ground_groups(1)), 'kind', "kind = 'synthetic' (a suite of generated motions)"// &
                   why, error)
      else if (allocated(d%ground%scale_to)) then
         if (len(d%ground%scale_to) > 0) call fail(site_of(path, ground_groups(1)), 'scale_to', &
                                                   'scale_to (a scaled suite)'//why, error)
      end if
   end subroutine check_plan_suite

   !> The pairs of `c` between floors (by elevation) become column nodes of the frames: the
   !> left building's rightmost column line, the right building's leftmost.
   pure subroutine add_contact_points(c, buildings)
      !> A resolved `&contact`.
      type(contact_config), intent(in) :: c
      !> The deck's buildings (their `contact_z_left`, `contact_z_right` extended).
      type(building_config), intent(inout) :: buildings(:)
      integer :: k

      if (.not. allocated(c%elevation)) return
      do k = 1, size(c%elevation)
         if (c%floor_left(k) == 0) call append(buildings(c%left_index)%contact_z_right, c%elevation(k))
         if (c%floor_right(k) == 0) call append(buildings(c%right_index)%contact_z_left, c%elevation(k))
      end do

   contains

      pure subroutine append(v, z)
         real(dp), allocatable, intent(inout) :: v(:)
         real(dp), intent(in) :: z

         if (allocated(v)) then
            v = [v, z]
         else
            v = [z]
         end if
      end subroutine append
   end subroutine add_contact_points

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

end module pound_deck
