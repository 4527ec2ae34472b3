!> The uncoupled runs of several ground motions on the same buildings at once: every building's
!> Khat is factored once and its motions are advanced together by `pound_newmark_batch`
!> (`batch_lanes` motions a pass, vectorised across the motions).
!>
!> Each motion's result equals `run_uncoupled`'s for that motion alone, bit for bit: the kernel
!> does each motion's operations in the same order, the peaks are taken at every step as
!> `response_sample` takes them, and at the output steps each motion's state is copied out and
!> sampled (`response_store`) and its energies summed as `integrate` does (the audit of every
!> step likewise). Only models on the fused tridiagonal path (shear buildings) qualify
!> (`batch_eligible`); the caller runs the others one motion at a time.
!>
!> A motion that cannot be run here (ground samples that are not finite, a state that stops
!> being finite) is reported in `ok` and left to `run_uncoupled`, whose message names the cause.
module pound_analysis_batch
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_analysis_plan, only: analysis_plan, free_newmark
   use pound_structure, only: structure_model, structure_strain_energy
   use pound_ground_motion, only: check_ground_samples
   use pound_progress, only: progress_steps, progress_run_done, progress_stride
   use pound_newmark_batch, only: batch_lanes, newmark_batch, batch_start, batch_step, batch_lane_state, &
                                  batch_reset_lane
   use pound_response, only: response_init, response_sample, response_store, response_finish
   use pound_analysis, only: analysis_result, start_result, audit_error, audit_warning_limit, add_warning, &
                             uncoupled_audit_warning, n_energy, e_input, e_kinetic, e_strain, e_damping
   implicit none
   private

   public :: batch_eligible, run_uncoupled_batch, batch_lanes

   !> Running peaks of one building for the lanes of a batch, (batch_lanes, 4, n).
   type :: lane_peaks
      real(dp), allocatable :: peak(:, :, :), time(:, :, :)
   end type lane_peaks

