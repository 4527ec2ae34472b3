!> The integrator interface: what the time loop (`pound_analysis`), contact
!> (`pound_contact`, `pound_contact_system`) and the reports see of the time integration of
!> one structural model.
!>
!> An integrator holds its state privately (u, v, a of the model, the step's increment du,
!> its factored effective matrix Khat and its running energies). A step is `predict` (the
!> increment du for the ground acceleration alone), then any number of `add_load` /
!> `add_load_rows` (contact: du += s Khat^{-1} w, with Khat^{-1} w from `solve`, computed
!> once), then `commit`. `advance` is `commit` and the next step's `predict` in one call
!> (a run without constraints). Contact reads the predicted end displacements
!> (`predicted`), the motion inside the step (`path`, over `path_span`) and the velocity per
!> displacement increment (`velocity_rate`: v_{n+1} = velocity_rate du + terms of the state
!> at t_n) and never a constant of a particular method. Every load of a step (the joints',
!> the bilinear storeys' and hinges' plastic loads) enters through `add_load`/`add_load_rows`,
!> which keep it where the method needs it (HHT-alpha's F_{n+1}); the views (`u_view` ...
!> `du_view`) are read only outside `src/solver/`; an element that forms a tangent system on
!> the step's matrix takes it from `solve_matrix` (the matrix `solve` inverts), and a frozen
!> building's step is `hold`. `properties` says what the method is (its name, which the
!> writers print) and can do (exact steps, lanes, dissipation).
!>
!> **Lanes.** An integrator may also advance up to `max_lanes` right-hand sides at once: the
!> same model under several ground motions (the uncoupled runs of a suite's motions), sharing
!> the factored Khat. `start_lanes` starts every lane at rest (after `init`), `advance_lanes`
!> takes one step of every lane (commit and predict in one; the running peaks of the response
!> points and the lanes' energy sums as `advance` adds them), `show_lane` makes lane l's state
!> the integrator's own state (u, v, a, energies: what `u_view`, `energies`,
!> `kinetic_energy`, ... then read) and `drop_lane` brings a lane to rest. The one time loop
!> (`integrate`, `pound_analysis`) drives them; an integrator without lanes keeps the defaults
!> below (`lanes_for` false, `start_lanes` an error).
!>
!> Extensions: Newmark average acceleration (`newmark_state`, `pound_newmark`, with its
!> tridiagonal, banded, batched and exact paths in submodules), HHT-alpha (`hht_state`,
!> `pound_hht`). `pound_integrators` allocates the one the analysis plan names.
module pound_integrator
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_structure, only: structure_model
   implicit none
   private

   public :: integrator, integrator_properties, trapezoid_rate, max_lanes, default_start_load
   public :: en_input, en_kinetic, en_strain, en_damping, en_numerical, n_integrator_energies

   !> Indices of `energies`: input work, kinetic, strain and viscous damping energy, and the
   !> energy the method itself dissipates (numerical dissipation; zero for Newmark).
   integer, parameter :: en_input = 1, en_kinetic = 2, en_strain = 3, en_damping = 4, en_numerical = 5
   !> Size of `energies`.
   integer, parameter :: n_integrator_energies = 5
   !> Right-hand sides (lanes) advanced together by `advance_lanes` (two AVX2 vectors of
   !> doubles); arrays per lane have this size, lanes without a motion are driven by zero.
   integer, parameter :: max_lanes = 8

   !> What an integrator is and can do (`properties`): the one place the loop, the batch and the
   !> writers ask, in place of tests of the method's kind.
   type :: integrator_properties
      !> The method's name, as the outputs print it ('Newmark', 'HHT-alpha').
      character(len=16) :: name = ''
      !> Average acceleration (no numerical dissipation; alpha = 0 of HHT-alpha).
      logical :: average_acceleration = .false.
      !> It can take exact free steps (`init(..., exact=.true.)`, `predict_exact`).
      logical :: exact_steps = .false.
      !> It can advance lanes (several motions; `lanes_for` says for which models).
      logical :: lanes = .false.
      !> Its numerical dissipation (`en_numerical`) may be non-zero.
      logical :: dissipates = .false.
   end type integrator_properties

   !> The time integration of one structural model (state private to each extension).
   type, abstract :: integrator
   contains
      !> The method's name and capabilities.
      procedure(properties_i), deferred :: properties
      !> Factor Khat for dt, start at rest in equilibrium with the ground acceleration ag0.
      procedure(init_i), deferred :: init
      !> The step's increment du for the ground acceleration increment alone.
      procedure(predict_i), deferred :: predict
      !> Predict the step exactly (exact free steps; an integrator without them predicts), under
      !> the ground along x and, with `ag2_old`, `ag2_new`, the model's second ground component
      !> (along y: `ground_set(:, 2)`), both linear over the step. An integrator with
      !> `exact_steps` takes both; one without predicts by its method under the first alone
      !> (its caller adds the second as load rows).
      procedure(predict_exact_i), deferred :: predict_exact
      !> Drop an exact prediction (the step is predicted again by `predict`).
      procedure(drop_exact_i), deferred :: drop_exact
      !> Complete the step with du, account the energies (optionally add them to two sums).
      procedure(commit_i), deferred :: commit
      !> `commit`, then `predict` of the next step.
      procedure(advance_i), deferred :: advance
      !> x = Khat^{-1} x.
      procedure(solve_i), deferred :: solve
      !> The matrix whose inverse `solve` applies, fk (K+G) + fm M, for Rayleigh damping
      !> C = a0 M + a1 (K+G): its two coefficients (an element that forms a tangent system on
      !> that matrix, `stick_active_set`, takes them from here).
      procedure(solve_matrix_i), deferred :: solve_matrix
      !> du = du + s x for a load increment s at one DOF, x = Khat^{-1} e_dof.
      procedure(add_load_i), deferred :: add_load
      !> du = du + s x for a load increment s along the weights w of the DOFs dof.
      procedure(add_load_rows_i), deferred :: add_load_rows
      !> Hold the model still over the step: du = 0 and no load of the step (a collapsed,
      !> frozen building: its end-of-step displacements are u).
      procedure(drop_exact_i), deferred :: hold
      !> Exchange the step data (dt, constants, factors) with an integrator of the same model
      !> and kind set up for another dt.
      procedure(swap_step_i), deferred :: swap_step
      !> Overwrite the state (tests).
      procedure(set_state_i), deferred :: set_state
      !> Number of DOFs.
      procedure(int_i), deferred :: dofs
      !> Time step (s).
      procedure(real_i), deferred :: step_size
      !> Velocity per displacement increment of the step (1/s).
      procedure(real_i), deferred :: velocity_rate
      !> Length of the step along which `path` is evaluated (s).
      procedure(real_i), deferred :: path_span
      !> The motion of DOF i inside the step as predicted so far: u0 + v0 s + am s^2/2.
      procedure(path_i), deferred :: path
      !> Views of u, v, a and du (pointers into the state of a target).
      procedure(view_i), deferred :: u_view, v_view, a_view, du_view
      !> u, v of DOF i now; u + du of DOF i.
      procedure(at_i), deferred :: u_at, v_at, predicted
      !> The running energies (`en_input` ... `en_numerical`), kJ.
      procedure(energies_i), deferred :: energies
      !> Add input work, kinetic, strain and damping energy and numerical dissipation to five sums.
      procedure(add_energies_i), deferred :: add_energies
      !> Kinetic and strain energy of the state (kJ).
      procedure(model_energy_i), deferred :: kinetic_energy, strain_energy
      !> Lanes: whether the integrator can advance several motions of the model at once.
      procedure :: lanes_for => no_lanes
      !> Lanes: start every lane at rest with its ground acceleration at t = 0 (after `init`).
      procedure :: start_lanes => no_start_lanes
      !> Lanes: one step of every lane, the running peaks and the energy sums.
      procedure :: advance_lanes => no_advance_lanes
      !> Lanes: lane l's state as the integrator's own state.
      procedure :: show_lane => no_lane
      !> Lanes: bring lane l to rest (a motion dropped from the batch).
      procedure :: drop_lane => no_lane
      !> Steps computed elsewhere (the closed steps of `pound_closed_steps`): whether
      !> `put_state` takes in such a step's end.
      procedure :: takes_state => no_takes_state
      !> Put in the end of a step computed elsewhere: u, v, a, the kinetic and strain energy
      !> of that state, the step's input work and the work of the joints' forces on the model
      !> (the damping energy is the balance). The default does nothing (`takes_state` false).
      procedure :: put_state => no_put_state
      !> Add work to the input work (a ground component the step took as a load,
      !> `add_load_rows`: the component along y). Every integrator overrides it (the default
      !> drops the work).
      procedure :: add_input_work => no_input_work
      !> Start at rest under a further load s w at t = 0 along the weights w of the DOFs dof
      !> (a ground component the steps take as load rows: -M r_y a_gy(0)): a_0 += M^-1 s w, and
      !> the loads at t_0 the method keeps (HHT-alpha's F_0). The default sets a through
      !> `set_state` (Newmark's step is incremental: a_0 is all it keeps).
      procedure :: start_load => default_start_load
      !> Take the method's settings (not its state) of another integrator of the same kind, so
      !> that one allocated with `mold=` and then `init` steps by the same method (HHT-alpha's
      !> alpha). The default: a method without settings.
      procedure :: take_settings => no_settings
   end type integrator

   abstract interface
      !> Interface of the binding(s) declared with `properties_i` (see the type).
      pure function properties_i(st) result(p)
         import :: integrator, integrator_properties
         class(integrator), intent(in) :: st
         type(integrator_properties) :: p
      end function properties_i
      !> Interface of the binding(s) declared with `init_i` (see the type).
      subroutine init_i(st, b, dt, ag0, error, general, refresh, exact)
         import :: integrator, structure_model, dp, error_type
         class(integrator), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in) :: dt, ag0
         type(error_type), allocatable, intent(out) :: error
         logical, intent(in), optional :: general
         integer, intent(in), optional :: refresh
         logical, intent(in), optional :: exact
      end subroutine init_i
      !> Interface of the binding(s) declared with `predict_i` (see the type).
      subroutine predict_i(st, b, dag)
         import :: integrator, structure_model, dp
         class(integrator), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: dag
      end subroutine predict_i
      !> Interface of the binding(s) declared with `predict_exact_i` (see the type).
      subroutine predict_exact_i(st, b, ag_old, ag_new, ag2_old, ag2_new)
         import :: integrator, structure_model, dp
         class(integrator), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: ag_old, ag_new
         real(dp), intent(in), optional :: ag2_old, ag2_new
      end subroutine predict_exact_i
      !> Interface of the binding(s) declared with `drop_exact_i` (see the type).
      pure subroutine drop_exact_i(st)
         import :: integrator
         class(integrator), intent(inout) :: st
      end subroutine drop_exact_i
      !> Interface of the binding(s) declared with `commit_i` (see the type).
      subroutine commit_i(st, b, ag_old, ag_new, w_in, e_out)
         import :: integrator, structure_model, dp
         class(integrator), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: ag_old, ag_new
         real(dp), intent(inout), optional :: w_in, e_out
      end subroutine commit_i
      !> Interface of the binding(s) declared with `advance_i` (see the type).
      subroutine advance_i(st, b, ag_old, ag_new, dag_next, w_in, e_out)
         import :: integrator, structure_model, dp
         class(integrator), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), value :: ag_old, ag_new, dag_next
         real(dp), intent(inout) :: w_in, e_out
      end subroutine advance_i
      !> Interface of the binding(s) declared with `solve_i` (see the type).
      subroutine solve_i(st, x)
         import :: integrator, dp
         class(integrator), intent(in) :: st
         real(dp), intent(inout) :: x(:)
      end subroutine solve_i
      !> Interface of the binding(s) declared with `solve_matrix_i` (see the type).
      pure subroutine solve_matrix_i(st, a0, a1, fk, fm)
         import :: integrator, dp
         class(integrator), intent(in) :: st
         real(dp), intent(in) :: a0, a1
         real(dp), intent(out) :: fk, fm
      end subroutine solve_matrix_i
      !> Interface of the binding(s) declared with `add_load_i` (see the type).
      pure subroutine add_load_i(st, s, dof, x)
         import :: integrator, dp
         class(integrator), intent(inout) :: st
         real(dp), intent(in) :: s
         integer, intent(in) :: dof
         real(dp), intent(in) :: x(:)
      end subroutine add_load_i
      !> Interface of the binding(s) declared with `add_load_rows_i` (see the type).
      pure subroutine add_load_rows_i(st, s, dof, w, x)
         import :: integrator, dp
         class(integrator), intent(inout) :: st
         real(dp), intent(in) :: s
         integer, intent(in) :: dof(:)
         real(dp), intent(in) :: w(:)
         real(dp), intent(in) :: x(:)
      end subroutine add_load_rows_i
      !> Interface of the binding(s) declared with `swap_step_i` (see the type).
      subroutine swap_step_i(st, other)
         import :: integrator
         class(integrator), intent(inout) :: st
         class(integrator), intent(inout) :: other
      end subroutine swap_step_i
      !> Interface of the binding(s) declared with `set_state_i` (see the type).
      subroutine set_state_i(st, b, u, v, a)
         import :: integrator, structure_model, dp
         class(integrator), intent(inout) :: st
         type(structure_model), intent(in) :: b
         real(dp), intent(in), optional :: u(:), v(:), a(:)
      end subroutine set_state_i
      !> Interface of the binding(s) declared with `int_i` (see the type).
      pure integer function int_i(st)
         import :: integrator
         class(integrator), intent(in) :: st
      end function int_i
      !> Interface of the binding(s) declared with `real_i` (see the type).
      pure real(dp) function real_i(st)
         import :: integrator, dp
         class(integrator), intent(in) :: st
      end function real_i
      !> Interface of the binding(s) declared with `path_i` (see the type).
      pure subroutine path_i(st, i, u0, v0, am)
         import :: integrator, dp
         class(integrator), intent(in) :: st
         integer, intent(in) :: i
         real(dp), intent(out) :: u0, v0, am
      end subroutine path_i
      !> Interface of the binding(s) declared with `view_i` (see the type).
      function view_i(st) result(p)
         import :: integrator, dp
         class(integrator), intent(in), target :: st
         real(dp), pointer, contiguous :: p(:)
      end function view_i
      !> Interface of the binding(s) declared with `at_i` (see the type).
      pure real(dp) function at_i(st, i)
         import :: integrator, dp
         class(integrator), intent(in) :: st
         integer, intent(in) :: i
      end function at_i
      !> Interface of the binding(s) declared with `energies_i` (see the type).
      pure function energies_i(st) result(e)
         import :: integrator, dp, n_integrator_energies
         class(integrator), intent(in) :: st
         real(dp) :: e(n_integrator_energies)
      end function energies_i
      !> Interface of the binding(s) declared with `add_energies_i` (see the type).
      pure subroutine add_energies_i(st, w_in, e_kinetic, e_strain, e_damping, e_numerical)
         import :: integrator, dp
         class(integrator), intent(in) :: st
         real(dp), intent(inout) :: w_in, e_kinetic, e_strain, e_damping, e_numerical
      end subroutine add_energies_i
      !> Interface of the binding(s) declared with `model_energy_i` (see the type).
      pure function model_energy_i(st, b) result(e)
         import :: integrator, structure_model, dp
         class(integrator), intent(in) :: st
         type(structure_model), intent(in) :: b
         real(dp) :: e
      end function model_energy_i
   end interface

contains

   ! The defaults of the lane bindings (an integrator without lanes) do not need every dummy;
   ! `same_type_as(st, st)` and the like only keep the compiler from warning about them.

   !> Default `lanes_for`: no lanes.
   pure logical function no_lanes(st, b)
      !> Integrator.
      class(integrator), intent(in) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b

      no_lanes = .not. same_type_as(st, st) .and. b%n < 0
   end function no_lanes

   !> Default `start_lanes`: an error (the integrator has no lanes).
   subroutine no_start_lanes(st, b, ag0, error)
      !> Integrator (initialised by `init`).
      class(integrator), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration of each lane at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0(max_lanes)
      !> Error state: always set.
      type(error_type), allocatable, intent(out) :: error

      if (same_type_as(st, st)) call fatal_error(error, 'the integrator of building '//trim(b%name)// &
                                                  ' cannot advance '//str(size(ag0))//' motions at once (internal)')
   end subroutine no_start_lanes

   !> Default `advance_lanes`: nothing (`start_lanes` refused).
   subroutine no_advance_lanes(st, b, ag_old, ag_new, t, peak, peak_time, w_in, e_out)
      !> Integrator.
      class(integrator), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration of each lane at the start and the end of the step (m/s^2).
      real(dp), intent(in) :: ag_old(max_lanes), ag_new(max_lanes)
      !> Time at the end of the step (s).
      real(dp), intent(in) :: t
      !> Running peaks of the response points and their times (max_lanes, 4, n).
      real(dp), intent(inout), contiguous :: peak(:, :, :), peak_time(:, :, :)
      !> Each lane's input work and kinetic + strain + damping energy (added to).
      real(dp), intent(inout) :: w_in(max_lanes), e_out(max_lanes)

      if (same_type_as(st, st) .or. b%n < 0) return
      w_in = w_in + 0.0_dp*(ag_old + ag_new + t + peak(1, 1, 1) + peak_time(1, 1, 1) + e_out)
   end subroutine no_advance_lanes

   !> Default `show_lane`, `drop_lane`: nothing.
   subroutine no_lane(st, l)
      !> Integrator.
      class(integrator), intent(inout) :: st
      !> Lane.
      integer, intent(in) :: l

      if (same_type_as(st, st) .or. l < 1) return
   end subroutine no_lane

   !> Default `takes_state`: no.
   pure logical function no_takes_state(st)
      !> Integrator.
      class(integrator), intent(in) :: st

      no_takes_state = .not. same_type_as(st, st)
   end function no_takes_state

   !> Default `put_state`: nothing (`takes_state` is false).
   pure subroutine no_put_state(st, u, v, a, kinetic, strain, work, joint_work)
      !> Integrator.
      class(integrator), intent(inout) :: st
      !> Displacement, velocity and acceleration at the end of the step (n each).
      real(dp), intent(in) :: u(:), v(:), a(:)
      !> Kinetic and strain energy of that state (kJ).
      real(dp), intent(in) :: kinetic, strain
      !> Input work of the step and work of the joints' forces on the model (kJ).
      real(dp), intent(in) :: work, joint_work

      if (same_type_as(st, st) .or. size(u) + size(v) + size(a) < 0) return
      if (kinetic + strain + work + joint_work < 0.0_dp) return
   end subroutine no_put_state

   !> Default `start_load`: a_0 += M^-1 s w at the DOFs with mass (`set_state`).
   subroutine default_start_load(st, b, s, dof, w)
      !> Integrator at t = 0.
      class(integrator), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Load factor (m/s^2: -a_gy(0)).
      real(dp), intent(in) :: s
      !> DOFs and weights (m_i r_i).
      integer, intent(in) :: dof(:)
      real(dp), intent(in) :: w(:)
      real(dp), pointer :: a(:)
      real(dp), allocatable :: a0(:)
      integer :: i

      if (s == 0.0_dp) return
      a => st%a_view()
      a0 = a
      do i = 1, size(dof)
         if (b%mass(dof(i)) > 0.0_dp) a0(dof(i)) = a0(dof(i)) + s*(w(i)/b%mass(dof(i)))
      end do
      call st%set_state(b, a=a0)
   end subroutine default_start_load

   !> Default `take_settings`: nothing (a method without settings of its own).
   pure subroutine no_settings(st, other)
      !> Integrator (not yet set up).
      class(integrator), intent(inout) :: st
      !> The integrator whose settings it takes.
      class(integrator), intent(in) :: other

      if (same_type_as(st, other)) return
   end subroutine no_settings

   !> Default `add_input_work`: nothing (an integrator that cannot take a ground load).
   pure subroutine no_input_work(st, w)
      !> Integrator state.
      class(integrator), intent(inout) :: st
      !> Work (kJ).
      real(dp), intent(in) :: w

      if (same_type_as(st, st) .or. w < 0.0_dp) return
   end subroutine no_input_work

   !> The velocity per displacement increment of the trapezoidal rule, 2/dt (1/s): the
   !> default rate of a joint's compression when no integrator is given
   !> (`contact_init_flexibility`).
   pure real(dp) function trapezoid_rate(dt)
      !> Time step (s).
      real(dp), intent(in) :: dt

      trapezoid_rate = 2.0_dp/dt
   end function trapezoid_rate

end module pound_integrator
