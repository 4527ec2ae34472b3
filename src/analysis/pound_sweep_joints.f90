!> The gap sweep per independent joint: the threshold gap of each joint where a deck has
!> several.
!>
!> A joint is the set of contact pairs between the same two buildings (in either order): a
!> deck with three buildings A|B|C and `&contact` groups A-B and B-C has two joints, whose
!> widths are independent; all pairs of one joint share its width. With more than one joint,
!> besides the sweep that gives every pair the same gap (`pound_sweep`, unchanged), one sweep
!> per joint applies the sweep's gaps (`sweep_gaps`) to that joint's pairs alone while every
!> other pair keeps its deck gap. Each is judged by the rule of the common sweep
!> (`sweep_from_table`: every targeted |lambda| of every building within the target; the
!> smallest gap from which on every larger gap of the grid meets it, no refinement, as a
!> run's common sweep), and gives the time-history threshold gap of the joint's pairs.
!>
!> All the joints' gaps are the cases of one `run_cases` (joint j's gap i is case
!> (j - 1) n_gaps + i), shared over the MPI ranks like the common sweep's. There is no probe:
!> with the other joints at their deck gaps a run without contact stands for none of them,
!> so every gap runs. A joint whose every gap fails has no threshold (a warning, not an
!> error: the common sweep has run).
module pound_sweep_joints
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str
   use pound_sweep_settings, only: sweep_config
   use pound_contact_settings, only: contact_config
   use pound_analysis_plan, only: analysis_plan
   use pound_structure, only: structure_model
   use pound_ground_motion, only: ground_motion_t
   use pound_analysis, only: analysis_result, add_warning
   use pound_contact, only: contact_pair
   use pound_sweep, only: sweep_result, gap_cases, gap_cases_init, sweep_column_width, sweep_from_table, &
                          gap_run
   use pound_cases, only: case_table, run_cases
   implicit none
   private

   public :: joint_sweep, find_joints, run_joint_sweeps, joint_thresholds, deck_joints, failed_joint_gaps
   public :: joint_gap_cases, joint_cases_init, joint_sweep_of

   !> One independent joint and its sweep.
   type :: joint_sweep
      !> Building index of its left and right end (as its first pair names them; 0: a rigid
      !> neighbour).
      integer :: left = 0, right = 0
      !> Its name: '<left building>-<right building>' (HDF5 group, listing, summary).
      character(len=:), allocatable :: name
      !> Its pairs (indices into the deck's pairs, in deck order).
      integer, allocatable :: pairs(:)
      !> Its sweep: its pairs at the sweep's gaps, the other pairs at their deck gaps
      !> (`seconds` is that of all the joints' runs together).
      type(sweep_result) :: sweep
      !> Whether its sweep ran (false when every gap failed: no threshold).
      logical :: done = .false.
   end type joint_sweep

   !> The joints' gaps as cases: case (j - 1) n_gaps + i is joint j at gap i, the other pairs
   !> at their deck gaps; the column of `gap_cases`.
   type, extends(gap_cases) :: joint_gap_cases
      !> The deck's gap of every pair (m).
      real(dp), allocatable :: deck_gap(:)
      !> The joint of every pair.
      integer, allocatable :: joint_of(:)
      !> Number of gaps of the sweep.
      integer :: n_gaps = 0
   contains
      procedure :: compute => joint_gap_case
   end type joint_gap_cases

contains

   !> The independent joints of the pairs: one per unordered pair of buildings, in the order
   !> of their first pair, named by that pair's left and right building.
   pure function find_joints(pairs, names) result(joints)
      !> The deck's contact pairs.
      type(contact_pair), intent(in) :: pairs(:)
      !> Building names, in deck order.
      character(len=*), intent(in) :: names(:)
      type(joint_sweep), allocatable :: joints(:)
      type(joint_sweep) :: found(size(pairs))
      integer :: joint_of(size(pairs)), k, j, n

      n = 0
      do k = 1, size(pairs)
         joint_of(k) = 0
         do j = 1, n
            if (same_joint(pairs(k)%building, [found(j)%left, found(j)%right])) joint_of(k) = j
         end do
         if (joint_of(k) == 0) then
            n = n + 1
            found(n)%left = pairs(k)%building(1)
            found(n)%right = pairs(k)%building(2)
            found(n)%name = building_name(found(n)%left)//'-'//building_name(found(n)%right)
            joint_of(k) = n
         end if
      end do
      do j = 1, n
         found(j)%pairs = pack([(k, k=1, size(pairs))], joint_of == j)
      end do
      joints = found(1:n)

   contains

      pure logical function same_joint(a, b)
         integer, intent(in) :: a(2), b(2)

         same_joint = all(a == b) .or. all(a == b(2:1:-1))
      end function same_joint

      pure function building_name(ib) result(s)
         integer, intent(in) :: ib
         character(len=:), allocatable :: s

         if (ib >= 1 .and. ib <= size(names)) then
            s = trim(names(ib))
         else
            s = 'rigid'
         end if
      end function building_name

   end function find_joints

   !> The number of independent joints of a deck's `&contact` groups (one per unordered pair
   !> of buildings), as `find_joints` finds them.
   pure integer function deck_joints(contacts) result(n)
      !> The deck's validated `&contact` groups.
      type(contact_config), intent(in) :: contacts(:)
      integer :: i, k

      n = 0
      do i = 1, size(contacts)
         associate (a => contacts(i))
            if (any([(same_ends(a%left_index, a%right_index, contacts(k)%left_index, &
                                 contacts(k)%right_index), k=1, i - 1)])) cycle
            n = n + 1
         end associate
      end do

   contains

      pure logical function same_ends(l1, r1, l2, r2)
         integer, intent(in) :: l1, r1, l2, r2

         same_ends = (l1 == l2 .and. r1 == r2) .or. (l1 == r2 .and. r1 == l2)
      end function same_ends

   end function deck_joints

   !> How many gaps of the joints' own sweeps failed (0 with fewer than two joints).
   pure integer function failed_joint_gaps(joints) result(n)
      !> The joints with their sweeps.
      type(joint_sweep), intent(in) :: joints(:)
      integer :: j

      n = 0
      if (size(joints) < 2) return
      do j = 1, size(joints)
         if (joints(j)%done) then
            n = n + count(joints(j)%sweep%failed)
         end if
      end do
   end function failed_joint_gaps

   !> Run the sweep of every joint (`joints` from `find_joints`; nothing for fewer than two):
   !> joint j's pairs at the sweep's gaps, the other pairs at their deck gaps, judged as the
   !> common sweep. Warnings (a joint's failed gaps, energy audit; a joint whose every gap
   !> failed) are appended to `warnings`.
   subroutine run_joint_sweeps(cfg, sweep, models, ag, pairs, unc, joints, warnings, error, ground)
      !> What `&analysis` asks of the runs (histories are not stored for the sweep runs).
      type(analysis_plan), intent(in) :: cfg
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> The buildings.
      type(structure_model), intent(in), target :: models(:)
      !> Ground acceleration at t_n = n dt (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The constraints of the deck, with their deck gaps.
      type(contact_pair), intent(in) :: pairs(:)
      !> Uncoupled result.
      type(analysis_result), intent(in), target :: unc
      !> The joints; their sweeps are set.
      type(joint_sweep), intent(inout) :: joints(:)
      !> Warnings, one line each (appended to).
      character(len=:), allocatable, intent(inout) :: warnings(:)
      !> Error state (the coupled model cannot be prepared).
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples (needed by `stepping = 'impact'`).
      type(ground_motion_t), intent(in), optional :: ground
      type(joint_gap_cases) :: cases
      type(case_table) :: table
      type(error_type), allocatable :: joint_error
      integer(int64) :: c0, c1, rate
      integer :: j, k, ng, nb
      real(dp) :: seconds

      if (size(joints) < 2) return
      call system_clock(c0, rate)
      ng = sweep%n_gaps
      nb = size(models)
      call joint_cases_init(cases, cfg, sweep, models, ag, pairs, unc, joints, error, ground)
      if (allocated(error)) return
      call run_cases(cases, size(joints)*ng, sweep_column_width(nb), table)
      call system_clock(c1)
      seconds = real(c1 - c0, dp)/real(rate, dp)
      do j = 1, size(joints)
         call joint_sweep_of(sweep, nb, table, 0, j, joints(j)%sweep, joint_error)
         if (allocated(joint_error)) then
            ! Every gap of this joint failed: no threshold; the run goes on.
            call add_warning(warnings, 'gap sweep of joint '//joints(j)%name//': every gap failed, the joint '// &
                             'has no threshold; the first: '//joint_error%message)
            deallocate (joint_error)
            cycle
         end if
         joints(j)%done = .true.
         joints(j)%sweep%seconds = seconds
         do k = 1, size(joints(j)%sweep%warnings)
            call add_warning(warnings, 'joint '//joints(j)%name//' ('//str(size(joints(j)%pairs))// &
                             ' pairs swept, the others at their deck gaps): '//trim(joints(j)%sweep%warnings(k)))
         end do
      end do
   end subroutine run_joint_sweeps

   !> The joints' gaps of `sweep` as cases (`joint_gap_cases`; `gap_cases_init` with the deck's
   !> gap of every pair and the joint of every pair).
   subroutine joint_cases_init(cases, cfg, sweep, models, ag, pairs, unc, joints, error, ground)
      !> The cases.
      type(joint_gap_cases), intent(out) :: cases
      !> What `&analysis` asks of the runs.
      type(analysis_plan), intent(in) :: cfg
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> The buildings (kept by reference).
      type(structure_model), intent(in), target :: models(:)
      !> Ground acceleration at t_n = n dt (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The constraints of the deck, with their deck gaps.
      type(contact_pair), intent(in) :: pairs(:)
      !> Uncoupled result (kept by reference).
      type(analysis_result), intent(in), target :: unc
      !> The joints (`find_joints`).
      type(joint_sweep), intent(in) :: joints(:)
      !> Error state (the coupled model cannot be prepared).
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples (needed by `stepping = 'impact'`).
      type(ground_motion_t), intent(in), optional :: ground
      integer :: j

      call gap_cases_init(cases%gap_cases, cfg, sweep, models, ag, pairs, unc, error, ground)
      if (allocated(error)) return
      cases%deck_gap = pairs(:)%gap
      cases%n_gaps = sweep%n_gaps
      allocate (cases%joint_of(size(pairs)))
      do j = 1, size(joints)
         cases%joint_of(joints(j)%pairs) = j
      end do
   end subroutine joint_cases_init

   !> Joint j's sweep from the joints' table (`joint_gap_cases`: joint j's gap i in column
   !> `first` + (j - 1) n_gaps + i), by `sweep_from_table`; an error when its every gap failed.
   subroutine joint_sweep_of(sweep, nb, table, first, j, res, error)
      !> `&sweep`.
      type(sweep_config), intent(in) :: sweep
      !> Number of buildings.
      integer, intent(in) :: nb
      !> The table.
      type(case_table), intent(in) :: table
      !> Columns before the joints' (0: the table is the joints').
      integer, intent(in) :: first
      !> The joint.
      integer, intent(in) :: j
      !> Its sweep.
      type(sweep_result), intent(out) :: res
      !> Error state: its every gap failed.
      type(error_type), allocatable, intent(out) :: error
      type(case_table) :: part
      integer :: k

      associate (cols => [(first + (j - 1)*sweep%n_gaps + k, k=1, sweep%n_gaps)])
         part%values = table%values(:, cols)
         part%failed = table%failed(cols)
         part%message = table%message(cols)
         part%time = table%time(cols)
         part%step = table%step(cols)
      end associate
      call sweep_from_table(sweep, nb, part, res, error)
   end subroutine joint_sweep_of

   !> Joint case i: joint j = (i - 1)/n_gaps + 1 at gap i - (j - 1) n_gaps, the other pairs at
   !> their deck gaps; its coupled run into a column (`gap_cases`).
   recursive subroutine joint_gap_case(work, i, values, error)
      !> The joints' cases.
      class(joint_gap_cases), intent(inout) :: work
      !> Case index.
      integer, intent(in) :: i
      !> The column.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: gaps(work%n_pairs)
      integer :: j

      j = (i - 1)/work%n_gaps + 1
      gaps = work%deck_gap
      where (work%joint_of == j) gaps = work%gap(i - (j - 1)*work%n_gaps)
      call gap_run(work, gaps, values, error)
   end subroutine joint_gap_case

   !> The time-history threshold gap of every pair from its joint's sweep (m; `valid` false
   !> where the joint's sweep found none or did not run).
   pure subroutine joint_thresholds(joints, n_pairs, gap, valid)
      !> The joints with their sweeps.
      type(joint_sweep), intent(in) :: joints(:)
      !> Number of pairs.
      integer, intent(in) :: n_pairs
      !> Threshold gap of each pair (m; -1 where not valid).
      real(dp), intent(out) :: gap(n_pairs)
      !> Whether it exists.
      logical, intent(out) :: valid(n_pairs)
      integer :: j

      gap = -1.0_dp
      valid = .false.
      do j = 1, size(joints)
         if (.not. joints(j)%done) cycle
         if (.not. joints(j)%sweep%found) cycle
         gap(joints(j)%pairs) = joints(j)%sweep%safe_gap
         valid(joints(j)%pairs) = .true.
      end do
   end subroutine joint_thresholds

end module pound_sweep_joints
