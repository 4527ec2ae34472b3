!> The small dense kernels of the steps with elastic joints closed (pound_closed_steps): the
!> substep of the condensed modes with the closed joints' forces implicit, the joints' closing
!> displacements, the products with the shapes, and the extreme of a cubic Hermite path.
!> Explicit-shape arguments, so that the loops run over contiguous memory in vectors.
module pound_closed_kernels
   use pound_kinds, only: dp
   implicit none
   private

   public :: closing, dot8, substep, modal_acceleration, mv2, mv, mvk, mv3, hermite_extreme

   !> Modal coordinates and rates below this are set to zero (as in pound_newmark_exact: no
   !> subnormal numbers).
   real(dp), parameter :: negligible = 1.0e-100_dp

contains

   !> Closing displacement w^_k . q and rate w^_k . q' of the joints k in `list`.
   pure subroutine closing(n, nj, nl, list, w, q, qd, d, dd)
      integer, intent(in) :: n, nj, nl, list(nl)
      real(dp), intent(in) :: w(n, nj), q(n), qd(n)
      real(dp), intent(inout) :: d(nj), dd(nj)
      integer :: l, k

      do l = 1, nl
         k = list(l)
         d(k) = dot8(n, w(:, k), q)
         dd(k) = dot8(n, w(:, k), qd)
      end do
   end subroutine closing

   !> x . y in eight partial sums (the sums vectorise; the order is fixed).
   pure real(dp) function dot8(n, x, y) result(s)
      integer, intent(in) :: n
      real(dp), intent(in) :: x(n), y(n)
      real(dp) :: p(8)
      integer :: i, n8

      p = 0.0_dp
      n8 = n - mod(n, 8)
      do i = 1, n8, 8
         p = p + x(i:i + 7)*y(i:i + 7)
      end do
      s = ((p(1) + p(5)) + (p(2) + p(6))) + ((p(3) + p(7)) + (p(4) + p(8)))
      do i = n8 + 1, n
         s = s + x(i)*y(i)
      end do
   end function dot8

   !> One substep of the modes under the load linear from p0 to p1 = -gamma a_g1 - W r1, r1 the
   !> closed joints' forces at its end (implicit: r1 = H^-1 K (W^T q_pred - g)); q, q' advanced,
   !> p1 and r (the closed joints' entries) set.
   pure subroutine substep(n, nj, nr, joint, cf, gam, w, hk, gap, a1, q, qd, p0, p1, qp, rhs, r)
      integer, intent(in) :: n, nj, nr, joint(nr)
      real(dp), intent(in) :: cf(n, 8), gam(n), w(n, nj), hk(nr, nr), gap(nj), a1, p0(n)
      real(dp), intent(inout) :: q(n), qd(n), r(nj)
      real(dp), intent(out) :: p1(n), qp(n), rhs(nr)
      integer :: i, l, k
      real(dp) :: x

      !GCC$ vector
      do i = 1, n
         qp(i) = cf(i, 1)*q(i) + cf(i, 2)*qd(i) + cf(i, 3)*p0(i) - cf(i, 4)*gam(i)*a1
         p1(i) = -gam(i)*a1
      end do
      do l = 1, nr
         k = joint(l)
         rhs(l) = dot8(n, w(:, k), qp) - gap(k)
      end do
      do l = 1, nr
         k = joint(l)
         x = 0.0_dp
         do i = 1, nr
            x = x + hk(l, i)*rhs(i)
         end do
         r(k) = x
         !GCC$ vector
         do i = 1, n
            p1(i) = p1(i) - w(i, k)*x
         end do
      end do
      ! The stiff, over-damped modes decay to subnormal numbers, which slow every product
      ! with them many times: below `negligible` they are zero.
      !GCC$ vector
      do i = 1, n
         x = cf(i, 5)*q(i) + cf(i, 6)*qd(i) + cf(i, 7)*p0(i) + cf(i, 8)*p1(i)
         qd(i) = merge(0.0_dp, x, abs(x) < negligible)
         x = qp(i) + cf(i, 4)*(p1(i) + gam(i)*a1)
         q(i) = merge(0.0_dp, x, abs(x) < negligible)
      end do
   end subroutine substep

   !> q'' = p - lambda q - c q'.
   pure subroutine modal_acceleration(n, p, lam, cm, q, qd, qdd)
      integer, intent(in) :: n
      real(dp), intent(in) :: p(n), lam(n), cm(n), q(n), qd(n)
      real(dp), intent(out) :: qdd(n)
      integer :: i

      !GCC$ vector
      do i = 1, n
         qdd(i) = p(i) - lam(i)*q(i) - cm(i)*qd(i)
      end do
   end subroutine modal_acceleration

   !> y = A x, z = A w, A (n, m) (columns; n small: the response points).
   pure subroutine mv2(n, m, a, x, w, y, z)
      integer, intent(in) :: n, m
      real(dp), intent(in) :: a(n, m), x(m), w(m)
      real(dp), intent(out) :: y(n), z(n)
      integer :: i, j

      y = 0.0_dp
      z = 0.0_dp
      do j = 1, m
         !GCC$ vector
         do i = 1, n
            y(i) = y(i) + a(i, j)*x(j)
            z(i) = z(i) + a(i, j)*w(j)
         end do
      end do
   end subroutine mv2

   !> y = A x, A (n, m) (columns).
   pure subroutine mv(n, m, a, x, y)
      integer, intent(in) :: n, m
      real(dp), intent(in) :: a(n, m), x(m)
      real(dp), intent(out) :: y(n)
      integer :: i, j

      y = 0.0_dp
      do j = 1, m
         !GCC$ vector
         do i = 1, n
            y(i) = y(i) + a(i, j)*x(j)
         end do
      end do
   end subroutine mv

   !> y = A x for k vectors at once, A (n, m), x (m, k), y (n, k) (A read once, by columns).
   pure subroutine mvk(n, m, k, a, x, y)
      integer, intent(in) :: n, m, k
      real(dp), intent(in) :: a(n, m), x(m, k)
      real(dp), intent(out) :: y(n, k)
      integer :: i, j, l, m4

      y = 0.0_dp
      ! Four columns of A at a time: y is read and written once for four.
      m4 = m - mod(m, 4)
      do j = 1, m4, 4
         do l = 1, k
            !GCC$ vector
            do i = 1, n
               y(i, l) = y(i, l) + ((a(i, j)*x(j, l) + a(i, j + 1)*x(j + 1, l)) + &
                                    (a(i, j + 2)*x(j + 2, l) + a(i, j + 3)*x(j + 3, l)))
            end do
         end do
      end do
      do j = m4 + 1, m
         do l = 1, k
            !GCC$ vector
            do i = 1, n
               y(i, l) = y(i, l) + a(i, j)*x(j, l)
            end do
         end do
      end do
   end subroutine mvk

   !> y1 = A x1, y2 = A x2, y3 = A x3 (A n x m) in one pass over A: the same sums, in the same
   !> order, as `mvk` with k = 3 (bit for bit), with A read once for the three products and
   !> the results written straight into the caller's vectors.
   pure subroutine mv3(n, m, a, x1, x2, x3, y1, y2, y3)
      !> Rows and columns of A.
      integer, intent(in) :: n, m
      !> The matrix.
      real(dp), intent(in) :: a(n, m)
      !> The vectors multiplied (m each).
      real(dp), intent(in) :: x1(m), x2(m), x3(m)
      !> The products (n each).
      real(dp), intent(out) :: y1(n), y2(n), y3(n)
      integer :: i, j, m4

      do i = 1, n
         y1(i) = 0.0_dp
         y2(i) = 0.0_dp
         y3(i) = 0.0_dp
      end do
      m4 = m - mod(m, 4)
      do j = 1, m4, 4
         !GCC$ vector
         do i = 1, n
            y1(i) = y1(i) + ((a(i, j)*x1(j) + a(i, j + 1)*x1(j + 1)) + (a(i, j + 2)*x1(j + 2) + a(i, j + 3)*x1(j + 3)))
            y2(i) = y2(i) + ((a(i, j)*x2(j) + a(i, j + 1)*x2(j + 1)) + (a(i, j + 2)*x2(j + 2) + a(i, j + 3)*x2(j + 3)))
            y3(i) = y3(i) + ((a(i, j)*x3(j) + a(i, j + 1)*x3(j + 1)) + (a(i, j + 2)*x3(j + 2) + a(i, j + 3)*x3(j + 3)))
         end do
      end do
      do j = m4 + 1, m
         !GCC$ vector
         do i = 1, n
            y1(i) = y1(i) + a(i, j)*x1(j)
            y2(i) = y2(i) + a(i, j)*x2(j)
            y3(i) = y3(i) + a(i, j)*x3(j)
         end do
      end do
   end subroutine mv3

   !> The least (`lowest`) or largest value over [0, h] of the cubic Hermite path through
   !> (c0, d0) at 0 and (c1, d1) at h (values, rates).
   pure real(dp) function hermite_extreme(c0, d0, c1, d1, h, lowest) result(x)
      !> Values and rates at both ends.
      real(dp), intent(in) :: c0, d0, c1, d1
      !> Length of the interval.
      real(dp), intent(in) :: h
      !> The least value (else the largest).
      logical, intent(in) :: lowest
      real(dp) :: a1, a2, a3, qa, qb, qc, disc, s(2), val
      integer :: i

      a1 = h*d0
      a2 = -3.0_dp*c0 - 2.0_dp*h*d0 + 3.0_dp*c1 - h*d1
      a3 = 2.0_dp*c0 + h*d0 - 2.0_dp*c1 + h*d1
      x = merge(min(c0, c1), max(c0, c1), lowest)
      qa = 3.0_dp*a3
      qb = 2.0_dp*a2
      qc = a1
      s = -1.0_dp
      if (qa /= 0.0_dp) then
         disc = qb*qb - 4.0_dp*qa*qc
         if (disc >= 0.0_dp) s = [(-qb + sqrt(disc))/(2.0_dp*qa), (-qb - sqrt(disc))/(2.0_dp*qa)]
      else if (qb /= 0.0_dp) then
         s(1) = -qc/qb
      end if
      do i = 1, 2
         if (s(i) > 0.0_dp .and. s(i) < 1.0_dp) then
            val = ((a3*s(i) + a2)*s(i) + a1)*s(i) + c0
            x = merge(min(x, val), max(x, val), lowest)
         end if
      end do
   end function hermite_extreme
end module pound_closed_kernels
