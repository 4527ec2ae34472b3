!> The engineering summary of a run: the answer an engineer copies into a report, computed from
!> the results (nothing is run again) and given as items (`summary_item`) that the terminal
!> summary, the top of the listing and `<stem>_summary.csv` (`pound_summary_output`) share.
!>
!> Order of the items:
!> 1. a suite (several `&ground`): the suite's answer first: the thresholds of the suite sweep
!>    on the mean and on every motion (refined by bisection, then on the grid), the motions
!>    used and the failed cases, and per building the largest |lambda| of the storey shear over
!>    the storeys of the suite mean of the lambdas, of the lambda of the means and of any one
!>    motion (with that motion);
!> 2. per building (a suite: of the single-motion case, `motion_heading`): the largest
!>    |lambda| of the storey shear with its storey and the time of the coupled peak; for a
!>    building in plan the largest plane-shear |lambda| (plane, storey) and the peak floor
!>    rotation (`pound_summary_plan`); for a
!>    frame also of the column segments' shear and end moments with the segment (storey,
!>    column line) and time; the largest impact force on the building with its joint and time;
!> 3. per contact pair: the no-contact gap, the time-history threshold gap of the sweep and
!>    the code separation rules (ABS, SRSS, DDC with its correlation rho, ASCE 7, EN 1998,
!>    IS 1893) and the two buildings' setbacks on the uncoupled peaks of the facing points, the
!>    location saying which peaks (`peaks_label`; a suite: its row of the suite, on the mean
!>    peaks); then each building's property-line setback (`building_setbacks`);
!> 4. collapses (counted for yielding buildings: buildings x analyses, then per analysis; a
!>    suite gives its totals over the motions and per motion among its answer, the
!>    single-motion counts are labelled with their motion), failed sweep gaps, warnings.
!>
!> A yielding building (bilinear storeys or plastic hinges) leads with what yielding tells:
!> the largest storey-drift lambda; bilinear storeys: the storey of largest |lambda| of the
!> ductility (coupled against uncoupled of the same storey, every storey's on the line), the
!> largest coupled ductility, the storeys that yield only with pounding; hinges: the hinges
!> that form only with pounding, the largest plastic-rotation lambda (column and beam hinges
!> that yield in both analyses), the largest coupled rotation; then the residual drift, and
!> only then the storey-shear line. A suite does the same with its statistics. A lambda that
!> is not meaningful (pound_influence) is "n/m" and left out of the largest.
!>
!> A value that cannot be given is "n/a" (`available = .false.`), never a number; +huge (a
!> lambda whose uncoupled peak is 0) is "inf". Gaps are in mm, lambda in %, forces in kN.
module pound_summary
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: counted, plain_real, str
   use pound_response, only: q_u, q_drift, q_shear
   use pound_case_result, only: case_result
   use pound_sweep_joints, only: failed_joint_gaps
   use pound_suite_statistics, only: suite_result
   use pound_separation, only: separation_t, no_contact_gap, peaks_label, building_setbacks
   use pound_structure, only: structure_yields
   use pound_summary_item, only: summary_item, summary_text_len, item, append, largest
   use pound_summary_plan, only: plan_items
   use pound_summary_yield, only: lambda_item, yield_items, suite_lambdas, suite_yield_items, suite_collapses
   implicit none
   private

   public :: summary_item, summary_text_len, build_summary, summary_lines, motion_heading, value_text, &
             suite_answer_line

   !> Width of the label column of the text lines.
   integer, parameter :: label_width = 56

contains

   !> Every item of the summary of the case `res`; with `suite`
   !> (a deck with several `&ground`) the suite's answer first and the case is the suite's
   !> single-motion case (`suite%first`).
   subroutine build_summary(res, items, suite)
      !> The single-motion case (the program's results).
      type(case_result), intent(in) :: res
      !> The summary.
      type(summary_item), allocatable, intent(out) :: items(:)
      !> The suite, when the deck has several `&ground`.
      type(suite_result), intent(in), optional :: suite
      character(len=:), allocatable :: motion, where
      integer :: ib, ip, i

      allocate (items(0))
      motion = ''
      if (present(suite)) then
         call suite_items(suite)
         motion = ' ('//motion_heading(suite)//')'
      end if
      do ib = 1, size(res%models)
         call building_items(ib)
      end do
      if (res%has_coupled) then
         do ip = 1, res%cs%m
            call pair_items(ip)
         end do
         call setback_items()
      end if
      if (allocated(res%unc%yielding)) then
         i = count(res%unc%yielding%collapse_storey > 0)
         if (allocated(res%cpl%yielding)) i = i + count(res%cpl%yielding%collapse_storey > 0)
         ! A suite's single-motion counts say their motion in the CSV too (its totals are above).
         where = ''
         if (present(suite)) where = motion_heading(suite)//' only: '
         call add(item('collapse', 'run', 'collapse', 'collapses'//motion, real(i, dp), '-', &
                       location=where//'buildings x analyses whose storey drift / height passed collapse_drift '// &
                       '(the listing''s bilinear-storey tables say which storey when)'))
         call add(item('collapse', 'run', 'collapses_uncoupled', 'collapses, uncoupled'//motion, &
                       real(count(res%unc%yielding%collapse_storey > 0), dp), '-', where//'buildings'))
         if (allocated(res%cpl%yielding)) &
            call add(item('collapse', 'run', 'collapses_coupled', 'collapses, coupled'//motion, &
                          real(count(res%cpl%yielding%collapse_storey > 0), dp), '-', where//'buildings'))
      else
         call add(item('collapse', 'run', 'collapse', 'collapses', unit='', &
                       location='not modelled: the buildings of this deck are elastic and cannot collapse', &
                       available=.false.))
      end if
      if (res%has_sweep) then
         if (any(res%sweep%failed)) call add(item('failed', 'run', 'failed_sweep_gaps', &
                                                  'failed gaps of the sweep'//motion, &
                                                  real(count(res%sweep%failed), dp), '-', &
                                                  'of '//counted(size(res%sweep%failed), 'gap')))
         if (allocated(res%joints)) then
            if (failed_joint_gaps(res%joints) > 0) call add(item('failed', 'run', 'failed_joint_sweep_gaps', &
                                                                 'failed gaps of the joints'' own sweeps', &
                                                                 real(failed_joint_gaps(res%joints), dp), '-', &
                                                                 'of '//counted(size(res%joints)* &
                                                                                size(res%sweep%gap), 'gap')))
         end if
      end if
      if (allocated(res%warnings)) then
         do i = 1, size(res%warnings)
            call add(item('warning', 'run', 'warning', 'WARNING'//motion, unit='', &
                          location=trim(res%warnings(i)), available=.false.))
         end do
      end if

   contains

      subroutine add(it)
         type(summary_item), intent(in) :: it

         call append(items, it)
      end subroutine add

      !> The suite's answer.
      subroutine suite_items(s)
         type(suite_result), intent(in) :: s
         integer :: nm, ib
         character(len=:), allocatable :: tol
         character(len=24) :: buf

         nm = size(s%names)
         if (s%has_sweep) then
            write (buf, '(f0.4)') 1000.0_dp*s%refine_tolerance
            if (buf(1:1) == '.') buf = '0'//buf
            tol = 'bisection to '//trim(buf)//' mm'
            call add(gap_item('refined_gap_mean', 'suite gap: sweep threshold on the mean, refined', &
                              s%refined_gap_mean, tol))
            call add(gap_item('refined_gap_every', 'suite gap: sweep threshold on every motion, refined', &
                              s%refined_gap_every, tol))
            call add(gap_item('safe_gap_mean', 'suite gap on the sweep grid, on the mean', s%safe_gap_mean, &
                              'grid of '//str(size(s%sweep_gap))//' gaps'))
            call add(gap_item('safe_gap_every', 'suite gap on the sweep grid, on every motion', s%safe_gap_every, &
                              'grid of '//str(size(s%sweep_gap))//' gaps'))
         else
            call add(item('suite', 'suite', 'refined_gap_mean', 'suite gap: sweep threshold on the mean', &
                          unit='mm', location='no &sweep with target_lambda: not computed', available=.false.))
         end if
         call add(item('suite', 'suite', 'motions', 'motions of the suite', real(nm, dp), '-', &
                       'statistics over '//str(s%n_used)))
         if (size(s%failures) > 0) then
            call add(item('suite', 'suite', 'failed_cases', 'failed cases of the suite', real(size(s%failures), dp), &
                          '-', counted(nm - s%n_used, 'motion')//' left out; named in the listing and /suite/failed'))
         else
            call add(item('suite', 'suite', 'failed_cases', 'failed cases of the suite', 0.0_dp, '-', 'none'))
         end if
         if (.not. s%has_coupled) return
         do ib = 1, size(s%building)
            if (structure_yields(res%models(ib))) then
               call suite_lambdas(items, s, res%models, ib, q_drift, 'storey_drift', 'storey-drift')
               call suite_yield_items(items, s, res%models, ib)
            end if
            call suite_lambdas(items, s, res%models, ib, q_shear, 'storey_shear', 'storey-shear')
         end do
         if (any([(structure_yields(res%models(ib)), ib=1, size(res%models))])) &
            call suite_collapses(items, s, res%models)
      end subroutine suite_items

      !> A gap item of the suite (m in, mm out; negative: none).
      function gap_item(quantity, label, gap, where) result(it)
         character(len=*), intent(in) :: quantity, label, where
         real(dp), intent(in) :: gap
         type(summary_item) :: it

         if (gap >= 0.0_dp) then
            it = item('suite', 'suite', quantity, label, 1000.0_dp*gap, 'mm', where)
         else
            it = item('suite', 'suite', quantity, label, unit='mm', available=.false., &
                      location='none: no target_lambda, or no gap of the sweep range meets it')
         end if
      end function gap_item

      !> Largest storey-shear lambda, of the column segments (frames), largest impact force.
      subroutine building_items(ib)
         integer, intent(in) :: ib
         character(len=:), allocatable :: b
         integer :: j, k, s, nq, best_k
         real(dp) :: f, t
         character(len=:), allocatable :: joint

         b = trim(res%models(ib)%name)
         if (.not. res%has_coupled) then
            call add(item('building', b, 'lambda_storey_shear', b//': largest storey-shear lambda'//motion, &
                          unit='%', location='no &contact: no coupled run', available=.false.))
            return
         end if
         call yield_items(items, res, ib, motion)
         call lambda_item(items, res, ib, b, q_shear, 'lambda_storey_shear', 'storey-shear', motion)
         call plan_items(items, res, ib, b, motion)
         if (res%buildings(ib)%kind%n_segments() > 0 .and. allocated(res%influence(ib)%member_lambda) .and. &
             allocated(res%cpl%building(ib)%member_time)) then
            nq = size(res%models(ib)%member_names)
            associate (ml => res%influence(ib)%member_lambda, kind => res%buildings(ib)%kind)
               ! Shear (quantity 1 of a segment), then the larger of the end moments (2, 3).
               do k = 1, 2
                  best_k = 0
                  do s = 1, kind%n_segments()
                     do j = merge(1, 2, k == 1), merge(1, 3, k == 1)
                        if (best_k == 0) then
                           best_k = (s - 1)*nq + j
                        else if (abs(ml((s - 1)*nq + j)) > abs(ml(best_k))) then
                           best_k = (s - 1)*nq + j
                        end if
                     end do
                  end do
                  if (best_k == 0) cycle
                  s = (best_k - 1)/nq + 1
                  call add(item('building', b, merge('lambda_column_shear ', 'lambda_column_moment', k == 1), &
                                b//': largest column-segment '//merge('shear lambda ', 'moment lambda', k == 1)// &
                                motion, ml(best_k), '%', 'segment '//str(s)//' (storey '// &
                                str(kind%segment_storey(s))//', column line '// &
                                str(kind%segment_line(s))//', '// &
                                trim(res%models(ib)%member_names(best_k - (s - 1)*nq))//')', &
                                res%cpl%building(ib)%member_time(best_k)))
               end do
            end associate
         end if
         f = -1.0_dp
         t = -1.0_dp
         joint = ''
         do k = 1, res%cs%m
            if (all(res%cs%pair(k)%building /= ib)) cycle
            if (res%cs%joint(k)%peak_force > f) then
               f = res%cs%joint(k)%peak_force
               t = res%cs%joint(k)%peak_time
               joint = res%cs%pair(k)%label
            end if
         end do
         if (f > 0.0_dp) then
            call add(item('building', b, 'impact_force', b//': largest impact force'//motion, f, 'kN', &
                          'joint '//joint, t))
         else if (f == 0.0_dp) then
            call add(item('building', b, 'impact_force', b//': largest impact force'//motion, 0.0_dp, 'kN', &
                          'no impact'))
         else
            call add(item('building', b, 'impact_force', b//': largest impact force'//motion, unit='kN', &
                          location='no joint at this building', available=.false.))
         end if
      end subroutine building_items

      !> No-contact gap, time-history threshold gap and code rules of pair ip.
      subroutine pair_items(ip)
         integer, intent(in) :: ip
         type(separation_t) :: sep
         character(len=:), allocatable :: p, why, where
         logical :: have
         real(dp) :: gap

         p = trim(res%cs%pair(ip)%label)
         if (present(suite)) then
            associate (s => suite%separation(size(suite%names) + 1, ip))
               if (s%no_contact >= 0.0_dp) then
                  call add(item('pair', p, 'no_contact_gap', p//': no-contact gap, largest over the motions', &
                                1000.0_dp*s%no_contact, 'mm', &
                                'the largest over the motions of each motion''s max_t (u1 - u2) of its uncoupled '// &
                                'histories: no motion makes contact'))
               else
                  call add(item('pair', p, 'no_contact_gap', p//': no-contact gap', unit='mm', &
                                location='the u histories at the pair''s ends are not kept (history = ''u''; '// &
                                'a point between floors also needs &analysis node_histories)', available=.false.))
               end if
               call th_item(p, s%time_history, 'suite sweep threshold on the mean (one gap for every joint)')
               if (s%abs >= 0.0_dp) then
                  call rule_items(p, s, .true., 'suite mean of the '//peaks_label(suite%separation(size(suite%names) + 1, :)))
               else
                  call rule_items(p, s, .false., 'a pair end between floors whose model has no node there')
               end if
            end associate
            return
         end if
         call pair_no_contact(res, ip, gap, why)
         if (len(why) == 0) then
            call add(item('pair', p, 'no_contact_gap', p//': no-contact gap', 1000.0_dp*gap, 'mm', &
                          'max_t (u1 - u2) of the uncoupled run'))
         else
            call add(item('pair', p, 'no_contact_gap', p//': no-contact gap', unit='mm', location=why, &
                          available=.false.))
         end if
         gap = -1.0_dp
         where = 'no &sweep'
         if (res%has_sweep) then
            where = 'no target_lambda, or no gap of the sweep range meets it'
            if (res%sweep%found) gap = res%sweep%safe_gap
         end if
         if (gap >= 0.0_dp) where = 'sweep threshold (one gap for every joint)'
         if (res%has_sweep) call joint_item(ip, gap, where)
         call th_item(p, gap, where)
         have = .false.
         why = 'the separation rules were not computed'
         if (allocated(res%separation)) then
            if (ip <= size(res%separation)) then
               sep = res%separation(ip)
               have = sep%computed
               why = 'a pair end between floors whose model has no node there: its peak is not known'
            end if
         end if
         if (have) then
            call rule_items(p, sep, .true., peaks_label(res%separation)//' of the facing points')
         else
            call rule_items(p, sep, .false., why)
         end if
      end subroutine pair_items

      !> With several independent joints, pair ip's threshold is its joint's own (`pound_sweep_joints`).
      subroutine joint_item(ip, gap, where)
         integer, intent(in) :: ip
         real(dp), intent(inout) :: gap
         character(len=:), allocatable, intent(inout) :: where
         integer :: j

         if (.not. allocated(res%joints)) return
         if (size(res%joints) < 2) return
         do j = 1, size(res%joints)
            if (all(res%joints(j)%pairs /= ip)) cycle
            gap = -1.0_dp
            where = 'joint '//res%joints(j)%name//': its sweep ran no gap'
            if (res%joints(j)%done) where = 'joint '//res%joints(j)%name//': no target_lambda, or no gap of '// &
                                            'the sweep range meets it (other joints at their deck gaps)'
            if (.not. res%joints(j)%done) return
            if (res%joints(j)%sweep%found) then
               gap = res%joints(j)%sweep%safe_gap
               where = 'sweep threshold of joint '//res%joints(j)%name//' (its pairs swept, the other joints '// &
                       'at their deck gaps)'
            end if
         end do
      end subroutine joint_item

      !> The time-history threshold gap of pair p (m in, mm out; negative: n/a, `where` says why).
      subroutine th_item(p, gap, where)
         character(len=*), intent(in) :: p
         real(dp), intent(in) :: gap
         character(len=*), intent(in) :: where

         if (gap >= 0.0_dp) then
            call add(item('pair', p, 'time_history_gap', p//': time-history threshold gap', 1000.0_dp*gap, 'mm', where))
         else
            call add(item('pair', p, 'time_history_gap', p//': time-history threshold gap', unit='mm', &
                          location=where, available=.false.))
         end if
      end subroutine th_item

      !> The code separations of pair p in mm (ABS, SRSS, DDC of the elastic peaks; ASCE 7, EN 1998
      !> and IS 1893 with the buildings' factors, n/a where a factor is not given) and the DDC's
      !> rho (`have` false: all n/a, `where` says why).
      subroutine rule_items(p, sep, have, where)
         character(len=*), intent(in) :: p
         type(separation_t), intent(in) :: sep
         logical, intent(in) :: have
         character(len=*), intent(in) :: where
         character(len=*), parameter :: quantity(6) = [character(len=15) :: 'code_gap_abs', 'code_gap_srss', &
                                                       'code_gap_ddc', 'code_gap_asce7', 'code_gap_en1998', &
                                                       'code_gap_is1893']
         character(len=*), parameter :: rule(6) = [character(len=48) :: 'ABS = u1 + u2', 'SRSS', 'DDC (CQC rho)', &
                                                   'ASCE 7-16 12.12.3 (Cd/Ie)', 'EN 1998-1 4.4.2.7 (q)', &
                                                   'IS 1893-1 7.11.3 (R)']
         character(len=*), parameter :: factor(6) = [character(len=20) :: '', '', '', 'cd', 'behaviour_factor', &
                                                     'response_reduction']
         character(len=*), parameter :: side_quantity(2) = [character(len=13) :: 'setback_left', 'setback_right']
         character(len=*), parameter :: side_name(2) = [character(len=5) :: 'left', 'right']
         real(dp) :: v(6)
         logical :: valid(6)
         integer :: r

         v = [sep%abs, sep%srss, sep%ddc, sep%asce7, sep%en1998, sep%is1893]
         valid = [.true., .true., .true., sep%asce7_valid, sep%en1998_valid, sep%is1893_valid]
         do r = 1, 6
            if (have .and. valid(r)) then
               call add(item('pair', p, trim(quantity(r)), p//': code gap '//trim(rule(r)), 1000.0_dp*v(r), 'mm', &
                             where))
            else if (have) then
               call add(item('pair', p, trim(quantity(r)), p//': code gap '//trim(rule(r)), unit='mm', &
                             location='&building '//trim(factor(r))//' not given for both buildings', &
                             available=.false.))
            else
               call add(item('pair', p, trim(quantity(r)), p//': code gap '//trim(rule(r)), unit='mm', &
                             location=where, available=.false.))
            end if
         end do
         if (have) then
            call add(item('pair', p, 'ddc_rho', p//': DDC correlation rho', sep%rho, '-', where))
         else
            call add(item('pair', p, 'ddc_rho', p//': DDC correlation rho', unit='-', location=where, &
                          available=.false.))
         end if
         do r = 1, 2
            if (have) then
               call add(item('pair', p, trim(side_quantity(r)), p//': property-line setback of the '// &
                             trim(side_name(r))//' building', 1000.0_dp*sep%setback(r), 'mm', &
                             trim(merge('Cd u / Ie', 'u (no cd)', sep%setback_amplified(r)))//' of the '//where))
            else
               call add(item('pair', p, trim(side_quantity(r)), p//': property-line setback of the '// &
                             trim(side_name(r))//' building', unit='mm', location=where, available=.false.))
            end if
         end do
      end subroutine rule_items

      !> Each building's property-line setback (ASCE 7-16 12.12.2 style): its largest setback
      !> over the pairs it faces (a suite: its row of the suite, on the mean peaks).
      subroutine setback_items()
         type(separation_t), allocatable :: sep(:)
         character(len=:), allocatable :: what
         real(dp) :: setback
         integer :: jb, k, e
         logical :: amplified

         if (present(suite)) then
            sep = suite%separation(size(suite%names) + 1, :)
         else if (allocated(res%separation)) then
            sep = res%separation
         else
            return
         end if
         if (size(sep) == 0) return
         what = peaks_label(sep)
         if (present(suite)) what = 'suite mean of the '//what
         do jb = 1, size(res%models)
            setback = building_setbacks(sep, jb, size(res%models))
            if (ieee_is_nan(setback)) cycle
            amplified = .false.
            do k = 1, size(sep)
               do e = 1, 2
                  if (sep(k)%building(e) == jb .and. sep(k)%setback_amplified(e)) amplified = .true.
               end do
            end do
            call add(item('building', res%models(jb)%name, 'setback', res%models(jb)%name// &
                          ': property-line setback (ASCE 7 12.12.2 style)', 1000.0_dp*setback, 'mm', &
                          'largest over its facing points of its own delta_M = '// &
                          trim(merge('Cd u / Ie', 'u (no cd)', amplified))//', u: '//what))
         end do
      end subroutine setback_items

   end subroutine build_summary

   !> The no-contact gap max_t (u1(t) - u2(t)) of pair ip of a single-motion case (m, >= 0):
   !> the sweep's largest closing displacement of the joint in its run without contact (every
   !> step's path, `/sweep/closing_max`) when the case has one, otherwise from the uncoupled
   !> u histories when they are held whole (not streamed) at both facing floors; `why` is
   !> empty when the gap is given, else why it is n/a.
   subroutine pair_no_contact(res, ip, gap, why)
      type(case_result), intent(in) :: res
      integer, intent(in) :: ip
      real(dp), intent(out) :: gap
      character(len=:), allocatable, intent(out) :: why
      real(dp), allocatable :: h(:, :)
      integer :: e, b, n

      gap = 0.0_dp
      why = ''
      if (res%has_sweep) then
         if (allocated(res%sweep%closing_max)) then
            if (size(res%sweep%closing_max) >= ip) then
               gap = max(0.0_dp, res%sweep%closing_max(ip))
               return
            end if
         end if
      end if
      n = res%unc%n_out
      allocate (h(max(n, 1), 2))
      h = 0.0_dp
      associate (pair => res%cs%pair(ip))
         do e = 1, 2
            b = pair%building(e)
            if (b == 0) cycle
            associate (r => res%unc%building(b))
               if (pair%floor(e) == 0) then
                  ! A point between floors: its DOF's history, when every DOF's is held.
                  if (.not. allocated(r%u_nodes) .or. r%streamed .or. n == 0) then
                     why = 'a pair between floors: give a &sweep (its run without contact gives the gap)'
                     return
                  end if
                  h(1:n, e) = r%u_nodes(pair%dof(e), 1:n)
               else
                  if (.not. allocated(r%u) .or. r%streamed .or. n == 0) then
                     why = 'give a &sweep (its run without contact gives the gap)'
                     return
                  end if
                  h(1:n, e) = r%u(pair%floor(e), 1:n)
               end if
            end associate
         end do
      end associate
      gap = no_contact_gap(h(:, 1), h(:, 2))
   end subroutine pair_no_contact

   !> The heading of a suite's single-motion results: 'motion k of n: NAME'.
   pure function motion_heading(suite) result(text)
      !> The suite.
      type(suite_result), intent(in) :: suite
      character(len=:), allocatable :: text

      if (suite%first < 1 .or. suite%first > size(suite%names)) then
         text = 'no motion of '//str(size(suite%names))
      else
         text = 'motion '//str(suite%first)//' of '//str(size(suite%names))//': '//trim(suite%names(suite%first))
      end if
   end function motion_heading

   !> One line of the suite's answer (for plot titles and the HDF5 root): the refined
   !> thresholds of the suite sweep on the mean and on every motion, or why there are none.
   pure function suite_answer_line(suite) result(text)
      !> The suite.
      type(suite_result), intent(in) :: suite
      character(len=:), allocatable :: text

      text = 'suite of '//counted(size(suite%names), 'motion')
      if (.not. suite%has_sweep) then
         text = text//': no sweep threshold (no &sweep)'
      else
         text = text//': gap '//gap_text(suite%refined_gap_mean, suite%safe_gap_mean)//' on the mean, '// &
                gap_text(suite%refined_gap_every, suite%safe_gap_every)//' on every motion'
      end if
      if (size(suite%failures) > 0) text = text//'; '//counted(size(suite%failures), 'failed case')

   contains

      pure function gap_text(refined, safe) result(t)
         real(dp), intent(in) :: refined, safe
         character(len=:), allocatable :: t
         character(len=16) :: buf

         if (refined >= 0.0_dp) then
            write (buf, '(f0.2)') 1000.0_dp*refined
            t = trim(buf)//' mm'
         else if (safe >= 0.0_dp) then
            write (buf, '(f0.2)') 1000.0_dp*safe
            t = trim(buf)//' mm (grid)'
         else
            t = 'none'
         end if
      end function gap_text

   end function suite_answer_line

   !> The value of an item as text: 'n/a', 'inf', or the number (`digits` decimals).
   pure function value_text(it, digits) result(text)
      !> The item.
      type(summary_item), intent(in) :: it
      !> Decimals of the fixed form (the scientific form beyond 1e9 or below 1e-3).
      integer, intent(in) :: digits
      character(len=:), allocatable :: text
      character(len=40) :: buf
      character(len=16) :: fmt

      if (.not. it%available) then
         text = 'n/a'
      else if (ieee_is_nan(it%value)) then
         text = 'n/m'
      else if (it%value >= huge(1.0_dp)) then
         text = 'inf'
      else if (.not. ieee_is_finite(it%value)) then
         text = 'n/a'
      else if (it%unit == '-' .and. it%value == aint(it%value) .and. abs(it%value) < 1.0e9_dp) then
         write (buf, '(i0)') nint(it%value)
         text = trim(buf)
      else if (it%value /= 0.0_dp .and. (abs(it%value) >= 1.0e9_dp .or. abs(it%value) < 10.0_dp**(-digits))) then
         write (buf, '(es12.4)') it%value
         text = trim(adjustl(buf))
      else
         write (fmt, '(a,i0,a)') '(f0.', digits, ')'
         write (buf, fmt) it%value
         text = trim(adjustl(buf))
         if (text(1:1) == '.') text = '0'//text
         if (text(1:min(2, len(text))) == '-.') text = '-0'//text(2:)
      end if
   end function value_text

   !> The summary as text lines (the terminal and the top of the listing): a suite's answer
   !> first, then `motion_heading`'s line and the single-motion items; label, value and unit,
   !> then where and when.
   pure function summary_lines(items, heading) result(lines)
      !> The items (`build_summary`).
      type(summary_item), intent(in) :: items(:)
      !> A suite's heading of the single-motion items (absent or empty: none).
      character(len=*), intent(in), optional :: heading
      character(len=2*summary_text_len), allocatable :: lines(:)
      character(len=:), allocatable :: line, where
      integer :: i
      logical :: headed, counted

      allocate (lines(0))
      headed = .true.
      if (present(heading)) headed = len(heading) == 0
      do i = 1, size(items)
         associate (it => items(i))
            if (.not. headed .and. it%kind /= 'suite') then
               lines = [character(len=2*summary_text_len) :: lines, &
                        'single-motion results below: '//heading//' (not the suite''s answer)']
               headed = .true.
            end if
            if (it%kind == 'warning') then
               ! The warnings themselves follow the summary (terminal) or their tables (listing).
               if (i == 1) then
                  counted = .false.
               else
                  counted = items(i - 1)%kind == 'warning'
               end if
               if (.not. counted) lines = [character(len=2*summary_text_len) :: lines, &
                                           'warnings: '//str(count(items(i:)%kind == 'warning'))// &
                                           ' (the WARNING lines)']
               cycle
            end if
            if (it%kind == 'pair') then
               if (it%quantity == 'no_contact_gap') call pair_line(i)
               cycle
            end if
            line = trim(it%label)//':'
            if (len(line) < label_width) line = line//repeat(' ', label_width - len(line))
            line = line//' '//value_text(it, decimals(it%unit))
            if (it%available .and. len_trim(it%unit) > 0 .and. it%unit /= '-') line = line//' '//trim(it%unit)
            where = trim(it%location)
            if (it%time >= 0.0_dp) where = where//', t = '//time_text(it%time)//' s'
            if (len(where) > 0) line = line//'  ('//where//')'
            lines = [character(len=2*summary_text_len) :: lines, line]
         end associate
      end do

   contains

      !> The items of one pair (from `first` on, while the subject is the same) on one line of
      !> gaps in mm, then a line of notes: what each is based on, or why it is n/a.
      pure subroutine pair_line(first)
         integer, intent(in) :: first
         character(len=:), allocatable :: text, notes, factor
         integer :: k

         text = 'pair '//trim(items(first)%subject)//', gaps [mm]:'
         notes = ''
         k = first
         do while (k <= size(items))
            if (items(k)%kind /= 'pair' .or. items(k)%subject /= items(first)%subject) exit
            associate (p => items(k))
               if (k > first .and. p%quantity /= 'ddc_rho') text = text//','
               text = text//' '//short_name(p%quantity)//' '//value_text(p, decimals(p%unit))
               ! A code rule that is n/a for want of a factor names it: 'IS1893 n/a (needs response_reduction)'.
               if (.not. p%available .and. index(p%location, '&building ') == 1) then
                  factor = p%location(len('&building ') + 1:)
                  text = text//' (needs '//factor(1:index(factor, ' ') - 1)//')'
               end if
               if (p%quantity == 'ddc_rho') text = text//')'
               if (p%quantity == 'no_contact_gap' .or. p%quantity == 'time_history_gap') then
                  if (len(notes) > 0) notes = notes//'; '
                  notes = notes//short_name(p%quantity)//': '//trim(p%location)
               else if (p%quantity == 'code_gap_abs') then
                  notes = notes//'; code rules: '//trim(p%location)
               end if
            end associate
            k = k + 1
         end do
         lines = [character(len=2*summary_text_len) :: lines, text, '  ('//notes//')']
      end subroutine pair_line

      !> The short name of a pair's quantity on its line.
      pure function short_name(quantity) result(name)
         character(len=*), intent(in) :: quantity
         character(len=:), allocatable :: name

         select case (quantity)
         case ('no_contact_gap')
            name = 'no-contact'
         case ('time_history_gap')
            name = 'time-history'
         case ('code_gap_abs')
            name = 'ABS'
         case ('code_gap_srss')
            name = 'SRSS'
         case ('code_gap_asce7')
            name = 'ASCE7'
         case ('code_gap_en1998')
            name = 'EN1998'
         case ('code_gap_is1893')
            name = 'IS1893'
         case ('code_gap_ddc')
            name = 'DDC'
         case ('ddc_rho')
            name = '(DDC rho'
         case ('setback_left')
            name = 'setback left'
         case ('setback_right')
            name = 'setback right'
         case default
            name = trim(quantity)
         end select
      end function short_name

      pure integer function decimals(unit)
         character(len=*), intent(in) :: unit

         select case (unit)
         case ('mm')
            decimals = 4
         case ('%', 'kN')
            decimals = 2
         case default
            decimals = 3
         end select
      end function decimals

      pure function time_text(t) result(s)
         real(dp), intent(in) :: t
         character(len=:), allocatable :: s
         character(len=24) :: buf

         write (buf, '(f0.4)') t
         s = trim(buf)
         if (s(1:1) == '.') s = '0'//s
      end function time_text

   end function summary_lines

end module pound_summary
