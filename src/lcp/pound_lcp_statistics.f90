!> What the per-step LCPs of an analysis cost and how they went: Lemke's solves, pivots, warm
!> starts, re-solves, non-convex steps, fallbacks to enumeration (each one recorded as an
!> event); the active-set method's solves, iterations, factor updates and fallbacks to
!> Lemke; the largest LCP and residual, and the time spent solving.
module pound_lcp_statistics
   use pound_kinds, only: dp
   implicit none
   private

   public :: lcp_statistics, contact_event, statistics_count_solve, statistics_add_event
   public :: statistics_count_active_set

   !> A step whose LCP Lemke could not solve, and what was done.
   type :: contact_event
      !> Time (s) and step.
      real(dp) :: time = 0.0_dp
      integer :: step = 0
      !> Lemke's status (`lemke_ray` or `lemke_max_iter`) and the LCP size.
      integer :: status = 0, rows = 0
      !> Solutions found by enumeration (the one nearest the previous state was taken).
      integer :: solutions = 0
      !> The constraints in the LCP.
      character(len=:), allocatable :: pairs
   end type contact_event

   !> LCP statistics of an analysis.
   type :: lcp_statistics
      !> Solves, total and largest pivot counts, steps needing no pivoting, warm starts
      !> accepted, re-solves after an excluded constraint would have closed or a segment end
      !> was passed, steps with softening rows (non-convex), enumeration fallbacks, largest
      !> LCP (rows).
      integer :: solves = 0, pivots_total = 0, pivots_max = 0, trivial = 0, warm = 0, resolves = 0
      integer :: nonconvex = 0, fallbacks = 0, largest_lcp = 0
      !> Active-set method (steps with elastic joints only): solves tried, their iterations
      !> (reduced solves; total and largest), factor updates, and the solves that failed
      !> (cycled, not positive definite, residual too large, a plastic joint closing) and
      !> were solved by Lemke instead (those Lemke runs count in `solves`).
      integer :: active_solves = 0, active_iterations = 0, active_iterations_max = 0
      integer :: active_updates = 0, active_fallbacks = 0
      !> Largest accepted natural residual.
      real(dp) :: residual_max = 0.0_dp
      !> Wall-clock time (s) spent solving LCPs: assembly, Lemke, checks, re-solves and
      !> fallbacks of the steps in which a joint is closed or predicted to close (the clock is
      !> read only in those steps, so that timing does not slow the step loop).
      real(dp) :: lcp_seconds = 0.0_dp
      !> Steps Lemke could not solve (fallbacks), in order: `events(1:n_events)`.
      type(contact_event), allocatable :: events(:)
      integer :: n_events = 0
   end type lcp_statistics

contains

   !> Count one Lemke run.
   pure subroutine statistics_count_solve(st, pivots, trivial, warm)
      !> The statistics.
      type(lcp_statistics), intent(inout) :: st
      !> Its pivots.
      integer, intent(in) :: pivots
      !> It needed no pivoting (q >= 0); its warm start was accepted.
      logical, intent(in) :: trivial, warm

      st%solves = st%solves + 1
      st%pivots_total = st%pivots_total + pivots
      st%pivots_max = max(st%pivots_max, pivots)
      if (trivial) st%trivial = st%trivial + 1
      if (warm) st%warm = st%warm + 1
   end subroutine statistics_count_solve

   !> Count one active-set solve.
   pure subroutine statistics_count_active_set(st, iterations, updates, failed)
      !> The statistics.
      type(lcp_statistics), intent(inout) :: st
      !> Its iterations (reduced solves) and factor updates.
      integer, intent(in) :: iterations, updates
      !> It failed: Lemke solves the step.
      logical, intent(in) :: failed

      st%active_solves = st%active_solves + 1
      st%active_iterations = st%active_iterations + iterations
      st%active_iterations_max = max(st%active_iterations_max, iterations)
      st%active_updates = st%active_updates + updates
      if (failed) st%active_fallbacks = st%active_fallbacks + 1
   end subroutine statistics_count_active_set

   !> Record a step solved by enumeration after Lemke failed.
   pure subroutine statistics_add_event(st, event)
      !> The statistics.
      type(lcp_statistics), intent(inout) :: st
      !> What happened.
      type(contact_event), intent(in) :: event
      type(contact_event), allocatable :: grown(:)

      if (.not. allocated(st%events)) allocate (st%events(0))
      st%fallbacks = st%fallbacks + 1
      st%n_events = st%n_events + 1
      if (st%n_events > size(st%events)) then
         allocate (grown(max(8, 2*size(st%events))))
         grown(1:size(st%events)) = st%events
         call move_alloc(grown, st%events)
      end if
      st%events(st%n_events) = event
   end subroutine statistics_add_event

end module pound_lcp_statistics
