!> Error state passed back to the caller (mctc-lib style).
!>
!> A procedure that can fail takes `type(error_type), allocatable, intent(out) :: error`
!> as its last argument. Unallocated on return means success. Only the main program stops.
!>
!> Beside its message an error carries, where the code that raised it knows them, the time
!> and step of an integration, the building, the joint and the case it concerns, so that no
!> caller parses them back out of the text (`error_at` sets them; unknown: -1 or 0).
module pound_error
   use pound_kinds, only: dp
   implicit none
   private

   public :: error_type, fatal_error, error_at

   !> A failure, described in one message for the user, and where it happened as numbers.
   type :: error_type
      !> What failed and where.
      character(len=:), allocatable :: message
      !> Exit status of a program that stops on it (1: a failure; the main program may use
      !> others for classes of failures).
      integer :: status = 1
      !> Time (s) and step of the integration at which it failed (-1: not an integration's,
      !> or not known).
      real(dp) :: time = -1.0_dp
      integer :: step = -1
      !> Building, joint (contact pair) and case (1-based; 0: none or not known).
      integer :: building = 0, joint = 0, case = 0
   end type error_type

contains

   !> Create an error carrying `message`.
   pure subroutine fatal_error(error, message)
      !> Error to allocate.
      type(error_type), allocatable, intent(out) :: error
      !> One-line description naming what failed and where.
      character(len=*), intent(in) :: message

      allocate (error)
      error%message = message
   end subroutine fatal_error

   !> Say where an allocated `error` happened: the time and step (kept when already known:
   !> the code nearest the failure set them), the building, joint and case (set when given).
   !> Nothing when `error` is not allocated.
   pure subroutine error_at(error, time, step, building, joint, case)
      !> The error.
      type(error_type), allocatable, intent(inout) :: error
      !> Time (s) and step of the integration.
      real(dp), intent(in), optional :: time
      integer, intent(in), optional :: step
      !> Building, joint and case indices (1-based).
      integer, intent(in), optional :: building, joint, case

      if (.not. allocated(error)) return
      if (present(time) .and. present(step) .and. error%step < 0) then
         error%time = time
         error%step = step
      end if
      if (present(building)) error%building = building
      if (present(joint)) error%joint = joint
      if (present(case)) error%case = case
   end subroutine error_at

end module pound_error
