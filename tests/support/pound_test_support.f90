!> Helpers shared by the test suite: locations from the environment and scratch files.
module pound_test_support
   implicit none
   private

   public :: source_dir, shared_dir, write_text_file

contains

   !> Project source directory (env POUND_SOURCE_DIR, set by CTest), or '.'.
   function source_dir() result(dir)
      character(len=:), allocatable :: dir

      dir = env_or('POUND_SOURCE_DIR', '.')
   end function source_dir

   !> The `shared/` directory beside the project (env POUND_SHARED_DIR), or '../shared'.
   function shared_dir() result(dir)
      character(len=:), allocatable :: dir

      dir = env_or('POUND_SHARED_DIR', '../shared')
   end function shared_dir

   !> Write `lines` (one per element, trailing blanks trimmed) to `path`.
   subroutine write_text_file(path, lines)
      !> File to (over)write.
      character(len=*), intent(in) :: path
      !> Lines of text.
      character(len=*), intent(in) :: lines(:)
      integer :: u, i

      open (newunit=u, file=path, status='replace', action='write')
      do i = 1, size(lines)
         write (u, '(a)') trim(lines(i))
      end do
      close (u)
   end subroutine write_text_file

   function env_or(name, default) result(val)
      character(len=*), intent(in) :: name, default
      character(len=:), allocatable :: val
      integer :: n, stat

      call get_environment_variable(name, length=n, status=stat)
      if (stat /= 0 .or. n == 0) then
         val = default
         return
      end if
      allocate (character(len=n) :: val)
      call get_environment_variable(name, value=val)
   end function env_or

end module pound_test_support
