!> The MPI case scheduler (`-DPOUND_MPI=ON`): dynamic self-scheduling over the ranks of
!> MPI_COMM_WORLD, every rank (rank 0 included) computing cases.
!>
!> The next case index comes from one 64-bit counter in a window on rank 0, taken with
!> `MPI_Fetch_and_op` (MPI_SUM of 1) under a shared lock: a rank asks for a case when it has
!> finished the last one, so fast and slow cases even out, and nobody waits for a master.
!> The counter is never reset: every `run_cases` of n cases raises it by exactly n + ranks
!> (each rank takes one index past the end and stops), so every rank knows where the next
!> call starts without a barrier. The columns are then gathered to every rank
!> (`MPI_Allgatherv` of the case indices, the columns, the failure flags, times, steps and
!> messages) and placed by case index. Rank 0 adds the runs the other ranks made to its progress line.
submodule(pound_cases) pound_cases_mpi
   use, intrinsic :: iso_c_binding, only: c_ptr
   use, intrinsic :: iso_fortran_env, only: int64
   use mpi_f08
   use pound_progress, only: progress_ended, progress_runs_elsewhere
   implicit none

   !> This rank and the number of ranks.
   integer, save :: my_rank = 0, n_ranks = 1
   !> The window holding the counter (on rank 0), and the counter's value at the start of the
   !> next `run_cases`.
   type(MPI_Win), save :: window
   integer(int64), save :: base = 0
   !> Whether MPI was started here, and whether a `run_cases` is under way (nested calls run
   !> their cases in order on the calling rank).
   logical, save :: started = .false., busy = .false.

contains

   module subroutine cases_start()
      type(c_ptr) :: memory
      integer(MPI_ADDRESS_KIND) :: bytes
      integer(int64) :: zero(1)

      call MPI_Init()
      started = .true.
      call MPI_Comm_rank(MPI_COMM_WORLD, my_rank)
      call MPI_Comm_size(MPI_COMM_WORLD, n_ranks)
      if (n_ranks == 1) return
      bytes = 0
      if (my_rank == 0) bytes = 8
      call MPI_Win_allocate(bytes, 8, MPI_INFO_NULL, MPI_COMM_WORLD, memory, window)
      if (my_rank == 0) then
         zero = 0
         call MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window)
         call MPI_Put(zero, 1, MPI_INTEGER8, 0, 0_MPI_ADDRESS_KIND, 1, MPI_INTEGER8, window)
         call MPI_Win_unlock(0, window)
      end if
      call MPI_Barrier(MPI_COMM_WORLD)
   end subroutine cases_start

   module subroutine cases_stop()
      if (.not. started) return
      if (n_ranks > 1) call MPI_Win_free(window)
      call MPI_Finalize()
      started = .false.
   end subroutine cases_stop

   module subroutine cases_abort(status)
      integer, intent(in) :: status

      if (started .and. n_ranks > 1) call MPI_Abort(MPI_COMM_WORLD, status)
   end subroutine cases_abort

   module integer function cases_rank()
      cases_rank = my_rank
   end function cases_rank

   module integer function cases_ranks()
      cases_ranks = n_ranks
   end function cases_ranks

   module logical function cases_all(flag)
      logical, intent(in) :: flag

      cases_all = flag
      if (n_ranks == 1) return
      call MPI_Allreduce(flag, cases_all, 1, MPI_LOGICAL, MPI_LAND, MPI_COMM_WORLD)
   end function cases_all

   recursive module subroutine run_cases(work, n, width, table)
      class(case_work), intent(inout) :: work
      integer, intent(in) :: n, width
      type(case_table), intent(out) :: table
      type(case_table) :: mine
      integer, allocatable :: index(:), runs(:), counts(:), displs(:), all_index(:), all_runs(:)
      integer, allocatable :: flags(:), all_flags(:), all_step(:)
      real(dp), allocatable :: columns(:, :), all_time(:)
      character(len=case_message_len), allocatable :: messages(:)
      integer :: n_mine, i, k, total, before, elsewhere

      if (busy .or. n_ranks == 1) then
         call run_in_order(work, n, width, table)
         return
      end if
      busy = .true.
      call table_init(mine, n, width)
      allocate (index(n), runs(n))
      n_mine = 0
      do
         i = next_case()
         if (i > n) exit
         n_mine = n_mine + 1
         index(n_mine) = i
         before = progress_ended()
         call compute_into(work, i, mine, n_mine)
         runs(n_mine) = progress_ended() - before
      end do
      base = base + n + n_ranks
      busy = .false.

      ! Every rank's columns to every rank, placed by case index.
      allocate (counts(n_ranks), displs(n_ranks))
      call MPI_Allgather(n_mine, 1, MPI_INTEGER, counts, 1, MPI_INTEGER, MPI_COMM_WORLD)
      total = sum(counts)
      displs = [(sum(counts(1:k - 1)), k=1, n_ranks)]
      allocate (all_index(total), all_runs(total), all_flags(total), columns(width, total), messages(total), &
                all_time(total), all_step(total))
      flags = merge(1, 0, mine%failed(1:n_mine))
      call MPI_Allgatherv(index, n_mine, MPI_INTEGER, all_index, counts, displs, MPI_INTEGER, MPI_COMM_WORLD)
      call MPI_Allgatherv(runs, n_mine, MPI_INTEGER, all_runs, counts, displs, MPI_INTEGER, MPI_COMM_WORLD)
      call MPI_Allgatherv(flags, n_mine, MPI_INTEGER, all_flags, counts, displs, MPI_INTEGER, MPI_COMM_WORLD)
      call MPI_Allgatherv(mine%values, n_mine*width, MPI_DOUBLE_PRECISION, columns, counts*width, &
                          displs*width, MPI_DOUBLE_PRECISION, MPI_COMM_WORLD)
      call MPI_Allgatherv(mine%time, n_mine, MPI_DOUBLE_PRECISION, all_time, counts, displs, MPI_DOUBLE_PRECISION, &
                          MPI_COMM_WORLD)
      call MPI_Allgatherv(mine%step, n_mine, MPI_INTEGER, all_step, counts, displs, MPI_INTEGER, MPI_COMM_WORLD)
      call MPI_Allgatherv(mine%message, n_mine*case_message_len, MPI_CHARACTER, messages, &
                          counts*case_message_len, displs*case_message_len, MPI_CHARACTER, MPI_COMM_WORLD)
      call table_init(table, n, width)
      do k = 1, total
         table%values(:, all_index(k)) = columns(:, k)
         table%failed(all_index(k)) = all_flags(k) /= 0
         table%message(all_index(k)) = messages(k)
         table%time(all_index(k)) = all_time(k)
         table%step(all_index(k)) = all_step(k)
      end do
      if (my_rank == 0) then
         elsewhere = sum(all_runs) - sum(runs(1:n_mine))
         call progress_runs_elsewhere(elsewhere)
      end if
   end subroutine run_cases

   !> The next case index of this `run_cases` (1-based; beyond n: none left).
   integer function next_case()
      integer(int64) :: one(1), old(1)

      one = 1
      call MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, window)
      call MPI_Fetch_and_op(one, old, MPI_INTEGER8, 0, 0_MPI_ADDRESS_KIND, MPI_SUM, window)
      call MPI_Win_unlock(0, window)
      next_case = int(old(1) - base) + 1
   end function next_case

end submodule pound_cases_mpi
