!> The retry of a step whose contact solve fails, a decorator around any step policy
!> (`retry_policy`, pound_step_policy): a step (or an impact substep) of
!> size h whose end-of-step contact equations do not converge (`contact_step`: the smooth
!> laws' Newton after `max_law_iterations` solves, or any other failure of the step's LCPs)
!> is taken again from its start as `retry_substeps` substeps of h/`retry_substeps`, with the
!> machinery of the impact substeps (`integrator%swap_step`, `contact_swap_step`: integrators
!> and a contact system at the retry's substep, made on the first retry and kept for the
!> next ones of the same h). The ground acceleration is linear between the step's ends within
!> it, and so is a ground component along y (its load rows at the substep, `ground_rows_of`).
!> The substeps commit the integrators and the joints (`contact_commit`); the time loop
!> then samples the step's end as after any step and does not commit it again. The first
!> retried step is listed as a warning (time, step, the failure), with the number of steps
!> retried in the run not counted. A retry that fails too is reported with the step's time
!> and step, the joint of the substep's failure, the substep's time and both messages: the
!> run fails, never a silent result.
module pound_step_retry
   use pound_kinds, only: dp
   use pound_strings, only: str, add_warning
   use pound_error, only: error_type
   use pound_structure, only: structure_model
   use pound_integrator, only: integrator
   use pound_contact, only: contact_system, contact_init, contact_step, contact_commit
   use pound_contact_system, only: contact_swap_step
   use pound_step_policy, only: step_policy, step_state, step_counts, policy_start, ground_y_rows, ground_rows_of, &
                                ground_rows_load, ground_rows_work
   use pound_swap, only: swap
   implicit none
   private

   public :: step_retry, retry_step, retry_substeps, swap_step_data, retry_policy

   !> Substeps of a retried step.
   integer, parameter :: retry_substeps = 10

   !> The step data of the retries of one run.
   type :: step_retry
      !> The substep the data below are for (s; 0: none yet).
      real(dp) :: h = 0.0_dp
      !> Integrators and contact system at the substep h (only their step data are used).
      class(integrator), allocatable :: st(:)
      type(contact_system) :: cs
      !> The load rows of a ground component along y at the substep h (runs with one).
      type(ground_y_rows), allocatable :: gy(:)
      !> Steps retried in the run.
      integer :: count = 0
   end type step_retry

   !> The retry around a step policy (`inner`): a pass whose contact solve fails is taken
   !> again with substeps (`retry_step`).
   type, extends(step_policy) :: retry_policy
      !> The policy retried.
      class(step_policy), allocatable :: inner
      !> The retries' step data.
      type(step_retry) :: rt
   contains
      procedure :: start => retry_start
      procedure :: begin => retry_begin
      procedure :: pass => retry_pass
      procedure :: tally => retry_tally
   end type retry_policy

