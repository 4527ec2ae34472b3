!> Exact free steps of the Newmark integrator (`&analysis free_steps = 'exact'`): the step of
!> the linear structure (K+G, M, Rayleigh C) under a ground acceleration linear over the step,
!> mode by mode (`pound_modal_step`), with its input work and damping energy exact too, so the
!> energy audit closes to round-off. The state stays u, v, a (and C v, the energies) as for a
!> Newmark step; the modal coordinates are carried from one exact step to the next and taken
!> from u, v again after steps that were not exact. A step costs O(n^2) (the modes' shapes),
!> hence `exact_max_dofs`.
!>
!> DOFs without mass (a frame's rotations, split column nodes) are condensed statically and
!> their elastic forces relax as exp(-t/a1) (`condensed_modes`): the same kernels then step
!> the nm modes of the condensed system and the ns relaxation coordinates, the coordinates of
!> a state are psi^T u, and a run of exact steps forms no band product (`band_stale`).
!>
!> Per mode, `coef(i, :)` holds (set up as coef(:, i), then held transposed, mode-fastest):
!> 1:4 and 5:8 the end q and q' against x = (q0, q0', a_g0, a_g1);
!> 9:15 the input work and 16:22 the damping energy against the products (q0^2, q0 q0',
!> q0'^2, q0 a_g0, q0 a_g1, q0' a_g0, q0' a_g1) (the forms' off-diagonal terms doubled); the
!> forms' terms in a_g alone (a_g0^2, a_g0 a_g1, a_g1^2) are the same for every step and summed
!> over the modes in `ground_terms` (1:3 input work, 4:6 damping energy).
!>
!> A model with a second ground component (a building in plan under a ground along y: load
!> -M (r_1 a_g1 + r_2 a_g2)) drives mode i by its modal ground g_i = Gamma_1 a_g1 + Gamma_2 a_g2,
!> linear over the step too: `coef2` holds each mode's step for a unit participation against
!> x = (q0, q0', g_i0, g_i1) (1:22 as `coef`, 23:25 and 26:28 the terms in g alone of the input
!> work and the damping energy, per mode since g differs from mode to mode), and
!> `newmark_predict_exact` with `ag2_old`, `ag2_new` steps it (`modal_kernel_g`).
submodule(pound_newmark) pound_newmark_exact
   use pound_modal_step, only: modal_step_coefficients
   use pound_band, only: band_to_dense
   use pound_band_lapack, only: dsygv
   implicit none

   !> Modal coordinates (sqrt(kJ)-like: q^2/2 is an energy in kJ), rates and accelerations
   !> below this are set to zero with DOFs without mass (`flush_negligible`).
   real(dp), parameter :: negligible = 1.0e-100_dp
   !> Relaxation coordinates adding less than this fraction of the largest |u|, |v|, |a| to
   !> the state are set to zero (`relaxed`; below the round-off of the state).
   real(dp), parameter :: relaxed_below = 1.0e-18_dp

   interface
      subroutine dpotrf(uplo, n, a, lda, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, lda
         real(dp), intent(inout) :: a(lda, *)
         integer, intent(out) :: info
      end subroutine dpotrf
      subroutine dtrtrs(uplo, trans, diag, n, nrhs, a, lda, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo, trans, diag
         integer, intent(in) :: n, nrhs, lda, ldb
         real(dp), intent(in) :: a(lda, *)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dtrtrs
   end interface

contains

   !> The modes of (K+G, M) (dense `dsygv`, mass-normalised) and each mode's step at dt; with
   !> DOFs without mass, the modes of the condensed system and the relaxation of the massless
   !> DOFs' elastic forces (`condensed_modes`).
   module subroutine exact_init(st, b, error)
      !> Integrator state (initialised by `newmark_init`).
      type(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Error state: too many DOFs, no DOF with mass, the eigenproblem failed.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: a(:, :), m(:, :), w(:), work(:)
      real(dp) :: gamma, wi(4, 4), wd(4, 4), decay
      integer :: n, nm, i, j, info, stat

      n = st%n
      if (n > exact_max_dofs) then
         call fatal_error(error, structure_label(b)//": free_steps = 'exact' takes at most "// &
                          str(exact_max_dofs)//' DOFs (it holds the n x n modes and costs O(n^2) a step); '// &
                          'the model has '//str(n)//": use free_steps = 'newmark'")
         return
      end if
      nm = count(b%mass > 0.0_dp)
      if (nm == 0) then
         call fatal_error(error, structure_label(b)//": free_steps = 'exact': no DOF has a mass; "// &
                          "use free_steps = 'newmark'")
         return
      end if
      allocate (w(n), st%phi(n, n), st%lam(n), st%cm(n), st%coef(22, n), &
                st%q(n), st%qd(n), st%xq(n), st%xqd(n), st%xw(n), st%xv(n), st%xa(n), stat=stat)
      if (stat == 0 .and. nm < n) allocate (st%psi(n, n), stat=stat)
      if (stat /= 0) then
         call fatal_error(error, structure_label(b)//": free_steps = 'exact': cannot allocate the modes ("// &
                          str(n)//' x '//str(n)//')')
         return
      end if
      if (nm == n) then
         allocate (m(n, n), work(max(1, 64*n)))
         a = band_to_dense(b%kt)
         m = 0.0_dp
         do j = 1, n
            m(j, j) = b%mass(j)
         end do
         call dsygv(1, 'V', 'U', n, a, n, m, n, w, work, size(work), info)
         if (info /= 0) then
            call fatal_error(error, structure_label(b)//": free_steps = 'exact': the eigenproblem of (K+G, M) "// &
                             'failed (dsygv info = '//str(info)//')')
            return
         end if
         st%phi = a
      else
         call condensed_modes(b, nm, st%phi, st%psi, w, error)
         if (allocated(error)) return
         ! Held transposed: q = psi^T u is then a sum of columns (`coordinate_kernel`).
         st%psi = transpose(st%psi)
         st%zscale = [(maxval(abs(st%phi(:, i))), i=nm + 1, n)]
      end if
      st%lam = w
      st%nm = nm
      st%ground_terms = 0.0_dp
      do i = 1, nm
         st%cm(i) = b%a0 + b%a1*w(i)
         gamma = sum(st%phi(:, i)*b%mass*b%ground)
         call modal_step_coefficients(w(i), st%cm(i), gamma, st%dt, st%coef(1:8, i), wi, wd)
         st%coef(9:15, i) = form_terms(wi)
         st%coef(16:22, i) = form_terms(wd)
         st%ground_terms(1:3) = st%ground_terms(1:3) + ground_terms_of(wi)
         st%ground_terms(4:6) = st%ground_terms(4:6) + ground_terms_of(wd)
         if (.not. all(ieee_is_finite(st%coef(:, i)))) then
            call fatal_error(error, structure_label(b)//": free_steps = 'exact': mode "//str(i)// &
                             ' (omega^2 = '//str(w(i))//' 1/s^2) gives a step that is not finite at dt = '// &
                             str(st%dt)//' s')
            return
         end if
      end do
      if (allocated(b%ground_set)) then
         if (size(b%ground_set, 2) >= 2) call second_component_init(st, b, w, error)
         if (allocated(error)) return
      end if
      ! The massless DOFs' relaxation coordinates z (g = L z, K_ss = L L^T): z' = -z/a1, so
      ! z(h) = exp(-h/a1) z(0), z' = -z/a1, z'' = z/a1^2 (lam = 0, cm = 1/a1 give
      ! xw = -(lam z + cm z') = z/a1^2), and the damping energy of the step is the strain
      ! energy z^2/2 lost, (1 - exp(-2h/a1)) z(0)^2/2. Without stiffness-proportional damping
      ! (a1 = 0) the massless rows read g = 0: z drops to 0 and its energy counts as damped.
      decay = 0.0_dp
      if (b%a1 > 0.0_dp) decay = exp(-st%dt/b%a1)
      do i = nm + 1, n
         st%lam(i) = 0.0_dp
         st%cm(i) = 0.0_dp
         if (b%a1 > 0.0_dp) st%cm(i) = 1.0_dp/b%a1
         st%coef(:, i) = 0.0_dp
         st%coef(1, i) = decay
         st%coef(5, i) = -decay*st%cm(i)
         st%coef(16, i) = 0.5_dp*(1.0_dp - decay*decay)
      end do
      if (.not. all(ieee_is_finite(st%ground_terms))) then
         call fatal_error(error, structure_label(b)//": free_steps = 'exact': the step's energy terms are "// &
                          'not finite at dt = '//str(st%dt)//' s')
         return
      end if
      ! Held mode-fastest, (n, 22): the step's kernel runs over the modes in vectors.
      st%coef = transpose(st%coef)
      if (allocated(st%coef2)) then
         do i = nm + 1, n
            st%coef2(1:22, i) = st%coef(i, :)
            st%coef2(23:28, i) = 0.0_dp
         end do
         st%coef2 = transpose(st%coef2)
      end if
      st%exact = .true.
      st%pending = .false.
      st%modal_valid = .false.
   end subroutine exact_init

   !> A form's terms in (q0^2, q0 q0', q0'^2, q0 a_g0, q0 a_g1, q0' a_g0, q0' a_g1) (the
   !> off-diagonal terms doubled).
   pure function form_terms(f) result(t)
      !> The form over (q0, q0', a_g0, a_g1).
      real(dp), intent(in) :: f(4, 4)
      real(dp) :: t(7)

      t = [f(1, 1), 2.0_dp*f(1, 2), f(2, 2), 2.0_dp*f(1, 3), 2.0_dp*f(1, 4), 2.0_dp*f(2, 3), 2.0_dp*f(2, 4)]
   end function form_terms

   !> A form's terms in the ground alone (a_g0^2, a_g0 a_g1, a_g1^2).
   pure function ground_terms_of(f) result(t)
      !> The form over (q0, q0', a_g0, a_g1).
      real(dp), intent(in) :: f(4, 4)
      real(dp) :: t(3)

      t = [f(3, 3), 2.0_dp*f(3, 4), f(4, 4)]
   end function ground_terms_of

   !> The step of each mode under its modal ground (a model with a second ground component,
   !> see the module doc): the participations of the first two components, the coefficients for
   !> a unit participation (28, n; the relaxation coordinates' are set with `coef`'s) and the
   !> work arrays of the modal ground.
   subroutine second_component_init(st, b, lam, error)
      !> Integrator state (its modes set).
      type(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> omega^2 of the modes.
      real(dp), intent(in) :: lam(:)
      !> Error state: a step that is not finite.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: wi(4, 4), wd(4, 4)
      integer :: i, n, stat

      n = st%n
      allocate (st%gam(n, 2), st%coef2(28, n), st%g0(n), st%g1(n), stat=stat)
      if (stat /= 0) then
         call fatal_error(error, structure_label(b)//": free_steps = 'exact': cannot allocate the modes' steps "// &
                          'under two ground components')
         return
      end if
      st%gam = 0.0_dp
      st%g0 = 0.0_dp
      st%g1 = 0.0_dp
      do i = 1, st%nm
         st%gam(i, 1) = sum(st%phi(:, i)*b%mass*b%ground_set(:, 1))
         st%gam(i, 2) = sum(st%phi(:, i)*b%mass*b%ground_set(:, 2))
         call modal_step_coefficients(lam(i), st%cm(i), 1.0_dp, st%dt, st%coef2(1:8, i), wi, wd)
         st%coef2(9:15, i) = form_terms(wi)
         st%coef2(16:22, i) = form_terms(wd)
         st%coef2(23:25, i) = ground_terms_of(wi)
         st%coef2(26:28, i) = ground_terms_of(wd)
         if (.not. all(ieee_is_finite(st%coef2(:, i)))) then
            call fatal_error(error, structure_label(b)//": free_steps = 'exact': mode "//str(i)// &
                             ' (omega^2 = '//str(lam(i))//' 1/s^2) gives a step that is not finite at dt = '// &
                             str(st%dt)//' s')
            return
         end if
      end do
   end subroutine second_component_init

   !> The exact free step of a model with DOFs without mass (index sets m: mass > 0, s: mass =
   !> 0; K meaning K+G). With C = a0 M + a1 K and no force at the s DOFs, their rows read
   !> a1 g' + g = 0, g = K_sm u_m + K_ss u_s their elastic forces, and the m rows reduce
   !> exactly to M_m u_m'' + (a0 M_m + a1 K_c) u_m' + K_c u_m = -M_m r_m a_g with
   !> K_c = K_mm - K_ms K_ss^-1 K_sm (the g terms enter as K_ms K_ss^-1 (a1 g' + g) = 0):
   !> classical damping again. So u = Phi q + S z with n columns: the nm modes of (K_c, M_m)
   !> (`phi(m, i)` mass-normalised, `phi(s, i)` = -K_ss^-1 K_sm phi(m, i)) and, with
   !> K_ss = L L^T and g = L z, the ns relaxation coordinates z (`phi(s, nm+k)` = L^-T e_k,
   !> `phi(m, nm+k)` = 0), which decay as exp(-t/a1). The coordinates of a state are
   !> psi^T u: `psi(:, i)` = M phi(:, i) for a mode, and for z = L^-1 K_sm u_m + L^T u_s,
   !> `psi(m, nm+k)` = (L^-1 K_sm)^T e_k, `psi(s, nm+k)` = L e_k. The strain energy is
   !> u_m^T K_c u_m/2 + z^T z/2 and the damping power v_m^T C_c v_m + a1 g'^T K_ss^-1 g'.
   subroutine condensed_modes(b, nm, phi, psi, lam, error)
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Number of DOFs with mass (0 < nm < n).
      integer, intent(in) :: nm
      !> Shapes and coordinate rows (n, n), see above.
      real(dp), intent(out) :: phi(:, :), psi(:, :)
      !> omega^2 of the nm modes (1:nm; the rest 0).
      real(dp), intent(out) :: lam(:)
      !> Error state: K_ss not positive definite, the eigenproblem failed.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: k(:, :), kss(:, :), wsm(:, :), tsm(:, :), kc(:, :), mm(:, :), work(:)
      integer, allocatable :: im(:), is(:)
      integer :: n, ns, i, j, info

      n = b%n
      ns = n - nm
      im = pack([(i, i=1, n)], b%mass > 0.0_dp)
      is = pack([(i, i=1, n)], .not. (b%mass > 0.0_dp))
      allocate (mm(nm, nm), work(max(1, 64*nm)))
      k = band_to_dense(b%kt)
      kss = k(is, is)
      wsm = k(is, im)
      call dpotrf('L', ns, kss, ns, info)
      if (info /= 0) then
         call fatal_error(error, structure_label(b)//": free_steps = 'exact': the stiffness of the "// &
                          str(ns)//' DOFs without mass is not positive definite (dpotrf info = '//str(info)//')')
         return
      end if
      do j = 1, ns
         kss(1:j - 1, j) = 0.0_dp
      end do
      ! W = L^-1 K_sm, T = K_ss^-1 K_sm = L^-T W, K_c = K_mm - W^T W.
      call dtrtrs('L', 'N', 'N', ns, nm, kss, ns, wsm, ns, info)
      tsm = wsm
      call dtrtrs('L', 'T', 'N', ns, nm, kss, ns, tsm, ns, info)
      kc = k(im, im) - matmul(transpose(wsm), wsm)
      mm = 0.0_dp
      do i = 1, nm
         mm(i, i) = b%mass(im(i))
      end do
      call dsygv(1, 'V', 'U', nm, kc, nm, mm, nm, lam, work, size(work), info)
      if (info /= 0) then
         call fatal_error(error, structure_label(b)//": free_steps = 'exact': the eigenproblem of the "// &
                          'condensed (K+G, M) failed (dsygv info = '//str(info)//')')
         return
      end if
      lam(nm + 1:) = 0.0_dp
      phi = 0.0_dp
      psi = 0.0_dp
      phi(im, 1:nm) = kc
      phi(is, 1:nm) = -matmul(tsm, kc)
      do i = 1, nm
         psi(im, i) = b%mass(im)*kc(:, i)
      end do
      ! L^-T: the shapes of the relaxation coordinates.
      k = 0.0_dp
      do i = 1, ns
         k(i, i) = 1.0_dp
      end do
      call dtrtrs('L', 'T', 'N', ns, ns, kss, ns, k, n, info)
      phi(is, nm + 1:n) = k(1:ns, 1:ns)
      psi(im, nm + 1:n) = transpose(wsm)
      psi(is, nm + 1:n) = kss
   end subroutine condensed_modes

   !> Predict the step exactly: the modal coordinates at its end, du, v and a at its end, and
   !> its input work and damping energy (committed by `newmark_commit`).
   module subroutine newmark_predict_exact(st, b, ag_old, ag_new, ag2_old, ag2_new)
      !> Integrator state; `du` is set.
      class(newmark_state), intent(inout) :: st
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> Ground acceleration at the start and the end of the step (m/s^2).
      real(dp), intent(in), value :: ag_old, ag_new
      !> The second ground component at the start and the end of the step (m/s^2; a model
      !> with one, `ground_set(:, 2)`).
      real(dp), intent(in), optional :: ag2_old, ag2_new
      integer :: n, ncol
      logical :: two

      if (.not. st%exact) then
         call newmark_predict(st, b, ag_new - ag_old)
         return
      end if
      n = st%n
      if (.not. st%modal_valid) then
         st%z_zero = .false.
         if (allocated(st%psi)) then
            ! With DOFs without mass: q = psi^T u, q' = psi^T v (`condensed_modes`).
            call coordinate_kernel(n, st%psi, st%u, st%v, st%q, st%qd)
         else
            call modal_state(n, st%phi, b%mass, st%u, st%v, st%q, st%qd)
         end if
      end if
      two = present(ag2_old) .and. present(ag2_new) .and. allocated(st%coef2)
      if (two) then
         ! Each mode under its modal ground (the relaxation coordinates' is 0).
         st%g0 = st%gam(:, 1)*ag_old + st%gam(:, 2)*ag2_old
         st%g1 = st%gam(:, 1)*ag_new + st%gam(:, 2)*ag2_new
         st%x_input = 0.0_dp
         st%x_damping = 0.0_dp
         call modal_kernel_g(n, st%coef2, st%lam, st%cm, st%q, st%qd, st%g0, st%g1, st%xq, st%xqd, st%xw, &
                             st%x_input, st%x_damping)
      else
         associate (g => st%ground_terms)
            st%x_input = (g(1)*ag_old + g(2)*ag_new)*ag_old + g(3)*ag_new*ag_new
            st%x_damping = (g(4)*ag_old + g(5)*ag_new)*ag_old + g(6)*ag_new*ag_new
         end associate
         call modal_kernel(n, st%coef, st%lam, st%cm, st%q, st%qd, ag_old, ag_new, st%xq, st%xqd, st%xw, &
                           st%x_input, st%x_damping)
      end if
      ! With DOFs without mass the relaxation coordinates (and, where the ground is still, the
      ! over-damped stiff modes) decay by exp(-h/a1) a step and would go subnormal, which
      ! slows every product with them many times: below `negligible` they are zero.
      ! Once the relaxation coordinates add less than `relaxed_below` of the largest u, v, a
      ! (or are 0, as in a run without joints acting) they are 0 and their columns are left out.
      ncol = n
      if (allocated(st%psi)) then
         if (st%z_zero) then
            ! Zero relaxation coordinates stay zero (z(h) = exp(-h/a1) z(0)).
            call flush_negligible(st%nm, st%xq, st%xqd, st%xw)
            ncol = st%nm
         else
            call flush_negligible(n, st%xq, st%xqd, st%xw)
            if (relaxed(st)) then
               st%xq(st%nm + 1:n) = 0.0_dp
               st%xqd(st%nm + 1:n) = 0.0_dp
               st%xw(st%nm + 1:n) = 0.0_dp
               ncol = st%nm
               st%z_zero = .true.
            end if
         end if
      end if
      call shape_kernel(n, ncol, st%phi, st%xq, st%xqd, st%xw, st%u, b%ground, ag_new, st%du, st%xv, st%xa)
      if (two) st%xa = st%xa - b%ground_set(:, 2)*ag2_new
      st%pending = .true.
   end subroutine newmark_predict_exact

   !> Whether every relaxation coordinate at the end of the predicted step, z, z' and z'', times
   !> its column's largest entry, is below `relaxed_below` of the largest |u|, |v|, |a| now.
   pure logical function relaxed(st)
      type(newmark_state), intent(in) :: st
      real(dp) :: umax, vmax, amax, s
      integer :: k

      relaxed = .false.
      umax = relaxed_below*maxval(abs(st%u))
      vmax = relaxed_below*maxval(abs(st%v))
      amax = relaxed_below*maxval(abs(st%a))
      do k = st%nm + 1, st%n
         s = st%zscale(k - st%nm)
         if (abs(st%xq(k))*s > umax .or. abs(st%xqd(k))*s > vmax .or. abs(st%xw(k))*s > amax) return
      end do
      relaxed = .true.
   end function relaxed

   !> Coordinates below `negligible` in magnitude (and their rates and accelerations when
   !> they are too) set to zero.
   pure subroutine flush_negligible(n, xq, xqd, xw)
      integer, intent(in) :: n
      real(dp), intent(inout) :: xq(n), xqd(n), xw(n)
      integer :: i

      ! (merge, not a branch per value: the loop vectorises; the same values.)
      !GCC$ vector
      do i = 1, n
         xq(i) = merge(0.0_dp, xq(i), abs(xq(i)) < negligible)
         xqd(i) = merge(0.0_dp, xqd(i), abs(xqd(i)) < negligible)
         xw(i) = merge(0.0_dp, xw(i), abs(xw(i)) < negligible)
      end do
   end subroutine flush_negligible

   !> q = psi^T u, q' = psi^T v from psi^T held as `psit` (n, n), column by column.
   pure subroutine coordinate_kernel(n, psit, u, v, q, qd)
      integer, intent(in) :: n
      real(dp), intent(in) :: psit(n, n), u(n), v(n)
      real(dp), intent(out) :: q(n), qd(n)
      integer :: i, j

      q = 0.0_dp
      qd = 0.0_dp
      do j = 1, n
         !GCC$ vector
         do i = 1, n
            q(i) = q(i) + psit(i, j)*u(j)
            qd(i) = qd(i) + psit(i, j)*v(j)
         end do
      end do
   end subroutine coordinate_kernel

   !> q = Phi^T M u, q' = Phi^T M v (mass-normalised modes).
   pure subroutine modal_state(n, phi, mass, u, v, q, qd)
      integer, intent(in) :: n
      real(dp), intent(in) :: phi(n, n), mass(n), u(n), v(n)
      real(dp), intent(out) :: q(n), qd(n)
      real(dp) :: mu(n), mv(n)
      integer :: i

      mu = mass*u
      mv = mass*v
      do i = 1, n
         q(i) = dot_product(phi(:, i), mu)
         qd(i) = dot_product(phi(:, i), mv)
      end do
   end subroutine modal_state

   !> Each mode's step: q, q' and -(omega^2 q + c q') at the end, and the step's input work
   !> and damping energy added to `din`, `ddamp`.
   pure subroutine modal_kernel(n, coef, lam, cm, q, qd, ag0, ag1, xq, xqd, xw, din, ddamp)
      integer, intent(in) :: n
      real(dp), intent(in) :: coef(n, 22), lam(n), cm(n), q(n), qd(n), ag0, ag1
      real(dp), intent(out) :: xq(n), xqd(n), xw(n)
      real(dp), intent(inout) :: din, ddamp
      ! The step's energies in four partial sums (modes i, i+1, i+2, i+3 of each block of four;
      ! the last, shorter block into the first sum), the modes' terms held for one block only
      ! (no work array of length n: nothing allocated in the step).
      real(dp) :: e1(4), e2(4), p1, p2, p3, p4, p5, p6, p7, s1(4), s2(4)
      integer :: i, i0, k, m

      s1 = 0.0_dp
      s2 = 0.0_dp
      do i0 = 1, n, 4
         m = min(4, n - i0 + 1)
         !GCC$ vector
         do k = 1, m
            i = i0 + k - 1
            xq(i) = coef(i, 1)*q(i) + coef(i, 2)*qd(i) + coef(i, 3)*ag0 + coef(i, 4)*ag1
            xqd(i) = coef(i, 5)*q(i) + coef(i, 6)*qd(i) + coef(i, 7)*ag0 + coef(i, 8)*ag1
            xw(i) = -(lam(i)*xq(i) + cm(i)*xqd(i))
            p1 = q(i)*q(i)
            p2 = q(i)*qd(i)
            p3 = qd(i)*qd(i)
            p4 = q(i)*ag0
            p5 = q(i)*ag1
            p6 = qd(i)*ag0
            p7 = qd(i)*ag1
            e1(k) = ((coef(i, 9)*p1 + coef(i, 10)*p2) + (coef(i, 11)*p3 + coef(i, 12)*p4)) + &
                    ((coef(i, 13)*p5 + coef(i, 14)*p6) + coef(i, 15)*p7)
            e2(k) = ((coef(i, 16)*p1 + coef(i, 17)*p2) + (coef(i, 18)*p3 + coef(i, 19)*p4)) + &
                    ((coef(i, 20)*p5 + coef(i, 21)*p6) + coef(i, 22)*p7)
         end do
         if (m == 4) then
            s1 = s1 + e1
            s2 = s2 + e2
         else
            do k = 1, m
               s1(1) = s1(1) + e1(k)
               s2(1) = s2(1) + e2(k)
            end do
         end if
      end do
      din = din + ((s1(1) + s1(3)) + (s1(2) + s1(4)))
      ddamp = ddamp + ((s2(1) + s2(3)) + (s2(2) + s2(4)))
   end subroutine modal_kernel

   !> Each mode's step under its modal ground, linear from g0(i) to g1(i) (unit participation,
   !> `coef2`): q, q' and -(omega^2 q + c q') at the end, and the step's input work and damping
   !> energy added to `din`, `ddamp`.
   pure subroutine modal_kernel_g(n, coef, lam, cm, q, qd, g0, g1, xq, xqd, xw, din, ddamp)
      integer, intent(in) :: n
      real(dp), intent(in) :: coef(n, 28), lam(n), cm(n), q(n), qd(n), g0(n), g1(n)
      real(dp), intent(out) :: xq(n), xqd(n), xw(n)
      real(dp), intent(inout) :: din, ddamp
      real(dp) :: p1, p2, p3, p4, p5, p6, p7, s1, s2
      integer :: i

      s1 = 0.0_dp
      s2 = 0.0_dp
      do i = 1, n
         xq(i) = coef(i, 1)*q(i) + coef(i, 2)*qd(i) + coef(i, 3)*g0(i) + coef(i, 4)*g1(i)
         xqd(i) = coef(i, 5)*q(i) + coef(i, 6)*qd(i) + coef(i, 7)*g0(i) + coef(i, 8)*g1(i)
         xw(i) = -(lam(i)*xq(i) + cm(i)*xqd(i))
         p1 = q(i)*q(i)
         p2 = q(i)*qd(i)
         p3 = qd(i)*qd(i)
         p4 = q(i)*g0(i)
         p5 = q(i)*g1(i)
         p6 = qd(i)*g0(i)
         p7 = qd(i)*g1(i)
         s1 = s1 + (((coef(i, 9)*p1 + coef(i, 10)*p2) + (coef(i, 11)*p3 + coef(i, 12)*p4)) + &
                    ((coef(i, 13)*p5 + coef(i, 14)*p6) + coef(i, 15)*p7)) + &
              ((coef(i, 23)*g0(i) + coef(i, 24)*g1(i))*g0(i) + coef(i, 25)*g1(i)*g1(i))
         s2 = s2 + (((coef(i, 16)*p1 + coef(i, 17)*p2) + (coef(i, 18)*p3 + coef(i, 19)*p4)) + &
                    ((coef(i, 20)*p5 + coef(i, 21)*p6) + coef(i, 22)*p7)) + &
              ((coef(i, 26)*g0(i) + coef(i, 27)*g1(i))*g0(i) + coef(i, 28)*g1(i)*g1(i))
      end do
      din = din + s1
      ddamp = ddamp + s2
   end subroutine modal_kernel_g

   !> u, v, a at the end from the modes: du = Phi q - u, v = Phi q', a = Phi w - r a_g (the first
   !> `ncol` columns; the others' coordinates are 0).
   pure subroutine shape_kernel(n, ncol, phi, xq, xqd, xw, u, ground, ag1, du, xv, xa)
      integer, intent(in) :: n, ncol
      real(dp), intent(in) :: phi(n, n), xq(n), xqd(n), xw(n), u(n), ground(n), ag1
      real(dp), intent(out) :: du(n), xv(n), xa(n)
      integer :: i, j, n4

      do j = 1, n
         du(j) = -u(j)
         xv(j) = 0.0_dp
         xa(j) = -ground(j)*ag1
      end do
      ! Four columns at a time: du, v and a are read and written once for four columns.
      n4 = ncol - mod(ncol, 4)
      do i = 1, n4, 4
         !GCC$ vector
         do j = 1, n
            du(j) = du(j) + ((phi(j, i)*xq(i) + phi(j, i + 1)*xq(i + 1)) + &
                             (phi(j, i + 2)*xq(i + 2) + phi(j, i + 3)*xq(i + 3)))
            xv(j) = xv(j) + ((phi(j, i)*xqd(i) + phi(j, i + 1)*xqd(i + 1)) + &
                             (phi(j, i + 2)*xqd(i + 2) + phi(j, i + 3)*xqd(i + 3)))
            xa(j) = xa(j) + ((phi(j, i)*xw(i) + phi(j, i + 1)*xw(i + 1)) + &
                             (phi(j, i + 2)*xw(i + 2) + phi(j, i + 3)*xw(i + 3)))
         end do
      end do
      do i = n4 + 1, ncol
         !GCC$ vector
         do j = 1, n
            du(j) = du(j) + phi(j, i)*xq(i)
            xv(j) = xv(j) + phi(j, i)*xqd(i)
            xa(j) = xa(j) + phi(j, i)*xw(i)
         end do
      end do
   end subroutine shape_kernel

   !> Complete the predicted exact step: u, v, a, C v, the modal coordinates and the energies.
   module subroutine commit_exact(st, w_in, e_out)
      !> Integrator state with a pending exact step.
      type(newmark_state), intent(inout) :: st
      !> Input work so far (added to; optional, with `e_out`).
      real(dp), intent(inout), optional :: w_in
      !> Kinetic + strain + damping energy so far (added to; optional, with `w_in`).
      real(dp), intent(inout), optional :: e_out

      st%u = st%u + st%du
      st%v = st%xv
      st%a = st%xa
      ! The energies from the coordinates (kinetic q'^T q'/2 of the mass-normalised modes,
      ! strain (sum omega^2 q^2 + z^T z)/2 with DOFs without mass), and C v, (K+G) u,
      ! (K+G) v only when a Newmark step needs them (`band_stale`): no band product in a run
      ! of exact steps.
      call modal_energies(st%n, st%nm, st%lam, st%xq, st%xqd, st%kinetic, st%strain)
      st%band_stale = .true.
      st%pending = .false.
      st%q = st%xq
      st%qd = st%xqd
      st%modal_valid = .true.
      st%input_work = st%input_work + st%x_input
      st%damping_energy = st%damping_energy + st%x_damping
      if (present(w_in) .and. present(e_out)) then
         w_in = w_in + st%input_work
         e_out = e_out + ((st%kinetic + st%strain) + st%damping_energy)
      end if
   end subroutine commit_exact

   !> Kinetic q'^T q'/2 and strain (sum omega^2 q^2 + z^T z)/2 energy of the modal coordinates
   !> (the first `nm` massive, the rest relaxation coordinates z): the three sums of
   !> `sum(qd(1:nm)**2)`, `sum(lam*q(1:nm)**2)` and `sum(q(nm+1:n)**2)` in the same order, bit for
   !> bit, but run side by side in one loop (their additions are three independent chains).
   pure subroutine modal_energies(n, nm, lam, q, qd, kinetic, strain)
      integer, intent(in) :: n, nm
      real(dp), intent(in) :: lam(nm), q(n), qd(n)
      real(dp), intent(out) :: kinetic, strain
      real(dp) :: sk, sl, sz
      integer :: i, nz

      sk = 0.0_dp
      sl = 0.0_dp
      sz = 0.0_dp
      nz = n - nm
      do i = 1, min(nm, nz)
         sk = sk + qd(i)**2
         sl = sl + lam(i)*q(i)**2
         sz = sz + q(nm + i)**2
      end do
      do i = min(nm, nz) + 1, nm
         sk = sk + qd(i)**2
         sl = sl + lam(i)*q(i)**2
      end do
      do i = min(nm, nz) + 1, nz
         sz = sz + q(nm + i)**2
      end do
      kinetic = 0.5_dp*sk
      strain = 0.5_dp*(sl + sz)
   end subroutine modal_energies

end submodule pound_newmark_exact
