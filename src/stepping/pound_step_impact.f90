!> Impact-aware substeps (`stepping = 'impact'`): a step in which a joint carries force at the
!> start or could close (`contact_may_act`) is taken as m passes of h = dt/m, with the ground
!> motion at the substeps' ends (`ground_accel`, and `ground_accel_y` with a ground along y,
!> whose load rows at dt/m the policy holds; the step's own samples at its end), each pass
!> the common one (`take_pass`: its LCP, commit, and the loop's sampling and audit). The
!> integrators and the contact system hold the substep's step data for those passes
!> (`swap_step_data` with the copies set up for dt/m, `coupled_prepare`). The other steps are
!> one pass of dt, predicted by the method or, with `free_steps = 'exact'`, exactly.
module pound_step_impact
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_integrator, only: integrator
   use pound_ground_motion, only: ground_motion_t, ground_accel, ground_accel_y
   use pound_contact, only: contact_system, contact_may_act
   use pound_step_policy, only: step_policy, step_state, free_prediction, take_pass, policy_start, ground_y_rows, &
                                ground_rows_of, ground_y_predict
   use pound_step_retry, only: swap_step_data
   implicit none
   private

   public :: impact_policy, impact_setup, impact_decide

   !> Impact substeps.
   type, extends(step_policy) :: impact_policy
      !> Substeps per impact step.
      integer :: m = 1
      !> Integrators and contact system holding the substep's step data.
      class(integrator), allocatable :: st(:)
      type(contact_system) :: cs
      !> The ground motion, evaluated at the substep times.
      type(ground_motion_t) :: ground
      !> The load rows of a ground component along y at dt/m (runs with one; swapped with the
      !> step's rows as the step data are).
      type(ground_y_rows), allocatable :: gy(:)
   contains
      procedure :: start => impact_start
      procedure :: begin => impact_begin
      procedure :: pass => impact_pass
   end type impact_policy

contains

   !> Set up the substeps: m of dt/m, the integrators and contact system `st`, `cs` at dt/m,
   !> the ground motion (whether free steps are exact is the caller's `exact_free`).
   subroutine impact_setup(pol, m, dt, st, cs, ground)
      !> The policy.
      class(impact_policy), intent(inout) :: pol
      !> Substeps per impact step.
      integer, intent(in) :: m
      !> Time step (s).
      real(dp), intent(in) :: dt
      !> Integrators and contact system set up for dt/m.
      class(integrator), intent(in) :: st(:)
      type(contact_system), intent(in) :: cs
      !> The ground motion.
      type(ground_motion_t), intent(in) :: ground

      pol%m = m
      pol%n%factor = m
      pol%n%h = dt/real(m, dp)
      allocate (pol%st, source=st)
      pol%cs = cs
      pol%ground = ground
      pol%track_free = .true.
   end subroutine impact_setup

   !> `start`: the run's flags; with a ground along y, its load rows at dt/m.
   subroutine impact_start(pol, s, inelastic)
      !> The policy.
      class(impact_policy), intent(inout) :: pol
      !> The step (what it acts on, at t = 0).
      type(step_state), intent(inout) :: s
      !> Some building yields.
      logical, intent(in) :: inelastic

      call policy_start(pol, s, inelastic)
      if (associated(s%ag_y)) call ground_rows_of(pol%gy, pol%st, s%models)
   end subroutine impact_start

   !> `begin`: the free prediction; substeps where a joint can act.
   subroutine impact_begin(pol, s)
      !> The policy.
      class(impact_policy), intent(inout) :: pol
      !> The step (`passes` set).
      type(step_state), intent(inout) :: s
      logical :: loaded

      call free_prediction(pol, s, loaded)
      call impact_decide(pol, s, loaded)
   end subroutine impact_begin

   !> The step as m substeps when a joint carries force at the start (`loaded`) or can act:
   !> the substeps' step data swapped in.
   subroutine impact_decide(pol, s, loaded)
      !> The policy.
      class(impact_policy), intent(inout) :: pol
      !> The step.
      type(step_state), intent(inout) :: s
      !> A joint carries force at the start (judged with exact free steps only).
      logical, intent(in) :: loaded

      if (.not. loaded) then
         if (.not. contact_may_act(s%cs, s%st)) return
      end if
      pol%n%method = pol%n%method + 1
      s%passes = pol%m
      s%exact_pred = .false.
      pol%n%substepped = pol%n%substepped + 1
      call swap_data(pol, s)
   end subroutine impact_decide

   !> `pass`: a substep (its end's time and ground, the method's prediction of every building
   !> not frozen), then the common pass; after the last substep the step data swapped back.
   subroutine impact_pass(pol, s, error)
      !> The policy.
      class(impact_policy), intent(inout) :: pol
      !> The step.
      type(step_state), intent(inout) :: s
      !> Error state.
      type(error_type), allocatable, intent(inout) :: error
      integer :: ib

      if (s%passes == 1) then
         call take_pass(pol, s, error)
         return
      end if
      s%h = pol%n%h
      if (s%pass < s%passes) then
         s%t_pass = real(s%step - 1, dp)*s%dt + real(s%pass, dp)*s%h
         s%ag_new = ground_accel(pol%ground, s%t_pass)
         if (associated(s%ag_y)) s%agy_new = ground_accel_y(pol%ground, s%t_pass)
      else
         s%t_pass = s%t
         s%ag_new = s%ag(s%step)
         if (associated(s%ag_y)) s%agy_new = s%ag_y(s%step)
      end if
      do ib = 1, size(s%st)
         if (.not. s%frozen(ib)) call s%st(ib)%predict(s%models(ib), s%ag_new - s%ag_old)
      end do
      if (associated(s%ag_y)) call ground_y_predict(s)
      pol%n%substeps = pol%n%substeps + 1
      call take_pass(pol, s, error)
      if (s%pass == s%passes) call swap_data(pol, s)
   end subroutine impact_pass

   !> Exchange the step data of the integrators and the contact system (and of the load rows of
   !> a ground along y) between the step's and the substeps'.
   subroutine swap_data(pol, s)
      class(impact_policy), intent(inout) :: pol
      type(step_state), intent(inout) :: s

      if (associated(s%ag_y)) then
         call swap_step_data(s%st, pol%st, s%cs, pol%cs, s%gy, pol%gy)
      else
         call swap_step_data(s%st, pol%st, s%cs, pol%cs)
      end if
   end subroutine swap_data

end module pound_step_impact
