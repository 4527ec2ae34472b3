!> The one time loop of every analysis, `integrate`, and its entries `run_uncoupled`,
!> `coupled_integrate` and `run_lanes`. How each step is taken is the step policy's
!> (`step_policy`, src/stepping: uniform, exact free steps, impact substeps, closed steps,
!> the retry around them); the loop does what every step shares: the output samples, the
!> response and energy samples of each pass, the energy audit and the test that the state is
!> finite. Lanes (several motions of the same buildings advanced together by the integrators,
!> `integrator%advance_lanes`) are an integrator capability that the loop drives
!> (`lanes_integrate`).
submodule(pound_analysis) pound_analysis_loop
   implicit none

contains

   !> `run_uncoupled` (the interface in `pound_analysis` documents it).
   module procedure run_uncoupled
      class(integrator), allocatable :: st(:)
      type(contact_system) :: cs
      type(uniform_policy) :: uniform
      type(exact_policy) :: exact
      integer :: ib, nb

      res%seconds = 0.0_dp
      call check_ground_samples(ag, cfg%dt, error)
      if (allocated(error)) return
      nb = size(models)
      call start_result(res, cfg, size(ag) - 1, nb, error)
      if (allocated(error)) return
      call integrators_for(cfg, nb, st)
      do ib = 1, nb
         call st(ib)%init(models(ib), cfg%dt, ag(0), error, exact=cfg%free_steps == free_exact)
         if (allocated(error)) return
      end do
      if (cfg%free_steps == free_exact) then
         exact%exact_free = .true.
         call integrate(cfg, models, ag, st, cs, res, error, exact, sink)
      else
         call integrate(cfg, models, ag, st, cs, res, error, uniform, sink)
      end if
   end procedure run_uncoupled

   !> `coupled_integrate` (the interface in `pound_analysis` documents it): the step policy
   !> of the plan (uniform or exact free steps; impact substeps, with closed steps when free
   !> steps are exact) with the retry around it.
   module procedure coupled_integrate
      class(integrator), allocatable :: st(:)
      type(retry_policy) :: pol
      logical :: exact

      call check_ground_samples(ag, cfg%dt, error)
      if (allocated(error)) return
      allocate (st, source=prep%st)
      cs = prep%cs
      if (present(gaps)) cs%pair(:)%gap = gaps
      if (present(track)) then
         if (track) call contact_track_closing(cs)
      end if
      call start_result(res, cfg, size(ag) - 1, size(models), error, cs%m)
      if (allocated(error)) return
      exact = cfg%free_steps == free_exact
      if (prep%substeps == 0 .and. exact) then
         allocate (exact_policy :: pol%inner)
      else if (prep%substeps == 0) then
         allocate (uniform_policy :: pol%inner)
      else if (.not. present(ground)) then
         call fatal_error(error, "&analysis: stepping = 'impact' needs the ground motion itself (internal)")
         return
      else if (exact) then
         allocate (closed_policy :: pol%inner)
      else
         allocate (impact_policy :: pol%inner)
      end if
      pol%inner%exact_free = exact
      select type (p => pol%inner)
      class is (impact_policy)
         call impact_setup(p, prep%substeps, cfg%dt, prep%st_sub, prep%cs_sub, ground)
      end select
      select type (p => pol%inner)
      type is (closed_policy)
         call closed_setup(p, models, cs, cfg%dt)
      end select
      call integrate(cfg, models, ag, st, cs, res, error, pol, sink)
   end procedure coupled_integrate

   !> The time-step loop of every analysis but lanes, from integrators at t = 0 and a contact
   !> system (`cs%m` = 0: no constraints): each step is the policy's `begin` and its passes;
   !> after each pass the response is sampled, the energy audited (with constraints each
   !> term summed over the buildings; without, each building's terms summed first: the
   !> integrators' sums) and the state tested for finiteness; output samples are stored.
   subroutine integrate(cfg, models, ag, st, cs, res, error, pol, sink)
      !> The analysis plan, the buildings, the ground acceleration at t_n = n dt (m/s^2).
      type(analysis_plan), intent(in) :: cfg
      type(structure_model), intent(in), target :: models(:)
      real(dp), intent(in), target :: ag(0:)
      !> Integrators and contact system at t = 0 (at the end on return).
      class(integrator), intent(inout), target :: st(:)
      type(contact_system), intent(inout), target :: cs
      !> The result, set up by `start_result`.
      type(analysis_result), intent(inout), target :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> How each step is taken.
      class(step_policy), intent(inout) :: pol
      !> Where the histories are streamed (none: held whole).
      class(history_sink), intent(inout), optional :: sink
      integer :: ib, step, k, j, until_out, n_steps
      integer(int64) :: c0, c1, rate, write_ticks
      real(dp) :: sample(e_numerical), lcp_start, resid, scale
      type(step_state) :: s
      type(step_counts) :: n
      type(state_view), allocatable :: view(:)
      type(lane_peaks), allocatable :: pk(:)
      real(dp) :: lag(max_lanes)
      logical :: out, coupled, inelastic, collapsed, finite
      logical, target :: frozen(size(models))
      type(storey_yield_set), allocatable, target :: ys(:)
      type(integrator_properties) :: props

      n_steps = size(ag) - 1
      props = st(1)%properties()
      res%integrator = trim(props%name)
      call yield_sets_init(ys, models, cfg, inelastic, collapsed, frozen)
      coupled = cs%m > 0
      call step_state_point(s, st, models, cs, ag, ys, frozen, res%building)
      if (allocated(cfg%ground_y)) call ground_y_setup(s, cfg%ground_y, st, models)
      call pol%start(s, inelastic)
      n = pol%tally()
      res%substep_factor = n%factor
      res%substep = n%h
      lag = ag(0)
      call start_histories(cfg, models, st, coupled, res, view, pk, lag, n%exact, error, sink)
      if (allocated(error)) return
      s%dt = cfg%dt
      call move_alloc(res%warnings, s%warnings)
      k = 1
      resid = 0.0_dp
      scale = 0.0_dp
      lcp_start = cs%stats%lcp_seconds
      write_ticks = 0
      until_out = cfg%output_every
      call system_clock(c0, rate)
      steps: do step = 1, n_steps
         if (mod(step, progress_stride) == 0) call progress_steps(step, n_steps)
         s%step = step
         s%t = real(step, dp)*cfg%dt
         s%t_pass = s%t
         s%h = cfg%dt
         s%ag_old = ag(step - 1)
         s%ag_new = ag(step)
         if (associated(s%ag_y)) then
            s%agy_old = s%ag_y(step - 1)
            s%agy_new = s%ag_y(step)
         end if
         ! out = mod(step, output_every) == 0, counted down (no division per step)
         until_out = until_out - 1
         out = until_out == 0
         if (out) until_out = cfg%output_every
         call pol%begin(s)
         do j = 1, s%passes
            s%pass = j
            s%output = out .and. j == s%passes
            call pol%pass(s, error)
            if (allocated(error)) then
               ! A state that is not finite is named as such, not as a failed LCP.
               if (s%solve_failed) call locate_nonfinite(st, models, cs, s%t_pass, step, error, predicted=.true.)
               if (s%solve_failed) call error_at(error, s%t_pass, step)
               exit steps
            end if
            do ib = 1, size(models)
               if (frozen(ib)) cycle
               call response_sample(res%building(ib), models(ib), view(ib)%u, view(ib)%v, view(ib)%a, &
                                    s%ag_new, s%t_pass, s%output)
               if (inelastic) call yield_sample(ys(ib), view(ib)%u, s%t_pass, s%output, res%building(ib), collapsed)
            end do
            ! The last block is handed over after the loop (writing it is not integration).
            if (s%output .and. present(sink) .and. step < n_steps) then
               call flush_full_blocks(res, sink, coupled, write_ticks, error)
               if (allocated(error)) exit steps
            end if
            if (s%output .or. coupled .or. inelastic) &
               call pass_energy(res, k, st, models, cs, ys, s, coupled, inelastic, sample)
            ! One test per pass: every value of the state feeds these sums.
            if (coupled) then
               finite = abs(sum(sample) + cs%work) <= huge(1.0_dp)
            else
               finite = abs(s%win + s%eout) <= huge(1.0_dp)
            end if
            if (.not. finite) then
               if (.not. coupled) call step_energy(st, sample)
               call state_failure(st, models, cs, sample, ag, cfg%dt, step, error)
               exit steps
            end if
            resid = max(resid, abs(s%win - s%eout))
            scale = max(scale, abs(s%win), s%eout)
            s%ag_old = s%ag_new
            s%agy_old = s%agy_new
         end do
         if (collapsed) call yield_freeze(ys, st, cs, s%t, frozen, collapsed)
         if (collapsed) exit steps
      end do steps
      call move_alloc(s%warnings, res%warnings)
      call take_counts(res, pol%tally(), n_steps, allocated(error))
      if (allocated(error)) return
      if (inelastic) call yield_hold(res%building, res%energy, k, coupled, error, sink)
      if (allocated(error)) return
      call system_clock(c1)
      res%seconds = real(c1 - c0 - write_ticks, dp)/real(rate, dp)
      res%write_seconds = real(write_ticks, dp)/real(rate, dp)
      res%contact_seconds = cs%stats%lcp_seconds - lcp_start
      call finish_run(res, models, cs, ys, inelastic, audit_error(resid, scale), merge(n%h, cfg%dt, n%factor > 0), &
                      error, sink)
   end subroutine integrate

   !> The time-step loop of the lanes (`run_lanes`: several motions of the same buildings, no
   !> constraints, no yielding, no sink): the integrators advance every lane at once
   !> (`advance_lanes`, which also keeps the running peaks of the response points); the
   !> outputs, the energy audit and the test that the state is finite are those of a single
   !> run, lane by lane (at an output step each lane's state is shown to the integrator,
   !> `show_lane`, and stored as a single run stores its own). A lane whose state stops being
   !> finite is dropped (`lanes%live`), not an error.
   subroutine lanes_integrate(cfg, models, st, res, lanes)
      !> The analysis plan, the buildings.
      type(analysis_plan), intent(in) :: cfg
      type(structure_model), intent(in) :: models(:)
      !> Integrators at t = 0, their lanes started (advanced to the end).
      class(integrator), intent(inout), target :: st(:)
      !> Lane 1's result, set up by `start_result` (left alone when lane 1 is not live).
      type(analysis_result), intent(inout), target :: res
      !> The lanes.
      type(lane_runs), intent(inout) :: lanes
      integer :: ib, step, k, until_out, n_steps, l
      integer(int64) :: c0, c1, rate
      real(dp) :: t, sample(e_numerical), win(max_lanes), eout(max_lanes), resid(max_lanes), scale(max_lanes)
      real(dp) :: lag_old(max_lanes), lag_new(max_lanes)
      type(state_view), allocatable :: view(:)
      type(lane_peaks), allocatable :: pk(:)
      type(analysis_result), pointer :: r
      type(contact_system) :: cs
      type(error_type), allocatable :: error

      n_steps = size(lanes%ag, 1) - 1
      call lane_ground(lanes, 0, lag_new)
      call start_histories(cfg, models, st, .false., res, view, pk, lag_new, .false., error, lanes=lanes)
      k = 1
      resid = 0.0_dp
      scale = 0.0_dp
      until_out = cfg%output_every
      call system_clock(c0, rate)
      do step = 1, n_steps
         if (mod(step, progress_stride) == 0) call progress_steps(step, n_steps)
         t = real(step, dp)*cfg%dt
         lag_old = lag_new
         call lane_ground(lanes, step, lag_new)
         until_out = until_out - 1
         win = 0.0_dp
         eout = 0.0_dp
         do ib = 1, size(models)
            call st(ib)%advance_lanes(models(ib), lag_old, lag_new, t, pk(ib)%peak, pk(ib)%time, win, eout)
         end do
         if (until_out == 0) then
            until_out = cfg%output_every
            k = k + 1
            do l = 1, max_lanes
               r => lane_result(res, lanes, l)
               if (.not. lanes%live(l)) cycle
               call show_lane_state(st, models, view, r, l, lag_new(l))
               call store_energy(r, k, st, models, cs, sample)
               win(l) = sample(e_input)
               eout(l) = sum(sample(e_kinetic:e_numerical))
            end do
         end if
         ! One test per step and lane: every value of the state feeds these sums.
         do l = 1, max_lanes
            if (.not. (abs(win(l) + eout(l)) <= huge(1.0_dp))) then
               ! The lane's motion is left to a run of its own, which names the cause.
               call drop_lane(lanes, st, l, lag_new)
               win(l) = 0.0_dp
               eout(l) = 0.0_dp
            end if
            resid(l) = max(resid(l), abs(win(l) - eout(l)))
            scale(l) = max(scale(l), abs(win(l)), eout(l))
         end do
      end do
      call system_clock(c1)
      call lanes_finish(lanes, res, models, pk, resid, scale, real(c1 - c0, dp)/real(rate, dp))
   end subroutine lanes_integrate


   !> The response records at t = 0 (`response_init`, the first sample; when streamed, the
   !> first block handed over) and the views of the integrators' state; with `lanes`, those of
   !> every lane that runs (a lane whose records cannot be set up is dropped) and its peaks.
   subroutine start_histories(cfg, models, st, coupled, res, view, pk, lag, refine, error, sink, lanes)
      !> The analysis plan, the buildings, their integrators at t = 0, constraints present.
      type(analysis_plan), intent(in) :: cfg
      type(structure_model), intent(in) :: models(:)
      class(integrator), intent(inout), target :: st(:)
      logical, intent(in) :: coupled
      !> The result (lane 1's with `lanes`).
      type(analysis_result), intent(inout), target :: res
      !> The views of every integrator's u, v, a; with `lanes`, each building's lane peaks.
      type(state_view), allocatable, intent(out) :: view(:)
      type(lane_peaks), allocatable, intent(out) :: pk(:)
      !> Ground acceleration of each lane at t = 0 (lane 1's only without `lanes`; a dropped
      !> lane's set to zero).
      real(dp), intent(inout) :: lag(max_lanes)
      !> Peaks refined between samples (exact free steps).
      logical, intent(in) :: refine
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Where the histories are streamed.
      class(history_sink), intent(inout), optional :: sink
      !> The lanes.
      type(lane_runs), intent(inout), optional :: lanes
      type(analysis_result), pointer :: r
      integer :: ib, l, nl, capacity

      allocate (view(size(models)))
      nl = 1
      if (present(lanes)) then
         nl = max_lanes
         allocate (pk(size(models)))
      end if
      do ib = 1, size(models)
         if (present(lanes)) allocate (pk(ib)%peak(max_lanes, 4, models(ib)%n), &
                                       pk(ib)%time(max_lanes, 4, models(ib)%n), source=0.0_dp)
         view(ib)%u => st(ib)%u_view()
         view(ib)%v => st(ib)%v_view()
         view(ib)%a => st(ib)%a_view()
         do l = 1, nl
            r => lane_result(res, lanes, l)
            if (present(lanes)) then
               if (.not. lanes%live(l)) cycle
               call st(ib)%show_lane(l)
            end if
            capacity = r%n_out
            if (present(sink)) capacity = history_block(size(models(ib)%floor_dof), r%n_out, sink%block)
            ! Node histories are held whole: the program streams only without them.
            ! Deformed shapes at the storey-shear peaks for models with a DOF layout (frames),
            ! within `deformed_limit`; not with plastic hinges (their storey shears are known
            ! only after the step's hinges are committed, pound_storey_yield_hinges).
            call response_init(r%building(ib), models(ib), cfg%store, capacity, error, &
                               nodes=cfg%node_histories .and. allocated(models(ib)%dof_node) .and. &
                                     .not. present(sink), &
                               snapshots=allocated(models(ib)%dof_node) .and. .not. allocated(models(ib)%hinge_moment) .and. &
                                         real(models(ib)%n, dp)*real(models(ib)%shear%n, dp) <= deformed_limit, &
                               refine=refine)
            if (allocated(error)) then
               if (.not. present(lanes)) return
               deallocate (error)
               call drop_lane(lanes, st, l, lag)
               cycle
            end if
            r%building(ib)%streamed = present(sink)
            call response_sample(r%building(ib), models(ib), view(ib)%u, view(ib)%v, view(ib)%a, lag(l), &
                                 0.0_dp, .true.)
            if (present(lanes)) then
               pk(ib)%peak(l, :, :) = transpose(r%building(ib)%peak(:, 1:4))
               pk(ib)%time(l, :, :) = transpose(r%building(ib)%peak_time(:, 1:4))
            end if
            if (present(sink)) then
               call response_flush(r%building(ib), sink, coupled, ib, .true., error)
               if (allocated(error)) return
            end if
         end do
      end do
   end subroutine start_histories

   !> The energy of a pass: with constraints, the buildings' sums and the joints' terms; at
   !> an output step the stored sample (`store_energy`); with yielding, the storeys' and
   !> hinges' terms (`yield_energy_step`). The audit's input work and energy `s%win`,
   !> `s%eout` are then the sample's (else the integrators' sums of the pass).
   subroutine pass_energy(res, k, st, models, cs, ys, s, coupled, inelastic, sample)
      !> The result, the output samples stored (one more at an output step).
      type(analysis_result), intent(inout) :: res
      integer, intent(inout) :: k
      !> The integrators, the buildings, the contact system, the yield sets.
      class(integrator), intent(in) :: st(:)
      type(structure_model), intent(in) :: models(:)
      type(contact_system), intent(in) :: cs
      type(storey_yield_set), allocatable, intent(inout) :: ys(:)
      !> The pass.
      type(step_state), intent(inout) :: s
      !> Constraints present, yield sets present.
      logical, intent(in) :: coupled, inelastic
      !> The energy sample.
      real(dp), intent(inout) :: sample(e_numerical)

      if (coupled) then
         ! An output step's sample is the stored one (below).
         if (.not. s%output) call step_energy(st, sample)
         sample(e_contact) = cs%element_work - cs%plastic_work
         sample(e_plastic) = cs%plastic_work
      end if
      if (s%output) then
         k = k + 1
         call store_energy(res, k, st, models, cs, sample)
         if (inelastic) call yield_energy_step(ys, .true., coupled, e_strain, e_plastic, res%energy(:, k), &
                                               sample, s%eout)
      else if (inelastic) then
         call yield_energy_step(ys, .false., coupled, e_strain, e_plastic, res%energy(:, k), sample, s%eout)
      end if
      if (.not. (s%output .or. coupled)) return
      s%win = sample(e_input)
      s%eout = sum(sample(e_kinetic:e_numerical))
   end subroutine pass_energy

   !> The policy's counts into the result (the free steps taken exactly only after a run that
   !> did not fail).
   subroutine take_counts(res, n, n_steps, failed)
      !> The result.
      type(analysis_result), intent(inout) :: res
      !> The counts.
      type(step_counts), intent(in) :: n
      !> Steps of the run.
      integer, intent(in) :: n_steps
      !> The run failed.
      logical, intent(in) :: failed

      res%substepped = n%substepped
      res%substeps = n%substeps
      res%closed_steps = n%closed
      if (n%exact .and. .not. failed) res%exact_steps = n_steps - n%method
   end subroutine take_counts

   !> The end of a run that did not fail: the last blocks handed over, the response records
   !> completed, the yield results, the audit and its warning.
   subroutine finish_run(res, models, cs, ys, inelastic, err, h, error, sink)
      !> The result.
      type(analysis_result), intent(inout) :: res
      !> The buildings, the contact system, the yield sets (`inelastic`).
      type(structure_model), intent(in) :: models(:)
      type(contact_system), intent(in) :: cs
      type(storey_yield_set), allocatable, intent(in) :: ys(:)
      logical, intent(in) :: inelastic
      !> The audit's relative residual, and the step (s; the substep with impact substeps).
      real(dp), intent(in) :: err, h
      !> Error state.
      type(error_type), allocatable, intent(inout) :: error
      !> Where the histories are streamed.
      class(history_sink), intent(inout), optional :: sink
      integer :: ib

      if (present(sink)) then
         do ib = 1, size(models)
            call response_flush(res%building(ib), sink, cs%m > 0, ib, .false., error)
            if (allocated(error)) return
            call response_release(res%building(ib))
         end do
      end if
      call progress_run_done()
      do ib = 1, size(models)
         call response_finish(res%building(ib), models(ib))
      end do
      if (inelastic) call yield_results(ys, res%building, res%yielding)
      res%energy_error = err
      if (res%energy_error <= audit_warning_limit) return
      if (cs%m > 0) then
         call warn_unresolved_joints(res, models, cs, h)
      else
         call add_warning(res%warnings, uncoupled_audit_warning(res%energy_error))
      end if
   end subroutine finish_run

   !> `run_lanes` (the interface in `pound_analysis` documents it).
   module procedure run_lanes
      class(integrator), allocatable :: st(:)
      type(lane_runs) :: lanes
      type(error_type), allocatable :: error
      real(dp) :: ag0(max_lanes)
      integer :: nb, ib

      nb = size(models)
      lanes%n = size(ag, 2)
      lanes%live(1:lanes%n) = ok
      if (.not. any(lanes%live)) return
      lanes%ag => ag
      if (lanes%n > 1) lanes%more => res(2:)
      call lane_ground(lanes, 0, ag0)
      call integrators_for(cfg, nb, st)
      do ib = 1, nb
         call st(ib)%init(models(ib), cfg%dt, ag0(1), error)
         if (.not. allocated(error)) call st(ib)%start_lanes(models(ib), ag0, error)
         if (allocated(error)) then
            ok = .false.
            return
         end if
      end do
      call lanes_integrate(cfg, models, st, res(1), lanes)
      ok = lanes%live(1:lanes%n)
   end procedure run_lanes

   !> The result of lane l: `res` for lane 1, `lanes%more(l - 1)` for the others (null for a
   !> lane without a motion).
   function lane_result(res, lanes, l) result(r)
      !> Lane 1's result.
      type(analysis_result), intent(inout), target :: res
      !> The lanes (absent: a single run, lane 1 only).
      type(lane_runs), intent(in), optional :: lanes
      !> Lane.
      integer, intent(in) :: l
      type(analysis_result), pointer :: r

      r => res
      if (l == 1) return
      r => null()
      if (l <= lanes%n) r => lanes%more(l - 1)
   end function lane_result

   !> The buildings' energies at the end of the step, from the integrators' running sums
   !> (contact and plastic terms zero).
   pure subroutine step_energy(st, sample)
      !> Integrator states.
      class(integrator), intent(in) :: st(:)
      !> Energy sample (n_energy).
      real(dp), intent(out) :: sample(:)
      integer :: ib

      sample = 0.0_dp
      do ib = 1, size(st)
         call st(ib)%add_energies(sample(e_input), sample(e_kinetic), sample(e_strain), sample(e_damping), &
                                  sample(e_numerical))
      end do
   end subroutine step_energy

   !> Each lane's ground acceleration at step `step` (zero in the lanes that do not run).
   subroutine lane_ground(lanes, step, g)
      !> The lanes.
      type(lane_runs), intent(in) :: lanes
      !> Step.
      integer, intent(in) :: step
      !> Ground acceleration of each lane (m/s^2).
      real(dp), intent(out) :: g(max_lanes)
      integer :: l

      g = 0.0_dp
      do l = 1, lanes%n
         if (lanes%live(l)) g(l) = lanes%ag(step, l)
      end do
   end subroutine lane_ground

   !> Lane l stops running: brought to rest in every integrator, driven by zero from now on.
   subroutine drop_lane(lanes, st, l, g)
      !> The lanes.
      type(lane_runs), intent(inout) :: lanes
      !> The integrators.
      class(integrator), intent(inout) :: st(:)
      !> Lane.
      integer, intent(in) :: l
      !> Each lane's ground acceleration at the step's end (lane l's set to zero).
      real(dp), intent(inout) :: g(max_lanes)
      integer :: ib

      lanes%live(l) = .false.
      g(l) = 0.0_dp
      do ib = 1, size(st)
         call st(ib)%drop_lane(l)
      end do
   end subroutine drop_lane

   !> Show lane l's state to every integrator and store it as the output sample of its
   !> result `r` (`response_store`).
   subroutine show_lane_state(st, models, view, r, l, ag)
      !> The integrators.
      class(integrator), intent(inout) :: st(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The integrators' u, v, a.
      type(state_view), intent(in) :: view(:)
      !> Lane l's result.
      type(analysis_result), intent(inout) :: r
      !> Lane.
      integer, intent(in) :: l
      !> Lane l's ground acceleration (m/s^2).
      real(dp), intent(in) :: ag
      integer :: ib

      do ib = 1, size(st)
         call st(ib)%show_lane(l)
         call response_store(r%building(ib), models(ib), view(ib)%u, view(ib)%v, view(ib)%a, ag)
      end do
   end subroutine show_lane_state

   !> Complete the results of the lanes that ran: peaks, response records, audit, timing.
   subroutine lanes_finish(lanes, res, models, pk, resid, scale, seconds)
      !> The lanes.
      type(lane_runs), intent(in) :: lanes
      !> Lane 1's result.
      type(analysis_result), intent(inout), target :: res
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The lanes' running peaks per building.
      type(lane_peaks), intent(in) :: pk(:)
      !> Audit: each lane's largest residual and energy scale.
      real(dp), intent(in) :: resid(max_lanes), scale(max_lanes)
      !> Wall-clock time of the loop (s), shared by the lanes that ran.
      real(dp), intent(in) :: seconds
      type(analysis_result), pointer :: r
      integer :: l, ib

      do l = 1, lanes%n
         if (.not. lanes%live(l)) cycle
         r => res
         if (l > 1) r => lanes%more(l - 1)
         do ib = 1, size(models)
            r%building(ib)%peak(:, 1:4) = transpose(pk(ib)%peak(l, :, :))
            r%building(ib)%peak_time(:, 1:4) = transpose(pk(ib)%time(l, :, :))
            call response_finish(r%building(ib), models(ib))
         end do
         r%seconds = seconds/real(count(lanes%live), dp)
         r%energy_error = audit_error(resid(l), scale(l))
         if (r%energy_error > audit_warning_limit) &
            call add_warning(r%warnings, uncoupled_audit_warning(r%energy_error))
         call progress_run_done()
      end do
   end subroutine lanes_finish

   !> A run under a ground component along y (`analysis_plan%ground_y`): each building with
   !> DOFs along y (`ground_set(:, c)`, direction y) gets its load rows, -M r_y, and
   !> x = Khat^{-1} M r_y (`ground_rows_of`), and starts at rest in equilibrium with both
   !> components, a_0 = -(r_x a_gx(0) + r_y a_gy(0)) (`integrator%start_load`: HHT-alpha also
   !> keeps the load in its F_0).
   subroutine ground_y_setup(s, ag_y, st, models)
      !> The step (pointed at the run).
      type(step_state), intent(inout) :: s
      !> The component along y at t_n (0:n_steps).
      real(dp), intent(in), target :: ag_y(0:)
      !> Integrators at t = 0.
      class(integrator), intent(inout) :: st(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      integer :: ib

      s%ag_y(0:) => ag_y
      call ground_rows_of(s%gy, st, models)
      do ib = 1, size(models)
         if (.not. allocated(s%gy(ib)%dof)) cycle
         call st(ib)%start_load(models(ib), -ag_y(0), s%gy(ib)%dof, s%gy(ib)%w)
      end do
   end subroutine ground_y_setup

end submodule pound_analysis_loop
