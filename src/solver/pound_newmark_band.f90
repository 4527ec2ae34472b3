!> The banded path of the Newmark step (half-bandwidth > 1, or a ground-influence vector
!> that is not all ones): right-hand side and the banded solve, the update, C v and the energies.
!> A unit of its own, so that it does not change how the tridiagonal step
!> (pound_newmark_step) is compiled.
!>
!> **No band product per step.** With Kt = K+G, fm = c1 + c2 a0 and fk = 1 + c2 a1 the
!> step solves Khat du = r, Khat = fm M + fk Kt, r = M (2 c2 v + 2 a - r_g dag) + 2 C v plus
!> the contact load increments fc (`newmark_add_response` keeps them beside du; the commit
!> forms r again from the state at the start of the step, as the predict did). Hence
!> Kt du = (r - fm M du) / fk exactly: a diagonal operation (a massless DOF simply has
!> Kt du = r / fk). The integrator keeps Kt u and Kt v: Kt u_new = Kt u + Kt du and, since
!> v_new = c2 du - v, Kt v_new = c2 Kt du - Kt v, so C v = a0 M v + a1 Kt v and the strain
!> energy u . Kt u / 2 cost O(n). Every `refresh`-th step takes the two exact band products
!> instead (the formulation before, same numbers): the recursions carry the solve's
!> round-off (the one for Kt v with eigenvalue -1, a random walk), and the refresh bounds
!> it (README, "The banded step without band products").
submodule(pound_newmark) pound_newmark_band
   use pound_band_solve, only: band_solve
   implicit none

