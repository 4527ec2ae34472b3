!> Plastic hinges of frames (issue 25, `&building hinge_law = 'elastic_plastic'`) as the
!> complementarity elements of `pound_storey_yield` with a 2 x 2 local stiffness per element.
!>
!> A hinge row j is the rotation of an element end relative to the element's chord, theta_j =
!> b_j^T u (pound_frame_hinges). The element's end moments are m = S (theta - p) with S =
!> [k kc; kc k] = (EI/L) [4 2; 2 4] (the bending part of the element's stiffness, which stays
!> in K: Khat is factored once). Hinges with linear kinematic hardening of modulus H_j (`hk`,
!> 0: elastic-perfectly plastic): |m_j - H_j p_j| <= My_j, the plastic rotation p_j = p_j,n +
!> lam_plus - lam_minus with lam >= 0 in complementarity with My - (m - H p) >= 0,
!> (m - H p) + My >= 0 (Maier). A plastic increment dp_j acts on the structure as the load
!> a_j dp_j with a_j = S B (row j) = k_j b_j + kc_j b_mate(j), the moment row; the end-of-step
!> moments are m = m_tr - (S - A) dp with A_ij = a_i^T Khat^{-1} a_j (symmetric). The LCP over the
!> rows whose trial value m_tr - H p_n leaves the elastic range, on that side sigma:
!>
!>     M = Sigma (S + diag(H) - A) Sigma,   q_i = My_i - sigma_i (m_tr,i - H_i p_n,i),   z = |dp|,
!>
!> solved by Lemke, every hinge checked afterwards and the LCP solved again with any that left
!> its range (`yield_step`), the natural residual checked (`check_step`). A shear
!> building's storey is the same element with a 1 x 1 block (kc = 0).
!>
!> Energies per step: W_L = sum_j (p_n + p)_j / 2 (m-row . (u_{n+1} - u_n)), strain energy
!> (theta - p)^T S (theta - p) / 2 per element, hysteretic energy sum_j (m_n + m)_j / 2 dp_j.
!> Recovery: storey shears and member end forces lose their plastic parts (the model's
!> `shear_plastic`, `member_plastic` rows over p).
submodule(pound_storey_yield) pound_storey_yield_hinges

   implicit none

