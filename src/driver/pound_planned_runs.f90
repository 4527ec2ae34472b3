!> The integration runs a deck plans, for the progress line (`pound_progress`): every
!> uncoupled and coupled run, a sweep's run without contact and its gaps, a single motion's
!> independent joints' own gaps, a suite's motions and the refinements of its threshold gaps
!> (at their most: `progress_skip` takes back what they do not run), the joint studies' runs.
module pound_planned_runs
   use pound_config, only: deck_type
   use pound_sweep_joints, only: deck_joints
   use pound_case_studies, only: has_parameter_sweep, has_law_study
   use pound_suite_refine, only: planned_refinement_runs
   implicit none
   private

   public :: planned_runs

contains

   !> The runs `deck` plans; `suite`: it runs as a suite (several motions, a synthetic motion
   !> or `scale_to`).
   integer function planned_runs(deck, suite) result(runs)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Whether it runs as a suite.
      logical, intent(in) :: suite

      runs = 1
      if (size(deck%contacts) > 0) then
         runs = 2
         ! A sweep: its run without contact (`probe_gap`) and its gaps; with several
         ! independent joints, also each joint's gaps (`pound_sweep_joints`; a suite's in
         ! every motion, `pound_suite_joints`).
         if (deck%sweep%active) runs = runs + 1 + deck%sweep%n_gaps
         if (deck%sweep%active .and. deck_joints(deck%contacts) > 1) &
            runs = runs + deck_joints(deck%contacts)*deck%sweep%n_gaps
      end if
      if (suite) runs = runs*size(deck%motions)
      ! A suite's refinements of its threshold gaps.
      if (suite .and. size(deck%contacts) > 0) runs = runs + planned_refinement_runs(deck%sweep, size(deck%motions))
      ! The studies of the joint (single motion only): one run per value or variant.
      if (has_parameter_sweep(deck)) runs = runs + size(deck%sweep%values)
      if (has_law_study(deck)) runs = runs + size(deck%variants) + 1
   end function planned_runs

end module pound_planned_runs
