!> Error state passed back to the caller (mctc-lib style).
!>
!> A procedure that can fail takes `type(error_type), allocatable, intent(out) :: error`
!> as its last argument. Unallocated on return means success. Only the main program stops.
!>
!> Beside its message an error carries, where the code that raised it knows them, the time
!> and step of an integration, the building, the joint and the case it concerns, so that no
!> caller parses them back out of the text (`error_at` sets them; unknown: -1 or 0).
!>
!> Its `status` says what kind of failure it is (`status_input`, `status_io`, ...), set by the
!> code that raised it, so that a caller that reacts to one kind (a temporary file that
!> exists: take another name) tests the status, never the message.
module pound_error
   use pound_kinds, only: dp
   implicit none
   private

   public :: error_type, fatal_error, error_at
   public :: status_failure, status_input, status_io, status_exists

   ! Kinds of failure, the values of `error_type%status`.
   !> A failure of no more particular kind (the default).
   integer, parameter :: status_failure = 1
   !> Input that breaks a rule: a deck, a record file, a value.
   integer, parameter :: status_input = 2
   !> A file or folder that cannot be opened, read, written, created or renamed.
   integer, parameter :: status_io = 3
   !> A file or folder to be created that exists already (or a file where a folder is wanted).
   integer, parameter :: status_exists = 4

   !> A failure, described in one message for the user, and where it happened as numbers.
   type :: error_type
      !> What failed and where.
      character(len=:), allocatable :: message
      !> Kind of failure (`status_failure`, `status_input`, ...; not an exit status: the main
      !> program exits 1 on every error).
      integer :: status = status_failure
      !> Time (s) and step of the integration at which it failed (-1: not an integration's,
      !> or not known).
      real(dp) :: time = -1.0_dp
      integer :: step = -1
      !> Building, joint (contact pair) and case (1-based; 0: none or not known).
      integer :: building = 0, joint = 0, case = 0
   end type error_type

contains

   !> Create an error carrying `message` and its kind `status` (default `status_failure`).
   pure subroutine fatal_error(error, message, status)
      !> Error to allocate.
      type(error_type), allocatable, intent(out) :: error
      !> One-line description naming what failed and where.
      character(len=*), intent(in) :: message
      !> Kind of failure (one of the `status_` values).
      integer, intent(in), optional :: status

      allocate (error)
      error%message = message
      if (present(status)) error%status = status
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
