!> What one case computes (`case_result`), as the writers read it: the models and their
!> building kinds, the uncoupled and coupled results, the contact system, the influence
!> coefficients, the sweep and the joint studies, the separation rules and the warnings.
!> Filled by the run driver (`run_case`, pound_run_case); read by src/output/.
module pound_case_result
   use pound_kinds, only: dp
   use pound_building, only: building_model
   use pound_structure, only: structure_model
   use pound_analysis, only: analysis_result
   use pound_contact, only: contact_system
   use pound_influence, only: building_influence
   use pound_sweep, only: sweep_result
   use pound_sweep_joints, only: joint_sweep
   use pound_separation, only: separation_t
   use pound_joint_study, only: joint_study_result
   implicit none
   private

   public :: case_result

   !> Everything a case computes, as the writers need it.
   type :: case_result
      !> The buildings' structural models, in configuration order.
      type(structure_model), allocatable :: models(:)
      !> The buildings' per-kind data for the writers (shear storey table, frame), same order.
      type(building_model), allocatable :: buildings(:)
      !> One-line description of the ground motion.
      character(len=:), allocatable :: ground_text
      !> Ground acceleration at the output times (m/s^2).
      real(dp), allocatable :: ag_out(:)
      !> Whether the uncoupled, the coupled analysis and the sweep ran.
      logical :: has_uncoupled = .false., has_coupled = .false., has_sweep = .false.
      !> Uncoupled result.
      type(analysis_result) :: unc
      !> Coupled result.
      type(analysis_result) :: cpl
      !> Contact system at the end of the coupled run.
      type(contact_system) :: cs
      !> Influence coefficients per building (with the uncoupled and the coupled run).
      type(building_influence), allocatable :: influence(:)
      !> Gap study.
      type(sweep_result) :: sweep
      !> Studies of the joint (`pound_case_studies`): the stiffness or restitution sweep
      !> (`&sweep parameter`) and the law study (`&contact variant`), and whether they ran.
      type(joint_study_result) :: parameter_sweep, law_study
      logical :: has_parameter_sweep = .false., has_law_study = .false.
      !> The independent joints (`pound_sweep_joints`; allocated with the sweep) and, where
      !> there are several, each one's own sweep (its pairs swept, the others at their deck gaps).
      type(joint_sweep), allocatable :: joints(:)
      !> Separation rules per contact pair (the deck's `&contact` pairs in order), from the
      !> uncoupled peaks (`pair_separation`; allocated when both analyses ran). With a sweep, the
      !> no-contact gap is its probe's largest closing displacement of each joint and the
      !> time-history gap its safe gap when found (with several independent joints, that of the
      !> pair's joint's own sweep); without, both are n/a.
      type(separation_t), allocatable :: separation(:)
      !> Warnings of the deck (plausibility), of the models (period against the code estimate),
      !> of the uncoupled run, the coupled run and the sweep, in that order, one line each (size
      !> 0 when there are none).
      character(len=:), allocatable :: warnings(:)
      !> How many of `warnings` (the first ones) concern the input: the deck's and the models'.
      integer :: n_input_warnings = 0
   end type case_result

end module pound_case_result
