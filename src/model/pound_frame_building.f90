!> Planar frame model of a `&building model = 'frame'` deck entry, as a `structure_model`.
!>
!> Choices (see README, How it works):
!> - Geometry from `height` (storeys), `bay_width` (bays), sections per storey (columns) and
!>   per floor (beams), `base`, `column_elements`; the constraints `rigid_beams`,
!>   `rigid_diaphragm`, `rigid_columns` are exact (eliminated DOFs, pound_frame).
!> - Mass: the building's floor masses (`mass` or `load_coeff`) lumped at the floor nodes by
!>   tributary width, the same in both translations, no rotary inertia. The lumped mass must
!>   stay diagonal on the reduced DOFs (rigid beams with axially deformable columns couple a
!>   floor's vertical and rotational DOFs: refused).
!> - P-Delta (`p_delta`): G of the column axial forces of the linear gravity analysis of the
!>   unconstrained frame (gravity loads `gravity_load` or the floor weights, split like the
!>   mass), `geometric` = 'chord' or 'consistent'; a frame that buckles is refused
!>   (building, lowest factor, storey).
!> - Ground vector r: 1 on the horizontal DOFs, 0 on the vertical and rotational ones.
!> - Periods: the lowest max(min(n_storeys, modes_listed), damping_modes) modes (at most the DOFs with mass)
!>   by subspace iteration in band storage (pound_band_eigen); each mode's participation
!>   factor phi^T M r and effective mass fraction (phi^T M r)^2 / (r^T M r) (phi^T M phi = 1).
!> - Response points `floor_dof`: each floor's lateral DOF on the RIGHTMOST column line (the
!>   line facing a building to the right); `floor_dof_left` holds the leftmost line's (the
!>   contact end when the frame stands on the right; equal with a rigid diaphragm).
!> - Contact points between floors (`&contact elevations`): the deck's elevations facing no
!>   floor become nodes of the facing column (`contact_z_left`, `contact_z_right`, splitting
!>   that column there); `point_z`/`point_dof` list every column node between floors on the
!>   rightmost line, `point_z_left`/`point_dof_left` on the leftmost.
!> - Storey drift: lateral displacement difference of consecutive floors on the rightmost
!>   line. Storey shear: sum of the storey's column shears at their bottom section (the
!>   first-order end force f(2) of each column's lowest element, pound_frame_element),
!>   a linear row over the DOFs. Strain energy from the band (no `strain_weight`).
!> - Member rows (`structure_model%member`, group 'columns'): per column segment (element,
!>   `column_elements`; a split column has one per segment) its shear, bottom and top end
!>   moments and axial force (first-order end forces, `column_rows`).
module pound_frame_building
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_constants, only: pi
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_building_spec, only: building_spec
   use pound_storey_properties, only: storey_properties
   use pound_structure, only: structure_model, recovery_rows, group_rows, chain_rows, structure_finish, structure_label, &
                              modes_listed
   use pound_frame, only: frame_spec, frame_model, build_frame, frame_stiffness, frame_mass, &
                          frame_geometric, element_column
   use pound_frame_element, only: beam_local_stiffness, geometric_chord, &
                                  geometric_consistent
   use pound_frame_gravity, only: frame_gravity_result, frame_gravity, check_frame_stability
   use pound_band_eigen, only: band_lowest_modes
   use pound_frame_hinges, only: element_rows, frame_hinges
   use pound_shear_building, only: rayleigh_coefficients
   implicit none
   private

   public :: frame_data, build_frame_building, frame_spec_of, column_rows, column_elements, shear_rows


   !> What the writers need of a frame besides its structural model.
   type :: frame_data
      !> The frame: nodes, elements, DOF map.
      type(frame_model) :: frame
      !> Gravity analysis (computed only with p_delta).
      type(frame_gravity_result) :: gravity
      !> Whether the gravity analysis was made (p_delta).
      logical :: p_delta = .false.
      !> 'chord' or 'consistent'.
      character(len=:), allocatable :: geometric
      !> 'fixed' or 'pinned'.
      character(len=:), allocatable :: base
      !> The constraints.
      logical :: rigid_beams = .false., rigid_diaphragm = .false., rigid_columns = .false.
      !> Per computed mode: participation factor Gamma_n = phi_n^T M r (mass-normalized
      !> phi_n, sign as computed) and effective mass fraction Gamma_n^2 / (r^T M r).
      real(dp), allocatable :: participation(:), effective_mass(:)
      !> The column segments of the member rows (`column_rows`): element of each segment.
      integer, allocatable :: column_element(:)
   end type frame_data

