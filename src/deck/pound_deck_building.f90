!> Reader of `&building`: name, storeys, heights, masses (or load coefficients), storey
!> stiffnesses (or columns), damping and P-Delta, kept as given (the model derives the
!> masses, stiffnesses and gravity loads: pound_storey_properties). A building in plan
!> (`model = 'plan'`) gives its outline, origin, centre of mass and rotational inertia here;
!> its storey stiffness comes from its planes (`&plane`, pound_deck_plane).
module pound_deck_building
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_config, only: building_config, deck_warning_len
   use pound_constants, only: g_accel
   use pound_deck_checks, only: check_plausible, check_real, fail, given_count, is_set, read_failed, require_real, &
                                widen, site, group_input, take_ints, take_reals, unset_int, unset_real, warn
   use pound_deck_storey_law, only: take_storey_law
   use pound_deck_hinge_law, only: take_hinge_law
   use pound_deck_lexer, only: group_extent, group_ref, is_name_char, lower
   use pound_deck_variables, only: max_name_length, max_storeys, word_len, max_bays, max_column_elements, &
                                   frame_variables, plan_variables
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: plain_real, plain_significant, str
   implicit none
   private

   public :: read_building

   !> The `&building` variables that give a shear building's storey stiffness (not with a frame).
   character(len=*), parameter :: shear_variables(5) = [character(len=11) :: 'stiffness', 'n_columns', &
      'e_modulus', 'inertia', 'column_ends']
   !> Why a plan variable is refused on another model (the building's model follows).
   character(len=*), parameter :: plan_only = " describes a building in plan: it applies only with model = 'plan' "
   !> The `&building` variables of a shear building's storey law (a building in plan: its planes').
   character(len=*), parameter :: storey_law_variables(3) = [character(len=15) :: 'storey_law', 'yield_shear', &
      'hardening_ratio']

