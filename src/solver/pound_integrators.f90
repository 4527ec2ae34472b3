!> The integrator an analysis plan names (`&analysis integrator`), allocated for every
!> building: the one place that knows the extension types of `integrator`.
module pound_integrators
   use pound_analysis_plan, only: analysis_plan
   use pound_integrator, only: integrator
   use pound_newmark, only: newmark_state
   use pound_hht, only: hht_new
   implicit none
   private

   public :: integrators_for

contains

   !> Allocate `n` integrators of the kind the plan names (not yet initialised: each
   !> building's `init`): Newmark average acceleration, also for HHT-alpha with alpha = 0 (the
   !> same method: the same code and numbers); HHT-alpha (`pound_hht`) otherwise.
   subroutine integrators_for(plan, n, st)
      !> The analysis plan.
      type(analysis_plan), intent(in) :: plan
      !> Number of buildings.
      integer, intent(in) :: n
      !> The integrators (allocated).
      class(integrator), allocatable, intent(out) :: st(:)

      if (plan%average_acceleration()) then
         allocate (newmark_state :: st(n))
      else
         allocate (st(n), source=hht_new(plan%hht_alpha))
      end if
   end subroutine integrators_for

end module pound_integrators
