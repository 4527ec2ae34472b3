!> Newmark average acceleration of one shear building (the fused tridiagonal path of
!> `pound_newmark`) under `batch_lanes` ground motions at once: the motions share the
!> factored Khat, and every vector is held motion-fastest, x(lane, floor), so that the
!> recurrences of the tridiagonal solve of the lanes overlap and vectorise.
!>
!> **Same numbers as one motion at a time.** Each lane performs the operations of
!> `predict_kernel` and `commit_kernel` (submodule `pound_newmark_step`) in the same order:
!> the same expressions, the energy sums kept in the same four partial sums (element i of
!> sum(m du) and of 2 E_kinetic in partial sum mod(i-1, 4), element i of du.(Cv_old + Cv_new)
!> and of -2 E_strain in partial sum mod(i-2, 4)), combined in the same order. The kernel also
!> takes the running absolute maxima of u, v, a_abs and the storey drift per floor and lane
!> (as `response_sample` of a stick does). A step is three passes over the floors: the forward
!> and the back sweep of the solve, then the update with C v and the energy sums (floor i+1
!> updated before C v of floor i), then the peaks. Buildings of two floors or more.
!>
!> Lanes that carry no motion (a batch of fewer motions than `batch_lanes`) are driven by a zero
!> ground acceleration and stay at rest.
module pound_newmark_batch
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_structure, only: structure_model, structure_label
   use pound_newmark, only: newmark_state, newmark_init, newmark_tridiagonal_factors
   implicit none
   private

   public :: batch_lanes, newmark_batch, batch_start, batch_init, batch_step, batch_lane_state, batch_reset_lane

   !> Motions advanced together (two AVX2 vectors of doubles).
   integer, parameter :: batch_lanes = 8

   !> The integrator state of one building for `batch_lanes` motions.
   type :: newmark_batch
      !> Number of floors.
      integer :: n = 0
      !> Newmark constants c1 = 4/dt^2, c2 = 2/dt.
      real(dp) :: c1 = 0.0_dp, c2 = 0.0_dp
      !> L D L^T factors of Khat: sub-diagonal e of L (max(n-1, 1)) and 1/d (n).
      real(dp), allocatable :: e(:), dinv(:)
      !> Relative displacement, velocity, acceleration, C v and the step's increment
      !> (batch_lanes, n).
      real(dp), allocatable :: u(:, :), v(:, :), a(:, :), cv(:, :), du(:, :)
      !> Input work, damping energy, kinetic and strain energy per lane (kJ), as `newmark_state`.
      real(dp) :: input_work(batch_lanes) = 0.0_dp, damping_energy(batch_lanes) = 0.0_dp
      real(dp) :: kinetic(batch_lanes) = 0.0_dp, strain(batch_lanes) = 0.0_dp
   end type newmark_batch

