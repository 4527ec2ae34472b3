!> The listing section of the joints' own sweeps (`pound_sweep_joints`): for a deck with
!> several independent joints, per joint its gaps, impacts, the largest targeted |lambda| over
!> the buildings, whether the target is met, and its threshold gap (the time-history gap of its
!> pairs in the separation table); its failed gaps and warnings. For a suite
!> (`pound_suite_joints`), per joint its suite mean and largest |lambda| over the motions at
!> each gap and its threshold gaps on the mean, on every motion and on each motion, in the
!> listing and in HDF5:
!>
!>     /suite/sweep/joints/<name>/mean, max            (n_gaps), %: the suite mean (of each
!>        quantity's and building's largest |lambda| over the motions, then the largest over the
!>        targeted ones) and the largest over the motions; 0 where a motion failed
!>     /suite/sweep/joints/<name>/max_abs_lambda       (n_motions, n_gaps), %: each motion's
!>     /suite/sweep/joints/<name>/failed               (n_motions, n_gaps), 0/1
!>     /suite/sweep/joints/<name>/safe_gap_mean, safe_gap_every   scalars, m (-1: none)
!>     /suite/sweep/joints/<name>/safe_gap_motion      (n_motions), m (-1: none)
!>     /suite/sweep/joints/<name>/pairs                (n_pairs of the joint) the pair labels
module pound_sweep_joints_output
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: fixed_cell, right_cell, left_cell, str, counted
   use pound_config, only: sweep_config
   use pound_sweep_joints, only: joint_sweep
   use pound_suite_statistics, only: suite_result
   use pound_listing, only: write_section
   use pound_influence_output, only: lambda_cell
   use pound_text_writer, only: text_writer
   use pound_h5, only: h5_file, h5_write
   implicit none
   private

   public :: write_joint_sweep_tables, write_suite_joint_tables, write_suite_joints_h5

