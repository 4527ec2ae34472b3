!> Error state passed back to the caller (mctc-lib style).
!>
!> A procedure that can fail takes `type(error_type), allocatable, intent(out) :: error`
!> as its last argument. Unallocated on return means success. Only the main program stops.
module pound_error
   implicit none
   private

   public :: error_type, fatal_error

   !> A failure, described in one message for the user.
   type :: error_type
      !> What failed and where.
      character(len=:), allocatable :: message
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

end module pound_error
