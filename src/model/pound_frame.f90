!> Planar frame of column lines and floors: geometry, node and DOF numbering, exact
!> constraints (eliminated DOFs) and assembly of K, G and the lumped M in band storage.
!>
!> Column lines 1..n_lines stand at x = 0, bay(1), bay(1)+bay(2), ...; floor j at
!> z_j = height(1) + ... + height(j); the base (level 0) is fixed or pinned per column line.
!> Each storey's column is divided into `n_sub` equal elements; `extra_z_first` and
!> `extra_z_last` add nodes on the first (leftmost) and the last (rightmost) column line at
!> given elevations (contact points), splitting only that column there. Beams join the
!> floor nodes of neighbouring column lines.
!>
!> Nodes are numbered level by level from the base up (nodes of one elevation left to
!> right), so the half-bandwidth stays about 3 (n_lines + 1). Reduced DOFs are numbered in
!> node order as they first appear.
!>
!> Constraints (each optional) are imposed exactly by a master-slave map: every physical node
!> DOF is a combination of at most two reduced DOFs (or zero), and element matrices are
!> transformed element by element during assembly (no dense n x n matrix):
!> - `rigid_diaphragm`: u of every node of floor j = u_j (one lateral DOF per floor);
!> - `rigid_columns` (axially rigid columns): the vertical DOFs of all nodes are zero (the
!>   bases are restrained vertically);
!> - `rigid_beams` (flexurally rigid beams, n_lines >= 2): floor j moves as a rigid body in
!>   the vertical plane, w_i = w_j + theta_j (x_i - x_1), theta_i = theta_j (beam axial
!>   deformation stays free unless the diaphragm is rigid too); with `rigid_columns` as
!>   well, w_j = theta_j = 0: the floor's rotations vanish.
!> With all three, the reduced DOFs of a frame without subdivisions are the floors' lateral
!> displacements and K is the shear building's with storey stiffness sum(12 E I / h^3).
!>
!> Mass is lumped at the floor nodes (tonnes), the same in u and w, split by tributary width
!> (half of each adjacent bay) unless given per node; no rotary inertia unless given.
module pound_frame
   use pound_kinds, only: dp
   use pound_constants, only: g_accel
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_frame_element, only: beam_global_stiffness, beam_global_geometric
   implicit none
   private

   public :: frame_spec, frame_model, build_frame, frame_stiffness, frame_mass, frame_geometric
   public :: frame_load_vector, frame_node_displacements, frame_node_at
   public :: element_column, element_beam

   !> Element kinds.
   integer, parameter :: element_column = 1, element_beam = 2
   !> Elevations closer than this are the same node (m).
   real(dp), parameter :: z_tol = 1.0e-6_dp

   !> What defines a frame (the future deck entry).
   type :: frame_spec
      !> Building name (for messages).
      character(len=:), allocatable :: name
      !> Bay widths (m), n_lines - 1 values (none: a single column line).
      real(dp), allocatable :: bay(:)
      !> Storey heights (m), n_storeys values, storey 1 at the bottom.
      real(dp), allocatable :: height(:)
      !> Columns: E (kPa), A (m^2), I (m^4), one value for all or one per storey.
      real(dp), allocatable :: col_e(:), col_a(:), col_i(:)
      !> Beams: E (kPa), A (m^2), I (m^4), one value for all or one per floor.
      real(dp), allocatable :: beam_e(:), beam_a(:), beam_i(:)
      !> Pinned base per column line (one value for all or n_lines); unallocated: fixed.
      logical, allocatable :: base_pinned(:)
      !> Elements per storey column (>= 1).
      integer :: n_sub = 1
      !> Extra node elevations (m) on the first and on the last column line.
      real(dp), allocatable :: extra_z_first(:), extra_z_last(:)
      !> Floor masses (t), n_storeys values.
      real(dp), allocatable :: floor_mass(:)
      !> Optional: mass per floor node (t), shape (n_lines, n_storeys); replaces floor_mass.
      real(dp), allocatable :: node_mass(:, :)
      !> Optional: rotary inertia per floor node (t m^2), shape (n_lines, n_storeys).
      real(dp), allocatable :: node_rotary(:, :)
      !> Optional: floor gravity loads (kN); default floor mass x g (`pound_constants::g_accel`), split like the mass.
      real(dp), allocatable :: floor_load(:)
      !> Optional: gravity load per floor node (kN), shape (n_lines, n_storeys).
      real(dp), allocatable :: node_load(:, :)
      !> Exact constraints.
      logical :: rigid_beams = .false., rigid_diaphragm = .false., rigid_columns = .false.
   end type frame_spec

   !> A built frame: nodes, elements, DOF map, masses and loads.
   type :: frame_model
      character(len=:), allocatable :: name
      integer :: n_lines = 0, n_storeys = 0, n_nodes = 0, n_elements = 0
      !> Number of reduced DOFs and half-bandwidth of K, G and M.
      integer :: n_dof = 0, kd = 0
      !> Elevation of floor j (m), j = 0 (base) .. n_storeys; x of column line i (m).
      real(dp), allocatable :: floor_z(:), line_x(:)
      !> Node coordinates (m), column line, floor (0: base or between floors; -1 for base).
      real(dp), allocatable :: node_x(:), node_z(:)
      integer, allocatable :: node_line(:), node_floor(:)
      !> Node of column line i at floor j (j = 0: base), shape (n_lines, 0:n_storeys).
      integer, allocatable :: floor_node(:, :)
      !> Element end nodes (2, n_elements), kind (column/beam), group (storey/floor).
      integer, allocatable :: element_nodes(:, :), element_kind(:), element_group(:)
      !> Element properties: E (kPa), A (m^2), I (m^4).
      real(dp), allocatable :: element_e(:), element_a(:), element_i(:)
      !> Master-slave map: physical DOF c of node k = sum_t map_coef(t, c, k) q(map_dof(t, c, k))
      !> (map_dof = 0: no term). Shape (2, 3, n_nodes).
      integer, allocatable :: map_dof(:, :, :)
      real(dp), allocatable :: map_coef(:, :, :)
      !> Lumped translational mass (t), rotary inertia (t m^2), gravity load (kN, downwards) per node.
      real(dp), allocatable :: node_mass(:), node_rotary(:), node_load(:)
   end type frame_model

