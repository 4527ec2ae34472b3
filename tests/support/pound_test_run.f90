!> Test helper: run a (possibly modified) deck through the whole analysis, as the program does.
module pound_test_run
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_config, only: deck_type
   use pound_ground_motion, only: ground_motion_t, pulse_motion, record_motion, sample_ground
   use pound_shear_building, only: shear_building, build_shear_building
   use pound_analysis, only: analysis_result, run_uncoupled, run_coupled
   use pound_contact, only: contact_system, contact_pair, pairs_from_config
   implicit none
   private

   public :: run_deck

contains

   !> Ground motion, models, pairs, and the coupled (and, if `unc` is present, uncoupled) runs.
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
      type(shear_building), allocatable, intent(out), optional :: models(:)
      type(ground_motion_t) :: gm
      type(shear_building), allocatable :: b(:)
      type(contact_pair), allocatable :: pairs(:)
      character(len=64), allocatable :: names(:)
      real(dp), allocatable :: ag(:)
      integer :: n_steps, ib

      if (deck%ground%kind == 'pulse') then
         call pulse_motion(gm, deck%ground%x0, deck%ground%a, deck%ground%b)
      else
         call record_motion(gm, deck%ground%file, deck%ground%format, deck%ground%scale, error)
         if (allocated(error)) return
      end if
      n_steps = nint(deck%analysis%t_end/deck%analysis%dt)
      allocate (ag(0:n_steps), b(size(deck%buildings)), names(size(deck%buildings)))
      call sample_ground(gm, deck%analysis%dt, n_steps, ag)
      do ib = 1, size(b)
         call build_shear_building(deck%buildings(ib), b(ib), error)
         if (allocated(error)) return
         names(ib) = b(ib)%name
      end do
      if (present(unc)) then
         call run_uncoupled(deck%analysis, b, ag, unc, error)
         if (allocated(error)) return
      end if
      pairs = pairs_from_config(deck%contacts, names, error)
      if (allocated(error)) return
      call run_coupled(deck%analysis, b, ag, pairs, cpl, cs, error)
      if (present(models)) call move_alloc(b, models)
   end subroutine run_deck

end module pound_test_run
