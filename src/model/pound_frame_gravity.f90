!> Linear static gravity analysis of a frame, its geometric stiffness and the buckling check.
!>
!> The gravity analysis is made on the frame WITHOUT the optional constraints (rigid beams,
!> diaphragm, axially rigid columns), whose column axial forces would otherwise be
!> reactions: nodal vertical loads at the floor nodes (split like the mass), K u = p solved
!> by banded Cholesky (dpbtrf/dpbtrs), element end forces and base reactions. The axial
!> forces of the columns give G (pound_frame's `frame_geometric`, beams ignored).
!>
!> Buckling: the lowest factor lambda with K + lambda G singular. K + lambda G is positive
!> definite exactly for 0 <= lambda < lambda_cr, so lambda_cr is bracketed by doubling and
!> bisected (to 1e-13 relative) with banded Cholesky factorizations (dpbtrf, O(n kd^2)
!> each); the mode then comes from inverse iteration at lambda_cr, its Rayleigh quotient
!> phi^T K phi / phi^T (-G) phi is the reported factor, and the column group (storey)
!> whose geometric energy phi^T (-G_e) phi dominates in it is named. A frame is refused when K+G is not positive definite (dpbtrf)
!> or lambda <= 1.
module pound_frame_gravity
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_plausibility, only: buckling_hint
   use pound_band_lapack, only: dpbtrf, dpbtrs
   use pound_band_eigen, only: band_inverse_iteration
   use pound_band, only: band_symv
   use pound_frame_element, only: beam_end_forces, beam_transformation, beam_global_geometric
   use pound_frame, only: frame_spec, frame_model, build_frame, frame_stiffness, frame_geometric, &
                          frame_load_vector, frame_node_displacements, element_column
   implicit none
   private

   public :: frame_gravity_result, frame_gravity, frame_buckling, check_frame_stability

   !> Results of the gravity analysis (element and node order of `build_frame`).
   type :: frame_gravity_result
      !> Axial force per element (kN), tension positive.
      real(dp), allocatable :: axial(:)
      !> End forces per element in local axes, (6, n_elements) (kN, kN m; pound_frame_element).
      real(dp), allocatable :: end_forces(:, :)
      !> Node displacements (3, n_nodes): u, w (m), theta (rad).
      real(dp), allocatable :: displacement(:, :)
      !> Base reactions per column line (3, n_lines): horizontal, vertical (up) (kN), moment (kN m).
      real(dp), allocatable :: reactions(:, :)
      !> Total gravity load (kN).
      real(dp) :: total_load = 0.0_dp
   end type frame_gravity_result

contains

   !> Linear static gravity analysis of the frame of `spec` without its optional constraints.
   subroutine frame_gravity(spec, res, error)
      !> The frame's description (its constraints are ignored here).
      type(frame_spec), intent(in) :: spec
      !> Axial forces, end forces, displacements, reactions.
      type(frame_gravity_result), intent(out) :: res
      !> Set if the description is invalid or the unconstrained frame is a mechanism.
      type(error_type), allocatable, intent(out) :: error
      type(frame_spec) :: free
      type(frame_model) :: f
      real(dp), allocatable :: kb(:, :), p(:, :), q(:, :), fg(:)
      integer :: e, k, info, n1, n2

      free = spec
      free%rigid_beams = .false.
      free%rigid_diaphragm = .false.
      free%rigid_columns = .false.
      call build_frame(free, f, error)
      if (allocated(error)) return
      call frame_stiffness(f, kb)
      allocate (p(3, f%n_nodes))
      p = 0.0_dp
      p(2, :) = -f%node_load
      res%total_load = sum(f%node_load)
      allocate (q(f%n_dof, 1))
      q(:, 1) = frame_load_vector(f, p)
      call dpbtrf('U', f%n_dof, f%kd, kb, f%kd + 1, info)
      if (info /= 0) then
         call fatal_error(error, 'frame '//f%name//': gravity analysis: the frame is a mechanism '// &
                          '(stiffness not positive definite at DOF '//str(info)//')')
         return
      end if
      call dpbtrs('U', f%n_dof, f%kd, 1, kb, f%kd + 1, q, f%n_dof, info)
      res%displacement = frame_node_displacements(f, q(:, 1))
      allocate (res%axial(f%n_elements), res%end_forces(6, f%n_elements), res%reactions(3, f%n_lines))
      res%reactions = 0.0_dp
      do e = 1, f%n_elements
         n1 = f%element_nodes(1, e)
         n2 = f%element_nodes(2, e)
         res%end_forces(:, e) = beam_end_forces(f%element_e(e), f%element_a(e), f%element_i(e), &
                                                f%node_x(n1), f%node_z(n1), f%node_x(n2), f%node_z(n2), &
                                                [res%displacement(:, n1), res%displacement(:, n2)])
         res%axial(e) = res%end_forces(4, e)
         ! Reaction = sum of the forces the base node exerts on its elements (global axes).
         fg = matmul(transpose(beam_transformation(f%node_x(n1), f%node_z(n1), f%node_x(n2), f%node_z(n2))), &
                     res%end_forces(:, e))
         do k = 1, 2
            if (f%node_floor(f%element_nodes(k, e)) < 0) then
               associate (line => f%node_line(f%element_nodes(k, e)))
                  res%reactions(:, line) = res%reactions(:, line) + fg(3*k - 2:3*k)
               end associate
            end if
         end do
      end do
   end subroutine frame_gravity

   !> Lowest buckling factor lambda (K + lambda G singular) for the axial forces `axial`
   !> (kN per element, tension positive) and the column group (storey) that buckles;
   !> lambda = huge and group = 0 if no factor up to 1e15 makes K + lambda G singular.
   subroutine frame_buckling(f, axial, kind, factor, group, error)
      !> The frame (with its constraints).
      type(frame_model), intent(in) :: f
      !> Axial force per element (kN), tension positive.
      real(dp), intent(in) :: axial(:)
      !> Kind of geometric stiffness (pound_frame_element).
      integer, intent(in) :: kind
      !> Lowest buckling factor.
      real(dp), intent(out) :: factor
      !> Storey of the column group with the largest geometric energy in the buckling mode.
      integer, intent(out) :: group
      !> Set if K is not positive definite or the mode cannot be computed.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: kb(:, :), gb(:, :), x(:), d(:, :), energy(:), de(:), kx(:), gx(:)
      real(dp) :: lo, hi, mid
      integer :: e, n1, n2, it

      factor = huge(1.0_dp)
      group = 0
      call frame_stiffness(f, kb)
      call frame_geometric(f, axial, kind, gb)
      if (.not. definite(0.0_dp)) then
         call fatal_error(error, 'frame '//f%name//': the stiffness K is not positive definite (a mechanism)')
         return
      end if
      if (all(gb == 0.0_dp)) return
      ! Bracket, then bisect: K + lambda G is positive definite exactly for lambda < lambda_cr.
      lo = 0.0_dp
      hi = 1.0_dp
      do while (definite(hi))
         lo = hi
         hi = 2.0_dp*hi
         if (hi > 1.0e15_dp) return
      end do
      do it = 1, 200
         mid = 0.5_dp*(lo + hi)
         if (mid <= lo .or. mid >= hi .or. hi - lo <= 1.0e-13_dp*hi) exit
         if (definite(mid)) then
            lo = mid
         else
            hi = mid
         end if
      end do
      ! Mode by inverse iteration; its Rayleigh quotient polishes the factor.
      gb = -gb
      call band_inverse_iteration(kb, gb, hi, x, error)
      if (allocated(error)) return
      allocate (kx(size(x)), gx(size(x)))
      call band_symv(kb, x, kx)
      call band_symv(gb, x, gx)
      factor = dot_product(x, kx)/dot_product(x, gx)
      d = frame_node_displacements(f, x)
      allocate (energy(f%n_storeys))
      energy = 0.0_dp
      do e = 1, f%n_elements
         if (f%element_kind(e) /= element_column) cycle
         n1 = f%element_nodes(1, e)
         n2 = f%element_nodes(2, e)
         de = [d(:, n1), d(:, n2)]
         energy(f%element_group(e)) = energy(f%element_group(e)) - dot_product(de, &
            matmul(beam_global_geometric(axial(e), f%node_x(n1), f%node_z(n1), f%node_x(n2), f%node_z(n2), kind), de))
      end do
      group = maxloc(energy, 1)

   contains

      !> Whether K + lambda G is positive definite (its banded Cholesky succeeds).
      logical function definite(lambda)
         real(dp), intent(in) :: lambda
         real(dp), allocatable :: ab(:, :)
         integer :: info

         ab = kb + lambda*gb
         call dpbtrf('U', f%n_dof, f%kd, ab, f%kd + 1, info)
         definite = info == 0
      end function definite

   end subroutine frame_buckling

   !> Refuse a frame that buckles under its gravity axial forces: K+G must be positive
   !> definite (dpbtrf), i.e. the lowest buckling factor > 1.
   subroutine check_frame_stability(f, axial, kind, error)
      !> The frame (with its constraints).
      type(frame_model), intent(in) :: f
      !> Axial force per element (kN), tension positive (from `frame_gravity`).
      real(dp), intent(in) :: axial(:)
      !> Kind of geometric stiffness (pound_frame_element).
      integer, intent(in) :: kind
      !> Set, naming the building, the factor and the column group, if the frame buckles.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: kb(:, :), gb(:, :)
      real(dp) :: factor
      integer :: group, info

      call frame_stiffness(f, kb)
      call frame_geometric(f, axial, kind, gb)
      kb = kb + gb
      call dpbtrf('U', f%n_dof, f%kd, kb, f%kd + 1, info)
      if (info == 0) return
      call frame_buckling(f, axial, kind, factor, group, error)
      if (allocated(error)) return
      call fatal_error(error, 'frame '//f%name//' buckles under its gravity loads: lowest buckling factor '// &
                       str(factor)//', must be > 1 (columns of storey '//str(group)//')'//buckling_hint)
   end subroutine check_frame_stability

end module pound_frame_gravity
