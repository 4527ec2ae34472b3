!> The lanes of the Newmark integrator: one shear building (the fused tridiagonal path of
!> `pound_newmark`) under `max_lanes` ground motions at once. The motions share the factored
!> Khat, and every vector is held motion-fastest, x(lane, floor), so that the recurrences of
!> the tridiagonal solve of the lanes overlap and vectorise.
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
!> Lanes that carry no motion (fewer motions than `max_lanes`, a dropped motion) are driven by
!> a zero ground acceleration and stay at rest. The two kernels are internal procedures of
!> `newmark_advance_lanes`, so that they are inlined (gfortran gives a submodule's own
!> procedures external linkage): as procedures of their own the step takes about 3 % more time.
submodule(pound_newmark) pound_newmark_batch
   implicit none

contains

   !> Whether the lanes can run the model: the fused tridiagonal path (half-bandwidth 1, every
   !> DOF moved by the ground) and two DOFs or more.
   pure module logical function newmark_lanes_for(st, b)
      !> Integrator (initialised by `newmark_init`).
      class(newmark_state), intent(in) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b

      newmark_lanes_for = st%tridiagonal .and. b%n >= 2
   end function newmark_lanes_for

   !> Start every lane at rest relative to the ground, in equilibrium with its ground
   !> acceleration at t = 0 (as `newmark_init`), with the integrator's factors.
   module subroutine newmark_start_lanes(st, b, ag0, error)
      !> Integrator, initialised by `newmark_init` (its factors are taken).
      class(newmark_state), intent(inout) :: st
      !> The structural model (a shear building: kd = 1, every DOF moved by the ground).
      type(structure_model), intent(in) :: b
      !> Ground acceleration of each lane at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0(max_lanes)
      !> Error state: the model does not take the tridiagonal path.
      type(error_type), allocatable, intent(out) :: error
      integer :: i

      if (.not. newmark_lanes_for(st, b)) then
         call fatal_error(error, structure_label(b)//': the batched integration needs the tridiagonal path '// &
                          'and two floors or more')
         return
      end if
      if (allocated(st%lanes)) deallocate (st%lanes)
      allocate (st%lanes)
      associate (ln => st%lanes)
         allocate (ln%u(max_lanes, b%n), ln%v(max_lanes, b%n), ln%a(max_lanes, b%n), &
                   ln%cv(max_lanes, b%n), ln%du(max_lanes, b%n), source=0.0_dp)
         do i = 1, b%n
            ln%a(:, i) = -ag0*b%ground(i)
         end do
      end associate
   end subroutine newmark_start_lanes

   !> One step of every lane (predict and commit of `pound_newmark` with no other load), and the
   !> running peaks: `peak(l, q, i)` the absolute maximum so far of quantity q at floor i in
   !> lane l and `peak_time` when it first occurred (q = 1 u, 2 v, 3 absolute
   !> acceleration, 4 drift). Each lane's input work and kinetic + strain + damping energy are
   !> added to `w_in`, `e_out` (as `newmark_commit` adds them).
   module subroutine newmark_advance_lanes(st, b, ag_old, ag_new, t, peak, peak_time, w_in, e_out)
      !> Integrator with lanes.
      class(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration of each lane at the start and the end of the step (m/s^2), and the
      !> time at the end of the step (s).
      real(dp), intent(in) :: ag_old(max_lanes), ag_new(max_lanes), t
      !> Running peaks and their times (max_lanes, 4, n).
      real(dp), intent(inout), contiguous :: peak(:, :, :), peak_time(:, :, :)
      !> Each lane's input work and energy (added to).
      real(dp), intent(inout) :: w_in(max_lanes), e_out(max_lanes)
      real(dp) :: mdu(max_lanes), ddamp(max_lanes), dag(max_lanes)
      real(dp), volatile :: work(max_lanes)

      associate (ln => st%lanes)
         dag = ag_new - ag_old
         call predict_lanes(b%n, 2.0_dp*st%c2, dag, b%mass, ln%v, ln%a, ln%cv, st%e, st%dinv, ln%du)
         call commit_lanes(b%n, st%c1, st%c2, b%a0, b%a1, b%mass, b%kt, ln%du, ln%u, ln%v, ln%a, ln%cv, &
                           ag_new, t, peak, peak_time, mdu, ddamp, ln%kinetic, ln%strain)
         ln%damping_energy = ln%damping_energy + 0.5_dp*ddamp
         ! The work increment is rounded before it is subtracted, as `newmark_commit` does (its
         ! scalar code has no fused multiply-add there); a volatile store keeps the compiler from
         ! fusing it here.
         work = 0.5_dp*(ag_old + ag_new)*mdu
         ln%input_work = ln%input_work - work
         w_in = w_in + ln%input_work
         e_out = e_out + ((ln%kinetic + ln%strain) + ln%damping_energy)
      end associate

   contains

      !> du = Khat^{-1} (M (4/dt v + 2 a - 1 dag) + 2 C v) for every lane (`predict_kernel`).
      pure subroutine predict_lanes(n, c4, dag, mass, v, a, cv, e, dinv, du)
         integer, intent(in) :: n
         real(dp), intent(in) :: c4, dag(max_lanes), mass(n), v(max_lanes, n), a(max_lanes, n)
         real(dp), intent(in) :: cv(max_lanes, n), e(max(n - 1, 1)), dinv(n)
         real(dp), intent(out) :: du(max_lanes, n)
         integer :: i, l

         do l = 1, max_lanes
            du(l, 1) = mass(1)*(c4*v(l, 1) + 2.0_dp*a(l, 1) - dag(l)) + 2.0_dp*cv(l, 1)
         end do
         do i = 2, n
            do l = 1, max_lanes
               du(l, i) = mass(i)*(c4*v(l, i) + 2.0_dp*a(l, i) - dag(l)) + 2.0_dp*cv(l, i) - e(i - 1)*du(l, i - 1)
            end do
         end do
         do l = 1, max_lanes
            du(l, n) = du(l, n)*dinv(n)
         end do
         do i = n - 1, 1, -1
            do l = 1, max_lanes
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
         real(dp), intent(in) :: c1, c2, a0, a1, mass(n), kt(2, n), du(max_lanes, n), ag(max_lanes), t
         real(dp), intent(inout) :: u(max_lanes, n), v(max_lanes, n), a(max_lanes, n), cv(max_lanes, n)
         real(dp), intent(inout) :: peak(max_lanes, 4, n), peak_time(max_lanes, 4, n)
         real(dp), intent(out) :: mdu(max_lanes), ddamp(max_lanes), ek(max_lanes), es(max_lanes)
         real(dp) :: sm(max_lanes, 0:3), sk(max_lanes, 0:3), sd(max_lanes, 0:3), ss(max_lanes, 0:3)
         real(dp) :: cvi, x, below
         integer :: i, j, l, q, r

         sm = 0.0_dp
         sk = 0.0_dp
         sd = 0.0_dp
         ss = 0.0_dp
         ! Floors 1 and 2 updated (partial sums 0 and 1), C v of floor 1 (partial sum 3, assigned).
         do j = 1, 2
            do l = 1, max_lanes
               a(l, j) = c1*du(l, j) - 2.0_dp*c2*v(l, j) - a(l, j)
               v(l, j) = c2*du(l, j) - v(l, j)
               u(l, j) = u(l, j) + du(l, j)
               sm(l, j - 1) = sm(l, j - 1) + mass(j)*du(l, j)
               sk(l, j - 1) = sk(l, j - 1) + mass(j)*v(l, j)*v(l, j)
            end do
         end do
         do l = 1, max_lanes
            cvi = a0*mass(1)*v(l, 1) + a1*(kt(2, 1)*v(l, 1) + kt(1, 2)*v(l, 2))
            sd(l, 3) = du(l, 1)*(cv(l, 1) + cvi)
            ss(l, 3) = -(kt(2, 1) + kt(1, 2))*u(l, 1)*u(l, 1)
            cv(l, 1) = cvi
         end do
         do i = 2, n - 1
            j = i + 1
            q = iand(i, 3)
            r = iand(i + 2, 3)
            do l = 1, max_lanes
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
         do l = 1, max_lanes
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
            do l = 1, max_lanes
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
   end subroutine newmark_advance_lanes

   !> Lane l's u, v, a and energies as the integrator's own state (what `newmark_u`,
   !> `kinetic_energy`, `energies` ... read); the single state's C v and du are left as they are.
   module subroutine newmark_show_lane(st, l)
      !> Integrator with lanes.
      class(newmark_state), intent(inout) :: st
      !> Lane.
      integer, intent(in) :: l

      st%u(:) = st%lanes%u(l, :)
      st%v(:) = st%lanes%v(l, :)
      st%a(:) = st%lanes%a(l, :)
      st%input_work = st%lanes%input_work(l)
      st%damping_energy = st%lanes%damping_energy(l)
      st%kinetic = st%lanes%kinetic(l)
      st%strain = st%lanes%strain(l)
   end subroutine newmark_show_lane

   !> Bring lane l to rest (zero state and energies): a motion dropped from the lanes.
   module subroutine newmark_drop_lane(st, l)
      !> Integrator with lanes.
      class(newmark_state), intent(inout) :: st
      !> Lane.
      integer, intent(in) :: l

      associate (ln => st%lanes)
         ln%u(l, :) = 0.0_dp
         ln%v(l, :) = 0.0_dp
         ln%a(l, :) = 0.0_dp
         ln%cv(l, :) = 0.0_dp
         ln%du(l, :) = 0.0_dp
         ln%input_work(l) = 0.0_dp
         ln%damping_energy(l) = 0.0_dp
         ln%kinetic(l) = 0.0_dp
         ln%strain(l) = 0.0_dp
      end associate
   end subroutine newmark_drop_lane

end submodule pound_newmark_batch
