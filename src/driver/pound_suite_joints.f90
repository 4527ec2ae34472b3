!> The per-joint sweeps of a suite whose deck has several independent joints
!> (`pound_sweep_joints`): in every motion of the statistics, each joint's pairs at the sweep's
!> gaps while every other pair keeps its deck gap, against the motion's uncoupled result
!> (`suite_context%unc`); then per joint the suite's criteria of the common sweep
!> (`suite_sweep_statistics`: the threshold on the suite mean, on every motion and on each
!> motion), on the grid (not refined, as a single motion's joints' thresholds).
!>
!> The cases of one `run_cases` (shared over the MPI ranks): case (m - 1) n_joints n_gaps +
!> (j - 1) n_gaps + i is motion `motions(m)`, joint j, gap i; a rank sets up a motion (its
!> ground motion, the gap-independent part of the coupled analysis) when its previous case was
!> another motion's. A gap at which a motion's run fails is a failed gap of the joint in that
!> motion (never meeting the target; its failure added to the suite's); a joint whose every
!> gap fails in a motion is failed at every gap of that motion.
module pound_suite_joints
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_config, only: n_target_quantities
   use pound_structure, only: structure_names
   use pound_ground_motion, only: ground_motion_t
   use pound_contact, only: contact_pair, pairs_from_config
   use pound_run_case, only: analysis_plan_of
   use pound_sweep, only: sweep_result, sweep_column_width
   use pound_sweep_joints, only: joint_sweep, find_joints, joint_gap_cases, joint_cases_init, joint_sweep_of
   use pound_cases, only: case_work, case_table, run_cases
   use pound_suite_context, only: suite_context
   use pound_suite_motions, only: suite_motion_setup
   use pound_suite_outcome, only: suite_failure
   use pound_suite_statistics, only: suite_result, suite_joint, suite_sweep_statistics, add_failure
   implicit none
   private

   public :: suite_joint_sweeps

   !> The joints' gaps of the motions as cases (see the module).
   type, extends(case_work) :: suite_joint_cases
      !> The suite's data.
      type(suite_context), pointer :: ctx => null()
      !> Motion index of each block of n_joints n_gaps cases.
      integer, allocatable :: motions(:)
      !> The joints.
      type(joint_sweep), allocatable :: joints(:)
      !> Entry of `motions` that `cases` is set up for (0: none).
      integer :: current = 0
      !> That motion's joints' gaps.
      type(joint_gap_cases) :: cases
   contains
      procedure :: compute => suite_joint_case
   end type suite_joint_cases

contains

   !> The joints' own sweeps of the suite (nothing with fewer than two joints): `suite%joint`,
   !> the failed gaps added to `suite%failures`. Needs the common sweep's statistics
   !> (`suite%motion_failed`, `n_used`, `sweep_gap`) and the motions' uncoupled results.
   subroutine suite_joint_sweeps(ctx, suite, first, error)
      !> The suite's data (`used`, `unc`).
      type(suite_context), intent(in), target :: ctx
      !> The suite.
      type(suite_result), intent(inout) :: suite
      !> The joints with their sweeps in the motion `suite%first` (what a single motion's run
      !> has: `pound_sweep_joints`); unallocated with fewer than two joints.
      type(joint_sweep), allocatable, intent(out) :: first(:)
      !> Error state (a motion that cannot be set up).
      type(error_type), allocatable, intent(out) :: error
      type(suite_joint_cases) :: work
      type(case_table) :: table
      type(contact_pair), allocatable :: pairs(:)
      type(suite_result) :: js
      type(sweep_result) :: sw
      type(error_type), allocatable :: failed
      real(dp), allocatable :: sweep_all(:, :, :, :)
      integer :: nm, nb, nj, ng, j, m, k, ig, iq

      pairs = pairs_from_config(ctx%deck%contacts, structure_names(ctx%models), error, ctx%models)
      if (allocated(error)) return
      work%joints = find_joints(pairs, structure_names(ctx%models))
      nj = size(work%joints)
      if (nj < 2) return
      nm = size(suite%motion_failed)
      nb = size(ctx%models)
      ng = ctx%deck%sweep%n_gaps
      work%ctx => ctx
      work%motions = ctx%used
      call run_cases(work, size(work%motions)*nj*ng, sweep_column_width(nb), table)
      allocate (suite%joint(nj))
      first = work%joints
      do j = 1, nj
         ! The suite's criteria on this joint's sweeps (as the common sweep's).
         js%motion_failed = suite%motion_failed
         js%n_used = suite%n_used
         js%sweep_gap = suite%sweep_gap
         allocate (js%sweep_lambda(nm, ng), source=0.0_dp)
         allocate (js%sweep_failed(nm, ng), sweep_all(n_target_quantities, nb, ng, nm))
         js%sweep_failed = spread(suite%motion_failed, 2, ng)
         sweep_all = 0.0_dp
         do m = 1, size(work%motions)
            k = work%motions(m)
            call joint_sweep_of(ctx%deck%sweep, nb, table, (m - 1)*nj*ng, j, sw, failed)
            if (allocated(failed)) then
               ! Every gap of the joint failed in this motion.
               js%sweep_failed(k, :) = .true.
               call add_failure(suite%failures, suite_failure(k, -1.0_dp, 'gap sweep of joint '// &
                                work%joints(j)%name//': every gap failed; the first: '//failed%message, &
                                failed%time, failed%step))
               deallocate (failed)
               cycle
            end if
            js%sweep_failed(k, :) = sw%failed
            sweep_all(:, :, :, k) = sw%max_abs_lambda
            if (k == suite%first) then
               first(j)%sweep = sw
               first(j)%done = .true.
            end if
            do ig = 1, ng
               if (sw%failed(ig)) call add_failure(suite%failures, suite_failure(k, sw%gap(ig), 'joint '// &
                                                   work%joints(j)%name//': '//trim(sw%messages(ig)), &
                                                   sw%time(ig), sw%step(ig)))
               do iq = 1, n_target_quantities
                  if (ctx%targeted(iq)) js%sweep_lambda(k, ig) = max(js%sweep_lambda(k, ig), &
                                                                     maxval(sw%max_abs_lambda(iq, :, ig)))
               end do
            end do
         end do
         call suite_sweep_statistics(js, sweep_all, ctx%targeted, ctx%deck%sweep%target)
         associate (r => suite%joint(j))
            r%name = work%joints(j)%name
            r%pairs = work%joints(j)%pairs
            r%lambda = js%sweep_lambda
            r%failed = js%sweep_failed
            r%mean = js%sweep_mean
            r%max = js%sweep_max
            r%gap_failed = js%gap_failed
            r%safe_gap_mean = js%safe_gap_mean
            r%safe_gap_every = js%safe_gap_every
            r%safe_gap_motion = js%safe_gap_motion
         end associate
         deallocate (js%sweep_lambda, js%sweep_failed, js%safe_gap_motion, js%non_monotone_motion, sweep_all)
      end do
   end subroutine suite_joint_sweeps

   !> Case i (see the module): the motion set up when it changes, then its joint case.
   recursive subroutine suite_joint_case(work, i, values, error)
      !> The cases.
      class(suite_joint_cases), intent(inout) :: work
      !> Case index.
      integer, intent(in) :: i
      !> The gap's column (`gap_cases`).
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(ground_motion_t) :: gm
      type(contact_pair), allocatable :: pairs(:)
      real(dp), allocatable :: ag(:)
      integer :: m, k, per_motion

      per_motion = size(work%joints)*work%ctx%deck%sweep%n_gaps
      m = (i - 1)/per_motion + 1
      if (work%current /= m) then
         work%current = 0
         k = work%motions(m)
         associate (deck => work%ctx%deck)
            call suite_motion_setup(deck, k, work%ctx%models, gm, ag, pairs, error)
            if (allocated(error)) return
            call joint_cases_init(work%cases, analysis_plan_of(deck%analysis), deck%sweep, work%ctx%models, ag, &
                                  pairs, work%ctx%unc(k), work%joints, error, gm)
            if (allocated(error)) return
         end associate
         work%current = m
      end if
      call work%cases%compute(i - (m - 1)*per_motion, values, error)
   end subroutine suite_joint_case

end module pound_suite_joints
