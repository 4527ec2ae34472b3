!> The deck's studies of the joint for `run_case` (issue 26): the configurations of a
!> stiffness or restitution sweep (`&sweep parameter`: every `&contact` group with each value)
!> and of a law study (`&contact variant`: the base, then each variant), run by
!> `run_joint_study` against the case's uncoupled result.
module pound_case_studies
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_config, only: deck_type, contact_config
   use pound_analysis_plan, only: analysis_plan
   use pound_structure, only: structure_model, structure_names
   use pound_ground_motion, only: ground_motion_t
   use pound_analysis, only: analysis_result
   use pound_joint_study, only: contact_set, joint_study_result, run_joint_study
   implicit none
   private

   public :: has_parameter_sweep, has_law_study, run_deck_study, parameter_sets

contains

   !> Whether the deck sweeps the stiffness or the restitution.
   pure logical function has_parameter_sweep(deck)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck

      has_parameter_sweep = .false.
      if (size(deck%contacts) == 0 .or. .not. allocated(deck%sweep%values)) return
      has_parameter_sweep = deck%sweep%parameter /= 'gap'
   end function has_parameter_sweep

   !> Whether the deck runs a law study (`&contact variant`).
   pure logical function has_law_study(deck)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck

      has_law_study = .false.
      if (allocated(deck%variants)) has_law_study = size(deck%variants) > 0 .and. size(deck%contacts) > 0
   end function has_law_study

   !> The configurations of the stiffness or restitution sweep: the deck's groups with the swept
   !> variable set to each value (as a deck that gives it; a restitution takes the place of a
   !> dashpot of 0).
   pure subroutine parameter_sets(deck, sets)
      !> A validated configuration with a stiffness or restitution sweep.
      type(deck_type), intent(in) :: deck
      !> One set per value.
      type(contact_set), allocatable, intent(out) :: sets(:)
      integer :: i

      allocate (sets(size(deck%sweep%values)))
      do i = 1, size(sets)
         sets(i)%contacts = deck%contacts
         if (deck%sweep%parameter == 'stiffness') then
            sets(i)%contacts(:)%stiffness = deck%sweep%values(i)
         else
            sets(i)%contacts(:)%restitution = deck%sweep%values(i)
         end if
      end do
   end subroutine parameter_sets

   !> The deck's stiffness or restitution sweep (`law` false) or its law study (`law` true:
   !> the base, the groups without a variant, then each variant).
   subroutine run_deck_study(law, deck, plan, models, ag, unc, res, error, ground)
      !> Which study: the law study, or the stiffness or restitution sweep.
      logical, intent(in) :: law
      !> A validated configuration that asks for it.
      type(deck_type), intent(in) :: deck
      !> The analysis plan.
      type(analysis_plan), intent(in) :: plan
      !> The buildings.
      type(structure_model), intent(in), target :: models(:)
      !> Ground acceleration at t_n = n dt (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> Uncoupled result.
      type(analysis_result), intent(in), target :: unc
      !> The study's result.
      type(joint_study_result), intent(out) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples.
      type(ground_motion_t), intent(in), optional :: ground
      type(contact_set), allocatable :: sets(:)
      character(len=32), allocatable :: labels(:)
      character(len=64), allocatable :: laws(:)
      real(dp), allocatable :: values(:)
      character(len=:), allocatable :: kind
      real(dp) :: target
      integer :: i

      if (law) then
         kind = 'law'
         allocate (sets(size(deck%variants) + 1), labels(size(deck%variants) + 1), laws(size(deck%variants) + 1))
         sets(1)%contacts = deck%contacts
         labels(1) = 'base'
         do i = 1, size(deck%variants)
            sets(i + 1)%contacts = deck%variants(i)%contacts
            labels(i + 1) = deck%variants(i)%name
         end do
         values = spread(0.0_dp, 1, size(labels))
         ! The target of the deck's `&sweep` (a gap sweep's too) judges the configurations.
         target = -1.0_dp
         if (deck%sweep%active .or. deck%sweep%parameter /= 'gap') target = deck%sweep%target
      else
         kind = trim(deck%sweep%parameter)
         call parameter_sets(deck, sets)
         allocate (labels(size(sets)), laws(size(sets)))
         do i = 1, size(labels)
            if (kind == 'stiffness') then
               write (labels(i), '(es12.4)') deck%sweep%values(i)
            else
               write (labels(i), '(f12.4)') deck%sweep%values(i)
            end if
            labels(i) = adjustl(labels(i))
         end do
         values = deck%sweep%values
         target = deck%sweep%target
      end if
      do i = 1, size(sets)
         laws(i) = group_laws(sets(i)%contacts)
      end do
      call run_joint_study(kind, plan, models, structure_names(models), ag, sets, labels, values, target, &
                           deck%sweep%target_quantities, unc, res, error, ground)
      if (.not. allocated(error)) res%law = laws
   end subroutine run_deck_study

   !> The laws of a configuration's groups, blank-separated.
   pure function group_laws(c) result(s)
      !> The groups.
      type(contact_config), intent(in) :: c(:)
      character(len=:), allocatable :: s
      integer :: i

      s = c(1)%law
      do i = 2, size(c)
         s = s//' '//c(i)%law
      end do
   end function group_laws

end module pound_case_studies
