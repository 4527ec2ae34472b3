!> The serial case scheduler (the default build): the cases in order, one after the other,
!> on the one process.
submodule(pound_cases) pound_cases_serial
   implicit none

contains

   module subroutine cases_start()
   end subroutine cases_start

   module subroutine cases_stop()
   end subroutine cases_stop

   module subroutine cases_abort(status)
      integer, intent(in) :: status

      associate (unused => status)
      end associate
   end subroutine cases_abort

   module integer function cases_rank()
      cases_rank = 0
   end function cases_rank

   module integer function cases_ranks()
      cases_ranks = 1
   end function cases_ranks

   module logical function cases_all(flag)
      logical, intent(in) :: flag

      cases_all = flag
   end function cases_all

   recursive module subroutine run_cases(work, n, width, table)
      class(case_work), intent(inout) :: work
      integer, intent(in) :: n, width
      type(case_table), intent(out) :: table

      call run_in_order(work, n, width, table)
   end subroutine run_cases

end submodule pound_cases_serial
