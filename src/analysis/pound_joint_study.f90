!> Studies of the joint itself (issue 26): the coupled analysis repeated for several joint
!> configurations of the same pairs against one uncoupled run. A **stiffness** or
!> **restitution sweep** (`&sweep parameter`) gives every `&contact` group of the deck each
!> value in turn; a **law study** (`&contact variant`) runs the deck's own joints (the base)
!> and each variant. Each configuration is one case (`pound_cases`: in order, or shared over
!> the MPI ranks) whose coupled run is the run a deck with that configuration makes, bit for
!> bit: the pairs are built from the configuration by `pairs_from_config` and run by
!> `run_coupled` (no histories kept). A case's column: the largest |lambda| per target
!> quantity and building (`max_abs_target`), the impacts, the energy residual, per pair its
!> peak force and its realised coefficient of restitution (`realised_restitution`), the first
!> warning. A failed case is marked and left out (zeros), as a failed gap of the gap sweep.
module pound_joint_study
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str
   use pound_contact_settings, only: contact_config
   use pound_quantities, only: n_target_quantities
   use pound_analysis_plan, only: analysis_plan
   use pound_structure, only: structure_model
   use pound_ground_motion, only: ground_motion_t
   use pound_analysis, only: analysis_result, run_coupled, add_warning, audit_warning_limit
   use pound_contact, only: contact_pair, contact_system, pairs_from_config
   use pound_contact_pair, only: end_mass
   use pound_law_impact, only: law_impact, impact_result, typical_impact_speed
   use pound_influence, only: influence_of, max_abs_target
   use pound_cases, only: case_work, case_table, run_cases, first_failure, text_to_column, column_to_text, &
                          case_message_len
   implicit none
   private

   public :: contact_set, joint_study_result, study_cases, run_joint_study, study_column_width
   public :: realised_restitution, realised_not_computed

   !> Characters kept of a case's first warning.
   integer, parameter :: warning_len = 512
   !> The realised restitution of a joint whose law has no calibration to compute it from.
   real(dp), parameter :: realised_not_computed = -1.0_dp

   !> One joint configuration: the `&contact` groups of one case.
   type :: contact_set
      !> The groups (the same pairs in every set of a study).
      type(contact_config), allocatable :: contacts(:)
   end type contact_set

   !> Result of a joint study: one column per configuration.
   type :: joint_study_result
      !> What varies: 'stiffness', 'restitution' or 'law'.
      character(len=16) :: kind = ''
      !> Name of each configuration: the value as text, or 'base' and the variants' names.
      character(len=32), allocatable :: label(:)
      !> The swept value (kN/m or -) of each configuration (a law study: 0).
      real(dp), allocatable :: value(:)
      !> Largest |lambda| (%), (n_target_quantities, n_buildings, n_configurations), as the
      !> gap sweep's.
      real(dp), allocatable :: max_abs_lambda(:, :, :)
      !> Impacts of every joint together, per configuration.
      integer, allocatable :: impacts(:)
      !> Peak force (kN) and realised coefficient of restitution (`realised_not_computed`
      !> where the law has none) of each pair, (n_pairs, n_configurations).
      real(dp), allocatable :: peak_force(:, :), realised_e(:, :)
      !> Relative energy residual of each run.
      real(dp), allocatable :: energy_error(:)
      !> Whether each configuration meets `target_lambda` (the gap sweep's rule); failed runs.
      logical, allocatable :: meets(:), failed(:)
      !> Message, time (s) and step of each failed run (blank, -1 otherwise).
      character(len=case_message_len), allocatable :: messages(:)
      real(dp), allocatable :: time(:)
      integer, allocatable :: step(:)
      !> The pairs' labels (in the order of `peak_force`).
      character(len=64), allocatable :: pair(:)
      !> The laws of each configuration's groups, blank-separated (set by the caller).
      character(len=64), allocatable :: law(:)
      !> Warnings (one line each).
      character(len=:), allocatable :: warnings(:)
   end type joint_study_result

   !> The configurations as cases against the uncoupled result.
   type, extends(case_work) :: study_cases
      !> Settings of the runs (no histories).
      type(analysis_plan) :: cfg
      type(structure_model), pointer :: models(:) => null()
      real(dp), allocatable :: ag(:)
      type(analysis_result), pointer :: unc => null()
      type(ground_motion_t), allocatable :: ground
      !> The buildings' names (for the pairs) and the configurations.
      character(len=64), allocatable :: names(:)
      type(contact_set), allocatable :: sets(:)
      integer :: n_pairs = 0
   contains
      procedure :: compute => study_case
   end type study_cases

contains

   !> Reals in a case's column for nb buildings and np pairs.
   pure integer function study_column_width(nb, np) result(width)
      !> Number of buildings and of pairs.
      integer, intent(in) :: nb, np

      width = n_target_quantities*nb + 3 + 2*np + warning_len
   end function study_column_width

   !> The realised coefficient of restitution of joint `p` (its law and ends as the run set
   !> them up) for an impact of its two facing masses m1, m2 (t): what the law's calibration
   !> delivers. A smooth law (`joint_law%force`): its central impact at the typical speed,
   !> finely integrated (`law_impact`, as the listing's "realised e"); a piecewise-linear
   !> joint with a dashpot calibrated to `restitution`: that e, which its calibration meets
   !> exactly (`dashpot_of_restitution`); otherwise `realised_not_computed` (listed 'n/a').
   pure real(dp) function realised_restitution(p, m1, m2) result(e)
      !> The joint.
      type(contact_pair), intent(in) :: p
      !> Masses of its two facing points (t).
      real(dp), intent(in) :: m1, m2
      type(impact_result) :: imp

      e = realised_not_computed
      ! Without both masses (a column point) there is no impact of two masses to compute.
      if (.not. (m1 > 0.0_dp .and. m2 > 0.0_dp)) return
      if (allocated(p%law%given)) then
         imp = law_impact(p%law%given, m1, m2, typical_impact_speed)
         if (imp%defined) then
            e = imp%restitution
            return
         end if
      end if
      if (p%law%restitution > 0.0_dp) e = p%law%restitution
   end function realised_restitution

   !> Configuration i: its coupled run into a column.
   recursive subroutine study_case(work, i, values, error)
      !> The study's cases.
      class(study_cases), intent(inout) :: work
      !> Configuration index.
      integer, intent(in) :: i
      !> The column.
      real(dp), intent(out) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(contact_pair), allocatable :: pairs(:)
      type(analysis_result) :: cpl
      type(contact_system) :: cs
      integer :: nl, np, k
      real(dp) :: m(2)

      pairs = pairs_from_config(work%sets(i)%contacts, work%names, error)
      if (allocated(error)) return
      ! An unallocated `ground` is an absent argument.
      call run_coupled(work%cfg, work%models, work%ag, pairs, cpl, cs, error, work%ground)
      if (allocated(error)) return
      nl = n_target_quantities*size(work%models)
      np = work%n_pairs
      values(1:nl) = reshape(max_abs_target(influence_of(work%unc, cpl, work%models), work%models, work%unc, cpl), [nl])
      values(nl + 1) = real(sum(cs%joint(:)%impacts), dp)
      values(nl + 2) = cpl%energy_error
      values(nl + 3) = real(size(cpl%warnings), dp)
      do k = 1, np
         values(nl + 3 + k) = cs%joint(k)%peak_force
         m = 0.0_dp
         associate (p => cs%pair(k))
            if (p%building(1) > 0) m(1) = end_mass(p, 1, work%models(p%building(1))%mass)
            if (p%building(2) > 0) m(2) = end_mass(p, 2, work%models(p%building(2))%mass)
            values(nl + 3 + np + k) = realised_restitution(p, m(1), m(2))
         end associate
      end do
      if (size(cpl%warnings) > 0) then
         call text_to_column(trim(cpl%warnings(1)), values(nl + 4 + 2*np:))
      else
         call text_to_column('', values(nl + 4 + 2*np:))
      end if
   end subroutine study_case

   !> Run the coupled analysis for every configuration `sets(i)` (labels `labels`, swept values
   !> `values`) against the uncoupled result `unc`; `target` and `targeted` judge each as the
   !> gap sweep judges a gap (no threshold: the configurations are not ordered by safety).
   subroutine run_joint_study(kind, plan, models, names, ag, sets, labels, values, target, targeted, unc, res, &
                              error, ground)
      !> 'stiffness', 'restitution' or 'law'.
      character(len=*), intent(in) :: kind
      !> The analysis plan (`&analysis`; the runs keep no histories).
      type(analysis_plan), intent(in) :: plan
      !> The buildings (kept by reference during the study).
      type(structure_model), intent(in), target :: models(:)
      !> Their names.
      character(len=*), intent(in) :: names(:)
      !> Ground acceleration at t_n = n dt (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The configurations (the same pairs in each).
      type(contact_set), intent(in) :: sets(:)
      !> Their labels and swept values.
      character(len=*), intent(in) :: labels(:)
      real(dp), intent(in) :: values(:)
      !> `&sweep target_lambda` (<= 0: none) and the quantities it applies to.
      real(dp), intent(in) :: target
      logical, intent(in) :: targeted(:)
      !> Uncoupled result.
      type(analysis_result), intent(in), target :: unc
      !> The study's result.
      type(joint_study_result), intent(out) :: res
      !> Error state: every configuration failed.
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion `ag` samples (needed by `stepping = 'impact'`).
      type(ground_motion_t), intent(in), optional :: ground
      type(study_cases) :: cases
      type(case_table) :: table
      type(contact_pair), allocatable :: pairs(:)
      character(len=64) :: case_names(size(sets))
      character(len=:), allocatable :: worst_text
      real(dp) :: worst
      integer :: i, n, nb, np, nl, q, n_bad

      n = size(sets)
      nb = size(models)
      cases%cfg = plan
      cases%cfg%store = .false.
      cases%cfg%output_every = max(1, plan%n_steps)
      cases%models => models
      cases%ag = ag
      cases%unc => unc
      if (present(ground)) cases%ground = ground
      cases%names = names
      cases%sets = sets
      pairs = pairs_from_config(sets(1)%contacts, names, error)
      if (allocated(error)) return
      np = size(pairs)
      cases%n_pairs = np
      call run_cases(cases, n, study_column_width(nb, np), table)

      res%kind = kind
      res%label = labels
      res%value = values
      allocate (res%pair(np))
      do i = 1, np
         res%pair(i) = pairs(i)%label
      end do
      do i = 1, n
         case_names(i) = trim(kind)//' study, '//trim(labels(i))
      end do
      if (all(table%failed)) then
         call first_failure(table, case_names, error)
         return
      end if
      nl = n_target_quantities*nb
      allocate (res%max_abs_lambda(n_target_quantities, nb, n), res%impacts(n), res%meets(n), &
                res%peak_force(np, n), res%realised_e(np, n), res%energy_error(n))
      allocate (character(len=1) :: res%warnings(0))
      res%failed = table%failed
      res%messages = table%message
      res%time = table%time
      res%step = table%step
      n_bad = 0
      worst = 0.0_dp
      do i = 1, n
         associate (col => table%values(:, i))
            res%max_abs_lambda(:, :, i) = reshape(col(1:nl), [n_target_quantities, nb])
            res%impacts(i) = nint(col(nl + 1))
            res%energy_error(i) = col(nl + 2)
            res%peak_force(:, i) = col(nl + 4:nl + 3 + np)
            res%realised_e(:, i) = col(nl + 4 + np:nl + 3 + 2*np)
            if (col(nl + 3) > 0.0_dp .and. .not. res%failed(i)) then
               n_bad = n_bad + 1
               if (col(nl + 2) >= worst) then
                  worst = col(nl + 2)
                  worst_text = trim(labels(i))//': '//column_to_text(col(nl + 4 + 2*np:))
               end if
            end if
         end associate
         if (res%failed(i)) res%realised_e(:, i) = realised_not_computed
         res%meets(i) = .not. res%failed(i)
         do q = 1, n_target_quantities
            if (targeted(q) .and. target > 0.0_dp) then
               if (any(res%max_abs_lambda(q, :, i) > target)) res%meets(i) = .false.
            end if
         end do
      end do
      if (n_bad > 0) then
         call add_warning(res%warnings, trim(kind)//' study: the coupled runs warn at '//str(n_bad)//' of '// &
                          str(n)//' configurations (energy audit above '//str(audit_warning_limit)// &
                          ' or other); the last worst, '//worst_text)
      end if
      if (any(res%failed)) then
         i = findloc(res%failed, .true., 1)
         call add_warning(res%warnings, trim(kind)//' study: '//str(count(res%failed))//' of '//str(n)// &
                          ' configurations failed and are left out; the first, '//trim(labels(i))//': '// &
                          trim(res%messages(i)))
      end if
   end subroutine run_joint_study

end module pound_joint_study
