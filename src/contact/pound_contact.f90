!> Unilateral constraints between facing floors, solved per time step as an LCP.
!>
!> Constraint k joins floor `floor(1)` of building `building(1)` (the one on the left,
!> whose displacement to the right closes the joint) and floor `floor(2)` of
!> `building(2)` (on the right); building 0 stands for a rigid, fixed neighbour. With
!> B the constraint incidence (+1 left, -1 right), the closing displacement is v = B^T u,
!> the contact forces act on the structure as -B r, and in the incremental Newmark step
!> u_{n+1} = u_n + du_pred - Khat^{-1} B (r_{n+1} - r_n). Condensed onto the constraints:
!>
!>   v_{n+1} = v_pred - F r_{n+1},  F = B^T Khat^{-1} B,  v_pred = B^T (u_n + du_pred) + F r_n.
!>
!> **Joint.** A spring (law of pound_contact_law: elastic stiffness k0, plastic penetration
!> d_p, yield force r_y(d_p)) with a dashpot c in parallel, in series with the gap g: the
!> open gap is w = g - v + d (d the joint's compression), the force r = k0 (d - d_p) + c d'.
!> The dashpot rate is d'_{n+1} = a (d_{n+1} - d_n) - b d'_n: (a, b) = (2/dt, 1) for the
!> trapezoidal rule, (1/dt, 0) for backward Euler. With phat = k0 + a c, beta = k0/phat
!> and the plastic increment x of the step (d_p,n+1 = d_p,n + x):
!>
!>   w = (F + diag(1/phat)) r + beta x + q,  q = g - v_pred + (c (a d_n + b d'_n) + k0 d_p,n)/phat,
!>   spring force r_s = beta r + (1 - beta) r_s,n + beta b c d'_n - k0 (1 - beta) x.
!>
!> **Plasticity (Maier).** The yield condition r_s <= r_y(d_p,n + x) with x >= 0 and
!> x (r_y - r_s) = 0 is one complementarity pair per joint; r_y is piecewise linear,
!> r_y(d_p,n + x) = r_y(d_p,n) + h_c x + sum_i (h_{c+i} - h_{c+i-1}) t_i with hinge variables
!> t_i = max(0, x - x_i) (x_i the distance to node c+i), each one more pair
!> (t_i >= 0, t_i - x + x_i >= 0, product 0). All rows are written in metres with the
!> plastic variables scaled to kN (X = k0 x, T_i = k0 t_i), so one LCP per step decides
!> contact, yielding and the crossing of segment ends together:
!>
!>   w   = (F + 1/phat) r + (beta/k0) X + q
!>   y/k0 = -(beta/k0) r + (h_c + k0 (1-beta))/k0^2 X + sum_i (h_{c+i} - h_{c+i-1})/k0^2 T_i
!>          + (r_y(d_p,n) - (1-beta) r_s,n - beta b c d'_n)/k0
!>   s_i = -X/k0 + T_i/k0 + x_i
!>
!> Only what the step needs is modelled: contact rows for the constraints carrying force or
!> whose q < 0, a yield row for each of those with a plastic law, and hinge rows only for
!> segment ends the solution actually passes. After a solve, a left-out constraint that
!> would penetrate, or a plastic increment reaching beyond the last modelled segment end,
!> is added and the LCP solved again, so the accepted solution solves the full problem.
!> Its natural residual ||min(z, w)||_inf / ||q||_inf over all rows must be below
!> `residual_limit`.
!>
!> **Non-convex steps.** Softening segments (h < 0) make the matrix lose the P-property:
!> the LCP may have several solutions or none and Lemke may end on a secondary ray. Then
!> every complementary basis is enumerated (problems of up to `fallback_max_rows` rows) and
!> the solution nearest to the previous state (forces as they were, no plastic flow) is
!> taken; every such event is recorded (time, step, pairs). If there is no solution, or the
!> problem is too large to enumerate, the step fails, naming time, step, pairs and data.
!> Once a joint with a fracturing law has reached the end of its envelope it is fractured:
!> it carries nothing and takes no part in the LCP for the rest of the analysis.
!> Khat^{-1} B is computed once (one tridiagonal solve per constraint end).
module pound_contact
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, error_at
   use pound_strings, only: mm_text, str
   use pound_integrator, only: integrator
   use pound_structure, only: recovery_rows
   use pound_contact_law, only: is_plastic, yield_segment
   use pound_contact_pair, only: contact_pair, pairs_from_config, end_sign
   use pound_joint_state, only: joint_state, joints_advance, joints_advance_idle, state_open, &
                                state_elastic, state_fractured, joint_history, joint_history_init, joint_history_record
   use pound_lcp_statistics, only: lcp_statistics, contact_event, statistics_count_solve, &
                                   statistics_add_event, statistics_count_active_set
   use pound_contact_lcp, only: lcp_layout, lcp_assemble, released_opening, lcp_residual
   use pound_lemke, only: lemke_solve, lemke_report, lemke_status_name, LEMKE_SOLVED, LEMKE_TRIVIAL
   use pound_lcp_enumerate, only: lcp_enumerate
   use pound_lcp_active_set, only: active_set_report, active_set_solve, active_set_solved
   use pound_joint_law, only: law_iteration_limit
   use pound_contact_smooth, only: smooth_start, smooth_relinearise, smooth_finish, smooth_commit, smooth_speeds, &
                                   smooth_unsettled
   use pound_contact_friction_lcp, only: friction_start, friction_assemble, friction_forces, friction_opening, &
                                         friction_q, friction_apply, friction_commit, friction_verify
   use pound_contact_system, only: contact_system, contact_init, contact_init_flexibility, contact_swap_step, &
                                   lcp_workspace, residual_limit, fallback_max_rows, initial_hinges, &
                                   lcp_solver_auto, lcp_solver_lemke, joint_constants
   implicit none
   private

   public :: contact_system, contact_init, contact_init_flexibility
   public :: contact_step, contact_solve, contact_commit, contact_update, contact_release
   public :: contact_apply, released_q, segment_ends_passed
   public :: contact_swap_step, contact_may_act, contact_track_closing, contact_track_paths
   public :: contact_carries_force
   public :: residual_limit, fallback_max_rows, initial_hinges
   public :: lcp_solver_auto, lcp_solver_lemke
   ! Re-exported: the constraint definitions, the joints' state and the LCP statistics.
   public :: contact_pair, pairs_from_config
   public :: joint_state, state_open, state_elastic, state_fractured
   public :: joint_history, joint_history_init, joint_history_record
   public :: lcp_statistics, contact_event

contains


   !> Whether a joint (not fractured) carries force at the start of the step: then it can act
   !> in the step (`contact_may_act` is true) whatever the step's prediction.
   pure logical function contact_carries_force(cs) result(carries)
      !> The contact system.
      type(contact_system), intent(in) :: cs
      integer :: k

      carries = .false.
      do k = 1, cs%m
         if (cs%joint(k)%fractured) cycle
         if (cs%joint(k)%r > 0.0_dp) then
            carries = .true.
            return
         end if
      end do
   end function contact_carries_force

   !> Whether a joint can act in the step predicted in `states` (after `integrator%predict`,
   !> before `contact_step`): one carries force at the start, or one would close with every
   !> force released, at the end of the step (the LCP's q < 0) or inside it (the closing
   !> displacement along the step's path, `integrator%path`, a parabola, reaches the gap).
   logical function contact_may_act(cs, states) result(acts)
      !> The contact system (not changed).
      type(contact_system), intent(in) :: cs
      !> Integrators with the predicted increments du.
      class(integrator), intent(in) :: states(:)
      real(dp) :: vmax, q
      integer :: k

      acts = .false.
      if (cs%m == 0) return
      do k = 1, cs%m
         associate (p => cs%pair(k), j => cs%joint(k), c => cs%pair(k)%law%dashpot)
            if (j%fractured) cycle
            if (j%r > 0.0_dp) then
               acts = .true.
               return
            end if
            vmax = path_closing_max(cs, states, k)
            q = p%gap - vmax + (c*(cs%rate_a(k)*j%d + cs%rate_b(k)*j%ddot) + p%law%stiffness*j%plastic)/cs%phat(k)
            if (q < 0.0_dp) then
               acts = .true.
               return
            end if
         end associate
      end do
   end function contact_may_act

   !> The largest closing displacement of joint k along the step predicted in `states`, every
   !> force released: at the end of the step or at the vertex of its average-acceleration
   !> path (a parabola in time) inside it (`contact_may_act`).
   pure real(dp) function path_closing_max(cs, states, k) result(vmax)
      !> The contact system.
      type(contact_system), intent(in) :: cs
      !> Integrators with the predicted increments du.
      class(integrator), intent(in) :: states(:)
      !> Joint.
      integer, intent(in) :: k
      real(dp) :: c0, cv, ca, u0, v0, am, s, h
      integer :: e, b

      h = cs%span
      c0 = 0.0_dp
      cv = 0.0_dp
      ca = 0.0_dp
      do e = 1, 2
         b = cs%pair(k)%building(e)
         if (b == 0) cycle
         if (cs%pair(k)%dof(e) > 0) then
            call states(b)%path(cs%pair(k)%dof(e), u0, v0, am)
         else
            call row_path(cs%pair(k)%end_row(e), states(b), u0, v0, am)
         end if
         c0 = c0 + end_sign(e)*u0
         cv = cv + end_sign(e)*v0
         ca = ca + end_sign(e)*am
      end do
      vmax = c0 + cv*h + 0.5_dp*ca*h*h
      if (ca < 0.0_dp .and. cv > 0.0_dp) then
         s = -cv/ca
         if (s < h) vmax = max(vmax, c0 + 0.5_dp*cv*s)
      end if
   end function path_closing_max

   !> `integrator%path` of an end that is a row of several DOFs: the row's values of u, v and
   !> the average acceleration.
   pure subroutine row_path(row, st, u0, v0, am)
      type(recovery_rows), intent(in) :: row
      class(integrator), intent(in) :: st
      real(dp), intent(out) :: u0, v0, am
      real(dp) :: u, v, a
      integer :: i

      u0 = 0.0_dp
      v0 = 0.0_dp
      am = 0.0_dp
      do i = row%start(1), row%start(2) - 1
         call st%path(row%dof(i), u, v, a)
         u0 = u0 + row%coef(i)*u
         v0 = v0 + row%coef(i)*v
         am = am + row%coef(i)*a
      end do
      u0 = row%scale(1)*u0
      v0 = row%scale(1)*v0
      am = row%scale(1)*am
   end subroutine row_path

   !> Start recording, per joint, the largest closing displacement the steps predict with
   !> every force released (`closing_max`): at the steps' ends in `contact_step`, inside the
   !> steps where `contact_track_paths` is called. A run in which no joint acts (its gaps
   !> above every value recorded) is the uncoupled motion of the buildings, so these are the
   !> gaps beyond which the joints never close.
   subroutine contact_track_closing(cs)
      !> The contact system.
      type(contact_system), intent(inout) :: cs

      allocate (cs%closing_max(cs%m))
      cs%closing_max = -huge(1.0_dp)
   end subroutine contact_track_closing

   !> Add the largest closing displacement inside the step predicted in `states` (the path
   !> of `contact_may_act`) to `closing_max` (`contact_track_closing`).
   subroutine contact_track_paths(cs, states)
      !> The contact system, tracking.
      type(contact_system), intent(inout) :: cs
      !> Integrators with the predicted increments du.
      class(integrator), intent(in) :: states(:)
      integer :: k

      do k = 1, cs%m
         cs%closing_max(k) = max(cs%closing_max(k), path_closing_max(cs, states, k))
      end do
   end subroutine contact_track_paths

   !> Decide the contact forces at the end of the step and add their effect to du.
   !>
   !> Call after `integrator%predict` of every building and before `integrator%commit`.
   subroutine contact_step(cs, states, t, step, error)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Integrators with the predicted increments du.
      class(integrator), intent(inout) :: states(:)
      !> Time at the end of the step (s), for messages.
      real(dp), intent(in) :: t
      !> Step number, for messages.
      integer, intent(in) :: step
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: k

      if (cs%m == 0) return
      ! Closing displacement if every force were released in this step.
      call closing_displacements(cs, states, .true.)
      if (allocated(cs%closing_max)) cs%closing_max = max(cs%closing_max, cs%vp)
      ! No joint can act: what `contact_solve` would find (no force, no plastic flow, du
      ! unchanged), without its set-up.
      cs%idle = cs%shortcut
      if (cs%idle) cs%idle = no_joint_acts(cs)
      if (cs%idle) then
         cs%r_new = 0.0_dp
         cs%x_new = 0.0_dp
         return
      end if
      do k = 1, cs%m
         if (cs%joint(k)%r /= 0.0_dp) cs%vp = cs%vp + cs%f(:, k)*cs%joint(k)%r
      end do
      ! Friction (pound_contact_friction_lcp): the tangential forces released too.
      if (cs%fr%n > 0) call friction_start(cs, states)
      ! The smooth joints' closing speeds at the step's start (pound_contact_smooth).
      if (size(cs%iterating) > 0) call smooth_speeds(cs, states)
      call contact_solve(cs, cs%vp, t, step, error)
      if (allocated(error)) return
      call apply_force_change(cs, states, .false.)
   end subroutine contact_step

   !> Take the forces of the step's solution out of du again (du += Khat^{-1} B (r_new -
   !> r_old)): the step's predicted du as it was before `contact_step`, so that it can be solved
   !> again after other elements of the step changed du (bilinear storeys, pound_storey_yield).
   subroutine contact_release(cs, states)
      !> The contact system after `contact_step`.
      type(contact_system), intent(inout) :: cs
      !> Integrators.
      class(integrator), intent(inout) :: states(:)

      if (cs%m == 0) return
      if (cs%idle) return
      call apply_force_change(cs, states, .true.)
   end subroutine contact_release

   !> Whether the plastic flow `x_new` of a joint in the LCP (contact rows `act(1:na)`) passes a
   !> segment end that is not modelled: then those ends are modelled (`nh` grows) and true.
   logical function segment_ends_passed(cs, na, qnorm) result(added)
      !> The contact system after a solve.
      type(contact_system), intent(inout) :: cs
      !> Contact rows of the LCP.
      integer, intent(in) :: na
      !> ||q||_inf of the step (the tolerance's scale).
      real(dp), intent(in) :: qnorm
      real(dp) :: reach
      integer :: j, k, nxt

      added = .false.
      do j = 1, na
         k = cs%act(j)
         if (cs%yrow(k) == 0 .or. cs%x_new(k) <= 0.0_dp) cycle
         associate (law => cs%pair(k)%law, pl => cs%joint(k)%plastic)
            reach = pl + cs%x_new(k) - residual_limit*qnorm
            nxt = yield_segment(law, pl) + cs%nh(k) + 1
            do while (nxt <= size(law%yp) - 1)
               if (law%yp(nxt) >= reach) exit
               cs%nh(k) = cs%nh(k) + 1
               added = .true.
               nxt = nxt + 1
            end do
         end associate
      end do
   end function segment_ends_passed

   !> Apply forces `r_new` that another solve set (the coupled joints-and-storeys LCP of
   !> pound_storey_yield) to du: du -= Khat^{-1} B (r_new - r_old).
   subroutine contact_apply(cs, states)
      !> The contact system with `r_new` set.
      type(contact_system), intent(inout) :: cs
      !> Integrators.
      class(integrator), intent(inout) :: states(:)

      call apply_force_change(cs, states, .false.)
   end subroutine contact_apply

   !> du -= Khat^{-1} B (r_new - r_old), only where the force changed (`undo`: du += ...).
   subroutine apply_force_change(cs, states, undo)
      type(contact_system), intent(inout) :: cs
      class(integrator), intent(inout) :: states(:)
      logical, intent(in) :: undo
      integer :: k, e, b
      real(dp) :: dr

      if (cs%fr%n > 0) call friction_apply(cs, states, undo)
      do k = 1, cs%m
         dr = cs%r_new(k) - cs%joint(k)%r
         if (dr == 0.0_dp) cycle
         if (undo) dr = -dr
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            if (cs%pair(k)%dof(e) > 0) then
               call states(b)%add_load(-(end_sign(e)*dr), cs%pair(k)%dof(e), cs%y(e, k)%x)
            else
               associate (row => cs%pair(k)%end_row(e))
                  ! (`contact_init` folded the row's scale into its weights.)
                  call states(b)%add_load_rows(-(end_sign(e)*dr), row%dof(row%start(1):row%start(2) - 1), &
                                               row%coef(row%start(1):row%start(2) - 1), cs%y(e, k)%x)
               end associate
            end if
         end do
      end do
   end subroutine apply_force_change

   !> The LCP's q of every joint into `cs%q`, the opening it would have at the end of the step
   !> with every force released: g - v_pred + (c (a d_n + b d'_n) + k0 d_p,n)/phat (the one
   !> formula of `contact_solve` and of the short path of `contact_step`).
   pure subroutine released_q(cs, v_pred)
      !> The contact system (`q` set).
      type(contact_system), intent(inout) :: cs
      !> Closing displacements with every force released (m).
      real(dp), intent(in) :: v_pred(:)
      integer :: k

      do k = 1, cs%m
         associate (p => cs%joint(k), c => cs%pair(k)%law%dashpot)
            cs%q(k) = cs%pair(k)%gap - v_pred(k) + (c*(cs%rate_a(k)*p%d + cs%rate_b(k)*p%ddot) + &
                                                    cs%pair(k)%law%stiffness*p%plastic)/cs%phat(k)
         end associate
      end do
   end subroutine released_q

   !> No joint can act in the step whose released closing displacements are in `cs%vp`:
   !> every joint carries no force at the start, and every one that is not fractured has a
   !> finite q >= 0. Then `contact_solve` models no row (its guard passes) and gives r = 0,
   !> x = 0, and `contact_step` changes no du: the short path is the full one, bit for bit.
   !> A joint of a `plain_law` at rest (d = 0, d_p = 0, d' finite) has q = g - v_pred exactly
   !> up to the sign of a zero (the term (c (a d + b d') + k0 d_p)/phat is a zero: c = 0 and
   !> a d + b d' is finite, b <= 1), so the test needs no division; for any other joint q is
   !> `released_q`'s.
   logical function no_joint_acts(cs) result(idle)
      type(contact_system), intent(inout) :: cs
      real(dp) :: q
      integer :: k
      logical :: general

      idle = .false.
      general = .false.
      do k = 1, cs%m
         associate (j => cs%joint(k))
            if (j%r /= 0.0_dp) return
            if (j%fractured) cycle
            if (cs%plain(k) .and. j%d == 0.0_dp .and. j%plastic == 0.0_dp .and. abs(j%ddot) <= huge(1.0_dp)) then
               q = cs%pair(k)%gap - cs%vp(k)
               if (.not. (q >= 0.0_dp .and. q <= huge(1.0_dp))) return
            else
               general = .true.
            end if
         end associate
      end do
      if (general) then
         call released_q(cs, cs%vp)
         do k = 1, cs%m
            if (cs%joint(k)%fractured) cycle
            if (.not. (cs%q(k) >= 0.0_dp .and. cs%q(k) <= huge(1.0_dp))) return
         end do
      end if
      idle = .true.
   end function no_joint_acts

   !> Solve the step's LCP for the closing displacements `v_pred` (forces released): sets
   !> `cs%r_new` and `cs%x_new`. `v_pred` may be `cs%vp` (not `cs%q`).
   !>
   !> Joints whose law iterates (`cs%iterating`, pound_joint_law: none of the piecewise-linear
   !> family, so the loop below runs once) are re-linearised around each solution and the
   !> LCP solved again until none moves its row (at most `max_law_iterations`): a smooth
   !> law's end-of-step equation solved exactly by Newton (pound_contact_smooth).
   subroutine contact_solve(cs, v_pred, t, step, error)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Closing displacement of each constraint if all forces were released (m).
      real(dp), intent(in) :: v_pred(:)
      !> Time at the end of the step (s), for messages.
      real(dp), intent(in) :: t
      !> Step number, for messages.
      integer, intent(in) :: step
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: it, k

      ! The constants of an iterating joint follow its current stiffness (after a step swap);
      ! a smooth law's first tangent row (pound_contact_smooth).
      if (size(cs%iterating) > 0) call smooth_start(cs, v_pred)
      do it = 1, law_iteration_limit
         call solve_lcp(cs, v_pred, t, step, error)
         if (allocated(error)) return
         if (size(cs%iterating) == 0) return
         if (.not. smooth_relinearise(cs, v_pred, it)) then
            call smooth_finish(cs, v_pred)
            if (cs%fr%n > 0) call friction_verify(cs, t, step, error)
            return
         end if
      end do
      call fatal_error(error, 'contact at t = '//str(t)//' s (step '//str(step)//'): the end-of-step '// &
                       'equations of the joints '//smooth_unsettled(cs, v_pred, k)//' did not converge in '// &
                       str(law_iteration_limit)//' solves (reduce dt, or stepping = ''impact'')')
      call error_at(error, joint=k)
   end subroutine contact_solve

   !> One LCP solve of the step (`contact_solve`).
   subroutine solve_lcp(cs, v_pred, t, step, error)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Closing displacement of each constraint if all forces were released (m).
      real(dp), intent(in) :: v_pred(:)
      !> Time at the end of the step (s), for messages.
      real(dp), intent(in) :: t
      !> Step number, for messages.
      integer, intent(in) :: step
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(lemke_report) :: rep
      integer :: k, na, n, j, nxt
      integer(int64) :: clock_start, clock_end, clock_rate
      real(dp) :: qnorm, wk, resid, reach
      logical :: added, nonconvex, timed

      if (cs%m == 0) return
      qnorm = 0.0_dp
      call released_q(cs, v_pred)
      ! The offsets of the smooth joints' tangent rows (pound_contact_smooth).
      do j = 1, size(cs%iterating)
         k = cs%iterating(j)
         cs%q(k) = cs%q(k) + cs%joint(k)%shift
      end do
      do k = 1, cs%m
         associate (p => cs%joint(k))
            cs%in_lcp(k) = .not. p%fractured .and. (p%r > 0.0_dp .or. cs%q(k) < 0.0_dp)
            if (.not. p%fractured) qnorm = max(qnorm, abs(cs%q(k)))
         end associate
      end do
      ! Guard: nothing that is not finite reaches the LCP solver.
      do k = 1, cs%m
         if (cs%joint(k)%fractured .or. ieee_is_finite(cs%q(k))) cycle
         call fatal_error(error, 'contact '//cs%pair(k)%label//': the step''s LCP data is not finite at t = '// &
                          str(t)//' s (step '//str(step)//'): predicted closing displacement '// &
                          mm_text(v_pred(k))//', joint compression '//mm_text(cs%joint(k)%d)//', rate '// &
                          str(cs%joint(k)%ddot)//' m/s, plastic penetration '//mm_text(cs%joint(k)%plastic))
         return
      end do
      qnorm = max(qnorm, tiny(1.0_dp))
      ! The clock is read only when there is an LCP to solve.
      ! No joint can act (every one open with q >= 0, or fractured): no force, and the
      ! solution z = 0, w = q is exact; the clock is read only when there is an LCP to solve.
      cs%r_new = 0.0_dp
      cs%x_new = 0.0_dp
      if (cs%fr%n > 0) then
         ! No friction rows until assembled (an iterate of a smooth law that opens every
         ! joint keeps no tangential force of the iterate before).
         cs%fr%nt = 0
         cs%fr%force_new = 0.0_dp
         cs%fr%slip_new = 0.0_dp
      end if
      timed = any(cs%in_lcp)
      if (.not. timed) return
      call system_clock(clock_start, clock_rate)
      ! Elastic joints only: the active-set method from the previous step's set (not with
      ! friction: its problem is not symmetric).
      if (cs%solver == lcp_solver_auto .and. cs%fr%n == 0) then
         if (active_set_step(cs)) then
            call system_clock(clock_end)
            cs%stats%lcp_seconds = cs%stats%lcp_seconds + real(clock_end - clock_start, dp)/real(clock_rate, dp)
            return
         end if
      end if
      ! Segment ends within reach: those the plastic increment would pass if the joint alone
      ! took up all of its predicted penetration -q plastically (more are added on demand).
      do k = 1, cs%m
         cs%nh(k) = 0
         if (.not. cs%in_lcp(k) .or. .not. is_plastic(cs%pair(k)%law)) cycle
         associate (law => cs%pair(k)%law, pl => cs%joint(k)%plastic)
            reach = pl + max(0.0_dp, -cs%q(k))/cs%beta(k)
            nxt = yield_segment(law, pl) + 1
            do while (nxt <= size(law%yp) - 1 .and. cs%nh(k) < initial_hinges)
               if (law%yp(nxt) >= reach) exit
               cs%nh(k) = cs%nh(k) + 1
               nxt = nxt + 1
            end do
         end associate
      end do
      nonconvex = .false.

      do
         call assemble(cs, na, n, nonconvex, error)
         if (allocated(error)) return
         if (n == 0) exit
         if (cs%fr%n > 0) then
            call friction_assemble(cs, na, n, error)
            if (allocated(error)) return
         end if
         cs%stats%largest_lcp = max(cs%stats%largest_lcp, n)
         if (cs%pivot_cap > 0) then
            call lemke_solve(cs%ws, n, cs%mat, cs%qa, cs%za, cs%wa, rep, active_guess=cs%guess(1:n), &
                             max_pivots=cs%pivot_cap)
         else
            call lemke_solve(cs%ws, n, cs%mat, cs%qa, cs%za, cs%wa, rep, active_guess=cs%guess(1:n))
         end if
         call statistics_count_solve(cs%stats, rep%pivots, rep%status == LEMKE_TRIVIAL, rep%warm_started)
         if (rep%status /= LEMKE_SOLVED .and. rep%status /= LEMKE_TRIVIAL) then
            ! A missing segment end can leave the model without a solution (a softening
            ! line extended below r = 0): model one more wherever there is one, and retry.
            if (more_hinges(cs, na)) then
               cs%stats%resolves = cs%stats%resolves + 1
               cycle
            end if
            call fallback(cs, n, rep, t, step, error)
            if (allocated(error)) return
         else if (.not. (rep%residual <= residual_limit)) then
            call fatal_error(error, 'contact LCP failed at t = '//str(t)//' s (step '//str(step)// &
                             '): Lemke ended with '//lemke_status_name(rep%status)//', residual '// &
                             str(rep%residual)//', '//str(rep%pivots)//' pivots; constraints '// &
                             labels(cs, cs%act(1:na))//'; q = '//vector_text(cs%qa(1:n)))
            return
         end if
         cs%r_new = 0.0_dp
         cs%x_new = 0.0_dp
         cs%r_new(cs%act(1:na)) = cs%za(1:na)
         if (cs%fr%n > 0) call friction_forces(cs, na)
         added = .false.
         do j = 1, na
            k = cs%act(j)
            if (cs%yrow(k) > 0) cs%x_new(k) = cs%za(cs%yrow(k))/cs%pair(k)%law%stiffness
         end do
         ! Constraints left out must stay open under the new forces.
         do k = 1, cs%m
            if (cs%in_lcp(k) .or. cs%joint(k)%fractured) cycle
            wk = released_opening(cs%f, cs%q, cs%act, na, cs%za, k)
            if (cs%fr%nt > 0) wk = wk + friction_opening(cs, k)
            if (wk < -residual_limit*qnorm) then
               cs%in_lcp(k) = .true.
               added = .true.
            end if
         end do
         ! Plastic flow must not pass a segment end that is not modelled.
         if (segment_ends_passed(cs, na, qnorm)) added = .true.
         if (.not. added) exit
         cs%stats%resolves = cs%stats%resolves + 1
      end do
      if (nonconvex) cs%stats%nonconvex = cs%stats%nonconvex + 1

      ! Verify the accepted solution on the full LCP: the assembled rows and the left-out
      ! constraints.
      if (cs%fr%nt > 0) then
         ! The joints left out open under the tangential forces too.
         call friction_q(cs)
         call lcp_residual(n, cs%mat, cs%qa, cs%za, cs%wa, cs%f, cs%fr%qx, cs%act, na, cs%in_lcp, cs%joint, qnorm, &
                           resid)
      else
         call lcp_residual(n, cs%mat, cs%qa, cs%za, cs%wa, cs%f, cs%q, cs%act, na, cs%in_lcp, cs%joint, qnorm, &
                           resid)
      end if
      cs%stats%residual_max = max(cs%stats%residual_max, resid)
      call system_clock(clock_end)
      cs%stats%lcp_seconds = cs%stats%lcp_seconds + real(clock_end - clock_start, dp)/real(clock_rate, dp)
      if (.not. (resid <= residual_limit)) then
         call fatal_error(error, 'contact LCP solution rejected at t = '//str(t)//' s (step '// &
                          str(step)//'): natural residual '//str(resid)//' > '//str(residual_limit)// &
                          '; constraints '//labels(cs, cs%act(1:na)))
         return
      end if
   end subroutine solve_lcp

   !> The step's LCP by the active-set method (`pound_lcp_active_set`) when every joint that
   !> can act in it is elastic (a plastic joint carrying force or predicted to close: not
   !> tried). True when solved and verified by its natural residual on every joint that is
   !> not fractured (sets `r_new`, `x_new`); false, counted as a fallback when it was tried,
   !> leaves the step to Lemke.
   logical function active_set_step(cs) result(solved)
      type(contact_system), intent(inout) :: cs
      type(active_set_report) :: rep
      integer :: k

      solved = .false.
      do k = 1, cs%m
         if (cs%joint(k)%fractured) then
            cs%role(k) = 0
         else if (is_plastic(cs%pair(k)%law)) then
            if (cs%in_lcp(k)) return
            cs%role(k) = 2
         else
            cs%role(k) = 1
         end if
      end do
      call active_set_solve(cs%as, cs%m, cs%f, cs%phat_inv, cs%q, cs%role, cs%in_lcp, cs%r_new, cs%wm, rep)
      solved = rep%status == active_set_solved .and. rep%residual <= residual_limit
      call statistics_count_active_set(cs%stats, rep%iterations, rep%updates, .not. solved)
      if (.not. solved) then
         cs%r_new = 0.0_dp
         return
      end if
      cs%x_new = 0.0_dp
      cs%stats%residual_max = max(cs%stats%residual_max, rep%residual)
      cs%stats%largest_lcp = max(cs%stats%largest_lcp, cs%as%na)
   end function active_set_step

   !> Lay out and assemble the LCP of the constraints in `cs%in_lcp` (`lcp_layout`,
   !> `lcp_assemble`), growing the workspace first when more segment ends are modelled than
   !> it holds (rare).
   subroutine assemble(cs, na, n, nonconvex, error)
      type(contact_system), intent(inout) :: cs
      integer, intent(out) :: na, n
      logical, intent(inout) :: nonconvex
      type(error_type), allocatable, intent(out) :: error
      integer :: k, n_full

      call lcp_layout(cs%pair, cs%in_lcp, cs%nh, cs%act, cs%yrow, na, n)
      if (n == 0) return
      if (n > cs%n_max) then
         n_full = cs%m
         do k = 1, cs%m
            if (is_plastic(cs%pair(k)%law)) n_full = n_full + size(cs%pair(k)%law%yp)
         end do
         call lcp_workspace(cs, max(n, min(2*cs%n_max, n_full)), error)
         if (allocated(error)) return
         call lcp_layout(cs%pair, cs%in_lcp, cs%nh, cs%act, cs%yrow, na, n)
      end if
      call lcp_assemble(cs%pair, cs%joint, cs%f, cs%phat, cs%beta, cs%rate_b, cs%q, cs%act, na, cs%yrow, &
                        cs%nh, n, cs%mat, cs%qa, cs%guess, cs%zref, nonconvex)
   end subroutine assemble

   !> One more modelled segment end for every plastic joint in the LCP that has one left;
   !> false if there was none.
   logical function more_hinges(cs, na) result(added)
      type(contact_system), intent(inout) :: cs
      integer, intent(in) :: na
      integer :: j, k

      added = .false.
      do j = 1, na
         k = cs%act(j)
         if (cs%yrow(k) == 0) cycle
         if (yield_segment(cs%pair(k)%law, cs%joint(k)%plastic) + cs%nh(k) >= size(cs%pair(k)%law%yp) - 1) cycle
         cs%nh(k) = cs%nh(k) + 1
         added = .true.
      end do
   end function more_hinges

   !> Lemke failed (ray or pivot cap): enumerate the complementary bases and take the
   !> solution nearest the previous state; record the event. Fails if there is none.
   subroutine fallback(cs, n, rep, t, step, error)
      type(contact_system), intent(inout) :: cs
      integer, intent(in) :: n
      type(lemke_report), intent(in) :: rep
      real(dp), intent(in) :: t
      integer, intent(in) :: step
      type(error_type), allocatable, intent(out) :: error
      integer :: nsol, k
      character(len=:), allocatable :: who

      who = ''
      do k = 1, cs%m
         if (.not. cs%in_lcp(k)) cycle
         if (len(who) > 0) who = who//', '
         who = who//cs%pair(k)%label
      end do
      if (n > fallback_max_rows) then
         call fatal_error(error, 'contact LCP failed at t = '//str(t)//' s (step '//str(step)// &
                          '): Lemke ended with '//lemke_status_name(rep%status)//' after '// &
                          str(rep%pivots)//' pivots on a non-convex LCP of '//str(n)// &
                          ' rows, too large to enumerate (limit '//str(fallback_max_rows)// &
                          '); constraints '//who//'; reduce dt')
         return
      end if
      call lcp_enumerate(cs%mat(1:n, 1:n), cs%qa(1:n), nsol, z=cs%za(1:n), reference=cs%zref(1:n), &
                         error=error)
      if (allocated(error)) return
      if (nsol == 0) then
         call fatal_error(error, 'contact LCP has no solution at t = '//str(t)//' s (step '//str(step)// &
                          '): Lemke ended with '//lemke_status_name(rep%status)//' and enumeration of '// &
                          'all '//str(2**n)//' complementary bases found none (softening steeper than '// &
                          'the structure can follow: snap-back); constraints '//who//'; q = '// &
                          vector_text(cs%qa(1:n)))
         return
      end if
      call statistics_add_event(cs%stats, contact_event(time=t, step=step, status=rep%status, rows=n, &
                                                        solutions=nsol, pairs=who))
   end subroutine fallback

   !> Update the joints after `integrator%commit`: compression, statistics and energy.
   subroutine contact_commit(cs, states, t, dt)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Integrators at the end of the step.
      class(integrator), intent(in) :: states(:)
      !> Time at the end of the step (s).
      real(dp), intent(in) :: t
      !> Time step (s).
      real(dp), intent(in) :: dt

      ! The closing displacements at the end of the step. After a step in which no joint
      ! could act, those `contact_step` predicted: du was not changed, and the commit's
      ! u_{n+1} = u_n + du is the prediction's sum, bit for bit.
      if (cs%idle) then
         cs%idle = .false.
         call joints_advance_idle(cs%m, cs%joint, cs%pair, cs%plain, cs%vp, t, dt, cs%rate_a, cs%rate_b, cs%phat, &
                                  cs%work, cs%element_work, cs%plastic_work)
         return
      end if
      call closing_displacements(cs, states, .false.)
      call contact_update(cs, cs%vp, t, dt)
      if (size(cs%iterating) > 0) call smooth_commit(cs)
      if (cs%fr%n > 0) call friction_commit(cs, states, t)
   end subroutine contact_commit

   !> Closing displacements v = B^T u of every constraint into `cs%vp` (left end + u, right
   !> end - u): of the displacements predicted for the end of the step, or of the committed.
   subroutine closing_displacements(cs, states, predicted)
      type(contact_system), intent(inout) :: cs
      class(integrator), intent(in) :: states(:)
      logical, intent(in) :: predicted
      integer :: k, b
      real(dp) :: v

      if (cs%general_ends) then
         call closing_rows(cs, states, predicted)
         return
      end if
      do k = 1, cs%m
         v = 0.0_dp
         b = cs%ends(1, k)
         if (b > 0) v = v + end_u(states(b), cs%ends(2, k))
         b = cs%ends(3, k)
         if (b > 0) v = v - end_u(states(b), cs%ends(4, k))
         cs%vp(k) = v
      end do

   contains

      real(dp) function end_u(st, i)
         class(integrator), intent(in) :: st
         integer, intent(in) :: i

         if (predicted) then
            end_u = st%predicted(i)
         else
            end_u = st%u_at(i)
         end if
      end function end_u
   end subroutine closing_displacements

   !> `closing_displacements` of joints whose ends are rows over their models' DOFs (buildings
   !> in plan): each building's u (and du) read through views taken once per call, not one
   !> call of the integrator per entry. The predicted displacement of a DOF is u + du, as the
   !> integrators' `predicted`, summed in the same order: the same numbers.
   subroutine closing_rows(cs, states, predicted)
      type(contact_system), intent(inout) :: cs
      class(integrator), intent(in), target :: states(:)
      logical, intent(in) :: predicted
      type :: dof_view
         real(dp), pointer, contiguous :: u(:) => null(), du(:) => null()
      end type dof_view
      type(dof_view) :: w(size(states))
      integer :: k, b
      real(dp) :: v

      do b = 1, size(states)
         w(b)%u => states(b)%u_view()
         if (predicted) w(b)%du => states(b)%du_view()
      end do
      do k = 1, cs%m
         v = 0.0_dp
         if (cs%ends(1, k) > 0) v = v + row_u(1)
         if (cs%ends(3, k) > 0) v = v - row_u(2)
         cs%vp(k) = v
      end do

   contains

      !> The displacement of end e of pair k (its DOF or its row).
      real(dp) function row_u(e)
         integer, intent(in) :: e
         integer :: i, b

         b = cs%ends(2*e - 1, k)
         if (cs%ends(2*e, k) > 0) then
            row_u = end_u(w(b), cs%ends(2*e, k))
            return
         end if
         row_u = 0.0_dp
         associate (row => cs%pair(k)%end_row(e))
            do i = row%start(1), row%start(2) - 1
               row_u = row_u + row%coef(i)*end_u(w(b), row%dof(i))
            end do
            row_u = row%scale(1)*row_u
         end associate
      end function row_u

      real(dp) function end_u(x, i)
         type(dof_view), intent(in) :: x
         integer, intent(in) :: i

         if (predicted) then
            end_u = x%u(i) + x%du(i)
         else
            end_u = x%u(i)
         end if
      end function end_u
   end subroutine closing_rows

   !> Update the joints for the accepted step: plastic penetration, compression, rate,
   !> state, statistics and energy. `v` (closing displacements at the end of the step) may
   !> be `cs%vp` itself (not modified here).
   subroutine contact_update(cs, v, t, dt)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Closing displacement of each constraint at the end of the step (m).
      real(dp), intent(in) :: v(:)
      !> Time at the end of the step (s).
      real(dp), intent(in) :: t
      !> Time step (s).
      real(dp), intent(in) :: dt

      call joints_advance(cs%joint, cs%pair, cs%r_new, cs%x_new, v, t, dt, cs%rate_a, cs%rate_b, cs%phat, &
                          cs%work, cs%element_work, cs%plastic_work)
   end subroutine contact_update


   !> Labels of the listed constraints, comma separated.
   function labels(cs, idx) result(s)
      type(contact_system), intent(in) :: cs
      integer, intent(in) :: idx(:)
      character(len=:), allocatable :: s
      integer :: i

      s = ''
      do i = 1, size(idx)
         if (i > 1) s = s//', '
         s = s//cs%pair(idx(i))%label
      end do
   end function labels

   !> A short vector as text.
   function vector_text(x) result(s)
      real(dp), intent(in) :: x(:)
      character(len=:), allocatable :: s
      integer :: i

      s = '['
      do i = 1, min(size(x), 8)
         if (i > 1) s = s//', '
         s = s//str(x(i))
      end do
      if (size(x) > 8) s = s//', ...'
      s = s//']'
   end function vector_text

end module pound_contact