contains

   !> `&building`: one shear building.
   subroutine read_building(path, text, g, previous, cfg, error, warnings)
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
      !> The deck's plausibility warnings, this group's appended.
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)
      character(len=word_len) :: name, column_ends, model, base, geometric, storey_law, hinge_law
      integer :: n_storeys, damping_modes(2), n_bays, column_elements
      logical :: rigid_beams, rigid_diaphragm, rigid_columns
      real(dp), allocatable :: bay_width(:), column_e(:), column_area(:), column_inertia(:), &
                               beam_e(:), beam_area(:), beam_inertia(:)
      real(dp) :: ref_floor_load, damping_ratio, cd, importance, behaviour_factor, response_reduction
      real(dp) :: plan_size(2), plan_origin_y, mass_centre(2)
      real(dp), allocatable :: rot_inertia(:)
      logical :: p_delta
      real(dp), allocatable :: height(:), mass(:), load_coeff(:), stiffness(:), e_modulus(:), &
                               inertia(:), gravity_load(:), yield_shear(:), hardening_ratio(:), &
                               column_yield_moment(:), beam_yield_moment(:), hinge_hardening(:)
      integer, allocatable :: n_columns(:)
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      integer :: ios, n, cap
      namelist /building/ name, n_storeys, height, mass, load_coeff, ref_floor_load, stiffness, &
         n_columns, e_modulus, inertia, column_ends, damping_ratio, damping_modes, p_delta, &
         gravity_load, model, n_bays, bay_width, column_e, column_area, column_inertia, beam_e, &
         beam_area, beam_inertia, base, column_elements, rigid_beams, rigid_diaphragm, rigid_columns, &
         geometric, cd, importance, behaviour_factor, response_reduction, storey_law, yield_shear, &
         hardening_ratio, hinge_law, column_yield_moment, beam_yield_moment, hinge_hardening, &
         plan_size, plan_origin_y, mass_centre, rot_inertia

      ! The per-storey arrays as long as the deck's highest element (the lexer checked it
      ! against max_storeys), widened to n_storeys once it is known: a few storeys do not
      ! touch max_storeys elements of each.
      cap = group_extent(g)
      allocate (height(cap), mass(cap), load_coeff(cap), stiffness(cap), e_modulus(cap), &
                inertia(cap), gravity_load(cap), n_columns(cap))
      name = ' '
      column_ends = ' '
      n_storeys = unset_int
      damping_modes = unset_int
      ref_floor_load = unset_real
      damping_ratio = 0.05_dp
      cd = unset_real
      importance = unset_real
      behaviour_factor = unset_real
      response_reduction = unset_real
      p_delta = .false.
      height = unset_real
      mass = unset_real
      load_coeff = unset_real
      stiffness = unset_real
      e_modulus = unset_real
      inertia = unset_real
      gravity_load = unset_real
      n_columns = unset_int
      model = ' '
      base = ' '
      geometric = ' '
      n_bays = unset_int
      column_elements = unset_int
      rigid_beams = .false.
      rigid_diaphragm = .false.
      rigid_columns = .false.
      storey_law = ' '
      hinge_law = ' '
      allocate (yield_shear(cap), hardening_ratio(cap), column_yield_moment(cap), beam_yield_moment(cap), &
                hinge_hardening(cap), rot_inertia(cap), source=unset_real)
      plan_size = unset_real
      plan_origin_y = unset_real
      mass_centre = unset_real
      allocate (bay_width(max_bays), column_e(cap), column_area(cap), column_inertia(cap), &
                beam_e(cap), beam_area(cap), beam_inertia(cap))
      bay_width = unset_real
      column_e = unset_real
      column_area = unset_real
      column_inertia = unset_real
      beam_e = unset_real
      beam_area = unset_real
      beam_inertia = unset_real
      call group_input(path, text, g, at, buf, msg)
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
      if (n > cap) then
         call widen(height, n)
         call widen(mass, n)
         call widen(load_coeff, n)
         call widen(stiffness, n)
         call widen(e_modulus, n)
         call widen(inertia, n)
         call widen(gravity_load, n)
         call widen(n_columns, n)
         call widen(column_e, n)
         call widen(column_area, n)
         call widen(column_inertia, n)
         call widen(beam_e, n)
         call widen(beam_area, n)
         call widen(beam_inertia, n)
         call widen(rot_inertia, n)
      end if

      call take_reals(at, 'height', height, n, '>', cfg%height, error)
      if (allocated(error)) return

      call resolve_masses(at, n, mass, load_coeff, ref_floor_load, cfg, error)
      if (allocated(error)) return
      select case (lower(trim(adjustl(model))))
      case ('', 'shear')
         cfg%model = 'shear'
         call refuse_given(at, frame_variables, " describes a frame: it applies only with model = 'frame' "// &
                           '(this building is a shear building)', error)
         if (allocated(error)) return
         call refuse_given(at, plan_variables, plan_only//'(this building is a shear building)', error)
         if (allocated(error)) return
         call resolve_stiffness(at, n, stiffness, n_columns, e_modulus, inertia, &
                                column_ends, cfg, error)
      case ('frame')
         cfg%model = 'frame'
         call refuse_given(at, shear_variables, " applies only to a shear building; a frame (model = 'frame') "// &
                           'takes its stiffness from column_e, column_area, column_inertia and the beams', error)
         if (allocated(error)) return
         call refuse_given(at, plan_variables, plan_only//'(this building is a frame)', error)
         if (allocated(error)) return
         call resolve_bays(at, n_bays, bay_width, cfg, error)
         if (allocated(error)) return
         call take_group(at, 'column_e', column_e, n, cfg%column_e, error)
         if (.not. allocated(error)) call take_group(at, 'column_area', column_area, n, cfg%column_area, error)
         if (.not. allocated(error)) call take_group(at, 'column_inertia', column_inertia, n, &
                                                     cfg%column_inertia, error)
         if (.not. allocated(error)) call take_group(at, 'beam_e', beam_e, n, cfg%beam_e, error)
         if (.not. allocated(error)) call take_group(at, 'beam_area', beam_area, n, cfg%beam_area, error)
         if (.not. allocated(error)) call take_group(at, 'beam_inertia', beam_inertia, n, cfg%beam_inertia, error)
         if (allocated(error)) return
         call choose(at, 'base', base, ['fixed ', 'pinned'], cfg%base, error)
         if (allocated(error)) return
         call choose(at, 'geometric', geometric, ['chord     ', 'consistent'], cfg%geometric, error)
         if (allocated(error)) return
         if (column_elements /= unset_int) then
            if (column_elements < 1 .or. column_elements > max_column_elements) then
               call fail(at, 'column_elements', 'column_elements = '//str(column_elements)// &
                         ', must be in 1..'//str(max_column_elements), error)
               return
            end if
            cfg%column_elements = column_elements
         end if
         cfg%rigid_beams = rigid_beams
         cfg%rigid_diaphragm = rigid_diaphragm
         cfg%rigid_columns = rigid_columns
      case ('plan')
         cfg%model = 'plan'
         call refuse_given(at, frame_variables, " describes a frame: it applies only with model = 'frame' "// &
                           "(this building is a building in plan, model = 'plan')", error)
         if (allocated(error)) return
         call refuse_given(at, shear_variables, " applies only to a shear building; a building in plan "// &
                           "(model = 'plan') takes its storey stiffness from its planes (&plane groups naming "// &
                           'it: stiffness per storey, kN/m)', error)
         if (allocated(error)) return
         call refuse_given(at, storey_law_variables, " is not a variable of a building in plan (model = 'plan'): "// &
                           'each plane has its own storey law (&plane storey_law, yield_shear, hardening_ratio)', error)
         if (allocated(error)) return
         call resolve_plan(at, n, plan_size, plan_origin_y, mass_centre, rot_inertia, cfg, warnings, error)
      case default
         call fail(at, 'model', "model = '"//trim(adjustl(model))//"', must be 'shear', 'frame' or 'plan'", error)
      end select
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
      if (cfg%model == 'plan') then
         ! Three modes a floor (x, y and torsion alike, in ascending frequency).
         call check_modes(at, 3*n, damping_modes, cfg%damping_modes, error, &
                          '3 n_storeys = '//str(3*n)//' (the 3D modes: three a floor)')
      else
         call check_modes(at, n, damping_modes, cfg%damping_modes, error)
      end if
      if (allocated(error)) return
      cfg%p_delta = p_delta
      call take_storey_law(at, storey_law, yield_shear, hardening_ratio, cfg, error)
      if (allocated(error)) return
      call take_hinge_law(at, hinge_law, column_yield_moment, beam_yield_moment, hinge_hardening, cfg, error)
      if (allocated(error)) return

      if (given_count(gravity_load) > 0) then
         call take_reals(at, 'gravity_load', gravity_load, n, '>=', cfg%gravity_load, error)
         if (allocated(error)) return
      end if

      call code_factor(at, 'cd', cd, 1.0_dp, 8.0_dp, 'ASCE 7 Table 12.2-1 gives Cd from 1.25 to 6.5', &
                       cfg%factors%cd, warnings, error)
      if (.not. allocated(error)) call code_factor(at, 'importance', importance, 1.0_dp, 1.5_dp, &
                                                   'ASCE 7 Table 1.5-2 gives Ie from 1.0 to 1.5', &
                                                   cfg%factors%importance, warnings, error)
      if (.not. allocated(error)) call code_factor(at, 'behaviour_factor', behaviour_factor, 1.0_dp, 8.0_dp, &
                                                   'EN 1998-1 gives q from 1.5 to about 6.5', &
                                                   cfg%factors%behaviour_factor, warnings, error)
      if (.not. allocated(error)) call code_factor(at, 'response_reduction', response_reduction, 1.0_dp, 8.0_dp, &
                                                   'IS 1893 Table 9 gives R from 1.5 to 5', &
                                                   cfg%factors%response_reduction, warnings, error)
      if (allocated(error)) return
      call unreduced_factor(at, 'cd', cfg%factors%cd, 'Cd', 'R/Ie', warnings)
      call unreduced_factor(at, 'behaviour_factor', cfg%factors%behaviour_factor, 'q', 'q', warnings)
      call unreduced_factor(at, 'response_reduction', cfg%factors%response_reduction, 'R', 'R', warnings)
   end subroutine read_building

   !> A design factor above 1 (`cd`, `behaviour_factor`, `response_reduction`) with the
   !> motions at full intensity: a warning. pound has no motion reduced to the design action
   !> (every record, synthetic motion and pulse is taken at the intensity the deck gives), so
   !> the uncoupled response-history peak already is the displacement demand; the code's
   !> factor converts a reduced elastic analysis and would amplify the peak again.
   pure subroutine unreduced_factor(at, var, value, symbol, reduction, warnings)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> The resolved factor (0: not given).
      real(dp), intent(in) :: value
      !> The code's symbol of the factor and of the reduction it undoes.
      character(len=*), intent(in) :: symbol, reduction
      !> The deck's plausibility warnings.
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)

      if (.not. (value > 1.0_dp)) return
      call warn(at, var, var//' = '//plain_real(value)//' > 1 with motions at full intensity (pound''s '// &
                'records, synthetic motions and pulses are not reduced): their response-history peak already is '// &
                'the displacement demand and '//symbol//' amplifies it again ('//plain_real(value)// &
                ' x); set '//var//' = 1, unless the motions are scaled down to the design spectrum / '// &
                reduction, warnings)
   end subroutine unreduced_factor

   !> One design-code factor of the separation rules (`cd`, `importance`, `behaviour_factor`,
   !> `response_reduction`): when given, > 0 (refused otherwise) and, outside the usual range
   !> lo..hi, a warning; when not given, `value` keeps its default.
   pure subroutine code_factor(at, var, raw, lo, hi, usual, value, warnings, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name as in the deck.
      character(len=*), intent(in) :: var
      !> Value as read (`unset_real` when not given).
      real(dp), intent(in) :: raw
      !> The usual range.
      real(dp), intent(in) :: lo, hi
      !> Where the usual range comes from (for the warning).
      character(len=*), intent(in) :: usual
      !> The resolved factor (default kept when not given).
      real(dp), intent(inout) :: value
      !> The deck's plausibility warnings.
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)
      !> Unallocated on success; otherwise the problem found.
      type(error_type), allocatable, intent(out) :: error

      if (.not. is_set(raw)) return
      call check_real(at, var, raw, '>', 0.0_dp, error)
      if (allocated(error)) return
      value = raw
      if (raw < lo .or. raw > hi) call warn(at, var, var//' = '//plain_real(raw)//' is outside the usual range '// &
                                            plain_real(lo)//'..'//plain_real(hi)//' ('//usual//'); check the value', warnings)
   end subroutine code_factor

   !> The first of `names` the group assigns is refused: `name` followed by `rule`.
   pure subroutine refuse_given(at, names, rule, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable names, lower case.
      character(len=*), intent(in) :: names(:)
      !> Why, after the variable's name.
      character(len=*), intent(in) :: rule
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer :: i

      do i = 1, size(names)
         if (assigned(at, names(i))) then
            call fail(at, trim(names(i)), trim(names(i))//rule, error)
            return
         end if
      end do
   end subroutine refuse_given

   !> A building in plan: the outline `plan_size` (required, Lx, Ly > 0), the site y of its
   !> edge y = 0 `plan_origin_y` (default 0), the centre of mass `mass_centre` (default the
   !> outline's centre; inside the outline) and the rotational inertia of each floor
   !> `rot_inertia` (n_storeys values > 0; default left to the builder: mass (Lx^2 + Ly^2)/12).
   !> A radius of gyration sqrt(I/m) beyond the outline's diagonal is warned.
   pure subroutine resolve_plan(at, n, plan_size, plan_origin_y, mass_centre, rot_inertia, cfg, warnings, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Number of storeys.
      integer, intent(in) :: n
      !> Namelist values as read (`unset_real` where not given).
      real(dp), intent(in) :: plan_size(2), plan_origin_y, mass_centre(2), rot_inertia(:)
      !> Building being resolved (its masses already).
      type(building_config), intent(inout) :: cfg
      !> The deck's plausibility warnings.
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: size_names(2) = ['Lx', 'Ly'], centre_names(2) = ['xm', 'ym']
      real(dp) :: m, radius, diagonal
      integer :: i, j

      if (given_count(plan_size) == 0) then
         call fail(at, 'plan_size', "plan_size is missing: model = 'plan' needs the outline plan_size = Lx, Ly "// &
                   '(m, > 0; x along the row of buildings, y along the facing facades)', error)
         return
      end if
      if (given_count(plan_size) == 1) then
         call fail(at, 'plan_size', 'plan_size has 1 value, must have 2: plan_size = Lx, Ly (m, > 0)', error)
         return
      end if
      do i = 1, 2
         if (.not. is_set(plan_size(i))) then
            call fail(at, 'plan_size', 'plan_size('//str(i)//') is missing; give plan_size = Lx, Ly (m, > 0)', error)
            return
         end if
         call check_real(at, 'plan_size', plan_size(i), '>', 0.0_dp, error, name='plan_size('//str(i)//')')
         if (allocated(error)) return
      end do
      cfg%plan_size = plan_size
      if (is_set(plan_origin_y)) then
         if (.not. ieee_is_finite(plan_origin_y)) then
            call fail(at, 'plan_origin_y', 'plan_origin_y = '//str(plan_origin_y)//', must be a finite number', error)
            return
         end if
         call check_plausible(at, 'plan_origin_y', plan_origin_y, 'plan_origin_y', error)
         if (allocated(error)) return
         cfg%plan_origin_y = plan_origin_y
      end if
      cfg%mass_centre = 0.5_dp*plan_size
      cfg%mass_centre_given = given_count(mass_centre) > 0
      if (cfg%mass_centre_given) then
         if (given_count(mass_centre) == 1) then
            call fail(at, 'mass_centre', 'mass_centre has 1 value, must have 2: mass_centre = xm, ym (m, in '// &
                      'the outline 0..Lx, 0..Ly)', error)
            return
         end if
         do i = 1, 2
            if (.not. is_set(mass_centre(i))) then
               call fail(at, 'mass_centre', 'mass_centre('//str(i)//') is missing; give mass_centre = xm, ym', error)
               return
            end if
            if (.not. ieee_is_finite(mass_centre(i))) then
               call fail(at, 'mass_centre', 'mass_centre('//str(i)//') = '//str(mass_centre(i))// &
                         ', must be a finite number', error)
               return
            end if
            if (mass_centre(i) < 0.0_dp .or. mass_centre(i) > plan_size(i)) then
               call fail(at, 'mass_centre', 'mass_centre('//str(i)//') = '//centre_names(i)//' = '// &
                         plain_real(mass_centre(i))//' m lies outside the outline: must be in 0..'// &
                         size_names(i)//' = '//plain_real(plan_size(i))//' m (plan_size; the centre of mass is '// &
                         "in the outline's coordinates, its corner at 0, 0)", error)
               return
            end if
         end do
         cfg%mass_centre = mass_centre
      end if
      if (given_count(rot_inertia) == 0) return
      call take_reals(at, 'rot_inertia', rot_inertia, n, '>', cfg%rot_inertia, error)
      if (allocated(error)) return
      diagonal = sqrt(plan_size(1)**2 + plan_size(2)**2)
      do j = 1, n
         if (allocated(cfg%mass)) then
            m = cfg%mass(j)
         else if (allocated(cfg%load_coeff)) then
            m = cfg%load_coeff(j)*cfg%ref_floor_load/g_accel
         else
            return
         end if
         radius = sqrt(cfg%rot_inertia(j)/m)
         if (radius > diagonal) then
            call warn(at, 'rot_inertia', 'rot_inertia('//str(j)//') = '//plain_significant(cfg%rot_inertia(j), 4)// &
                      ' t m^2 gives a radius of gyration sqrt(I/m) = '//plain_significant(radius, 4)// &
                      ' m, more than the outline''s diagonal '//plain_significant(diagonal, 4)//' m: no mass '// &
                      'inside the outline has it; rot_inertia is in t m^2 per floor about the centre of mass '// &
                      '(uniform floor: mass (Lx^2 + Ly^2)/12 = '// &
                      plain_significant(m*diagonal**2/12.0_dp, 4)//' t m^2)', warnings)
            return
         end if
      end do
   end subroutine resolve_plan

   !> Whether the deck assigns `var` in this group occurrence.
   pure logical function assigned(at, var)
      !> Where messages point (the group occurrence).
      type(site), intent(in) :: at
      !> Variable name, lower case.
      character(len=*), intent(in) :: var
      integer :: i

      assigned = .false.
      do i = 1, at%group%n_vars
         if (at%group%vars(i)%name == trim(var)) assigned = .true.
      end do
   end function assigned

   !> Bay widths of a frame: `bay_width` (required) with n_bays values, or one value repeated
   !> `n_bays` times.
   pure subroutine resolve_bays(at, n_bays, raw, cfg, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> `n_bays` as read (`unset_int`: the number of widths given).
      integer, intent(in) :: n_bays
      !> `bay_width` as read.
      real(dp), intent(in) :: raw(:)
      !> Building being resolved.
      type(building_config), intent(inout) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, nb

      k = given_count(raw)
      if (k == 0) then
         call fail(at, 'bay_width', "bay_width is missing (bay widths in m, left to right) for "// &
                   "model = 'frame'", error)
         return
      end if
      nb = k
      if (n_bays /= unset_int) then
         if (n_bays < 1 .or. n_bays > max_bays) then
            call fail(at, 'n_bays', 'n_bays = '//str(n_bays)//', must be in 1..'//str(max_bays), error)
            return
         end if
         if (k /= 1 .and. k /= n_bays) then
            call fail(at, 'bay_width', 'bay_width has '//str(k)//' values, must have 1 or n_bays = '// &
                      str(n_bays), error)
            return
         end if
         nb = n_bays
      end if
      call take_group(at, 'bay_width', raw, nb, cfg%bay_width, error)
   end subroutine resolve_bays

   !> A frame section group: one value for all (repeated `n` times) or `n` values, each > 0.
   pure subroutine take_group(at, var, raw, n, values, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name.
      character(len=*), intent(in) :: var
      !> Namelist array as read.
      real(dp), intent(in) :: raw(:)
      !> Number of values wanted.
      integer, intent(in) :: n
      !> The `n` values.
      real(dp), allocatable, intent(out) :: values(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: one(:)
      integer :: k

      if (given_count(raw) == 0) then
         call fail(at, var, var//" is missing (one value for all, or "//str(n)//" values) for "// &
                   "model = 'frame'", error)
      else if (given_count(raw) == 1 .and. n > 1) then
         call take_reals(at, var, raw, 1, '>', one, error)
         if (.not. allocated(error)) values = [(one(1), k=1, n)]
      else
         call take_reals(at, var, raw, n, '>', values, error)
      end if
   end subroutine take_group

   !> A word variable with a default (the first choice): lower case, one of `choices`.
   pure subroutine choose(at, var, raw, choices, value, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Variable name.
      character(len=*), intent(in) :: var
      !> As read.
      character(len=*), intent(in) :: raw
      !> The choices (first: the default).
      character(len=*), intent(in) :: choices(:)
      !> The choice.
      character(len=:), allocatable, intent(out) :: value
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: w
      integer :: i

      w = lower(trim(adjustl(raw)))
      if (len(w) == 0) then
         value = trim(choices(1))
         return
      end if
      do i = 1, size(choices)
         if (w == trim(choices(i))) then
            value = w
            return
         end if
      end do
      call fail(at, var, var//" = '"//trim(adjustl(raw))//"', must be '"//trim(choices(1))// &
                "' or '"//trim(choices(2))//"'", error)
   end subroutine choose

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
   pure subroutine check_modes(at, n, raw, modes, error, limit)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Number of modes (the storeys; a building in plan: three a floor).
      integer, intent(in) :: n
      !> `damping_modes` as read (`unset_int` where not given).
      integer, intent(in) :: raw(2)
      !> Modes for the Rayleigh fit.
      integer, intent(out) :: modes(2)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> How the messages name the largest mode (default 'n_storeys = n').
      character(len=*), intent(in), optional :: limit
      character(len=:), allocatable :: largest
      integer :: i, given

      largest = 'n_storeys = '//str(n)
      if (present(limit)) largest = limit
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
                      ', must be in 1..'//largest, error)
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

end module pound_deck_building
