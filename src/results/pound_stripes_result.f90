!> What the multiple-stripe analysis gives (`stripes_result`): per (gap, stripe, motion) the
!> 0/1 outcomes (`outcome_names`), their fragility fits, mean annual frequencies and
!> probabilities, the risk-targeted gaps and the coupled demands. Filled by `run_stripes`
!> (pound_stripes); read by src/output/pound_stripes_output.f90.
module pound_stripes_result
   use pound_kinds, only: dp
   use pound_fragility, only: fragility_fit
   implicit none
   private

   public :: stripes_result, demand_set, outcome_names, n_outcomes, o_contact, o_lambda, o_collapse, o_due

   !> The outcomes, in this order.
   integer, parameter :: n_outcomes = 4
   integer, parameter :: o_contact = 1, o_lambda = 2, o_collapse = 3, o_due = 4
   character(len=*), parameter :: outcome_names(n_outcomes) = [character(len=24) :: 'contact', &
      'lambda_exceeded', 'collapse', 'collapse_due_to_pounding']

   !> What the multiple-stripe analysis gives.
   type :: stripes_result
      !> Stripe levels (m/s^2) and the measure's period (s; 0 for 'pga').
      real(dp), allocatable :: levels(:)
      real(dp) :: period = 0.0_dp
      !> Motion names.
      character(len=256), allocatable :: motions(:)
      !> Gaps (m): the sweep's, or the deck gap alone (the first pair's) without a sweep; the
      !> deck gap.
      real(dp), allocatable :: gaps(:)
      real(dp) :: deck_gap = 0.0_dp
      !> Whether a building can yield (the collapse outcomes exist).
      logical :: yields = .false.
      !> Outcomes 0/1 (n_outcomes, n_motions, n_stripes, n_gaps), and at the deck gap
      !> (n_outcomes, n_motions, n_stripes).
      integer, allocatable :: outcome(:, :, :, :), deck_outcome(:, :, :)
      !> Fragility fits (n_outcomes, n_gaps) and at the deck gap (n_outcomes).
      type(fragility_fit), allocatable :: fit(:, :), deck_fit(:)
      !> Mean annual frequency (1/year) and probability in `years`, (n_outcomes, n_gaps), and
      !> at the deck gap (n_outcomes).
      real(dp), allocatable :: maf(:, :), probability(:, :), deck_maf(:), deck_probability(:)
      !> Risk-targeted gap per outcome (m; NaN where none or no target probability).
      real(dp) :: risk_gap(n_outcomes)
      !> Coupled demands at the deck gap per building: peak interstorey drift ratio
      !> (n_storeys, n_motions, n_stripes) and peak floor acceleration (m/s^2; floors 0..n,
      !> floor 0 the PGA), (0:n_storeys, n_motions, n_stripes).
      type(demand_set), allocatable :: demand(:)
      !> Wall-clock time of the analysis (s).
      real(dp) :: seconds = 0.0_dp
   end type stripes_result

   !> One building's demands.
   type :: demand_set
      real(dp), allocatable :: pid(:, :, :), pfa(:, :, :)
   end type demand_set

end module pound_stripes_result