contains

   !> Whether the buildings can be run by `run_uncoupled_batch`: every model takes the fused
   !> tridiagonal path (half-bandwidth 1, every DOF moved by the ground), is a stick (response
   !> points DOFs 1..n, chain storey rows) and has two storeys or more (the one-storey kernel of
   !> `pound_newmark_step` is straight-line code that the compiler fuses differently), and the
   !> steps are Newmark's (`free_steps = 'newmark'`: the batch has no exact steps; the integrator
   !> is average acceleration, `analysis_plan%average_acceleration`); no building has bilinear storeys.
   pure logical function batch_eligible(cfg, models)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      integer :: ib

      batch_eligible = size(models) > 0 .and. cfg%free_steps == free_newmark .and. cfg%average_acceleration()
      do ib = 1, size(models)
         if (models(ib)%kd /= 1 .or. .not. models(ib)%stick .or. models(ib)%n < 2) batch_eligible = .false.
         ! Bilinear storeys (pound_storey_yield) are stepped by `integrate` only.
         if (allocated(models(ib)%yield_shear)) batch_eligible = .false.
         if (batch_eligible) batch_eligible = all(models(ib)%ground == 1.0_dp)
      end do
   end function batch_eligible

   !> The uncoupled runs of the motions `ag(:, m)` (m = 1..size(ag, 2)), `batch_lanes` at a time.
   subroutine run_uncoupled_batch(cfg, models, ag, res, ok)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings (`batch_eligible`).
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration of each motion at t_n = n dt, n = 0..n_steps (m/s^2), (0:n_steps, n_motions).
      real(dp), intent(in) :: ag(0:, :)
      !> The result of each motion (n_motions), as `run_uncoupled` gives it where `ok`.
      type(analysis_result), intent(out) :: res(:)
      !> Whether the motion ran; otherwise its result is not set (run it with `run_uncoupled`).
      logical, intent(out) :: ok(:)
      type(error_type), allocatable :: error
      integer :: m, m1

      ok = .true.
      do m = 1, size(ag, 2)
         call check_ground_samples(ag(:, m), cfg%dt, error)
         if (.not. allocated(error)) call start_result(res(m), cfg, size(ag, 1) - 1, size(models), error)
         if (allocated(error)) ok(m) = .false.
      end do
      do m1 = 1, size(ag, 2), batch_lanes
         call run_lanes(cfg, models, ag, m1, min(size(ag, 2), m1 + batch_lanes - 1), res, ok)
      end do
   end subroutine run_uncoupled_batch

   !> Motions m1..m2 (at most `batch_lanes`) in one batch.
   subroutine run_lanes(cfg, models, ag, m1, m2, res, ok)
      !> The analysis plan (`&analysis`).
      type(analysis_plan), intent(in) :: cfg
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration of every motion (0:n_steps, n_motions).
      real(dp), intent(in) :: ag(0:, :)
      !> First and last motion of the batch.
      integer, intent(in) :: m1, m2
      !> Results of every motion (those of m1..m2 completed), set up by `start_result`.
      type(analysis_result), intent(inout) :: res(:)
      !> Whether each motion can run / ran (m1..m2 updated).
      logical, intent(inout) :: ok(:)
      type(newmark_batch), allocatable :: bt(:)
      type(lane_peaks), allocatable :: pk(:)
      type(error_type), allocatable :: error
      real(dp), allocatable :: wu(:), wv(:), wa(:)
      real(dp) :: ag_old(batch_lanes), ag_new(batch_lanes), win(batch_lanes), eout(batch_lanes)
      real(dp) :: resid(batch_lanes), scale(batch_lanes), t, sample(n_energy), seconds
      logical :: live(batch_lanes), out
      integer(int64) :: c0, c1, rate
      integer :: nb, ib, l, n_steps, step, k, n, nmax

      nb = size(models)
      n_steps = size(ag, 1) - 1
      live = .false.
      live(1:m2 - m1 + 1) = ok(m1:m2)
      if (.not. any(live)) return
      call lane_ground(0, ag_new)
      allocate (bt(nb), pk(nb))
      nmax = 0
      do ib = 1, nb
         nmax = max(nmax, models(ib)%n)
      end do
      allocate (wu(nmax), wv(nmax), wa(nmax))
      do ib = 1, nb
         n = models(ib)%n
         call batch_start(bt(ib), models(ib), cfg%dt, ag_new, error)
         if (allocated(error)) then
            ok(m1:m2) = .false.
            return
         end if
         allocate (pk(ib)%peak(batch_lanes, 4, n), pk(ib)%time(batch_lanes, 4, n), source=0.0_dp)
         do l = 1, batch_lanes
            if (.not. live(l)) cycle
            associate (rec => res(m1 + l - 1)%building(ib))
               call response_init(rec, models(ib), cfg%store, res(m1 + l - 1)%n_out, error, &
                                  nodes=cfg%node_histories .and. allocated(models(ib)%dof_node))
               if (allocated(error)) then
                  call drop(l)
                  cycle
               end if
               call lane_vectors(ib, l)
               call response_sample(rec, models(ib), wu(1:n), wv(1:n), wa(1:n), ag_new(l), 0.0_dp, .true.)
               pk(ib)%peak(l, :, :) = transpose(rec%peak(:, 1:4))
               pk(ib)%time(l, :, :) = transpose(rec%peak_time(:, 1:4))
            end associate
         end do
      end do
      k = 1
      resid = 0.0_dp
      scale = 0.0_dp
      call system_clock(c0, rate)
      do step = 1, n_steps
         if (mod(step, progress_stride) == 0) call progress_steps(step, n_steps)
         t = real(step, dp)*cfg%dt
         ag_old = ag_new
         call lane_ground(step, ag_new)
         do ib = 1, nb
            call batch_step(bt(ib), models(ib), ag_old, ag_new, t, pk(ib)%peak, pk(ib)%time)
         end do
         out = mod(step, cfg%output_every) == 0
         win = 0.0_dp
         eout = 0.0_dp
         if (out) then
            k = k + 1
            do l = 1, batch_lanes
               if (.not. live(l)) cycle
               sample = 0.0_dp
               do ib = 1, nb
                  n = models(ib)%n
                  call lane_vectors(ib, l)
                  call response_store(res(m1 + l - 1)%building(ib), models(ib), wu(1:n), wv(1:n), wa(1:n), &
                                      ag_new(l))
                  sample(e_input) = sample(e_input) + bt(ib)%input_work(l)
                  sample(e_kinetic) = sample(e_kinetic) + 0.5_dp*sum(models(ib)%mass*wv(1:n)**2)
                  sample(e_strain) = sample(e_strain) + structure_strain_energy(models(ib), wu(1:n))
                  sample(e_damping) = sample(e_damping) + bt(ib)%damping_energy(l)
               end do
               res(m1 + l - 1)%energy(:, k) = sample
               win(l) = sample(e_input)
               eout(l) = sum(sample(e_kinetic:n_energy))
            end do
         else
            do ib = 1, nb
               win = win + bt(ib)%input_work
               eout = eout + ((bt(ib)%kinetic + bt(ib)%strain) + bt(ib)%damping_energy)
            end do
         end if
         do l = 1, batch_lanes
            if (.not. live(l)) cycle
            if (.not. abs(win(l) + eout(l)) <= huge(1.0_dp)) call drop(l)
         end do
         resid = max(resid, abs(win - eout))
         scale = max(scale, abs(win), eout)
      end do
      call system_clock(c1)
      seconds = real(c1 - c0, dp)/real(rate, dp)/real(count(live), dp)
      do l = 1, batch_lanes
         if (.not. live(l)) cycle
         associate (r => res(m1 + l - 1))
            do ib = 1, nb
               r%building(ib)%peak(:, 1:4) = transpose(pk(ib)%peak(l, :, :))
               r%building(ib)%peak_time(:, 1:4) = transpose(pk(ib)%time(l, :, :))
               call response_finish(r%building(ib), models(ib))
            end do
            r%seconds = seconds
            r%energy_error = audit_error(resid(l), scale(l))
            if (r%energy_error > audit_warning_limit) &
               call add_warning(r%warnings, uncoupled_audit_warning(r%energy_error))
         end associate
         call progress_run_done()
      end do

   contains

      !> Ground acceleration of every lane at step `step` (zero in the lanes without a motion).
      subroutine lane_ground(step, g)
         integer, intent(in) :: step
         real(dp), intent(out) :: g(batch_lanes)
         integer :: l

         g = 0.0_dp
         do l = 1, batch_lanes
            if (live(l)) g(l) = ag(step, m1 + l - 1)
         end do
      end subroutine lane_ground

      !> Lane l's state of building ib into wu, wv, wa.
      subroutine lane_vectors(ib, l)
         integer, intent(in) :: ib, l

         call batch_lane_state(bt(ib), l, wu(1:models(ib)%n), wv(1:models(ib)%n), wa(1:models(ib)%n))
      end subroutine lane_vectors

      !> Lane l cannot be completed here: its motion is left to `run_uncoupled`, the lane is
      !> brought to rest and carries no motion from now on.
      subroutine drop(l)
         integer, intent(in) :: l
         integer :: i

         live(l) = .false.
         ok(m1 + l - 1) = .false.
         ag_new(l) = 0.0_dp
         win(l) = 0.0_dp
         eout(l) = 0.0_dp
         do i = 1, nb
            call batch_reset_lane(bt(i), l)
         end do
      end subroutine drop
   end subroutine run_lanes

end module pound_analysis_batch
