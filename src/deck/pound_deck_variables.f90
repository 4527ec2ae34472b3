!> The deck's groups and variables, in ONE table: name, type and size of every variable of
!> every group (the joint laws' `&contact` variables generated from the law registry, where
!> each law declares its own), and the limits they are checked against. The lexer checks every assignment
!> against it (known variable, type, subscript range, duplicates), messages list a group's
!> variables from it, and each group's reader declares its `namelist` with these names (the
!> test `test_deck_cases: test_namelists_match_the_table` reads every group with every
!> variable of the table, so a name missing from a `namelist` statement fails there).
module pound_deck_variables
   use pound_envelope_rules, only: max_law_points, max_segments
   use pound_joint_law, only: law_variable
   use pound_law_registry, only: law_variables
   implicit none
   private

   public :: var_spec, variables, known_groups, known_variable, variable_index, variable_type, &
             variable_list, group_variable_count, findloc_name, join
   public :: max_storeys, max_name_length, max_pairs, max_columns, max_steps, title_len, path_len, &
             word_len, max_substeps, max_envelope_points, max_segments, max_bays, max_column_elements, &
             frame_variables, plan_variables, max_risk_points

   !> Largest number of storeys a `&building` may have.
   integer, parameter :: max_storeys = 20000
   !> Longest building name (it is used as an HDF5 group name).
   integer, parameter :: max_name_length = 64
   !> Largest number of bays of a frame (`&building model = 'frame'`).
   integer, parameter :: max_bays = 1000
   !> Largest number of elements per storey column of a frame.
   integer, parameter :: max_column_elements = 100
   !> The `&building` variables that describe a building in plan (only with model = 'plan').
   character(len=*), parameter :: plan_variables(4) = [character(len=13) :: 'plan_size', 'plan_origin_y', &
      'mass_centre', 'rot_inertia']
   !> The `&building` variables that describe a frame (only with model = 'frame').
   character(len=*), parameter :: frame_variables(14) = [character(len=15) :: 'n_bays', 'bay_width', &
      'column_e', 'column_area', 'column_inertia', 'beam_e', 'beam_area', 'beam_inertia', 'base', &
      'column_elements', 'rigid_beams', 'rigid_diaphragm', 'rigid_columns', 'geometric']
   !> Largest number of floor pairs in one `&contact`.
   integer, parameter :: max_pairs = 1000
   !> Largest number of columns in one storey.
   integer, parameter :: max_columns = 100000
   !> Largest number of time steps t_end/dt.
   integer, parameter :: max_steps = 1000000000
   !> Largest number of substeps per impact step (`&analysis impact_substeps`).
   integer, parameter :: max_substeps = 1000
   !> Lengths of the character buffers the namelist reads into.
   integer, parameter :: title_len = 1024, path_len = 4096, word_len = 256
   !> Largest number of envelope points of a `piecewise` law (the contact law's own limit).
   integer, parameter :: max_envelope_points = max_law_points
   !> Largest number of stripe levels of `&stripes` and of points of the `&hazard` curve.
   integer, parameter :: max_risk_points = 1000

   !> The groups a deck may hold.
   character(len=*), parameter :: known_groups(8) = &
      [character(len=8) :: 'analysis', 'ground', 'building', 'contact', 'sweep', 'stripes', 'hazard', 'plane']

   !> One variable of one group.
   type :: var_spec
      !> Group name.
      character(len=8) :: group
      !> Variable name (lower case).
      character(len=20) :: name
      !> Type: 'r' real, 'i' integer, 'l' logical, 'c' character.
      character :: vtype
      !> Number of elements, 0 for a scalar.
      integer :: vsize
   end type var_spec

   !> Where the table holds the variables of the joint laws (`&contact`), generated from the
   !> law registry (`law_variables`, pound_law_registry: each law declares its own).
   character(len=*), parameter :: laws_marker = '*laws*'

   !> Every variable of every group that is not a joint law's, in the order the messages list
   !> them (`variables` inserts the laws' at `laws_marker`).
   type(var_spec), parameter :: fixed_variables(133) = [ &
      var_spec('analysis', 'title', 'c', 0), var_spec('analysis', 'dt', 'r', 0), &
      var_spec('analysis', 't_end', 'r', 0), var_spec('analysis', 't_free', 'r', 0), &
      var_spec('analysis', 'output_every', 'i', 0), &
      var_spec('analysis', 'history', 'c', 0), &
      var_spec('ground', 'kind', 'c', 0), var_spec('ground', 'x0', 'r', 0), &
      var_spec('ground', 'a', 'r', 0), var_spec('ground', 'b', 'r', 0), &
      var_spec('ground', 'file', 'c', 0), var_spec('ground', 'format', 'c', 0), &
      var_spec('ground', 'scale', 'r', 0), var_spec('ground', 'name', 'c', 0), &
      var_spec('ground', 'scale_to', 'c', 0), var_spec('ground', 'target', 'r', 0), &
      var_spec('ground', 'period', 'r', 0), var_spec('ground', 'filter', 'c', 0), &
      var_spec('ground', 'ground_frequency', 'r', 0), var_spec('ground', 'ground_damping', 'r', 0), &
      var_spec('ground', 'filter_frequency', 'r', 0), var_spec('ground', 'filter_damping', 'r', 0), &
      var_spec('ground', 'envelope', 'c', 0), var_spec('ground', 'rise_time', 'r', 0), &
      var_spec('ground', 'plateau_end', 'r', 0), var_spec('ground', 'decay_rate', 'r', 0), &
      var_spec('ground', 'peak_fraction', 'r', 0), var_spec('ground', 'end_level', 'r', 0), &
      var_spec('ground', 'duration', 'r', 0), var_spec('ground', 'pga', 'r', 0), &
      var_spec('ground', 'seed', 'i', 0), &
      var_spec('building', 'name', 'c', 0), var_spec('building', 'n_storeys', 'i', 0), &
      var_spec('building', 'height', 'r', max_storeys), var_spec('building', 'mass', 'r', max_storeys), &
      var_spec('building', 'load_coeff', 'r', max_storeys), var_spec('building', 'ref_floor_load', 'r', 0), &
      var_spec('building', 'stiffness', 'r', max_storeys), var_spec('building', 'n_columns', 'i', max_storeys), &
      var_spec('building', 'e_modulus', 'r', max_storeys), var_spec('building', 'inertia', 'r', max_storeys), &
      var_spec('building', 'column_ends', 'c', 0), var_spec('building', 'damping_ratio', 'r', 0), &
      var_spec('building', 'damping_modes', 'i', 2), var_spec('building', 'p_delta', 'l', 0), &
      var_spec('building', 'gravity_load', 'r', max_storeys), &
      var_spec('building', 'model', 'c', 0), var_spec('building', 'n_bays', 'i', 0), &
      var_spec('building', 'bay_width', 'r', max_bays), var_spec('building', 'column_e', 'r', max_storeys), &
      var_spec('building', 'column_area', 'r', max_storeys), &
      var_spec('building', 'column_inertia', 'r', max_storeys), &
      var_spec('building', 'beam_e', 'r', max_storeys), var_spec('building', 'beam_area', 'r', max_storeys), &
      var_spec('building', 'beam_inertia', 'r', max_storeys), var_spec('building', 'base', 'c', 0), &
      var_spec('building', 'column_elements', 'i', 0), var_spec('building', 'rigid_beams', 'l', 0), &
      var_spec('building', 'rigid_diaphragm', 'l', 0), var_spec('building', 'rigid_columns', 'l', 0), &
      var_spec('building', 'geometric', 'c', 0), &
      var_spec('contact', 'left', 'c', 0), var_spec('contact', 'right', 'c', 0), &
      var_spec('contact', 'floors_left', 'i', max_pairs), var_spec('contact', 'floors_right', 'i', max_pairs), &
      var_spec('contact', 'gap', 'r', max_pairs), var_spec('contact', 'law', 'c', 0), &
      var_spec('contact', laws_marker, ' ', 0), &
      var_spec('sweep', 'gap_from', 'r', 0), var_spec('sweep', 'gap_to', 'r', 0), &
      var_spec('sweep', 'n_gaps', 'i', 0), var_spec('sweep', 'target_lambda', 'r', 0), &
      var_spec('sweep', 'target_quantities', 'c', 0), &
      var_spec('analysis', 'stepping', 'c', 0), var_spec('analysis', 'impact_substeps', 'i', 0), &
      var_spec('sweep', 'refine_tolerance', 'r', 0), var_spec('ground', 'histories', 'l', 0), &
      var_spec('analysis', 'compress', 'l', 0), &
      var_spec('contact', 'elevations', 'r', max_pairs), &
      var_spec('analysis', 'node_histories', 'l', 0), &
      var_spec('analysis', 'lcp_solver', 'c', 0), var_spec('analysis', 'free_steps', 'c', 0), &
      var_spec('building', 'cd', 'r', 0), var_spec('building', 'importance', 'r', 0), &
      var_spec('building', 'behaviour_factor', 'r', 0), var_spec('building', 'response_reduction', 'r', 0), &
      var_spec('ground', 'target_g', 'r', 0), &
      var_spec('sweep', 'parameter', 'c', 0), var_spec('sweep', 'values', 'r', 10000), &
      var_spec('sweep', 'value_from', 'r', 0), var_spec('sweep', 'value_to', 'r', 0), &
      var_spec('sweep', 'n_values', 'i', 0), var_spec('sweep', 'spacing', 'c', 0), &
      var_spec('contact', 'variant', 'c', 0), &
      var_spec('analysis', 'integrator', 'c', 0), var_spec('analysis', 'hht_alpha', 'r', 0), &
      var_spec('building', 'storey_law', 'c', 0), var_spec('building', 'yield_shear', 'r', max_storeys), &
      var_spec('building', 'hardening_ratio', 'r', max_storeys), var_spec('analysis', 'collapse_drift', 'r', 0), &
      var_spec('building', 'hinge_law', 'c', 0), var_spec('building', 'column_yield_moment', 'r', max_storeys), &
      var_spec('building', 'beam_yield_moment', 'r', max_storeys), &
      var_spec('building', 'hinge_hardening', 'r', max_storeys), &
      var_spec('ground', 'folder', 'c', 0), var_spec('ground', 'pattern', 'c', 0), &
      var_spec('stripes', 'measure', 'c', 0), var_spec('stripes', 'period', 'r', 0), &
      var_spec('stripes', 'levels', 'r', max_risk_points), var_spec('stripes', 'levels_g', 'r', max_risk_points), &
      var_spec('stripes', 'target_lambda', 'r', 0), var_spec('stripes', 'target_quantities', 'c', 0), &
      var_spec('hazard', 'im', 'r', max_risk_points), var_spec('hazard', 'im_g', 'r', max_risk_points), &
      var_spec('hazard', 'rate', 'r', max_risk_points), var_spec('hazard', 'years', 'r', 0), &
      var_spec('hazard', 'target_probability', 'r', 0), &
      var_spec('building', 'plan_size', 'r', 2), var_spec('building', 'plan_origin_y', 'r', 0), &
      var_spec('building', 'mass_centre', 'r', 2), var_spec('building', 'rot_inertia', 'r', max_storeys), &
      var_spec('plane', 'building', 'c', 0), var_spec('plane', 'direction', 'c', 0), &
      var_spec('plane', 'position', 'r', 0), var_spec('plane', 'stiffness', 'r', max_storeys), &
      var_spec('plane', 'storey_law', 'c', 0), var_spec('plane', 'yield_shear', 'r', max_storeys), &
      var_spec('plane', 'hardening_ratio', 'r', max_storeys), &
      var_spec('contact', 'friction', 'r', 0), var_spec('contact', 'shear_stiffness', 'r', 0), &
      var_spec('ground', 'angle', 'r', 0), var_spec('ground', 'file_2', 'c', 0), var_spec('ground', 'scale_2', 'r', 0)]

contains

   !> Every variable of every group, in the order the messages list them: `fixed_variables`
   !> with the joint laws' `&contact` variables (pound_law_registry) in place of `laws_marker`.
   pure function variables() result(table)
      type(var_spec), allocatable :: table(:)
      type(law_variable), allocatable :: laws(:)
      integer :: i, k, m

      laws = law_variables()
      allocate (table(size(fixed_variables) - 1 + size(laws)))
      k = 0
      do i = 1, size(fixed_variables)
         if (fixed_variables(i)%name == laws_marker) then
            do m = 1, size(laws)
               table(k + m) = var_spec('contact', laws(m)%name, laws(m)%vtype, laws(m)%vsize)
            end do
            k = k + size(laws)
         else
            k = k + 1
            table(k) = fixed_variables(i)
         end if
      end do
   end function variables

   !> Whether `name` is a variable of group `group` (the fixed table first: the lexer asks
   !> this of every assignment; the laws' variables only for `&contact`).
   pure logical function known_variable(group, name)
      !> Group name and variable name, lower case.
      character(len=*), intent(in) :: group, name
      character :: vtype
      integer :: vsize

      call lookup(group, name, vtype, vsize, known_variable)
   end function known_variable

   !> Type and size of variable `name` of `group`, and whether it is one: the fixed table,
   !> then for `&contact` the joint laws' variables (pound_law_registry).
   pure subroutine lookup(group, name, vtype, vsize, found)
      character(len=*), intent(in) :: group, name
      character, intent(out) :: vtype
      integer, intent(out) :: vsize
      logical, intent(out) :: found
      type(law_variable), allocatable :: laws(:)
      integer :: i

      vtype = 'r'
      vsize = 0
      found = .false.
      do i = 1, size(fixed_variables)
         if (fixed_variables(i)%group == group .and. fixed_variables(i)%name == name) then
            vtype = fixed_variables(i)%vtype
            vsize = fixed_variables(i)%vsize
            found = name /= laws_marker
            return
         end if
      end do
      if (group /= 'contact') return
      laws = law_variables()
      do i = 1, size(laws)
         if (laws(i)%name == name) then
            vtype = laws(i)%vtype
            vsize = laws(i)%vsize
            found = .true.
            return
         end if
      end do
   end subroutine lookup

   !> Position of variable `name` among the variables of group `group` (0: not one of them).
   pure integer function variable_index(group, name) result(k)
      !> Group name and variable name, lower case.
      character(len=*), intent(in) :: group, name
      type(var_spec), allocatable :: table(:)
      integer :: i

      table = variables()
      k = 0
      do i = 1, size(table)
         if (table(i)%group /= group) cycle
         k = k + 1
         if (table(i)%name == name) return
      end do
      k = 0
   end function variable_index

   !> Type ('r', 'i', 'l', 'c') and number of elements (0: scalar) of variable `name` of
   !> group `group` (a real scalar when it is not in the table).
   pure subroutine variable_type(group, name, vtype, vsize)
      !> Group name and variable name, lower case.
      character(len=*), intent(in) :: group, name
      !> Type letter.
      character, intent(out) :: vtype
      !> Number of elements, 0 for a scalar.
      integer, intent(out) :: vsize
      logical :: found

      call lookup(group, name, vtype, vsize, found)
   end subroutine variable_type

   !> The variables of `group`, comma separated.
   pure function variable_list(group) result(list)
      !> Group name, lower case.
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: list
      type(var_spec), allocatable :: table(:)

      table = variables()
      if (count(table%group == group) == 0) then
         list = ''
      else
         list = join(pack(table%name, table%group == group))
      end if
   end function variable_list

   !> Number of variables of `group`.
   pure integer function group_variable_count(group) result(n)
      !> Group name, lower case.
      character(len=*), intent(in) :: group

      type(var_spec), allocatable :: table(:)

      table = variables()
      n = count(table%group == group)
   end function group_variable_count

   !> Position of `word` in `names` (0 if absent).
   pure integer function findloc_name(names, word) result(k)
      !> Names to search, word to find.
      character(len=*), intent(in) :: names(:), word

      do k = 1, size(names)
         if (names(k) == word) return
      end do
      k = 0
   end function findloc_name

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

end module pound_deck_variables
