!> The integrator an analysis plan names (`&analysis integrator`), allocated for every
!> building: the one place that knows the extension types of `integrator`.
module pound_integrators
   use pound_analysis_plan, only: analysis_plan
   use pound_integrator, only: integrator
   use pound_newmark, only: newmark_state
   implicit none
   private

   public :: integrators_for

contains

   !> Allocate `n` integrators of the kind the plan names (not yet initialised: each
   !> building's `init`).
   subroutine integrators_for(plan, n, st)
      !> The analysis plan.
      type(analysis_plan), intent(in) :: plan
      !> Number of buildings.
      integer, intent(in) :: n
      !> The integrators (allocated).
      class(integrator), allocatable, intent(out) :: st(:)

      associate (unused => plan%dt)
      end associate
      allocate (newmark_state :: st(n))
   end subroutine integrators_for

end module pound_integrators
