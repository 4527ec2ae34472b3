!> Reader of `&building`: name, storeys, heights, masses (or load coefficients), storey
!> stiffnesses (or columns), damping and P-Delta, kept as given (the model derives the
!> masses, stiffnesses and gravity loads: pound_storey_properties).
module pound_deck_building
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_config, only: building_config
   use pound_deck_checks, only: check_real, fail, given_count, is_set, read_failed, require_real, &
                                site, site_of, take_ints, take_reals, unset_int, unset_real
   use pound_deck_lexer, only: group_ref, group_text, is_name_char, lower
   use pound_deck_variables, only: max_name_length, max_storeys, word_len
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: read_building

contains

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

end module pound_deck_building
