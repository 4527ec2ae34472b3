!> Reader of `&plane`: one lateral load-resisting plane (a frame or wall line) of a building in
!> plan (`&building model = 'plan'`), appended to that building's `planes` in deck order.
!>
!>     &plane
!>        building = 'A'            ! a building of the deck with model = 'plan' (groups in any order)
!>        direction = 'x'           ! the direction the plane resists: 'x' or 'y'
!>        position = 0.0            ! m, outline coordinates: y of an 'x' plane, x of a 'y' plane
!>        stiffness = 3*4.0e4       ! kN/m per storey, > 0, n_storeys values
!>        storey_law = 'bilinear'   ! 'elastic' (default) or 'bilinear' with yield_shear(:), hardening_ratio(:)
!>     /
!>
!> A position outside the outline (0..Ly of an 'x' plane, 0..Lx of a 'y' plane) is warned,
!> not refused. The deck's rules over all planes (every building in plan has a plane in each
!> direction, every building is in plan once one is) are `check_plan_deck`'s.
module pound_deck_plane
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_config, only: building_config, deck_warning_len
   use pound_building_spec, only: plane_spec, is_plan
   use pound_deck_contact, only: find_building
   use pound_deck_checks, only: fail, given_count, is_set, read_failed, site, site_of, group_input, take_reals, unset_real, &
                                warn, widen
   use pound_deck_lexer, only: group_extent, group_ref, lower
   use pound_deck_storey_law, only: take_law_values
   use pound_deck_variables, only: word_len
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: plain_real, str
   implicit none
   private

   public :: read_plane, check_plan_deck, deck_yields

