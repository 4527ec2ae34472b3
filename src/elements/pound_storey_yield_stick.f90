!> The storeys' step of a stick (`pound_storey_yield`): the primal-dual active-set method on the
!> tridiagonal tangent system, O(n) a pass, in place of the dense LCP where it settles.
submodule(pound_storey_yield) pound_storey_yield_stick
   implicit none

   !> Passes of the active-set method before Lemke's method takes the step.
   integer, parameter :: max_passes = 30

   interface
      subroutine dpttrf(n, d, e, info)
         import :: dp
         integer, intent(in) :: n
         real(dp), intent(inout) :: d(*), e(*)
         integer, intent(out) :: info
      end subroutine dpttrf
      subroutine dpttrs(n, nrhs, d, e, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, ldb
         real(dp), intent(in) :: d(*), e(*)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpttrs
   end interface

contains

   module subroutine stick_khat(ys, st)
      type(storey_yield_set), intent(inout) :: ys
      class(integrator), intent(in) :: st
      real(dp) :: fk, fm
      integer :: n

      n = ys%n
      call st%solve_matrix(ys%a0, ys%a1, fk, fm)
      ys%khat_d = fk*ys%kt(2, :) + fm*ys%mass
      ys%khat_e = 0.0_dp
      if (n > 1) ys%khat_e(1:n - 1) = fk*ys%kt(1, 2:n)
   end subroutine stick_khat

   module subroutine stick_active_set(ys, u, du, solved)
      type(storey_yield_set), intent(inout) :: ys
      real(dp), intent(in) :: u(:), du(:)
      logical, intent(out) :: solved
      real(dp) :: c, g, f, h, below, here, dp_j, lo, hi
      integer :: pass, j, n, info, na0
      logical :: changed

      solved = .false.
      n = ys%n
      na0 = ys%na
      do pass = 1, max_passes
         ! The tangent system of the active set and its right-hand side sum_A k b dp_trial.
         ys%td = ys%khat_d
         if (n > 1) ys%te(1:n - 1) = ys%khat_e(1:n - 1)
         ys%ty = 0.0_dp
         do j = 1, n
            if (ys%side(j) == 0) cycle
            c = (1.0_dp - ys%r(j))*ys%k(j)
            g = (ys%f(j) - real(ys%side(j), dp)*(1.0_dp - ys%r(j))*ys%fy(j))/ys%k(j) - ys%d(j)
            dp_j = ys%k(j)*((1.0_dp - ys%r(j))*ys%dtr(j) + g)
            ys%td(j) = ys%td(j) - c
            ys%ty(j) = ys%ty(j) + dp_j
            if (j > 1) then
               ys%td(j - 1) = ys%td(j - 1) - c
               ys%te(j - 1) = ys%te(j - 1) + c
               ys%ty(j - 1) = ys%ty(j - 1) - dp_j
            end if
         end do
         call dpttrf(n, ys%td, ys%te, info)
         if (info /= 0) exit
         call dpttrs(n, 1, ys%td, ys%te, ys%ty, n, info)
         if (info /= 0) exit
         ys%stick_solves = ys%stick_solves + 1
         ! Drifts at the end of the step; the active storeys' plastic increments.
         below = 0.0_dp
         do j = 1, n
            here = u(j) + du(j) + ys%ty(j)
            ys%dnew(j) = here - below
            below = here
         end do
         changed = .false.
         do j = 1, n
            if (ys%side(j) /= 0) then
               g = (ys%f(j) - real(ys%side(j), dp)*(1.0_dp - ys%r(j))*ys%fy(j))/ys%k(j) - ys%d(j)
               dp_j = (1.0_dp - ys%r(j))*ys%dnew(j) + g
               ys%dpl(j) = dp_j
               if (real(ys%side(j), dp)*dp_j < 0.0_dp) then
                  ys%side(j) = 0
                  ys%dpl(j) = 0.0_dp
                  changed = .true.
               end if
            else
               ys%dpl(j) = 0.0_dp
               f = ys%f(j) + ys%k(j)*(ys%dnew(j) - ys%d(j))
               h = (1.0_dp - ys%r(j))*ys%fy(j) + enter_tolerance*ys%fy(j)
               lo = ys%r(j)*ys%k(j)*ys%dnew(j) - h
               hi = ys%r(j)*ys%k(j)*ys%dnew(j) + h
               if (f > hi) then
                  ys%side(j) = 1
                  changed = .true.
               else if (f < lo) then
                  ys%side(j) = -1
                  changed = .true.
               end if
            end if
         end do
         if (changed) cycle
         ! Settled: the plastic response and the active list.
         ys%xdp = ys%ty
         ys%na = 0
         do j = 1, n
            if (ys%side(j) == 0) cycle
            ys%na = ys%na + 1
            ys%act(ys%na) = j
         end do
         solved = .true.
         return
      end do
      ! Not settled: the entering storeys as they were, for Lemke's method.
      ys%side = 0
      ys%dpl = 0.0_dp
      do j = 1, na0
         call restore(ys%act(j))
      end do

   contains

      !> The side storey j entered by (from its trial force).
      subroutine restore(i)
         integer, intent(in) :: i
         real(dp) :: fi, ci

         fi = ys%f(i) + ys%k(i)*(ys%dtr(i) - ys%d(i))
         ci = ys%r(i)*ys%k(i)*ys%dtr(i)
         ys%side(i) = merge(1, -1, fi > ci)
      end subroutine restore
   end subroutine stick_active_set

   !> The drift of every storey of `ys` for the DOF vector x (+ y, when given) into `d`
   !> (`work`: the sum x + y on the general path). `d` and `work` may be components of `ys`:
   !> only its rows and sizes are read through `ys`.
   pure module subroutine drifts(ys, x, d, work, y)
      type(storey_yield_set), intent(in) :: ys
      real(dp), intent(in) :: x(:)
      real(dp), intent(out) :: d(:), work(:)
      real(dp), intent(in), optional :: y(:)
      real(dp) :: below, here
      integer :: j

      if (ys%stick) then
         ! Storey j joins floors j-1 and j (DOFs; the ground below storey 1).
         below = 0.0_dp
         if (present(y)) then
            do j = 1, ys%n
               here = x(j) + y(j)
               d(j) = here - below
               below = here
            end do
         else
            do j = 1, ys%n
               d(j) = x(j) - below
               below = x(j)
            end do
         end if
         return
      end if
      if (present(y)) then
         do j = 1, ys%nd
            work(j) = x(j) + y(j)
         end do
         do j = 1, ys%n
            d(j) = recover(ys%rows, j, work)
         end do
      else
         do j = 1, ys%n
            d(j) = recover(ys%rows, j, x)
         end do
      end if
   end subroutine drifts

   pure module subroutine step_drifts(ys, u, du)
      type(storey_yield_set), intent(inout) :: ys
      real(dp), intent(in) :: u(:), du(:)
      integer :: j

      do j = 1, ys%nd
         ys%xdp(j) = ys%xdp(j) + du(j)
      end do
      call drifts(ys, u, ys%dnew, ys%work, ys%xdp)
      do j = 1, ys%nd
         ys%xdp(j) = ys%xdp(j) - du(j)
      end do
   end subroutine step_drifts

end submodule pound_storey_yield_stick
