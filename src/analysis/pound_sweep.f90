!> Seismic-joint gap study: the coupled analysis repeated for a range of gaps.
!>
!> The uncoupled analysis is run once (it does not depend on the gap); everything of the
!> coupled analysis that does not depend on the gap — the factored Khat of every building and
!> the condensed constraints Khat^{-1} B and F — is prepared once and reused for every gap.
!> Each gap is applied to every constraint. For every gap the largest |lambda| over the
!> floors (storeys) is kept per building and quantity, and the smallest gap from which on every
!> targeted |lambda| stays within the target is reported.
module pound_sweep
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str
   use pound_config, only: analysis_config, sweep_config, n_history_quantities
   use pound_structure, only: structure_model
   use pound_ground_motion, only: ground_motion_t
   use pound_analysis, only: analysis_result, coupled_model, coupled_prepare, coupled_integrate, &
                             add_warning, audit_warning_limit
   use pound_contact, only: contact_pair, contact_system
   use pound_influence, only: influence_of, max_abs_influence
   implicit none
   private

   public :: sweep_result, run_sweep, sweep_gaps

   !> Result of a gap sweep.
   type :: sweep_result
      !> Gaps (m).
      real(dp), allocatable :: gap(:)
      !> Largest |lambda| (%) over floors/storeys, (n_history_quantities, n_buildings, n_gaps).
      real(dp), allocatable :: max_abs_lambda(:, :, :)
      !> Total number of impacts at each gap.
      integer, allocatable :: impacts(:)
      !> Whether each gap meets the target on every targeted quantity and building.
      logical, allocatable :: meets(:)
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

contains

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
      type(analysis_config), intent(in) :: cfg
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration at t_n = n dt (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The constraints of the deck.
      type(contact_pair), intent(in) :: pairs(:)
      !> Uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> The sweep result.
      type(sweep_result), intent(out) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples (needed by `stepping = 'impact'`).
      type(ground_motion_t), intent(in), optional :: ground
      type(analysis_config) :: quiet
      type(coupled_model) :: prep
      type(analysis_result) :: cpl
      type(contact_system) :: cs
      real(dp) :: gaps(size(pairs)), worst
      integer :: i, q, n_bad
      character(len=:), allocatable :: worst_text
      integer(int64) :: c0, c1, rate

      call system_clock(c0, rate)
      quiet = cfg
      quiet%store = .false.
      quiet%output_every = max(1, nint(cfg%t_end/cfg%dt))
      res%gap = sweep_gaps(sweep)
      allocate (res%max_abs_lambda(n_history_quantities, size(models), sweep%n_gaps), &
                res%impacts(sweep%n_gaps), res%meets(sweep%n_gaps))
      allocate (character(len=1) :: res%warnings(0))
      n_bad = 0
      worst = 0.0_dp
      call coupled_prepare(quiet, models, ag(0), pairs, prep, error)
      if (allocated(error)) return
      do i = 1, sweep%n_gaps
         gaps = res%gap(i)
         call coupled_integrate(quiet, models, ag, prep, cpl, cs, error, gaps, ground)
         if (allocated(error)) then
            error%message = 'gap sweep, gap = '//str(res%gap(i))//' m: '//error%message
            return
         end if
         if (size(cpl%warnings) > 0) then
            n_bad = n_bad + 1
            if (cpl%energy_error > worst) then
               worst = cpl%energy_error
               worst_text = 'gap = '//str(res%gap(i))//' m: '//trim(cpl%warnings(1))
            end if
         end if
         res%impacts(i) = sum(cs%joint(:)%impacts)
         res%max_abs_lambda(:, :, i) = max_abs_influence(influence_of(unc, cpl))
         res%meets(i) = .true.
         do q = 1, n_history_quantities
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
      call system_clock(c1)
      res%seconds = real(c1 - c0, dp)/real(rate, dp)
   end subroutine run_sweep

end module pound_sweep
