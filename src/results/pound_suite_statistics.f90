!> The statistics of a suite over its motions (pure): what a suite computes (`suite_result`),
!> and its reductions.
!>
!> Over the suite (n motions, those whose run did not fail):
!> * mean of the lambdas: (1/n) sum_k lambda_k (per floor/storey and quantity), and their
!>   maximum; the lambda of the means: lambda(mean coupled peak, mean uncoupled peak). Codes
!>   (ASCE 7 16.2.4, EC8 4.3.3.4.3) take the mean of the responses of the suite, i.e. the
!>   peaks are averaged first: that is the lambda of the means; both are given
!>   (`suite_building_statistics`).
!> * separation rules at every contact pair (`suite_pair_rules`, pound_separation), per motion
!>   from the uncoupled peak displacements at the pair's two ends and their stored uncoupled
!>   histories (the no-contact gap needs `history` with 'u', or for a point between floors
!>   `node_histories`; it is sampled every `output_every` steps), and for the suite from the
!>   mean peak displacements (ABS, SRSS, EC8, DDC, the design-code rules with the buildings'
!>   factors, the setbacks) and the mean of the per-motion no-contact gaps. The peaks are the
!>   uncoupled response-history peaks of the buildings as analysed (a yielding building's
!>   inelastic ones, `separation_t%inelastic`). An end between floors (a frame's split column
!>   node) has its DOF's peak |u| at every step (`response_point_peak`); the x0.7 / x0.5 of
!>   coinciding floors apply only where both ends are floors at the same level.
!> * the time-history threshold gap (with `&sweep` and a target): per motion, the smallest gap
!>   of the sweep from which on the motion's own largest |lambda| meets the target, refined by
!>   bisection (`pound_suite_refine`); for the suite, that of the suite mean. One value for
!>   every pair (the sweep gives every pair the same gap); -1 when not computed
!>   (`time_history_gap`, `suite_sweep_statistics`).
!> * the failed cases, one per motion and gap, sorted (`add_failure`, `sort_failures`).
module pound_suite_statistics
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_config, only: n_history_quantities, code_factors
   use pound_deck_variables, only: word_len, path_len
   use pound_influence, only: influences, max_meaningful, created_by_pounding, not_meaningful
   use pound_separation, only: separation_t, code_separation
   use pound_analysis, only: analysis_result
   use pound_sort, only: sort_ascending
   use pound_suite_columns, only: column_suite
   use pound_suite_outcome, only: suite_failure
   implicit none
   private

   public :: suite_joint, suite_result, motion_histories, building_suite
   public :: suite_sweep_statistics, suite_building_statistics, suite_pair_rules, time_history_gap
   public :: add_failure, sort_failures, suite_result_init

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
      !> Bilinear storeys, per motion (n_motions, n, 4): peak ductility uncoupled, coupled,
      !> residual drift (m) uncoupled, coupled; the storey that collapsed (n_motions, 2: uncoupled,
      !> coupled; 0: none). Zeros for elastic storeys and failed motions.
      real(dp), allocatable :: yield(:, :, :)
      integer, allocatable :: collapse(:, :)
   end type building_suite

   !> One independent joint of a suite with several (`pound_sweep_joints`): its own sweep in
   !> every motion (its pairs at the sweep's gaps, every other pair at its deck gap) and its
   !> threshold gaps on the suite mean, on every motion and on each motion, as the suite's
   !> common sweep has them (`suite_sweep_statistics`; on the grid: not refined).
   type :: suite_joint
      !> Its name ('<left>-<right>') and its pairs (indices in deck order).
      character(len=:), allocatable :: name
      integer, allocatable :: pairs(:)
      !> Per motion and gap, the largest |lambda| (%) over the targeted quantities and the
      !> buildings (0 where failed), and whether the run failed (a failed motion: every gap),
      !> (n_motions, n_gaps).
      real(dp), allocatable :: lambda(:, :)
      logical, allocatable :: failed(:, :)
      !> Per gap: the suite mean (of each quantity's and building's largest |lambda| over the
      !> motions, then the largest) and the largest over the motions (%; 0 where failed), and
      !> whether a motion failed there (n_gaps).
      real(dp), allocatable :: mean(:), max(:)
      logical, allocatable :: gap_failed(:)
      !> Threshold gaps (m; -1: none or no target): on the mean, on every motion, on each
      !> motion's own (n_motions).
      real(dp) :: safe_gap_mean = -1.0_dp, safe_gap_every = -1.0_dp
      real(dp), allocatable :: safe_gap_motion(:)
   end type suite_joint

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
      !> every `&contact` in deck order. The suite row's no-contact gap is the largest over the
      !> motions (the gap at which no motion makes contact; -1 when a motion's is not known).
      type(separation_t), allocatable :: separation(:, :)
      !> With `&sweep` and several independent joints: each joint's own sweep over the
      !> motions (unallocated otherwise).
      type(suite_joint), allocatable :: joint(:)
      !> Per pair: the mean over the motions of their no-contact gaps, the mean closing
      !> displacement (m; -1 when a motion's is not known; n_pairs).
      real(dp), allocatable :: mean_closing(:)
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

contains

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

   !> The time-history threshold gap: the refined gap when there is one, else the safe grid
   !> gap (the first gap of the grid when it already meets the target: an upper bound), else -1.
   elemental real(dp) function time_history_gap(safe, refined) result(gap)
      !> Safe grid gap and its refinement (m; -1: none).
      real(dp), intent(in) :: safe, refined

      gap = merge(refined, safe, refined >= 0.0_dp)
   end function time_history_gap

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

   !> The separation rules of one pair from the peaks p1, p2 at its ends (`code_separation`:
   !> ABS, SRSS, EC8, DDC, and ASCE 7, EN 1998, IS 1893 with the buildings' factors f1, f2),
   !> keeping the no-contact and time-history gaps already in `sep`. A peak < 0 is not known
   !> (a point between floors the model has no node at): then the pair's rules are n/a
   !> (`computed` false; ABS, SRSS, EC8, DDC, the peaks and setbacks -1 as in /suite/separation).
   pure subroutine suite_pair_rules(p1, p2, f1, f2, t1, t2, z1, z2, coincide, sep)
      !> Peak displacements at the two ends (m; < 0: not known).
      real(dp), intent(in) :: p1, p2
      !> Design-code factors of the two buildings.
      type(code_factors), intent(in) :: f1, f2
      !> Periods (s) and damping ratios of the two buildings.
      real(dp), intent(in) :: t1, t2, z1, z2
      !> Whether the ends' levels coincide.
      logical, intent(in) :: coincide
      !> The rules (its no-contact and time-history members untouched).
      type(separation_t), intent(inout) :: sep
      type(separation_t) :: rules

      if (p1 < 0.0_dp .or. p2 < 0.0_dp) then
         rules = code_separation(0.0_dp, 0.0_dp, code_factors(), code_factors(), t1, t2, z1, z2, coincide)
         rules%computed = .false.
         rules%abs = -1.0_dp
         rules%srss = -1.0_dp
         rules%ec8 = -1.0_dp
         rules%ddc = -1.0_dp
         rules%u = -1.0_dp
         rules%setback = -1.0_dp
      else
         rules = code_separation(p1, p2, f1, f2, t1, t2, z1, z2, coincide)
      end if
      rules%no_contact = sep%no_contact
      rules%no_contact_valid = sep%no_contact_valid
      rules%time_history = sep%time_history
      rules%time_history_valid = sep%time_history_valid
      sep = rules
   end subroutine suite_pair_rules

   !> Building ib's influence over the motions `used` (out of n, their lambdas in
   !> `s%lambda`): the maximum and the mean of the lambdas (+huge where a motion's is +huge),
   !> and the lambda of the mean peaks `mean_cpl`, `mean_unc` ((n_storeys, n_history_quantities)).
   pure subroutine suite_building_statistics(s, used, mean_cpl, mean_unc)
      !> The building's statistics (`lambda` set).
      type(building_suite), intent(inout) :: s
      !> The motions of the statistics.
      integer, intent(in) :: used(:)
      !> Mean coupled and uncoupled peaks over them.
      real(dp), intent(in) :: mean_cpl(:, :), mean_unc(:, :)
      integer :: k, q

      ! A lambda that is not meaningful (NaN, `pound_influence`) is left out of the maximum
      ! (NaN when every motion's is) and makes the mean NaN (unless a motion's is +huge).
      s%max_lambda = -huge(1.0_dp)
      do k = 1, size(used)
         s%max_lambda = max_meaningful(s%max_lambda, s%lambda(used(k), :, :))
      end do
      where (all(ieee_is_nan(s%lambda(used, :, :)), dim=1) .and. size(used) > 0) s%max_lambda = not_meaningful()
      where (any(created_by_pounding(s%lambda), dim=1))
         s%mean_lambda = huge(1.0_dp)
      elsewhere
         s%mean_lambda = sum(s%lambda, dim=1)/size(used)
      end where
      do q = 1, size(mean_unc, 2)
         s%lambda_of_means(:, q) = influences(mean_cpl(:, q), mean_unc(:, q))
      end do
   end subroutine suite_building_statistics

   !> The per-motion arrays of a suite of `nm` motions over buildings of `n_storeys` storeys
   !> with `np` contact pairs, `period` set: names, sources, targets, scale factors, PGA, spectra,
   !> per building lambdas and their statistics (zero), the separation rules (n_motions + 1,
   !> n_pairs) and the histories.
   pure subroutine suite_result_init(suite, nm, n_storeys, np)
      !> The suite (`period` allocated).
      type(suite_result), intent(inout) :: suite
      !> Number of motions.
      integer, intent(in) :: nm
      !> Storeys of each building.
      integer, intent(in) :: n_storeys(:)
      !> Number of contact pairs.
      integer, intent(in) :: np
      integer :: ib, nb

      nb = size(n_storeys)
      allocate (suite%names(nm), suite%source(nm), suite%target(nm), suite%target_period(nm))
      allocate (suite%scale_factor(nm), suite%pga(nm), suite%sa(nm, size(suite%period)), suite%sa_building(nm, nb))
      allocate (suite%building(nb), suite%separation(nm + 1, np), suite%histories(nm))
      allocate (suite%mean_closing(np), source=0.0_dp)
      do ib = 1, nb
         associate (n => n_storeys(ib), s => suite%building(ib))
            allocate (s%lambda(nm, n, n_history_quantities), s%mean_lambda(n, n_history_quantities), &
                      s%max_lambda(n, n_history_quantities), s%lambda_of_means(n, n_history_quantities))
            s%lambda = 0.0_dp
            s%mean_lambda = 0.0_dp
            s%max_lambda = 0.0_dp
            s%lambda_of_means = 0.0_dp
            allocate (s%yield(nm, n, 4), source=0.0_dp)
            allocate (s%collapse(nm, 2), source=0)
         end associate
      end do
   end subroutine suite_result_init

end module pound_suite_statistics
