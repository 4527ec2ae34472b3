!> The refinement of a suite's threshold gaps: bisection between the last failing and the
!> first passing gap of the sweep's grid, down to `&sweep refine_tolerance`.
!>
!> Three criteria: the suite mean and every motion (the motions of the statistics at each
!> trial gap are the cases of one `run_cases`), and each motion's own (one case per motion:
!> its whole bisection, `refine_cases`). A trial gap at which a motion fails does not meet the
!> target (the refined gap lies above it); the failure is kept (`suite_failure`, with the time
!> and step of the error). The bisection itself is reverse communication (`bisection`,
!> `bisection_step`, `bisection_update`).
module pound_suite_refine
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str, fit_with_suffix
   use pound_config, only: n_target_quantities, sweep_config
   use pound_sweep, only: sweep_gaps
   use pound_influence, only: max_abs_target
   use pound_run_case, only: case_options, case_result, run_case
   use pound_cases, only: case_work, case_table, run_cases, first_failure, case_message_len
   use pound_suite_outcome, only: suite_failure, failure_width, failure_pack, failure_unpack
   use pound_suite_context, only: suite_context
   use pound_suite_motions, only: suite_motion, motion_names
   use pound_suite_statistics, only: add_failure
   implicit none
   private

   public :: bisection, bisection_step, bisection_update, refine, refine_motions
   public :: refine_trials, planned_refinement_runs

   !> Failed trial gaps a motion's own threshold refinement carries to the writer (more are
   !> counted in the last one's message).
   integer, parameter :: refine_failures_kept = 8

   !> Bisection for a threshold gap: `lo` fails the target, `hi` meets it; halved until
   !> hi - lo <= tol (reverse communication: `bisection_step` gives the trial gap,
   !> `bisection_update` takes its verdict).
   type :: bisection
      !> Failing and passing gap, tolerance (m).
      real(dp) :: lo = 0.0_dp, hi = 0.0_dp, tol = 0.0_dp
   end type bisection

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

   !> The motions' own threshold refinements as cases: column = motion k's refined gap, the
   !> number of its failed trial gaps and the first `refine_failures_kept` of them
   !> (`failure_pack`).
   type, extends(case_work) :: refine_cases
      !> The refinement's data.
      type(suite_context), pointer :: ctx => null()
      !> Each motion's safe grid gap (m; -1: none).
      real(dp), allocatable :: safe(:)
   contains
      procedure :: compute => refine_case
   end type refine_cases

contains

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
            call add_failure(failures, suite_failure(which, gap, error%message, error%time, error%step))
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
         if (table%failed(m)) call add_failure(failures, suite_failure(ctx%used(m), gap, table%message(m), &
                                                                       table%time(m), table%step(m)))
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
      lam = max_abs_target(r%influence, r%models, r%unc, r%cpl)
      do iq = 1, n_target_quantities
         if (.not. ctx%targeted(iq)) lam(iq, :) = 0.0_dp
      end do
   end subroutine motion_lambda

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
         call failure_pack(suite_failure(i, failures(j)%gap, text, failures(j)%time, failures(j)%step), &
                           values(o + 1:o + failure_width))
      end do
   end subroutine refine_case

   !> Every motion's own refinement (`refine` with criterion k), one case each (they are
   !> independent): `refined(k)` from motion k's safe grid gap `safe(k)`, its failed trial
   !> gaps added to `failures`.
   subroutine refine_motions(ctx, safe, refined, failures, error)
      !> The suite's data.
      type(suite_context), intent(in), target :: ctx
      !> Each motion's safe grid gap (m; -1: none).
      real(dp), intent(in) :: safe(:)
      !> Each motion's refined gap (m; -1: not refined).
      real(dp), intent(out) :: refined(:)
      !> The failed cases so far.
      type(suite_failure), allocatable, intent(inout) :: failures(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(refine_cases) :: chains
      type(case_table) :: table
      integer :: k, j, o

      chains%ctx => ctx
      chains%safe = safe
      call run_cases(chains, size(safe), 2 + refine_failures_kept*failure_width, table)
      call first_failure(table, motion_names(ctx%deck, ''), error)
      if (allocated(error)) return
      do k = 1, size(safe)
         refined(k) = table%values(1, k)
         do j = 1, min(nint(table%values(2, k)), refine_failures_kept)
            o = 2 + (j - 1)*failure_width
            call add_failure(failures, failure_unpack(table%values(o + 1:o + failure_width, k), k))
         end do
      end do
   end subroutine refine_motions

   !> The trial gaps `refine` takes from the safe grid gap `safe` of the grid `gap` down to the
   !> tolerance `tol` (0: no refinement): the bisection's halvings (each verdict halves the
   !> interval alike; counted with every trial passing).
   pure integer function refine_trials(gap, safe, tol) result(n)
      !> The sweep's grid (m).
      real(dp), intent(in) :: gap(:)
      !> Safe grid gap (m; <= 0: none).
      real(dp), intent(in) :: safe
      !> Tolerance (m).
      real(dp), intent(in) :: tol
      type(bisection) :: b
      real(dp) :: mid
      integer :: ig
      logical :: more

      n = 0
      ig = findloc(gap, safe, 1)
      if (.not. (safe > 0.0_dp) .or. ig <= 1) return
      b = bisection(gap(ig - 1), safe, tol)
      mid = safe
      do
         call bisection_step(b, mid, more)
         if (.not. more) exit
         n = n + 1
         call bisection_update(b, mid, .true.)
      end do
   end function refine_trials

   !> The most integration runs the refinements of a suite of `nm` motions with `sweep` can
   !> take (for the progress line): the three criteria (mean, every motion, each motion's own)
   !> refined from the grid's first interval, every motion run at each trial gap of the suite
   !> criteria and one at each of its own; 0 without a target.
   pure integer function planned_refinement_runs(sweep, nm) result(runs)
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> Number of motions.
      integer, intent(in) :: nm
      real(dp), allocatable :: gap(:)

      runs = 0
      if (.not. (sweep%active .and. sweep%target > 0.0_dp) .or. sweep%n_gaps < 2) return
      gap = sweep_gaps(sweep)
      runs = 3*nm*refine_trials(gap, gap(2), sweep%refine_tolerance)
   end function planned_refinement_runs

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

end module pound_suite_refine
