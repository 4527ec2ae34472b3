!> The step's LCP as pure procedures over the joint data: which rows it has, its matrix and
!> vector with the warm-start guess and the reference point, the closing of a constraint
!> left out of it, and the check of a solution on the full problem. The formulation is
!> described in `pound_contact`.
module pound_contact_lcp
   use pound_kinds, only: dp
   use pound_contact_pair, only: contact_pair
   use pound_joint_state, only: joint_state
   use pound_contact_law, only: is_plastic, yield_force, yield_segment
   use pound_lemke, only: lcp_evaluate
   implicit none
   private

   public :: lcp_layout, lcp_assemble, released_opening, lcp_residual

contains

   !> The rows of the LCP of the constraints in `in_lcp`: contact rows 1..na (`act(j)` the
   !> constraint of row j), then per plastic joint its yield row (`yrow(k)`, 0 for none)
   !> followed by its `nh(k)` segment-end rows; n rows in all.
   pure subroutine lcp_layout(pairs, in_lcp, nh, act, yrow, na, n)
      !> The constraints.
      type(contact_pair), intent(in) :: pairs(:)
      !> The constraints in the LCP and the segment ends modelled for each.
      logical, intent(in) :: in_lcp(:)
      integer, intent(in) :: nh(:)
      !> Constraint of each contact row (at least count(in_lcp) long).
      integer, intent(inout) :: act(:)
      !> Row of each constraint's yield variable (0: none).
      integer, intent(out) :: yrow(:)
      !> Contact rows and all rows.
      integer, intent(out) :: na, n
      integer :: j, k

      na = 0
      do k = 1, size(pairs)
         yrow(k) = 0
         if (.not. in_lcp(k)) cycle
         na = na + 1
         act(na) = k
      end do
      n = na
      do j = 1, na
         k = act(j)
         if (.not. is_plastic(pairs(k)%law)) cycle
         n = n + 1
         yrow(k) = n
         n = n + nh(k)
      end do
   end subroutine lcp_layout

   !> Assemble the n-row LCP of `lcp_layout`, the warm-start guess (rows active in the
   !> previous step) and the reference point (previous forces, no plastic flow); sets
   !> `nonconvex` when a softening segment enters.
   pure subroutine lcp_assemble(pairs, joints, f, phat, beta, rate_b, q, act, na, yrow, nh, n, mat, qa, &
                                guess, zref, nonconvex)
      !> The constraints and their joints' state at the start of the step.
      type(contact_pair), intent(in) :: pairs(:)
      type(joint_state), intent(in) :: joints(:)
      !> Condensed flexibility F (m, m).
      real(dp), intent(in) :: f(:, :)
      !> Per joint: phat = k0 + a c, beta = k0/phat, dashpot rate coefficient b.
      real(dp), intent(in) :: phat(:), beta(:), rate_b(:)
      !> Contact vector q of every constraint (m).
      real(dp), intent(in) :: q(:)
      !> The layout (`lcp_layout`).
      integer, intent(in) :: act(:), na, yrow(:), nh(:), n
      !> The LCP matrix (rows/columns 1..n set) and vector.
      real(dp), intent(inout) :: mat(:, :), qa(:)
      !> Warm-start guess.
      logical, intent(inout) :: guess(:)
      !> Reference point (for the choice among several solutions).
      real(dp), intent(inout) :: zref(:)
      !> Set when a softening segment is in the LCP.
      logical, intent(inout) :: nonconvex
      integer :: i, j, k, l, seg, iy
      real(dp) :: k0, rs

      mat(1:n, 1:n) = 0.0_dp
      do j = 1, na
         do i = 1, na
            mat(i, j) = f(act(i), act(j))
         end do
         k = act(j)
         mat(j, j) = mat(j, j) + 1.0_dp/phat(k)
         qa(j) = q(k)
         guess(j) = joints(k)%r > 0.0_dp
         zref(j) = joints(k)%r
      end do
      do j = 1, na
         k = act(j)
         iy = yrow(k)
         if (iy == 0) cycle
         associate (p => joints(k), law => pairs(k)%law, b => beta(k))
            k0 = law%stiffness
            seg = yield_segment(law, p%plastic)
            rs = k0*(p%d - p%plastic)
            mat(j, iy) = b/k0
            mat(iy, j) = -b/k0
            mat(iy, iy) = (law%yh(seg) + k0*(1.0_dp - b))/k0**2
            qa(iy) = (yield_force(law, p%plastic) - (1.0_dp - b)*rs - b*rate_b(k)*law%dashpot*p%ddot)/k0
            guess(iy) = p%x > 0.0_dp
            zref(iy) = 0.0_dp
            if (law%yh(seg) < 0.0_dp) nonconvex = .true.
            do l = 1, nh(k)
               i = iy + l
               mat(iy, i) = (law%yh(seg + l) - law%yh(seg + l - 1))/k0**2
               mat(i, iy) = -1.0_dp/k0
               mat(i, i) = 1.0_dp/k0
               qa(i) = law%yp(seg + l) - p%plastic
               guess(i) = .false.
               zref(i) = 0.0_dp
               if (law%yh(seg + l) < 0.0_dp) nonconvex = .true.
            end do
         end associate
      end do
   end subroutine lcp_assemble

   !> Opening w_k = q_k + F(k, act) z of constraint k under the forces z of the contact rows.
   pure real(dp) function released_opening(f, q, act, na, z, k) result(wk)
      !> Condensed flexibility and contact vector.
      real(dp), intent(in) :: f(:, :), q(:)
      !> Contact rows and their forces.
      integer, intent(in) :: act(:), na
      real(dp), intent(in) :: z(:)
      !> The constraint.
      integer, intent(in) :: k

      wk = q(k) + dot_product(f(k, act(1:na)), z(1:na))
   end function released_opening

   !> Natural residual ||min(z, w)||_inf / ||q||_inf of a solution on the full problem: the
   !> assembled rows and the constraints left out of it (not in `in_lcp`, not fractured),
   !> which must stay open.
   pure subroutine lcp_residual(n, mat, qa, za, wa, f, q, act, na, in_lcp, joints, qnorm, resid)
      !> Rows of the assembled LCP, its matrix, vector, solution and w (work).
      integer, intent(in) :: n
      real(dp), intent(in) :: mat(:, :), qa(:), za(:)
      real(dp), intent(inout) :: wa(:)
      !> Condensed flexibility and contact vector of every constraint.
      real(dp), intent(in) :: f(:, :), q(:)
      !> Contact rows.
      integer, intent(in) :: act(:), na
      !> The constraints in the LCP, and the joints (fractured ones carry nothing).
      logical, intent(in) :: in_lcp(:)
      type(joint_state), intent(in) :: joints(:)
      !> ||q||_inf of the constraints, raised to that of the LCP's vector.
      real(dp), intent(inout) :: qnorm
      !> The relative residual.
      real(dp), intent(out) :: resid
      integer :: k

      resid = 0.0_dp
      if (n > 0) then
         call lcp_evaluate(n, mat, qa, za, wa, resid)
         resid = resid*max(maxval(abs(qa(1:n))), tiny(1.0_dp))
      end if
      do k = 1, size(q)
         if (in_lcp(k) .or. joints(k)%fractured) cycle
         resid = max(resid, abs(min(0.0_dp, released_opening(f, q, act, na, za, k))))
      end do
      if (n > 0) qnorm = max(qnorm, maxval(abs(qa(1:n))))
      resid = resid/qnorm
   end subroutine lcp_residual

end module pound_contact_lcp
