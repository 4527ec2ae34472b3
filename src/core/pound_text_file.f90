!> Whole input files read into memory (decks, accelerograms).
module pound_text_file
   use, intrinsic :: iso_fortran_env, only: iostat_end
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   implicit none
   private

   public :: read_whole_file

contains

   !> The whole file as one string, read with stream access so that any line ending
   !> (LF, CRLF, CR CR LF) and a missing final newline survive for the caller to handle.
   !>
   !> A regular file is read in one piece, sized first. A file whose size is not known in
   !> advance (a pipe: `pound /dev/stdin < deck`, `<(sed ...)`; files under /proc) is read
   !> until its end. The memory used is the file's size (plus growth by doubling for pipes);
   !> an allocation that fails ends in a message naming the file and the size.
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
      integer :: u, ios, nbytes, stat
      character(len=512) :: msg

      inquire (file=path, exist=exists)
      if (.not. exists) then
         call fatal_error(error, path//': cannot open the '//what//': file not found')
         return
      end if
      msg = ' '
      open (newunit=u, file=path, access='stream', form='unformatted', action='read', &
            status='old', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call fatal_error(error, path//': cannot open the '//what//': '//trim(msg))
         return
      end if
      inquire (unit=u, size=nbytes)
      if (nbytes <= 0) then
         ! Size unknown (pipe) or zero: read until the end of the file.
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
      if (ios /= 0) call fatal_error(error, path//': cannot read the '//what//': '//trim(msg))
   end subroutine read_whole_file

   !> Read the open stream unit `u` byte by byte until its end (works on pipes).
   subroutine read_until_end(u, path, what, buf, error)
      !> Unit opened for stream access.
      integer, intent(in) :: u
      !> File name and what it is, for messages.
      character(len=*), intent(in) :: path, what
      !> The file's bytes.
      character(len=:), allocatable, intent(out) :: buf
      !> Error state: the file cannot be read, or the memory for it cannot be had.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: grown
      character :: c
      integer :: n, ios, stat
      character(len=512) :: msg

      allocate (character(len=4096) :: buf)
      n = 0
      do
         msg = ' '
         read (u, iostat=ios, iomsg=msg) c
         if (ios == iostat_end) exit
         if (ios /= 0) then
            call fatal_error(error, path//': cannot read the '//what//': '//trim(msg))
            return
         end if
         if (n == len(buf)) then
            if (n > huge(n)/2) then
               call fatal_error(error, path//': the '//what//' is larger than '//str(n)//' bytes')
               return
            end if
            allocate (character(len=2*n) :: grown, stat=stat)
            if (stat /= 0) then
               call fatal_error(error, path//': cannot allocate '//str(2*n)//' bytes to read the '//what)
               return
            end if
            grown(1:n) = buf
            call move_alloc(grown, buf)
         end if
         n = n + 1
         buf(n:n) = c
      end do
      buf = buf(1:n)
   end subroutine read_until_end

end module pound_text_file
