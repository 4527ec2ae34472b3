!> Test helper: run a (possibly modified) deck through the library's run driver
!> (`pound_run_case`), with the result parts the contact tests look at.
module pound_test_run
   use pound_error, only: error_type
   use pound_config, only: deck_type
   use pound_structure, only: structure_model
   use pound_analysis, only: analysis_result
   use pound_contact, only: contact_system
   use pound_run_case, only: case_options, case_result, run_case
   implicit none
   private

   public :: run_deck

contains

   !> `run_case` on `deck` without its sweep: the coupled run (and, if `unc` is present, the
   !> uncoupled one; without it, only the coupled analysis runs).
   subroutine run_deck(deck, cpl, cs, error, unc, models)
      !> A validated deck (it may have been changed after reading).
      type(deck_type), intent(in) :: deck
      !> The coupled result.
      type(analysis_result), intent(out) :: cpl
      !> The contact system at the end.
      type(contact_system), intent(out) :: cs
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The uncoupled result, if wanted.
      type(analysis_result), intent(out), optional :: unc
      !> The buildings, if wanted.
      type(structure_model), allocatable, intent(out), optional :: models(:)
      type(case_options) :: options
      type(case_result) :: res
      type(deck_type) :: no_sweep

      no_sweep = deck
      no_sweep%sweep%active = .false.
      options%coupled_only = .not. present(unc)
      call run_case(no_sweep, res, error, options)
      if (allocated(error)) return
      call take(res%cpl, cpl)
      cs = res%cs
      if (present(unc)) call take(res%unc, unc)
      if (present(models)) call move_alloc(res%models, models)
   end subroutine run_deck

   !> `to = from`, the warnings moved apart (gfortran's intrinsic assignment of a
   !> deferred-length character array component is not reliable).
   subroutine take(from, to)
      type(analysis_result), intent(inout) :: from
      type(analysis_result), intent(out) :: to
      character(len=:), allocatable :: warnings(:)

      call move_alloc(from%warnings, warnings)
      to = from
      call move_alloc(warnings, to%warnings)
   end subroutine take

end module pound_test_run
