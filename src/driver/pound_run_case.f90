!> The run driver: one analysis case, from a validated configuration to all its results.
!>
!> `run_case` samples the ground motion, builds the models and the contact pairs, runs the
!> uncoupled analysis and, when the configuration declares contact, the coupled one, the
!> influence coefficients (`pound_influence`) and the gap sweep, and gathers the warnings.
!> It reads no deck and writes no file (a recorded ground motion is read by
!> `deck_ground_motion`, which the program calls first so that a missing record is reported
!> before anything is reserved): the program (`src/main/pound.f90`) and every test that needs a
!> whole run call it, and a record suite or an MPI rank will call it once per case.
!>
!> A case is the configuration plus `case_options`: what a suite varies from one case to the
!> next (the ground motion, the gap of every joint) and a label for the messages. One
!> configuration can be run for many cases; `run_case` does not change it.
module pound_run_case
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, status_input
   use pound_strings, only: str
   use pound_config, only: deck_type, ground_config, analysis_config
   use pound_contact_settings, only: contact_config
   use pound_analysis_plan, only: analysis_plan, steps_of, stepping_uniform, stepping_impact, free_newmark, &
                                  free_exact, lcp_auto, lcp_lemke, integrator_newmark, integrator_hht
   use pound_ground_motion, only: ground_motion_t, pulse_motion, record_motion, sample_ground, stop_ground, &
                                  describe_ground, second_component, set_ground_angle, ground_moves_y, &
                                 ground_accel_y, check_ground_samples
   use pound_building, only: building_model, build_building
   use pound_structure, only: structure_model, structure_names, structure_yields, structure_end_dof, direction_y
   use pound_newmark, only: exact_max_dofs
   use pound_residual_settle, only: residual_warning, ground_tail_fraction, kinetic_tail_fraction
   use pound_response, only: response_point_peak
   use pound_analysis, only: analysis_result, run_uncoupled, run_coupled, add_warning, history_sink, &
                             analysis_copy, e_kinetic
   use pound_contact, only: contact_system, contact_pair, pairs_from_config
   use pound_contact_corners, only: add_corner_rows
   use pound_influence, only: building_influence, influence_of
   use pound_sweep, only: sweep_result, run_sweep
   use pound_sweep_joints, only: joint_sweep, find_joints, run_joint_sweeps, joint_thresholds
   use pound_separation, only: separation_t, code_separation, levels_coincide, not_computed
   use pound_plausibility, only: period_warning, unit_suspects, pga_warning, scale_warning
   use pound_joint_study, only: joint_study_result
   use pound_case_result, only: case_result
   use pound_case_studies, only: has_parameter_sweep, has_law_study, run_deck_study
   implicit none
   private

   public :: case_options, case_result, run_case, deck_ground_motion, configured_motion, label_prefix
   public :: analysis_plan_of, pair_separation

   !> What distinguishes one case of a configuration from another; every component is
   !> optional (the defaults run the configuration as the deck states it).
   type :: case_options
      !> Ground motion of the case; when unallocated, the configuration's `&ground`
      !> (`deck_ground_motion`, which reads a record file).
      type(ground_motion_t), allocatable :: ground
      !> Gap (m) given to every joint instead of the configuration's gaps.
      real(dp), allocatable :: gap
      !> Run only the coupled analysis (no uncoupled run, hence no influence coefficients and
      !> no sweep): for studies of the contact response alone.
      logical :: coupled_only = .false.
      !> Put before the messages of the errors that concern the configuration (models, joints,
      !> coupled run), followed by ': ' (the program gives the deck's path); none when empty.
      character(len=:), allocatable :: label
      !> Where the uncoupled and coupled runs stream their histories (the program's HDF5
      !> file); not associated: the histories are held whole in the results (the sweep's
      !> runs never stream).
      class(history_sink), pointer :: sink => null()
      !> The uncoupled result of this case, already computed (a suite's uncoupled runs of
      !> several motions at once, `pound_analysis_batch`): taken instead of running it.
      type(analysis_result), pointer :: unc => null()
   end type case_options

contains

   !> The analysis plan of `&analysis`: the number of steps, the output and the stepping,
   !> free-step and LCP policies as enumerations (pound_analysis_plan), decided once here so
   !> that no kernel reads the configuration.
   pure function analysis_plan_of(cfg) result(plan)
      !> `&analysis`, validated (dt > 0).
      type(analysis_config), intent(in) :: cfg
      type(analysis_plan) :: plan

      plan%dt = cfg%dt
      plan%t_end = cfg%t_end
      if (cfg%dt > 0.0_dp) plan%n_steps = steps_of(cfg%t_end, cfg%dt)
      plan%output_every = cfg%output_every
      plan%store = cfg%store
      plan%node_histories = cfg%node_histories
      plan%stepping = merge(stepping_impact, stepping_uniform, cfg%stepping == 'impact')
      plan%impact_substeps = cfg%impact_substeps
      plan%free_steps = merge(free_exact, free_newmark, cfg%free_steps == 'exact')
      plan%lcp_solver = merge(lcp_lemke, lcp_auto, cfg%lcp_solver == 'lemke')
      plan%collapse_drift = cfg%collapse_drift
      plan%integrator = merge(integrator_hht, integrator_newmark, cfg%integrator == 'hht')
      if (plan%integrator == integrator_hht) plan%hht_alpha = cfg%hht_alpha
   end function analysis_plan_of

   !> The ground motion the configuration `&ground` describes: a pulse, or a record read
   !> whole from its file (its memory is proportional to the file).
   subroutine deck_ground_motion(deck, gm, error)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> The ground motion.
      type(ground_motion_t), intent(out) :: gm
      !> Error state (a record that cannot be read).
      type(error_type), allocatable, intent(out) :: error

      call configured_motion(deck%ground, gm, error)
      if (allocated(error)) return
      gm%name = deck%ground%name
      if (deck%analysis%t_free > 0.0_dp) &
         call stop_ground(gm, deck%analysis%t_end - deck%analysis%t_free, deck%analysis%dt)
   end subroutine deck_ground_motion

   !> The pulse or the record (read whole from its file) that one `&ground` describes.
   subroutine configured_motion(g, gm, error)
      !> One validated `&ground` of kind 'pulse' or 'record'.
      type(ground_config), intent(in) :: g
      !> The ground motion.
      type(ground_motion_t), intent(out) :: gm
      !> Error state (a record that cannot be read).
      type(error_type), allocatable, intent(out) :: error

      select case (g%kind)
      case ('pulse')
         call pulse_motion(gm, g%x0, g%a, g%b)
      case default
         call record_motion(gm, g%file, g%format, g%scale, error)
         if (allocated(error)) return
         ! Component 2 in the same format; scale_2 defaults to scale.
         if (allocated(g%file_2)) call second_component(gm, g%file_2, g%format, merge(g%scale_2, g%scale, g%scale_2_given), &
                                                        error)
      end select
      call set_ground_angle(gm, g%angle)
   end subroutine configured_motion

   !> What `run_case` puts before its error messages for a case labelled `label` (`case_options`):
   !> 'label: ', or nothing without a label or with an empty one.
   pure function label_prefix(label) result(prefix)
      !> The case's label (absent: none).
      character(len=*), intent(in), optional :: label
      character(len=:), allocatable :: prefix

      prefix = ''
      if (present(label)) then
         if (len(label) > 0) prefix = label//': '
      end if
   end function label_prefix

   !> Run one case of the validated configuration `deck`: ground sampling, models, joints,
   !> uncoupled and coupled analyses, influence coefficients, gap sweep and warnings.
   subroutine run_case(deck, res, error, options)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Everything the case computes.
      type(case_result), intent(out) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> What distinguishes this case (defaults: the configuration as it is).
      type(case_options), intent(in), optional, target :: options
      type(ground_motion_t), target :: deck_gm
      !> The case's ground motion: `options%ground`, else the deck's (`deck_gm`).
      type(ground_motion_t), pointer :: gm
      type(contact_pair), allocatable :: pairs(:)
      ! Row of each joint end in its building's result rows (buildings in plan: `corner_ux`).
      integer, allocatable :: corner_row(:, :)
      type(analysis_plan) :: plan
      character(len=:), allocatable :: prefix, text, joint_warnings(:)
      real(dp), allocatable :: ag(:)
      logical :: coupled_only
      integer :: n_steps, n_out, ib, stat, k
      class(history_sink), pointer :: sink

      prefix = ''
      coupled_only = .false.
      nullify (sink)
      if (present(options)) then
         sink => options%sink
         ! An unallocated label is an absent argument.
         prefix = label_prefix(options%label)
         coupled_only = options%coupled_only
      end if

      ! Ground motion, sampled at every step and at the output steps.
      plan = analysis_plan_of(deck%analysis)
      n_steps = plan%n_steps
      n_out = plan%outputs()
      allocate (ag(0:n_steps), res%ag_out(n_out), stat=stat)
      if (stat /= 0) then
         call fatal_error(error, prefix//'&analysis: not enough memory for the ground motion at '// &
                          str(n_steps + 1)//' steps: raise output_every, store fewer history '// &
                          'quantities, shorten t_end or enlarge dt')
         return
      end if
      nullify (gm)
      if (present(options)) then
         if (allocated(options%ground)) gm => options%ground
      end if
      if (.not. associated(gm)) then
         call deck_ground_motion(deck, deck_gm, error)
         if (allocated(error)) return
         gm => deck_gm
      end if
      call sample_ground(gm, deck%analysis%dt, n_steps, ag)
      res%ground_text = describe_ground(gm)
      res%ag_out = ag(0:n_steps:deck%analysis%output_every)

      ! Models.
      allocate (res%models(size(deck%buildings)), res%buildings(size(deck%buildings)))
      do ib = 1, size(res%models)
         call build_building(deck%buildings(ib), res%models(ib), res%buildings(ib), error)
         if (allocated(error)) then
            error%message = prefix//error%message
            return
         end if
      end do

      ! The ground along y (an angle, a second component): a building with DOFs along y (in
      ! plan) takes -M (r_x a_gx + r_y a_gy); `run_case` samples the component along y at the
      ! steps (`analysis_plan%ground_y`), which every integrator and step policy takes (the
      ! load rows of the method's steps, the exact steps' modal forcing, the substeps').
      do ib = 1, size(res%models)
         if (.not. ground_moves_y(gm)) exit
         if (.not. allocated(res%models(ib)%ground_direction)) cycle
         if (.not. any(res%models(ib)%ground_direction == direction_y)) cycle
         allocate (plan%ground_y(0:n_steps))
         do k = 0, n_steps
            plan%ground_y(k) = ground_accel_y(gm, real(k, dp)*deck%analysis%dt)
         end do
         call check_ground_samples(plan%ground_y, deck%analysis%dt, error, gm)
         if (allocated(error)) return
         exit
      end do

      ! The exact free steps hold every building's n x n modes: refused for a larger model,
      ! pointing at the deck's free_steps.
      if (plan%free_steps == free_exact) then
         do ib = 1, size(res%models)
            if (res%models(ib)%n <= exact_max_dofs) cycle
            text = ''
            if (allocated(deck%analysis%free_steps_site)) text = deck%analysis%free_steps_site
            call fatal_error(error, text//"free_steps = 'exact' takes at most "//str(exact_max_dofs)// &
                             ' DOFs a building (it holds the n x n modes and costs O(n^2) a step); building '// &
                             res%models(ib)%name//' has '//str(res%models(ib)%n)//": use free_steps = 'newmark'")
            return
         end do
      end if

      ! The joints. The contact points of buildings in plan are results of both analyses
      ! (`corner_ux`): their uncoupled peaks give the separation rules point by point.
      if (size(deck%contacts) > 0) then
         pairs = pairs_from_config(deck%contacts, structure_names(res%models), error, res%models)
         if (allocated(error)) then
            error%message = prefix//error%message
            return
         end if
         if (any([(allocated(res%models(ib)%plan), ib=1, size(res%models))])) &
            call add_corner_rows(res%models, pairs, corner_row)
      end if

      ! Analyses.
      if (.not. coupled_only) then
         if (has_uncoupled()) then
            call analysis_copy(options%unc, res%unc)
         else
            call run_uncoupled(plan, res%models, ag, res%unc, error, sink)
            if (allocated(error)) return
         end if
         res%has_uncoupled = .true.
      end if
      if (size(deck%contacts) > 0) then
         if (present(options)) then
            if (allocated(options%gap)) pairs(:)%gap = options%gap
         end if
         call run_coupled(plan, res%models, ag, pairs, res%cpl, res%cs, error, gm, sink)
         if (allocated(error)) then
            error%message = prefix//error%message
            return
         end if
         res%has_coupled = .true.
         if (res%has_uncoupled) then
            res%influence = influence_of(res%unc, res%cpl, res%models)
            if (deck%sweep%active) then
               call run_sweep(plan, deck%sweep, res%models, ag, pairs, res%unc, res%sweep, error, gm)
               if (allocated(error)) then
                  error%message = prefix//error%message
                  return
               end if
               res%has_sweep = .true.
               call joint_sweeps()
               if (allocated(error)) return
            end if
            call joint_studies()
            if (allocated(error)) return
         end if
      end if

      if (res%has_uncoupled .and. res%has_coupled) call separations()
      allocate (character(len=1) :: res%warnings(0))
      if (allocated(deck%warnings)) then
         do ib = 1, size(deck%warnings)
            call add_warning(res%warnings, trim(deck%warnings(ib)))
         end do
      end if
      do ib = 1, size(res%models)
         text = period_warning(res%models(ib)%name, res%models(ib)%period(1), sum(deck%buildings(ib)%height), &
                               unit_suspects(deck%buildings(ib)))
         if (len(text) > 0) call add_warning(res%warnings, text)
      end do
      call ground_plausible(gm)
      res%n_input_warnings = size(res%warnings)
      if (res%has_uncoupled) call collect(res%unc%warnings)
      if (res%has_coupled) call collect(res%cpl%warnings)
      call residual_settled()
      if (res%has_sweep) call collect(res%sweep%warnings)
      if (allocated(joint_warnings)) call collect(joint_warnings)
      if (res%has_parameter_sweep) call collect(res%parameter_sweep%warnings)
      if (res%has_law_study) call collect(res%law_study%warnings)

   contains

      !> The motion's plausibility warnings (`pound_plausibility`): its PGA as run, the factor
      !> of its `scale_to`.
      subroutine ground_plausible(gm)
         type(ground_motion_t), intent(in) :: gm
         character(len=:), allocatable :: name

         name = ''
         if (allocated(gm%name)) name = gm%name
         text = pga_warning(name, maxval(abs(ag)), gm%scale, gm%scaled, gm%kind == 'record')
         if (len(text) > 0) call add_warning(res%warnings, text)
         if (.not. gm%scaled) return
         text = scale_warning(name, gm%scale)
         if (len(text) > 0) call add_warning(res%warnings, text)
      end subroutine ground_plausible

      !> The warning of `pound_residual_settle` when yielding buildings' residual drift is read
      !> while the ground or the buildings still move.
      subroutine residual_settled()
         character(len=:), allocatable :: names
         real(dp) :: period, span, k_unc, k_cpl

         names = ''
         period = 0.0_dp
         do ib = 1, size(res%models)
            if (.not. structure_yields(res%models(ib))) cycle
            if (len(names) > 0) names = names//', '
            names = names//res%models(ib)%name
            period = max(period, res%models(ib)%period(1))
         end do
         if (len(names) == 0) return
         span = max(1.0_dp, period)
         k_unc = 0.0_dp
         k_cpl = 0.0_dp
         if (res%has_uncoupled) k_unc = kinetic_tail_fraction(res%unc%time, res%unc%energy(e_kinetic, :), span)
         if (res%has_coupled) k_cpl = kinetic_tail_fraction(res%cpl%time, res%cpl%energy(e_kinetic, :), span)
         text = residual_warning(names, ground_tail_fraction(ag, plan%dt), k_unc, k_cpl, plan%t_end, &
                                 deck%analysis%t_free, period)
         if (len(text) > 0) call add_warning(res%warnings, text)
      end subroutine residual_settled

      !> The stiffness or restitution sweep and the law study of the deck, if it asks for them.
      subroutine joint_studies()
         if (has_parameter_sweep(deck)) then
            call deck_study(.false., res%parameter_sweep)
            if (allocated(error)) return
            res%has_parameter_sweep = .true.
         end if
         if (has_law_study(deck)) then
            call deck_study(.true., res%law_study)
            if (allocated(error)) return
            res%has_law_study = .true.
         end if
      end subroutine joint_studies

      subroutine deck_study(law, study)
         logical, intent(in) :: law
         type(joint_study_result), intent(out) :: study

         call run_deck_study(law, deck, plan, res%models, ag, res%unc, study, error, gm)
         if (allocated(error)) error%message = prefix//error%message
      end subroutine deck_study

      !> The independent joints and, where there are several, each one's sweep (its warnings
      !> into `joint_warnings`).
      subroutine joint_sweeps()
         res%joints = find_joints(pairs, structure_names(res%models))
         if (size(res%joints) < 2) return
         allocate (character(len=1) :: joint_warnings(0))
         call run_joint_sweeps(plan, deck%sweep, res%models, ag, pairs, res%unc, res%joints, &
                               joint_warnings, error, gm)
         if (allocated(error)) error%message = prefix//error%message
      end subroutine joint_sweeps

      logical function has_uncoupled()
         has_uncoupled = .false.
         if (present(options)) has_uncoupled = associated(options%unc)
      end function has_uncoupled

      !> The separation rules of every pair from the uncoupled peak displacements of the
      !> facing points (floors, or points between floors).
      subroutine separations()
         integer :: ic, k, np
         ! Contiguous copies for `joint_thresholds` (no array temporary at the call).
         real(dp), allocatable :: th_gap(:)
         logical, allocatable :: th_valid(:)

         np = 0
         if (allocated(corner_row)) then
            ! Buildings in plan: every contact point, from the uncoupled peaks of its corners.
            np = size(pairs)
            allocate (res%separation(np))
            do k = 1, np
               associate (p => pairs(k))
                  res%separation(k) = pair_separation(deck, p%building(1), p%building(2), p%floor(1), &
                                                      p%floor(2), corner_peak(1, k), corner_peak(2, k), &
                                                      res%models(p%building(1))%period(1), &
                                                      res%models(p%building(2))%period(1))
                  res%separation(k)%inelastic = [structure_yields(res%models(p%building(1))), &
                                                 structure_yields(res%models(p%building(2)))]
               end associate
            end do
         else
            allocate (res%separation(sum([(size(deck%contacts(ic)%floor_left), ic=1, size(deck%contacts))])))
         end if
         do ic = 1, size(deck%contacts)
            if (allocated(corner_row)) exit
            associate (c => deck%contacts(ic), z => elevations(deck%contacts(ic)))
               do k = 1, size(c%floor_left)
                  np = np + 1
                  res%separation(np) = pair_separation(deck, c%left_index, c%right_index, c%floor_left(k), &
                                                       c%floor_right(k), peak_u(c%left_index, 1, c%floor_left(k), z(k)), &
                                                       peak_u(c%right_index, 2, c%floor_right(k), z(k)), &
                                                       res%models(c%left_index)%period(1), &
                                                       res%models(c%right_index)%period(1))
                  res%separation(np)%inelastic = [structure_yields(res%models(c%left_index)), &
                                                  structure_yields(res%models(c%right_index))]
               end do
            end associate
         end do
         if (res%has_sweep) then
            allocate (th_gap(np), th_valid(np))
            if (size(res%joints) > 1) then
               call joint_thresholds(res%joints, np, th_gap, th_valid)
               res%separation%time_history = th_gap
               res%separation%time_history_valid = th_valid
            else
               res%separation%time_history_valid = res%sweep%found
               if (res%sweep%found) res%separation%time_history = res%sweep%safe_gap
            end if
            ! The sweep's probe (the uncoupled motion run as a coupled one no joint closes) gives
            ! each joint's largest closing displacement: the no-contact gap (0 if it never closes).
            if (allocated(res%sweep%closing_max)) then
               if (size(res%sweep%closing_max) == np) then
                  res%separation%no_contact = max(0.0_dp, res%sweep%closing_max)
                  res%separation%no_contact_valid = .true.
               end if
            end if
         end if
      end subroutine separations

      !> Peak |u_x| (m) in the uncoupled run of end e of joint k (a contact point of a building
      !> in plan: its `corner_ux` row).
      real(dp) function corner_peak(e, k)
         integer, intent(in) :: e, k

         corner_peak = res%unc%building(pairs(k)%building(e))%result_peak(corner_row(e, k))
      end function corner_peak

      !> The elevations (m) of a `&contact`'s pairs (0 where it gives floors).
      pure function elevations(c) result(z)
         type(contact_config), intent(in) :: c
         real(dp) :: z(size(c%floor_left))

         z = 0.0_dp
         if (allocated(c%elevation)) z = c%elevation
      end function elevations

      !> Peak |u| (m) in the uncoupled run of building ib at its end `side` of a pair (1: it
      !> stands on the left): floor j, or for j = 0 the point between floors at elevation z
      !> (m; a frame's split column node, `response_point_peak`; -1 when the model has no
      !> such node).
      real(dp) function peak_u(ib, side, j, z)
         integer, intent(in) :: ib, side, j
         real(dp), intent(in) :: z

         if (j >= 1) then
            peak_u = res%unc%building(ib)%peak(j, 1)
         else
            peak_u = response_point_peak(res%unc%building(ib), structure_end_dof(res%models(ib), side, 0, z))
         end if
      end function peak_u

      subroutine collect(warnings)
         character(len=:), allocatable, intent(in) :: warnings(:)
         integer :: i

         if (.not. allocated(warnings)) return
         do i = 1, size(warnings)
            call add_warning(res%warnings, trim(warnings(i)))
         end do
      end subroutine collect

   end subroutine run_case

   !> The rules of one contact pair of the deck (`code_separation`): building `left` (its
   !> floor `floor_left`) facing building `right` (its floor `floor_right`), with their factors
   !> and damping ratios from the deck, the periods t1, t2 (s) and the uncoupled peaks u1, u2
   !> (m) of the facing points (a floor, or for floor 0 a point between floors). The floors
   !> coincide when both ends are floors whose levels above the common base agree
   !> (`levels_coincide`); a point between floors never coincides. A peak < 0 (not known) gives
   !> no rule (`computed` false, every rule NaN).
   pure function pair_separation(deck, left, right, floor_left, floor_right, u1, u2, t1, t2) result(sep)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Buildings on the left and on the right (indices in `deck%buildings`).
      integer, intent(in) :: left, right
      !> Facing floors (0: a point between floors).
      integer, intent(in) :: floor_left, floor_right
      !> Uncoupled peak displacements of the facing points (m; < 0: not known).
      real(dp), intent(in) :: u1, u2
      !> Fundamental periods of the two buildings (s).
      real(dp), intent(in) :: t1, t2
      type(separation_t) :: sep
      logical :: coincide

      if (u1 < 0.0_dp .or. u2 < 0.0_dp) then
         sep%computed = .false.
         sep%abs = not_computed(u1)
         sep%srss = sep%abs
         sep%ec8 = sep%abs
         sep%ddc = sep%abs
         sep%rho = sep%abs
         sep%asce7 = sep%abs
         sep%en1998 = sep%abs
         sep%is1893 = sep%abs
         sep%u = sep%abs
         sep%setback = sep%abs
         sep%building = [left, right]
         return
      end if
      associate (b1 => deck%buildings(left), b2 => deck%buildings(right))
         coincide = levels_coincide(sum(b1%height(1:floor_left)), sum(b2%height(1:floor_right)), floor_left, &
                                    floor_right)
         sep = code_separation(u1, u2, b1%factors, b2%factors, t1, t2, b1%damping_ratio, b2%damping_ratio, &
                               coincide)
      end associate
      sep%building = [left, right]
   end function pair_separation

end module pound_run_case
