!> A text file being written (the listing, the summary CSV): its unit, its file and the first
!> write failure.
!>
!> A writer writes with `iostat=w%ios, iomsg=w%msg` and then calls `w%note()`, which keeps the
!> first failure (no space left, file too large, ...); the listing's writers (`pound_listing`,
!> `pound_suite_output`, `pound_suite_columns_output`) take the writer and never return an
!> error of their own. The caller asks once, in `close_text`, which also checks that every
!> byte reached the file. Messages: 'cannot write the <what> <path>: <reason>'.
module pound_text_writer
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_error, only: error_type, fatal_error, status_io
   use pound_posix, only: posix_set_errno, posix_storage_error
   implicit none
   private

   public :: text_writer, open_text, close_text

   !> An open text file and the first failed write since it was opened.
   type :: text_writer
      !> Unit (formatted stream), opened by `open_text`.
      integer :: unit = -1
      !> The file, for messages.
      character(len=:), allocatable :: path
      !> What the file is, for messages ('listing', 'summary').
      character(len=:), allocatable :: what
      !> Status of the last write (`iostat=w%ios`).
      integer :: ios = 0
      !> Message of the last write (`iomsg=w%msg`).
      character(len=256) :: msg = ''
      !> Status of the first failed write (0: none).
      integer :: first_ios = 0
      !> Message of the first failed write.
      character(len=256) :: first_msg = ''
   contains
      !> Keep the last write's failure if it is the first.
      procedure :: note => writer_note
      !> Write one line (`text`) and keep its failure (`note`).
      procedure :: put => writer_put
      !> The first failure, as an error naming the file (unallocated if none).
      procedure :: io_error => writer_io_error
   end type text_writer

contains

   !> Keep the last write's failure (`ios`, `msg`) if it is the first.
   subroutine writer_note(w)
      !> The writer.
      class(text_writer), intent(inout) :: w

      if (w%ios /= 0 .and. w%first_ios == 0) then
         w%first_ios = w%ios
         w%first_msg = w%msg
      end if
   end subroutine writer_note

   !> Write one line and keep its failure if it is the first.
   subroutine writer_put(w, text)
      !> The writer.
      class(text_writer), intent(inout) :: w
      !> The line.
      character(len=*), intent(in) :: text

      write (w%unit, '(a)', iostat=w%ios, iomsg=w%msg) text
      call w%note()
   end subroutine writer_put

   !> The first write failure (unallocated if none), naming the file.
   subroutine writer_io_error(w, error)
      !> The writer.
      class(text_writer), intent(in) :: w
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      if (w%first_ios /= 0) call fatal_error(error, failure_text(w, trim(w%first_msg)), status_io)
   end subroutine writer_io_error

   !> Open `path` (created, or emptied), as a formatted stream so that `close_text` can check
   !> that every byte reached the file.
   subroutine open_text(path, what, w, error)
      !> File.
      character(len=*), intent(in) :: path
      !> What the file is, for messages ('listing', 'summary').
      character(len=*), intent(in) :: what
      !> The writer, opened on `path` with no failure kept.
      type(text_writer), intent(out) :: w
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      character(len=7) :: status
      integer(int64) :: bytes

      w%path = path
      w%what = what
      ! An empty file there (the run's temporary, reserved empty) is opened as it is: ext4
      ! writes a file truncated to empty back when it is closed (auto_da_alloc), in the process.
      status = 'replace'
      inquire (file=path, size=bytes, iostat=w%ios)
      if (w%ios == 0 .and. bytes == 0) status = 'old'
      call posix_set_errno(0)
      open (newunit=w%unit, file=path, status=status, action='write', access='stream', form='formatted', &
            iostat=w%ios, iomsg=w%msg)
      if (w%ios /= 0) call fatal_error(error, failure_text(w, trim(w%msg)), status_io)
   end subroutine open_text

   !> Close the file and check it: a failed write, or a file shorter than what was written
   !> (the Fortran run-time can drop a buffer the system refused: no space, file too large),
   !> is an error naming the system's reason.
   subroutine close_text(w, error)
      !> The writer of `open_text`.
      type(text_writer), intent(inout) :: w
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      integer(int64) :: written, size_on_disk
      character(len=:), allocatable :: reason
      character(len=80) :: counts

      call w%io_error(error)
      inquire (unit=w%unit, pos=written, iostat=stat)
      if (stat /= 0) written = -1
      close (w%unit, iostat=w%ios, iomsg=w%msg)
      if (allocated(error)) return
      if (w%ios /= 0) then
         call fatal_error(error, failure_text(w, trim(w%msg)), status_io)
         return
      end if
      inquire (file=w%path, size=size_on_disk, iostat=stat)
      if (stat /= 0 .or. written < 1 .or. size_on_disk /= written - 1) then
         reason = posix_storage_error()
         if (len(reason) == 0) reason = 'the file system did not take every byte'
         write (counts, '(a,i0,a,i0,a)') ' (the file holds ', size_on_disk, ' of ', written - 1, ' bytes)'
         call fatal_error(error, failure_text(w, reason//trim(counts)), status_io)
      end if
   end subroutine close_text

   !> 'cannot write the <what> <path>: <reason>'.
   pure function failure_text(w, reason) result(text)
      !> The writer.
      type(text_writer), intent(in) :: w
      !> The system's reason.
      character(len=*), intent(in) :: reason
      character(len=:), allocatable :: text

      text = 'cannot write the '//w%what//' '//w%path//': '//reason
   end function failure_text

end module pound_text_writer
