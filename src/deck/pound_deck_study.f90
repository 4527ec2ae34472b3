!> The deck's studies of the joint (issue 26): a `&sweep` of the joint stiffness or of the
!> restitution instead of the gap (`take_parameter_sweep`, `check_parameter_sweep`) and the law
!> study's `&contact variant = 'name'` groups (`split_variants`): the groups of each variant
!> define the base's pairs with another law; the base is the deck's groups without a variant.
module pound_deck_study
   use pound_config, only: deck_type, contact_config, contact_variant, sweep_config
   use pound_deck_checks, only: check_real, fail, given_count, is_set, site, site_of, unset_int, unset_real
   use pound_deck_lexer, only: group_ref, lower, is_name_char
   use pound_law_registry, only: law_reads, law_restitution, law_from_config
   use pound_contact_law, only: contact_law
   use pound_error, only: error_type, fatal_error, status_input
   use pound_law_smooth, only: hertz_stiffness_range, smooth_law
   use pound_kinds, only: dp
   use pound_building_spec, only: is_plan
   use pound_strings, only: str
   implicit none
   private

   public :: take_parameter_sweep, check_parameter_sweep, split_variants, spaced_values, max_study_values
   public :: study_deck_is_suite

   !> Most values of a stiffness or restitution sweep (as many as gaps).
   integer, parameter :: max_study_values = 10000
   !> Longest variant name (characters).
   integer, parameter :: max_variant_len = 32
   !> The plausible range of a joint stiffness (kN/m), as `&contact stiffness`.
   real(dp), parameter :: stiffness_min = 1.0e-3_dp, stiffness_max = 1.0e13_dp

