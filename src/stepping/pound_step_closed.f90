!> Steps with elastic joints closed (`stepping = 'impact'` with `free_steps = 'exact'`): a
!> step that starts with joints carrying force, all elastic and staying closed along it, is
!> taken exactly in the buildings' condensed modes (`closed_step`, pound_closed_steps; the
!> integrators take its end through `integrator%put_state`) as one pass in which the common
!> pass commits only the joints; otherwise (and in a run with a ground along y, which the
!> closed steps' modes do not take) the step is an impact step (`impact_policy`).
module pound_step_closed
   use pound_kinds, only: dp
   use pound_structure, only: structure_model
   use pound_contact, only: contact_system
   use pound_closed_steps, only: closed_stepper, closed_init, closed_step
   use pound_step_policy, only: step_state, free_prediction
   use pound_step_impact, only: impact_policy, impact_decide
   implicit none
   private

   public :: closed_policy, closed_setup

   !> Impact substeps, and closed steps where elastic joints stay closed.
   type, extends(impact_policy) :: closed_policy
      !> The condensed modes and the sets of closed joints met.
      type(closed_stepper) :: closed
   contains
      procedure :: begin => closed_begin
   end type closed_policy

contains

   !> Set up the closed steps (after `impact_setup`) for the contact system `cs` at dt.
   subroutine closed_setup(pol, models, cs, dt)
      !> The policy.
      class(closed_policy), intent(inout) :: pol
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The contact system (its gaps those of the run).
      type(contact_system), intent(in) :: cs
      !> Time step (s).
      real(dp), intent(in) :: dt

      call closed_init(pol%closed, models, cs, dt, pol%m)
   end subroutine closed_setup

   !> `begin`: the free prediction; a closed step when joints carry force at the start and it
   !> is valid; else substeps where a joint can act.
   subroutine closed_begin(pol, s)
      !> The policy.
      class(closed_policy), intent(inout) :: pol
      !> The step (`passes`, `closed` set; after a closed step the integrators at its end).
      type(step_state), intent(inout) :: s
      logical :: loaded

      call free_prediction(pol, s, loaded)
      ! The closed steps' modes take the ground along x only: with a ground along y the step is
      ! an impact step.
      if (loaded .and. .not. associated(s%ag_y)) &
         call closed_step(pol%closed, s%st, s%models, s%cs, s%ag_old, s%ag_new, s%step, s%closed, s%rec, s%t - s%dt)
      if (s%closed) then
         pol%n%closed = pol%n%closed + 1
         return
      end if
      call impact_decide(pol, s, loaded)
   end subroutine closed_begin

end module pound_step_closed
