!> Lemke's complementary pivoting method for the linear complementarity problem.
!>
!> LCP(M, q): find z >= 0 such that w = M z + q >= 0 and z.w = 0, M dense m x m.
!>
!> The method (Lemke 1965; Cottle, Pang & Stone, *The Linear Complementarity Problem*,
!> section 4.4) augments the system with an artificial variable z0 and the covering
!> vector d = e (all ones):  w - M z - e z0 = q.  Starting from the basis of all w with
!> z0 = -min(q), it follows the almost complementary path by alternating the entering
!> variable with the complement of the variable that just left, until z0 leaves the
!> basis (a solution), the entering column has no positive entry (ray termination), or
!> the pivot cap is reached. Ray termination proves that no solution exists when M is
!> copositive-plus (e.g. positive semidefinite, not necessarily symmetric); for a
!> P-matrix (e.g. symmetric positive definite) the method always solves.
!>
!> Implementation: the inverse B^-1 of the basis and the basic values B^-1 q are kept
!> explicitly (revised tableau), so a pivot costs O(m^2) and the solve allocates
!> nothing: all storage lives in a `lemke_workspace` sized once for the largest m.
!> Degenerate steps are resolved by the lexicographic minimum-ratio rule on the rows
!> of [B^-1 q, B^-1] (equivalent to perturbing q by (eps, eps^2, ..., eps^m)), which
!> rules out cycling; if z0 is among the tied rows it leaves at once (this ends the
!> path, so it cannot cycle). Every result is checked against the original data: w is
!> recomputed as M z + q and the natural residual ||min(z, w)||_inf / ||q||_inf is
!> reported. A solution read off the final tableau is also recomputed from its active
!> set A = {i: z_i basic} by solving M_AA z_A = -q_A (LU with partial pivoting); the
!> better of the two, by natural residual, is returned.
!>
!> Tolerances are relative, so the solver is invariant to the units of M and q:
!> an entry d_i of the entering column B^-1 a qualifies as a pivot only if
!> d_i > pivot_tol * ||row i of B^-1||_1 * ||a||_inf (the bound that |d_i| would reach
!> without cancellation, so residues of exact cancellation are rejected); two ratios
!> tie when they differ by less than ratio_tol times the analogous bound for the
!> compared quantities.
!>
!> Data must be finite. Usage:
!>
!>     type(lemke_workspace) :: ws
!>     type(lemke_report) :: rep
!>     call lemke_init(ws, m_max)
!>     ...  ! per time step:
!>     call lemke_solve(ws, m, mat, q, z, w, rep, active_guess=z_prev > 0)
!>     if (rep%residual > 1.0e-10_dp) ...  ! or: if (.not. rep%ok) ...
module pound_lemke
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   implicit none
   private

   public :: lemke_workspace, lemke_report
   public :: lemke_init, lemke_solve, lemke_status_name
   public :: lcp_evaluate, lcp_principal_solve
   public :: lemke_solved, lemke_trivial, lemke_ray, lemke_max_iter, lemke_invalid

   !> The artificial variable left the basis: (z, w) solves the LCP (see `residual`).
   integer, parameter :: lemke_solved = 0
   !> q >= 0: z = 0, w = q, no pivot.
   integer, parameter :: lemke_trivial = 1
   !> Ray termination: the entering column had no admissible pivot (`ray_variable`).
   !> For copositive-plus M this proves that the LCP has no solution.
   integer, parameter :: lemke_ray = 2
   !> The pivot cap was reached (cycling or exponential path); no solution returned.
   integer, parameter :: lemke_max_iter = 3
   !> Invalid call: m outside 0..m_max, arrays too small, or workspace not initialised.
   integer, parameter :: lemke_invalid = 4

   !> Storage and settings of the solver, sized once for the largest problem.
   !>
   !> The tolerances may be changed after `lemke_init` (which sets the defaults).
   type :: lemke_workspace
      !> Largest problem size the storage holds (-1: not initialised).
      integer :: m_max = -1
      !> Relative pivot tolerance (Lemke pivots and LU of principal submatrices).
      real(dp) :: pivot_tol = 1.0e-11_dp
      !> Relative tolerance for ties in the (lexicographic) ratio test.
      real(dp) :: ratio_tol = 1.0e-11_dp
      !> A warm-start guess is accepted if its natural residual is at most this.
      real(dp) :: warm_tol = 1.0e-12_dp
      !> `report%ok` requires a natural residual at most this.
      real(dp) :: ok_tol = 1.0e-10_dp
      !> Re-solve the final active set by LU and keep the more accurate result.
      logical :: polish = .true.
      !> Basis inverse B^-1 (leading m x m part used).
      real(dp), allocatable :: binv(:, :)
      !> LU factors of a principal submatrix.
      real(dp), allocatable :: lu(:, :)
      !> Basic values B^-1 q.
      real(dp), allocatable :: xb(:)
      !> Entering column B^-1 a.
      real(dp), allocatable :: col(:)
      !> 1-norms of the rows of B^-1.
      real(dp), allocatable :: rnorm(:)
      !> Right-hand side / solution of the principal subsystem.
      real(dp), allocatable :: rhs(:)
      !> Polished solution candidate and its w.
      real(dp), allocatable :: zp(:), wp(:)
      !> Variable basic in each row: 1..m w_i, m+1..2m z_i, 2m+1 z0.
      integer, allocatable :: basis(:)
      !> Candidate rows of the ratio test.
      integer, allocatable :: cand(:)
      !> Indices of the active set / LU row permutation.
      integer, allocatable :: idx(:), ipiv(:)
      !> Active-set flags of the final basis.
      logical, allocatable :: active(:)
   end type lemke_workspace

   !> Outcome of one `lemke_solve`.
   type :: lemke_report
      !> One of `lemke_solved`, `lemke_trivial`, `lemke_ray`, `lemke_max_iter`, `lemke_invalid`.
      integer :: status = lemke_invalid
      !> Basis exchanges made, counting the first (z0 enters) and the last (z0 leaves).
      integer :: pivots = 0
      !> Natural residual ||min(z, w)||_inf / max(||q||_inf, tiny) of the returned z,
      !> with w = M z + q recomputed from the data.
      real(dp) :: residual = huge(1.0_dp)
      !> The active-set guess was accepted (no pivot made).
      logical :: warm_started = .false.
      !> On ray termination, the entering variable: +i for z_i, -i for w_i.
      integer :: ray_variable = 0
      !> Convenience: status solved or trivial and residual <= `ok_tol`.
      logical :: ok = .false.
   end type lemke_report

