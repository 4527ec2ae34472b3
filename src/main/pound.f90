!> pound: seismic pounding of adjacent buildings.
!>
!>     pound DECK.nml [-o DIR] [--progress | --quiet]
!>                                 writes DIR/<stem>.out (listing), DIR/<stem>.h5 (histories) and
!>                                 DIR/<stem>_summary.csv (the engineering summary, pound_summary)
!>     pound --help | --version
!>
!> Long runs show a progress line on standard error when it is a terminal (pound_progress);
!> `--progress` forces it, `--quiet` silences it.
!>
!> The program keeps the command line, the writers and the exit status; the analyses are one
!> case of the library's run driver (`pound_run_case`): the buildings uncoupled and, when the
!> deck declares contact, coupled, with influence coefficients and the gap sweep.
!> Before computing, the memory the run needs is checked against what the machine can give
!> (pound_memory) and the output folder is created and reserved (pound_files). A single-motion
!> deck streams its building histories into the temporary HDF5 file during the analyses
!> (`h5_history_sink`), so that their memory is one block, not the whole run. Outputs are
!> written under temporary names unique to the run and published together at the end; on any
!> error, SIGINT or SIGTERM this run's temporaries are removed and the exit status is non-zero.
program pound
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use, intrinsic :: ieee_exceptions, only: ieee_set_halting_mode, ieee_overflow, ieee_invalid, &
                                            ieee_divide_by_zero
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_version, only: program_name, program_version
   use pound_config, only: deck_type
   use pound_deck, only: read_deck
   use pound_ground_motion, only: ground_motion_t
   use pound_run_case, only: case_options, case_result, run_case, deck_ground_motion
   use pound_structure, only: structure_names
   use pound_sweep_joints, only: failed_joint_gaps
   use pound_sweep_joints_output, only: write_joint_sweep_tables
   use pound_suite, only: suite_result, run_suite
   use pound_planned_runs, only: planned_runs
   use pound_suite_motions, only: single_motion
   use pound_case_studies, only: has_parameter_sweep, has_law_study
   use pound_study_output, only: write_study_tables, write_stiffness_rules, write_study_h5
   use pound_suite_output, only: write_suite_listing, write_suite_h5
   use pound_separation_output, only: write_run_separation, pair_labels
   use pound_listing, only: write_listing_header, write_model_summary, write_peak_tables, write_warning_lines, &
                            write_contact_summary, write_influence_tables, write_sweep_table, write_column_tables, &
                            write_sweep_column_table, write_section
   use pound_result_groups_output, only: write_result_groups_listing
   use pound_text_writer, only: text_writer, open_text, close_text
   use pound_summary, only: summary_item, build_summary, summary_lines, motion_heading, summary_text_len
   use pound_summary_output, only: write_summary_csv, write_summary_attributes, summary_attribute_text
   use pound_results_h5, only: write_results_h5, h5_history_sink, history_sink_init
   use pound_h5, only: h5_file
   use pound_yield_output, only: write_yield_tables
   use pound_files, only: output_set, plan_outputs, publish_outputs, discard_outputs, &
                          install_signal_cleanup
   use pound_memory, only: estimate_memory, memory_available, memory_refusal
   use pound_posix, only: posix_std_fd_open, posix_reserve_fd, posix_exit_now, posix_write, posix_strerror, &
                          posix_keep_freed_memory, posix_sleep
   use pound_strings, only: counted, fixed_cell, str
   use pound_analysis, only: substep_text, exact_text
   use pound_response, only: discard_sink
   use pound_progress, only: progress_setup, progress_start, progress_finish, progress_auto, progress_on, &
                             progress_off
   use pound_cases, only: cases_start, cases_stop, cases_abort, cases_rank, cases_ranks, cases_all
   use pound_stripes, only: stripes_result, run_stripes, stripes_runs
   use pound_stripes_output, only: risk_answer_lines, risk_summary_items, write_stripes_listing, write_stripes_h5, &
                                   write_demand_files
   implicit none

   character(len=:), allocatable :: deck_path, out_dir
   type(deck_type) :: deck
   type(case_options) :: options
   type(case_result) :: res
   type(output_set) :: outputs
   type(h5_history_sink), target :: sink
   type(discard_sink), target :: dropped
   logical :: stdout_closed
   type(error_type), allocatable :: error
   character(len=512) :: ground_text(1)
   type(suite_result) :: suite
   !> `&stripes` (pound_stripes): the deck as given (its sweep serves the stripes; the suite of
   !> the motions as given runs without it) and the multiple-stripe analysis.
   type(deck_type) :: risk_deck
   type(stripes_result) :: risk
   logical :: is_suite, streamed, one_scaled
   !> The engineering summary (`pound_summary`): its items and its text lines.
   type(summary_item), allocatable :: summary_items(:)
   character(len=2*summary_text_len), allocatable :: summary_text(:)
   integer :: progress_mode = progress_auto
   !> Exit status of a run whose results were written but some of whose cases (gaps of a
   !> sweep; a suite's motions, their gaps and trial gaps) failed.
   integer, parameter :: failed_cases_status = 3
   logical :: writer
   !> Whether an error now may be rank 0's alone (its streamed HDF5 file), while the other
   !> ranks compute: then MPI_Abort ends the job instead of leaving them waiting.
   logical :: alone = .false.

   call install_signal_cleanup()
   call posix_keep_freed_memory()
   call guard_standard_descriptors()
   ! With MPI every rank reads and checks the deck and runs the same driver; the cases are
   ! shared (pound_cases) and rank 0, the writer, alone plans, writes and reports.
   call cases_start()
   writer = cases_rank() == 0
   call parse_arguments()
   call read_deck(deck_path, deck, error)
   call check(error)
   call test_overflow()
   if (deck%risk%active) then
      risk_deck = deck
      deck%sweep%active = .false.
   end if

   ! Ground motion (a record is read whole: its memory is proportional to the file). A suite
   ! (several &ground, a synthetic motion or scale_to) builds its motions one at a time.
   is_suite = size(deck%motions) > 1 .or. deck%ground%kind == 'synthetic' .or. len(deck%ground%scale_to) > 0
   ! A joint study (stiffness or restitution sweep, law study) with one scaled or synthetic
   ! motion runs that motion as one case.
   one_scaled = .false.
   if (is_suite .and. size(deck%motions) == 1) one_scaled = has_parameter_sweep(deck) .or. has_law_study(deck)
   if (one_scaled) is_suite = .false.
   ! One deck, one motion, no node histories: the histories go to the file during the run.
   streamed = .not. (is_suite .or. deck%analysis%node_histories)
   if (.not. is_suite) then
      allocate (options%ground)
      if (one_scaled) then
         call single_motion(deck, options%ground, error)
      else
         call deck_ground_motion(deck, options%ground, error)
      end if
      call check(error)
   end if

   ! Resources and the output folder, before anything large is allocated or computed.
   call check_memory()
   if (writer) call plan_run_outputs()
   if (.not. cases_all(.not. allocated(error))) then
      if (.not. allocated(error)) call fatal_error(error, 'rank 0 could not reserve the outputs')
      call check(error)
   end if

   ! One deck, one motion: the histories are streamed into this run's temporary .h5 during
   ! the analyses (a suite, or a run with node histories, holds them and writes them at the end).
   ! The other MPI ranks drop them (rank 0 alone writes).
   if (streamed .and. writer) then
      alone = cases_ranks() > 1
      call history_sink_init(sink, outputs%h5_tmp, outputs%h5, deck, error)
      call check(error)
      options%sink => sink
   else if (streamed) then
      options%sink => dropped
   end if

   ! The analyses.
   options%label = deck_path
   if (.not. writer) progress_mode = progress_off
   call progress_setup(progress_mode)
   if (risk_deck%risk%active) then
      call progress_start(planned_runs(deck, is_suite) + stripes_runs(risk_deck))
   else
      call progress_start(planned_runs(deck, is_suite))
   end if
   if (is_suite) then
      call run_suite(deck, suite, res, error, deck_path)
   else
      call run_case(deck, res, error, options)
   end if
   if (.not. allocated(error) .and. risk_deck%risk%active) call run_stripes(risk_deck, risk, error)
   call check(error)
   alone = .false.
   call progress_finish(.true.)
   ground_text(1) = res%ground_text
   if (.not. writer) then
      call cases_stop()
      call posix_exit_now(0)
   end if
   call make_summary()

   ! Outputs: this run's temporaries first, published together when all are complete.
   call write_listing(outputs%listing_tmp, error)
   call check(error)
   call test_pause()
   if (streamed) then
      call write_h5(sink%h5)
   else
      call write_h5()
   end if
   if (.not. allocated(error) .and. size(deck%motions) > 1) &
      call write_suite_h5(outputs%h5_tmp, res%models, suite, error, res%cs)
   if (.not. allocated(error)) call write_studies_h5(error)
   if (.not. allocated(error) .and. risk_deck%risk%active) call write_stripes_h5(outputs%h5_tmp, risk_deck, risk, error)
   if (.not. allocated(error) .and. size(deck%motions) > 1) call write_summary_h5(error)
   if (allocated(error)) error%message = 'cannot write '//outputs%h5//': '//error%message
   call check(error)
   call write_summary_csv(outputs%summary_tmp, summary_items, error)
   call check(error)
   call publish_outputs(outputs, error)
   call check(error)
   if (risk_deck%risk%active) then
      call write_demand_files(outputs%listing, risk_deck, risk, error)
      call check(error)
   end if
   call write_summary()
   ! Results written, but some cases failed (named in the listing, the file and the summary).
   ! (A suite of one motion writes no /suite: its failed gaps are those of its own sweep.)
   if (size(deck%motions) > 1) then
      if (size(suite%failures) > 0) then
         call stop_with(counted(size(suite%failures), 'case')//' of the suite failed ('// &
                        str(count(suite%motion_failed))//' of '//str(size(suite%names))// &
                        ' motions left out of the suite statistics; named in '//outputs%listing//' and '// &
                        outputs%h5//' /suite/failed); the other results were written', failed_cases_status)
      end if
   else if (res%has_sweep) then
      if (any(res%sweep%failed)) then
         call stop_with(str(count(res%sweep%failed))//' of '//str(size(res%sweep%failed))// &
                        ' gaps of the sweep failed (named in '//outputs%listing//' and '//outputs%h5// &
                        ' /sweep/failed); the other results were written', failed_cases_status)
      end if
      if (joint_count() > 0) then
         if (failed_joint_gaps(res%joints) > 0) &
            call stop_with(str(failed_joint_gaps(res%joints))//' gaps of the joints'' own sweeps failed (named in '// &
                           outputs%listing//' and '//outputs%h5//' /sweep/joint/<joint>/failed); the other '// &
                           'results were written', failed_cases_status)
      end if
   end if
   ! The studies of the joint (single motion only): failed runs give status 3 as failed gaps.
   if (size(deck%motions) == 1) call stop_on_failed_studies()
   call finish()

contains

   !> End a run whose outputs are written and closed as `stop_with` does (standard units
   !> flushed, _exit): the exit handlers have nothing left to do, and HDF5's alone (freeing
   !> its free lists and property lists) costs about 0.4 ms.
   subroutine finish()
      integer :: ios

      flush (error_unit, iostat=ios)
      flush (output_unit, iostat=ios)
      call cases_stop()
      call posix_exit_now(0)
   end subroutine finish

   !> The studies of the joint (`pound_study_output`) appended to this run's results file.
   subroutine write_studies_h5(err)
      type(error_type), allocatable, intent(out) :: err

      if (res%has_parameter_sweep .and. res%has_law_study) then
         call write_study_h5(outputs%h5_tmp, deck, res%models, err, sweep=res%parameter_sweep, law=res%law_study)
      else if (res%has_parameter_sweep) then
         call write_study_h5(outputs%h5_tmp, deck, res%models, err, sweep=res%parameter_sweep)
      else if (res%has_law_study) then
         call write_study_h5(outputs%h5_tmp, deck, res%models, err, law=res%law_study)
      end if
   end subroutine write_studies_h5

   !> Results written, but some runs of a stiffness or restitution sweep or of a law study
   !> failed: status 3, as failed gaps.
   subroutine stop_on_failed_studies()
      integer :: n

      n = 0
      if (res%has_parameter_sweep) n = n + count(res%parameter_sweep%failed)
      if (res%has_law_study) n = n + count(res%law_study%failed)
      if (n > 0) call stop_with(str(n)//' runs of the joint studies failed (named in '//outputs%listing// &
                                '); the other results were written', failed_cases_status)
   end subroutine stop_on_failed_studies

   !> The engineering summary's items and text lines (a suite: its answer first).
   subroutine make_summary()
      if (size(deck%motions) > 1) then
         call build_summary(res, summary_items, suite)
         summary_text = summary_lines(summary_items, motion_heading(suite))
      else
         call build_summary(res, summary_items)
         summary_text = summary_lines(summary_items)
      end if
      ! The multiple-stripe analysis's answer first.
      if (risk_deck%risk%active) then
         summary_items = [risk_summary_items(risk_deck, risk), summary_items]
         summary_text = [character(len=len(summary_text)) :: risk_answer_lines(risk_deck, risk), summary_text]
      end if
   end subroutine make_summary

   !> The summary's root attributes in the results file (this run's temporary).
   subroutine write_summary_h5(err)
      type(error_type), allocatable, intent(out) :: err

      call write_summary_attributes(outputs%h5_tmp, summary_items, summary_text, err, suite)
   end subroutine write_summary_h5

   !> The results file: this run's temporary, created here or (`file`) open since the
   !> analyses streamed their histories into it.
   subroutine write_h5(file)
      type(h5_file), intent(inout), optional :: file
      ! The summary attribute, written with the rest for one motion (unallocated: absent; a
      ! suite adds it after /suite, `write_summary_h5`).
      character(len=:), allocatable :: summary

      if (size(deck%motions) == 1) summary = summary_attribute_text(summary_text)

      if (.not. allocated(res%separation)) allocate (res%separation(0))
      if (res%has_sweep) then
         call write_results_h5(outputs%h5_tmp, deck, res%models, res%buildings, trim(ground_text(1)), res%ag_out, &
                               res%unc, error, res%cpl, res%cs, res%influence, res%sweep, file=file, &
                               separation=res%separation, joints=res%joints, summary=summary)
      else if (res%has_coupled) then
         call write_results_h5(outputs%h5_tmp, deck, res%models, res%buildings, trim(ground_text(1)), res%ag_out, &
                               res%unc, error, res%cpl, res%cs, res%influence, file=file, separation=res%separation, &
                               summary=summary)
      else
         call write_results_h5(outputs%h5_tmp, deck, res%models, res%buildings, trim(ground_text(1)), res%ag_out, &
                               res%unc, error, file=file, summary=summary)
      end if
   end subroutine write_h5

   !> Stop with the message and exit status 1 if `err` is set (whatever its kind: the
   !> `status` of an error is for the code, not the shell); remove this run's temporaries.
   subroutine check(err)
      type(error_type), allocatable, intent(in) :: err

      if (.not. allocated(err)) return
      call discard_outputs(outputs)
      call stop_with(err%message, 1)
   end subroutine check

   !> Write `message` to standard error and end the process with `status` by _exit, after
   !> flushing the standard units. Exit handlers are not run: they have nothing left to do,
   !> and HDF5's would crash on a dataset whose close failed when the disk filled up.
   subroutine stop_with(message, status)
      character(len=*), intent(in) :: message
      integer, intent(in) :: status
      integer :: ios

      call progress_finish(.false.)
      if (writer) write (error_unit, '(a)', iostat=ios) program_name//': error: '//message
      flush (error_unit, iostat=ios)
      flush (output_unit, iostat=ios)
      if (alone) call cases_abort(status)
      call cases_stop()
      call posix_exit_now(status)
   end subroutine stop_with

   !> The number of independent joints whose own sweeps ran (0 without a sweep).
   integer function joint_count()
      joint_count = 0
      if (allocated(res%joints)) joint_count = size(res%joints)
   end function joint_count

   !> Refuse the run if its estimated memory exceeds what the machine can give.
   !> Plan the outputs (`plan_outputs`): they must not be the deck or any record it reads.
   !> The paths are copied into an explicit-length array, never an array constructor
   !> `[character(len=n) :: a, b]`: gfortran 12 sizes such a constructor of deferred-length
   !> strings by `len(a)`, not `n`, and writes past the heap block when `b` is longer (an
   !> absolute record path longer than the deck path crashed the program).
   subroutine plan_run_outputs()
      integer :: i, n

      n = len(deck_path)
      do i = 1, size(deck%motions)
         if (deck%motions(i)%kind == 'record') n = max(n, len(deck%motions(i)%file))
      end do
      block
         character(len=n) :: inputs(1 + size(deck%motions))

         inputs = ''
         inputs(1) = deck_path
         do i = 1, size(deck%motions)
            if (deck%motions(i)%kind == 'record') inputs(1 + i) = deck%motions(i)%file
         end do
         call plan_outputs(out_dir, deck_path, inputs, outputs, error)
      end block
   end subroutine plan_run_outputs

   subroutine check_memory()
      real(dp) :: available
      character(len=:), allocatable :: source

      call memory_available(available, source)
      call memory_refusal(deck, estimate_memory(deck, streamed=streamed), available, source, error)
      call check(error)
   end subroutine check_memory

   !> The listing at `path` (this run's temporary); every write is checked.
   subroutine write_listing(path, err)
      character(len=*), intent(in) :: path
      type(error_type), allocatable, intent(out) :: err
      type(text_writer) :: lst
      character(len=:), allocatable :: input_warnings(:)
      character(len=len(ground_text)) :: suite_ground(1)

      call open_text(path, 'listing', lst, err)
      if (allocated(err)) return
      if (size(deck%motions) > 1) then
         ! Assigned (cut to the length of ground_text) before the call: an array constructor
         ! with a shorter type-spec length than its value was read past its end by gfortran.
         suite_ground(1) = motion_heading(suite)//': '//trim(ground_text(1))
         call write_listing_header(lst, deck, suite_ground, summary_text)
      else
         call write_listing_header(lst, deck, ground_text, summary_text)
      end if
      call write_model_summary(lst, res%models, res%buildings)
      if (res%n_input_warnings > 0) then
         input_warnings = res%warnings(1:res%n_input_warnings)
         call write_warning_lines(lst, input_warnings)
      end if
      if (size(deck%motions) > 1) then
         call write_section(lst, motion_heading(suite)//': the single-motion results of this motion alone '// &
                            '(the suite''s answer: Summary above and Ground-motion suite below)')
      end if
      call write_peak_tables(lst, 'Uncoupled', res%models, res%unc)
      if (.not. res%has_coupled) call write_column_tables(lst, res%models, res%buildings, res%unc)
      if (.not. res%has_coupled) call write_result_groups_listing(lst, res%models, res%unc)
      if (.not. res%has_coupled) call write_yield_tables(lst, res%models, res%unc)
      if (res%has_coupled) then
         call write_peak_tables(lst, 'Coupled', res%models, res%cpl)
         call write_contact_summary(lst, res%cs)
         call write_stiffness_rules(lst, deck%contacts)
         call write_influence_tables(lst, res%models, res%influence)
         call write_yield_tables(lst, res%models, res%unc, res%cpl)
         call write_column_tables(lst, res%models, res%buildings, res%unc, res%cpl, res%influence)
         call write_result_groups_listing(lst, res%models, res%unc, res%cpl, res%influence)
         if (res%has_sweep) call write_sweep_table(lst, res%models, deck%sweep, res%sweep)
         if (res%has_sweep) call write_sweep_column_table(lst, res%models, deck%sweep, res%sweep)
         if (joint_count() > 1) call write_joint_sweep_tables(lst, deck%sweep, res%joints, pair_labels(res%cs))
         if (size(deck%motions) == 1 .and. allocated(res%separation)) &
            call write_run_separation(lst, pair_labels(res%cs), res%separation, per_joint=joint_count() > 1, &
                                      names=structure_names(res%models))
         if (res%has_parameter_sweep) call write_study_tables(lst, res%models, res%parameter_sweep, &
                                                              deck%sweep%target, deck%sweep%target_quantities)
         if (res%has_law_study) call write_study_tables(lst, res%models, res%law_study, deck%sweep%target, &
                                                        deck%sweep%target_quantities)
      end if
      if (size(deck%motions) > 1) then
         call write_suite_listing(lst, res%models, suite, res%cs)
      end if
      if (risk_deck%risk%active) call write_stripes_listing(lst, risk_deck, risk)
      write (lst%unit, '(/,a,es10.3,a)', iostat=lst%ios, iomsg=lst%msg) '  uncoupled integration: ', res%unc%seconds, ' s'
      if (res%has_coupled .and. lst%ios == 0) write (lst%unit, '(a,es10.3,a,es10.3,a)', iostat=lst%ios, iomsg=lst%msg) &
         '  coupled integration:   ', res%cpl%seconds, ' s, of which LCP solves ', res%cpl%contact_seconds, ' s'
      if (res%unc%write_seconds + res%cpl%write_seconds > 0.0_dp .and. lst%ios == 0) &
         write (lst%unit, '(a,es10.3,a,es10.3,a)', iostat=lst%ios, iomsg=lst%msg) '  histories written during the integration: ', &
         res%unc%write_seconds, ' s (uncoupled), ', res%cpl%write_seconds, ' s (coupled), not in the times above'
      if (res%has_coupled .and. lst%ios == 0) then
         if (res%cpl%substep_factor > 0) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
            '  impact stepping:       '//substep_text(res%cpl)
         if (res%cpl%exact_steps >= 0 .and. lst%ios == 0) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
            '  free steps:            '//exact_text(res%cpl)
      end if
      call lst%note()
      call close_text(lst, err)
   end subroutine write_listing

   !> The summary on standard output, written unbuffered: a failed write (standard output
   !> closed, /dev/full, a reader gone) is an error with status 1.
   subroutine write_summary()
      character(len=:), allocatable :: text
      character(len=256) :: line
      integer :: e, ib, i

      text = program_name//' '//program_version//': '//deck%analysis%title//new_line('a')
      associate (models => res%models, unc => res%unc, cpl => res%cpl, cs => res%cs, sweep => res%sweep)
         do ib = 1, size(models)
            text = text//'  building '//models(ib)%name//': '//counted(size(models(ib)%floor_dof), 'storey')// &
                   ', T1 = '//trim(adjustl(fixed_cell(models(ib)%period(1), 11, 5, .true.)))//' s'//new_line('a')
         end do
         do i = 1, size(summary_text)
            text = text//'  '//trim(summary_text(i))//new_line('a')
         end do
         write (line, '(a,es10.3,a,es9.2)') '  uncoupled integration: ', unc%seconds, &
            ' s, energy balance error ', unc%energy_error
         text = text//trim(line)//new_line('a')
         if (res%has_coupled) then
            write (line, '(a,es10.3,a,es9.2,a)') '  coupled integration:   ', cpl%seconds, &
               ' s, energy balance error ', cpl%energy_error, ', '
            text = text//trim(line)//' '//counted(sum(cs%joint(:)%impacts), 'impact')//', '// &
                   counted(cs%stats%pivots_total, 'LCP pivot')//new_line('a')
            write (line, '(a,es10.3,a,i0,a,i0,a,i0)') '  contact (LCP) time:    ', cpl%contact_seconds, &
               ' s, LCP solves ', cs%stats%solves + cs%stats%active_solves - cs%stats%active_fallbacks, &
               ', pivots max ', cs%stats%pivots_max, ', steps ', cpl%n_steps
            text = text//trim(line)//new_line('a')
            if (cs%stats%active_solves > 0) then
               write (line, '(a,i0,a,i0,a,i0,a,i0)') '  LCP active set:        active-set solves ', &
                  cs%stats%active_solves, ', iterations ', cs%stats%active_iterations, ' (max ', &
                  cs%stats%active_iterations_max, '), fallbacks to Lemke ', cs%stats%active_fallbacks
               text = text//trim(line)//new_line('a')
            end if
            if (cpl%substep_factor > 0) then
               text = text//'  impact stepping:       '//substep_text(cpl)//new_line('a')
            end if
            if (cpl%exact_steps >= 0) text = text//'  free steps:            '//exact_text(cpl)//new_line('a')
         end if
         if (res%has_sweep) then
            write (line, '(a,i0,a,es10.3,a)') '  gap sweep: ', size(sweep%gap), ' gaps in ', sweep%seconds, ' s'
            text = text//trim(line)//new_line('a')
            if (sweep%found) then
               write (line, '(a,f10.4,a)') 'smallest gap meeting the target: ', 1000.0_dp*sweep%safe_gap, ' mm'
               if (size(deck%motions) > 1) then
                  text = text//'  '//motion_heading(suite)//', '//trim(line)//' (this motion alone)'//new_line('a')
               else if (joint_count() > 1) then
                  text = text//'  '//trim(line)//' (every joint at this gap; each joint''s own: the pair lines)'// &
                         new_line('a')
               else
                  text = text//'  '//trim(line)//new_line('a')
               end if
            end if
         end if
      end associate
      if (size(deck%motions) > 1) then
         if (size(suite%failures) > 0) then
            text = text//'  suite: '//counted(size(suite%names), 'motion')//', statistics over '// &
                   str(suite%n_used)//', '//counted(size(suite%failures), 'failed case')// &
                   ' (FAILED in the listing)'//new_line('a')
         end if
         if (suite%first > 1) text = text//'  the single-motion results are those of &ground '''// &
                                     trim(suite%names(suite%first))//''' (the first motion run whole that '// &
                                     'did not fail)'//new_line('a')
      end if
      do i = 1, size(res%warnings)
         text = text//'  WARNING: '//trim(res%warnings(i))//new_line('a')
      end do
      text = text//'  wrote '//outputs%listing//' and '//outputs%h5//' (summary: '//outputs%summary//')'//new_line('a')
      if (stdout_closed) then
         call stop_with('cannot write the summary: standard output is closed (the results were written to '// &
                        outputs%listing//' and '//outputs%h5//')', 1)
      end if
      e = posix_write(1, text)
      if (e /= 0) call stop_with('cannot write the summary to standard output: '//posix_strerror(e)// &
                                 ' (the results were written to '//outputs%listing//' and '//outputs%h5//')', 1)
   end subroutine write_summary

   !> Test hook: with POUND_TEST_PAUSE_WRITING=<seconds> in the environment, the run sleeps
   !> after its listing is written and before its HDF5 file is (so that a test can signal
   !> it while it writes).
   subroutine test_pause()
      character(len=16) :: value
      integer :: seconds, stat

      call get_environment_variable('POUND_TEST_PAUSE_WRITING', value, status=stat)
      if (stat /= 0) return
      read (value, *, iostat=stat) seconds
      if (stat == 0 .and. seconds > 0) call posix_sleep(seconds)
   end subroutine test_pause

   !> Test hook: with POUND_TEST_OVERFLOW=<name> in the environment, that `&ground` gets the
   !> amplitude x0 = 1e300 m (a pulse) or pga = 1e300 m/s^2 (a synthetic motion), beyond the
   !> reader's ranges (no deck can ask for it), and the floating-point traps of a Debug build
   !> are lifted: the motion's run
   !> overflows and fails as a real failure does (the run's finiteness checks name it). The
   !> command-line and MPI tests of a suite's failed cases need a case that fails, and no deck
   !> within the reader's ranges makes the solvers fail.
   subroutine test_overflow()
      character(len=64) :: name
      integer :: stat, k

      call get_environment_variable('POUND_TEST_OVERFLOW', name, status=stat)
      if (stat /= 0) return
      do k = 1, size(deck%motions)
         if (deck%motions(k)%name /= name) cycle
         deck%motions(k)%x0 = 1.0e300_dp
         deck%motions(k)%pga = 1.0e300_dp
         if (k == 1) deck%ground = deck%motions(k)
         call ieee_set_halting_mode([ieee_overflow, ieee_invalid, ieee_divide_by_zero], .false.)
      end do
   end subroutine test_overflow

   !> Keep closed standard descriptors (0, 1, 2) from being reused by the run's files: they
   !> are occupied by /dev/null, and a closed standard output is remembered as a failure.
   subroutine guard_standard_descriptors()
      integer :: fd, reserved

      stdout_closed = .not. posix_std_fd_open(1)
      do fd = 0, 2
         if (.not. posix_std_fd_open(fd)) reserved = posix_reserve_fd()
      end do
   end subroutine guard_standard_descriptors

   subroutine usage(unit)
      integer, intent(in) :: unit

      write (unit, '(a)') 'usage: pound DECK.nml [-o DIR] [--progress | --quiet]'
      write (unit, '(a)') '       pound --help | --version'
      write (unit, '(a)') 'Seismic pounding of adjacent buildings: runs the deck''s buildings uncoupled and'
      write (unit, '(a)') 'coupled by unilateral contact and writes DIR/<deck>.out (listing) and'
      write (unit, '(a)') 'DIR/<deck>.h5 (histories, HDF5). DIR defaults to the current directory.'
      write (unit, '(a)') 'A progress line goes to standard error when it is a terminal; --progress'
      write (unit, '(a)') 'shows it anyway, --quiet never.'
   end subroutine usage

   subroutine parse_arguments()
      integer :: i, n, length
      character(len=:), allocatable :: arg

      n = command_argument_count()
      out_dir = '.'
      i = 0
      do while (i < n)
         i = i + 1
         call get_command_argument(i, length=length)
         if (allocated(arg)) deallocate (arg)
         allocate (character(len=length) :: arg)
         call get_command_argument(i, arg)
         select case (arg)
         case ('-h', '--help')
            if (writer) call usage(output_unit)
            call cases_stop()
            stop
         case ('-V', '--version')
            if (writer) write (output_unit, '(a)') program_name//' '//program_version
            call cases_stop()
            stop
         case ('--progress')
            progress_mode = progress_on
         case ('-q', '--quiet')
            progress_mode = progress_off
         case ('-o', '--output')
            if (i == n) call bad_usage('option '//arg//' needs a directory')
            i = i + 1
            call get_command_argument(i, length=length)
            deallocate (out_dir)
            allocate (character(len=length) :: out_dir)
            call get_command_argument(i, out_dir)
            if (len(out_dir) == 0) call bad_usage('option -o needs a directory, got an empty name')
         case default
            if (len(arg) == 0) call bad_usage('the deck name is empty')
            if (arg(1:1) == '-') call bad_usage('unknown option '//arg)
            if (allocated(deck_path)) call bad_usage('more than one deck given: '//deck_path//', '//arg)
            deck_path = arg
         end select
      end do
      if (.not. allocated(deck_path)) call bad_usage('no deck given')
   end subroutine parse_arguments

   subroutine bad_usage(message)
      character(len=*), intent(in) :: message

      integer :: ios

      if (writer) then
         write (error_unit, '(a)', iostat=ios) program_name//': error: '//message
         call usage(error_unit)
      end if
      flush (error_unit, iostat=ios)
      call cases_stop()
      call posix_exit_now(2)
   end subroutine bad_usage

end program pound
