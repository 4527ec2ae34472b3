!> The uncoupled runs of several ground motions on the same buildings at once: passes of
!> `batch_lanes` motions, each pass one run of the time loop (`run_lanes` of `pound_analysis`)
!> whose integrators advance the motions together (the integrator's lanes: every building's
!> Khat factored once, the motions vectorised, Newmark's submodule pound_newmark_batch).
!>
!> Each motion's result equals `run_uncoupled`'s for that motion alone, bit for bit: the lanes
!> do each motion's operations in the same order, the peaks are taken at every step as
!> `response_sample` takes them, and outputs, energy audit and finiteness test are the loop's
!> own, lane by lane. Only models on the fused tridiagonal path (shear buildings) qualify
!> (`batch_eligible`); the caller runs the others one motion at a time.
!>
!> A motion that cannot be run here (ground samples that are not finite, a state that stops
!> being finite) is reported in `ok` and left to `run_uncoupled`, whose message names the cause.
module pound_analysis_batch
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_analysis_plan, only: analysis_plan, free_newmark
   use pound_structure, only: structure_model, structure_yields
   use pound_ground_motion, only: check_ground_samples
   use pound_integrator, only: batch_lanes => max_lanes
   use pound_analysis, only: analysis_result, start_result, run_lanes
   implicit none
   private

   public :: batch_eligible, run_uncoupled_batch, batch_lanes

contains

   !> Whether the buildings can be run by `run_uncoupled_batch`: every model takes the fused
   !> tridiagonal path (half-bandwidth 1, every DOF moved by the ground), is a stick (response
   !> points DOFs 1..n, chain storey rows) and has two storeys or more (the one-storey kernel of
   !> `pound_newmark_step` is straight-line code that the compiler fuses differently), and the
   !> steps are Newmark's (`free_steps = 'newmark'`: the batch has no exact steps; the integrator
   !> is average acceleration, `analysis_plan%average_acceleration`); no building has bilinear storeys
   !> or plastic hinges.
   pure logical function batch_eligible(cfg, models)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      integer :: ib

      batch_eligible = size(models) > 0 .and. cfg%free_steps == free_newmark .and. cfg%average_acceleration()
      do ib = 1, size(models)
         if (models(ib)%kd /= 1 .or. .not. models(ib)%stick .or. models(ib)%n < 2) batch_eligible = .false.
         ! Bilinear storeys and plastic hinges (pound_storey_yield) are stepped by `integrate` only.
         if (structure_yields(models(ib))) batch_eligible = .false.
         if (batch_eligible) batch_eligible = models(ib)%uniform_ground
      end do
   end function batch_eligible

   !> The uncoupled runs of the motions `ag(:, m)` (m = 1..size(ag, 2)), `batch_lanes` at a time.
   subroutine run_uncoupled_batch(cfg, models, ag, res, ok)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings (`batch_eligible`).
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration of each motion at t_n = n dt, n = 0..n_steps (m/s^2), (0:n_steps, n_motions).
      real(dp), intent(in), target, contiguous :: ag(0:, :)
      !> The result of each motion (n_motions), as `run_uncoupled` gives it where `ok`.
      type(analysis_result), intent(out), target :: res(:)
      !> Whether the motion ran; otherwise its result is not set (run it with `run_uncoupled`).
      logical, intent(out) :: ok(:)
      type(error_type), allocatable :: error
      integer :: m, m1, m2

      ok = .true.
      do m = 1, size(ag, 2)
         call check_ground_samples(ag(:, m), cfg%dt, error)
         if (.not. allocated(error)) call start_result(res(m), cfg, size(ag, 1) - 1, size(models), error)
         if (allocated(error)) ok(m) = .false.
      end do
      do m1 = 1, size(ag, 2), batch_lanes
         m2 = min(size(ag, 2), m1 + batch_lanes - 1)
         call run_lanes(cfg, models, ag(:, m1:m2), res(m1:m2), ok(m1:m2))
      end do
   end subroutine run_uncoupled_batch

end module pound_analysis_batch