contains

   !> n values from `from` to `to`, ends included: evenly spaced (`log` false) or evenly spaced
   !> in log (v_i = from (to/from)^((i-1)/(n-1)), from > 0); the ends are exactly `from` and `to`.
   pure function spaced_values(from, to, n, log) result(v)
      !> First and last value.
      real(dp), intent(in) :: from, to
      !> Number of values (>= 2).
      integer, intent(in) :: n
      !> Log spacing.
      logical, intent(in) :: log
      real(dp) :: v(n)
      integer :: i
      real(dp) :: t

      do i = 1, n
         t = real(i - 1, dp)/real(n - 1, dp)
         if (log) then
            v(i) = from*(to/from)**t
         else
            v(i) = from + (to - from)*t
         end if
      end do
      v(1) = from
      v(n) = to
   end function spaced_values

   !> A `&sweep` with `parameter` other than 'gap': the values of the stiffness (kN/m) or of the
   !> restitution, listed (`values`) or spaced from `value_from` to `value_to` (`n_values`,
   !> `spacing` 'log' (default of a stiffness) or 'linear' (default of a restitution)).
   pure subroutine take_parameter_sweep(at, parameter, values, value_from, value_to, n_values, spacing, &
                                        gaps_given, cfg, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> `parameter` as read.
      character(len=*), intent(in) :: parameter
      !> `values` as read (`unset_real` where not given).
      real(dp), intent(in) :: values(:)
      !> `value_from`, `value_to`, `n_values` as read.
      real(dp), intent(in) :: value_from, value_to
      integer, intent(in) :: n_values
      !> `spacing` as read (blank: not given).
      character(len=*), intent(in) :: spacing
      !> Whether any of gap_from, gap_to, n_gaps is given.
      logical, intent(in) :: gaps_given
      !> The sweep (its `parameter` and `values` set).
      type(sweep_config), intent(inout) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: p, sp, what
      logical :: listed, ranged, log
      integer :: k, i

      p = lower(trim(adjustl(parameter)))
      if (p /= 'stiffness' .and. p /= 'restitution') then
         call fail(at, 'parameter', "parameter = '"//trim(adjustl(parameter))//"', must be 'gap' (the default), "// &
                   "'stiffness' or 'restitution'", error)
         return
      end if
      if (p == 'stiffness') then
         what = 'joint stiffness in kN/m'
      else
         what = 'coefficient of restitution'
      end if
      if (gaps_given) then
         call fail(at, 'parameter', "gap_from, gap_to and n_gaps are for parameter = 'gap'; parameter = '"//p// &
                   "' keeps the deck's gaps and takes values (a list) or value_from, value_to, n_values", error)
         return
      end if
      k = given_count(values)
      listed = k > 0
      ranged = is_set(value_from) .or. is_set(value_to) .or. n_values /= unset_int
      if (listed .and. ranged) then
         call fail(at, 'values', 'values and value_from/value_to/n_values are both given; give the '//what// &
                   ' as a list (values) or as a range (value_from, value_to, n_values), not both', error)
         return
      end if
      if (.not. (listed .or. ranged)) then
         call fail(at, 'parameter', "parameter = '"//p//"' needs its values: values = v1, v2, ... or "// &
                   'value_from, value_to and n_values ('//what//')', error)
         return
      end if
      if (listed) then
         if (len_trim(spacing) > 0) then
            call fail(at, 'spacing', 'spacing applies to a range (value_from, value_to, n_values), not to '// &
                      'listed values', error)
            return
         end if
         if (k > max_study_values) then
            call fail(at, 'values', 'values has '//str(k)//' values, must have at most '//str(max_study_values), &
                      error)
            return
         end if
         do i = 1, k
            if (.not. is_set(values(i))) then
               call fail(at, 'values', 'values('//str(i)//') is missing; give every value of the list', error)
               return
            end if
         end do
         cfg%values = values(1:k)
      else
         if (.not. is_set(value_from) .or. .not. is_set(value_to) .or. n_values == unset_int) then
            call fail(at, 'value_from', 'a range needs value_from, value_to and n_values (first and last '// &
                      what//', number of values)', error)
            return
         end if
         if (n_values < 2 .or. n_values > max_study_values) then
            call fail(at, 'n_values', 'n_values = '//str(n_values)//', must be in 2..'//str(max_study_values), error)
            return
         end if
         call check_real(at, 'value_to', value_to, '>', value_from, error, 'value_from = '//str(value_from))
         if (allocated(error)) return
         sp = lower(trim(adjustl(spacing)))
         if (len(sp) == 0) then
            sp = merge('log   ', 'linear', p == 'stiffness')
            sp = trim(sp)
         end if
         if (sp /= 'log' .and. sp /= 'linear') then
            call fail(at, 'spacing', "spacing = '"//trim(adjustl(spacing))//"', must be 'log' or 'linear'", error)
            return
         end if
         log = sp == 'log'
         if (log .and. .not. value_from > 0.0_dp) then
            call fail(at, 'value_from', 'value_from = '//str(value_from)//', must be > 0 for spacing = ''log''', error)
            return
         end if
         cfg%values = spaced_values(value_from, value_to, n_values, log)
      end if
      do i = 1, size(cfg%values)
         call check_value(p, cfg%values(i), i, listed, error)
         if (allocated(error)) return
      end do
      cfg%parameter = p
   contains

      !> The i-th value against the rule of the parameter.
      pure subroutine check_value(p, x, i, listed, error)
         character(len=*), intent(in) :: p
         real(dp), intent(in) :: x
         integer, intent(in) :: i
         logical, intent(in) :: listed
         type(error_type), allocatable, intent(out) :: error
         character(len=:), allocatable :: var, shown

         if (listed) then
            var = 'values'
            shown = 'values('//str(i)//')'
         else if (i == 1) then
            var = 'value_from'
            shown = var
         else
            var = 'value_to'
            shown = var
         end if
         if (p == 'stiffness') then
            if (.not. (x >= stiffness_min .and. x <= stiffness_max)) then
               call fail(at, var, shown//' = '//str(x)//', must be a joint stiffness in '//str(stiffness_min)// &
                         '..'//str(stiffness_max)//' kN/m', error)
            end if
         else
            if (.not. (x > 0.0_dp .and. x < 1.0_dp)) then
               call fail(at, var, shown//' = '//str(x)//', must be > 0 and < 1 (coefficient of restitution '// &
                         'of an impact)', error)
            end if
         end if
      end subroutine check_value
   end subroutine take_parameter_sweep

   !> Whether the deck is a suite for a joint study: several `&ground`. A single motion, also
   !> one scaled by `scale_to` or a synthetic one, is one motion: a deck with a joint study runs
   !> it as one case (`pound.f90`).
   pure logical function study_deck_is_suite(d)
      !> The deck (its motions read).
      type(deck_type), intent(in) :: d

      study_deck_is_suite = size(d%motions) > 1
   end function study_deck_is_suite

   !> A stiffness or restitution sweep against the deck's joints (the base groups): every
   !> group's law must take the swept variable, and every value must make a valid law of every
   !> group (the law's own constructor decides, e.g. a bilinear's second slope below k0);
   !> one motion only.
   pure subroutine check_parameter_sweep(path, g, d, error)
      !> Deck path as given.
      character(len=*), intent(in) :: path
      !> The `&sweep` group.
      type(group_ref), intent(in) :: g
      !> The deck (contacts split from the variants, sweep read).
      type(deck_type), intent(in) :: d
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(site) :: at
      type(contact_config) :: c
      type(contact_law) :: law
      type(error_type), allocatable :: law_error
      integer :: ic, i, k

      if (d%sweep%parameter == 'gap') return
      at = site_of(path, g)
      if (any([(is_plan(d%buildings(k)), k=1, size(d%buildings))])) then
         call fail(at, 'parameter', "parameter = '"//trim(d%sweep%parameter)//"' sweeps the joints' law; "// &
                   'it does not take buildings in plan (model = ''plan''): their contact points are not '// &
                   "built by the study. Run one deck per value, or sweep the gap (parameter = 'gap')", error)
         return
      end if
      if (study_deck_is_suite(d)) then
         call fail(at, 'parameter', "parameter = '"//trim(d%sweep%parameter)//"' runs with one ground motion; "// &
                   'this deck is a suite of '//str(size(d%motions))//' motions (several &ground): run its '// &
                   'motions one by one (one &ground each; it may be scaled by scale_to)', error)
         return
      end if
      do ic = 1, size(d%contacts)
         associate (cc => d%contacts(ic))
            if (d%sweep%parameter == 'stiffness') then
               if (.not. law_reads(cc%law, 'stiffness')) then
                  call fail(at, 'parameter', "parameter = 'stiffness': &contact #"//str(ic)//' ('//cc%left//', '// &
                            cc%right//") has law = '"//cc%law//"', which has no stiffness variable", error)
                  return
               end if
            else
               if (.not. law_restitution(cc%law)) then
                  call fail(at, 'parameter', "parameter = 'restitution': &contact #"//str(ic)//' ('//cc%left// &
                            ', '//cc%right//") has law = '"//cc%law//"', which takes no restitution", error)
                  return
               end if
               if (cc%dashpot > 0.0_dp) then
                  call fail(at, 'parameter', "parameter = 'restitution': &contact #"//str(ic)//' ('//cc%left// &
                            ', '//cc%right//') gives a dashpot, which the restitution would replace; give '// &
                            'the group no dashpot', error)
                  return
               end if
               do k = 1, size(cc%floor_left)
                  if (cc%floor_left(k) == 0 .or. cc%floor_right(k) == 0) then
                     call fail(at, 'parameter', "parameter = 'restitution': &contact #"//str(ic)//' ('// &
                               cc%left//', '//cc%right//') has a pair at a column point between floors '// &
                               '(no mass of its own: no impact of two masses to calibrate the dashpot to a '// &
                               'restitution); sweep the stiffness instead, or give the dashpot of an elastic '// &
                               'law directly in a deck per value', error)
                     return
                  end if
               end do
            end if
            do i = 1, size(d%sweep%values)
               c = swept_config(cc, d%sweep%parameter, d%sweep%values(i))
               call law_from_config(c, law, law_error)
               if (.not. allocated(law_error) .and. d%sweep%parameter == 'stiffness') then
                  ! The deck's range of a Hertz-type stiffness (pound_law_smooth), which the law
                  ! itself does not check.
                  select type (given => law%given)
                  class is (smooth_law)
                     if (given%stiffness_unit() == 'kN/m^(3/2)' .and. .not. (c%stiffness >= &
                         hertz_stiffness_range(1) .and. c%stiffness <= hertz_stiffness_range(2))) &
                        call fatal_error(law_error, "law '"//cc%law//"': a Hertz-type stiffness must be in "// &
                                         str(hertz_stiffness_range(1))//' to '//str(hertz_stiffness_range(2))// &
                                         ' kN/m^(3/2), as the deck''s stiffness (concrete floors: about 1e6 to 1e9)', status_input)
                  end select
               end if
               if (allocated(law_error)) then
                  call fail(at, 'values', trim(d%sweep%parameter)//' = '//str(d%sweep%values(i))// &
                            ' (value '//str(i)//') makes no valid law of &contact #'//str(ic)//' ('//cc%left// &
                            ', '//cc%right//'): '//law_error%message, error)
                  return
               end if
            end do
         end associate
      end do
   end subroutine check_parameter_sweep

   !> The group `c` with its stiffness or restitution set to `x` (`parameter`), as a deck that
   !> gives that value would configure it.
   pure function swept_config(c, parameter, x) result(s)
      type(contact_config), intent(in) :: c
      character(len=*), intent(in) :: parameter
      real(dp), intent(in) :: x
      type(contact_config) :: s

      s = c
      if (parameter == 'stiffness') then
         s%stiffness = x
      else
         s%restitution = x
      end if
   end function swept_config

   !> Split the deck's `&contact` groups: those without a variant stay in `d%contacts` (the
   !> base), those with one go to `d%variants` (one entry per name, ignoring case, its groups in
   !> deck order). Each variant must define the base's pairs (buildings, floors or elevations and
   !> gaps, in the same order); a name is letters, digits, '_', '-' (not 'base'); one motion only.
   pure subroutine split_variants(path, groups, d, error)
      !> Deck path as given.
      character(len=*), intent(in) :: path
      !> The deck's groups (the `&contact` ones in the order of `d%contacts`).
      type(group_ref), intent(in) :: groups(:)
      !> The deck.
      type(deck_type), intent(inout) :: d
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(contact_config), allocatable :: base(:)
      integer, allocatable :: gi(:), owner(:)
      character(len=max_variant_len), allocatable :: names(:)
      type(site) :: at
      integer :: i, k, nv, j

      allocate (gi(size(d%contacts)))
      k = 0
      do i = 1, size(groups)
         if (groups(i)%name /= 'contact') cycle
         k = k + 1
         if (k <= size(gi)) gi(k) = i
      end do
      if (.not. any(len_trim(d%contacts(:)%variant) > 0)) then
         allocate (d%variants(0))
         return
      end if
      if (any([(is_plan(d%buildings(j)), j=1, size(d%buildings))])) then
         do i = 1, size(d%contacts)
            if (len_trim(d%contacts(i)%variant) == 0) cycle
            at = site_of(path, groups(gi(i)))
            call fail(at, 'variant', "variant = '"//trim(d%contacts(i)%variant)//"': a law study does not take "// &
                      "buildings in plan (model = 'plan'): their contact points are not built by the study. "// &
                      'Run one deck per law', error)
            return
         end do
      end if
      allocate (names(size(d%contacts)), owner(size(d%contacts)))
      owner = 0
      nv = 0
      do i = 1, size(d%contacts)
         if (len_trim(d%contacts(i)%variant) == 0) cycle
         at = site_of(path, groups(gi(i)))
         at%label = at%label//' ('//d%contacts(i)%left//', '//d%contacts(i)%right//')'
         call check_name(at, d%contacts(i)%variant, error)
         if (allocated(error)) return
         j = 0
         do k = 1, nv
            if (lower(names(k)) == lower(d%contacts(i)%variant)) j = k
         end do
         if (j == 0) then
            nv = nv + 1
            names(nv) = d%contacts(i)%variant
            j = nv
         end if
         owner(i) = j
      end do
      at = site_of(path, groups(gi(findloc(owner > 0, .true., 1))))
      if (study_deck_is_suite(d)) then
         call fail(at, 'variant', 'a law study (&contact variant) runs with one ground motion; this deck is '// &
                   'a suite of '//str(size(d%motions))//' motions (several &ground): run its motions one by one '// &
                   '(one &ground each; it may be scaled by scale_to)', error)
         return
      end if
      if (all(owner > 0)) then
         call fail(at, 'variant', 'every &contact group has a variant: a law study compares its variants '// &
                   'with the base, the &contact groups without a variant (the deck''s own joints); give them', &
                   error)
         return
      end if
      base = pack(d%contacts, owner == 0)
      allocate (d%variants(nv))
      do j = 1, nv
         d%variants(j)%name = names(j)
         d%variants(j)%contacts = pack(d%contacts, owner == j)
         k = findloc(owner, j, 1)
         at = site_of(path, groups(gi(k)))
         at%label = at%label//' ('//d%contacts(k)%left//', '//d%contacts(k)%right//')'
         call check_same_pairs(at, trim(names(j)), base, d%variants(j)%contacts, error)
         if (allocated(error)) return
      end do
      d%contacts = base
   end subroutine split_variants

   !> A variant's name: 1..32 letters, digits, '_' or '-', not 'base' (the base's column).
   pure subroutine check_name(at, name, error)
      type(site), intent(in) :: at
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      character(len=:), allocatable :: t

      t = trim(adjustl(name))
      do i = 1, len(t)
         if (.not. (is_name_char(t(i:i)) .or. t(i:i) == '-')) then
            call fail(at, 'variant', "variant = '"//t//"': a variant's name is letters, digits, '_' and '-' "// &
                      '(it names an HDF5 group /law_study/<variant>)', error)
            return
         end if
      end do
      if (lower(t) == 'base') then
         call fail(at, 'variant', "variant = '"//t//"': 'base' names the study's base (the groups without "// &
                   'a variant); give the variant another name', error)
      end if
   end subroutine check_name

   !> The pairs of a variant's groups `v` against the base's `base`: the same count and, in
   !> order, the same buildings, floors (or elevations) and gaps.
   pure subroutine check_same_pairs(at, name, base, v, error)
      type(site), intent(in) :: at
      character(len=*), intent(in) :: name
      type(contact_config), intent(in) :: base(:), v(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=64), allocatable :: pb(:), pv(:)
      integer :: k

      call pair_texts(base, pb)
      call pair_texts(v, pv)
      if (size(pv) /= size(pb)) then
         call fail(at, 'variant', "variant = '"//name//"' defines "//str(size(pv))//' pairs, the base (the '// &
                   '&contact groups without a variant) '//str(size(pb))//': a variant gives the same pairs '// &
                   'with another law (two variants with the same name are one variant: name each one)', error)
         return
      end if
      do k = 1, size(pb)
         if (pv(k) /= pb(k)) then
            call fail(at, 'variant', "variant = '"//name//"': its pair "//str(k)//' is '//trim(pv(k))// &
                      ', the base''s pair '//str(k)//' is '//trim(pb(k))//'; a variant gives the base''s pairs '// &
                      '(buildings, floors or elevations, gaps, in the same order) with another law', error)
            return
         end if
      end do
   end subroutine check_same_pairs

   !> Each pair of the groups as text: 'A:floor-B:floor gap g m' (floor 0: 'A@z m').
   pure subroutine pair_texts(groups, texts)
      type(contact_config), intent(in) :: groups(:)
      character(len=64), allocatable, intent(out) :: texts(:)
      integer :: ic, k, n

      n = 0
      do ic = 1, size(groups)
         n = n + size(groups(ic)%floor_left)
      end do
      allocate (texts(n))
      n = 0
      do ic = 1, size(groups)
         associate (c => groups(ic))
            do k = 1, size(c%floor_left)
               n = n + 1
               texts(n) = c%left//':'//end_text(c, k, c%floor_left(k))//'-'//c%right//':'// &
                          end_text(c, k, c%floor_right(k))//' gap '//str(c%gap(k))//' m'
            end do
         end associate
      end do
   end subroutine pair_texts

   pure function end_text(c, k, floor) result(t)
      type(contact_config), intent(in) :: c
      integer, intent(in) :: k, floor
      character(len=:), allocatable :: t

      if (allocated(c%elevation)) then
         t = '@'//str(c%elevation(k))//' m'
      else
         t = str(floor)
      end if
   end function end_text

end module pound_deck_study
