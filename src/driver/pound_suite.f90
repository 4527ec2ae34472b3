!> A suite of ground motions: every `&ground` of the deck, scaled, run as one case each
!> (`run_case`), with the suite statistics of the influence coefficients, the code separation
!> rules per contact pair and the 5 %-damped spectra.
!>
!> Per motion k:
!> 1. the motion: a pulse or a record (`deck_ground_motion`'s kinds), or a synthetic motion
!>    (`pound_synthetic_motion`, sampled at the analysis step `dt`);
!> 2. its scaling: the factor `scale` (records: applied on reading; synthetic: applied here), or
!>    `scale_to = 'pga'` / `'sa'`: the factor f = target/PGA or target/Sa(T) (5 % damping,
!>    T = `period`, by default the fundamental period of the most flexible building) of the
!>    motion as the solver samples it, a_g(n dt), n = 0..n_steps. A scaled motion is run as
!>    the samples f a_g(n dt) (a record of step dt, linear between samples: what the solver saw
!>    before scaling, times f), so it meets its target up to rounding. A pulse or record without
!>    `scale_to` is run as it is: a suite of one is today's single run, bit for bit;
!> 3. `run_case` with that motion: peaks, influence coefficients lambda (%).
!>
!> Over the suite (n motions):
!> * mean of the lambdas: (1/n) sum_k lambda_k (per floor/storey and quantity), and their
!>   maximum; the lambda of the means: lambda(mean coupled peak, mean uncoupled peak). Codes
!>   (ASCE 7 16.2.4, EC8 4.3.3.4.3) take the mean of the responses of the suite, i.e. the
!>   peaks are averaged first: that is the lambda of the means; both are given.
!> * separation rules at every contact pair (pound_separation), per motion from the uncoupled
!>   peak displacements of the two facing floors and their stored uncoupled histories (the
!>   no-contact gap needs `history` with 'u'; it is sampled every `output_every` steps), and
!>   for the suite from the mean peak displacements (ABS, SRSS, EC8, DDC) and the mean of the
!>   per-motion no-contact gaps. Elastic time-history peaks, no amplification factors.
!> * the time-history threshold gap (with `&sweep` and a target): per motion, the smallest gap
!>   of the sweep from which on the motion's own largest |lambda| meets the target, refined by
!>   bisection; for the suite, that of the suite mean. One value for every pair (the sweep gives
!>   every pair the same gap); -1 when not computed (no sweep, no target, none in the range).
!> * per-motion histories, for the motions whose `&ground` sets `histories` (kept for the
!>   HDF5 writer; the other motions keep only their peaks).
!> * spectra: Sa of every scaled motion at `n_spectrum` log-spaced periods from 0.02 to 4 s plus
!>   the buildings' fundamental periods, and their mean.
module pound_suite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str, fit_with_suffix
   use pound_config, only: deck_type, ground_config, n_history_quantities, n_target_quantities
   use pound_deck_variables, only: word_len, path_len
   use pound_ground_motion, only: ground_motion_t, sample_ground
   use pound_synthetic_motion, only: synthetic_config, synthetic_motion
   use pound_structure, only: structure_model, structure_names
   use pound_building, only: building_model, build_building
   use pound_spectrum, only: response_spectrum, period_grid, peak_ground_acceleration, &
                             scale_to_pga, scale_to_sa
   use pound_influence, only: influence_coefficient, max_abs_target
   use pound_separation, only: separation_t, separation_abs, separation_srss, separation_ec8, &
                               separation_ddc, cqc_correlation, no_contact_gap
   use pound_run_case, only: case_options, case_result, run_case, configured_motion, label_prefix, &
                             analysis_plan_of
   use pound_analysis_plan, only: steps_of, output_steps
   use pound_analysis, only: analysis_result, n_energy, analysis_copy, add_warning
   use pound_contact, only: contact_pair, pairs_from_config
   use pound_sweep, only: sweep_result, gap_cases, gap_cases_init, gap_cases_probe, gap_cases_set_probe, &
                          sweep_column_width, sweep_from_table
   use iso_fortran_env, only: int64
   use pound_analysis_batch, only: batch_eligible, run_uncoupled_batch, batch_lanes
   use pound_cases, only: case_work, case_table, run_cases, first_failure, cases_ranks, case_message_len, &
                          text_to_column, column_to_text
   use pound_sort, only: sort_ascending
   use pound_suite_columns, only: column_suite, column_block_width, columns_to_block, columns_init, &
                                  columns_gather, columns_finish, member_peaks_from_block
   implicit none
   private

   public :: suite_result, suite_failure, run_suite, suite_sweep_statistics, suite_motion, suite_pairs, n_spectrum, spectrum_damping
   public :: motion_histories, bisection, bisection_step, bisection_update, time_history_gap

   !> Log-spaced periods of the suite spectra (before the buildings' periods are added).
   integer, parameter :: n_spectrum = 60
   !> Damping ratio of the spectra and of `scale_to = 'sa'`.
   real(dp), parameter :: spectrum_damping = 0.05_dp
   !> Batched uncoupled runs (`pound_analysis_batch`): at least this many motions a batch (fewer
   !> run one by one), and at most this many bytes of their results held at once.
   integer, parameter :: batch_min = 3
   real(dp), parameter :: batch_bytes = 256.0_dp*2.0_dp**20
   !> Failed trial gaps a motion's own threshold refinement carries to the writer (more are
   !> counted in the last one's message).
   integer, parameter :: refine_failures_kept = 8
   !> Reals of one failure in a case's column: the gap, then the message (`text_to_column`).
   integer, parameter :: failure_width = 2 + case_message_len

   !> A failed case of a suite: a motion's run at the deck's gaps (uncoupled or coupled), at a
   !> gap of its sweep, or at a trial gap of a threshold refinement.
   type :: suite_failure
      !> Motion index.
      integer :: motion = 0
      !> Gap of every joint (m); -1: the motion's run at the deck's gaps.
      real(dp) :: gap = -1.0_dp
      !> The error message.
      character(len=case_message_len) :: message = ''
   end type suite_failure

   !> Bisection for a threshold gap: `lo` fails the target, `hi` meets it; halved until
   !> hi - lo <= tol (reverse communication: `bisection_step` gives the trial gap,
   !> `bisection_update` takes its verdict).
   type :: bisection
      !> Failing and passing gap, tolerance (m).
      real(dp) :: lo = 0.0_dp, hi = 0.0_dp, tol = 0.0_dp
   end type bisection

   !> The histories of one motion of the suite, kept when its `&ground` sets `histories`.
   type :: motion_histories
      !> Whether they were kept, and whether the coupled analysis ran.
      logical :: stored = .false., has_coupled = .false.
      !> Ground acceleration at the output times (m/s^2).
      real(dp), allocatable :: ag_out(:)
      !> Uncoupled and coupled results.
      type(analysis_result) :: unc, cpl
   end type motion_histories

   !> Influence coefficients of one building over the suite, (n, n_history_quantities) each.
   type :: building_suite
      !> Mean and maximum of the per-motion lambdas, and the lambda of the mean peaks (%).
      real(dp), allocatable :: mean_lambda(:, :), max_lambda(:, :), lambda_of_means(:, :)
      !> Per motion lambda (%), (n_motions, n, n_history_quantities).
      real(dp), allocatable :: lambda(:, :, :)
   end type building_suite

   !> Everything a suite computes.
   type :: suite_result
      !> Motion names, the scale factor applied by the suite (1 for `scale`), PGA (m/s^2) of
      !> the motion as run.
      character(len=word_len), allocatable :: names(:)
      !> Where each motion comes from: the record file as resolved, 'synthetic, seed N' or
      !> 'pulse'.
      character(len=path_len), allocatable :: source(:)
      real(dp), allocatable :: scale_factor(:), pga(:)
      !> Periods of the spectra (s), Sa (m/s^2, n_motions x n_periods) and its suite mean.
      real(dp), allocatable :: period(:), sa(:, :), mean_sa(:)
      !> Fundamental period of every building (s).
      real(dp), allocatable :: building_period(:)
      !> Scaling target of every motion (m/s^2; -1: scaled by a factor) and its period (s; the
      !> period of a Sa target, 0 for a PGA target, the rigid limit of the spectrum; -1: none).
      real(dp), allocatable :: target(:), target_period(:)
      !> Sa of every motion at every building's fundamental period (n_motions, n_buildings).
      real(dp), allocatable :: sa_building(:, :)
      !> Whether the deck declares contact (influence and separation exist).
      logical :: has_coupled = .false.
      !> Per building.
      type(building_suite), allocatable :: building(:)
      !> Per building: its column segments' lambdas over the suite (frames; `pound_suite_columns`).
      type(column_suite), allocatable :: columns(:)
      !> Separation rules (n_motions + 1, n_pairs; the last row: the suite), over every pair of
      !> every `&contact` in deck order.
      type(separation_t), allocatable :: separation(:, :)
      !> Whether the deck's `&sweep` ran for every motion.
      logical :: has_sweep = .false.
      !> Sweep gaps (m).
      real(dp), allocatable :: sweep_gap(:)
      !> Largest |lambda| (%) over the targeted quantities (all, without a target), buildings and
      !> floors/storeys, per motion and gap (n_motions, n_gaps).
      real(dp), allocatable :: sweep_lambda(:, :)
      !> Per gap: the suite mean of the per-motion largest |lambda| of each quantity and
      !> building, maximised over the targeted ones, and the largest over the motions (n_gaps).
      real(dp), allocatable :: sweep_mean(:), sweep_max(:)
      !> Smallest gap from which on every larger gap meets the target on the mean and on every
      !> motion (m; -1 when none or no target).
      real(dp) :: safe_gap_mean = -1.0_dp, safe_gap_every = -1.0_dp
      !> The same thresholds refined by bisection between the last failing and the first
      !> passing gap of the grid, to `refine_tolerance` (m; -1 when not refined).
      real(dp) :: refined_gap_mean = -1.0_dp, refined_gap_every = -1.0_dp
      !> Grid gaps below the safe gap that pass nevertheless (non-monotone behaviour), on the
      !> mean and on every motion.
      integer :: non_monotone_mean = 0, non_monotone_every = 0
      !> Per motion: the safe grid gap and its refinement on the motion's own largest |lambda|
      !> (m; -1 when none), and the grid gaps below it that pass nevertheless (n_motions).
      real(dp), allocatable :: safe_gap_motion(:), refined_gap_motion(:)
      integer, allocatable :: non_monotone_motion(:)
      !> Tolerance of the refinements (m, `&sweep refine_tolerance`).
      real(dp) :: refine_tolerance = 0.0_dp
      !> Per motion: its histories, when asked (n_motions).
      type(motion_histories), allocatable :: histories(:)
      !> Per motion: whether its run at the deck's gaps failed (it is then left out of every
      !> statistic over the motions; n_motions).
      logical, allocatable :: motion_failed(:)
      !> Number of motions the statistics are over (those that did not fail).
      integer :: n_used = 0
      !> The motion whose case is the run's single-motion results (the first motion run whole that did not fail).
      integer :: first = 0
      !> Per motion and sweep gap: whether the motion's run at the gap failed (n_motions, n_gaps);
      !> per gap: whether any motion of the statistics failed at it (the suite gap is FAILED:
      !> not meeting the target, its mean and max 0).
      logical, allocatable :: sweep_failed(:, :), gap_failed(:)
      !> Every failed case, by motion, then gap (-1, the deck's gaps, first).
      type(suite_failure), allocatable :: failures(:)
   end type suite_result

   !> What the suite's cases share: the configuration (and the same without its sweep), the
   !> buildings, the spectra's periods, the contact pairs, the targeted quantities, the sweep's
   !> grid and the label of the messages.
   type :: suite_context
      !> The deck as given, and the same without its sweep (the runs at a trial gap).
      type(deck_type), pointer :: deck => null()
      type(deck_type) :: plain
      !> The buildings (periods for `scale_to = 'sa'`).
      type(structure_model), pointer :: models(:) => null()
      !> Quantities the target applies to (`target_names`).
      logical :: targeted(n_target_quantities) = .true.
      !> The sweep's gaps (m).
      real(dp), allocatable :: gap(:)
      !> Put before the messages (may be empty).
      character(len=:), allocatable :: label
      !> Periods of the spectra and the buildings' fundamental periods (s).
      real(dp), allocatable :: period(:), building_period(:)
      !> Contact pairs in deck order: buildings on the left and right, facing floors.
      integer, allocatable :: left(:), right(:), fl(:), fr(:)
      !> The motions the statistics are over (those whose run did not fail), in order.
      integer, allocatable :: used(:)
      !> With `&sweep`: each motion's uncoupled peaks (from its column), and whether they are
      !> there (its run did not fail); the runs at the sweep's gaps and at a refinement's trial
      !> gaps compare with them instead of running the uncoupled analysis again (it does not
      !> depend on the gap).
      type(analysis_result), allocatable :: unc(:)
      logical, allocatable :: has_unc(:)
      !> Whether the motions' sweeps run (`&sweep` and contact): each motion's case then makes
      !> its sweep's probe, and the gaps of every motion are the cases of one loop
      !> (`suite_gap_cases`).
      logical :: sweep = .false.
   end type suite_context

   !> The motions of a suite without `&sweep` as cases: case i is the group of motions
   !> `motion(start(i):start(i+1)-1)`, their uncoupled runs batched (`batch_uncoupled`), each
   !> motion then scaled, its spectra and its run into its part of the column (`motion_run`;
   !> `motion_width` reals a motion, motion j of the group at (j-1)*motion_width).
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

   !> The motions at one trial gap as cases: column = the largest |lambda| of motion
   !> `motions(i)` per targeted quantity and building (n_target_quantities x n_buildings; 0
   !> where not targeted).
   type, extends(case_work) :: motion_cases
      !> The refinement's data.
      type(suite_context), pointer :: ctx => null()
      !> Motion index of each case.
      integer, allocatable :: motions(:)
      !> Trial gap (m).
      real(dp) :: gap = 0.0_dp
   contains
      procedure :: compute => motion_case
   end type motion_cases

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
      !> Each motion's probe block of its column (`probe_slot`), by entry of `motions`.
      real(dp), allocatable :: probes(:, :)
      !> Entry of `motions` that `gaps` is set up for (0: none).
      integer :: current = 0
      !> That motion's gaps.
      type(gap_cases) :: gaps
   contains
      procedure :: compute => suite_gap_case
   end type suite_gap_cases

   !> The motions' own threshold refinements as cases: column = motion k's refined gap, the
   !> number of its failed trial gaps and the first `refine_failures_kept` of them
   !> (`failure_to_column`).
   type, extends(case_work) :: refine_cases
      !> The refinement's data.
      type(suite_context), pointer :: ctx => null()
      !> Each motion's safe grid gap (m; -1: none).
      real(dp), allocatable :: safe(:)
   contains
      procedure :: compute => refine_case
   end type refine_cases

contains

   !> The group of motions of case i (a case of `suite_cases`): their uncoupled runs batched,
   !> then each motion's run.
   recursive subroutine suite_case(work, i, values, error)
      !> The cases.
      class(suite_cases), intent(inout) :: work
      !> Case index.
      integer, intent(in) :: i
      !> The motions' columns one after the other (`motion_run`).
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(case_result) :: res
      type(analysis_result), allocatable, target :: batched(:)
      logical, allocatable :: ok(:)
      integer :: j, w

      values = 0.0_dp
      w = motion_width(work%ctx)
      associate (ms => work%motion(work%start(i):work%start(i + 1) - 1))
         call batch_uncoupled(work%ctx, ms, batched, ok, error)
         if (allocated(error)) return
         do j = 1, size(ms)
            if (ok(j)) then
               call motion_run(work%ctx, ms(j), res, values((j - 1)*w + 1:j*w), error, batched(j))
            else
               call motion_run(work%ctx, ms(j), res, values((j - 1)*w + 1:j*w), error)
            end if
            if (allocated(error)) return
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

   !> Reals in the column of one motion (`motion_run`).
   pure integer function motion_width(ctx) result(width)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx

      width = failure_slot(ctx) + 1 + failure_width
      if (ctx%sweep) width = probe_slot(ctx) + probe_width(ctx)
      ! Last, the frames' member lambdas and uncoupled member peaks (`columns_to_block`).
      width = width + column_block_width(ctx%models)
   end function motion_width

   !> Offset in a motion's column of its sweep's probe (with `ctx%sweep`): 1 when the probe
   !> ran, each joint's largest closing displacement, the probe's column (`gap_cases_probe`).
   pure integer function probe_slot(ctx) result(offset)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx

      offset = failure_slot(ctx) + 1 + failure_width
   end function probe_slot

   !> Reals of the probe block (`probe_slot`).
   pure integer function probe_width(ctx) result(width)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx

      width = 1 + size(ctx%left) + sweep_column_width(size(ctx%models))
   end function probe_width

   !> Offset in a motion's column of its failure: 1 when its run failed, then the failure
   !> (`failure_to_column`, gap -1).
   pure integer function failure_slot(ctx) result(offset)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx

      offset = motion_offset(ctx, 4, 1) + size(ctx%left)
   end function failure_slot

   !> A failure at `gap` (m; -1: the deck's gaps) with `message` into `values`
   !> (`failure_width` reals).
   pure subroutine failure_to_column(gap, message, values)
      !> Gap (m).
      real(dp), intent(in) :: gap
      !> The error message (cut to `case_message_len`).
      character(len=*), intent(in) :: message
      !> The column's part.
      real(dp), intent(out) :: values(:)

      values(1) = gap
      call text_to_column(message, values(2:failure_width))
   end subroutine failure_to_column

   !> Mark a motion's column `col` as its failed run's (`failure_slot`) with `message`: the
   !> scaling and the spectra kept, its results (influence flag, lambdas, peaks, no-contact
   !> gaps) zero.
   pure subroutine mark_failed(ctx, message, col)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> The error message.
      character(len=*), intent(in) :: message
      !> The motion's column.
      real(dp), intent(inout) :: col(:)
      integer :: o

      o = failure_slot(ctx)
      col(3) = 0.0_dp
      col(motion_offset(ctx, 1, 1) + 1:o) = 0.0_dp
      col(o + 1) = 1.0_dp
      call failure_to_column(-1.0_dp, message, col(o + 2:o + 1 + failure_width))
   end subroutine mark_failed

   !> The failure of motion k that `failure_to_column` put in `values`.
   pure function column_failure(values, k) result(f)
      !> The column's part.
      real(dp), intent(in) :: values(:)
      !> Motion index.
      integer, intent(in) :: k
      type(suite_failure) :: f

      f%motion = k
      f%gap = values(1)
      f%message = column_to_text(values(2:failure_width))
   end function column_failure

   !> Add the failure `f` to `list` unless the same motion already failed at the same gap
   !> (the suite's two refinements may try the same gap).
   pure subroutine add_failure(list, f)
      !> The failures so far.
      type(suite_failure), allocatable, intent(inout) :: list(:)
      !> The new one.
      type(suite_failure), intent(in) :: f
      integer :: i

      if (.not. allocated(list)) allocate (list(0))
      do i = 1, size(list)
         if (list(i)%motion == f%motion .and. list(i)%gap == f%gap) return
      end do
      list = [list, f]
   end subroutine add_failure

   !> Offset in a motion's column of block `which` (1 lambda, 2 uncoupled peaks, 3 coupled
   !> peaks) of building ib, each (n_storeys, n_history_quantities).
   pure integer function motion_offset(ctx, which, ib) result(offset)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> Block and building.
      integer, intent(in) :: which, ib
      integer :: total

      total = n_history_quantities*sum(ctx%deck%buildings%n_storeys)
      offset = 3 + size(ctx%period) + size(ctx%building_period) + (which - 1)*total + &
               n_history_quantities*sum(ctx%deck%buildings(1:ib - 1)%n_storeys)
   end function motion_offset

   !> Motion k of the suite: scaled, its spectra, run (`run_case`) into `res`, and what the
   !> suite's statistics need of it in `col`: scale factor, PGA, whether the influence exists,
   !> Sa at the spectra's periods and at the buildings' periods, per building lambda, the
   !> uncoupled and the coupled peaks, and per pair the no-contact gap (-1 without 'u'); with
   !> the motions' sweeps (`ctx%sweep`), not the sweep's gaps (`suite_gap_cases`) but its
   !> probe (`probe_slot`). A run that fails is no error: its failure is put in the column
   !> (`failure_slot`), the spectra kept. With `unc`, the motion's uncoupled result is taken
   !> from there (a batch ran it).
   subroutine motion_run(ctx, k, res, col, error, unc)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> Motion index.
      integer, intent(in) :: k
      !> The motion's case.
      type(case_result), intent(out), target :: res
      !> Its column (`motion_width` reals).
      real(dp), intent(out) :: col(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The motion's uncoupled result, already computed (`batch_uncoupled`).
      type(analysis_result), intent(inout), target, optional :: unc
      type(case_options) :: options
      real(dp), allocatable :: ag(:), sa(:), u1(:), u2(:)
      real(dp) :: dt
      integer :: n_steps, o, ib, ip, n, w

      col = 0.0_dp
      dt = ctx%deck%analysis%dt
      n_steps = steps_of(ctx%deck%analysis%t_end, dt)
      if (allocated(ctx%label)) options%label = ctx%label
      allocate (options%ground, ag(0:n_steps))
      call suite_motion_samples(ctx%deck, k, ctx%models, options%ground, col(1), ag, error)
      if (allocated(error)) return
      col(2) = peak_ground_acceleration(ag)
      o = 3
      call response_spectrum(ag, dt, ctx%period, spectrum_damping, sa, error)
      if (allocated(error)) return
      col(o + 1:o + size(sa)) = sa
      o = o + size(sa)
      call response_spectrum(ag, dt, ctx%building_period, spectrum_damping, sa, error)
      if (allocated(error)) return
      col(o + 1:o + size(sa)) = sa
      if (present(unc)) options%unc => unc
      if (ctx%sweep) then
         call run_case(ctx%plain, res, error, options)
      else
         call run_case(ctx%deck, res, error, options)
      end if
      if (allocated(error)) then
         ! A failed run is the motion's failure, carried in its column: the others go on.
         call mark_failed(ctx, error%message, col)
         deallocate (error)
         return
      end if
      if (.not. (res%has_coupled .and. res%has_uncoupled)) return
      col(3) = 1.0_dp
      do ib = 1, size(ctx%models)
         n = ctx%deck%buildings(ib)%n_storeys
         w = n*n_history_quantities
         o = motion_offset(ctx, 1, ib)
         col(o + 1:o + w) = reshape(res%influence(ib)%lambda, [w])
         o = motion_offset(ctx, 2, ib)
         col(o + 1:o + w) = reshape(res%unc%building(ib)%peak, [w])
         o = motion_offset(ctx, 3, ib)
         col(o + 1:o + w) = reshape(res%cpl%building(ib)%peak, [w])
      end do
      call columns_to_block(ctx%models, res%influence, res%unc, col(size(col) - column_block_width(ctx%models) + 1:))
      o = motion_offset(ctx, 4, 1)
      do ip = 1, size(ctx%left)
         col(o + ip) = -1.0_dp
         if (ctx%deck%analysis%store(1)) then
            associate (b1 => res%unc%building(ctx%left(ip)), b2 => res%unc%building(ctx%right(ip)))
               u1 = b1%u(ctx%fl(ip), 1:b1%n_out)
               u2 = b2%u(ctx%fr(ip), 1:b2%n_out)
               col(o + ip) = no_contact_gap(u1, u2)
            end associate
         end if
      end do
      if (ctx%sweep) call motion_probe(ctx, res, ag, options%ground, &
                                       col(probe_slot(ctx) + 1:probe_slot(ctx) + probe_width(ctx)))
   end subroutine motion_run

   !> The probe of motion k's sweep (`gap_cases_probe`) into its block of the column
   !> (`probe_slot`): 1 and the joints' largest closing displacements and the probe's column,
   !> or 0 when the probe could not be made (every gap then runs).
   subroutine motion_probe(ctx, res, ag, ground, block)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> The motion's case (models, uncoupled result).
      type(case_result), intent(in), target :: res
      !> The motion's ground acceleration at every step (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The motion.
      type(ground_motion_t), intent(in) :: ground
      !> The probe block (`probe_width` reals).
      real(dp), intent(out) :: block(:)
      type(gap_cases) :: cases
      type(contact_pair), allocatable :: pairs(:)
      type(error_type), allocatable :: error
      integer :: nj

      block = 0.0_dp
      nj = size(ctx%left)
      pairs = pairs_from_config(ctx%deck%contacts, structure_names(res%models), error)
      if (allocated(error)) return
      call gap_cases_init(cases, analysis_plan_of(ctx%deck%analysis), ctx%deck%sweep, res%models, ag, pairs, res%unc, &
                          error, ground)
      if (allocated(error)) return
      call gap_cases_probe(cases)
      if (.not. allocated(cases%probe)) return
      block(1) = 1.0_dp
      block(2:1 + nj) = cases%closing_max
      block(2 + nj:) = cases%probe
   end subroutine motion_probe

   !> A motion's uncoupled peaks from its column (`motion_run`), as the uncoupled result that
   !> the coupled runs at other gaps compare with (`influence_of` takes the peaks).
   pure subroutine peaks_from_column(ctx, col, unc)
      !> The suite's data.
      type(suite_context), intent(in) :: ctx
      !> The motion's column.
      real(dp), intent(in) :: col(:)
      !> Its uncoupled peaks (no output times, no histories).
      type(analysis_result), intent(out) :: unc
      integer :: ib, n, o

      allocate (unc%time(0), unc%energy(n_energy, 0), unc%building(size(ctx%models)))
      do ib = 1, size(ctx%models)
         n = ctx%deck%buildings(ib)%n_storeys
         o = motion_offset(ctx, 2, ib)
         unc%building(ib)%peak = reshape(col(o + 1:o + n*n_history_quantities), [n, n_history_quantities])
      end do
      call member_peaks_from_block(ctx%models, col(size(col) - column_block_width(ctx%models) + 1:), unc)
   end subroutine peaks_from_column

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
      real(dp) :: factor
      integer :: j, k, ng, nj, n_steps

      ng = work%ctx%deck%sweep%n_gaps
      j = (i - 1)/ng + 1
      if (work%current /= j) then
         work%current = 0
         k = work%motions(j)
         associate (deck => work%ctx%deck)
            n_steps = steps_of(deck%analysis%t_end, deck%analysis%dt)
            allocate (ag(0:n_steps))
            call suite_motion_samples(deck, k, work%ctx%models, gm, factor, ag, error)
            if (allocated(error)) return
            pairs = pairs_from_config(deck%contacts, structure_names(work%ctx%models), error)
            if (allocated(error)) return
            call gap_cases_init(work%gaps, analysis_plan_of(deck%analysis), deck%sweep, work%ctx%models, ag, pairs, &
                                work%ctx%unc(k), error, gm)
            if (allocated(error)) return
         end associate
         nj = size(work%ctx%left)
         if (work%probes(1, j) > 0.0_dp) call gap_cases_set_probe(work%gaps, work%probes(2:1 + nj, j), &
                                                                  work%probes(2 + nj:, j))
         work%current = j
      end if
      call work%gaps%compute(i - (j - 1)*ng, values, error)
   end subroutine suite_gap_case

   !> Motion m at the trial gap (a case of `motion_cases`).
   recursive subroutine motion_case(work, i, values, error)
      !> The cases.
      class(motion_cases), intent(inout) :: work
      !> Motion index.
      integer, intent(in) :: i
      !> Its largest |lambda| per quantity and building.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: lam(n_target_quantities, size(work%ctx%models))

      call motion_lambda(work%ctx, work%motions(i), work%gap, lam, error)
      if (allocated(error)) return
      values = reshape(lam, [size(lam)])
   end subroutine motion_case

   !> Motion k's threshold refinement (a case of `refine_cases`).
   recursive subroutine refine_case(work, i, values, error)
      !> The cases.
      class(refine_cases), intent(inout) :: work
      !> Motion index.
      integer, intent(in) :: i
      !> Its refined gap (m; -1: none), its failed trial gaps.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(suite_failure), allocatable :: failures(:)
      character(len=:), allocatable :: text
      integer :: j, o

      values = 0.0_dp
      call refine(work%ctx, work%safe(i), i, values(1), failures, error)
      if (allocated(error)) return
      values(2) = real(size(failures), dp)
      do j = 1, min(size(failures), refine_failures_kept)
         text = trim(failures(j)%message)
         if (j == refine_failures_kept .and. size(failures) > j) text = fit_with_suffix(text, ' (and '// &
            str(size(failures) - j)//' more trial gaps of this refinement failed)', case_message_len)
         o = 2 + (j - 1)*failure_width
         call failure_to_column(failures(j)%gap, text, values(o + 1:o + failure_width))
      end do
   end subroutine refine_case

   !> Motion m run at `gap` (no sweep): its largest |lambda| over the floors per quantity and
   !> building, zero for the quantities not targeted.
   subroutine motion_lambda(ctx, m, gap, lam, error)
      !> The refinement's data.
      type(suite_context), intent(in), target :: ctx
      !> Motion index.
      integer, intent(in) :: m
      !> Gap of every joint (m).
      real(dp), intent(in) :: gap
      !> Largest |lambda| (%), (n_target_quantities, n_buildings).
      real(dp), intent(out) :: lam(:, :)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(case_options) :: opt
      type(case_result) :: r
      real(dp) :: factor
      integer :: iq

      opt%gap = gap
      if (allocated(ctx%label)) opt%label = ctx%label
      allocate (opt%ground)
      call suite_motion(ctx%deck, m, ctx%models, opt%ground, factor, error)
      if (allocated(error)) return
      if (allocated(ctx%has_unc)) then
         if (ctx%has_unc(m)) opt%unc => ctx%unc(m)
      end if
      call run_case(ctx%plain, r, error, opt)
      if (allocated(error)) return
      lam = max_abs_target(r%influence, r%models)
      do iq = 1, n_target_quantities
         if (.not. ctx%targeted(iq)) lam(iq, :) = 0.0_dp
      end do
   end subroutine motion_lambda

   !> Bisection between the grid gap below `safe` (failing) and `safe` (passing), down to
   !> the tolerance: the motions run at the trial gap (no sweep), the criterion on the suite
   !> mean (`which` = 0), on every motion (-1) or on motion `which` alone (> 0). A trial gap
   !> at which a motion fails does not meet the target (the refined gap lies above it); its
   !> failures are added to `failures`.
   subroutine refine(ctx, safe, which, refined, failures, error)
      !> The refinement's data.
      type(suite_context), intent(in), target :: ctx
      !> Safe grid gap (m; <= 0: none).
      real(dp), intent(in) :: safe
      !> Criterion: 0 the suite mean, -1 every motion, k > 0 motion k.
      integer, intent(in) :: which
      !> Refined gap (m; -1: not refined).
      real(dp), intent(out) :: refined
      !> The failed cases so far.
      type(suite_failure), allocatable, intent(inout) :: failures(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(bisection) :: b
      real(dp) :: mid, worst
      integer :: ig
      logical :: more

      refined = -1.0_dp
      if (.not. allocated(failures)) allocate (failures(0))
      ig = findloc(ctx%gap, safe, 1)
      if (.not. (safe > 0.0_dp) .or. ig <= 1) return
      b = bisection(ctx%gap(ig - 1), safe, ctx%deck%sweep%refine_tolerance)
      mid = safe
      do
         call bisection_step(b, mid, more)
         if (.not. more) exit
         call worst_at(ctx, mid, which, worst, failures, error)
         if (allocated(error)) return
         call bisection_update(b, mid, worst <= ctx%deck%sweep%target)
      end do
      refined = b%hi
   end subroutine refine

   !> The motions at one gap: the largest |lambda| over the targeted quantities and the
   !> buildings, as the suite mean (`which` = 0: the mean per quantity and building, then the
   !> largest), the largest over the motions (-1), or of motion `which` alone (> 0). The
   !> motions of a suite criterion (those of the statistics) are cases (`motion_cases`),
   !> summed in motion order. A motion that fails at the gap is added to `failures` and the
   !> gap does not meet the target (`worst` = huge).
   subroutine worst_at(ctx, gap, which, worst, failures, error)
      !> The refinement's data.
      type(suite_context), intent(in), target :: ctx
      !> Trial gap (m).
      real(dp), intent(in) :: gap
      !> Criterion: 0 the suite mean, -1 every motion, k > 0 motion k.
      integer, intent(in) :: which
      !> The criterion's value (%).
      real(dp), intent(out) :: worst
      !> The failed cases so far.
      type(suite_failure), allocatable, intent(inout) :: failures(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(motion_cases) :: cases
      type(case_table) :: table
      real(dp) :: lam(n_target_quantities, size(ctx%models)), total(n_target_quantities, size(ctx%models))
      integer :: m, nm

      worst = huge(1.0_dp)
      if (which > 0) then
         call motion_lambda(ctx, which, gap, lam, error)
         if (allocated(error)) then
            call add_failure(failures, suite_failure(which, gap, error%message))
            deallocate (error)
            return
         end if
         worst = max(0.0_dp, maxval(lam))
         return
      end if
      nm = size(ctx%used)
      cases%ctx => ctx
      cases%gap = gap
      cases%motions = ctx%used
      call run_cases(cases, nm, size(lam), table)
      do m = 1, nm
         if (table%failed(m)) call add_failure(failures, suite_failure(ctx%used(m), gap, table%message(m)))
      end do
      if (any(table%failed)) return
      total = 0.0_dp
      worst = 0.0_dp
      do m = 1, nm
         lam = reshape(table%values(:, m), shape(lam))
         total = total + lam/nm
         worst = max(worst, maxval(lam))
      end do
      if (which == 0) worst = maxval(total)
   end subroutine worst_at

   !> "&ground 'name'" and `suffix` for every motion of the deck (the names of its cases).
   !> With `which`, those motions only; with `bare`, blank names (the cases' messages name their
   !> motion themselves).
   pure function motion_names(deck, suffix, which, bare) result(names)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Put after each name.
      character(len=*), intent(in) :: suffix
      !> Motion indices (default: every motion).
      integer, intent(in), optional :: which(:)
      !> Blank names.
      logical, intent(in), optional :: bare
      character(len=word_len + 12 + len(suffix)), allocatable :: names(:)
      integer, allocatable :: m(:)
      integer :: i

      if (present(which)) then
         allocate (m(size(which)))
         m = which
      else
         allocate (m(size(deck%motions)))
         m = [(i, i=1, size(deck%motions))]
      end if
      allocate (names(size(m)))
      names = ''
      if (present(bare)) then
         if (bare) return
      end if
      do i = 1, size(m)
         names(i) = "&ground '"//deck%motions(m(i))%name//"'"//suffix
      end do
   end function motion_names

   !> Next trial gap `mid` of the bisection `b`, or `more` false when hi - lo <= tol.
   pure subroutine bisection_step(b, mid, more)
      !> The bisection.
      type(bisection), intent(in) :: b
      !> Trial gap (m), the midpoint; unchanged when `more` is false.
      real(dp), intent(inout) :: mid
      !> Whether a trial is needed.
      logical, intent(out) :: more

      more = b%hi - b%lo > b%tol
      if (more) mid = 0.5_dp*(b%lo + b%hi)
   end subroutine bisection_step

   !> The verdict on the trial gap `mid`: it becomes `hi` when it meets the target, else `lo`.
   pure subroutine bisection_update(b, mid, passes)
      !> The bisection.
      type(bisection), intent(inout) :: b
      !> Trial gap (m).
      real(dp), intent(in) :: mid
      !> Whether `mid` meets the target.
      logical, intent(in) :: passes

      if (passes) then
         b%hi = mid
      else
         b%lo = mid
      end if
   end subroutine bisection_update

   !> The time-history threshold gap: the refined gap when there is one, else the safe grid
   !> gap (the first gap of the grid when it already meets the target: an upper bound), else -1.
   elemental real(dp) function time_history_gap(safe, refined) result(gap)
      !> Safe grid gap and its refinement (m; -1: none).
      real(dp), intent(in) :: safe, refined

      gap = merge(refined, safe, refined >= 0.0_dp)
   end function time_history_gap

   !> The ground motion k of the suite as it is run, and the factor the suite applied to it.
   subroutine suite_motion(deck, k, models, gm, factor, error)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Motion index in `deck%motions`.
      integer, intent(in) :: k
      !> The buildings (their fundamental periods give the default period of `scale_to = 'sa'`).
      type(structure_model), intent(in) :: models(:)
      !> The motion as run.
      type(ground_motion_t), intent(out) :: gm
      !> Scale factor applied by the suite (1: none, or `scale` of a synthetic motion).
      real(dp), intent(out) :: factor
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(ground_config) :: g
      type(ground_motion_t) :: base
      real(dp), allocatable :: ag(:)
      real(dp) :: dt, period
      integer :: n_steps, i, ib

      g = deck%motions(k)
      dt = deck%analysis%dt
      n_steps = steps_of(deck%analysis%t_end, dt)
      factor = 1.0_dp
      if (g%kind == 'synthetic') then
         call synthetic(base, error)
         factor = g%scale
      else
         call configured_motion(g, base, error)
      end if
      if (allocated(error)) then
         error%message = "&ground '"//g%name//"': "//error%message
         return
      end if
      if (len(g%scale_to) == 0 .and. g%kind /= 'synthetic') then
         gm = base
         return
      end if
      allocate (ag(0:n_steps))
      call sample_ground(base, dt, n_steps, ag)
      select case (g%scale_to)
      case ('pga')
         call scale_to_pga(ag, g%target, factor, error)
      case ('sa')
         period = g%period
         if (.not. (period > 0.0_dp)) then
            period = 0.0_dp
            do ib = 1, size(models)
               period = max(period, models(ib)%period(1))
            end do
         end if
         call scale_to_sa(ag, dt, period, spectrum_damping, g%target, factor, error)
      end select
      if (allocated(error)) then
         error%message = "&ground '"//g%name//"': "//error%message
         return
      end if
      gm%kind = 'record'
      gm%path = g%name
      gm%format = g%kind
      gm%title = g%name
      gm%scale = factor
      gm%dt = dt
      gm%time = [(real(i, dp)*dt, i=0, n_steps)]
      gm%accel = factor*ag

   contains

      subroutine synthetic(s, error)
         type(ground_motion_t), intent(out) :: s
         type(error_type), allocatable, intent(out) :: error
         type(synthetic_config) :: c

         c%filter = g%filter
         c%wg = g%ground_frequency
         c%zg = g%ground_damping
         c%wf = g%filter_frequency
         c%zf = g%filter_damping
         c%envelope = g%envelope
         c%t1 = g%rise_time
         c%t2 = g%plateau_end
         c%c = g%decay_rate
         c%eps = g%peak_fraction
         c%eta = g%end_level
         c%duration = g%duration
         c%pga = g%pga
         c%seed = g%seed
         s%kind = 'record'
         s%path = g%name
         s%format = 'synthetic'
         s%title = g%name
         s%dt = dt
         call synthetic_motion(c, dt, s%accel, error)
         if (allocated(error)) return
         s%time = [(real(i, dp)*dt, i=0, size(s%accel) - 1)]
      end subroutine synthetic

   end subroutine suite_motion

   !> Motion k as run (`suite_motion`) and its ground accelerations at t_n = n dt,
   !> n = 0..size(ag) - 1 (m/s^2).
   subroutine suite_motion_samples(deck, k, models, gm, factor, ag, error)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Motion index in `deck%motions`.
      integer, intent(in) :: k
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The motion as run.
      type(ground_motion_t), intent(out) :: gm
      !> Scale factor applied by the suite.
      real(dp), intent(out) :: factor
      !> The samples.
      real(dp), intent(out) :: ag(0:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call suite_motion(deck, k, models, gm, factor, error)
      if (allocated(error)) return
      call sample_ground(gm, deck%analysis%dt, size(ag) - 1, ag)
   end subroutine suite_motion_samples

   !> The contact pairs of the deck in order: building indices and floors (n_pairs each).
   pure subroutine suite_pairs(deck, left, right, floor_left, floor_right)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Building on the left and on the right, facing floors.
      integer, allocatable, intent(out) :: left(:), right(:), floor_left(:), floor_right(:)
      integer :: ic

      allocate (left(0), right(0), floor_left(0), floor_right(0))
      do ic = 1, size(deck%contacts)
         associate (c => deck%contacts(ic))
            left = [left, spread(c%left_index, 1, size(c%floor_left))]
            right = [right, spread(c%right_index, 1, size(c%floor_left))]
            floor_left = [floor_left, c%floor_left]
            floor_right = [floor_right, c%floor_right]
         end associate
      end do
   end subroutine suite_pairs

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

   !> The suite's sweep statistics on the grid from every motion's sweep (`suite%sweep_gap`,
   !> `sweep_lambda`, `sweep_failed`, `motion_failed` and `n_used` set): per gap the mean over the
   !> motions used of each quantity's and building's largest |lambda| (summed in motion order),
   !> then the largest over the targeted quantities, and the largest over the motions used; a gap
   !> at which a motion used failed is `gap_failed` (mean and max 0, never meeting the target);
   !> the safe gaps (on the mean, on every motion, per motion: from which on every larger gap
   !> meets the target and none failed; -1: none, or no target) and the grid gaps below them that
   !> pass nevertheless. A failed motion has none of its own (-1, 0).
   pure subroutine suite_sweep_statistics(suite, sweep_all, targeted, target)
      !> The suite.
      type(suite_result), intent(inout) :: suite
      !> Every motion's largest |lambda| (%), (n_target_quantities, n_buildings, n_gaps, n_motions).
      real(dp), intent(in) :: sweep_all(:, :, :, :)
      !> Quantities the target applies to.
      logical, intent(in) :: targeted(:)
      !> `&sweep target_lambda` (%; <= 0: none).
      real(dp), intent(in) :: target
      real(dp) :: total(size(sweep_all, 1), size(sweep_all, 2), size(sweep_all, 3))
      integer, allocatable :: used(:)
      integer :: nm, k, iq

      nm = size(suite%motion_failed)
      used = pack([(k, k=1, nm)], .not. suite%motion_failed)
      total = 0.0_dp
      do k = 1, size(used)
         total = total + sweep_all(:, :, :, used(k))/suite%n_used
      end do
      do iq = 1, size(targeted)
         if (.not. targeted(iq)) total(iq, :, :) = 0.0_dp
      end do
      suite%gap_failed = any(suite%sweep_failed(used, :), dim=1)
      suite%sweep_mean = maxval(reshape(total, [size(total, 1)*size(total, 2), size(total, 3)]), dim=1)
      if (suite%n_used == nm) then
         suite%sweep_max = maxval(suite%sweep_lambda, dim=1)
      else
         suite%sweep_max = maxval(suite%sweep_lambda(used, :), dim=1)
      end if
      where (suite%gap_failed)
         suite%sweep_mean = 0.0_dp
         suite%sweep_max = 0.0_dp
      end where
      suite%safe_gap_mean = safe_gap(suite%sweep_mean, suite%gap_failed)
      suite%safe_gap_every = safe_gap(suite%sweep_max, suite%gap_failed)
      suite%non_monotone_mean = non_monotone(suite%sweep_mean, suite%gap_failed, suite%safe_gap_mean)
      suite%non_monotone_every = non_monotone(suite%sweep_max, suite%gap_failed, suite%safe_gap_every)
      allocate (suite%safe_gap_motion(nm), suite%non_monotone_motion(nm))
      suite%safe_gap_motion = -1.0_dp
      suite%non_monotone_motion = 0
      do k = 1, size(used)
         associate (m => used(k))
            suite%safe_gap_motion(m) = safe_gap(suite%sweep_lambda(m, :), suite%sweep_failed(m, :))
            suite%non_monotone_motion(m) = non_monotone(suite%sweep_lambda(m, :), suite%sweep_failed(m, :), &
                                                        suite%safe_gap_motion(m))
         end associate
      end do

   contains

      !> Number of grid gaps below `safe` whose `worst` meets the target (failed gaps never do).
      pure integer function non_monotone(worst, failed, safe)
         real(dp), intent(in) :: worst(:)
         logical, intent(in) :: failed(:)
         real(dp), intent(in) :: safe
         integer :: ig

         non_monotone = 0
         if (.not. (safe > 0.0_dp)) return
         do ig = 1, size(worst)
            if (suite%sweep_gap(ig) < safe .and. worst(ig) <= target .and. .not. failed(ig)) &
               non_monotone = non_monotone + 1
         end do
      end function non_monotone

      !> Smallest gap from which on every larger gap of the sweep `worst` <= the target and
      !> none failed (so it lies above every failed gap).
      pure real(dp) function safe_gap(worst, failed)
         real(dp), intent(in) :: worst(:)
         logical, intent(in) :: failed(:)
         integer :: ig

         safe_gap = -1.0_dp
         if (.not. (target > 0.0_dp)) return
         do ig = size(worst), 1, -1
            if (worst(ig) > target .or. failed(ig)) exit
            safe_gap = suite%sweep_gap(ig)
         end do
      end function safe_gap

   end subroutine suite_sweep_statistics

   !> The failures by motion, then by gap (the deck's gaps, -1, first); `add_failure` keeps
   !> one entry a motion and gap.
   pure subroutine sort_failures(list)
      !> The failures.
      type(suite_failure), allocatable, intent(inout) :: list(:)
      type(suite_failure), allocatable :: sorted(:)
      real(dp), allocatable :: gaps(:)
      integer :: k, i, j

      allocate (sorted(0))
      do k = minval([list%motion, huge(k)]), maxval([list%motion, 0])
         allocate (gaps(0))
         do j = 1, size(list)
            if (list(j)%motion == k) gaps = [gaps, list(j)%gap]
         end do
         call sort_ascending(gaps)
         do i = 1, size(gaps)
            do j = 1, size(list)
               if (list(j)%motion == k .and. list(j)%gap == gaps(i)) sorted = [sorted, list(j)]
            end do
         end do
         deallocate (gaps)
      end do
      call move_alloc(sorted, list)
   end subroutine sort_failures

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
      type(refine_cases) :: chains
      type(suite_cases) :: motions
      type(case_table) :: table
      real(dp), allocatable :: columns(:, :)
      logical, allocatable :: whole(:)
      type(case_result) :: res
      integer, allocatable :: left(:), right(:), fl(:), fr(:)
      real(dp), allocatable :: mean_unc(:, :, :), mean_cpl(:, :, :)
      real(dp), allocatable :: z(:), sweep_all(:, :, :, :)
      character(len=:), allocatable :: text
      logical :: targeted(n_target_quantities)
      integer :: nm, nb, k, ib, np, ip, nmax, ig, iq
      integer, allocatable :: start(:), ms(:)
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
      call suite_pairs(deck, left, right, fl, fr)
      np = size(left)
      suite%has_coupled = np > 0
      nmax = maxval(deck%buildings%n_storeys)
      allocate (suite%names(nm), suite%source(nm), suite%target(nm), suite%target_period(nm))
      allocate (suite%scale_factor(nm), suite%pga(nm), suite%sa(nm, size(suite%period)), &
                suite%sa_building(nm, nb), mean_unc(nmax, n_history_quantities, nb), &
                mean_cpl(nmax, n_history_quantities, nb))
      mean_unc = 0.0_dp
      mean_cpl = 0.0_dp
      allocate (suite%building(nb), suite%separation(nm + 1, np), suite%histories(nm))
      call columns_init(models, nm, suite%columns)
      do ib = 1, nb
         associate (n => deck%buildings(ib)%n_storeys, s => suite%building(ib))
            allocate (s%lambda(nm, n, n_history_quantities), s%mean_lambda(n, n_history_quantities), &
                      s%max_lambda(n, n_history_quantities), s%lambda_of_means(n, n_history_quantities))
            s%lambda = 0.0_dp
            s%mean_lambda = 0.0_dp
            s%max_lambda = 0.0_dp
            s%lambda_of_means = 0.0_dp
         end associate
      end do
      suite%refine_tolerance = deck%sweep%refine_tolerance
      targeted = deck%sweep%target_quantities
      if (.not. (deck%sweep%target > 0.0_dp)) targeted(1:n_history_quantities) = .true.

      do k = 1, nm
         suite%names(k) = deck%motions(k)%name
         select case (deck%motions(k)%kind)
         case ('record')
            suite%source(k) = deck%motions(k)%file
         case ('synthetic')
            suite%source(k) = 'synthetic, seed '//str(deck%motions(k)%seed)
         case default
            suite%source(k) = deck%motions(k)%kind
         end select
         suite%target(k) = -1.0_dp
         suite%target_period(k) = -1.0_dp
         select case (deck%motions(k)%scale_to)
         case ('pga')
            suite%target(k) = deck%motions(k)%target
            suite%target_period(k) = 0.0_dp
         case ('sa')
            suite%target(k) = deck%motions(k)%target
            suite%target_period(k) = deck%motions(k)%period
            if (.not. (suite%target_period(k) > 0.0_dp)) suite%target_period(k) = maxval(suite%building_period)
         end select
      end do

      ! The motions are the cases, and those the writers need whole (the first, and those
      ! whose histories are kept) run on every rank beside them; the statistics take the
      ! motions' columns in motion order. The uncoupled runs are batched in groups of
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
      ctx%left = left
      ctx%right = right
      ctx%fl = fl
      ctx%fr = fr
      ctx%sweep = deck%sweep%active .and. np > 0
      allocate (columns(motion_width(ctx), nm), whole(nm), suite%motion_failed(nm))
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
      call run_cases(motions, k, size(columns, 1)*max(1, maxval(motions%start(2:) - motions%start(:k))), table)
      call first_failure(table, motion_names(deck, '', motions%motion(motions%start(1:k)), bare=.true.), error)
      if (allocated(error)) return
      do ig = 1, k
         associate (m => motions%motion(motions%start(ig):motions%start(ig + 1) - 1))
            columns(:, m) = reshape(table%values(1:size(columns, 1)*size(m), ig), [size(columns, 1), size(m)])
         end associate
      end do
      if (ctx%sweep) then
         call motion_sweeps()
         if (allocated(error)) return
      end if

      ! The motions whose run failed are left out of every statistic over the motions; their
      ! rows of the sweep are FAILED at every gap (their other per-motion rows stay 0).
      ip = failure_slot(ctx)
      do k = 1, nm
         suite%motion_failed(k) = columns(ip + 1, k) > 0.0_dp
         if (.not. suite%motion_failed(k)) cycle
         call add_failure(suite%failures, column_failure(columns(ip + 2:ip + 1 + failure_width, k), k))
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
      do k = 1, nm
         call gather(columns(:, k))
      end do
      if (suite%n_used == nm) then
         suite%mean_sa = sum(suite%sa, dim=1)/nm
      else
         suite%mean_sa = sum(suite%sa(ctx%used, :), dim=1)/suite%n_used
      end if

      if (.not. suite%has_coupled) call sort_failures(suite%failures)
      if (.not. suite%has_coupled) return
      do ib = 1, nb
         associate (s => suite%building(ib), n => deck%buildings(ib)%n_storeys)
            if (suite%n_used == nm) then
               s%max_lambda = maxval(s%lambda, dim=1)
            else
               s%max_lambda = maxval(s%lambda(ctx%used, :, :), dim=1)
            end if
            where (any(s%lambda >= huge(1.0_dp), dim=1))
               s%mean_lambda = huge(1.0_dp)
            elsewhere
               s%mean_lambda = sum(s%lambda, dim=1)/suite%n_used
            end where
            s%lambda_of_means = influence_coefficient(mean_cpl(1:n, :, ib), mean_unc(1:n, :, ib))
         end associate
      end do
      call columns_finish(ctx%used, suite%columns)
      do ip = 1, np
         call rules(mean_unc(fl(ip), 1, left(ip)), mean_unc(fr(ip), 1, right(ip)), ip, &
                    suite%separation(nm + 1, ip))
      end do
      if (suite%has_sweep) then
         call suite_sweep_statistics(suite, sweep_all, targeted, deck%sweep%target)
         ctx%gap = suite%sweep_gap
         call refine(ctx, suite%safe_gap_mean, 0, suite%refined_gap_mean, suite%failures, error)
         if (allocated(error)) return
         call refine(ctx, suite%safe_gap_every, -1, suite%refined_gap_every, suite%failures, error)
         if (allocated(error)) return
         allocate (suite%refined_gap_motion(nm))
         ! The motions' own refinements are independent of each other: one case each.
         chains%ctx => ctx
         chains%safe = suite%safe_gap_motion
         call run_cases(chains, nm, 2 + refine_failures_kept*failure_width, table)
         call first_failure(table, motion_names(deck, ''), error)
         if (allocated(error)) return
         do k = 1, nm
            suite%refined_gap_motion(k) = table%values(1, k)
            do ip = 1, min(nint(table%values(2, k)), refine_failures_kept)
               iq = 2 + (ip - 1)*failure_width
               call add_failure(suite%failures, column_failure(table%values(iq + 1:iq + failure_width, k), k))
            end do
            suite%separation(k, :)%time_history = time_history_gap(suite%safe_gap_motion(k), &
                                                                   suite%refined_gap_motion(k))
         end do
         suite%separation(nm + 1, :)%time_history = time_history_gap(suite%safe_gap_mean, suite%refined_gap_mean)
      end if
      call sort_failures(suite%failures)

   contains

      !> Motion k run on every rank (its uncoupled run from the batch when it took it): its
      !> column, and unless it failed its sweep and its histories; the first that does not
      !> fail is the run's single-motion case.
      subroutine whole_run(r, j)
         type(case_result), intent(out) :: r
         integer, intent(in) :: j

         if (batched_ok(j)) then
            call motion_run(ctx, k, r, columns(:, k), error, batched(j))
         else
            call motion_run(ctx, k, r, columns(:, k), error)
         end if
         if (allocated(error)) return
         if (columns(failure_slot(ctx) + 1, k) > 0.0_dp) return
         if (suite%first == 0) suite%first = k
         call keep(r)
      end subroutine whole_run

      !> The sweeps of the motions whose run did not fail, as one loop of cases
      !> (`suite_gap_cases`), against their uncoupled peaks (kept in `ctx%unc` for the
      !> refinements too); each motion's sweep result from its gaps (`sweep_from_table`). A
      !> motion whose every gap fails fails as its run would (its column marked, its histories
      !> dropped). The first motion that does not fail is the run's single-motion case: run
      !> whole again if the one run whole failed here; it takes its sweep (result, warnings).
      subroutine motion_sweeps()
         type(suite_gap_cases) :: gaps
         type(case_table) :: all, one
         type(sweep_result), allocatable :: sweeps(:)
         type(error_type), allocatable :: failed
         real(dp), allocatable :: col(:)
         integer, allocatable :: ks(:)
         integer :: j, ng, fs, ps, nj, k1, iw
         integer(int64) :: c0, c1, rate

         call system_clock(c0, rate)
         fs = failure_slot(ctx)
         ps = probe_slot(ctx)
         nj = size(ctx%left)
         ng = deck%sweep%n_gaps
         ks = pack([(k, k=1, nm)], columns(fs + 1, :) == 0.0_dp .and. columns(3, :) > 0.0_dp)
         do j = 1, size(ks)
            call peaks_from_column(ctx, columns(:, ks(j)), ctx%unc(ks(j)))
            ctx%has_unc(ks(j)) = .true.
         end do
         gaps%ctx => ctx
         gaps%motions = ks
         gaps%probes = columns(ps + 1:ps + probe_width(ctx), ks)
         call run_cases(gaps, size(ks)*ng, sweep_column_width(nb), all)
         call system_clock(c1)
         allocate (sweeps(nm))
         do j = 1, size(ks)
            k = ks(j)
            one%values = all%values(:, (j - 1)*ng + 1:j*ng)
            one%failed = all%failed((j - 1)*ng + 1:j*ng)
            one%message = all%message((j - 1)*ng + 1:j*ng)
            call sweep_from_table(deck%sweep, nb, one, sweeps(k), failed)
            if (allocated(failed)) then
               ! As `motion_run` marks a failed run (its message as `run_case` gives it).
               call mark_failed(ctx, label_prefix(ctx%label)//failed%message, columns(:, k))
               ctx%has_unc(k) = .false.
               suite%histories(k) = motion_histories()
               deallocate (failed)
               cycle
            end if
            if (gaps%probes(1, j) > 0.0_dp) sweeps(k)%closing_max = gaps%probes(2:1 + nj, j)
            ! The loop's time shared evenly by the motions.
            sweeps(k)%seconds = real(c1 - c0, dp)/real(rate, dp)/size(ks)
            call gather_sweep(sweeps(k))
         end do
         k1 = findloc(columns(fs + 1, :) == 0.0_dp, .true., 1)
         if (k1 == 0) return
         if (k1 /= suite%first) then
            k = k1
            allocate (col(size(columns, 1)))
            call motion_run(ctx, k, first, col, error)
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
            if (sweep%failed(ig)) call add_failure(suite%failures, &
                                                       suite_failure(k, sweep%gap(ig), sweep%messages(ig)))
            suite%sweep_lambda(k, ig) = 0.0_dp
            do iq = 1, n_target_quantities
               if (targeted(iq)) suite%sweep_lambda(k, ig) = max(suite%sweep_lambda(k, ig), &
                                                                 maxval(sweep%max_abs_lambda(iq, :, ig)))
            end do
         end do
      end subroutine gather_sweep

      !> Scaling, spectra, peaks, lambdas and rules of motion k from its column (`motion_run`);
      !> a failed motion has its scaling and spectra only.
      subroutine gather(col)
         real(dp), intent(in) :: col(:)
         integer :: o, n, w, o2

         suite%scale_factor(k) = col(1)
         suite%pga(k) = col(2)
         o = 3
         suite%sa(k, :) = col(o + 1:o + size(suite%period))
         o = o + size(suite%period)
         suite%sa_building(k, :) = col(o + 1:o + nb)
         if (col(3) == 0.0_dp) return
         call columns_gather(models, k, col(size(col) - column_block_width(models) + 1:), suite%columns)
         do ib = 1, nb
            n = deck%buildings(ib)%n_storeys
            w = n*n_history_quantities
            o = motion_offset(ctx, 1, ib)
            suite%building(ib)%lambda(k, :, :) = reshape(col(o + 1:o + w), [n, n_history_quantities])
            o = motion_offset(ctx, 2, ib)
            mean_unc(1:n, :, ib) = mean_unc(1:n, :, ib) + reshape(col(o + 1:o + w), [n, n_history_quantities]) &
                                   /suite%n_used
            o = motion_offset(ctx, 3, ib)
            mean_cpl(1:n, :, ib) = mean_cpl(1:n, :, ib) + reshape(col(o + 1:o + w), [n, n_history_quantities]) &
                                   /suite%n_used
         end do
         o = motion_offset(ctx, 4, 1)
         do ip = 1, np
            o2 = motion_offset(ctx, 2, left(ip))
            w = motion_offset(ctx, 2, right(ip))
            call rules(col(o2 + fl(ip)), col(w + fr(ip)), ip, suite%separation(k, ip))
            suite%separation(k, ip)%no_contact = col(o + ip)
            suite%separation(nm + 1, ip)%no_contact = suite%separation(nm + 1, ip)%no_contact + &
                                                      suite%separation(k, ip)%no_contact/suite%n_used
         end do
      end subroutine gather

      !> ABS, SRSS, EC8 and DDC of pair ip from the peaks p1, p2 (m).
      subroutine rules(p1, p2, ip, sep)
         real(dp), intent(in) :: p1, p2
         integer, intent(in) :: ip
         type(separation_t), intent(inout) :: sep
         logical :: coincide

         coincide = abs(sum(deck%buildings(left(ip))%height(1:fl(ip))) - &
                        sum(deck%buildings(right(ip))%height(1:fr(ip)))) <= 1.0e-9_dp
         sep%abs = separation_abs(p1, p2)
         sep%srss = separation_srss(p1, p2)
         sep%ec8 = separation_ec8(p1, p2, coincide)
         sep%rho = cqc_correlation(suite%building_period(left(ip)), suite%building_period(right(ip)), &
                                   z(left(ip)), z(right(ip)))
         sep%ddc = separation_ddc(p1, p2, suite%building_period(left(ip)), &
                                  suite%building_period(right(ip)), z(left(ip)), z(right(ip)))
      end subroutine rules

   end subroutine run_suite

end module pound_suite
