!> The structural model every model builder produces, as data.
!>
!> A `structure_model` is what the integrator, contact, response and the writers see of a
!> building, whatever built it: n degrees of freedom, the tangent stiffness K+G in LAPACK
!> upper band storage of half-bandwidth kd (`ab(kd+1+i-j, j) = (K+G)(i, j)`, see
!> pound_band), lumped masses (zero allowed, e.g. massless rotations), Rayleigh damping
!> C = a0 M + a1 (K+G), the ground-influence vector r (the equation of motion relative to
!> the ground is M a + C v + (K+G) u = -M r a_g: r = 1 on lateral DOFs, 0 on rotations),
!> the named response points (the DOF of each floor's lateral displacement) and the storey
!> quantities as linear recovery operators over the DOFs (`recovery_row`).
!>
!> **Dimension-free.** Each DOF has a mass and a direction (`dof_direction`: `direction_x`
!> along the row of buildings, `direction_z` up, `direction_rotation` in the x-z plane;
!> `direction_y` and `direction_torsion` for buildings in plan), and the ground is a set of
!> components, each with its direction (`ground_direction`) and its influence vector
!> (`ground_set(:, c)`, r_c(i) = 1 where component c moves DOF i). Today every deck has one
!> component along x; `ground` is its vector, which the integrators read. `uniform_ground`
!> (one component moving every DOF by 1: a shear building) is the property the fused
!> tridiagonal kernels and the batched suites need.
!>
!> **Strain energy.** When the builder can write K+G = sum_j w_j d_j d_j^T with d_j the
!> storey-drift rows (a shear building: w_j = k_j - P_j/h_j), it stores the weights
!> `strain_weight` and the strain energy is sum_j w_j (d_j . u)^2 / 2, storey by storey;
!> otherwise it is u^T (K+G) u / 2 from the band.
!>
!> **A plain data type.** The components are public: a model is written once by its
!> builder and then only read, every reader needs most of it, and accessors for a dozen
!> arrays would add nothing but calls inside the time-step kernels. The invariants (sizes
!> n, kd+1; one drift and one shear row per storey; `floor_dof` within 1..n) are the
!> builder's to keep. Builder-specific data (e.g. the
!> shear building's storey table, a frame's nodes and elements) lives in its building kind
!> (`pound_building_kind`), which answers the writers.
module pound_structure
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_strings, only: str
   use pound_error, only: error_type, fatal_error
   use pound_band, only: band_symv
   use pound_plan_geometry, only: plan_geometry, plan_dof, plane_x, plan_ux, plan_uy, plan_theta
   use pound_padded_rows, only: pad_width, pad_layout, padded_kernel, padded_peaks_kernel
   implicit none
   private

   public :: structure_model, recovery_rows, recover, recover_all, recover_peaks, group_rows, pad_rows, structure_label
   public :: structure_names, result_group, result_rows_of, result_noise
   public :: structure_strain_energy
   public :: direction_x, direction_z, direction_rotation, direction_y, direction_torsion
   public :: structure_check, chain_rows, structure_is_stick, structure_finish, modes_listed, structure_end_dof, &
             structure_end_row, single_row, structure_yields, plan_point_row, never_yields

   !> Directions of a DOF and of a ground component: translation along site x (the row of
   !> buildings), along z (up), rotation in the x-z plane (a frame's node); for buildings in
   !> plan, translation along y and rotation about z.
   integer, parameter :: direction_x = 1, direction_z = 2, direction_rotation = 3, direction_y = 4, &
                         direction_torsion = 5

   !> The yield shear (kN) of a yielding row that never yields (an elastic plane among
   !> bilinear ones, `yield_rows`): far beyond any force, yet its sums stay finite.
   real(dp), parameter :: never_yields = 1.0e100_dp
   !> Relative size below which a result row is round-off (`result_group%arm`).
   real(dp), parameter :: result_noise = 1.0e-9_dp

   !> Natural modes a builder computes besides the two Rayleigh modes: the periods the listing
   !> shows (the lowest `modes_listed`; fewer when the model has fewer modes).
   integer, parameter :: modes_listed = 12

   !> Linear recovery operators over the DOFs, one per row, in compressed sparse rows: row j
   !> is value_j = scale(j) * sum_i coef(i) u(dof(i)), i = start(j) .. start(j+1)-1, the sum
   !> taken in the order of the entries (e.g. a storey drift: dof = [j-1, j], coef = [-1, 1],
   !> scale 1; its storey shear: the same with scale k_j; a storey shear over several
   !> columns: one entry per column end, scale 1).
   type :: recovery_rows
      !> Number of rows.
      integer :: n = 0
      !> First entry of each row (n+1; start(n+1) = number of entries + 1).
      integer, allocatable :: start(:)
      !> DOF (1..n_dofs) and coefficient of each entry.
      integer, allocatable :: dof(:)
      real(dp), allocatable :: coef(:)
      !> Factor applied to each row's sum (n).
      real(dp), allocatable :: scale(:)
      !> Grouped layout (`group_rows`, set up once; 0: none): rows in groups of `group_width`
      !> consecutive rows (a frame's column segment: its four member rows) whose entries lie on
      !> one list of DOFs, group g's DOFs `group_dof(group_start(g) : group_start(g+1)-1)`
      !> with the coefficients of the group's rows in the columns of `group_coef(:, i)` (zero
      !> where a row has no entry). `recover_all` then reads each DOF once per group.
      integer :: group_width = 0
      integer, allocatable :: group_start(:), group_dof(:)
      !> Shared coefficient blocks of the grouped layout: group g's coefficients are the columns
      !> `block_first(b) + (0 : group_start(g+1) - group_start(g) - 1)` of `group_coef` and
      !> its rows' scales `block_scale(:, b)`, b = `group_block(g)`. Groups whose entry count,
      !> coefficients and scales are the same bit for bit (the identical columns of a regular
      !> frame) share one block, so that a step reads the coefficients from cache, not memory.
      integer, allocatable :: group_block(:), block_first(:)
      real(dp), allocatable :: group_coef(:, :), block_scale(:, :)
      !> Padded layout (`pad_rows`, pound_padded_rows; 0: none): short rows of at most
      !> `pad_width` entries in the columns of `pad_dof` and `pad_coef`.
      integer :: pad_width = 0
      integer, allocatable :: pad_dof(:, :)
      real(dp), allocatable :: pad_coef(:, :)
   end type recovery_rows

   !> A named group of result rows (`structure_model%result`): rows `first` ..
   !> `first + product(extent) - 1` of the result rows, an array of Fortran shape `extent`
   !> (first index fastest; h5py reads it reversed: a building in plan's plane shears, extent
   !> (n_storeys, n_planes), read as (n_planes, n_storeys)). The response takes the rows'
   !> absolute maxima at every step; the writers name the group's peaks `peak/<name>` and its
   !> influence coefficients `/influence/<b>/<name>`.
   type :: result_group
      !> Dataset name (e.g. 'plane_shear', 'rotation') and the rows' units.
      character(len=32) :: name = ''
      character(len=16) :: units = ''
      !> First row of the group in the result rows.
      integer :: first = 1
      !> Shape of the group's array (Fortran order; its product is the number of rows).
      integer, allocatable :: extent(:)
      !> What the rows are (the dataset's description attribute).
      character(len=200) :: description = ''
      !> A length (m) that makes the rows displacements (a rotation: the outline's half
      !> diagonal): a row whose uncoupled peak times `arm` is below `result_noise` times the
      !> building's largest floor displacement peak is round-off, taken as 0 (lambda NaN);
      !> 0: no such test.
      real(dp) :: arm = 0.0_dp
   end type result_group

   !> A structural model ready for time integration (a plain data type: see the module doc).
   type :: structure_model
      !> Name (from the deck).
      character(len=:), allocatable :: name
      !> Occurrence of its group in the deck (0: not known), for messages.
      integer :: number = 0
      !> Number of degrees of freedom.
      integer :: n = 0
      !> Half-bandwidth of K+G (1: tridiagonal).
      integer :: kd = 1
      !> Tangent stiffness K+G in upper band storage, shape (kd+1, n).
      real(dp), allocatable :: kt(:, :)
      !> Lumped masses (t or t m^2), >= 0.
      real(dp), allocatable :: mass(:)
      !> Ground-influence vector r (n) of ground component 1: 1 where the ground moves the
      !> DOF, 0 where not (what the integrators read).
      real(dp), allocatable :: ground(:)
      !> The ground components: the direction of each (n_ground) and their influence vectors
      !> (n, n_ground), column 1 = `ground`; set by `structure_finish` from `ground` (one
      !> component along x) where the builder leaves them unset.
      integer, allocatable :: ground_direction(:)
      real(dp), allocatable :: ground_set(:, :)
      !> One ground component moving every DOF by 1 (r = 1): the shear building's property
      !> the fused tridiagonal kernels and the batched suites need; set by `structure_finish`.
      logical :: uniform_ground = .false.
      !> Rayleigh coefficients: C = a0 M + a1 (K+G).
      real(dp) :: a0 = 0.0_dp, a1 = 0.0_dp
      !> Damping ratio and the modes it is fitted at.
      real(dp) :: damping_ratio = 0.0_dp
      integer :: damping_modes(2) = [1, 2]
      !> Circular natural frequencies (rad/s), ascending, and natural periods (s), descending:
      !> the lowest modes only (`modes_listed` and the Rayleigh modes, see the builders).
      real(dp), allocatable :: omega(:), period(:)
      !> Response points: the DOF of each floor's lateral displacement (n_floors); a contact
      !> end on this building when it stands on the left (its right face).
      integer, allocatable :: floor_dof(:)
      !> The DOF of each floor's lateral displacement on the building's left face, the contact
      !> end when it stands on the right (a frame: its leftmost column line); unallocated:
      !> `floor_dof`.
      integer, allocatable :: floor_dof_left(:)
      !> Contact points between floors (a frame's column nodes): elevation (m) and lateral DOF
      !> of each such node on the right face (`point_z`, `point_dof`: contact ends when the
      !> building stands on the left) and on the left face (`point_z_left`, `point_dof_left`);
      !> unallocated: none (a shear building).
      real(dp), allocatable :: point_z(:), point_z_left(:)
      integer, allocatable :: point_dof(:), point_dof_left(:)
      !> Storey drift and storey shear recovery rows (n_storeys each, storey 1 at the bottom).
      type(recovery_rows) :: drift, shear
      !> Weights w_j of K+G = sum_j w_j d_j d_j^T over the drift rows d_j, when the builder
      !> has that form (then the strain energy is taken storey by storey); else unallocated.
      real(dp), allocatable :: strain_weight(:)
      !> The model is a stick as data (`structure_is_stick`); set by `structure_finish`, which
      !> every builder calls last. Consumers then take floors and storeys straight from the DOF
      !> vectors (same numbers as through the rows, fewer operations).
      logical :: stick = .false.
      !> DOF layout, when the builder has nodes (a frame): the node (1-based, as in the builder's
      !> node list) each DOF was created at (n); unallocated: the DOFs are the floors'
      !> lateral displacements.
      integer, allocatable :: dof_node(:)
      !> The direction of each DOF (n; `direction_x`, ...: for a frame 1 horizontal,
      !> 2 vertical, 3 rotation); set by `structure_finish` to `direction_x` everywhere
      !> where the builder leaves it unset (the floors' lateral displacements).
      integer, allocatable :: dof_direction(:)
      !> Member recovery rows (a frame's column end forces; none: `member%n` = 0, a shear
      !> building): rows in groups of size(member_names), row (s-1)*size(member_names) + q is
      !> quantity q of member s. The response samples their absolute maxima at every step (and
      !> the influence coefficients follow); the writers name them `member_group`/`member_names`.
      type(recovery_rows) :: member
      !> Name of the member rows' group (e.g. 'columns') and of the quantities of one member.
      character(len=:), allocatable :: member_group
      character(len=16), allocatable :: member_names(:)
      !> Bilinear storeys (`&building storey_law = 'bilinear'`, issue 25): yield shear (kN) and
      !> hardening ratio of each drift row's storey spring, whose initial stiffness is the
      !> shear row's scale; unallocated: elastic storeys (pound_storey_yield).
      real(dp), allocatable :: yield_shear(:), hardening(:)
      !> Their storey heights (m), for the collapse check (drift / height).
      real(dp), allocatable :: yield_height(:)
      !> Yielding rows that are not the drift rows (a building in plan: one per plane and
      !> storey, planes in deck order, storey fastest; unallocated `yield_k`: the drift rows,
      !> k the shear row's scale): the rows (scale 1; `yield_shear`, `hardening`,
      !> `yield_height` are then per row), each row's initial stiffness k (kN/m), its storey and
      !> plane, whether its force is part of its storey's storey shear (the shear rows are
      !> then the sums of those forces), and the result row of row 1 (0: none; the rows'
      !> forces are then result rows `yield_result_first` onward, e.g. the plane shears).
      !> An elastic row (a plane without storey law) has the yield shear `never_yields`.
      type(recovery_rows) :: yield_rows
      real(dp), allocatable :: yield_k(:)
      integer, allocatable :: yield_storey(:), yield_plane(:)
      logical, allocatable :: yield_in_shear(:)
      integer :: yield_result_first = 0
      !> Plastic hinges of a frame (`&building hinge_law = 'elastic_plastic'`, issue 25): one
      !> row per element end (`hinge%n`), its rotation relative to the element's chord (rad); the
      !> element's flexural stiffness S = [k kc; kc k] joins the two ends (`hinge_mate`: the row of
      !> the other end), end moments m = S (theta - p); yield moment (kN m) of each end; the
      !> plastic parts of the storey-shear and member rows as rows over the hinges (a force is
      !> row . u - plastic row . p); unallocated `hinge_moment`: no hinges (pound_frame_hinges).
      type(recovery_rows) :: hinge, shear_plastic, member_plastic
      real(dp), allocatable :: hinge_moment(:), hinge_k(:), hinge_kc(:)
      !> Each hinge's kinematic hardening modulus H (kN m/rad): |m - H p| <= My (0: none).
      real(dp), allocatable :: hinge_hardening(:)
      integer, allocatable :: hinge_mate(:)
      !> A building in plan (`&building model = 'plan'`): outline, centre of mass, planes and
      !> DOF layout (pound_plan_geometry); unallocated: a planar building.
      type(plan_geometry), allocatable :: plan
      !> Result rows (none: `result_rows%n` = 0): further linear quantities whose absolute
      !> maxima the response takes at every step and whose influence coefficients follow (a
      !> building in plan's plane shears and floor rotations), in named groups
      !> (`result_group`), the groups' rows consecutive in group order.
      type(recovery_rows) :: result_rows
      type(result_group), allocatable :: result(:)
      !> Each hinge's element kind (1 column, 2 beam), storey (column) or floor (beam), column
      !> line of the element's first node, end (1: bottom or left, 2: top or right), element.
      integer, allocatable :: hinge_kind(:), hinge_level(:), hinge_line(:), hinge_end(:), hinge_element(:)
   end type structure_model

contains

   !> The value of row j of `rows` for the DOF vector u.
   pure real(dp) function recover(rows, j, u) result(x)
      !> The rows.
      type(recovery_rows), intent(in) :: rows
      !> Row.
      integer, intent(in) :: j
      !> DOF values (n).
      real(dp), intent(in) :: u(:)
      integer :: i

      x = 0.0_dp
      do i = rows%start(j), rows%start(j + 1) - 1
         x = x + rows%coef(i)*u(rows%dof(i))
      end do
      x = rows%scale(j)*x
   end function recover

   !> The values of all rows for the DOF vector u.
   pure subroutine recover_all(rows, u, y)
      !> The rows.
      type(recovery_rows), intent(in) :: rows
      !> DOF values (n).
      real(dp), intent(in) :: u(:)
      !> Row values (rows%n).
      real(dp), intent(out) :: y(:)

      if (rows%group_width == 4) then
         call grouped4_kernel(rows%n/4, size(rows%group_dof), size(rows%group_coef, 2), size(rows%block_first), &
                              size(u), rows%group_start, rows%group_dof, rows%group_block, rows%block_first, &
                              rows%group_coef, rows%block_scale, u, y)
      else if (rows%pad_width > 0) then
         call padded_kernel(rows%n, size(u), rows%pad_dof, rows%pad_coef, rows%scale, u, y)
      else
         call rows_kernel(rows%n, size(rows%dof), size(u), rows%start, rows%dof, rows%coef, rows%scale, u, y)
      end if
   end subroutine recover_all

   !> The running absolute maxima of the rows' values: where |y(j)| exceeds peak(j),
   !> peak(j) = |y(j)| and peak_time(j) = t. Rows grouped by four (a frame's member rows) take
   !> them in the recovery pass, without storing the values.
   pure subroutine recover_peaks(rows, u, t, y, peak, peak_time)
      !> The rows.
      type(recovery_rows), intent(in) :: rows
      !> DOF values (n).
      real(dp), intent(in) :: u(:)
      !> Time of u.
      real(dp), intent(in) :: t
      !> Work space (rows%n; the row values, except for rows grouped by four, whose values go
      !> straight into the maxima).
      real(dp), intent(inout) :: y(:)
      !> Running absolute maxima of the rows and their times (rows%n each).
      real(dp), intent(inout) :: peak(:), peak_time(:)
      integer :: j

      if (rows%group_width == 4) then
         call grouped4_kernel(rows%n/4, size(rows%group_dof), size(rows%group_coef, 2), size(rows%block_first), &
                              size(u), rows%group_start, rows%group_dof, rows%group_block, rows%block_first, &
                              rows%group_coef, rows%block_scale, u, y, t, peak, peak_time)
         return
      end if
      if (rows%pad_width > 0) then
         call padded_peaks_kernel(rows%n, size(u), rows%pad_dof, rows%pad_coef, rows%scale, u, t, peak, peak_time)
         return
      end if
      call recover_all(rows, u, y)
      do j = 1, rows%n
         if (abs(y(j)) > peak(j)) then
            peak(j) = abs(y(j))
            peak_time(j) = t
         end if
      end do
   end subroutine recover_peaks

   !> `recover_all` on the grouped layout of four rows per group (a frame's member rows):
   !> each group's DOFs read once, its rows summed side by side with its block's coefficients,
   !> the sums in scalars (registers). Every row's sum takes its products in the order of its
   !> entries (a row's entries are in the order of the group's DOF list, `group_rows` checks),
   !> plus exact zeros where it has no entry: the same values as `rows_kernel` (at most the
   !> sign of a zero differs). Two neighbouring groups with as many entries (the common case:
   !> alike members) are summed side by side, so that the chains of dependent additions of the
   !> two overlap. With `peak`, the values update the running absolute maxima and their times
   !> (t) instead of being stored in y (`recover_peaks`).
   pure subroutine grouped4_kernel(ng, nnz, nc, nb, nu, start, dof, block, first, coef, scale, u, y, &
                                   t, peak, peak_time)
      integer, intent(in) :: ng, nnz, nc, nb, nu, start(ng + 1), dof(nnz), block(ng), first(nb)
      real(dp), intent(in) :: coef(4, nc), scale(4, nb), u(nu)
      real(dp), intent(inout) :: y(4, ng)
      real(dp), intent(in), optional :: t
      real(dp), intent(inout), optional :: peak(4, ng), peak_time(4, ng)
      real(dp) :: x1, x2, x3, x4, z1, z2, z3, z4, ui, uk, w(4, 2)
      integer :: g, h, i, k, c, d, len, q, r

      g = 1
      do while (g <= ng)
         len = start(g + 1) - start(g)
         h = g
         if (g < ng) then
            if (start(g + 2) - start(g + 1) == len) h = g + 1
         end if
         c = first(block(g)) - start(g)
         d = first(block(h)) - start(h)
         x1 = 0.0_dp
         x2 = 0.0_dp
         x3 = 0.0_dp
         x4 = 0.0_dp
         z1 = 0.0_dp
         z2 = 0.0_dp
         z3 = 0.0_dp
         z4 = 0.0_dp
         ! h = g (a group alone): the second sums repeat the first's and are dropped.
         do i = start(g), start(g + 1) - 1
            k = i + start(h) - start(g)
            ui = u(dof(i))
            uk = u(dof(k))
            x1 = x1 + coef(1, c + i)*ui
            x2 = x2 + coef(2, c + i)*ui
            x3 = x3 + coef(3, c + i)*ui
            x4 = x4 + coef(4, c + i)*ui
            z1 = z1 + coef(1, d + k)*uk
            z2 = z2 + coef(2, d + k)*uk
            z3 = z3 + coef(3, d + k)*uk
            z4 = z4 + coef(4, d + k)*uk
         end do
         w(:, 2) = scale(:, block(h))*[z1, z2, z3, z4]
         w(:, 1) = scale(:, block(g))*[x1, x2, x3, x4]
         if (present(peak)) then
            do q = g, h
               do r = 1, 4
                  if (abs(w(r, q - g + 1)) > peak(r, q)) then
                     peak(r, q) = abs(w(r, q - g + 1))
                     peak_time(r, q) = t
                  end if
               end do
            end do
         else
            y(:, h) = w(:, 2)
            y(:, g) = w(:, 1)
         end if
         g = h + 1
      end do
   end subroutine grouped4_kernel

   !> Set up the grouped layout of `rows` (`recovery_rows%group_width`) for groups of w
   !> consecutive rows: each group's DOF list is the union of its rows' DOFs in the order of
   !> first appearance. Groups of four only (a frame segment's member rows: the kernel's
   !> width, `grouped4_kernel`). Left without one (rows unchanged) when w is not 4, rows%n is
   !> not a multiple of w or some row's entries are not in the order of its group's list (the
   !> sums would change order).
   pure subroutine group_rows(rows, w)
      !> The rows.
      type(recovery_rows), intent(inout) :: rows
      !> Rows per group.
      integer, intent(in) :: w
      integer, allocatable :: gstart(:), gdof(:)
      real(dp), allocatable :: gcoef(:, :)
      integer :: ng, g, r, j, i, k, last, nnz

      rows%group_width = 0
      if (w /= 4 .or. rows%n == 0 .or. mod(rows%n, w) /= 0) return
      ng = rows%n/w
      allocate (gstart(ng + 1), gdof(size(rows%dof)), gcoef(w, size(rows%dof)))
      gcoef = 0.0_dp
      gstart(1) = 1
      nnz = 0
      do g = 1, ng
         do r = 1, w
            j = (g - 1)*w + r
            last = gstart(g) - 1
            do i = rows%start(j), rows%start(j + 1) - 1
               k = findloc(gdof(gstart(g):nnz), rows%dof(i), dim=1) + gstart(g) - 1
               if (k < gstart(g)) then
                  nnz = nnz + 1
                  gdof(nnz) = rows%dof(i)
                  k = nnz
               end if
               if (k <= last) return
               last = k
               gcoef(r, k) = rows%coef(i)
            end do
         end do
         gstart(g + 1) = nnz + 1
      end do
      rows%group_start = gstart
      rows%group_dof = gdof(1:nnz)
      call share_blocks(rows, w, ng, gstart, gcoef)
      rows%group_width = w
   end subroutine group_rows

   !> The shared coefficient blocks of `group_rows`' layout (`recovery_rows%group_block`): a
   !> group takes the block of one of the `recent_blocks` newest blocks when its entry count,
   !> coefficients and scales equal that block's bit for bit, else a new block of its own.
   !> Identical members come in runs (storey by storey, column line by column line), so a
   !> short window finds them at a cost linear in the number of groups.
   pure subroutine share_blocks(rows, w, ng, gstart, gcoef)
      !> The rows (their scales; the blocks are set).
      type(recovery_rows), intent(inout) :: rows
      !> Rows per group and number of groups.
      integer, intent(in) :: w, ng
      !> The groups' first entries (ng + 1) and coefficients (w, entries).
      integer, intent(in) :: gstart(:)
      real(dp), intent(in) :: gcoef(:, :)
      integer, parameter :: recent_blocks = 8
      integer, allocatable :: first(:), length(:)
      real(dp), allocatable :: coef(:, :), scale(:, :)
      integer :: g, b, nb, nc, len, found

      allocate (rows%group_block(ng), first(ng), length(ng), coef(w, gstart(ng + 1) - 1), scale(w, ng))
      nb = 0
      nc = 0
      do g = 1, ng
         len = gstart(g + 1) - gstart(g)
         found = 0
         do b = nb, max(1, nb - recent_blocks + 1), -1
            if (length(b) /= len) cycle
            if (.not. all(same_bits(scale(:, b), rows%scale((g - 1)*w + 1:g*w)))) cycle
            if (.not. all(same_bits(coef(:, first(b):first(b) + len - 1), gcoef(:, gstart(g):gstart(g + 1) - 1)))) &
               cycle
            found = b
            exit
         end do
         if (found == 0) then
            nb = nb + 1
            first(nb) = nc + 1
            length(nb) = len
            coef(:, nc + 1:nc + len) = gcoef(:, gstart(g):gstart(g + 1) - 1)
            scale(:, nb) = rows%scale((g - 1)*w + 1:g*w)
            nc = nc + len
            found = nb
         end if
         rows%group_block(g) = found
      end do
      rows%block_first = first(1:nb)
      rows%group_coef = coef(:, 1:nc)
      rows%block_scale = scale(:, 1:nb)
   end subroutine share_blocks

   !> Whether two reals hold the same bits (a zero's sign included).
   elemental logical function same_bits(a, b)
      real(dp), intent(in) :: a, b

      same_bits = transfer(a, 0_int64) == transfer(b, 0_int64)
   end function same_bits

   !> `recover_all` on explicit-shape arrays (one pass, no calls per row).
   pure subroutine rows_kernel(n, nnz, nu, start, dof, coef, scale, u, y)
      integer, intent(in) :: n, nnz, nu, start(n + 1), dof(nnz)
      real(dp), intent(in) :: coef(nnz), scale(n), u(nu)
      real(dp), intent(out) :: y(n)
      real(dp) :: x
      integer :: i, j

      do j = 1, n
         x = 0.0_dp
         do i = start(j), start(j + 1) - 1
            x = x + coef(i)*u(dof(i))
         end do
         y(j) = scale(j)*x
      end do
   end subroutine rows_kernel

   !> Finish a model built by a builder: records the properties that consumers read
   !> (`stick`, `uniform_ground`) and, where the builder left them unset, the DOFs'
   !> directions (all along x) and the ground set (one component along x, vector `ground`).
   !> Every builder calls it last.
   pure subroutine structure_finish(m)
      !> The model.
      class(structure_model), intent(inout) :: m

      m%stick = structure_is_stick(m)
      if (.not. allocated(m%dof_direction)) then
         allocate (m%dof_direction(m%n))
         m%dof_direction = direction_x
      end if
      if (.not. allocated(m%ground_set) .and. allocated(m%ground)) then
         m%ground_set = reshape(m%ground, [m%n, 1])
         m%ground_direction = [direction_x]
      end if
      m%uniform_ground = .false.
      if (allocated(m%ground_set)) m%uniform_ground = size(m%ground_set, 2) == 1 .and. all(m%ground_set == 1.0_dp)
   end subroutine structure_finish

   !> sum_j w_j drift_j^2 / 2 of a stick (drift_1 = u_1, drift_j = u_j - u_{j-1}): the same
   !> numbers as `weighted_rows_kernel` on the chain rows.
   pure subroutine weighted_chain_kernel(n, w, u, e)
      integer, intent(in) :: n
      real(dp), intent(in) :: w(n), u(n)
      real(dp), intent(out) :: e
      real(dp) :: x
      integer :: j

      e = 0.5_dp*w(1)*u(1)**2
      do j = 2, n
         x = u(j) - u(j - 1)
         e = e + 0.5_dp*w(j)*x**2
      end do
   end subroutine weighted_chain_kernel

   !> sum_j w_j (row_j . u)^2 / 2 over compressed sparse rows (explicit shapes, so that the
   !> compiler sees plain contiguous arrays; the same operations, in the same order, as `recover`).
   pure subroutine weighted_rows_kernel(n, nnz, nu, start, dof, coef, scale, w, u, e)
      integer, intent(in) :: n, nnz, nu, start(n + 1), dof(nnz)
      real(dp), intent(in) :: coef(nnz), scale(n), w(n), u(nu)
      real(dp), intent(out) :: e
      real(dp) :: x
      integer :: i, j

      e = 0.0_dp
      do j = 1, n
         x = 0.0_dp
         do i = start(j), start(j + 1) - 1
            x = x + coef(i)*u(dof(i))
         end do
         x = scale(j)*x
         e = e + 0.5_dp*w(j)*x**2
      end do
   end subroutine weighted_rows_kernel

   !> Whether the model can yield: bilinear storeys (`yield_shear`) or a frame's plastic hinges
   !> (`hinge_moment`).
   pure logical function structure_yields(m) result(yields)
      !> The model.
      type(structure_model), intent(in) :: m

      yields = allocated(m%yield_shear) .or. allocated(m%hinge_moment)
   end function structure_yields

   !> Whether the model is a stick as data: response point i is DOF i (i = 1..n, n DOFs), the
   !> drift rows are u_1 and u_j - u_{j-1} with scale 1, and the shear rows have the drift
   !> rows' pattern (any scale). Consumers may then take the floors' values straight from
   !> the DOF vectors; the numbers are the same as through the rows.
   pure logical function structure_is_stick(m) result(stick)
      !> The model.
      class(structure_model), intent(in) :: m
      integer :: j

      stick = .false.
      if (.not. (allocated(m%floor_dof) .and. allocated(m%drift%start) .and. allocated(m%shear%start))) return
      if (size(m%floor_dof) /= m%n .or. m%drift%n /= m%n .or. m%shear%n /= m%n) return
      do j = 1, m%n
         if (m%floor_dof(j) /= j) return
      end do
      if (.not. (chain(m%drift) .and. chain(m%shear))) return
      stick = all(m%drift%scale == 1.0_dp)

   contains

      pure logical function chain(rows)
         type(recovery_rows), intent(in) :: rows
         integer :: i, p

         chain = .false.
         if (size(rows%start) /= m%n + 1) return
         if (rows%start(1) /= 1) return
         do i = 1, m%n
            p = rows%start(i)
            if (i == 1) then
               if (rows%start(2) /= 2) return
               if (rows%dof(1) /= 1 .or. rows%coef(1) /= 1.0_dp) return
            else
               if (rows%start(i + 1) /= p + 2) return
               if (rows%dof(p) /= i - 1 .or. rows%coef(p) /= -1.0_dp) return
               if (rows%dof(p + 1) /= i .or. rows%coef(p + 1) /= 1.0_dp) return
            end if
         end do
         chain = .true.
      end function chain
   end function structure_is_stick

   !> The DOF of a contact end on model `m`: floor `floor` (> 0) or, for floor 0, the point at
   !> elevation `z` (m, within 1e-6 m), on the right face when `side` = 1 (the building stands
   !> on the left of the pair) or on the left face when `side` = 2. 0 if there is no such point.
   pure integer function structure_end_dof(m, side, floor, z) result(dof)
      !> The model.
      class(structure_model), intent(in) :: m
      !> End of the pair: 1 (left building) or 2 (right building).
      integer, intent(in) :: side
      !> Floor (0: a point between floors).
      integer, intent(in) :: floor
      !> Elevation of a point between floors (m).
      real(dp), intent(in) :: z
      integer :: k

      dof = 0
      if (floor > 0) then
         dof = m%floor_dof(floor)
         if (side == 2 .and. allocated(m%floor_dof_left)) dof = m%floor_dof_left(floor)
      else if (side == 1 .and. allocated(m%point_z)) then
         k = findloc(abs(m%point_z - z) <= 1.0e-6_dp, .true., 1)
         if (k > 0) dof = m%point_dof(k)
      else if (side == 2 .and. allocated(m%point_z_left)) then
         k = findloc(abs(m%point_z_left - z) <= 1.0e-6_dp, .true., 1)
         if (k > 0) dof = m%point_dof_left(k)
      end if
   end function structure_end_dof

   !> A contact end on model `m` as a sparse row over its DOFs (one row: the end's displacement
   !> is the row's value): the point of `structure_end_dof`, one DOF with coefficient 1; no
   !> row (n = 0) if there is no such point.
   pure function structure_end_row(m, side, floor, z) result(row)
      !> The model.
      class(structure_model), intent(in) :: m
      !> End of the pair: 1 (left building) or 2 (right building).
      integer, intent(in) :: side
      !> Floor (0: a point between floors).
      integer, intent(in) :: floor
      !> Elevation of a point between floors (m).
      real(dp), intent(in) :: z
      type(recovery_rows) :: row
      integer :: dof

      dof = structure_end_dof(m, side, floor, z)
      if (dof == 0) return
      row = single_row(dof)
   end function structure_end_row

   !> One row: the displacement along `direction` (`plane_x`: u_x(P), `plane_y`: u_y(P)) of
   !> the point P = (px, py) (outline coordinates) of floor j: u_x - theta (py - ym) or
   !> u_y + theta (px - xm). A point on the line through the centre of mass has its
   !> rotation entry left out (the row is the one DOF with coefficient 1).
   pure function plan_point_row(m, j, px, py, direction) result(row)
      !> The model (a building in plan: `m%plan` allocated).
      class(structure_model), intent(in) :: m
      !> Floor (1 = lowest).
      integer, intent(in) :: j
      !> The point (m, outline coordinates).
      real(dp), intent(in) :: px, py
      !> `plane_x` or `plane_y`.
      integer, intent(in) :: direction
      type(recovery_rows) :: row
      real(dp) :: arm

      if (direction == plane_x) then
         arm = -(py - m%plan%ym)
      else
         arm = px - m%plan%xm
      end if
      row%n = 1
      row%scale = [1.0_dp]
      if (arm == 0.0_dp) then
         row%start = [1, 2]
         row%dof = [plan_dof(j, merge(plan_ux, plan_uy, direction == plane_x))]
         row%coef = [1.0_dp]
      else
         row%start = [1, 3]
         row%dof = [plan_dof(j, merge(plan_ux, plan_uy, direction == plane_x)), plan_dof(j, plan_theta)]
         row%coef = [1.0_dp, arm]
      end if
   end function plan_point_row

   !> The rows of `parts` one after the other, as one set of rows (each part's rows in order).
   pure function result_rows_of(parts) result(rows)
      !> The parts (each any number of rows).
      type(recovery_rows), intent(in) :: parts(:)
      type(recovery_rows) :: rows
      integer :: k, nnz, p, i

      rows%n = sum(parts%n)
      nnz = 0
      do k = 1, size(parts)
         if (parts(k)%n > 0) nnz = nnz + parts(k)%start(parts(k)%n + 1) - 1
      end do
      allocate (rows%start(rows%n + 1), rows%dof(nnz), rows%coef(nnz), rows%scale(rows%n))
      rows%start(1) = 1
      i = 0
      p = 0
      do k = 1, size(parts)
         if (parts(k)%n == 0) cycle
         associate (q => parts(k), e => parts(k)%start(parts(k)%n + 1) - 1)
            rows%dof(p + 1:p + e) = q%dof(1:e)
            rows%coef(p + 1:p + e) = q%coef(1:e)
            rows%start(i + 2:i + q%n + 1) = q%start(2:q%n + 1) + p
            rows%scale(i + 1:i + q%n) = q%scale
            p = p + e
            i = i + q%n
         end associate
      end do
      call pad_rows(rows)
   end function result_rows_of

   !> Set up the padded layout of `rows` (`recovery_rows%pad_width`) when every row has at most
   !> `pad_width` entries and the rows are not grouped (else rows unchanged): the same values.
   pure subroutine pad_rows(rows)
      !> The rows.
      type(recovery_rows), intent(inout) :: rows
      logical :: ok

      rows%pad_width = 0
      if (rows%group_width /= 0) return
      call pad_layout(rows%n, rows%start, rows%dof, rows%coef, rows%pad_dof, rows%pad_coef, ok)
      if (ok) rows%pad_width = pad_width
   end subroutine pad_rows

   !> One row of one DOF with coefficient 1 (the value is u(dof)).
   pure function single_row(dof) result(row)
      !> The DOF.
      integer, intent(in) :: dof
      type(recovery_rows) :: row

      row%n = 1
      row%start = [1, 2]
      row%dof = [dof]
      row%coef = [1.0_dp]
      row%scale = [1.0_dp]
   end function single_row

   !> `&building #k (name)` when the occurrence is known, else `building name`.
   pure function structure_label(m) result(s)
      !> The model.
      class(structure_model), intent(in) :: m
      character(len=:), allocatable :: s

      if (m%number > 0) then
         s = '&building #'//str(m%number)//' ('//m%name//')'
      else
         s = 'building '//m%name
      end if
   end function structure_label

   !> The models' names, in order (what the joints of a configuration name: `pairs_from_config`).
   pure function structure_names(models) result(names)
      !> The models.
      type(structure_model), intent(in) :: models(:)
      character(len=64) :: names(size(models))
      integer :: ib

      do ib = 1, size(models)
         names(ib) = models(ib)%name
      end do
   end function structure_names

   !> Strain energy including the geometric term, u^T (K+G) u / 2 (kJ): storey by storey
   !> from `strain_weight` and the drift rows when the model has them, else from the band.
   pure function structure_strain_energy(m, u) result(e)
      !> The model.
      class(structure_model), intent(in) :: m
      !> Displacements (n).
      real(dp), intent(in) :: u(:)
      real(dp) :: e

      e = 0.0_dp
      if (allocated(m%strain_weight) .and. m%stick) then
         call weighted_chain_kernel(m%n, m%strain_weight, u, e)
      else if (allocated(m%strain_weight)) then
         call weighted_rows_kernel(m%drift%n, size(m%drift%dof), size(u), m%drift%start, m%drift%dof, &
                                   m%drift%coef, m%drift%scale, m%strain_weight, u, e)
      else
         e = band_energy()
      end if

   contains

      !> u^T (K+G) u / 2 from the band (its work vector lives here, so that the storey-by-storey
      !> paths, taken at every output step of the time loop, allocate nothing).
      pure real(dp) function band_energy()
         real(dp) :: y(size(u))

         call band_symv(m%kt, u, y)
         band_energy = 0.5_dp*dot_product(u, y)
      end function band_energy
   end function structure_strain_energy

   !> Drift rows of a chain of floors on DOFs `dofs` (storey j joins floor j-1 and floor j,
   !> floor 0 the fixed ground), and shear rows with the storey stiffnesses `k` as scales.
   pure subroutine chain_rows(dofs, k, drift, shear)
      !> DOF of each floor (n_storeys).
      integer, intent(in) :: dofs(:)
      !> Storey stiffness of each storey (kN/m).
      real(dp), intent(in) :: k(:)
      !> Storey drift and storey shear rows.
      type(recovery_rows), intent(out) :: drift, shear
      integer :: j, n

      n = size(dofs)
      drift%n = n
      allocate (drift%start(n + 1), drift%dof(max(2*n - 1, 0)), drift%coef(max(2*n - 1, 0)), drift%scale(n))
      drift%start(1) = 1
      do j = 1, n
         if (j == 1) then
            drift%dof(1) = dofs(1)
            drift%coef(1) = 1.0_dp
            drift%start(2) = 2
         else
            drift%dof(2*j - 2:2*j - 1) = [dofs(j - 1), dofs(j)]
            drift%coef(2*j - 2:2*j - 1) = [-1.0_dp, 1.0_dp]
            drift%start(j + 1) = 2*j
         end if
      end do
      drift%scale = 1.0_dp
      shear = drift
      shear%scale = k
   end subroutine chain_rows

   !> Check the sizes and index ranges of a model (a builder's invariants).
   pure subroutine structure_check(m, error)
      !> The model.
      class(structure_model), intent(in) :: m
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: k

      if (.not. (allocated(m%kt) .and. allocated(m%mass) .and. allocated(m%ground) .and. &
                 allocated(m%floor_dof) .and. allocated(m%drift%start) .and. allocated(m%shear%start))) then
         call fatal_error(error, structure_label(m)//': incomplete structural model')
         return
      end if
      if (size(m%kt, 1) /= m%kd + 1 .or. size(m%kt, 2) /= m%n .or. size(m%mass) /= m%n .or. &
          size(m%ground) /= m%n .or. m%kd < 1) then
         call fatal_error(error, structure_label(m)//': structural model of '//str(m%n)//' DOFs and '// &
                          'half-bandwidth '//str(m%kd)//' has arrays of the wrong size')
         return
      end if
      if (any(m%floor_dof < 1) .or. any(m%floor_dof > m%n) .or. m%drift%n /= m%shear%n .or. &
          any(m%drift%dof < 1) .or. any(m%drift%dof > m%n) .or. any(m%shear%dof < 1) .or. &
          any(m%shear%dof > m%n)) then
         call fatal_error(error, structure_label(m)//': response points or storey rows out of range')
         return
      end if
      if (allocated(m%ground_set)) then
         if (size(m%ground_set, 1) /= m%n .or. .not. allocated(m%ground_direction)) then
            call fatal_error(error, structure_label(m)//': ground components of the wrong size')
            return
         else if (size(m%ground_direction) /= size(m%ground_set, 2) .or. &
                  any(m%ground_set(:, 1) /= m%ground)) then
            call fatal_error(error, structure_label(m)//': ground component 1 differs from the ground vector')
            return
         end if
      end if
      if (allocated(m%dof_direction)) then
         if (size(m%dof_direction) /= m%n .or. any(m%dof_direction < direction_x) .or. &
             any(m%dof_direction > direction_torsion)) then
            call fatal_error(error, structure_label(m)//': DOF directions of the wrong size or unknown')
            return
         end if
      end if
      if (m%result_rows%n > 0) then
         if (.not. allocated(m%result)) then
            call fatal_error(error, structure_label(m)//': result rows without groups')
            return
         else if (any(m%result_rows%dof < 1) .or. any(m%result_rows%dof > m%n) .or. &
                  sum([(product(m%result(k)%extent), k=1, size(m%result))]) /= m%result_rows%n) then
            call fatal_error(error, structure_label(m)//': result rows out of range')
            return
         end if
      end if
      if (m%member%n > 0) then
         if (.not. allocated(m%member_names) .or. .not. allocated(m%member_group)) then
            call fatal_error(error, structure_label(m)//': member rows without names')
         else if (mod(m%member%n, max(1, size(m%member_names))) /= 0 .or. any(m%member%dof < 1) .or. &
                  any(m%member%dof > m%n)) then
            call fatal_error(error, structure_label(m)//': member rows out of range')
         end if
      end if
   end subroutine structure_check
end module pound_structure
