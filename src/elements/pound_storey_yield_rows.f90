!> The rows of the bilinear storeys and of the plastic hinges (`pound_storey_yield`) as an
!> element set of the complementarity core (`complementarity_set`): the rows' values and
!> scatter, the columns Khat^{-1} a_j from the integrator's solve, the set's LCP block and
!> its solve, the check of a solved step, and the commit.
submodule(pound_storey_yield) pound_storey_yield_rows
   implicit none

contains

   module procedure storey_rows

      storey_rows = set%n
   end procedure storey_rows

   module procedure storey_row_value

      storey_row_value = recover(set%rows, i, x)
   end procedure storey_row_value

   module procedure storey_row_scatter
      integer :: e

      do e = set%rows%start(i), set%rows%start(i + 1) - 1
         x(set%rows%dof(e)) = x(set%rows%dof(e)) + s*set%rows%coef(e)
      end do
   end procedure storey_row_scatter

   !> Khat^{-1} a_j: a storey's load per unit dp is k_j b_j (its column Khat^{-1} b_j, scaled
   !> by the caller), a hinge's k_j b_j + kc_j b_mate(j).
   module procedure storey_column

      if (set%hinges) then
         call hinge_column(set, st, i, x)
      else
         call column_of(set, st, i, x)
      end if
   end procedure storey_column

   !> The storeys' block: M = S (K - D A) S with A_ij = k_j b_i^T Khat^{-1} b_j,
   !> D = diag((1-r) k), S the sides; q from the trial state (hinges: `hinge_block`).
   module procedure storey_block
      real(dp) :: h, ftr
      integer :: a, b, i, j

      if (set%hinges) then
         call hinge_block(set, st, m)
         return
      end if
      associate (ys => set, mat => set%lcp%mat, q => set%lcp%q)
         do b = 1, m
            j = ys%act(b)
            call column_of(ys, st, j, ys%work)
            do a = 1, m
               i = ys%act(a)
               mat(a, b) = -real(ys%side(i)*ys%side(j), dp)*(1.0_dp - ys%r(i))*ys%k(i)*ys%k(j)*recover(ys%rows, i, ys%work)
            end do
            mat(b, b) = mat(b, b) + ys%k(j)
            h = (1.0_dp - ys%r(j))*ys%fy(j)
            ftr = ys%f(j) + ys%k(j)*(ys%dtr(j) - ys%d(j))
            q(b) = h - real(ys%side(j), dp)*(ftr - ys%r(j)*ys%k(j)*ys%dtr(j))
         end do
      end associate
   end procedure storey_block

   module procedure storey_check

      call check_step(set, t, step, label, error)
   end procedure storey_check

   module procedure storey_commit

      call yield_commit(set, u, t, shear)
   end procedure storey_commit

   !> Column Khat^{-1} b_j of row j (solved once per dt, kept when the building is small).
   subroutine column_of(ys, st, j, x)
      type(storey_yield_set), intent(inout) :: ys
      class(integrator), intent(in) :: st
      integer, intent(in) :: j
      real(dp), intent(out) :: x(:)

      if (size(ys%col, 2) >= ys%n) then
         if (ys%slot(j) > 0) then
            x = ys%col(:, ys%slot(j))
            return
         end if
      end if
      x = 0.0_dp
      call ys%row_scatter(j, 1.0_dp, x)
      call st%solve(x)
      if (size(ys%col, 2) >= ys%n) then
         ys%n_slots = ys%n_slots + 1
         ys%slot(j) = ys%n_slots
         ys%col(:, ys%n_slots) = x
      end if
   end subroutine column_of

   !> Khat^{-1} a_j of hinge j (a_j = k_j b_j + kc_j b_mate(j), its load per unit dp) into x.
   subroutine hinge_column(ys, st, j, x)
      type(storey_yield_set), intent(inout) :: ys
      class(integrator), intent(in) :: st
      integer, intent(in) :: j
      real(dp), intent(out) :: x(:)

      call column_of(ys, st, j, x)
      call column_of(ys, st, ys%mate(j), ys%tmp)
      x = ys%k(j)*x + ys%kc(j)*ys%tmp
   end subroutine hinge_column

   module procedure solve_rows
      integer :: b, j, m

      m = ys%na
      call dense_lcp_reserve(ys%lcp, m, m)
      ! (The trial state: no plastic increment of this step.)
      ys%dpl = 0.0_dp
      call ys%lcp_block(st, m)
      call solve_lcp(ys, m, t, step, label, error)
      if (allocated(error)) return
      do b = 1, m
         j = ys%act(b)
         ys%dpl(j) = real(ys%side(j), dp)*ys%lcp%z(b)
      end do
      if (ys%hinges) then
         call hinge_loads(ys, st)
      else
         ys%xdp = 0.0_dp
         do b = 1, m
            j = ys%act(b)
            if (ys%dpl(j) == 0.0_dp) cycle
            call column_of(ys, st, j, ys%work)
            ys%xdp = ys%xdp + (ys%k(j)*ys%dpl(j))*ys%work
         end do
      end if
      call step_drifts(ys, u, du)
   end procedure solve_rows

   subroutine solve_lcp(ys, m, t, step, label, error)
      type(storey_yield_set), intent(inout) :: ys
      integer, intent(in) :: m
      real(dp), intent(in) :: t
      integer, intent(in) :: step
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      type(lemke_report) :: rep

      ys%lcp%guess(1:m) = .true.
      call dense_lcp_solve(ys%lcp, m, rep)
      ys%solves = ys%solves + 1
      ys%lcp_rows = ys%lcp_rows + m
      ys%max_rows = max(ys%max_rows, m)
      if (rep%ok) return
      call fatal_error(error, 'building '//label//': '//trim(merge('the plastic hinges''  ', 'the yielding storeys''', &
                       ys%hinges))//' LCP ('//str(m)//' '//trim(merge('hinges ', 'storeys', ys%hinges))//') at t = '// &
                       str(t)//' s (step '//str(step)//') was not solved: '//lemke_status_name(rep%status)// &
                       ', natural residual '//str(rep%residual)//' (reduce dt)')
   end subroutine solve_lcp

   subroutine check_step(ys, t, step, label, error)
      type(storey_yield_set), intent(inout) :: ys
      real(dp), intent(in) :: t
      integer, intent(in) :: step
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: f, c, h, up, lo, res, worst
      integer :: j, at

      worst = 0.0_dp
      at = 0
      do j = 1, ys%n
         f = ys%f(j) + ys%k(j)*(ys%dnew(j) - ys%d(j)) - ys%k(j)*ys%dpl(j)
         if (ys%hinges) f = hinge_force(ys, j, ys%dnew)
         c = ys%r(j)*ys%k(j)*ys%dnew(j)
         h = (1.0_dp - ys%r(j))*ys%fy(j)
         up = c + h - f
         lo = f - c + h
         res = max(0.0_dp, -up, -lo)
         if (ys%dpl(j) > 0.0_dp) res = max(res, abs(min(ys%k(j)*ys%dpl(j), up)))
         if (ys%dpl(j) < 0.0_dp) res = max(res, abs(min(-ys%k(j)*ys%dpl(j), lo)))
         if (ys%hinges) then
            ! (Relative to the largest of My, the trial moment and S |theta|: the round-off of
            ! m = S (theta - p).)
            res = res/max(ys%fy(j), abs(ys%f(j) + ys%k(j)*(ys%dtr(j) - ys%d(j)) + &
                                       ys%kc(j)*(ys%dtr(ys%mate(j)) - ys%d(ys%mate(j)))), &
                          ys%k(j)*abs(ys%dnew(j)) + ys%kc(j)*abs(ys%dnew(ys%mate(j))))
         else
            res = res/ys%fy(j)
         end if
         if (res > worst) then
            worst = res
            at = j
         end if
      end do
      ys%residual = max(ys%residual, worst)
      if (worst <= yield_residual_limit) return
      call fatal_error(error, 'building '//label//', '//trim(merge('hinge ', 'storey', ys%hinges))//' '//str(at)//': '// &
                       trim(merge('the plastic hinges''  ', 'the yielding storeys''', ys%hinges))//' step at t = '// &
                       str(t)//' s (step '//str(step)//') has the natural residual '//str(worst)// &
                       ' (limit '//str(yield_residual_limit)//'; reduce dt)')
   end subroutine check_step

end submodule pound_storey_yield_rows
