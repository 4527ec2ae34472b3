!> A step in which bilinear storeys yield while joints can act (`pound_storey_yield`), solved
!> as ONE linear complementarity problem over the joints' rows and the yielding storeys' rows.
!>
!> Unknowns: the joints' variables z_J of `pound_contact_lcp` (contact forces r in kN, scaled
!> plastic variables of plastic laws) and the storeys' plastic increments |dp_s| (m, on the
!> side each storey yields to, sigma_s = +-1). With G(k, s) = B_k^T Khat^{-1} b_s (the
!> storey's column Khat^{-1} b_s read at the joint's ends, the same factored Khat), the
!> plastic load k_s b_s dp_s closes joint k by G(k, s) k_s dp_s and a joint force r_k changes
!> the storey's drift by -G(k, s) (r_k - r_k,n). So, rows of joints in metres, rows of storeys
!> divided by k_s (metres):
!>
!>     w_J = M_JJ z_J - G_J^T diag(sigma k) z_S + q_J                       (contact rows only)
!>     w_s = sigma_s (1-r_s) G(:, s)^T r + z_s - sigma_s (1-r_s) sum_t sigma_t k_t b_s^T Khat^{-1} b_t z_t
!>           + [ (1-r_s) Fy_s - sigma_s (f_tr - r_s k_s d_tr) ] / k_s - sigma_s (1-r_s) G(:, s)^T r_n
!>
!> with M_JJ, q_J the joints' LCP (`lcp_assemble`, q from the step's released closing
!> displacements) and d_tr, f_tr the storeys' trial drift and force with the joints' forces of
!> the start of the step. The matrix is not symmetric and, with softening joints or storeys
!> (r < 0, P-Delta), not a P-matrix: Lemke's method solves it (enumeration of the complementary
!> bases for problems of up to `fallback_max_rows` rows when Lemke ends on a ray). Rows enter
!> on demand: a joint left out that would penetrate, a segment end a plastic joint passes, a
!> storey left out that leaves its elastic range (or a storey in on one side that leaves by the
!> other) enters and the LCP is solved again. The accepted solution is checked on every row:
!> the natural residual of the assembled LCP relative to ||q|| (<= `residual_limit`), every
!> joint left out open, and every storey's conditions (`check_step`, <= 1e-8 Fy).
submodule(pound_storey_yield) pound_storey_yield_coupled
   use pound_contact, only: contact_apply, released_q, segment_ends_passed
   use pound_contact_lcp, only: lcp_layout, lcp_assemble
   use pound_contact_system, only: lcp_workspace, residual_limit, fallback_max_rows
   use pound_contact_pair, only: end_sign, end_value
   use pound_lemke, only: lcp_evaluate, LEMKE_SOLVED, LEMKE_TRIVIAL
   use pound_lcp_enumerate, only: lcp_enumerate
   use pound_lcp_statistics, only: statistics_count_solve
   implicit none

   !> Most solves of the coupled LCP in a step (each adds at least one row).
   integer, parameter :: max_rounds = 500

