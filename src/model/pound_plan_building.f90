!> Buildings in plan (`&building model = 'plan'`): rigid floor diaphragms with three DOFs a
!> floor at the centre of mass and lateral load-resisting planes placed in plan.
!>
!> **DOFs** (pound_plan_geometry): floor j has u_x = DOF 3j-2, u_y = DOF 3j-1 and theta = DOF
!> 3j (about z, counter-clockwise positive); n = 3 n_storeys, half-bandwidth kd = 5 (a storey
!> joins the six DOFs of its two floors). A point P = (px, py) of floor j moves by
!> u_x(P) = u_x - theta (py - ym), u_y(P) = u_y + theta (px - xm) (`plan_point_row`).
!>
!> **Stiffness.** Storey j of a plane has the drift row a = row(P_j) - row(P_{j-1}) (floor 0
!> the ground; an 'x' plane at y = c: the u_x rows of P = (xm, c); a 'y' plane at x = c: the
!> u_y rows of P = (c, ym)) and K = sum over planes and storeys of k a a^T (`plane_drift_row`).
!>
!> **Mass.** M = diag(m_j, m_j, I_j): floor masses as for a shear building
!> (pound_storey_properties: `mass`, or `load_coeff` x `ref_floor_load` / g), rotational
!> inertia `rot_inertia` or m_j (Lx^2 + Ly^2)/12.
!>
!> **P-Delta** (chord, `p_delta`): G_j = -(1/h_j) diag(W_j, W_j, R_j) on the storey's relative
!> DOFs (q(j) - q(j-1), q = (u_x, u_y, theta)), W_j = sum_{i>=j} w_i, R_j = sum_{i>=j} w_i I_i/m_i,
!> w the floors' gravity loads (as for a shear building).
!>
!> **Modes and damping.** The lowest modes of (K+G) phi = omega^2 M phi (x, y and torsion
!> alike, ascending) by the banded generalized eigensolver dsbgvx (eigenvalues only, as the
!> shear building); Rayleigh C = a0 M + a1 (K+G) fitted at `damping_modes`.
!>
!> **Refused:** K not positive definite (a mechanism: no plane in one direction, or every
!> plane through one point, about which the floors turn freely), or K+G not positive definite
!> (buckling under gravity).
!>
!> **Bilinear planes** (`&plane storey_law = 'bilinear'`): the model's yielding rows
!> (`structure_model%yield_rows`, `yield_planes`) are the planes' storey drift rows, which
!> the storey yield set (pound_storey_yield) takes as its springs.
!>
!> **Response.** Response points (`floor_dof`, both faces) are the u_x DOFs; drift rows are the
!> storey x drifts at the centre of mass, shear rows the storey x shears (sum over the 'x'
!> planes of k a.u). Result rows (`structure_model%result`): `plane_shear`, the storey shear
!> k a.u of every plane and storey (extent (n_storeys, n_planes): h5py (n_planes, n_storeys),
!> planes in deck order), and `rotation`, theta of every floor (n_storeys).
!> Ground: component 1 along x (r_x: 1 on every u_x DOF), component 2 along y (r_y).
module pound_plan_building
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_constants, only: pi
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_plausibility, only: buckling_hint
   use pound_building_spec, only: building_spec
   use pound_storey_properties, only: storey_properties
   use pound_sort, only: sort_ascending
   use pound_band_lapack, only: dpbtrf, dsbgvx, dlamch
   use pound_plan_geometry, only: plan_geometry, plan_dof, plane_x, plane_y, plan_ux, plan_uy, plan_theta
   use pound_structure, only: structure_model, recovery_rows, structure_label, chain_rows, structure_finish, &
                              modes_listed, plan_point_row, never_yields, result_group, result_rows_of, direction_x, &
                              direction_y, direction_torsion
   use pound_shear_building, only: rayleigh_coefficients
   implicit none
   private

   public :: plan_data, build_plan_building, plane_drift_row

   !> Half-bandwidth of a building in plan's K+G.
   integer, parameter :: plan_kd = 5

   !> What the writers need of a building in plan besides its structural model.
   type :: plan_data
      !> Floor masses (t) and rotational inertias about the centre of mass (t m^2).
      real(dp), allocatable :: floor_mass(:), rot_inertia(:)
      !> Each plane's storey stiffness (kN/m), (n_storeys, n_planes).
      real(dp), allocatable :: plane_stiffness(:, :)
      !> P-Delta: the storey's gravity load W_j (kN) and its rotational counterpart
      !> R_j = sum_{i>=j} w_i I_i/m_i (kN m^2); zero without P-Delta.
      real(dp), allocatable :: storey_load(:), storey_load_rot(:)
   end type plan_data

