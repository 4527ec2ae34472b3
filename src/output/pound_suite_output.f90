!> Outputs of a suite of ground motions (`pound_suite`): the listing sections and the HDF5
!> group `/suite`, written only when the deck has more than one motion.
!>
!> HDF5 (appended to the results file; shapes as h5py reads them, one row per motion; every
!> dataset has a `units` attribute):
!>
!>     /suite/names, /suite/scale_factor, /suite/pga            (n_motions); m/s^2
!>     /suite/source       (n_motions) record file as resolved, 'synthetic, seed N' or 'pulse'
!>     /suite/building_period                                   (n_buildings), s
!>     /suite/target, /suite/target_period   (n_motions) scaling target m/s^2 and its period s
!>        (0: a PGA target; -1: scaled by a factor)
!>     /suite/spectrum/period (n_periods), /suite/spectrum/sa   (n_motions, n_periods), m/s^2
!>     /suite/spectrum/mean_sa                                  (n_periods)
!>     /suite/influence/<b>/<q>                                 (n_motions, n), %
!>     /suite/mean/influence/<b>/<q>, /suite/max/influence/<b>/<q>, /suite/lambda_of_means/<b>/<q>  (n)
!>     /suite/influence/<b>/columns/<c>, /suite/mean/..., /suite/max/...   frames: the column
!>        segments' lambdas (pound_suite_columns_output)
!>     /suite/separation/<rule>                                 (n_motions + 1, n_pairs), m;
!>        rule: abs, srss, ec8, ddc, no_contact, time_history; the last row is the suite value
!>        (no_contact: the largest over the motions; time_history: the threshold gap of the
!>        sweep, -1 when not computed)
!>     /suite/separation/mean_closing    (n_pairs), m: the mean of the motions' no-contact gaps
!>        (NaN where a motion's is not known)
!>     /suite/sweep/gap, /suite/sweep/mean, /suite/sweep/max   (n_gaps), m and %
!>     /suite/sweep/max_abs_lambda                              (n_motions, n_gaps), %
!>     /suite/sweep/safe_gap_mean, /suite/sweep/safe_gap_every  scalars (m; -1: none)
!>     /suite/sweep/refined_gap_mean, /suite/sweep/refined_gap_every  bisection (-1: none)
!>     /suite/sweep/safe_gap_motion, refined_gap_motion, non_monotone_motion  (n_motions)
!>     /suite/sweep attributes refine_tolerance (m), non_monotone_mean, non_monotone_every
!>     /suite/sweep/joints/<left>-<right>/...   with several independent joints: each joint's
!>        own sweep over the motions (pound_sweep_joints_output)
!>     /suite/<motion>/ground/acceleration, /suite/<motion>/uncoupled/..., /suite/<motion>/coupled/...
!>        (as /uncoupled and /coupled) and /suite/<motion>/coupled/contact/force, closing
!>        (n_out, n_pairs): only for the motions whose `&ground` sets `histories`
!>     only when some case failed: /suite/failed/motion, gap (m; -1: the deck's gaps), time (s),
!>        step, message (n_failed), attributes n_motions, n_motions_used, single_motion (the
!>        motion of /uncoupled, /coupled, /sweep: the first motion run whole that did not fail);
!>        /suite/motion_failed
!>        (n_motions, 0/1); with &sweep /suite/sweep/failed (n_motions, n_gaps, 0/1; a failed
!>        motion's row 1 at every gap) and
!>        /suite/sweep/gap_failed (n_gaps, 0/1)
!>
!> (the per-motion arrays are held (n_motions, n) in Fortran and written transposed, so that
!> h5py, C and NumPy read them as documented, with one row per motion like the histories' one
!> row per output time).
module pound_suite_output
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_config, only: history_names, n_history_quantities
   use pound_strings, only: counted, str, left_cell, right_cell, fixed_cell
   use pound_contact, only: contact_system
   use pound_structure, only: structure_model, structure_names
   use pound_influence, only: building_influence, max_abs_meaningful
   use pound_text_writer, only: text_writer
   use pound_listing, only: write_section, write_influence_tables, gap_cell, mm
   use pound_h5, only: h5_file, h5_open, h5_close, h5_write, h5_write_attr
   use pound_suite_statistics, only: suite_result
   use pound_results_h5, only: write_analysis_h5, write_failed_cases, pair_list
   use pound_cases, only: case_message_len
   use pound_suite_columns_output, only: write_suite_columns_listing, write_suite_columns_h5
   use pound_suite_yield_output, only: write_suite_yield_listing, write_suite_yield_h5
   use pound_sweep_joints_output, only: write_suite_joint_tables, write_suite_joints_h5
   use pound_separation_output, only: write_separation_h5, write_separation_head, write_separation_rows, &
                                      write_separation_legend, write_setbacks
   implicit none
   private

   public :: write_suite_listing, write_suite_h5

   !> Separation rules, as named in HDF5.
   character(len=*), parameter :: rule_names(6) = &
      [character(len=12) :: 'abs', 'srss', 'ec8', 'ddc', 'no_contact', 'time_history']

contains

   !> Listing sections of the suite: motions, per-motion largest |lambda|, mean influence
   !> tables, separation rules per pair.
   !>
   !> Every table has one heading per column (names separated by at least two blanks) and one
   !> cell per column in every row (no blank inside a cell): the motion and building columns
   !> are as wide as the longest name, gaps are in mm ('n/a': not computed, or none).
   subroutine write_suite_listing(lst, models, suite, cs)
      !> The listing writer (unit, first write failure: the caller asks it).
      type(text_writer), intent(inout) :: lst
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> The contact system of the deck (its pairs' labels name the separation tables).
      type(contact_system), intent(in), optional :: cs
      type(building_influence), allocatable :: infl(:)
      integer :: k, ib, q, ip, nm, nb, wm, wb
      integer, allocatable :: used(:)
      character(len=:), allocatable :: over, line
      !> Why a safe gap of the suite sweep is n/a.
      character(len=*), parameter :: none_met = 'no gap of the range meets the target, or no target'

      nm = size(suite%names)
      nb = size(models)
      used = pack([(k, k=1, nm)], .not. suite%motion_failed)
      over = ''
      if (suite%n_used < nm) over = ' ('//str(suite%n_used)//' of '//str(nm)//' motions used, '// &
                                    str(nm - suite%n_used)//' FAILED and left out)'
      wm = len('mean_of_'//str(nm)//'/'//str(nm))
      do k = 1, nm
         wm = max(wm, len_trim(suite%names(k)))
      end do
      wb = len('building')
      do ib = 1, nb
         wb = max(wb, len(models(ib)%name))
      end do
      call write_section(lst, 'Ground-motion suite ('//counted(nm, 'motion')//')')
      call lst%put('  Sa: 5 %-damped pseudo-acceleration at the fundamental '// &
         'period of each building (m/s^2); row T1: that period (s)')
      line = '  '//left_cell('motion', wm)//'  scale_factor  PGA [m/s^2]'
      do ib = 1, nb
         line = line//right_cell('Sa '//models(ib)%name, sa_width(ib))
      end do
      call lst%put(line)
      do k = 1, nm
         line = '  '//left_cell(trim(suite%names(k)), wm)//es_cell(suite%scale_factor(k), 14)// &
                es_cell(suite%pga(k), 13)
         do ib = 1, nb
            line = line//es_cell(suite%sa_building(k, ib), sa_width(ib))
         end do
         call lst%put(line)
         if (suite%motion_failed(k)) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) '  '//repeat(' ', wm)// &
            '   FAILED (see the failed cases below): left out of every suite statistic'
         call lst%note()
      end do
      if (suite%n_used == nm) then
         line = '  '//left_cell('mean', wm)//right_cell('-', 14)//es_cell(sum(suite%pga)/nm, 13)
         do ib = 1, nb
            line = line//es_cell(sum(suite%sa_building(:, ib))/nm, sa_width(ib))
         end do
      else
         line = '  '//left_cell('mean_of_'//str(suite%n_used)//'/'//str(nm), wm)//right_cell('-', 14)// &
                es_cell(sum(suite%pga, mask=.not. suite%motion_failed)/suite%n_used, 13)
         do ib = 1, nb
            line = line//es_cell(sum(suite%sa_building(used, ib))/suite%n_used, sa_width(ib))
         end do
      end if
      call lst%put(line)
      line = '  '//left_cell('T1', wm)//right_cell('-', 14)//right_cell('-', 13)
      do ib = 1, nb
         line = line//repeat(' ', sa_width(ib) - 14)//fixed_cell(suite%building_period(ib), 14, 4)
      end do
      call lst%put(line)
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  '//left_cell('motion', wm)//'  source'
      call lst%note()
      do k = 1, nm
         call lst%put('  '//left_cell(trim(suite%names(k)), wm)//'  '// &
            trim(suite%source(k)))
      end do
      if (lst%first_ios /= 0) return
      if (.not. suite%has_coupled) then
         call write_failures()
         return
      end if

      call write_section(lst, 'Suite: largest |lambda| per motion, building and quantity [%]')
      line = '  '//left_cell('motion', wm)//'  '//left_cell('building', wb)
      do q = 1, n_history_quantities
         line = line//right_cell(trim(history_names(q)), 14)
      end do
      call lst%put(line)
      do k = 1, nm
         if (suite%motion_failed(k)) then
            call lst%put('  '//left_cell(trim(suite%names(k)), wm)//'   FAILED')
            cycle
         end if
         do ib = 1, nb
            line = '  '//left_cell(trim(suite%names(k)), wm)//'  '//left_cell(models(ib)%name, wb)
            do q = 1, n_history_quantities
               line = line//es_cell(max_abs_meaningful(suite%building(ib)%lambda(k, :, q)), 14)
            end do
            call lst%put(line)
         end do
      end do

      allocate (infl(nb))
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) &
         '  Suite mean of the lambdas (each motion''s lambda, '// &
         'then their arithmetic mean'//over//'):'
      call lst%note()
      do ib = 1, nb
         infl(ib)%lambda = suite%building(ib)%mean_lambda
      end do
      call write_influence_tables(lst, models, infl)
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Suite lambda of the means (the mean coupled and '// &
         'uncoupled peaks'//over//', then lambda; the codes average the responses: this is the one they ask for):'
      call lst%note()
      do ib = 1, nb
         infl(ib)%lambda = suite%building(ib)%lambda_of_means
      end do
      call write_influence_tables(lst, models, infl)
      call write_suite_columns_listing(lst, models, suite%names, suite%motion_failed, suite%columns)
      call write_suite_yield_listing(lst, models, suite)
      if (lst%first_ios /= 0) return

      call write_section(lst, 'Separation rules per contact pair [mm]')
      call write_separation_legend(lst, .true., suite%separation(nm + 1, :))
      call lst%put('  The suite row: rules on the mean peaks; no-contact gap: '// &
         'the largest over the motions'//over//' (the gap at which no motion makes contact); below each table the '// &
         'mean closing displacement: the mean of the motions'' no-contact gaps (some motion still makes contact there).')
      do ip = 1, size(suite%separation, 2)
         call write_separation_head(lst, suite_pair_name(ip, cs), 'motion', wm, suite%separation(nm + 1, ip))
         do k = 1, nm + 1
            if (k <= nm) then
               if (suite%motion_failed(k)) then
                  call lst%put('  '//left_cell(row_name(k), wm)//'   FAILED')
                  cycle
               end if
            end if
            call write_separation_rows(lst, row_name(k), suite%separation(k, ip), wm)
         end do
         if (suite%mean_closing(ip) >= 0.0_dp) then
            call lst%put('  mean closing displacement (mean over the '// &
               'motions of max_t (u1 - u2)): '// &
               trim(adjustl(fixed_cell(1000.0_dp*suite%mean_closing(ip), 14, 3)))//' mm')
         end if
      end do
      block
         character(len=64) :: plabels(size(suite%separation, 2))

         do ip = 1, size(plabels)
            plabels(ip) = suite_pair_name(ip, cs)
         end do
         call write_setbacks(lst, structure_names(models), plabels, suite%separation(nm + 1, :), 'the suite''s mean ')
      end block
      if (suite%has_sweep) then
         call write_section(lst, 'Suite gap sweep: largest |lambda| [%] over the targeted quantities')
         call lst%put('  mean: the suite mean of each quantity''s and '// &
            'building''s largest |lambda|, then the largest; max: the largest over the motions'//over)
         if (any(suite%gap_failed)) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
            '  FAILED: a motion''s run '// &
            'failed at the gap (see the failed cases below): not averaged over the others, never meeting the target'
         call lst%note()
         call lst%put('      gap [mm]          mean           max')
         do k = 1, size(suite%sweep_gap)
            if (suite%gap_failed(k)) then
               call lst%put('  '//gap_cell(suite%sweep_gap(k), 12)//'        FAILED')
               cycle
            end if
            call lst%put('  '//gap_cell(suite%sweep_gap(k), 12)// &
               es_cell(suite%sweep_mean(k), 14)//es_cell(suite%sweep_max(k), 14))
         end do
         call lst%put('  smallest gap meeting the target on the mean: '// &
            gap_or_why(suite%safe_gap_mean, none_met))
         call lst%put('  smallest gap meeting the target on every motion: '// &
            gap_or_why(suite%safe_gap_every, none_met))
         call lst%put('  refined by bisection (mean, every motion): '// &
            gap_or_why(suite%refined_gap_mean, 'not refined')//', '// &
            gap_or_why(suite%refined_gap_every, 'not refined')//' (tolerance '// &
            trim(adjustl(fixed_cell(mm*suite%refine_tolerance, 14, 4, .true.)))//' mm)')
         write (lst%unit, '(a,2(1x,i0),a)', iostat=lst%ios, iomsg=lst%msg) &
            '  non-monotone: grid gaps below the safe gap '// &
            'that pass nevertheless (mean, every motion):', suite%non_monotone_mean, suite%non_monotone_every, &
            '  (0: monotone on the grid)'
         call lst%note()
         if (suite%non_monotone_mean > 0 .or. suite%non_monotone_every > 0) write (lst%unit, '(a)', iostat=lst%ios, &
            iomsg=lst%msg) '  WARNING: |lambda| is not monotone in the gap: a smaller gap of the grid passes, '// &
            'yet the thresholds above are the gaps from which on every larger gap passes'
         call lst%note()
         write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) &
            '  Per motion: the threshold on its own largest |lambda| '// &
            '(the time_history rule)'
         call lst%note()
         call lst%put('  '//left_cell('motion', wm)// &
            '     grid [mm]  refined [mm]  non-monotone')
         do k = 1, nm
            if (suite%motion_failed(k)) then
               call lst%put('  '//left_cell(trim(suite%names(k)), wm)//'        FAILED')
               cycle
            end if
            write (lst%unit, '(a,i14)', iostat=lst%ios, iomsg=lst%msg) '  '//left_cell(trim(suite%names(k)), wm)// &
               gap_cell(suite%safe_gap_motion(k), 14)//gap_cell(suite%refined_gap_motion(k), 14), &
               suite%non_monotone_motion(k)
            call lst%note()
         end do
         call write_suite_joint_tables(lst, suite, suite_pair_names(size(suite%separation, 2), cs))
      end if
      if (lst%first_ios /= 0) return
      call write_failures()

   contains

      !> The table of the failed cases: motion, gap (mm; '-': the deck's gaps), time, step, message;
      !> each write checked, the first that fails named (no later write tried).
      subroutine write_failures()
         integer :: i
         character(len=14) :: gap

         if (size(suite%failures) == 0) return
         call write_section(lst, 'Failed cases of the suite ('//str(size(suite%failures))//')')
         write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
            '  gap -: the motion''s run at the deck''s gaps failed, or '// &
            'every gap of its sweep did (the motion is left out of every suite statistic);', &
            '  a gap: its run at that gap of the sweep or of a refinement failed (the gap never meets the target).'
         call lst%note()
         if (lst%ios == 0) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) '  '//left_cell('motion', wm)// &
            '      gap [mm]       t [s]      step  message'
         call lst%note()
         do i = 1, size(suite%failures)
            if (lst%ios /= 0) exit
            associate (f => suite%failures(i))
               gap = '             -'
               if (f%gap >= 0.0_dp) gap = fixed_cell(mm*f%gap, 14, 4)
               write (lst%unit, '(a,a14,es12.4,i10,2x,a)', iostat=lst%ios, iomsg=lst%msg) '  '// &
                  left_cell(trim(suite%names(f%motion)), wm), gap, f%time, f%step, trim(f%message)
               call lst%note()
            end associate
         end do
      end subroutine write_failures

      !> A gap of the suite sweep in mm, or, only when there is none (negative), 'n/a' and why.
      pure function gap_or_why(gap, why) result(text)
         real(dp), intent(in) :: gap
         character(len=*), intent(in) :: why
         character(len=:), allocatable :: text

         if (gap >= 0.0_dp) then
            text = trim(adjustl(gap_cell(gap, 14)))//' mm'
         else
            text = 'n/a ('//why//')'
         end if
      end function gap_or_why

      !> Width of the Sa column of building ib: its heading and a blank.
      pure integer function sa_width(ib)
         integer, intent(in) :: ib

         sa_width = max(14, len(models(ib)%name) + 5)
      end function sa_width

      !> x in scientific notation (6 significant digits) in a field of width w (>= 13).
      pure function es_cell(x, w) result(cell)
         real(dp), intent(in) :: x
         integer, intent(in) :: w
         character(len=w) :: cell

         write (cell, '(es'//str(w)//'.'//str(min(5, w - 8))//')') x
      end function es_cell

      !> The label of pair ip (`pair_label`), or 'ip' without the contact system.
      function row_name(k) result(name)
         integer, intent(in) :: k
         character(len=:), allocatable :: name

         if (k <= nm) then
            name = trim(suite%names(k))
         else
            name = 'suite'
         end if
      end function row_name

   end subroutine write_suite_listing

   !> Append `/suite` to the results file at `path`.
   subroutine write_suite_h5(path, models, suite, error, cs)
      !> Results file (written and closed).
      character(len=*), intent(in) :: path
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The contact system of the deck: its pairs' labels become the attribute `pairs` of
      !> /suite/separation (blank-separated, in the order of the columns).
      type(contact_system), intent(in), optional :: cs
      type(error_type), allocatable :: close_error
      type(h5_file) :: h5

      call h5_open(h5, path, error, writable=.true.)
      if (.not. allocated(error)) then
         call write_all()
         call h5_close(h5, close_error)
         if (allocated(close_error) .and. .not. allocated(error)) call move_alloc(close_error, error)
      end if

   contains

      subroutine write_all()
         real(dp), allocatable :: rule(:, :)
         integer :: ib, q, r
         character(len=:), allocatable :: b, qn

         call h5_write(h5, '/suite/names', suite%names, error, units='-')
         if (.not. allocated(error)) call h5_write(h5, '/suite/source', suite%source, error, units='-')
         if (.not. allocated(error)) call h5_write(h5, '/suite/scale_factor', suite%scale_factor, error, units='1')
         if (.not. allocated(error)) call h5_write(h5, '/suite/pga', suite%pga, error, units='m/s^2')
         if (.not. allocated(error)) call h5_write(h5, '/suite/building_period', suite%building_period, error, units='s')
         if (.not. allocated(error)) call h5_write(h5, '/suite/target', suite%target, error, units='m/s^2')
         if (.not. allocated(error)) call h5_write(h5, '/suite/target_period', suite%target_period, error, units='s')
         if (.not. allocated(error)) call h5_write(h5, '/suite/spectrum/period', suite%period, error, units='s')
         if (.not. allocated(error)) call h5_write(h5, '/suite/spectrum/sa', transpose(suite%sa), error, units='m/s^2')
         if (.not. allocated(error)) call h5_write(h5, '/suite/spectrum/mean_sa', suite%mean_sa, error, units='m/s^2')
         if (.not. allocated(error)) call write_failures()
         if (allocated(error) .or. .not. suite%has_coupled) return
         do ib = 1, size(models)
            b = models(ib)%name
            do q = 1, n_history_quantities
               qn = trim(history_names(q))
               call h5_write(h5, '/suite/influence/'//b//'/'//qn, transpose(suite%building(ib)%lambda(:, :, q)), &
                            error, units='%')
               if (.not. allocated(error)) call h5_write(h5, '/suite/mean/influence/'//b//'/'//qn, &
                                                         suite%building(ib)%mean_lambda(:, q), error, units='%')
               if (.not. allocated(error)) call h5_write(h5, '/suite/max/influence/'//b//'/'//qn, &
                                                         suite%building(ib)%max_lambda(:, q), error, units='%')
               if (.not. allocated(error)) call h5_write(h5, '/suite/lambda_of_means/'//b//'/'//qn, &
                                                         suite%building(ib)%lambda_of_means(:, q), error, units='%')
               if (allocated(error)) return
            end do
         end do
         call write_suite_columns_h5(h5, models, suite%columns, error)
         if (.not. allocated(error)) call write_suite_yield_h5(h5, models, suite, error)
         if (allocated(error)) return
         do r = 1, size(rule_names)
            select case (r)
            case (1)
               rule = suite%separation%abs
            case (2)
               rule = suite%separation%srss
            case (3)
               rule = suite%separation%ec8
            case (4)
               rule = suite%separation%ddc
            case (5)
               rule = suite%separation%no_contact
            case default
               rule = suite%separation%time_history
            end select
            call h5_write(h5, '/suite/separation/'//trim(rule_names(r)), transpose(rule), error, units='m')
            if (allocated(error)) return
         end do
         if (present(cs)) then
            if (cs%m > 0 .and. cs%m == size(suite%separation, 2)) then
               call h5_write_attr(h5, '/suite/separation', 'pairs', pair_list(cs), error)
               if (allocated(error)) return
            end if
         end if
         call write_separation_h5(h5, '/suite/separation', suite%separation, &
                                  suite_pair_names(size(suite%separation, 2), cs), .true., error, structure_names(models))
         if (.not. allocated(error)) call h5_write(h5, '/suite/separation/mean_closing', &
                                                   merge(suite%mean_closing, ieee_value(1.0_dp, ieee_quiet_nan), &
                                                         suite%mean_closing >= 0.0_dp), error, units='m')
         if (.not. allocated(error)) call h5_write_attr(h5, '/suite/separation/mean_closing', 'rule', &
                                                        'mean over the motions of each motion''s no-contact gap '// &
                                                        'max_t (u1 - u2): not a safe gap (some motion still makes '// &
                                                        'contact); the suite row of no_contact is the largest', error)
         if (allocated(error)) return
         call write_histories()
         if (allocated(error) .or. .not. suite%has_sweep) return
         call h5_write(h5, '/suite/sweep/gap', suite%sweep_gap, error, units='m')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/max_abs_lambda', transpose(suite%sweep_lambda), error, &
                                                   units='%')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/mean', suite%sweep_mean, error, units='%')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/max', suite%sweep_max, error, units='%')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/safe_gap_mean', suite%safe_gap_mean, error, units='m')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/safe_gap_every', suite%safe_gap_every, error, units='m')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/refined_gap_mean', suite%refined_gap_mean, error, units='m')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/refined_gap_every', suite%refined_gap_every, error, units='m')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/safe_gap_motion', suite%safe_gap_motion, error, units='m')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/refined_gap_motion', suite%refined_gap_motion, &
                                                   error, units='m')
         if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/non_monotone_motion', &
                                                   suite%non_monotone_motion, error, units='1')
         if (.not. allocated(error)) call h5_write_attr(h5, '/suite/sweep', 'non_monotone_mean', &
                                                        suite%non_monotone_mean, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/suite/sweep', 'non_monotone_every', &
                                                        suite%non_monotone_every, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/suite/sweep', 'refine_tolerance', &
                                                        suite%refine_tolerance, error)
         if (.not. allocated(error)) call write_suite_joints_h5(h5, suite, &
                                                                suite_pair_names(size(suite%separation, 2), cs), error)
         if (.not. allocated(error) .and. size(suite%failures) > 0) then
            call h5_write(h5, '/suite/sweep/failed', transpose(merge(1, 0, suite%sweep_failed)), error, &
                                units='1')
            if (.not. allocated(error)) call h5_write(h5, '/suite/sweep/gap_failed', merge(1, 0, suite%gap_failed), &
                                                      error, units='1')
         end if
         ! /sweep (the first motion's own sweep, per quantity) gets the suite statistics beside it.
         if (.not. allocated(error)) call h5_write(h5, '/sweep/suite_mean', suite%sweep_mean, error, units='%')
         if (.not. allocated(error)) call h5_write(h5, '/sweep/suite_max', suite%sweep_max, error, units='%')
         if (.not. allocated(error)) call h5_write_attr(h5, '/sweep', 'motion', trim(suite%names(suite%first)), &
                                                        error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/sweep', 'suite_safe_gap_mean', suite%safe_gap_mean, &
                                                        error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/sweep', 'suite_safe_gap_every', suite%safe_gap_every, &
                                                        error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/sweep', 'suite_refined_gap_mean', &
                                                        suite%refined_gap_mean, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/sweep', 'suite_refined_gap_every', &
                                                        suite%refined_gap_every, error)
      end subroutine write_all

      !> /suite/failed and /suite/motion_failed, when some case failed: `write_failed_cases`
      !> (every failure a case) with the motion of each in place of the case index.
      subroutine write_failures()
         real(dp), allocatable :: gap(:), time(:)
         character(len=len(suite%names)), allocatable :: motion(:)
         character(len=case_message_len), allocatable :: message(:)
         integer, allocatable :: step(:)
         logical, allocatable :: failed(:)
         integer :: i, n

         n = size(suite%failures)
         if (n == 0) return
         allocate (gap(n), motion(n), message(n), time(n), step(n), failed(n))
         failed = .true.
         do i = 1, n
            gap(i) = suite%failures(i)%gap
            time(i) = suite%failures(i)%time
            step(i) = suite%failures(i)%step
            motion(i) = suite%names(suite%failures(i)%motion)
            message(i) = suite%failures(i)%message
         end do
         call h5_write(h5, '/suite/failed/motion', motion, error, units='-')
         if (.not. allocated(error)) call write_failed_cases(h5, '/suite/failed', gap, failed, message, time, step, error, &
                                                             indexed=.false.)
         if (.not. allocated(error)) call h5_write_attr(h5, '/suite/failed', 'n_motions', size(suite%names), error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/suite/failed', 'n_motions_used', suite%n_used, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/suite/failed', 'single_motion', &
                                                        trim(suite%names(suite%first)), error)
         if (.not. allocated(error)) call h5_write(h5, '/suite/motion_failed', merge(1, 0, suite%motion_failed), &
                                                   error, units='1')
      end subroutine write_failures

      !> /suite/<motion>/... for the motions whose histories were kept.
      subroutine write_histories()
         character(len=:), allocatable :: g
         integer :: k

         do k = 1, size(suite%names)
            if (.not. suite%histories(k)%stored) cycle
            associate (h => suite%histories(k))
               g = '/suite/'//trim(suite%names(k))
               call h5_write(h5, g//'/ground/time', h%unc%time, error, units='s')
               if (.not. allocated(error)) call h5_write(h5, g//'/ground/acceleration', h%ag_out, error, units='m/s^2')
               if (.not. allocated(error)) call write_analysis_h5(h5, g//'/uncoupled', models, h%unc, error)
               if (allocated(error)) return
               if (.not. h%has_coupled) cycle
               call write_analysis_h5(h5, g//'/coupled', models, h%cpl, error)
               if (.not. allocated(error)) call h5_write(h5, g//'/coupled/contact/force', h%cpl%joints%force, error, units='kN')
               if (.not. allocated(error)) call h5_write(h5, g//'/coupled/contact/closing', &
                                                         h%cpl%joints%closing, error, units='m')
               if (allocated(error)) return
            end associate
         end do
      end subroutine write_histories


   end subroutine write_suite_h5

   !> The labels of the pairs 1..np (`suite_pair_name`), one length.
   function suite_pair_names(np, cs) result(labels)
      !> Number of pairs (the columns of `suite%separation`).
      integer, intent(in) :: np
      !> The contact system of the deck.
      type(contact_system), intent(in), optional :: cs
      character(len=:), allocatable :: labels(:)
      integer :: length, ip

      length = 1
      do ip = 1, np
         length = max(length, len(suite_pair_name(ip, cs)))
      end do
      allocate (character(len=length) :: labels(np))
      do ip = 1, np
         labels(ip) = suite_pair_name(ip, cs)
      end do
   end function suite_pair_names

   !> The label of pair `ip` ('A:3-B:z=7.50m', `pair_label`), or its number without a contact
   !> system: the separation tables and /suite/separation name the pairs by it.
   function suite_pair_name(ip, cs) result(name)
      !> Index of the pair (a column of `suite%separation`).
      integer, intent(in) :: ip
      !> The contact system of the deck.
      type(contact_system), intent(in), optional :: cs
      character(len=:), allocatable :: name

      name = str(ip)
      if (.not. present(cs)) return
      if (.not. allocated(cs%pair)) return
      if (ip <= size(cs%pair)) name = cs%pair(ip)%label
   end function suite_pair_name

end module pound_suite_output
