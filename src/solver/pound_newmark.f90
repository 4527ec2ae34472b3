!> Newmark average-acceleration integration of one shear building, incremental form.
!>
!> With c1 = 4/dt^2 and c2 = 2/dt the effective stiffness
!> Khat = (K+G) + c1 M + c2 C, C = a0 M + a1 (K+G), is tridiagonal, symmetric and positive
!> definite; it is factored once (LAPACK dpttrf, the tridiagonal L D L^T form of the banded
!> Cholesky) and each step costs one dpttrs solve and one tridiagonal product.
!>
!> A step is split so that contact forces can be added between the two halves:
!> `newmark_predict` computes the increment du for the ground motion alone,
!> the caller may add Khat^{-1} times further load increments to `du`, and
!> `newmark_commit` updates u, v, a and the energy accumulators.
!> Equation of motion, relative to the ground: M a + C v + (K+G) u = -M 1 a_g + f_ext.
module pound_newmark
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_shear_building, only: shear_building, building_label
   implicit none
   private

   public :: newmark_state, newmark_init, newmark_predict, newmark_commit, newmark_solve
   public :: kinetic_energy, strain_energy

   !> Integrator state of one building.
   type :: newmark_state
      !> Number of floors.
      integer :: n = 0
      !> Time step and Newmark constants c1 = 4/dt^2, c2 = 2/dt.
      real(dp) :: dt = 0.0_dp, c1 = 0.0_dp, c2 = 0.0_dp
      !> L D L^T factors of Khat: diagonal d (n) and sub-diagonal e (n-1), and 1/d.
      real(dp), allocatable :: d(:), e(:), dinv(:)
      !> Relative displacement, velocity and acceleration at the current time.
      real(dp), allocatable :: u(:), v(:), a(:)
      !> Displacement increment of the step in progress.
      real(dp), allocatable :: du(:)
      !> Damping force C v at the current time.
      real(dp), allocatable :: cv(:)
      !> Work done by the ground motion (effective loads -M 1 a_g) on the relative motion (kJ).
      real(dp) :: input_work = 0.0_dp
      !> Energy dissipated by viscous damping (kJ).
      real(dp) :: damping_energy = 0.0_dp
      !> Kinetic and strain energy at the current time (kJ), summed in the fused update of
      !> `newmark_commit` for the energy audit of every step (they agree with
      !> `kinetic_energy` and `strain_energy` to round-off).
      real(dp) :: kinetic = 0.0_dp, strain = 0.0_dp
   end type newmark_state

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

   !> Factor Khat and start at rest relative to the ground, in equilibrium with the
   !> ground acceleration at t = 0: u = v = 0, M a = -M 1 a_g(0), so a = -a_g(0).
   subroutine newmark_init(st, b, dt, ag0, error)
      !> Integrator state.
      type(newmark_state), intent(out) :: st
      !> The building.
      type(shear_building), intent(in) :: b
      !> Time step (s).
      real(dp), intent(in) :: dt
      !> Ground acceleration at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: fk, fm
      integer :: n, info, i, stat
      character(len=:), allocatable :: sources

      n = b%n
      st%n = n
      st%dt = dt
      st%c1 = 4.0_dp/dt**2
      st%c2 = 2.0_dp/dt
      fk = 1.0_dp + st%c2*b%a1
      fm = st%c1 + st%c2*b%a0
      sources = ' from dt = '//str(dt)//' s, the masses, the storey stiffnesses and the damping (a0 = '// &
                str(b%a0)//', a1 = '//str(b%a1)//')'
      if (.not. (ieee_is_finite(fk) .and. ieee_is_finite(fm))) then
         call fatal_error(error, building_label(b)//': Newmark coefficients 1 + 2 a1/dt = '//str(fk)// &
                          ' and 4/dt^2 + 2 a0/dt = '//str(fm)//sources//' are not finite')
         return
      end if
      allocate (st%d(n), st%e(max(n - 1, 1)), st%u(n), st%v(n), st%a(n), st%du(n), st%cv(n), stat=stat)
      if (stat /= 0) then
         call fatal_error(error, building_label(b)//': cannot allocate the integrator state ('// &
                          str(7*n)//' reals; n_storeys = '//str(n)//')')
         return
      end if
      st%d = fk*b%kt(2, :) + fm*b%mass
      st%e = 0.0_dp
      if (n > 1) st%e(1:n - 1) = fk*b%kt(1, 2:n)
      do i = 1, n
         if (.not. (ieee_is_finite(st%d(i)) .and. ieee_is_finite(st%e(min(i, size(st%e)))))) then
            call fatal_error(error, building_label(b)//': floor '//str(i)//': effective stiffness Khat = '// &
                             '(K+G)(1 + 2 a1/dt) + M (4/dt^2 + 2 a0/dt)'//sources//' is not finite')
            return
         end if
      end do
      call dpttrf(n, st%d, st%e, info)
      if (info /= 0) then
         call fatal_error(error, building_label(b)//': effective stiffness not positive definite '// &
                          '(dpttrf info = '//str(info)//')'//sources)
         return
      end if
      st%dinv = 1.0_dp/st%d
      do i = 1, n
         if (.not. (ieee_is_finite(st%d(i)) .and. ieee_is_finite(st%dinv(i)) .and. &
                    ieee_is_finite(st%e(min(i, size(st%e)))))) then
            call fatal_error(error, building_label(b)//': floor '//str(i)//': factorization of the '// &
                             'effective stiffness Khat out of range (pivot '//str(st%d(i))//')'//sources)
            return
         end if
      end do
      st%u = 0.0_dp
      st%v = 0.0_dp
      st%a = -ag0
      st%du = 0.0_dp
      st%cv = 0.0_dp
      st%input_work = 0.0_dp
      st%damping_energy = 0.0_dp
      st%kinetic = 0.5_dp*sum(b%mass*st%v**2)
      st%strain = 0.0_dp
   end subroutine newmark_init

   !> Increment du of the step for the ground acceleration increment `dag` alone.
   !>
   !> The right-hand side is formed inside the forward sweep of the L D L^T solve and the
   !> back sweep multiplies by the stored 1/d: two passes over the floors, no division.
   subroutine newmark_predict(st, b, dag)
      !> Integrator state; `du` is set.
      type(newmark_state), intent(inout) :: st
      !> The building.
      type(shear_building), intent(in) :: b
      !> Ground acceleration increment a_g(t+dt) - a_g(t) (m/s^2).
      real(dp), intent(in) :: dag

      call predict_kernel(st%n, 2.0_dp*st%c2, dag, b%mass, st%v, st%a, st%cv, st%e, st%dinv, st%du)
   end subroutine newmark_predict

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

   !> Overwrite x with Khat^{-1} x (one tridiagonal solve).
   subroutine newmark_solve(st, x)
      !> Integrator state (factors).
      type(newmark_state), intent(in) :: st
      !> Right-hand side on entry, solution on return.
      real(dp), intent(inout) :: x(:)
      integer :: info

      call dpttrs(st%n, 1, st%d, st%e, x, st%n, info)
   end subroutine newmark_solve

   !> Complete the step with the increment `du` and account the energy.
   !>
   !> `ag_old` and `ag_new` are the ground accelerations at the start and end of the step;
   !> the input work increment is du . (p_old + p_new)/2 with p = -M 1 a_g, the damping
   !> increment du . (C v_old + C v_new)/2: the trapezoidal sums under which the average
   !> acceleration method balances energy exactly for a linear system.
   subroutine newmark_commit(st, b, ag_old, ag_new)
      !> Integrator state.
      type(newmark_state), intent(inout) :: st
      !> The building.
      type(shear_building), intent(in) :: b
      !> Ground acceleration at the start and end of the step (m/s^2).
      real(dp), intent(in) :: ag_old, ag_new
      real(dp) :: mdu, ddamp

      call commit_kernel(st%n, st%c1, st%c2, b%a0, b%a1, b%mass, b%kt, st%du, st%u, st%v, st%a, &
                         st%cv, mdu, ddamp, st%kinetic, st%strain)
      st%damping_energy = st%damping_energy + 0.5_dp*ddamp
      st%input_work = st%input_work - 0.5_dp*(ag_old + ag_new)*mdu
   end subroutine newmark_commit

   !> Newmark update of u, v, a from du; C v at the new time; sum(m du) and du.(Cv_old + Cv_new);
   !> the kinetic and strain energy at the new time.
   !>
   !> Each sum is kept in four partial sums, element i going to partial sum mod(i, 4), so that
   !> the loops are not bound by the latency of one chain of additions. The loops run over
   !> blocks of four consecutive elements with one accumulator per lane (lane l of a block
   !> starting at i0 holds partial sum mod(i0 + l, 4)), which the compiler can vectorise.
   pure subroutine commit_kernel(n, c1, c2, a0, a1, mass, kt, du, u, v, a, cv, mdu, ddamp, ek, es)
      integer, intent(in) :: n
      real(dp), intent(in) :: c1, c2, a0, a1, mass(n), kt(2, n), du(n)
      real(dp), intent(inout) :: u(n), v(n), a(n), cv(n)
      real(dp), intent(out) :: mdu, ddamp, ek, es
      real(dp) :: cvi, sm(0:3), sd(0:3), sk(0:3), ss(0:3)
      integer :: i, i0, l, last

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

   !> Kinetic energy of the relative motion, v^T M v / 2 (kJ).
   pure function kinetic_energy(st, b) result(e)
      !> Integrator state.
      type(newmark_state), intent(in) :: st
      !> The building.
      type(shear_building), intent(in) :: b
      real(dp) :: e

      e = 0.5_dp*sum(b%mass*st%v**2)
   end function kinetic_energy

   !> Strain energy including the geometric term, u^T (K+G) u / 2 (kJ).
   pure function strain_energy(st, b) result(e)
      !> Integrator state.
      type(newmark_state), intent(in) :: st
      !> The building.
      type(shear_building), intent(in) :: b
      real(dp) :: e, drift
      integer :: j

      e = 0.0_dp
      do j = 1, st%n
         if (j == 1) then
            drift = st%u(1)
         else
            drift = st%u(j) - st%u(j - 1)
         end if
         e = e + 0.5_dp*(b%storey_stiffness(j) - b%geometric_stiffness(j))*drift**2
      end do
   end function strain_energy

end module pound_newmark
