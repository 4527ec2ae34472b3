!> HHT-alpha (Hilber, Hughes and Taylor 1977) for one structural model, any half-bandwidth:
!> the second extension of `integrator`.
!>
!>   M a_{n+1} + (1+alpha)(C v_{n+1} + K u_{n+1}) - alpha (C v_n + K u_n)
!>        = (1+alpha) F_{n+1} - alpha F_n,     F = -M r a_g + f (f: the contact loads),
!>
!> with Newmark's kinematics for beta = (1-alpha)^2/4, gamma = (1-2 alpha)/2 and
!> -1/3 <= alpha <= 0 (alpha = 0: average acceleration, which `pound_integrators` runs as
!> `newmark_state`). With du = u_{n+1} - u_n,
!>
!>   a_{n+1} = c0 du + a*,  a* = -v_n/(beta dt) - (1/(2 beta) - 1) a_n,   c0 = 1/(beta dt^2)
!>   v_{n+1} = c1 du + v*,  v* = (1 - gamma/beta) v_n + dt (1 - gamma/(2 beta)) a_n,   c1 = gamma/(beta dt)
!>   Khat du = F_n + (1+alpha)(F_{n+1} - F_n) - M a* - (1+alpha) C v* - K u_n + alpha C v_n,
!>   Khat = c0 M + (1+alpha)(c1 C + K).
!>
!> **Contact loads.** A load increment s along w within the step (`add_load`) enters F_{n+1}
!> with the weight 1+alpha: du += s (1+alpha) Khat^{-1} w. `solve` returns (1+alpha) Khat^{-1} x,
!> so the contact system's condensed flexibility F = B^T (1+alpha) Khat^{-1} B and its columns
!> are the response of du to the joint forces at t_{n+1}, and contact needs no other change.
!> The integrator keeps the contact loads f_n (the sum of the increments) for F_n. The
!> closing path inside the step (`path`) is the parabola through u_n with slope v_n that ends
!> at u_n + du; the joints' compression rate keeps the trapezoidal rule (`velocity_rate` =
!> 2/dt: a joint's rate is its own variable).
!>
!> **Other ground components.** A ground component the caller takes as load rows (along y:
!> -M r_y a_gy, `add_load_rows` with its increments) is a load of F like the contact loads, so
!> it enters F_{n+1} with the weight 1+alpha and F_n exactly as -M r_x a_gx does: its value
!> at t = 0 is put in f_0 (`start_load`) and its trapezoid work added to the input work
!> (`add_input_work`).
!>
!> **Energy.** With e_n = M a_n + C v_n + K u_n - F_n (the force HHT leaves unbalanced at
!> t_n; e_0 = 0) the averaged equation M a_avg + C v_avg + K u_avg = F_avg + e_avg and the
!> kinematics give, exactly, per step
!>   W_input + W_contact = dE_kinetic + dE_strain + dE_damping + dD,
!>   dD = -du.e_avg - dt (gamma - 1/2) v_avg.M (a_{n+1} - a_n)
!>        + dt^2 (beta - gamma/2) (a_{n+1} - a_n).M a_avg,
!> the numerical dissipation of the step, computed from that formula (not as a remainder),
!> so the energy audit is a check of the step. For alpha = 0 every term of dD is zero.
module pound_hht
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_band, only: band_symv
   use pound_band_lapack, only: dpbtrf, dpbtrs, dpttrf, dpttrs
   use pound_swap, only: swap
   use pound_structure, only: structure_model, structure_label, structure_strain_energy
   use pound_integrator, only: integrator, integrator_properties, trapezoid_rate, n_integrator_energies, &
                               default_start_load
   implicit none
   private

   public :: hht_state, hht_new, hht_alpha_min, hht_alpha_max

   !> The range of alpha.
   real(dp), parameter :: hht_alpha_min = -1.0_dp/3.0_dp, hht_alpha_max = 0.0_dp

   !> HHT-alpha state of one model (components private).
   type, extends(integrator) :: hht_state
      private
      !> alpha, beta, gamma; time step; c0 = 1/(beta dt^2), c1 = gamma/(beta dt).
      real(dp) :: alpha = -0.05_dp, beta = 0.0_dp, gamma = 0.0_dp, dt = 0.0_dp, c0 = 0.0_dp, c1 = 0.0_dp
      !> a* = -ca v_n - cb a_n, v* = cc v_n + cd a_n: ca = 1/(beta dt), cb = 1/(2 beta) - 1,
      !> cc = 1 - gamma/beta, cd = dt (1 - gamma/(2 beta)) (held with dt, swapped with it).
      real(dp) :: ca = 0.0_dp, cb = 0.0_dp, cc = 0.0_dp, cd = 0.0_dp
      !> Number of DOFs and half-bandwidth.
      integer :: n = 0, kd = 0
      !> Cholesky factor of Khat (kd+1, n); half-bandwidth 1 (`tri`): its L D L^T factors
      !> (dpttrf: diagonal td, sub-diagonal te) and the fused one-pass kernels instead.
      real(dp), allocatable :: chol(:, :), td(:), te(:)
      logical :: tri = .false.
      !> State at t_n: u, v, a; (K+G) u, (K+G) v, C v; the contact loads f_n; the unbalanced
      !> force e_n; the step's increment du and load increment df; work vectors.
      real(dp), allocatable :: u(:), v(:), a(:), ku(:), kv(:), cv(:), f(:), e(:), du(:), df(:), w1(:), w2(:)
      !> Ground acceleration at t_n (m/s^2).
      real(dp) :: ag = 0.0_dp
      !> Input work of the ground, kinetic, strain, damping energy, numerical dissipation (kJ).
      real(dp) :: input_work = 0.0_dp, kinetic = 0.0_dp, strain = 0.0_dp, damping_energy = 0.0_dp
      real(dp) :: numerical = 0.0_dp
   contains
      procedure :: properties => hht_properties
      procedure :: init => hht_init
      procedure :: predict => hht_predict
      procedure :: predict_exact => hht_predict_exact
      procedure :: drop_exact => hht_drop_exact
      procedure :: hold => hht_hold
      procedure :: commit => hht_commit
      procedure :: advance => hht_advance
      procedure :: solve => hht_solve
      procedure :: solve_matrix => hht_solve_matrix
      procedure :: add_load => hht_add_load
      procedure :: add_load_rows => hht_add_load_rows
      procedure :: swap_step => hht_swap_step
      procedure :: set_state => hht_set_state
      procedure :: dofs => hht_dofs
      procedure :: step_size => hht_step_size
      procedure :: velocity_rate => hht_velocity_rate
      procedure :: path_span => hht_step_size
      procedure :: path => hht_path
      procedure :: u_view => hht_u_view
      procedure :: v_view => hht_v_view
      procedure :: a_view => hht_a_view
      procedure :: du_view => hht_du_view
      procedure :: u_at => hht_u_at
      procedure :: v_at => hht_v_at
      procedure :: predicted => hht_predicted
      procedure :: energies => hht_energies
      procedure :: add_energies => hht_add_energies
      procedure :: kinetic_energy => hht_kinetic_energy
      procedure :: strain_energy => hht_strain_energy
      procedure :: add_input_work => hht_add_input_work
      procedure :: start_load => hht_start_load
      procedure :: take_settings => hht_take_settings
   end type hht_state

