!> The friction rows of the step's LCP (pound_contact_friction): their set-up at the start of
!> the step, their assembly after the joints' rows, the tangential forces of a solution, their
!> load on the buildings and the commit with the friction work.
!>
!> With the released tangential displacement s_rel = C^T u_pred + C^T Khat^{-1} (B N_n + C T_n)
!> (every force of the step released, as v_pred for the normal rows), the end-of-step
!> tangential displacement is s = s_rel - G_tn N - G_tt T (G_tn = C^T Khat^{-1} B, G_tt =
!> C^T Khat^{-1} C). T = kt (s - s_p,n - l) with l = l+ - l- is linear in N and l and is
!> eliminated: with S = diag(1/kt) + G_tt (symmetric positive definite) and W = S^{-1},
!>
!>   T = W (e - G_tn N - l),  e = s_rel - s_p,n.
!>
!> Over the points whose contact row is in the LCP (the others are open: T = 0), the rows,
!> in metres with the slip variables in kN (L = kt l, as the plastic rows), are
!>
!>   w_N  = (joint rows) + G_nt W e - G_nt W G_tn N - G_nt W D (L+ - L-)
!>   w+/kt = D (mu N - T) = -D W e + D (mu + W G_tn) N + D W D L+ - D W D L-
!>   w-/kt = D (mu N + T) =  D W e + D (mu - W G_tn) N - D W D L+ + D W D L-
!>
!> (D = diag(1/kt), G_nt = B^T Khat^{-1} C), complementary to N, L+, L-. The normal block
!> F + 1/phat - G_nt W G_tn = B^T (Khat + C kt C^T)^{-1} B + 1/phat is the frictionless one
!> with the points stuck, symmetric positive definite; the friction couples it
!> non-symmetrically through mu, so the step is solved by Lemke (never the active-set method).
module pound_contact_friction_lcp
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, error_at
   use pound_strings, only: str
   use pound_integrator, only: integrator
   use pound_structure, only: recovery_rows
   use pound_contact_pair, only: end_sign
   use pound_contact_system, only: contact_system, lcp_workspace
   implicit none
   private

   public :: friction_start, friction_assemble, friction_forces, friction_opening, friction_q, friction_apply, &
             friction_commit, friction_verify, friction_check_limit

   !> Largest violation of a friction row after a step whose normal rows were iterated
   !> (`friction_verify`), relative to mu N + |T| + kt (|e| + |q|_inf) of the point (|q|_inf:
   !> the step's largest released opening, the scale of the LCP's own residual).
   real(dp), parameter :: friction_check_limit = 1.0e-8_dp

