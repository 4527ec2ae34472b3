!> Seismic-joint gap study: the coupled analysis repeated for a range of gaps.
!>
!> The uncoupled analysis is run once (it does not depend on the gap); everything of the
!> coupled analysis that does not depend on the gap — the factored Khat of every building and
!> the condensed constraints Khat^{-1} B and F — is prepared once and reused for every gap.
!> Each gap is applied to every constraint. For every gap the largest |lambda| over the
!> floors (storeys) is kept per building and quantity (and, for frames, over the column
!> segments: `max_abs_target`), and the smallest gap from which on every targeted |lambda|
!> stays within the target is reported.
!>
!> The gaps are independent cases (`pound_cases`): one after the other in the serial build,
!> shared over the ranks with MPI; each gap's coupled run gives a column (the largest
!> |lambda| per quantity and building, impacts, energy residual, first warning), and the
!> result is assembled from the columns in gap order, so it is the same for any number of
!> ranks. Before the gaps, one coupled run in which no joint can close (`probe_gap`)
!> records each joint's largest closing displacement: a gap beyond them all has no contact in
!> its run, which would be that run bit for bit, so its column is the probe's (no run). A gap
!> whose run fails (e.g. an LCP with no solution) does not stop the others: it
!> is marked (`failed`, `messages`), left out of the results (zeros, never meeting the target,
!> so that the smallest safe gap lies above it) and named in a warning. Only a sweep whose
!> every gap fails ends with an error naming the first.
module pound_sweep
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: mm_text, str
   use pound_sweep_settings, only: sweep_config
   use pound_quantities, only: n_target_quantities
   use pound_analysis_plan, only: analysis_plan
   use pound_structure, only: structure_model
   use pound_ground_motion, only: ground_motion_t
   use pound_analysis, only: analysis_result, coupled_model, coupled_prepare, coupled_integrate, &
                             add_warning, audit_warning_limit, beyond_closing, probe_gap
   use pound_contact, only: contact_pair, contact_system
   use pound_influence, only: influence_of, max_abs_target
   use pound_progress, only: progress_run_done
   use pound_cases, only: case_work, case_table, run_cases, first_failure, text_to_column, column_to_text, &
                          case_message_len
   implicit none
   private

   public :: sweep_result, run_sweep, sweep_gaps, sweep_from_table
   public :: gap_cases, gap_cases_init, gap_cases_probe, gap_cases_set_probe, sweep_column_width, gap_run

   !> Characters kept of a gap's first warning.
   integer, parameter :: warning_len = 512

   !> Result of a gap sweep.
   type :: sweep_result
      !> Gaps (m).
      real(dp), allocatable :: gap(:)
      !> Largest |lambda| (%) over floors/storeys (the history quantities) and over a frame's
      !> column segments (column_shear, column_moment; 0 for a shear building), in the order of
      !> `target_names`, (n_target_quantities, n_buildings, n_gaps).
      real(dp), allocatable :: max_abs_lambda(:, :, :)
      !> Total number of impacts at each gap.
      integer, allocatable :: impacts(:)
      !> Whether each gap meets the target on every targeted quantity and building (false for
      !> a failed gap).
      logical, allocatable :: meets(:)
      !> Whether each gap's coupled run failed (its results are zeros, left out).
      logical, allocatable :: failed(:)
      !> Whether each gap lies beyond every joint's largest closing displacement without
      !> contact (`probe_gap`): no contact, the probe's result taken, no run of its own.
      logical, allocatable :: beyond(:)
      !> The joints' largest closing displacement without contact (m; not allocated when the
      !> probe failed).
      real(dp), allocatable :: closing_max(:)
      !> The message of each failed gap (blank otherwise).
      character(len=case_message_len), allocatable :: messages(:)
      !> Time (s) and step at which each failed gap's run failed (-1: not known, or not failed).
      real(dp), allocatable :: time(:)
      integer, allocatable :: step(:)
      !> Smallest gap from which on every larger gap of the sweep meets the target (m).
      real(dp) :: safe_gap = -1.0_dp
      !> Whether such a gap exists in the range (only with a target).
      logical :: found = .false.
      !> Wall-clock time of all coupled runs (s).
      real(dp) :: seconds = 0.0_dp
      !> Warnings (one line each): the gaps whose energy audit exceeds `audit_warning_limit`,
      !> with the first warning of the worst one.
      character(len=:), allocatable :: warnings(:)
   end type sweep_result

   !> The gaps of a sweep as cases: gap i's coupled run, against the uncoupled result
   !> (`gap_cases_init`, then `gap_cases_probe` or `gap_cases_set_probe`).
   !> Column (`sweep_column_width` reals): max |lambda| (n_target_quantities x n_buildings),
   !> impacts, energy residual, number of warnings, 1 when the gap is beyond the joints'
   !> closing (the probe's column), the first warning (`text_to_column`).
   type, extends(case_work) :: gap_cases
      !> Settings of the sweep's runs (no histories).
      type(analysis_plan) :: cfg
      !> The buildings, the ground samples, the prepared coupled model, the uncoupled result,
      !> the ground motion (not allocated: none needed; passed on as an absent argument).
      type(structure_model), pointer :: models(:) => null()
      real(dp), allocatable :: ag(:)
      type(coupled_model) :: prep
      type(analysis_result), pointer :: unc => null()
      type(ground_motion_t), allocatable :: ground
      !> The gaps (m) and the number of constraints.
      real(dp), allocatable :: gap(:)
      integer :: n_pairs = 0
      !> The probe's largest closing displacement of each joint and its column (not allocated
      !> when the probe failed: every gap runs).
      real(dp), allocatable :: closing_max(:), probe(:)
   contains
      procedure :: compute => gap_case
   end type gap_cases