contains

   module subroutine hinge_set_init(ys, b, collapse_drift)
      type(storey_yield_set), intent(inout) :: ys
      type(structure_model), intent(in) :: b
      real(dp), intent(in), optional :: collapse_drift
      integer :: n, ns, i

      n = b%hinge%n
      ns = b%drift%n
      ys%hinges = .true.
      ys%n = n
      ys%nd = b%n
      ys%rows = b%hinge
      ys%k = b%hinge_k
      ys%kc = b%hinge_kc
      ys%mate = b%hinge_mate
      ys%hk = b%hinge_hardening
      ys%level = b%hinge_level
      ys%fy = b%hinge_moment
      ys%r = spread(0.0_dp, 1, n)
      ys%limit = spread(huge(1.0_dp), 1, n)
      ys%crows = b%drift
      ys%srows = b%shear
      ys%sprows = b%shear_plastic
      ys%mrows = b%member
      ys%mprows = b%member_plastic
      ys%climit = spread(huge(1.0_dp), 1, ns)
      if (present(collapse_drift) .and. allocated(b%yield_height)) ys%climit = collapse_drift*b%yield_height
      allocate (ys%cdrift(ns), ys%sval(ns), ys%speak(ns), ys%stime(ns), ys%mpeak(b%member%n), &
                ys%mtime(b%member%n), ys%pmax(n), ys%ratio(n), ys%pold(n), ys%fold(n), ys%fload(b%n), &
                source=0.0_dp)
      ys%alldof = [(i, i=1, b%n)]
   end subroutine hinge_set_init

   pure module real(dp) function hinge_force(ys, j, d) result(f)
      type(storey_yield_set), intent(in) :: ys
      integer, intent(in) :: j
      real(dp), intent(in) :: d(:)
      integer :: m

      m = ys%mate(j)
      f = ys%f(j) + ys%k(j)*(d(j) - ys%d(j) - ys%dpl(j)) + ys%kc(j)*(d(m) - ys%d(m) - ys%dpl(m)) - &
          ys%hk(j)*(ys%p(j) + ys%dpl(j))
   end function hinge_force

   module subroutine hinge_block(ys, st, m)
      type(storey_yield_set), intent(inout) :: ys
      class(integrator), intent(in) :: st
      integer, intent(in) :: m
      real(dp) :: s
      integer :: a, b, i, j

      do b = 1, m
         j = ys%act(b)
         call ys%set_column(st, j, ys%work)
         do a = 1, m
            i = ys%act(a)
            s = real(ys%side(i)*ys%side(j), dp)
            ys%lcp%mat(a, b) = -s*(ys%k(i)*recover(ys%rows, i, ys%work) + ys%kc(i)*recover(ys%rows, ys%mate(i), ys%work))
            if (i == j) ys%lcp%mat(a, b) = ys%lcp%mat(a, b) + ys%k(j) + ys%hk(j)
            if (i == ys%mate(j)) ys%lcp%mat(a, b) = ys%lcp%mat(a, b) + s*ys%kc(j)
         end do
         ys%lcp%q(b) = ys%fy(j) - real(ys%side(j), dp)*hinge_force(ys, j, ys%dtr)
      end do
   end subroutine hinge_block

   module subroutine hinge_loads(ys, st)
      type(storey_yield_set), intent(inout) :: ys
      class(integrator), intent(in) :: st
      integer :: j

      ys%xdp = 0.0_dp
      ys%fload = 0.0_dp
      do j = 1, ys%n
         if (ys%dpl(j) == 0.0_dp) cycle
         call ys%set_column(st, j, ys%work)
         ys%xdp = ys%xdp + ys%dpl(j)*ys%work
         ! The load dp_j a_j = dp_j (k_j b_j + kc_j b_mate(j)).
         call ys%row_scatter(j, ys%dpl(j)*ys%k(j), ys%fload)
         call ys%row_scatter(ys%mate(j), ys%dpl(j)*ys%kc(j), ys%fload)
      end do
   end subroutine hinge_loads

   module subroutine hinge_turns(ys, added)
      type(storey_yield_set), intent(inout) :: ys
      logical, intent(inout) :: added
      real(dp) :: f, h
      integer :: a, j

      do a = 1, ys%na
         j = ys%act(a)
         if (ys%dpl(j) /= 0.0_dp) cycle
         f = hinge_force(ys, j, ys%dnew)
         h = ys%fy(j)*(1.0_dp + enter_tolerance)
         if (ys%side(j) > 0 .and. f < -h) then
            ys%side(j) = -1
            added = .true.
         else if (ys%side(j) < 0 .and. f > h) then
            ys%side(j) = 1
            added = .true.
         end if
      end do
   end subroutine hinge_turns

   module procedure hinge_commit
      real(dp) :: x
      integer :: j, m

      call drifts(ys, u, ys%dnew, ys%work)
      ys%dold = ys%d
      ys%pold = ys%p
      ys%fold = ys%f
      ys%p = ys%p + ys%dpl
      ys%d = ys%dnew
      do j = 1, ys%n
         m = ys%mate(j)
         ys%f(j) = ys%k(j)*(ys%d(j) - ys%p(j)) + ys%kc(j)*(ys%d(m) - ys%p(m))
      end do
      do j = 1, ys%n
         m = ys%mate(j)
         ys%load_work = ys%load_work + 0.5_dp*(ys%pold(j) + ys%p(j))* &
                        (ys%k(j)*(ys%d(j) - ys%dold(j)) + ys%kc(j)*(ys%d(m) - ys%dold(m)))
         ys%hysteretic = ys%hysteretic + 0.5_dp*(ys%fold(j) + ys%f(j))*ys%dpl(j)
         ys%dmax(j) = max(ys%dmax(j), abs(ys%d(j)))
         ys%pmax(j) = max(ys%pmax(j), abs(ys%p(j)))
         ys%ratio(j) = max(ys%ratio(j), abs(ys%f(j))/ys%fy(j))
         if (abs(ys%f(j)) > ys%fmax(j)) then
            ys%fmax(j) = abs(ys%f(j))
            ys%tmax(j) = t
         end if
      end do
      do j = 1, ys%crows%n
         ys%cdrift(j) = recover(ys%crows, j, u)
         if (abs(ys%cdrift(j)) > ys%climit(j) .and. ys%collapse_storey == 0) then
            ys%collapse_storey = j
            ys%collapse_time = t
         end if
         ys%sval(j) = recover(ys%srows, j, u) - recover(ys%sprows, j, ys%p)
         if (abs(ys%sval(j)) > ys%speak(j)) then
            ys%speak(j) = abs(ys%sval(j))
            ys%stime(j) = t
         end if
      end do
      do j = 1, ys%mrows%n
         x = abs(recover(ys%mrows, j, u) - recover(ys%mprows, j, ys%p))
         if (x > ys%mpeak(j)) then
            ys%mpeak(j) = x
            ys%mtime(j) = t
         end if
      end do
      if (present(shear)) shear = ys%sval
      ys%dpl = 0.0_dp
      ys%xdp = 0.0_dp
      ys%fload = 0.0_dp
      ys%loaded = .false.
   end procedure hinge_commit

   pure module subroutine hinge_finish(ys, rec, res)
      type(storey_yield_set), intent(in) :: ys
      type(response_record), intent(inout) :: rec
      type(storey_yield_result), intent(out) :: res
      integer :: j, h

      res%n = ys%crows%n
      res%n_hinges = ys%n
      res%rotation = ys%pmax
      res%moment_ratio = ys%ratio
      res%residual_drift = ys%cdrift
      res%peak_force = ys%speak
      allocate (res%ductility(res%n), source=0.0_dp)
      call finish_tallies(ys, res)
      rec%peak(:, q_shear) = ys%speak
      rec%peak_time(:, q_shear) = ys%stime
      if (allocated(rec%member_peak)) then
         rec%member_peak = ys%mpeak
         rec%member_time = ys%mtime
      end if
      do h = 1, ys%n
         j = ys%level(h)
         if (j > 0 .and. j <= res%n) res%ductility(j) = max(res%ductility(j), ys%pmax(h))
      end do
   end subroutine hinge_finish

end submodule pound_storey_yield_hinges
