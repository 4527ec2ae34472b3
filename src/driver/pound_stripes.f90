!> The multiple-stripe analysis (`&stripes`, `&hazard`): the risk-targeted joint.
!>
!> Every (stripe, motion) is a case (`pound_cases`: one after the other serially, shared over
!> the ranks with MPI, assembled in case order, so the results do not depend on the number of
!> ranks). A case scales the motion to the stripe's level by the stripes' measure exactly as
!> `scale_to` would (`suite_motion_samples` of a one-motion deck whose motion has `scale_to`,
!> `target` and `period` set), runs it uncoupled and coupled at the deck's gaps (`run_case`)
!> and, with a `&sweep`, coupled again at every gap of the sweep: the gap-independent part of
!> the coupled model is prepared once per case (`gap_cases_init`), one coupled run in which no
!> joint can close (the sweep's probe) gives every gap beyond the joints' largest closing
!> displacement (no contact: that run bit for bit), the other gaps run.
!>
!> Per (gap, stripe, motion) the 0/1 outcomes (`outcome_names`): contact (an impact in the
!> coupled run), lambda_exceeded (the largest |lambda| of the targeted quantities over every
!> building and storey, `max_abs_target` as the sweep's target, above target_lambda), collapse
!> (a building collapses coupled) and collapse_due_to_pounding (a building collapses coupled
!> and not uncoupled), the last two where a building can yield. Per gap and outcome the
!> lognormal fragility fitted by binomial maximum likelihood over the stripes
!> (`pound_fragility`), the mean annual frequency against the hazard curve and the probability
!> in `years` (`pound_hazard`); per outcome the risk-targeted gap: the smallest gap of the grid
!> at which P <= target_probability there and at every larger gap (NaN where none; not refined
!> between grid gaps). Per (stripe, motion) the coupled demands at the deck gap for loss tools:
!> peak interstorey drift ratio per storey, peak floor acceleration per floor (floor 0: PGA).
module pound_stripes
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_config, only: deck_type, n_target_quantities
   use pound_ground_motion, only: ground_motion_t, ground_moves_y
   use pound_structure, only: structure_model, structure_names, direction_y
   use pound_building, only: building_model, build_building
   use pound_analysis, only: analysis_result, coupled_integrate, beyond_closing, probe_gap
   use pound_analysis_plan, only: steps_of
   use pound_contact, only: contact_pair, contact_system, pairs_from_config
   use pound_influence, only: influence_of, max_abs_target
   use pound_spectrum, only: peak_ground_acceleration
   use pound_run_case, only: case_options, case_result, run_case, analysis_plan_of
   use pound_sweep, only: gap_cases, gap_cases_init, sweep_gaps
   use pound_suite_motions, only: suite_motion_samples
   use pound_cases, only: case_work, case_table, run_cases, first_failure
   use pound_progress, only: progress_run_done
   use pound_fragility, only: fit_fragility
   use pound_stripes_result, only: stripes_result, outcome_names, n_outcomes, o_contact, o_lambda, o_collapse, o_due
   use pound_hazard, only: hazard_curve, fragility_maf, probability_in
   implicit none
   private

   public :: stripes_result, run_stripes, outcome_names, n_outcomes, stripes_runs, o_contact, o_lambda, &
             o_collapse, o_due

   !> The (stripe, motion) cases: case (s - 1) n_motions + k is motion k at stripe s. Column:
   !> the outcomes at the deck gap, at every sweep gap, then per building its drift ratios and
   !> floor accelerations (`column_width`).
   type, extends(case_work) :: stripe_cases
      !> The deck.
      type(deck_type), pointer :: deck => null()
      !> A one-motion copy of the deck without sweep (its motion set per case).
      type(deck_type) :: one
      !> Number of sweep gaps (0: none) and the storeys of each building.
      integer :: n_gaps = 0
      integer, allocatable :: n_storeys(:)
      !> The buildings (their periods give the default period of Sa).
      type(structure_model), allocatable :: models(:)
   contains
      procedure :: compute => stripe_case
   end type stripe_cases

contains

   !> The integration runs of the analysis (the progress line's total): per case an uncoupled
   !> and a coupled run, with a sweep its probe and every gap.
   pure integer function stripes_runs(deck) result(n)
      !> A validated configuration with `&stripes`.
      type(deck_type), intent(in) :: deck

      n = 2
      if (deck%sweep%active) n = n + 1 + deck%sweep%n_gaps
      n = n*size(deck%risk%levels)*size(deck%motions)
   end function stripes_runs

   !> Reals in a case's column.
   pure integer function column_width(n_gaps, n_storeys) result(w)
      integer, intent(in) :: n_gaps, n_storeys(:)

      w = n_outcomes*(1 + n_gaps) + sum(2*n_storeys + 1)
   end function column_width

   !> Run the multiple-stripe analysis of `deck` (`&stripes` active) into `res`.
   subroutine run_stripes(deck, res, error)
      !> A validated configuration with `&stripes` and `&hazard`.
      type(deck_type), intent(in), target :: deck
      !> The results.
      type(stripes_result), intent(out) :: res
      !> Error state: a model that cannot be built, a case that failed (named), a fit that failed.
      type(error_type), allocatable, intent(out) :: error
      type(stripe_cases) :: work
      type(case_table) :: table
      type(structure_model), allocatable :: models(:)
      type(building_model) :: bm
      character(len=300), allocatable :: names(:)
      integer :: ib, nm, ns, ng, s, k, i, nb
      integer(int64) :: c0, c1, rate

      call system_clock(c0, rate)
      nm = size(deck%motions)
      ns = size(deck%risk%levels)
      nb = size(deck%buildings)
      allocate (models(nb))
      do ib = 1, nb
         call build_building(deck%buildings(ib), models(ib), bm, error)
         if (allocated(error)) return
      end do
      res%levels = deck%risk%levels
      res%period = 0.0_dp
      if (deck%risk%measure == 'sa') then
         res%period = deck%risk%period
         if (.not. (res%period > 0.0_dp)) res%period = maxval([(models(ib)%period(1), ib=1, nb)])
      end if
      allocate (res%motions(nm))
      do k = 1, nm
         res%motions(k) = deck%motions(k)%name
      end do
      res%deck_gap = deck%contacts(1)%gap(1)
      if (deck%sweep%active) then
         res%gaps = sweep_gaps(deck%sweep)
      else
         res%gaps = [res%deck_gap]
      end if
      res%yields = any(deck%buildings%storey_law == 'bilinear' .or. deck%buildings%hinge_law == 'elastic_plastic')

      work%deck => deck
      work%one = deck
      work%one%sweep%active = .false.
      work%one%risk%active = .false.
      work%one%motions = deck%motions(1:1)
      work%n_gaps = 0
      if (deck%sweep%active) work%n_gaps = deck%sweep%n_gaps
      work%n_storeys = [(size(models(ib)%floor_dof), ib=1, nb)]
      work%models = models
      call run_cases(work, ns*nm, column_width(work%n_gaps, work%n_storeys), table)
      allocate (names(ns*nm))
      do s = 1, ns
         do k = 1, nm
            names((s - 1)*nm + k) = "stripe "//str(s)//", &ground '"//trim(res%motions(k))//"'"
         end do
      end do
      call first_failure(table, names, error)
      if (allocated(error)) return

      ng = size(res%gaps)
      allocate (res%outcome(n_outcomes, nm, ns, ng), res%deck_outcome(n_outcomes, nm, ns), res%demand(nb))
      do ib = 1, nb
         allocate (res%demand(ib)%pid(work%n_storeys(ib), nm, ns), res%demand(ib)%pfa(0:work%n_storeys(ib), nm, ns))
      end do
      do s = 1, ns
         do k = 1, nm
            associate (col => table%values(:, (s - 1)*nm + k))
               res%deck_outcome(:, k, s) = nint(col(1:n_outcomes))
               if (work%n_gaps > 0) then
                  do i = 1, ng
                     res%outcome(:, k, s, i) = nint(col(i*n_outcomes + 1:(i + 1)*n_outcomes))
                  end do
               else
                  res%outcome(:, k, s, 1) = res%deck_outcome(:, k, s)
               end if
               i = n_outcomes*(1 + work%n_gaps)
               do ib = 1, nb
                  associate (n => work%n_storeys(ib))
                     res%demand(ib)%pid(:, k, s) = col(i + 1:i + n)
                     res%demand(ib)%pfa(:, k, s) = col(i + n + 1:i + 2*n + 1)
                     i = i + 2*n + 1
                  end associate
               end do
            end associate
         end do
      end do
      call risk_of(deck, res, error)
      call system_clock(c1)
      res%seconds = real(c1 - c0, dp)/real(rate, dp)
   end subroutine run_stripes

   !> The fragilities, frequencies, probabilities and risk-targeted gaps of `res` from its outcomes.
   subroutine risk_of(deck, res, error)
      !> The configuration (its hazard, years and target probability).
      type(deck_type), intent(in) :: deck
      !> The results (outcomes set).
      type(stripes_result), intent(inout) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(hazard_curve) :: hz
      integer :: o, g, ng, ns, nm, s, first
      integer, allocatable :: n_total(:), n_yes(:)

      hz%im = deck%risk%im
      hz%rate = deck%risk%rate
      ng = size(res%gaps)
      ns = size(res%levels)
      nm = size(res%motions)
      allocate (res%fit(n_outcomes, ng), res%deck_fit(n_outcomes), res%maf(n_outcomes, ng), &
                res%probability(n_outcomes, ng), res%deck_maf(n_outcomes), res%deck_probability(n_outcomes))
      n_total = spread(nm, 1, ns)
      allocate (n_yes(ns))
      res%risk_gap = ieee_value(1.0_dp, ieee_quiet_nan)
      do o = 1, n_outcomes
         do g = 0, ng
            if (g == 0) then
               n_yes = [(sum(res%deck_outcome(o, :, s)), s=1, ns)]
               call fit_fragility(res%levels, n_total, n_yes, res%deck_fit(o), error)
               if (allocated(error)) return
               res%deck_maf(o) = fragility_maf(res%deck_fit(o), hz)
               res%deck_probability(o) = probability_in(res%deck_maf(o), deck%risk%years)
            else
               n_yes = [(sum(res%outcome(o, :, s, g)), s=1, ns)]
               call fit_fragility(res%levels, n_total, n_yes, res%fit(o, g), error)
               if (allocated(error)) return
               res%maf(o, g) = fragility_maf(res%fit(o, g), hz)
               res%probability(o, g) = probability_in(res%maf(o, g), deck%risk%years)
            end if
         end do
         if (deck%risk%target_probability < 0.0_dp) cycle
         first = 0
         do g = ng, 1, -1
            if (.not. (res%probability(o, g) <= deck%risk%target_probability)) exit
            first = g
         end do
         if (first > 0) res%risk_gap(o) = res%gaps(first)
      end do
   end subroutine risk_of

   !> Case i: motion k at stripe s, its outcomes at the deck gap and at the sweep's gaps, and
   !> its coupled demands at the deck gap.
   recursive subroutine stripe_case(work, i, values, error)
      !> The cases.
      class(stripe_cases), intent(inout) :: work
      !> Case index.
      integer, intent(in) :: i
      !> The column.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(case_options) :: options
      type(case_result), target :: res
      type(ground_motion_t) :: gm
      real(dp), allocatable :: ag(:)
      real(dp) :: factor, pga
      integer :: s, k, nm, n_steps, ib, j, n, at

      values = 0.0_dp
      nm = size(work%deck%motions)
      s = (i - 1)/nm + 1
      k = i - (s - 1)*nm
      associate (one => work%one, risk => work%deck%risk)
         one%motions(1) = work%deck%motions(k)
         one%motions(1)%scale_to = risk%measure
         one%motions(1)%target = risk%levels(s)
         one%motions(1)%period = risk%period
         one%motions(1)%scale = 1.0_dp
         one%ground = one%motions(1)
         n_steps = steps_of(one%analysis%t_end, one%analysis%dt)
         allocate (ag(0:n_steps))
         call suite_motion_samples(one, 1, work%models, gm, factor, ag, error)
      end associate
      if (allocated(error)) return
      pga = peak_ground_acceleration(ag)
      allocate (options%ground, source=gm)
      call run_case(work%one, res, error, options)
      if (allocated(error)) return
      values(1:n_outcomes) = outcomes_of(work%deck, res%models, res%unc, res%cpl, sum(res%cs%joint(:)%impacts))
      if (work%n_gaps > 0) then
         call sweep_outcomes(work, res, ag, gm, values(n_outcomes + 1:n_outcomes*(1 + work%n_gaps)), error)
         if (allocated(error)) return
      end if
      at = n_outcomes*(1 + work%n_gaps)
      do ib = 1, size(res%models)
         n = work%n_storeys(ib)
         do j = 1, n
            values(at + j) = res%cpl%building(ib)%peak(j, 4)/work%deck%buildings(ib)%height(j)
         end do
         values(at + n + 1) = pga
         values(at + n + 2:at + 2*n + 1) = res%cpl%building(ib)%peak(1:n, 3)
         at = at + 2*n + 1
      end do
   end subroutine stripe_case

   !> The outcomes of one coupled run `cpl` against the uncoupled `unc` with `impacts` impacts:
   !> contact, lambda_exceeded, collapse, collapse_due_to_pounding, as 0/1.
   pure function outcomes_of(deck, models, unc, cpl, impacts) result(o)
      !> The configuration (its target).
      type(deck_type), intent(in) :: deck
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Uncoupled and coupled results.
      type(analysis_result), intent(in) :: unc, cpl
      !> Number of impacts of the coupled run.
      integer, intent(in) :: impacts
      real(dp) :: o(n_outcomes)
      real(dp) :: m(n_target_quantities, size(models))
      logical :: unc_collapse, cpl_collapse
      integer :: ib

      o = 0.0_dp
      if (impacts > 0) o(o_contact) = 1.0_dp
      m = max_abs_target(influence_of(unc, cpl), models, unc, cpl)
      if (any(spread(deck%risk%target_quantities, 2, size(models)) .and. m > deck%risk%target_lambda)) &
         o(o_lambda) = 1.0_dp
      if (.not. (allocated(unc%yielding) .and. allocated(cpl%yielding))) return
      do ib = 1, size(models)
         cpl_collapse = cpl%yielding(ib)%collapse_storey > 0
         unc_collapse = unc%yielding(ib)%collapse_storey > 0
         if (cpl_collapse) o(o_collapse) = 1.0_dp
         if (cpl_collapse .and. .not. unc_collapse) o(o_due) = 1.0_dp
      end do
   end function outcomes_of

   !> The outcomes at every gap of the sweep (`values`: n_outcomes a gap), the coupled model
   !> prepared once, the gaps beyond the joints' largest closing taking the probe's outcomes.
   subroutine sweep_outcomes(work, res, ag, gm, values, error)
      !> The cases.
      class(stripe_cases), intent(in) :: work
      !> The case's result at the deck gap (models, uncoupled run).
      type(case_result), intent(in), target :: res
      !> The scaled motion's samples and the motion.
      real(dp), intent(in) :: ag(0:)
      type(ground_motion_t), intent(in) :: gm
      !> The outcomes, gap after gap.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(gap_cases) :: cases
      type(contact_pair), allocatable :: pairs(:)
      type(analysis_result) :: cpl
      type(contact_system) :: cs
      type(error_type), allocatable :: probe_error
      real(dp), allocatable :: gaps(:), closing(:)
      real(dp) :: probe(n_outcomes)
      logical :: has_probe
      integer :: g

      ! The stripes' gap runs take the ground along x only (no `analysis_plan%ground_y`).
      do g = 1, size(res%models)
         if (.not. ground_moves_y(gm) .or. .not. allocated(res%models(g)%ground_direction)) cycle
         if (.not. any(res%models(g)%ground_direction == direction_y)) cycle
         call fatal_error(error, '&risk: the stripes take the ground along x only; buildings in plan under a '// &
                          'ground along y (angle or file_2) are refused here: give angle = 0 and no file_2')
         return
      end do
      pairs = pairs_from_config(work%deck%contacts, structure_names(res%models), error, res%models)
      if (allocated(error)) return
      call gap_cases_init(cases, analysis_plan_of(work%deck%analysis), work%deck%sweep, res%models, ag, pairs, &
                          res%unc, error, gm)
      if (allocated(error)) return
      allocate (gaps(size(pairs)))
      call coupled_integrate(cases%cfg, res%models, ag, cases%prep, cpl, cs, probe_error, &
                             spread(probe_gap, 1, size(pairs)), gm, track=.true.)
      has_probe = .not. allocated(probe_error)
      if (has_probe) then
         closing = cs%closing_max
         probe = outcomes_of(work%deck, res%models, res%unc, cpl, 0)
      end if
      do g = 1, work%n_gaps
         gaps = cases%gap(g)
         if (has_probe) then
            if (beyond_closing(gaps, closing)) then
               values((g - 1)*n_outcomes + 1:g*n_outcomes) = probe
               call progress_run_done()
               cycle
            end if
         end if
         call coupled_integrate(cases%cfg, res%models, ag, cases%prep, cpl, cs, error, gaps, gm)
         if (allocated(error)) then
            error%message = 'gap '//str(1000.0_dp*gaps(1))//' mm: '//error%message
            return
         end if
         values((g - 1)*n_outcomes + 1:g*n_outcomes) = outcomes_of(work%deck, res%models, res%unc, cpl, &
                                                                   sum(cs%joint(:)%impacts))
      end do
   end subroutine sweep_outcomes

end module pound_stripes
