!> Collapse of a building with bilinear storeys (issue 25): a building one of whose storeys
!> passed `&analysis collapse_drift` stops being integrated at the end of that step, and the
!> other buildings of the analysis go on to t_end. The collapsed building is frozen: its
!> integrator is no longer predicted or committed (its state stays that of the collapse, its
!> energies constant in the balance), its storeys take no part in the steps, its output
!> samples hold the last one taken, and its joints open (marked fractured: the force they
!> carried is released in the next step, as for a fracturing joint law, and the work of that
!> release on the buildings is booked in the joints' energy, pound_joint_state). Its step
!> increment du is kept at zero, so that the joints read its displacements (`predicted`
!> = u) and not a stale increment.
module pound_storey_collapse
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_integrator, only: integrator
   use pound_contact, only: contact_system, state_fractured
   use pound_response, only: response_record, history_sink, response_flush
   use pound_storey_yield, only: storey_yield_set
   implicit none
   private

   public :: yield_freeze, yield_frozen_step, yield_hold

contains

   !> After a step in which some building collapsed (`yield_sample`): freeze every building
   !> that collapsed and is not frozen yet (its increment du set to zero) and open its joints.
   !> `all_frozen` on return: every building is frozen (the analysis can stop).
   subroutine yield_freeze(ys, st, cs, t, frozen, all_frozen)
      !> The buildings' storeys.
      type(storey_yield_set), intent(inout) :: ys(:)
      !> The buildings' integrators (at the end of the step).
      class(integrator), intent(inout), target :: st(:)
      !> The contact system (m = 0: none).
      type(contact_system), intent(inout) :: cs
      !> Time (s).
      real(dp), intent(in) :: t
      !> Per building: frozen.
      logical, intent(inout) :: frozen(:)
      !> Every building is frozen.
      logical, intent(out) :: all_frozen
      integer :: ib, k

      do ib = 1, size(ys)
         if (ys(ib)%collapse_storey == 0 .or. ys(ib)%frozen) cycle
         ys(ib)%frozen = .true.
         frozen(ib) = .true.
         call st(ib)%hold()
         ys(ib)%na = 0
         ys(ib)%loaded = .false.
         ys(ib)%dpl = 0.0_dp
         ys(ib)%xdp = 0.0_dp
         do k = 1, cs%m
            if (all(cs%pair(k)%building /= ib)) cycle
            if (cs%joint(k)%fractured) cycle
            cs%joint(k)%fractured = .true.
            cs%joint(k)%fracture_time = t
            cs%joint(k)%state = state_fractured
         end do
      end do
      all_frozen = all(frozen)
   end subroutine yield_freeze

   !> The step of a frozen building in place of its commit and sample: its (constant) energies
   !> into the uncoupled balance (`w_in`, `e_out`), on an output step a copy of its last
   !> history sample (peaks unchanged), and its increment du back to zero (the step's joint
   !> forces, released, were added to it).
   subroutine yield_frozen_step(st, rec, output, w_in, e_out)
      !> The building's integrator (not advanced).
      class(integrator), intent(inout), target :: st
      !> The building's response record.
      type(response_record), intent(inout) :: rec
      !> An output step.
      logical, intent(in) :: output
      !> The integrators' sums of input work and of kinetic + strain + damping (+ numerical) energy.
      real(dp), intent(inout) :: w_in, e_out
      real(dp) :: w, ek, es, ed, en
      integer :: last

      call st%hold()
      w = 0.0_dp
      ek = 0.0_dp
      es = 0.0_dp
      ed = 0.0_dp
      en = 0.0_dp
      call st%add_energies(w, ek, es, ed, en)
      w_in = w_in + w
      e_out = e_out + (((ek + es) + ed) + en)
      if (.not. output) return
      ! The last sample taken: in the block, or the block's last column after a flush.
      last = rec%n_out
      if (last == 0) last = rec%capacity
      rec%n_out = rec%n_out + 1
      call hold_column(rec, last, rec%n_out)
   end subroutine yield_frozen_step

   !> After a collapse: the output samples not reached hold the last one taken (energies;
   !> the histories held in memory, or streamed to `sink` block by block); `k` samples were
   !> taken of `size(energy, 2)`.
   subroutine yield_hold(rec, energy, k, coupled, error, sink)
      !> The buildings' response records.
      type(response_record), intent(inout) :: rec(:)
      !> The energy history (n_energy, n_out).
      real(dp), intent(inout) :: energy(:, :)
      !> Output samples taken.
      integer, intent(in) :: k
      !> The coupled analysis (for the sink).
      logical, intent(in) :: coupled
      !> Error state (a failed write to the sink).
      type(error_type), allocatable, intent(out) :: error
      !> Where streamed histories go.
      class(history_sink), intent(inout), optional :: sink
      integer :: ib, i, last

      do i = k + 1, size(energy, 2)
         energy(:, i) = energy(:, k)
      end do
      do ib = 1, size(rec)
         associate (r => rec(ib))
            ! The last sample taken: in the block, or the block's last column after a flush.
            last = r%n_out
            if (last == 0) last = r%capacity
            do i = r%first + r%n_out, size(energy, 2)
               call hold_column(r, last, r%n_out + 1)
               r%n_out = r%n_out + 1
               if (r%streamed .and. present(sink)) then
                  call response_flush(r, sink, coupled, ib, .true., error)
                  if (allocated(error)) return
               end if
            end do
         end associate
      end do
   end subroutine yield_hold

   !> Column `from` of every stored history into column `to` (no copy when the same).
   pure subroutine hold_column(r, from, to)
      type(response_record), intent(inout) :: r
      integer, intent(in) :: from, to

      if (from == to) return
      if (allocated(r%u)) r%u(:, to) = r%u(:, from)
      if (allocated(r%v)) r%v(:, to) = r%v(:, from)
      if (allocated(r%a_abs)) r%a_abs(:, to) = r%a_abs(:, from)
      if (allocated(r%drift)) r%drift(:, to) = r%drift(:, from)
      if (allocated(r%shear)) r%shear(:, to) = r%shear(:, from)
      if (allocated(r%u_nodes)) r%u_nodes(:, to) = r%u_nodes(:, from)
   end subroutine hold_column

end module pound_storey_collapse