contains

   !> Factor Khat of the model for dt (`newmark_init`) and start every lane at rest
   !> (`batch_init`): the batch's own set-up, so that the caller names no integrator type.
   subroutine batch_start(bt, b, dt, ag0, error)
      !> The batch (set up).
      type(newmark_batch), intent(out) :: bt
      !> The structural model (a shear building: kd = 1, every DOF moved by the ground).
      type(structure_model), intent(in) :: b
      !> Time step (s).
      real(dp), intent(in) :: dt
      !> Ground acceleration of each lane at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0(batch_lanes)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(newmark_state) :: st

      call newmark_init(st, b, dt, ag0(1), error)
      if (.not. allocated(error)) call batch_init(bt, st, b, ag0, error)
   end subroutine batch_start

   !> Start every lane at rest relative to the ground, in equilibrium with its ground
   !> acceleration at t = 0 (as `newmark_init`), with the factors of `st`.
   subroutine batch_init(bt, st, b, ag0, error)
      !> The batch (set up).
      type(newmark_batch), intent(out) :: bt
      !> An integrator of the model, initialised by `newmark_init` (its factors are taken).
      type(newmark_state), intent(in) :: st
      !> The structural model (a shear building: kd = 1, every DOF moved by the ground).
      type(structure_model), intent(in) :: b
      !> Ground acceleration of each lane at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0(batch_lanes)
      !> Error state: the model does not take the tridiagonal path.
      type(error_type), allocatable, intent(out) :: error
      logical :: tridiagonal
      integer :: i

      call newmark_tridiagonal_factors(st, tridiagonal, bt%e, bt%dinv, bt%c1, bt%c2)
      if (.not. tridiagonal .or. b%n < 2) then
         call fatal_error(error, structure_label(b)//': the batched integration needs the tridiagonal path '// &
                          'and two floors or more')
         return
      end if
      bt%n = b%n
      allocate (bt%u(batch_lanes, b%n), bt%v(batch_lanes, b%n), bt%a(batch_lanes, b%n), &
                bt%cv(batch_lanes, b%n), bt%du(batch_lanes, b%n), source=0.0_dp)
      do i = 1, b%n
         bt%a(:, i) = -ag0*b%ground(i)
      end do
      bt%input_work = 0.0_dp
      bt%damping_energy = 0.0_dp
      bt%kinetic = 0.0_dp
      bt%strain = 0.0_dp
   end subroutine batch_init

   !> One step of every lane (predict and commit of `pound_newmark` with no other load), and the
   !> running peaks: `peak(l, q, i)` the absolute maximum so far of quantity q at floor i in
   !> lane l and `peak_time` when it first occurred (q = 1 u, 2 v, 3 absolute
   !> acceleration, 4 drift).
   subroutine batch_step(bt, b, ag_old, ag_new, t, peak, peak_time)
      !> The batch.
      type(newmark_batch), intent(inout) :: bt
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration of each lane at the start and the end of the step (m/s^2).
      real(dp), intent(in) :: ag_old(batch_lanes), ag_new(batch_lanes)
      !> Time at the end of the step (s).
      real(dp), intent(in) :: t
      !> Running peaks and their times (batch_lanes, 4, n).
      real(dp), intent(inout), contiguous :: peak(:, :, :), peak_time(:, :, :)
      real(dp) :: mdu(batch_lanes), ddamp(batch_lanes), dag(batch_lanes)
      real(dp), volatile :: work(batch_lanes)

      dag = ag_new - ag_old
      call predict_lanes(bt%n, 2.0_dp*bt%c2, dag, b%mass, bt%v, bt%a, bt%cv, bt%e, bt%dinv, bt%du)
      call commit_lanes(bt%n, bt%c1, bt%c2, b%a0, b%a1, b%mass, b%kt, bt%du, bt%u, bt%v, bt%a, bt%cv, &
                        ag_new, t, peak, peak_time, mdu, ddamp, bt%kinetic, bt%strain)
      bt%damping_energy = bt%damping_energy + 0.5_dp*ddamp
      ! The work increment is rounded before it is subtracted, as `newmark_commit` does (its
      ! scalar code has no fused multiply-add there); a volatile store keeps the compiler from
      ! fusing it here.
      work = 0.5_dp*(ag_old + ag_new)*mdu
      bt%input_work = bt%input_work - work
   end subroutine batch_step

   !> Copy lane l's u, v, a (n each) out of the batch.
   pure subroutine batch_lane_state(bt, l, u, v, a)
      !> The batch.
      type(newmark_batch), intent(in) :: bt
      !> Lane.
      integer, intent(in) :: l
      !> Displacement, velocity, acceleration of the lane.
      real(dp), intent(out) :: u(:), v(:), a(:)

      u = bt%u(l, :)
      v = bt%v(l, :)
      a = bt%a(l, :)
   end subroutine batch_lane_state

   !> Bring lane l to rest (zero state and energies): a lane dropped from the batch.
   pure subroutine batch_reset_lane(bt, l)
      !> The batch.
      type(newmark_batch), intent(inout) :: bt
      !> Lane.
      integer, intent(in) :: l

      bt%u(l, :) = 0.0_dp
      bt%v(l, :) = 0.0_dp
      bt%a(l, :) = 0.0_dp
      bt%cv(l, :) = 0.0_dp
      bt%du(l, :) = 0.0_dp
      bt%input_work(l) = 0.0_dp
      bt%damping_energy(l) = 0.0_dp
      bt%kinetic(l) = 0.0_dp
      bt%strain(l) = 0.0_dp
   end subroutine batch_reset_lane

   !> du = Khat^{-1} (M (4/dt v + 2 a - 1 dag) + 2 C v) for every lane (`predict_kernel`).
   pure subroutine predict_lanes(n, c4, dag, mass, v, a, cv, e, dinv, du)
      integer, intent(in) :: n
      real(dp), intent(in) :: c4, dag(batch_lanes), mass(n), v(batch_lanes, n), a(batch_lanes, n)
      real(dp), intent(in) :: cv(batch_lanes, n), e(max(n - 1, 1)), dinv(n)
      real(dp), intent(out) :: du(batch_lanes, n)
      integer :: i, l

      do l = 1, batch_lanes
         du(l, 1) = mass(1)*(c4*v(l, 1) + 2.0_dp*a(l, 1) - dag(l)) + 2.0_dp*cv(l, 1)
      end do
      do i = 2, n
         do l = 1, batch_lanes
            du(l, i) = mass(i)*(c4*v(l, i) + 2.0_dp*a(l, i) - dag(l)) + 2.0_dp*cv(l, i) - e(i - 1)*du(l, i - 1)
         end do
      end do
      do l = 1, batch_lanes
         du(l, n) = du(l, n)*dinv(n)
      end do
      do i = n - 1, 1, -1
         do l = 1, batch_lanes
            du(l, i) = du(l, i)*dinv(i) - e(i)*du(l, i + 1)
         end do
      end do
   end subroutine predict_lanes

   !> Newmark update, C v at the new time, the energy sums and the peaks of every lane, in one
   !> ascending pass: floor i+1 is updated before C v of floor i (which needs v(i+1)). The
   !> statements of a floor are those of `update_floor` and `damp_floor` (pound_newmark_step)
   !> and of `track_peaks` (pound_response), written out in the loop (n >= 2).
   pure subroutine commit_lanes(n, c1, c2, a0, a1, mass, kt, du, u, v, a, cv, ag, t, peak, peak_time, &
                                mdu, ddamp, ek, es)
      integer, intent(in) :: n
      real(dp), intent(in) :: c1, c2, a0, a1, mass(n), kt(2, n), du(batch_lanes, n), ag(batch_lanes), t
      real(dp), intent(inout) :: u(batch_lanes, n), v(batch_lanes, n), a(batch_lanes, n), cv(batch_lanes, n)
      real(dp), intent(inout) :: peak(batch_lanes, 4, n), peak_time(batch_lanes, 4, n)
      real(dp), intent(out) :: mdu(batch_lanes), ddamp(batch_lanes), ek(batch_lanes), es(batch_lanes)
      real(dp) :: sm(batch_lanes, 0:3), sk(batch_lanes, 0:3), sd(batch_lanes, 0:3), ss(batch_lanes, 0:3)
      real(dp) :: cvi, x, below
      integer :: i, j, l, q, r

      sm = 0.0_dp
      sk = 0.0_dp
      sd = 0.0_dp
      ss = 0.0_dp
      ! Floors 1 and 2 updated (partial sums 0 and 1), C v of floor 1 (partial sum 3, assigned).
      do j = 1, 2
         do l = 1, batch_lanes
            a(l, j) = c1*du(l, j) - 2.0_dp*c2*v(l, j) - a(l, j)
            v(l, j) = c2*du(l, j) - v(l, j)
            u(l, j) = u(l, j) + du(l, j)
            sm(l, j - 1) = sm(l, j - 1) + mass(j)*du(l, j)
            sk(l, j - 1) = sk(l, j - 1) + mass(j)*v(l, j)*v(l, j)
         end do
      end do
      do l = 1, batch_lanes
         cvi = a0*mass(1)*v(l, 1) + a1*(kt(2, 1)*v(l, 1) + kt(1, 2)*v(l, 2))
         sd(l, 3) = du(l, 1)*(cv(l, 1) + cvi)
         ss(l, 3) = -(kt(2, 1) + kt(1, 2))*u(l, 1)*u(l, 1)
         cv(l, 1) = cvi
      end do
      do i = 2, n - 1
         j = i + 1
         q = iand(i, 3)
         r = iand(i + 2, 3)
         do l = 1, batch_lanes
            a(l, j) = c1*du(l, j) - 2.0_dp*c2*v(l, j) - a(l, j)
            v(l, j) = c2*du(l, j) - v(l, j)
            u(l, j) = u(l, j) + du(l, j)
            sm(l, q) = sm(l, q) + mass(j)*du(l, j)
            sk(l, q) = sk(l, q) + mass(j)*v(l, j)*v(l, j)
            cvi = a0*mass(i)*v(l, i) + a1*(kt(1, i)*v(l, i - 1) + kt(2, i)*v(l, i) + kt(1, i + 1)*v(l, i + 1))
            sd(l, r) = sd(l, r) + du(l, i)*(cv(l, i) + cvi)
            ss(l, r) = ss(l, r) + kt(1, i)*(u(l, i) - u(l, i - 1))**2
            cv(l, i) = cvi
         end do
      end do
      r = iand(n + 2, 3)
      do l = 1, batch_lanes
         cvi = a0*mass(n)*v(l, n) + a1*(kt(1, n)*v(l, n - 1) + kt(2, n)*v(l, n))
         sd(l, r) = sd(l, r) + du(l, n)*(cv(l, n) + cvi)
         ss(l, r) = ss(l, r) + kt(1, n)*(u(l, n) - u(l, n - 1))**2
         cv(l, n) = cvi
      end do
      ! Peaks (`track_peaks`); the drift of floor 1 is u_1 (u_0 = 0). The time of quantity q
      ! becomes t when x > peak (then 0.5 - sign(0.5, peak - x) = 1, else 0; t exceeds every
      ! time before it), the peak max(peak, x): no branch and no masked merge, so that the
      ! lanes vectorise; the same peaks and times as `track_peaks`.
      do i = 1, n
         j = max(i - 1, 1)
         below = merge(1.0_dp, 0.0_dp, i > 1)
         do l = 1, batch_lanes
            x = abs(u(l, i))
            peak_time(l, 1, i) = max(peak_time(l, 1, i), t*(0.5_dp - sign(0.5_dp, peak(l, 1, i) - x)))
            peak(l, 1, i) = max(peak(l, 1, i), x)
            x = abs(v(l, i))
            peak_time(l, 2, i) = max(peak_time(l, 2, i), t*(0.5_dp - sign(0.5_dp, peak(l, 2, i) - x)))
            peak(l, 2, i) = max(peak(l, 2, i), x)
            x = abs(a(l, i) + ag(l))
            peak_time(l, 3, i) = max(peak_time(l, 3, i), t*(0.5_dp - sign(0.5_dp, peak(l, 3, i) - x)))
            peak(l, 3, i) = max(peak(l, 3, i), x)
            x = abs(u(l, i) - below*u(l, j))
            peak_time(l, 4, i) = max(peak_time(l, 4, i), t*(0.5_dp - sign(0.5_dp, peak(l, 4, i) - x)))
            peak(l, 4, i) = max(peak(l, 4, i), x)
         end do
      end do
      mdu = (sm(:, 3) + sm(:, 0)) + (sm(:, 1) + sm(:, 2))
      ek = 0.5_dp*((sk(:, 3) + sk(:, 0)) + (sk(:, 1) + sk(:, 2)))
      ddamp = (sd(:, 2) + sd(:, 3)) + (sd(:, 0) + sd(:, 1))
      es = -0.5_dp*((ss(:, 2) + ss(:, 3)) + (ss(:, 0) + ss(:, 1)))

   end subroutine commit_lanes

end module pound_newmark_batch
