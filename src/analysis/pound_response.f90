!> Response of one building over an analysis: peaks at every step, histories at output steps.
!>
!> Quantities (indices match `history_names` of pound_config): floor displacement `u`,
!> floor velocity `v` (relative to the ground), floor absolute acceleration `a_abs`,
!> storey drift `drift` (u_j - u_{j-1}) and storey shear `storey_shear` Q_j = k_j drift_j.
!> Peaks are absolute maxima over all steps, not only the stored ones. Histories are held
!> as (n, n_out) so that h5py reads them as (n_out, n).
module pound_response
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_config, only: n_history_quantities
   use pound_shear_building, only: shear_building
   implicit none
   private

   public :: response_record, response_init, response_sample, response_finish
   public :: q_u, q_v, q_a_abs, q_drift, q_shear

   !> Quantity indices.
   integer, parameter :: q_u = 1, q_v = 2, q_a_abs = 3, q_drift = 4, q_shear = 5

   !> Peaks and histories of one building.
   type :: response_record
      !> Number of floors.
      integer :: n = 0
      !> Which histories are stored.
      logical :: store(n_history_quantities) = .false.
      !> Output samples written so far, and capacity.
      integer :: n_out = 0, capacity = 0
      !> Histories (n, capacity), allocated only for stored quantities.
      real(dp), allocatable :: u(:, :), v(:, :), a_abs(:, :), drift(:, :), shear(:, :)
      !> Peak absolute value per floor/storey and quantity (n, n_history_quantities).
      real(dp), allocatable :: peak(:, :)
      !> Time of each peak (s).
      real(dp), allocatable :: peak_time(:, :)
      !> Work array (n): drift or absolute acceleration of the step being sampled.
      real(dp), allocatable :: work(:)
   end type response_record

contains

   !> Prepare a record for `capacity` output samples.
   !>
   !> Fails (nothing allocated is kept) when the memory cannot be had, with the size asked
   !> for and the deck variables that set it.
   pure subroutine response_init(rec, n, store, capacity, error)
      !> The record.
      type(response_record), intent(out) :: rec
      !> Number of floors.
      integer, intent(in) :: n
      !> Which histories to store.
      logical, intent(in) :: store(n_history_quantities)
      !> Number of output samples that will be taken.
      integer, intent(in) :: capacity
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: stat(6)
      real(dp) :: mib

      rec%n = n
      rec%store = store
      rec%capacity = capacity
      rec%n_out = 0
      stat = 0
      ! Histories are zeroed here, so that their memory is touched before the time loop.
      if (store(q_u)) allocate (rec%u(n, capacity), source=0.0_dp, stat=stat(1))
      if (store(q_v)) allocate (rec%v(n, capacity), source=0.0_dp, stat=stat(2))
      if (store(q_a_abs)) allocate (rec%a_abs(n, capacity), source=0.0_dp, stat=stat(3))
      if (store(q_drift)) allocate (rec%drift(n, capacity), source=0.0_dp, stat=stat(4))
      if (store(q_shear)) allocate (rec%shear(n, capacity), source=0.0_dp, stat=stat(5))
      allocate (rec%peak(n, n_history_quantities), rec%peak_time(n, n_history_quantities), rec%work(n), &
                stat=stat(6))
      if (any(stat /= 0)) then
         mib = 8.0_dp*real(n, dp)*real(capacity, dp)*real(count(store), dp)/2.0_dp**20
         rec = response_record()
         call fatal_error(error, 'cannot allocate the response histories: '//str(count(store))// &
                          ' quantities x '//str(n)//' floors x '//str(capacity)//' output samples = '// &
                          str(mib)//' MiB; store fewer or less often (history, output_every) or '// &
                          'shorten the run (t_end, dt)')
         return
      end if
      rec%peak = 0.0_dp
      rec%peak_time = 0.0_dp
   end subroutine response_init

   !> Take the state at time t: update peaks and, if `output`, append a history sample.
   pure subroutine response_sample(rec, b, u, v, a, ag, t, output)
      !> The record.
      type(response_record), intent(inout) :: rec
      !> The building.
      type(shear_building), intent(in) :: b
      !> Relative displacement, velocity and acceleration.
      real(dp), intent(in) :: u(:), v(:), a(:)
      !> Ground acceleration (m/s^2).
      real(dp), intent(in) :: ag
      !> Time (s).
      real(dp), intent(in) :: t
      !> Whether this is an output step.
      logical, intent(in) :: output
      integer :: k

      call track_peaks(rec%n, u, v, a, ag, t, rec%peak, rec%peak_time)
      if (.not. output) return
      rec%n_out = rec%n_out + 1
      k = rec%n_out
      if (rec%store(q_u)) rec%u(:, k) = u
      if (rec%store(q_v)) rec%v(:, k) = v
      if (rec%store(q_a_abs)) rec%a_abs(:, k) = a + ag
      if (rec%store(q_drift) .or. rec%store(q_shear)) then
         rec%work(1) = u(1)
         rec%work(2:) = u(2:) - u(:rec%n - 1)
         if (rec%store(q_drift)) rec%drift(:, k) = rec%work
         if (rec%store(q_shear)) rec%shear(:, k) = b%storey_stiffness*rec%work
      end if
   end subroutine response_sample

   !> Running absolute maxima of u, v, a_abs and drift in one pass over the floors
   !> (explicit-shape arrays, so the compiler sees plain contiguous memory).
   pure subroutine track_peaks(n, u, v, a, ag, t, peak, peak_time)
      integer, intent(in) :: n
      real(dp), intent(in) :: u(n), v(n), a(n), ag, t
      real(dp), intent(inout) :: peak(n, n_history_quantities), peak_time(n, n_history_quantities)
      real(dp) :: x, below
      integer :: i

      below = 0.0_dp
      do i = 1, n
         x = abs(u(i))
         if (x > peak(i, q_u)) then
            peak(i, q_u) = x
            peak_time(i, q_u) = t
         end if
         x = abs(v(i))
         if (x > peak(i, q_v)) then
            peak(i, q_v) = x
            peak_time(i, q_v) = t
         end if
         x = abs(a(i) + ag)
         if (x > peak(i, q_a_abs)) then
            peak(i, q_a_abs) = x
            peak_time(i, q_a_abs) = t
         end if
         x = abs(u(i) - below)
         below = u(i)
         if (x > peak(i, q_drift)) then
            peak(i, q_drift) = x
            peak_time(i, q_drift) = t
         end if
      end do
   end subroutine track_peaks

   !> Derive the storey-shear peaks (Q_j = k_j drift_j, so they occur with the drift peaks).
   pure subroutine response_finish(rec, b)
      !> The record.
      type(response_record), intent(inout) :: rec
      !> The building.
      type(shear_building), intent(in) :: b

      rec%peak(:, q_shear) = b%storey_stiffness*rec%peak(:, q_drift)
      rec%peak_time(:, q_shear) = rec%peak_time(:, q_drift)
   end subroutine response_finish

end module pound_response
