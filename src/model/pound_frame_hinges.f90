!> Plastic hinges of a frame (issue 25, `&building hinge_law = 'elastic_plastic'`) and the
!> element rows they are made of.
!>
!> Every element (column segment or beam) of the frame has a rigid-plastic rotational hinge at
!> each end. In the element's local axes (pound_frame_element: local DOFs a1 v1 r1 a2 v2 r2)
!> the end rotations relative to the chord are
!>
!>     theta1 = r1 + (v1 - v2)/L,   theta2 = r2 + (v1 - v2)/L,
!>
!> and the Euler-Bernoulli end moments are m = S (theta - p), S = (EI/L) [4 2; 2 4] (exactly
!> the bending part of k_local: f(3) = M1, f(6) = M2, the shear f(2) = (M1 + M2)/L), p the
!> plastic rotations. Each hinge is one recovery row theta_i over the reduced DOFs (mapped
!> through the frame's constraints like the member rows); `hinge_k` = 4EI/L, `hinge_kc` =
!> 2EI/L, `hinge_mate` the row of the element's other end. The storey-shear rows (the
!> storey's lowest column segments' f(2)) and the member rows (shear, moment_bottom,
!> moment_top, axial of each column segment) lose their plastic parts: `shear_plastic` and
!> `member_plastic` are rows over the hinges, so that a force is row . u - plastic row . p.
module pound_frame_hinges
   use pound_kinds, only: dp
   use pound_structure, only: structure_model, recovery_rows
   use pound_frame, only: frame_model, element_column
   use pound_frame_element, only: beam_transformation
   implicit none
   private

   public :: element_rows, frame_hinges

