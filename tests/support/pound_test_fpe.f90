!> Test helper: let a test provoke overflow and invalid operations on purpose. Debug builds
!> trap them (-ffpe-trap); a test of the checks that catch the results switches the traps
!> off for its duration and restores them at its end.
module pound_test_fpe
   use, intrinsic :: ieee_exceptions, only: ieee_get_halting_mode, ieee_set_halting_mode, &
                                            ieee_overflow, ieee_invalid, ieee_divide_by_zero, &
                                            ieee_set_flag, ieee_flag_type
   implicit none
   private

   public :: fpe_quiet, fpe_restore

   type(ieee_flag_type), parameter :: trapped(3) = [ieee_overflow, ieee_invalid, ieee_divide_by_zero]
   logical, save :: saved(3) = .false.

contains

   !> Stop trapping overflow, invalid and division by zero (remember the modes).
   subroutine fpe_quiet()
      call ieee_get_halting_mode(trapped, saved)
      call ieee_set_halting_mode(trapped, .false.)
   end subroutine fpe_quiet

   !> Clear the flags raised meanwhile and restore the modes of `fpe_quiet`.
   subroutine fpe_restore()
      call ieee_set_flag(trapped, .false.)
      call ieee_set_halting_mode(trapped, saved)
   end subroutine fpe_restore

end module pound_test_fpe
