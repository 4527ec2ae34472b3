!> The case scheduler: independent cases (the gaps of a sweep, the motions of a suite at one
!> gap, the motions' threshold refinements) computed into a table, one column per case.
!>
!> A caller describes its cases by extending `case_work` (the data the cases share, and
!> `compute`: case i into a column of `width` reals) and calls `run_cases`, which fills a
!> `case_table` on every process, placed by case index. Two implementations give the same
!> interface (submodules; CMake compiles one):
!>
!> * `pound_cases_serial` (the default build): the cases in order, one after the other;
!> * `pound_cases_mpi` (`-DPOUND_MPI=ON`): the cases shared over the MPI ranks by dynamic
!>   self-scheduling (every rank, rank 0 included, takes the next case index from a counter
!>   on rank 0 by `MPI_Fetch_and_op` when it is done), then every column gathered to every
!>   rank (`MPI_Allgatherv`), so that all ranks go on with the same table.
!>
!> Each case is computed exactly as in the serial loop and placed by its index, so the table
!> does not depend on the number of ranks or on the order the cases finish in. A case that
!> fails is marked (`failed`, `message`) and the others go on. A `run_cases` called from
!> inside a case (a suite motion's sweep) runs its cases in order on the calling rank (no
!> nesting of the scheduler; the procedures are recursive for it).
module pound_cases
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   implicit none
   private

   public :: case_work, case_table, run_cases, first_failure, case_message_len
   public :: cases_start, cases_stop, cases_abort, cases_rank, cases_ranks, cases_all
   public :: text_to_column, column_to_text
   ! For the implementations (submodules):
   public :: run_in_order, table_init, compute_into

   !> Characters kept of a failed case's message.
   integer, parameter :: case_message_len = 512

   !> The cases of one `run_cases`: what they share, and how case i is computed.
   type, abstract :: case_work
   contains
      !> Compute case i into its column.
      procedure(case_compute), deferred :: compute
   end type case_work

   abstract interface
      !> Case `i` of the work: its `values` (the column of the table), or an error.
      recursive subroutine case_compute(work, i, values, error)
         import :: case_work, dp, error_type
         !> The cases (may keep caches between cases of one rank).
         class(case_work), intent(inout) :: work
         !> Case index, 1..n.
         integer, intent(in) :: i
         !> The case's column (`width` reals).
         real(dp), intent(out) :: values(:)
         !> Error state: the case failed.
         type(error_type), allocatable, intent(out) :: error
      end subroutine case_compute
   end interface

   !> Every case's column, whether it failed, its message and where it failed (the same on
   !> every rank).
   type :: case_table
      !> Columns, (width, n): column i is case i's values (0 when it failed).
      real(dp), allocatable :: values(:, :)
      !> Whether case i failed.
      logical, allocatable :: failed(:)
      !> The message of a failed case (blank otherwise).
      character(len=case_message_len), allocatable :: message(:)
      !> Time (s) and step at which a failed case's integration failed (`error_type`'s; -1: not
      !> known, or not failed).
      real(dp), allocatable :: time(:)
      integer, allocatable :: step(:)
   end type case_table

   interface
      !> Start the processes' communication (MPI_Init); nothing in the serial build.
      module subroutine cases_start()
      end subroutine cases_start

      !> End it (MPI_Finalize); nothing in the serial build. Call once, before exiting.
      module subroutine cases_stop()
      end subroutine cases_stop

      !> End every rank of the job with `status` (MPI_Abort), for an error that may be this
      !> rank's alone (a file rank 0 cannot write): the others must not wait for it. Nothing
      !> in the serial build, nor with one rank.
      module subroutine cases_abort(status)
         !> Exit status.
         integer, intent(in) :: status
      end subroutine cases_abort

      !> This process' rank, 0-based (0 in the serial build): rank 0 writes the outputs.
      module integer function cases_rank()
      end function cases_rank

      !> Number of ranks (1 in the serial build).
      module integer function cases_ranks()
      end function cases_ranks

      !> Whether `flag` holds on every rank (collective; `flag` itself in the serial build).
      module logical function cases_all(flag)
         !> This rank's value.
         logical, intent(in) :: flag
      end function cases_all

      !> Compute cases 1..n of `work` into `table` (collective: every rank calls it with the
      !> same n and width, and every rank gets the whole table).
      recursive module subroutine run_cases(work, n, width, table)
         !> The cases.
         class(case_work), intent(inout) :: work
         !> Number of cases (>= 0) and reals per case (>= 1).
         integer, intent(in) :: n, width
         !> Every case's column, by case index.
         type(case_table), intent(out) :: table
      end subroutine run_cases
   end interface

