!> The step policy: how the time loop (`integrate`, pound_analysis) takes a step from t_{n-1}
!> to t_n. A step is `begin` (the step's prediction and the choice of how to take it: the
!> number of passes, `step_state%passes`), then `pass` once for each pass (a pass ends at
!> `step_state%t_pass` with the ground at `step_state%ag_new`: the constraints' forces, the
!> storeys' and hinges' yielding, the integrators' commit and the joints'). After each pass
!> the loop does what every policy shares: it samples the response, audits the energy,
!> stores the output samples and tests that the state is finite.
!>
!> `step_state` carries the step (its number, times, ground, passes) and what a step acts on
!> (pointers to the integrators, buildings, contact system, ground samples, yield sets, frozen
!> buildings and response records of the run, set by the loop once: `step_state_point`), so
!> that every binding takes the policy and the step alone.
!>
!> The common pass (`take_pass`) is the default `pass`: the step's LCP (`contact_step`, when
!> there are constraints and the step was not taken otherwise), the yield sets
!> (`yield_steps`), the commit of every building (a building frozen after a collapse is held
!> still, `yield_frozen_step`) and of the joints (`contact_commit`). A solve that fails
!> leaves `solve_failed` set (the loop then locates any value that is not finite); the retry
!> (`retry_policy`, pound_step_retry) takes such a pass again with substeps.
!>
!> Extensions: `uniform_policy` (every step one pass of dt, predicted by the integrator's
!> method; without constraints or yielding the commit and the next prediction fused,
!> `integrator%advance`), `exact_policy` (pound_step_exact: exact free steps),
!> `impact_policy` (pound_step_impact: impact substeps), `closed_policy`
!> (pound_step_closed: steps with elastic joints closed) and the decorator `retry_policy`
!> (pound_step_retry) around any of them.
module pound_step_policy
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_structure, only: structure_model, direction_y
   use pound_integrator, only: integrator, integrator_properties
   use pound_contact, only: contact_system, contact_step, contact_commit, contact_carries_force, contact_track_paths
   use pound_response, only: response_record
   use pound_storey_yield, only: storey_yield_set, yield_steps
   use pound_storey_collapse, only: yield_frozen_step
   implicit none
   private

   public :: step_policy, step_state, step_counts, uniform_policy, policy_start, take_pass, predict_again, free_prediction
   public :: ground_y_rows, ground_y_predict, ground_rows_of, ground_rows_load, ground_rows_work
   public :: step_state_point

   !> A building's load of the ground component along y, -M r_y a_gy (`ground_y_setup`): the
   !> DOFs r_y moves, their weights m_i r_y,i and x = Khat^{-1} M r_y.
   type :: ground_y_rows
      integer, allocatable :: dof(:)
      real(dp), allocatable :: w(:), x(:)
   end type ground_y_rows

   !> One step of the time loop as the policies see it.
   type :: step_state
      !> Step number and steps in the run (set by the loop); passes of the step (set by
      !> `begin`) and the pass taken.
      integer :: step = 0, n_steps = 0, passes = 1, pass = 1
      !> The time step (s), the time at the step's end and at the pass's end (s), the pass's
      !> length (s).
      real(dp) :: dt = 0.0_dp, t = 0.0_dp, t_pass = 0.0_dp, h = 0.0_dp
      !> Ground acceleration at the pass's start and end (m/s^2).
      real(dp) :: ag_old = 0.0_dp, ag_new = 0.0_dp
      !> Ground acceleration along y at the pass's start and end (m/s^2; runs with `ag_y`).
      real(dp) :: agy_old = 0.0_dp, agy_new = 0.0_dp
      !> The ground component along y at t_n (0:n_steps; null: none) and each building's
      !> load rows of it (unallocated for a building without DOFs along y).
      real(dp), pointer :: ag_y(:) => null()
      type(ground_y_rows), allocatable :: gy(:)
      !> The step's prediction is every building's exact step (`free_prediction`), which takes
      !> every ground component itself: no load rows of the component along y, no work of them.
      logical :: exact_pred = .false.
      !> The pass's end is an output sample.
      logical :: output = .false.
      !> The step was taken exactly with joints closed (pound_step_closed; the pass commits
      !> only the joints).
      logical :: closed = .false.
      !> The pass's contact solve failed (the error is set).
      logical :: solve_failed = .false.
      !> The integrators' input work and kinetic + strain + damping energy of the pass (the
      !> sums of their commits).
      real(dp) :: win = 0.0_dp, eout = 0.0_dp
      !> What the step acts on: the integrators, the buildings, the contact system, the ground
      !> acceleration at t_n = n dt (0:n_steps), the yield sets (null when no building
      !> yields), the buildings frozen after a collapse, each building's response record.
      class(integrator), pointer :: st(:) => null()
      type(structure_model), pointer :: models(:) => null()
      type(contact_system), pointer :: cs => null()
      real(dp), pointer :: ag(:) => null()
      type(storey_yield_set), pointer :: ys(:) => null()
      logical, pointer :: frozen(:) => null()
      type(response_record), pointer :: rec(:) => null()
      !> The run's warnings (held here while the loop runs; a retry adds one).
      character(len=:), allocatable :: warnings(:)
   end type step_state

   !> What a policy counts over a run.
   type :: step_counts
      !> Free steps exact (`free_steps = 'exact'` and no yielding).
      logical :: exact = .false.
      !> Substeps of an impact step (0: no impact substeps) and their length (s).
      integer :: factor = 0
      real(dp) :: h = 0.0_dp
      !> Steps taken by the method where free steps are exact (a joint could act), steps taken
      !> as impact substeps, substeps taken, steps taken with joints closed.
      integer :: method = 0, substepped = 0, substeps = 0, closed = 0
   end type step_counts

   !> How a step is taken.
   type, abstract :: step_policy
      !> Free steps exact where no building yields (`free_steps = 'exact'`, set by the
      !> caller); the joints' closing paths tracked with free steps of the method too (impact
      !> substeps).
      logical :: exact_free = .false., track_free = .false.
      !> Constraints (a contact system with joints); yield sets (bilinear storeys, hinges);
      !> the joints' closing paths tracked (`contact_track_paths`: when the contact system
      !> records them, `contact_track_closing`, with exact free steps or `track_free`).
      logical :: coupled = .false., inelastic = .false., track = .false.
      !> The run's counts.
      type(step_counts) :: n
   contains
      !> Before the first step: the flags of the run (and any first prediction).
      procedure :: start => policy_start
      !> The step's prediction and its passes.
      procedure(begin_i), deferred :: begin
      !> One pass of the step.
      procedure :: pass => take_pass
      !> The run's counts.
      procedure :: tally => policy_tally
   end type step_policy

   !> Every step one pass of dt, predicted by the integrator's method.
   type, extends(step_policy) :: uniform_policy
      !> No constraints, no yielding: commit and the next prediction in one
      !> (`integrator%advance`).
      logical :: fused = .false.
   contains
      procedure :: start => uniform_start
      procedure :: begin => uniform_begin
      procedure :: pass => uniform_pass
   end type uniform_policy

   abstract interface
      !> Interface of `begin` (see the type).
      subroutine begin_i(pol, s)
         import :: step_policy, step_state
         !> The policy.
         class(step_policy), intent(inout) :: pol
         !> The step (`passes` set; the integrators predicted).
         type(step_state), intent(inout) :: s
      end subroutine begin_i
   end interface

