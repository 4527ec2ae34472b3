!> Whole input files read into memory (decks, accelerograms).
module pound_text_file
   use, intrinsic :: iso_fortran_env, only: iostat_end, iostat_eor, int64
   use pound_error, only: error_type, fatal_error, status_input, status_io
   use pound_strings, only: str
   implicit none
   private

   public :: read_whole_file

   !> Largest file read whose size is not known in advance (pipes, devices): 256 MiB.
   integer, parameter, public :: max_unsized_bytes = 268435456

contains

   !> The whole file as one string, read with stream access so that any line ending
   !> (LF, CRLF, CR CR LF) and a missing final newline survive for the caller to handle.
   !>
   !> A regular file is read in one piece, sized first. A file whose size is not known in
   !> advance (a pipe: `pound /dev/stdin < deck`, `<(sed ...)`; files under /proc) is read
   !> line by line until its end (CR LF arrives as LF, and a final line end is added), up to
   !> `max_unsized_bytes`. The memory used is proportional to the file; an allocation that
   !> fails ends in a message naming the file and the size.
   subroutine read_whole_file(path, what, buf, error)
      !> File to read.
      character(len=*), intent(in) :: path
      !> What the file is, for messages (e.g. 'deck', 'accelerogram file').
      character(len=*), intent(in) :: what
      !> The file's bytes.
      character(len=:), allocatable, intent(out) :: buf
      !> Error state: the file is missing, cannot be opened, sized or read.
      type(error_type), allocatable, intent(out) :: error
      logical :: exists
      integer :: u, ios, stat
      integer(int64) :: nbytes
      character(len=512) :: msg

      inquire (file=path, exist=exists, size=nbytes)
      if (.not. exists) then
         call fatal_error(error, path//': cannot open the '//what//': file not found', status_io)
         return
      end if
      if (nbytes > huge(1)) then
         call fatal_error(error, path//': the '//what//' has '//str(nbytes)//' bytes, more than '// &
                          'the '//str(huge(1))//' pound reads', status_input)
         return
      end if
      msg = ' '
      if (nbytes <= 0) then
         ! Size unknown (pipe, /proc) or zero: read until the end of the file.
         open (newunit=u, file=path, access='stream', form='formatted', action='read', &
               status='old', iostat=ios, iomsg=msg)
      else
         open (newunit=u, file=path, access='stream', form='unformatted', action='read', &
               status='old', iostat=ios, iomsg=msg)
      end if
      if (ios /= 0) then
         call fatal_error(error, path//': cannot open the '//what//': '//trim(msg), status_io)
         return
      end if
      if (nbytes <= 0) then
         call read_until_end(u, path, what, buf, error)
         close (u)
         return
      end if
      allocate (character(len=nbytes) :: buf, stat=stat)
      if (stat /= 0) then
         close (u)
         call fatal_error(error, path//': cannot allocate '//str(nbytes)//' bytes to read the '//what)
         return
      end if
      ios = 0
      read (u, iostat=ios, iomsg=msg) buf
      close (u)
      if (ios /= 0) call fatal_error(error, path//': cannot read the '//what//': '//trim(msg), status_io)
   end subroutine read_whole_file

   !> Read the unit `u` (formatted stream) line by line until its end (works on pipes).
   subroutine read_until_end(u, path, what, buf, error)
      !> Unit opened for formatted stream access.
      integer, intent(in) :: u
      !> File name and what it is, for messages.
      character(len=*), intent(in) :: path, what
      !> The file's bytes, every line ended by LF.
      character(len=:), allocatable, intent(out) :: buf
      !> Error state: the file cannot be read, is too large, or its memory cannot be had.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: grown
      character(len=65536) :: chunk
      integer :: n, got, ios, stat, need
      character(len=512) :: msg

      allocate (character(len=65536) :: buf)
      n = 0
      do
         msg = ' '
         got = 0
         read (u, '(a)', advance='no', size=got, iostat=ios, iomsg=msg) chunk
         if (ios /= 0 .and. ios /= iostat_eor .and. ios /= iostat_end) then
            call fatal_error(error, path//': cannot read the '//what//': '//trim(msg), status_io)
            return
         end if
         need = n + got
         if (ios == iostat_eor) need = need + 1
         if (need > max_unsized_bytes) then
            call fatal_error(error, path//': the '//what//' read from a pipe or device is larger '// &
                             'than '//str(max_unsized_bytes/1048576)//' MiB; give it as a regular file', status_input)
            return
         end if
         if (need > len(buf)) then
            allocate (character(len=min(2*len(buf), max_unsized_bytes)) :: grown, stat=stat)
            if (stat /= 0) then
               call fatal_error(error, path//': cannot allocate '//str(2*len(buf))// &
                                ' bytes to read the '//what)
               return
            end if
            grown(1:n) = buf(1:n)
            call move_alloc(grown, buf)
         end if
         buf(n + 1:n + got) = chunk(1:got)
         n = n + got
         if (ios == iostat_eor) then
            n = n + 1
            buf(n:n) = achar(10)
         end if
         if (ios == iostat_end) exit
      end do
      buf = buf(1:n)
   end subroutine read_until_end

end module pound_text_file