contains

   !> Build the frame described by `spec`.
   pure subroutine build_frame(spec, f, error)
      !> Description.
      type(frame_spec), intent(in) :: spec
      !> The frame.
      type(frame_model), intent(out) :: f
      !> Set if the description breaks a rule (one message: building, variable, rule).
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: trib(:), zl(:), levels(:), ez1(:), ez2(:)
      integer, allocatable :: last(:)
      integer :: nl, ns, j, i, k, m, nmax, emax

      call check_spec(spec, error)
      if (allocated(error)) return
      f%name = '(unnamed)'
      if (allocated(spec%name)) f%name = spec%name
      ez1 = [real(dp) ::]
      ez2 = [real(dp) ::]
      if (allocated(spec%extra_z_first)) ez1 = spec%extra_z_first
      if (allocated(spec%extra_z_last)) ez2 = spec%extra_z_last
      nl = size(spec%bay) + 1
      ns = size(spec%height)
      f%n_lines = nl
      f%n_storeys = ns
      allocate (f%floor_z(0:ns), f%line_x(nl), f%floor_node(nl, 0:ns), last(nl))
      f%floor_z(0) = 0.0_dp
      do j = 1, ns
         f%floor_z(j) = f%floor_z(j - 1) + spec%height(j)
      end do
      f%line_x(1) = 0.0_dp
      do i = 2, nl
         f%line_x(i) = f%line_x(i - 1) + spec%bay(i - 1)
      end do
      nmax = nl*(ns*spec%n_sub + 1) + size(ez1) + size(ez2)
      emax = nmax + nl*ns
      allocate (f%node_x(nmax), f%node_z(nmax), f%node_line(nmax), f%node_floor(nmax))
      allocate (f%element_nodes(2, emax), f%element_kind(emax), f%element_group(emax))
      do i = 1, nl
         call add_node(f, i, 0.0_dp, -1)
         f%floor_node(i, 0) = f%n_nodes
         last(i) = f%n_nodes
      end do
      do j = 1, ns
         ! Interior levels of storey j: subdivisions on every line, extra nodes on the facing lines.
         levels = [(f%floor_z(j - 1) + spec%height(j)*real(k, dp)/real(spec%n_sub, dp), k=1, spec%n_sub - 1)]
         levels = [levels, pack(ez1, inside(ez1)), &
                   pack(ez2, inside(ez2))]
         levels = sorted_unique(levels)
         do k = 1, size(levels)
            do i = 1, nl
               zl = [(f%floor_z(j - 1) + spec%height(j)*real(m, dp)/real(spec%n_sub, dp), m=1, spec%n_sub - 1)]
               if (i == 1) zl = [zl, ez1]
               if (i == nl) zl = [zl, ez2]
               if (.not. any(abs(zl - levels(k)) <= z_tol)) cycle
               call add_node(f, i, levels(k), 0)
               call add_element(f, last(i), f%n_nodes, element_column, j)
               last(i) = f%n_nodes
            end do
         end do
         do i = 1, nl
            call add_node(f, i, f%floor_z(j), j)
            f%floor_node(i, j) = f%n_nodes
            call add_element(f, last(i), f%n_nodes, element_column, j)
            last(i) = f%n_nodes
         end do
         do i = 1, nl - 1
            call add_element(f, f%floor_node(i, j), f%floor_node(i + 1, j), element_beam, j)
         end do
      end do
      f%node_x = f%node_x(1:f%n_nodes)
      f%node_z = f%node_z(1:f%n_nodes)
      f%node_line = f%node_line(1:f%n_nodes)
      f%node_floor = f%node_floor(1:f%n_nodes)
      f%element_nodes = f%element_nodes(:, 1:f%n_elements)
      f%element_kind = f%element_kind(1:f%n_elements)
      f%element_group = f%element_group(1:f%n_elements)
      allocate (f%element_e(f%n_elements), f%element_a(f%n_elements), f%element_i(f%n_elements))
      do k = 1, f%n_elements
         j = f%element_group(k)
         if (f%element_kind(k) == element_column) then
            f%element_e(k) = spec%col_e(min(j, size(spec%col_e)))
            f%element_a(k) = spec%col_a(min(j, size(spec%col_a)))
            f%element_i(k) = spec%col_i(min(j, size(spec%col_i)))
         else
            f%element_e(k) = spec%beam_e(min(j, size(spec%beam_e)))
            f%element_a(k) = spec%beam_a(min(j, size(spec%beam_a)))
            f%element_i(k) = spec%beam_i(min(j, size(spec%beam_i)))
         end if
      end do

      ! Masses, rotary inertias and gravity loads at the floor nodes.
      allocate (trib(nl))
      trib = 1.0_dp
      if (nl > 1) then
         trib = 0.0_dp
         trib(1:nl - 1) = trib(1:nl - 1) + 0.5_dp*spec%bay
         trib(2:nl) = trib(2:nl) + 0.5_dp*spec%bay
         trib = trib/sum(spec%bay)
      end if
      allocate (f%node_mass(f%n_nodes), f%node_rotary(f%n_nodes), f%node_load(f%n_nodes))
      f%node_mass = 0.0_dp
      f%node_rotary = 0.0_dp
      f%node_load = 0.0_dp
      do j = 1, ns
         do i = 1, nl
            k = f%floor_node(i, j)
            if (allocated(spec%node_mass)) then
               f%node_mass(k) = spec%node_mass(i, j)
            else
               f%node_mass(k) = spec%floor_mass(j)*trib(i)
            end if
            if (allocated(spec%node_rotary)) f%node_rotary(k) = spec%node_rotary(i, j)
            if (allocated(spec%node_load)) then
               f%node_load(k) = spec%node_load(i, j)
            else if (allocated(spec%floor_load)) then
               if (allocated(spec%node_mass)) then
                  f%node_load(k) = spec%floor_load(j)*spec%node_mass(i, j)/sum(spec%node_mass(:, j))
               else
                  f%node_load(k) = spec%floor_load(j)*trib(i)
               end if
            else
               f%node_load(k) = g_accel*f%node_mass(k)
            end if
         end do
      end do
      call number_dofs(spec, f)

   contains

      !> Elevations strictly inside storey j (not at its floors).
      pure elemental logical function inside(z)
         real(dp), intent(in) :: z
         inside = z > f%floor_z(j - 1) + z_tol .and. z < f%floor_z(j) - z_tol
      end function inside

   end subroutine build_frame

   !> Check the description: sizes and signs, one message naming the rule.
   pure subroutine check_spec(spec, error)
      type(frame_spec), intent(in) :: spec
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: who
      integer :: ns, nl, j

      who = 'frame'
      if (allocated(spec%name)) who = 'frame '//spec%name
      if (.not. allocated(spec%height) .or. .not. allocated(spec%bay) .or. .not. allocated(spec%floor_mass)) then
         call fatal_error(error, who//': bay, height and floor_mass are required')
         return
      end if
      ns = size(spec%height)
      nl = size(spec%bay) + 1
      if (ns < 1) then
         call fatal_error(error, who//': height has no values, needs at least one storey')
         return
      end if
      do j = 1, ns
         if (.not. (spec%height(j) > 0.0_dp)) then
            call fatal_error(error, who//': height('//str(j)//') = '//str(spec%height(j))//', must be > 0')
            return
         end if
      end do
      do j = 1, nl - 1
         if (.not. (spec%bay(j) > 0.0_dp)) then
            call fatal_error(error, who//': bay('//str(j)//') = '//str(spec%bay(j))//', must be > 0')
            return
         end if
      end do
      call check_group(spec%col_e, 'col_e', error)
      if (.not. allocated(error)) call check_group(spec%col_a, 'col_a', error)
      if (.not. allocated(error)) call check_group(spec%col_i, 'col_i', error)
      if (.not. allocated(error) .and. nl > 1) call check_group(spec%beam_e, 'beam_e', error)
      if (.not. allocated(error) .and. nl > 1) call check_group(spec%beam_a, 'beam_a', error)
      if (.not. allocated(error) .and. nl > 1) call check_group(spec%beam_i, 'beam_i', error)
      if (allocated(error)) return
      if (spec%n_sub < 1) then
         call fatal_error(error, who//': n_sub = '//str(spec%n_sub)//', must be >= 1')
         return
      end if
      if (allocated(spec%base_pinned)) then
         if (size(spec%base_pinned) /= 1 .and. size(spec%base_pinned) /= nl) then
            call fatal_error(error, who//': base_pinned has '//str(size(spec%base_pinned))// &
                             ' values, needs 1 or n_lines = '//str(nl))
            return
         end if
      end if
      call check_extra(spec%extra_z_first, 'extra_z_first', error)
      if (.not. allocated(error)) call check_extra(spec%extra_z_last, 'extra_z_last', error)
      if (allocated(error)) return
      if (size(spec%floor_mass) /= ns) then
         call fatal_error(error, who//': floor_mass has '//str(size(spec%floor_mass))// &
                          ' values, needs n_storeys = '//str(ns))
         return
      end if
      if (any(spec%floor_mass < 0.0_dp)) then
         call fatal_error(error, who//': floor_mass('//str(minloc(spec%floor_mass, 1))//') = '// &
                          str(minval(spec%floor_mass))//', must be >= 0')
         return
      end if
      call check_nodal(spec%node_mass, 'node_mass', error)
      if (.not. allocated(error)) call check_nodal(spec%node_rotary, 'node_rotary', error)
      if (.not. allocated(error)) call check_nodal(spec%node_load, 'node_load', error)
      if (allocated(error)) return
      if (allocated(spec%floor_load)) then
         if (size(spec%floor_load) /= ns) then
            call fatal_error(error, who//': floor_load has '//str(size(spec%floor_load))// &
                             ' values, needs n_storeys = '//str(ns))
            return
         end if
      end if
      if (allocated(spec%node_mass) .and. allocated(spec%floor_load) .and. .not. allocated(spec%node_load)) then
         do j = 1, ns
            if (sum(spec%node_mass(:, j)) == 0.0_dp .and. spec%floor_load(j) /= 0.0_dp) then
               call fatal_error(error, who//': floor_load('//str(j)//') = '//str(spec%floor_load(j))// &
                                ' on a floor without mass, give node_load instead')
               return
            end if
         end do
      end if

   contains

      pure subroutine check_group(v, name, error)
         real(dp), allocatable, intent(in) :: v(:)
         character(len=*), intent(in) :: name
         type(error_type), allocatable, intent(out) :: error
         integer :: k

         if (.not. allocated(v)) then
            call fatal_error(error, who//': '//name//' is required')
            return
         end if
         if (size(v) /= 1 .and. size(v) /= ns) then
            call fatal_error(error, who//': '//name//' has '//str(size(v))//' values, needs 1 or n_storeys = '//str(ns))
            return
         end if
         k = findloc(v > 0.0_dp, .false., 1)
         if (k > 0) call fatal_error(error, who//': '//name//'('//str(k)//') = '//str(v(k))//', must be > 0')
      end subroutine check_group

      pure subroutine check_extra(v, name, error)
         real(dp), allocatable, intent(in) :: v(:)
         character(len=*), intent(in) :: name
         type(error_type), allocatable, intent(out) :: error
         integer :: k

         if (.not. allocated(v)) return
         k = findloc(v > 0.0_dp .and. v <= sum(spec%height) + z_tol, .false., 1)
         if (k > 0) call fatal_error(error, who//': '//name//'('//str(k)//') = '//str(v(k))// &
                                     ' m, must be above the base and not above the roof ('// &
                                     str(sum(spec%height))//' m)')
      end subroutine check_extra

      pure subroutine check_nodal(v, name, error)
         real(dp), allocatable, intent(in) :: v(:, :)
         character(len=*), intent(in) :: name
         type(error_type), allocatable, intent(out) :: error

         if (.not. allocated(v)) return
         if (size(v, 1) /= nl .or. size(v, 2) /= ns) then
            call fatal_error(error, who//': '//name//' has shape ('//str(size(v, 1))//', '//str(size(v, 2))// &
                             '), needs (n_lines, n_storeys) = ('//str(nl)//', '//str(ns)//')')
         else if (any(v < 0.0_dp)) then
            call fatal_error(error, who//': '//name//' has a value '//str(minval(v))//', must be >= 0')
         end if
      end subroutine check_nodal

   end subroutine check_spec

   !> Append a node on column line `line` at elevation `z` (floor: j, 0 between floors, -1 base).
   pure subroutine add_node(f, line, z, floor)
      type(frame_model), intent(inout) :: f
      integer, intent(in) :: line, floor
      real(dp), intent(in) :: z

      f%n_nodes = f%n_nodes + 1
      f%node_x(f%n_nodes) = f%line_x(line)
      f%node_z(f%n_nodes) = z
      f%node_line(f%n_nodes) = line
      f%node_floor(f%n_nodes) = floor
   end subroutine add_node

   !> Append an element from node n1 to node n2.
   pure subroutine add_element(f, n1, n2, kind, group)
      type(frame_model), intent(inout) :: f
      integer, intent(in) :: n1, n2, kind, group

      f%n_elements = f%n_elements + 1
      f%element_nodes(:, f%n_elements) = [n1, n2]
      f%element_kind(f%n_elements) = kind
      f%element_group(f%n_elements) = group
   end subroutine add_element

   !> The distinct values of `v` (within z_tol), ascending, by repeated selection (few values).
   pure function sorted_unique(v) result(u)
      real(dp), intent(in) :: v(:)
      real(dp), allocatable :: u(:)
      real(dp) :: z

      allocate (u(0))
      if (size(v) == 0) return
      z = minval(v)
      do
         u = [u, z]
         if (.not. any(v > z + z_tol)) exit
         z = minval(v, v > z + z_tol)
      end do
   end function sorted_unique

   !> Master-slave map and numbering of the reduced DOFs, node by node; half-bandwidth.
   pure subroutine number_dofs(spec, f)
      type(frame_spec), intent(in) :: spec
      type(frame_model), intent(inout) :: f
      integer :: k, nd, line, floor, first, lo, hi, e
      logical :: pinned, rigid_floor

      allocate (f%map_dof(2, 3, f%n_nodes), f%map_coef(2, 3, f%n_nodes))
      f%map_dof = 0
      f%map_coef = 0.0_dp
      nd = 0
      rigid_floor = spec%rigid_beams .and. f%n_lines > 1
      do k = 1, f%n_nodes
         line = f%node_line(k)
         floor = f%node_floor(k)
         if (floor < 0) then
            pinned = .false.
            if (allocated(spec%base_pinned)) pinned = spec%base_pinned(min(line, size(spec%base_pinned)))
            if (pinned) call new_dof(f, nd, k, 3)
            cycle
         end if
         if (floor == 0) then
            call new_dof(f, nd, k, 1)
            if (.not. spec%rigid_columns) call new_dof(f, nd, k, 2)
            call new_dof(f, nd, k, 3)
            cycle
         end if
         first = f%floor_node(1, floor)
         if (spec%rigid_diaphragm .and. line > 1) then
            call slave(f, k, 1, first, 1, 1.0_dp)
         else
            call new_dof(f, nd, k, 1)
         end if
         if (rigid_floor) then
            if (spec%rigid_columns) cycle
            if (line == 1) then
               call new_dof(f, nd, k, 2)
               call new_dof(f, nd, k, 3)
            else
               call slave(f, k, 2, first, 2, 1.0_dp)
               f%map_dof(2, 2, k) = f%map_dof(1, 3, first)
               f%map_coef(2, 2, k) = f%node_x(k) - f%node_x(first)
               call slave(f, k, 3, first, 3, 1.0_dp)
            end if
         else
            if (.not. spec%rigid_columns) call new_dof(f, nd, k, 2)
            call new_dof(f, nd, k, 3)
         end if
      end do
      f%n_dof = nd
      f%kd = 0
      do e = 1, f%n_elements
         lo = huge(1)
         hi = 0
         do k = 1, 2
            associate (d => f%map_dof(:, :, f%element_nodes(k, e)))
               if (any(d > 0)) then
                  lo = min(lo, minval(d, d > 0))
                  hi = max(hi, maxval(d))
               end if
            end associate
         end do
         if (hi > 0) f%kd = max(f%kd, hi - lo)
      end do

   end subroutine number_dofs

   !> Make physical DOF c of node k a new reduced DOF.
   pure subroutine new_dof(f, nd, k, c)
      type(frame_model), intent(inout) :: f
      integer, intent(inout) :: nd
      integer, intent(in) :: k, c

      nd = nd + 1
      f%map_dof(1, c, k) = nd
      f%map_coef(1, c, k) = 1.0_dp
   end subroutine new_dof

   !> Make physical DOF c of node k equal coef x the first term of DOF cm of node `master`.
   pure subroutine slave(f, k, c, master, cm, coef)
      type(frame_model), intent(inout) :: f
      integer, intent(in) :: k, c, master, cm
      real(dp), intent(in) :: coef

      f%map_dof(1, c, k) = f%map_dof(1, cm, master)
      f%map_coef(1, c, k) = coef
   end subroutine slave

   !> Add the matrix `ke` of physical node DOFs (3 per node of `nodes`) to the reduced band
   !> matrix: ab += T_e^T ke T_e, T_e the nodes' rows of the master-slave map.
   pure subroutine add_to_band(f, nodes, ke, ab)
      type(frame_model), intent(in) :: f
      integer, intent(in) :: nodes(:)
      real(dp), intent(in) :: ke(:, :)
      real(dp), intent(inout) :: ab(:, :)
      integer :: dof(2, 3*size(nodes)), a, b, s, t, p, q
      real(dp) :: coef(2, 3*size(nodes))

      do a = 1, size(nodes)
         dof(:, 3*a - 2:3*a) = f%map_dof(:, :, nodes(a))
         coef(:, 3*a - 2:3*a) = f%map_coef(:, :, nodes(a))
      end do
      do b = 1, size(dof, 2)
         do s = 1, 2
            q = dof(s, b)
            if (q == 0) cycle
            do a = 1, size(dof, 2)
               if (ke(a, b) == 0.0_dp) cycle
               do t = 1, 2
                  p = dof(t, a)
                  if (p == 0 .or. p > q) cycle
                  ab(f%kd + 1 + p - q, q) = ab(f%kd + 1 + p - q, q) + coef(t, a)*coef(s, b)*ke(a, b)
               end do
            end do
         end do
      end do
   end subroutine add_to_band

   !> Elastic stiffness K of the reduced DOFs in upper band storage (kd+1, n_dof), kN/m.
   pure subroutine frame_stiffness(f, kb)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> K in upper band storage.
      real(dp), allocatable, intent(out) :: kb(:, :)
      integer :: e

      allocate (kb(f%kd + 1, f%n_dof))
      kb = 0.0_dp
      do e = 1, f%n_elements
         associate (n1 => f%element_nodes(1, e), n2 => f%element_nodes(2, e))
            call add_to_band(f, f%element_nodes(:, e), beam_global_stiffness(f%element_e(e), &
                             f%element_a(e), f%element_i(e), f%node_x(n1), f%node_z(n1), &
                             f%node_x(n2), f%node_z(n2)), kb)
         end associate
      end do
   end subroutine frame_stiffness

   !> Geometric stiffness G of the columns' axial forces `axial` (kN per element, tension
   !> positive; beams are ignored), `kind` = geometric_chord or geometric_consistent, in
   !> upper band storage (kd+1, n_dof), kN/m.
   pure subroutine frame_geometric(f, axial, kind, gb)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Axial force per element (kN), tension positive.
      real(dp), intent(in) :: axial(:)
      !> Kind of geometric stiffness (pound_frame_element).
      integer, intent(in) :: kind
      !> G in upper band storage.
      real(dp), allocatable, intent(out) :: gb(:, :)
      integer :: e

      allocate (gb(f%kd + 1, f%n_dof))
      gb = 0.0_dp
      do e = 1, f%n_elements
         if (f%element_kind(e) /= element_column) cycle
         associate (n1 => f%element_nodes(1, e), n2 => f%element_nodes(2, e))
            call add_to_band(f, f%element_nodes(:, e), beam_global_geometric(axial(e), &
                             f%node_x(n1), f%node_z(n1), f%node_x(n2), f%node_z(n2), kind), gb)
         end associate
      end do
   end subroutine frame_geometric

   !> Lumped mass M of the reduced DOFs in upper band storage (kd+1, n_dof), t (t m^2).
   !> Diagonal unless rigid beams couple a floor's vertical and rotational DOFs.
   pure subroutine frame_mass(f, mb)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> M in upper band storage.
      real(dp), allocatable, intent(out) :: mb(:, :)
      real(dp) :: me(3, 3)
      integer :: k

      allocate (mb(f%kd + 1, f%n_dof))
      mb = 0.0_dp
      do k = 1, f%n_nodes
         if (f%node_mass(k) == 0.0_dp .and. f%node_rotary(k) == 0.0_dp) cycle
         me = 0.0_dp
         me(1, 1) = f%node_mass(k)
         me(2, 2) = f%node_mass(k)
         me(3, 3) = f%node_rotary(k)
         call add_to_band(f, [k], me, mb)
      end do
   end subroutine frame_mass

   !> Reduced load vector T^T p of nodal loads `p` (3, n_nodes): Fx (kN), Fz (kN), moment (kN m).
   pure function frame_load_vector(f, p) result(r)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Nodal loads in global axes.
      real(dp), intent(in) :: p(:, :)
      real(dp) :: r(f%n_dof)
      integer :: k, c, t

      r = 0.0_dp
      do k = 1, f%n_nodes
         do c = 1, 3
            do t = 1, 2
               if (f%map_dof(t, c, k) > 0) r(f%map_dof(t, c, k)) = r(f%map_dof(t, c, k)) + &
                  f%map_coef(t, c, k)*p(c, k)
            end do
         end do
      end do
   end function frame_load_vector

   !> Physical node displacements (3, n_nodes) = T q of the reduced DOFs `q` (m, rad).
   pure function frame_node_displacements(f, q) result(d)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Reduced DOFs (n_dof).
      real(dp), intent(in) :: q(:)
      real(dp) :: d(3, f%n_nodes)
      integer :: k, c, t

      d = 0.0_dp
      do k = 1, f%n_nodes
         do c = 1, 3
            do t = 1, 2
               if (f%map_dof(t, c, k) > 0) d(c, k) = d(c, k) + f%map_coef(t, c, k)*q(f%map_dof(t, c, k))
            end do
         end do
      end do
   end function frame_node_displacements

   !> Node on column line `line` at elevation `z` (m); 0 if there is none.
   pure integer function frame_node_at(f, line, z) result(k)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Column line (1 = leftmost).
      integer, intent(in) :: line
      !> Elevation (m).
      real(dp), intent(in) :: z

      do k = 1, f%n_nodes
         if (f%node_line(k) == line .and. abs(f%node_z(k) - z) <= z_tol) return
      end do
      k = 0
   end function frame_node_at

end module pound_frame
