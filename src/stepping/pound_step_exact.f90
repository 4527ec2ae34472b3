!> Exact free steps (`free_steps = 'exact'`, uniform stepping): a step in which no joint can
!> act is each building's exact step under the ground motion linear over the step
!> (`integrator%predict_exact`, pound_newmark_exact); a step in which a joint carries force at
!> the start or could close (`contact_may_act`: the Hermite path of its closing displacement
!> reaches the gap) is the integrator's method at dt, predicted again (`predict_again`, with
!> the load rows of a ground along y, `ground_y_predict`), and counted (`step_counts%method`). With yielding buildings every step is the method's.
module pound_step_exact
   use pound_contact, only: contact_may_act
   use pound_step_policy, only: step_policy, step_state, free_prediction, predict_again, ground_y_predict
   implicit none
   private

   public :: exact_policy

   !> Exact free steps (the caller sets `exact_free`); the method's where a joint can act.
   type, extends(step_policy) :: exact_policy
   contains
      procedure :: begin => exact_begin
   end type exact_policy

contains

   !> `begin`: the exact prediction, dropped for the method's where a joint can act.
   subroutine exact_begin(pol, s)
      !> The policy.
      class(exact_policy), intent(inout) :: pol
      !> The step (one pass).
      type(step_state), intent(inout) :: s
      logical :: loaded

      call free_prediction(pol, s, loaded)
      if (.not. (pol%n%exact .and. pol%coupled)) return
      if (.not. loaded) then
         if (.not. contact_may_act(s%cs, s%st)) return
      end if
      pol%n%method = pol%n%method + 1
      call predict_again(s%st, s%models, s%ag_new - s%ag_old)
      s%exact_pred = .false.
      if (associated(s%ag_y)) call ground_y_predict(s)
   end subroutine exact_begin

end module pound_step_exact
