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
!> With the spring-dashpot law r = p d + c d' (trapezoidal d', phat = p + c2 c) and the open
!> gap w = g - v + d, each step is the LCP
!>
!>   w = (F + diag(1/phat)) r + q,  r >= 0, w >= 0, r.w = 0,  q = g - v_pred + c (c2 d_n + d'_n)/phat,
!>
!> solved by Lemke's method (pound_lemke) over the constraints that can close in this step:
!> those carrying force at the start of the step or whose q < 0. The others are checked
!> after the solve (w_k = q_k + F_kA r_A >= 0) and, if one would penetrate, added and the
!> LCP solved again, so the accepted r solves the full LCP; its natural residual
!> ||min(r, w)||_inf / ||q||_inf over all constraints must be below `residual_limit`.
!> Khat^{-1} B is computed once (one tridiagonal solve per constraint end).
module pound_contact
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_shear_building, only: shear_building
   use pound_newmark, only: newmark_state, newmark_solve
   use pound_contact_law, only: contact_law, law_elastic
   use pound_config, only: contact_config
   use pound_lemke, only: lemke_workspace, lemke_init, lemke_solve, lemke_report, &
                          lemke_status_name, LEMKE_SOLVED, LEMKE_TRIVIAL
   implicit none
   private

   public :: contact_pair, contact_system, contact_init, contact_step, contact_commit
   public :: residual_limit, pairs_from_config

   !> Largest accepted natural residual of a step's LCP, relative to ||q||.
   real(dp), parameter :: residual_limit = 1.0e-10_dp

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
      !> Floor of each end.
      integer :: floor(2) = 0
      !> Initial gap g (m).
      real(dp) :: gap = 0.0_dp
      !> Constraint law.
      type(contact_law) :: law
      !> Compressive force r (kN), spring compression d (m) and its rate (m/s).
      real(dp) :: r = 0.0_dp, d = 0.0_dp, ddot = 0.0_dp
      !> Closing displacement v = B^T u (m).
      real(dp) :: v = 0.0_dp
      !> Number of impacts (open -> closed transitions).
      integer :: impacts = 0
      !> Time in contact (s), peak force (kN) and its time (s).
      real(dp) :: contact_time = 0.0_dp, peak_force = 0.0_dp, peak_time = 0.0_dp
   end type contact_pair

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
      !> Effective joint stiffness phat = p + c2 c.
      real(dp), allocatable :: phat(:)
      !> Newmark c2 = 2/dt.
      real(dp) :: c2 = 0.0_dp
      !> Step work arrays.
      real(dp), allocatable :: q(:), r_new(:), mat(:, :), qa(:), za(:), wa(:)
      integer, allocatable :: act(:)
      logical, allocatable :: in_lcp(:), guess(:)
      type(lemke_workspace) :: ws
      !> Work of the contact forces on the structure, sum r_avg dv (kJ).
      real(dp) :: work = 0.0_dp
      !> Work stored in or dissipated by the joints, sum r_avg dd (kJ).
      real(dp) :: element_work = 0.0_dp
      !> LCP statistics: solves, total and largest pivot counts, steps needing no pivoting,
      !> warm starts accepted, re-solves after an excluded constraint would have closed.
      integer :: solves = 0, pivots_total = 0, pivots_max = 0, trivial = 0, warm = 0, resolves = 0
      !> Largest accepted natural residual.
      real(dp) :: residual_max = 0.0_dp
   end type contact_system

contains

   !> Condense the structure onto the constraints: Khat^{-1} B and F.
   subroutine contact_init(cs, pairs, states, error)
      !> The contact system.
      type(contact_system), intent(out) :: cs
      !> The constraints (ends, gaps, laws).
      type(contact_pair), intent(in) :: pairs(:)
      !> Initialised integrators (their factored Khat).
      type(newmark_state), intent(in) :: states(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, l, e, g, b, m

      m = size(pairs)
      cs%m = m
      cs%pair = pairs
      if (m == 0) return
      cs%c2 = states(1)%c2
      allocate (cs%y(2, m), cs%f(m, m), cs%phat(m), cs%q(m), cs%r_new(m), cs%mat(m, m), &
                cs%qa(m), cs%za(m), cs%wa(m), cs%act(m), cs%in_lcp(m), cs%guess(m))
      do k = 1, m
         associate (p => cs%pair(k))
            if (p%law%stiffness <= 0.0_dp) then
               call fatal_error(error, 'contact '//p%label//': stiffness must be > 0')
               return
            end if
            cs%phat(k) = p%law%stiffness + cs%c2*p%law%dashpot
            do e = 1, 2
               b = p%building(e)
               if (b == 0) cycle
               allocate (cs%y(e, k)%x(states(b)%n))
               cs%y(e, k)%x = 0.0_dp
               cs%y(e, k)%x(p%floor(e)) = 1.0_dp
               call newmark_solve(states(b), cs%y(e, k)%x)
            end do
         end associate
      end do
      ! F_kl = sum over ends e of k and g of l on the same building of s_e s_g y(g,l)(floor_e).
      do l = 1, m
         do k = 1, m
            cs%f(k, l) = 0.0_dp
            do e = 1, 2
               b = cs%pair(k)%building(e)
               if (b == 0) cycle
               do g = 1, 2
                  if (cs%pair(l)%building(g) /= b) cycle
                  cs%f(k, l) = cs%f(k, l) + end_sign(e)*end_sign(g)*cs%y(g, l)%x(cs%pair(k)%floor(e))
               end do
            end do
         end do
      end do
      call lemke_init(cs%ws, m)
   end subroutine contact_init

   !> One constraint per facing floor pair of the deck's `&contact` groups, in deck order.
   function pairs_from_config(contacts, names) result(pairs)
      !> The deck's contact groups.
      type(contact_config), intent(in) :: contacts(:)
      !> Building names, in deck order.
      character(len=*), intent(in) :: names(:)
      type(contact_pair), allocatable :: pairs(:)
      integer :: i, k, n

      n = 0
      do i = 1, size(contacts)
         n = n + size(contacts(i)%floor_left)
      end do
      allocate (pairs(n))
      n = 0
      do i = 1, size(contacts)
         associate (c => contacts(i))
            do k = 1, size(c%floor_left)
               n = n + 1
               pairs(n)%label = trim(names(c%left_index))//':'//str(c%floor_left(k))//'-'// &
                                trim(names(c%right_index))//':'//str(c%floor_right(k))
               pairs(n)%building = [c%left_index, c%right_index]
               pairs(n)%floor = [c%floor_left(k), c%floor_right(k)]
               pairs(n)%gap = c%gap(k)
               pairs(n)%law%kind = law_elastic
               pairs(n)%law%stiffness = c%stiffness
               pairs(n)%law%dashpot = c%dashpot
            end do
         end associate
      end do
   end function pairs_from_config

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
      type(lemke_report) :: rep
      integer :: k, e, b, na, i, j
      real(dp) :: vp, dr, qnorm, wk, resid
      logical :: added

      if (cs%m == 0) return
      ! Closing displacement if every force were released in this step.
      do k = 1, cs%m
         vp = 0.0_dp
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            i = cs%pair(k)%floor(e)
            vp = vp + end_sign(e)*(states(b)%u(i) + states(b)%du(i))
         end do
         cs%q(k) = vp
      end do
      do k = 1, cs%m
         if (cs%pair(k)%r /= 0.0_dp) cs%q = cs%q + cs%f(:, k)*cs%pair(k)%r
      end do
      qnorm = 0.0_dp
      do k = 1, cs%m
         associate (p => cs%pair(k))
            cs%q(k) = p%gap - cs%q(k) + p%law%dashpot*(cs%c2*p%d + p%ddot)/cs%phat(k)
            cs%in_lcp(k) = p%r > 0.0_dp .or. cs%q(k) < 0.0_dp
         end associate
         qnorm = max(qnorm, abs(cs%q(k)))
      end do
      qnorm = max(qnorm, tiny(1.0_dp))

      cs%r_new = 0.0_dp
      do
         na = 0
         do k = 1, cs%m
            if (.not. cs%in_lcp(k)) cycle
            na = na + 1
            cs%act(na) = k
         end do
         if (na == 0) exit
         do j = 1, na
            do i = 1, na
               cs%mat(i, j) = cs%f(cs%act(i), cs%act(j))
            end do
            cs%mat(j, j) = cs%mat(j, j) + 1.0_dp/cs%phat(cs%act(j))
            cs%qa(j) = cs%q(cs%act(j))
            cs%guess(j) = cs%pair(cs%act(j))%r > 0.0_dp
         end do
         call lemke_solve(cs%ws, na, cs%mat, cs%qa, cs%za, cs%wa, rep, active_guess=cs%guess(1:na))
         cs%solves = cs%solves + 1
         cs%pivots_total = cs%pivots_total + rep%pivots
         cs%pivots_max = max(cs%pivots_max, rep%pivots)
         if (rep%status == LEMKE_TRIVIAL) cs%trivial = cs%trivial + 1
         if (rep%warm_started) cs%warm = cs%warm + 1
         if ((rep%status /= LEMKE_SOLVED .and. rep%status /= LEMKE_TRIVIAL) .or. &
             .not. (rep%residual <= residual_limit)) then
            call fatal_error(error, 'contact LCP failed at t = '//str(t)//' s (step '//str(step)// &
                             '): Lemke ended with '//lemke_status_name(rep%status)//', residual '// &
                             str(rep%residual)//', '//str(rep%pivots)//' pivots; constraints '// &
                             labels(cs, cs%act(1:na))//'; q = '//vector_text(cs%qa(1:na)))
            return
         end if
         cs%r_new = 0.0_dp
         cs%r_new(cs%act(1:na)) = cs%za(1:na)
         ! Constraints left out must stay open under the new forces.
         added = .false.
         do k = 1, cs%m
            if (cs%in_lcp(k)) cycle
            wk = cs%q(k) + dot_product(cs%f(k, cs%act(1:na)), cs%za(1:na))
            if (wk < -residual_limit*qnorm) then
               cs%in_lcp(k) = .true.
               added = .true.
            end if
         end do
         if (.not. added) exit
         cs%resolves = cs%resolves + 1
      end do

      ! Verify the accepted forces on the full LCP.
      resid = 0.0_dp
      do k = 1, cs%m
         wk = cs%q(k) + dot_product(cs%f(k, cs%act(1:na)), cs%r_new(cs%act(1:na))) + cs%r_new(k)/cs%phat(k)
         if (na == 0) wk = cs%q(k)
         resid = max(resid, abs(min(cs%r_new(k), wk)))
      end do
      resid = resid/qnorm
      cs%residual_max = max(cs%residual_max, resid)
      if (.not. (resid <= residual_limit)) then
         call fatal_error(error, 'contact LCP solution rejected at t = '//str(t)//' s (step '// &
                          str(step)//'): natural residual '//str(resid)//' > '//str(residual_limit))
         return
      end if

      ! du -= Khat^{-1} B (r_new - r_old), only where the force changed.
      do k = 1, cs%m
         dr = cs%r_new(k) - cs%pair(k)%r
         if (dr == 0.0_dp) cycle
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            states(b)%du = states(b)%du - end_sign(e)*dr*cs%y(e, k)%x
         end do
      end do
   end subroutine contact_step

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
      real(dp) :: v, r, r0, d, ddot

      do k = 1, cs%m
         associate (p => cs%pair(k))
            v = 0.0_dp
            do e = 1, 2
               b = p%building(e)
               if (b == 0) cycle
               v = v + end_sign(e)*states(b)%u(p%floor(e))
            end do
            r0 = p%r
            r = cs%r_new(k)
            ! The spring-dashpot evolves by its own law also while the gap is open (r = 0):
            ! p d + c d' = 0 relaxes d, which is exactly 0 without a dashpot.
            d = (r + p%law%dashpot*(cs%c2*p%d + p%ddot))/cs%phat(k)
            ddot = cs%c2*(d - p%d) - p%ddot
            if (r > 0.0_dp) then
               if (r0 == 0.0_dp) p%impacts = p%impacts + 1
               p%contact_time = p%contact_time + dt
               if (r > p%peak_force) then
                  p%peak_force = r
                  p%peak_time = t
               end if
            end if
            cs%work = cs%work + 0.5_dp*(r0 + r)*(v - p%v)
            cs%element_work = cs%element_work + 0.5_dp*(r0 + r)*(d - p%d)
            p%r = r
            p%d = d
            p%ddot = ddot
            p%v = v
         end associate
      end do
   end subroutine contact_commit

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
