!> A suite of ground motions, the thin driver: every `&ground` of the deck, scaled
!> (`pound_suite_motions`), run as one case each (`run_case`), its outcome typed
!> (`pound_suite_outcome`: the one layout of the columns that cross the ranks), the suite
!> statistics of the influence coefficients, the code separation rules per contact pair and
!> the 5 %-damped spectra (`pound_suite_statistics`), the threshold gaps refined by bisection
!> (`pound_suite_refine`).
!>
!> Per motion k (`motion_run`): the motion as run, its spectra, `run_case` with it (peaks,
!> influence coefficients lambda (%)), per contact pair the uncoupled peak displacement at
!> each end and the no-contact gap, and with the motions' sweeps its sweep's probe. The pairs
!> are indexed by pair (`pound_suite_context`): an end at a floor takes the floor's peak and
!> history, an end between floors (a frame's column node, `&contact elevations`) its DOF's
!> stored history (`node_histories`), so a suite accepts every contact a single run accepts.
!>
!> Over the suite: the statistics (`pound_suite_statistics`); per-motion histories, for the
!> motions whose `&ground` sets `histories` (kept for the HDF5 writer; the other motions keep
!> only their outcomes); spectra: Sa of every scaled motion at `n_spectrum` log-spaced periods
!> from 0.02 to 4 s plus the buildings' fundamental periods, and their mean.
module pound_suite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_config, only: deck_type, n_history_quantities, n_target_quantities
   use pound_ground_motion, only: ground_motion_t
   use pound_structure, only: structure_model, structure_names, structure_yields
   use pound_building, only: building_model, build_building
   use pound_spectrum, only: response_spectrum, period_grid, peak_ground_acceleration
   use pound_separation, only: separation_t, no_contact_gap
   use pound_run_case, only: case_options, case_result, run_case, label_prefix, analysis_plan_of
   use pound_analysis_plan, only: steps_of, output_steps
   use pound_analysis, only: analysis_result, n_energy, analysis_copy, add_warning
   use pound_response, only: response_point_peak
   use pound_contact, only: contact_pair, pairs_from_config
   use pound_sweep, only: sweep_result, gap_cases, gap_cases_init, gap_cases_probe, gap_cases_set_probe, &
                          sweep_column_width, sweep_from_table
   use iso_fortran_env, only: int64
   use pound_analysis_batch, only: batch_eligible, run_uncoupled_batch, batch_lanes
   use pound_cases, only: case_work, case_table, run_cases, first_failure, cases_ranks
   use pound_suite_columns, only: column_block_width, columns_to_block, columns_init, &
                                  columns_gather, columns_finish, member_peaks_from_block
   use pound_suite_outcome, only: suite_failure, motion_outcome, outcome_init, outcome_fail, outcome_width, &
                                  outcome_pack, outcome_unpack
   use pound_suite_context, only: suite_context, suite_pair, suite_pairs
   use pound_suite_motions, only: suite_motion, suite_motion_samples, suite_motion_setup, motion_names, &
                                  motion_sources, n_spectrum, spectrum_damping
   use pound_suite_statistics, only: suite_result, motion_histories, suite_sweep_statistics, &
                                     suite_building_statistics, suite_pair_rules, time_history_gap, &
                                     add_failure, sort_failures, suite_result_init
   use pound_suite_refine, only: bisection, bisection_step, bisection_update, refine, refine_motions, &
                                 refine_trials, planned_refinement_runs
   use pound_progress, only: progress_skip
   use pound_suite_joints, only: suite_joint_sweeps
   use pound_sweep_joints, only: joint_thresholds
   implicit none
   private

   public :: run_suite
   ! The suite's pieces, for the writers and the tests:
   public :: suite_result, suite_failure, suite_sweep_statistics, suite_motion, n_spectrum, spectrum_damping
   public :: motion_histories, bisection, bisection_step, bisection_update, time_history_gap

   !> Batched uncoupled runs (`pound_analysis_batch`): at least this many motions a batch (fewer
   !> run one by one), and at most this many bytes of their results held at once.
   integer, parameter :: batch_min = 3
   real(dp), parameter :: batch_bytes = 256.0_dp*2.0_dp**20

   !> The motions of a suite without `&sweep` as cases: case i is the group of motions
   !> `motion(start(i):start(i+1)-1)`, their uncoupled runs batched (`batch_uncoupled`), each
   !> motion then scaled, its spectra and its run, its outcome packed into its part of the
   !> column (`motion_run`, `outcome_pack`: `outcome_width` reals a motion, motion j of the group
   !> at (j-1)*outcome_width).
   type, extends(case_work) :: suite_cases
      !> The suite's data.
      type(suite_context), pointer :: ctx => null()
      !> Motion indices of the cases, group after group.
      integer, allocatable :: motion(:)
      !> First entry of `motion` of each group, and one past the last (n_cases + 1).
      integer, allocatable :: start(:)
   contains
      procedure :: compute => suite_case
   end type suite_cases

   !> The sweeps of the motions as the cases of one loop: case (j - 1) n_gaps + g is gap g of
   !> motion `motions(j)`, its coupled run against the motion's uncoupled peaks
   !> (`ctx%unc`), or the probe's column when the gap is beyond the joints' closing. A rank
   !> sets up the motion of a case (its ground motion, the gap-independent part of the coupled
   !> analysis) when its previous case was another motion's.
   type, extends(case_work) :: suite_gap_cases
      !> The suite's data.
      type(suite_context), pointer :: ctx => null()
      !> Motion index of each block of n_gaps cases.
      integer, allocatable :: motions(:)
      !> Each motion's probe (`motion_outcome`'s), by entry of `motions`: whether it ran, the
      !> joints' largest closing displacements and the probe's column.
      logical, allocatable :: has_probe(:)
      real(dp), allocatable :: closing(:, :), probe(:, :)
      !> Entry of `motions` that `gaps` is set up for (0: none).
      integer :: current = 0
      !> That motion's gaps.
      type(gap_cases) :: gaps
   contains
      procedure :: compute => suite_gap_case
   end type suite_gap_cases

