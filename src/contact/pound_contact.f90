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
   use pound_strings, only: str
   use pound_newmark, only: newmark_state, newmark_solve, newmark_n, newmark_dt, newmark_predicted, &
                            newmark_u_at, newmark_add_response
   use pound_structure, only: structure_model, structure_end_dof
   use pound_contact_law, only: contact_law, make_elastic, make_elastic_plastic, make_bilinear, &
                                make_piecewise, make_parabola_cubic, is_plastic, yield_force, &
                                yield_segment, rate_trapezoidal, rate_backward_euler, &
                                dashpot_of_restitution
   use pound_config, only: contact_config
   use pound_lemke, only: lemke_workspace, lemke_init, lemke_solve, lemke_report, lcp_evaluate, &
                          lemke_status_name, LEMKE_SOLVED, LEMKE_TRIVIAL
   use pound_lcp_enumerate, only: lcp_enumerate
   implicit none
   private

   public :: contact_pair, contact_system, contact_event, contact_init, contact_init_flexibility
   public :: contact_step, contact_solve, contact_commit, contact_update
   public :: residual_limit, fallback_max_rows, initial_hinges, pairs_from_config
   public :: state_open, state_elastic, state_fractured
   public :: joint_history, joint_history_init, joint_history_record

   !> Largest accepted natural residual of a step's LCP, relative to ||q||.
   real(dp), parameter :: residual_limit = 1.0e-10_dp
   !> Largest LCP (rows) solved by enumeration when Lemke ends on a ray.
   integer, parameter :: fallback_max_rows = 16
   !> Segment ends per joint modelled up front (rows held by the initial workspace); a step
   !> that passes more models them on demand and grows the workspace (no fixed limit).
   integer, parameter :: initial_hinges = 32
   !> Joint state codes (per step; > 0: yielding on that yield segment, 1-based).
   integer, parameter :: state_open = 0, state_elastic = -1, state_fractured = -2

   !> A vector of its own length (Khat^{-1} e of one constraint end).
   type :: column
      real(dp), allocatable :: x(:)
   end type column

   !> One unilateral constraint and its state.
   type :: contact_pair
      !> Text for messages and the listing, e.g. 'A:2-B:2'.
      character(len=:), allocatable :: label
      !> Building index of each end (1 = left, 2 = right); 0 = rigid fixed neighbour.
      integer :: building(2) = 0
      !> Floor of each end (labels, messages, listing); 0: a point between floors at `elevation`.
      integer :: floor(2) = 0
      !> Elevation of the pair (m) when given by elevation (locates ends between floors).
      real(dp) :: elevation = 0.0_dp
      !> DOF of each end in its building's model (set by `contact_init` from the model's
      !> response points: the model says which DOF a floor is).
      integer :: dof(2) = 0
      !> Initial gap g (m).
      real(dp) :: gap = 0.0_dp
      !> Constraint law.
      type(contact_law) :: law
      !> Compressive force r (kN), joint compression d (m) and its rate (m/s).
      real(dp) :: r = 0.0_dp, d = 0.0_dp, ddot = 0.0_dp
      !> Plastic penetration d_p (m) and the plastic increment of the last step (m).
      real(dp) :: plastic = 0.0_dp, x = 0.0_dp
      !> Closing displacement v = B^T u (m).
      real(dp) :: v = 0.0_dp
      !> State after the last step: `state_open`, `state_elastic`, `state_fractured` or the
      !> yield segment (1-based) the joint is yielding on.
      integer :: state = state_open
      !> The joint has fractured (carries nothing from then on), and when (s).
      logical :: fractured = .false.
      real(dp) :: fracture_time = 0.0_dp
      !> Number of impacts (open -> closed transitions).
      integer :: impacts = 0
      !> Time in contact (s), peak force (kN) and its time (s).
      real(dp) :: contact_time = 0.0_dp, peak_force = 0.0_dp, peak_time = 0.0_dp
      !> Largest compression d reached (m).
      real(dp) :: peak_penetration = 0.0_dp
   end type contact_pair

   !> Histories of every joint at the output samples, (n_pairs, n_out) each: what a
   !> result holds of the joints (filled by `joint_history_record`, not field by field).
   type :: joint_history
      !> Contact force r (kN), closing displacement v (m), joint compression d (m) and
      !> plastic penetration d_p (m).
      real(dp), allocatable :: force(:, :), closing(:, :), penetration(:, :), plastic(:, :)
      !> Joint state (`state_open`, `state_elastic`, `state_fractured` or the yield segment).
      integer, allocatable :: state(:, :)
   end type joint_history

   !> A step whose LCP Lemke could not solve, and what was done.
   type :: contact_event
      !> Time (s) and step.
      real(dp) :: time = 0.0_dp
      integer :: step = 0
      !> Lemke's status (`lemke_ray` or `lemke_max_iter`) and the LCP size.
      integer :: status = 0, rows = 0
      !> Solutions found by enumeration (the one nearest the previous state was taken).
      integer :: solutions = 0
      !> The constraints in the LCP.
      character(len=:), allocatable :: pairs
   end type contact_event

   !> All constraints of an analysis, their condensed flexibility and LCP statistics.
   type :: contact_system
      !> Number of constraints.
      integer :: m = 0
      !> The constraints.
      type(contact_pair), allocatable :: pair(:)
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
      !> LCP statistics: solves, total and largest pivot counts, steps needing no pivoting,
      !> warm starts accepted, re-solves after an excluded constraint would have closed or a
      !> segment end was passed, steps with softening rows (non-convex), enumeration fallbacks.
      integer :: solves = 0, pivots_total = 0, pivots_max = 0, trivial = 0, warm = 0, resolves = 0
      integer :: nonconvex = 0, fallbacks = 0, largest_lcp = 0
      !> Largest accepted natural residual.
      real(dp) :: residual_max = 0.0_dp
      !> Wall-clock time (s) spent solving LCPs: assembly, Lemke, checks, re-solves and
      !> fallbacks of the steps in which a joint is closed or predicted to close (the clock is
      !> read only in those steps, so that timing does not slow the step loop).
      real(dp) :: lcp_seconds = 0.0_dp
      !> Pivot cap of each Lemke run (0: Lemke's default, 50 (n + 1)).
      integer :: pivot_cap = 0
      !> Steps Lemke could not solve (fallbacks), in order.
      type(contact_event), allocatable :: events(:)
      integer :: n_events = 0
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
      if (m == 0) return
      cs%c2 = 2.0_dp/dt
      allocate (cs%phat(m), cs%beta(m), cs%rate_a(m), cs%rate_b(m), cs%q(m), cs%vp(m), cs%r_new(m), &
                cs%x_new(m), cs%in_lcp(m), cs%yrow(m), cs%nh(m), stat=k)
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
      allocate (cs%events(0))
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

   !> One constraint per facing floor pair of the deck's `&contact` groups, in deck order.
   function pairs_from_config(contacts, names, error) result(pairs)
      !> The deck's contact groups.
      type(contact_config), intent(in) :: contacts(:)
      !> Building names, in deck order.
      character(len=*), intent(in) :: names(:)
      !> Error state (a law that cannot be built).
      type(error_type), allocatable, intent(out) :: error
      type(contact_pair), allocatable :: pairs(:)
      type(contact_law) :: law
      integer :: i, k, n

      n = 0
      do i = 1, size(contacts)
         n = n + size(contacts(i)%floor_left)
      end do
      allocate (pairs(n))
      n = 0
      do i = 1, size(contacts)
         associate (c => contacts(i))
            select case (c%law)
            case ('elastic_plastic')
               call make_elastic_plastic(law, c%stiffness, c%yield_force, c%dashpot, error)
            case ('bilinear')
               call make_bilinear(law, c%stiffness, c%yield_force, c%second_slope, c%dashpot, error)
            case ('piecewise')
               call make_piecewise(law, c%envelope_d, c%envelope_r, c%dashpot, error)
            case ('parabola_cubic')
               call make_parabola_cubic(law, c%stiffness, c%peak_penetration, c%fracture_penetration, &
                                        c%n_segments, c%dashpot, error)
            case default
               call make_elastic(law, c%stiffness, c%dashpot, error)
            end select
            if (allocated(error)) then
               error%message = '&contact #'//str(i)//': '//error%message
               return
            end if
            if (c%dashpot_rate == 'trapezoidal') then
               law%dashpot_rate = rate_trapezoidal
            else
               law%dashpot_rate = rate_backward_euler
            end if
            law%restitution = c%restitution
            do k = 1, size(c%floor_left)
               n = n + 1
               pairs(n)%building = [c%left_index, c%right_index]
               pairs(n)%floor = [c%floor_left(k), c%floor_right(k)]
               if (allocated(c%elevation)) pairs(n)%elevation = c%elevation(k)
               pairs(n)%label = trim(names(c%left_index))//':'//end_text(pairs(n), 1)//'-'// &
                                trim(names(c%right_index))//':'//end_text(pairs(n), 2)
               pairs(n)%gap = c%gap(k)
               pairs(n)%law = law
            end do
         end associate
      end do
   end function pairs_from_config

   !> A pair end in labels: its floor, or its elevation for a point between floors ('z3.25m').
   pure function end_text(p, e) result(s)
      !> The pair (its floors and elevation set).
      type(contact_pair), intent(in) :: p
      !> End: 1 (left building) or 2 (right building).
      integer, intent(in) :: e
      character(len=:), allocatable :: s
      character(len=32) :: buf

      if (p%floor(e) > 0) then
         s = str(p%floor(e))
      else
         write (buf, '(f0.3)') p%elevation
         s = trim(adjustl(buf))
         if (s(1:1) == '.') s = '0'//s
         do while (s(len(s):len(s)) == '0')
            s = s(1:len(s) - 1)
         end do
         if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
         s = 'z'//s//'m'
      end if
   end function end_text

   !> Sign of a constraint end in B: +1 on the left, -1 on the right.
   pure real(dp) function end_sign(e)
      integer, intent(in) :: e

      end_sign = merge(1.0_dp, -1.0_dp, e == 1)
   end function end_sign

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
      integer :: k, e, b, i
      real(dp) :: vp, dr

      if (cs%m == 0) return
      ! Closing displacement if every force were released in this step.
      do k = 1, cs%m
         vp = 0.0_dp
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            i = cs%pair(k)%dof(e)
            vp = vp + end_sign(e)*newmark_predicted(states(b), i)
         end do
         cs%vp(k) = vp
      end do
      do k = 1, cs%m
         if (cs%pair(k)%r /= 0.0_dp) cs%vp = cs%vp + cs%f(:, k)*cs%pair(k)%r
      end do
      call contact_solve(cs, cs%vp, t, step, error)
      if (allocated(error)) return

      ! du -= Khat^{-1} B (r_new - r_old), only where the force changed.
      do k = 1, cs%m
         dr = cs%r_new(k) - cs%pair(k)%r
         if (dr == 0.0_dp) cycle
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            call newmark_add_response(states(b), -(end_sign(e)*dr), cs%y(e, k)%x)
         end do
      end do
   end subroutine contact_step

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
      do k = 1, cs%m
         associate (p => cs%pair(k), c => cs%pair(k)%law%dashpot)
            cs%q(k) = p%gap - v_pred(k) + (c*(cs%rate_a(k)*p%d + cs%rate_b(k)*p%ddot) + &
                                           p%law%stiffness*p%plastic)/cs%phat(k)
            cs%in_lcp(k) = .not. p%fractured .and. (p%r > 0.0_dp .or. cs%q(k) < 0.0_dp)
            if (.not. p%fractured) qnorm = max(qnorm, abs(cs%q(k)))
         end associate
      end do
      ! Guard: nothing that is not finite reaches the LCP solver.
      do k = 1, cs%m
         if (cs%pair(k)%fractured .or. ieee_is_finite(cs%q(k))) cycle
         call fatal_error(error, 'contact '//cs%pair(k)%label//': the step''s LCP data is not finite at t = '// &
                          str(t)//' s (step '//str(step)//'): predicted closing displacement '// &
                          str(v_pred(k))//' m, joint compression '//str(cs%pair(k)%d)//' m, rate '// &
                          str(cs%pair(k)%ddot)//' m/s, plastic penetration '//str(cs%pair(k)%plastic)//' m')
         return
      end do
      qnorm = max(qnorm, tiny(1.0_dp))
      ! Segment ends within reach: those the plastic increment would pass if the joint alone
      ! took up all of its predicted penetration -q plastically (more are added on demand).
      do k = 1, cs%m
         cs%nh(k) = 0
         if (.not. cs%in_lcp(k) .or. .not. is_plastic(cs%pair(k)%law)) cycle
         associate (law => cs%pair(k)%law, pl => cs%pair(k)%plastic)
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

      cs%r_new = 0.0_dp
      cs%x_new = 0.0_dp
      ! The clock is read only when there is an LCP to solve.
      timed = any(cs%in_lcp)
      if (timed) call system_clock(clock_start, clock_rate)
      do
         call assemble(cs, na, n, nonconvex, error)
         if (allocated(error)) return
         if (n == 0) exit
         cs%largest_lcp = max(cs%largest_lcp, n)
         if (cs%pivot_cap > 0) then
            call lemke_solve(cs%ws, n, cs%mat, cs%qa, cs%za, cs%wa, rep, active_guess=cs%guess(1:n), &
                             max_pivots=cs%pivot_cap)
         else
            call lemke_solve(cs%ws, n, cs%mat, cs%qa, cs%za, cs%wa, rep, active_guess=cs%guess(1:n))
         end if
         cs%solves = cs%solves + 1
         cs%pivots_total = cs%pivots_total + rep%pivots
         cs%pivots_max = max(cs%pivots_max, rep%pivots)
         if (rep%status == LEMKE_TRIVIAL) cs%trivial = cs%trivial + 1
         if (rep%warm_started) cs%warm = cs%warm + 1
         if (rep%status /= LEMKE_SOLVED .and. rep%status /= LEMKE_TRIVIAL) then
            ! A missing segment end can leave the model without a solution (a softening
            ! line extended below r = 0): model one more wherever there is one, and retry.
            if (more_hinges(cs, na)) then
               cs%resolves = cs%resolves + 1
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
            if (cs%in_lcp(k) .or. cs%pair(k)%fractured) cycle
            wk = cs%q(k) + dot_product(cs%f(k, cs%act(1:na)), cs%za(1:na))
            if (wk < -residual_limit*qnorm) then
               cs%in_lcp(k) = .true.
               added = .true.
            end if
         end do
         ! Plastic flow must not pass a segment end that is not modelled.
         do j = 1, na
            k = cs%act(j)
            if (cs%yrow(k) == 0 .or. cs%x_new(k) <= 0.0_dp) cycle
            associate (law => cs%pair(k)%law, pl => cs%pair(k)%plastic)
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
         cs%resolves = cs%resolves + 1
      end do
      if (nonconvex) cs%nonconvex = cs%nonconvex + 1

      ! Verify the accepted solution on the full LCP: the assembled rows and the left-out
      ! constraints.
      resid = 0.0_dp
      if (n > 0) then
         call lcp_evaluate(n, cs%mat, cs%qa, cs%za, cs%wa, resid)
         resid = resid*max(maxval(abs(cs%qa(1:n))), tiny(1.0_dp))
      end if
      do k = 1, cs%m
         if (cs%in_lcp(k) .or. cs%pair(k)%fractured) cycle
         wk = cs%q(k)
         if (na > 0) wk = wk + dot_product(cs%f(k, cs%act(1:na)), cs%za(1:na))
         resid = max(resid, abs(min(0.0_dp, wk)))
      end do
      if (n > 0) qnorm = max(qnorm, maxval(abs(cs%qa(1:n))))
      resid = resid/qnorm
      cs%residual_max = max(cs%residual_max, resid)
      if (timed) then
         call system_clock(clock_end)
         cs%lcp_seconds = cs%lcp_seconds + real(clock_end - clock_start, dp)/real(clock_rate, dp)
      end if
      if (.not. (resid <= residual_limit)) then
         call fatal_error(error, 'contact LCP solution rejected at t = '//str(t)//' s (step '// &
                          str(step)//'): natural residual '//str(resid)//' > '//str(residual_limit)// &
                          '; constraints '//labels(cs, cs%act(1:na)))
         return
      end if
   end subroutine contact_solve

   !> Assemble the LCP of the constraints in `cs%in_lcp` (contact rows 1..na, then per
   !> plastic joint its yield row and `cs%nh` hinge rows), the warm-start guess and the
   !> reference point (previous forces, no plastic flow).
   subroutine assemble(cs, na, n, nonconvex, error)
      type(contact_system), intent(inout) :: cs
      integer, intent(out) :: na, n
      logical, intent(inout) :: nonconvex
      type(error_type), allocatable, intent(out) :: error
      integer :: i, j, k, l, seg, iy, n_full
      real(dp) :: k0, rs

      na = 0
      do k = 1, cs%m
         cs%yrow(k) = 0
         if (.not. cs%in_lcp(k)) cycle
         na = na + 1
         cs%act(na) = k
      end do
      n = na
      do j = 1, na
         k = cs%act(j)
         if (.not. is_plastic(cs%pair(k)%law)) cycle
         n = n + 1
         cs%yrow(k) = n
         n = n + cs%nh(k)
      end do
      if (n == 0) return
      if (n > cs%n_max) then
         ! More segment ends passed in one step than the workspace holds: grow it (rare).
         n_full = cs%m
         do k = 1, cs%m
            if (is_plastic(cs%pair(k)%law)) n_full = n_full + size(cs%pair(k)%law%yp)
         end do
         call lcp_workspace(cs, max(n, min(2*cs%n_max, n_full)), error)
         if (allocated(error)) return
         ! act(1:na) was set above in the old arrays.
         na = 0
         do k = 1, cs%m
            if (.not. cs%in_lcp(k)) cycle
            na = na + 1
            cs%act(na) = k
         end do
      end if
      cs%mat(1:n, 1:n) = 0.0_dp
      do j = 1, na
         do i = 1, na
            cs%mat(i, j) = cs%f(cs%act(i), cs%act(j))
         end do
         k = cs%act(j)
         cs%mat(j, j) = cs%mat(j, j) + 1.0_dp/cs%phat(k)
         cs%qa(j) = cs%q(k)
         cs%guess(j) = cs%pair(k)%r > 0.0_dp
         cs%zref(j) = cs%pair(k)%r
      end do
      do j = 1, na
         k = cs%act(j)
         iy = cs%yrow(k)
         if (iy == 0) cycle
         associate (p => cs%pair(k), law => cs%pair(k)%law, b => cs%beta(k))
            k0 = law%stiffness
            seg = yield_segment(law, p%plastic)
            rs = k0*(p%d - p%plastic)
            cs%mat(j, iy) = b/k0
            cs%mat(iy, j) = -b/k0
            cs%mat(iy, iy) = (law%yh(seg) + k0*(1.0_dp - b))/k0**2
            cs%qa(iy) = (yield_force(law, p%plastic) - (1.0_dp - b)*rs - &
                         b*cs%rate_b(k)*law%dashpot*p%ddot)/k0
            cs%guess(iy) = p%x > 0.0_dp
            cs%zref(iy) = 0.0_dp
            if (law%yh(seg) < 0.0_dp) nonconvex = .true.
            do l = 1, cs%nh(k)
               i = iy + l
               cs%mat(iy, i) = (law%yh(seg + l) - law%yh(seg + l - 1))/k0**2
               cs%mat(i, iy) = -1.0_dp/k0
               cs%mat(i, i) = 1.0_dp/k0
               cs%qa(i) = law%yp(seg + l) - p%plastic
               cs%guess(i) = .false.
               cs%zref(i) = 0.0_dp
               if (law%yh(seg + l) < 0.0_dp) nonconvex = .true.
            end do
         end associate
      end do
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
         if (yield_segment(cs%pair(k)%law, cs%pair(k)%plastic) + cs%nh(k) >= size(cs%pair(k)%law%yp) - 1) cycle
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
      type(contact_event), allocatable :: grown(:)
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
      cs%fallbacks = cs%fallbacks + 1
      cs%n_events = cs%n_events + 1
      if (cs%n_events > size(cs%events)) then
         allocate (grown(max(8, 2*size(cs%events))))
         grown(1:size(cs%events)) = cs%events
         call move_alloc(grown, cs%events)
      end if
      cs%events(cs%n_events) = contact_event(time=t, step=step, status=rep%status, rows=n, &
                                             solutions=nsol, pairs=who)
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
      integer :: k, e, b

      ! The closing displacements at the end of the step.
      do k = 1, cs%m
         cs%vp(k) = 0.0_dp
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            cs%vp(k) = cs%vp(k) + end_sign(e)*newmark_u_at(states(b), cs%pair(k)%dof(e))
         end do
      end do
      call contact_update(cs, cs%vp, t, dt)
   end subroutine contact_commit

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
      integer :: k, seg, ns
      real(dp) :: r, r0, d, ddot, pl, k0, rs0, rs, tol

      do k = 1, cs%m
         associate (p => cs%pair(k), c => cs%pair(k)%law%dashpot)
            k0 = p%law%stiffness
            r0 = p%r
            r = cs%r_new(k)
            if (p%fractured) then
               cs%work = cs%work + 0.5_dp*r0*(v(k) - p%v)
               p%r = 0.0_dp
               p%v = v(k)
               cycle
            end if
            pl = p%plastic + cs%x_new(k)
            seg = 0
            if (is_plastic(p%law)) then
               ! Land exactly on a segment end passed within round-off.
               seg = yield_segment(p%law, pl)
               ns = size(p%law%yp) - 1
               if (ns > 0) then
                  tol = 1.0e-9_dp*(p%law%yp(min(seg + 1, ns)) - p%law%yp(min(seg + 1, ns) - 1))
                  if (seg < ns .and. p%law%yp(min(seg + 1, ns)) - pl <= tol) then
                     seg = seg + 1
                     pl = p%law%yp(seg)
                  else if (seg > 0 .and. pl - p%law%yp(seg) <= tol) then
                     pl = p%law%yp(seg)
                  end if
               end if
            end if
            ! The spring-dashpot evolves by its own law also while the gap is open (r = 0):
            ! k0 (d - d_p) + c d' = 0 relaxes d, which stays d_p without a dashpot.
            d = (r + c*(cs%rate_a(k)*p%d + cs%rate_b(k)*p%ddot) + k0*pl)/cs%phat(k)
            ddot = cs%rate_a(k)*(d - p%d) - cs%rate_b(k)*p%ddot
            rs0 = k0*(p%d - p%plastic)
            rs = k0*(d - pl)
            if (r > 0.0_dp) then
               if (r0 == 0.0_dp) p%impacts = p%impacts + 1
               p%contact_time = p%contact_time + dt
               if (r > p%peak_force) then
                  p%peak_force = r
                  p%peak_time = t
               end if
               p%state = state_elastic
               ! Yielding: on the segment the flow ended in (at a segment end, the one before).
               if (cs%x_new(k) > 0.0_dp) p%state = seg + merge(0, 1, seg > 0 .and. pl == p%law%yp(seg))
            else
               p%state = state_open
            end if
            cs%work = cs%work + 0.5_dp*(r0 + r)*(v(k) - p%v)
            cs%element_work = cs%element_work + 0.5_dp*(r0 + r)*(d - p%d)
            cs%plastic_work = cs%plastic_work + 0.5_dp*(rs0 + rs)*cs%x_new(k)
            p%peak_penetration = max(p%peak_penetration, d)
            p%r = r
            p%d = d
            p%ddot = ddot
            p%v = v(k)
            p%x = cs%x_new(k)
            p%plastic = pl
            if (p%law%fractures) then
               if (pl >= p%law%yp(size(p%law%yp) - 1)) then
                  p%fractured = .true.
                  p%fracture_time = t
                  p%state = state_fractured
               end if
            end if
         end associate
      end do
   end subroutine contact_update

   !> Histories for `m` joints and `n` output samples, the first sample (t = 0) at rest and
   !> open. `stat` /= 0 when the memory cannot be had (nothing is kept then).
   pure subroutine joint_history_init(h, m, n, stat)
      !> The histories.
      type(joint_history), intent(out) :: h
      !> Number of joints and of output samples.
      integer, intent(in) :: m, n
      !> Allocation status.
      integer, intent(out) :: stat

      allocate (h%force(m, n), h%closing(m, n), h%penetration(m, n), h%plastic(m, n), h%state(m, n), &
                stat=stat)
      if (stat /= 0) then
         h = joint_history()
         return
      end if
      if (n < 1) return
      h%force(:, 1) = 0.0_dp
      h%closing(:, 1) = 0.0_dp
      h%penetration(:, 1) = 0.0_dp
      h%plastic(:, 1) = 0.0_dp
      h%state(:, 1) = state_open
   end subroutine joint_history_init

   !> Store the joints' state as output sample k.
   pure subroutine joint_history_record(h, k, cs)
      !> The histories.
      type(joint_history), intent(inout) :: h
      !> Output sample.
      integer, intent(in) :: k
      !> The contact system after the step.
      type(contact_system), intent(in) :: cs
      integer :: ip

      do ip = 1, cs%m
         h%force(ip, k) = cs%pair(ip)%r
         h%closing(ip, k) = cs%pair(ip)%v
         h%penetration(ip, k) = cs%pair(ip)%d
         h%plastic(ip, k) = cs%pair(ip)%plastic
         h%state(ip, k) = cs%pair(ip)%state
      end do
   end subroutine joint_history_record

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