contains

   !> `start`: the run's flags, and the wrapped policy's start.
   subroutine retry_start(pol, s, inelastic)
      !> The policy.
      class(retry_policy), intent(inout) :: pol
      !> The step (what it acts on, at t = 0).
      type(step_state), intent(inout) :: s
      !> Some building yields (no retry then: the failure is the run's).
      logical, intent(in) :: inelastic

      call policy_start(pol, s, inelastic)
      call pol%inner%start(s, inelastic)
   end subroutine retry_start

   !> `begin`: the wrapped policy's.
   subroutine retry_begin(pol, s)
      !> The policy.
      class(retry_policy), intent(inout) :: pol
      !> The step.
      type(step_state), intent(inout) :: s

      call pol%inner%begin(s)
   end subroutine retry_begin

   !> `pass`: the wrapped policy's; a pass whose contact solve failed is taken again as
   !> `retry_substeps` substeps (`retry_step`, committed), unless a building yields.
   subroutine retry_pass(pol, s, error)
      !> The policy.
      class(retry_policy), intent(inout) :: pol
      !> The step.
      type(step_state), intent(inout) :: s
      !> Error state.
      type(error_type), allocatable, intent(inout) :: error

      call pol%inner%pass(s, error)
      if (.not. s%solve_failed .or. pol%inelastic) return
      if (associated(s%ag_y)) then
         call retry_step(pol%rt, s%models, s%st, s%cs, s%ag_old, s%ag_new, s%t_pass, s%h, s%step, error, s%warnings, &
                         s%agy_old, s%agy_new)
      else
         call retry_step(pol%rt, s%models, s%st, s%cs, s%ag_old, s%ag_new, s%t_pass, s%h, s%step, error, s%warnings)
      end if
      s%solve_failed = allocated(error)
   end subroutine retry_pass

   !> `tally`: the wrapped policy's counts.
   pure function retry_tally(pol) result(n)
      !> The policy.
      class(retry_policy), intent(in) :: pol
      type(step_counts) :: n

      n = pol%inner%tally()
   end function retry_tally

   !> Take the step from t - h to t, whose `contact_step` failed with `error`, again as
   !> `retry_substeps` substeps, committed (integrators and joints). On return `error` is
   !> unallocated when the retry succeeded, else it says where both failed.
   subroutine retry_step(rt, models, st, cs, ag_old, ag_new, t, h, step, error, warnings, agy_old, agy_new)
      !> The retry's step data (set up on the first retry of this h).
      type(step_retry), intent(inout) :: rt
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Integrators at the step's start (its failed prediction is dropped); at its end.
      class(integrator), intent(inout) :: st(:)
      !> The contact system at the step's start (the failed solve's rows are set again by
      !> the substeps' solves); at its end.
      type(contact_system), intent(inout) :: cs
      !> Ground acceleration at the step's start and end (m/s^2).
      real(dp), intent(in) :: ag_old, ag_new
      !> Time at the step's end (s) and the step (s).
      real(dp), intent(in) :: t, h
      !> Step number.
      integer, intent(in) :: step
      !> The step's failure on entry; the retry's failure on return (else deallocated).
      type(error_type), allocatable, intent(inout) :: error
      !> The run's warnings (the first retry is listed).
      character(len=:), allocatable, intent(inout) :: warnings(:)
      !> A ground component along y at the step's start and end (m/s^2; its load rows at the
      !> substep are the retry's, `step_retry%gy`).
      real(dp), intent(in), optional :: agy_old, agy_new
      type(error_type), allocatable :: failed
      real(dp) :: hs, a0, a1, ts, w, e, b0, b1
      integer :: i, j

      call move_alloc(error, failed)
      hs = h/real(retry_substeps, dp)
      if (rt%h /= hs .or. (present(agy_old) .neqv. allocated(rt%gy))) then
         call retry_setup(rt, models, st, cs, ag_old, hs, error, present(agy_old))
         if (allocated(error)) then
            error%message = failed%message//'; the retry with substeps could not be set up: '//error%message
            call place(error, failed, t, step)
            return
         end if
      end if
      call swap_step_data(st, rt%st, cs, rt%cs)
      a0 = ag_old
      b0 = 0.0_dp
      b1 = 0.0_dp
      if (present(agy_old)) b0 = agy_old
      do j = 1, retry_substeps
         ts = t - h + real(j, dp)*hs
         a1 = ag_old + (ag_new - ag_old)*(real(j, dp)/real(retry_substeps, dp))
         if (present(agy_old)) b1 = agy_old + (agy_new - agy_old)*(real(j, dp)/real(retry_substeps, dp))
         if (j == retry_substeps) then
            ts = t
            a1 = ag_new
            if (present(agy_old)) b1 = agy_new
         end if
         do i = 1, size(st)
            call st(i)%drop_exact()
            call st(i)%predict(models(i), a1 - a0)
            if (present(agy_old)) call ground_rows_load(st(i), rt%gy(i), b1 - b0)
         end do
         call contact_step(cs, st, ts, step, error)
         if (allocated(error)) then
            call swap_step_data(st, rt%st, cs, rt%cs)
            error%message = failed%message//'; retried with '//str(retry_substeps)//' substeps of '// &
                            str(hs)//' s, which failed at t = '//str(ts)//' s (substep '//str(j)//'): '// &
                            error%message
            call place(error, failed, t, step)
            return
         end if
         w = 0.0_dp
         e = 0.0_dp
         do i = 1, size(st)
            if (present(agy_old)) call ground_rows_work(st(i), rt%gy(i), b0, b1)
            call st(i)%commit(models(i), a0, a1, w, e)
         end do
         call contact_commit(cs, st, ts, hs)
         a0 = a1
         b0 = b1
      end do
      call swap_step_data(st, rt%st, cs, rt%cs)
      rt%count = rt%count + 1
      if (rt%count == 1) call add_warning(warnings, 'contact: the step ending at t = '//str(t)//' s (step '// &
                                          str(step)//') was retried with '//str(retry_substeps)// &
                                          ' substeps of '//str(hs)//' s, which converged: '//failed%message// &
                                          ' (the first retried step of the run)')
   end subroutine retry_step

   !> Integrators and contact system at the substep hs (with `ground_y`, the load rows of the
   !> ground along y at hs).
   subroutine retry_setup(rt, models, st, cs, ag0, hs, error, ground_y)
      type(step_retry), intent(inout) :: rt
      type(structure_model), intent(in) :: models(:)
      class(integrator), intent(in) :: st(:)
      type(contact_system), intent(in) :: cs
      real(dp), intent(in) :: ag0, hs
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in) :: ground_y
      integer :: i

      rt%h = 0.0_dp
      if (allocated(rt%st)) deallocate (rt%st)
      allocate (rt%st(size(st)), mold=st)
      do i = 1, size(st)
         ! mold= gives the kind, not its settings: the substeps take the run's (HHT's alpha).
         call rt%st(i)%take_settings(st(i))
         call rt%st(i)%init(models(i), hs, ag0, error)
         if (allocated(error)) return
      end do
      call contact_init(rt%cs, cs%pair, rt%st, models, error)
      if (allocated(error)) return
      if (allocated(rt%gy)) deallocate (rt%gy)
      if (ground_y) call ground_rows_of(rt%gy, rt%st, models)
      rt%h = hs
   end subroutine retry_setup

   !> Exchange the step data of the integrators and the contact system with those of `sst`
   !> and `scs` (the same buildings and constraints at another step: the impact substeps,
   !> pound_analysis, and the retry's); with `gy`, `sgy`, the load rows of a ground component
   !> along y at each step too.
   subroutine swap_step_data(st, sst, cs, scs, gy, sgy)
      !> Integrators.
      class(integrator), intent(inout) :: st(:)
      !> Integrators at the other step.
      class(integrator), intent(inout) :: sst(:)
      !> The contact system.
      type(contact_system), intent(inout) :: cs
      !> The contact system at the other step.
      type(contact_system), intent(inout) :: scs
      !> The load rows of a ground component along y at each step.
      type(ground_y_rows), intent(inout), optional :: gy(:), sgy(:)
      integer :: i

      do i = 1, size(st)
         call st(i)%swap_step(sst(i))
      end do
      call contact_swap_step(cs, scs)
      if (.not. (present(gy) .and. present(sgy))) return
      do i = 1, size(gy)
         if (allocated(gy(i)%x)) call swap(gy(i)%x, sgy(i)%x)
      end do
   end subroutine swap_step_data

   !> The failure placed at the step: its time and step, the joint of the substep's failure
   !> (else the step's).
   pure subroutine place(error, failed, t, step)
      type(error_type), intent(inout) :: error
      type(error_type), intent(in) :: failed
      real(dp), intent(in) :: t
      integer, intent(in) :: step

      error%time = t
      error%step = step
      if (error%joint == 0) error%joint = failed%joint
   end subroutine place

end module pound_step_retry
