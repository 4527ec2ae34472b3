!> Steps with elastic joints closed (`stepping = 'impact'` with `free_steps = 'exact'`): in a
!> step that starts with joints carrying force, when every such joint has an elastic law
!> without dashpot (`plain_law`, not smooth) and its ends at DOFs with a mass (or a rigid
!> neighbour), and every other joint is open at rest (or fractured), the step is taken in the
!> condensed modes of the buildings instead of as Newmark substeps of every DOF.
!>
!> The DOFs without mass carry no joint force, so their elastic forces relax as exp(-t/a1)
!> and the DOFs with mass follow the condensed system exactly (as in an exact free step,
!> pound_newmark_exact). In each building's condensed modes (q = Phi^T M u_m, mass-normalised,
!> omega^2 = Lambda, modal damping c = a0 + a1 omega^2, gamma = Phi^T M r) and with the
!> closed joints' forces r_j = k_j (w^_j . q - g_j) (w^_j = Phi^T w_j, w_j the joint's
!> incidence: +1 left end, -1 right end; both buildings' modes stacked):
!>
!>   q'' + c q' + Lambda q = p(t) = -gamma a_g(t) - sum_j w^_j r_j(t).
!>
!> The step of dt is cut into m substeps of h = dt/m (m: the automatic impact substep count,
!> set by the joints' contact half-period, or `impact_substeps`). Over each substep the modal
!> load p is taken linear between its ends (a_g linear over dt, as in an exact free step; the
!> joint forces linear between the substep ends: the trapezoidal rule of Newmark's substeps),
!> and each mode's response to it is exact (`modal_step_coefficients`: q1 = A q0 + B q0' +
!> C p0 + D p1). The forces at the substep's end are implicit, r1 = K (W^T q1 - g) with
!> q1 = q_pred - D W r1, so (I + K W^T D W) r1 = K (W^T q_pred - g): an r x r system per set
!> of closed joints (inverted once when the set is first met). The error is second order in h
!> through the joint forces alone (the structure's own response is exact), no larger than that
!> of the Newmark substeps it replaces; the cost is a few multiply-adds per mode and substep
!> and no factorisation, instead of m solves, contact steps and response samples of every
!> DOF. The response is sampled at the step's ends only; its peaks between them are refined
!> as those of an exact free step (`refine_peaks` of pound_response, the cubic Hermite path
!> through the samples' values and rates).
!>
!> The step is kept only if it is valid: at every substep's end each closed joint still
!> carries compression and every other joint is still open, and between the substep ends the
!> cubic Hermite path of each closing displacement (values and rates at the ends) stays on the
!> same side of the gap. Otherwise nothing is changed and the caller takes the step as impact
!> substeps (Newmark, the LCP deciding the contact), as before: the steps in which a joint
!> closes or opens are always substepped.
!>
!> Energy: the kinetic and strain energy are those of the end state, from the coordinates;
!> each building's input work -int a_g gamma^T q' dt is summed by the trapezoidal rule over the
!> substeps; the joints' work is that of `contact_commit`, (r0 + r1)/2 (d1 - d0), exact for a
!> linear spring, split over the buildings by the same rule; the damping energy of each
!> building is the balance (so over such a step the audit measures round-off, not the
!> damping).
module pound_closed_steps
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_structure, only: structure_model
   use pound_band_lapack, only: dsygv
   use pound_modal_step, only: modal_step_response
   use pound_integrator, only: integrator
   use pound_newmark, only: newmark_state, newmark_u, newmark_v, newmark_u_at, newmark_v_at, newmark_put_state
   use pound_contact, only: contact_system
   use pound_contact_pair, only: end_sign
   use pound_law_smooth, only: is_smooth
   use pound_response, only: response_record, response_peaks_inside
   implicit none
   private

   public :: closed_stepper, closed_init, closed_step, hermite_extreme, closed_max_dofs

   !> Largest number of DOFs with mass (all buildings) for which closed steps are set up.
   integer, parameter :: closed_max_dofs = 400
   !> Most sets of closed joints set up in one run (more are substepped).
   integer, parameter :: max_sets = 64
   !> The peaks of v and a_abs are kept at every `inside_stride`-th
   !> substep end inside a step: with the automatic substep count (60 substeps a contact
   !> half-period with exact free steps) 30 samples a half-period, a peak within
   !> 1 - cos(pi/60) = 0.14 % of its value.
   integer, parameter :: inside_stride = 2
   !> Modal coordinates, rates and step coefficients below this are set to zero (as in
   !> pound_newmark_exact: no subnormal numbers).
   real(dp), parameter :: negligible = 1.0e-100_dp
   !> Largest number of joints (the set is a bit mask).
   integer, parameter :: max_joints = 62

   !> One building's condensed modes and its massless DOFs' data.
   type :: closed_building
      !> DOFs, DOFs with mass, without, and the offset of its modes among all buildings'.
      integer :: n = 0, nm = 0, ns = 0, off = 0
      !> The DOFs without mass, and each DOF's place among those with mass (0: none).
      integer, allocatable :: is(:), pos(:)
      !> Modes (nm, nm), omega^2, modal damping, gamma = Phi^T M r (nm).
      real(dp), allocatable :: phi(:, :), lam(:), cm(:), gam(:)
      !> K_ss^-1 (ns, ns).
      real(dp), allocatable :: kssi(:, :)
      !> Over all n DOFs: the shapes with the static rows without mass (-K_ss^-1 K_sm phi)
      !> (n, nm); (M phi)^T (nm, n) (q = phimt u) and (K_sm | K_ss) (ns, n) (g = kgt u).
      real(dp), allocatable :: phin(:, :), phimt(:, :), kgt(:, :)
      !> The shapes at the response points (n_points, nm): v and a there inside a step.
      real(dp), allocatable :: pf(:, :)
      !> exp(-h/a1) (0 without stiffness-proportional damping) and 1/a1.
      real(dp) :: decay = 0.0_dp, ra1 = 0.0_dp
   end type closed_building

   !> One set of closed joints.
   type :: closed_config
      !> The set: bit k-1 for joint k.
      integer(int64) :: key = 0
      !> Its joints (r) and the others (open), and (I + K W^T D W)^-1 K (r, r) (see the
      !> module doc).
      integer, allocatable :: joint(:), open(:)
      real(dp), allocatable :: hk(:, :)
      !> Whether the set can be stepped (its ends have a mass).
      logical :: ok = .false.
   end type closed_config

   !> Closed steps of one analysis: the buildings' modes, the sets set up, the work arrays.
   type :: closed_stepper
      !> Whether closed steps are taken in this analysis.
      logical :: on = .false.
      !> The step (s).
      real(dp) :: h = 0.0_dp
      !> Modes of all buildings, buildings, sets set up.
      integer :: nmt = 0, nb = 0, ncfg = 0
      !> Each building's modes.
      type(closed_building), allocatable :: b(:)
      !> The sets met (`max_sets`).
      type(closed_config), allocatable :: cfg(:)
      !> Substeps per step, and the substep (s).
      integer :: m = 1
      real(dp) :: hs = 0.0_dp
      !> Each mode's substep coefficients against (q0, q0', p0, p1) (nmt, 8): q1 from 1:4,
      !> q1' from 5:8.
      real(dp), allocatable :: cf(:, :)
      !> w^_j of every joint (nmt, n_joints), and its stiffness and gap; whether both its
      !> ends have a mass (or are the rigid neighbour).
      real(dp), allocatable :: w(:, :), kj(:), gap(:)
      logical, allocatable :: joint_ok(:)
      !> Coordinates and rates (nmt) now, the modal load now and at the substep's end, the
      !> prediction, and q'' at the end; the closing displacements and rates of every joint
      !> at the substep's start and end; the closed joints' forces (n_joints).
      real(dp), allocatable :: q(:), qd(:), p0(:), p1(:), qp(:), qdd(:), d0(:), dd0(:), d1(:), dd1(:), r(:), rhs(:)
      !> omega^2, modal damping and gamma of every building's modes, in turn (nmt).
      real(dp), allocatable :: lam(:), cm(:), gam(:)
      !> End state of each building (n_max, nb), the massless DOFs' forces at the start
      !> (n_max, nb), each building's share of the joints' work and its input work (nb).
      real(dp), allocatable :: ue(:, :), ve(:, :), ae(:, :), g0(:, :), jw(:), win(:)
      !> Twice the strain energy of each building's massless DOFs' forces at the step's end (nb).
      real(dp), allocatable :: ez(:)
      !> Each joint's largest force at the substeps' ends inside the step and its time.
      real(dp), allocatable :: rmax(:), tmax(:)
      !> v and a at the response points at the substeps' ends inside the step (points, m, nb),
      !> the ground acceleration there (m): the peaks inside, kept once the step is valid.
      real(dp), allocatable :: vin(:, :, :), ain(:, :, :), agin(:)
      !> Work arrays of the products by columns (n_max, 3).
      real(dp), allocatable :: xin(:, :), xout(:, :)
      !> Steps taken closed, and the step (of the time loop) of the last one.
      integer :: steps = 0, last = -1
   end type closed_stepper

   interface
      subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgesv
      subroutine dposv(uplo, n, nrhs, a, lda, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: info
      end subroutine dposv
   end interface

contains

   !> Set up closed steps for the buildings and joints of an analysis at step dt with m
   !> substeps: each building's condensed modes, each mode's substep, each joint's w^. Off
   !> (`cl%on` false) when a joint end is a row of several DOFs, the buildings are too large,
   !> one has no mass, or its modes cannot be had; the analysis then substeps as before.
   subroutine closed_init(cl, models, cs, dt, m)
      !> Closed steps (set up).
      type(closed_stepper), intent(out) :: cl
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The contact system.
      type(contact_system), intent(in) :: cs
      !> Time step (s).
      real(dp), intent(in) :: dt
      !> Substeps per step.
      integer, intent(in) :: m
      integer :: ib, off, nmax, i, k, e, bb, p, nj
      logical :: ok

      cl%h = dt
      cl%m = max(1, m)
      cl%hs = dt/real(cl%m, dp)
      cl%nb = size(models)
      nj = cs%m
      if (nj == 0 .or. nj > max_joints .or. cs%general_ends) return
      if (sum([(count(models(ib)%mass > 0.0_dp), ib=1, cl%nb)]) > closed_max_dofs) return
      allocate (cl%b(cl%nb))
      off = 0
      do ib = 1, cl%nb
         call building_modes(models(ib), dt, cl%b(ib), ok)
         if (.not. ok) return
         cl%b(ib)%off = off
         off = off + cl%b(ib)%nm
      end do
      cl%nmt = off
      allocate (cl%lam(off), cl%cm(off), cl%gam(off), cl%cf(off, 8))
      do ib = 1, cl%nb
         associate (cb => cl%b(ib))
            cl%lam(cb%off + 1:cb%off + cb%nm) = cb%lam
            cl%cm(cb%off + 1:cb%off + cb%nm) = cb%cm
            cl%gam(cb%off + 1:cb%off + cb%nm) = cb%gam
         end associate
      end do
      ! A mode's step under the load p linear from p0 to p1 (the ground's with gamma = -1).
      do i = 1, off
         cl%cf(i, :) = modal_step_response(cl%lam(i), cl%cm(i), -1.0_dp, cl%hs)
      end do
      where (abs(cl%cf) < negligible) cl%cf = 0.0_dp
      if (.not. all(ieee_is_finite(cl%cf))) return
      ! w^_j = Phi^T w_j of every joint (0 where an end has no mass: such a joint cannot be
      ! closed in a closed step, `joint_ok`).
      allocate (cl%w(off, nj), cl%kj(nj), cl%gap(nj), cl%joint_ok(nj))
      cl%w = 0.0_dp
      cl%joint_ok = .true.
      do k = 1, nj
         cl%kj(k) = cs%pair(k)%law%stiffness
         cl%gap(k) = cs%pair(k)%gap
         do e = 1, 2
            bb = cs%ends(2*e - 1, k)
            if (bb == 0) cycle
            p = cl%b(bb)%pos(cs%ends(2*e, k))
            if (p == 0) then
               cl%joint_ok(k) = .false.
               cycle
            end if
            associate (cb => cl%b(bb))
               cl%w(cb%off + 1:cb%off + cb%nm, k) = cl%w(cb%off + 1:cb%off + cb%nm, k) + end_sign(e)*cb%phi(p, :)
            end associate
         end do
      end do
      nmax = maxval(models%n)
      allocate (cl%cfg(max_sets))
      allocate (cl%q(off), cl%qd(off), cl%p0(off), cl%p1(off), cl%qp(off), cl%qdd(off))
      allocate (cl%d0(nj), cl%dd0(nj), cl%d1(nj), cl%dd1(nj), cl%r(nj), cl%rhs(nj), cl%rmax(nj), cl%tmax(nj))
      allocate (cl%ue(nmax, cl%nb), cl%ve(nmax, cl%nb), cl%ae(nmax, cl%nb), cl%g0(nmax, cl%nb), cl%jw(cl%nb), &
                cl%win(cl%nb), cl%ez(cl%nb))
      allocate (cl%xin(nmax, 3), cl%xout(nmax, 3))
      allocate (cl%vin(maxval([(size(models(ib)%floor_dof), ib=1, cl%nb)]), cl%m, cl%nb), cl%agin(cl%m))
      allocate (cl%ain, mold=cl%vin)
      cl%on = .true.
   end subroutine closed_init

   !> The condensed modes of one building (as `condensed_modes` of pound_newmark_exact).
   subroutine building_modes(b, h, cb, ok)
      type(structure_model), intent(in) :: b
      real(dp), intent(in) :: h
      type(closed_building), intent(inout) :: cb
      logical, intent(out) :: ok
      real(dp), allocatable :: k(:, :), kc(:, :), mm(:, :), rhs(:, :), fac(:, :), work(:), tsm(:, :), ksm(:, :)
      integer, allocatable :: im(:)
      integer :: n, nm, ns, i, j, info

      ok = .false.
      n = b%n
      nm = count(b%mass > 0.0_dp)
      ns = n - nm
      if (nm == 0) return
      cb%n = n
      cb%nm = nm
      cb%ns = ns
      if (b%a1 > 0.0_dp) then
         cb%ra1 = 1.0_dp/b%a1
         cb%decay = exp(-h/b%a1)
      end if
      im = pack([(i, i=1, n)], b%mass > 0.0_dp)
      cb%is = pack([(i, i=1, n)], .not. (b%mass > 0.0_dp))
      allocate (cb%pos(n))
      cb%pos = 0
      cb%pos(im) = [(i, i=1, nm)]
      allocate (k(n, n))
      k = 0.0_dp
      do j = 1, n
         do i = max(1, j - b%kd), j
            k(i, j) = b%kt(b%kd + 1 + i - j, j)
            k(j, i) = k(i, j)
         end do
      end do
      kc = k(im, im)
      allocate (cb%phin(n, nm), cb%kgt(ns, n))
      if (ns > 0) then
         ksm = k(cb%is, im)
         allocate (rhs(ns, nm + ns))
         rhs(:, 1:nm) = ksm
         rhs(:, nm + 1:) = 0.0_dp
         do i = 1, ns
            rhs(i, nm + i) = 1.0_dp
         end do
         fac = k(cb%is, cb%is)
         call dposv('U', ns, nm + ns, fac, ns, rhs, ns, info)
         if (info /= 0) return
         tsm = rhs(:, 1:nm)
         cb%kssi = rhs(:, nm + 1:)
         kc = kc - matmul(transpose(ksm), tsm)
         kc = 0.5_dp*(kc + transpose(kc))
         cb%kgt = k(cb%is, :)
      end if
      allocate (mm(nm, nm), work(max(1, 64*nm)), cb%lam(nm))
      mm = 0.0_dp
      do i = 1, nm
         mm(i, i) = b%mass(im(i))
      end do
      call dsygv(1, 'V', 'U', nm, kc, nm, mm, nm, cb%lam, work, size(work), info)
      if (info /= 0) return
      cb%phi = kc
      cb%cm = b%a0 + b%a1*cb%lam
      cb%gam = matmul(transpose(cb%phi), b%mass(im)*b%ground(im))
      allocate (cb%phimt(nm, n))
      cb%phimt = 0.0_dp
      cb%phin = 0.0_dp
      do i = 1, nm
         cb%phimt(i, im) = b%mass(im)*cb%phi(:, i)
         cb%phin(im, i) = cb%phi(:, i)
      end do
      if (ns > 0) cb%phin(cb%is, :) = -matmul(tsm, cb%phi)
      cb%pf = cb%phin(b%floor_dof, :)
      ok = all(ieee_is_finite(cb%phi)) .and. all(ieee_is_finite(cb%lam))
   end subroutine building_modes

   !> Try the step from the integrators' state as an exact step of the closed joints (those
   !> carrying force). On success the integrators hold the step's end (`newmark_put_state`)
   !> and `cs%r_new`, `cs%x_new` the joints' forces at the end (for `contact_commit`); `taken`
   !> is false when the step must be substepped (nothing changed then).
   subroutine closed_step(cl, st, models, cs, ag0, ag1, step, taken, rec, t0)
      !> Closed steps.
      type(closed_stepper), intent(inout) :: cl
      !> The integrators (state at the start of the step).
      class(integrator), intent(inout), target :: st(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The contact system (state at the start of the step).
      type(contact_system), intent(inout) :: cs
      !> Ground acceleration at the start and the end of the step (m/s^2).
      real(dp), intent(in) :: ag0, ag1
      !> The step of the time loop (a closed step right after another starts from its
      !> coordinates).
      integer, intent(in) :: step
      !> Whether the step was taken.
      logical, intent(out) :: taken
      !> Each building's response record (the peaks of v and a_abs inside the step), and the
      !> time at the step's start (s).
      type(response_record), intent(inout) :: rec(:)
      real(dp), intent(in) :: t0

      taken = .false.
      if (.not. cl%on) return
      select type (st)
      type is (newmark_state)
         call closed_newmark(cl, st, models, cs, ag0, ag1, step, taken, rec, t0)
      end select
   end subroutine closed_step

   !> `closed_step` of Newmark integrators.
   subroutine closed_newmark(cl, st, models, cs, ag0, ag1, step, taken, rec, t0)
      type(closed_stepper), intent(inout) :: cl
      type(newmark_state), intent(inout), target :: st(:)
      type(structure_model), intent(in) :: models(:)
      type(contact_system), intent(inout) :: cs
      real(dp), intent(in) :: ag0, ag1
      integer, intent(in) :: step
      logical, intent(out) :: taken
      type(response_record), intent(inout) :: rec(:)
      real(dp), intent(in) :: t0
      integer(int64) :: key
      integer :: k, ic, ib, e, bb, nmt, i, j, l, nr, nj
      real(dp) :: w0, w1, a1, s0
      real(dp), pointer, contiguous :: u(:), v(:)

      taken = .false.
      key = 0
      do k = 1, cs%m
         if (cs%joint(k)%fractured) cycle
         if (cs%joint(k)%r > 0.0_dp) then
            if (.not. (cs%plain(k) .and. cl%joint_ok(k))) return
            if (allocated(cs%pair(k)%law%given)) then
               if (is_smooth(cs%pair(k)%law%given)) return
            end if
            key = ibset(key, k - 1)
         else if (.not. (cs%plain(k) .and. cs%joint(k)%d == 0.0_dp)) then
            return
         end if
      end do
      ic = find_config(cl, key)
      if (ic == 0) return
      nmt = cl%nmt
      ! Start: modal coordinates of each building, and the massless DOFs' elastic forces
      ! (after a closed step: its end's, held in q, qd and g0).
      if (cl%last /= step - 1) then
         do ib = 1, cl%nb
            associate (cb => cl%b(ib))
               u => newmark_u(st(ib))
               v => newmark_v(st(ib))
               cl%xin(1:cb%n, 1) = u
               cl%xin(1:cb%n, 2) = v
               call mvk(cb%nm, cb%n, 2, cb%phimt, cl%xin(1:cb%n, 1:2), cl%xout(1:cb%nm, 1:2))
               cl%qp(cb%off + 1:cb%off + cb%nm) = cl%xout(1:cb%nm, 1)
               cl%p1(cb%off + 1:cb%off + cb%nm) = cl%xout(1:cb%nm, 2)
               if (cb%ns > 0) call mv(cb%ns, cb%n, cb%kgt, u, cl%g0(1:cb%ns, ib))
            end associate
         end do
         cl%q = cl%qp
         cl%qd = cl%p1
      end if
      nr = size(cl%cfg(ic)%joint)
      nj = cs%m
      ! Closing displacements and rates of every joint now, the closed joints' forces and the
      ! modal load.
      call closing(nmt, nr, cl%cfg(ic)%joint, cl%w, cl%q, cl%qd, cl%d0, cl%dd0)
      call closing(nmt, nj - nr, cl%cfg(ic)%open, cl%w, cl%q, cl%qd, cl%d0, cl%dd0)
      cl%r = 0.0_dp
      cl%p0 = -cl%gam*ag0
      do l = 1, nr
         k = cl%cfg(ic)%joint(l)
         cl%r(k) = cl%kj(k)*(cl%d0(k) - cl%gap(k))
         cl%p0 = cl%p0 - cl%w(:, k)*cl%r(k)
      end do
      cl%win = 0.0_dp
      cl%rmax = 0.0_dp
      a1 = ag0
      call input_rate(cl, cl%qd, a1, cl%win, 0.5_dp*cl%hs)
      do j = 1, cl%m
         a1 = ag0 + (ag1 - ag0)*real(j, dp)/real(cl%m, dp)
         call substep(nmt, nj, nr, cl%cfg(ic)%joint, cl%cf, cl%gam, cl%w, cl%cfg(ic)%hk, cl%gap, a1, cl%q, cl%qd, &
                      cl%p0, cl%p1, cl%qp, cl%rhs, cl%r)
         cl%p0 = cl%p1
         ! Validity: closed joints in compression at the substep's end.
         do l = 1, nr
            if (.not. (cl%r(cl%cfg(ic)%joint(l)) > 0.0_dp)) return
         end do
         do l = 1, nr
            k = cl%cfg(ic)%joint(l)
            if (cl%r(k) > cl%rmax(k) .and. j < cl%m) then
               cl%rmax(k) = cl%r(k)
               cl%tmax(k) = t0 + real(j, dp)*cl%hs
            end if
         end do
         if (j < cl%m .and. mod(j, inside_stride) == 0) then
            ! v and a at the response points (the relaxation of the massless DOFs' forces
            ! left out inside the step).
            call modal_acceleration(nmt, cl%p1, cl%lam, cl%cm, cl%q, cl%qd, cl%qdd)
            cl%agin(j) = a1
            do ib = 1, cl%nb
               associate (cb => cl%b(ib), o => cl%b(ib)%off, np => size(cl%b(ib)%pf, 1))
                  call mv2(np, cb%nm, cb%pf, cl%qd(o + 1:o + cb%nm), cl%qdd(o + 1:o + cb%nm), cl%vin(1:np, j, ib), &
                           cl%ain(1:np, j, ib))
               end associate
            end do
         end if
         s0 = 0.5_dp*cl%hs
         if (j == cl%m) s0 = 0.0_dp
         call input_rate(cl, cl%qd, a1, cl%win, 0.5_dp*cl%hs + s0)
      end do
      ! The other joints open along the step: the Hermite path of their closing displacement
      ! through its values and rates at the step's ends (as `contact_may_act` for an exact
      ! free step) stays short of the gap.
      call closing(nmt, nj - nr, cl%cfg(ic)%open, cl%w, cl%q, cl%qd, cl%d1, cl%dd1)
      do l = 1, nj - nr
         k = cl%cfg(ic)%open(l)
         if (cs%joint(k)%fractured) cycle
         if (hermite_extreme(cl%d0(k), cl%dd0(k), cl%d1(k), cl%dd1(k), cl%h, .false.) >= cl%gap(k)) return
      end do
      ! q'' at the end (the load p1 includes the ground and the joints).
      call modal_acceleration(nmt, cl%p1, cl%lam, cl%cm, cl%q, cl%qd, cl%qdd)
      if (.not. (all(ieee_is_finite(cl%q)) .and. all(ieee_is_finite(cl%qd)))) return
      ! End state of each building: u = phin q (rows without mass: their static part), plus
      ! the relaxation of the massless DOFs' forces.
      do ib = 1, cl%nb
         associate (cb => cl%b(ib), o => cl%b(ib)%off)
            cl%xin(1:cb%nm, 1) = cl%q(o + 1:o + cb%nm)
            cl%xin(1:cb%nm, 2) = cl%qd(o + 1:o + cb%nm)
            cl%xin(1:cb%nm, 3) = cl%qdd(o + 1:o + cb%nm)
            call mvk(cb%n, cb%nm, 3, cb%phin, cl%xin(1:cb%nm, 1:3), cl%xout(1:cb%n, 1:3))
            cl%ue(1:cb%n, ib) = cl%xout(1:cb%n, 1)
            cl%ve(1:cb%n, ib) = cl%xout(1:cb%n, 2)
            cl%ae(1:cb%n, ib) = cl%xout(1:cb%n, 3)
            cl%ez(ib) = 0.0_dp
            if (cb%ns > 0) call massless_end(cb, cl%g0(1:cb%ns, ib), cl%ue(1:cb%n, ib), cl%ve(1:cb%n, ib), &
                                             cl%ae(1:cb%n, ib), cl%ez(ib))
         end associate
      end do
      ! The joints' forces at the end (for `contact_commit`) and each building's share of
      ! their work over the step (trapezoidal).
      cl%jw = 0.0_dp
      do k = 1, cs%m
         cs%r_new(k) = 0.0_dp
         if (cs%joint(k)%fractured .or. .not. btest(key, k - 1)) cycle
         cs%r_new(k) = cl%r(k)
         do e = 1, 2
            bb = cs%ends(2*e - 1, k)
            if (bb == 0) cycle
            i = cs%ends(2*e, k)
            w0 = newmark_u_at(st(bb), i)
            w1 = cl%ue(i, bb)
            cl%jw(bb) = cl%jw(bb) - end_sign(e)*0.5_dp*(cs%joint(k)%r + cs%r_new(k))*(w1 - w0)
         end do
      end do
      ! The energies from the coordinates: kinetic q'^T q'/2 (mass-normalised modes; the DOFs
      ! without mass have none), strain (sum omega^2 q^2 + g^T K_ss^-1 g)/2.
      do ib = 1, cl%nb
         associate (n => models(ib)%n, cb => cl%b(ib), o => cl%b(ib)%off)
            call newmark_put_state(st(ib), cl%ue(1:n, ib), cl%ve(1:n, ib), cl%ae(1:n, ib), &
                                   0.5_dp*sum(cl%qd(o + 1:o + cb%nm)**2), &
                                   0.5_dp*(sum(cb%lam*cl%q(o + 1:o + cb%nm)**2) + cl%ez(ib)), cl%win(ib), cl%jw(ib))
            ! The next closed step starts from these coordinates.
            cl%g0(1:cb%ns, ib) = cb%decay*cl%g0(1:cb%ns, ib)
         end associate
      end do
      do ib = 1, cl%nb
         associate (np => size(cl%b(ib)%pf, 1))
            do j = inside_stride, cl%m - 1, inside_stride
               call response_peaks_inside(rec(ib), cl%vin(1:np, j, ib), cl%ain(1:np, j, ib), cl%agin(j), &
                                          t0 + real(j, dp)*cl%hs)
            end do
         end associate
      end do
      ! The joints' peaks inside the step (the end's are `contact_commit`'s).
      do k = 1, cs%m
         if (cl%rmax(k) > cs%joint(k)%peak_force) then
            cs%joint(k)%peak_force = cl%rmax(k)
            cs%joint(k)%peak_time = cl%tmax(k)
            cs%joint(k)%peak_penetration = max(cs%joint(k)%peak_penetration, cl%rmax(k)/cl%kj(k))
         end if
      end do
      cl%last = step
      cs%x_new = 0.0_dp
      cs%idle = .false.
      cl%steps = cl%steps + 1
      taken = .true.
   end subroutine closed_newmark

   !> Closing displacement w^_k . q and rate w^_k . q' of the joints k in `list`.
   pure subroutine closing(n, nl, list, w, q, qd, d, dd)
      integer, intent(in) :: n, nl, list(nl)
      real(dp), intent(in) :: w(:, :), q(n), qd(n)
      real(dp), intent(inout) :: d(:), dd(:)
      integer :: l, k

      do l = 1, nl
         k = list(l)
         d(k) = dot8(n, w(:, k), q)
         dd(k) = dot8(n, w(:, k), qd)
      end do
   end subroutine closing

   !> x . y in eight partial sums (the sums vectorise; the order is fixed).
   pure real(dp) function dot8(n, x, y) result(s)
      integer, intent(in) :: n
      real(dp), intent(in) :: x(n), y(n)
      real(dp) :: p(8)
      integer :: i, n8

      p = 0.0_dp
      n8 = n - mod(n, 8)
      do i = 1, n8, 8
         p = p + x(i:i + 7)*y(i:i + 7)
      end do
      s = ((p(1) + p(5)) + (p(2) + p(6))) + ((p(3) + p(7)) + (p(4) + p(8)))
      do i = n8 + 1, n
         s = s + x(i)*y(i)
      end do
   end function dot8

   !> One substep of the modes under the load linear from p0 to p1 = -gamma a_g1 - W r1, r1 the
   !> closed joints' forces at its end (implicit: r1 = H^-1 K (W^T q_pred - g)); q, q' advanced,
   !> p1 and r (the closed joints' entries) set.
   pure subroutine substep(n, nj, nr, joint, cf, gam, w, hk, gap, a1, q, qd, p0, p1, qp, rhs, r)
      integer, intent(in) :: n, nj, nr, joint(nr)
      real(dp), intent(in) :: cf(n, 8), gam(n), w(n, nj), hk(nr, nr), gap(nj), a1, p0(n)
      real(dp), intent(inout) :: q(n), qd(n), r(nj)
      real(dp), intent(out) :: p1(n), qp(n), rhs(nr)
      integer :: i, l, k
      real(dp) :: x

      !GCC$ vector
      do i = 1, n
         qp(i) = cf(i, 1)*q(i) + cf(i, 2)*qd(i) + cf(i, 3)*p0(i) - cf(i, 4)*gam(i)*a1
         p1(i) = -gam(i)*a1
      end do
      do l = 1, nr
         k = joint(l)
         rhs(l) = dot8(n, w(:, k), qp) - gap(k)
      end do
      do l = 1, nr
         k = joint(l)
         x = 0.0_dp
         do i = 1, nr
            x = x + hk(l, i)*rhs(i)
         end do
         r(k) = x
         !GCC$ vector
         do i = 1, n
            p1(i) = p1(i) - w(i, k)*x
         end do
      end do
      ! The stiff, over-damped modes decay to subnormal numbers, which slow every product
      ! with them many times: below `negligible` they are zero.
      !GCC$ vector
      do i = 1, n
         x = cf(i, 5)*q(i) + cf(i, 6)*qd(i) + cf(i, 7)*p0(i) + cf(i, 8)*p1(i)
         qd(i) = merge(0.0_dp, x, abs(x) < negligible)
         x = qp(i) + cf(i, 4)*(p1(i) + gam(i)*a1)
         q(i) = merge(0.0_dp, x, abs(x) < negligible)
      end do
   end subroutine substep

   !> q'' = p - lambda q - c q'.
   pure subroutine modal_acceleration(n, p, lam, cm, q, qd, qdd)
      integer, intent(in) :: n
      real(dp), intent(in) :: p(n), lam(n), cm(n), q(n), qd(n)
      real(dp), intent(out) :: qdd(n)
      integer :: i

      !GCC$ vector
      do i = 1, n
         qdd(i) = p(i) - lam(i)*q(i) - cm(i)*qd(i)
      end do
   end subroutine modal_acceleration

   !> y = A x, z = A w, A (n, m) (columns; n small: the response points).
   pure subroutine mv2(n, m, a, x, w, y, z)
      integer, intent(in) :: n, m
      real(dp), intent(in) :: a(n, m), x(m), w(m)
      real(dp), intent(out) :: y(n), z(n)
      integer :: i, j

      y = 0.0_dp
      z = 0.0_dp
      do j = 1, m
         !GCC$ vector
         do i = 1, n
            y(i) = y(i) + a(i, j)*x(j)
            z(i) = z(i) + a(i, j)*w(j)
         end do
      end do
   end subroutine mv2

   !> Add weight times each building's input power -a_g gamma_b^T q'_b to `win` (the
   !> trapezoidal sum of the input work over the substeps).
   pure subroutine input_rate(cl, qd, ag, win, weight)
      type(closed_stepper), intent(in) :: cl
      real(dp), intent(in) :: qd(:), ag, weight
      real(dp), intent(inout) :: win(:)
      integer :: ib

      do ib = 1, cl%nb
         associate (o => cl%b(ib)%off, nm => cl%b(ib)%nm)
            win(ib) = win(ib) - weight*ag*dot8(nm, cl%gam(o + 1:o + nm), qd(o + 1:o + nm))
         end associate
      end do
   end subroutine input_rate

   !> The massless DOFs at the end of the step: g = g0 exp(-h/a1) (g = 0 without a1), and
   !> u_s = K_ss^-1 g - T u_m, v_s = K_ss^-1 g' - T v_m, a_s = K_ss^-1 g'' - T a_m: the terms
   !> in g added to the static parts (-T u_m, ... from the shapes `phin`).
   pure subroutine massless_end(cb, g0, u, v, a, ez)
      type(closed_building), intent(in) :: cb
      real(dp), intent(in) :: g0(:)
      real(dp), intent(inout) :: u(:), v(:), a(:)
      !> g^T K_ss^-1 g at the end (twice the strain energy of the massless DOFs' forces).
      real(dp), intent(out) :: ez
      real(dp) :: g(size(g0))
      integer :: i, j, r

      ez = 0.0_dp
      if (cb%decay == 0.0_dp) return
      g = 0.0_dp
      do j = 1, cb%ns
         do i = 1, cb%ns
            g(i) = g(i) + cb%kssi(i, j)*g0(j)
         end do
      end do
      ez = cb%decay*cb%decay*dot_product(g0, g)
      do i = 1, cb%ns
         r = cb%is(i)
         u(r) = u(r) + cb%decay*g(i)
         v(r) = v(r) - cb%ra1*cb%decay*g(i)
         a(r) = a(r) + cb%ra1*cb%ra1*cb%decay*g(i)
      end do
   end subroutine massless_end

   !> y = A x, A (n, m) (columns).
   pure subroutine mv(n, m, a, x, y)
      integer, intent(in) :: n, m
      real(dp), intent(in) :: a(n, m), x(m)
      real(dp), intent(out) :: y(n)
      integer :: i, j

      y = 0.0_dp
      do j = 1, m
         !GCC$ vector
         do i = 1, n
            y(i) = y(i) + a(i, j)*x(j)
         end do
      end do
   end subroutine mv

   !> y = A x for k vectors at once, A (n, m), x (m, k), y (n, k) (A read once, by columns).
   pure subroutine mvk(n, m, k, a, x, y)
      integer, intent(in) :: n, m, k
      real(dp), intent(in) :: a(n, m), x(m, k)
      real(dp), intent(out) :: y(n, k)
      integer :: i, j, l, m4

      y = 0.0_dp
      ! Four columns of A at a time: y is read and written once for four.
      m4 = m - mod(m, 4)
      do j = 1, m4, 4
         do l = 1, k
            !GCC$ vector
            do i = 1, n
               y(i, l) = y(i, l) + ((a(i, j)*x(j, l) + a(i, j + 1)*x(j + 1, l)) + &
                                    (a(i, j + 2)*x(j + 2, l) + a(i, j + 3)*x(j + 3, l)))
            end do
         end do
      end do
      do j = m4 + 1, m
         do l = 1, k
            !GCC$ vector
            do i = 1, n
               y(i, l) = y(i, l) + a(i, j)*x(j, l)
            end do
         end do
      end do
   end subroutine mvk

   !> The least (`lowest`) or largest value over [0, h] of the cubic Hermite path through
   !> (c0, d0) at 0 and (c1, d1) at h (values, rates).
   pure real(dp) function hermite_extreme(c0, d0, c1, d1, h, lowest) result(x)
      !> Values and rates at both ends.
      real(dp), intent(in) :: c0, d0, c1, d1
      !> Length of the interval.
      real(dp), intent(in) :: h
      !> The least value (else the largest).
      logical, intent(in) :: lowest
      real(dp) :: a1, a2, a3, qa, qb, qc, disc, s(2), val
      integer :: i

      a1 = h*d0
      a2 = -3.0_dp*c0 - 2.0_dp*h*d0 + 3.0_dp*c1 - h*d1
      a3 = 2.0_dp*c0 + h*d0 - 2.0_dp*c1 + h*d1
      x = merge(min(c0, c1), max(c0, c1), lowest)
      qa = 3.0_dp*a3
      qb = 2.0_dp*a2
      qc = a1
      s = -1.0_dp
      if (qa /= 0.0_dp) then
         disc = qb*qb - 4.0_dp*qa*qc
         if (disc >= 0.0_dp) s = [(-qb + sqrt(disc))/(2.0_dp*qa), (-qb - sqrt(disc))/(2.0_dp*qa)]
      else if (qb /= 0.0_dp) then
         s(1) = -qc/qb
      end if
      do i = 1, 2
         if (s(i) > 0.0_dp .and. s(i) < 1.0_dp) then
            val = ((a3*s(i) + a2)*s(i) + a1)*s(i) + c0
            x = merge(min(x, val), max(x, val), lowest)
         end if
      end do
   end function hermite_extreme

   !> Index of the set `key` among those met, set up when first met (0: it cannot be stepped,
   !> or more than `max_sets` sets were met).
   integer function find_config(cl, key) result(ic)
      type(closed_stepper), intent(inout) :: cl
      integer(int64), intent(in) :: key
      real(dp), allocatable :: h(:, :), ident(:, :)
      integer :: i, l, k, nr, info
      integer, allocatable :: piv(:)

      ic = 0
      do i = 1, cl%ncfg
         if (cl%cfg(i)%key == key) then
            if (cl%cfg(i)%ok) ic = i
            return
         end if
      end do
      if (cl%ncfg == max_sets) return
      cl%ncfg = cl%ncfg + 1
      associate (c => cl%cfg(cl%ncfg))
         c%key = key
         c%joint = pack([(k, k=1, size(cl%kj))], [(btest(key, k - 1), k=1, size(cl%kj))])
         c%open = pack([(k, k=1, size(cl%kj))], [(.not. btest(key, k - 1), k=1, size(cl%kj))])
         nr = size(c%joint)
         ! H = I + K W^T D W (D = diag(cf(:, 4)), the end load's part of the substep), then
         ! H^-1 K: r1 = H^-1 K (W^T q_pred - g).
         allocate (h(nr, nr), ident(nr, nr), piv(nr))
         ident = 0.0_dp
         do l = 1, nr
            ident(l, l) = cl%kj(c%joint(l))
            do i = 1, nr
               h(l, i) = cl%kj(c%joint(l))*sum(cl%w(:, c%joint(l))*cl%cf(:, 4)*cl%w(:, c%joint(i)))
            end do
            h(l, l) = h(l, l) + 1.0_dp
         end do
         call dgesv(nr, nr, h, nr, piv, ident, nr, info)
         c%ok = info == 0 .and. all(ieee_is_finite(ident))
         if (c%ok) then
            c%hk = ident
            ic = cl%ncfg
         end if
      end associate
   end function find_config

end module pound_closed_steps
