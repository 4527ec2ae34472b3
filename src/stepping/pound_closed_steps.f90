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
!> The step of dt is cut into substeps of h. Over each substep the modal load p is taken
!> linear between its ends (a_g linear over dt, as in an exact free step; the joint forces
!> linear between the substep ends: the trapezoidal rule of Newmark's substeps), and each
!> mode's response to it is exact (`modal_step_response`: q1 = A q0 + B q0' + C p0 + D p1).
!> The forces at the substep's end are implicit, r1 = K (W^T q1 - g) with q1 = q_pred - D W r1,
!> so (I + K W^T D W) r1 = K (W^T q_pred - g): an r x r system per set of closed joints and
!> substep length (inverted once, when the set is first met). The structure's own response is
!> exact; the joint forces' interpolation errs by c h^2 + O(h^4) (a symmetric rule), so the step
!> is taken twice from its start, with mc substeps and with 2 mc, and extrapolated,
!> (4 x_fine - x_coarse)/3 (Richardson): fourth order. mc = ceil(m/10), m the impact substep
!> count (automatic: 60 substeps a contact half-period with exact free steps), so the coarse
!> substep is at most 1/6 of the contact half-period and the fine one 1/12. The cost is a few multiply-adds per
!> mode and substep, 3 mc substeps in all, and no factorisation, instead of m solves, contact
!> steps and response samples of every DOF. The response is sampled at the step's ends; u,
!> drift and storey shear peaks between them are refined as those of an exact free step
!> (`refine_peaks` of pound_response, the cubic Hermite path through the samples' values and
!> rates), v and a_abs at the response points and the joints' forces are kept at the fine
!> pass's substep ends.
!>
!> The step is kept only if it is valid: at every substep's end of both passes, and at the
!> extrapolated end, each closed joint still carries compression, and every other joint stays
!> open along the step (the cubic Hermite path of its closing displacement through the values
!> and rates at the step's ends stays short of the gap, as `contact_may_act` judges an exact
!> free step). Otherwise nothing is changed and the caller takes the step as impact
!> substeps (Newmark, the LCP deciding the contact), as before: the steps in which a joint
!> closes or opens are always substepped.
!>
!> Energy: the kinetic and strain energy are those of the end state, from the coordinates;
!> each building's input work -int a_g gamma^T q' dt is summed by the trapezoidal rule over the
!> substeps of each pass and extrapolated; the joints' work is that of `contact_commit`,
!> (r0 + r1)/2 (d1 - d0), exact for a linear spring, split over the buildings by the same rule;
!> the damping energy of each building is the balance (so over such a step the audit measures
!> round-off, not the damping).
module pound_closed_steps
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_structure, only: structure_model
   use pound_band, only: band_to_dense
   use pound_band_lapack, only: dsygv
   use pound_modal_step, only: modal_step_response
   use pound_integrator, only: integrator
   use pound_contact, only: contact_system
   use pound_contact_pair, only: end_sign
   use pound_response, only: response_record, response_peaks_inside
   use pound_closed_kernels, only: closing, substep, modal_acceleration, mv2, mv, mvk, mv3, hermite_extreme, dot8
   implicit none
   private

   public :: closed_stepper, closed_init, closed_step, hermite_extreme, closed_max_dofs

   !> Largest number of DOFs with mass (all buildings) for which closed steps are set up.
   integer, parameter :: closed_max_dofs = 400
   !> Most sets of closed joints set up in one run (more are substepped).
   integer, parameter :: max_sets = 64
   !> The peaks of v and a_abs (and the joints' forces) are kept at every `inside_stride`-th
   !> substep end of the fine pass inside a step: its substep is at most 1/12 of the contact
   !> half-period, a peak of the contact oscillation within 1 - cos(pi/24) = 0.9 % of its
   !> value (faster components, excited by the impacts, less well).
   integer, parameter :: inside_stride = 1
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
      !> Work arrays of the products by columns: over its DOFs (n, 3) and its modes (nm, 3)
      !> (whole columns are passed: no array temporaries).
      real(dp), allocatable :: xn(:, :), xm(:, :)
      !> exp(-h/a1) (0 without stiffness-proportional damping) and 1/a1.
      real(dp) :: decay = 0.0_dp, ra1 = 0.0_dp
   end type closed_building

   !> One set of closed joints.
   type :: closed_config
      !> The set: bit k-1 for joint k.
      integer(int64) :: key = 0
      !> Its joints (r) and the others (open), and (I + K W^T D W)^-1 K (r, r) (see the
      !> module doc) at the fine and at the coarse substep.
      integer, allocatable :: joint(:), open(:)
      real(dp), allocatable :: hk(:, :), hkc(:, :)
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
      !> Substeps per step of the fine and the coarse pass (m = 2 mc), and their lengths (s).
      integer :: m = 2, mc = 1
      real(dp) :: hs = 0.0_dp, hc = 0.0_dp
      !> Each mode's substep coefficients against (q0, q0', p0, p1) (nmt, 8): q1 from 1:4,
      !> q1' from 5:8; of the fine and of the coarse substep.
      real(dp), allocatable :: cf(:, :), cfc(:, :)
      !> The coarse pass's end: q, q' (nmt), and each building's input work (nb); the start's
      !> q, q' and load (nmt).
      real(dp), allocatable :: qa(:), qda(:), wina(:), q0(:), qd0(:), ps(:)
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
      !> Each joint's largest force inside the step and its time; its closing displacement
      !> and rate at the last substep's end.
      real(dp), allocatable :: rmax(:), tmax(:), dl(:), ddl(:)
      !> v and a at the response points at the substeps' ends inside the step (points, m, nb),
      !> the ground acceleration there (m): the peaks inside, kept once the step is valid.
      real(dp), allocatable :: vin(:, :, :), ain(:, :, :), agin(:)
      !> Unused.
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
      ! The coarse substep at most 1/6 of the contact half-period (the automatic m puts 60
      ! substeps in it), the fine one half that.
      cl%mc = max(1, ceiling(real(m, dp)/10.0_dp - 1.0e-9_dp))
      cl%m = 2*cl%mc
      cl%hs = dt/real(cl%m, dp)
      cl%hc = dt/real(cl%mc, dp)
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
      allocate (cl%lam(off), cl%cm(off), cl%gam(off), cl%cf(off, 8), cl%cfc(off, 8))
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
         cl%cfc(i, :) = modal_step_response(cl%lam(i), cl%cm(i), -1.0_dp, cl%hc)
      end do
      where (abs(cl%cf) < negligible) cl%cf = 0.0_dp
      where (abs(cl%cfc) < negligible) cl%cfc = 0.0_dp
      if (.not. (all(ieee_is_finite(cl%cf)) .and. all(ieee_is_finite(cl%cfc)))) return
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
      allocate (cl%qa(off), cl%qda(off), cl%q0(off), cl%qd0(off), cl%ps(off), cl%wina(cl%nb))
      allocate (cl%d0(nj), cl%dd0(nj), cl%d1(nj), cl%dd1(nj), cl%r(nj), cl%rhs(nj), cl%rmax(nj), cl%tmax(nj), &
                cl%dl(nj), cl%ddl(nj))
      allocate (cl%ue(nmax, cl%nb), cl%ve(nmax, cl%nb), cl%ae(nmax, cl%nb), cl%g0(nmax, cl%nb), cl%jw(cl%nb), &
                cl%win(cl%nb), cl%ez(cl%nb))
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
      integer :: n, nm, ns, i, info

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
      k = band_to_dense(b%kt)
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
      allocate (cb%xn(n, 3), cb%xm(nm, 3))
      ok = all(ieee_is_finite(cb%phi)) .and. all(ieee_is_finite(cb%lam))
   end subroutine building_modes

   !> Try the step from the integrators' state as an exact step of the closed joints (those
   !> carrying force). On success the integrators hold the step's end (`integrator%put_state`)
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

      integer :: ib

      taken = .false.
      if (.not. cl%on) return
      do ib = 1, size(st)
         if (.not. st(ib)%takes_state()) return
      end do
      call closed_take(cl, st, models, cs, ag0, ag1, step, taken, rec, t0)
   end subroutine closed_step

   !> `closed_step` of integrators that take in a state (`integrator%takes_state`).
   subroutine closed_take(cl, st, models, cs, ag0, ag1, step, taken, rec, t0)
      type(closed_stepper), intent(inout) :: cl
      class(integrator), intent(inout), target :: st(:)
      type(structure_model), intent(in) :: models(:)
      type(contact_system), intent(inout) :: cs
      real(dp), intent(in) :: ag0, ag1
      integer, intent(in) :: step
      logical, intent(out) :: taken
      type(response_record), intent(inout) :: rec(:)
      real(dp), intent(in) :: t0
      integer(int64) :: key
      integer :: k, ic, ib, e, bb, nmt, i, j, l, nr, nj
      real(dp) :: w0, w1
      logical :: valid
      real(dp), pointer, contiguous :: u(:), v(:)

      taken = .false.
      key = 0
      do k = 1, cs%m
         if (cs%joint(k)%fractured) cycle
         if (cs%joint(k)%r > 0.0_dp) then
            if (.not. (cs%plain(k) .and. cl%joint_ok(k))) return
            ! A point with friction rows (pound_contact_friction): the step is substepped.
            if (cs%fr%n > 0) then
               if (cs%fr%index(k) > 0) return
            end if
            if (allocated(cs%pair(k)%law%given)) then
               if (cs%pair(k)%law%given%has_force()) return
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
               u => st(ib)%u_view()
               v => st(ib)%v_view()
               cb%xn(:, 1) = u
               cb%xn(:, 2) = v
               call mvk(cb%nm, cb%n, 2, cb%phimt, cb%xn, cb%xm)
               cl%qp(cb%off + 1:cb%off + cb%nm) = cb%xm(:, 1)
               cl%p1(cb%off + 1:cb%off + cb%nm) = cb%xm(:, 2)
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
      call closing(nmt, cs%m, nr, cl%cfg(ic)%joint, cl%w, cl%q, cl%qd, cl%d0, cl%dd0)
      call closing(nmt, cs%m, nj - nr, cl%cfg(ic)%open, cl%w, cl%q, cl%qd, cl%d0, cl%dd0)
      cl%r = 0.0_dp
      cl%p0 = -cl%gam*ag0
      do l = 1, nr
         k = cl%cfg(ic)%joint(l)
         cl%r(k) = cl%kj(k)*(cl%d0(k) - cl%gap(k))
         cl%p0 = cl%p0 - cl%w(:, k)*cl%r(k)
      end do
      ! The coarse pass (mc substeps), then the fine one (m = 2 mc, the peaks inside kept)
      ! from the same start, extrapolated (Richardson: the passes' error is c h^2 + O(h^4)).
      cl%q0 = cl%q
      cl%qd0 = cl%qd
      cl%ps = cl%p0
      cl%rmax = 0.0_dp
      call march(cl, cl%cfg(ic), cs, cl%mc, cl%cfc, cl%cfg(ic)%hkc, cl%hc, ag0, ag1, t0, .false., valid)
      if (.not. valid) return
      cl%qa = cl%q
      cl%qda = cl%qd
      cl%wina = cl%win
      cl%q = cl%q0
      cl%qd = cl%qd0
      cl%p0 = cl%ps
      call march(cl, cl%cfg(ic), cs, cl%m, cl%cf, cl%cfg(ic)%hk, cl%hs, ag0, ag1, t0, .true., valid)
      if (.not. valid) return
      cl%q = (4.0_dp*cl%q - cl%qa)/3.0_dp
      cl%qd = (4.0_dp*cl%qd - cl%qda)/3.0_dp
      cl%win = (4.0_dp*cl%win - cl%wina)/3.0_dp
      ! The closed joints' forces at the end, from the extrapolated coordinates, and the load.
      call closing(nmt, cs%m, nr, cl%cfg(ic)%joint, cl%w, cl%q, cl%qd, cl%d1, cl%dd1)
      cl%p1 = -cl%gam*ag1
      do l = 1, nr
         k = cl%cfg(ic)%joint(l)
         cl%r(k) = cl%kj(k)*(cl%d1(k) - cl%gap(k))
         if (.not. (cl%r(k) > 0.0_dp)) return
         cl%p1 = cl%p1 - cl%w(:, k)*cl%r(k)
      end do
      ! The other joints open along the step: the Hermite path of their closing displacement
      ! through its values and rates at the step's ends (as `contact_may_act` for an exact
      ! free step) stays short of the gap.
      call closing(nmt, cs%m, nj - nr, cl%cfg(ic)%open, cl%w, cl%q, cl%qd, cl%d1, cl%dd1)
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
            call mv3(cb%n, cb%nm, cb%phin, cl%q(o + 1:o + cb%nm), cl%qd(o + 1:o + cb%nm), cl%qdd(o + 1:o + cb%nm), &
                     cl%ue(1:cb%n, ib), cl%ve(1:cb%n, ib), cl%ae(1:cb%n, ib))
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
            w0 = st(bb)%u_at(i)
            w1 = cl%ue(i, bb)
            cl%jw(bb) = cl%jw(bb) - end_sign(e)*0.5_dp*(cs%joint(k)%r + cs%r_new(k))*(w1 - w0)
         end do
      end do
      ! The energies from the coordinates: kinetic q'^T q'/2 (mass-normalised modes; the DOFs
      ! without mass have none), strain (sum omega^2 q^2 + g^T K_ss^-1 g)/2.
      do ib = 1, cl%nb
         associate (n => models(ib)%n, cb => cl%b(ib), o => cl%b(ib)%off)
            call st(ib)%put_state(cl%ue(1:n, ib), cl%ve(1:n, ib), cl%ae(1:n, ib), &
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
   end subroutine closed_take

   !> One pass of ms substeps of length h (coefficients cf, the set's implicit forces hk)
   !> from cl%q, cl%qd, cl%p0: the end in cl%q, cl%qd, cl%p1, cl%r, the input work in cl%win;
   !> `valid` false as soon as a closed joint stops carrying compression at a substep's end.
   !> With `record`, the closed joints' largest forces and the response points' v and a at
   !> every `inside_stride`-th substep end inside the step are kept.
   subroutine march(cl, c, cs, ms, cf, hk, h, ag0, ag1, t0, record, valid)
      type(closed_stepper), intent(inout) :: cl
      type(closed_config), intent(in) :: c
      type(contact_system), intent(in) :: cs
      integer, intent(in) :: ms
      real(dp), intent(in) :: cf(:, :), hk(:, :), h, ag0, ag1, t0
      logical, intent(in) :: record
      logical, intent(out) :: valid
      integer :: j, l, k, ib, nr, nmt
      real(dp) :: a1, s0, rk

      valid = .false.
      nr = size(c%joint)
      nmt = cl%nmt
      cl%dl = cl%d0
      cl%ddl = cl%dd0
      cl%win = 0.0_dp
      a1 = ag0
      call input_rate(cl, cl%qd, a1, cl%win, 0.5_dp*h)
      do j = 1, ms
         a1 = ag0 + (ag1 - ag0)*real(j, dp)/real(ms, dp)
         call substep(nmt, cs%m, nr, c%joint, cf, cl%gam, cl%w, hk, cl%gap, a1, cl%q, cl%qd, cl%p0, cl%p1, cl%qp, &
                      cl%rhs, cl%r)
         cl%p0 = cl%p1
         ! Validity: closed joints in compression at the substep's end.
         do l = 1, nr
            if (.not. (cl%r(c%joint(l)) > 0.0_dp)) return
         end do
         if (record) then
            ! The closed joints' largest force along the substep: the Hermite path of the
            ! closing displacement through its values and rates at the substep's ends.
            call closing(nmt, cs%m, nr, c%joint, cl%w, cl%q, cl%qd, cl%d1, cl%dd1)
            do l = 1, nr
               k = c%joint(l)
               rk = cl%kj(k)*(hermite_extreme(cl%dl(k), cl%ddl(k), cl%d1(k), cl%dd1(k), h, .false.) - cl%gap(k))
               if (rk > cl%rmax(k)) then
                  cl%rmax(k) = rk
                  cl%tmax(k) = t0 + real(j, dp)*h
               end if
               cl%dl(k) = cl%d1(k)
               cl%ddl(k) = cl%dd1(k)
            end do
         end if
         if (record .and. j < ms) then
            if (mod(j, inside_stride) == 0) then
               ! v and a at the response points (the relaxation of the massless DOFs' forces
               ! left out inside the step).
               call modal_acceleration(nmt, cl%p1, cl%lam, cl%cm, cl%q, cl%qd, cl%qdd)
               cl%agin(j) = a1
               do ib = 1, cl%nb
                  associate (cb => cl%b(ib), o => cl%b(ib)%off, np => size(cl%b(ib)%pf, 1))
                     call mv2(np, cb%nm, cb%pf, cl%qd(o + 1:o + cb%nm), cl%qdd(o + 1:o + cb%nm), &
                              cl%vin(1:np, j, ib), cl%ain(1:np, j, ib))
                  end associate
               end do
            end if
         end if
         s0 = 0.5_dp*h
         if (j == ms) s0 = 0.0_dp
         call input_rate(cl, cl%qd, a1, cl%win, 0.5_dp*h + s0)
      end do
      valid = .true.
   end subroutine march






   !> Add weight times each building's input power -a_g gamma_b^T q'_b to `win` (the
   !> trapezoidal sum of the input work over the substeps).
   pure subroutine input_rate(cl, qd, ag, win, weight)
      type(closed_stepper), intent(in) :: cl
      real(dp), intent(in) :: qd(cl%nmt), ag, weight
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
      integer :: i, r

      ez = 0.0_dp
      if (cb%decay == 0.0_dp) return
      call mv(cb%ns, cb%ns, cb%kssi, g0, g)
      ez = cb%decay*cb%decay*dot_product(g0, g)
      do i = 1, cb%ns
         r = cb%is(i)
         u(r) = u(r) + cb%decay*g(i)
         v(r) = v(r) - cb%ra1*cb%decay*g(i)
         a(r) = a(r) + cb%ra1*cb%ra1*cb%decay*g(i)
      end do
   end subroutine massless_end




   !> Index of the set `key` among those met, set up when first met (0: it cannot be stepped,
   !> or more than `max_sets` sets were met).
   integer function find_config(cl, key) result(ic)
      type(closed_stepper), intent(inout) :: cl
      integer(int64), intent(in) :: key
      integer :: i, k

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
         ! H = I + K W^T D W (D = diag(cf(:, 4)), the end load's part of the substep), then
         ! H^-1 K: r1 = H^-1 K (W^T q_pred - g); for the fine and the coarse substep.
         c%hk = implicit_forces(cl, c%joint, cl%cf(:, 4), c%ok)
         if (c%ok) c%hkc = implicit_forces(cl, c%joint, cl%cfc(:, 4), c%ok)
         if (c%ok) ic = cl%ncfg
      end associate
   end function find_config

   !> (I + K W^T D W)^-1 K of the closed joints `joint`, D = diag(d) (`ok` false when H is
   !> singular or the result not finite).
   function implicit_forces(cl, joint, d, ok) result(hk)
      type(closed_stepper), intent(in) :: cl
      integer, intent(in) :: joint(:)
      real(dp), intent(in) :: d(:)
      logical, intent(out) :: ok
      real(dp), allocatable :: hk(:, :)
      real(dp), allocatable :: h(:, :)
      integer, allocatable :: piv(:)
      integer :: nr, l, i, info

      nr = size(joint)
      allocate (h(nr, nr), hk(nr, nr), piv(nr))
      hk = 0.0_dp
      do l = 1, nr
         hk(l, l) = cl%kj(joint(l))
         do i = 1, nr
            h(l, i) = cl%kj(joint(l))*sum(cl%w(:, joint(l))*d*cl%w(:, joint(i)))
         end do
         h(l, l) = h(l, l) + 1.0_dp
      end do
      call dgesv(nr, nr, h, nr, piv, hk, nr, info)
      ok = info == 0 .and. all(ieee_is_finite(hk))
   end function implicit_forces

end module pound_closed_steps