contains

   !> An HHT-alpha integrator with the given alpha (not yet set up: `init`).
   pure function hht_new(alpha) result(st)
      !> alpha in [-1/3, 0].
      real(dp), intent(in) :: alpha
      type(hht_state) :: st

      st%alpha = alpha
   end function hht_new

   !> HHT-alpha's setting is alpha: taken from another HHT-alpha integrator.
   pure subroutine hht_take_settings(st, other)
      !> Integrator (not yet set up).
      class(hht_state), intent(inout) :: st
      !> The integrator whose alpha it takes.
      class(integrator), intent(in) :: other

      select type (other)
      class is (hht_state)
         st%alpha = other%alpha
      end select
   end subroutine hht_take_settings

   !> HHT-alpha: no exact free steps, no lanes; it dissipates when alpha < 0.
   pure function hht_properties(st) result(p)
      !> Integrator.
      class(hht_state), intent(in) :: st
      type(integrator_properties) :: p

      p = integrator_properties(name='HHT-alpha', average_acceleration=st%alpha == 0.0_dp, exact_steps=.false., &
                                lanes=.false., dissipates=st%alpha /= 0.0_dp)
   end function hht_properties

   !> Factor Khat for dt and start at rest relative to the ground, a = -r a_g(0) (e_0 = 0).
   subroutine hht_init(st, b, dt, ag0, error, general, refresh, exact)
      !> Integrator (its alpha set).
      class(hht_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Time step (s) and ground acceleration at t = 0 (m/s^2).
      real(dp), intent(in) :: dt, ag0
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Not used (one path for every bandwidth).
      logical, intent(in), optional :: general
      !> Not used.
      integer, intent(in), optional :: refresh
      !> Exact free steps: refused (they are Newmark's).
      logical, intent(in), optional :: exact
      real(dp) :: fk, fm, alpha
      integer :: n, kd, info, i

      if (present(exact)) then
         if (exact) then
            call fatal_error(error, structure_label(b)//': exact free steps are Newmark''s, not HHT-alpha''s')
            return
         end if
      end if
      if (present(general) .or. present(refresh)) continue
      alpha = st%alpha
      if (.not. (alpha >= hht_alpha_min .and. alpha <= hht_alpha_max)) then
         call fatal_error(error, 'HHT-alpha: alpha = '//str(alpha)//' outside [-1/3, 0]')
         return
      end if
      n = b%n
      kd = b%kd
      st%n = n
      st%kd = kd
      st%beta = (1.0_dp - alpha)**2/4.0_dp
      st%gamma = 0.5_dp - alpha
      st%dt = dt
      st%c0 = 1.0_dp/(st%beta*dt**2)
      st%c1 = st%gamma/(st%beta*dt)
      call kinematic_constants(st)
      fk = (1.0_dp + alpha)*(1.0_dp + st%c1*b%a1)
      fm = st%c0 + (1.0_dp + alpha)*st%c1*b%a0
      st%chol = fk*b%kt
      st%chol(kd + 1, :) = st%chol(kd + 1, :) + fm*b%mass
      if (.not. all(ieee_is_finite(st%chol))) then
         call fatal_error(error, structure_label(b)//': HHT-alpha effective stiffness from dt = '//str(dt)// &
                          ' s is not finite')
         return
      end if
      st%tri = kd == 1
      if (st%tri) then
         st%td = st%chol(2, :)
         allocate (st%te(max(n - 1, 1)), source=0.0_dp)
         if (n > 1) st%te = st%chol(1, 2:n)
         call dpttrf(n, st%td, st%te, info)
         ! (The pivots' check below reads the diagonal of a Cholesky factor.)
         if (info == 0) st%chol(2, :) = sqrt(st%td)
      else
         call dpbtrf('U', n, kd, st%chol, kd + 1, info)
      end if
      if (info /= 0) then
         call fatal_error(error, structure_label(b)//': HHT-alpha effective stiffness not positive definite '// &
                          '(dpbtrf info = '//str(info)//')')
         return
      end if
      do i = 1, n
         if (.not. (st%chol(kd + 1, i) > 0.0_dp .and. ieee_is_finite(1.0_dp/st%chol(kd + 1, i)))) then
            call fatal_error(error, structure_label(b)//': DOF '//str(i)//': factorization of the HHT-alpha '// &
                             'effective stiffness out of range')
            return
         end if
      end do
      allocate (st%u(n), st%v(n), st%ku(n), st%kv(n), st%cv(n), st%f(n), st%e(n), st%du(n), st%df(n), &
                st%w1(n), st%w2(n), source=0.0_dp)
      st%a = -ag0*b%ground
      st%ag = ag0
      st%input_work = 0.0_dp
      st%kinetic = 0.0_dp
      st%strain = 0.0_dp
      st%damping_energy = 0.0_dp
      st%numerical = 0.0_dp
   end subroutine hht_init

   !> du for the ground acceleration increment `dag` (contact loads held at f_n).
   subroutine hht_predict(st, b, dag)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration increment of the step (m/s^2).
      real(dp), intent(in), value :: dag
      real(dp) :: ap, vp, alpha
      integer :: i

      if (st%tri) then
         call predict_tri(st, b, dag)
         return
      end if
      alpha = st%alpha
      ! w1 = v*, then C v* = a0 M v* + a1 (K+G) v* (w2 = (K+G) v*).
      do i = 1, st%n
         st%w1(i) = st%cc*st%v(i) + st%cd*st%a(i)
      end do
      call band_symv(b%kt, st%w1, st%w2)
      do i = 1, st%n
         ap = -st%ca*st%v(i) - st%cb*st%a(i)
         vp = b%a0*b%mass(i)*st%w1(i) + b%a1*st%w2(i)
         st%du(i) = -b%mass(i)*b%ground(i)*(st%ag + (1.0_dp + alpha)*dag) + st%f(i) - b%mass(i)*ap - &
                    (1.0_dp + alpha)*vp - st%ku(i) + alpha*st%cv(i)
      end do
      call dpbtrs_vec(st, st%du)
      st%df = 0.0_dp
   end subroutine hht_predict

   !> The constants of a* and v* for the state's beta, gamma and dt.
   pure subroutine kinematic_constants(st)
      type(hht_state), intent(inout) :: st

      st%ca = 1.0_dp/(st%beta*st%dt)
      st%cb = 0.5_dp/st%beta - 1.0_dp
      st%cc = 1.0_dp - st%gamma/st%beta
      st%cd = st%dt*(1.0_dp - st%gamma/(2.0_dp*st%beta))
   end subroutine kinematic_constants

   !> HHT-alpha has no exact steps: predicts by `hht_predict` under the first component.
   subroutine hht_predict_exact(st, b, ag_old, ag_new, ag2_old, ag2_new)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration at the start and end of the step (m/s^2).
      real(dp), intent(in), value :: ag_old, ag_new
      !> Not used (a second component is the caller's load rows: no exact steps).
      real(dp), intent(in), optional :: ag2_old, ag2_new

      if (present(ag2_old) .or. present(ag2_new)) continue
      call hht_predict(st, b, ag_new - ag_old)
   end subroutine hht_predict_exact

   !> Nothing to drop (no exact steps).
   pure subroutine hht_drop_exact(st)
      !> Integrator.
      class(hht_state), intent(inout) :: st

      if (st%n < 0) st%n = 0
   end subroutine hht_drop_exact

   !> Hold the model still over the step: du = 0, no load increment (a frozen building).
   pure subroutine hht_hold(st)
      !> Integrator.
      class(hht_state), intent(inout) :: st

      st%du = 0.0_dp
      st%df = 0.0_dp
   end subroutine hht_hold

   !> Complete the step with du: the state at t_{n+1}, the contact loads, the unbalanced force
   !> and the step's energies (with `w_in`, `e_out`: add the input work and kinetic + strain
   !> + damping + numerical energy to them).
   subroutine hht_commit(st, b, ag_old, ag_new, w_in, e_out)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration at the start and end of the step (m/s^2).
      real(dp), intent(in), value :: ag_old, ag_new
      !> Running input work and energy (added to).
      real(dp), intent(inout), optional :: w_in, e_out
      real(dp) :: win, dd, ddamp, ekin, a1, v1, ep, aa, da, va
      integer :: i

      if (st%tri) then
         call commit_tri(st, b, ag_old, ag_new)
         if (present(w_in)) w_in = w_in + st%input_work
         if (present(e_out)) e_out = e_out + (st%kinetic + st%strain + st%damping_energy + st%numerical)
         return
      end if
      ! u, v, a at t_{n+1} (w1 keeps a_n, w2 keeps v_n for the energies).
      st%w1 = st%a
      st%w2 = st%v
      do i = 1, st%n
         a1 = st%c0*st%du(i) - st%ca*st%v(i) - st%cb*st%a(i)
         v1 = st%c1*st%du(i) + st%cc*st%v(i) + st%cd*st%a(i)
         st%u(i) = st%u(i) + st%du(i)
         st%v(i) = v1
         st%a(i) = a1
      end do
      st%f = st%f + st%df
      st%df = 0.0_dp
      win = 0.0_dp
      dd = 0.0_dp
      ddamp = 0.0_dp
      ekin = 0.0_dp
      ! dE_damping = du.(C v_n + C v_{n+1})/2 (C v_n first), the ground's work, e_{n+1} and
      ! the numerical dissipation dD.
      do i = 1, st%n
         ddamp = ddamp + st%du(i)*st%cv(i)
         win = win - st%du(i)*b%mass(i)*b%ground(i)*0.5_dp*(ag_old + ag_new)
      end do
      call band_symv(b%kt, st%u, st%ku)
      call band_symv(b%kt, st%v, st%kv)
      do i = 1, st%n
         st%cv(i) = b%a0*b%mass(i)*st%v(i) + b%a1*st%kv(i)
         ddamp = ddamp + st%du(i)*st%cv(i)
         ep = st%e(i)
         st%e(i) = b%mass(i)*st%a(i) + st%cv(i) + st%ku(i) - (-b%mass(i)*b%ground(i)*ag_new + st%f(i))
         aa = 0.5_dp*(st%w1(i) + st%a(i))
         da = st%a(i) - st%w1(i)
         va = 0.5_dp*(st%w2(i) + st%v(i))
         dd = dd - st%du(i)*0.5_dp*(ep + st%e(i)) - st%dt*(st%gamma - 0.5_dp)*va*b%mass(i)*da + &
              st%dt**2*(st%beta - 0.5_dp*st%gamma)*da*b%mass(i)*aa
         ekin = ekin + b%mass(i)*st%v(i)**2
      end do
      ddamp = 0.5_dp*ddamp
      st%damping_energy = st%damping_energy + ddamp
      st%input_work = st%input_work + win
      st%numerical = st%numerical + dd
      st%kinetic = 0.5_dp*ekin
      st%strain = 0.5_dp*dot_product(st%u, st%ku)
      st%ag = ag_new
      if (present(w_in)) w_in = w_in + st%input_work
      if (present(e_out)) e_out = e_out + (st%kinetic + st%strain + st%damping_energy + st%numerical)
   end subroutine hht_commit

   !> `hht_commit`, then `hht_predict` of the next step.
   subroutine hht_advance(st, b, ag_old, ag_new, dag_next, w_in, e_out)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration at the start and end of the step, increment of the next (m/s^2).
      real(dp), intent(in), value :: ag_old, ag_new, dag_next
      !> Running input work and energy (added to).
      real(dp), intent(inout) :: w_in, e_out

      call hht_commit(st, b, ag_old, ag_new, w_in, e_out)
      call hht_predict(st, b, dag_next)
   end subroutine hht_advance

   !> x = Khat^{-1} x (no scaling; internal).
   subroutine dpbtrs_vec(st, x)
      type(hht_state), intent(in) :: st
      real(dp), intent(inout) :: x(:)
      integer :: info

      if (st%tri) then
         call dpttrs(st%n, 1, st%td, st%te, x, st%n, info)
      else
         call dpbtrs('U', st%n, st%kd, 1, st%chol, st%kd + 1, x, st%n, info)
      end if
   end subroutine dpbtrs_vec

   !> `hht_predict` on a tridiagonal model in two passes: v* (w1, one DOF ahead), (K+G) v* by
   !> the three-term stencil, the right-hand side and the forward sweep of the L D L^T solve
   !> in one; then the backward sweep (the sweeps as dpttrs takes them).
   subroutine predict_tri(st, b, dag)
      type(hht_state), intent(inout) :: st
      type(structure_model), intent(in) :: b
      real(dp), intent(in) :: dag
      real(dp) :: ap, kw, alpha, rhs, prev
      integer :: i, n

      alpha = st%alpha
      n = st%n
      st%w1(1) = st%cc*st%v(1) + st%cd*st%a(1)
      prev = 0.0_dp
      do i = 1, n
         if (i < n) st%w1(i + 1) = st%cc*st%v(i + 1) + st%cd*st%a(i + 1)
         kw = b%kt(2, i)*st%w1(i)
         if (i > 1) kw = kw + b%kt(1, i)*st%w1(i - 1)
         if (i < n) kw = kw + b%kt(1, i + 1)*st%w1(i + 1)
         ap = -st%ca*st%v(i) - st%cb*st%a(i)
         rhs = -b%mass(i)*b%ground(i)*(st%ag + (1.0_dp + alpha)*dag) + st%f(i) - b%mass(i)*ap - &
               (1.0_dp + alpha)*(b%a0*b%mass(i)*st%w1(i) + b%a1*kw) - st%ku(i) + alpha*st%cv(i)
         if (i > 1) rhs = rhs - prev*st%te(i - 1)
         st%du(i) = rhs
         prev = rhs
         st%df(i) = 0.0_dp
      end do
      st%du(n) = st%du(n)/st%td(n)
      do i = n - 1, 1, -1
         st%du(i) = st%du(i)/st%td(i) - st%du(i + 1)*st%te(i)
      end do
   end subroutine predict_tri

   !> `hht_commit` on a tridiagonal model in two passes: the state at t_{n+1}, the loads and the
   !> first half of the damping energy (w1, w2 keep a_n, v_n); then (K+G) u, (K+G) v by the
   !> three-term stencil, C v, the unbalanced force, the numerical dissipation and the
   !> kinetic and strain energy.
   subroutine commit_tri(st, b, ag_old, ag_new)
      type(hht_state), intent(inout) :: st
      type(structure_model), intent(in) :: b
      real(dp), intent(in) :: ag_old, ag_new
      real(dp) :: win, dd, ddamp, ekin, estr, ep, aa, da, va, hg, ku, kv
      integer :: i, n

      n = st%n
      win = 0.0_dp
      ddamp = 0.0_dp
      hg = 0.5_dp*(ag_old + ag_new)
      do i = 1, n
         st%w1(i) = st%a(i)
         st%w2(i) = st%v(i)
         st%a(i) = st%c0*st%du(i) - st%ca*st%w2(i) - st%cb*st%w1(i)
         st%v(i) = st%c1*st%du(i) + st%cc*st%w2(i) + st%cd*st%w1(i)
         st%u(i) = st%u(i) + st%du(i)
         st%f(i) = st%f(i) + st%df(i)
         st%df(i) = 0.0_dp
         ddamp = ddamp + st%du(i)*st%cv(i)
         win = win - st%du(i)*b%mass(i)*b%ground(i)*hg
      end do
      dd = 0.0_dp
      ekin = 0.0_dp
      estr = 0.0_dp
      do i = 1, n
         ku = b%kt(2, i)*st%u(i)
         kv = b%kt(2, i)*st%v(i)
         if (i > 1) then
            ku = ku + b%kt(1, i)*st%u(i - 1)
            kv = kv + b%kt(1, i)*st%v(i - 1)
         end if
         if (i < n) then
            ku = ku + b%kt(1, i + 1)*st%u(i + 1)
            kv = kv + b%kt(1, i + 1)*st%v(i + 1)
         end if
         st%ku(i) = ku
         st%kv(i) = kv
         st%cv(i) = b%a0*b%mass(i)*st%v(i) + b%a1*kv
         ddamp = ddamp + st%du(i)*st%cv(i)
         ep = st%e(i)
         st%e(i) = b%mass(i)*st%a(i) + st%cv(i) + ku - (-b%mass(i)*b%ground(i)*ag_new + st%f(i))
         aa = 0.5_dp*(st%w1(i) + st%a(i))
         da = st%a(i) - st%w1(i)
         va = 0.5_dp*(st%w2(i) + st%v(i))
         dd = dd - st%du(i)*0.5_dp*(ep + st%e(i)) - st%dt*(st%gamma - 0.5_dp)*va*b%mass(i)*da + &
              st%dt**2*(st%beta - 0.5_dp*st%gamma)*da*b%mass(i)*aa
         ekin = ekin + b%mass(i)*st%v(i)**2
         estr = estr + st%u(i)*ku
      end do
      st%damping_energy = st%damping_energy + 0.5_dp*ddamp
      st%input_work = st%input_work + win
      st%numerical = st%numerical + dd
      st%kinetic = 0.5_dp*ekin
      st%strain = 0.5_dp*estr
      st%ag = ag_new
   end subroutine commit_tri

   !> x = (1+alpha) Khat^{-1} x: the response of du to a load x at t_{n+1}.
   subroutine hht_solve(st, x)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> Right-hand side on entry, solution on return.
      real(dp), intent(inout) :: x(:)

      call dpbtrs_vec(st, x)
      x = (1.0_dp + st%alpha)*x
   end subroutine hht_solve

   !> The matrix whose inverse `hht_solve` applies, Khat/(1+alpha) = fk (K+G) + fm M:
   !> fk = 1 + c1 a1, fm = c0/(1+alpha) + c1 a0.
   pure subroutine hht_solve_matrix(st, a0, a1, fk, fm)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> Rayleigh damping coefficients of the model.
      real(dp), intent(in) :: a0, a1
      !> Coefficients of K+G and of M.
      real(dp), intent(out) :: fk, fm

      fk = 1.0_dp + st%c1*a1
      fm = st%c0/(1.0_dp + st%alpha) + st%c1*a0
   end subroutine hht_solve_matrix

   !> du = du + s x, x = `hht_solve` of e_dof; the load increment kept for F_{n+1}.
   pure subroutine hht_add_load(st, s, dof, x)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> Load increment (kN).
      real(dp), intent(in) :: s
      !> The DOF.
      integer, intent(in) :: dof
      !> (1+alpha) Khat^{-1} e_dof.
      real(dp), intent(in) :: x(:)

      st%du = st%du + s*x
      st%df(dof) = st%df(dof) + s
   end subroutine hht_add_load

   !> du = du + s x along the weights w of the DOFs dof.
   pure subroutine hht_add_load_rows(st, s, dof, w, x)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> Load increment (kN).
      real(dp), intent(in) :: s
      !> DOFs and weights.
      integer, intent(in) :: dof(:)
      real(dp), intent(in) :: w(:)
      !> (1+alpha) Khat^{-1} sum_i w_i e_dof(i).
      real(dp), intent(in) :: x(:)
      integer :: i

      st%du = st%du + s*x
      do i = 1, size(dof)
         st%df(dof(i)) = st%df(dof(i)) + s*w(i)
      end do
   end subroutine hht_add_load_rows

   !> Exchange dt, c0, c1 and the factor with an HHT integrator of the same model and alpha
   !> set up for another dt (the state at t_n is all the next step needs).
   subroutine hht_swap_step(st, other)
      !> Integrator that goes on with the other step.
      class(hht_state), intent(inout) :: st
      !> The same model at the other step.
      class(integrator), intent(inout) :: other

      select type (other)
      class is (hht_state)
         call swap(st%dt, other%dt)
         call swap(st%c0, other%c0)
         call swap(st%c1, other%c1)
         call swap(st%ca, other%ca)
         call swap(st%cb, other%cb)
         call swap(st%cc, other%cc)
         call swap(st%cd, other%cd)
         call swap(st%chol, other%chol)
         if (st%tri) then
            call swap(st%td, other%td)
            call swap(st%te, other%te)
         end if
      end select
   end subroutine hht_swap_step

   !> Overwrite the state (tests): (K+G) u, C v, the energies of the state and e = M a + C v +
   !> (K+G) u - F_n are formed again.
   subroutine hht_set_state(st, b, u, v, a)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Displacement, velocity and acceleration (n each).
      real(dp), intent(in), optional :: u(:), v(:), a(:)

      if (present(u)) st%u = u
      if (present(v)) st%v = v
      if (present(a)) st%a = a
      call band_symv(b%kt, st%u, st%ku)
      call band_symv(b%kt, st%v, st%kv)
      st%cv = b%a0*b%mass*st%v + b%a1*st%kv
      st%e = b%mass*st%a + st%cv + st%ku - (-b%mass*b%ground*st%ag + st%f)
      st%kinetic = 0.5_dp*sum(b%mass*st%v**2)
      st%strain = structure_strain_energy(b, st%u)
   end subroutine hht_set_state

   !> Number of DOFs.
   pure integer function hht_dofs(st)
      !> Integrator.
      class(hht_state), intent(in) :: st

      hht_dofs = st%n
   end function hht_dofs

   !> The time step (s), also the span of `hht_path`.
   pure real(dp) function hht_step_size(st)
      !> Integrator.
      class(hht_state), intent(in) :: st

      hht_step_size = st%dt
   end function hht_step_size

   !> The joints' compression rate per increment: the trapezoidal rule's 2/dt.
   pure real(dp) function hht_velocity_rate(st)
      !> Integrator.
      class(hht_state), intent(in) :: st

      hht_velocity_rate = trapezoid_rate(st%dt)
   end function hht_velocity_rate

   !> The motion of DOF i inside the step: the parabola u_n + v_n s + am s^2/2 through
   !> u_n + du at s = dt.
   pure subroutine hht_path(st, i, u0, v0, am)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i
      !> Displacement, velocity at the start, acceleration of the parabola.
      real(dp), intent(out) :: u0, v0, am

      u0 = st%u(i)
      v0 = st%v(i)
      am = 2.0_dp*(st%du(i) - st%v(i)*st%dt)/st%dt**2
   end subroutine hht_path

   !> View of u.
   function hht_u_view(st) result(p)
      !> Integrator.
      class(hht_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%u
   end function hht_u_view

   !> View of v.
   function hht_v_view(st) result(p)
      !> Integrator.
      class(hht_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%v
   end function hht_v_view

   !> View of a.
   function hht_a_view(st) result(p)
      !> Integrator.
      class(hht_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%a
   end function hht_a_view

   !> View of du.
   function hht_du_view(st) result(p)
      !> Integrator.
      class(hht_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%du
   end function hht_du_view

   !> u of DOF i.
   pure real(dp) function hht_u_at(st, i)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i

      hht_u_at = st%u(i)
   end function hht_u_at

   !> v of DOF i.
   pure real(dp) function hht_v_at(st, i)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i

      hht_v_at = st%v(i)
   end function hht_v_at

   !> u + du of DOF i.
   pure real(dp) function hht_predicted(st, i)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i

      hht_predicted = st%u(i) + st%du(i)
   end function hht_predicted

   !> Input work, kinetic, strain, damping energy and numerical dissipation (kJ).
   pure function hht_energies(st) result(e)
      !> Integrator.
      class(hht_state), intent(in) :: st
      real(dp) :: e(n_integrator_energies)

      e = [st%input_work, st%kinetic, st%strain, st%damping_energy, st%numerical]
   end function hht_energies

   !> Add the running energies to the sums (the numerical dissipation to `e_numerical`).
   pure subroutine hht_add_energies(st, w_in, e_kinetic, e_strain, e_damping, e_numerical)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> Sums (added to).
      real(dp), intent(inout) :: w_in, e_kinetic, e_strain, e_damping, e_numerical

      w_in = w_in + st%input_work
      e_kinetic = e_kinetic + st%kinetic
      e_strain = e_strain + st%strain
      e_damping = e_damping + st%damping_energy
      e_numerical = e_numerical + st%numerical
   end subroutine hht_add_energies

   !> Add work to the input work (a ground component taken as load rows).
   pure subroutine hht_add_input_work(st, w)
      !> Integrator.
      class(hht_state), intent(inout) :: st
      !> Work (kJ).
      real(dp), intent(in) :: w

      st%input_work = st%input_work + w
   end subroutine hht_add_input_work

   !> Start at rest under a further load s w at t = 0: kept in the loads f_0 (F_0), then a_0 +=
   !> M^-1 s w as any integrator starts (`default_start_load`, whose `set_state` forms e_0 = 0
   !> again with f_0).
   subroutine hht_start_load(st, b, s, dof, w)
      !> Integrator at t = 0.
      class(hht_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Load factor (m/s^2: -a_gy(0)).
      real(dp), intent(in) :: s
      !> DOFs and weights (m_i r_i).
      integer, intent(in) :: dof(:)
      real(dp), intent(in) :: w(:)

      st%f(dof) = st%f(dof) + s*w
      call default_start_load(st, b, s, dof, w)
   end subroutine hht_start_load

   !> Kinetic energy v^T M v/2 (kJ).
   pure function hht_kinetic_energy(st, b) result(e)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      real(dp) :: e

      e = 0.5_dp*sum(b%mass*st%v**2)
   end function hht_kinetic_energy

   !> Strain energy u^T (K+G) u/2 (kJ).
   pure function hht_strain_energy(st, b) result(e)
      !> Integrator.
      class(hht_state), intent(in) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      real(dp) :: e

      e = structure_strain_energy(b, st%u)
   end function hht_strain_energy

end module pound_hht
