!> Bilinear storeys of shear buildings (issue 25): complementarity elements acting along the
!> storey drift rows, solved exactly in each step on the constant factored Khat.
!>
!> A storey j joins the DOFs of its drift row b_j (d_j = b_j^T u); its spring has the initial
!> stiffness k_j (the shear row's scale), the yield shear Fy_j and the hardening ratio r_j.
!> Hysteresis is Steel01's with kinematic hardening only: from the committed (d_n, f_n)
!>
!>     f = max(r k d - (1-r) Fy, min(r k d + (1-r) Fy, f_n + k (d - d_n)))      (`bilinear_force`)
!>
!> Maier's form: f = k (d - p), the plastic drift p = p_n + lam_plus - lam_minus with
!> lam >= 0 in complementarity with phi_plus = r k d + (1-r) Fy - f >= 0 and
!> phi_minus = f - r k d + (1-r) Fy >= 0. The elastic k_j stays in K (Khat factored once); a
!> plastic increment dp_j acts on the structure as the load k_j b_j dp_j, so the drift of the
!> step is d = d_tr + A dp with A_ij = k_j b_i^T Khat^{-1} b_j (the columns Khat^{-1} b_j from
!> the integrator's solve, kept for small buildings). Only the storeys whose trial force
!> leaves its elastic range enter the LCP (one row each, on the side it leaves by); the
!> solution is then checked on every storey and the LCP solved again with any storey that left
!> its range (exact: the loop ends with every storey's conditions met), and its natural
!> residual is checked. The LCP is non-convex where r < 0 or P-Delta makes the tangent
!> negative: Lemke's method solves it (`pound_lemke`).
!>
!> Energies: the plastic load's work W_L = sum_j k_j (p_n + p_{n+1})/2 (d_{n+1} - d_n) per step
!> (the trapezoid, consistent with Newmark's balance) enters the integrator's balance; the
!> recoverable strain energy is sum_j k_j (d - p)^2 / 2 (plus the P-Delta part), the hysteretic
!> energy sum_j (f_n + f_{n+1})/2 dp_j; their sum is the elastic u.(K+G)u/2 - W_L exactly, so
!> the audit checks the step's plastic loads.
module pound_storey_yield
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, error_at
   use pound_strings, only: str
   use pound_structure, only: structure_model, recovery_rows, recover, structure_yields, never_yields
   use pound_integrator, only: integrator
   use pound_analysis_plan, only: analysis_plan
   use pound_contact, only: contact_system, contact_step, contact_release
   use pound_response, only: response_record, q_shear, history_sink, response_flush
   use pound_lemke, only: lemke_report, lemke_status_name
   use pound_lcp_dense, only: dense_lcp, dense_lcp_init, dense_lcp_reserve, dense_lcp_solve
   use pound_complementarity_set, only: complementarity_set
   implicit none
   private

   public :: bilinear_force, storey_yield_set, storey_yield_result
   public :: yield_set_init, yield_step, yield_steps, yield_commit, yield_energy_terms, yield_load_work, yield_finish
   public :: stick_khat, stick_active_set
   public :: yield_residual_limit, yield_sets_init, yield_sample, yield_results, yield_energy_step
   ! (Used by the submodules: gfortran drops private procedures a submodule calls.)
   public :: drifts, step_drifts, solve_rows, hinge_block, finish_tallies, plastic_loads

   !> Largest natural residual of a step's storey LCP (relative to the storey's yield shear).
   real(dp), parameter :: yield_residual_limit = 1.0e-8_dp
   !> A coupled step's plastic increments have settled when no storey's changed by more than
   !> this times its yield drift Fy/k between two solves of the joints.
   real(dp), parameter :: settle_tolerance = 1.0e-12_dp
   !> Largest number of alternations between the joints' LCP and the storeys' LCP in a step.
   integer, parameter :: max_alternations = 200
   !> After a solve, a storey outside its elastic range by more than this times its yield
   !> shear enters the LCP.
   real(dp), parameter :: enter_tolerance = 1.0e-11_dp
   !> Largest n_dofs x n_storeys for which the columns Khat^{-1} b_j are kept between steps.
   integer, parameter :: cache_limit = 4000000

   !> The bilinear storeys of one building (n = 0: elastic storeys, nothing to do): an
   !> element set of the complementarity core (its rows the storeys' drift rows, or the
   !> hinges' rotation rows; its dense LCP `lcp` the base's).
   type, extends(complementarity_set) :: storey_yield_set
      !> Storeys and DOFs.
      integer :: n = 0, nd = 0
      !> The rows are a stick's chain: storey j joins DOFs j-1 and j with coefficients -1, 1.
      logical :: stick = .false.
      !> Drift rows (the model's, with each row's scale folded into its coefficients).
      type(recovery_rows) :: rows
      !> Initial stiffness (kN/m), yield shear (kN), hardening ratio of each storey.
      real(dp), allocatable :: k(:), fy(:), r(:)
      !> Committed drift (m), spring force (kN) and plastic drift (m) of each storey.
      real(dp), allocatable :: d(:), f(:), p(:)
      !> Peak |drift| and peak |force| with its time, over the run.
      real(dp), allocatable :: dmax(:), fmax(:), tmax(:)
      !> The step: trial drift (plastic increments removed), plastic increments applied, their
      !> response Khat^{-1} sum_j k_j b_j dp_j (in du), side of each LCP row (+1, -1; 0: not in).
      real(dp), allocatable :: dtr(:), dpl(:), xdp(:), work(:), dnew(:), dold(:)
      integer, allocatable :: side(:), act(:)
      integer :: na = 0
      logical :: loaded = .false.
      !> Columns Khat^{-1} b_j: slot of storey j (0: none yet) and the dt they belong to.
      real(dp), allocatable :: col(:, :)
      integer, allocatable :: slot(:)
      integer :: n_slots = 0
      real(dp) :: col_dt = -1.0_dp
      !> Collapse: drift limit of each storey (collapse_drift x height; m), the storey that
      !> passed it first (0: none) and when (s).
      real(dp), allocatable :: limit(:)
      integer :: collapse_storey = 0
      real(dp) :: collapse_time = 0.0_dp
      !> The building collapsed: it is no longer integrated (`pound_storey_collapse`).
      logical :: frozen = .false.
      !> A stick's tridiagonal Khat (diagonal, off-diagonal) of the dt `col_dt`, and the work
      !> arrays of its tangent system (`stick_active_set`).
      real(dp), allocatable :: khat_d(:), khat_e(:), td(:), te(:), ty(:)
      !> A stick's K+G (band storage), masses and Rayleigh coefficients.
      real(dp), allocatable :: kt(:, :), mass(:)
      real(dp) :: a0 = 0.0_dp, a1 = 0.0_dp
      integer :: stick_solves = 0
      !> Work of the plastic loads on the elastic structure (W_L) and hysteretic energy (kJ).
      real(dp) :: load_work = 0.0_dp, hysteretic = 0.0_dp
      !> LCP solves, storeys that entered them, the most in one solve, steps with storeys
      !> yielding while joints act (the LCPs alternated), largest residual.
      integer :: solves = 0, lcp_rows = 0, max_rows = 0, joint_steps = 0
      !> Most solves of the joints' LCP in one step beyond the first (alternations).
      integer :: alternations = 0
      real(dp) :: residual = 0.0_dp
      !> A DOF vector of work (the coupled step's end-of-step increment).
      real(dp), allocatable :: tmp(:)
      !> The coupled LCP of joints and storeys (`yield_coupled`; held by the first building's
      !> set), the building and storey of each storey row, the joints' coupling
      !> G(k, s) = B_k^T Khat^{-1} b_s (m, rows).
      type(dense_lcp) :: clcp
      real(dp), allocatable :: cg(:, :)
      integer, allocatable :: cb(:), cj(:)
      !> Rows that are not the storeys (a building in plan's planes, `structure_model%yield_k`):
      !> the storey of each row, whether its force is part of its storey's storey shear
      !> (`sval`, `speak`, `stime` then hold the storey shears), the result row of row 1
      !> (0: none; the rows' peak forces become the result rows' peaks).
      integer, allocatable :: storey_of(:)
      logical, allocatable :: in_shear(:)
      integer :: result_first = 0
      !> Plastic hinges of a frame (pound_storey_yield_hinges): the rows are the hinges' end
      !> rotations (k = 4EI/L, fy the yield moment, r = 0), each coupled by kc = 2EI/L to the
      !> row `mate` (the element's other end): m = S (theta - p), S = [k kc; kc k] per element.
      logical :: hinges = .false.
      !> (`hk`: each hinge's kinematic hardening modulus H (kN m/rad): |m - H p| <= My.)
      real(dp), allocatable :: kc(:), hk(:)
      !> (`level`: the storey of a column's hinge, the floor of a beam's: the storey below it.)
      integer, allocatable :: mate(:), level(:)
      !> Frames: storey drift rows, storey-shear and member rows and their plastic parts (over
      !> the hinges), collapse drift limits, the storeys' drifts and shears of the last commit,
      !> their peaks and times (plastic parts removed), the members' peaks and times, each
      !> hinge's peak |p| and peak |m|/My, the plastic rotations and moments before the commit.
      type(recovery_rows) :: crows, srows, sprows, mrows, mprows
      real(dp), allocatable :: climit(:), cdrift(:), sval(:), speak(:), stime(:), mpeak(:), mtime(:)
      real(dp), allocatable :: pmax(:), ratio(:), pold(:), fold(:)
      !> The step's plastic loads over every DOF (`alldof`: 1 .. nd), as given to the
      !> integrator's `add_load_rows`: sum_j k_j dp_j b_j (storeys), sum_j dp_j a_j (hinges).
      real(dp), allocatable :: fload(:)
      integer, allocatable :: alldof(:)
   contains
      procedure :: set_rows => storey_rows
      procedure :: row_value => storey_row_value
      procedure :: row_scatter => storey_row_scatter
      procedure :: set_column => storey_column
      procedure :: lcp_block => storey_block
      procedure :: check => storey_check
      procedure :: commit => storey_commit
      procedure :: energy => storey_energy
   end type storey_yield_set

   !> What a run reports of a building's bilinear storeys (n = 0: elastic storeys).
   type :: storey_yield_result
      !> Storeys (0: elastic).
      integer :: n = 0
      !> Peak ductility max|d| / (Fy/k), residual drift (m) at the end, peak |force| (kN).
      real(dp), allocatable :: ductility(:), residual_drift(:), peak_force(:)
      !> Hysteretic (plastic) energy dissipated by the storeys (kJ).
      real(dp) :: hysteretic = 0.0_dp
      !> The storey whose drift / height passed `collapse_drift` first (0: no collapse) and when
      !> (s): the analysis stopped at the end of that step.
      integer :: collapse_storey = 0
      real(dp) :: collapse_time = 0.0_dp
      !> LCP solves, rows solved, the most rows in one solve, steps with storeys yielding while
      !> joints act, and the largest natural residual.
      integer :: solves = 0, lcp_rows = 0, max_rows = 0, joint_steps = 0
      !> Most solves of the joints' LCP in one step beyond the first (alternations).
      integer :: alternations = 0
      real(dp) :: residual = 0.0_dp
      !> A frame's plastic hinges (0: none; then `ductility` holds each storey's largest peak
      !> |plastic rotation| of its column hinges and of the beam hinges of the floor at its top,
      !> rad): peak |plastic rotation| (rad) and peak
      !> |moment| / yield moment of each hinge.
      integer :: n_hinges = 0
      real(dp), allocatable :: rotation(:), moment_ratio(:)
   end type storey_yield_result

   interface
      !> A stick's tridiagonal matrix fk (K+G) + fm M whose inverse the integrator's `solve`
      !> applies, its coefficients from the integrator (`solve_matrix`; `yield_set_init` keeps
      !> K+G, M, a0, a1 for it).
      module subroutine stick_khat(ys, st)
         !> The building's storeys (a stick).
         type(storey_yield_set), intent(inout) :: ys
         !> Its integrator, set up for the step.
         class(integrator), intent(in) :: st
      end subroutine stick_khat

      !> The storeys' step of a stick by the primal-dual active-set method on the tangent
      !> system: with the active storeys (`act`, `side`) on their yield lines the step is the
      !> tridiagonal solve (Khat - sum_A (1-r) k b b^T) y = sum_A k b dp_trial; storeys whose
      !> plastic increment has the wrong sign leave, storeys outside their range enter, until
      !> the set repeats. `solved` false (set restored): the method did not settle or the
      !> tangent system is not positive definite (Lemke's method takes the step).
      module subroutine stick_active_set(ys, u, du, solved)
         !> The building's storeys with the entering storeys in `act`, `side`.
         type(storey_yield_set), intent(inout) :: ys
         !> Committed displacements and the trial du (plastic loads removed).
         real(dp), intent(in) :: u(:), du(:)
         !> The step was solved (`dpl`, `xdp`, `dnew`, `act`, `side` set).
         logical, intent(out) :: solved
      end subroutine stick_active_set

      !> A step in which storeys yield while joints can act, as ONE LCP over the acting joints'
      !> rows (`lcp_assemble`) and the yielding storeys' rows, coupled through Khat^{-1}
      !> (pound_storey_yield_coupled): called after a first `yield_step` of every building
      !> with the joints' solution of `contact_step` in du, it replaces both.
      module subroutine yield_coupled(ys, st, cs, t, step, models, error)
         !> The buildings' storeys.
         type(storey_yield_set), intent(inout) :: ys(:)
         !> The integrators (du: predicted, with the first solutions' loads).
         class(integrator), intent(inout), target :: st(:)
         !> The contact system after `contact_step`.
         type(contact_system), intent(inout) :: cs
         !> Time and step, for messages.
         real(dp), intent(in) :: t
         integer, intent(in) :: step
         !> The buildings (names, for messages).
         type(structure_model), intent(in) :: models(:)
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine yield_coupled

      !> The hinge rows, stiffness, yield moments and the frame's rows of building `b` (a frame
      !> with plastic hinges) into `ys` (n, nd set; the common arrays are the caller's).
      module subroutine hinge_set_init(ys, b, collapse_drift)
         type(storey_yield_set), intent(inout) :: ys
         type(structure_model), intent(in) :: b
         real(dp), intent(in), optional :: collapse_drift
      end subroutine hinge_set_init

      !> `storey_block` of a frame's hinges: M = S_a (S + diag H - A) S_a over the rows in the
      !> LCP, A_ij = a_i^T Khat^{-1} a_j with a_j = k_j b_j + kc_j b_mate(j) (the moment row),
      !> q = My - s (m_tr - H p).
      module subroutine hinge_block(ys, st, m)
         type(storey_yield_set), intent(inout) :: ys
         class(integrator), intent(in) :: st
         integer, intent(in) :: m
      end subroutine hinge_block


      !> One LCP over the rows `act(1:na)` (each on its side; the block from `lcp_block`):
      !> the plastic increments `dpl`, their response `xdp` and the end-of-step values `dnew`
      !> of every row (pound_storey_yield_rows).
      module subroutine solve_rows(ys, st, u, du, t, step, label, error)
         type(storey_yield_set), intent(inout) :: ys
         class(integrator), intent(in) :: st
         real(dp), intent(in) :: u(:), du(:)
         real(dp), intent(in) :: t
         integer, intent(in) :: step
         character(len=*), intent(in) :: label
         type(error_type), allocatable, intent(out) :: error
      end subroutine solve_rows

      !> The set's bindings of `complementarity_set` (pound_storey_yield_rows).
      pure module integer function storey_rows(set)
         class(storey_yield_set), intent(in) :: set
      end function storey_rows
      pure module real(dp) function storey_row_value(set, i, x)
         class(storey_yield_set), intent(in) :: set
         integer, intent(in) :: i
         real(dp), intent(in) :: x(:)
      end function storey_row_value
      pure module subroutine storey_row_scatter(set, i, s, x)
         class(storey_yield_set), intent(in) :: set
         integer, intent(in) :: i
         real(dp), intent(in) :: s
         real(dp), intent(inout) :: x(:)
      end subroutine storey_row_scatter
      module subroutine storey_column(set, st, i, x)
         class(storey_yield_set), intent(inout) :: set
         class(integrator), intent(in) :: st
         integer, intent(in) :: i
         real(dp), intent(out) :: x(:)
      end subroutine storey_column
      module subroutine storey_block(set, st, m)
         class(storey_yield_set), intent(inout) :: set
         class(integrator), intent(in) :: st
         integer, intent(in) :: m
      end subroutine storey_block
      module subroutine storey_check(set, t, step, label, error)
         class(storey_yield_set), intent(inout) :: set
         real(dp), intent(in) :: t
         integer, intent(in) :: step
         character(len=*), intent(in) :: label
         type(error_type), allocatable, intent(out) :: error
      end subroutine storey_check
      pure module subroutine storey_commit(set, u, t, shear)
         class(storey_yield_set), intent(inout) :: set
         real(dp), intent(in) :: u(:)
         real(dp), intent(in) :: t
         real(dp), intent(inout), optional :: shear(:)
      end subroutine storey_commit
      !> (pound_storey_yield_energy.)
      pure module subroutine storey_energy(set, strain, dissipated)
         class(storey_yield_set), intent(in) :: set
         real(dp), intent(inout) :: strain, dissipated
      end subroutine storey_energy

      !> The end moment of hinge row j less its back moment, m - H p, for the rotations `d`
      !> (plastic increments `dpl` included): the argument of its yield function.
      pure module real(dp) function hinge_force(ys, j, d) result(f)
         type(storey_yield_set), intent(in) :: ys
         integer, intent(in) :: j
         real(dp), intent(in) :: d(:)
      end function hinge_force


      !> The plastic loads of the hinges' increments `dpl`: `fload` = sum_j dp_j a_j and its
      !> response `xdp` = Khat^{-1} fload.
      module subroutine hinge_loads(ys, st)
         type(storey_yield_set), intent(inout) :: ys
         class(integrator), intent(in) :: st
      end subroutine hinge_loads

      !> A hinge in the LCP without plastic increment whose end moment passes the other yield
      !> line turns to that side (`added` set).
      module subroutine hinge_turns(ys, added)
         type(storey_yield_set), intent(inout) :: ys
         logical, intent(inout) :: added
      end subroutine hinge_turns

      !> `yield_commit` of a frame's hinges: rotations, plastic rotations, moments, energies,
      !> peaks; the storeys' drifts (collapse) and shears and the member rows without their
      !> plastic parts (the storey-shear history column `shear` replaced).
      pure module subroutine hinge_commit(ys, u, t, shear)
         type(storey_yield_set), intent(inout) :: ys
         real(dp), intent(in) :: u(:)
         real(dp), intent(in) :: t
         real(dp), intent(inout), optional :: shear(:)
      end subroutine hinge_commit

      !> `yield_finish` of a frame's hinges: the response's storey-shear and member peaks become
      !> those without the plastic parts.
      pure module subroutine hinge_finish(ys, rec, res)
         type(storey_yield_set), intent(in) :: ys
         type(response_record), intent(inout) :: rec
         type(storey_yield_result), intent(out) :: res
      end subroutine hinge_finish

      !> Total work W_L of the plastic loads of every building (kJ): what the integrators'
      !> balance counts beyond the elastic structure (pound_storey_yield_energy).
      pure module real(dp) function yield_load_work(ys) result(w)
         !> The buildings' storeys.
         type(storey_yield_set), intent(in) :: ys(:)
      end function yield_load_work

      !> Turn an energy sample of the elastic integrators into that of the inelastic buildings
      !> (pound_storey_yield_energy).
      pure module subroutine yield_energy_terms(ys, strain, plastic)
         !> The buildings' storeys.
         type(storey_yield_set), intent(in) :: ys(:)
         !> The sample's strain energy and plastic work (kJ).
         real(dp), intent(inout) :: strain, plastic
      end subroutine yield_energy_terms

      !> The energy terms of the step (pound_storey_yield_energy).
      pure module subroutine yield_energy_step(ys, output, coupled, i_strain, i_plastic, stored, sample, e_out)
         !> The buildings' storeys after the step's commit.
         type(storey_yield_set), intent(in) :: ys(:)
         !> An output step; a coupled analysis.
         logical, intent(in) :: output, coupled
         !> Positions of the strain energy and of the plastic work in a sample.
         integer, intent(in) :: i_strain, i_plastic
         !> The stored output sample, the step's sample (kJ; at least as long).
         real(dp), intent(inout) :: stored(:), sample(:)
         !> The integrators' sum kinetic + strain + damping of an uncoupled step (kJ).
         real(dp), intent(inout) :: e_out
      end subroutine yield_energy_step

      !> The drift of every storey of `ys` for the DOF vector x (+ y, when given) into `d`
      !> (`work`: the sum x + y on the general path; pound_storey_yield_stick).
      pure module subroutine drifts(ys, x, d, work, y)
         type(storey_yield_set), intent(in) :: ys
         real(dp), intent(in) :: x(:)
         real(dp), intent(out) :: d(:), work(:)
         real(dp), intent(in), optional :: y(:)
      end subroutine drifts

      !> The drifts `dnew` at the end of a solved step: of u + du + xdp (the step's response
      !> with the plastic increments; pound_storey_yield_stick).
      pure module subroutine step_drifts(ys, u, du)
         type(storey_yield_set), intent(inout) :: ys
         real(dp), intent(in) :: u(:), du(:)
      end subroutine step_drifts
   end interface

contains

   !> The end-of-step force of a bilinear storey (Steel01, kinematic hardening) from the
   !> committed drift and force.
   pure elemental real(dp) function bilinear_force(k, fy, r, d_n, f_n, d) result(f)
      !> Initial stiffness, yield force, hardening ratio.
      real(dp), intent(in) :: k, fy, r
      !> Committed drift and force; drift at the end of the step.
      real(dp), intent(in) :: d_n, f_n, d

      f = max(r*k*d - (1.0_dp - r)*fy, min(r*k*d + (1.0_dp - r)*fy, f_n + k*(d - d_n)))
   end function bilinear_force

   !> Set up the storeys of building `b` (nothing when its storeys are elastic).
   subroutine yield_set_init(ys, b, collapse_drift)
      !> The set (at rest on return).
      type(storey_yield_set), intent(out) :: ys
      !> The building.
      type(structure_model), intent(in) :: b
      !> Storey drift / height at which the building collapses (none: no check).
      real(dp), intent(in), optional :: collapse_drift
      integer :: j, n, i, e

      if (allocated(b%hinge_moment)) then
         call hinge_set_init(ys, b, collapse_drift)
         n = ys%n
      else
         if (.not. allocated(b%yield_shear)) return
         if (allocated(b%yield_k)) then
            ! The model's own yielding rows (a building in plan's planes).
            n = b%yield_rows%n
            ys%n = n
            ys%nd = b%n
            ys%rows = b%yield_rows
            ys%k = b%yield_k
            ys%storey_of = b%yield_storey
            ys%in_shear = b%yield_in_shear
            ys%result_first = b%yield_result_first
            allocate (ys%sval(b%drift%n), ys%speak(b%drift%n), ys%stime(b%drift%n), source=0.0_dp)
         else
            n = b%drift%n
            ys%n = n
            ys%nd = b%n
            ys%rows = b%drift
            allocate (ys%k(n))
            do j = 1, n
               do e = b%drift%start(j), b%drift%start(j + 1) - 1
                  ys%rows%coef(e) = b%drift%scale(j)*b%drift%coef(e)
               end do
               ys%rows%scale(j) = 1.0_dp
               ys%k(j) = b%shear%scale(j)/b%drift%scale(j)
            end do
            ys%stick = b%stick .and. b%n == n .and. b%kd == 1
            if (ys%stick) ys%stick = all(b%drift%scale == 1.0_dp)
         end if
         ys%limit = spread(huge(1.0_dp), 1, n)
         if (present(collapse_drift) .and. allocated(b%yield_height)) ys%limit = collapse_drift*b%yield_height
         ys%fy = b%yield_shear
         ys%r = b%hardening
      end if
      allocate (ys%d(n), ys%f(n), ys%p(n), ys%dmax(n), ys%fmax(n), ys%tmax(n), ys%dtr(n), ys%dpl(n), &
                ys%dnew(n), ys%dold(n), source=0.0_dp)
      allocate (ys%xdp(b%n), ys%work(b%n), ys%tmp(b%n), source=0.0_dp)
      if (.not. ys%hinges) then
         allocate (ys%fload(b%n), source=0.0_dp)
         ys%alldof = [(i, i=1, b%n)]
      end if
      allocate (ys%side(n), ys%act(n), source=0)
      allocate (ys%slot(n), source=0)
      i = n
      if (real(b%n, dp)*real(n, dp) > real(cache_limit, dp)) i = 0
      allocate (ys%col(b%n, max(i, 1)))
      if (ys%stick) then
         ys%kt = b%kt
         ys%mass = b%mass
         ys%a0 = b%a0
         ys%a1 = b%a1
         allocate (ys%khat_d(n), ys%khat_e(max(n - 1, 1)), ys%td(n), ys%te(max(n - 1, 1)), ys%ty(n), &
                   source=0.0_dp)
      end if
      i = min(n, 16)
      call dense_lcp_init(ys%lcp, i)
   end subroutine yield_set_init

   !> Set up the storeys of every building; `inelastic`: some building has bilinear storeys
   !> or plastic hinges (`ys` is then allocated, one set a building). Any integrator: the
   !> storeys load and solve only through its `add_load_rows`, `solve` and `solve_matrix`.
   subroutine yield_sets_init(ys, models, cfg, inelastic, collapsed, frozen)
      !> One set a building (unallocated when every building is elastic).
      type(storey_yield_set), allocatable, intent(out) :: ys(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The analysis plan (`collapse_drift`).
      type(analysis_plan), intent(in) :: cfg
      !> Some building has bilinear storeys; none has collapsed (false).
      logical, intent(out) :: inelastic, collapsed
      !> Per building: collapsed, no longer integrated (all false).
      logical, intent(out) :: frozen(:)
      integer :: ib

      collapsed = .false.
      frozen = .false.
      inelastic = any([(structure_yields(models(ib)), ib=1, size(models))])
      if (.not. inelastic) return
      allocate (ys(size(models)))
      do ib = 1, size(models)
         call yield_set_init(ys(ib), models(ib), cfg%collapse_drift)
      end do
   end subroutine yield_sets_init

   !> Commit a building's storeys after its integrator's commit and `response_sample`: the
   !> storey-shear sample just stored (an output step) becomes the spring forces.
   subroutine yield_sample(ys, u, t, output, rec, collapsed)
      !> The building's storeys.
      type(storey_yield_set), intent(inout) :: ys
      !> Committed displacements.
      real(dp), intent(in) :: u(:)
      !> Time (s).
      real(dp), intent(in) :: t
      !> An output step (its sample was just stored).
      logical, intent(in) :: output
      !> The building's response record.
      type(response_record), intent(inout) :: rec
      !> Set when the building has collapsed (`yield_freeze` at the end of the step).
      logical, intent(inout) :: collapsed

      ! (`yield_commit` is the set's `commit`, called directly on the step's path.)
      if (output .and. rec%store(q_shear)) then
         call yield_commit(ys, u, t, rec%shear(:, rec%n_out))
      else
         call yield_commit(ys, u, t)
      end if
      if (ys%collapse_storey > 0) collapsed = .true.
   end subroutine yield_sample

   !> The run's storey results of every building (`yield_finish`).
   pure subroutine yield_results(ys, rec, res)
      !> The buildings' storeys at the end of the run.
      type(storey_yield_set), intent(in) :: ys(:)
      !> The buildings' response records (storey-shear peaks replaced).
      type(response_record), intent(inout) :: rec(:)
      !> One result a building.
      type(storey_yield_result), allocatable, intent(out) :: res(:)
      integer :: ib

      allocate (res(size(ys)))
      do ib = 1, size(ys)
         if (ys(ib)%hinges) then
            call hinge_finish(ys(ib), rec(ib), res(ib))
         else if (allocated(ys(ib)%storey_of)) then
            call yield_finish(ys(ib), rec(ib)%peak(:, q_shear), rec(ib)%peak_time(:, q_shear), res(ib))
            ! The storey shears and the result rows of the rows' forces (a plan's plane shears).
            rec(ib)%peak(:, q_shear) = ys(ib)%speak
            rec(ib)%peak_time(:, q_shear) = ys(ib)%stime
            if (ys(ib)%result_first > 0 .and. allocated(rec(ib)%result_peak)) then
               associate (i0 => ys(ib)%result_first, n => ys(ib)%n)
                  rec(ib)%result_peak(i0:i0 + n - 1) = ys(ib)%fmax
                  rec(ib)%result_time(i0:i0 + n - 1) = ys(ib)%tmax
               end associate
            end if
         else
            call yield_finish(ys(ib), rec(ib)%peak(:, q_shear), rec(ib)%peak_time(:, q_shear), res(ib))
         end if
      end do
   end subroutine yield_results

   !> Solve the step's storey conditions for the predicted increment du of integrator `st`
   !> (which may hold this step's plastic loads of an earlier call: they are replaced).
   !> `changed`: the plastic loads in du changed (a coupled step then solves its joints again).
   subroutine yield_step(ys, st, u, t, step, label, changed, error)
      !> The building's storeys.
      type(storey_yield_set), intent(inout) :: ys
      !> Its integrator, with the predicted du.
      class(integrator), intent(inout), target :: st
      !> Committed displacements.
      real(dp), intent(in) :: u(:)
      !> Time and step, building name, for messages.
      real(dp), intent(in) :: t
      integer, intent(in) :: step
      character(len=*), intent(in) :: label
      !> The plastic loads applied to du changed.
      logical, intent(out) :: changed
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp), pointer :: du(:)
      real(dp) :: f, c, h
      integer :: j, round
      logical :: added, solved

      changed = .false.
      if (ys%n == 0) return
      ! The trial (elastic) state: du without this step's plastic loads.
      if (ys%loaded) call plastic_loads(ys, st, -1.0_dp)
      du => st%du_view()
      call drifts(ys, u, ys%dtr, ys%work, du)
      ys%na = 0
      ! Every storey whose trial force is outside its elastic range (the loop of an elastic
      ! step: one test a storey).
      do j = 1, ys%n
         f = ys%f(j) + ys%k(j)*(ys%dtr(j) - ys%d(j))
         if (ys%hinges) f = f + ys%kc(j)*(ys%dtr(ys%mate(j)) - ys%d(ys%mate(j))) - ys%hk(j)*ys%p(j)
         c = ys%r(j)*ys%k(j)*ys%dtr(j)
         h = (1.0_dp - ys%r(j))*ys%fy(j)
         if (abs(f - c) > h) call enter(j)
      end do
      ys%dold = ys%dpl
      if (ys%na == 0) then
         ys%dpl = 0.0_dp
         ys%xdp = 0.0_dp
         changed = ys%loaded
         ys%loaded = .false.
         return
      end if
      if (st%step_size() /= ys%col_dt) then
         ys%slot = 0
         ys%n_slots = 0
         ys%col_dt = st%step_size()
         if (ys%stick) call stick_khat(ys, st)
      end if
      ! A stick: the active-set method on the tridiagonal tangent system first (O(n) a pass).
      solved = .false.
      if (ys%stick) call stick_active_set(ys, u, du, solved)
      if (solved) then
         ys%solves = ys%solves + 1
         ys%lcp_rows = ys%lcp_rows + ys%na
         ys%max_rows = max(ys%max_rows, ys%na)
      end if
      do round = 1, ys%n + 1
         if (solved) exit
         call solve_rows(ys, st, u, du, t, step, label, error)
         if (allocated(error)) return
         ! Every storey outside its range enters (on its side); the others are met.
         added = .false.
         do j = 1, ys%n
            if (ys%side(j) /= 0) cycle
            call enter(j, ys%dnew(j))
            if (ys%side(j) /= 0) added = .true.
         end do
         if (ys%hinges) call hinge_turns(ys, added)
         if (.not. added) exit
      end do
      call ys%check(t, step, label, error)
      if (allocated(error)) return
      call plastic_loads(ys, st, 1.0_dp)
      ys%loaded = .true.
      ! Changed beyond round-off (a coupled step solves its joints again).
      do j = 1, ys%n
         if (abs(ys%dpl(j) - ys%dold(j)) > settle_tolerance*ys%fy(j)/ys%k(j)) changed = .true.
      end do
      do j = 1, ys%na
         ys%side(ys%act(j)) = 0
      end do

   contains

      !> Storey j enters the LCP when its force for the drift `dj` (default the trial drift) is
      !> outside its elastic range, on the side it leaves by.
      subroutine enter(j, dj)
         integer, intent(in) :: j
         real(dp), intent(in), optional :: dj
         real(dp) :: d, f, c, h

         if (present(dj)) then
            d = dj
         else
            d = ys%dtr(j)
         end if
         f = ys%f(j) + ys%k(j)*(d - ys%d(j))
         if (ys%hinges) then
            f = f + ys%kc(j)*(ys%dtr(ys%mate(j)) - ys%d(ys%mate(j))) - ys%hk(j)*ys%p(j)
            if (present(dj)) f = hinge_force(ys, j, ys%dnew)
         end if
         c = ys%r(j)*ys%k(j)*d
         h = (1.0_dp - ys%r(j))*ys%fy(j)
         ! (After a solve: outside by more than round-off.)
         if (present(dj)) h = h + enter_tolerance*ys%fy(j)
         if (f > c + h) then
            ys%side(j) = 1
         else if (f < c - h) then
            ys%side(j) = -1
         else
            return
         end if
         ys%na = ys%na + 1
         ys%act(ys%na) = j
      end subroutine enter
   end subroutine yield_step

   !> The storeys of every building in the step whose predicted du the integrators hold (after
   !> `contact_step` when there are joints). With joints, the joints' LCP and the storeys' are
   !> solved in turn (each exactly, from the step's predicted du with the other's forces) until
   !> the storeys' plastic increments no longer change (`settle_tolerance`): the end of the
   !> step then meets the joints' and the storeys' conditions together.
   subroutine yield_steps(ys, st, cs, models, t, step, error)
      !> The buildings' storeys.
      type(storey_yield_set), intent(inout) :: ys(:)
      !> The integrators with the predicted du.
      class(integrator), intent(inout), target :: st(:)
      !> The contact system (after `contact_step`; m = 0: none).
      type(contact_system), intent(inout) :: cs
      !> The buildings (names for messages).
      type(structure_model), intent(in) :: models(:)
      !> Time and step, for messages.
      real(dp), intent(in) :: t
      integer, intent(in) :: step
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: it, ib
      logical :: changed, any_change

      do it = 1, max_alternations
         any_change = .false.
         do ib = 1, size(ys)
            if (ys(ib)%n == 0 .or. ys(ib)%frozen) cycle
            call yield_step(ys(ib), st(ib), st(ib)%u_view(), t, step, models(ib)%name, changed, error)
            if (allocated(error)) then
               call error_at(error, t, step)
               return
            end if
            any_change = any_change .or. changed
         end do
         if (cs%m == 0) return
         ! Joints of piecewise-linear laws: one LCP of joints and storeys together.
         if (it == 1 .and. any_change .and. size(cs%iterating) == 0) then
            call yield_coupled(ys, st, cs, t, step, models, error)
            if (allocated(error)) call error_at(error, t, step)
            return
         end if
         if (it > 1) ys%alternations = max(ys%alternations, it - 1)
         if (.not. any_change) then
            if (cs%idle) return
            do ib = 1, size(ys)
               if (ys(ib)%loaded) ys(ib)%joint_steps = ys(ib)%joint_steps + 1
            end do
            return
         end if
         call contact_release(cs, st)
         call contact_step(cs, st, t, step, error)
         if (allocated(error)) then
            call error_at(error, t, step)
            return
         end if
      end do
      call fatal_error(error, 'the yielding storeys and the joints did not settle in '//str(max_alternations)// &
                       ' alternations of their LCPs at t = '//str(t)//' s (step '//str(step)//'; reduce dt)')
      call error_at(error, t, step)
   end subroutine yield_steps

   !> Apply (s = 1) or take back (s = -1) the step's plastic loads `fload` and their response
   !> `xdp` through the integrator's `add_load_rows` (it keeps the loads, for HHT-alpha's
   !> F_{n+1}). Applying forms the storeys' loads sum_j k_j dp_j b_j from `dpl` (a frame's
   !> hinges have them from `hinge_loads`); taking back uses the loads applied.
   subroutine plastic_loads(ys, st, s)
      type(storey_yield_set), intent(inout) :: ys
      class(integrator), intent(inout) :: st
      real(dp), intent(in) :: s
      real(dp) :: c
      integer :: j, e

      if (s > 0.0_dp .and. .not. ys%hinges) then
         ys%fload = 0.0_dp
         do j = 1, ys%n
            if (ys%dpl(j) == 0.0_dp) cycle
            c = ys%k(j)*ys%dpl(j)
            do e = ys%rows%start(j), ys%rows%start(j + 1) - 1
               ys%fload(ys%rows%dof(e)) = ys%fload(ys%rows%dof(e)) + c*ys%rows%coef(e)
            end do
         end do
      end if
      call st%add_load_rows(s, ys%alldof, ys%fload, ys%xdp)
   end subroutine plastic_loads

   !> Commit the step: drift, force (`bilinear_force`), plastic drift, energies and peaks of
   !> every storey from the committed displacements u; the storey shears of an output sample
   !> (`shear`, the response's history column) become the spring forces.
   pure subroutine yield_commit(ys, u, t, shear)
      !> The building's storeys.
      type(storey_yield_set), intent(inout) :: ys
      !> Committed displacements.
      real(dp), intent(in) :: u(:)
      !> Time (s).
      real(dp), intent(in) :: t
      !> The storey-shear history column of this output step, when one is stored.
      real(dp), intent(inout), optional :: shear(:)
      real(dp) :: d, f, pn
      integer :: j

      if (ys%n == 0) return
      if (ys%hinges) then
         call hinge_commit(ys, u, t, shear)
         return
      end if
      call drifts(ys, u, ys%dnew, ys%work)
      do j = 1, ys%n
         d = ys%dnew(j)
         f = bilinear_force(ys%k(j), ys%fy(j), ys%r(j), ys%d(j), ys%f(j), d)
         pn = ys%p(j)
         ys%p(j) = pn + ys%dpl(j)
         ys%load_work = ys%load_work + ys%k(j)*0.5_dp*(pn + ys%p(j))*(d - ys%d(j))
         ys%hysteretic = ys%hysteretic + 0.5_dp*(ys%f(j) + f)*ys%dpl(j)
         ys%d(j) = d
         ys%f(j) = f
         ys%dmax(j) = max(ys%dmax(j), abs(d))
         if (abs(d) > ys%limit(j) .and. ys%collapse_storey == 0) then
            ys%collapse_storey = j
            if (allocated(ys%storey_of)) ys%collapse_storey = ys%storey_of(j)
            ys%collapse_time = t
         end if
         if (abs(f) > ys%fmax(j)) then
            ys%fmax(j) = abs(f)
            ys%tmax(j) = t
         end if
      end do
      if (allocated(ys%storey_of)) then
         ! The storey shears: the sums of their rows' forces.
         ys%sval = 0.0_dp
         do j = 1, ys%n
            if (ys%in_shear(j)) ys%sval(ys%storey_of(j)) = ys%sval(ys%storey_of(j)) + ys%f(j)
         end do
         do j = 1, size(ys%sval)
            if (abs(ys%sval(j)) > ys%speak(j)) then
               ys%speak(j) = abs(ys%sval(j))
               ys%stime(j) = t
            end if
         end do
         if (present(shear)) shear = ys%sval
      else
         if (present(shear)) shear = ys%f
      end if
      ys%dpl = 0.0_dp
      ys%xdp = 0.0_dp
      ys%loaded = .false.
   end subroutine yield_commit

   !> The run's results of the storeys; the response's storey-shear peaks and their times
   !> become the spring forces'.
   pure subroutine yield_finish(ys, peak, peak_time, res)
      !> The building's storeys at the end of the run.
      type(storey_yield_set), intent(in) :: ys
      !> The response's storey-shear peaks and times (n_storeys).
      real(dp), intent(inout) :: peak(:), peak_time(:)
      !> The building's result.
      type(storey_yield_result), intent(out) :: res

      if (ys%n == 0) return
      res%n = ys%n
      res%ductility = ys%dmax/(ys%fy/ys%k)
      ! (A row that never yields, an elastic plane: mu = 0.)
      where (ys%fy >= never_yields) res%ductility = 0.0_dp
      res%residual_drift = ys%d
      res%peak_force = ys%fmax
      call finish_tallies(ys, res)
      if (allocated(ys%storey_of)) return
      peak = ys%fmax
      peak_time = ys%tmax
   end subroutine yield_finish

   !> The energy, collapse and LCP tallies of a set into its result (`yield_finish`,
   !> `hinge_finish`).
   pure subroutine finish_tallies(ys, res)
      !> The building's set at the end of the run.
      type(storey_yield_set), intent(in) :: ys
      !> The building's result.
      type(storey_yield_result), intent(inout) :: res

      res%hysteretic = ys%hysteretic
      res%collapse_storey = ys%collapse_storey
      res%collapse_time = ys%collapse_time
      res%solves = ys%solves
      res%lcp_rows = ys%lcp_rows
      res%max_rows = ys%max_rows
      res%joint_steps = ys%joint_steps
      res%alternations = ys%alternations
      res%residual = ys%residual
   end subroutine finish_tallies

end module pound_storey_yield