contains

   !> The general (banded) path of `newmark_predict`: the right-hand side, then the solve
   !> with the Cholesky factor (`band_solve`, the step's own sweeps in place of dpbtrs).
   module subroutine predict_general(st, b, dag)
      type(newmark_state), intent(inout) :: st
      type(structure_model), intent(in) :: b
      real(dp), intent(in) :: dag

      st%dag = dag
      call rhs_kernel(st%n, 2.0_dp*st%c2, dag, b%mass, b%ground, st%v, st%a, st%cv, st%du)
      call band_solve(st%n, st%kd, st%chol, st%dinv, st%du)
   end subroutine predict_general

   !> The step's right-hand side r = m (c4 v + 2 a - r_g dag) + 2 C v (c4 = 2 c2) on
   !> explicit-shape arrays (one vectorised pass).
   pure subroutine rhs_kernel(n, c4, dag, mass, ground, v, a, cv, r)
      integer, intent(in) :: n
      real(dp), intent(in) :: c4, dag, mass(n), ground(n), v(n), a(n), cv(n)
      real(dp), intent(out) :: r(n)
      integer :: i

      do i = 1, n
         r(i) = mass(i)*(c4*v(i) + 2.0_dp*a(i) - ground(i)*dag) + 2.0_dp*cv(i)
      end do
   end subroutine rhs_kernel

   !> The general (banded) path of `newmark_commit`: the Newmark update, Kt u, Kt v and
   !> C v (derived, or by band products on a refresh step), sum(m r du), du.(Cv_old + Cv_new)
   !> and the kinetic and strain energy.
   module subroutine commit_general(st, b, mdu, ddamp)
      type(newmark_state), intent(inout) :: st
      type(structure_model), intent(in) :: b
      real(dp), intent(out) :: mdu, ddamp
      real(dp) :: es, coef(8)

      st%since_refresh = st%since_refresh + 1
      if (st%since_refresh >= st%refresh) then
         st%since_refresh = 0
         st%a = st%c1*st%du - 2.0_dp*st%c2*st%v - st%a
         st%v = st%c2*st%du - st%v
         st%u = st%u + st%du
         mdu = sum(b%mass*b%ground*st%du)
         call band_symv(b%kt, st%v, st%ktv)
         st%work = b%a0*b%mass*st%v + b%a1*st%ktv
         ddamp = dot_product(st%du, st%cv + st%work)
         st%cv = st%work
         call band_symv(b%kt, st%u, st%ktu)
         es = 0.5_dp*dot_product(st%u, st%ktu)
         st%kinetic = 0.5_dp*sum(b%mass*st%v**2)
      else
         ! c1, c2, a0, a1, fm = c1 + c2 a0, 1/fk = 1/(1 + c2 a1), dag, 2 c2.
         coef = [st%c1, st%c2, b%a0, b%a1, st%c1 + st%c2*b%a0, 1.0_dp/(1.0_dp + st%c2*b%a1), st%dag, &
                 2.0_dp*st%c2]
         call derived_kernel(st%n, coef, b%mass, b%ground, st%fc, st%du, st%u, st%v, st%a, st%ktu, st%ktv, st%cv, &
                             mdu, ddamp, st%kinetic, es)
      end if
      if (st%loaded) then
         st%fc = 0.0_dp
         st%loaded = .false.
      end if
      if (allocated(b%strain_weight)) then
         st%strain = structure_strain_energy(b, st%u)
      else
         st%strain = es
      end if
   end subroutine commit_general

   !> The derived step in one pass over the DOFs: the step's right-hand side r from the state
   !> at the start (as `predict_general` formed it) plus the load increments fc,
   !> Kt du = (r - fm m du)/fk, the Newmark update of u, v, a, Kt u, Kt v and C v, and the sums
   !> sum(m r du), du.(Cv_old + Cv_new), v.M v/2 and u.Kt u/2 (coef: c1, c2, a0, a1, fm,
   !> 1/fk, dag, 2 c2). Each sum is kept in four partial sums (element i in partial sum
   !> mod(i - 1, 4), summed (0 + 1) + (2 + 3)); the blocks of four are vectorised, the last
   !> n mod 4 DOFs go through the same block code padded with zeros (which add nothing).
   pure subroutine derived_kernel(n, coef, mass, ground, fc, du, u, v, a, ktu, ktv, cv, mdu, ddamp, ek, es)
      integer, intent(in) :: n
      real(dp), intent(in) :: coef(8), mass(n), ground(n), fc(n), du(n)
      real(dp), intent(inout) :: u(n), v(n), a(n), ktu(n), ktv(n), cv(n)
      real(dp), intent(out) :: mdu, ddamp, ek, es
      real(dp) :: sums(0:3, 4), t(4, 10)
      integer :: n4, r

      sums = 0.0_dp
      n4 = 4*(n/4)
      call derived_blocks(n4, n, coef, mass, ground, fc, du, u, v, a, ktu, ktv, cv, sums)
      r = n - n4
      if (r > 0) then
         t = 0.0_dp
         t(1:r, 1) = mass(n4 + 1:n)
         t(1:r, 2) = ground(n4 + 1:n)
         t(1:r, 3) = fc(n4 + 1:n)
         t(1:r, 4) = du(n4 + 1:n)
         t(1:r, 5) = u(n4 + 1:n)
         t(1:r, 6) = v(n4 + 1:n)
         t(1:r, 7) = a(n4 + 1:n)
         t(1:r, 8) = ktu(n4 + 1:n)
         t(1:r, 9) = ktv(n4 + 1:n)
         t(1:r, 10) = cv(n4 + 1:n)
         call derived_blocks(4, 4, coef, t(:, 1), t(:, 2), t(:, 3), t(:, 4), t(:, 5), t(:, 6), t(:, 7), &
                             t(:, 8), t(:, 9), t(:, 10), sums)
         u(n4 + 1:n) = t(1:r, 5)
         v(n4 + 1:n) = t(1:r, 6)
         a(n4 + 1:n) = t(1:r, 7)
         ktu(n4 + 1:n) = t(1:r, 8)
         ktv(n4 + 1:n) = t(1:r, 9)
         cv(n4 + 1:n) = t(1:r, 10)
      end if
      mdu = (sums(0, 1) + sums(1, 1)) + (sums(2, 1) + sums(3, 1))
      ddamp = (sums(0, 2) + sums(1, 2)) + (sums(2, 2) + sums(3, 2))
      ek = 0.5_dp*((sums(0, 3) + sums(1, 3)) + (sums(2, 3) + sums(3, 3)))
      es = 0.5_dp*((sums(0, 4) + sums(1, 4)) + (sums(2, 4) + sums(3, 4)))
   end subroutine derived_kernel

   !> `derived_kernel` on DOFs 1..nb (nb a multiple of 4) of arrays of n; adds to the partial
   !> sums (lane, [m r du, du.(Cv_old + Cv_new), m v^2, u Kt u]).
   pure subroutine derived_blocks(nb, n, coef, mass, ground, fc, du, u, v, a, ktu, ktv, cv, sums)
      integer, intent(in) :: nb, n
      real(dp), intent(in) :: coef(8), mass(n), ground(n), fc(n), du(n)
      real(dp), intent(inout) :: u(n), v(n), a(n), ktu(n), ktv(n), cv(n), sums(0:3, 4)
      real(dp) :: sm(0:3), sd(0:3), sk(0:3), ss(0:3), c1, c2, a0, a1, fm, rfk, dag, c4, kdu, cvn
      integer :: i, i0, l

      c1 = coef(1)
      c2 = coef(2)
      a0 = coef(3)
      a1 = coef(4)
      fm = coef(5)
      rfk = coef(6)
      dag = coef(7)
      c4 = coef(8)
      sm = sums(:, 1)
      sd = sums(:, 2)
      sk = sums(:, 3)
      ss = sums(:, 4)
      do i0 = 1, nb - 3, 4
         do l = 0, 3
            i = i0 + l
            kdu = (mass(i)*(c4*v(i) + 2.0_dp*a(i) - ground(i)*dag) + 2.0_dp*cv(i) + fc(i) - fm*mass(i)*du(i))*rfk
            a(i) = c1*du(i) - 2.0_dp*c2*v(i) - a(i)
            v(i) = c2*du(i) - v(i)
            u(i) = u(i) + du(i)
            ktu(i) = ktu(i) + kdu
            ktv(i) = c2*kdu - ktv(i)
            cvn = a0*mass(i)*v(i) + a1*ktv(i)
            sd(l) = sd(l) + du(i)*(cv(i) + cvn)
            cv(i) = cvn
            sm(l) = sm(l) + mass(i)*ground(i)*du(i)
            sk(l) = sk(l) + mass(i)*v(i)*v(i)
            ss(l) = ss(l) + u(i)*ktu(i)
         end do
      end do
      sums(:, 1) = sm
      sums(:, 2) = sd
      sums(:, 3) = sk
      sums(:, 4) = ss
   end subroutine derived_blocks

end submodule pound_newmark_band