contains

   !> The group of motions of case i (a case of `suite_cases`): their uncoupled runs batched,
   !> then each motion's run.
   recursive subroutine suite_case(work, i, values, error)
      !> The cases.
      class(suite_cases), intent(inout) :: work
      !> Case index.
      integer, intent(in) :: i
      !> The motions' packed outcomes one after the other (`outcome_pack`).
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(case_result) :: res
      type(motion_outcome) :: o
      type(analysis_result), allocatable, target :: batched(:)
      logical, allocatable :: ok(:)
      integer :: j, w

      values = 0.0_dp
      w = outcome_width(work%ctx%layout)
      associate (ms => work%motion(work%start(i):work%start(i + 1) - 1))
         call batch_uncoupled(work%ctx, ms, batched, ok, error)
         if (allocated(error)) return
         do j = 1, size(ms)
            if (ok(j)) then
               call motion_run(work%ctx, ms(j), res, o, error, batched(j))
            else
               call motion_run(work%ctx, ms(j), res, o, error)
            end if
            if (allocated(error)) return
            call outcome_pack(o, work%ctx%layout, values((j - 1)*w + 1:j*w))
         end do
      end associate
   end subroutine suite_case

   !> The uncoupled runs of the motions `ms` made together (`run_uncoupled_batch`) when they are
   !> `batch_min` or more and the buildings qualify: `ok(j)` tells whether `batched(j)` holds
   !> motion ms(j)'s result (bit for bit its run alone); the others run one by one.
   subroutine batch_uncoupled(ctx, ms, batched, ok, error)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> Motion indices.
      integer, intent(in) :: ms(:)
      !> The motions' uncoupled results, where `ok`.
      type(analysis_result), allocatable, intent(out) :: batched(:)
      !> Whether the batch ran the motion.
      logical, allocatable, intent(out) :: ok(:)
      !> Error state (a motion that cannot be built or scaled).
      type(error_type), allocatable, intent(out) :: error
      type(ground_motion_t) :: gm
      real(dp), allocatable :: agb(:, :)
      real(dp) :: factor
      integer :: j, n_steps

      allocate (batched(size(ms)), ok(size(ms)))
      ok = .false.
      if (size(ms) < batch_min .or. .not. batch_eligible(analysis_plan_of(ctx%deck%analysis), ctx%models)) return
      n_steps = steps_of(ctx%deck%analysis%t_end, ctx%deck%analysis%dt)
      allocate (agb(0:n_steps, size(ms)))
      do j = 1, size(ms)
         call suite_motion_samples(ctx%deck, ms(j), ctx%models, gm, factor, agb(:, j), error)
         if (allocated(error)) then
            error%message = "&ground '"//ctx%deck%motions(ms(j))%name//"': "//error%message
            return
         end if
      end do
      call run_uncoupled_batch(analysis_plan_of(ctx%deck%analysis), ctx%models, agb, batched, ok)
   end subroutine batch_uncoupled

   !> Motion k of the suite: scaled, its spectra, run (`run_case`) into `res`, and what the
   !> suite's statistics need of it in its outcome `o`: scale factor, PGA, whether the
   !> influence exists, Sa at the spectra's periods and at the buildings' periods, per building
   !> lambda, the uncoupled and the coupled peaks, the frames' member block, and per pair its
   !> ends' uncoupled peaks and the no-contact gap (`pair_response`); with the motions' sweeps
   !> (`ctx%sweep`), not the sweep's gaps (`suite_gap_cases`) but its probe. A run that fails
   !> is no error: its failure (message, time, step) is the outcome's (`outcome_fail`), the
   !> spectra kept. With `unc`, the motion's uncoupled result is taken from there (a batch ran
   !> it).
   subroutine motion_run(ctx, k, res, o, error, unc)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> Motion index.
      integer, intent(in) :: k
      !> The motion's case.
      type(case_result), intent(out), target :: res
      !> Its outcome.
      type(motion_outcome), intent(out) :: o
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The motion's uncoupled result, already computed (`batch_uncoupled`).
      type(analysis_result), intent(inout), target, optional :: unc
      type(case_options) :: options
      real(dp), allocatable :: ag(:), sa(:)
      real(dp) :: dt
      integer :: n_steps, ib, ip

      call outcome_init(ctx%layout, o)
      dt = ctx%deck%analysis%dt
      n_steps = steps_of(ctx%deck%analysis%t_end, dt)
      if (allocated(ctx%label)) options%label = ctx%label
      allocate (options%ground, ag(0:n_steps))
      call suite_motion_samples(ctx%deck, k, ctx%models, options%ground, o%scale_factor, ag, error)
      if (allocated(error)) return
      o%pga = peak_ground_acceleration(ag)
      call response_spectrum(ag, dt, ctx%period, spectrum_damping, sa, error)
      if (allocated(error)) return
      o%sa = sa
      call response_spectrum(ag, dt, ctx%building_period, spectrum_damping, sa, error)
      if (allocated(error)) return
      o%sa_building = sa
      if (present(unc)) options%unc => unc
      if (ctx%sweep) then
         call run_case(ctx%plain, res, error, options)
      else
         call run_case(ctx%deck, res, error, options)
      end if
      if (allocated(error)) then
         ! A failed run is the motion's failure, carried in its outcome: the others go on.
         call outcome_fail(o, error%message, error%time, error%step)
         deallocate (error)
         return
      end if
      if (.not. (res%has_coupled .and. res%has_uncoupled)) return
      o%has_influence = .true.
      do ib = 1, size(ctx%models)
         o%building(ib)%lambda = res%influence(ib)%lambda
         o%building(ib)%unc = res%unc%building(ib)%peak
         o%building(ib)%cpl = res%cpl%building(ib)%peak
         if (.not. allocated(res%unc%yielding)) cycle
         if (res%unc%yielding(ib)%n == 0) cycle
         o%building(ib)%yield = reshape([res%unc%yielding(ib)%ductility, res%cpl%yielding(ib)%ductility, &
                                         res%unc%yielding(ib)%residual_drift, res%cpl%yielding(ib)%residual_drift], &
                                        shape(o%building(ib)%yield))
         o%building(ib)%collapse = real([res%unc%yielding(ib)%collapse_storey, res%cpl%yielding(ib)%collapse_storey], dp)
      end do
      call columns_to_block(ctx%models, res%influence, res%unc, o%member)
      do ip = 1, size(ctx%pair)
         call pair_response(ctx, ctx%pair(ip), res%unc, o%pair_peak(:, ip), o%no_contact(ip))
      end do
      if (ctx%sweep) call motion_probe(ctx, res, ag, options%ground, o)
   end subroutine motion_run

   !> A pair's uncoupled response: the peak displacement at each end (a floor's peak; for a
   !> point between floors, its DOF's peak |u| at every step, `response_point_peak`; -1 when
   !> the model has no such node) and the no-contact gap max_t (u1 - u2) of the two ends' stored histories
   !> (a floor's with `history` 'u', a point's with `node_histories`; -1 without them).
   subroutine pair_response(ctx, pair, unc, peak, gap)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> The pair.
      type(suite_pair), intent(in) :: pair
      !> The motion's uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> Peak displacement at each end (m; -1: not kept).
      real(dp), intent(out) :: peak(2)
      !> No-contact gap (m; -1: no histories).
      real(dp), intent(out) :: gap
      real(dp), allocatable :: u(:, :)
      logical :: have(2)
      integer :: e, n

      gap = -1.0_dp
      have = .false.
      n = min(unc%building(pair%building(1))%n_out, unc%building(pair%building(2))%n_out)
      allocate (u(n, 2))
      do e = 1, 2
         associate (b => unc%building(pair%building(e)))
            if (pair%floor(e) > 0) then
               peak(e) = b%peak(pair%floor(e), 1)
               if (ctx%deck%analysis%store(1)) then
                  u(:, e) = b%u(pair%floor(e), 1:n)
                  have(e) = .true.
               end if
            else
               peak(e) = response_point_peak(b, pair%dof(e))
               if (allocated(b%u_nodes) .and. .not. b%streamed .and. b%n_out > 0 .and. pair%dof(e) > 0) then
                  u(:, e) = b%u_nodes(pair%dof(e), 1:n)
                  have(e) = .true.
               end if
            end if
         end associate
      end do
      if (all(have)) gap = no_contact_gap(u(:, 1), u(:, 2))
   end subroutine pair_response

   !> The probe of motion k's sweep (`gap_cases_probe`) into its outcome: the joints' largest
   !> closing displacements and the probe's column, or `has_probe` false when the probe could
   !> not be made (every gap then runs).
   subroutine motion_probe(ctx, res, ag, ground, o)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> The motion's case (models, uncoupled result).
      type(case_result), intent(in), target :: res
      !> The motion's ground acceleration at every step (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The motion.
      type(ground_motion_t), intent(in) :: ground
      !> The motion's outcome.
      type(motion_outcome), intent(inout) :: o
      type(gap_cases) :: cases
      type(contact_pair), allocatable :: pairs(:)
      type(error_type), allocatable :: error

      o%has_probe = .false.
      pairs = pairs_from_config(ctx%deck%contacts, structure_names(res%models), error, res%models)
      if (allocated(error)) return
      call gap_cases_init(cases, analysis_plan_of(ctx%deck%analysis), ctx%deck%sweep, res%models, ag, pairs, res%unc, &
                          error, ground)
      if (allocated(error)) return
      call gap_cases_probe(cases)
      if (.not. allocated(cases%probe)) return
      o%has_probe = .true.
      o%closing_max = cases%closing_max
      o%probe = cases%probe
   end subroutine motion_probe

   !> A motion's uncoupled peaks from its outcome (`motion_run`), as the uncoupled result that
   !> the coupled runs at other gaps compare with: everything a target quantity's lambda reads
   !> of the uncoupled run (`influence_of`, `max_abs_target`): the floors' and storeys' peaks,
   !> the frames' member peaks and, for buildings with bilinear storeys or plastic hinges, the
   !> storeys' peak ductility (a frame's: the storeys' largest plastic rotation), so that a
   !> sweep's or a refinement's lambda is the single run's at that gap bit for bit.
   pure subroutine peaks_from_outcome(ctx, o, unc)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> The motion's outcome.
      type(motion_outcome), intent(in) :: o
      !> Its uncoupled peaks (no output times, no histories).
      type(analysis_result), intent(out) :: unc
      integer :: ib

      allocate (unc%time(0), unc%energy(n_energy, 0), unc%building(size(ctx%models)))
      do ib = 1, size(ctx%models)
         unc%building(ib)%peak = o%building(ib)%unc
      end do
      call member_peaks_from_block(ctx%models, o%member, unc)
      if (.not. any([(structure_yields(ctx%models(ib)), ib=1, size(ctx%models))])) return
      ! As `yield_results` gives them: one result a building, n = 0 for an elastic one.
      allocate (unc%yielding(size(ctx%models)))
      do ib = 1, size(ctx%models)
         if (.not. structure_yields(ctx%models(ib))) cycle
         unc%yielding(ib)%n = size(o%building(ib)%yield, 1)
         unc%yielding(ib)%ductility = o%building(ib)%yield(:, 1)
      end do
   end subroutine peaks_from_outcome

   !> Gap case i of the motions' sweeps (a case of `suite_gap_cases`).
   recursive subroutine suite_gap_case(work, i, values, error)
      !> The cases.
      class(suite_gap_cases), intent(inout) :: work
      !> Case index.
      integer, intent(in) :: i
      !> The gap's column (`gap_cases`).
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(ground_motion_t) :: gm
      type(contact_pair), allocatable :: pairs(:)
      real(dp), allocatable :: ag(:)
      integer :: j, k, ng

      ng = work%ctx%deck%sweep%n_gaps
      j = (i - 1)/ng + 1
      if (work%current /= j) then
         work%current = 0
         k = work%motions(j)
         associate (deck => work%ctx%deck)
            call suite_motion_setup(deck, k, work%ctx%models, gm, ag, pairs, error)
            if (allocated(error)) return
            call gap_cases_init(work%gaps, analysis_plan_of(deck%analysis), deck%sweep, work%ctx%models, ag, pairs, &
                                work%ctx%unc(k), error, gm)
            if (allocated(error)) return
         end associate
         if (work%has_probe(j)) call gap_cases_set_probe(work%gaps, work%closing(:, j), work%probe(:, j))
         work%current = j
      end if
      call work%gaps%compute(i - (j - 1)*ng, values, error)
   end subroutine suite_gap_case

   !> Groups of n motions whose uncoupled runs a suite makes together (`batch_uncoupled`):
   !> group g is entries start(g):start(g+1)-1, of up to `batch_lanes` motions (and `most`), as
   !> many as `batch_bytes` of results allow, the groups as even as possible; one motion a group
   !> (one by one) for fewer than `batch_min` motions or buildings the batch cannot run.
   pure function batch_groups(deck, models, n, most) result(start)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Number of motions, and the most a group may take.
      integer, intent(in) :: n, most
      integer, allocatable :: start(:)
      real(dp) :: bytes
      integer :: ib, groups, n_out, size_of, g

      start = [(g, g=1, n + 1)]
      if (n < batch_min .or. .not. batch_eligible(analysis_plan_of(deck%analysis), models)) return
      n_out = output_steps(steps_of(deck%analysis%t_end, deck%analysis%dt), deck%analysis%output_every)
      bytes = real(1 + n_energy, dp)
      do ib = 1, size(models)
         bytes = bytes + real(size(models(ib)%floor_dof), dp)*real(count(deck%analysis%store), dp)
      end do
      bytes = 8.0_dp*real(n_out, dp)*bytes
      size_of = int(min(real(min(batch_lanes, most), dp), batch_bytes/bytes))
      if (size_of < batch_min) return
      groups = (n + size_of - 1)/size_of
      size_of = (n + groups - 1)/groups
      start = [(min(1 + (g - 1)*size_of, n + 1), g=1, groups + 1)]
   end function batch_groups

   !> Run every motion of the deck's suite and gather the suite statistics. A motion whose
   !> run fails, a gap of a motion's sweep or a trial gap of a refinement at which a motion
   !> fails is recorded in `suite%failures` and the others go on: the failed motion is left out
   !> of every statistic over the motions (they are over `suite%n_used` motions), a suite gap
   !> at which a motion failed is FAILED (never meeting the target, so the safe gaps lie above
   !> it); only a suite whose every motion fails is an error.
   subroutine run_suite(deck, suite, first, error, label)
      !> A validated configuration.
      type(deck_type), intent(in), target :: deck
      !> Everything the suite computes.
      type(suite_result), intent(out) :: suite
      !> The case of the first motion that did not fail (`suite%first`: what a single-motion
      !> run writes).
      type(case_result), intent(out) :: first
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Put before the messages of the configuration's errors (e.g. the deck path).
      character(len=*), intent(in), optional :: label
      type(structure_model), allocatable, target :: models(:)
      type(building_model), allocatable :: kinds(:)
      type(suite_context), target :: ctx
      type(suite_cases) :: motions
      type(case_table) :: table
      type(motion_outcome), allocatable :: outcomes(:)
      logical, allocatable :: whole(:), known(:, :), closing_known(:)
      type(case_result) :: res
      type(suite_failure) :: f
      real(dp), allocatable :: mean_unc(:, :, :), mean_cpl(:, :, :), mean_pair(:, :)
      real(dp), allocatable :: z(:), sweep_all(:, :, :, :)
      character(len=:), allocatable :: text
      logical :: targeted(n_target_quantities)
      integer :: nm, nb, k, ib, np, ip, nmax, ig, w
      integer, allocatable :: start(:), ms(:), n_storeys(:)
      type(analysis_result), allocatable, target :: batched(:)
      logical, allocatable :: batched_ok(:)

      nm = size(deck%motions)
      nb = size(deck%buildings)
      allocate (models(nb), kinds(nb), suite%building_period(nb), z(nb))
      do ib = 1, nb
         call build_building(deck%buildings(ib), models(ib), kinds(ib), error)
         if (allocated(error)) return
         suite%building_period(ib) = models(ib)%period(1)
         z(ib) = deck%buildings(ib)%damping_ratio
      end do
      call period_grid(n_spectrum, suite%building_period, suite%period, error)
      if (allocated(error)) return
      ctx%pair = suite_pairs(deck, models)
      np = size(ctx%pair)
      suite%has_coupled = np > 0
      nmax = maxval(deck%buildings%n_storeys)
      allocate (mean_unc(nmax, n_history_quantities, nb), mean_cpl(nmax, n_history_quantities, nb))
      mean_unc = 0.0_dp
      mean_cpl = 0.0_dp
      n_storeys = deck%buildings%n_storeys
      call suite_result_init(suite, nm, n_storeys, np)
      call columns_init(models, nm, suite%columns)
      suite%refine_tolerance = deck%sweep%refine_tolerance
      targeted = deck%sweep%target_quantities
      if (.not. (deck%sweep%target > 0.0_dp)) targeted(1:n_history_quantities) = .true.
      call motion_sources(deck, suite%building_period, suite%names, suite%source, suite%target, suite%target_period)

      ! The motions are the cases, and those the writers need whole (the first, and those
      ! whose histories are kept) run on every rank beside them; the statistics take the
      ! motions' outcomes in motion order. The uncoupled runs are batched in groups of
      ! consecutive motions (`batch_groups`): the whole motions' groups on every rank, the
      ! other motions' groups as the cases (at most as many motions a group as give every rank
      ! a case); a batched run is bit for bit its run alone, so the grouping and the ranks do
      ! not change the numbers. With `&sweep` a motion's case makes its sweep's probe, and the
      ! gaps of all the motions' sweeps are then the cases of one loop (`motion_sweeps`).
      ctx%deck => deck
      ctx%plain = deck
      ctx%plain%sweep%active = .false.
      ctx%models => models
      ctx%targeted = targeted
      if (present(label)) ctx%label = label
      ctx%period = suite%period
      ctx%building_period = suite%building_period
      ctx%sweep = deck%sweep%active .and. np > 0
      ctx%layout%n_periods = size(suite%period)
      ctx%layout%n_storeys = deck%buildings%n_storeys
      ctx%layout%n_pairs = np
      ctx%layout%sweep = ctx%sweep
      if (ctx%sweep) ctx%layout%n_probe = sweep_column_width(nb)
      ctx%layout%n_member = column_block_width(models)
      w = outcome_width(ctx%layout)
      allocate (outcomes(nm), whole(nm), suite%motion_failed(nm))
      if (deck%sweep%active) then
         allocate (ctx%unc(nm), ctx%has_unc(nm))
         ctx%has_unc = .false.
      end if
      suite%motion_failed = .false.
      allocate (suite%failures(0))
      whole = [(k == 1 .or. deck%motions(k)%histories, k=1, nm)]
      ms = pack([(k, k=1, nm)], whole)
      do
         start = batch_groups(deck, models, size(ms), nm)
         do ig = 1, size(start) - 1
            call batch_uncoupled(ctx, ms(start(ig):start(ig + 1) - 1), batched, batched_ok, error)
            if (allocated(error)) return
            do ip = 1, size(batched)
               k = ms(start(ig) + ip - 1)
               if (suite%first == 0) then
                  call whole_run(first, ip)
               else
                  call whole_run(res, ip)
               end if
               if (allocated(error)) return
            end do
            deallocate (batched, batched_ok)
         end do
         ! Every motion run whole failed: the next one is run whole too (the first motion that
         ! does not fail gives the run's single-motion results).
         if (suite%first > 0 .or. all(whole)) exit
         k = findloc(whole, .false., 1)
         whole(k) = .true.
         ms = [k]
      end do
      motions%ctx => ctx
      motions%motion = pack([(k, k=1, nm)], .not. whole)
      motions%start = batch_groups(deck, models, size(motions%motion), &
                                   (size(motions%motion) + cases_ranks() - 1)/cases_ranks())
      k = size(motions%start) - 1
      call run_cases(motions, k, w*max(1, maxval(motions%start(2:) - motions%start(:k))), table)
      call first_failure(table, motion_names(deck, '', motions%motion(motions%start(1:k)), bare=.true.), error)
      if (allocated(error)) return
      do ig = 1, k
         associate (m => motions%motion(motions%start(ig):motions%start(ig + 1) - 1))
            do ip = 1, size(m)
               call outcome_unpack(table%values((ip - 1)*w + 1:ip*w, ig), ctx%layout, outcomes(m(ip)))
            end do
         end associate
      end do
      if (ctx%sweep) then
         call motion_sweeps()
         if (allocated(error)) return
      end if

      ! The motions whose run failed are left out of every statistic over the motions; their
      ! rows of the sweep are FAILED at every gap (their other per-motion rows stay 0).
      do k = 1, nm
         suite%motion_failed(k) = outcomes(k)%failed
         if (.not. suite%motion_failed(k)) cycle
         f = outcomes(k)%failure
         f%motion = k
         call add_failure(suite%failures, f)
         if (suite%has_sweep) suite%sweep_failed(k, :) = .true.
      end do
      suite%n_used = count(.not. suite%motion_failed)
      if (suite%n_used == 0) then
         ! A suite of one motion (synthetic or scaled) fails as a run of that motion.
         text = "&ground '"//trim(suite%names(suite%failures(1)%motion))//"': "//trim(suite%failures(1)%message)
         if (nm > 1) text = 'every motion of the suite failed; the first, '//text
         call fatal_error(error, text)
         return
      end if
      ctx%used = pack([(k, k=1, nm)], .not. suite%motion_failed)
      allocate (mean_pair(2, np), known(2, np), closing_known(np))
      mean_pair = 0.0_dp
      known = .true.
      closing_known = .true.
      do k = 1, nm
         call gather(outcomes(k))
      end do
      if (suite%n_used == nm) then
         suite%mean_sa = sum(suite%sa, dim=1)/nm
      else
         suite%mean_sa = sum(suite%sa(ctx%used, :), dim=1)/suite%n_used
      end if

      if (.not. suite%has_coupled) call sort_failures(suite%failures)
      if (.not. suite%has_coupled) return
      do ib = 1, nb
         associate (n => deck%buildings(ib)%n_storeys)
            call suite_building_statistics(suite%building(ib), ctx%used, mean_cpl(1:n, :, ib), mean_unc(1:n, :, ib))
         end associate
      end do
      call columns_finish(ctx%used, suite%columns)
      ! The suite's rules on the mean peaks at the pairs' ends (n/a where a motion's is not kept).
      where (.not. known) mean_pair = -1.0_dp
      do ip = 1, np
         call rules(mean_pair(1, ip), mean_pair(2, ip), ip, suite%separation(nm + 1, ip))
      end do
      ! The no-contact gap is -1 where the histories at a pair's ends are not kept (for the
      ! suite's: under some motion).
      where (.not. closing_known)
         suite%separation(nm + 1, :)%no_contact = -1.0_dp
         suite%mean_closing = -1.0_dp
      end where
      suite%separation%no_contact_valid = suite%separation%no_contact >= 0.0_dp
      if (suite%has_sweep) then
         call suite_sweep_statistics(suite, sweep_all, targeted, deck%sweep%target)
         ctx%gap = suite%sweep_gap
         ! The progress line planned the refinements at their most: the runs they will take.
         associate (tol => deck%sweep%refine_tolerance)
            call progress_skip(planned_refinement_runs(deck%sweep, nm) - size(ctx%used)* &
                               (refine_trials(ctx%gap, suite%safe_gap_mean, tol) + &
                                refine_trials(ctx%gap, suite%safe_gap_every, tol)) - &
                               sum([(refine_trials(ctx%gap, suite%safe_gap_motion(k), tol), k=1, nm)]))
         end associate
         call refine(ctx, suite%safe_gap_mean, 0, suite%refined_gap_mean, suite%failures, error)
         if (allocated(error)) return
         call refine(ctx, suite%safe_gap_every, -1, suite%refined_gap_every, suite%failures, error)
         if (allocated(error)) return
         allocate (suite%refined_gap_motion(nm))
         ! The motions' own refinements are independent of each other: one case each.
         call refine_motions(ctx, suite%safe_gap_motion, suite%refined_gap_motion, suite%failures, error)
         if (allocated(error)) return
         do k = 1, nm
            suite%separation(k, :)%time_history = time_history_gap(suite%safe_gap_motion(k), &
                                                                   suite%refined_gap_motion(k))
         end do
         suite%separation(nm + 1, :)%time_history = time_history_gap(suite%safe_gap_mean, suite%refined_gap_mean)
         suite%separation%time_history_valid = suite%separation%time_history >= 0.0_dp
         ! With several independent joints, each joint's own sweep over the motions; the
         ! first motion's are its case's, as a single motion's run has them (the time-history
         ! gap of each joint's pairs).
         call suite_joint_sweeps(ctx, suite, first%joints, error)
         if (allocated(error)) return
         if (allocated(first%joints) .and. allocated(first%separation)) then
            block
               real(dp) :: th_gap(np)
               logical :: th_valid(np)

               call joint_thresholds(first%joints, np, th_gap, th_valid)
               first%separation%time_history = th_gap
               first%separation%time_history_valid = th_valid
            end block
         end if
      end if
      call sort_failures(suite%failures)

   contains

      !> Motion k run on every rank (its uncoupled run from the batch when it took it): its
      !> outcome, and unless it failed its histories; the first that does not
      !> fail is the run's single-motion case.
      subroutine whole_run(r, j)
         type(case_result), intent(out) :: r
         integer, intent(in) :: j

         if (batched_ok(j)) then
            call motion_run(ctx, k, r, outcomes(k), error, batched(j))
         else
            call motion_run(ctx, k, r, outcomes(k), error)
         end if
         if (allocated(error)) return
         if (outcomes(k)%failed) return
         if (suite%first == 0) suite%first = k
         call keep(r)
      end subroutine whole_run

      !> The sweeps of the motions whose run did not fail, as one loop of cases
      !> (`suite_gap_cases`), against their uncoupled peaks (kept in `ctx%unc` for the
      !> refinements too); each motion's sweep result from its gaps (`sweep_from_table`). A
      !> motion whose every gap fails fails as its run would (its outcome marked, its histories
      !> dropped). The first motion that does not fail is the run's single-motion case: run
      !> whole again if the one run whole failed here; it takes its sweep (result, warnings).
      subroutine motion_sweeps()
         type(suite_gap_cases) :: gaps
         type(case_table) :: all, one
         type(sweep_result), allocatable :: sweeps(:)
         type(error_type), allocatable :: failed
         type(motion_outcome) :: scratch
         integer, allocatable :: ks(:)
         integer :: j, ng, k1, iw
         integer(int64) :: c0, c1, rate

         call system_clock(c0, rate)
         ng = deck%sweep%n_gaps
         ks = pack([(k, k=1, nm)], .not. outcomes%failed .and. outcomes%has_influence)
         allocate (gaps%has_probe(size(ks)), gaps%closing(np, size(ks)), &
                   gaps%probe(ctx%layout%n_probe, size(ks)))
         do j = 1, size(ks)
            call peaks_from_outcome(ctx, outcomes(ks(j)), ctx%unc(ks(j)))
            ctx%has_unc(ks(j)) = .true.
            gaps%has_probe(j) = outcomes(ks(j))%has_probe
            gaps%closing(:, j) = outcomes(ks(j))%closing_max
            gaps%probe(:, j) = outcomes(ks(j))%probe
         end do
         gaps%ctx => ctx
         gaps%motions = ks
         call run_cases(gaps, size(ks)*ng, sweep_column_width(nb), all)
         call system_clock(c1)
         allocate (sweeps(nm))
         do j = 1, size(ks)
            k = ks(j)
            one%values = all%values(:, (j - 1)*ng + 1:j*ng)
            one%failed = all%failed((j - 1)*ng + 1:j*ng)
            one%message = all%message((j - 1)*ng + 1:j*ng)
            one%time = all%time((j - 1)*ng + 1:j*ng)
            one%step = all%step((j - 1)*ng + 1:j*ng)
            call sweep_from_table(deck%sweep, nb, one, sweeps(k), failed)
            if (allocated(failed)) then
               ! As `motion_run` marks a failed run (its message as `run_case` gives it).
               call outcome_fail(outcomes(k), label_prefix(ctx%label)//failed%message, failed%time, failed%step)
               ctx%has_unc(k) = .false.
               suite%histories(k) = motion_histories()
               deallocate (failed)
               cycle
            end if
            if (gaps%has_probe(j)) sweeps(k)%closing_max = gaps%closing(:, j)
            ! The loop's time shared evenly by the motions.
            sweeps(k)%seconds = real(c1 - c0, dp)/real(rate, dp)/size(ks)
            call gather_sweep(sweeps(k))
         end do
         k1 = findloc(outcomes%failed, .false., 1)
         if (k1 == 0) return
         if (k1 /= suite%first) then
            k = k1
            call motion_run(ctx, k, first, scratch, error)
            if (allocated(error)) return
            suite%first = k
         end if
         first%sweep = sweeps(k1)
         first%has_sweep = .true.
         if (allocated(sweeps(k1)%warnings)) then
            do iw = 1, size(sweeps(k1)%warnings)
               call add_warning(first%warnings, trim(sweeps(k1)%warnings(iw)))
            end do
         end if
      end subroutine motion_sweeps

      !> The histories of motion k, when its `&ground` asks for them.
      subroutine keep(res)
         type(case_result), intent(in) :: res

         if (.not. deck%motions(k)%histories) return
         suite%histories(k)%stored = .true.
         suite%histories(k)%ag_out = res%ag_out
         call analysis_copy(res%unc, suite%histories(k)%unc)
         suite%histories(k)%has_coupled = res%has_coupled
         if (res%has_coupled) call analysis_copy(res%cpl, suite%histories(k)%cpl)
      end subroutine keep

      !> The sweep of motion k: its largest |lambda| per quantity, building and gap (summed
      !> into the suite means at the end, over the motions of the statistics), its failed gaps.
      subroutine gather_sweep(sweep)
         type(sweep_result), intent(in) :: sweep
         integer :: iq, ig

         if (.not. suite%has_sweep) then
            suite%has_sweep = .true.
            suite%sweep_gap = sweep%gap
            allocate (suite%sweep_lambda(nm, size(sweep%gap)), suite%sweep_failed(nm, size(sweep%gap)))
            allocate (sweep_all(n_target_quantities, nb, size(sweep%gap), nm))
            suite%sweep_lambda = 0.0_dp
            suite%sweep_failed = .false.
            sweep_all = 0.0_dp
         end if
         sweep_all(:, :, :, k) = sweep%max_abs_lambda
         suite%sweep_failed(k, :) = sweep%failed
         do ig = 1, size(sweep%gap)
            if (sweep%failed(ig)) call add_failure(suite%failures, suite_failure(k, sweep%gap(ig), &
                                                   sweep%messages(ig), sweep%time(ig), sweep%step(ig)))
            suite%sweep_lambda(k, ig) = 0.0_dp
            do iq = 1, n_target_quantities
               if (targeted(iq)) suite%sweep_lambda(k, ig) = max(suite%sweep_lambda(k, ig), &
                                                                 maxval(sweep%max_abs_lambda(iq, :, ig)))
            end do
         end do
      end subroutine gather_sweep

      !> Scaling, spectra, peaks, lambdas and rules of motion k from its outcome (`motion_run`);
      !> a failed motion has its scaling and spectra only.
      subroutine gather(o)
         type(motion_outcome), intent(in) :: o
         integer :: n

         suite%scale_factor(k) = o%scale_factor
         suite%pga(k) = o%pga
         suite%sa(k, :) = o%sa
         suite%sa_building(k, :) = o%sa_building
         if (.not. o%has_influence) return
         call columns_gather(models, k, o%member, suite%columns)
         do ib = 1, nb
            n = deck%buildings(ib)%n_storeys
            suite%building(ib)%lambda(k, :, :) = o%building(ib)%lambda
            suite%building(ib)%yield(k, :, :) = o%building(ib)%yield
            suite%building(ib)%collapse(k, :) = nint(o%building(ib)%collapse)
            mean_unc(1:n, :, ib) = mean_unc(1:n, :, ib) + o%building(ib)%unc/suite%n_used
            mean_cpl(1:n, :, ib) = mean_cpl(1:n, :, ib) + o%building(ib)%cpl/suite%n_used
         end do
         do ip = 1, np
            known(:, ip) = known(:, ip) .and. o%pair_peak(:, ip) >= 0.0_dp
            mean_pair(:, ip) = mean_pair(:, ip) + o%pair_peak(:, ip)/suite%n_used
            call rules(o%pair_peak(1, ip), o%pair_peak(2, ip), ip, suite%separation(k, ip))
            ! The suite's no-contact gap: the largest over the motions (no motion makes
            ! contact at it); their mean is the mean closing displacement.
            suite%separation(k, ip)%no_contact = o%no_contact(ip)
            suite%separation(nm + 1, ip)%no_contact = max(suite%separation(nm + 1, ip)%no_contact, o%no_contact(ip))
            suite%mean_closing(ip) = suite%mean_closing(ip) + o%no_contact(ip)/suite%n_used
            closing_known(ip) = closing_known(ip) .and. o%no_contact(ip) >= 0.0_dp
         end do
      end subroutine gather

      !> The rules of pair ip from the peaks p1, p2 at its ends (m; < 0: not known, the rules
      !> n/a), with the buildings' design-code factors (`suite_pair_rules`), keeping the
      !> no-contact and time-history gaps already in `sep`.
      subroutine rules(p1, p2, ip, sep)
         real(dp), intent(in) :: p1, p2
         integer, intent(in) :: ip
         type(separation_t), intent(inout) :: sep

         associate (b => ctx%pair(ip)%building)
            call suite_pair_rules(p1, p2, deck%buildings(b(1))%factors, deck%buildings(b(2))%factors, &
                                  suite%building_period(b(1)), suite%building_period(b(2)), &
                                  z(b(1)), z(b(2)), ctx%pair(ip)%coincide, sep)
            sep%inelastic = [structure_yields(models(b(1))), structure_yields(models(b(2)))]
            sep%building = b
         end associate
      end subroutine rules

   end subroutine run_suite

end module pound_suite
