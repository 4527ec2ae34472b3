!> The step of the Newmark integrator: `newmark_predict` and `newmark_commit`, with the fused
!> tridiagonal kernels of half-bandwidth 1; the banded path (`predict_general`,
!> `commit_general`) is in pound_newmark_band. The predict kernel is an internal procedure
!> of `newmark_predict` (gfortran gives a submodule's own procedures external linkage, so
!> only internal ones are inlined into their caller).
submodule(pound_newmark) pound_newmark_step
   implicit none

contains

   !> C v, and on the general path (K+G) u and (K+G) v, of the state u, v (band products).
   module subroutine band_state(st, b)
      !> Integrator state.
      type(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b

      call band_symv(b%kt, st%v, st%cv)
      if (.not. st%tridiagonal) then
         st%ktv = st%cv
         call band_symv(b%kt, st%u, st%ktu)
         st%since_refresh = 0
      end if
      st%cv = b%a0*b%mass*st%v + b%a1*st%cv
      st%band_stale = .false.
   end subroutine band_state

   !> Increment du of the step for the ground acceleration increment `dag` alone.
   !>
   !> Tridiagonal path: the right-hand side is formed inside the forward sweep of the
   !> L D L^T solve and the back sweep multiplies by the stored 1/d: two passes over the
   !> floors, no division. General path: the right-hand side, then dpbtrs.
   module subroutine newmark_predict(st, b, dag)
      !> Integrator state; `du` is set.
      class(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration increment a_g(t+dt) - a_g(t) (m/s^2; by value, as the time loop's
      !> other scalars: nothing is stored to be passed).
      real(dp), intent(in), value :: dag

      ! After exact free steps of a model with DOFs without mass (`commit_exact`).
      if (st%band_stale) call band_state(st, b)
      if (st%tridiagonal) then
         call predict_kernel(st%n, 2.0_dp*st%c2, dag, b%mass, st%v, st%a, st%cv, st%e, st%dinv, st%du)
      else
         call predict_general(st, b, dag)
      end if

   contains

      !> du = Khat^{-1} (M (4/dt v + 2 a - 1 dag) + 2 C v) with Khat = L D L^T.
      pure subroutine predict_kernel(n, c4, dag, mass, v, a, cv, e, dinv, du)
         integer, intent(in) :: n
         real(dp), intent(in) :: c4, dag, mass(n), v(n), a(n), cv(n), e(max(n - 1, 1)), dinv(n)
         real(dp), intent(out) :: du(n)
         real(dp) :: y
         integer :: i

         y = mass(1)*(c4*v(1) + 2.0_dp*a(1) - dag) + 2.0_dp*cv(1)
         du(1) = y
         do i = 2, n
            y = mass(i)*(c4*v(i) + 2.0_dp*a(i) - dag) + 2.0_dp*cv(i) - e(i - 1)*y
            du(i) = y
         end do
         du(n) = du(n)*dinv(n)
         do i = n - 1, 1, -1
            du(i) = du(i)*dinv(i) - e(i)*du(i + 1)
         end do
      end subroutine predict_kernel
   end subroutine newmark_predict

   !> `newmark_commit`, then `newmark_predict` of the next step for its ground acceleration
   !> increment `dag_next`: the step of a model without contact loads. The time loop
   !> samples the committed step after this call (u, v and a are the committed ones), so
   !> that the work of sampling overlaps the next step's tridiagonal solve, which is a chain
   !> of dependent operations.
   module subroutine newmark_advance(st, b, ag_old, ag_new, dag_next, w_in, e_out)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration at the start and end of the step, and the increment of the next
      !> step (m/s^2; by value).
      real(dp), intent(in), value :: ag_old, ag_new, dag_next
      !> Input work so far (added to).
      real(dp), intent(inout) :: w_in
      !> Kinetic + strain + damping energy so far (added to).
      real(dp), intent(inout) :: e_out

      call newmark_commit(st, b, ag_old, ag_new, w_in, e_out)
      call newmark_predict(st, b, dag_next)
   end subroutine newmark_advance

   !> Complete the step with the increment `du` and account the energy.
   !>
   !> `ag_old` and `ag_new` are the ground accelerations at the start and end of the step;
   !> the input work increment is du . (p_old + p_new)/2 with p = -M r a_g, the damping
   !> increment du . (C v_old + C v_new)/2: the trapezoidal sums under which the average
   !> acceleration method balances energy exactly for a linear system.
   !>
   !> With `w_in` and `e_out` the integrator's input work and its kinetic + strain + damping
   !> energy are added to them (the per-step audit of the time loop without a call of its
   !> own).
   module subroutine newmark_commit(st, b, ag_old, ag_new, w_in, e_out)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration at the start and end of the step (m/s^2; by value).
      real(dp), intent(in), value :: ag_old, ag_new
      !> Input work so far (added to; optional, with `e_out`).
      real(dp), intent(inout), optional :: w_in
      !> Kinetic + strain + damping energy so far (added to; optional, with `w_in`).
      real(dp), intent(inout), optional :: e_out
      real(dp) :: mdu, ddamp, coef(4), sums(4)

      if (st%pending) then
         call commit_exact(st, w_in, e_out)
         return
      end if
      if (st%tridiagonal) then
         ! The scalars in and out of the kernel in two arrays (fewer arguments to pass).
         coef(1) = st%c1
         coef(2) = st%c2
         coef(3) = b%a0
         coef(4) = b%a1
         call commit_kernel(st%n, coef, b%mass, b%kt, st%du, st%u, st%v, st%a, st%cv, sums)
         mdu = sums(1)
         ddamp = sums(2)
         st%kinetic = sums(3)
         st%strain = sums(4)
      else
         call commit_general(st, b, mdu, ddamp)
      end if
      st%damping_energy = st%damping_energy + 0.5_dp*ddamp
      st%input_work = st%input_work - 0.5_dp*(ag_old + ag_new)*mdu
      if (present(w_in) .and. present(e_out)) then
         w_in = w_in + st%input_work
         e_out = e_out + ((st%kinetic + st%strain) + st%damping_energy)
      end if

   end subroutine newmark_commit

   ! Tridiagonal kernel of the commit (kd = 1). It stays a procedure of its own, called with
   ! explicit-shape arrays: inlined into `newmark_commit`, whose arrays are components of
   ! `st`, the compiler no longer vectorises its blocks of four floors.
   !> Newmark update of u, v, a from du; C v at the new time; sum(m du) and du.(Cv_old + Cv_new);
   !> the kinetic and strain energy at the new time.
   !>
   !> Each sum is kept in four partial sums, element i going to partial sum mod(i, 4), so that
   !> the loops are not bound by the latency of one chain of additions. The loops run over
   !> blocks of four consecutive elements with one accumulator per lane (lane l of a block
   !> starting at i0 holds partial sum mod(i0 + l, 4)), which the compiler can vectorise.
   !>
   !> coef = [c1, c2, a0, a1]; sums = [sum(m du), du.(Cv_old + Cv_new), E_kinetic, E_strain].
   pure subroutine commit_kernel(n, coef, mass, kt, du, u, v, a, cv, sums)
      integer, intent(in) :: n
      real(dp), intent(in) :: coef(4), mass(n), kt(2, n), du(n)
      real(dp), intent(inout) :: u(n), v(n), a(n), cv(n)
      real(dp), intent(out) :: sums(4)
      real(dp) :: c1, c2, a0, a1, mdu, ddamp, ek, es
      real(dp) :: cvi, sm(0:3), sd(0:3), sk(0:3), ss(0:3)
      integer :: i, i0, l, last

      c1 = coef(1)
      c2 = coef(2)
      a0 = coef(3)
      a1 = coef(4)

      ! Lanes of blocks starting at i0 = 1, 5, 9, ...: lane l holds partial sum mod(l + 1, 4).
      sm = 0.0_dp
      sk = 0.0_dp
      do i0 = 1, n - 3, 4
         do l = 0, 3
            i = i0 + l
            call update_floor(c1, c2, mass(i), du(i), u(i), v(i), a(i), sm(l), sk(l))
         end do
      end do
      do i = 4*(n/4) + 1, n
         l = i - 4*(n/4) - 1
         call update_floor(c1, c2, mass(i), du(i), u(i), v(i), a(i), sm(l), sk(l))
      end do
      ! Partial sums 0, 1, 2, 3 are lanes 3, 0, 1, 2.
      mdu = (sm(3) + sm(0)) + (sm(1) + sm(2))
      ek = 0.5_dp*((sk(3) + sk(0)) + (sk(1) + sk(2)))
      ! C v = a0 M v + a1 (K+G) v; (K+G) tridiagonal with kt(1, i) = (K+G)(i-1, i).
      if (n == 1) then
         cvi = (a0*mass(1) + a1*kt(2, 1))*v(1)
         ddamp = du(1)*(cv(1) + cvi)
         cv(1) = cvi
         es = 0.5_dp*kt(2, 1)*u(1)*u(1)
         sums = [mdu, ddamp, ek, es]
         return
      end if
      ! Strain energy sum_j s_j drift_j^2 / 2 with the net storey stiffness s_j = -kt(1, j)
      ! (j >= 2) and s_1 = kt(2, 1) + kt(1, 2). Element 1 is partial sum 1, elements
      ! 2..n-1 run in blocks starting at i0 = 2, 6, ... (lane l: partial sum mod(l + 2, 4)),
      ! element n (and the rest of 2..n-1) one by one.
      sd = 0.0_dp
      ss = 0.0_dp
      cvi = a0*mass(1)*v(1) + a1*(kt(2, 1)*v(1) + kt(1, 2)*v(2))
      sd(3) = du(1)*(cv(1) + cvi)
      ss(3) = -(kt(2, 1) + kt(1, 2))*u(1)*u(1)
      cv(1) = cvi
      last = n - 1
      do i0 = 2, last - 3, 4
         do l = 0, 3
            i = i0 + l
            call damp_floor(a0, a1, mass(i), kt(:, i), kt(1, i + 1), v(i - 1:i + 1), u(i - 1:i), du(i), &
                            cv(i), sd(l), ss(l))
         end do
      end do
      do i = 2 + 4*((last - 1)/4), last
         l = i - 2 - 4*((last - 1)/4)
         call damp_floor(a0, a1, mass(i), kt(:, i), kt(1, i + 1), v(i - 1:i + 1), u(i - 1:i), du(i), &
                         cv(i), sd(l), ss(l))
      end do
      cvi = a0*mass(n)*v(n) + a1*(kt(1, n)*v(n - 1) + kt(2, n)*v(n))
      l = iand(n + 2, 3)
      sd(l) = sd(l) + du(n)*(cv(n) + cvi)
      ss(l) = ss(l) + kt(1, n)*(u(n) - u(n - 1))**2
      cv(n) = cvi
      ! Partial sums 0, 1, 2, 3 are lanes 2, 3, 0, 1.
      ddamp = (sd(2) + sd(3)) + (sd(0) + sd(1))
      es = -0.5_dp*((ss(2) + ss(3)) + (ss(0) + ss(1)))
      sums = [mdu, ddamp, ek, es]
   end subroutine commit_kernel

   !> Newmark update of one floor; its terms of sum(m du) and of 2 E_kinetic.
   pure subroutine update_floor(c1, c2, mass, du, u, v, a, sm, sk)
      real(dp), intent(in) :: c1, c2, mass, du
      real(dp), intent(inout) :: u, v, a, sm, sk

      a = c1*du - 2.0_dp*c2*v - a
      v = c2*du - v
      u = u + du
      sm = sm + mass*du
      sk = sk + mass*v*v
   end subroutine update_floor

   !> C v of an inner floor i (kt_i = kt(:, i), kt_up = kt(1, i+1), v3 = v(i-1:i+1),
   !> u2 = u(i-1:i)); its terms of du.(Cv_old + Cv_new) and of -2 E_strain.
   pure subroutine damp_floor(a0, a1, mass, kt_i, kt_up, v3, u2, du, cv, sd, ss)
      real(dp), intent(in) :: a0, a1, mass, kt_i(2), kt_up, v3(3), u2(2), du
      real(dp), intent(inout) :: cv, sd, ss
      real(dp) :: cvi

      cvi = a0*mass*v3(2) + a1*(kt_i(1)*v3(1) + kt_i(2)*v3(2) + kt_up*v3(3))
      sd = sd + du*(cv + cvi)
      ss = ss + kt_i(1)*(u2(2) - u2(1))**2
      cv = cvi
   end subroutine damp_floor

end submodule pound_newmark_step
