!> The exact step of one mode of a linear structure under a ground acceleration that varies
!> linearly over the step (`&analysis free_steps = 'exact'`).
!>
!> A mode (mass-normalised shape phi, eigenvalue lambda = omega^2 of (K+G, M), modal damping
!> c = a0 + a1 lambda of the Rayleigh damping, participation Gamma = phi^T M r) obeys
!> q'' + c q' + lambda q = -Gamma a_g(t). Over a step of length h with a_g linear from a_g0 to
!> a_g1, the state y = (q, q', a_g, s), s = (a_g1 - a_g0)/h, obeys y' = A y with a constant
!> 4 x 4 matrix A, so y(h) = exp(A h) y(0) exactly, for any sign of lambda and any damping
!> (under-, critically or over-damped). In the variables x = (q0, q0', a_g0, a_g1):
!>
!>     q1 = coef(1:4) . x,   q1' = coef(5:8) . x,
!>
!> and the energies of the step are quadratic forms in x (Van Loan's block exponential for
!> the integrals int_0^h y^T Q y dt over a short step, doubled up to h): the input work -Gamma int q' a_g dt = x^T wi x and the
!> damping energy c int q'^2 dt = x^T wd x. Everything is computed once per mode and step
!> size; a step then costs a few multiply-adds per mode.
module pound_modal_step
   use pound_kinds, only: dp
   use pound_expm, only: expm
   implicit none
   private

   public :: modal_step_coefficients, modal_step_response

contains

   !> The step coefficients of one mode (see the module doc).
   pure subroutine modal_step_coefficients(lambda, c, gamma, h, coef, wi, wd)
      !> Eigenvalue omega^2 (1/s^2; any sign), modal damping c = a0 + a1 lambda (1/s),
      !> participation Gamma, step h (s, > 0).
      real(dp), intent(in) :: lambda, c, gamma, h
      !> q1 = coef(1:4) . x and q1' = coef(5:8) . x, x = (q0, q0', a_g0, a_g1).
      real(dp), intent(out) :: coef(8)
      !> Input work and damping energy of the step: x^T wi x, x^T wd x.
      real(dp), intent(out) :: wi(4, 4), wd(4, 4)
      real(dp) :: a(4, 4), t(4, 4), q(4, 4)

      call step_system(lambda, c, gamma, h, a, t)
      coef = modal_step_response(lambda, c, gamma, h)
      q = 0.0_dp
      q(2, 3) = -0.5_dp*gamma
      q(3, 2) = -0.5_dp*gamma
      wi = integral_form(a, q, h, t)
      q = 0.0_dp
      q(2, 2) = c
      wd = integral_form(a, q, h, t)
   end subroutine modal_step_coefficients

   !> The step coefficients alone (`coef` of `modal_step_coefficients`): q1 = coef(1:4) . x
   !> and q1' = coef(5:8) . x, x = (q0, q0', a_g0, a_g1); with gamma = -1, x = (q0, q0', p0,
   !> p1) for a modal load p linear over the step.
   pure function modal_step_response(lambda, c, gamma, h) result(coef)
      !> As `modal_step_coefficients`.
      real(dp), intent(in) :: lambda, c, gamma, h
      real(dp) :: coef(8)
      real(dp) :: a(4, 4), t(4, 4), pt(4, 4)

      call step_system(lambda, c, gamma, h, a, t)
      pt = matmul(expm(a*h), t)
      coef(1:4) = pt(1, :)
      coef(5:8) = pt(2, :)
   end function modal_step_response

   !> The mode's first-order system y' = A y, y = (q, q', a_g, s), and y0 = t x.
   pure subroutine step_system(lambda, c, gamma, h, a, t)
      real(dp), intent(in) :: lambda, c, gamma, h
      real(dp), intent(out) :: a(4, 4), t(4, 4)

      a = 0.0_dp
      a(1, 2) = 1.0_dp
      a(2, 1) = -lambda
      a(2, 2) = -c
      a(2, 3) = -gamma
      a(3, 4) = 1.0_dp
      ! y0 = t x: s = (a_g1 - a_g0)/h.
      t = 0.0_dp
      t(1, 1) = 1.0_dp
      t(2, 2) = 1.0_dp
      t(3, 3) = 1.0_dp
      t(4, 3) = -1.0_dp/h
      t(4, 4) = 1.0_dp/h
   end subroutine step_system

   !> t^T (int_0^h exp(A^T s) Q exp(A s) ds) t, symmetrised. The integral over h/2^k, with
   !> |A| h/2^k <= 1/2, is the exponential of the block matrix [[-A^T, Q], [0, A]] h/2^k (Van
   !> Loan); it is then doubled k times, W(2 s) = W(s) + exp(A s)^T W(s) exp(A s), which never
   !> forms exp(-A^T h): that factor grows as exp(c h) for a strongly damped mode and would
   !> leave W to the cancellation of huge terms.
   pure function integral_form(a, q, h, t) result(w)
      real(dp), intent(in) :: a(4, 4), q(4, 4), h, t(4, 4)
      real(dp) :: w(4, 4)
      real(dp) :: big(8, 8), e(8, 8), p(4, 4), h0, nrm
      integer :: k, halvings

      nrm = maxval(sum(abs(a), dim=1))*h
      halvings = 0
      if (nrm > 0.5_dp) halvings = ceiling(log(nrm/0.5_dp)/log(2.0_dp))
      h0 = h/2.0_dp**halvings
      big = 0.0_dp
      big(1:4, 1:4) = -transpose(a)
      big(1:4, 5:8) = q
      big(5:8, 5:8) = a
      e = expm(big*h0)
      p = e(5:8, 5:8)
      w = matmul(transpose(p), e(1:4, 5:8))
      do k = 1, halvings
         w = w + matmul(transpose(p), matmul(w, p))
         p = matmul(p, p)
      end do
      w = matmul(transpose(t), matmul(w, t))
      w = 0.5_dp*(w + transpose(w))
   end function integral_form

end module pound_modal_step
