!> Solve with a band Cholesky factor: the banded Newmark step's own replacement of dpbtrs.
!>
!> `ab(kd+1, n)` holds the upper factor U of A = U^T U exactly as dpbtrf('U') leaves it
!> (`ab(kd+1+i-j, j) = U(i, j)` for `max(1, j-kd) <= i <= j`; the unreferenced corner of
!> the first kd columns is never read) and `dinv(n)` the reciprocals 1/U(j, j), computed
!> once with the factor: the sweeps multiply, they do not divide.
!>
!> Both sweeps run over contiguous columns of `ab` (the forward one as dot products, the
!> backward one as column updates) and keep the newest element of the solution in a
!> register: the term that couples a DOF to its neighbour, U(j-1, j), is the only one on the
!> sweep's chain of dependent operations (one multiply-add and one multiply per DOF), while
!> the older terms are summed from memory ahead of it in four partial sums. Reference dtbsv,
!> which dpbtrs calls, stores and reloads every element it updates and so runs the whole
!> column on that chain; here the solve takes about 0.5 to 0.67 of its time at kd = 8 to 20
!> (README, "The banded solve"). The sums are taken in another order than dtbsv's: the
!> results agree with dpbtrs to round-off (tests/test_band_solve.pf).
module pound_band_solve
   use pound_kinds, only: dp
   implicit none
   private

   public :: band_solve

contains

   !> Overwrite x with A^{-1} x, A = U^T U: the forward sweep U^T y = x,
   !> y(j) = (x(j) - sum_i U(i, j) y(i)) / U(j, j), i = j-kd .. j-1, then the backward sweep
   !> U x = y: x(j) = y(j)/U(j, j), y(i) = y(i) - U(i, j) x(j), i = j-kd .. j-1, j = n .. 1.
   pure subroutine band_solve(n, kd, ab, dinv, x)
      !> Order and half-bandwidth (kd >= 0).
      integer, intent(in) :: n, kd
      !> The factor U of dpbtrf('U') in upper band storage.
      real(dp), intent(in) :: ab(kd + 1, n)
      !> 1/U(j, j).
      real(dp), intent(in) :: dinv(n)
      !> Right-hand side on entry, solution on return.
      real(dp), intent(inout) :: x(n)
      real(dp) :: s(0:3), t, xp, r1, r2, r3, r4
      integer :: j, m, k, jw

      if (n < 1) return
      if (kd == 0) then
         x = x*dinv*dinv
         return
      end if
      ! Columns jw .. n take the windowed sweeps (kd >= 5: U(j-4 .. j-1, j) with the four
      ! newest elements in registers), the first ones the plain column loops.
      jw = n + 1
      if (kd >= 5 .and. n > kd) jw = kd + 1
      ! Forward. Rows m of column j hold U(k + m, j); row kd is U(j-1, j), the register term.
      xp = x(1)*dinv(1)
      x(1) = xp
      do j = 2, jw - 1
         k = j - kd - 1
         t = 0.0_dp
         do m = max(1, kd + 2 - j), kd - 1
            t = t + ab(m, j)*x(k + m)
         end do
         xp = (x(j) - t - ab(kd, j)*xp)*dinv(j)
         x(j) = xp
      end do
      if (jw <= n) then
         r1 = x(jw - 1)
         r2 = x(jw - 2)
         r3 = x(jw - 3)
         r4 = x(jw - 4)
         do j = jw, n
            k = j - kd - 1
            s = 0.0_dp
            do m = 1, kd - 7, 4
               s = s + ab(m:m + 3, j)*x(k + m:k + m + 3)
            end do
            t = (s(0) + s(1)) + (s(2) + s(3))
            do m = m, kd - 4
               t = t + ab(m, j)*x(k + m)
            end do
            t = t + ab(kd - 3, j)*r4 + ab(kd - 2, j)*r3 + ab(kd - 1, j)*r2
            xp = (x(j) - t - ab(kd, j)*r1)*dinv(j)
            x(j) = xp
            r4 = r3
            r3 = r2
            r2 = r1
            r1 = xp
         end do
      end if
      ! Backward from y(n) = xp. Row kd of column j is U(j-1, j): with it x(j-1) is complete.
      xp = xp*dinv(n)
      if (jw <= n) then
         ! The pending x(j-1 .. j-4) in registers r1 .. r4, the older ones updated in memory.
         r1 = x(n - 1)
         r2 = x(n - 2)
         r3 = x(n - 3)
         r4 = x(n - 4)
         do j = n, jw, -1
            x(j) = xp
            k = j - kd - 1
            do m = 1, kd - 4
               x(k + m) = x(k + m) - xp*ab(m, j)
            end do
            r4 = r4 - xp*ab(kd - 3, j)
            r3 = r3 - xp*ab(kd - 2, j)
            r2 = r2 - xp*ab(kd - 1, j)
            xp = (r1 - xp*ab(kd, j))*dinv(j - 1)
            r1 = r2
            r2 = r3
            r3 = r4
            r4 = x(j - 5)
         end do
         x(jw - 2) = r1
         x(jw - 3) = r2
         x(jw - 4) = r3
      end if
      do j = min(n, jw - 1), 2, -1
         x(j) = xp
         k = j - kd - 1
         do m = max(1, kd + 2 - j), kd - 1
            x(k + m) = x(k + m) - xp*ab(m, j)
         end do
         xp = (x(j - 1) - xp*ab(kd, j))*dinv(j - 1)
      end do
      x(1) = xp
   end subroutine band_solve

end module pound_band_solve