contains

   !> Rows over the reduced DOFs from rows over elements' local end displacements: row j = sum
   !> over its terms t = start(j) .. start(j+1)-1 of local(:, t) . T d_e of element elem(t),
   !> mapped to the reduced DOFs (duplicates merged, the terms' contributions summed in the
   !> order given; zero entries dropped), scale 1.
   pure subroutine element_rows(f, n, start, elem, local, rows)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Number of reduced DOFs.
      integer, intent(in) :: n
      !> First term of each row (rows + 1).
      integer, intent(in) :: start(:)
      !> Element of each term.
      integer, intent(in) :: elem(:)
      !> The row of each term over the element's local DOFs (6, terms).
      real(dp), intent(in) :: local(:, :)
      !> The rows.
      type(recovery_rows), intent(inout) :: rows
      real(dp), allocatable :: work(:), coef(:)
      integer, allocatable :: touched(:), dof(:), rstart(:)
      logical, allocatable :: seen(:)
      real(dp) :: row(6), t(6, 6)
      integer :: j, e, k, c, tt, nt, n1, n2, node, q, ne, it, nr, nnz

      nr = size(start) - 1
      allocate (work(n), seen(n), touched(n), rstart(nr + 1))
      ! At most 12 entries per term (two nodes, three directions, two map terms).
      allocate (dof(12*size(elem)), coef(12*size(elem)))
      work = 0.0_dp
      seen = .false.
      rstart(1) = 1
      nnz = 0
      do j = 1, nr
         nt = 0
         do it = start(j), start(j + 1) - 1
            e = elem(it)
            n1 = f%element_nodes(1, e)
            n2 = f%element_nodes(2, e)
            t = beam_transformation(f%node_x(n1), f%node_z(n1), f%node_x(n2), f%node_z(n2))
            row = matmul(local(:, it), t)
            do k = 1, 2
               node = f%element_nodes(k, e)
               do c = 1, 3
                  do tt = 1, 2
                     q = f%map_dof(tt, c, node)
                     if (q == 0) cycle
                     if (.not. seen(q)) then
                        seen(q) = .true.
                        nt = nt + 1
                        touched(nt) = q
                     end if
                     work(q) = work(q) + f%map_coef(tt, c, node)*row(3*(k - 1) + c)
                  end do
               end do
            end do
         end do
         ne = 0
         do k = 1, nt
            q = touched(k)
            if (work(q) /= 0.0_dp) then
               nnz = nnz + 1
               dof(nnz) = q
               coef(nnz) = work(q)
               ne = ne + 1
            end if
            work(q) = 0.0_dp
            seen(q) = .false.
         end do
         rstart(j + 1) = rstart(j) + ne
      end do
      rows%n = nr
      rows%start = rstart
      rows%dof = dof(1:nnz)
      rows%coef = coef(1:nnz)
      rows%scale = [(1.0_dp, j=1, nr)]
   end subroutine element_rows

   !> The hinges of frame `f` into model `m`: two a element (element order), their rows, local
   !> stiffness, yield moments, descriptions, and the plastic parts of the storey-shear rows
   !> (`shear_elems`: the storey's lowest column segments, `shear_start` their storeys) and of
   !> the member rows (`column_elems`: four rows each, shear, moment_bottom, moment_top, axial).
   pure subroutine frame_hinges(f, column_yield_moment, beam_yield_moment, hardening_ratio, shear_start, shear_elems, &
                                column_elems, m)
      !> The frame.
      type(frame_model), intent(in) :: f
      !> Yield moment of the columns of each storey and of the beams of each floor (kN m).
      real(dp), intent(in) :: column_yield_moment(:), beam_yield_moment(:)
      !> Kinematic hardening ratio r of the hinges of each storey's columns and floor's beams:
      !> H = r/(1-r) (k + kc) = r/(1-r) 6EI/L.
      real(dp), intent(in) :: hardening_ratio(:)
      !> The storey-shear rows' segments: first of each storey (n_storeys + 1) and elements.
      integer, intent(in) :: shear_start(:), shear_elems(:)
      !> The member rows' column segments.
      integer, intent(in) :: column_elems(:)
      !> The model (n, storey-shear and member rows set; hinges added).
      type(structure_model), intent(inout) :: m
      real(dp), allocatable :: local(:, :), ek(:), ekc(:), el(:)
      integer, allocatable :: start(:), elem(:), hdof(:), st(:)
      real(dp), allocatable :: hcoef(:)
      real(dp) :: l
      integer :: e, ne, h, j, s, i, n1, n2

      ne = f%n_elements
      allocate (local(6, 2*ne), start(2*ne + 1), elem(2*ne), ek(ne), ekc(ne), el(ne))
      allocate (m%hinge_moment(2*ne), m%hinge_k(2*ne), m%hinge_kc(2*ne), m%hinge_mate(2*ne), m%hinge_hardening(2*ne), &
                m%hinge_kind(2*ne), m%hinge_level(2*ne), m%hinge_line(2*ne), m%hinge_end(2*ne), m%hinge_element(2*ne))
      do e = 1, ne
         n1 = f%element_nodes(1, e)
         n2 = f%element_nodes(2, e)
         l = hypot(f%node_x(n2) - f%node_x(n1), f%node_z(n2) - f%node_z(n1))
         el(e) = l
         ek(e) = 4.0_dp*f%element_e(e)*f%element_i(e)/l
         ekc(e) = 2.0_dp*f%element_e(e)*f%element_i(e)/l
         do i = 1, 2
            h = 2*(e - 1) + i
            start(h) = h
            elem(h) = e
            local(:, h) = [0.0_dp, 1.0_dp/l, 0.0_dp, 0.0_dp, -1.0_dp/l, 0.0_dp]
            local(3*i, h) = 1.0_dp
            m%hinge_k(h) = ek(e)
            m%hinge_kc(h) = ekc(e)
            m%hinge_mate(h) = 2*(e - 1) + 3 - i
            m%hinge_kind(h) = f%element_kind(e)
            m%hinge_level(h) = f%element_group(e)
            m%hinge_line(h) = f%node_line(n1)
            m%hinge_end(h) = i
            m%hinge_element(h) = e
            associate (r => hardening_ratio(f%element_group(e)))
               m%hinge_hardening(h) = r/(1.0_dp - r)*(ek(e) + ekc(e))
            end associate
            if (f%element_kind(e) == element_column) then
               m%hinge_moment(h) = column_yield_moment(f%element_group(e))
            else
               m%hinge_moment(h) = beam_yield_moment(f%element_group(e))
            end if
         end do
      end do
      start(2*ne + 1) = 2*ne + 1
      call element_rows(f, m%n, start, elem, local, m%hinge)
      ! Storey shear: each lowest segment's V = (M1 + M2)/L loses ((k + kc)/L) (p1 + p2).
      allocate (st(size(shear_start)), hdof(0), hcoef(0))
      st(1) = 1
      do j = 1, size(shear_start) - 1
         do s = shear_start(j), shear_start(j + 1) - 1
            e = shear_elems(s)
            hdof = [hdof, 2*e - 1, 2*e]
            hcoef = [hcoef, (ek(e) + ekc(e))/el(e), (ek(e) + ekc(e))/el(e)]
         end do
         st(j + 1) = size(hdof) + 1
      end do
      call set_rows(m%shear_plastic, st, hdof, hcoef)
      ! Member rows: shear, moment_bottom (M1 loses k p1 + kc p2), moment_top, axial (none).
      deallocate (st, hdof, hcoef)
      allocate (st(4*size(column_elems) + 1), hdof(0), hcoef(0))
      st(1) = 1
      do s = 1, size(column_elems)
         e = column_elems(s)
         hdof = [hdof, 2*e - 1, 2*e, 2*e - 1, 2*e, 2*e - 1, 2*e]
         hcoef = [hcoef, (ek(e) + ekc(e))/el(e), (ek(e) + ekc(e))/el(e), ek(e), ekc(e), ekc(e), ek(e)]
         st(4*s - 2) = st(4*s - 3) + 2
         st(4*s - 1) = st(4*s - 2) + 2
         st(4*s) = st(4*s - 1) + 2
         st(4*s + 1) = st(4*s)
      end do
      call set_rows(m%member_plastic, st, hdof, hcoef)
   end subroutine frame_hinges

   !> Rows of scale 1 from their starts, columns and coefficients.
   pure subroutine set_rows(rows, start, col, coef)
      type(recovery_rows), intent(inout) :: rows
      integer, intent(in) :: start(:), col(:)
      real(dp), intent(in) :: coef(:)
      integer :: j

      rows%n = size(start) - 1
      rows%start = start
      rows%dof = col
      rows%coef = coef
      rows%scale = [(1.0_dp, j=1, rows%n)]
   end subroutine set_rows

end module pound_frame_hinges