contains

   !> The step's start (a step in which a joint can act): the tangential displacements at the
   !> start, the slip of an open point relaxed to them (T = 0), the released tangential
   !> displacements e and the normal closings `cs%vp` released of the tangential forces.
   subroutine friction_start(cs, states)
      !> The contact system (`vp` released of the normal forces).
      type(contact_system), intent(inout) :: cs
      !> Integrators with the predicted increments du.
      class(integrator), intent(in) :: states(:)
      integer :: i, k, l, j
      real(dp) :: s

      associate (fr => cs%fr)
         do i = 1, fr%n
            k = fr%joint(i)
            fr%p(i)%s = tangential(cs, states, i, .false.)
            if (cs%joint(k)%r == 0.0_dp) then
               fr%p(i)%slip = fr%p(i)%s
               fr%p(i)%force = 0.0_dp
            end if
            s = tangential(cs, states, i, .true.)
            do l = 1, cs%m
               s = s + fr%gtn(i, l)*cs%joint(l)%r
            end do
            do j = 1, fr%n
               s = s + fr%gtt(i, j)*fr%p(j)%force
            end do
            fr%e(i) = s - fr%p(i)%slip
         end do
         do i = 1, fr%n
            if (fr%p(i)%force /= 0.0_dp) cs%vp = cs%vp + fr%gnt(:, i)*fr%p(i)%force
         end do
         fr%force_new = 0.0_dp
         fr%slip_new = 0.0_dp
         fr%nt = 0
         fr%solved = .true.
      end associate
   end subroutine friction_start

   !> The tangential displacement s = C_i^T u of point i: of the predicted or of the committed
   !> displacements.
   real(dp) function tangential(cs, states, i, predicted) result(s)
      type(contact_system), intent(in) :: cs
      class(integrator), intent(in) :: states(:)
      integer, intent(in) :: i
      logical, intent(in) :: predicted
      integer :: e, b, l, k

      s = 0.0_dp
      k = cs%fr%joint(i)
      do e = 1, 2
         b = cs%pair(k)%building(e)
         if (b == 0) cycle
         associate (row => cs%pair(k)%tan_row(e))
            do l = row%start(1), row%start(2) - 1
               if (predicted) then
                  s = s + end_sign(e)*row%coef(l)*states(b)%predicted(row%dof(l))
               else
                  s = s + end_sign(e)*row%coef(l)*states(b)%u_at(row%dof(l))
               end if
            end do
         end associate
      end do
   end function tangential

   !> Append the friction rows of the points whose contact row is in the assembled LCP (rows
   !> 1..na contact, n rows in all): 2 nt more rows (module header); n grows.
   subroutine friction_assemble(cs, na, n, error)
      !> The contact system with its LCP assembled (`lcp_assemble`).
      type(contact_system), intent(inout) :: cs
      !> Contact rows and all rows (grows by 2 nt).
      integer, intent(in) :: na
      integer, intent(inout) :: n
      !> Error state (the workspace cannot grow).
      type(error_type), allocatable, intent(out) :: error
      integer :: a, b, j, jj, i, nt, pa, ma, c
      real(dp) :: da, db, g

      associate (fr => cs%fr)
         nt = 0
         do j = 1, na
            i = fr%index(cs%act(j))
            if (i == 0) cycle
            nt = nt + 1
            fr%sub(nt) = i
            fr%jrow(nt) = j
         end do
         fr%nt = nt
         fr%row0 = n
         if (nt == 0) return
         if (n + 2*nt > cs%n_max) then
            call grow(cs, n + 2*nt, error)
            if (allocated(error)) return
         end if
         ! S = diag(1/kt) + G_tt, and S^{-1} [G_tn(:, act), e, I].
         do b = 1, nt
            do a = 1, nt
               fr%s_mat(a, b) = fr%gtt(fr%sub(a), fr%sub(b))
            end do
            fr%s_mat(b, b) = fr%s_mat(b, b) + 1.0_dp/fr%kt(fr%sub(b))
         end do
         c = na + 1 + nt
         do a = 1, nt
            do j = 1, na
               fr%x_mat(a, j) = fr%gtn(fr%sub(a), cs%act(j))
            end do
            fr%x_mat(a, na + 1) = fr%e(fr%sub(a))
            fr%x_mat(a, na + 2:c) = 0.0_dp
            fr%x_mat(a, na + 1 + a) = 1.0_dp
         end do
         call cholesky_solve(nt, c, fr%s_mat, fr%x_mat)
         ma = n + 2*nt
         cs%mat(1:ma, n + 1:ma) = 0.0_dp
         cs%mat(n + 1:ma, 1:ma) = 0.0_dp
         associate (wg => fr%x_mat(:, 1:na), we => fr%x_mat(:, na + 1), w => fr%x_mat(:, na + 2:c))
            ! Joint rows: + G_nt T.
            do j = 1, na
               do a = 1, nt
                  g = fr%gnt(cs%act(j), fr%sub(a))
                  if (g == 0.0_dp) cycle
                  cs%qa(j) = cs%qa(j) + g*we(a)
                  do jj = 1, na
                     cs%mat(j, jj) = cs%mat(j, jj) - g*wg(a, jj)
                  end do
                  do b = 1, nt
                     db = 1.0_dp/fr%kt(fr%sub(b))
                     cs%mat(j, n + b) = cs%mat(j, n + b) - g*w(a, b)*db
                     cs%mat(j, n + nt + b) = cs%mat(j, n + nt + b) + g*w(a, b)*db
                  end do
               end do
            end do
            ! Friction rows, divided by kt.
            do a = 1, nt
               i = fr%sub(a)
               da = 1.0_dp/fr%kt(i)
               pa = n + a
               do jj = 1, na
                  cs%mat(pa, jj) = da*wg(a, jj)
                  cs%mat(pa + nt, jj) = -da*wg(a, jj)
               end do
               cs%mat(pa, fr%jrow(a)) = cs%mat(pa, fr%jrow(a)) + da*fr%mu(i)
               cs%mat(pa + nt, fr%jrow(a)) = cs%mat(pa + nt, fr%jrow(a)) + da*fr%mu(i)
               do b = 1, nt
                  db = 1.0_dp/fr%kt(fr%sub(b))
                  cs%mat(pa, n + b) = da*w(a, b)*db
                  cs%mat(pa, n + nt + b) = -da*w(a, b)*db
                  cs%mat(pa + nt, n + b) = -da*w(a, b)*db
                  cs%mat(pa + nt, n + nt + b) = da*w(a, b)*db
               end do
               cs%qa(pa) = -da*we(a)
               cs%qa(pa + nt) = da*we(a)
               cs%guess(pa) = fr%p(i)%direction > 0
               cs%guess(pa + nt) = fr%p(i)%direction < 0
               cs%zref(pa) = 0.0_dp
               cs%zref(pa + nt) = 0.0_dp
            end do
         end associate
      end associate
      n = n + 2*nt
   end subroutine friction_assemble

   !> Grow the LCP workspace to `n` rows keeping the assembled rows (rare: more segment ends
   !> modelled than the workspace was made for).
   subroutine grow(cs, n, error)
      type(contact_system), intent(inout) :: cs
      integer, intent(in) :: n
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: mat(:, :), qa(:), zref(:)
      logical, allocatable :: guess(:)
      integer, allocatable :: act(:)
      integer :: n0

      n0 = cs%n_max
      mat = cs%mat
      qa = cs%qa
      zref = cs%zref
      guess = cs%guess
      act = cs%act
      call lcp_workspace(cs, n, error)
      if (allocated(error)) return
      cs%mat(1:n0, 1:n0) = mat
      cs%qa(1:n0) = qa
      cs%zref(1:n0) = zref
      cs%guess(1:n0) = guess
      cs%act(1:n0) = act
   end subroutine grow

   !> Solve S X = X in place for the symmetric positive definite S (nt, nt) and c right-hand
   !> sides (Cholesky; S is overwritten by its factor).
   pure subroutine cholesky_solve(nt, c, s, x)
      integer, intent(in) :: nt, c
      real(dp), intent(inout) :: s(:, :), x(:, :)
      integer :: i, j, k

      do j = 1, nt
         do k = 1, j - 1
            s(j, j) = s(j, j) - s(j, k)**2
         end do
         s(j, j) = sqrt(s(j, j))
         do i = j + 1, nt
            do k = 1, j - 1
               s(i, j) = s(i, j) - s(i, k)*s(j, k)
            end do
            s(i, j) = s(i, j)/s(j, j)
         end do
      end do
      do k = 1, c
         do i = 1, nt
            do j = 1, i - 1
               x(i, k) = x(i, k) - s(i, j)*x(j, k)
            end do
            x(i, k) = x(i, k)/s(i, i)
         end do
         do i = nt, 1, -1
            do j = i + 1, nt
               x(i, k) = x(i, k) - s(j, i)*x(j, k)
            end do
            x(i, k) = x(i, k)/s(i, i)
         end do
      end do
   end subroutine cholesky_solve

   !> The tangential forces and slip increments of the LCP's solution `cs%za` (contact rows
   !> 1..na): T = W (e - G_tn N - D L) of the points in the LCP, 0 elsewhere.
   pure subroutine friction_forces(cs, na)
      !> The contact system after a solve.
      type(contact_system), intent(inout) :: cs
      !> Contact rows.
      integer, intent(in) :: na
      integer :: a, b, j, i, nt, c, n0
      real(dp) :: t

      associate (fr => cs%fr)
         fr%force_new = 0.0_dp
         fr%slip_new = 0.0_dp
         nt = fr%nt
         n0 = fr%row0
         c = na + 1
         do a = 1, nt
            t = fr%x_mat(a, c)
            do j = 1, na
               t = t - fr%x_mat(a, j)*cs%za(j)
            end do
            do b = 1, nt
               t = t - fr%x_mat(a, c + b)*(cs%za(n0 + b) - cs%za(n0 + nt + b))/fr%kt(fr%sub(b))
            end do
            i = fr%sub(a)
            fr%force_new(i) = t
            fr%slip_new(i) = (cs%za(n0 + a) - cs%za(n0 + nt + a))/fr%kt(i)
         end do
      end associate
   end subroutine friction_forces

   !> The opening the tangential forces of the solution add to joint k: G_nt(k, :) T.
   pure real(dp) function friction_opening(cs, k) result(w)
      !> The contact system after `friction_forces`.
      type(contact_system), intent(in) :: cs
      !> Joint.
      integer, intent(in) :: k
      integer :: a

      w = 0.0_dp
      do a = 1, cs%fr%nt
         w = w + cs%fr%gnt(k, cs%fr%sub(a))*cs%fr%force_new(cs%fr%sub(a))
      end do
   end function friction_opening

   !> The contact q of every joint with the tangential forces' opening, `fr%qx` = q + G_nt T
   !> (the check of the joints left out of the LCP, `lcp_residual`).
   pure subroutine friction_q(cs)
      !> The contact system after `friction_forces`.
      type(contact_system), intent(inout) :: cs
      integer :: k

      do k = 1, cs%m
         cs%fr%qx(k) = cs%q(k) + friction_opening(cs, k)
      end do
   end subroutine friction_q

   !> du -= Khat^{-1} C (T_new - T_old) (`undo`: du += ...): A is pushed by -T, B by +T along y.
   subroutine friction_apply(cs, states, undo)
      !> The contact system after a solve.
      type(contact_system), intent(inout) :: cs
      !> Integrators.
      class(integrator), intent(inout) :: states(:)
      !> Take the change out again.
      logical, intent(in) :: undo
      integer :: i, k, e, b
      real(dp) :: dt

      do i = 1, cs%fr%n
         dt = cs%fr%force_new(i) - cs%fr%p(i)%force
         if (dt == 0.0_dp) cycle
         if (undo) dt = -dt
         k = cs%fr%joint(i)
         do e = 1, 2
            b = cs%pair(k)%building(e)
            if (b == 0) cycle
            associate (row => cs%pair(k)%tan_row(e))
               call states(b)%add_load_rows(-(end_sign(e)*dt), row%dof(row%start(1):row%start(2) - 1), &
                                            row%coef(row%start(1):row%start(2) - 1), cs%fr%y(e, i)%x)
            end associate
         end do
      end do
   end subroutine friction_apply

   !> Commit the step's friction (after `integrator%commit`): slip, force, peaks and the work:
   !> the tangential forces' work on the buildings, T_avg ds, enters the joints' work and
   !> element work (stored kt (s - s_p)^2/2 plus dissipated), its slip part T_avg ds_p the
   !> plastic (dissipated) work and `fr%work`. A step not solved with the rows (every point
   !> open: an idle or a closed step) keeps T = 0.
   subroutine friction_commit(cs, states, t)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> Integrators at the end of the step.
      class(integrator), intent(in) :: states(:)
      !> Time at the end of the step (s).
      real(dp), intent(in) :: t
      integer :: i
      real(dp) :: s1, tavg, w

      if (.not. cs%fr%solved) return
      cs%fr%solved = .false.
      do i = 1, cs%fr%n
         associate (p => cs%fr%p(i))
            tavg = 0.5_dp*(p%force + cs%fr%force_new(i))
            if (tavg /= 0.0_dp) then
               s1 = tangential(cs, states, i, .false.)
               w = tavg*(s1 - p%s)
               cs%work = cs%work + w
               cs%element_work = cs%element_work + w
               w = tavg*cs%fr%slip_new(i)
               cs%plastic_work = cs%plastic_work + w
               cs%fr%work = cs%fr%work + w
            end if
            p%slip = p%slip + cs%fr%slip_new(i)
            p%force = cs%fr%force_new(i)
            p%direction = 0
            if (cs%fr%slip_new(i) > 0.0_dp) p%direction = 1
            if (cs%fr%slip_new(i) < 0.0_dp) p%direction = -1
            if (abs(p%force) > p%peak) then
               p%peak = abs(p%force)
               p%peak_time = t
            end if
         end associate
      end do
   end subroutine friction_commit

   !> The check of a step whose smooth joints were iterated (pound_contact_smooth: each
   !> iterate's LCP holds the friction rows with the iterate's linearised normal rows): with
   !> the step's final normal forces N = r_new, every point's tangential force T and slip
   !> increment l = l+ - l- meet Coulomb's complementarity, min(kt max(l, 0), mu N - T) = 0 and
   !> min(kt max(-l, 0), mu N + T) = 0 (so |T| <= mu N, T = mu N while slipping forward, T =
   !> -mu N backward, T = 0 at an open point), within `friction_check_limit`. A point that does
   !> not fails the step, named with time, step and its values.
   subroutine friction_verify(cs, t, step, error)
      !> The contact system after the step's last solve.
      type(contact_system), intent(in) :: cs
      !> Time at the end of the step (s) and step, for the message.
      real(dp), intent(in) :: t
      integer, intent(in) :: step
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, k
      real(dp) :: n, tt, l, mu, kt, tol, plus, minus, qnorm

      ! The step's scale in metres (the last solve's q, as the LCP's residual).
      qnorm = 0.0_dp
      do k = 1, cs%m
         if (.not. cs%joint(k)%fractured) qnorm = max(qnorm, abs(cs%q(k)))
      end do
      do i = 1, cs%fr%n
         k = cs%fr%joint(i)
         n = cs%r_new(k)
         tt = cs%fr%force_new(i)
         l = cs%fr%slip_new(i)
         mu = cs%fr%mu(i)
         kt = cs%fr%kt(i)
         tol = friction_check_limit*max(mu*abs(n) + abs(tt) + kt*(abs(cs%fr%e(i)) + qnorm), tiny(1.0_dp))
         plus = min(kt*max(l, 0.0_dp), mu*n - tt)
         minus = min(kt*max(-l, 0.0_dp), mu*n + tt)
         if (abs(plus) <= tol .and. abs(minus) <= tol) cycle
         call fatal_error(error, 'contact at t = '//str(t)//' s (step '//str(step)//'): the friction of contact '// &
                          'point '//cs%pair(k)%label//' does not hold with the step''s normal force N = '//str(n)// &
                          ' kN: T = '//str(tt)//' kN, mu N = '//str(mu*n)//' kN, slip increment '//str(l)// &
                          ' m (reduce dt)')
         call error_at(error, time=t, step=step, joint=k)
         return
      end do
   end subroutine friction_verify

end module pound_contact_friction_lcp
