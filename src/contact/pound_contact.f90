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
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: mm_text, str
   use pound_newmark, only: newmark_state, newmark_solve, newmark_n, newmark_dt, newmark_predicted, &
                            newmark_u_at, newmark_add_response, newmark_path
   use pound_structure, only: structure_model, structure_end_dof
   use pound_contact_law, only: is_plastic, yield_segment, rate_trapezoidal, dashpot_of_restitution
   use pound_contact_pair, only: contact_pair, pairs_from_config, end_sign
   use pound_joint_state, only: joint_state, joints_advance, joints_advance_idle, plain_law, state_open, &
                                state_elastic, state_fractured, joint_history, joint_history_init, joint_history_record
   use pound_lcp_statistics, only: lcp_statistics, contact_event, statistics_count_solve, &
                                   statistics_add_event, statistics_count_active_set
   use pound_contact_lcp, only: lcp_layout, lcp_assemble, released_opening, lcp_residual
   use pound_lemke, only: lemke_workspace, lemke_init, lemke_solve, lemke_report, &
                          lemke_status_name, LEMKE_SOLVED, LEMKE_TRIVIAL
   use pound_lcp_enumerate, only: lcp_enumerate
   use pound_lcp_active_set, only: active_set_workspace, active_set_report, active_set_init, &
                                   active_set_solve, active_set_solved
   use pound_swap, only: swap
   implicit none
   private

   public :: contact_system, contact_init, contact_init_flexibility
   public :: contact_step, contact_solve, contact_commit, contact_update
   public :: contact_swap_step, contact_may_act, contact_track_closing, contact_track_paths
   public :: contact_carries_force
   public :: residual_limit, fallback_max_rows, initial_hinges
   public :: lcp_solver_auto, lcp_solver_lemke
   ! Re-exported: the constraint definitions, the joints' state and the LCP statistics.
   public :: contact_pair, pairs_from_config
   public :: joint_state, state_open, state_elastic, state_fractured
   public :: joint_history, joint_history_init, joint_history_record
   public :: lcp_statistics, contact_event

   !> Largest accepted natural residual of a step's LCP, relative to ||q||.
   real(dp), parameter :: residual_limit = 1.0e-10_dp
   !> Largest LCP (rows) solved by enumeration when Lemke ends on a ray.
   integer, parameter :: fallback_max_rows = 16
   !> Segment ends per joint modelled up front (rows held by the initial workspace); a step
   !> that passes more models them on demand and grows the workspace (no fixed limit).
   integer, parameter :: initial_hinges = 32
   !> LCP method: the active-set method for steps with elastic joints only, Lemke otherwise
   !> and when it fails (the default); Lemke for every step.
   integer, parameter :: lcp_solver_auto = 0, lcp_solver_lemke = 1

   !> A vector of its own length (Khat^{-1} e of one constraint end).
   type :: column
      real(dp), allocatable :: x(:)
   end type column

   !> All constraints of an analysis: their definitions, their joints' state, the condensed
   !> flexibility, the step's LCP work arrays and the LCP statistics.
   type :: contact_system
      !> Number of constraints.
      integer :: m = 0
      !> The constraints (what they join, gap, law; fixed during the analysis).
      type(contact_pair), allocatable :: pair(:)
      !> The state of each constraint's joint.
      type(joint_state), allocatable :: joint(:)
      !> Khat^{-1} e for each end, (2, m).
      type(column), allocatable :: y(:, :)
      !> Condensed flexibility F = B^T Khat^{-1} B (m, m).
      real(dp), allocatable :: f(:, :)
      !> Per joint: phat = k0 + a c, beta = k0/phat, dashpot rate coefficients a, b.
      real(dp), allocatable :: phat(:), beta(:), rate_a(:), rate_b(:)
      !> Newmark c2 = 2/dt.
      real(dp) :: c2 = 0.0_dp
      !> Largest LCP size (rows) the workspace holds.
      integer :: n_max = 0
      !> Step work arrays: contact q, new forces and plastic increments, LCP data.
      real(dp), allocatable :: q(:), r_new(:), x_new(:), mat(:, :), qa(:), za(:), wa(:), zref(:)
      !> Closing displacements if all forces were released (m).
      real(dp), allocatable :: vp(:)
      !> Each constraint's ends packed for the per-step loops: building and DOF of the left
      !> end (rows 1, 2) and of the right end (rows 3, 4); building 0: rigid (4, m).
      integer, allocatable :: ends(:, :)
      !> Row bookkeeping: constraint of each contact row, row of each joint's yield variable,
      !> modelled segment ends per joint.
      integer, allocatable :: act(:), yrow(:), nh(:)
      logical, allocatable :: in_lcp(:), guess(:)
      type(lemke_workspace) :: ws
      !> Work of the contact forces on the structure, sum r_avg dv (kJ).
      real(dp) :: work = 0.0_dp
      !> Work stored in or dissipated by the joints, sum r_avg dd (kJ), and the part of it
      !> dissipated by plastic flow, sum r_s,avg dd_p (kJ).
      real(dp) :: element_work = 0.0_dp, plastic_work = 0.0_dp
      !> LCP statistics.
      type(lcp_statistics) :: stats
      !> Pivot cap of each Lemke run (0: Lemke's default, 50 (n + 1)).
      integer :: pivot_cap = 0
      !> LCP method (`lcp_solver_auto`, `lcp_solver_lemke`).
      integer :: solver = lcp_solver_auto
      !> Active-set method: its set and factor kept between steps, 1/phat per joint, the
      !> role of each joint in the step (0 fractured, 1 elastic, 2 plastic), w of every joint.
      type(active_set_workspace), allocatable :: as
      real(dp), allocatable :: phat_inv(:), wm(:)
      integer, allocatable :: role(:)
      !> Steps in which no joint can act take the short path of `contact_step` (false: every
      !> step takes the full path; the tests compare both).
      logical :: shortcut = .true.
      !> The last `contact_step` found that no joint can act: the forces stay zero and `vp`
      !> holds the closing displacements it predicted, which `contact_commit` takes.
      logical :: idle = .false.
      !> Whether each joint's law is a `plain_law` (elastic, no dashpot, not fracturing).
      logical, allocatable :: plain(:)
      !> When allocated (`contact_track_closing`): per joint, the largest closing displacement
      !> released of every force that the steps have predicted so far, at the steps' ends
      !> (`contact_step`) and, where `contact_track_paths` is called, inside them (m).
      real(dp), allocatable :: closing_max(:)
   end type contact_system

contains

   !> Condense the structure onto the constraints: Khat^{-1} B and F.
   subroutine contact_init(cs, pairs, states, models, error)
      !> The contact system.
      type(contact_system), intent(out) :: cs
      !> The constraints (ends, gaps, laws).
      type(contact_pair), intent(in) :: pairs(:)
      !> Initialised integrators (their factored Khat).
      type(newmark_state), intent(in) :: states(:)
      !> The structural models of the integrators (the DOF of each floor).
      type(structure_model), intent(in) :: models(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(column), allocatable :: y(:, :)
      type(contact_pair), allocatable :: located(:)
      real(dp), allocatable :: f(:, :)
      integer :: k, l, e, g, b, m, stat

      m = size(pairs)
      located = pairs
      do k = 1, m
         do e = 1, 2
            b = pairs(k)%building(e)
            if (b == 0) cycle
            located(k)%dof(e) = structure_end_dof(models(b), e, pairs(k)%floor(e), pairs(k)%elevation)
            if (located(k)%dof(e) == 0) then
               call fatal_error(error, 'contact '//pairs(k)%label//': building '//models(b)%name// &
                                ' has no node at the contact point')
               return
            end if
         end do
         if (pairs(k)%law%restitution > 0.0_dp) then
            call calibrate_dashpot(located(k), models, error)
            if (allocated(error)) return
         end if
      end do
      allocate (y(2, m), f(m, m), stat=stat)
      if (stat /= 0) then
         call fatal_error(error, 'contact: cannot allocate the condensed flexibility F for '//str(m)// &
                          ' pairs ('//str(8.0_dp*real(m, dp)**2/2.0_dp**20)//' MiB; fewer floors_left / '// &
                          'floors_right pairs)')
         return
      end if
      do k = 1, m
         do e = 1, 2
            b = pairs(k)%building(e)
            if (b == 0) cycle
            allocate (y(e, k)%x(newmark_n(states(b))), stat=stat)
            if (stat /= 0) then
               call fatal_error(error, 'contact '//pairs(k)%label//': cannot allocate Khat^{-1} B ('// &
                                str(newmark_n(states(b)))//' reals per pair end; fewer pairs or storeys)')
               return
            end if
            y(e, k)%x = 0.0_dp
            y(e, k)%x(located(k)%dof(e)) = 1.0_dp
            call newmark_solve(states(b), y(e, k)%x)
            if (.not. all(ieee_is_finite(y(e, k)%x))) then
               call fatal_error(error, 'contact '//pairs(k)%label//': Khat^{-1} B (the response of the '// &
                                'building to a unit force at floor '//str(pairs(k)%floor(e))//') is not '// &
                                'finite: from dt and the building''s masses, stiffnesses and damping')
               return
            end if
         end do
      end do
      ! F_kl = sum over ends e of k and g of l on the same building of s_e s_g y(g,l)(floor_e).
      do l = 1, m
         do k = 1, m
            f(k, l) = 0.0_dp
            do e = 1, 2
               b = pairs(k)%building(e)
               if (b == 0) cycle
               do g = 1, 2
                  if (pairs(l)%building(g) /= b) cycle
                  f(k, l) = f(k, l) + end_sign(e)*end_sign(g)*y(g, l)%x(located(k)%dof(e))
               end do
            end do
         end do
      end do
      do k = 1, m
         if (.not. all(ieee_is_finite(f(:, k)))) then
            call fatal_error(error, 'contact '//pairs(k)%label//': condensed flexibility F = B^T Khat^{-1} B '// &
                             'is not finite: from dt and the buildings'' masses, stiffnesses and damping')
            return
         end if
      end do
      call contact_init_flexibility(cs, located, f, newmark_dt(states(1)), error)
      if (allocated(error)) return
      call move_alloc(y, cs%y)
   end subroutine contact_init

   !> Dashpot of a joint calibrated to its coefficient of restitution: from the joint
   !> stiffness and the lumped masses of the two facing DOFs (a rigid fixed end: infinite
   !> mass), by the exact relation of the joint pound integrates (`dashpot_of_restitution`).
   subroutine calibrate_dashpot(p, models, error)
      !> The constraint, its DOFs located; its law's dashpot is set.
      type(contact_pair), intent(inout) :: p
      !> The structural models (the lumped masses).
      type(structure_model), intent(in) :: models(:)
      !> Error state (a facing DOF without mass).
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: mass(2)
      integer :: e, b

      mass = 0.0_dp
      do e = 1, 2
         b = p%building(e)
         if (b == 0) cycle
         mass(e) = models(b)%mass(p%dof(e))
         if (.not. (mass(e) > 0.0_dp)) then
            call fatal_error(error, 'contact '//p%label//': restitution needs the mass of floor '// &
                             str(p%floor(e))//' of '//models(b)%name//', which is '//str(mass(e))//' t')
            return
         end if
      end do
      p%law%dashpot = dashpot_of_restitution(p%law%restitution, p%law%stiffness, mass(1), mass(2))
   end subroutine calibrate_dashpot

   !> Set up the joints for a given condensed flexibility F (the structure enters only
   !> through F and v_pred, so F = 0 drives the joints by prescribed closing displacements).
   subroutine contact_init_flexibility(cs, pairs, f, dt, error)
      !> The contact system.
      type(contact_system), intent(out) :: cs
      !> The constraints (ends, gaps, laws).
      type(contact_pair), intent(in) :: pairs(:)
      !> Condensed flexibility F (m, m), symmetric positive semidefinite.
      real(dp), intent(in) :: f(:, :)
      !> Time step (s).
      real(dp), intent(in) :: dt
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, m, ns

      m = size(pairs)
      cs%m = m
      cs%pair = pairs
      cs%f = f
      allocate (cs%joint(m), cs%stats%events(0))
      if (m == 0) return
      cs%c2 = 2.0_dp/dt
      allocate (cs%phat(m), cs%beta(m), cs%rate_a(m), cs%rate_b(m), cs%q(m), cs%vp(m), cs%r_new(m), &
                cs%x_new(m), cs%in_lcp(m), cs%yrow(m), cs%nh(m), cs%phat_inv(m), cs%wm(m), cs%role(m), stat=k)
      if (k /= 0) then
         call fatal_error(error, 'contact: cannot allocate the joint data for '//str(m)//' pairs')
         return
      end if
      cs%n_max = m
      do k = 1, m
         associate (p => cs%pair(k), law => cs%pair(k)%law)
            if (.not. (law%stiffness > 0.0_dp)) then
               call fatal_error(error, 'contact '//p%label//': stiffness must be > 0')
               return
            end if
            if (law%dashpot_rate == rate_trapezoidal) then
               cs%rate_a(k) = cs%c2
               cs%rate_b(k) = 1.0_dp
            else
               cs%rate_a(k) = 1.0_dp/dt
               cs%rate_b(k) = 0.0_dp
            end if
            cs%phat(k) = law%stiffness + cs%rate_a(k)*law%dashpot
            cs%beta(k) = law%stiffness/cs%phat(k)
            cs%phat_inv(k) = 1.0_dp/cs%phat(k)
            if (.not. (ieee_is_finite(cs%phat(k)) .and. ieee_is_finite(1.0_dp/cs%phat(k)))) then
               call fatal_error(error, 'contact '//p%label//': joint stiffness with its dashpot, stiffness + '// &
                                str(cs%rate_a(k))//' dashpot = '//str(cs%phat(k))//' kN/m from stiffness = '// &
                                str(law%stiffness)//', dashpot = '//str(law%dashpot)//' and dt = '// &
                                str(dt)//' is not finite')
               return
            end if
            if (is_plastic(law)) then
               ns = size(law%yp) - 1
               cs%n_max = cs%n_max + 1 + min(ns, initial_hinges)
            end if
         end associate
      end do
      cs%nh = 0
      cs%yrow = 0
      cs%r_new = 0.0_dp
      cs%x_new = 0.0_dp
      allocate (cs%ends(4, m), cs%plain(m))
      do k = 1, m
         cs%plain(k) = plain_law(cs%pair(k)%law)
      end do
      do k = 1, m
         cs%ends(:, k) = [cs%pair(k)%building(1), cs%pair(k)%dof(1), cs%pair(k)%building(2), cs%pair(k)%dof(2)]
      end do
      allocate (cs%as)
      call active_set_init(cs%as, m)
      call lcp_workspace(cs, cs%n_max, error)
   end subroutine contact_init_flexibility

   !> (Re)allocate the LCP work arrays and Lemke's workspace for `n` rows.
   subroutine lcp_workspace(cs, n, error)
      type(contact_system), intent(inout) :: cs
      integer, intent(in) :: n
      type(error_type), allocatable, intent(out) :: error
      integer :: stat

      if (allocated(cs%mat)) deallocate (cs%mat, cs%qa, cs%za, cs%wa, cs%zref, cs%act, cs%guess)
      allocate (cs%mat(n, n), cs%qa(n), cs%za(n), cs%wa(n), cs%zref(n), cs%act(n), cs%guess(n), &
                stat=stat)
      if (stat == 0) call lemke_init(cs%ws, n)
      if (stat /= 0 .or. .not. allocated(cs%ws%binv)) then
         call fatal_error(error, 'contact: cannot allocate the LCP workspace for '//str(n)//' rows ('// &
                          str(3.0_dp*8.0_dp*real(n, dp)**2/2.0_dp**20)//' MiB): too many joints or '// &
                          'envelope segments in one step (reduce dt, the number of &contact pairs or '// &
                          'of envelope points / n_segments)')
         return
      end if
      cs%n_max = n
   end subroutine lcp_workspace



   !> Exchange the data that depend on the time step (Khat^{-1} B, F, the joints' phat, beta
   !> and dashpot rate coefficients, c2) with `other`, a contact system of the same
   !> constraints initialised for another dt; the joints' state and the statistics stay.
   !> No copy, no allocation (`move_alloc`); swapping back restores both.
   subroutine contact_swap_step(cs, other)
      !> The contact system that goes on with the other step.
      type(contact_system), intent(inout) :: cs
      !> The same constraints at the other step (only its step data are used).
      type(contact_system), intent(inout) :: other
      type(column), allocatable :: ty(:, :)
      type(active_set_workspace), allocatable :: ta

      call swap(cs%c2, other%c2)
      call move_alloc(cs%y, ty)
      call move_alloc(other%y, cs%y)
      call move_alloc(ty, other%y)
      call swap(cs%f, other%f)
      call swap(cs%phat, other%phat)
      call swap(cs%beta, other%beta)
      call swap(cs%rate_a, other%rate_a)
      call swap(cs%rate_b, other%rate_b)
      call swap(cs%phat_inv, other%phat_inv)
      ! Each F keeps its active set and factor (the set is brought to the step's guess by
      ! factor updates at the next solve).
      call move_alloc(cs%as, ta)
      call move_alloc(other%as, cs%as)
      call move_alloc(ta, other%as)
   end subroutine contact_swap_step

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

   !> Whether a joint can act in the step predicted in `states` (after `newmark_predict`,
   !> before `contact_step`): one carries force at the start, or one would close with every
   !> force released, at the end of the step (the LCP's q < 0) or inside it (the closing
   !> displacement along the step's average-acceleration path, a parabola, reaches the gap).
   logical function contact_may_act(cs, states) result(acts)
      !> The contact system (not changed).
      type(contact_system), intent(in) :: cs
      !> Integrators with the predicted increments du.
      type(newmark_state), intent(in) :: states(:)
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
      type(newmark_state), intent(in) :: states(:)
      !> Joint.
      integer, intent(in) :: k
      real(dp) :: c0, cv, ca, u0, v0, am, s, h
      integer :: e, b

      h = 2.0_dp/cs%c2
      c0 = 0.0_dp
      cv = 0.0_dp
      ca = 0.0_dp
      do e = 1, 2
         b = cs%pair(k)%building(e)
         if (b == 0) cycle
         call newmark_path(states(b), cs%pair(k)%dof(e), u0, v0, am)
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
      type(newmark_state), intent(in) :: states(:)
      integer :: k

      do k = 1, cs%m
         cs%closing_max(k) = max(cs%closing_max(k), path_closing_max(cs, states, k))
      end do
   end subroutine contact_track_paths

   !> Decide the contact forces at the end of the step and add their effect to du.
   !>
   !> Call after `newmark_predict` of every building and before `newmark_commit`.
   subroutine contact_step(cs, states, t, step, error)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Integrators with the predicted increments du.
      type(newmark_state), intent(inout) :: states(:)
      !> Time at the end of the step (s), for messages.
      real(dp), intent(in) :: t
      !> Step number, for messages.
      integer, intent(in) :: step
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, e, b
      real(dp) :: dr

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
      call contact_solve(cs, cs%vp, t, step, error)
      if (allocated(error)) return

      ! du -= Khat^{-1} B (r_new - r_old), only where the force changed.
      do k = 1, cs%m
         dr = cs%r_new(k) - cs%joint(k)%r
         if (dr == 0.0_dp) cycle
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            call newmark_add_response(states(b), -(end_sign(e)*dr), cs%pair(k)%dof(e), cs%y(e, k)%x)
         end do
      end do
   end subroutine contact_step

   !> The LCP's q of every joint into `cs%q`, the opening it would have at the end of the step
   !> with every force released: g - v_pred + (c (a d_n + b d'_n) + k0 d_p,n)/phat (the one
   !> formula of `contact_solve` and of the short path of `contact_step`).
   pure subroutine released_q(cs, v_pred)
      type(contact_system), intent(inout) :: cs
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
      type(lemke_report) :: rep
      integer :: k, na, n, j, nxt
      integer(int64) :: clock_start, clock_end, clock_rate
      real(dp) :: qnorm, wk, resid, reach
      logical :: added, nonconvex, timed

      if (cs%m == 0) return
      qnorm = 0.0_dp
      call released_q(cs, v_pred)
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
      timed = any(cs%in_lcp)
      if (.not. timed) return
      call system_clock(clock_start, clock_rate)
      ! Elastic joints only: the active-set method from the previous step's set.
      if (cs%solver == lcp_solver_auto) then
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
         added = .false.
         do j = 1, na
            k = cs%act(j)
            if (cs%yrow(k) > 0) cs%x_new(k) = cs%za(cs%yrow(k))/cs%pair(k)%law%stiffness
         end do
         ! Constraints left out must stay open under the new forces.
         do k = 1, cs%m
            if (cs%in_lcp(k) .or. cs%joint(k)%fractured) cycle
            wk = released_opening(cs%f, cs%q, cs%act, na, cs%za, k)
            if (wk < -residual_limit*qnorm) then
               cs%in_lcp(k) = .true.
               added = .true.
            end if
         end do
         ! Plastic flow must not pass a segment end that is not modelled.
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
         if (.not. added) exit
         cs%stats%resolves = cs%stats%resolves + 1
      end do
      if (nonconvex) cs%stats%nonconvex = cs%stats%nonconvex + 1

      ! Verify the accepted solution on the full LCP: the assembled rows and the left-out
      ! constraints.
      call lcp_residual(n, cs%mat, cs%qa, cs%za, cs%wa, cs%f, cs%q, cs%act, na, cs%in_lcp, cs%joint, qnorm, &
                        resid)
      cs%stats%residual_max = max(cs%stats%residual_max, resid)
      call system_clock(clock_end)
      cs%stats%lcp_seconds = cs%stats%lcp_seconds + real(clock_end - clock_start, dp)/real(clock_rate, dp)
      if (.not. (resid <= residual_limit)) then
         call fatal_error(error, 'contact LCP solution rejected at t = '//str(t)//' s (step '// &
                          str(step)//'): natural residual '//str(resid)//' > '//str(residual_limit)// &
                          '; constraints '//labels(cs, cs%act(1:na)))
         return
      end if
   end subroutine contact_solve

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

   !> Update the joints after `newmark_commit`: compression, statistics and energy.
   subroutine contact_commit(cs, states, t, dt)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Integrators at the end of the step.
      type(newmark_state), intent(in) :: states(:)
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
   end subroutine contact_commit

   !> Closing displacements v = B^T u of every constraint into `cs%vp` (left end + u, right
   !> end - u): of the displacements predicted for the end of the step, or of the committed.
   subroutine closing_displacements(cs, states, predicted)
      type(contact_system), intent(inout) :: cs
      type(newmark_state), intent(in) :: states(:)
      logical, intent(in) :: predicted
      integer :: k, b
      real(dp) :: v

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
         type(newmark_state), intent(in) :: st
         integer, intent(in) :: i

         if (predicted) then
            end_u = newmark_predicted(st, i)
         else
            end_u = newmark_u_at(st, i)
         end if
      end function end_u
   end subroutine closing_displacements

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
