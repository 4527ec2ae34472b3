!> File helpers for outputs that appear complete or not at all.
!>
!> Outputs are written under a temporary name beside the final one and renamed at the
!> end (rename(2) is atomic within a directory), so an interrupted run never leaves a
!> half-written file that looks complete.
module pound_files
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
   use pound_error, only: error_type, fatal_error
   implicit none
   private

   public :: rename_file, delete_file, file_stem, temporary_name, file_exists, directory_of, join_path

   interface
      function c_rename(old, new) bind(C, name='rename') result(stat)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: stat
      end function c_rename
   end interface

contains

   !> Rename `old` to `new`, replacing `new`.
   subroutine rename_file(old, new, error)
      !> Existing file.
      character(len=*), intent(in) :: old
      !> New name.
      character(len=*), intent(in) :: new
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      if (c_rename(old//c_null_char, new//c_null_char) /= 0) then
         call fatal_error(error, 'cannot rename '//old//' to '//new)
      end if
   end subroutine rename_file

   !> Delete a file if it exists (errors ignored: used on the way out of a failure).
   subroutine delete_file(path)
      !> File to delete.
      character(len=*), intent(in) :: path
      integer :: u, stat

      if (.not. file_exists(path)) return
      open (newunit=u, file=path, status='old', iostat=stat)
      if (stat == 0) close (u, status='delete', iostat=stat)
   end subroutine delete_file

   !> Whether a file exists.
   function file_exists(path) result(exists)
      !> Path to test.
      character(len=*), intent(in) :: path
      logical :: exists

      inquire (file=path, exist=exists)
   end function file_exists

   !> File name without directory and without its last extension: 'in/deck.nml' -> 'deck'.
   pure function file_stem(path) result(stem)
      !> A path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: stem
      integer :: slash, dot

      slash = index(path, '/', back=.true.)
      stem = path(slash + 1:)
      dot = index(stem, '.', back=.true.)
      if (dot > 1) stem = stem(:dot - 1)
   end function file_stem

   !> Directory part of a path ('.' when there is none): 'in/deck.nml' -> 'in'.
   pure function directory_of(path) result(dir)
      !> A path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: slash

      slash = index(path, '/', back=.true.)
      if (slash == 0) then
         dir = '.'
      else if (slash == 1) then
         dir = '/'
      else
         dir = path(:slash - 1)
      end if
   end function directory_of

   !> `dir/name`, or `name` itself when it is absolute.
   pure function join_path(dir, name) result(path)
      !> Directory.
      character(len=*), intent(in) :: dir
      !> File name, relative or absolute.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path

      if (len(name) > 0) then
         if (name(1:1) == '/') then
            path = name
            return
         end if
      end if
      if (dir == '.' .or. len(dir) == 0) then
         path = name
      else if (dir(len(dir):len(dir)) == '/') then
         path = dir//name
      else
         path = dir//'/'//name
      end if
   end function join_path

   !> Temporary name beside `path`: 'dir/x.out' -> 'dir/.x.out.partial'.
   pure function temporary_name(path) result(tmp)
      !> Final path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: tmp
      integer :: slash

      slash = index(path, '/', back=.true.)
      tmp = path(:slash)//'.'//path(slash + 1:)//'.partial'
   end function temporary_name

end module pound_files