contains

   !> Build the model of a building in plan from its entry (values as given).
   subroutine build_plan_building(spec, m, data, error, number)
      !> The building (`model = 'plan'`).
      type(building_spec), intent(in) :: spec
      !> The structural model.
      type(structure_model), intent(out) :: m
      !> Its data for the writers.
      type(plan_data), intent(out) :: data
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Occurrence of the `&building` group in the deck, for messages.
      integer, intent(in), optional :: number
      type(building_spec) :: cfg
      type(recovery_rows) :: a
      type(recovery_rows), allocatable :: parts(:)
      real(dp), allocatable :: kb(:, :)
      integer :: n, ns, np, j, p, c, i, info

      cfg = storey_properties(spec)
      ns = cfg%n_storeys
      m%name = cfg%name
      if (present(number)) m%number = number
      call check_inputs(cfg, m, error)
      if (allocated(error)) return
      np = size(cfg%planes)
      n = 3*ns
      m%n = n
      m%kd = plan_kd
      m%damping_ratio = cfg%damping_ratio
      m%damping_modes = cfg%damping_modes
      allocate (m%plan)
      m%plan%lx = cfg%plan_size(1)
      m%plan%ly = cfg%plan_size(2)
      m%plan%y0 = cfg%plan_origin_y
      m%plan%xm = 0.5_dp*m%plan%lx
      m%plan%ym = 0.5_dp*m%plan%ly
      if (cfg%mass_centre_given) then
         m%plan%xm = cfg%mass_centre(1)
         m%plan%ym = cfg%mass_centre(2)
      end if
      m%plan%plane_direction = [(merge(plane_x, plane_y, cfg%planes(p)%direction == 'x'), p=1, np)]
      m%plan%plane_position = [(cfg%planes(p)%position, p=1, np)]

      data%floor_mass = cfg%mass
      if (allocated(cfg%rot_inertia)) then
         data%rot_inertia = cfg%rot_inertia
      else
         data%rot_inertia = cfg%mass*(m%plan%lx**2 + m%plan%ly**2)/12.0_dp
      end if
      allocate (data%plane_stiffness(ns, np))
      do p = 1, np
         data%plane_stiffness(:, p) = cfg%planes(p)%stiffness
      end do
      allocate (m%mass(n))
      do j = 1, ns
         m%mass(plan_dof(j, plan_ux)) = data%floor_mass(j)
         m%mass(plan_dof(j, plan_uy)) = data%floor_mass(j)
         m%mass(plan_dof(j, plan_theta)) = data%rot_inertia(j)
      end do

      call check_mechanism(m, error)
      if (allocated(error)) return
      ! K = sum over planes and storeys of k a a^T.
      allocate (m%kt(plan_kd + 1, n), source=0.0_dp)
      do p = 1, np
         do j = 1, ns
            a = plane_drift_row(m, p, j)
            call band_add_outer(m%kt, data%plane_stiffness(j, p), a)
         end do
      end do
      kb = m%kt
      call dpbtrf('U', n, plan_kd, kb, plan_kd + 1, info)
      if (info /= 0) then
         call fatal_error(error, structure_label(m)//': the planes'' stiffness K is not positive definite '// &
                          '(leading minor '//str(info)//', floor '//str((info + 2)/3)//'): a mechanism')
         return
      end if

      ! Chord P-Delta: G_j = -(1/h_j) diag(W_j, W_j, R_j) on the storey's relative DOFs.
      allocate (data%storey_load(ns), data%storey_load_rot(ns), source=0.0_dp)
      if (cfg%p_delta) then
         data%storey_load(ns) = cfg%gravity_load(ns)
         data%storey_load_rot(ns) = cfg%gravity_load(ns)*data%rot_inertia(ns)/data%floor_mass(ns)
         do j = ns - 1, 1, -1
            data%storey_load(j) = data%storey_load(j + 1) + cfg%gravity_load(j)
            data%storey_load_rot(j) = data%storey_load_rot(j + 1) + cfg%gravity_load(j)*data%rot_inertia(j)/ &
                                      data%floor_mass(j)
         end do
         do j = 1, ns
            do c = plan_ux, plan_theta
               call band_add_relative(m%kt, j, c, -merge(data%storey_load_rot(j), data%storey_load(j), &
                                                         c == plan_theta)/cfg%height(j))
            end do
         end do
         if (.not. all(ieee_is_finite(m%kt))) then
            call fatal_error(error, structure_label(m)//': the geometric stiffness (gravity_load, height, '// &
                             'rot_inertia) is not finite')
            return
         end if
         kb = m%kt
         call dpbtrf('U', n, plan_kd, kb, plan_kd + 1, info)
         if (info /= 0) then
            call fatal_error(error, structure_label(m)//': buckles under its own gravity loads (K+G not '// &
                             'positive definite, leading minor '//str(info)//', floor '//str((info + 2)/3)//')'// &
                             buckling_hint)
            return
         end if
      end if

      call natural_frequencies(m, error)
      if (allocated(error)) return
      call rayleigh_coefficients(m%omega, m%damping_ratio, m%damping_modes, m%a0, m%a1)
      if (.not. (ieee_is_finite(m%a0) .and. ieee_is_finite(m%a1))) then
         call fatal_error(error, structure_label(m)//': Rayleigh coefficients a0 = '//str(m%a0)//', a1 = '// &
                          str(m%a1)//' from damping_ratio, damping_modes and the natural frequencies are not finite')
         return
      end if

      ! Directions and the two ground components (x, then y).
      allocate (m%dof_direction(n), m%ground_set(n, 2))
      do j = 1, ns
         m%dof_direction(plan_dof(j, plan_ux)) = direction_x
         m%dof_direction(plan_dof(j, plan_uy)) = direction_y
         m%dof_direction(plan_dof(j, plan_theta)) = direction_torsion
      end do
      m%ground_set = 0.0_dp
      do j = 1, ns
         m%ground_set(plan_dof(j, plan_ux), 1) = 1.0_dp
         m%ground_set(plan_dof(j, plan_uy), 2) = 1.0_dp
      end do
      m%ground = m%ground_set(:, 1)
      m%ground_direction = [direction_x, direction_y]

      ! Response points, storey x drifts at the centre of mass and storey x shears.
      m%floor_dof = plan_dof([(j, j=1, ns)], plan_ux)
      m%floor_dof_left = m%floor_dof
      call chain_rows(m%floor_dof, [(1.0_dp, j=1, ns)], m%drift, a)
      allocate (parts(ns))
      do j = 1, ns
         parts(j) = storey_x_shear(m, data%plane_stiffness, j)
      end do
      m%shear = result_rows_of(parts)

      ! Result rows: every plane's storey shear, every floor's rotation.
      deallocate (parts)
      allocate (parts(np*ns + 1))
      do p = 1, np
         do j = 1, ns
            parts((p - 1)*ns + j) = plane_drift_row(m, p, j)
            parts((p - 1)*ns + j)%scale = data%plane_stiffness(j, p)
         end do
      end do
      allocate (parts(np*ns + 1)%start(ns + 1), parts(np*ns + 1)%dof(ns), parts(np*ns + 1)%coef(ns), &
                parts(np*ns + 1)%scale(ns))
      parts(np*ns + 1)%n = ns
      parts(np*ns + 1)%start = [(i, i=1, ns + 1)]
      parts(np*ns + 1)%dof = plan_dof([(j, j=1, ns)], plan_theta)
      parts(np*ns + 1)%coef = 1.0_dp
      parts(np*ns + 1)%scale = 1.0_dp
      m%result_rows = result_rows_of(parts)
      allocate (m%result(2))
      m%result(1) = result_group(name='plane_shear', units='kN', first=1, extent=[ns, np], &
                                 description='storey shear k d of every plane (row, deck order) and '// &
                                 'storey (column)')
      m%result(2) = result_group(name='rotation', units='rad', first=np*ns + 1, extent=[ns], &
                                 description='floor rotation theta about z at the centre of mass, '// &
                                 'counter-clockwise positive', arm=0.5_dp*hypot(m%plan%lx, m%plan%ly))
      call yield_planes(cfg, m, data)
      call structure_finish(m)
   end subroutine build_plan_building

   !> Bilinear planes (`&plane storey_law = 'bilinear'` on some plane): the model's yielding
   !> rows are every plane's storey drift rows (`plane_drift_row`, planes in deck order, storey
   !> fastest: the rows of the `plane_shear` result group), k the plane's storey stiffness,
   !> the yield shear and hardening ratio of a bilinear plane, `never_yields` and 0 for an
   !> elastic plane (it never yields); an 'x' plane's forces sum to the storey x shear.
   pure subroutine yield_planes(cfg, m, data)
      type(building_spec), intent(in) :: cfg
      type(structure_model), intent(inout) :: m
      type(plan_data), intent(in) :: data
      type(recovery_rows), allocatable :: parts(:)
      integer :: ns, np, p, j, i

      if (.not. any([(cfg%planes(p)%storey_law == 'bilinear', p=1, size(cfg%planes))])) return
      ns = cfg%n_storeys
      np = size(cfg%planes)
      allocate (parts(np*ns), m%yield_k(np*ns), m%yield_shear(np*ns), m%hardening(np*ns), m%yield_height(np*ns), &
                m%yield_storey(np*ns), m%yield_plane(np*ns), m%yield_in_shear(np*ns))
      do p = 1, np
         do j = 1, ns
            i = (p - 1)*ns + j
            parts(i) = plane_drift_row(m, p, j)
            m%yield_k(i) = data%plane_stiffness(j, p)
            if (cfg%planes(p)%storey_law == 'bilinear') then
               m%yield_shear(i) = cfg%planes(p)%yield_shear(j)
               m%hardening(i) = cfg%planes(p)%hardening_ratio(j)
            else
               m%yield_shear(i) = never_yields
               m%hardening(i) = 0.0_dp
            end if
            m%yield_height(i) = cfg%height(j)
            m%yield_storey(i) = j
            m%yield_plane(i) = p
            m%yield_in_shear(i) = m%plan%plane_direction(p) == plane_x
         end do
      end do
      m%yield_rows = result_rows_of(parts)
      m%yield_result_first = m%result(1)%first
      m%result(1)%description = 'storey shear of every plane (row, deck order) and storey (column): the '// &
                                'spring force k (d - p) of a bilinear plane, k d of an elastic one'
   end subroutine yield_planes

   !> The drift row of storey j of plane p: row(P_j) - row(P_{j-1}) (floor 0: the ground), with
   !> P on the plane's line (an 'x' plane at y = c: P = (xm, c), u_x rows; a 'y' plane at
   !> x = c: P = (c, ym), u_y rows); scale 1.
   pure function plane_drift_row(m, p, j) result(row)
      !> A building in plan (`m%plan` with its planes).
      type(structure_model), intent(in) :: m
      !> Plane (deck order) and storey (1 = bottom).
      integer, intent(in) :: p, j
      type(recovery_rows) :: row
      type(recovery_rows) :: top, bottom
      real(dp) :: px, py
      integer :: d

      d = m%plan%plane_direction(p)
      if (d == plane_x) then
         px = m%plan%xm
         py = m%plan%plane_position(p)
      else
         px = m%plan%plane_position(p)
         py = m%plan%ym
      end if
      top = plan_point_row(m, j, px, py, d)
      row%n = 1
      row%scale = [1.0_dp]
      if (j == 1) then
         row%dof = top%dof
         row%coef = top%coef
      else
         bottom = plan_point_row(m, j - 1, px, py, d)
         row%dof = [bottom%dof, top%dof]
         row%coef = [-bottom%coef, top%coef]
      end if
      row%start = [1, size(row%dof) + 1]
   end function plane_drift_row

   !> The storey x shear of storey j as one row: sum over the 'x' planes of k a.u, with the
   !> planes' coefficients gathered on the storey's u_x and theta DOFs; scale 1.
   pure function storey_x_shear(m, k, j) result(row)
      type(structure_model), intent(in) :: m
      real(dp), intent(in) :: k(:, :)
      integer, intent(in) :: j
      type(recovery_rows) :: row
      type(recovery_rows) :: a
      integer, allocatable :: dofs(:)
      real(dp), allocatable :: coef(:)
      integer :: p, i, f, keep(4), nk

      if (j == 1) then
         dofs = [plan_dof(j, plan_ux), plan_dof(j, plan_theta)]
      else
         dofs = [plan_dof(j - 1, plan_ux), plan_dof(j - 1, plan_theta), plan_dof(j, plan_ux), plan_dof(j, plan_theta)]
      end if
      allocate (coef(size(dofs)), source=0.0_dp)
      do p = 1, size(m%plan%plane_direction)
         if (m%plan%plane_direction(p) /= plane_x) cycle
         a = plane_drift_row(m, p, j)
         do i = 1, size(a%dof)
            f = findloc(dofs, a%dof(i), 1)
            coef(f) = coef(f) + k(j, p)*a%coef(i)
         end do
      end do
      ! The rotation entries vanish when the x planes balance about the centre of mass.
      nk = 0
      do i = 1, size(dofs)
         if (coef(i) /= 0.0_dp .or. mod(dofs(i), 3) /= 0) then
            nk = nk + 1
            keep(nk) = i
         end if
      end do
      row%n = 1
      row%start = [1, nk + 1]
      row%dof = dofs(keep(1:nk))
      row%coef = coef(keep(1:nk))
      row%scale = [1.0_dp]
   end function storey_x_shear

   !> ab = ab + k a a^T for one sparse row a (upper band storage).
   pure subroutine band_add_outer(ab, k, a)
      real(dp), intent(inout) :: ab(:, :)
      real(dp), intent(in) :: k
      type(recovery_rows), intent(in) :: a
      integer :: i, l, r, c, kd

      kd = size(ab, 1) - 1
      do i = a%start(1), a%start(2) - 1
         do l = a%start(1), a%start(2) - 1
            r = a%dof(i)
            c = a%dof(l)
            if (r > c) cycle
            ab(kd + 1 + r - c, c) = ab(kd + 1 + r - c, c) + k*a%coef(i)*a%coef(l)
         end do
      end do
   end subroutine band_add_outer

   !> ab = ab + s d d^T with d = q_c(j) - q_c(j-1) (component c of floors j and j-1; floor 0
   !> the ground).
   pure subroutine band_add_relative(ab, j, c, s)
      real(dp), intent(inout) :: ab(:, :)
      integer, intent(in) :: j, c
      real(dp), intent(in) :: s
      integer :: kd, top, bottom

      kd = size(ab, 1) - 1
      top = plan_dof(j, c)
      ab(kd + 1, top) = ab(kd + 1, top) + s
      if (j > 1) then
         bottom = plan_dof(j - 1, c)
         ab(kd + 1, bottom) = ab(kd + 1, bottom) + s
         ab(kd + 1 + bottom - top, top) = ab(kd + 1 + bottom - top, top) - s
      end if
   end subroutine band_add_relative

   !> A mechanism the planes leave: no plane in one direction, or every plane through one
   !> point (the 'x' planes on one line y = c, the 'y' planes on one line x = c').
   pure subroutine check_mechanism(m, error)
      type(structure_model), intent(in) :: m
      type(error_type), allocatable, intent(out) :: error
      logical :: is_x(size(m%plan%plane_direction))
      real(dp) :: cx, cy

      is_x = m%plan%plane_direction == plane_x
      if (.not. any(is_x)) then
         call fatal_error(error, structure_label(m)//': no &plane resists x (direction = ''x''): the floors '// &
                          'slide freely along x (a mechanism); a plan building needs planes in both directions')
         return
      end if
      if (all(is_x)) then
         call fatal_error(error, structure_label(m)//': no &plane resists y (direction = ''y''): the floors '// &
                          'slide freely along y (a mechanism); a plan building needs planes in both directions')
         return
      end if
      cy = m%plan%plane_position(findloc(is_x, .true., 1))
      cx = m%plan%plane_position(findloc(is_x, .false., 1))
      if (all(pack(m%plan%plane_position, is_x) == cy) .and. all(pack(m%plan%plane_position, .not. is_x) == cx)) then
         call fatal_error(error, structure_label(m)//': every &plane passes through the point x = '//str(cx)// &
                          ' m, y = '//str(cy)//' m (the ''x'' planes on one line, the ''y'' planes on one line): '// &
                          'the floors turn freely about it (a torsional mechanism); place a plane off that point')
      end if
   end subroutine check_mechanism

   !> The entry's values: storeys, heights, masses, outline, centre of mass, rotational
   !> inertia and planes (the deck reader validates them; checked again here so that a
   !> model built by hand fails with a message, not nonsense).
   pure subroutine check_inputs(cfg, m, error)
      type(building_spec), intent(in) :: cfg
      type(structure_model), intent(in) :: m
      type(error_type), allocatable, intent(out) :: error
      integer :: ns, p

      ns = cfg%n_storeys
      if (ns < 1 .or. .not. allocated(cfg%height) .or. .not. allocated(cfg%mass)) then
         call fatal_error(error, structure_label(m)//': n_storeys, height and mass (or load_coeff) are required')
         return
      end if
      if (size(cfg%height) /= ns .or. size(cfg%mass) /= ns) then
         call fatal_error(error, structure_label(m)//': height and mass need n_storeys = '//str(ns)//' values')
         return
      end if
      if (.not. all(cfg%mass > 0.0_dp .and. ieee_is_finite(cfg%mass))) then
         call fatal_error(error, structure_label(m)//': the floor masses are not all positive and finite')
         return
      end if
      if (.not. all(cfg%height > 0.0_dp .and. ieee_is_finite(cfg%height))) then
         call fatal_error(error, structure_label(m)//': the storey heights are not all positive and finite')
         return
      end if
      if (.not. all(cfg%plan_size > 0.0_dp .and. ieee_is_finite(cfg%plan_size))) then
         call fatal_error(error, structure_label(m)//': plan_size = Lx, Ly must be positive and finite (m)')
         return
      end if
      if (allocated(cfg%rot_inertia)) then
         if (size(cfg%rot_inertia) /= ns .or. .not. all(cfg%rot_inertia > 0.0_dp .and. &
                                                        ieee_is_finite(cfg%rot_inertia))) then
            call fatal_error(error, structure_label(m)//': rot_inertia needs n_storeys = '//str(ns)// &
                             ' positive, finite values (t m^2)')
            return
         end if
      end if
      if (cfg%p_delta) then
         if (.not. allocated(cfg%gravity_load)) then
            call fatal_error(error, structure_label(m)//': p_delta needs the floors'' gravity loads')
            return
         end if
      end if
      if (.not. allocated(cfg%planes)) then
         call fatal_error(error, structure_label(m)//': a plan building needs &plane groups '// &
                          '(at least one in each direction)')
         return
      end if
      if (size(cfg%planes) == 0) then
         call fatal_error(error, structure_label(m)//': a plan building needs &plane groups '// &
                          '(at least one in each direction)')
         return
      end if
      do p = 1, size(cfg%planes)
         associate (pl => cfg%planes(p))
            if (pl%storey_law /= 'elastic' .and. pl%storey_law /= 'bilinear') then
               call fatal_error(error, structure_label(m)//': &plane '//str(p)//' (line '//str(pl%line)// &
                                "): storey_law = '"//trim(pl%storey_law)//"', must be 'elastic' or 'bilinear'")
               return
            end if
            if (pl%storey_law == 'bilinear') then
               if (.not. (allocated(pl%yield_shear) .and. allocated(pl%hardening_ratio))) then
                  call fatal_error(error, structure_label(m)//': &plane '//str(p)//' (line '//str(pl%line)// &
                                   "): storey_law = 'bilinear' needs yield_shear (and hardening_ratio)")
                  return
               end if
               if (size(pl%yield_shear) /= ns .or. .not. all(pl%yield_shear > 0.0_dp .and. &
                                                             ieee_is_finite(pl%yield_shear))) then
                  call fatal_error(error, structure_label(m)//': &plane '//str(p)//' (line '//str(pl%line)// &
                                   '): yield_shear needs n_storeys = '//str(ns)//' positive, finite values (kN)')
                  return
               end if
               if (size(pl%hardening_ratio) /= ns .or. .not. all(pl%hardening_ratio > -1.0_dp .and. &
                                                                 pl%hardening_ratio < 1.0_dp)) then
                  call fatal_error(error, structure_label(m)//': &plane '//str(p)//' (line '//str(pl%line)// &
                                   '): hardening_ratio needs n_storeys = '//str(ns)//' values > -1 and < 1')
                  return
               end if
            end if
            if (.not. allocated(pl%stiffness)) then
               call fatal_error(error, structure_label(m)//': &plane '//str(p)//' has no stiffness')
               return
            end if
            if (size(pl%stiffness) /= ns .or. .not. all(pl%stiffness > 0.0_dp .and. ieee_is_finite(pl%stiffness))) then
               call fatal_error(error, structure_label(m)//': &plane '//str(p)//' (line '//str(pl%line)// &
                                '): stiffness needs n_storeys = '//str(ns)//' positive, finite values (kN/m)')
               return
            end if
            if (pl%direction /= 'x' .and. pl%direction /= 'y') then
               call fatal_error(error, structure_label(m)//': &plane '//str(p)//": direction must be 'x' or 'y'")
               return
            end if
         end associate
      end do
   end subroutine check_inputs

   !> The lowest natural frequencies of (K+G, M) by dsbgvx (eigenvalues only; M diagonal and
   !> positive): modes 1 .. min(n, max(modes_listed, damping modes)), ascending; periods
   !> longest first.
   subroutine natural_frequencies(m, error)
      type(structure_model), intent(inout) :: m
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: ab(:, :), bb(:, :), w(:), work(:)
      integer, allocatable :: iwork(:), ifail(:)
      real(dp) :: z(1, 1), q(1, 1)
      integer :: info, nf, n_wanted

      n_wanted = min(m%n, max(modes_listed, maxval(m%damping_modes)))
      allocate (ab(plan_kd + 1, m%n), bb(1, m%n), w(m%n), work(7*m%n), iwork(5*m%n), ifail(m%n))
      ab = m%kt
      bb(1, :) = m%mass
      call dsbgvx('N', 'I', 'U', m%n, plan_kd, 0, ab, plan_kd + 1, bb, 1, q, 1, 0.0_dp, 0.0_dp, 1, n_wanted, &
                  merge(0.0_dp, 2.0_dp*dlamch('S'), n_wanted == m%n), nf, w, z, 1, work, iwork, ifail, info)
      if (info /= 0 .or. nf /= n_wanted) then
         call fatal_error(error, structure_label(m)//': eigenvalue solver dsbgvx failed (info = '// &
                          str(info)//', '//str(nf)//' of '//str(n_wanted)//' eigenvalues); check the masses, '// &
                          'rot_inertia and the planes'' stiffness')
         return
      end if
      call sort_ascending(w(1:nf))
      if (.not. (w(1) > 0.0_dp .and. ieee_is_finite(w(nf)))) then
         call fatal_error(error, structure_label(m)//': natural frequencies out of range (omega^2 from '// &
                          str(w(1))//' to '//str(w(nf))//' 1/s^2)')
         return
      end if
      m%omega = sqrt(w(1:nf))
      m%period = 2.0_dp*pi/m%omega
   end subroutine natural_frequencies

end module pound_plan_building
