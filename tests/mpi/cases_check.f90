!> The MPI case scheduler on synthetic cases, run under mpirun: every rank checks that its
!> table holds every case's column by index, the failed case marked with its message, a
!> nested `run_cases` computed on the calling rank, and that consecutive calls (n = 7, 0, 1,
!> 5) each start afresh. Rank 0 prints "cases: ok, N ranks"; any mismatch stops the rank
!> with status 1.
program cases_check
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_cases, only: case_table, run_cases, first_failure, cases_start, cases_stop, cases_rank, cases_ranks, &
                          cases_all
   use cases_check_work, only: square_cases
   implicit none

   type(square_cases) :: work
   type(case_table) :: table
   type(error_type), allocatable :: error
   character(len=16) :: names(7)
   integer :: i, n, round
   logical :: ok
   integer, parameter :: sizes(4) = [7, 0, 1, 5]

   call cases_start()
   ok = .true.
   do round = 1, size(sizes)
      n = sizes(round)
      work%fail = merge(3, 0, round == 1)
      work%nest = merge(5, 0, round == 1)
      call run_cases(work, n, 3, table)
      ok = ok .and. size(table%failed) == n .and. all(shape(table%values) == [3, n])
      do i = 1, n
         if (i == work%fail) then
            ok = ok .and. table%failed(i) .and. trim(table%message(i)) == 'no solution at case 3'
            ok = ok .and. all(table%values(:, i) == 0.0_dp)
         else if (i == work%nest) then
            ok = ok .and. .not. table%failed(i)
            ok = ok .and. all(table%values(:, i) == [10.0_dp, 30.0_dp, sum(sqrt([1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp]))])
         else
            ok = ok .and. .not. table%failed(i)
            ok = ok .and. all(table%values(:, i) == [real(i, dp), real(i, dp)**2, sqrt(real(i, dp))])
         end if
      end do
      if (round == 1) then
         do i = 1, 7
            write (names(i), '(a,i0)') 'case ', i
         end do
         call first_failure(table, names, error)
         ok = ok .and. allocated(error)
         if (allocated(error)) ok = ok .and. error%message == 'case 3: no solution at case 3'
      end if
   end do
   ok = cases_all(ok)
   if (ok .and. cases_rank() == 0) write (*, '(a,i0,a)') 'cases: ok, ', cases_ranks(), ' ranks'
   if (.not. ok) write (*, '(a,i0)') 'cases: MISMATCH on rank ', cases_rank()
   call cases_stop()
   if (.not. ok) error stop 1
end program cases_check
