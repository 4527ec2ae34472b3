!> The state of a joint during an analysis and what it has done: force, compression and its
!> rate, plastic penetration, open/closed/yielding/fractured, impacts, time in contact and
!> peaks; the update of one joint for an accepted step; the joints' histories.
!>
!> A joint is a spring (law of pound_contact_law: elastic stiffness k0, plastic penetration
!> d_p) with a dashpot c in parallel, in series with the gap: the force is
!> r = k0 (d - d_p) + c d', the dashpot rate d'_{n+1} = a (d_{n+1} - d_n) - b d'_n
!> ((a, b) = (2/dt, 1) trapezoidal, (1/dt, 0) backward Euler) and phat = k0 + a c.
module pound_joint_state
   use pound_kinds, only: dp
   use pound_contact_law, only: contact_law, is_plastic, yield_segment
   use pound_contact_pair, only: contact_pair
   implicit none
   private

   public :: joint_state, joint_advance, joints_advance, joints_advance_idle, plain_law
   public :: state_open, state_elastic, state_fractured
   public :: joint_history, joint_history_init, joint_history_record

   !> Joint state codes (per step; > 0: yielding on that yield segment, 1-based).
   integer, parameter :: state_open = 0, state_elastic = -1, state_fractured = -2

   !> The state of one joint and its tallies.
   type :: joint_state
      !> Compressive force r (kN), joint compression d (m) and its rate (m/s).
      real(dp) :: r = 0.0_dp, d = 0.0_dp, ddot = 0.0_dp
      !> Plastic penetration d_p (m) and the plastic increment of the last step (m).
      real(dp) :: plastic = 0.0_dp, x = 0.0_dp
      !> Closing displacement v = B^T u (m).
      real(dp) :: v = 0.0_dp
      !> State after the last step: `state_open`, `state_elastic`, `state_fractured` or the
      !> yield segment (1-based) the joint is yielding on.
      integer :: state = state_open
      !> The joint has fractured (carries nothing from then on), and when (s).
      logical :: fractured = .false.
      real(dp) :: fracture_time = 0.0_dp
      !> Number of impacts (open -> closed transitions).
      integer :: impacts = 0
      !> Time in contact (s), peak force (kN) and its time (s).
      real(dp) :: contact_time = 0.0_dp, peak_force = 0.0_dp, peak_time = 0.0_dp
      !> Largest compression d reached (m).
      real(dp) :: peak_penetration = 0.0_dp
      !> Smooth laws (pound_contact_smooth): the closing speed v' (m/s), the closing speed
      !> latched at the impact's start v0 (m/s; 0: open) and the offset of the step's tangent
      !> row (m); the step's previous Newton iterate (penetration m, law force kN).
      real(dp) :: vdot = 0.0_dp, v0 = 0.0_dp, shift = 0.0_dp, d_iter = 0.0_dp, f_iter = 0.0_dp
   end type joint_state

   !> Histories of every joint at the output samples, (n_pairs, n_out) each: what a
   !> result holds of the joints (filled by `joint_history_record`, not field by field).
   type :: joint_history
      !> Contact force r (kN), closing displacement v (m), joint compression d (m) and
      !> plastic penetration d_p (m).
      real(dp), allocatable :: force(:, :), closing(:, :), penetration(:, :), plastic(:, :)
      !> Joint state (`state_open`, `state_elastic`, `state_fractured` or the yield segment).
      integer, allocatable :: state(:, :)
      !> Contact points with friction (pound_contact_friction): the tangential force T on the
      !> right building (kN) and the committed slip s_p (m) of every joint (0 without
      !> friction); unallocated when no point has friction.
      real(dp), allocatable :: friction(:, :), slip(:, :)
   end type joint_history

