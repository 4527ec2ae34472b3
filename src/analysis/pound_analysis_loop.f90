!> The one time loop of every analysis, `integrate` (uncoupled, coupled, with impact substeps
!> or exact free steps, and with lanes: several motions of the same buildings advanced together
!> by the integrators, `integrator%advance_lanes`), and its entries `run_uncoupled`,
!> `coupled_integrate` and `run_lanes`. The outputs, the energy audit and the test that the
!> state is finite are written once, in `integrate`, lane by lane; the lanes' parts that are
!> not the integrator's (their ground samples, a dropped lane, an output sample, the end) are
!> procedures of this submodule.
submodule(pound_analysis) pound_analysis_loop
   implicit none

contains

   !> `run_uncoupled` (the interface in `pound_analysis` documents it).
   module procedure run_uncoupled
      class(integrator), allocatable :: st(:)
      type(contact_system) :: cs
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
      call integrate(cfg, models, ag, st, cs, res, error, sink=sink)
   end procedure run_uncoupled

   !> `coupled_integrate` (the interface in `pound_analysis` documents it).
   module procedure coupled_integrate
      class(integrator), allocatable :: st(:)
      type(impact_stepping) :: sub
      integer :: nb

      nb = size(models)
      call check_ground_samples(ag, cfg%dt, error)
      if (allocated(error)) return
      allocate (st, source=prep%st)
      cs = prep%cs
      if (present(gaps)) cs%pair(:)%gap = gaps
      if (present(track)) then
         if (track) call contact_track_closing(cs)
      end if
      call start_result(res, cfg, size(ag) - 1, nb, error, cs%m)
      if (allocated(error)) return
      if (prep%substeps == 0) then
         call integrate(cfg, models, ag, st, cs, res, error, sink=sink)
         return
      end if
      if (.not. present(ground)) then
         call fatal_error(error, "&analysis: stepping = 'impact' needs the ground motion itself (internal)")
         return
      end if
      sub%m = prep%substeps
      allocate (sub%st, source=prep%st_sub)
      sub%cs = prep%cs_sub
      sub%ground = ground
      if (cfg%free_steps == free_exact) call closed_init(sub%closed, models, cs, cfg%dt, sub%m)
      call integrate(cfg, models, ag, st, cs, res, error, sub, sink)
   end procedure coupled_integrate

   !> The time-step loop of every analysis, from integrators at t = 0 and a contact system
   !> (`cs%m` = 0: no constraints, the uncoupled run): predict every building, the step's
   !> contact forces, commit, sample the response, audit the energy, store output samples.
   !>
   !> A plain run (no constraints, no substeps, no exact free steps) predicts each step at
   !> the end of the one before (`integrator%advance`: commit, then predict the next) and
   !> samples the committed response after that, which the prediction leaves untouched: the
   !> same numbers, with the sampling free to overlap the tridiagonal solve, a chain of
   !> dependent operations.
   !>
   !> With `lanes` (`run_lanes`: several motions of the same buildings, no constraints) the
   !> integrators advance every lane at once (`advance_lanes`, which also keeps the running
   !> peaks of the response points); the outputs, the energy audit and the test that the state
   !> is finite are those of a single run, lane by lane (at an output step each lane's state
   !> is shown to the integrator, `show_lane`, and stored as a single run stores its own). A
   !> lane whose state stops being finite is dropped (`lanes%live`), not an error.
   !>
   !> Without constraints each building's kinetic, strain and damping energy are summed first
   !> and then over the buildings (the order the uncoupled run has always used, so that its
   !> audit residual stays bit-identical); with constraints each term is summed over the
   !> buildings first.
   subroutine integrate(cfg, models, ag, st, cs, res, error, sub, sink, lanes)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration at t_n = n dt, n = 0..n_steps (m/s^2) (with `lanes`: lane 1's).
      real(dp), intent(in) :: ag(0:)
      !> Integrators at t = 0 (advanced to the end; with `lanes`, their lanes started).
      class(integrator), intent(inout), target :: st(:)
      !> The contact system at t = 0 (at the end on return).
      type(contact_system), intent(inout) :: cs
      !> The result, set up by `start_result` (contact histories when cs%m > 0) (with `lanes`:
      !> lane 1's, left alone when lane 1 is not live).
      type(analysis_result), intent(inout), target :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Impact-aware substeps (`stepping = 'impact'`): a step in which a joint carries force
      !> at the start or is predicted to close (`contact_may_act`) is taken as `sub%m`
      !> substeps of dt/m.
      type(impact_stepping), intent(inout), optional :: sub
      !> Where the histories are streamed: each building holds one block of output samples,
      !> handed over when full and after the loop (none: the whole history is held).
      class(history_sink), intent(inout), optional :: sink
      !> Several motions at once (no constraints, no substeps, no sink).
      type(lane_runs), intent(inout), optional :: lanes
      integer :: ib, step, k, every, nb, j, n_sub, capacity, until_out, n_steps, nl, l
      integer(int64) :: c0, c1, rate, write_ticks
      real(dp) :: t, sample(e_numerical), lcp_start, h, t_sub, ag_old, ag_new, dt_now
      real(dp) :: win(max_lanes), eout(max_lanes), resid(max_lanes), scale(max_lanes), resid1, scale1
      real(dp) :: lag_old(max_lanes), lag_new(max_lanes)
      type(state_view), allocatable :: view(:)
      type(lane_peaks), allocatable :: pk(:)
      type(analysis_result), pointer :: r
      logical :: out, coupled, finite, impact, output, track, exact, plain, loaded, batched, inelastic, collapsed, retried
      logical :: closed
      logical :: frozen(size(models))
      integer :: method_steps
      type(storey_yield_set), allocatable :: ys(:)
      type(step_retry) :: rt
      type(integrator_properties) :: props

      nb = size(models)
      n_steps = size(ag) - 1
      allocate (view(nb))
      call yield_sets_init(ys, models, cfg, inelastic, collapsed, frozen)
      coupled = cs%m > 0
      impact = present(sub)
      props = st(1)%properties()
      res%integrator = trim(props%name)
      exact = cfg%free_steps == free_exact .and. .not. inelastic .and. props%exact_steps
      batched = present(lanes)
      plain = .not. (coupled .or. impact .or. exact .or. batched .or. inelastic)
      track = (impact .or. exact) .and. allocated(cs%closing_max)
      method_steps = 0
      retried = .false.
      every = cfg%output_every
      h = cfg%dt
      if (impact) then
         h = cfg%dt/real(sub%m, dp)
         res%substep_factor = sub%m
         res%substep = h
      end if
      nl = 1
      lag_new = 0.0_dp
      if (batched) then
         nl = max_lanes
         allocate (pk(nb))
         call lane_ground(lanes, 0, lag_new)
      end if
      do ib = 1, nb
         if (batched) allocate (pk(ib)%peak(max_lanes, 4, models(ib)%n), pk(ib)%time(max_lanes, 4, models(ib)%n), &
                                source=0.0_dp)
         view(ib)%u => st(ib)%u_view()
         view(ib)%v => st(ib)%v_view()
         view(ib)%a => st(ib)%a_view()
         do l = 1, nl
            r => lane_result(res, lanes, l)
            if (batched) then
               if (.not. lanes%live(l)) cycle
               call st(ib)%show_lane(l)
               ag_new = lag_new(l)
            else
               ag_new = ag(0)
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
                               refine=exact)
            if (allocated(error)) then
               if (.not. batched) return
               deallocate (error)
               call drop_lane(lanes, st, l, lag_new)
               cycle
            end if
            r%building(ib)%streamed = present(sink)
            call response_sample(r%building(ib), models(ib), view(ib)%u, view(ib)%v, view(ib)%a, ag_new, &
                                 0.0_dp, .true.)
            if (batched) then
               pk(ib)%peak(l, :, :) = transpose(r%building(ib)%peak(:, 1:4))
               pk(ib)%time(l, :, :) = transpose(r%building(ib)%peak_time(:, 1:4))
            end if
            if (present(sink)) then
               call response_flush(r%building(ib), sink, cs%m > 0, ib, .true., error)
               if (allocated(error)) return
            end if
         end do
      end do
      k = 1
      resid = 0.0_dp
      scale = 0.0_dp
      resid1 = 0.0_dp
      scale1 = 0.0_dp
      lcp_start = cs%stats%lcp_seconds
      write_ticks = 0
      until_out = every
      call system_clock(c0, rate)
      if (plain .and. n_steps > 0) call predict_again(st, models, ag(1) - ag(0))
      steps: do step = 1, n_steps
         if (mod(step, progress_stride) == 0) call progress_steps(step, n_steps)
         t = real(step, dp)*cfg%dt
         ag_old = ag(step - 1)
         ag_new = ag(step)
         if (batched) then
            lag_old = lag_new
            call lane_ground(lanes, step, lag_new)
         end if
         ! A joint carrying force at the start makes the step Newmark's (below): its exact
         ! prediction, which would be dropped, is not made.
         loaded = .false.
         if (exact .and. coupled .and. .not. track) loaded = contact_carries_force(cs)
         if (exact) then
            if (.not. loaded) then
               do ib = 1, nb
                  call st(ib)%predict_exact(models(ib), ag_old, ag_new)
               end do
            end if
         else if (.not. (plain .or. batched)) then
            do ib = 1, nb
               if (.not. frozen(ib)) call st(ib)%predict(models(ib), ag_new - ag_old)
            end do
         end if
         ! out = mod(step, every) == 0, counted down (no division per step)
         until_out = until_out - 1
         out = until_out == 0
         if (out) until_out = every
         ! A step is one pass of the body below, or, with impact stepping when a joint can act,
         ! m passes of h = dt/m with the ground motion at the substeps' ends.
         ! With exact free steps (uniform stepping) a step in which a joint can act is Newmark's
         ! at dt, predicted again.
         n_sub = 1
         closed = .false.
         if (impact .or. (exact .and. coupled)) then
            if (track) call contact_track_paths(cs, st)
            ! Joints carrying force, all elastic and staying closed: the step exact (closed).
            if (loaded .and. impact) call closed_step(sub%closed, st, models, cs, ag_old, ag_new, step, closed, res%building, &
                                                     t - cfg%dt)
            if (closed) then
               res%closed_steps = res%closed_steps + 1
            else if (loaded .or. contact_may_act(cs, st)) then
               method_steps = method_steps + 1
               if (impact) then
                  n_sub = sub%m
                  res%substepped = res%substepped + 1
                  call swap_steps(st, cs, sub)
               else
                  call predict_again(st, models, ag_new - ag_old)
               end if
            end if
         end if
         t_sub = t
         dt_now = cfg%dt
         do j = 1, n_sub
            if (n_sub > 1) then
               dt_now = h
               if (j < n_sub) then
                  t_sub = real(step - 1, dp)*cfg%dt + real(j, dp)*h
                  ag_new = ground_accel(sub%ground, t_sub)
               else
                  t_sub = t
                  ag_new = ag(step)
               end if
               do ib = 1, nb
                  if (.not. frozen(ib)) call st(ib)%predict(models(ib), ag_new - ag_old)
               end do
               res%substeps = res%substeps + 1
            end if
            output = out .and. j == n_sub
            if (closed) retried = .false.
            if (coupled .and. .not. closed) then
               call contact_step(cs, st, t_sub, step, error)
               retried = allocated(error) .and. .not. inelastic
               if (retried) call retry_step(rt, models, st, cs, ag_old, ag_new, t_sub, dt_now, step, error, res%warnings)
               if (allocated(error)) then
                  ! A state that is not finite is named as such, not as a failed LCP.
                  call locate_nonfinite(st, models, cs, t_sub, step, error, predicted=.true.)
                  call error_at(error, t_sub, step)
                  return
               end if
            end if
            if (inelastic) call yield_steps(ys, st, cs, models, t_sub, step, error)
            if (allocated(error)) return
            ! win, eout: the integrators' energy balance of each lane, added up by the commits
            ! (uncoupled; replaced by the sample below when coupled)
            win(1:nl) = 0.0_dp
            eout(1:nl) = 0.0_dp
            do ib = 1, nb
               ! The plain step first: every uncoupled run of the program (no frozen building,
               ! no lanes, no retry there).
               if (plain .and. step < n_steps) then
                  call st(ib)%advance(models(ib), ag_old, ag_new, ag(step + 1) - ag_new, win(1), eout(1))
               else if (frozen(ib)) then
                  call yield_frozen_step(st(ib), res%building(ib), output, win(1), eout(1))
                  cycle
               else if (batched) then
                  call st(ib)%advance_lanes(models(ib), lag_old, lag_new, t, pk(ib)%peak, pk(ib)%time, win, eout)
                  cycle
               else if (.not. (retried .or. closed)) then
                  call st(ib)%commit(models(ib), ag_old, ag_new, win(1), eout(1))
               end if
               call response_sample(res%building(ib), models(ib), view(ib)%u, view(ib)%v, view(ib)%a, &
                                    ag_new, t_sub, output)
               if (inelastic) call yield_sample(ys(ib), view(ib)%u, t_sub, output, res%building(ib), collapsed)
            end do
            ! The last block is handed over after the loop (writing it is not integration).
            if (output .and. present(sink) .and. step < n_steps) then
               call flush_full_blocks(res, sink, coupled, write_ticks, error)
               if (allocated(error)) return
            end if
            if (coupled) then
               ! An output step's sample is the stored one (below).
               if (.not. output) call step_energy(st, sample)
               if (.not. retried) call contact_commit(cs, st, t_sub, dt_now)
               sample(e_contact) = cs%element_work - cs%plastic_work
               sample(e_plastic) = cs%plastic_work
            end if
            if (output) then
               k = k + 1
               do l = 1, nl
                  r => lane_result(res, lanes, l)
                  if (batched) then
                     if (.not. lanes%live(l)) cycle
                     call show_lane_state(st, models, view, r, l, lag_new(l))
                  end if
                  call store_energy(r, k, st, models, cs, sample)
                  if (inelastic) call yield_energy_step(ys, .true., coupled, e_strain, e_plastic, r%energy(:, k), &
                                                        sample, eout(l))
                  win(l) = sample(e_input)
                  eout(l) = sum(sample(e_kinetic:e_numerical))
               end do
            else if (coupled) then
               if (inelastic) call yield_energy_step(ys, .false., .true., e_strain, e_plastic, res%energy(:, k), &
                                                     sample, eout(1))
               win(1) = sample(e_input)
               eout(1) = sum(sample(e_kinetic:e_numerical))
            else if (inelastic) then
               call yield_energy_step(ys, .false., .false., e_strain, e_plastic, res%energy(:, k), sample, eout(1))
            end if
            ! One test per step (and lane): every value of the state feeds these sums. A single
            ! run keeps its audit sums in scalars (registers: the lanes' arrays are passed to
            ! `lanes_finish`, so they live in memory).
            if (batched) then
               do l = 1, nl
                  finite = abs(win(l) + eout(l)) <= huge(1.0_dp)
                  if (.not. finite) then
                     ! The lane's motion is left to a run of its own, which names the cause.
                     call drop_lane(lanes, st, l, lag_new)
                     win(l) = 0.0_dp
                     eout(l) = 0.0_dp
                  end if
                  resid(l) = max(resid(l), abs(win(l) - eout(l)))
                  scale(l) = max(scale(l), abs(win(l)), eout(l))
               end do
            else
               if (coupled) then
                  finite = abs(sum(sample) + cs%work) <= huge(1.0_dp)
               else
                  finite = abs(win(1) + eout(1)) <= huge(1.0_dp)
               end if
               if (.not. finite) then
                  if (.not. coupled) call step_energy(st, sample)
                  call state_failure(st, models, cs, sample, ag, cfg%dt, step, error)
                  return
               end if
               resid1 = max(resid1, abs(win(1) - eout(1)))
               scale1 = max(scale1, abs(win(1)), eout(1))
            end if
            ag_old = ag_new
         end do
         if (n_sub > 1) call swap_steps(st, cs, sub)
         if (collapsed) call yield_freeze(ys, st, cs, t, frozen, collapsed)
         if (collapsed) exit steps
      end do steps
      if (inelastic) call yield_hold(res%building, res%energy, k, coupled, error, sink)
      if (allocated(error)) return
      call system_clock(c1)
      if (present(sink)) then
         do ib = 1, nb
            call response_flush(res%building(ib), sink, coupled, ib, .false., error)
            if (allocated(error)) return
            call response_release(res%building(ib))
         end do
      end if
      if (batched) then
         call lanes_finish(lanes, res, models, pk, resid, scale, real(c1 - c0, dp)/real(rate, dp))
         return
      end if
      call progress_run_done()
      res%seconds = real(c1 - c0 - write_ticks, dp)/real(rate, dp)
      res%write_seconds = real(write_ticks, dp)/real(rate, dp)
      res%contact_seconds = cs%stats%lcp_seconds - lcp_start
      do ib = 1, nb
         call response_finish(res%building(ib), models(ib))
      end do
      if (inelastic) call yield_results(ys, res%building, res%yielding)
      if (exact) res%exact_steps = n_steps - method_steps
      res%energy_error = audit_error(resid1, scale1)
      if (res%energy_error <= audit_warning_limit) return
      if (coupled) then
         call warn_unresolved_joints(res, models, cs, h)
      else
         call add_warning(res%warnings, uncoupled_audit_warning(res%energy_error))
      end if
   end subroutine integrate

   !> `run_lanes` (the interface in `pound_analysis` documents it).
   module procedure run_lanes
      class(integrator), allocatable :: st(:)
      type(contact_system) :: cs
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
      call integrate(cfg, models, ag(:, 1), st, cs, res(1), error, lanes=lanes)
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

   !> Predict the step of every building by Newmark, dropping any exact step predicted
   !> (`free_steps = 'exact'`, a step in which a joint can act; a plain run's first step).
   subroutine predict_again(st, models, dag)
      !> Integrators.
      class(integrator), intent(inout) :: st(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration increment of the step (m/s^2).
      real(dp), intent(in) :: dag
      integer :: ib

      do ib = 1, size(st)
         call st(ib)%drop_exact()
         call st(ib)%predict(models(ib), dag)
      end do
   end subroutine predict_again

   !> Exchange the step data of the integrators and the contact system with `sub`'s (a
   !> procedure of the submodule, not of `integrate`: an internal one would keep the time loop's
   !> variables that it reaches in memory).
   subroutine swap_steps(st, cs, sub)
      !> Integrators.
      class(integrator), intent(inout) :: st(:)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> The substep data of `stepping = 'impact'`.
      type(impact_stepping), intent(inout) :: sub

      call swap_step_data(st, sub%st, cs, sub%cs)
   end subroutine swap_steps

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

end submodule pound_analysis_loop