contains

   !> Allocate the workspace for problems of up to `m_max` constraints and set the
   !> default tolerances (change them afterwards if needed).
   !>
   !> A negative `m_max` leaves the workspace unusable (every solve reports
   !> `lemke_invalid`) and sets `error` if present.
   pure subroutine lemke_init(ws, m_max, error)
      !> Workspace to (re)initialise.
      type(lemke_workspace), intent(out) :: ws
      !> Largest number of constraints that will be solved (>= 0).
      integer, intent(in) :: m_max
      !> Set if `m_max` is negative or the storage cannot be allocated.
      type(error_type), allocatable, intent(out), optional :: error
      integer :: n, stat

      if (m_max < 0) then
         if (present(error)) call fatal_error(error, 'lemke_init: m_max must be >= 0, got '//str(m_max))
         return
      end if
      n = max(m_max, 1)
      allocate (ws%binv(n, n), ws%lu(n, n), ws%xb(n), ws%col(n), ws%rnorm(n), ws%rhs(n), &
                ws%zp(n), ws%wp(n), ws%basis(n), ws%cand(n), ws%idx(n), ws%ipiv(n), ws%active(n), &
                stat=stat)
      if (stat /= 0) then
         if (allocated(ws%binv)) deallocate (ws%binv)
         if (present(error)) call fatal_error(error, 'lemke_init: cannot allocate the workspace for '// &
                                              str(m_max)//' rows')
         return
      end if
      ws%m_max = m_max
   end subroutine lemke_init

   !> Solve LCP(mat(1:m,1:m), q(1:m)) by Lemke's method (covering vector e).
   !>
   !> With `active_guess`, the principal system M_AA z_A = -q_A of the guessed active
   !> set A is solved first and accepted (no pivot, `warm_started`) if its natural
   !> residual is at most `ws%warm_tol`; otherwise Lemke runs from scratch.
   !> On `lemke_ray` / `lemke_max_iter`, z is the z-part of the last almost complementary
   !> point (z0 > 0) and w = M z + q: not a solution, `ok` is false.
   pure subroutine lemke_solve(ws, m, mat, q, z, w, report, active_guess, lexicographic, max_pivots)
      !> Workspace from `lemke_init` with m_max >= m.
      type(lemke_workspace), intent(inout) :: ws
      !> Number of constraints (0 <= m <= ws%m_max).
      integer, intent(in) :: m
      !> The matrix M in mat(1:m, 1:m).
      real(dp), intent(in) :: mat(:, :)
      !> The vector q in q(1:m).
      real(dp), intent(in) :: q(:)
      !> Solution z in z(1:m) (entries beyond m are not touched).
      real(dp), intent(inout) :: z(:)
      !> w = M z + q, recomputed from mat and q, in w(1:m).
      real(dp), intent(inout) :: w(:)
      !> Status, pivots and accuracy of the result.
      type(lemke_report), intent(out) :: report
      !> Guess of the active set {i: z_i > 0}, e.g. from the previous step.
      logical, intent(in), optional :: active_guess(:)
      !> Lexicographic ratio rule (default true); false: plain minimum ratio with ties
      !> broken by the smallest variable index (w_1..w_m before z_1..z_m; may cycle).
      logical, intent(in), optional :: lexicographic
      !> Pivot cap (default 50 (m + 1)).
      integer, intent(in), optional :: max_pivots
      logical :: lex, nonsingular
      integer :: cap, i, v
      real(dp) :: res, res_p

      if (.not. allocated(ws%binv) .or. m < 0 .or. m > ws%m_max .or. size(mat, 1) < m &
          .or. size(mat, 2) < m .or. size(q) < m .or. size(z) < m .or. size(w) < m) return
      if (present(active_guess)) then
         if (size(active_guess) < m) return
      end if

      z(1:m) = 0.0_dp
      w(1:m) = q(1:m)
      if (all(q(1:m) >= 0.0_dp)) then
         report%status = lemke_trivial
         report%residual = 0.0_dp
         report%ok = .true.
         return
      end if

      if (present(active_guess)) then
         call lcp_principal_solve(ws, m, mat, q, active_guess(1:m), z, w, res, nonsingular)
         if (nonsingular .and. res <= ws%warm_tol) then
            report%status = lemke_solved
            report%warm_started = .true.
            report%residual = res
            report%ok = res <= ws%ok_tol
            return
         end if
      end if

      lex = .true.
      if (present(lexicographic)) lex = lexicographic
      cap = 50*(m + 1)
      if (present(max_pivots)) cap = max(max_pivots, 0)

      call run_lemke(ws, m, mat, q, lex, cap, report)

      z(1:m) = 0.0_dp
      do i = 1, m
         v = ws%basis(i)
         if (v > m .and. v <= 2*m) z(v - m) = max(ws%xb(i), 0.0_dp)
      end do
      call lcp_evaluate(m, mat, q, z, w, res)

      if (report%status == lemke_solved .and. ws%polish .and. res > 0.0_dp) then
         ws%active(1:m) = .false.
         do i = 1, m
            v = ws%basis(i)
            if (v > m .and. v <= 2*m) ws%active(v - m) = .true.
         end do
         call principal_core(m, mat, q, ws%active, ws%pivot_tol, ws%lu, ws%rhs, ws%idx, ws%ipiv, &
                             ws%zp, ws%wp, res_p, nonsingular)
         if (nonsingular .and. res_p < res) then
            z(1:m) = ws%zp(1:m)
            w(1:m) = ws%wp(1:m)
            res = res_p
         end if
      end if
      report%residual = res
      report%ok = report%status == lemke_solved .and. res <= ws%ok_tol
   end subroutine lemke_solve

   !> Name of a status code: 'solved', 'trivial', 'ray', 'max_iter', 'invalid' or 'unknown'.
   pure function lemke_status_name(status) result(name)
      !> A `lemke_*` status constant.
      integer, intent(in) :: status
      character(len=:), allocatable :: name

      select case (status)
      case (lemke_solved)
         name = 'solved'
      case (lemke_trivial)
         name = 'trivial'
      case (lemke_ray)
         name = 'ray'
      case (lemke_max_iter)
         name = 'max_iter'
      case (lemke_invalid)
         name = 'invalid'
      case default
         name = 'unknown'
      end select
   end function lemke_status_name

   !> w = M z + q and the natural residual ||min(z, w)||_inf / max(||q||_inf, tiny).
   !>
   !> The residual is zero exactly for solutions; it measures the violation of z >= 0,
   !> w >= 0 and complementarity together, relative to the size of q.
   pure subroutine lcp_evaluate(m, mat, q, z, w, residual)
      !> Number of constraints.
      integer, intent(in) :: m
      !> The matrix M in mat(1:m, 1:m).
      real(dp), intent(in) :: mat(:, :)
      !> The vector q in q(1:m).
      real(dp), intent(in) :: q(:)
      !> The point z in z(1:m).
      real(dp), intent(in) :: z(:)
      !> M z + q in w(1:m).
      real(dp), intent(inout) :: w(:)
      !> Natural residual, relative to ||q||_inf.
      real(dp), intent(out) :: residual
      integer :: i, j
      real(dp) :: qn

      w(1:m) = q(1:m)
      do j = 1, m
         if (abs(z(j)) > 0.0_dp) w(1:m) = w(1:m) + mat(1:m, j)*z(j)
      end do
      residual = 0.0_dp
      qn = 0.0_dp
      do i = 1, m
         residual = max(residual, abs(min(z(i), w(i))))
         qn = max(qn, abs(q(i)))
      end do
      residual = residual/max(qn, tiny(1.0_dp))
   end subroutine lcp_evaluate

   !> Solve the principal system of an active set: z_A = -M_AA^-1 q_A, z_N = 0.
   !>
   !> Negative components of z_A are set to zero, w = M z + q is recomputed and the natural
   !> residual returned, so a small residual certifies (z, w) as a solution whatever the
   !> active set was. `nonsingular` is false (and z = 0, w = q, residual huge) when
   !> M_AA has a pivot below `ws%pivot_tol` times its largest entry.
   pure subroutine lcp_principal_solve(ws, m, mat, q, active, z, w, residual, nonsingular)
      !> Workspace from `lemke_init` with m_max >= m (uses its LU storage).
      type(lemke_workspace), intent(inout) :: ws
      !> Number of constraints.
      integer, intent(in) :: m
      !> The matrix M in mat(1:m, 1:m).
      real(dp), intent(in) :: mat(:, :)
      !> The vector q in q(1:m).
      real(dp), intent(in) :: q(:)
      !> Active set: z_i may be nonzero where true.
      logical, intent(in) :: active(:)
      !> Solution candidate in z(1:m).
      real(dp), intent(inout) :: z(:)
      !> M z + q in w(1:m).
      real(dp), intent(inout) :: w(:)
      !> Natural residual of (z, w) (see `lcp_evaluate`).
      real(dp), intent(out) :: residual
      !> The principal submatrix was numerically nonsingular.
      logical, intent(out) :: nonsingular

      call principal_core(m, mat, q, active, ws%pivot_tol, ws%lu, ws%rhs, ws%idx, ws%ipiv, &
                          z, w, residual, nonsingular)
   end subroutine lcp_principal_solve

   pure subroutine principal_core(m, mat, q, active, pivot_tol, lu, rhs, idx, ipiv, z, w, &
                                  residual, nonsingular)
      integer, intent(in) :: m
      real(dp), intent(in) :: mat(:, :), q(:)
      logical, intent(in) :: active(:)
      real(dp), intent(in) :: pivot_tol
      real(dp), intent(inout) :: lu(:, :), rhs(:)
      integer, intent(inout) :: idx(:), ipiv(:)
      real(dp), intent(inout) :: z(:), w(:)
      real(dp), intent(out) :: residual
      logical, intent(out) :: nonsingular
      integer :: i, j, k, na, p
      real(dp) :: amax, t

      na = 0
      do i = 1, m
         if (active(i)) then
            na = na + 1
            idx(na) = i
         end if
      end do
      z(1:m) = 0.0_dp
      nonsingular = .true.
      if (na > 0) then
         amax = 0.0_dp
         do j = 1, na
            do i = 1, na
               lu(i, j) = mat(idx(i), idx(j))
               amax = max(amax, abs(lu(i, j)))
            end do
            rhs(j) = -q(idx(j))
         end do
         ! LU with partial pivoting, a pivot below pivot_tol * max|M_AA| counts as zero.
         do k = 1, na
            p = k
            do i = k + 1, na
               if (abs(lu(i, k)) > abs(lu(p, k))) p = i
            end do
            ipiv(k) = p
            if (.not. (abs(lu(p, k)) > pivot_tol*amax)) then
               nonsingular = .false.
               exit
            end if
            if (p /= k) then
               do j = 1, na
                  t = lu(k, j)
                  lu(k, j) = lu(p, j)
                  lu(p, j) = t
               end do
            end if
            lu(k + 1:na, k) = lu(k + 1:na, k)/lu(k, k)
            do j = k + 1, na
               if (abs(lu(k, j)) > 0.0_dp) lu(k + 1:na, j) = lu(k + 1:na, j) - lu(k + 1:na, k)*lu(k, j)
            end do
         end do
         if (.not. nonsingular) then
            w(1:m) = q(1:m)
            residual = huge(1.0_dp)
            return
         end if
         do k = 1, na
            p = ipiv(k)
            if (p /= k) then
               t = rhs(k)
               rhs(k) = rhs(p)
               rhs(p) = t
            end if
         end do
         do k = 1, na
            if (abs(rhs(k)) > 0.0_dp) rhs(k + 1:na) = rhs(k + 1:na) - lu(k + 1:na, k)*rhs(k)
         end do
         do k = na, 1, -1
            rhs(k) = rhs(k)/lu(k, k)
            if (abs(rhs(k)) > 0.0_dp) rhs(1:k - 1) = rhs(1:k - 1) - lu(1:k - 1, k)*rhs(k)
         end do
         do k = 1, na
            z(idx(k)) = max(rhs(k), 0.0_dp)
         end do
      end if
      call lcp_evaluate(m, mat, q, z, w, residual)
   end subroutine principal_core

   !> Lemke's pivoting from the all-w basis; leaves basis/xb in ws and fills
   !> status, pivots and ray_variable of the report.
   pure subroutine run_lemke(ws, m, mat, q, lex, cap, report)
      type(lemke_workspace), intent(inout) :: ws
      integer, intent(in) :: m
      real(dp), intent(in) :: mat(:, :), q(:)
      logical, intent(in) :: lex
      integer, intent(in) :: cap
      type(lemke_report), intent(inout) :: report
      integer :: i, nc, r, entering, leaving, z0, row_z0
      real(dp) :: qn, amax, tol

      z0 = 2*m + 1
      qn = maxval(abs(q(1:m)))
      ws%binv(1:m, 1:m) = 0.0_dp
      do i = 1, m
         ws%binv(i, i) = 1.0_dp
         ws%basis(i) = i
      end do
      ws%xb(1:m) = q(1:m)
      ws%rnorm(1:m) = 1.0_dp
      row_z0 = 0
      report%pivots = 0
      entering = z0

      do
         if (report%pivots >= cap) then
            report%status = lemke_max_iter
            return
         end if

         ! Entering column d = B^-1 a and amax = ||a||_inf.
         call entering_column(m, size(ws%binv, 1), entering, mat, ws%binv, ws%col, amax)
         associate (d => ws%col)

            nc = 0
            if (entering == z0 .and. row_z0 == 0) then
               ! First pivot: column -e, z0 rises to -min(q); every row is a candidate and
               ! the lexicographic minimum of the rows (q_i, e_i) leaves.
               do i = 1, m
                  nc = nc + 1
                  ws%cand(nc) = i
               end do
            else
               do i = 1, m
                  tol = ws%pivot_tol*ws%rnorm(i)*amax
                  if (d(i) > tol) then
                     nc = nc + 1
                     ws%cand(nc) = i
                  end if
               end do
            end if
         end associate
         if (nc == 0) then
            report%status = lemke_ray
            if (entering <= m) then
               report%ray_variable = -entering
            else
               report%ray_variable = entering - m
            end if
            return
         end if

         call leaving_row(ws, m, nc, qn, row_z0, lex, r)
         leaving = ws%basis(r)
         call pivot(ws, m, r)
         ws%basis(r) = entering
         report%pivots = report%pivots + 1
         if (entering == z0) row_z0 = r
         if (leaving == z0) then
            report%status = lemke_solved
            return
         end if
         if (leaving <= m) then
            entering = leaving + m
         else
            entering = leaving - m
         end if
      end do
   end subroutine run_lemke

   !> Row leaving the basis among the candidates ws%cand(1:nc), for the entering column in
   !> ws%col: the lexicographic minimum of (xb_i, B^-1(i, :)) / |d_i| (z0 first if it ties
   !> in the plain ratio); without `lex`, the smallest variable index among the ties.
   pure subroutine leaving_row(ws, m, nc_in, qn, row_z0, lex, r)
      type(lemke_workspace), intent(inout) :: ws
      integer, intent(in) :: m, nc_in, row_z0
      real(dp), intent(in) :: qn
      logical, intent(in) :: lex
      integer, intent(out) :: r
      integer :: i, j, k, l, nc, best
      real(dp) :: vmin, tmin, v, t

      nc = nc_in
      ! Plain ratio xb_i / |d_i|; the bound on the rounding error of xb_i is
      ! ratio_tol * ||B^-1(i,:)||_1 * ||q||_inf.
      best = ws%cand(1)
      vmin = ws%xb(best)/abs(ws%col(best))
      do l = 2, nc
         i = ws%cand(l)
         v = ws%xb(i)/abs(ws%col(i))
         if (v < vmin) then
            vmin = v
            best = i
         end if
      end do
      tmin = ws%ratio_tol*ws%rnorm(best)*qn/abs(ws%col(best))
      k = 0
      do l = 1, nc
         i = ws%cand(l)
         v = ws%xb(i)/abs(ws%col(i))
         t = ws%ratio_tol*ws%rnorm(i)*qn/abs(ws%col(i))
         if (v - t <= vmin + tmin) then
            k = k + 1
            ws%cand(k) = i
         end if
      end do
      nc = k
      r = ws%cand(1)
      if (nc == 1) return
      if (row_z0 > 0) then
         do l = 1, nc
            if (ws%cand(l) == row_z0) then
               r = row_z0
               return
            end if
         end do
      end if
      if (.not. lex) then
         do l = 2, nc
            if (ws%basis(ws%cand(l)) < ws%basis(r)) r = ws%cand(l)
         end do
         return
      end if
      ! Lexicographic tie-break on the columns of B^-1 in order.
      do j = 1, m
         best = ws%cand(1)
         vmin = ws%binv(best, j)/abs(ws%col(best))
         do l = 2, nc
            i = ws%cand(l)
            v = ws%binv(i, j)/abs(ws%col(i))
            if (v < vmin) then
               vmin = v
               best = i
            end if
         end do
         tmin = ws%ratio_tol*ws%rnorm(best)/abs(ws%col(best))
         k = 0
         do l = 1, nc
            i = ws%cand(l)
            v = ws%binv(i, j)/abs(ws%col(i))
            t = ws%ratio_tol*ws%rnorm(i)/abs(ws%col(i))
            if (v - t <= vmin + tmin) then
               k = k + 1
               ws%cand(k) = i
            end if
         end do
         nc = k
         if (nc == 1) exit
      end do
      r = ws%cand(1)
   end subroutine leaving_row

   !> Entering column d = B^-1 a of variable `entering` (a = e_j for w_j, -M(:,j) for z_j,
   !> -e for z0) and amax = ||a||_inf.
   pure subroutine entering_column(m, ld, entering, mat, binv, d, amax)
      integer, intent(in) :: m, ld, entering
      real(dp), intent(in) :: mat(:, :), binv(ld, m)
      real(dp), intent(out) :: d(m), amax
      integer :: k
      real(dp) :: c

      if (entering <= m) then
         d = binv(1:m, entering)
         amax = 1.0_dp
      else if (entering <= 2*m) then
         d = 0.0_dp
         amax = 0.0_dp
         do k = 1, m
            c = mat(k, entering - m)
            amax = max(amax, abs(c))
            if (abs(c) > 0.0_dp) d = d - binv(1:m, k)*c
         end do
      else
         d = 0.0_dp
         do k = 1, m
            d = d - binv(1:m, k)
         end do
         amax = 1.0_dp
      end if
   end subroutine entering_column

   !> Pivot on row r of the entering column ws%col: update B^-1, B^-1 q and row norms.
   pure subroutine pivot(ws, m, r)
      type(lemke_workspace), intent(inout) :: ws
      integer, intent(in) :: m, r

      call pivot_update(m, size(ws%binv, 1), r, ws%col, ws%binv, ws%xb, ws%rnorm)
   end subroutine pivot

   !> Rank-one update of B^-1 (leading dimension ld) and B^-1 q for pivot row r of the
   !> entering column d; recomputes the row 1-norms of B^-1. Explicit-shape dummies:
   !> contiguous and unaliased, so the inner loops vectorise.
   pure subroutine pivot_update(m, ld, r, d, binv, xb, rn)
      integer, intent(in) :: m, ld, r
      real(dp), intent(inout) :: d(m), binv(ld, m), xb(m), rn(m)
      integer :: i, k
      real(dp) :: dr, t, sr

      dr = d(r)
      d(r) = 0.0_dp
      t = xb(r)/dr
      xb = xb - d*t
      xb(r) = t
      rn = 0.0_dp
      sr = 0.0_dp
      do k = 1, m
         t = binv(r, k)/dr
         if (abs(t) > 0.0_dp) then
            do i = 1, m
               binv(i, k) = binv(i, k) - d(i)*t
               rn(i) = rn(i) + abs(binv(i, k))
            end do
         else
            do i = 1, m
               rn(i) = rn(i) + abs(binv(i, k))
            end do
         end if
         binv(r, k) = t
         sr = sr + abs(t)
      end do
      rn(r) = sr
   end subroutine pivot_update

end module pound_lemke
