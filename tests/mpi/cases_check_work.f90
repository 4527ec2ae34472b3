!> Synthetic cases for the MPI scheduler check (cases_check): case i gives (i, i^2, sqrt(i));
!> case `fail` fails; case `nest` runs a nested `run_cases` and gives the sum of its columns.
module cases_check_work
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_cases, only: case_work, case_table, run_cases
   implicit none
   private

   public :: square_cases

   !> The synthetic cases.
   type, extends(case_work) :: square_cases
      !> The case that fails and the case that nests (0: none).
      integer :: fail = 0, nest = 0
   contains
      procedure :: compute => square_case
   end type square_cases

contains

   !> Case i: (i, i^2, sqrt(i)); an error for `fail`; the sums of 4 nested cases for `nest`.
   recursive subroutine square_case(work, i, values, error)
      !> The cases, the case index, its column and the error state.
      class(square_cases), intent(inout) :: work
      integer, intent(in) :: i
      real(dp), intent(out) :: values(:)
      type(error_type), allocatable, intent(out) :: error
      type(square_cases) :: inner
      type(case_table) :: table

      if (i == work%fail) then
         call fatal_error(error, 'no solution at case '//str(i))
         return
      end if
      if (i == work%nest) then
         call run_cases(inner, 4, size(values), table)
         values = sum(table%values, dim=2)
         return
      end if
      values(1) = real(i, dp)
      values(2) = real(i, dp)**2
      values(3) = sqrt(real(i, dp))
   end subroutine square_case

end module cases_check_work
