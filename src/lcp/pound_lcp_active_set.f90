!> Active-set method (block principal pivoting) for the LCP of elastic joints:
!> find z >= 0 with w = M z + q >= 0, z.w = 0, where M = F + diag(d) is symmetric positive
!> definite (F the condensed flexibility, d = 1/phat > 0), so that the solution is unique.
!>
!> The active set A (the joints carrying force) is kept from one call to the next together
!> with the Cholesky factor of M_AA (M_AA = R^T R, R upper triangular): F does not change
!> between steps of the same dt, so a step costs two triangular solves and one product
!> F(:, A) z_A, plus one factor update (O(|A|^2): a column appended, or one deleted and the
!> factor restored by Givens rotations) per joint that enters or leaves the set; no dense
!> tableau is formed.
!>
!> Iteration (Judice & Pires 1994, block principal pivoting for P-matrices): solve
!> M_AA z_A = -q_A, form w = q + M z for every joint, and exchange the violators (active
!> joints with z < 0, inactive ones with w < 0) all at once while their number decreases,
!> allowing `bpp_tries` exchanges that do not decrease it; then exchange only the violator
!> of largest index (Murty's rule, finite for P-matrices) until the number drops below the
!> best again. A cap on the iterations ends the method (`active_set_cycled`). A violation is
!> counted only beyond `tol` relative to ||q||_inf (z_k scaled by M_kk), so round-off does
!> not make joints enter and leave for ever; the result is verified afterwards: z is clipped
!> to z >= 0, w = M z + q recomputed from F, d and q (not from the factor), and the natural
!> residual ||min(z, w)||_inf / ||q||_inf returned.
!>
!> Each joint has a role: 0 ignored (z = 0, not checked: e.g. fractured), 1 may carry force,
!> 2 must stay open (w >= 0; it may not enter the set: a joint of another law, which the
!> caller solves by another method: `active_set_blocked` when it would close).
!>
!> All storage lives in an `active_set_workspace` sized once (`active_set_init`); the solve
!> allocates nothing.
module pound_lcp_active_set
   use pound_kinds, only: dp
   implicit none
   private

   public :: active_set_workspace, active_set_report, active_set_init, active_set_solve
   public :: active_set_forget
   public :: active_set_solved, active_set_not_spd, active_set_cycled, active_set_blocked

   !> Solved: every violation within the tolerance.
   integer, parameter :: active_set_solved = 0
   !> A factor update met a pivot that is not positive (M_AA numerically not positive definite).
   integer, parameter :: active_set_not_spd = 1
   !> The iteration cap was reached.
   integer, parameter :: active_set_cycled = 2
   !> A joint of role 2 would close (w < 0).
   integer, parameter :: active_set_blocked = 3
   !> Full exchanges allowed that do not reduce the number of violators.
   integer, parameter :: bpp_tries = 3

   !> The active set, its Cholesky factor and the work arrays (sized once).
   type :: active_set_workspace
      !> Largest number of joints (-1: not initialised).
      integer :: m_max = -1
      !> Size of the active set.
      integer :: na = 0
      !> `r` holds the factor of M_AA for `aset(1:na)` (false: rebuilt at the next solve).
      logical :: factored = .false.
      !> Relative tolerance of a violation (of ||q||_inf).
      real(dp) :: tol = 1.0e-13_dp
      !> Iteration cap (0: max(50, 2 m)).
      integer :: max_iter = 0
      !> Joints of the active set in factor order, and each joint's position in it (0: not in).
      integer, allocatable :: aset(:), pos(:)
      !> Upper Cholesky factor R of M_AA (leading na x na).
      real(dp), allocatable :: r(:, :)
      !> Work: reduced right-hand side/solution, a new column, the violators.
      real(dp), allocatable :: za(:), col(:)
      integer, allocatable :: viol(:)
   end type active_set_workspace

   !> Outcome of one `active_set_solve`.
   type :: active_set_report
      !> `active_set_solved`, `active_set_not_spd`, `active_set_cycled` or `active_set_blocked`.
      integer :: status = active_set_cycled
      !> Reduced solves (iterations) and factor updates (columns appended or deleted).
      integer :: iterations = 0, updates = 0
      !> Natural residual ||min(z, w)||_inf / ||q||_inf of the returned z (w recomputed).
      real(dp) :: residual = huge(1.0_dp)
   end type active_set_report

contains

   !> Allocate the workspace for up to `m_max` joints; the active set starts empty.
   pure subroutine active_set_init(ws, m_max)
      !> The workspace.
      type(active_set_workspace), intent(out) :: ws
      !> Largest number of joints.
      integer, intent(in) :: m_max
      integer :: n

      n = max(m_max, 1)
      allocate (ws%aset(n), ws%pos(n), ws%r(n, n), ws%za(n), ws%col(n), ws%viol(n))
      ws%pos = 0
      ws%m_max = m_max
   end subroutine active_set_init

   !> Mark the factor stale (the matrix changed, e.g. another dt): the set is kept as the
   !> next guess and refactored at the next solve.
   pure subroutine active_set_forget(ws)
      !> The workspace.
      type(active_set_workspace), intent(inout) :: ws

      ws%factored = .false.
   end subroutine active_set_forget

   !> Solve LCP(F + diag(d), q) over joints 1..m, starting from the active set `guess`
   !> (the joints with guess true and role 1; the set and factor of the previous call are
   !> updated to it, not rebuilt). F, d and m must be those of the previous call unless
   !> `active_set_forget` was called since (a stale factor is caught by the residual, which
   !> is computed from F, d and q, but the solve is then wasted).
   pure subroutine active_set_solve(ws, m, f, d, q, role, guess, z, w, report)
      !> Workspace from `active_set_init` (m_max >= m).
      type(active_set_workspace), intent(inout) :: ws
      !> Number of joints.
      integer, intent(in) :: m
      !> Symmetric part F (m, m) and diagonal addend d (m): M = F + diag(d), SPD on role 1.
      real(dp), intent(in) :: f(:, :), d(:)
      !> The vector q (m).
      real(dp), intent(in) :: q(:)
      !> Role of each joint: 0 ignored, 1 may carry force, 2 must stay open.
      integer, intent(in) :: role(:)
      !> Initial guess of the active set.
      logical, intent(in) :: guess(:)
      !> Solution z (m; 0 where inactive) and w = M z + q (m; 0 where ignored).
      real(dp), intent(inout) :: z(:), w(:)
      !> Status, iterations, updates, residual.
      type(active_set_report), intent(out) :: report
      integer :: k, j, p, it, cap, nv, best, tries
      real(dp) :: qn, res
      logical :: ok

      qn = 0.0_dp
      do k = 1, m
         if (role(k) /= 0) qn = max(qn, abs(q(k)))
      end do
      qn = max(qn, tiny(1.0_dp))
      cap = ws%max_iter
      if (cap <= 0) cap = max(50, 2*m)

      ! The set of the previous call, refactored if stale, then brought to the guess.
      if (.not. ws%factored) then
         nv = ws%na
         ws%viol(1:nv) = ws%aset(1:nv)
         ws%na = 0
         ws%pos = 0
         do j = 1, nv
            if (ws%viol(j) > m) cycle
            call append(ws, m, f, d, ws%viol(j), ok)
            report%updates = report%updates + 1
            if (.not. ok) exit
         end do
         ws%factored = .true.
      end if
      j = ws%na
      do while (j >= 1)
         k = ws%aset(j)
         if (k > m) then
            call delete(ws, j)
            report%updates = report%updates + 1
         else if (.not. (guess(k) .and. role(k) == 1)) then
            call delete(ws, j)
            report%updates = report%updates + 1
         end if
         j = j - 1
      end do
      do k = 1, m
         if (guess(k) .and. role(k) == 1 .and. ws%pos(k) == 0) then
            call append(ws, m, f, d, k, ok)
            report%updates = report%updates + 1
            if (.not. ok) then
               report%status = active_set_not_spd
               return
            end if
         end if
      end do

      best = m + 1
      tries = bpp_tries
      do it = 1, cap
         report%iterations = it
         call reduced_solve(ws, q)
         call evaluate(ws, m, f, d, q, role, z, w)
         ! Violators, in increasing joint order.
         nv = 0
         do k = 1, m
            select case (role(k))
            case (1)
               if (ws%pos(k) > 0) then
                  if (z(k)*(f(k, k) + d(k)) < -ws%tol*qn) then
                     nv = nv + 1
                     ws%viol(nv) = k
                  end if
               else if (w(k) < -ws%tol*qn) then
                  nv = nv + 1
                  ws%viol(nv) = k
               end if
            case (2)
               if (w(k) < -ws%tol*qn) then
                  report%status = active_set_blocked
                  return
               end if
            end select
         end do
         if (nv == 0) then
            report%status = active_set_solved
            exit
         end if
         if (nv < best) then
            best = nv
            tries = bpp_tries
         else if (tries > 0) then
            tries = tries - 1
         else
            ! Murty's rule: only the violator of largest index.
            ws%viol(1) = ws%viol(nv)
            nv = 1
         end if
         do j = 1, nv
            k = ws%viol(j)
            p = ws%pos(k)
            if (p > 0) then
               call delete(ws, p)
            else
               call append(ws, m, f, d, k, ok)
               if (.not. ok) then
                  report%status = active_set_not_spd
                  report%updates = report%updates + j
                  return
               end if
            end if
         end do
         report%updates = report%updates + nv
      end do
      if (report%status /= active_set_solved) return

      ! Verification: z >= 0, w = M z + q from the data, natural residual.
      if (any(z(1:m) < 0.0_dp)) then
         do k = 1, m
            z(k) = max(z(k), 0.0_dp)
         end do
         call evaluate_from(ws, m, f, d, q, role, z, w)
      end if
      res = 0.0_dp
      do k = 1, m
         if (role(k) /= 0) res = max(res, abs(min(z(k), w(k))))
      end do
      report%residual = res/qn
   end subroutine active_set_solve

   !> z_A = -M_AA^{-1} q_A by the factor: R^T y = -q_A, R z_A = y (in ws%za).
   pure subroutine reduced_solve(ws, q)
      type(active_set_workspace), intent(inout) :: ws
      real(dp), intent(in) :: q(:)
      integer :: j, na

      na = ws%na
      do j = 1, na
         ws%za(j) = (-q(ws%aset(j)) - dot_product(ws%r(1:j - 1, j), ws%za(1:j - 1)))/ws%r(j, j)
      end do
      do j = na, 1, -1
         ws%za(j) = ws%za(j)/ws%r(j, j)
         if (j > 1) ws%za(1:j - 1) = ws%za(1:j - 1) - ws%r(1:j - 1, j)*ws%za(j)
      end do
   end subroutine reduced_solve

   !> z from the reduced solution (0 off the set) and w = q + F z + d z.
   pure subroutine evaluate(ws, m, f, d, q, role, z, w)
      type(active_set_workspace), intent(in) :: ws
      integer, intent(in) :: m
      real(dp), intent(in) :: f(:, :), d(:), q(:)
      integer, intent(in) :: role(:)
      real(dp), intent(inout) :: z(:), w(:)
      integer :: j

      z(1:m) = 0.0_dp
      do j = 1, ws%na
         z(ws%aset(j)) = ws%za(j)
      end do
      call evaluate_from(ws, m, f, d, q, role, z, w)
   end subroutine evaluate

   !> w = q + F z + d z over the active set's columns; 0 for ignored joints.
   pure subroutine evaluate_from(ws, m, f, d, q, role, z, w)
      type(active_set_workspace), intent(in) :: ws
      integer, intent(in) :: m
      real(dp), intent(in) :: f(:, :), d(:), q(:)
      integer, intent(in) :: role(:)
      real(dp), intent(in) :: z(:)
      real(dp), intent(inout) :: w(:)
      integer :: j, k

      w(1:m) = q(1:m)
      do j = 1, ws%na
         k = ws%aset(j)
         if (z(k) /= 0.0_dp) w(1:m) = w(1:m) + f(1:m, k)*z(k)
      end do
      do j = 1, ws%na
         k = ws%aset(j)
         w(k) = w(k) + d(k)*z(k)
      end do
      do k = 1, m
         if (role(k) == 0) w(k) = 0.0_dp
      end do
   end subroutine evaluate_from

   !> Append joint k to the set: R^T c = M_A,k, rho = sqrt(M_kk - c.c). `ok` false (set
   !> unchanged) when rho^2 is not positive beyond round-off.
   pure subroutine append(ws, m, f, d, k, ok)
      type(active_set_workspace), intent(inout) :: ws
      integer, intent(in) :: m, k
      real(dp), intent(in) :: f(:, :), d(:)
      logical, intent(out) :: ok
      integer :: j, na
      real(dp) :: mkk, rho2

      na = ws%na
      ok = .false.
      if (na >= m) return
      do j = 1, na
         ws%col(j) = (f(ws%aset(j), k) - dot_product(ws%r(1:j - 1, j), ws%col(1:j - 1)))/ws%r(j, j)
      end do
      mkk = f(k, k) + d(k)
      rho2 = mkk - dot_product(ws%col(1:na), ws%col(1:na))
      if (.not. (rho2 > 1.0e-12_dp*mkk)) return
      ws%r(1:na, na + 1) = ws%col(1:na)
      ws%r(na + 1, na + 1) = sqrt(rho2)
      ws%na = na + 1
      ws%aset(na + 1) = k
      ws%pos(k) = na + 1
      ok = .true.
   end subroutine append

   !> Delete position p from the set: drop column p of R and restore the upper triangle by
   !> Givens rotations on rows p..na. `p` must not be a part of `ws` (it changes `ws%pos`).
   pure subroutine delete(ws, p)
      type(active_set_workspace), intent(inout) :: ws
      integer, intent(in) :: p
      integer :: j, l, na
      real(dp) :: a, b, h, c, s, t1, t2

      na = ws%na
      ws%pos(ws%aset(p)) = 0
      do j = p + 1, na
         ws%r(1:j, j - 1) = ws%r(1:j, j)
         ws%aset(j - 1) = ws%aset(j)
         ws%pos(ws%aset(j - 1)) = j - 1
      end do
      ! Column j (p <= j < na) now has a subdiagonal entry in row j + 1.
      do j = p, na - 1
         a = ws%r(j, j)
         b = ws%r(j + 1, j)
         h = hypot(a, b)
         c = a/h
         s = b/h
         ws%r(j, j) = h
         ws%r(j + 1, j) = 0.0_dp
         do l = j + 1, na - 1
            t1 = ws%r(j, l)
            t2 = ws%r(j + 1, l)
            ws%r(j, l) = c*t1 + s*t2
            ws%r(j + 1, l) = c*t2 - s*t1
         end do
      end do
      ws%na = na - 1
   end subroutine delete

end module pound_lcp_active_set