contains

   !> Some building of the deck yields: bilinear storeys (`storey_law = 'bilinear'`), plastic
   !> hinges (`hinge_law = 'elastic_plastic'`) or a bilinear plane of a building in plan.
   pure logical function deck_yields(buildings) result(yields)
      !> The deck's buildings (with their planes).
      type(building_config), intent(in) :: buildings(:)
      integer :: ib, p

      yields = any(buildings%storey_law == 'bilinear' .or. buildings%hinge_law == 'elastic_plastic')
      do ib = 1, size(buildings)
         if (.not. allocated(buildings(ib)%planes)) cycle
         do p = 1, size(buildings(ib)%planes)
            if (buildings(ib)%planes(p)%storey_law == 'bilinear') yields = .true.
         end do
      end do
   end function deck_yields

   !> `&plane`: one plane, appended to the `planes` of the building it names.
   subroutine read_plane(path, text, g, buildings, error, warnings)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> The deck's buildings (resolved); the named one gets the plane.
      type(building_config), intent(inout) :: buildings(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> The deck's plausibility warnings, this group's appended.
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)
      character(len=word_len) :: building, direction, storey_law
      real(dp) :: position
      real(dp), allocatable :: stiffness(:), yield_shear(:), hardening_ratio(:)
      character(len=:), allocatable :: buf, name, dir
      character(len=512) :: msg
      type(site) :: at
      type(plane_spec) :: p
      integer :: ios, ib, n, cap
      namelist /plane/ building, direction, position, stiffness, storey_law, yield_shear, hardening_ratio

      cap = group_extent(g)
      allocate (stiffness(cap), yield_shear(cap), hardening_ratio(cap), source=unset_real)
      building = ' '
      direction = ' '
      storey_law = ' '
      position = unset_real
      call group_input(path, text, g, at, buf, msg)
      read (buf, nml=plane, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      call find_building(at, 'building', building, "the building in plan (model = 'plan') whose plane this is", &
                         buildings, ib, error)
      if (allocated(error)) return
      name = trim(adjustl(building))
      at%label = at%label//' ('//buildings(ib)%name//')'
      if (.not. is_plan(buildings(ib))) then
         call fail(at, 'building', "building = '"//name//"' is "//model_text(buildings(ib))// &
                   "; a &plane belongs to a building in plan: give model = 'plan' (with plan_size) on &building #"// &
                   str(ib)//' ('//buildings(ib)%name//')', error)
         return
      end if
      n = buildings(ib)%n_storeys
      p%line = g%line1

      dir = lower(trim(adjustl(direction)))
      select case (dir)
      case ('x', 'y')
         p%direction = dir
      case ('')
         call fail(at, 'direction', "direction is missing: 'x' (the plane resists along x, the row of "// &
                   "buildings) or 'y' (along the facing facades)", error)
         return
      case default
         call fail(at, 'direction', "direction = '"//trim(adjustl(direction))//"', must be 'x' or 'y'", error)
         return
      end select

      call take_position(error)
      if (allocated(error)) return

      if (n > size(stiffness)) then
         call widen(stiffness, n)
         call widen(yield_shear, n)
         call widen(hardening_ratio, n)
      end if
      if (given_count(stiffness) == 0) then
         call fail(at, 'stiffness', "stiffness is missing: the plane's storey stiffness (kN/m, > 0, n_storeys = "// &
                   str(n)//' values of building '//buildings(ib)%name//')', error)
         return
      end if
      call take_reals(at, 'stiffness', stiffness, n, '>', p%stiffness, error)
      if (allocated(error)) return
      call take_law_values(at, storey_law, yield_shear, hardening_ratio, n, "this plane's storeys are elastic", &
                           p%storey_law, p%yield_shear, p%hardening_ratio, error, .true.)
      if (allocated(error)) return
      call append_plane(buildings(ib)%planes, p)

   contains

      !> `position` (required, finite, m): outside the outline a warning.
      subroutine take_position(error)
         type(error_type), allocatable, intent(out) :: error
         character(len=:), allocatable :: what
         real(dp) :: length

         if (p%direction == 'x') then
            what = "y of an 'x' plane, 0..Ly"
            length = buildings(ib)%plan_size(2)
         else
            what = "x of a 'y' plane, 0..Lx"
            length = buildings(ib)%plan_size(1)
         end if
         if (.not. is_set(position)) then
            call fail(at, 'position', 'position is missing (m, outline coordinates: '//what//' = '// &
                      plain_real(length)//' m of building '//buildings(ib)%name//')', error)
            return
         end if
         if (.not. ieee_is_finite(position)) then
            call fail(at, 'position', 'position = '//str(position)//', must be a finite number', error)
            return
         end if
         p%position = position
         if (position < 0.0_dp .or. position > length) then
            call warn(at, 'position', 'position = '//plain_real(position)//' m lies outside the outline of '// &
                      buildings(ib)%name//' ('//what//' = '//plain_real(length)//' m): positions are in the '// &
                      "outline's coordinates (0 at its edge, not the site's); a plane outside the building is "// &
                      'unusual: check the value', warnings)
         end if
      end subroutine take_position

   end subroutine read_plane

   !> The rules over the whole deck: once a building is in plan every building is, and each
   !> building in plan has at least one plane in each direction. `groups` are the deck's
   !> groups (the `&building` ones name the messages' lines).
   pure subroutine check_plan_deck(path, groups, buildings, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> The deck's groups, in deck order.
      type(group_ref), intent(in) :: groups(:)
      !> The deck's buildings, their planes appended.
      type(building_config), intent(in) :: buildings(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(site) :: at
      integer :: i, k, first, nx, ny

      first = 0
      do k = 1, size(buildings)
         if (is_plan(buildings(k))) then
            first = k
            exit
         end if
      end do
      if (first == 0) return
      k = 0
      do i = 1, size(groups)
         if (groups(i)%name /= 'building') cycle
         k = k + 1
         at = site_of(path, groups(i))
         at%label = at%label//' ('//buildings(k)%name//')'
         if (.not. is_plan(buildings(k))) then
            call fail(at, 'model', 'this building is '//model_text(buildings(k))//', and '// &
                      buildings(first)%name//" (&building #"//str(first)//") is a building in plan: in a deck "// &
                      "with a building in plan every building is one; give model = 'plan', plan_size and its "// &
                      '&plane groups', error)
            return
         end if
         nx = 0
         ny = 0
         if (allocated(buildings(k)%planes)) then
            nx = count(buildings(k)%planes%direction == 'x')
            ny = count(buildings(k)%planes%direction == 'y')
         end if
         if (nx == 0 .or. ny == 0) then
            call fail(at, 'model', "model = 'plan' needs at least one &plane in each direction; "// &
                      buildings(k)%name//' has '//planes_text(nx, 'x')//' and '//planes_text(ny, 'y')// &
                      ": add &plane building = '"//buildings(k)%name//"', direction = '"// &
                      trim(merge('x', 'y', nx == 0))//"', position, stiffness", error)
            return
         end if
      end do
   end subroutine check_plan_deck

   !> 'no 'x' plane', '1 'x' plane', '3 'x' planes'.
   pure function planes_text(n, d) result(s)
      integer, intent(in) :: n
      character(len=*), intent(in) :: d
      character(len=:), allocatable :: s

      if (n == 0) then
         s = "no '"//d//"' plane"
      else if (n == 1) then
         s = "1 '"//d//"' plane"
      else
         s = str(n)//" '"//d//"' planes"
      end if
   end function planes_text

   !> 'a shear building (model = 'shear')' or 'a frame (model = 'frame')'.
   pure function model_text(b) result(s)
      type(building_config), intent(in) :: b
      character(len=:), allocatable :: s

      s = "a shear building (model = 'shear')"
      if (allocated(b%model)) then
         if (b%model == 'frame') s = "a frame (model = 'frame')"
      end if
   end function model_text

   !> Append plane `p` to `planes` (unallocated: none yet).
   pure subroutine append_plane(planes, p)
      type(plane_spec), allocatable, intent(inout) :: planes(:)
      type(plane_spec), intent(in) :: p
      type(plane_spec), allocatable :: grown(:)
      integer :: n

      n = 0
      if (allocated(planes)) n = size(planes)
      allocate (grown(n + 1))
      if (n > 0) grown(1:n) = planes
      grown(n + 1) = p
      call move_alloc(grown, planes)
   end subroutine append_plane

end module pound_deck_plane
