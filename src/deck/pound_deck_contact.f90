!> Reader of `&contact`: the two buildings, the floor pairs, gaps and the joint law with its
!> parameters (each law's own variables are checked by its module: pound_law_registry).
module pound_deck_contact
   use pound_config, only: building_config, contact_config, is_frame, deck_warning_len
   use pound_building_spec, only: is_plan
   use pound_deck_checks, only: check_real, fail, warn, given_count, is_set, read_failed, site, group_input, unset_int, &
                                unset_real, values_text
   use pound_deck_lexer, only: group_ref, lower
   use pound_law_registry, only: registered_law_names, law_is_registered, law_reads, law_restitution, law_take_deck, &
                                 restitution_law_names, law_variables, law_stiffness_linear
   use pound_joint_law, only: law_input, law_variable
   use pound_deck_variables, only: max_envelope_points, max_pairs, word_len
   use pound_deck_stiffness, only: stiffness_has_default, default_joint_stiffness
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str, plain_real
   implicit none
   private

   public :: read_contact, elevation_tol, find_building

   !> Elevations closer than this are the same point (m): a pair's elevation and a floor's.
   real(dp), parameter :: elevation_tol = 1.0e-6_dp
   !> A gap above this (m), or above this fraction of the lower building's height, is warned.
   real(dp), parameter :: gap_high = 1.0_dp, gap_height_fraction = 0.1_dp

contains

   !> `&contact`: unilateral constraints between facing floors of two buildings.
   subroutine read_contact(path, text, g, buildings, cfg, error, warnings)
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
      !> The deck's warnings, extended by an implausible gap's (`gap_warning`).
      character(len=deck_warning_len), allocatable, intent(inout), optional :: warnings(:)
      character(len=word_len) :: left, right, law, dashpot_rate, variant
      integer, allocatable :: floors_left(:), floors_right(:)
      real(dp), allocatable :: gap(:), envelope_d(:), envelope_r(:), elevations(:)
      real(dp) :: stiffness, dashpot, yield_force, second_slope, peak_force, peak_penetration, &
                  fracture_penetration, restitution, friction, shear_stiffness
      integer :: n_segments
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      type(law_input) :: raw
      type(law_variable), allocatable :: vars(:)
      integer :: ios, n, k, i
      namelist /contact/ left, right, floors_left, floors_right, gap, law, stiffness, dashpot, &
         dashpot_rate, yield_force, second_slope, envelope_d, envelope_r, peak_force, peak_penetration, &
         fracture_penetration, n_segments, restitution, elevations, variant, friction, shear_stiffness

      ! One slot more than allowed, so that too many pairs get our message, not gfortran's.
      allocate (floors_left(max_pairs + 1), floors_right(max_pairs + 1), gap(max_pairs + 1), &
                envelope_d(max_envelope_points + 1), envelope_r(max_envelope_points + 1), &
                elevations(max_pairs + 1))
      left = ' '
      right = ' '
      law = ' '
      dashpot_rate = 'backward_euler'
      variant = ' '
      floors_left = unset_int
      floors_right = unset_int
      gap = unset_real
      elevations = unset_real
      envelope_d = unset_real
      envelope_r = unset_real
      stiffness = unset_real
      yield_force = unset_real
      second_slope = unset_real
      peak_force = unset_real
      peak_penetration = unset_real
      fracture_penetration = unset_real
      n_segments = unset_int
      dashpot = unset_real
      restitution = unset_real
      friction = unset_real
      shear_stiffness = unset_real
      call group_input(path, text, g, at, buf, msg)
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

      if (given_count(elevations) > 0) then
         if (given_count(floors_left) > 0 .or. given_count(floors_right) > 0) then
            call fail(at, 'elevations', 'elevations and floors_left/floors_right are both given; give '// &
                      'the pairs by floor (floors_left, floors_right) or by elevation (elevations), not both', error)
            return
         end if
         call take_elevations(error)
         if (allocated(error)) return
      else
         call take_floors(at, 'floors_left', floors_left, buildings(cfg%left_index), cfg%floor_left, error)
         if (allocated(error)) return
         call take_floors(at, 'floors_right', floors_right, buildings(cfg%right_index), cfg%floor_right, error)
         if (allocated(error)) return
      end if
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
      if (present(warnings)) call gap_warning(at, cfg%gap, buildings(cfg%left_index), &
                                              buildings(cfg%right_index), warnings)

      cfg%law = lower(trim(adjustl(law)))
      if (cfg%law == '') then
         call fail(at, 'law', 'law is missing, must be '//registered_law_names(), error)
         return
      else if (.not. law_is_registered(cfg%law)) then
         call fail(at, 'law', "law = '"//trim(adjustl(law))//"', must be "//registered_law_names(), error)
         return
      end if

      ! Variables of other laws (pound_law_registry: what each law declares) are an error.
      raw = law_input(stiffness=stiffness, yield_force=yield_force, second_slope=second_slope, &
                      peak_force=peak_force, peak_penetration=peak_penetration, &
                      fracture_penetration=fracture_penetration, n_segments=n_segments, &
                      envelope_d=envelope_d, envelope_r=envelope_r, dashpot=dashpot, restitution=restitution)
      vars = law_variables()
      do i = 1, size(vars)
         if (.not. vars(i)%refused) cycle
         call unused(trim(vars(i)%name), raw%given(trim(vars(i)%name)), error)
         if (allocated(error)) return
      end do

      ! No stiffness: the default of the facing floors (pound_deck_stiffness), as if given.
      if (.not. is_set(stiffness) .and. stiffness_has_default(cfg%law) .and. law_reads(cfg%law, 'stiffness')) then
         call default_joint_stiffness(at, cfg, buildings, stiffness, cfg%stiffness_rule, error)
         if (allocated(error)) return
      end if
      if (len_trim(variant) > 32) then
         call fail(at, 'variant', "variant = '"//trim(adjustl(variant))//"' is longer than 32 characters", error)
         return
      end if
      cfg%variant = trim(adjustl(variant))

      ! The law's own variables, checked by the law's module (pound_law_registry).
      raw%stiffness = stiffness
      call law_take_deck(cfg%law, at, raw, cfg, error)
      if (allocated(error)) return

      if (is_set(restitution)) then
         if (.not. law_restitution(cfg%law)) then
            call fail(at, 'restitution', "restitution is not a variable of law = '"//cfg%law// &
                      "' (it is for law = "//restitution_law_names()//')', error)
            return
         end if
         if (is_set(dashpot)) then
            call fail(at, 'restitution', 'restitution and dashpot are both given; give one of them '// &
                      '(restitution sets the dashpot from the joint stiffness and the facing masses)', error)
            return
         end if
         if (.not. (restitution > 0.0_dp .and. restitution < 1.0_dp)) then
            call fail(at, 'restitution', 'restitution = '//str(restitution)//', must be > 0 and < 1 '// &
                      '(coefficient of restitution of an impact)', error)
            return
         end if
         do i = 1, n
            if (cfg%floor_left(i) == 0 .or. cfg%floor_right(i) == 0) then
               call fail(at, 'restitution', 'restitution = '//plain_real(restitution)//" (law = '"//cfg%law// &
                         "') needs the masses of both facing points: the dashpot is calibrated so that an "// &
                         'impact of the two facing masses rebounds with that restitution, and elevations('// &
                         str(i)//') = '//plain_real(cfg%elevation(i))//' m is a column point between floors of '// &
                         trim(merge(cfg%left, cfg%right, cfg%floor_left(i) == 0))//', which has no mass of its '// &
                         'own (no impact to calibrate); '//instead(cfg%law), error)
               return
            end if
         end do
         cfg%restitution = restitution
      end if
      if (.not. is_set(dashpot)) dashpot = 0.0_dp
      call check_real(at, 'dashpot', dashpot, '>=', 0.0_dp, error)
      if (allocated(error)) return
      cfg%dashpot = dashpot
      cfg%dashpot_rate = lower(trim(adjustl(dashpot_rate)))
      if (cfg%dashpot_rate /= 'backward_euler' .and. cfg%dashpot_rate /= 'trapezoidal') then
         call fail(at, 'dashpot_rate', "dashpot_rate = '"//trim(adjustl(dashpot_rate))// &
                   "', must be 'backward_euler' or 'trapezoidal'", error)
         return
      end if
      call take_friction(at, friction, shear_stiffness, is_plan(buildings(cfg%left_index)) .or. &
                         is_plan(buildings(cfg%right_index)), cfg, error, warnings)

   contains

      !> What a joint at a point without mass takes instead of `restitution`.
      pure function instead(name) result(text)
         character(len=*), intent(in) :: name
         character(len=:), allocatable :: text

         if (name == 'elastic') then
            text = 'give the dashpot (kN s/m) instead of restitution'
         else
            text = "instead use law = 'hertz' (the same contact without damping), law = 'elastic' with "// &
                   'a dashpot (kN s/m) given directly, or put the floor-to-floor pairs in a &contact group '// &
                   'of their own with this law'
         end if
      end function instead

      !> Pairs by elevation: 1..`max_pairs` values, each > 0, at a floor or on a frame's
      !> facing column of each building (pound_deck_contact's `point_at`).
      subroutine take_elevations(error)
         type(error_type), allocatable, intent(out) :: error
         integer :: ne, j

         ne = given_count(elevations)
         if (ne > max_pairs) then
            call fail(at, 'elevations', 'elevations has '//values_text(ne)//', must have at most '// &
                      str(max_pairs)//' (one per pair)', error)
            return
         end if
         allocate (cfg%elevation(ne), cfg%floor_left(ne), cfg%floor_right(ne))
         do j = 1, ne
            if (.not. is_set(elevations(j))) then
               call fail(at, 'elevations', 'elevations('//str(j)//') is missing; give one elevation '// &
                         '(m above the base) per pair', error)
               return
            end if
            call check_real(at, 'elevations', elevations(j), '>', 0.0_dp, error, name='elevations('//str(j)//')')
            if (allocated(error)) return
            cfg%elevation(j) = elevations(j)
            call point_at(at, j, elevations(j), buildings(cfg%left_index), cfg%floor_left(j), error)
            if (allocated(error)) return
            call point_at(at, j, elevations(j), buildings(cfg%right_index), cfg%floor_right(j), error)
            if (allocated(error)) return
         end do
      end subroutine take_elevations

      !> `var` was given (`given`) although the law does not read it (pound_law_registry).
      pure subroutine unused(var, given, error)
         character(len=*), intent(in) :: var
         logical, intent(in) :: given
         type(error_type), allocatable, intent(out) :: error

         if (given .and. .not. law_reads(cfg%law, var)) then
            if (var == 'stiffness') then
               call fail(at, var, "stiffness is not used by law = 'piecewise' (k0 is the slope of "// &
                         'its first segment, envelope_r(1)/envelope_d(1))', error)
            else
               call fail(at, var, var//" is not used by law = '"//cfg%law//"'", error)
            end if
         end if
      end subroutine unused



   end subroutine read_contact

   !> `friction` (Coulomb mu >= 0, default 0) and `shear_stiffness` (kt in kN/m, > 0 when given) of
   !> group `cfg` (its law and stiffness resolved), only between buildings in plan (a planar
   !> building has no motion along the facades). kt defaults to the group's stiffness k0 for
   !> the laws whose stiffness is linear (kN/m; pound_law_registry `law_stiffness_linear`) and
   !> is required for the others (the Hertz family, kN/m^(3/2)) when mu > 0. Stored resolved:
   !> `cfg%shear_stiffness` = 0 only without friction and without a given kt. A mu above 1 is warned.
   pure subroutine take_friction(at, friction, shear_stiffness, in_plan, cfg, error, warnings)
      !> Where messages point.
      type(site), intent(in) :: at
      !> As read (`unset_real`: not given).
      real(dp), intent(in) :: friction, shear_stiffness
      !> Whether the pair's buildings are in plan.
      logical, intent(in) :: in_plan
      !> The group (law and stiffness resolved).
      type(contact_config), intent(inout) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> The deck's warnings.
      character(len=deck_warning_len), allocatable, intent(inout), optional :: warnings(:)

      if (is_set(friction)) then
         call check_real(at, 'friction', friction, '>=', 0.0_dp, error)
         if (allocated(error)) return
         if (friction > 0.0_dp .and. .not. in_plan) then
            call fail(at, 'friction', 'friction = '//plain_real(friction)//' applies only between buildings '// &
                      "in plan (model = 'plan'): a planar building has no tangential DOF (no motion along the "// &
                      'facing facades) for friction to act on', error)
            return
         end if
         cfg%friction = friction
         if (friction > 1.0_dp .and. present(warnings)) call warn(at, 'friction', 'friction = '// &
            plain_real(friction)//' is above 1: Coulomb coefficients between concrete or masonry facades are '// &
            'about 0.3 to 0.8; a value above 1 nearly locks the facades together while in contact; check the value', &
            warnings)
      end if
      if (is_set(shear_stiffness)) then
         if (.not. in_plan) then
            call fail(at, 'shear_stiffness', 'shear_stiffness applies only between buildings in plan '// &
                      "(model = 'plan', with friction): a planar building has no tangential DOF", error)
            return
         end if
         call check_real(at, 'shear_stiffness', shear_stiffness, '>', 0.0_dp, error)
         if (allocated(error)) return
         cfg%shear_stiffness = shear_stiffness
      else if (cfg%friction > 0.0_dp) then
         if (.not. law_stiffness_linear(cfg%law)) then
            call fail(at, 'shear_stiffness', 'shear_stiffness is missing: friction = '//plain_real(cfg%friction)// &
                      " with law = '"//cfg%law//"' needs the tangential stiffness kt (kN/m, > 0) of the pair; "// &
                      "the law's stiffness is a Hertz coefficient (kN/m^(3/2)), no default for kt", error)
            return
         end if
         cfg%shear_stiffness = cfg%stiffness
      end if
   end subroutine take_friction

   !> A gap above `gap_high` m, or above `gap_height_fraction` of the lower building's height,
   !> most likely in cm or mm instead of m (`gap = 4.0` meant as 4 cm): warned (one line, the
   !> largest such gap of the group), not refused.
   pure subroutine gap_warning(at, gaps, a, b, warnings)
      !> Where messages point.
      type(site), intent(in) :: at
      !> The group's gaps (m), one per pair.
      real(dp), intent(in) :: gaps(:)
      !> The two buildings.
      type(building_config), intent(in) :: a, b
      !> The deck's warnings.
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)
      real(dp) :: g, h, limit

      if (size(gaps) == 0) return
      g = maxval(gaps)
      h = huge(1.0_dp)
      if (allocated(a%height)) h = min(h, sum(a%height))
      if (allocated(b%height)) h = min(h, sum(b%height))
      limit = min(gap_high, gap_height_fraction*h)
      if (.not. (g > limit)) return
      call warn(at, 'gap', 'gap = '//plain_real(g)//' m is above '//plain_real(limit)//' m (1 m, or a tenth '// &
                'of the lower building''s height '//plain_real(h)//' m): gaps are in m; did you mean '// &
                plain_real(g/100.0_dp)//' m (cm) or '//plain_real(g/1000.0_dp)//' m (mm)? With such a gap the '// &
                'buildings may never touch', warnings)
   end subroutine gap_warning

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

   !> The floor of building `b` at elevation `z` of pair `k` (within `elevation_tol`), or 0 for a
   !> point between floors, which only a frame has (a node on its facing column); above the
   !> roof or between the floors of a shear building: an error.
   pure subroutine point_at(at, k, z, b, floor, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> Pair (for messages).
      integer, intent(in) :: k
      !> Elevation above the base (m), > 0.
      real(dp), intent(in) :: z
      !> The building.
      type(building_config), intent(in) :: b
      !> The floor at z, or 0 between floors.
      integer, intent(out) :: floor
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: what
      real(dp) :: zf
      integer :: j

      what = 'elevations('//str(k)//') = '//str(z)//' m'
      floor = 0
      zf = 0.0_dp
      do j = 1, b%n_storeys
         zf = zf + b%height(j)
         if (abs(zf - z) <= elevation_tol) then
            floor = j
            return
         end if
         if (zf > z) exit
      end do
      if (z > zf) then
         call fail(at, 'elevations', what//' is above the roof of building '//b%name//' ('//str(zf)// &
                   ' m); every pair needs a point of both buildings', error)
      else if (is_plan(b)) then
         call fail(at, 'elevations', what//' lies between floors '//str(j - 1)//' ('//str(zf - b%height(j))// &
                   ' m) and '//str(j)//' ('//str(zf)//' m) of building '//b%name//', a building in plan '// &
                   "(DOFs only at its floors): give a floor's elevation", error)
      else if (.not. is_frame(b)) then
         call fail(at, 'elevations', what//' lies between floors '//str(j - 1)//' ('//str(zf - b%height(j))// &
                   ' m) and '//str(j)//' ('//str(zf)//' m) of building '//b%name//', a shear building '// &
                   "(DOFs only at its floors): give a floor's elevation, or model = 'frame' for "//b%name// &
                   ' (its facing column gets a node there)', error)
      end if
   end subroutine point_at

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

      k = given_count(raw)
      if (k == 0) then
         call fail(at, var, var//' is missing (floor of building '//b%name//' in each pair, '// &
                   '1..n_storeys = '//str(b%n_storeys)//'; or give the pairs by elevations, m)', error)
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

end module pound_deck_contact