contains

   !> Cases 1..n of `work` in order on this process, into a new table.
   recursive subroutine run_in_order(work, n, width, table)
      !> The cases.
      class(case_work), intent(inout) :: work
      !> Number of cases and reals per case.
      integer, intent(in) :: n, width
      !> Every case's column.
      type(case_table), intent(out) :: table
      integer :: i

      call table_init(table, n, width)
      do i = 1, n
         call compute_into(work, i, table, i)
      end do
   end subroutine run_in_order

   !> An empty table of n cases of `width` reals.
   subroutine table_init(table, n, width)
      !> The table.
      type(case_table), intent(out) :: table
      !> Number of cases and reals per case.
      integer, intent(in) :: n, width

      allocate (table%values(width, n), table%failed(n), table%message(n), table%time(n), table%step(n))
      table%values = 0.0_dp
      table%failed = .false.
      table%message = ''
      table%time = -1.0_dp
      table%step = -1
   end subroutine table_init

   !> Case i of `work` into column j of `table` (a failed case: zeros, its message).
   recursive subroutine compute_into(work, i, table, j)
      !> The cases.
      class(case_work), intent(inout) :: work
      !> Case index.
      integer, intent(in) :: i
      !> The table.
      type(case_table), intent(inout) :: table
      !> Column.
      integer, intent(in) :: j
      type(error_type), allocatable :: error

      call work%compute(i, table%values(:, j), error)
      if (allocated(error)) then
         table%failed(j) = .true.
         table%message(j) = error%message
         table%time(j) = error%time
         table%step(j) = error%step
         table%values(:, j) = 0.0_dp
      end if
   end subroutine compute_into

   !> `text` into a column's reals: its length, then one character code each (cut to fit).
   pure subroutine text_to_column(text, values)
      !> The text.
      character(len=*), intent(in) :: text
      !> Length and codes; size >= 1.
      real(dp), intent(out) :: values(:)
      integer :: i, n

      n = min(len(text), size(values) - 1)
      values = 0.0_dp
      values(1) = real(n, dp)
      do i = 1, n
         values(1 + i) = real(ichar(text(i:i)), dp)
      end do
   end subroutine text_to_column

   !> The text `text_to_column` stored in `values`.
   pure function column_to_text(values) result(text)
      !> Length and codes.
      real(dp), intent(in) :: values(:)
      character(len=:), allocatable :: text
      integer :: i, n

      n = nint(values(1))
      allocate (character(len=n) :: text)
      do i = 1, n
         text(i:i) = achar(nint(values(1 + i)))
      end do
   end function column_to_text

   !> An error for the failed cases of `table`, if any: the first one's message (after its
   !> name and ': ', unless the name is blank), and how many others failed; its case index,
   !> time and step.
   subroutine first_failure(table, names, error)
      !> The cases' table.
      type(case_table), intent(in) :: table
      !> One name per case (e.g. 'gap sweep, gap = 0.01 m'), put before its message.
      character(len=*), intent(in) :: names(:)
      !> Error state: set when a case failed.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      integer :: i, n_failed

      n_failed = count(table%failed)
      if (n_failed == 0) return
      i = findloc(table%failed, .true., 1)
      text = trim(table%message(i))
      if (len_trim(names(i)) > 0) text = trim(names(i))//': '//text
      if (n_failed > 1) text = text//' (and '//str(n_failed - 1)//' more of '//str(size(table%failed))//' failed)'
      call fatal_error(error, text)
      error%case = i
      error%time = table%time(i)
      error%step = table%step(i)
   end subroutine first_failure

end module pound_cases
