!> The HDF5 results file (`.h5`): model data, histories, peaks, contact and influence.
!>
!> Layout (as read by h5py; histories are (n_out, n) with one row per output time). Every
!> dataset carries a string attribute `units` ('m', 'kN', 's', '%', 'kN m', '1' for a
!> dimensionless number, a count, an index or a code, '-' for text; a dataset whose columns
!> differ lists them, e.g. '1/s, s'):
!>
!>     /                          attributes program, version, units, g (the acceleration of
!>                                gravity in m/s^2, `pound_constants::g_accel`), title, deck
!>     /ground/time, /ground/acceleration        (n_out), m/s^2; attribute description
!>     /model/<b>/height, mass, storey_stiffness, geometric_stiffness, axial_load,
!>                periods, omega, rayleigh (a0, a1)
!>     /<analysis>/time                          (n_out), analysis = uncoupled | coupled
!>     /<analysis>/<b>/u, v, a_abs               (n_out, n_floors), only those stored
!>     /<analysis>/<b>/drift, storey_shear       (n_out, n_storeys), only those stored
!>                                               (with `&analysis compress`: chunked, deflate)
!>     /<analysis>/<b>/u_nodes                   (n_out, n_dofs) every DOF of a frame, only with
!>                                               `&analysis node_histories`; its layout in
!>     /model/<b>/dofs                           (2, n_dofs) integer: node, direction (1 horizontal,
!>                                               2 vertical, 3 rotation) each DOF was created at
!>     /model/<b>/node_dofs, node_coefficients   (6, n_nodes) integer, real: node k's horizontal,
!>                                               vertical and rotation = sum of coefficient x DOF
!>                                               over two terms each (DOF 0: no term)
!>     /<analysis>/<b>/peak/<q>, peak_time/<q>   (n) for every quantity q
!>     /<analysis>/<b>/columns/<c>, <c>_time     (n_segments) frame: peak |column end force| per
!>                                               segment, c = shear moment_bottom moment_top axial
!>     /<analysis>/<b>/deformed, deformed_time   (n_storeys, n_dofs), (n_storeys) frame: every DOF
!>                                               at the peak storey shear of each storey
!>     /model/<b>/columns                        (n_segments, 3) integer: element, storey, line
!>     /<analysis>/energy                        (n_out, 6): input, kinetic, strain, damping,
!>                                               contact, plastic; attributes components, relative_error
!>     /coupled/contact/force, closing, penetration, plastic   (n_out, n_pairs); attribute pairs
!>     /coupled/contact/state                    (n_out, n_pairs) integer: 0 open, -1 elastic,
!>                                               -2 fractured, k > 0 yielding on segment k
!>     /coupled/contact/impacts, contact_time, peak_force, peak_time, gap, law, stiffness,
!>                 plastic_final, peak_penetration, fractured, fracture_time   (n_pairs)
!>     /coupled/contact/envelope/<pair>          (n_points+1, 2) the envelope used: d (m), r (kN)
!>     /coupled/contact/events/time, step, status, rows, solutions, pairs   (n_events)
!>                                               steps Lemke could not solve (enumeration fallback)
!>     /influence/<b>/<q>                        (n) lambda in percent
!>     /influence/<b>/columns/<c>                (n_segments) frame: lambda of the column peaks
!>     /sweep/gap, impacts, meets                (n_gaps)
!>     /sweep/no_contact                         (n_gaps) 1 where the gap is beyond every joint's
!>                                               largest closing displacement without contact
!>     /sweep/closing_max                        (n_pairs) those displacements (m; absent when
!>                                               the run without contact failed)
!>     /sweep/max_abs_lambda/<b>/<q>             (n_gaps) largest |lambda| over the storeys, percent;
!>                                               attributes target_lambda, safe_gap (-1: none),
!>                                               and, when some gaps failed, failed_gaps (count)
!>                                               and safe_gap_note
!>     /sweep/max_abs_lambda/<b>/column_shear, column_moment   (n_gaps) of a frame, where targeted:
!>                                               largest |lambda| over its column segments, percent
!>                                               (attribute units = '%')
!>     /sweep/failed/case, gap, time, step, message   (n_failed) the gaps whose run failed
!>     /sweep/joint/<left>-<right>/...           only with several independent joints (pairs
!>                                               between different pairs of buildings): that
!>                                               joint's own sweep (its pairs at the gaps, the
!>                                               others at their deck gaps): gap, impacts, meets,
!>                                               max_abs_lambda/<b>/<q>, failed/... as /sweep;
!>                                               safe_gap () m, -1: none; pairs (n) its pair
!>                                               labels; attributes target_lambda, safe_gap, left,
!>                                               right (building names)
module pound_results_h5
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_version, only: program_name, program_version
   use pound_config, only: deck_type, history_names, n_history_quantities, target_names, q_column_shear, q_ductility, &
                           q_column_moment
   use pound_building, only: building_model
   use pound_h5_sink, only: h5_sink
   use pound_structure, only: structure_model, structure_yields, structure_names
   use pound_analysis, only: analysis_result, history_sink
   use pound_analysis_plan, only: output_steps, steps_of
   use pound_contact, only: contact_system, joint_history
   use pound_contact_law, only: add_stiffness_unit
   use pound_response, only: response_record, q_u, q_v, q_a_abs, q_drift, q_shear
   use pound_influence, only: building_influence
   use pound_influence_output, only: write_lambda_h5
   use pound_result_groups_output, only: write_result_groups_h5
   use pound_h5, only: h5_file, h5_create, h5_close, h5_write, h5_write_attr, h5_create_history, h5_write_columns
   use pound_sweep, only: sweep_result
   use pound_sweep_joints, only: joint_sweep
   use pound_separation, only: separation_t
   use pound_separation_output, only: write_separation_h5, pair_labels
   use pound_yield_output, only: write_yield_h5, write_yield_influence_h5, write_yield_model_h5
   use pound_config, only: sweep_config
   use pound_constants, only: g_accel
   implicit none
   private

   public :: write_results_h5, write_analysis_h5, h5_history_sink, history_sink_init, write_failed_cases
   public :: quantity_units, member_units, pair_list

   !> Streams the uncoupled and coupled histories into an open results file: each dataset
   !> is created at its full shape (n_out, n) with its first block (chunked; compressed with
   !> `&analysis compress`) and its blocks written as they come; `write_results_h5` then
   !> skips them.
   type, extends(history_sink) :: h5_history_sink
      !> The open file (this run's temporary).
      type(h5_file) :: h5
      !> Building names (deck order).
      character(len=64), allocatable :: names(:)
      !> Output samples of a whole history.
      integer :: n_out = 0
      !> Compress the histories.
      logical :: compress = .false.
      !> The file's name in messages.
      character(len=:), allocatable :: label
   contains
      procedure :: put => h5_sink_put
   end type h5_history_sink

   !> Units, as written in the root attribute.
   character(len=*), parameter :: units = 'kN, m, s, t (tonne); accelerations m/s^2; energies kJ; '// &
                                          'influence coefficients percent'

contains

   !> A sink streaming the histories of the deck's analyses into the results file `path`,
   !> created here (truncated) and kept open (`sink%h5`) for `write_results_h5`.
   subroutine history_sink_init(sink, path, label, deck, error)
      !> The sink.
      type(h5_history_sink), intent(out) :: sink
      !> The results file to create.
      character(len=*), intent(in) :: path
      !> Its name in messages ('cannot write <label>: ...'; the published name).
      character(len=*), intent(in) :: label
      !> The deck.
      type(deck_type), intent(in) :: deck
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: ib

      sink%label = label
      call h5_create(sink%h5, path, error)
      if (allocated(error)) then
         error%message = 'cannot write '//label//': '//error%message
         return
      end if
      sink%n_out = output_steps(steps_of(deck%analysis%t_end, deck%analysis%dt), deck%analysis%output_every)
      sink%compress = deck%analysis%compress
      allocate (sink%names(size(deck%buildings)))
      do ib = 1, size(deck%buildings)
         sink%names(ib) = deck%buildings(ib)%name
      end do
   end subroutine history_sink_init

   !> Write one block of a history (creating the dataset with the first block).
   subroutine h5_sink_put(sink, coupled, building, quantity, first, values, error)
      !> The sink.
      class(h5_history_sink), intent(inout) :: sink
      !> The coupled analysis (else the uncoupled one).
      logical, intent(in) :: coupled
      !> Building index and quantity index.
      integer, intent(in) :: building, quantity
      !> Index of the first sample.
      integer, intent(in) :: first
      !> The samples (n, k).
      real(dp), intent(in), contiguous :: values(:, :)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: path

      path = merge('/coupled  ', '/uncoupled', coupled)
      path = trim(path)//'/'//trim(sink%names(building))//'/'//trim(history_names(quantity))
      if (first == 1 .and. size(values, 2) == sink%n_out .and. .not. sink%compress) then
         ! The whole history in one block (a short run): one contiguous dataset, as a history
         ! held in memory is written.
         call h5_write(sink%h5, path, values, error, units=quantity_units(quantity))
      else
         if (first == 1) then
            call h5_create_history(sink%h5, path, size(values, 1), sink%n_out, sink%compress, error, &
                                   units=quantity_units(quantity))
         end if
         if (.not. allocated(error)) call h5_write_columns(sink%h5, path, first, values, error)
      end if
      if (allocated(error)) error%message = 'cannot write '//sink%label//': '//error%message
   end subroutine h5_sink_put

   !> Write the whole results file at `path`.
   subroutine write_results_h5(path, deck, models, buildings, ground_text, ag_out, unc, error, cpl, cs, influence, sweep, &
                               file, separation, joints, summary)
      !> File to create (truncated).
      character(len=*), intent(in) :: path
      !> The deck.
      type(deck_type), intent(in) :: deck
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Their per-kind data (storey table, frame), same order.
      type(building_model), intent(in) :: buildings(:)
      !> One-line description of the ground motion.
      character(len=*), intent(in) :: ground_text
      !> Ground acceleration at the output times (m/s^2).
      real(dp), intent(in) :: ag_out(:)
      !> Uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Coupled result, when the deck declares contact.
      type(analysis_result), intent(in), optional :: cpl
      !> Contact system at the end of the coupled run.
      type(contact_system), intent(in), optional :: cs
      !> Influence coefficients of every building (`pound_influence`), written with `cpl`.
      type(building_influence), intent(in), optional :: influence(:)
      !> Gap study, when the deck asks for one.
      type(sweep_result), intent(in), optional :: sweep
      !> The file already open (created at `path` before the analyses, holding the streamed
      !> histories): written into and closed.
      type(h5_file), intent(inout), optional :: file
      !> Separation rules per contact pair (`pound_separation`), written to /separation
      !> (`write_separation_h5`) for a deck with one motion; none when absent or empty.
      type(separation_t), intent(in), optional :: separation(:)
      !> The independent joints with their own sweeps (written with `sweep` where there are
      !> several: /sweep/joint/<name>).
      type(joint_sweep), intent(in), optional :: joints(:)
      !> The engineering summary's text, written as the root attribute `summary` before the
      !> file is closed (else the caller adds it: `write_summary_attributes`).
      character(len=*), intent(in), optional :: summary
      type(h5_file) :: h5
      type(error_type), allocatable :: close_error
      integer :: ib, q

      if (present(file)) then
         h5 = file
      else
         call h5_create(h5, path, error)
         if (allocated(error)) return
      end if
      call write_all()
      call h5_close(h5, close_error)
      if (present(file)) file = h5
      if (.not. allocated(error) .and. allocated(close_error)) call move_alloc(close_error, error)

   contains

      subroutine write_all()
         call h5_write_attr(h5, '/', 'program', program_name, error)
         if (allocated(error)) return
         call h5_write_attr(h5, '/', 'version', program_version, error)
         if (allocated(error)) return
         call h5_write_attr(h5, '/', 'units', units, error)
         if (allocated(error)) return
         call h5_write_attr(h5, '/', 'g', g_accel, error)
         if (allocated(error)) return
         call h5_write_attr(h5, '/', 'title', deck%analysis%title, error)
         if (allocated(error)) return
         call h5_write_attr(h5, '/', 'deck', deck%text, error)
         if (allocated(error)) return
         call h5_write_attr(h5, '/', 'dt', deck%analysis%dt, error)
         if (allocated(error)) return
         ! Free vibration after the motion (the histories run on to t_end + t_free).
         if (deck%analysis%t_free > 0.0_dp) call h5_write_attr(h5, '/', 't_free', deck%analysis%t_free, error)
         if (allocated(error)) return
         if (present(summary)) call h5_write_attr(h5, '/', 'summary', summary, error)
         if (allocated(error)) return
         call h5_write(h5, '/ground/time', unc%time, error, units='s')
         if (allocated(error)) return
         call h5_write(h5, '/ground/acceleration', ag_out, error, units='m/s^2')
         if (allocated(error)) return
         call h5_write_attr(h5, '/ground', 'description', ground_text, error)
         if (allocated(error)) return
         do ib = 1, size(models)
            call write_model(models(ib), buildings(ib))
            if (allocated(error)) return
         end do
         call write_analysis_h5(h5, '/uncoupled', models, unc, error, deck%analysis%compress)
         if (allocated(error)) return
         if (.not. present(cpl)) return
         call write_analysis_h5(h5, '/coupled', models, cpl, error, deck%analysis%compress)
         if (allocated(error)) return
         if (present(cs)) then
            call write_contact()
            if (allocated(error)) return
         end if
         if (present(influence)) then
            do ib = 1, size(models)
               do q = 1, n_history_quantities
                  call write_lambda_h5(h5, '/influence/'//models(ib)%name//'/'//trim(history_names(q)), &
                                       influence(ib)%lambda(:, q), error)
                  if (allocated(error)) return
               end do
               if (allocated(influence(ib)%member_lambda)) call write_member_influence(models(ib), influence(ib))
               if (allocated(error)) return
               if (allocated(influence(ib)%result_lambda)) &
                  call write_result_groups_h5(h5, '/influence/'//models(ib)%name//'/', models(ib), &
                                              influence(ib)%result_lambda, error, units='%')
               if (allocated(error)) return
            end do
            if (present(cpl)) call write_yield_influence_h5(h5, models, unc, cpl, error)
            if (allocated(error)) return
         end if
         if (present(sweep)) call write_sweep()
         if (allocated(error)) return
         if (present(sweep) .and. present(joints)) call write_joint_sweeps()
         if (allocated(error) .or. .not. present(separation)) return
         if (.not. present(cs)) return
         if (size(separation) > 0 .and. size(deck%motions) == 1) &
            call write_separation_h5(h5, '/separation', reshape(separation, [1, size(separation)]), &
                                     pair_labels(cs), .false., error, structure_names(models))
         if (allocated(error) .or. .not. (present(sweep) .and. present(joints))) return
         if (size(joints) > 1 .and. size(separation) > 0 .and. size(deck%motions) == 1) &
            call h5_write_attr(h5, '/separation/time_history', 'rule', 'per pair, the threshold of its joint''s own '// &
                               'sweep (its pairs at the gaps, the other pairs at their deck gaps): '// &
                               '/sweep/joint/<left>-<right>/safe_gap', error)
      end subroutine write_all

      !> lambda of the member rows by quantity: /influence/<b>/<group>/<name> (n_members).
      subroutine write_member_influence(b, infl)
         type(structure_model), intent(in) :: b
         type(building_influence), intent(in) :: infl
         real(dp), allocatable :: rv(:)
         integer :: nq, k

         nq = size(b%member_names)
         do k = 1, nq
            rv = infl%member_lambda(k::nq)
            call write_lambda_h5(h5, '/influence/'//b%name//'/'//b%member_group//'/'//trim(b%member_names(k)), rv, &
                                 error)
            if (allocated(error)) return
         end do
      end subroutine write_member_influence

      subroutine write_sweep()
         call write_sweep_group('/sweep', sweep)
         if (allocated(error)) return
         call h5_write(h5, '/sweep/no_contact', merge(1, 0, sweep%beyond), error, units='1')
         if (allocated(error)) return
         if (allocated(sweep%closing_max)) call h5_write(h5, '/sweep/closing_max', sweep%closing_max, error, units='m')
      end subroutine write_sweep

      !> Every joint's own sweep where there are several (`pound_sweep_joints`).
      subroutine write_joint_sweeps()
         character(len=:), allocatable :: g, labels(:)
         integer :: j

         if (size(joints) < 2 .or. .not. present(cs)) return
         labels = pair_labels(cs)
         do j = 1, size(joints)
            if (.not. joints(j)%done) cycle
            g = '/sweep/joint/'//joints(j)%name
            call write_sweep_group(g, joints(j)%sweep)
            if (allocated(error)) return
            call h5_write(h5, g//'/safe_gap', joints(j)%sweep%safe_gap, error, units='m')
            if (allocated(error)) return
            call h5_write(h5, g//'/pairs', labels(joints(j)%pairs), error, units='-')
            if (allocated(error)) return
            call h5_write_attr(h5, g, 'left', end_name(joints(j)%left), error)
            if (allocated(error)) return
            call h5_write_attr(h5, g, 'right', end_name(joints(j)%right), error)
            if (allocated(error)) return
         end do
      end subroutine write_joint_sweeps

      !> A joint end's building name ('rigid' for a fixed neighbour).
      function end_name(ib) result(name)
         integer, intent(in) :: ib
         character(len=:), allocatable :: name

         name = 'rigid'
         if (ib >= 1) name = models(ib)%name
      end function end_name

      !> A sweep's gaps, impacts, whether each meets the target, the largest |lambda| per
      !> building and quantity, its attributes and failed gaps, under group g.
      subroutine write_sweep_group(g, sw)
         character(len=*), intent(in) :: g
         type(sweep_result), intent(in) :: sw
         ! A contiguous copy of each (quantity, building) row (no array temporary at the call).
         real(dp), allocatable :: row(:)

         call h5_write(h5, g//'/gap', sw%gap, error, units='m')
         if (allocated(error)) return
         call h5_write(h5, g//'/impacts', sw%impacts, error, units='1')
         if (allocated(error)) return
         call h5_write(h5, g//'/meets', merge(1, 0, sw%meets), error, units='1')
         if (allocated(error)) return
         do ib = 1, size(models)
            do q = 1, n_history_quantities
               row = sw%max_abs_lambda(q, ib, :)
               call h5_write(h5, g//'/max_abs_lambda/'//models(ib)%name//'/'//trim(history_names(q)), &
                             row, error, units='%')
               if (allocated(error)) return
            end do
            ! The peak ductility of bilinear storeys, where the deck targets it.
            if (deck%sweep%target_quantities(q_ductility) .and. structure_yields(models(ib))) then
               row = sw%max_abs_lambda(q_ductility, ib, :)
               call h5_write(h5, g//'/max_abs_lambda/'//models(ib)%name//'/ductility', row, error, units='%')
               if (allocated(error)) return
            end if
            ! The column segments' quantities of a frame, where the deck targets them.
            if (models(ib)%member%n == 0) cycle
            do q = q_column_shear, q_column_moment
               if (.not. deck%sweep%target_quantities(q)) cycle
               row = sw%max_abs_lambda(q, ib, :)
               call h5_write(h5, g//'/max_abs_lambda/'//models(ib)%name//'/'//trim(target_names(q)), &
                             row, error)
               if (.not. allocated(error)) call h5_write_attr(h5, g//'/max_abs_lambda/'//models(ib)%name// &
                                                              '/'//trim(target_names(q)), 'units', '%', error)
               if (allocated(error)) return
            end do
         end do
         call h5_write_attr(h5, g, 'target_lambda', deck%sweep%target, error)
         if (allocated(error)) return
         call h5_write_attr(h5, g, 'safe_gap', sw%safe_gap, error)
         if (allocated(error) .or. .not. any(sw%failed)) return
         call h5_write_attr(h5, g, 'failed_gaps', count(sw%failed), error)
         if (allocated(error)) return
         call h5_write_attr(h5, g, 'safe_gap_note', 'failed gaps counted as not meeting the target', error)
         if (allocated(error)) return
         call write_failed_cases(h5, g//'/failed', sw%gap, sw%failed, sw%messages, sw%time, &
                                 sw%step, error)
      end subroutine write_sweep_group

      subroutine write_model(b, s)
         type(structure_model), intent(in) :: b
         type(building_model), intent(in) :: s
         character(len=:), allocatable :: g
         type(h5_sink) :: sink

         g = '/model/'//b%name//'/'
         sink = h5_sink(file=h5, group=g)
         call h5_write(h5, g//'height', s%kind%height, error, units='m')
         if (allocated(error)) return
         call h5_write(h5, g//'mass', s%kind%floor_mass, error, units='t')
         if (allocated(error)) return
         call s%kind%write_data(b, sink, error)
         if (.not. allocated(error)) call write_yield_model_h5(h5, g, b, error)
         if (allocated(error)) return
         call h5_write(h5, g//'periods', b%period, error, units='s')
         if (allocated(error)) return
         call h5_write(h5, g//'omega', b%omega, error, units='rad/s')
         if (allocated(error)) return
         call h5_write(h5, g//'rayleigh', [b%a0, b%a1], error, units='1/s, s')
         if (allocated(error)) return
         call h5_write_attr(h5, '/model/'//b%name, 'p_delta', merge(1, 0, s%kind%p_delta), error)
         if (allocated(error)) return
         call h5_write_attr(h5, '/model/'//b%name, 'damping_ratio', b%damping_ratio, error)
      end subroutine write_model

      subroutine write_contact()
         character(len=*), parameter :: c = '/coupled/contact'
         character(len=16), allocatable :: laws(:)
         character(len=:), allocatable :: kunits
         integer :: k, ne
         logical :: smooth
         ! Contiguous copies of component sections (no array temporaries at the calls).
         real(dp), allocatable :: rv(:), envelope(:, :)
         integer, allocatable :: iv(:)

         call h5_write(h5, c//'/force', cpl%joints%force, error, units='kN')
         if (allocated(error)) return
         call h5_write(h5, c//'/closing', cpl%joints%closing, error, units='m')
         if (allocated(error)) return
         call h5_write(h5, c//'/penetration', cpl%joints%penetration, error, units='m')
         if (allocated(error)) return
         call h5_write(h5, c//'/plastic', cpl%joints%plastic, error, units='m')
         if (allocated(error)) return
         call h5_write(h5, c//'/state', cpl%joints%state, error, units='1')
         if (allocated(error)) return
         call h5_write_attr(h5, c//'/state', 'codes', '0 open, -1 closed elastic, -2 fractured, '// &
                            'k > 0 yielding on yield segment k of the law', error)
         if (allocated(error)) return
         iv = cs%joint(:)%impacts
         call h5_write(h5, c//'/impacts', iv, error, units='1')
         if (allocated(error)) return
         rv = cs%joint(:)%contact_time
         call h5_write(h5, c//'/contact_time', rv, error, units='s')
         if (allocated(error)) return
         rv = cs%joint(:)%peak_force
         call h5_write(h5, c//'/peak_force', rv, error, units='kN')
         if (allocated(error)) return
         rv = cs%joint(:)%peak_time
         call h5_write(h5, c//'/peak_time', rv, error, units='s')
         if (allocated(error)) return
         if (cs%fr%n > 0) then
            call write_friction(h5, c, cs, cpl%joints, error)
            if (allocated(error)) return
         end if
         rv = cs%pair(:)%gap
         call h5_write(h5, c//'/gap', rv, error, units='m')
         if (allocated(error)) return
         kunits = ''
         do k = 1, cs%m
            call add_stiffness_unit(kunits, cs%pair(k)%law)
         end do
         call h5_write(h5, c//'/stiffness', [(cs%pair(k)%law%stiffness, k=1, cs%m)], error, units=kunits)
         if (allocated(error)) return
         allocate (laws(cs%m))
         do k = 1, cs%m
            laws(k) = cs%pair(k)%law%title()
         end do
         call h5_write(h5, c//'/law', laws, error, units='-')
         if (allocated(error)) return
         rv = cs%joint(:)%plastic
         call h5_write(h5, c//'/plastic_final', rv, error, units='m')
         if (allocated(error)) return
         rv = cs%joint(:)%peak_penetration
         call h5_write(h5, c//'/peak_penetration', rv, error, units='m')
         if (allocated(error)) return
         call h5_write(h5, c//'/fractured', [(merge(1, 0, cs%joint(k)%fractured), k=1, cs%m)], error, units='1')
         if (allocated(error)) return
         rv = cs%joint(:)%fracture_time
         call h5_write(h5, c//'/fracture_time', rv, error, units='s')
         if (allocated(error)) return
         ! The smooth laws' realised restitution (issue 26), only where there is one.
         rv = [(0.0_dp, k=1, cs%m)]
         smooth = .false.
         do k = 1, cs%m
            if (.not. allocated(cs%pair(k)%law%given)) cycle
            if (.not. cs%pair(k)%law%given%has_force()) cycle
            smooth = .true.
            rv(k) = cs%pair(k)%law%given%realised_restitution()
         end do
         if (smooth) then
            call h5_write(h5, c//'/realised_restitution', rv, error, units='1')
            if (allocated(error)) return
            call h5_write_attr(h5, c//'/realised_restitution', 'description', 'separation speed / approach '// &
                               'speed of a central impact of the facing masses on the joint''s smooth law, '// &
                               'finely integrated (pound_law_impact); 0: not a smooth law', error)
            if (allocated(error)) return
         end if
         do k = 1, cs%m
            envelope = cs%pair(k)%law%envelope_points()
            if (size(envelope, 2) == 0) cycle
            call h5_write(h5, c//'/envelope/'//cs%pair(k)%label, envelope, error, units='m, kN')
            if (allocated(error)) return
         end do
         ne = cs%stats%n_events
         rv = cs%stats%events(1:ne)%time
         call h5_write(h5, c//'/events/time', rv, error, units='s')
         if (allocated(error)) return
         iv = cs%stats%events(1:ne)%step
         call h5_write(h5, c//'/events/step', iv, error, units='1')
         if (allocated(error)) return
         iv = cs%stats%events(1:ne)%status
         call h5_write(h5, c//'/events/status', iv, error, units='1')
         if (allocated(error)) return
         iv = cs%stats%events(1:ne)%rows
         call h5_write(h5, c//'/events/rows', iv, error, units='1')
         if (allocated(error)) return
         iv = cs%stats%events(1:ne)%solutions
         call h5_write(h5, c//'/events/solutions', iv, error, units='1')
         if (allocated(error)) return
         call h5_write(h5, c//'/events/pairs', [(event_pairs(k), k=1, ne)], error, units='-')
         if (allocated(error)) return
         call h5_write_attr(h5, c//'/events', 'description', 'steps on which Lemke ended on a ray '// &
                            '(status 2) or at its pivot cap (3); the LCP was solved by enumeration and '// &
                            'the solution nearest the previous state taken', error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'pairs', pair_list(cs), error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_solves', cs%stats%solves, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_pivots_total', cs%stats%pivots_total, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_pivots_max', cs%stats%pivots_max, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_residual_max', cs%stats%residual_max, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_resolves', cs%stats%resolves, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_nonconvex_steps', cs%stats%nonconvex, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_fallbacks', cs%stats%fallbacks, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_largest', cs%stats%largest_lcp, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_active_set_solves', cs%stats%active_solves, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_active_set_iterations', cs%stats%active_iterations, error)
         if (allocated(error)) return
         call h5_write_attr(h5, c, 'lcp_active_set_fallbacks', cs%stats%active_fallbacks, error)
      end subroutine write_contact

      !> Pairs of event k, padded to a common length for the string dataset.
      function event_pairs(k) result(text)
         integer, intent(in) :: k
         character(len=256) :: text

         text = cs%stats%events(k)%pairs
      end function event_pairs

   end subroutine write_results_h5

   !> Write one analysis (time, energy, the stored histories and the peaks of every building)
   !> under the group `g` of an open file.
   subroutine write_analysis_h5(h5, g, models, res, error, compress)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> Group path, e.g. '/uncoupled'.
      character(len=*), intent(in) :: g
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The analysis.
      type(analysis_result), intent(in) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The building histories chunked and compressed (`&analysis compress`; default no).
      logical, intent(in), optional :: compress
      character(len=:), allocatable :: gb
      integer :: i, n, q
      logical :: packed

      packed = .false.
      if (present(compress)) packed = compress
      n = res%n_out
      call h5_write(h5, g//'/time', res%time, error, units='s')
      if (allocated(error)) return
      call h5_write(h5, g//'/energy', res%energy, error, units='kJ')
      if (allocated(error)) return
      call h5_write_attr(h5, g//'/energy', 'components', 'input kinetic strain damping contact plastic', &
                         error)
      if (allocated(error)) return
      call h5_write_attr(h5, g//'/energy', 'relative_error', res%energy_error, error)
      if (allocated(error)) return
      if (allocated(res%numerical)) then
         call h5_write(h5, g//'/energy_numerical', res%numerical, error, units='kJ')
         if (allocated(error)) return
         call h5_write_attr(h5, g//'/energy_numerical', 'description', 'numerical dissipation of the '// &
                            'integrator ('//res%integrator//'), summed over the buildings; the energy audit balances '// &
                            'input = kinetic + strain + damping + contact + plastic + numerical', error)
         if (allocated(error)) return
      end if
      call h5_write_attr(h5, g, 'integration_seconds', res%seconds, error)
      if (allocated(error)) return
      do i = 1, size(models)
         gb = g//'/'//models(i)%name//'/'
         associate (r => res%building(i))
            if (.not. r%streamed) call write_histories(r)
            if (allocated(error)) return
            if (r%nodes) then
               call write_history(h5, gb//'u_nodes', r%u_nodes(:, 1:n), packed, error, 'm, rad')
               if (allocated(error)) return
               call h5_write_attr(h5, gb//'u_nodes', 'dofs', 'column i: DOF i, its node and direction in '// &
                                  '/model/'//models(i)%name//'/dofs', error)
               if (allocated(error)) return
            end if
            do q = 1, n_history_quantities
               call h5_write(h5, gb//'peak/'//trim(history_names(q)), r%peak(:, q), error, units=quantity_units(q))
               if (allocated(error)) return
               call h5_write(h5, gb//'peak_time/'//trim(history_names(q)), r%peak_time(:, q), error, units='s')
               if (allocated(error)) return
            end do
            if (allocated(r%member_peak)) call write_members(models(i), r)
            if (allocated(error)) return
            if (allocated(r%result_peak)) then
               call write_result_groups_h5(h5, gb//'peak/', models(i), r%result_peak, error)
               if (allocated(error)) return
               call write_result_groups_h5(h5, gb//'peak_time/', models(i), r%result_time, error, units='s')
               if (allocated(error)) return
            end if
            if (r%snapshots) then
               call h5_write(h5, gb//'deformed', r%deformed, error, units='m, rad')
               if (allocated(error)) return
               call h5_write_attr(h5, gb//'deformed', 'description', 'row j: every DOF (as u_nodes, layout '// &
                                  'in /model/'//models(i)%name//'/dofs) at the step of the peak storey shear '// &
                                  'of storey j (time: deformed_time)', error)
               if (allocated(error)) return
               call h5_write(h5, gb//'deformed_time', r%peak_time(:, q_shear), error, units='s')
               if (allocated(error)) return
            end if
         end associate
      end do
      call write_yield_h5(h5, g, models, res, error)

   contains

      !> Peaks of the member rows by quantity: <group>/<name> and <group>/<name>_time (n_members).
      subroutine write_members(b, r)
         type(structure_model), intent(in) :: b
         type(response_record), intent(in) :: r
         ! Contiguous copies of the strided rows (no array temporaries at the calls).
         real(dp), allocatable :: rv(:)
         integer :: nq, k

         nq = size(b%member_names)
         do k = 1, nq
            rv = r%member_peak(k::nq)
            call h5_write(h5, gb//b%member_group//'/'//trim(b%member_names(k)), rv, error, &
                          units=member_units(b%member_names(k)))
            if (allocated(error)) return
            rv = r%member_time(k::nq)
            call h5_write(h5, gb//b%member_group//'/'//trim(b%member_names(k))//'_time', rv, error, units='s')
            if (allocated(error)) return
         end do
      end subroutine write_members

      !> The histories held in memory (the whole run).
      subroutine write_histories(r)
         type(response_record), intent(in) :: r

         if (r%store(q_u)) call write_history(h5, gb//'u', r%u(:, 1:n), packed, error, quantity_units(q_u))
         if (allocated(error)) return
         if (r%store(q_v)) call write_history(h5, gb//'v', r%v(:, 1:n), packed, error, quantity_units(q_v))
         if (allocated(error)) return
         if (r%store(q_a_abs)) call write_history(h5, gb//'a_abs', r%a_abs(:, 1:n), packed, error, quantity_units(q_a_abs))
         if (allocated(error)) return
         if (r%store(q_drift)) call write_history(h5, gb//'drift', r%drift(:, 1:n), packed, error, quantity_units(q_drift))
         if (allocated(error)) return
         if (r%store(q_shear)) call write_history(h5, gb//'storey_shear', r%shear(:, 1:n), packed, error, quantity_units(q_shear))
         if (allocated(error)) return
      end subroutine write_histories
   end subroutine write_analysis_h5

   !> One building history (n, n_out): contiguous, or chunked and compressed.
   subroutine write_history(h5, path, values, compress, error, units)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The history.
      real(dp), intent(in), contiguous :: values(:, :)
      !> Chunked and compressed.
      logical, intent(in) :: compress
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute.
      character(len=*), intent(in) :: units

      if (compress) then
         call h5_create_history(h5, path, size(values, 1), size(values, 2), .true., error, units=units)
         if (.not. allocated(error)) call h5_write_columns(h5, path, 1, values, error)
      else
         call h5_write(h5, path, values, error, units=units)
      end if
   end subroutine write_history

   !> The failed cases of a set of cases (a sweep's gaps, a suite's motions) in group `path`:
   !> `case` (1-based index), `gap` (m), `time` (s) and `step` of the failure (-1: not known)
   !> and `message`, one entry per failed case; attribute `n_cases` (all cases).
   !> Without `indexed` (.false.: the caller names the cases itself) neither `case` nor `n_cases`.
   subroutine write_failed_cases(h5, path, gap, failed, messages, times, steps, error, indexed)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> Group path (e.g. '/sweep/failed').
      character(len=*), intent(in) :: path
      !> Gap of each case (m).
      real(dp), intent(in) :: gap(:)
      !> Whether each case failed.
      logical, intent(in) :: failed(:)
      !> Message of each case.
      character(len=*), intent(in) :: messages(:)
      !> Time (s) and step of each case's failure (`error_type`'s; -1: not known).
      real(dp), intent(in) :: times(:)
      integer, intent(in) :: steps(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Whether to write `case` and `n_cases` (default .true.).
      logical, intent(in), optional :: indexed
      integer, allocatable :: idx(:), step(:)
      real(dp), allocatable :: g(:), t(:)
      character(len=len(messages)), allocatable :: m(:)
      logical :: with_index
      integer :: i

      with_index = .true.
      if (present(indexed)) with_index = indexed
      idx = pack([(i, i=1, size(failed))], failed)
      g = gap(idx)
      m = messages(idx)
      t = times(idx)
      step = steps(idx)
      if (with_index) then
         call h5_write(h5, path//'/case', idx, error, units='1')
         if (allocated(error)) return
      end if
      call h5_write(h5, path//'/gap', g, error, units='m')
      if (allocated(error)) return
      call h5_write(h5, path//'/time', t, error, units='s')
      if (allocated(error)) return
      call h5_write(h5, path//'/step', step, error, units='1')
      if (allocated(error)) return
      call h5_write(h5, path//'/message', m, error, units='-')
      if (allocated(error) .or. .not. with_index) return
      call h5_write_attr(h5, path, 'n_cases', size(failed), error)
   end subroutine write_failed_cases

   !> Units of the response quantity q (`pound_response`: u, v, a_abs, drift, storey_shear),
   !> as its datasets' `units` attribute.
   pure function quantity_units(q) result(units)
      !> Quantity index (q_u .. q_shear).
      integer, intent(in) :: q
      character(len=:), allocatable :: units

      select case (q)
      case (q_u, q_drift)
         units = 'm'
      case (q_v)
         units = 'm/s'
      case (q_a_abs)
         units = 'm/s^2'
      case default
         units = 'kN'
      end select
   end function quantity_units

   !> Units of a member row of a frame's column segments (shear, moment_bottom, moment_top,
   !> axial): kN m for the moments, kN for the forces.
   pure function member_units(name) result(units)
      !> The member row's name.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: units

      if (index(name, 'moment') == 1) then
         units = 'kN m'
      else
         units = 'kN'
      end if
   end function member_units

   !> The labels of the pairs (`pair_label`), separated by one blank (a label has none).
   function pair_list(cs) result(labels)
      !> The contact system.
      type(contact_system), intent(in) :: cs
      character(len=:), allocatable :: labels
      integer :: k

      labels = ''
      do k = 1, cs%m
         if (k > 1) labels = labels//' '
         labels = labels//cs%pair(k)%label
      end do
   end function pair_list

   !> The contact points' friction (pound_contact_friction) under `/coupled/contact`: peak |T|
   !> per point (`peak_friction`, 0 for a point without friction) and its time, the final
   !> slip, the friction work, and the histories of T (`friction_force`) and of the committed
   !> slip (`slip`), (n_points, n_out) as the joints' other histories.
   subroutine write_friction(h5, c, cs, joints, error)
      type(h5_file), intent(inout) :: h5
      character(len=*), intent(in) :: c
      type(contact_system), intent(in) :: cs
      type(joint_history), intent(in) :: joints
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: peak(:), when(:), slip(:), mu(:)
      integer :: i

      allocate (peak(cs%m), when(cs%m), slip(cs%m), mu(cs%m))
      peak = 0.0_dp
      when = 0.0_dp
      slip = 0.0_dp
      mu = cs%pair(:)%friction
      do i = 1, cs%fr%n
         peak(cs%fr%joint(i)) = cs%fr%p(i)%peak
         when(cs%fr%joint(i)) = cs%fr%p(i)%peak_time
         slip(cs%fr%joint(i)) = cs%fr%p(i)%slip
      end do
      call h5_write(h5, c//'/peak_friction', peak, error, units='kN')
      if (allocated(error)) return
      call h5_write(h5, c//'/peak_friction_time', when, error, units='s')
      if (allocated(error)) return
      call h5_write(h5, c//'/slip_final', slip, error, units='m')
      if (allocated(error)) return
      call h5_write(h5, c//'/friction', mu, error, units='1')
      if (allocated(error)) return
      call h5_write(h5, c//'/friction_work', [cs%fr%work], error, units='kJ')
      if (allocated(error)) return
      if (.not. allocated(joints%friction)) return
      call h5_write(h5, c//'/friction_force', joints%friction, error, units='kN')
      if (allocated(error)) return
      call h5_write(h5, c//'/slip', joints%slip, error, units='m')
   end subroutine write_friction

end module pound_results_h5
