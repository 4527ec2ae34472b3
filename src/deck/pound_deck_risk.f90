!> Readers of `&stripes` (the multiple-stripe analysis: measure, period, levels, target) and
!> `&hazard` (the site's hazard curve, the exposure time, the target probability), and the
!> rules between them and the rest of the deck (`check_risk`): both groups or neither, a suite
!> of several motions, contact, no motion's own `scale_to`, no joint study.
module pound_deck_risk
   use pound_config, only: deck_type, risk_config, is_frame
   use pound_constants, only: g_accel
   use pound_deck_checks, only: check_real, fail, take_real, take_sa_period, given_count, group_input, is_set, &
                                read_failed, site, site_of, unset_real
   use pound_deck_lexer, only: group_ref, lower
   use pound_deck_targets, only: take_target_quantities
   use pound_deck_plane, only: deck_yields
   use pound_deck_variables, only: path_len, max_risk_points
   use pound_error, only: error_type, fatal_error
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: read_stripes, read_hazard, check_risk

contains

   !> `&stripes`: measure ('sa' | 'pga'), period (s, 'sa' only), levels (m/s^2) or levels_g (g),
   !> > 0 and strictly ascending; target_lambda (%) and target_quantities, by default the
   !> `&sweep`'s (`sweep_target`, `sweep_quantities`: its target when it gives one), else 10 % on
   !> storey_shear.
   subroutine read_stripes(path, text, g, d, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> The deck read so far (its buildings and sweep); `d%risk` set.
      type(deck_type), intent(inout) :: d
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=64) :: measure
      character(len=path_len) :: target_quantities
      real(dp) :: period, target_lambda
      real(dp), allocatable :: levels(:), levels_g(:)
      integer :: ios
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      namelist /stripes/ measure, period, levels, levels_g, target_lambda, target_quantities

      measure = 'sa'
      period = unset_real
      target_lambda = unset_real
      target_quantities = ' '
      allocate (levels(max_risk_points + 1), levels_g(max_risk_points + 1))
      levels = unset_real
      levels_g = unset_real
      call group_input(path, text, g, at, buf, msg)
      read (buf, nml=stripes, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return
      associate (r => d%risk)
         r%active = .true.
         r%measure = lower(trim(adjustl(measure)))
         if (r%measure /= 'sa' .and. r%measure /= 'pga') then
            call fail(at, 'measure', "measure = '"//trim(adjustl(measure))//"', must be 'sa' (5 %-damped Sa "// &
                      "at period) or 'pga'", error)
            return
         end if
         call take_sa_period(at, 'measure', r%measure, period, r%period, error)
         if (allocated(error)) return
         call take_ascending(at, 'levels', levels, 'levels_g', levels_g, r%levels, error)
         if (allocated(error)) return
         if (d%sweep%active .and. d%sweep%target > 0.0_dp) then
            r%target_lambda = d%sweep%target
            r%target_quantities = d%sweep%target_quantities
         end if
         call take_real(at, 'target_lambda', target_lambda, '>', 0.0_dp, r%target_lambda, error)
         if (allocated(error)) return
         if (len_trim(target_quantities) > 0) then
            call take_target_quantities(at, target_quantities, any([(is_frame(d%buildings(ios)), &
                                        ios=1, size(d%buildings))]), deck_yields(d%buildings), &
                                        r%target_quantities, error)
            if (allocated(error)) return
         end if
      end associate
   end subroutine read_stripes

   !> `&hazard`: im (m/s^2) or im_g (g), > 0, strictly ascending; rate (1/year), one per im,
   !> > 0 and strictly decreasing; years > 0 (default 50); target_probability in (0, 1).
   subroutine read_hazard(path, text, g, r, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> The risk settings (`im`, `rate`, `years`, `target_probability` set).
      type(risk_config), intent(inout) :: r
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: years, target_probability
      real(dp), allocatable :: im(:), im_g(:), rate(:)
      integer :: ios, n, i
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      namelist /hazard/ im, im_g, rate, years, target_probability

      years = unset_real
      target_probability = unset_real
      allocate (im(max_risk_points + 1), im_g(max_risk_points + 1), rate(max_risk_points + 1))
      im = unset_real
      im_g = unset_real
      rate = unset_real
      call group_input(path, text, g, at, buf, msg)
      read (buf, nml=hazard, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return
      call take_ascending(at, 'im', im, 'im_g', im_g, r%im, error)
      if (allocated(error)) return
      n = size(r%im)
      if (n < 2) then
         call fail(at, 'im', 'the hazard curve needs at least 2 points, im has '//str(n), error)
         return
      end if
      if (given_count(rate) == 0) then
         call fail(at, 'rate', 'rate is missing (annual rate of exceedance at each im, 1/year)', error)
         return
      end if
      if (given_count(rate) /= n .or. any(.not. [(is_set(rate(i)), i=1, n)])) then
         call fail(at, 'rate', 'rate has '//str(given_count(rate))//' values, must have one per im ('// &
                   str(n)//')', error)
         return
      end if
      do i = 1, n
         call check_real(at, 'rate', rate(i), '>', 0.0_dp, error, name='rate('//str(i)//')')
         if (allocated(error)) return
         if (i > 1) then
            if (.not. (rate(i) < rate(i - 1))) then
               call fail(at, 'rate', 'rate('//str(i)//') = '//str(rate(i))//', must be < rate('//str(i - 1)// &
                         ') = '//str(rate(i - 1))//': the rate of exceedance decreases as im grows', error)
               return
            end if
         end if
      end do
      r%rate = rate(1:n)
      call take_real(at, 'years', years, '>', 0.0_dp, r%years, error)
      if (allocated(error)) return
      if (is_set(target_probability)) then
         call check_real(at, 'target_probability', target_probability, '>', 0.0_dp, error)
         if (allocated(error)) return
         if (.not. (target_probability < 1.0_dp)) then
            call fail(at, 'target_probability', 'target_probability = '//str(target_probability)// &
                      ', must be < 1 (a probability in years)', error)
            return
         end if
         r%target_probability = target_probability
      end if
   end subroutine read_hazard

   !> `var` (m/s^2) or `var_g` (g), one of them, each value > 0 and strictly ascending.
   pure subroutine take_ascending(at, var, raw, var_g, raw_g, values, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Names of the two variables.
      character(len=*), intent(in) :: var, var_g
      !> Their values as read (`unset_real` where not given).
      real(dp), intent(in) :: raw(:), raw_g(:)
      !> The values in m/s^2.
      real(dp), allocatable, intent(out) :: values(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: name
      real(dp) :: factor
      integer :: n, i

      if (given_count(raw) > 0 .and. given_count(raw_g) > 0) then
         call fail(at, var_g, var//' and '//var_g//' exclude each other: give one ('//var//' in m/s^2, '// &
                   var_g//' in g)', error)
         return
      end if
      if (given_count(raw_g) > 0) then
         name = var_g
         factor = g_accel
         values = raw_g
      else
         name = var
         factor = 1.0_dp
         values = raw
      end if
      n = given_count(values)
      if (n == 0) then
         call fail(at, var, var//' is missing (in m/s^2, or '//var_g//' in g)', error)
         return
      end if
      if (n > size(values) - 1) then
         call fail(at, name, name//' has more than '//str(size(values) - 1)//' values', error)
         return
      end if
      do i = 1, n
         if (.not. is_set(values(i))) then
            call fail(at, name, name//'('//str(i)//') is missing; give the values one after the other', error)
            return
         end if
         call check_real(at, name, values(i), '>', 0.0_dp, error, name=name//'('//str(i)//')')
         if (allocated(error)) return
         if (i > 1) then
            if (.not. (values(i) > values(i - 1))) then
               call fail(at, name, name//'('//str(i)//') = '//str(values(i))//', must be > '//name//'('// &
                         str(i - 1)//') = '//str(values(i - 1))//': the values ascend', error)
               return
            end if
         end if
      end do
      values = factor*values(1:n)
   end subroutine take_ascending

   !> The rules between `&stripes`, `&hazard` and the rest of the deck (after every group is
   !> read; `ground_groups(k)` is the group of motion k before the record sets are expanded).
   subroutine check_risk(path, d, stripes_group, hazard_group, ground_groups, n_motions, error)
      !> Deck path as given.
      character(len=*), intent(in) :: path
      !> The deck (its motions not yet expanded).
      type(deck_type), intent(in) :: d
      !> `&stripes` and `&hazard` (line1 0: absent).
      type(group_ref), intent(in) :: stripes_group, hazard_group
      !> The `&ground` groups, in deck order.
      type(group_ref), intent(in) :: ground_groups(:)
      !> Number of motions after the record sets are expanded.
      integer, intent(in) :: n_motions
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(site) :: at
      integer :: k

      if (stripes_group%line1 == 0) then
         if (hazard_group%line1 /= 0) then
            at = site_of(path, hazard_group)
            call fail(at, 'im', '&hazard needs &stripes (the multiple-stripe analysis whose fragilities the '// &
                      'hazard curve weighs)', error)
         end if
         return
      end if
      at = site_of(path, stripes_group)
      if (hazard_group%line1 == 0) then
         call fail(at, 'levels', '&hazard is missing: &stripes needs the site''s hazard curve of the same '// &
                   'measure (&hazard im, rate)', error)
         return
      end if
      if (n_motions < 2) then
         call fail(at, 'levels', '&stripes needs a suite of several motions (several &ground, or kind = '// &
                   "'record_set'), and the deck has "//str(n_motions), error)
         return
      end if
      if (size(d%contacts) == 0) then
         call fail(at, 'levels', '&stripes runs every motion coupled, and the deck has no &contact', error)
         return
      end if
      if (len_trim(d%sweep%parameter) > 0 .and. d%sweep%parameter /= 'gap') then
         call fail(at, 'levels', "&stripes works with a gap sweep; &sweep parameter = '"// &
                   trim(d%sweep%parameter)//"' is a joint study (run it without &stripes)", error)
         return
      end if
      if (size(d%variants) > 0) then
         call fail(at, 'levels', '&stripes does not take a law study (&contact variant); run it without &stripes', &
                   error)
         return
      end if
      do k = 1, size(d%motions)
         if (len(d%motions(k)%scale_to) > 0) then
            at = site_of(path, ground_groups(k))
            if (size(ground_groups) > 1) at%label = at%label//' #'//str(k)//' ('//d%motions(k)%name//')'
            call fail(at, 'scale_to', 'scale_to is refused with &stripes: the stripes set the scale of every '// &
                      'motion (&stripes measure and levels)', error)
            return
         end if
      end do
   end subroutine check_risk

end module pound_deck_risk