contains

   !> The frame description of a deck entry (masses and gravity loads derived as for a shear building).
   pure function frame_spec_of(deck_entry) result(spec)
      !> Validated deck entry with model = 'frame'.
      type(building_spec), intent(in) :: deck_entry
      type(frame_spec) :: spec
      type(building_spec) :: cfg

      cfg = storey_properties(deck_entry)
      spec%name = cfg%name
      spec%bay = cfg%bay_width
      spec%height = cfg%height
      spec%col_e = cfg%column_e
      spec%col_a = cfg%column_area
      spec%col_i = cfg%column_inertia
      spec%beam_e = cfg%beam_e
      spec%beam_a = cfg%beam_area
      spec%beam_i = cfg%beam_inertia
      spec%base_pinned = [.false.]
      if (allocated(cfg%base)) spec%base_pinned = [cfg%base == 'pinned']
      spec%n_sub = cfg%column_elements
      if (allocated(deck_entry%contact_z_left)) spec%extra_z_first = deck_entry%contact_z_left
      if (allocated(deck_entry%contact_z_right)) spec%extra_z_last = deck_entry%contact_z_right
      spec%floor_mass = cfg%mass
      spec%floor_load = cfg%gravity_load
      spec%rigid_beams = cfg%rigid_beams
      spec%rigid_diaphragm = cfg%rigid_diaphragm
      spec%rigid_columns = cfg%rigid_columns
   end function frame_spec_of

   !> Build the structural model of a frame deck entry.
   subroutine build_frame_building(deck_entry, m, fd, error, number)
      !> Validated deck entry with model = 'frame'.
      type(building_spec), intent(in) :: deck_entry
      !> The structural model.
      type(structure_model), intent(out) :: m
      !> The frame data for the writers.
      type(frame_data), intent(out) :: fd
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Occurrence of the `&building` group in the deck, for messages.
      integer, intent(in), optional :: number
      type(frame_spec) :: spec
      real(dp), allocatable :: kb(:, :), gb(:, :), mb(:, :), mb_full(:, :), shapes(:, :)
      integer, allocatable :: hs(:), he(:)
      real(dp), allocatable :: hr(:)
      integer :: kind, j, k, nl, ns, n_modes, kd, q

      spec = frame_spec_of(deck_entry)
      m%name = deck_entry%name
      if (present(number)) m%number = number
      call build_frame(spec, fd%frame, error)
      if (allocated(error)) then
         error%message = structure_label(m)//': '//error%message
         return
      end if
      associate (f => fd%frame)
         nl = f%n_lines
         ns = f%n_storeys
         call frame_stiffness(f, kb)
         fd%geometric = 'chord'
         if (allocated(deck_entry%geometric)) fd%geometric = deck_entry%geometric
         kind = merge(geometric_consistent, geometric_chord, fd%geometric == 'consistent')
         fd%p_delta = deck_entry%p_delta
         fd%base = 'fixed'
         if (spec%base_pinned(1)) fd%base = 'pinned'
         fd%rigid_beams = spec%rigid_beams
         fd%rigid_diaphragm = spec%rigid_diaphragm
         fd%rigid_columns = spec%rigid_columns
         if (fd%p_delta) then
            call frame_gravity(spec, fd%gravity, error)
            if (.not. allocated(error)) call check_frame_stability(f, fd%gravity%axial, kind, error)
            if (allocated(error)) then
               error%message = structure_label(m)//': '//error%message
               return
            end if
            call frame_geometric(f, fd%gravity%axial, kind, gb)
            kb = kb + gb
         end if
         call frame_mass(f, mb)
         if (f%kd > 0) then
            if (any(mb(1:f%kd, :) /= 0.0_dp)) then
               call fatal_error(error, structure_label(m)//': rigid_beams with axially deformable '// &
                                'columns couple the floors'' vertical and rotational masses; not supported: '// &
                                'give rigid_columns = .true. as well, or flexible beams')
               return
            end if
         end if
         m%n = f%n_dof
         kd = max(1, f%kd)
         m%kd = kd
         allocate (m%kt(kd + 1, m%n))
         m%kt = 0.0_dp
         m%kt(kd + 1 - f%kd:kd + 1, :) = kb
         m%mass = mb(f%kd + 1, :)
         if (.not. all(ieee_is_finite(m%kt))) then
            call fatal_error(error, structure_label(m)//': stiffness matrix K+G is not finite (sections, '// &
                             'height, bay_width)')
            return
         end if
         ! Ground influence: 1 on the reduced DOFs that carry horizontal node displacements.
         allocate (m%ground(m%n))
         m%ground = 0.0_dp
         do k = 1, f%n_nodes
            if (f%map_dof(1, 1, k) > 0) m%ground(f%map_dof(1, 1, k)) = 1.0_dp
         end do
         ! DOF layout: each reduced DOF at the node and direction it was created at (nodes are
         ! numbered before their slaves, so the first appearance of a DOF is its master).
         allocate (m%dof_node(m%n), m%dof_direction(m%n))
         m%dof_node = 0
         m%dof_direction = 0
         do k = 1, f%n_nodes
            do j = 1, 3
               q = f%map_dof(1, j, k)
               if (q == 0) cycle
               if (m%dof_node(q) > 0) cycle
               m%dof_node(q) = k
               m%dof_direction(q) = j
            end do
         end do
         allocate (m%floor_dof(ns), m%floor_dof_left(ns))
         do j = 1, ns
            m%floor_dof(j) = f%map_dof(1, 1, f%floor_node(nl, j))
            m%floor_dof_left(j) = f%map_dof(1, 1, f%floor_node(1, j))
         end do
         ! Contact points between floors: every column node between floors on the two faces.
         m%point_dof = pack(f%map_dof(1, 1, :), f%node_line == nl .and. f%node_floor == 0)
         m%point_z = pack(f%node_z, f%node_line == nl .and. f%node_floor == 0)
         m%point_dof_left = pack(f%map_dof(1, 1, :), f%node_line == 1 .and. f%node_floor == 0)
         m%point_z_left = pack(f%node_z, f%node_line == 1 .and. f%node_floor == 0)
         call chain_rows(m%floor_dof, [(1.0_dp, j=1, ns)], m%drift, m%shear)
         call shear_rows(f, m%n, m%shear)
         call column_rows(f, m%n, m%member)
         m%member_group = 'columns'
         m%member_names = [character(len=16) :: 'shear', 'moment_bottom', 'moment_top', 'axial']
         call group_rows(m%member, size(m%member_names))
         fd%column_element = column_elements(f)
         if (deck_entry%hinge_law == 'elastic_plastic') then
            call shear_segments(f, hs, he)
            ! (No hardening ratios given: elastic-perfectly plastic.)
            hr = spread(0.0_dp, 1, ns)
            if (allocated(deck_entry%hinge_hardening_ratio)) hr = deck_entry%hinge_hardening_ratio
            call frame_hinges(f, deck_entry%column_yield_moment, deck_entry%beam_yield_moment, hr, hs, he, &
                              fd%column_element, m)
            m%yield_height = deck_entry%height
         end if

         m%damping_ratio = deck_entry%damping_ratio
         m%damping_modes = deck_entry%damping_modes
         ! The lateral modes the listing shows (one per storey, at most modes_listed) and the
         ! Rayleigh modes.
         n_modes = min(max(min(ns, modes_listed), maxval(m%damping_modes)), count(m%mass > 0.0_dp))
         allocate (mb_full(kd + 1, m%n))
         mb_full = 0.0_dp
         mb_full(kd + 1, :) = m%mass
         call band_lowest_modes(m%kt, mb_full, n_modes, m%omega, shapes, error)
         if (allocated(error)) then
            error%message = structure_label(m)//': natural modes: '//error%message
            return
         end if
         fd%participation = matmul(m%mass*m%ground, shapes)
         fd%effective_mass = fd%participation**2/sum(m%mass*m%ground**2)
      end associate
      m%period = 2.0_dp*pi/m%omega
      call rayleigh_coefficients(m%omega, m%damping_ratio, m%damping_modes, m%a0, m%a1)
      call structure_finish(m)
   end subroutine build_frame_building

   !> Storey shear rows: storey j = sum over the column lines of the shear f(2) at the bottom
   !> end of the storey's lowest column element (first order: k_local T of the element,
   !> mapped to the reduced DOFs; duplicates merged).
   pure subroutine shear_rows(f, n, shear)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Number of reduced DOFs.
      integer, intent(in) :: n
      !> The rows (replaced).
      type(recovery_rows), intent(inout) :: shear
      integer, allocatable :: start(:), elems(:)
      integer :: j

      call shear_segments(f, start, elems)
      call end_force_rows(f, n, start, elems, [(2, j=1, size(elems))], shear)
   end subroutine shear_rows

   !> The segments of the storey-shear rows: storey j's lowest column segments
   !> elems(start(j) : start(j+1)-1).
   pure subroutine shear_segments(f, start, elems)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> First segment of each storey (n_storeys + 1) and the segments' elements.
      integer, allocatable, intent(out) :: start(:), elems(:)
      integer :: j, e

      allocate (start(f%n_storeys + 1), elems(0))
      start(1) = 1
      do j = 1, f%n_storeys
         do e = 1, f%n_elements
            if (f%element_kind(e) /= element_column .or. f%element_group(e) /= j) cycle
            if (abs(f%node_z(f%element_nodes(1, e)) - f%floor_z(j - 1)) > 1.0e-6_dp) cycle
            elems = [elems, e]
         end do
         start(j + 1) = size(elems) + 1
      end do
   end subroutine shear_segments

   !> The column elements (segments between nodes) in element order: storey by storey from
   !> the base, a storey's segments level by level, left to right.
   pure function column_elements(f) result(elems)
      !> The frame.
      type(frame_model), intent(in) :: f
      integer, allocatable :: elems(:)
      integer :: e

      elems = pack([(e, e=1, f%n_elements)], f%element_kind == element_column)
   end function column_elements

   !> Member rows of every column segment (`column_elements`), four per segment: the shear
   !> V = f(2) (constant along the segment, first order), the end moments M1 = f(3) at the
   !> bottom and M2 = f(6) at the top (acting on the element, counterclockwise) and the axial
   !> force N = f(4) (tension positive) of the end forces f = k_local T d (pound_frame_element).
   !> The DOFs are the dynamic response about the gravity state, so N is N - N_gravity.
   pure subroutine column_rows(f, n, rows)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Number of reduced DOFs.
      integer, intent(in) :: n
      !> The rows (4 per segment).
      type(recovery_rows), intent(out) :: rows
      integer, allocatable :: elems(:)
      integer :: s, ns

      elems = column_elements(f)
      ns = size(elems)
      call end_force_rows(f, n, [(s, s=1, 4*ns + 1)], [(elems((s + 3)/4), s=1, 4*ns)], &
                          [([2, 3, 6, 4], s=1, ns)], rows)
   end subroutine column_rows

   !> Rows of element end forces: row j = sum over its terms t = start(j) .. start(j+1)-1 of
   !> component comp(t) (1..6, pound_frame_element's [N1 V1 M1 N2 V2 M2]) of element elem(t)'s
   !> first-order end forces k_local T d, mapped to the reduced DOFs (`element_rows`).
   pure subroutine end_force_rows(f, n, start, elem, comp, rows)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Number of reduced DOFs.
      integer, intent(in) :: n
      !> First term of each row (rows + 1).
      integer, intent(in) :: start(:)
      !> Element and end-force component of each term.
      integer, intent(in) :: elem(:), comp(:)
      !> The rows.
      type(recovery_rows), intent(inout) :: rows
      real(dp), allocatable :: local(:, :)
      real(dp) :: kl(6, 6)
      integer :: e, n1, n2, it

      allocate (local(6, size(elem)))
      do it = 1, size(elem)
         e = elem(it)
         n1 = f%element_nodes(1, e)
         n2 = f%element_nodes(2, e)
         kl = beam_local_stiffness(f%element_e(e), f%element_a(e), f%element_i(e), &
                                   hypot(f%node_x(n2) - f%node_x(n1), f%node_z(n2) - f%node_z(n1)))
         local(:, it) = kl(comp(it), :)
      end do
      call element_rows(f, n, start, elem, local, rows)
   end subroutine end_force_rows

end module pound_frame_building
