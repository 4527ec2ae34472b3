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
   use pound_strings, only: str
   use pound_config, only: deck_type, ground_config, n_history_quantities
   use pound_deck_variables, only: word_len, path_len
   use pound_ground_motion, only: ground_motion_t, sample_ground
   use pound_synthetic_motion, only: synthetic_config, synthetic_motion
   use pound_structure, only: structure_model
   use pound_building, only: building_model, build_building
   use pound_spectrum, only: response_spectrum, period_grid, peak_ground_acceleration, &
                             scale_to_pga, scale_to_sa
   use pound_influence, only: influence_coefficient, max_abs_influence
   use pound_separation, only: separation_t, separation_abs, separation_srss, separation_ec8, &
                               separation_ddc, cqc_correlation, no_contact_gap
   use pound_run_case, only: case_options, case_result, run_case, configured_motion
   use pound_analysis, only: analysis_result, n_energy, analysis_copy
   use pound_analysis_batch, only: batch_eligible, run_uncoupled_batch, batch_lanes
   implicit none
   private

   public :: suite_result, run_suite, suite_motion, suite_pairs, n_spectrum, spectrum_damping
   public :: motion_histories, bisection, bisection_step, bisection_update, time_history_gap

   !> Log-spaced periods of the suite spectra (before the buildings' periods are added).
   integer, parameter :: n_spectrum = 60
   !> Damping ratio of the spectra and of `scale_to = 'sa'`.
   real(dp), parameter :: spectrum_damping = 0.05_dp
   !> Batched uncoupled runs (`pound_analysis_batch`): at least this many motions a batch (fewer
   !> run one by one), and at most this many bytes of their results held at once.
   integer, parameter :: batch_min = 3
   real(dp), parameter :: batch_bytes = 256.0_dp*2.0_dp**20

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
   end type suite_result

contains

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
      n_steps = nint(deck%analysis%t_end/dt)
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

   !> Motions whose uncoupled runs a suite makes together (`pound_analysis_batch`): up to
   !> `batch_lanes`, as many as `batch_bytes` of results allow, the groups as even as possible;
   !> 0 (one by one) for fewer than `batch_min` motions or buildings the batch cannot run.
   integer function batch_group(deck, models) result(size_of)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      real(dp) :: bytes
      integer :: nm, ib, groups, n_out

      size_of = 0
      nm = size(deck%motions)
      if (nm < batch_min .or. .not. batch_eligible(models)) return
      n_out = nint(deck%analysis%t_end/deck%analysis%dt)/deck%analysis%output_every + 1
      bytes = real(1 + n_energy, dp)
      do ib = 1, size(models)
         bytes = bytes + real(size(models(ib)%floor_dof), dp)*real(count(deck%analysis%store), dp)
      end do
      bytes = 8.0_dp*real(n_out, dp)*bytes
      size_of = int(min(real(batch_lanes, dp), batch_bytes/bytes))
      if (size_of < batch_min) then
         size_of = 0
         return
      end if
      groups = (nm + size_of - 1)/size_of
      size_of = (nm + groups - 1)/groups
   end function batch_group

   !> Run every motion of the deck's suite and gather the suite statistics.
   subroutine run_suite(deck, suite, first, error, label)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Everything the suite computes.
      type(suite_result), intent(out) :: suite
      !> The case of the first motion (what a single-motion run writes).
      type(case_result), intent(out) :: first
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Put before the messages of the configuration's errors (e.g. the deck path).
      character(len=*), intent(in), optional :: label
      type(structure_model), allocatable :: models(:)
      type(building_model), allocatable :: kinds(:)
      type(case_options) :: options
      type(case_result) :: res
      integer, allocatable :: left(:), right(:), fl(:), fr(:)
      real(dp), allocatable :: ag(:), u1(:), u2(:), mean_unc(:, :, :), mean_cpl(:, :, :)
      real(dp), allocatable :: z(:), sa(:), sweep_sum(:, :, :)
      logical :: targeted(n_history_quantities)
      integer :: nm, nb, k, ib, n_steps, np, ip, nmax
      logical :: has_u
      type(analysis_result), allocatable, target :: batched(:)
      logical, allocatable :: batched_ok(:)
      integer :: batch_first, batch_size, batch_count

      nm = size(deck%motions)
      nb = size(deck%buildings)
      n_steps = nint(deck%analysis%t_end/deck%analysis%dt)
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
                suite%sa_building(nm, nb), ag(0:n_steps), mean_unc(nmax, n_history_quantities, nb), &
                mean_cpl(nmax, n_history_quantities, nb))
      mean_unc = 0.0_dp
      mean_cpl = 0.0_dp
      allocate (suite%building(nb), suite%separation(nm + 1, np), suite%histories(nm))
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
      has_u = deck%analysis%store(1)
      suite%refine_tolerance = deck%sweep%refine_tolerance
      targeted = deck%sweep%target_quantities
      if (.not. (deck%sweep%target > 0.0_dp)) targeted = .true.
      if (present(label)) options%label = label
      batch_size = batch_group(deck, models)
      batch_first = 0
      batch_count = 0

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
         allocate (options%ground)
         call suite_motion(deck, k, models, options%ground, suite%scale_factor(k), error)
         if (allocated(error)) return
         call sample_ground(options%ground, deck%analysis%dt, n_steps, ag)
         suite%pga(k) = peak_ground_acceleration(ag)
         call response_spectrum(ag, deck%analysis%dt, suite%period, spectrum_damping, sa, error)
         if (allocated(error)) return
         suite%sa(k, :) = sa
         call response_spectrum(ag, deck%analysis%dt, suite%building_period, spectrum_damping, sa, error)
         if (allocated(error)) return
         suite%sa_building(k, :) = sa
         if (batch_size > 0) then
            call take_uncoupled(error)
            if (allocated(error)) return
         end if
         if (k == 1) then
            call run_case(deck, first, error, options)
         else
            call run_case(deck, res, error, options)
         end if
         deallocate (options%ground)
         nullify (options%unc)
         if (allocated(error)) then
            error%message = "&ground '"//deck%motions(k)%name//"': "//error%message
            return
         end if
         if (k == 1) then
            call gather(first)
            call keep(first)
         else
            call gather(res)
            call keep(res)
         end if
      end do
      suite%mean_sa = sum(suite%sa, dim=1)/nm

      if (.not. suite%has_coupled) return
      do ib = 1, nb
         associate (s => suite%building(ib), n => deck%buildings(ib)%n_storeys)
            s%max_lambda = maxval(s%lambda, dim=1)
            where (any(s%lambda >= huge(1.0_dp), dim=1))
               s%mean_lambda = huge(1.0_dp)
            elsewhere
               s%mean_lambda = sum(s%lambda, dim=1)/nm
            end where
            s%lambda_of_means = influence_coefficient(mean_cpl(1:n, :, ib), mean_unc(1:n, :, ib))
         end associate
      end do
      do ip = 1, np
         call rules(mean_unc(fl(ip), 1, left(ip)), mean_unc(fr(ip), 1, right(ip)), ip, &
                    suite%separation(nm + 1, ip))
      end do
      if (suite%has_sweep) then
         suite%sweep_mean = maxval(reshape(sweep_sum, [n_history_quantities*nb, size(suite%sweep_gap)]), dim=1)
         suite%sweep_max = maxval(suite%sweep_lambda, dim=1)
         suite%safe_gap_mean = safe_gap(suite%sweep_mean)
         suite%safe_gap_every = safe_gap(suite%sweep_max)
         suite%non_monotone_mean = non_monotone(suite%sweep_mean, suite%safe_gap_mean)
         suite%non_monotone_every = non_monotone(suite%sweep_max, suite%safe_gap_every)
         call refine(suite%safe_gap_mean, 0, suite%refined_gap_mean, error)
         if (allocated(error)) return
         call refine(suite%safe_gap_every, -1, suite%refined_gap_every, error)
         if (allocated(error)) return
         allocate (suite%safe_gap_motion(nm), suite%refined_gap_motion(nm), suite%non_monotone_motion(nm))
         do k = 1, nm
            suite%safe_gap_motion(k) = safe_gap(suite%sweep_lambda(k, :))
            suite%non_monotone_motion(k) = non_monotone(suite%sweep_lambda(k, :), suite%safe_gap_motion(k))
            call refine(suite%safe_gap_motion(k), k, suite%refined_gap_motion(k), error)
            if (allocated(error)) return
            suite%separation(k, :)%time_history = time_history_gap(suite%safe_gap_motion(k), &
                                                                   suite%refined_gap_motion(k))
         end do
         suite%separation(nm + 1, :)%time_history = time_history_gap(suite%safe_gap_mean, suite%refined_gap_mean)
      end if

   contains

      !> Motion k's uncoupled result in `options%unc` when a batch ran it: at the first motion of
      !> a group (`batch_size` motions; the last `batch_min` - 1 or fewer run one by one) the
      !> group's uncoupled runs are made together.
      subroutine take_uncoupled(error)
         type(error_type), allocatable, intent(out) :: error
         type(ground_motion_t) :: gm
         real(dp), allocatable :: agb(:, :)
         real(dp) :: factor
         integer :: j

         if (batch_first == 0 .or. k >= batch_first + batch_count) then
            batch_first = k
            batch_count = min(batch_size, nm - k + 1)
            if (allocated(batched)) deallocate (batched, batched_ok)
            if (batch_count < batch_min) then
               batch_count = nm - k + 1
               return
            end if
            allocate (agb(0:n_steps, batch_count), batched(batch_count), batched_ok(batch_count))
            do j = 1, batch_count
               call suite_motion(deck, k + j - 1, models, gm, factor, error)
               if (allocated(error)) then
                  error%message = "&ground '"//deck%motions(k + j - 1)%name//"': "//error%message
                  return
               end if
               call sample_ground(gm, deck%analysis%dt, n_steps, agb(:, j))
            end do
            call run_uncoupled_batch(deck%analysis, models, agb, batched, batched_ok)
         end if
         if (.not. allocated(batched)) return
         if (batched_ok(k - batch_first + 1)) options%unc => batched(k - batch_first + 1)
      end subroutine take_uncoupled

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

      !> Peaks, lambdas and rules of motion k.
      subroutine gather(res)
         type(case_result), intent(in) :: res

         integer :: iq, ig

         if (.not. (res%has_coupled .and. res%has_uncoupled)) return
         if (res%has_sweep) then
            if (k == 1) then
               suite%has_sweep = .true.
               suite%sweep_gap = res%sweep%gap
               allocate (suite%sweep_lambda(nm, size(res%sweep%gap)))
               allocate (sweep_sum(n_history_quantities, nb, size(res%sweep%gap)))
               sweep_sum = 0.0_dp
            end if
            sweep_sum = sweep_sum + res%sweep%max_abs_lambda/nm
            do ig = 1, size(res%sweep%gap)
               suite%sweep_lambda(k, ig) = 0.0_dp
               do iq = 1, n_history_quantities
                  if (targeted(iq)) suite%sweep_lambda(k, ig) = max(suite%sweep_lambda(k, ig), &
                                                                    maxval(res%sweep%max_abs_lambda(iq, :, ig)))
               end do
            end do
            do iq = 1, n_history_quantities
               if (.not. targeted(iq)) sweep_sum(iq, :, :) = 0.0_dp
            end do
         end if
         do ib = 1, nb
            associate (n => deck%buildings(ib)%n_storeys)
               suite%building(ib)%lambda(k, :, :) = res%influence(ib)%lambda
               mean_unc(1:n, :, ib) = mean_unc(1:n, :, ib) + res%unc%building(ib)%peak/nm
               mean_cpl(1:n, :, ib) = mean_cpl(1:n, :, ib) + res%cpl%building(ib)%peak/nm
            end associate
         end do
         do ip = 1, np
            call separation_of(res, ip, suite%separation(k, ip))
            suite%separation(nm + 1, ip)%no_contact = suite%separation(nm + 1, ip)%no_contact + &
                                                      suite%separation(k, ip)%no_contact/nm
         end do
      end subroutine gather

      !> Number of grid gaps below `safe` whose `worst` meets the target.
      integer function non_monotone(worst, safe)
         real(dp), intent(in) :: worst(:), safe
         integer :: ig

         non_monotone = 0
         if (.not. (safe > 0.0_dp)) return
         do ig = 1, size(worst)
            if (suite%sweep_gap(ig) < safe .and. worst(ig) <= deck%sweep%target) non_monotone = non_monotone + 1
         end do
      end function non_monotone

      !> Bisection between the grid gap below `safe` (failing) and `safe` (passing), down to
      !> the tolerance: the motions run at the trial gap (no sweep), the criterion on the suite
      !> mean (`which` = 0), on every motion (-1) or on motion `which` alone (> 0).
      subroutine refine(safe, which, refined, error)
         real(dp), intent(in) :: safe
         integer, intent(in) :: which
         real(dp), intent(out) :: refined
         type(error_type), allocatable, intent(out) :: error
         type(deck_type) :: plain
         type(bisection) :: b
         real(dp) :: mid, worst
         integer :: ig
         logical :: more

         refined = -1.0_dp
         ig = findloc(suite%sweep_gap, safe, 1)
         if (.not. (safe > 0.0_dp) .or. ig <= 1) return
         plain = deck
         plain%sweep%active = .false.
         b = bisection(suite%sweep_gap(ig - 1), safe, deck%sweep%refine_tolerance)
         mid = safe
         do
            call bisection_step(b, mid, more)
            if (.not. more) exit
            call worst_at(plain, mid, which, worst, error)
            if (allocated(error)) return
            call bisection_update(b, mid, worst <= deck%sweep%target)
         end do
         refined = b%hi
      end subroutine refine

      !> The motions at one gap: the largest |lambda| over the targeted quantities and the
      !> buildings, as the suite mean (`which` = 0: the mean per quantity and building, then the
      !> largest), the largest over the motions (-1), or of motion `which` alone (> 0).
      subroutine worst_at(plain, gap, which, worst, error)
         type(deck_type), intent(in) :: plain
         real(dp), intent(in) :: gap
         integer, intent(in) :: which
         real(dp), intent(out) :: worst
         type(error_type), allocatable, intent(out) :: error
         type(case_options) :: opt
         type(case_result) :: r
         real(dp) :: lam(n_history_quantities, nb), total(n_history_quantities, nb)
         real(dp) :: factor, worst_max
         integer :: m, iq, m_first, m_last

         total = 0.0_dp
         worst_max = 0.0_dp
         opt%gap = gap
         if (present(label)) opt%label = label
         m_first = 1
         m_last = nm
         if (which > 0) then
            m_first = which
            m_last = which
         end if
         do m = m_first, m_last
            allocate (opt%ground)
            call suite_motion(deck, m, models, opt%ground, factor, error)
            if (allocated(error)) return
            call run_case(plain, r, error, opt)
            deallocate (opt%ground)
            if (allocated(error)) return
            lam = max_abs_influence(r%influence)
            do iq = 1, n_history_quantities
               if (.not. targeted(iq)) lam(iq, :) = 0.0_dp
            end do
            total = total + lam/nm
            worst_max = max(worst_max, maxval(lam))
         end do
         if (which == 0) then
            worst = maxval(total)
         else
            worst = worst_max
         end if
      end subroutine worst_at

      !> Smallest gap from which on every larger gap of the sweep `worst` <= the target.
      real(dp) function safe_gap(worst)
         real(dp), intent(in) :: worst(:)
         integer :: ig

         safe_gap = -1.0_dp
         if (.not. (deck%sweep%target > 0.0_dp)) return
         do ig = size(worst), 1, -1
            if (worst(ig) > deck%sweep%target) exit
            safe_gap = suite%sweep_gap(ig)
         end do
      end function safe_gap

      !> The rules of pair ip for one motion.
      subroutine separation_of(res, ip, sep)
         type(case_result), intent(in) :: res
         integer, intent(in) :: ip
         type(separation_t), intent(out) :: sep

         associate (b1 => res%unc%building(left(ip)), b2 => res%unc%building(right(ip)))
            call rules(b1%peak(fl(ip), 1), b2%peak(fr(ip), 1), ip, sep)
            if (has_u) then
               u1 = b1%u(fl(ip), 1:b1%n_out)
               u2 = b2%u(fr(ip), 1:b2%n_out)
               sep%no_contact = no_contact_gap(u1, u2)
            else
               sep%no_contact = -1.0_dp
            end if
         end associate
      end subroutine separation_of

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
