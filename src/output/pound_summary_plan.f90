!> The summary items of a building in plan: the largest plane-shear lambda (plane and storey)
!> and the peak floor rotation of the coupled run (floor); the impact-force item names the
!> contact point (its facade corner) that struck (pound_summary).
module pound_summary_plan
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_strings, only: str
   use pound_case_result, only: case_result
   use pound_summary_item, only: summary_item, item, append
   implicit none
   private

   public :: plan_items

contains

   !> Append the plan items of building ib (nothing for a planar building).
   subroutine plan_items(items, res, ib, b, motion)
      !> The summary so far.
      type(summary_item), allocatable, intent(inout) :: items(:)
      !> The case.
      type(case_result), intent(in) :: res
      !> Building index and name, and the motion's heading (blank for one motion).
      integer, intent(in) :: ib
      character(len=*), intent(in) :: b, motion
      integer :: g, k, best, ns

      if (.not. allocated(res%models(ib)%plan) .or. .not. allocated(res%models(ib)%result)) return
      do g = 1, size(res%models(ib)%result)
         associate (grp => res%models(ib)%result(g))
            select case (trim(grp%name))
            case ('plane_shear')
               if (.not. allocated(res%influence(ib)%result_lambda)) cycle
               ns = grp%extent(1)
               best = 0
               do k = grp%first, grp%first + product(grp%extent) - 1
                  if (ieee_is_nan(res%influence(ib)%result_lambda(k))) cycle
                  if (best == 0) then
                     best = k
                  else if (abs(res%influence(ib)%result_lambda(k)) > abs(res%influence(ib)%result_lambda(best))) then
                     best = k
                  end if
               end do
               if (best == 0) then
                  call append(items, item('building', b, 'lambda_plane_shear', b//': largest plane-shear lambda'// &
                                          motion, unit='%', location='every uncoupled plane shear is 0', &
                                          available=.false.))
               else
                  k = best - grp%first
                  call append(items, item('building', b, 'lambda_plane_shear', b//': largest plane-shear lambda'// &
                                          motion, res%influence(ib)%result_lambda(best), '%', 'plane '// &
                                          str(k/ns + 1)//', storey '//str(mod(k, ns) + 1), &
                                          res%cpl%building(ib)%result_time(best)))
               end if
            case ('rotation')
               best = grp%first
               do k = grp%first, grp%first + product(grp%extent) - 1
                  if (res%cpl%building(ib)%result_peak(k) > res%cpl%building(ib)%result_peak(best)) best = k
               end do
               call append(items, item('building', b, 'peak_rotation', b//': peak floor rotation (coupled)'// &
                                       motion, res%cpl%building(ib)%result_peak(best)*1.0e3_dp, 'mrad', &
                                       'floor '//str(best - grp%first + 1), res%cpl%building(ib)%result_time(best)))
            end select
         end associate
      end do
   end subroutine plan_items

end module pound_summary_plan
