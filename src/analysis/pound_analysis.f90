!> The analyses a deck asks for: the buildings uncoupled (no contact) and coupled.
!>
!> Each building is integrated with Newmark's average acceleration method; in the coupled
!> analysis the contact forces of every step come from the step's LCP (pound_contact). How a
!> step is taken is a step policy's (src/stepping: uniform, exact free steps, impact
!> substeps, closed steps, and the retry with substeps of a step whose solve fails). The response record keeps
!> peaks at every step and histories at output steps, and the energy balance W_input =
!> E_kinetic + E_strain + E_damping + E_contact + E_plastic is audited at every step
!> (E_contact: stored in the joints' springs and dissipated by their dashpots; E_plastic:
!> dissipated by the joints' plastic flow).
!>
!> **Nothing non-finite passes.** The energy sums of every step take in every displacement,
!> velocity, contact force and joint state, so one test per step on their total catches the
!> first NaN or Infinity of the run; only then is the culprit located (building and floor,
!> or joint) and the run stops, naming time and step. The ground acceleration samples are
!> checked before the first step.
!>
!> **Audit warning.** When the relative residual exceeds `audit_warning_limit`, the result
!> carries a warning (`res%warnings`, written by `write_warnings`) naming the likely cause: a
!> joint whose contact half-period pi sqrt(m_eff/k0) spans fewer than `resolved_steps`
!> steps, with the dt that would resolve it.
module pound_analysis
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_constants, only: pi
   use pound_error, only: error_type, fatal_error, error_at
   use pound_strings, only: str, add_warning
   use pound_analysis_plan, only: analysis_plan, output_steps, stepping_impact, free_exact, lcp_lemke
   use pound_structure, only: structure_model
   use pound_ground_motion, only: check_ground_samples, ground_motion_t
   use pound_progress, only: progress_steps, progress_run_done, progress_stride
   use pound_integrator, only: integrator, integrator_properties, max_lanes, en_input, en_damping, en_numerical, &
                               n_integrator_energies
   use pound_integrators, only: integrators_for
   use pound_response, only: response_record, response_init, response_sample, response_finish, history_sink, &
                             response_store, &
                             response_flush, history_block, deformed_limit, response_block_full, response_release
   use pound_contact, only: contact_system, contact_pair, contact_init, &
                            joint_history, joint_history_init, joint_history_record, &
                            lcp_solver_lemke, contact_track_closing
   use pound_deck_variables, only: max_substeps
   use pound_contact_friction, only: friction_history_record
   use pound_storey_yield, only: storey_yield_set, storey_yield_result, yield_sets_init, &
                                 yield_sample, yield_results, yield_energy_step
   use pound_storey_collapse, only: yield_hold, yield_freeze
   use pound_contact_period, only: joint_half_period, substep_impact_speed
   use pound_step_policy, only: step_policy, step_state, step_counts, uniform_policy, step_state_point, ground_rows_of
   use pound_step_exact, only: exact_policy
   use pound_step_impact, only: impact_policy, impact_setup
   use pound_step_closed, only: closed_policy, closed_setup
   use pound_step_retry, only: retry_policy
   implicit none
   private

   public :: analysis_result, run_uncoupled, run_coupled, history_sink
   public :: coupled_model, coupled_prepare, coupled_integrate, beyond_closing, probe_gap
   public :: e_input, e_kinetic, e_strain, e_damping, e_contact, e_plastic, n_energy, energy_names
   public :: add_warning, write_warnings, audit_warning_limit, resolved_steps
   public :: substeps_per_half_period, impact_substeps_of, contact_half_period, substep_text, exact_text
   public :: start_result, audit_error, uncoupled_audit_warning, analysis_copy
   public :: flush_full_blocks, store_energy, run_lanes

   !> Relative energy residual above which the result carries a warning.
   real(dp), parameter :: audit_warning_limit = 1.0e-2_dp
   !> A joint is resolved when its contact half-period spans at least this many steps; the
   !> warning recommends a dt of a tenth of the half-period.
   real(dp), parameter :: resolved_steps = 5.0_dp
   !> `stepping = 'impact'` without `impact_substeps`: the substep is at most the shortest
   !> contact half-period pi sqrt(m_eff/k0) divided by this.
   real(dp), parameter :: substeps_per_half_period = 40.0_dp
   !> The same with exact free steps (`free_steps = 'exact'`), whose error is then the contact
   !> substeps' alone.
   real(dp), parameter, public :: substeps_per_half_period_exact = 60.0_dp
   !> A gap no joint closes (m): `coupled_integrate` with every gap at it and `track` is the
   !> buildings' uncoupled motion with the coupled analysis's own sums, and records per joint
   !> the largest closing displacement its steps predict with every force released
   !> (`cs%closing_max`). A run whose every gap is `beyond_closing` those values has no step
   !> in which a joint can act (no LCP, no substep): it follows the same states bit for bit
   !> and gives the same result.
   real(dp), parameter :: probe_gap = 0.25_dp*huge(1.0_dp)
   !> `beyond_closing`: a gap counts as beyond a joint's largest closing displacement c when it
   !> is at least c + `closing_margin` |c| (room for the round-off of the path's vertex).
   real(dp), parameter :: closing_margin = 1.0e-9_dp

   !> Energy history components.
   integer, parameter :: e_input = 1, e_kinetic = 2, e_strain = 3, e_damping = 4, e_contact = 5
   integer, parameter :: e_plastic = 6
   integer, parameter :: n_energy = 6
   !> The step's energy sample also holds the integrators' numerical dissipation (zero for
   !> average acceleration), after the `n_energy` components of the history.
   integer, parameter :: e_numerical = n_energy + 1
   !> Energy component names (HDF5 attribute, listing).
   character(len=*), parameter :: energy_names(n_energy) = &
      [character(len=8) :: 'input', 'kinetic', 'strain', 'damping', 'contact', 'plastic']

   !> Result of one analysis (all buildings).
   type :: analysis_result
      !> Number of steps and of output samples.
      integer :: n_steps = 0, n_out = 0
      !> Output times (s).
      real(dp), allocatable :: time(:)
      !> One record per building, in deck order.
      type(response_record), allocatable :: building(:)
      !> Energy history (n_energy, n_out), summed over the buildings (kJ).
      real(dp), allocatable :: energy(:, :)
      !> Numerical dissipation of the integrators at the output times, summed over the buildings
      !> (kJ; allocated when the integrator dissipates: HHT-alpha with alpha < 0). The energy audit
      !> counts it among the terms that balance the input.
      real(dp), allocatable :: numerical(:)
      !> The integrator's name (its `properties()%name`, set by `integrate`), as the writers
      !> print it.
      character(len=:), allocatable :: integrator
      !> Audit: max over all steps of |W_in - sum of the other terms| / max energy scale.
      real(dp) :: energy_error = 0.0_dp
      !> Warnings for the user (e.g. a large audit residual and its likely cause), one per
      !> element (trailing blanks not significant); size 0 when there are none.
      character(len=:), allocatable :: warnings(:)
      !> Joint histories (force, closing displacement, compression, plastic penetration,
      !> state; n_pairs x n_out); allocated in the coupled analysis only.
      type(joint_history) :: joints
      !> Wall-clock time of the time-step loops (s; set-up and output excluded), and the part
      !> of it spent solving the contact LCPs (assembly, Lemke, checks, re-solves, in the steps
      !> where a joint is closed or predicted to close: `contact_system%stats%lcp_seconds`; forming
      !> q, applying and committing the forces are not in it). Streamed histories: the blocks
      !> handed to the sink during the loop are written in `write_seconds`, not in `seconds`.
      real(dp) :: seconds = 0.0_dp, contact_seconds = 0.0_dp, write_seconds = 0.0_dp
      !> `stepping = 'impact'`: substeps per impact step (0: uniform stepping), the steps taken
      !> as substeps and the substeps taken.
      integer :: substep_factor = 0, substepped = 0, substeps = 0
      !> The substep dt/m (s; 0: uniform stepping).
      real(dp) :: substep = 0.0_dp
      !> `free_steps = 'exact'`: the steps taken exactly (no joint acting; -1: free steps by
      !> Newmark).
      integer :: exact_steps = -1
      !> Of those, the steps taken exactly with elastic joints closed (pound_closed_steps).
      integer :: closed_steps = 0
      !> Bilinear storeys (pound_storey_yield): one result a building; unallocated: all elastic.
      type(storey_yield_result), allocatable :: yielding(:)
   end type analysis_result

   !> What the coupled analysis needs that does not depend on the gaps: the factored
   !> integrators at rest and the condensed constraints (Khat^{-1} B, F). Prepared once,
   !> reused for every gap of a sweep.
   type :: coupled_model
      !> Integrators at t = 0.
      class(integrator), allocatable :: st(:)
      !> Contact system at t = 0.
      type(contact_system) :: cs
      !> `stepping = 'impact'`: substeps per impact step (0: uniform stepping), and the
      !> integrators and the condensed constraints at the substep dt/m (only their step data
      !> are used: `integrator%swap_step`, `contact_swap_step`).
      integer :: substeps = 0
      class(integrator), allocatable :: st_sub(:)
      type(contact_system) :: cs_sub
   end type coupled_model

   !> The integrator's u, v, a of one building, taken once before the time loop.
   type :: state_view
      real(dp), pointer, contiguous :: u(:) => null(), v(:) => null(), a(:) => null()
   end type state_view

   !> The lanes of a batched run (`integrate` with `lanes`, set up by `run_lanes`): up to
   !> `max_lanes` motions of the same buildings, advanced together by the integrators. Lane 1
   !> is `integrate`'s own `ag` and `res`, lane l > 1 `ag(:, l)` and `more(l - 1)` here.
   type :: lane_runs
      !> Lanes that carry a motion (1..n).
      integer :: n = 0
      !> Ground acceleration of every lane (0:n_steps, n) (m/s^2).
      real(dp), pointer, contiguous :: ag(:, :) => null()
      !> Results of lanes 2..n.
      type(analysis_result), pointer :: more(:) => null()
      !> Whether each lane runs (a lane is dropped when its state stops being finite).
      logical :: live(max_lanes) = .false.
   end type lane_runs

   !> Running peaks of one building for the lanes, (max_lanes, 4, n): u, v, a_abs, drift.
   type :: lane_peaks
      !> Peaks and the times they first occurred (s).
      real(dp), allocatable :: peak(:, :, :), time(:, :, :)
   end type lane_peaks

   !> The cold part of the analyses, in submodule pound_analysis_reports: the result copy, the
   !> warnings and their text (and a joint's effective mass), and the failure diagnostics of a step that is not finite.
   interface
      !> dst = src, component by component, but the substep counts of `stepping = 'impact'`
      !> (the warnings, an array of deferred-length strings, line by line: gfortran 12 does not
      !> copy such a component of a derived type reliably).
      module subroutine analysis_copy(src, dst)
         !> The result copied.
         type(analysis_result), intent(in) :: src
         !> The copy.
         type(analysis_result), intent(out) :: dst
      end subroutine analysis_copy
      !> The warning of an uncoupled run whose relative audit residual `err` exceeds
      !> `audit_warning_limit`.
      pure module function uncoupled_audit_warning(err) result(text)
         !> Relative residual of the energy audit.
         real(dp), intent(in) :: err
         character(len=:), allocatable :: text
      end function uncoupled_audit_warning
      !> The substeps an analysis with `stepping = 'impact'` took, as one line of text.
      module function substep_text(res) result(text)
         !> The result.
         type(analysis_result), intent(in) :: res
         character(len=:), allocatable :: text
      end function substep_text
      !> The steps an analysis with `free_steps = 'exact'` took exactly, as one line of text.
      module function exact_text(res) result(text)
         !> The result.
         type(analysis_result), intent(in) :: res
         character(len=:), allocatable :: text
      end function exact_text
      !> Write each warning of a list (e.g. `res%warnings`, `sweep%warnings`) as one line, `prefix`
      !> first (e.g. 'pound: warning: '); nothing for an empty or unallocated list.
      module subroutine write_warnings(unit, warnings, prefix)
         !> Open formatted unit.
         integer, intent(in) :: unit
         !> The warnings.
         character(len=:), allocatable, intent(in) :: warnings(:)
         !> Text put before each warning.
         character(len=*), intent(in) :: prefix
      end subroutine write_warnings
      !> The audit residual is large: name the joints whose contact half-period pi sqrt(m_eff/k0)
      !> (m_eff = m1 m2/(m1 + m2) of the facing floor masses) spans fewer than `resolved_steps`
      !> steps, and the dt that would resolve them (a tenth of the half-period).
      module subroutine warn_unresolved_joints(res, models, cs, dt)
         !> The coupled result (its warnings extended).
         type(analysis_result), intent(inout) :: res
         !> The buildings.
         type(structure_model), intent(in) :: models(:)
         !> The contact system at the end of the run.
         type(contact_system), intent(in) :: cs
         !> The step (s) the joints are judged by.
         real(dp), intent(in) :: dt
      end subroutine warn_unresolved_joints
      !> The energy sum of a step is not finite: name the first non-finite value (building and
      !> floor, or joint), or else the building and energy term that overflowed, with the largest
      !> ground acceleration so far.
      module subroutine state_failure(st, models, cs, sample, ag, dt, step, error)
         !> Integrator states at the end of the step.
         class(integrator), intent(in), target :: st(:)
         !> The buildings.
         type(structure_model), intent(in) :: models(:)
         !> The contact system.
         type(contact_system), intent(in) :: cs
         !> The step's energy sample (n_energy), not finite in total.
         real(dp), intent(in) :: sample(:)
         !> Ground acceleration samples (m/s^2) from step 0.
         real(dp), intent(in) :: ag(0:)
         !> Time step (s).
         real(dp), intent(in) :: dt
         !> The step that failed.
         integer, intent(in) :: step
         !> Error state: what is not finite, where and when.
         type(error_type), allocatable, intent(out) :: error
      end subroutine state_failure
      !> Set `error` to the first value of the state that is not finite, if there is one: u, v,
      !> a (and, if `predicted`, the step's increment du) of every building by floor, then every
      !> joint's force, compression, rate, plastic penetration and closing displacement. An
      !> `error` passed in is kept when everything is finite.
      module subroutine locate_nonfinite(st, models, cs, t, step, error, predicted)
         !> Integrator states.
         class(integrator), intent(in), target :: st(:)
         !> The buildings.
         type(structure_model), intent(in) :: models(:)
         !> The contact system.
         type(contact_system), intent(in) :: cs
         !> Time (s) named in the message.
         real(dp), intent(in) :: t
         !> Step named in the message.
         integer, intent(in) :: step
         !> Error state: set to the first non-finite value (kept when all is finite).
         type(error_type), allocatable, intent(inout) :: error
         !> Also check the step's increment du (the state was predicted).
         logical, intent(in), optional :: predicted
      end subroutine locate_nonfinite
      !> m_eff = m1 m2/(m1 + m2) of a joint's facing floor masses (the mass of the one
      !> building against a rigid neighbour) (t).
      pure module function effective_mass(p, models) result(meff)
         !> The constraint, its DOFs located.
         type(contact_pair), intent(in) :: p
         !> The buildings.
         type(structure_model), intent(in) :: models(:)
         real(dp) :: meff
      end function effective_mass
      !> Integrate every building without contact: the coupled run with no constraints.
      module subroutine run_uncoupled(cfg, models, ag, res, error, sink)
         !> The analysis plan (`&analysis`).
         type(analysis_plan), intent(in) :: cfg
         !> The buildings.
         type(structure_model), intent(in) :: models(:)
         !> Ground acceleration at t_n = n dt, n = 0..n_steps (m/s^2).
         real(dp), intent(in) :: ag(0:)
         !> The result.
         type(analysis_result), intent(out) :: res
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
         !> Where the histories are streamed (none: held whole in `res`).
         class(history_sink), intent(inout), optional :: sink
      end subroutine run_uncoupled
      !> The coupled time integration from a prepared model (left unchanged, so that it can be
      !> reused); `gaps`, when given, replace the gaps of the constraints.
      module subroutine coupled_integrate(cfg, models, ag, prep, res, cs, error, gaps, ground, sink, track)
         !> The analysis plan (`&analysis`).
         type(analysis_plan), intent(in) :: cfg
         !> The buildings.
         type(structure_model), intent(in) :: models(:)
         !> Ground acceleration at t_n = n dt, n = 0..n_steps (m/s^2).
         real(dp), intent(in) :: ag(0:)
         !> The prepared model.
         type(coupled_model), intent(in) :: prep
         !> The result.
         type(analysis_result), intent(out) :: res
         !> The contact system at the end (statistics per pair and of the LCPs).
         type(contact_system), intent(out) :: cs
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
         !> Gaps of the constraints (m), one per constraint.
         real(dp), intent(in), optional :: gaps(:)
         !> The ground motion `ag` samples (needed by `stepping = 'impact'`).
         type(ground_motion_t), intent(in), optional :: ground
         !> Where the histories are streamed (none: held whole in `res`).
         class(history_sink), intent(inout), optional :: sink
         !> Record the joints' largest closing displacements in `cs%closing_max`
         !> (`contact_track_closing`; default: no).
         logical, intent(in), optional :: track
      end subroutine coupled_integrate
      !> The uncoupled runs of the motions `ag(:, m)` (m = 1..size(ag, 2) <= `max_lanes`) on the
      !> buildings at once, by the one time loop with the integrators' lanes (`integrate`; each
      !> motion's result as its own `run_uncoupled` gives it).
      module subroutine run_lanes(cfg, models, ag, res, ok)
         !> The analysis plan (`&analysis`; average acceleration, no exact free steps).
         type(analysis_plan), intent(in) :: cfg
         !> The buildings (every integrator's `lanes_for`).
         type(structure_model), intent(in) :: models(:)
         !> Ground acceleration of each motion (0:n_steps, n_motions) (m/s^2).
         real(dp), intent(in), target, contiguous :: ag(0:, :)
         !> Results, set up by `start_result` where `ok`; completed where `ok` stays true.
         type(analysis_result), intent(inout), target :: res(:)
         !> Whether each motion runs / ran (otherwise: run it with `run_uncoupled`).
         logical, intent(inout) :: ok(:)
      end subroutine run_lanes
   end interface

contains

   !> Integrate all buildings together with the unilateral constraints `pairs`.
   subroutine run_coupled(cfg, models, ag, pairs, res, cs, error, ground, sink)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration at t_n = n dt, n = 0..n_steps (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The constraints, at rest and open at t = 0.
      type(contact_pair), intent(in) :: pairs(:)
      !> The result.
      type(analysis_result), intent(out) :: res
      !> The contact system at the end (statistics per pair and of the LCPs).
      type(contact_system), intent(out) :: cs
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples (needed by `stepping = 'impact'`, which evaluates it
      !> at the substep times).
      type(ground_motion_t), intent(in), optional :: ground
      !> Where the histories are streamed (none: held whole in `res`).
      class(history_sink), intent(inout), optional :: sink
      type(coupled_model) :: prep

      call coupled_prepare(cfg, models, ag(0), pairs, prep, error)
      if (allocated(error)) return
      call coupled_integrate(cfg, models, ag, prep, res, cs, error, ground=ground, sink=sink)
   end subroutine run_coupled

   !> Factor every building's Khat and condense the structure onto the constraints.
   subroutine coupled_prepare(cfg, models, ag0, pairs, prep, error)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0
      !> The constraints, at rest and open at t = 0.
      type(contact_pair), intent(in) :: pairs(:)
      !> The prepared model.
      type(coupled_model), intent(out) :: prep
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: ib

      call integrators_for(cfg, size(models), prep%st)
      call check_ground_samples([ag0], cfg%dt, error)
      if (allocated(error)) return
      do ib = 1, size(models)
         call prep%st(ib)%init(models(ib), cfg%dt, ag0, error, exact=cfg%free_steps == free_exact)
         if (allocated(error)) return
      end do
      call contact_init(prep%cs, pairs, prep%st, models, error)
      if (allocated(error)) return
      if (cfg%lcp_solver == lcp_lemke) prep%cs%solver = lcp_solver_lemke
      if (cfg%stepping /= stepping_impact .or. size(pairs) == 0) return
      ! Impact-aware substeps: Khat and F factored once more, for dt/m.
      prep%substeps = impact_substeps_of(cfg, models, prep%cs)
      call integrators_for(cfg, size(models), prep%st_sub)
      do ib = 1, size(models)
         call prep%st_sub(ib)%init(models(ib), cfg%dt/real(prep%substeps, dp), ag0, error)
         if (allocated(error)) return
      end do
      call contact_init(prep%cs_sub, pairs, prep%st_sub, models, error)
      prep%cs_sub%solver = prep%cs%solver
   end subroutine coupled_prepare

   !> Substeps per impact step: `impact_substeps` when given, else the least m for which
   !> dt/m is at most the shortest contact half-period of the joints (`joint_half_period`: the
   !> facing masses, or for an end without mass its condensed mass and point stiffness) divided by
   !> `substeps_per_half_period` (`substeps_per_half_period_exact` with exact free steps; at
   !> least 2, at most `max_substeps`).
   integer function impact_substeps_of(cfg, models, cs) result(m)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The constraints, their DOFs located (`contact_init`).
      type(contact_system), intent(in) :: cs
      real(dp) :: half, per_half
      integer :: k

      if (cfg%impact_substeps > 0) then
         m = cfg%impact_substeps
         return
      end if
      half = huge(1.0_dp)
      do k = 1, cs%m
         half = min(half, joint_half_period(cs%pair(k), models))
      end do
      per_half = substeps_per_half_period
      if (cfg%free_steps == free_exact) per_half = substeps_per_half_period_exact
      m = max(2, min(max_substeps, ceiling(per_half*cfg%dt/half - 1.0e-9_dp)))
   end function impact_substeps_of

   !> Contact half-period pi sqrt(m_eff/k0) of a joint (s), m_eff = m1 m2/(m1 + m2) of the
   !> facing floor masses (the mass of the one building against a rigid neighbour); of a
   !> smooth law, its contact duration at `substep_impact_speed` (pound_law_impact).
   pure real(dp) function contact_half_period(p, models) result(half)
      !> The constraint, its DOFs located.
      type(contact_pair), intent(in) :: p
      !> The buildings.
      type(structure_model), intent(in) :: models(:)

      half = pi*sqrt(effective_mass(p, models)/p%law%stiffness)
      ! A smooth law (issue 26): its contact duration at `substep_impact_speed`.
      if (.not. allocated(p%law%given)) return
      if (.not. p%law%given%has_force()) return
      half = p%law%given%contact_duration(effective_mass(p, models), 0.0_dp, substep_impact_speed)
   end function contact_half_period

   !> Whether every gap is beyond its joint's largest closing displacement (`probe_gap`)
   !> (by `closing_margin`): a run with these gaps is the probe's run.
   pure logical function beyond_closing(gaps, closing_max)
      !> Gap of each joint (m).
      real(dp), intent(in) :: gaps(:)
      !> Largest closing displacement of each joint (m; `probe_gap`).
      real(dp), intent(in) :: closing_max(:)

      beyond_closing = all(gaps >= closing_max + closing_margin*abs(closing_max))
   end function beyond_closing

   ! The rarely taken parts of `integrate`'s step, kept out of its loop so that the loop's
   ! own state stays in registers (public only so that the compiler does not inline them).

   !> Hand the histories' blocks over to the sink when one of them is full; the time spent
   !> is added to `write_ticks`.
   subroutine flush_full_blocks(res, sink, coupled, write_ticks, error)
      !> The result being integrated.
      type(analysis_result), intent(inout) :: res
      !> Where the histories are streamed.
      class(history_sink), intent(inout) :: sink
      !> Whether the run has constraints.
      logical, intent(in) :: coupled
      !> Clock ticks spent writing (added to).
      integer(int64), intent(inout) :: write_ticks
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer(int64) :: w0, w1
      integer :: ib
      logical :: full

      full = .false.
      do ib = 1, size(res%building)
         full = full .or. response_block_full(res%building(ib))
      end do
      if (.not. full) return
      call system_clock(w0)
      do ib = 1, size(res%building)
         call response_flush(res%building(ib), sink, coupled, ib, .true., error)
         if (allocated(error)) return
      end do
      call system_clock(w1)
      write_ticks = write_ticks + (w1 - w0)
   end subroutine flush_full_blocks

   !> The energy sample `k` of an output step (and the joints' history when constrained);
   !> `sample` is set to it.
   subroutine store_energy(res, k, st, models, cs, sample)
      !> The result being integrated.
      type(analysis_result), intent(inout) :: res
      !> Index of the output sample.
      integer, intent(in) :: k
      !> The integrators.
      class(integrator), intent(in) :: st(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The contact system.
      type(contact_system), intent(in) :: cs
      !> The stored sample and the numerical dissipation (`e_numerical`).
      real(dp), intent(out) :: sample(e_numerical)
      real(dp) :: e(n_integrator_energies)
      integer :: ib

      do ib = 1, size(st)
         call add_structure_energy(res%energy(:, k), st(ib), models(ib))
      end do
      if (cs%m > 0) then
         res%energy(e_contact, k) = cs%element_work - cs%plastic_work
         res%energy(e_plastic, k) = cs%plastic_work
         call joint_history_record(res%joints, k, cs%joint)
         if (cs%fr%n > 0) call friction_history_record(res%joints, k, cs%fr, cs%m)
      end if
      sample(1:n_energy) = res%energy(:, k)
      sample(e_numerical) = 0.0_dp
      if (.not. allocated(res%numerical)) return
      do ib = 1, size(st)
         e = st(ib)%energies()
         sample(e_numerical) = sample(e_numerical) + e(en_numerical)
      end do
      res%numerical(k) = sample(e_numerical)
   end subroutine store_energy

   !> Sizes, output times, a zero energy history and (with `n_pairs`) the contact histories
   !> of a result for `n_steps` steps; no warnings yet.
   pure subroutine start_result(res, cfg, n_steps, n_buildings, error, n_pairs)
      !> The result (set up).
      type(analysis_result), intent(inout) :: res
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> Number of time steps.
      integer, intent(in) :: n_steps
      !> Number of buildings.
      integer, intent(in) :: n_buildings
      !> Error state: the histories cannot be allocated.
      type(error_type), allocatable, intent(out) :: error
      !> Number of contact pairs (coupled analysis).
      integer, intent(in), optional :: n_pairs
      integer :: k, stat, n, m

      res%n_steps = n_steps
      res%n_out = output_steps(n_steps, cfg%output_every)
      n = res%n_out
      m = 0
      if (present(n_pairs)) m = n_pairs
      allocate (character(len=1) :: res%warnings(0))
      allocate (res%time(n), res%building(n_buildings), res%energy(n_energy, n), stat=stat)
      if (stat == 0 .and. present(n_pairs)) call joint_history_init(res%joints, m, n, stat)
      if (stat /= 0) then
         call fatal_error(error, 'cannot allocate the time, energy and contact histories: '// &
                          str(n)//' output samples x '//str(1 + n_energy + 5*m)//' values = '// &
                          str(8.0_dp*real(n, dp)*real(1 + n_energy + 5*m, dp)/2.0_dp**20)// &
                          ' MiB; store less often (output_every) or shorten the run (t_end, dt)')
         return
      end if
      res%time = [(real((k - 1)*cfg%output_every, dp)*cfg%dt, k=1, n)]
      res%energy = 0.0_dp
      if (.not. cfg%average_acceleration()) then
         allocate (res%numerical(n), stat=stat)
         if (stat /= 0) then
            call fatal_error(error, 'cannot allocate the numerical dissipation history ('//str(n)//' samples)')
            return
         end if
         res%numerical = 0.0_dp
      end if
   end subroutine start_result

   !> Add one building's input work and kinetic, strain and damping energy to an energy sample.
   pure subroutine add_structure_energy(sample, st, b)
      !> Energy sample (n_energy).
      real(dp), intent(inout) :: sample(:)
      !> Integrator state.
      class(integrator), intent(in) :: st
      !> The building.
      type(structure_model), intent(in) :: b

      real(dp) :: e(n_integrator_energies)

      e = st%energies()
      sample(e_input) = sample(e_input) + e(en_input)
      sample(e_kinetic) = sample(e_kinetic) + st%kinetic_energy(b)
      sample(e_strain) = sample(e_strain) + st%strain_energy(b)
      sample(e_damping) = sample(e_damping) + e(en_damping)
   end subroutine add_structure_energy

   !> Relative energy balance error max_t |residual| / max_t scale (0 when nothing moved).
   pure real(dp) function audit_error(resid, scale) result(err)
      real(dp), intent(in) :: resid, scale

      if (scale > 0.0_dp) then
         err = resid/scale
      else
         err = 0.0_dp
      end if
   end function audit_error

end module pound_analysis
