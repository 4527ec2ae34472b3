!> The listing section of the joints' own sweeps (`pound_sweep_joints`): for a deck with
!> several independent joints, per joint its gaps, impacts, the largest targeted |lambda| over
!> the buildings, whether the target is met, and its threshold gap (the time-history gap of its
!> pairs in the separation table); its failed gaps and warnings.
module pound_sweep_joints_output
   use pound_kinds, only: dp
   use pound_strings, only: fixed_cell, right_cell, str, counted
   use pound_config, only: sweep_config
   use pound_sweep_joints, only: joint_sweep
   use pound_listing, only: write_section
   use pound_text_writer, only: text_writer
   implicit none
   private

   public :: write_joint_sweep_tables

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
               write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
                  '    every gap failed: no threshold (see the warnings)'
               call lst%note()
               cycle
            end if
            line = '      gap [mm]    impacts  max |lambda|'
            if (cfg%target > 0.0_dp) line = line//'  target'
            write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) line
            call lst%note()
            do i = 1, size(sw%gap)
               line = '  '//fixed_cell(1000.0_dp*sw%gap(i), 12, 4)
               if (sw%failed(i)) then
                  write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
                     line//'   FAILED: '//trim(sw%messages(i))
                  call lst%note()
                  cycle
               end if
               worst = maxval(sw%max_abs_lambda(:, :, i), mask=spread(cfg%target_quantities, 2, &
                                                                     size(sw%max_abs_lambda, 2)))
               line = line//right_cell(str(sw%impacts(i)), 11)
               if (worst >= huge(1.0_dp)) then
                  line = line//right_cell('inf', 14)
               else
                  line = line//fixed_cell(worst, 14, 2)
               end if
               if (cfg%target > 0.0_dp) line = line//merge('     met', '      no', sw%meets(i))
               write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) line
               call lst%note()
            end do
            if (cfg%target <= 0.0_dp) cycle
            if (sw%found) then
               write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
                  '    threshold gap of joint '//jt%name//': '// &
                  trim(adjustl(fixed_cell(1000.0_dp*sw%safe_gap, 12, 4)))//' mm'
               call lst%note()
            else
               write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
                  '    threshold gap of joint '//jt%name//': none in the sweep range'
               call lst%note()
            end if
         end associate
      end do
   end subroutine write_joint_sweep_tables

end module pound_sweep_joints_output
