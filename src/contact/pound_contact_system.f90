!> The contact system of an analysis: its joints (definitions and state), the structure
!> condensed onto them (Khat^{-1} B and F = B^T Khat^{-1} B), the per-joint constants of the
!> step (phat, beta, dashpot rate) and the LCP workspace; set up once per time step size
!> (`contact_init`, `contact_init_flexibility`) and exchanged between step sizes
!> (`contact_swap_step`). The step itself is pound_contact.
module pound_contact_system
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_integrator, only: integrator, trapezoid_rate
   use pound_structure, only: structure_model, structure_end_row, recovery_rows, recover
   use pound_contact_friction, only: friction_set, friction_vector
   use pound_contact_law, only: is_plastic, rate_trapezoidal
   use pound_contact_pair, only: contact_pair, end_sign, end_value, end_load, end_mass, end_single_dof
   use pound_joint_state, only: joint_state, plain_law
   use pound_lcp_statistics, only: lcp_statistics
   use pound_lemke, only: lemke_workspace, lemke_init
   use pound_lcp_active_set, only: active_set_workspace, active_set_init
   use pound_swap, only: swap
   implicit none
   private

   public :: contact_system, column, contact_init, contact_init_flexibility, contact_swap_step, lcp_workspace, &
             joint_constants
   public :: residual_limit, fallback_max_rows, initial_hinges, lcp_solver_auto, lcp_solver_lemke


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
      !> The integrator's velocity per displacement increment (`integrator%velocity_rate`), the
      !> dashpot rate coefficient of a joint whose compression rate follows the structure's
      !> step (`rate_trapezoidal`), and the span of the step's path (`integrator%path_span`).
      real(dp) :: rate = 0.0_dp, span = 0.0_dp
      !> Largest LCP size (rows) the workspace holds.
      integer :: n_max = 0
      !> Step work arrays: contact q, new forces and plastic increments, LCP data.
      real(dp), allocatable :: q(:), r_new(:), x_new(:), mat(:, :), qa(:), za(:), wa(:), zref(:)
      !> Closing displacements if all forces were released (m).
      real(dp), allocatable :: vp(:)
      !> Each constraint's ends packed for the per-step loops: building and DOF of the left
      !> end (rows 1, 2) and of the right end (rows 3, 4); building 0: rigid (4, m).
      integer, allocatable :: ends(:, :)
      !> Some end is a row of several DOFs (its `ends` DOF is 0): the per-step loops take
      !> the rows (`contact_pair%end_row`) instead of the packed DOFs.
      logical :: general_ends = .false.
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
      !> The joints whose law iterates (`joint_law%iterates`; none for piecewise-linear laws):
      !> `contact_solve` re-linearises them and solves again until none moves.
      integer, allocatable :: iterating(:)
      !> When allocated (`contact_track_closing`): per joint, the largest closing displacement
      !> released of every force that the steps have predicted so far, at the steps' ends
      !> (`contact_step`) and, where `contact_track_paths` is called, inside them (m).
      real(dp), allocatable :: closing_max(:)
      !> Coulomb friction at the contact points with mu > 0 (pound_contact_friction; `fr%n`
      !> = 0: none, and no tangential row anywhere).
      type(friction_set) :: fr
   end type contact_system