contains

   module subroutine yield_coupled(ys, st, cs, t, step, models, error)
      type(storey_yield_set), intent(inout) :: ys(:)
      class(integrator), intent(inout), target :: st(:)
      type(contact_system), intent(inout) :: cs
      real(dp), intent(in) :: t
      integer, intent(in) :: step
      type(structure_model), intent(in) :: models(:)
      type(error_type), allocatable, intent(out) :: error
      type(lemke_report) :: rep
      real(dp), pointer :: du(:)
      real(dp) :: qnorm, resid
      integer :: ib, j, k, a, s, na, nj, n, ns, round, nsol
      logical :: added, nonconvex

      if (cs%fr%n > 0) then
         call fatal_error(error, 'at t = '//str(t)//' s (step '//str(step)//'): storeys, planes or hinges '// &
                          'yield while contact points with friction act; friction is not solved together with '// &
                          'yielding storeys or planes (set friction = 0, or elastic storeys and planes)')
         return
      end if
      ! du back to the prediction: the joints' forces of the start of the step, no plastic load.
      call contact_release(cs, st)
      do ib = 1, size(ys)
         if (ys(ib)%n == 0 .or. ys(ib)%frozen) cycle
         if (ys(ib)%loaded) call plastic_loads(ys(ib), st(ib), -1.0_dp)
         du => st(ib)%du_view()
         ys(ib)%loaded = .false.
         ys(ib)%dold = ys(ib)%dpl
         call drifts(ys(ib), st(ib)%u_view(), ys(ib)%dtr, ys(ib)%work, du)
         ! Storeys that yielded in the first solution, or whose trial force leaves its range.
         ys(ib)%na = 0
         ys(ib)%side = 0
         do j = 1, ys(ib)%n
            if (ys(ib)%dold(j) > 0.0_dp) then
               call join(ys(ib), j, 1)
            else if (ys(ib)%dold(j) < 0.0_dp) then
               call join(ys(ib), j, -1)
            else
               call enter_out(ys(ib), j, ys(ib)%dtr, 0.0_dp, .false.)
            end if
         end do
      end do
      ! The joints' LCP vector from the step's released closing displacements (`contact_step`'s).
      call released_q(cs, cs%vp)
      qnorm = tiny(1.0_dp)
      do k = 1, cs%m
         associate (p => cs%joint(k))
            cs%in_lcp(k) = .not. p%fractured .and. (p%r > 0.0_dp .or. cs%q(k) < 0.0_dp .or. cs%r_new(k) > 0.0_dp)
            if (.not. p%fractured) qnorm = max(qnorm, abs(cs%q(k)))
            cs%nh(k) = 0
         end associate
      end do
      nonconvex = .false.

      do round = 1, max_rounds
         call lcp_layout(cs%pair, cs%in_lcp, cs%nh, cs%act, cs%yrow, na, nj)
         if (nj > cs%n_max) then
            call lcp_workspace(cs, max(nj, 2*cs%n_max), error)
            if (allocated(error)) return
            call lcp_layout(cs%pair, cs%in_lcp, cs%nh, cs%act, cs%yrow, na, nj)
         end if
         if (nj > 0) call lcp_assemble(cs%pair, cs%joint, cs%f, cs%phat, cs%beta, cs%rate_b, cs%q, cs%act, na, &
                                       cs%yrow, cs%nh, nj, cs%mat, cs%qa, cs%guess, cs%zref, nonconvex)
         ns = sum(ys%na)
         n = nj + ns
         call coupled_workspace(ys(1), n, cs%m)
         call assemble_coupled(ys, st, cs, na, nj, n)
         call dense_lcp_solve(ys(1)%clcp, n, rep)
         call statistics_count_solve(cs%stats, rep%pivots, rep%status == LEMKE_TRIVIAL, rep%warm_started)
         cs%stats%largest_lcp = max(cs%stats%largest_lcp, n)
         if ((rep%status /= LEMKE_SOLVED .and. rep%status /= LEMKE_TRIVIAL) .or. &
             .not. (rep%residual <= residual_limit)) then
            ! Lemke on a ray (non-convex rows): every complementary basis of a small problem.
            if (n > fallback_max_rows) then
               call fatal_error(error, 'the coupled LCP of '//str(na)//' joints and '//str(ns)//' yielding storeys '// &
                                'at t = '//str(t)//' s (step '//str(step)//') was not solved: '// &
                                lemke_status_name(rep%status)//', natural residual '//str(rep%residual)// &
                                ', too large to enumerate (reduce dt)')
               return
            end if
            call lcp_enumerate(ys(1)%clcp%mat(1:n, 1:n), ys(1)%clcp%q(1:n), nsol, z=ys(1)%clcp%z(1:n), &
                               reference=ys(1)%clcp%ref(1:n), error=error)
            if (allocated(error)) return
            if (nsol == 0) then
               call fatal_error(error, 'the coupled LCP of '//str(na)//' joints and '//str(ns)//' yielding storeys '// &
                                'at t = '//str(t)//' s (step '//str(step)//') has no solution (Lemke: '// &
                                lemke_status_name(rep%status)//'; enumeration found none: reduce dt)')
               return
            end if
            cs%stats%nonconvex = cs%stats%nonconvex + 1
         end if
         ! The solution: joints' forces and plastic increments, storeys' plastic increments.
         cs%r_new = 0.0_dp
         cs%x_new = 0.0_dp
         cs%r_new(cs%act(1:na)) = ys(1)%clcp%z(1:na)
         do a = 1, na
            k = cs%act(a)
            if (cs%yrow(k) > 0) cs%x_new(k) = ys(1)%clcp%z(cs%yrow(k))/cs%pair(k)%law%stiffness
         end do
         do ib = 1, size(ys)
            if (ys(ib)%n > 0) ys(ib)%dpl = 0.0_dp
         end do
         do s = nj + 1, n
            associate (y => ys(ys(1)%cb(s)))
               j = ys(1)%cj(s)
               y%dpl(j) = real(y%side(j), dp)*ys(1)%clcp%z(s)
            end associate
         end do
         call end_drifts(ys, st, cs)
         added = .false.
         ! Joints left out must stay open under the new forces and plastic loads.
         do k = 1, cs%m
            if (cs%in_lcp(k) .or. cs%joint(k)%fractured) cycle
            if (opening(k) < -residual_limit*qnorm) then
               cs%in_lcp(k) = .true.
               added = .true.
            end if
         end do
         ! Plastic flow of a joint must not pass a segment end that is not modelled.
         if (segment_ends_passed(cs, na, qnorm)) added = .true.
         ! Storeys outside their range enter (on their side; a storey in on one side whose end
         ! force passes the other line turns round).
         do ib = 1, size(ys)
            if (ys(ib)%frozen) cycle
            do j = 1, ys(ib)%n
               if (ys(ib)%side(j) == 0) then
                  call enter_out(ys(ib), j, ys(ib)%dnew, enter_tolerance*ys(ib)%fy(j), .true.)
                  if (ys(ib)%side(j) /= 0) added = .true.
               else if (ys(ib)%dpl(j) == 0.0_dp) then
                  if (turns(ys(ib), j)) added = .true.
               end if
            end do
         end do
         if (.not. added) exit
         cs%stats%resolves = cs%stats%resolves + 1
      end do
      if (added) then
         call fatal_error(error, 'the coupled LCP of the joints and the yielding storeys at t = '//str(t)// &
                          ' s (step '//str(step)//') still gained rows after '//str(max_rounds)//' solves')
         return
      end if

      ! Every row checked: the assembled LCP (relative to ||q||) and the joints left out.
      call lcp_evaluate(n, ys(1)%clcp%mat, ys(1)%clcp%q, ys(1)%clcp%z, ys(1)%clcp%w, resid)
      resid = resid*max(maxval(abs(ys(1)%clcp%q(1:n))), tiny(1.0_dp))
      do k = 1, cs%m
         if (cs%in_lcp(k) .or. cs%joint(k)%fractured) cycle
         resid = max(resid, -min(0.0_dp, opening(k)))
      end do
      resid = resid/max(qnorm, maxval(abs(ys(1)%clcp%q(1:n))))
      cs%stats%residual_max = max(cs%stats%residual_max, resid)
      if (nonconvex) cs%stats%nonconvex = cs%stats%nonconvex + 1
      if (.not. (resid <= residual_limit)) then
         call fatal_error(error, 'the coupled LCP of '//str(na)//' joints and '//str(ns)//' yielding storeys at t = '// &
                          str(t)//' s (step '//str(step)//'): natural residual '//str(resid)//' > '// &
                          str(residual_limit))
         return
      end if

      ! Apply: the joints' forces and the storeys' plastic loads go into du.
      cs%idle = .false.
      call contact_apply(cs, st)
      do ib = 1, size(ys)
         if (ys(ib)%n == 0 .or. ys(ib)%frozen) cycle
         call ys(ib)%check(t, step, models(ib)%name, error)
         if (allocated(error)) return
         call plastic_loads(ys(ib), st(ib), 1.0_dp)
         ys(ib)%loaded = ys(ib)%na > 0
         ys(ib)%alternations = max(ys(ib)%alternations, round - 1)
         if (ys(ib)%na > 0) then
            ys(ib)%solves = ys(ib)%solves + 1
            ys(ib)%lcp_rows = ys(ib)%lcp_rows + ys(ib)%na
            ys(ib)%max_rows = max(ys(ib)%max_rows, ys(ib)%na)
            if (na > 0) ys(ib)%joint_steps = ys(ib)%joint_steps + 1
         end if
         do j = 1, ys(ib)%na
            ys(ib)%side(ys(ib)%act(j)) = 0
         end do
      end do

   contains

      !> Opening of joint k (left out of the LCP) under the solution.
      real(dp) function opening(k) result(w)
         integer, intent(in) :: k
         integer :: a, s

         w = cs%q(k)
         do a = 1, na
            w = w + cs%f(k, cs%act(a))*ys(1)%clcp%z(a)
         end do
         do s = nj + 1, n
            associate (y => ys(ys(1)%cb(s)))
               if (y%hinges) then
                  ! (A hinge's column is Khat^{-1} a_j: its load per unit dp.)
                  w = w - ys(1)%cg(k, s)*y%dpl(ys(1)%cj(s))
               else
                  w = w - ys(1)%cg(k, s)*y%k(ys(1)%cj(s))*y%dpl(ys(1)%cj(s))
               end if
            end associate
         end do
      end function opening
   end subroutine yield_coupled

   !> Storey j joins the LCP on side `sg`.
   subroutine join(ys, j, sg)
      type(storey_yield_set), intent(inout) :: ys
      integer, intent(in) :: j, sg

      ys%side(j) = sg
      ys%na = ys%na + 1
      ys%act(ys%na) = j
   end subroutine join

   !> Storey j joins the LCP when its force at the drifts dv (no plastic increment of its own;
   !> a hinge: with the increments `dpl` when `solved`) is outside its elastic range widened by
   !> `tol` (kN), on the side it leaves by.
   subroutine enter_out(ys, j, dv, tol, solved)
      type(storey_yield_set), intent(inout) :: ys
      integer, intent(in) :: j
      real(dp), intent(in) :: dv(:), tol
      logical, intent(in) :: solved
      real(dp) :: f, c, h, d

      d = dv(j)
      f = ys%f(j) + ys%k(j)*(d - ys%d(j))
      if (ys%hinges) then
         f = f + ys%kc(j)*(dv(ys%mate(j)) - ys%d(ys%mate(j))) - ys%hk(j)*ys%p(j)
         if (solved) f = hinge_force(ys, j, dv)
      end if
      c = ys%r(j)*ys%k(j)*d
      h = (1.0_dp - ys%r(j))*ys%fy(j) + tol
      if (f > c + h) then
         call join(ys, j, 1)
      else if (f < c - h) then
         call join(ys, j, -1)
      end if
   end subroutine enter_out

   !> A storey in the LCP without plastic increment whose end force passes the other yield line
   !> turns to that side (true).
   logical function turns(ys, j)
      type(storey_yield_set), intent(inout) :: ys
      integer, intent(in) :: j
      real(dp) :: f, c, h

      f = ys%f(j) + ys%k(j)*(ys%dnew(j) - ys%d(j))
      if (ys%hinges) f = hinge_force(ys, j, ys%dnew)
      c = ys%r(j)*ys%k(j)*ys%dnew(j)
      h = (1.0_dp - ys%r(j))*ys%fy(j)*(1.0_dp + enter_tolerance)
      turns = .false.
      if (ys%side(j) > 0 .and. f < c - h) then
         ys%side(j) = -1
         turns = .true.
      else if (ys%side(j) < 0 .and. f > c + h) then
         ys%side(j) = 1
         turns = .true.
      end if
   end function turns

   !> Room for n rows of the coupled LCP and m joints (grows, rarely).
   subroutine coupled_workspace(w, n, m)
      type(storey_yield_set), intent(inout) :: w
      integer, intent(in) :: n, m
      logical :: grew

      call dense_lcp_reserve(w%clcp, n, 16, grew)
      if (.not. grew .and. allocated(w%cg)) then
         if (size(w%cg, 1) >= m) return
      end if
      if (allocated(w%cg)) deallocate (w%cg, w%cb, w%cj)
      associate (nmax => w%clcp%ws%m_max)
         allocate (w%cg(max(m, 1), nmax), w%cb(nmax), w%cj(nmax))
      end associate
   end subroutine coupled_workspace

   !> The coupled LCP (module comment) from the joints' assembled rows (cs%mat, cs%qa: nj rows,
   !> na contact rows) and the storeys in the LCP, into ys(1)'s workspace.
   subroutine assemble_coupled(ys, st, cs, na, nj, n)
      type(storey_yield_set), intent(inout) :: ys(:)
      class(integrator), intent(in) :: st(:)
      type(contact_system), intent(in) :: cs
      integer, intent(in) :: na, nj, n
      real(dp) :: g, h, ftr, shift
      integer :: ib, j, i, k, a, s, s2, e, sg

      associate (mat => ys(1)%clcp%mat, q => ys(1)%clcp%q)
         mat(1:n, 1:n) = 0.0_dp
         if (nj > 0) then
            mat(1:nj, 1:nj) = cs%mat(1:nj, 1:nj)
            q(1:nj) = cs%qa(1:nj)
            ys(1)%clcp%guess(1:nj) = cs%guess(1:nj)
            ys(1)%clcp%ref(1:nj) = cs%zref(1:nj)
         end if
         s = nj
         do ib = 1, size(ys)
            do a = 1, ys(ib)%na
               s = s + 1
               ys(1)%cb(s) = ib
               ys(1)%cj(s) = ys(ib)%act(a)
            end do
         end do
         do s = nj + 1, n
            ib = ys(1)%cb(s)
            j = ys(1)%cj(s)
            call ys(ib)%set_column(st(ib), j, ys(ib)%work)
            sg = ys(ib)%side(j)
            ! The joints' coupling G(k, s) = B_k^T Khat^{-1} b_j.
            shift = 0.0_dp
            do k = 1, cs%m
               g = 0.0_dp
               do e = 1, 2
                  if (cs%pair(k)%building(e) /= ib) cycle
                  g = g + end_sign(e)*end_value(cs%pair(k), e, ys(ib)%work)
               end do
               ys(1)%cg(k, s) = g
               shift = shift + g*cs%joint(k)%r
            end do
            if (ys(ib)%hinges) then
               call hinge_entries(ys(ib), j, sg, shift)
               cycle
            end if
            do a = 1, na
               k = cs%act(a)
               mat(a, s) = -real(sg, dp)*ys(ib)%k(j)*ys(1)%cg(k, s)
               mat(s, a) = real(sg, dp)*(1.0_dp - ys(ib)%r(j))*ys(1)%cg(k, s)
            end do
            ! The storeys of the same building (rows divided by their k).
            do s2 = nj + 1, n
               if (ys(1)%cb(s2) /= ib) cycle
               i = ys(1)%cj(s2)
               mat(s2, s) = -real(ys(ib)%side(i)*sg, dp)*(1.0_dp - ys(ib)%r(i))*ys(ib)%k(j)* &
                            recover(ys(ib)%rows, i, ys(ib)%work)
            end do
            mat(s, s) = mat(s, s) + 1.0_dp
            h = (1.0_dp - ys(ib)%r(j))*ys(ib)%fy(j)
            ftr = ys(ib)%f(j) + ys(ib)%k(j)*(ys(ib)%dtr(j) - ys(ib)%d(j))
            q(s) = (h - real(sg, dp)*(ftr - ys(ib)%r(j)*ys(ib)%k(j)*ys(ib)%dtr(j)))/ys(ib)%k(j) - &
                   real(sg, dp)*(1.0_dp - ys(ib)%r(j))*shift
            ys(1)%clcp%guess(s) = .true.
            ys(1)%clcp%ref(s) = 0.0_dp
         end do
      end associate

   contains

      !> Column s of a hinge j (work = Khat^{-1} a_j: G(k, s) is the closing of joint k per unit
      !> dp_j; rows of hinges divided by their k): joints' rows -sg G, the hinge's row sg G / k,
      !> the hinges of the building sg_i sg (S_ij - a_i^T Khat^{-1} a_j) / k_i, q from the trial
      !> moment and the joints' forces of the start of the step (`shift`).
      subroutine hinge_entries(y, j, sg, shift)
         type(storey_yield_set), intent(inout) :: y
         integer, intent(in) :: j, sg
         real(dp), intent(in) :: shift
         real(dp) :: sij
         integer :: a, k, s2, i

         associate (mat => ys(1)%clcp%mat, q => ys(1)%clcp%q)
            do a = 1, na
               k = cs%act(a)
               mat(a, s) = -real(sg, dp)*ys(1)%cg(k, s)
               mat(s, a) = real(sg, dp)*ys(1)%cg(k, s)/y%k(j)
            end do
            do s2 = nj + 1, n
               if (ys(1)%cb(s2) /= ib) cycle
               i = ys(1)%cj(s2)
               sij = 0.0_dp
               if (i == j) sij = y%k(j) + y%hk(j)
               if (i == y%mate(j)) sij = y%kc(j)
               mat(s2, s) = real(y%side(i)*sg, dp)*(sij - y%k(i)*recover(y%rows, i, y%work) - &
                                                    y%kc(i)*recover(y%rows, y%mate(i), y%work))/y%k(i)
            end do
            q(s) = (y%fy(j) - real(sg, dp)*(y%f(j) + y%k(j)*(y%dtr(j) - y%d(j)) + &
                                            y%kc(j)*(y%dtr(y%mate(j)) - y%d(y%mate(j))) - y%hk(j)*y%p(j)) - &
                  real(sg, dp)*shift)/y%k(j)
            ys(1)%clcp%guess(s) = .true.
            ys(1)%clcp%ref(s) = 0.0_dp
         end associate
      end subroutine hinge_entries
   end subroutine assemble_coupled

   !> Each building's plastic response xdp = sum_s k_s dp_s Khat^{-1} b_s and the drifts `dnew`
   !> of every storey at the end of the step (du + xdp - Khat^{-1} B (r - r_n)).
   subroutine end_drifts(ys, st, cs)
      type(storey_yield_set), intent(inout) :: ys(:)
      class(integrator), intent(inout), target :: st(:)
      type(contact_system), intent(in) :: cs
      real(dp), pointer :: du(:)
      real(dp) :: dr
      integer :: ib, j, k, e

      do ib = 1, size(ys)
         if (ys(ib)%n == 0 .or. ys(ib)%frozen) cycle
         if (ys(ib)%hinges) call hinge_loads(ys(ib), st(ib))
         if (.not. ys(ib)%hinges) ys(ib)%xdp = 0.0_dp
         do j = 1, ys(ib)%n
            if (ys(ib)%hinges) exit
            if (ys(ib)%dpl(j) == 0.0_dp) cycle
            call ys(ib)%set_column(st(ib), j, ys(ib)%work)
            ys(ib)%xdp = ys(ib)%xdp + (ys(ib)%k(j)*ys(ib)%dpl(j))*ys(ib)%work
         end do
         du => st(ib)%du_view()
         ys(ib)%tmp = du + ys(ib)%xdp
         do k = 1, cs%m
            dr = cs%r_new(k) - cs%joint(k)%r
            if (dr == 0.0_dp) cycle
            do e = 1, 2
               if (cs%pair(k)%building(e) /= ib) cycle
               ys(ib)%tmp = ys(ib)%tmp - (end_sign(e)*dr)*cs%y(e, k)%x
            end do
         end do
         call drifts(ys(ib), st(ib)%u_view(), ys(ib)%dnew, ys(ib)%work, ys(ib)%tmp)
      end do
   end subroutine end_drifts

end submodule pound_storey_yield_coupled
