!> Whole input files read into memory (decks, accelerograms).
module pound_text_file
   use pound_error, only: error_type, fatal_error
   implicit none
   private

   public :: read_whole_file

contains

   !> The whole file as one string, read with stream access so that any line ending
   !> (LF, CRLF, CR CR LF) and a missing final newline survive for the caller to handle.
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
      integer :: u, ios, nbytes
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
      if (nbytes < 0) then
         close (u)
         call fatal_error(error, path//': cannot determine the size of the '//what)
         return
      end if
      allocate (character(len=nbytes) :: buf)
      ios = 0
      if (nbytes > 0) read (u, iostat=ios, iomsg=msg) buf
      close (u)
      if (ios /= 0) call fatal_error(error, path//': cannot read the '//what//': '//trim(msg))
   end subroutine read_whole_file

end module pound_text_file