contains

   !> The joints' sweeps in the listing (nothing with fewer than two joints).
   subroutine write_joint_sweep_tables(lst, cfg, joints, labels)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> `&sweep`.
      type(sweep_config), intent(in) :: cfg
      !> The joints with their sweeps.
      type(joint_sweep), intent(in) :: joints(:)
      !> The pair labels (`pair_labels`), in deck order.
      character(len=*), intent(in) :: labels(:)
      character(len=*), parameter :: title = 'Gap study per joint: the joint''s pairs at the gaps, '// &
                                             'every other pair at its deck gap'
      character(len=:), allocatable :: line
      real(dp) :: worst
      integer :: i, j, k

      if (size(joints) < 2) return
      call write_section(lst, title)
      write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
         '  '//str(size(joints))//' independent joints (the pairs between two buildings form one joint, '// &
         'whose width is one gap); largest |lambda| [%]: over every building and', &
         '  every targeted quantity; the joint''s threshold is the smallest gap from which on every larger '// &
         'gap meets the target (as the common sweep''s):', &
         '  it is the time-history gap of the joint''s pairs in the separation rules.'
      call lst%note()
      do j = 1, size(joints)
         associate (jt => joints(j), sw => joints(j)%sweep)
            line = '  Joint '//jt%name//' ('//counted(size(jt%pairs), 'pair')//':'
            do k = 1, size(jt%pairs)
               line = line//' '//trim(labels(jt%pairs(k)))
            end do
            write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) line//')'
            call lst%note()
            if (.not. jt%done) then
               call lst%put('    every gap failed: no threshold (see the warnings)')
               cycle
            end if
            line = '      gap [mm]    impacts  max |lambda|'
            if (cfg%target > 0.0_dp) line = line//'  target'
            call lst%put(line)
            do i = 1, size(sw%gap)
               line = '  '//fixed_cell(1000.0_dp*sw%gap(i), 12, 4)
               if (sw%failed(i)) then
                  call lst%put(line//'   FAILED: '//trim(sw%messages(i)))
                  cycle
               end if
               worst = maxval(sw%max_abs_lambda(:, :, i), mask=spread(cfg%target_quantities, 2, &
                                                                     size(sw%max_abs_lambda, 2)))
               line = line//right_cell(str(sw%impacts(i)), 11)
               line = line//lambda_cell(worst, 14, 2)
               if (cfg%target > 0.0_dp) line = line//merge('     met', '      no', sw%meets(i))
               call lst%put(line)
            end do
            if (cfg%target <= 0.0_dp) cycle
            if (sw%found) then
               call lst%put( &
                  '    threshold gap of joint '//jt%name//': '// &
                  trim(adjustl(fixed_cell(1000.0_dp*sw%safe_gap, 12, 4)))//' mm')
            else
               call lst%put('    threshold gap of joint '//jt%name//': none in the sweep range')
            end if
         end associate
      end do
   end subroutine write_joint_sweep_tables

   !> A suite's joints' own sweeps in the listing (nothing without them): per joint its pairs,
   !> a table `gap [mm]  mean  max` (FAILED where a motion's run failed) and its thresholds on
   !> the mean, on every motion and per motion.
   subroutine write_suite_joint_tables(lst, suite, labels)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> The pair labels, in deck order.
      character(len=*), intent(in) :: labels(:)
      character(len=:), allocatable :: line
      integer :: i, j, k, w

      if (.not. allocated(suite%joint)) return
      call write_section(lst, 'Suite gap sweep per joint: the joint''s pairs at the gaps, every other pair at '// &
                         'its deck gap')
      write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
         '  '//str(size(suite%joint))//' independent joints, each swept in every motion; mean and max as the '// &
         'suite gap sweep''s (largest |lambda| [%] over every building and every targeted quantity);', &
         '  thresholds on the grid (not refined): the smallest gap from which on every larger gap meets the '// &
         'target on the mean, on every motion, and on each motion.'
      call lst%note()
      w = max(12, maxval(len_trim(suite%names)) + 2)
      do j = 1, size(suite%joint)
         associate (jt => suite%joint(j))
            line = '  Joint '//jt%name//' ('//counted(size(jt%pairs), 'pair')//':'
            do k = 1, size(jt%pairs)
               line = line//' '//trim(labels(jt%pairs(k)))
            end do
            write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) line//')'
            call lst%note()
            call lst%put('      gap [mm]          mean           max')
            do i = 1, size(suite%sweep_gap)
               line = '  '//fixed_cell(1000.0_dp*suite%sweep_gap(i), 12, 3)
               if (jt%gap_failed(i)) then
                  line = line//'        FAILED'
               else
                  line = line//lambda_cell(jt%mean(i), 14, 2)//lambda_cell(jt%max(i), 14, 2)
               end if
               call lst%put(line)
            end do
            call lst%put( &
               '    threshold gap of joint '//jt%name//': on the mean '//gap_text(jt%safe_gap_mean)// &
               ', on every motion '//gap_text(jt%safe_gap_every))
            do k = 1, size(suite%names)
               if (suite%motion_failed(k)) then
                  line = 'FAILED'
               else
                  line = gap_text(jt%safe_gap_motion(k))
               end if
               call lst%put('      '//left_cell(trim(suite%names(k)), w)//line)
            end do
         end associate
      end do

   contains

      !> A gap in mm, or 'n/a (none in the sweep range)'.
      pure function gap_text(gap) result(text)
         real(dp), intent(in) :: gap
         character(len=:), allocatable :: text

         if (gap >= 0.0_dp) then
            text = trim(adjustl(fixed_cell(1000.0_dp*gap, 12, 3)))//' mm'
         else
            text = 'n/a (none in the sweep range, or no target)'
         end if
      end function gap_text

   end subroutine write_suite_joint_tables

   !> A suite's joints' own sweeps in HDF5 (see the module; nothing without them).
   subroutine write_suite_joints_h5(h5, suite, labels, error)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> The pair labels, in deck order.
      character(len=*), intent(in) :: labels(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: g
      integer :: j

      if (.not. allocated(suite%joint)) return
      do j = 1, size(suite%joint)
         associate (jt => suite%joint(j))
            g = '/suite/sweep/joints/'//jt%name//'/'
            call h5_write(h5, g//'mean', jt%mean, error, units='%')
            if (.not. allocated(error)) call h5_write(h5, g//'max', jt%max, error, units='%')
            if (.not. allocated(error)) call h5_write(h5, g//'max_abs_lambda', transpose(jt%lambda), error, units='%')
            if (.not. allocated(error)) call h5_write(h5, g//'failed', transpose(merge(1, 0, jt%failed)), error, &
                                                      units='1')
            if (.not. allocated(error)) call h5_write(h5, g//'safe_gap_mean', jt%safe_gap_mean, error, units='m')
            if (.not. allocated(error)) call h5_write(h5, g//'safe_gap_every', jt%safe_gap_every, error, units='m')
            if (.not. allocated(error)) call h5_write(h5, g//'safe_gap_motion', jt%safe_gap_motion, error, units='m')
            if (.not. allocated(error)) call h5_write(h5, g//'pairs', labels(jt%pairs), error, units='-')
         end associate
         if (allocated(error)) return
      end do
   end subroutine write_suite_joints_h5

end module pound_sweep_joints_output
