!> Response of one building over an analysis: peaks at every step, histories at output steps.
!>
!> Quantities (indices match `history_names` of pound_quantities): floor displacement `u`,
!> floor velocity `v` (relative to the ground), floor absolute acceleration `a_abs`,
!> storey drift `drift` and storey shear `storey_shear`, both from the model's recovery
!> rows (a shear building: u_j - u_{j-1} and k_j drift_j). Floor quantities are taken at
!> the model's response points (`floor_dof`). Peaks are absolute maxima over all steps, not
!> only the stored ones; the drift peaks are tracked in the fused pass over the floors
!> (consecutive response points), the storey-shear peaks are the shear rows' scales times
!> the drift peaks (each shear row is its drift row scaled: see `response_finish`). Histories are held
!> as (n, n_out) so that h5py reads them as (n_out, n). On request (`nodes`) the record also holds
!> every DOF's displacement at the output steps, `u_nodes` (n_dofs, n_out): a copy of the
!> integrator's u, so its floor DOFs' rows equal the floor history `u` bit for bit.
!>
!> **Member rows.** A model with member recovery rows (`structure_model%member`, a frame's
!> column end forces) gets their absolute maxima and times at every step (`member_peak`,
!> `member_time`), whatever the rows mean; so do a model's result rows (`structure_model%result_rows`,
!> a building in plan's plane shears and floor rotations: `result_peak`, `result_time`). **Points between floors** (a frame's split column
!> nodes, contact ends of `&contact elevations`: `point_dof`, `point_dof_left`) get their
!> absolute maxima of u at every step (`point_peak`, `response_point_peak`; not refined between
!> samples). **Deformed shapes** (`snapshots`): the DOF vector
!> at the step of each storey's peak storey shear (`deformed` (n_dofs, n_storeys), after
!> `response_finish`); asked for only where n_dofs x n_storeys <= `deformed_limit`. During the
!> run a pool of n_storeys + 1 DOF vectors, preallocated (no allocation in the loop), holds
!> them: a step on which any storey's shear exceeds its peak copies u once into a free slot
!> and points those storeys at it; a slot no storey points at is free again. So a step costs
!> at most one copy of u, however many storeys peak together.
module pound_response
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_quantities, only: n_history_quantities
   use pound_structure, only: structure_model, recover_all, recover_peaks
   implicit none
   private

   public :: response_record, response_init, response_sample, response_finish, response_store
   public :: history_sink, response_flush, default_block_bytes, history_block, discard_sink
   public :: response_block_full, response_sample_rows, response_release, response_peaks_inside
   public :: q_u, q_v, q_a_abs, q_drift, q_shear, deformed_limit, response_point_peak

   !> Quantity indices.
   integer, parameter :: q_u = 1, q_v = 2, q_a_abs = 3, q_drift = 4, q_shear = 5

   !> Bytes of one block of a streamed history (per building and quantity) when the sink
   !> does not set `block`.
   integer, parameter :: default_block_bytes = 4*2**20

   !> Largest n_dofs x n_storeys for which the deformed shapes at the storey-shear peaks are
   !> kept (32 MiB per building and analysis).
   integer, parameter :: deformed_limit = 4*2**20

   !> Where streamed histories go (the program's HDF5 file; a test's arrays): analyses hand
   !> it full blocks of output samples, so that they do not depend on HDF5.
   type, abstract :: history_sink
      !> Output samples per block; 0: about `default_block_bytes` per building and quantity.
      integer :: block = 0
   contains
      procedure(sink_put), deferred :: put
   end type history_sink

   abstract interface
      !> Take output samples first .. first+k-1 of one history.
      subroutine sink_put(sink, coupled, building, quantity, first, values, error)
         import :: history_sink, dp, error_type
         !> The sink.
         class(history_sink), intent(inout) :: sink
         !> The coupled analysis (else the uncoupled one).
         logical, intent(in) :: coupled
         !> Building index (deck order) and quantity index (q_u .. q_shear).
         integer, intent(in) :: building, quantity
         !> Index of the first sample (1-based, over the whole run).
         integer, intent(in) :: first
         !> The samples (n, k).
         real(dp), intent(in), contiguous :: values(:, :)
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine sink_put
   end interface

   !> A sink that keeps nothing: an MPI rank that does not write the results runs the same
   !> analyses in the memory of one block.
   type, extends(history_sink) :: discard_sink
   contains
      procedure :: put => discard_put
   end type discard_sink

   !> Peaks and histories of one building.
   type :: response_record
      !> Number of floors.
      integer :: n = 0
      !> Which histories are stored.
      logical :: store(n_history_quantities) = .false.
      !> Output samples held (in the block), and capacity.
      integer :: n_out = 0, capacity = 0
      !> Index over the run of the first sample held (> 1 only when streamed).
      integer :: first = 1
      !> The histories are streamed to a sink block by block (only the last block is held).
      logical :: streamed = .false.
      !> Histories (n, capacity), allocated only for stored quantities.
      real(dp), allocatable :: u(:, :), v(:, :), a_abs(:, :), drift(:, :), shear(:, :)
      !> Whether every DOF's displacement is stored, and that history (n_dofs, capacity).
      logical :: nodes = .false.
      real(dp), allocatable :: u_nodes(:, :)
      !> Peak absolute value per floor/storey and quantity (n, n_history_quantities).
      real(dp), allocatable :: peak(:, :)
      !> Time of each peak (s).
      real(dp), allocatable :: peak_time(:, :)
      !> Work array (n): drift or absolute acceleration of the step being sampled.
      real(dp), allocatable :: work(:)
      !> The model's response points are DOFs 1..n and its storey rows the chain
      !> u_j - u_{j-1} (times the shear row's scale): peaks and histories are taken
      !> straight from the DOF vectors (same numbers as the general path, fewer passes).
      logical :: stick = .false.
      !> A stick's peaks: whether the last step set a new maximum (`track_peaks`).
      logical :: rising = .true.
      !> General path: the response points' u, v, a_abs and the storey rows of the step.
      real(dp), allocatable :: pu(:), pv(:), pa(:), pd(:), ps(:)
      !> Member rows (`structure_model%member`): peak absolute value and its time per row, and
      !> the rows' values of the step (work); unallocated without member rows.
      real(dp), allocatable :: member_peak(:), member_time(:), pm(:)
      !> Result rows (`structure_model%result_rows`, in its groups `structure_model%result`): peak
      !> absolute value and its time per row, and the rows' values of the step (work);
      !> unallocated without result rows.
      real(dp), allocatable :: result_peak(:), result_time(:), pr(:)
      !> Points between floors (the model's `point_dof` and `point_dof_left`, each DOF once):
      !> their DOFs and the peak |u| of each at every step (m); unallocated: none.
      integer, allocatable :: point_dofs(:)
      real(dp), allocatable :: point_peak(:)
      !> Whether the deformed shapes are kept, and (after `response_finish`) the DOF vector at
      !> the peak storey shear of each storey (n_dofs, n_storeys); its time is
      !> `peak_time(:, q_shear)`.
      logical :: snapshots = .false.
      real(dp), allocatable :: deformed(:, :)
      !> During the run: the pool of DOF vectors (n_dofs, n_storeys + 1), the slot of each
      !> storey's vector (0: none yet), the storeys pointing at each slot, and the free slots
      !> (a stack of `n_free`).
      real(dp), allocatable :: pool(:, :)
      integer, allocatable :: slot_of(:), refs(:), free(:)
      integer :: n_free = 0
      !> Peaks refined between the samples (`refine_peaks`, `free_steps = 'exact'`): the
      !> previous sample's time (< 0: none yet) and the previous and this sample's u, drift
      !> (and a frame's storey shear) with their rates at the response points and storey rows
      !> (n, 2, 3, 2: value and rate; u, drift, shear; previous, this).
      logical :: refine = .false.
      real(dp) :: t_last = -1.0_dp
      real(dp), allocatable :: last(:, :, :, :)
      !> A frame's previous DOF velocities (its rows' rates are recovered only on the steps
      !> that may refine a peak).
      real(dp), allocatable :: v_last(:)
      !> Whether the last sample's rates of the rows were recovered (`refine_peaks`: they are
      !> then the next interval's start rates, not recovered again).
      logical :: rates_last = .false.
   end type response_record

contains

   !> Prepare a record for `capacity` output samples.
   !>
   !> Fails (nothing allocated is kept) when the memory cannot be had, with the size asked
   !> for and the deck variables that set it.
   pure subroutine response_init(rec, b, store, capacity, error, nodes, snapshots, refine)
      !> The record (reset).
      type(response_record), intent(out) :: rec
      !> The structural model: its response points (floors) and storey rows.
      type(structure_model), intent(in) :: b
      !> Which quantities keep histories.
      logical, intent(in) :: store(n_history_quantities)
      !> Number of output samples.
      integer, intent(in) :: capacity
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Store every DOF's displacement as well (`u_nodes`); default no.
      logical, intent(in), optional :: nodes
      !> Keep the DOF vector at each storey's peak storey shear (`deformed`); default no.
      logical, intent(in), optional :: snapshots
      !> Refine the peaks of u, drift and storey shear between the samples (`refine_peaks`);
      !> default no.
      logical, intent(in), optional :: refine
      integer :: stat(8)
      real(dp) :: mib
      integer :: n, n_node, k

      n = size(b%floor_dof)
      rec%snapshots = .false.
      if (present(snapshots)) rec%snapshots = snapshots
      rec%stick = b%stick .and. b%member%n == 0 .and. b%result_rows%n == 0 .and. .not. rec%snapshots
      if (.not. rec%stick) then
         allocate (rec%pu(n), rec%pv(n), rec%pa(n), rec%pd(n), rec%ps(n), stat=stat(1))
         if (stat(1) /= 0) then
            call fatal_error(error, 'cannot allocate the response work arrays ('//str(5*n)//' reals)')
            return
         end if
      end if
      rec%n = n
      rec%store = store
      rec%capacity = capacity
      rec%n_out = 0
      rec%nodes = .false.
      if (present(nodes)) rec%nodes = nodes
      n_node = 0
      if (rec%nodes) n_node = b%n
      rec%first = 1
      stat = 0
      ! Histories are zeroed here, so that their memory is touched before the time loop.
      if (store(q_u)) allocate (rec%u(n, capacity), source=0.0_dp, stat=stat(1))
      if (store(q_v)) allocate (rec%v(n, capacity), source=0.0_dp, stat=stat(2))
      if (store(q_a_abs)) allocate (rec%a_abs(n, capacity), source=0.0_dp, stat=stat(3))
      if (store(q_drift)) allocate (rec%drift(n, capacity), source=0.0_dp, stat=stat(4))
      if (store(q_shear)) allocate (rec%shear(n, capacity), source=0.0_dp, stat=stat(5))
      if (rec%nodes) allocate (rec%u_nodes(n_node, capacity), source=0.0_dp, stat=stat(7))
      if (b%member%n > 0) allocate (rec%member_peak(b%member%n), rec%member_time(b%member%n), &
                                    rec%pm(b%member%n), source=0.0_dp, stat=stat(8))
      if (b%result_rows%n > 0 .and. stat(8) == 0) &
         allocate (rec%result_peak(b%result_rows%n), rec%result_time(b%result_rows%n), rec%pr(b%result_rows%n), &
                   source=0.0_dp, stat=stat(8))
      if (rec%snapshots .and. stat(8) == 0) then
         allocate (rec%pool(b%n, n + 1), source=0.0_dp, stat=stat(8))
         if (stat(8) == 0) allocate (rec%slot_of(n), rec%refs(n + 1), rec%free(n + 1), source=0, stat=stat(8))
         rec%n_free = n + 1
         if (stat(8) == 0) rec%free = [(n + 2 - k, k=1, n + 1)]
      end if
      call point_dof_list(b, rec%point_dofs)
      if (allocated(rec%point_dofs)) allocate (rec%point_peak(size(rec%point_dofs)), source=0.0_dp)
      allocate (rec%peak(n, n_history_quantities), rec%peak_time(n, n_history_quantities), rec%work(n), &
                stat=stat(6))
      if (any(stat /= 0)) then
         mib = 8.0_dp*(real(n, dp)*real(count(store), dp) + real(n_node, dp))*real(capacity, dp)/2.0_dp**20
         rec = response_record()
         call fatal_error(error, 'cannot allocate the response histories: ('//str(count(store))// &
                          ' quantities x '//str(n)//' floors + '//str(n_node)//' node DOFs) x '//str(capacity)// &
                          ' output samples = '//str(mib)//' MiB; store fewer or less often (history, '// &
                          'node_histories, output_every) or shorten the run (t_end, dt)')
         return
      end if
      rec%peak = 0.0_dp
      rec%peak_time = 0.0_dp
      rec%refine = .false.
      if (present(refine)) rec%refine = refine
      if (rec%refine) then
         allocate (rec%last(n, 2, 3, 2), source=0.0_dp, stat=stat(1))
         if (stat(1) == 0 .and. .not. rec%stick) allocate (rec%v_last(b%n), source=0.0_dp, stat=stat(1))
         rec%t_last = -1.0_dp
         rec%rates_last = .false.
         if (stat(1) /= 0) then
            call fatal_error(error, 'cannot allocate the response work arrays ('//str(12*n)//' reals)')
            return
         end if
      end if
   end subroutine response_init

   !> Take the state at time t: update peaks and, if `output`, append a history sample.
   pure subroutine response_sample(rec, b, u, v, a, ag, t, output)
      !> The record.
      type(response_record), intent(inout) :: rec
      !> The building.
      type(structure_model), intent(in) :: b
      !> Relative displacement, velocity and acceleration (`b%n` each; explicit shape, so that
      !> the time loop passes their addresses and builds no descriptors).
      real(dp), intent(in) :: u(b%n), v(b%n), a(b%n)
      !> Ground acceleration (m/s^2; the scalars by value).
      real(dp), intent(in), value :: ag
      !> Time (s).
      real(dp), intent(in), value :: t
      !> Whether this is an output step.
      logical, intent(in), value :: output

      if (rec%stick) then
         call track_peaks(rec%n, u, v, a, ag, t, rec%peak, rec%peak_time, rec%rising)
         if (output) call response_store(rec, b, u, v, a, ag)
      else
         call response_sample_rows(rec, b, u, v, a, ag, t, output)
      end if
      if (rec%refine) call refine_peaks(rec, b, u, v, t)
      if (allocated(rec%point_peak)) call track_points(size(rec%point_dofs), b%n, rec%point_dofs, u, rec%point_peak)
   end subroutine response_sample

   !> Running absolute maxima of u at the points between floors.
   pure subroutine track_points(np, nu, dof, u, peak)
      integer, intent(in) :: np, nu, dof(np)
      real(dp), intent(in) :: u(nu)
      real(dp), intent(inout) :: peak(np)
      integer :: i

      do i = 1, np
         peak(i) = max(peak(i), abs(u(dof(i))))
      end do
   end subroutine track_points

   !> The DOFs of the model's points between floors (right face, then the left face's not
   !> already listed); unallocated when it has none.
   pure subroutine point_dof_list(b, dofs)
      !> The model.
      type(structure_model), intent(in) :: b
      !> Their DOFs.
      integer, allocatable, intent(out) :: dofs(:)
      integer :: i

      if (allocated(b%point_dof)) dofs = b%point_dof
      if (allocated(b%point_dof_left)) then
         if (.not. allocated(dofs)) allocate (dofs(0))
         do i = 1, size(b%point_dof_left)
            if (all(dofs /= b%point_dof_left(i))) dofs = [dofs, b%point_dof_left(i)]
         end do
      end if
      if (allocated(dofs)) then
         if (size(dofs) == 0) deallocate (dofs)
      end if
   end subroutine point_dof_list

   !> The peak |u| (m) over the run of DOF `dof` when it is one of the record's points between
   !> floors (`point_peak`); -1 when it is not (or `dof` is 0).
   pure real(dp) function response_point_peak(rec, dof) result(peak)
      !> The record after the run.
      type(response_record), intent(in) :: rec
      !> A DOF of the model.
      integer, intent(in) :: dof
      integer :: i

      peak = -1.0_dp
      if (.not. allocated(rec%point_dofs) .or. dof < 1) return
      do i = 1, size(rec%point_dofs)
         if (rec%point_dofs(i) == dof) peak = rec%point_peak(i)
      end do
   end function response_point_peak

   !> `response_sample` of a model that is not a stick: through the response points and
   !> the recovery rows (a procedure of its own, so that a stick's step calls a small
   !> `response_sample`; public only so that the compiler does not inline it).
   pure subroutine response_sample_rows(rec, b, u, v, a, ag, t, output)
      !> The record of a model that is not a stick.
      type(response_record), intent(inout) :: rec
      !> Its building.
      type(structure_model), intent(in) :: b
      !> Ground acceleration (m/s^2) and time (s), by value.
      real(dp), intent(in), value :: ag, t
      !> Relative displacement, velocity and acceleration (`b%n` each).
      real(dp), intent(in) :: u(b%n), v(b%n), a(b%n)
      !> Whether this is an output step.
      logical, intent(in), value :: output
      integer :: k

      call recover_all(b%drift, u, rec%pd)
      call recover_all(b%shear, u, rec%ps)
      if (rec%snapshots) call take_snapshots(b%n, rec%n, u, rec%ps, rec%peak(:, q_shear), rec%pool, &
                                             rec%slot_of, rec%refs, rec%free, rec%n_free)
      if (b%member%n > 0) then
         call recover_peaks(b%member, u, t, rec%pm, rec%member_peak, rec%member_time)
      end if
      if (b%result_rows%n > 0) call recover_peaks(b%result_rows, u, t, rec%pr, rec%result_peak, rec%result_time)
      call track_general(rec%n, b%n, b%floor_dof, u, v, a, ag, rec%pd, rec%ps, t, rec%pu, rec%pv, rec%pa, &
                         rec%peak, rec%peak_time)
      if (.not. output) return
      rec%n_out = rec%n_out + 1
      k = rec%n_out
      if (rec%nodes) rec%u_nodes(:, k) = u
      if (rec%store(q_u)) rec%u(:, k) = rec%pu
      if (rec%store(q_v)) rec%v(:, k) = rec%pv
      if (rec%store(q_a_abs)) rec%a_abs(:, k) = rec%pa
      if (rec%store(q_drift)) rec%drift(:, k) = rec%pd
      if (rec%store(q_shear)) rec%shear(:, k) = rec%ps
   end subroutine response_sample_rows

   !> Append a history sample of a stick (`rec%stick`) from its DOF vectors, peaks untouched:
   !> the output part of `response_sample` (also used by the batched uncoupled runs, which
   !> track the peaks in their own pass).
   pure subroutine response_store(rec, b, u, v, a, ag)
      !> The record of a stick.
      type(response_record), intent(inout) :: rec
      !> The building.
      type(structure_model), intent(in) :: b
      !> Relative displacement, velocity and acceleration (`b%n` each).
      real(dp), intent(in) :: u(b%n), v(b%n), a(b%n)
      !> Ground acceleration (m/s^2; by value).
      real(dp), intent(in), value :: ag
      integer :: k

      rec%n_out = rec%n_out + 1
      k = rec%n_out
      if (rec%nodes) rec%u_nodes(:, k) = u
      if (rec%store(q_u)) rec%u(:, k) = u
      if (rec%store(q_v)) rec%v(:, k) = v
      if (rec%store(q_a_abs)) rec%a_abs(:, k) = a + ag
      if (rec%store(q_drift) .or. rec%store(q_shear)) then
         call chain_drift(rec%n, u, rec%work)
         if (rec%store(q_drift)) rec%drift(:, k) = rec%work
         if (rec%store(q_shear)) rec%shear(:, k) = b%shear%scale*rec%work
      end if
   end subroutine response_store

   !> Running absolute maxima of u, v, a_abs and drift (explicit-shape arrays, so the
   !> compiler sees plain contiguous memory).
   !>
   !> New maxima come in runs of steps (while the response grows) between long runs of steps
   !> without any. After a step without one (`rising` false) one pass without branches counts
   !> the new maxima of all four quantities first (vectorised) and the floors are visited
   !> only when there are some; after a step with one they are visited at once.
   pure subroutine track_peaks(n, u, v, a, ag, t, peak, peak_time, rising)
      integer, intent(in) :: n
      real(dp), intent(in) :: u(n), v(n), a(n), ag, t
      real(dp), intent(inout) :: peak(n, n_history_quantities), peak_time(n, n_history_quantities)
      !> Whether the last step set a new maximum (updated for this one).
      logical, intent(inout) :: rising
      real(dp) :: x, below
      integer :: i, hits

      if (.not. rising) then
         ! (The drift of floor 1 is its u: its peak is u's.)
         hits = merge(1, 0, abs(u(1)) > peak(1, q_u)) + merge(1, 0, abs(v(1)) > peak(1, q_v)) + &
                merge(1, 0, abs(a(1) + ag) > peak(1, q_a_abs))
         !GCC$ vector
         do i = 2, n
            hits = hits + merge(1, 0, abs(u(i)) > peak(i, q_u)) + merge(1, 0, abs(v(i)) > peak(i, q_v)) + &
                   merge(1, 0, abs(a(i) + ag) > peak(i, q_a_abs)) + merge(1, 0, abs(u(i) - u(i - 1)) > peak(i, q_drift))
         end do
         if (hits == 0) return
      end if
      rising = .false.
      below = 0.0_dp
      do i = 1, n
         x = abs(u(i))
         if (x > peak(i, q_u)) then
            peak(i, q_u) = x
            peak_time(i, q_u) = t
            rising = .true.
         end if
         x = abs(v(i))
         if (x > peak(i, q_v)) then
            peak(i, q_v) = x
            peak_time(i, q_v) = t
            rising = .true.
         end if
         x = abs(a(i) + ag)
         if (x > peak(i, q_a_abs)) then
            peak(i, q_a_abs) = x
            peak_time(i, q_a_abs) = t
            rising = .true.
         end if
         x = abs(u(i) - below)
         below = u(i)
         if (x > peak(i, q_drift)) then
            peak(i, q_drift) = x
            peak_time(i, q_drift) = t
            rising = .true.
         end if
      end do
   end subroutine track_peaks

   !> Peaks of u, drift and (a frame's) storey shear between the previous sample and this
   !> one (`free_steps = 'exact'`, whose samples are exact: what is left of a peak's error is
   !> the peak between two samples, O((omega dt)^2)): the largest |p(s)| of the cubic Hermite
   !> interpolant through the two samples' values and rates (the rates from v: the quantities
   !> are linear in u), fourth order; where it exceeds the peak, the peak and its time (the
   !> interpolant's) are set. An interval whose bound max(|x0|, |x1|) + 4/27 h (|x0'| + |x1'|)
   !> is not above the peak is skipped. A stick's storey shears follow from its drift peaks
   !> (`response_finish`). A frame's rows' rates (two more recoveries) are taken only on the
   !> steps where some value of the two samples is within `refine_band` of its peak (a peak
   !> between samples more than 20 % above both would need omega dt > 1.29).
   pure subroutine refine_peaks(rec, b, u, v, t)
      !> The record (`rec%refine`).
      type(response_record), intent(inout) :: rec
      !> The building.
      type(structure_model), intent(in) :: b
      !> Relative displacement and velocity (`b%n` each).
      real(dp), intent(in) :: u(b%n), v(b%n)
      !> Time (s).
      real(dp), intent(in) :: t
      integer, parameter :: quantity(3) = [q_u, q_drift, q_shear]
      real(dp), parameter :: refine_band = 0.8_dp
      integer :: i, q, nq, k, qq
      real(dp) :: h, x0, x1, d0, d1, ca, cb, cc, disc, w, s(2), p
      logical :: near

      associate (now => rec%last(:, :, :, 2), old => rec%last(:, :, :, 1), n => rec%n)
         if (rec%stick) then
            now(:, 1, 1) = u(1:n)
            now(:, 2, 1) = v(1:n)
            call chain_drift(n, u, now(:, 1, 2))
            call chain_drift(n, v, now(:, 2, 2))
            nq = 2
         else
            ! Gathers by explicit loops: an index-vector assignment copies the index first.
            do i = 1, n
               now(i, 1, 1) = u(b%floor_dof(i))
            end do
            now(:, 1, 2) = rec%pd
            now(:, 1, 3) = rec%ps
            nq = 3
            near = .false.
            do q = 1, nq
               do i = 1, n
                  if (max(abs(old(i, 1, q)), abs(now(i, 1, q))) >= refine_band*rec%peak(i, quantity(q))) near = .true.
               end do
            end do
            if (near .and. rec%t_last >= 0.0_dp) then
               do i = 1, n
                  now(i, 2, 1) = v(b%floor_dof(i))
               end do
               if (.not. rec%rates_last) then
                  do i = 1, n
                     old(i, 2, 1) = rec%v_last(b%floor_dof(i))
                  end do
                  call recover_all(b%drift, rec%v_last, old(:, 2, 2))
                  call recover_all(b%shear, rec%v_last, old(:, 2, 3))
               end if
               call recover_all(b%drift, v, now(:, 2, 2))
               call recover_all(b%shear, v, now(:, 2, 3))
               rec%rates_last = .true.
            else
               nq = 0
               rec%rates_last = .false.
            end if
            rec%v_last = v
         end if
         h = t - rec%t_last
         if (rec%t_last >= 0.0_dp .and. h > 0.0_dp) then
            do q = 1, nq
               qq = quantity(q)
               do i = 1, n
                  x0 = old(i, 1, q)
                  x1 = now(i, 1, q)
                  d0 = h*old(i, 2, q)
                  d1 = h*now(i, 2, q)
                  if (max(abs(x0), abs(x1)) + 4.0_dp/27.0_dp*(abs(d0) + abs(d1)) <= rec%peak(i, qq)) cycle
                  ! p(s) = ((ca s + cb) s + cc) s + x0 on s in (0, 1); p'(s) = 0.
                  ca = 2.0_dp*(x0 - x1) + d0 + d1
                  cb = 3.0_dp*(x1 - x0) - 2.0_dp*d0 - d1
                  cc = d0
                  disc = cb*cb - 3.0_dp*ca*cc
                  if (disc < 0.0_dp) cycle
                  w = -(cb + sign(sqrt(disc), cb))
                  s = -1.0_dp
                  if (ca /= 0.0_dp) s(1) = w/(3.0_dp*ca)
                  if (w /= 0.0_dp) s(2) = cc/w
                  do k = 1, 2
                     if (.not. (s(k) > 0.0_dp .and. s(k) < 1.0_dp)) cycle
                     p = abs(((ca*s(k) + cb)*s(k) + cc)*s(k) + x0)
                     if (p > rec%peak(i, qq)) then
                        rec%peak(i, qq) = p
                        rec%peak_time(i, qq) = rec%t_last + s(k)*h
                     end if
                  end do
               end do
            end do
         end if
      end associate
      ! The last sample becomes the previous one (whole planes of one array: no temporary).
      rec%last(:, :, :, 1) = rec%last(:, :, :, 2)
      rec%t_last = t
   end subroutine refine_peaks

   !> Storey drifts of a stick: u_1, u_j - u_{j-1}.
   pure subroutine chain_drift(n, u, d)
      integer, intent(in) :: n
      real(dp), intent(in) :: u(n)
      real(dp), intent(out) :: d(n)
      integer :: i

      d(1) = u(1)
      do i = 2, n
         d(i) = u(i) - u(i - 1)
      end do
   end subroutine chain_drift

   !> The response points' u, v and a_abs (gathered from the DOF vectors at `dof`) and the
   !> running absolute maxima of all five quantities at the points and storey rows, in one
   !> pass over the floors (the same comparisons as one pass per quantity).
   pure subroutine track_general(n, nu, dof, u, v, a, ag, pd, ps, t, pu, pv, pa, peak, peak_time)
      integer, intent(in) :: n, nu, dof(n)
      real(dp), intent(in) :: u(nu), v(nu), a(nu), ag, pd(n), ps(n), t
      real(dp), intent(out) :: pu(n), pv(n), pa(n)
      real(dp), intent(inout) :: peak(n, n_history_quantities), peak_time(n, n_history_quantities)
      integer :: i, k

      do i = 1, n
         k = dof(i)
         pu(i) = u(k)
         pv(i) = v(k)
         pa(i) = a(k) + ag
         call keep_peak(pu(i), t, peak(i, q_u), peak_time(i, q_u))
         call keep_peak(pv(i), t, peak(i, q_v), peak_time(i, q_v))
         call keep_peak(pa(i), t, peak(i, q_a_abs), peak_time(i, q_a_abs))
         call keep_peak(pd(i), t, peak(i, q_drift), peak_time(i, q_drift))
         call keep_peak(ps(i), t, peak(i, q_shear), peak_time(i, q_shear))
      end do
   end subroutine track_general

   !> Point every storey j whose shear exceeds its peak so far (called before the peaks are
   !> updated, with the same test) at a copy of u: one free slot of the pool, taken once per
   !> step; the slots left without storeys are freed. At most n storeys point at n + 1 slots,
   !> so a slot is free at the start of every step.
   pure subroutine take_snapshots(nu, n, u, ps, peak, pool, slot_of, refs, free, n_free)
      integer, intent(in) :: nu, n
      real(dp), intent(in) :: u(nu), ps(n), peak(n)
      real(dp), intent(inout) :: pool(nu, n + 1)
      integer, intent(inout) :: slot_of(n), refs(n + 1), free(n + 1), n_free
      integer :: j, new, old

      new = 0
      do j = 1, n
         if (.not. abs(ps(j)) > peak(j)) cycle
         if (new == 0) then
            new = free(n_free)
            n_free = n_free - 1
            pool(:, new) = u
         end if
         old = slot_of(j)
         if (old > 0) then
            refs(old) = refs(old) - 1
            if (refs(old) == 0) then
               n_free = n_free + 1
               free(n_free) = old
            end if
         end if
         slot_of(j) = new
         refs(new) = refs(new) + 1
      end do
   end subroutine take_snapshots

   !> Peaks of v and a_abs at the response points from a state inside a step that is not
   !> sampled (the substeps of a step with joints closed, pound_closed_steps).
   pure subroutine response_peaks_inside(rec, pv, pa, ag, t)
      !> The record.
      type(response_record), intent(inout) :: rec
      !> Relative velocity and acceleration at the response points (`rec%n` each).
      real(dp), intent(in) :: pv(:), pa(:)
      !> Ground acceleration (m/s^2) and time (s).
      real(dp), intent(in) :: ag, t
      integer :: i

      do i = 1, rec%n
         call keep_peak(pv(i), t, rec%peak(i, q_v), rec%peak_time(i, q_v))
         call keep_peak(pa(i) + ag, t, rec%peak(i, q_a_abs), rec%peak_time(i, q_a_abs))
      end do
   end subroutine response_peaks_inside

   !> Running absolute maximum of one value: peak and its time when |x| exceeds the peak.
   pure subroutine keep_peak(x, t, peak, peak_time)
      real(dp), intent(in) :: x, t
      real(dp), intent(inout) :: peak, peak_time

      if (abs(x) > peak) then
         peak = abs(x)
         peak_time = t
      end if
   end subroutine keep_peak

   !> Output samples per block of a streamed history of n floors: `block` when positive,
   !> else about `default_block_bytes` per quantity; never more than the n_out of the run.
   pure integer function history_block(n, n_out, block)
      !> Floors (rows of the history).
      integer, intent(in) :: n
      !> Output samples of the run.
      integer, intent(in) :: n_out
      !> Samples per block asked for (0: automatic).
      integer, intent(in) :: block

      if (block > 0) then
         history_block = min(n_out, block)
      else
         history_block = min(n_out, max(1, default_block_bytes/(8*max(1, n))))
      end if
   end function history_block

   !> Drop the samples (`discard_sink`).
   subroutine discard_put(sink, coupled, building, quantity, first, values, error)
      !> The sink; whether the coupled analysis; building, quantity and first sample index.
      class(discard_sink), intent(inout) :: sink
      logical, intent(in) :: coupled
      integer, intent(in) :: building, quantity, first
      !> The samples, dropped.
      real(dp), intent(in), contiguous :: values(:, :)
      !> Error state (never set).
      type(error_type), allocatable, intent(out) :: error

      associate (unused => [sink%block, merge(1, 0, coupled), building, quantity, first, size(values)])
      end associate
      if (allocated(error)) deallocate (error)
   end subroutine discard_put

   !> Whether the record's block of output samples is full (a streamed record hands it over).
   elemental logical function response_block_full(rec) result(full)
      !> The record.
      type(response_record), intent(in) :: rec

      full = rec%n_out > 0 .and. rec%n_out >= rec%capacity
   end function response_block_full

   !> Streamed histories: hand the samples held to `sink` and empty the block (when `full`,
   !> only if the block is full).
   subroutine response_flush(rec, sink, coupled, building, full, error)
      !> The record.
      type(response_record), intent(inout) :: rec
      !> Where the histories go.
      class(history_sink), intent(inout) :: sink
      !> The coupled analysis (else the uncoupled one).
      logical, intent(in) :: coupled
      !> Building index (by value: the time loop's index is not kept in memory for it).
      integer, intent(in), value :: building
      !> Flush only a full block.
      logical, intent(in) :: full
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: k

      k = rec%n_out
      if (k == 0) return
      if (full .and. .not. response_block_full(rec)) return
      if (rec%store(q_u)) call sink%put(coupled, building, q_u, rec%first, rec%u(:, 1:k), error)
      if (allocated(error)) return
      if (rec%store(q_v)) call sink%put(coupled, building, q_v, rec%first, rec%v(:, 1:k), error)
      if (allocated(error)) return
      if (rec%store(q_a_abs)) call sink%put(coupled, building, q_a_abs, rec%first, rec%a_abs(:, 1:k), error)
      if (allocated(error)) return
      if (rec%store(q_drift)) call sink%put(coupled, building, q_drift, rec%first, rec%drift(:, 1:k), error)
      if (allocated(error)) return
      if (rec%store(q_shear)) call sink%put(coupled, building, q_shear, rec%first, rec%shear(:, 1:k), error)
      if (allocated(error)) return
      rec%first = rec%first + k
      rec%n_out = 0
   end subroutine response_flush

   !> Free the histories of a streamed record whose samples have all gone to the sink (after
   !> the last flush): the next analysis' histories take the same memory again (no new pages
   !> for the kernel to fault in and zero).
   subroutine response_release(rec)
      !> The record.
      type(response_record), intent(inout) :: rec

      if (.not. rec%streamed .or. rec%n_out /= 0) return
      if (allocated(rec%u)) deallocate (rec%u)
      if (allocated(rec%v)) deallocate (rec%v)
      if (allocated(rec%a_abs)) deallocate (rec%a_abs)
      if (allocated(rec%drift)) deallocate (rec%drift)
      if (allocated(rec%shear)) deallocate (rec%shear)
   end subroutine response_release

   !> Derive the storey-shear peaks: each shear row is its drift row times the row's scale
   !> (a shear building: Q_j = k_j drift_j), so they occur with the drift peaks; put the
   !> deformed shapes (`snapshots`) in storey order.
   pure subroutine response_finish(rec, b)
      !> The record.
      type(response_record), intent(inout) :: rec
      !> The building.
      type(structure_model), intent(in) :: b

      integer :: j

      if (allocated(rec%pool)) then
         ! The deformed shapes in storey order (zero for a storey whose shear never moved).
         allocate (rec%deformed(size(rec%pool, 1), rec%n), source=0.0_dp)
         do j = 1, rec%n
            if (rec%slot_of(j) > 0) rec%deformed(:, j) = rec%pool(:, rec%slot_of(j))
         end do
         deallocate (rec%pool, rec%slot_of, rec%refs, rec%free)
      end if
      if (.not. rec%stick) return
      do j = 1, b%shear%n
         rec%peak(j, q_shear) = b%shear%scale(j)*rec%peak(j, q_drift)
      end do
      rec%peak_time(:, q_shear) = rec%peak_time(:, q_drift)
   end subroutine response_finish

end module pound_response
