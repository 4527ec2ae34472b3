!> The exact step of the joints whose law iterates (`joint_law%iterates`): the smooth laws
!> (extensions of `smooth_law`, pound_law_smooth: a force f(d, d'; v0) of their own,
!> `joint_law%force`) by Newton on the
!> step's LCP, and laws that only re-linearise a secant (`joint_law%relinearise`).
!>
!> **Smooth laws.** With the penetration d = v - gap at the end of the step, v = v_pred -
!> F r (F = B^T Khat^{-1} B, pound_contact), the end-of-step contact equations are
!>
!>   r_k = max(0, f_k(d_k, d'_k; v0_k)) for d_k > 0,  r_k = 0 for d_k <= 0,
!>
!> with the rate by the trapezoidal rule, d'_{n+1} = (2/h) (d_{n+1} - d_n) - d'_n, d'_n the
!> closing speed of the integrators at the step's start (Newmark's own velocity), and v0 the
!> closing speed latched when d crosses 0 upwards: the speed at the crossing of the step's
!> free path (the average-acceleration parabola through d_n, d'_n and the released end d),
!> kept while d > 0 and reset when d <= 0 (joint state `v0`, at least `v0_floor`).
!> Each Newton iterate is one LCP of the step (pound_contact: the condensed system on the
!> constant factored Khat) in which joint k is an elastic row of the tangent
!> kt = df/dd + (2/h) df/dd' through the iterate (d_i, f_i), r = max(0, kt (d - s)),
!> s = d_i - f_i/kt (the row's offset, joint state `shift`, added to its q): the LCP keeps
!> the complementarity of the clip and of the open joint exact at every iterate. Newton
!> starts from the released penetration (every force of the step released: from above for a
!> convex law; a joint open there gets a row through d = 0 without a force evaluated). Where
!> a tangent would cross r = 0 at d < 0 and the law has no force at d = 0+, the row is the
!> secant from the origin instead; an iterate that lands open with force takes the secant from
!> the origin to the last closed iterate. From the `secant_after`-th iterate on, a joint's row
!> is the secant through its last two iterates (regula falsi where the law has a kink between
!> them, Jankowski's damping switching off at d' = 0, where tangents from its two sides would
!> cycle). A Kelvin joint's force jumps to c d' at d = 0+: at an iterate with d <= 0 and
!> f(0+) > 0 the row is rigid (`rigid_stiffness`, no offset) and d = 0 with 0 <= r <= f(0+)
!> is the solution of the set-valued equation. Newton stops when every joint's residual
!> |r - max(0, f(d))| is at most `smooth_residual_limit` (1e-12) of its force, or below the
!> force the round-off of v makes (64 eps (|v| + gap) times the tangent); after
!> `max_law_iterations` solves the step fails (`smooth_unsettled` names the joints).
!> After the solve the row takes the secant r/d, so that the joint's update
!> (`joint_advance`, pound_joint_state) gives d. Every row of an iterate is the law's trial
!> state (`contact_law%set_trial`, `joint_law%set_trial`: the LCP reads the rows' slope);
!> the commit drops it (`contact_law%commit`: the row is back at the law's stiffness).
!> With friction (contact points of buildings in plan, pound_contact_friction_lcp) each
!> iterate's LCP holds the friction rows with the iterate's linearised normal rows, and the
!> end-of-step closing includes the tangential forces' opening (`solved_closing`); the
!> converged step's friction is checked with its final N (`friction_verify`). A contact point
!> that takes a share of its pair has the pair's law with its force scaled (`scale_law_force`).
module pound_contact_smooth
   use pound_kinds, only: dp
   use pound_strings, only: str
   use pound_integrator, only: integrator
   use pound_contact_pair, only: end_sign
   use pound_contact_system, only: contact_system, joint_constants
   use pound_lcp_active_set, only: active_set_forget
   use pound_contact_friction_lcp, only: friction_opening
   implicit none
   private

   public :: smooth_start, smooth_relinearise, smooth_finish, smooth_commit, smooth_joint_commit, smooth_residual, &
             smooth_speeds, smooth_unsettled, &
             latch_speed
   public :: smooth_residual_limit, v0_floor, rigid_stiffness

   !> Largest relative residual of a smooth joint's end-of-step equation.
   real(dp), parameter :: smooth_residual_limit = 1.0e-12_dp
   !> Newton iterates after which a smooth joint's row is the secant through its last two
   !> iterates (a kink between them: tangents from its two sides can cycle).
   integer, parameter :: secant_after = 4
   !> Smallest latched closing speed v0 (m/s): a grazing impact (v0 -> 0) keeps a finite
   !> Hertz-damp constant a/v0.
   real(dp), parameter :: v0_floor = 1.0e-6_dp
   !> A rigid row's stiffness (kN/m; 1/phat = 1e-200: d = 0 to round-off), the Kelvin joint
   !> at d = 0.
   real(dp), parameter :: rigid_stiffness = 1.0e200_dp

contains

   !> The law of joint k has a force of its own (a smooth law; no evaluation).
   pure logical function has_force(cs, k)
      type(contact_system), intent(in) :: cs
      integer, intent(in) :: k

      has_force = cs%pair(k)%law%given%has_force()
   end function has_force

   !> The closing displacement of joint k at the end of the step for the last solve's forces:
   !> v_pred - F r_new, and with friction rows in the solve the tangential forces' opening
   !> (- G_nt T, `friction_opening`).
   pure real(dp) function solved_closing(cs, v_pred, k) result(v)
      !> The contact system after a solve.
      type(contact_system), intent(in) :: cs
      !> Closing displacements with every force of the step released (m).
      real(dp), intent(in) :: v_pred(:)
      !> Joint.
      integer, intent(in) :: k

      v = v_pred(k) - dot_product(cs%f(:, k), cs%r_new)
      if (cs%fr%nt > 0) v = v - friction_opening(cs, k)
   end function solved_closing

   !> Before the step's first LCP: the constants of every iterating joint, a smooth joint's
   !> latch candidate v0 (when it starts open) and its first tangent row, at the released
   !> penetration v_pred - gap.
   pure subroutine smooth_start(cs, v_pred)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Closing displacements with every force of the step released (m).
      real(dp), intent(in) :: v_pred(:)
      integer :: i, k
      real(dp) :: dn

      do i = 1, size(cs%iterating)
         k = cs%iterating(i)
         if (.not. has_force(cs, k)) then
            call joint_constants(cs, k)
            cycle
         end if
         associate (j => cs%joint(k), gap => cs%pair(k)%gap)
            dn = j%v - gap
            if (dn <= 0.0_dp) j%v0 = latch_speed(dn, j%vdot, v_pred(k) - gap, cs%span)
         end associate
         cs%joint(k)%d_iter = 0.0_dp
         if (v_pred(k) - cs%pair(k)%gap <= 0.0_dp) then
            ! Open with every force released (most joints in most steps): a row through
            ! d = 0 of the row's slope, no force evaluated (one that closes after all is
            ! re-linearised after the solve).
            cs%joint(k)%shift = 0.0_dp
            call joint_constants(cs, k)
            cycle
         end if
         call linearise(cs, k, v_pred(k) - cs%pair(k)%gap, .false.)
      end do
      ! The rows moved: the active set's factor is stale (its set is kept as the guess).
      if (size(cs%iterating) > 0) call active_set_forget(cs%as)
   end subroutine smooth_start

   !> The closing speed at which the step's free path d(s) = d_n + d'_n s + a s^2/2 (through
   !> d(h) = d_h) crosses d = 0 (at least `v0_floor`); d_n <= 0.
   pure real(dp) function latch_speed(dn, vn, dh, h) result(v0)
      !> Penetration and its rate at the step's start, released penetration at its end (m,
      !> m/s, m).
      real(dp), intent(in) :: dn, vn, dh
      !> Step (s).
      real(dp), intent(in) :: h
      real(dp) :: am, disc, s, den

      am = 2.0_dp*(dh - dn - vn*h)/(h*h)
      s = h
      disc = max(0.0_dp, vn*vn - 2.0_dp*am*dn)
      den = vn + sqrt(disc)
      if (den > 0.0_dp) s = min(h, -2.0_dp*dn/den)
      v0 = max(v0_floor, vn + am*s)
   end function latch_speed

   !> Tangent row of smooth joint k through its law at the penetration d (m); with `secant`,
   !> the secant through the previous iterate where it has a positive slope (a kink of the
   !> law between the iterates: Jankowski's damping switching at d' = 0).
   pure subroutine linearise(cs, k, d, secant)
      type(contact_system), intent(inout) :: cs
      integer, intent(in) :: k
      real(dp), intent(in) :: d
      logical, intent(in) :: secant
      real(dp) :: f, fd, fv, kt, dd, shift, ks, f0
      logical :: ok

      associate (j => cs%joint(k), law => cs%pair(k)%law)
         if (d > 0.0_dp) then
            dd = cs%rate*(d - (j%v - cs%pair(k)%gap)) - j%vdot
            call law%given%force(d, dd, max(j%v0, v0_floor), f, fd, fv, ok)
            ks = 0.0_dp
            if (secant .and. j%d_iter > 0.0_dp .and. d /= j%d_iter) ks = (f - j%f_iter)/(d - j%d_iter)
            if (ks > 0.0_dp) then
               kt = ks
               shift = d - f/kt
            else
               kt = fd + cs%rate*fv
               if (.not. (kt > 0.0_dp)) kt = cs%rate*fv
               if (.not. (kt > 0.0_dp)) kt = law%stiffness
               shift = d - f/kt
               if (shift < 0.0_dp .and. f > 0.0_dp) then
                  ! The tangent would push at d < 0 where a law without force at d = 0+ has
                  ! none (the Hertz family's start, Jankowski's c ~ d^(1/4)): the secant from
                  ! d = 0.
                  call law%given%force(0.0_dp, dd, max(j%v0, v0_floor), f0, fd, fv, ok)
                  if (.not. (f0 > 0.0_dp)) then
                     kt = f/d
                     shift = 0.0_dp
                  end if
               end if
            end if
            j%d_iter = d
            j%f_iter = f
         else
            dd = cs%rate*(0.0_dp - (j%v - cs%pair(k)%gap)) - j%vdot
            call law%given%force(0.0_dp, dd, max(j%v0, v0_floor), f, fd, fv, ok)
            ! Open at the iterate: the secant from d = 0 to the last closed iterate (else the
            ! row's slope), or a rigid row where the force jumps at d = 0+ (Kelvin).
            kt = law%stiffness
            if (j%d_iter > 0.0_dp) kt = j%f_iter/j%d_iter
            if (.not. (kt > 0.0_dp)) kt = max(fd + cs%rate*fv, law%stiffness)
            if (f > 0.0_dp) kt = rigid_stiffness
            shift = 0.0_dp
         end if
         call law%set_trial(kt)
         j%shift = shift
      end associate
      call joint_constants(cs, k)
   end subroutine linearise

   !> Relative residual of smooth joint k's end-of-step equation for the force r (kN) and
   !> the closing displacement v (m) (`pound_contact_smooth`: below the force the round-off of
   !> v makes, 0).
   pure real(dp) function smooth_residual(cs, k, v, r) result(res)
      !> The contact system (the joint's state at the step's start).
      type(contact_system), intent(in) :: cs
      !> Joint.
      integer, intent(in) :: k
      !> Closing displacement (m) and force (kN) at the end of the step.
      real(dp), intent(in) :: v, r
      real(dp) :: d, dd, f, fd, fv, rt, kt, tol
      logical :: ok

      associate (j => cs%joint(k), law => cs%pair(k)%law, gap => cs%pair(k)%gap)
         d = v - gap
         ! The round-off of v (m) and the force it makes through the law's tangent and the
         ! row's (not a rigid row's).
         tol = 64.0_dp*epsilon(1.0_dp)*(abs(v) + abs(gap))
         if (d < -tol .and. r == 0.0_dp) then
            ! Open without force: solved, no force to evaluate.
            res = 0.0_dp
            return
         end if
         dd = cs%rate*(max(d, 0.0_dp) - (j%v - gap)) - j%vdot
         call law%given%force(max(d, 0.0_dp), dd, max(j%v0, v0_floor), f, fd, fv, ok)
         kt = max(0.0_dp, fd + cs%rate*fv)
         if (law%stiffness < rigid_stiffness) kt = max(kt, law%stiffness)
         if (abs(d) <= tol) then
            ! d = 0: any force from 0 to f(0+) (a Kelvin joint's jump; 0 for the Hertz family).
            res = max(0.0_dp, r - max(f, 0.0_dp) - kt*tol, -r)/max(abs(r), tiny(1.0_dp))
         else if (d > 0.0_dp) then
            rt = max(0.0_dp, f)
            res = max(0.0_dp, abs(r - rt) - kt*tol)/max(r, rt, tiny(1.0_dp))
         else
            res = abs(r)/max(abs(r), tiny(1.0_dp))
         end if
      end associate
   end function smooth_residual

   !> After an LCP of the step: true when an iterating joint moved its row (then the LCP is
   !> solved again): a smooth joint whose residual is above `smooth_residual_limit` takes
   !> the tangent at the solution's penetration; another iterating law re-linearises its
   !> secant (`joint_law%relinearise`).
   function smooth_relinearise(cs, v_pred, it) result(changed)
      !> The contact system, `r_new` and `x_new` of the last solve.
      type(contact_system), intent(inout) :: cs
      !> Closing displacements with every force of the step released (m).
      real(dp), intent(in) :: v_pred(:)
      !> Solves of the step so far (from `secant_after` on, secant rows).
      integer, intent(in) :: it
      logical :: changed
      integer :: i, k
      real(dp) :: d, v
      logical :: moved

      changed = .false.
      do i = 1, size(cs%iterating)
         k = cs%iterating(i)
         ! A fractured joint (a collapse opened it) carries nothing: no equation to solve.
         if (cs%joint(k)%fractured) cycle
         if (has_force(cs, k)) then
            v = solved_closing(cs, v_pred, k)
            if (smooth_residual(cs, k, v, cs%r_new(k)) <= smooth_residual_limit) cycle
            call linearise(cs, k, v - cs%pair(k)%gap, it >= secant_after)
            changed = .true.
            cycle
         end if
         associate (j => cs%joint(k), law => cs%pair(k)%law)
            d = (cs%r_new(k) + law%dashpot*(cs%rate_a(k)*j%d + cs%rate_b(k)*j%ddot) + &
                 law%stiffness*(j%plastic + cs%x_new(k)))/cs%phat(k)
            call law%given%relinearise(d, cs%r_new(k), law%stiffness, moved)
         end associate
         if (.not. moved) cycle
         call joint_constants(cs, k)
         changed = .true.
      end do
      if (changed) call active_set_forget(cs%as)
   end function smooth_relinearise

   !> The iterating joints whose end-of-step equation is not solved (smooth joints: residual
   !> above `smooth_residual_limit`, named with it; others: all), for the step's failure.
   function smooth_unsettled(cs, v_pred, first) result(text)
      !> The contact system after the step's last solve.
      type(contact_system), intent(in) :: cs
      !> Closing displacements with every force of the step released (m).
      real(dp), intent(in) :: v_pred(:)
      !> The first joint named (0: none).
      integer, intent(out) :: first
      character(len=:), allocatable :: text
      integer :: i, k
      real(dp) :: res

      text = ''
      first = 0
      do i = 1, size(cs%iterating)
         k = cs%iterating(i)
         if (cs%joint(k)%fractured) cycle
         if (has_force(cs, k)) then
            res = smooth_residual(cs, k, solved_closing(cs, v_pred, k), cs%r_new(k))
            if (res <= smooth_residual_limit) cycle
            if (first == 0) first = k
            if (len(text) > 0) text = text//', '
            text = text//cs%pair(k)%label//' (residual '//str(res)//')'
         else
            if (first == 0) first = k
            if (len(text) > 0) text = text//', '
            text = text//cs%pair(k)%label
         end if
      end do
   end function smooth_unsettled

   !> After the step's last LCP: every smooth joint's row takes the secant r/d of the
   !> solution (the joint's update then gives its penetration d; a rigid row stays).
   pure subroutine smooth_finish(cs, v_pred)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Closing displacements with every force of the step released (m).
      real(dp), intent(in) :: v_pred(:)
      integer :: i, k
      real(dp) :: d

      do i = 1, size(cs%iterating)
         k = cs%iterating(i)
         if (.not. has_force(cs, k)) cycle
         d = solved_closing(cs, v_pred, k) - cs%pair(k)%gap
         if (cs%r_new(k) > 0.0_dp .and. d > 0.0_dp) then
            call cs%pair(k)%law%set_trial(cs%r_new(k)/d)
            call joint_constants(cs, k)
         end if
         cs%joint(k)%shift = 0.0_dp
      end do
   end subroutine smooth_finish

   !> Before a step's solve (`contact_step`, the integrators at the step's start): every
   !> smooth joint's closing speed d'_n (m/s), the rate the step's trapezoidal d' starts from.
   subroutine smooth_speeds(cs, states)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> The integrators (their velocities: the step's start).
      class(integrator), intent(in) :: states(:)
      integer :: i, k, e, b, l
      real(dp) :: s, w

      do i = 1, size(cs%iterating)
         k = cs%iterating(i)
         s = 0.0_dp
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            if (cs%pair(k)%dof(e) > 0) then
               w = states(b)%v_at(cs%pair(k)%dof(e))
            else
               w = 0.0_dp
               associate (row => cs%pair(k)%end_row(e))
                  do l = row%start(1), row%start(2) - 1
                     w = w + row%coef(l)*states(b)%v_at(row%dof(l))
                  end do
                  w = row%scale(1)*w
               end associate
            end if
            s = s + end_sign(e)*w
         end do
         cs%joint(k)%vdot = s
      end do
   end subroutine smooth_speeds

   !> After the commit of a step with a solve (`contact_commit`): every smooth joint's latch
   !> reset where it is open (d <= 0), its row back at the law's stiffness (what the listing
   !> and the results show). (A step in which no joint can act changes neither.)
   pure subroutine smooth_commit(cs)
      !> The contact system, `vp` the committed closing displacements.
      type(contact_system), intent(inout) :: cs
      integer :: i, k

      do i = 1, size(cs%iterating)
         k = cs%iterating(i)
         if (.not. has_force(cs, k)) cycle
         call smooth_joint_commit(cs, k, cs%vp(k))
      end do
   end subroutine smooth_commit

   !> `smooth_commit` of smooth joint k with its committed closing displacement v (m).
   pure subroutine smooth_joint_commit(cs, k, v)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Joint.
      integer, intent(in) :: k
      !> Closing displacement (m) at the end of the step.
      real(dp), intent(in) :: v

      if (v - cs%pair(k)%gap <= 0.0_dp) cs%joint(k)%v0 = 0.0_dp
      call cs%pair(k)%law%commit()
      call joint_constants(cs, k)
   end subroutine smooth_joint_commit

end module pound_contact_smooth