contains

   !> Point `s` at what the steps of a run act on (the actual arguments must outlive the run's
   !> loop: the loop's own dummies and locals).
   subroutine step_state_point(s, st, models, cs, ag, ys, frozen, rec)
      !> The step.
      type(step_state), intent(inout) :: s
      !> The integrators, the buildings, the contact system, the ground acceleration (0:n_steps).
      class(integrator), intent(in), target :: st(:)
      type(structure_model), intent(in), target :: models(:)
      type(contact_system), intent(in), target :: cs
      real(dp), intent(in), target :: ag(:)
      !> The yield sets (unallocated: none).
      type(storey_yield_set), allocatable, intent(in), target :: ys(:)
      !> Buildings frozen after a collapse; each building's response record.
      logical, intent(in), target :: frozen(:)
      type(response_record), intent(in), target :: rec(:)

      s%st => st
      s%models => models
      s%cs => cs
      s%ag(0:) => ag
      s%ys => null()
      if (allocated(ys)) s%ys => ys
      s%frozen => frozen
      s%rec => rec
      s%n_steps = size(ag) - 1
   end subroutine step_state_point

   !> Default `start`: the flags of the run.
   subroutine policy_start(pol, s, inelastic)
      !> The policy.
      class(step_policy), intent(inout) :: pol
      !> The step (what it acts on, at t = 0).
      type(step_state), intent(inout) :: s
      !> Some building yields (`yield_sets_init`).
      logical, intent(in) :: inelastic
      type(integrator_properties) :: props

      props = s%st(1)%properties()
      pol%coupled = s%cs%m > 0
      pol%inelastic = inelastic
      pol%n%exact = pol%exact_free .and. .not. inelastic .and. props%exact_steps
      pol%track = allocated(s%cs%closing_max) .and. (pol%n%exact .or. pol%track_free)
   end subroutine policy_start

   !> Default `tally`: the counts of the policy.
   pure function policy_tally(pol) result(n)
      !> The policy.
      class(step_policy), intent(in) :: pol
      type(step_counts) :: n

      n = pol%n
   end function policy_tally

   !> The common pass (see the module doc).
   subroutine take_pass(pol, s, error)
      !> The policy.
      class(step_policy), intent(inout) :: pol
      !> The step (the integrators predicted; committed on return, as the joints).
      type(step_state), intent(inout) :: s
      !> Error state.
      type(error_type), allocatable, intent(inout) :: error
      integer :: ib

      s%win = 0.0_dp
      s%eout = 0.0_dp
      s%solve_failed = .false.
      if (pol%coupled .and. .not. s%closed) then
         call contact_step(s%cs, s%st, s%t_pass, s%step, error)
         s%solve_failed = allocated(error)
         if (s%solve_failed) return
      end if
      if (pol%inelastic) call yield_steps(s%ys, s%st, s%cs, s%models, s%t_pass, s%step, error)
      if (allocated(error)) return
      do ib = 1, size(s%st)
         if (s%frozen(ib)) then
            call yield_frozen_step(s%st(ib), s%rec(ib), s%output, s%win, s%eout)
         else if (.not. s%closed) then
            if (associated(s%ag_y) .and. .not. s%exact_pred) &
               call ground_rows_work(s%st(ib), s%gy(ib), s%agy_old, s%agy_new)
            call s%st(ib)%commit(s%models(ib), s%ag_old, s%ag_new, s%win, s%eout)
         end if
      end do
      if (pol%coupled) call contact_commit(s%cs, s%st, s%t_pass, s%h)
   end subroutine take_pass

   !> `start` of the uniform steps: fused without constraints and yielding (the first step
   !> predicted here).
   subroutine uniform_start(pol, s, inelastic)
      class(uniform_policy), intent(inout) :: pol
      type(step_state), intent(inout) :: s
      logical, intent(in) :: inelastic

      call policy_start(pol, s, inelastic)
      pol%fused = .not. (pol%coupled .or. inelastic .or. associated(s%ag_y))
      if (pol%fused .and. s%n_steps > 0) call predict_again(s%st, s%models, s%ag(1) - s%ag(0))
   end subroutine uniform_start

   !> `begin` of the uniform steps: every building not frozen predicted (fused: the step was
   !> predicted at the end of the one before).
   subroutine uniform_begin(pol, s)
      class(uniform_policy), intent(inout) :: pol
      type(step_state), intent(inout) :: s
      integer :: ib

      s%passes = 1
      s%closed = .false.
      s%exact_pred = .false.
      if (pol%fused) return
      do ib = 1, size(s%st)
         if (.not. s%frozen(ib)) call s%st(ib)%predict(s%models(ib), s%ag_new - s%ag_old)
      end do
      if (associated(s%ag_y)) call ground_y_predict(s)
   end subroutine uniform_begin

   !> After the method's prediction (ground along x): the increment of the ground load along
   !> y, -M r_y (a_gy,new - a_gy,old), added to every building not frozen that has DOFs along y
   !> (`add_load_rows`: the step of every integrator is linear in its load increments, so this
   !> is the step under -M (r_x a_gx + r_y a_gy); HHT-alpha keeps it in F_{n+1} as it keeps
   !> -M r_x a_gx).
   subroutine ground_y_predict(s)
      !> The step (predicted along x; `ag_y`, `gy` set).
      type(step_state), intent(inout) :: s
      integer :: ib

      do ib = 1, size(s%st)
         if (s%frozen(ib)) cycle
         call ground_rows_load(s%st(ib), s%gy(ib), s%agy_new - s%agy_old)
      end do
   end subroutine ground_y_predict

   !> The load increment -M r_y dag of one building's rows (none without rows), predicted with
   !> x = Khat^{-1} M r_y of the integrator's present step.
   pure subroutine ground_rows_load(st, rows, dag)
      !> The integrator (predicted).
      class(integrator), intent(inout) :: st
      !> The building's rows of the component.
      type(ground_y_rows), intent(in) :: rows
      !> Increment of the component over the pass (m/s^2).
      real(dp), intent(in) :: dag

      if (.not. allocated(rows%dof)) return
      call st%add_load_rows(-dag, rows%dof, rows%w, rows%x)
   end subroutine ground_rows_load

   !> Before a building's commit: the input work of the ground along y over the pass,
   !> -sum_i m_i r_y,i du_i (a_gy,old + a_gy,new)/2 (the trapezoid the method's input work of
   !> the component along x takes), added to the integrator's input work.
   subroutine ground_rows_work(st, rows, ag_old, ag_new)
      !> The integrator (predicted and loaded; not yet committed).
      class(integrator), intent(inout) :: st
      !> The building's rows of the component (none: nothing).
      type(ground_y_rows), intent(in) :: rows
      !> The component at the pass's start and end (m/s^2).
      real(dp), intent(in) :: ag_old, ag_new
      real(dp), pointer :: du(:)
      real(dp) :: mdu
      integer :: i

      if (.not. allocated(rows%dof)) return
      du => st%du_view()
      mdu = 0.0_dp
      do i = 1, size(rows%dof)
         mdu = mdu + rows%w(i)*du(rows%dof(i))
      end do
      call st%add_input_work(-0.5_dp*(ag_old + ag_new)*mdu)
   end subroutine ground_rows_work

   !> Each building's rows of the ground component along y for the integrators `st` (at their
   !> step: the run's, the impact substeps', a retry's): the DOFs r_y moves, m_i r_y,i, and
   !> x = Khat^{-1} M r_y (one solve a building; unallocated for a building without DOFs
   !> along y).
   subroutine ground_rows_of(gy, st, models)
      !> The rows (one per building).
      type(ground_y_rows), allocatable, intent(out) :: gy(:)
      !> The integrators (their step data the step's).
      class(integrator), intent(in) :: st(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      integer :: ib, c, i

      allocate (gy(size(models)))
      do ib = 1, size(models)
         if (.not. allocated(models(ib)%ground_direction)) cycle
         c = findloc(models(ib)%ground_direction, direction_y, 1)
         if (c == 0) cycle
         gy(ib)%dof = pack([(i, i=1, models(ib)%n)], models(ib)%ground_set(:, c) /= 0.0_dp)
         gy(ib)%w = models(ib)%mass(gy(ib)%dof)*models(ib)%ground_set(gy(ib)%dof, c)
         allocate (gy(ib)%x(models(ib)%n))
         gy(ib)%x = 0.0_dp
         gy(ib)%x(gy(ib)%dof) = gy(ib)%w
         call st(ib)%solve(gy(ib)%x)
      end do
   end subroutine ground_rows_of

   !> `pass` of the uniform steps: fused, every building's commit and the next step's
   !> prediction (the last step only committed); else the common pass.
   subroutine uniform_pass(pol, s, error)
      class(uniform_policy), intent(inout) :: pol
      type(step_state), intent(inout) :: s
      type(error_type), allocatable, intent(inout) :: error
      integer :: ib

      if (.not. pol%fused) then
         call take_pass(pol, s, error)
         return
      end if
      s%win = 0.0_dp
      s%eout = 0.0_dp
      do ib = 1, size(s%st)
         if (s%step < s%n_steps) then
            call s%st(ib)%advance(s%models(ib), s%ag_old, s%ag_new, s%ag(s%step + 1) - s%ag_new, s%win, s%eout)
         else
            call s%st(ib)%commit(s%models(ib), s%ag_old, s%ag_new, s%win, s%eout)
         end if
      end do
   end subroutine uniform_pass

   !> Predict the step of every building by the integrator's method, dropping any exact step
   !> predicted (`free_steps = 'exact'`, a step in which a joint can act; a fused run's first
   !> step).
   subroutine predict_again(st, models, dag)
      !> Integrators.
      class(integrator), intent(inout) :: st(:)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Ground acceleration increment of the step (m/s^2).
      real(dp), intent(in) :: dag
      integer :: ib

      do ib = 1, size(st)
         call st(ib)%drop_exact()
         call st(ib)%predict(models(ib), dag)
      end do
   end subroutine predict_again

   !> The prediction of a step whose free motion may be exact (`exact_policy`,
   !> `impact_policy`), one pass: with exact free steps, every building's exact step, unless a
   !> joint carries force at the start (`loaded`: the step is the method's, its exact
   !> prediction would be dropped; not judged when the closing paths are tracked); else the
   !> method's prediction of every building not frozen. A ground component along y enters the
   !> exact step as a second component (`predict_exact`'s `ag2_old`, `ag2_new`), the method's
   !> as load rows (`ground_y_predict`). With `track`, the joints' closing paths are then
   !> tracked (`contact_track_paths`).
   subroutine free_prediction(pol, s, loaded)
      !> The policy.
      class(step_policy), intent(in) :: pol
      !> The step.
      type(step_state), intent(inout) :: s
      !> A joint carries force at the step's start.
      logical, intent(out) :: loaded
      integer :: ib

      s%passes = 1
      s%closed = .false.
      loaded = .false.
      if (pol%n%exact .and. pol%coupled .and. .not. pol%track) loaded = contact_carries_force(s%cs)
      s%exact_pred = pol%n%exact .and. .not. loaded
      if (pol%n%exact) then
         if (.not. loaded) then
            do ib = 1, size(s%st)
               if (associated(s%ag_y)) then
                  call s%st(ib)%predict_exact(s%models(ib), s%ag_old, s%ag_new, s%agy_old, s%agy_new)
               else
                  call s%st(ib)%predict_exact(s%models(ib), s%ag_old, s%ag_new)
               end if
            end do
         end if
      else
         do ib = 1, size(s%st)
            if (.not. s%frozen(ib)) call s%st(ib)%predict(s%models(ib), s%ag_new - s%ag_old)
         end do
         if (associated(s%ag_y)) call ground_y_predict(s)
      end if
      if (pol%track) call contact_track_paths(s%cs, s%st)
   end subroutine free_prediction

end module pound_step_policy