contains


   !> Condense the structure onto the constraints: Khat^{-1} B and F.
   subroutine contact_init(cs, pairs, states, models, error)
      !> The contact system.
      type(contact_system), intent(out) :: cs
      !> The constraints (ends, gaps, laws).
      type(contact_pair), intent(in) :: pairs(:)
      !> Initialised integrators (their factored Khat).
      class(integrator), intent(in) :: states(:)
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
            ! An end given as a row is kept; else the model locates the floor or elevation.
            if (pairs(k)%end_row(e)%n == 0) located(k)%end_row(e) = structure_end_row(models(b), e, &
                                                                                     pairs(k)%floor(e), pairs(k)%elevation)
            associate (row => located(k)%end_row(e))
               if (row%n /= 1) then
                  call fatal_error(error, 'contact '//pairs(k)%label//': building '//models(b)%name// &
                                   ' has no node at the contact point')
                  return
               end if
               if (any(row%dof(row%start(1):row%start(2) - 1) < 1 .or. &
                       row%dof(row%start(1):row%start(2) - 1) > states(b)%dofs())) then
                  call fatal_error(error, 'contact '//pairs(k)%label//': an end row names a DOF outside '// &
                                   'building '//models(b)%name//' (1..'//str(states(b)%dofs())//')')
                  return
               end if
               ! The scale folded into the weights (scale 1: the step passes the weights to the
               ! integrator as they are stored, no temporary).
               row%coef = row%scale(1)*row%coef
               row%scale(1) = 1.0_dp
               located(k)%dof(e) = end_single_dof(row)
            end associate
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
            allocate (y(e, k)%x(states(b)%dofs()), stat=stat)
            if (stat /= 0) then
               call fatal_error(error, 'contact '//pairs(k)%label//': cannot allocate Khat^{-1} B ('// &
                                str(states(b)%dofs())//' reals per pair end; fewer pairs or storeys)')
               return
            end if
            y(e, k)%x = 0.0_dp
            call end_load(located(k), e, y(e, k)%x)
            call states(b)%solve(y(e, k)%x)
            if (.not. all(ieee_is_finite(y(e, k)%x))) then
               call fatal_error(error, 'contact '//pairs(k)%label//': Khat^{-1} B (the response of the '// &
                                'building to a unit force at floor '//str(pairs(k)%floor(e))//') is not '// &
                                'finite: from dt and the building''s masses, stiffnesses and damping')
               return
            end if
         end do
      end do
      ! F_kl = sum over ends e of k and g of l on the same building of s_e s_g B_e^T y(g,l).
      do l = 1, m
         do k = 1, m
            f(k, l) = 0.0_dp
            do e = 1, 2
               b = pairs(k)%building(e)
               if (b == 0) cycle
               do g = 1, 2
                  if (pairs(l)%building(g) /= b) cycle
                  f(k, l) = f(k, l) + end_sign(e)*end_sign(g)*end_value(located(k), e, y(g, l)%x)
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
      call contact_init_flexibility(cs, located, f, states(1)%step_size(), error, states(1)%velocity_rate())
      if (allocated(error)) return
      cs%span = states(1)%path_span()
      if (any(cs%pair(:)%friction > 0.0_dp)) then
         call friction_init(cs%fr, cs%pair, y, states, error)
         if (allocated(error)) return
         call lcp_workspace(cs, cs%n_max + 2*cs%fr%n, error)
         if (allocated(error)) return
      end if
      call move_alloc(y, cs%y)
   end subroutine contact_init

   !> The contact points with friction (mu > 0) of `pairs`: their tangential ends as rows,
   !> Khat^{-1} C and the condensed flexibilities C^T Khat^{-1} C, C^T Khat^{-1} B and
   !> B^T Khat^{-1} C, and the step's work arrays.
   subroutine friction_init(fr, pairs, y, states, error)
      !> The friction set (built).
      type(friction_set), intent(out) :: fr
      !> The constraints, their ends located (their tangential rows' scale is folded here).
      type(contact_pair), intent(inout) :: pairs(:)
      !> Khat^{-1} B of every normal end.
      type(column), intent(in) :: y(:, :)
      !> Initialised integrators.
      class(integrator), intent(in) :: states(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, j, k, l, e, g, b, m, n

      m = size(pairs)
      n = count(pairs(:)%friction > 0.0_dp)
      fr%n = n
      allocate (fr%joint(n), fr%index(m), fr%mu(n), fr%kt(n), fr%y(2, n), fr%gtt(n, n), fr%gtn(n, m), &
                fr%gnt(m, n), fr%p(n), fr%e(n), fr%force_new(n), fr%slip_new(n), fr%sub(n), fr%jrow(n), &
                fr%s_mat(n, n), fr%x_mat(n, m + 1 + n), fr%qx(m))
      fr%index = 0
      i = 0
      do k = 1, m
         if (.not. (pairs(k)%friction > 0.0_dp)) cycle
         i = i + 1
         fr%joint(i) = k
         fr%index(k) = i
         fr%mu(i) = pairs(k)%friction
         fr%kt(i) = pairs(k)%shear_stiffness
         if (.not. (fr%kt(i) > 0.0_dp)) then
            call fatal_error(error, 'contact '//pairs(k)%label//': friction needs a shear_stiffness > 0')
            return
         end if
         do e = 1, 2
            b = pairs(k)%building(e)
            if (b == 0) cycle
            associate (row => pairs(k)%tan_row(e))
               if (row%n /= 1) then
                  call fatal_error(error, 'contact '//pairs(k)%label//': friction needs the end''s '// &
                                   'displacement along the facade (a building in plan)')
                  return
               end if
               if (any(row%dof(row%start(1):row%start(2) - 1) < 1 .or. &
                       row%dof(row%start(1):row%start(2) - 1) > states(b)%dofs())) then
                  call fatal_error(error, 'contact '//pairs(k)%label//': a tangential end row names a DOF '// &
                                   'outside its building (1..'//str(states(b)%dofs())//')')
                  return
               end if
               row%coef = row%scale(1)*row%coef
               row%scale(1) = 1.0_dp
               allocate (fr%y(e, i)%x(states(b)%dofs()))
               fr%y(e, i)%x = 0.0_dp
               do l = row%start(1), row%start(2) - 1
                  fr%y(e, i)%x(row%dof(l)) = fr%y(e, i)%x(row%dof(l)) + row%coef(l)
               end do
               call states(b)%solve(fr%y(e, i)%x)
            end associate
         end do
      end do
      fr%gtt = 0.0_dp
      fr%gtn = 0.0_dp
      fr%gnt = 0.0_dp
      do i = 1, n
         k = fr%joint(i)
         do e = 1, 2
            b = pairs(k)%building(e)
            if (b == 0) cycle
            do j = 1, n
               l = fr%joint(j)
               do g = 1, 2
                  if (pairs(l)%building(g) /= b) cycle
                  fr%gtt(i, j) = fr%gtt(i, j) + end_sign(e)*end_sign(g)*recover(pairs(k)%tan_row(e), 1, fr%y(g, j)%x)
               end do
            end do
            do l = 1, m
               do g = 1, 2
                  if (pairs(l)%building(g) /= b) cycle
                  fr%gtn(i, l) = fr%gtn(i, l) + end_sign(e)*end_sign(g)*recover(pairs(k)%tan_row(e), 1, y(g, l)%x)
                  fr%gnt(l, i) = fr%gnt(l, i) + end_sign(e)*end_sign(g)*end_value(pairs(l), g, fr%y(e, i)%x)
               end do
            end do
         end do
      end do
      if (.not. (all(ieee_is_finite(fr%gtt)) .and. all(ieee_is_finite(fr%gtn)) .and. all(ieee_is_finite(fr%gnt)))) then
         call fatal_error(error, 'contact: the condensed tangential flexibility C^T Khat^{-1} C is not finite: '// &
                          'from dt and the buildings'' masses, stiffnesses and damping')
         return
      end if
      fr%force_new = 0.0_dp
      fr%slip_new = 0.0_dp
      fr%e = 0.0_dp
   end subroutine friction_init

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
         if (p%mass_dof(e) > 0) then
            mass(e) = p%share*models(b)%mass(p%mass_dof(e))
         else
            mass(e) = end_mass(p, e, models(b)%mass)
         end if
         if (.not. (mass(e) > 0.0_dp)) then
            call fatal_error(error, 'contact '//p%label//': restitution needs the mass of floor '// &
                             str(p%floor(e))//' of '//models(b)%name//', which is '//str(mass(e))//' t')
            return
         end if
      end do
      call p%law%calibrate(mass(1), mass(2))
   end subroutine calibrate_dashpot

   !> Set up the joints for a given condensed flexibility F (the structure enters only
   !> through F and v_pred, so F = 0 drives the joints by prescribed closing displacements).
   subroutine contact_init_flexibility(cs, pairs, f, dt, error, rate)
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
      !> The integrator's velocity per displacement increment (1/s; default: the trapezoidal
      !> rule's, `trapezoid_rate`).
      real(dp), intent(in), optional :: rate
      integer :: k, m, ns, e

      m = size(pairs)
      cs%m = m
      cs%pair = pairs
      cs%f = f
      allocate (cs%joint(m), cs%stats%events(0))
      if (m == 0) return
      if (present(rate)) then
         cs%rate = rate
      else
         cs%rate = trapezoid_rate(dt)
      end if
      cs%span = dt
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
               cs%rate_a(k) = cs%rate
               cs%rate_b(k) = 1.0_dp
            else
               cs%rate_a(k) = 1.0_dp/dt
               cs%rate_b(k) = 0.0_dp
            end if
            call joint_constants(cs, k)
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
      allocate (cs%ends(4, m), cs%plain(m), cs%iterating(0))
      do k = 1, m
         cs%plain(k) = plain_law(cs%pair(k)%law)
         if (.not. allocated(cs%pair(k)%law%given)) cycle
         if (cs%pair(k)%law%given%iterates()) cs%iterating = [cs%iterating, k]
      end do
      do k = 1, m
         cs%ends(:, k) = [cs%pair(k)%building(1), cs%pair(k)%dof(1), cs%pair(k)%building(2), cs%pair(k)%dof(2)]
         do e = 1, 2
            if (cs%ends(2*e - 1, k) > 0 .and. cs%ends(2*e, k) == 0 .and. cs%pair(k)%end_row(e)%n > 0) &
               cs%general_ends = .true.
         end do
      end do
      allocate (cs%as)
      call active_set_init(cs%as, m)
      call lcp_workspace(cs, cs%n_max, error)
   end subroutine contact_init_flexibility

   !> The step constants of joint k from its law's stiffness k0 and dashpot c and the dashpot
   !> rate coefficient a: phat = k0 + a c, beta = k0/phat, 1/phat.
   pure subroutine joint_constants(cs, k)
      !> The contact system (`rate_a` set).
      type(contact_system), intent(inout) :: cs
      !> Joint.
      integer, intent(in) :: k

      associate (law => cs%pair(k)%law)
         cs%phat(k) = law%stiffness + cs%rate_a(k)*law%dashpot
         cs%beta(k) = law%stiffness/cs%phat(k)
         cs%phat_inv(k) = 1.0_dp/cs%phat(k)
      end associate
   end subroutine joint_constants

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
   !> and dashpot rate coefficients, the integrator's rate and path span) with `other`, a contact system of the same
   !> constraints initialised for another dt; the joints' state and the statistics stay.
   !> No copy, no allocation (`move_alloc`); swapping back restores both.
   subroutine contact_swap_step(cs, other)
      !> The contact system that goes on with the other step.
      type(contact_system), intent(inout) :: cs
      !> The same constraints at the other step (only its step data are used).
      type(contact_system), intent(inout) :: other
      type(column), allocatable :: ty(:, :)
      type(active_set_workspace), allocatable :: ta
      type(friction_vector), allocatable :: ty2(:, :)

      call swap(cs%rate, other%rate)
      call swap(cs%span, other%span)
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
      if (cs%fr%n > 0) then
         call move_alloc(cs%fr%y, ty2)
         call move_alloc(other%fr%y, cs%fr%y)
         call move_alloc(ty2, other%fr%y)
         call swap(cs%fr%gtt, other%fr%gtt)
         call swap(cs%fr%gtn, other%fr%gtn)
         call swap(cs%fr%gnt, other%fr%gnt)
      end if
   end subroutine contact_swap_step

end module pound_contact_system