contains

   !> Gap i of the sweep: its coupled run into a column.
   recursive subroutine gap_case(work, i, values, error)
      !> The sweep's cases.
      class(gap_cases), intent(inout) :: work
      !> Gap index.
      integer, intent(in) :: i
      !> The column.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: gaps(work%n_pairs)

      gaps = work%gap(i)
      if (allocated(work%probe)) then
         if (beyond_closing(gaps, work%closing_max)) then
            values = work%probe
            ! A case done (the progress line counts cases), without a run.
            call progress_run_done()
            return
         end if
      end if
      call gap_run(work, gaps, values, error)
   end subroutine gap_case

   !> The coupled run of the cases' prepared model with the gaps `gaps` (one per constraint)
   !> into a column (`gap_cases`; also the joints' cases of `pound_sweep_joints`).
   recursive subroutine gap_run(work, gaps, values, error)
      !> The sweep's cases.
      class(gap_cases), intent(in) :: work
      !> Gap of every constraint (m).
      real(dp), intent(in) :: gaps(:)
      !> The column.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(analysis_result) :: cpl
      type(contact_system) :: cs

      ! An unallocated `ground` is an absent argument.
      call coupled_integrate(work%cfg, work%models, work%ag, work%prep, cpl, cs, error, gaps, work%ground)
      if (allocated(error)) return
      call result_column(work, cpl, sum(cs%joint(:)%impacts), values)
   end subroutine gap_run

   !> A coupled run's column (`gap_cases`); the flag of a gap beyond the closing is 0.
   subroutine result_column(work, cpl, impacts, values)
      !> The sweep's cases.
      class(gap_cases), intent(in) :: work
      !> The coupled result.
      type(analysis_result), intent(in) :: cpl
      !> Its number of impacts.
      integer, intent(in) :: impacts
      !> The column.
      real(dp), intent(out) :: values(:)
      integer :: nl

      nl = n_target_quantities*size(work%models)
      values(1:nl) = reshape(max_abs_target(influence_of(work%unc, cpl, work%models), work%models, work%unc, cpl), [nl])
      values(nl + 1) = real(impacts, dp)
      values(nl + 2) = cpl%energy_error
      values(nl + 3) = real(size(cpl%warnings), dp)
      values(nl + 4) = 0.0_dp
      if (size(cpl%warnings) > 0) then
         call text_to_column(trim(cpl%warnings(1)), values(nl + 5:))
      else
         call text_to_column('', values(nl + 5:))
      end if
   end subroutine result_column

   !> The gaps of a sweep: n_gaps values evenly spaced from gap_from to gap_to.
   pure function sweep_gaps(cfg) result(gaps)
      !> `&sweep`.
      type(sweep_config), intent(in) :: cfg
      real(dp) :: gaps(cfg%n_gaps)
      integer :: i

      do i = 1, cfg%n_gaps
         gaps(i) = cfg%gap_from + (cfg%gap_to - cfg%gap_from)*real(i - 1, dp)/real(cfg%n_gaps - 1, dp)
      end do
   end function sweep_gaps

   !> Run the coupled analysis for every gap of the sweep, against the uncoupled result `unc`.
   subroutine run_sweep(cfg, sweep, models, ag, pairs, unc, res, error, ground)
      !> `&analysis` settings (histories are not stored for the sweep runs).
      type(analysis_plan), intent(in) :: cfg
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> The buildings.
      type(structure_model), intent(in), target :: models(:)
      !> Ground acceleration at t_n = n dt (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The constraints of the deck.
      type(contact_pair), intent(in) :: pairs(:)
      !> Uncoupled result.
      type(analysis_result), intent(in), target :: unc
      !> The sweep result.
      type(sweep_result), intent(out) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples (needed by `stepping = 'impact'`).
      type(ground_motion_t), intent(in), optional :: ground
      type(gap_cases) :: cases
      type(case_table) :: table
      integer(int64) :: c0, c1, rate

      call system_clock(c0, rate)
      call gap_cases_init(cases, cfg, sweep, models, ag, pairs, unc, error, ground)
      if (allocated(error)) return
      call gap_cases_probe(cases)
      call run_cases(cases, sweep%n_gaps, sweep_column_width(size(models)), table)
      call sweep_from_table(sweep, size(models), table, res, error)
      if (allocated(error)) return
      if (allocated(cases%probe)) res%closing_max = cases%closing_max
      call system_clock(c1)
      res%seconds = real(c1 - c0, dp)/real(rate, dp)
   end subroutine run_sweep

   !> Reals in a gap's column (`gap_cases`) for nb buildings.
   pure integer function sweep_column_width(nb) result(width)
      !> Number of buildings.
      integer, intent(in) :: nb

      width = n_target_quantities*nb + 5 + warning_len
   end function sweep_column_width

   !> The gaps of `sweep` as cases against the uncoupled result `unc`: what the coupled runs
   !> share and what does not depend on the gap (the factored Khat of every building, the
   !> condensed constraints) prepared once; the runs store no histories. No probe yet: every
   !> gap runs until `gap_cases_probe` or `gap_cases_set_probe`.
   subroutine gap_cases_init(cases, cfg, sweep, models, ag, pairs, unc, error, ground)
      !> The cases.
      type(gap_cases), intent(out) :: cases
      !> `&analysis` settings.
      type(analysis_plan), intent(in) :: cfg
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> The buildings (kept by reference).
      type(structure_model), intent(in), target :: models(:)
      !> Ground acceleration at t_n = n dt (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The constraints of the deck.
      type(contact_pair), intent(in) :: pairs(:)
      !> Uncoupled result (kept by reference; its peaks are used).
      type(analysis_result), intent(in), target :: unc
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples (needed by `stepping = 'impact'`).
      type(ground_motion_t), intent(in), optional :: ground

      cases%cfg = cfg
      cases%cfg%store = .false.
      cases%cfg%output_every = max(1, cfg%n_steps)
      call coupled_prepare(cases%cfg, models, ag(0), pairs, cases%prep, error)
      if (allocated(error)) return
      cases%models => models
      cases%ag = ag
      cases%unc => unc
      if (present(ground)) cases%ground = ground
      cases%gap = sweep_gaps(sweep)
      cases%n_pairs = size(pairs)
   end subroutine gap_cases_init

   !> The probe: one coupled run in which no joint can close (`probe_gap`) records each joint's
   !> largest closing displacement; every gap beyond them all then takes the probe's column
   !> (no run). A probe that fails decides nothing: every gap runs.
   subroutine gap_cases_probe(cases)
      !> The cases (`gap_cases_init`).
      type(gap_cases), intent(inout) :: cases
      type(analysis_result) :: probe
      type(contact_system) :: probe_cs
      type(error_type), allocatable :: probe_error

      call coupled_integrate(cases%cfg, cases%models, cases%ag, cases%prep, probe, probe_cs, probe_error, &
                             spread(probe_gap, 1, cases%n_pairs), cases%ground, track=.true.)
      if (allocated(probe_error)) return
      cases%closing_max = probe_cs%closing_max
      allocate (cases%probe(sweep_column_width(size(cases%models))))
      call result_column(cases, probe, 0, cases%probe)
      cases%probe(n_target_quantities*size(cases%models) + 4) = 1.0_dp
   end subroutine gap_cases_probe

   !> Take a probe made elsewhere (`gap_cases_probe` of the same motion and models: its
   !> `closing_max` and `probe`).
   pure subroutine gap_cases_set_probe(cases, closing_max, column)
      !> The cases (`gap_cases_init`).
      type(gap_cases), intent(inout) :: cases
      !> Each joint's largest closing displacement (m).
      real(dp), intent(in) :: closing_max(:)
      !> The probe's column.
      real(dp), intent(in) :: column(:)

      cases%closing_max = closing_max
      cases%probe = column
   end subroutine gap_cases_set_probe

   !> The sweep result from its cases' table (column i: gap i, see `gap_cases`). A failed gap
   !> is marked, its results zeros, counted as not meeting the target (so that the smallest
   !> gap meeting it lies above every failed gap) and named in a warning; an error when every
   !> gap failed.
   subroutine sweep_from_table(sweep, nb, table, res, error)
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> Number of buildings.
      integer, intent(in) :: nb
      !> The gaps' table (sweep%n_gaps columns).
      type(case_table), intent(in) :: table
      !> The sweep result (`seconds` not set).
      type(sweep_result), intent(out) :: res
      !> Error state: every gap failed.
      type(error_type), allocatable, intent(out) :: error
      character(len=64) :: names(sweep%n_gaps)
      character(len=:), allocatable :: worst_text
      real(dp) :: worst
      integer :: i, q, n_bad, nl

      nl = n_target_quantities*nb
      res%gap = sweep_gaps(sweep)
      allocate (res%max_abs_lambda(n_target_quantities, nb, sweep%n_gaps), &
                res%impacts(sweep%n_gaps), res%meets(sweep%n_gaps))
      allocate (character(len=1) :: res%warnings(0))
      n_bad = 0
      worst = 0.0_dp
      do i = 1, sweep%n_gaps
         names(i) = 'gap sweep, gap = '//mm_text(res%gap(i))
      end do
      if (all(table%failed)) then
         call first_failure(table, names, error)
         return
      end if
      res%failed = table%failed
      res%messages = table%message
      res%time = table%time
      res%step = table%step
      res%beyond = table%values(nl + 4, :) > 0.0_dp .and. .not. table%failed
      do i = 1, sweep%n_gaps
         associate (col => table%values(:, i))
            if (col(nl + 3) > 0.0_dp) then
               n_bad = n_bad + 1
               if (col(nl + 2) > worst) then
                  worst = col(nl + 2)
                  worst_text = 'gap = '//mm_text(res%gap(i))//': '//column_to_text(col(nl + 5:))
               end if
            end if
            res%impacts(i) = nint(col(nl + 1))
            res%max_abs_lambda(:, :, i) = reshape(col(1:nl), [n_target_quantities, nb])
         end associate
         res%meets(i) = .not. res%failed(i)
         do q = 1, n_target_quantities
            if (sweep%target_quantities(q)) then
               if (any(res%max_abs_lambda(q, :, i) > sweep%target)) res%meets(i) = .false.
            end if
         end do
      end do
      if (sweep%target > 0.0_dp) then
         do i = sweep%n_gaps, 1, -1
            if (.not. res%meets(i)) exit
            res%safe_gap = res%gap(i)
            res%found = .true.
         end do
      end if
      if (n_bad > 0) then
         call add_warning(res%warnings, 'gap sweep: the energy audit exceeds '//str(audit_warning_limit)// &
                          ' at '//str(n_bad)//' of '//str(sweep%n_gaps)//' gaps; the worst, '//worst_text)
      end if
      if (any(res%failed)) then
         i = findloc(res%failed, .true., 1)
         call add_warning(res%warnings, 'gap sweep: '//str(count(res%failed))//' of '//str(sweep%n_gaps)// &
                          ' gaps failed and are left out (counted as not meeting the target, so the '// &
                          'smallest gap meeting it lies above them); the first, '//trim(names(i))//': '// &
                          trim(res%messages(i)))
      end if
   end subroutine sweep_from_table

end module pound_sweep
