!> Newmark average-acceleration integration of one structural model, incremental form.
!>
!> With c1 = 4/dt^2 and c2 = 2/dt the effective stiffness
!> Khat = (K+G) + c1 M + c2 C, C = a0 M + a1 (K+G), has the band of K+G; it is factored
!> once. Equation of motion, relative to the ground: M a + C v + (K+G) u = -M r a_g + f_ext,
!> r the model's ground-influence vector.
!>
!> **Two paths, one interface.** Half-bandwidth 1 with every DOF moved by the ground (the
!> shear building) uses fused tridiagonal kernels: dpttrf's L D L^T factors, the
!> right-hand side formed inside the forward sweep, the Newmark update, C v and the energy
!> sums in one pass. Any other model uses the banded Cholesky factor (dpbtrf/dpbtrs) and
!> obtains (K+G) u and (K+G) v (for C v and the strain energy) without a band product from
!> the step's own equation (see pound_newmark_band), with an exact band product every
!> `refresh` steps. `newmark_init(..., general=.true.)` forces the general path (tests).
!>
!> **State is private.** A step is `newmark_predict` (the increment du for the ground motion
!> alone), then any number of `newmark_add_response` (contact adds Khat^{-1} times its load
!> increment, obtained once from `newmark_solve`), then `newmark_commit` (u, v, a and the
!> energy accumulators). dt and the Newmark constants live here only (`newmark_dt`). The
!> state is read through `newmark_u`, `newmark_v`, `newmark_a`, `newmark_du` (pointers to
!> the state of a `target` argument, no copy), `newmark_predicted` and `newmark_energies`.
!>
!> **Exact free steps** (`newmark_init(..., exact=.true.)`, `&analysis free_steps = 'exact'`):
!> the integrator also holds the modes of (K+G, M) and, per mode, the exact step for a ground
!> acceleration linear over the step (`pound_modal_step`). `newmark_predict_exact` predicts the
!> step exactly (du, and the v and a at its end) instead of by average acceleration; the next
!> `newmark_commit` completes it, unless the caller drops it (`newmark_drop_exact`, a step in
!> which a joint acts) and predicts by Newmark instead. DOFs without mass are condensed
!> statically, their elastic forces relaxing as exp(-t/a1) (exact as well). Submodule
!> pound_newmark_exact.
!>
!> **Lanes** (the integrator's `start_lanes`, `advance_lanes`, `show_lane`, `drop_lane`): on
!> the fused tridiagonal path (two DOFs or more) the integrator also advances `max_lanes`
!> ground motions of its model at once, with the same factors, each lane bit for bit the
!> tridiagonal kernels' single motion (submodule pound_newmark_batch).
module pound_newmark
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_band, only: band_symv
   use pound_swap, only: swap
   use pound_band_lapack, only: dpbtrf, dpbtrs, dpttrf, dpttrs
   use pound_structure, only: structure_model, structure_label, structure_strain_energy
   use pound_integrator, only: integrator, integrator_properties, max_lanes, en_input, en_kinetic, en_strain, en_damping, &
                               en_numerical, &
                               n_integrator_energies
   implicit none
   private

   public :: newmark_state, newmark_init, newmark_predict, newmark_commit, newmark_advance, newmark_solve
   public :: newmark_add_response, newmark_add_response_rows, newmark_set_state, newmark_dt, newmark_n, newmark_swap_step
   public :: newmark_u, newmark_v, newmark_a, newmark_du, newmark_u_at, newmark_v_at, newmark_predicted, newmark_energies
   public :: newmark_path
   public :: kinetic_energy, strain_energy
   public :: en_input, en_kinetic, en_strain, en_damping
   public :: newmark_add_energies, newmark_predict_exact, newmark_drop_exact, newmark_put_state
   !> Largest model (DOFs) that exact free steps take: they hold the n x n modes and cost
   !> O(n^2) a step.
   integer, parameter, public :: exact_max_dofs = 2000

   !> Default steps between exact band products of the general path (see pound_newmark_band).
   integer, parameter, public :: band_refresh_steps = 100

   !> The lanes of a Newmark integrator (`start_lanes`): `max_lanes` motions of its model,
   !> every vector held motion-fastest, x(lane, DOF) (submodule pound_newmark_batch).
   type :: newmark_lanes
      !> Relative displacement, velocity, acceleration, C v and the step's increment (max_lanes, n).
      real(dp), allocatable :: u(:, :), v(:, :), a(:, :), cv(:, :), du(:, :)
      !> Input work, damping energy, kinetic and strain energy per lane (kJ), as `newmark_state`.
      real(dp) :: input_work(max_lanes) = 0.0_dp, damping_energy(max_lanes) = 0.0_dp
      real(dp) :: kinetic(max_lanes) = 0.0_dp, strain(max_lanes) = 0.0_dp
   end type newmark_lanes

   !> Integrator state of one structural model (components private: see the module doc): the
   !> Newmark average-acceleration extension of `integrator`.
   type, extends(integrator) :: newmark_state
      private
      !> Number of DOFs and half-bandwidth.
      integer :: n = 0, kd = 1
      !> Whether the fused tridiagonal path is taken.
      logical :: tridiagonal = .true.
      !> Time step and Newmark constants c1 = 4/dt^2, c2 = 2/dt.
      real(dp) :: dt = 0.0_dp, c1 = 0.0_dp, c2 = 0.0_dp
      !> Tridiagonal path: L D L^T factors of Khat: diagonal d (n) and sub-diagonal e (n-1), and 1/d
      !> (general path: 1/U(j, j) of the Cholesky factor).
      real(dp), allocatable :: d(:), e(:), dinv(:)
      !> General path: Cholesky factor U of Khat in upper band storage (kd+1, n); work vector (n).
      real(dp), allocatable :: chol(:, :), work(:)
      !> General path: the load increments of `newmark_add_response` in the step in progress
      !> (zero elsewhere), and (K+G) u, (K+G) v at the current time (n each).
      real(dp), allocatable :: fc(:), ktu(:), ktv(:)
      !> General path: ground acceleration increment of the step in progress (m/s^2).
      real(dp) :: dag = 0.0_dp
      !> General path: whether `fc` holds a load increment.
      logical :: loaded = .false.
      !> General path: steps between exact band products for (K+G) u and (K+G) v (1: every
      !> step, the band-product formulation), and steps since the last one.
      integer :: refresh = 1, since_refresh = 0
      !> Relative displacement, velocity and acceleration at the current time.
      real(dp), allocatable :: u(:), v(:), a(:)
      !> Displacement increment of the step in progress.
      real(dp), allocatable :: du(:)
      !> Damping force C v at the current time.
      real(dp), allocatable :: cv(:)
      !> Work done by the ground motion (effective loads -M r a_g) on the relative motion (kJ).
      real(dp) :: input_work = 0.0_dp
      !> Energy dissipated by viscous damping (kJ).
      real(dp) :: damping_energy = 0.0_dp
      !> Kinetic and strain energy at the current time (kJ), summed in the update of
      !> `newmark_commit` for the energy audit of every step (they agree with
      !> `kinetic_energy` and `strain_energy` to round-off).
      real(dp) :: kinetic = 0.0_dp, strain = 0.0_dp
      !> Exact free steps: whether this integrator takes them (`newmark_predict_exact`), whether
      !> one is predicted and not yet committed, and whether q, qd are the modal coordinates
      !> of u, v.
      logical :: exact = .false., pending = .false., modal_valid = .false.
      !> Exact free steps: mass-normalised modes (n, n), eigenvalues omega^2, modal damping
      !> a0 + a1 omega^2, per mode the step's coefficients (22, n: see pound_newmark_exact) and
      !> the terms of the step's energies in the ground acceleration alone, summed over the
      !> modes (6) (`modal_step_coefficients`).
      real(dp), allocatable :: phi(:, :), lam(:), cm(:), coef(:, :)
      !> Exact free steps of a model with DOFs without mass: the number of DOFs with mass (the
      !> first nm coordinates are the condensed modes, the others the relaxation coordinates),
      !> and whether C v, (K+G) u and (K+G) v are still those of an earlier state (they are
      !> formed again, `band_state`, before a Newmark step needs them).
      integer :: nm = 0
      logical :: band_stale = .false.
      !> Exact free steps of a model with DOFs without mass: the relaxation coordinates of q
      !> are zero (set to zero by `relaxed` and not taken from a state since): they stay zero.
      logical :: z_zero = .false.
      !> Exact free steps of a model with DOFs without mass: psi^T, whose rows give the
      !> coordinates (condensed modes and relaxation coordinates) of a state, q = psi^T u
      !> (n, n; unallocated when every DOF has a mass: q = phi^T M u).
      real(dp), allocatable :: psi(:, :)
      !> The largest entry of each relaxation coordinate's column of phi (n - nm).
      real(dp), allocatable :: zscale(:)
      real(dp) :: ground_terms(6) = 0.0_dp
      !> Exact free steps of a model with a second ground component (`ground_set(:, 2)`): per
      !> mode its participations Gamma_1, Gamma_2 (n, 2), the step's coefficients for a unit
      !> participation (n, 28: `coef`'s 22 and the six terms of the energies in the modal ground
      !> alone) and the modal ground Gamma_1 a_g1 + Gamma_2 a_g2 at the step's ends (n each).
      real(dp), allocatable :: gam(:, :), coef2(:, :), g0(:), g1(:)
      !> Exact free steps: modal coordinates and rates now and at the end of the predicted
      !> step, the modal accelerations without the ground term at its end; v and a at its end
      !> (n each).
      real(dp), allocatable :: q(:), qd(:), xq(:), xqd(:), xw(:), xv(:), xa(:)
      !> Exact free steps: input work and damping energy of the predicted step (kJ).
      real(dp) :: x_input = 0.0_dp, x_damping = 0.0_dp
      !> Lanes (`start_lanes`; unallocated otherwise).
      type(newmark_lanes), allocatable :: lanes
   contains
      procedure :: properties => newmark_properties
      procedure :: init => init_binding
      procedure :: predict => newmark_predict
      procedure :: predict_exact => newmark_predict_exact
      procedure :: drop_exact => newmark_drop_exact
      procedure :: hold => newmark_hold
      procedure :: commit => newmark_commit
      procedure :: advance => newmark_advance
      procedure :: solve => newmark_solve
      procedure :: solve_matrix => newmark_solve_matrix
      procedure :: add_load => newmark_add_response
      procedure :: add_load_rows => newmark_add_response_rows
      procedure :: add_input_work => newmark_add_input_work
      procedure :: swap_step => swap_binding
      procedure :: set_state => newmark_set_state
      procedure :: dofs => newmark_n
      procedure :: step_size => newmark_dt
      procedure :: velocity_rate => newmark_velocity_rate
      procedure :: path_span => newmark_path_span
      procedure :: path => newmark_path
      procedure :: u_view => newmark_u
      procedure :: v_view => newmark_v
      procedure :: a_view => newmark_a
      procedure :: du_view => newmark_du
      procedure :: u_at => newmark_u_at
      procedure :: v_at => newmark_v_at
      procedure :: predicted => newmark_predicted
      procedure :: energies => energies_binding
      procedure :: add_energies => newmark_add_energies
      procedure :: kinetic_energy => kinetic_energy
      procedure :: strain_energy => strain_energy
      procedure :: lanes_for => newmark_lanes_for
      procedure :: start_lanes => newmark_start_lanes
      procedure :: advance_lanes => newmark_advance_lanes
      procedure :: show_lane => newmark_show_lane
      procedure :: drop_lane => newmark_drop_lane
      procedure :: takes_state => newmark_takes_state
      procedure :: put_state => newmark_put_state
   end type newmark_state

   interface
      !> Increment du of the step for the ground acceleration increment `dag` alone
      !> (in submodule pound_newmark_step, with the tridiagonal kernels).
      module subroutine newmark_predict(st, b, dag)
         class(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: dag
      end subroutine newmark_predict
      !> Complete the step with the increment `du` and account the energy; with `w_in` and
      !> `e_out`, add the integrator's input work and its kinetic + strain + damping energy to
      !> them (the per-step audit; in submodule pound_newmark_step).
      module subroutine newmark_commit(st, b, ag_old, ag_new, w_in, e_out)
         class(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: ag_old, ag_new
         real(dp), intent(inout), optional :: w_in, e_out
      end subroutine newmark_commit
      !> `newmark_commit`, then `newmark_predict` of the next step (in submodule
      !> pound_newmark_step).
      module subroutine newmark_advance(st, b, ag_old, ag_new, dag_next, w_in, e_out)
         class(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: ag_old, ag_new, dag_next
         real(dp), intent(inout) :: w_in, e_out
      end subroutine newmark_advance
      !> The banded path of the step (submodule pound_newmark_band).
      module subroutine predict_general(st, b, dag)
         type(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in) :: dag
      end subroutine predict_general
      module subroutine commit_general(st, b, mdu, ddamp)
         type(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(out) :: mdu, ddamp
      end subroutine commit_general
      !> C v, and on the general path (K+G) u and (K+G) v, of the state u, v (band products;
      !> submodule pound_newmark_step).
      module subroutine band_state(st, b)
         type(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
      end subroutine band_state
      !> Set up exact free steps: the modes and each mode's step (submodule
      !> pound_newmark_exact).
      module subroutine exact_init(st, b, error)
         type(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         type(error_type), allocatable, intent(out) :: error
      end subroutine exact_init
      !> Predict the step exactly for the ground acceleration linear from `ag_old` to `ag_new`
      !> (and a second component from `ag2_old` to `ag2_new`) (du, and v, a at the end); an
      !> integrator without exact steps predicts by Newmark (`newmark_predict`). Submodule
      !> pound_newmark_exact.
      module subroutine newmark_predict_exact(st, b, ag_old, ag_new, ag2_old, ag2_new)
         class(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: ag_old, ag_new
         real(dp), intent(in), optional :: ag2_old, ag2_new
      end subroutine newmark_predict_exact
      !> Complete the exact step predicted by `newmark_predict_exact` (submodule
      !> pound_newmark_exact).
      module subroutine commit_exact(st, w_in, e_out)
         type(newmark_state), intent(inout) :: st
         real(dp), intent(inout), optional :: w_in, e_out
      end subroutine commit_exact
      !> Whether the lanes can run the model: the fused tridiagonal path, two DOFs or more
      !> (submodule pound_newmark_batch, as the other lane procedures).
      pure module logical function newmark_lanes_for(st, b)
         class(newmark_state), intent(in) :: st
         type(structure_model), intent(in) :: b
      end function newmark_lanes_for
      !> Start every lane at rest in equilibrium with its ground acceleration at t = 0.
      module subroutine newmark_start_lanes(st, b, ag0, error)
         class(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in) :: ag0(max_lanes)
         type(error_type), allocatable, intent(out) :: error
      end subroutine newmark_start_lanes
      !> One step of every lane, the running peaks, the lanes' energy sums.
      module subroutine newmark_advance_lanes(st, b, ag_old, ag_new, t, peak, peak_time, w_in, e_out)
         class(newmark_state), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in) :: ag_old(max_lanes), ag_new(max_lanes), t
         real(dp), intent(inout), contiguous :: peak(:, :, :), peak_time(:, :, :)
         real(dp), intent(inout) :: w_in(max_lanes), e_out(max_lanes)
      end subroutine newmark_advance_lanes
      !> Lane l's u, v, a and energies as the integrator's own state.
      module subroutine newmark_show_lane(st, l)
         class(newmark_state), intent(inout) :: st
         integer, intent(in) :: l
      end subroutine newmark_show_lane
      !> Bring lane l to rest (zero state and energies).
      module subroutine newmark_drop_lane(st, l)
         class(newmark_state), intent(inout) :: st
         integer, intent(in) :: l
      end subroutine newmark_drop_lane
   end interface

contains

   !> Factor Khat and start at rest relative to the ground, in equilibrium with the
   !> ground acceleration at t = 0: u = v = 0, M a = -M r a_g(0), so a = -r a_g(0).
   subroutine newmark_init(st, b, dt, ag0, error, general, refresh, exact)
      !> Integrator state.
      type(newmark_state), intent(out) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Time step (s).
      real(dp), intent(in) :: dt
      !> Ground acceleration at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Take the general banded path even for a tridiagonal model (default: .false.).
      logical, intent(in), optional :: general
      !> General path: steps between exact band products for (K+G) u and (K+G) v
      !> (default `band_refresh_steps`; 1: a band product every step; >= 1).
      integer, intent(in), optional :: refresh
      !> Prepare exact free steps (`newmark_predict_exact`; default: no).
      logical, intent(in), optional :: exact
      real(dp) :: fk, fm
      integer :: n, info, i, stat, kd
      character(len=:), allocatable :: sources

      n = b%n
      kd = b%kd
      st%n = n
      st%kd = kd
      st%tridiagonal = kd == 1
      if (st%tridiagonal) st%tridiagonal = all(b%ground == 1.0_dp)
      if (present(general)) then
         if (general) st%tridiagonal = .false.
      end if
      st%dt = dt
      st%c1 = 4.0_dp/dt**2
      st%c2 = 2.0_dp/dt
      fk = 1.0_dp + st%c2*b%a1
      fm = st%c1 + st%c2*b%a0
      sources = ' from dt = '//str(dt)//' s, the masses, the storey stiffnesses and the damping (a0 = '// &
                str(b%a0)//', a1 = '//str(b%a1)//')'
      if (.not. (ieee_is_finite(fk) .and. ieee_is_finite(fm))) then
         call fatal_error(error, structure_label(b)//': Newmark coefficients 1 + 2 a1/dt = '//str(fk)// &
                          ' and 4/dt^2 + 2 a0/dt = '//str(fm)//sources//' are not finite')
         return
      end if
      allocate (st%u(n), st%v(n), st%a(n), st%du(n), st%cv(n), stat=stat)
      if (stat == 0) then
         if (st%tridiagonal) then
            allocate (st%d(n), st%e(max(n - 1, 1)), stat=stat)
         else
            allocate (st%chol(kd + 1, n), st%work(n), st%fc(n), st%ktu(n), st%ktv(n), stat=stat)
         end if
      end if
      if (stat /= 0) then
         call fatal_error(error, structure_label(b)//': cannot allocate the integrator state ('// &
                          str((10 + kd)*n)//' reals; n_storeys = '//str(n)//')')
         return
      end if
      if (st%tridiagonal) then
         st%d = fk*b%kt(2, :) + fm*b%mass
         st%e = 0.0_dp
         if (n > 1) st%e(1:n - 1) = fk*b%kt(1, 2:n)
         do i = 1, n
            if (.not. (ieee_is_finite(st%d(i)) .and. ieee_is_finite(st%e(min(i, size(st%e)))))) then
               call khat_not_finite(i)
               return
            end if
         end do
         call dpttrf(n, st%d, st%e, info)
         if (info /= 0) then
            call fatal_error(error, structure_label(b)//': effective stiffness not positive definite '// &
                             '(dpttrf info = '//str(info)//')'//sources)
            return
         end if
         st%dinv = 1.0_dp/st%d
         do i = 1, n
            if (.not. (ieee_is_finite(st%d(i)) .and. ieee_is_finite(st%dinv(i)) .and. &
                       ieee_is_finite(st%e(min(i, size(st%e)))))) then
               call fatal_error(error, structure_label(b)//': floor '//str(i)//': factorization of the '// &
                                'effective stiffness Khat out of range (pivot '//str(st%d(i))//')'//sources)
               return
            end if
         end do
      else
         st%chol = fk*b%kt
         st%chol(kd + 1, :) = st%chol(kd + 1, :) + fm*b%mass
         do i = 1, n
            if (.not. all(ieee_is_finite(st%chol(:, i)))) then
               call khat_not_finite(i)
               return
            end if
         end do
         call dpbtrf('U', n, kd, st%chol, kd + 1, info)
         if (info /= 0) then
            call fatal_error(error, structure_label(b)//': effective stiffness not positive definite '// &
                             '(dpbtrf info = '//str(info)//')'//sources)
            return
         end if
         st%dinv = 1.0_dp/st%chol(kd + 1, :)
         do i = 1, n
            if (.not. (all(ieee_is_finite(st%chol(:, i))) .and. st%chol(kd + 1, i) > 0.0_dp .and. &
                       ieee_is_finite(st%dinv(i)))) then
               call fatal_error(error, structure_label(b)//': DOF '//str(i)//': factorization of the '// &
                                'effective stiffness Khat out of range (pivot '//str(st%chol(kd + 1, i))//')'// &
                                sources)
               return
            end if
         end do
      end if
      st%u = 0.0_dp
      st%v = 0.0_dp
      st%a = -ag0*b%ground
      st%du = 0.0_dp
      st%cv = 0.0_dp
      st%input_work = 0.0_dp
      st%damping_energy = 0.0_dp
      st%kinetic = 0.5_dp*sum(b%mass*st%v**2)
      st%strain = 0.0_dp
      if (.not. st%tridiagonal) then
         st%fc = 0.0_dp
         st%loaded = .false.
         st%ktu = 0.0_dp
         st%ktv = 0.0_dp
         st%refresh = band_refresh_steps
         if (present(refresh)) st%refresh = max(1, refresh)
         st%since_refresh = 0
      end if
      if (present(exact)) then
         if (exact) call exact_init(st, b, error)
      end if

   contains

      subroutine khat_not_finite(i)
         integer, intent(in) :: i

         call fatal_error(error, structure_label(b)//': floor '//str(i)//': effective stiffness Khat = '// &
                          '(K+G)(1 + 2 a1/dt) + M (4/dt^2 + 2 a0/dt)'//sources//' is not finite')
      end subroutine khat_not_finite
   end subroutine newmark_init

   !> Exchange the time step, the Newmark constants and the factored Khat of `st` with those
   !> of `other` (an integrator of the same model initialised with another dt): `st` goes on
   !> from its state u, v, a with the other step size (average acceleration allows a change
   !> of dt between steps: each step only needs the state at its start). No copy, no
   !> allocation (`move_alloc`); swapping back restores both.
   subroutine newmark_swap_step(st, other)
      !> Integrator whose state continues with the other step.
      type(newmark_state), intent(inout) :: st
      !> Integrator of the same model at the other step (its state is not used).
      type(newmark_state), intent(inout) :: other

      call swap(st%dt, other%dt)
      call swap(st%c1, other%c1)
      call swap(st%c2, other%c2)
      if (st%tridiagonal) then
         call swap(st%d, other%d)
         call swap(st%e, other%e)
      else
         call swap(st%chol, other%chol)
      end if
      call swap(st%dinv, other%dinv)
      ! Exact free steps belong to the step they were set up for: the other step takes the
      ! other's setting (its modal data stay where they are).
      call swap(st%exact, other%exact)
      st%pending = .false.
      st%modal_valid = .false.
   end subroutine newmark_swap_step

   !> Drop the exact step predicted by `newmark_predict_exact` (a joint acts in the step: it is
   !> predicted again by `newmark_predict`); the modal coordinates are taken from u, v again
   !> at the next exact step.
   pure subroutine newmark_drop_exact(st)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st

      st%pending = .false.
      st%modal_valid = .false.
   end subroutine newmark_drop_exact

   !> Newmark average acceleration: exact free steps, lanes (on the fused tridiagonal path), no
   !> numerical dissipation.
   pure function newmark_properties(st) result(p)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      type(integrator_properties) :: p

      p = integrator_properties(name='Newmark', average_acceleration=.true., exact_steps=.true., &
                                lanes=st%tridiagonal, dissipates=.false.)
   end function newmark_properties

   !> Hold the model still over the step: du = 0 (a frozen building; it is not committed).
   pure subroutine newmark_hold(st)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st

      st%du = 0.0_dp
   end subroutine newmark_hold

   !> Overwrite the state (tests: initial conditions other than rest; an exact step's end).
   !> Each of u, v, a defaults to unchanged; C v, (K+G) u and v and the kinetic and strain
   !> energy are recomputed from the state.
   subroutine newmark_set_state(st, b, u, v, a)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Displacement, velocity and acceleration (n each).
      real(dp), intent(in), optional :: u(:), v(:), a(:)

      if (present(u)) st%u = u
      if (present(v)) st%v = v
      if (present(a)) st%a = a
      call band_state(st, b)
      st%kinetic = 0.5_dp*sum(b%mass*st%v**2)
      st%strain = structure_strain_energy(b, st%u)
      ! Exact free steps take the modal coordinates from the new u, v.
      st%pending = .false.
      st%modal_valid = .false.
   end subroutine newmark_set_state

   !> `takes_state`: Newmark takes in the end of a step computed elsewhere (`newmark_put_state`).
   pure logical function newmark_takes_state(st)
      !> Integrator state.
      class(newmark_state), intent(in) :: st

      newmark_takes_state = same_type_as(st, st)
   end function newmark_takes_state

   !> Put in the end of a step computed elsewhere (an exact step with joints closed,
   !> pound_closed_steps): u, v, a, with the kinetic and strain energy of that state (the
   !> caller has them from its modal coordinates: no band product here; C v, (K+G) u and
   !> (K+G) v are formed again, `band_state`, before a Newmark step needs them), the step's
   !> input work `work` and the work `joint_work` the joints' forces did on the building; the
   !> damping energy of the step is the balance, work + joint_work minus the change of
   !> kinetic + strain energy.
   pure subroutine newmark_put_state(st, u, v, a, kinetic, strain, work, joint_work)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st
      !> Displacement, velocity and acceleration at the end of the step (n each).
      real(dp), intent(in) :: u(:), v(:), a(:)
      !> Kinetic and strain energy of that state (kJ).
      real(dp), intent(in) :: kinetic, strain
      !> Input work of the step and work of the joints' forces on the building (kJ).
      real(dp), intent(in) :: work, joint_work
      real(dp) :: e0

      e0 = st%kinetic + st%strain
      st%u = u
      st%v = v
      st%a = a
      st%kinetic = kinetic
      st%strain = strain
      st%band_stale = .true.
      st%pending = .false.
      st%modal_valid = .false.
      st%input_work = st%input_work + work
      st%damping_energy = st%damping_energy + (work + joint_work) - ((st%kinetic + st%strain) - e0)
   end subroutine newmark_put_state

   !> Overwrite x with Khat^{-1} x (one tridiagonal or banded solve).
   subroutine newmark_solve(st, x)
      !> Integrator state (factors).
      class(newmark_state), intent(in) :: st
      !> Right-hand side on entry, solution on return.
      real(dp), intent(inout) :: x(:)
      integer :: info

      if (st%tridiagonal) then
         call dpttrs(st%n, 1, st%d, st%e, x, st%n, info)
      else
         call dpbtrs('U', st%n, st%kd, 1, st%chol, st%kd + 1, x, st%n, info)
      end if
   end subroutine newmark_solve

   !> Khat = fk (K+G) + fm M: fk = 1 + c2 a1, fm = c1 + c2 a0 (as `newmark_init` forms it).
   pure subroutine newmark_solve_matrix(st, a0, a1, fk, fm)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      !> Rayleigh damping coefficients of the model.
      real(dp), intent(in) :: a0, a1
      !> Coefficients of K+G and of M.
      real(dp), intent(out) :: fk, fm

      fk = 1.0_dp + st%c2*a1
      fm = st%c1 + st%c2*a0
   end subroutine newmark_solve_matrix

   !> du = du + s x: the response to a load increment s at DOF `dof` of the step,
   !> x = Khat^{-1} e_dof (from `newmark_solve`, computed once). The general path also keeps
   !> the load increment (it derives (K+G) du from the step's right-hand side).
   pure subroutine newmark_add_response(st, s, dof, x)
      !> Integrator state with the predicted `du`.
      class(newmark_state), intent(inout) :: st
      !> The load increment (kN).
      real(dp), intent(in) :: s
      !> The DOF it acts on.
      integer, intent(in) :: dof
      !> Khat^{-1} e_dof (n).
      real(dp), intent(in) :: x(:)

      st%du = st%du + s*x
      if (.not. st%tridiagonal) then
         st%fc(dof) = st%fc(dof) + s
         st%loaded = .true.
      end if
   end subroutine newmark_add_response

   !> du = du + s x: the response to a load increment s along the weights w of the DOFs `dof`
   !> (a contact end that is a sparse row), x = Khat^{-1} sum_i w_i e_dof(i) (computed once).
   pure subroutine newmark_add_response_rows(st, s, dof, w, x)
      !> Integrator state with the predicted `du`.
      class(newmark_state), intent(inout) :: st
      !> The load increment (kN).
      real(dp), intent(in) :: s
      !> The DOFs it acts on and their weights.
      integer, intent(in) :: dof(:)
      real(dp), intent(in) :: w(:)
      !> Khat^{-1} sum_i w_i e_dof(i) (n).
      real(dp), intent(in) :: x(:)
      integer :: i

      st%du = st%du + s*x
      if (.not. st%tridiagonal) then
         do i = 1, size(dof)
            st%fc(dof(i)) = st%fc(dof(i)) + s*w(i)
         end do
         st%loaded = .true.
      end if
   end subroutine newmark_add_response_rows

   !> Add work to the input work (a ground component taken as a load).
   pure subroutine newmark_add_input_work(st, w)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st
      !> Work (kJ).
      real(dp), intent(in) :: w

      st%input_work = st%input_work + w
   end subroutine newmark_add_input_work

   !> Number of DOFs.
   pure integer function newmark_n(st)
      !> Integrator state.
      class(newmark_state), intent(in) :: st

      newmark_n = st%n
   end function newmark_n

   !> The time step (s).
   pure real(dp) function newmark_dt(st)
      !> Integrator state.
      class(newmark_state), intent(in) :: st

      newmark_dt = st%dt
   end function newmark_dt

   !> Relative displacements at the current time (a view of the state: `st` must be a target).
   function newmark_u(st) result(p)
      !> Integrator state.
      class(newmark_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%u
   end function newmark_u

   !> Relative velocities at the current time (a view of the state).
   function newmark_v(st) result(p)
      !> Integrator state.
      class(newmark_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%v
   end function newmark_v

   !> Relative accelerations at the current time (a view of the state).
   function newmark_a(st) result(p)
      !> Integrator state.
      class(newmark_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%a
   end function newmark_a

   !> Displacement increment of the step in progress (a view of the state).
   function newmark_du(st) result(p)
      !> Integrator state.
      class(newmark_state), intent(in), target :: st
      real(dp), pointer, contiguous :: p(:)

      p => st%du
   end function newmark_du

   !> u of DOF i at the current time.
   pure real(dp) function newmark_u_at(st, i)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i

      newmark_u_at = st%u(i)
   end function newmark_u_at

   !> v of DOF i at the current time.
   pure real(dp) function newmark_v_at(st, i)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i

      newmark_v_at = st%v(i)
   end function newmark_v_at

   !> u + du of DOF i: the displacement at the end of the step in progress as predicted so far.
   pure real(dp) function newmark_predicted(st, i)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i

      newmark_predicted = st%u(i) + st%du(i)
   end function newmark_predicted

   !> The motion of DOF i within the step in progress as predicted so far: average
   !> acceleration gives u(s) = u0 + v0 s + am s^2/2 for 0 <= s <= dt, with am the mean of the
   !> accelerations at the ends (u(dt) = u + du).
   pure subroutine newmark_path(st, i, u0, v0, am)
      !> Integrator state with the predicted `du`.
      class(newmark_state), intent(in) :: st
      !> DOF.
      integer, intent(in) :: i
      !> Displacement and velocity at the start of the step, mean acceleration of the step.
      real(dp), intent(out) :: u0, v0, am

      u0 = st%u(i)
      v0 = st%v(i)
      am = 0.5_dp*(st%c1*st%du(i) - 2.0_dp*st%c2*st%v(i))
   end subroutine newmark_path

   !> The running energies of the integrator (kJ): input work, kinetic, strain and damping
   !> energy at the current time (indices `en_input`, `en_kinetic`, `en_strain`, `en_damping`).
   pure function newmark_energies(st) result(e)
      !> Integrator state.
      type(newmark_state), intent(in) :: st
      real(dp) :: e(4)

      e = [st%input_work, st%kinetic, st%strain, st%damping_energy]
   end function newmark_energies

   !> Add the running energies of the integrator (kJ) to four sums: `newmark_energies`
   !> without an array result (the per-step audit of the coupled analysis, where loading
   !> the result just stored stalls).
   pure subroutine newmark_add_energies(st, w_in, e_kinetic, e_strain, e_damping, e_numerical)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      !> Input work, kinetic, strain and damping energy so far (added to).
      real(dp), intent(inout) :: w_in, e_kinetic, e_strain, e_damping
      !> Numerical dissipation so far (added to: average acceleration has none).
      real(dp), intent(inout) :: e_numerical

      w_in = w_in + st%input_work
      e_kinetic = e_kinetic + st%kinetic
      e_strain = e_strain + st%strain
      e_damping = e_damping + st%damping_energy
      e_numerical = e_numerical + 0.0_dp
   end subroutine newmark_add_energies

   !> Kinetic energy of the relative motion, v^T M v / 2 (kJ).
   pure function kinetic_energy(st, b) result(e)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      real(dp) :: e

      e = 0.5_dp*sum(b%mass*st%v**2)
   end function kinetic_energy

   !> Strain energy including the geometric term, u^T (K+G) u / 2 (kJ): see
   !> `structure_strain_energy`; on the banded path of a model without storey weights (a
   !> frame) the integrator's own u . (K+G) u / 2 from the carried (K+G) u (O(n), no band
   !> product; equal to the band product to round-off, exact on refresh steps).
   pure function strain_energy(st, b) result(e)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      real(dp) :: e

      if (.not. st%tridiagonal .and. .not. allocated(b%strain_weight)) then
         e = st%strain
      else
         e = structure_strain_energy(b, st%u)
      end if
   end function strain_energy

   !> `newmark_init` as the integrator's `init`.
   subroutine init_binding(st, b, dt, ag0, error, general, refresh, exact)
      !> Integrator state.
      class(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Time step and ground acceleration at t = 0.
      real(dp), intent(in) :: dt, ag0
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> As `newmark_init`.
      logical, intent(in), optional :: general
      !> As `newmark_init`.
      integer, intent(in), optional :: refresh
      !> As `newmark_init`.
      logical, intent(in), optional :: exact

      call newmark_init(st, b, dt, ag0, error, general, refresh, exact)
   end subroutine init_binding

   !> `newmark_swap_step` as the integrator's `swap_step` (`other` is a Newmark integrator).
   subroutine swap_binding(st, other)
      !> Integrator whose state continues with the other step.
      class(newmark_state), intent(inout) :: st
      !> Integrator of the same model at the other step.
      class(integrator), intent(inout) :: other

      select type (other)
      class is (newmark_state)
         call newmark_swap_step(st, other)
      end select
   end subroutine swap_binding

   !> Velocity per displacement increment of the step: v_{n+1} = c2 du - v_n, c2 = 2/dt.
   pure real(dp) function newmark_velocity_rate(st)
      !> Integrator state.
      class(newmark_state), intent(in) :: st

      newmark_velocity_rate = st%c2
   end function newmark_velocity_rate

   !> The step length along which `newmark_path` is evaluated, 2/c2 (s).
   pure real(dp) function newmark_path_span(st)
      !> Integrator state.
      class(newmark_state), intent(in) :: st

      newmark_path_span = 2.0_dp/st%c2
   end function newmark_path_span

   !> `newmark_energies` and a numerical dissipation of zero (average acceleration conserves
   !> the energy of a free undamped system).
   pure function energies_binding(st) result(e)
      !> Integrator state.
      class(newmark_state), intent(in) :: st
      real(dp) :: e(n_integrator_energies)

      e = 0.0_dp
      e(1:4) = newmark_energies(st)
   end function energies_binding

end module pound_newmark