contains

   !> Advance one joint over an accepted step: plastic penetration (landing exactly on a
   !> segment end passed within round-off), compression and its rate, state, tallies and the
   !> step's work. The spring-dashpot evolves by its own law also while the gap is open
   !> (r = 0): k0 (d - d_p) + c d' = 0 relaxes d, which stays d_p without a dashpot.
   pure subroutine joint_advance(j, law, r, x, v, t, dt, rate_a, rate_b, phat, work, element_work, &
                                 plastic_work)
      !> The joint.
      type(joint_state), intent(inout) :: j
      !> Its law.
      type(contact_law), intent(in) :: law
      !> Force (kN) and plastic increment (m) the step's LCP gave.
      real(dp), intent(in) :: r, x
      !> Closing displacement at the end of the step (m).
      real(dp), intent(in) :: v
      !> Time at the end of the step and time step (s).
      real(dp), intent(in) :: t, dt
      !> Dashpot rate coefficients a, b and phat = k0 + a c.
      real(dp), intent(in) :: rate_a, rate_b, phat
      !> Work of the contact force on the structure, work stored in or dissipated by the
      !> joint and its plastic part (kJ), accumulated.
      real(dp), intent(inout) :: work, element_work, plastic_work
      integer :: seg, ns
      real(dp) :: r0, d, ddot, pl, k0, rs0, rs, tol, c

      k0 = law%stiffness
      c = law%dashpot
      r0 = j%r
      if (stays_open(j, law, r)) then
         call open_step(j, r, x, v, rate_a, rate_b)
         return
      end if
      if (j%fractured) then
         ! The force r0 it carried is released over this step (the trapezoid, as the
         ! integrators take it): its work on the buildings is the joint's too, or the energy
         ! balance would miss it (a joint opened by a collapse, pound_storey_collapse).
         work = work + 0.5_dp*r0*(v - j%v)
         element_work = element_work + 0.5_dp*r0*(v - j%v)
         j%r = 0.0_dp
         j%v = v
         return
      end if
      pl = j%plastic + x
      seg = 0
      if (is_plastic(law)) then
         seg = yield_segment(law, pl)
         ns = size(law%yp) - 1
         if (ns > 0) then
            tol = 1.0e-9_dp*(law%yp(min(seg + 1, ns)) - law%yp(min(seg + 1, ns) - 1))
            if (seg < ns .and. law%yp(min(seg + 1, ns)) - pl <= tol) then
               seg = seg + 1
               pl = law%yp(seg)
            else if (seg > 0 .and. pl - law%yp(seg) <= tol) then
               pl = law%yp(seg)
            end if
         end if
      end if
      d = (r + c*(rate_a*j%d + rate_b*j%ddot) + k0*pl)/phat
      ddot = rate_a*(d - j%d) - rate_b*j%ddot
      rs0 = k0*(j%d - j%plastic)
      rs = k0*(d - pl)
      if (r > 0.0_dp) then
         if (r0 == 0.0_dp) j%impacts = j%impacts + 1
         j%contact_time = j%contact_time + dt
         if (r > j%peak_force) then
            j%peak_force = r
            j%peak_time = t
         end if
         j%state = state_elastic
         ! Yielding: on the segment the flow ended in (at a segment end, the one before).
         if (x > 0.0_dp) j%state = seg + merge(0, 1, seg > 0 .and. pl == law%yp(seg))
      else
         j%state = state_open
      end if
      work = work + 0.5_dp*(r0 + r)*(v - j%v)
      element_work = element_work + 0.5_dp*(r0 + r)*(d - j%d)
      plastic_work = plastic_work + 0.5_dp*(rs0 + rs)*x
      j%peak_penetration = max(j%peak_penetration, d)
      j%r = r
      j%d = d
      j%ddot = ddot
      j%v = v
      j%x = x
      j%plastic = pl
      if (law%fractures) then
         if (pl >= law%yp(size(law%yp) - 1)) then
            j%fractured = .true.
            j%fracture_time = t
            j%state = state_fractured
         end if
      end if
   end subroutine joint_advance

   !> Advance every joint over an accepted step, in order (`joint_advance` for each: one
   !> call for all, so that the per-joint update can be inlined into the loop).
   pure subroutine joints_advance(j, pairs, r, x, v, t, dt, rate_a, rate_b, phat, work, element_work, &
                                  plastic_work)
      !> The joints.
      type(joint_state), intent(inout) :: j(:)
      !> Their constraints (the laws).
      type(contact_pair), intent(in) :: pairs(:)
      !> Forces (kN), plastic increments (m) and closing displacements at the end of the
      !> step (m), one per joint.
      real(dp), intent(in) :: r(:), x(:), v(:)
      !> Time at the end of the step and time step (s).
      real(dp), intent(in) :: t, dt
      !> Per joint: dashpot rate coefficients a, b and phat = k0 + a c.
      real(dp), intent(in) :: rate_a(:), rate_b(:), phat(:)
      !> Work sums (kJ), accumulated as by `joint_advance`.
      real(dp), intent(inout) :: work, element_work, plastic_work
      integer :: k

      do k = 1, size(j)
         if (stays_open(j(k), pairs(k)%law, r(k))) then
            call open_step(j(k), r(k), x(k), v(k), rate_a(k), rate_b(k))
         else
            call joint_advance(j(k), pairs(k)%law, r(k), x(k), v(k), t, dt, rate_a(k), rate_b(k), phat(k), work, &
                               element_work, plastic_work)
         end if
      end do
   end subroutine joints_advance

   !> Advance every joint over a step in which none can act (the short path of
   !> `contact_step`: no force at its start, none at its end, no plastic flow): `joints_advance`
   !> with r = x = 0, a joint of a `plain_law` at d = 0 taken by `open_step` without testing
   !> its law again.
   !> (Explicit-shape arrays: the step of a few joints is not spent on array descriptors.)
   pure subroutine joints_advance_idle(m, j, pairs, plain, v, t, dt, rate_a, rate_b, phat, work, element_work, &
                                       plastic_work)
      !> Number of joints.
      integer, intent(in) :: m
      !> The joints (none carries force).
      type(joint_state), intent(inout) :: j(m)
      !> Their constraints (the laws).
      type(contact_pair), intent(in) :: pairs(m)
      !> Whether each joint's law is a `plain_law`.
      logical, intent(in) :: plain(m)
      !> Closing displacements at the end of the step (m), one per joint.
      real(dp), intent(in) :: v(m)
      !> Time at the end of the step and time step (s).
      real(dp), intent(in) :: t, dt
      !> Per joint: dashpot rate coefficients a, b and phat = k0 + a c.
      real(dp), intent(in) :: rate_a(m), rate_b(m), phat(m)
      !> Work sums (kJ), accumulated as by `joint_advance`.
      real(dp), intent(inout) :: work, element_work, plastic_work
      integer :: k

      do k = 1, m
         if (plain(k)) then
            ! `stays_open` with r = 0 and j%r = 0 (a plain law never fractures).
            if (j(k)%d == 0.0_dp) then
               call open_step(j(k), 0.0_dp, 0.0_dp, v(k), rate_a(k), rate_b(k))
               cycle
            end if
         end if
         call joint_advance(j(k), pairs(k)%law, 0.0_dp, 0.0_dp, v(k), t, dt, rate_a(k), rate_b(k), phat(k), work, &
                            element_work, plastic_work)
      end do
   end subroutine joints_advance_idle

   !> An elastic law without dashpot that does not fracture: a joint of it that carries no
   !> force and has no compression stays so while it is open (`stays_open`).
   pure logical function plain_law(law)
      !> The law.
      type(contact_law), intent(in) :: law

      plain_law = law%dashpot == 0.0_dp .and. .not. is_plastic(law) .and. .not. law%fractures
   end function plain_law

   !> An elastic joint without dashpot, open with no compression, that stays open (most
   !> joints in most steps): `open_step` is its whole update.
   pure logical function stays_open(j, law, r)
      type(joint_state), intent(in) :: j
      type(contact_law), intent(in) :: law
      real(dp), intent(in) :: r

      stays_open = r == 0.0_dp .and. j%r == 0.0_dp .and. j%d == 0.0_dp .and. .not. j%fractured .and. &
                   plain_law(law)
   end function stays_open

   !> The step of a joint that `stays_open`: d = 0, no force, no work; the same numbers as
   !> the general update of `joint_advance` (which would add only signed zeros to the work
   !> sums).
   pure subroutine open_step(j, r, x, v, rate_a, rate_b)
      type(joint_state), intent(inout) :: j
      real(dp), intent(in) :: r, x, v, rate_a, rate_b
      real(dp) :: pl

      pl = j%plastic + x
      j%ddot = rate_a*(0.0_dp - j%d) - rate_b*j%ddot
      j%peak_penetration = max(j%peak_penetration, 0.0_dp)
      j%state = state_open
      j%r = r
      j%d = 0.0_dp
      j%v = v
      j%x = x
      j%plastic = pl
   end subroutine open_step

   !> Histories for `m` joints and `n` output samples, the first sample (t = 0) at rest and
   !> open. `stat` /= 0 when the memory cannot be had (nothing is kept then).
   pure subroutine joint_history_init(h, m, n, stat)
      !> The histories.
      type(joint_history), intent(out) :: h
      !> Number of joints and of output samples.
      integer, intent(in) :: m, n
      !> Allocation status.
      integer, intent(out) :: stat

      allocate (h%force(m, n), h%closing(m, n), h%penetration(m, n), h%plastic(m, n), h%state(m, n), &
                stat=stat)
      if (stat /= 0) then
         h = joint_history()
         return
      end if
      if (n < 1) return
      h%force(:, 1) = 0.0_dp
      h%closing(:, 1) = 0.0_dp
      h%penetration(:, 1) = 0.0_dp
      h%plastic(:, 1) = 0.0_dp
      h%state(:, 1) = state_open
   end subroutine joint_history_init

   !> Store the joints' state as output sample k.
   pure subroutine joint_history_record(h, k, joints)
      !> The histories.
      type(joint_history), intent(inout) :: h
      !> Output sample.
      integer, intent(in) :: k
      !> The joints after the step.
      type(joint_state), intent(in) :: joints(:)
      integer :: ip

      do ip = 1, size(joints)
         h%force(ip, k) = joints(ip)%r
         h%closing(ip, k) = joints(ip)%v
         h%penetration(ip, k) = joints(ip)%d
         h%plastic(ip, k) = joints(ip)%plastic
         h%state(ip, k) = joints(ip)%state
      end do
   end subroutine joint_history_record

end module pound_joint_state
