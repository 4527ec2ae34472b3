!> The files of a folder that match a shell-style pattern, in sorted order (`&ground kind =
!> 'record_set'`). The folder is read by `posix_directory_names`; the pattern (`*`, `?`,
!> `[...]`, `[!...]`) is matched without regard to case, so that '*.AT2' matches 'x.at2'.
module pound_folder
   use pound_error, only: error_type, fatal_error
   use pound_posix, only: posix_directory_names, posix_strerror
   use pound_strings, only: lower
   implicit none
   private

   public :: folder_files, pattern_matches

   !> Longest file name kept (a longer one cannot match: it is skipped).
   integer, parameter :: name_len = 256

contains

   !> The names (not paths) of the entries of `folder` that match `pattern` (`pattern_matches`),
   !> sorted by byte; '.' and '..' and hidden files ('.' first) only when the pattern starts
   !> with '.'. An error when the folder cannot be read.
   subroutine folder_files(folder, pattern, names, error)
      !> Folder path.
      character(len=*), intent(in) :: folder
      !> Shell-style pattern.
      character(len=*), intent(in) :: pattern
      !> Matching names, sorted.
      character(len=name_len), allocatable, intent(out) :: names(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      character(len=name_len), allocatable :: all(:)
      logical, allocatable :: keep(:)
      integer :: e, k

      call posix_directory_names(folder, all, e)
      if (e /= 0) then
         call fatal_error(error, "folder '"//folder//"' cannot be read: "//posix_strerror(e))
         return
      end if
      allocate (keep(size(all)))
      do k = 1, size(all)
         keep(k) = pattern_matches(pattern, trim(all(k)))
         if (all(k)(1:1) == '.' .and. pattern(1:min(1, len(pattern))) /= '.') keep(k) = .false.
      end do
      names = pack(all, keep)
      call sort_names(names)
   end subroutine folder_files

   !> Names sorted by byte (insertion sort: a folder of records holds tens to hundreds).
   pure subroutine sort_names(names)
      !> The names.
      character(len=*), intent(inout) :: names(:)
      character(len=len(names)) :: t
      integer :: i, j

      do i = 2, size(names)
         t = names(i)
         j = i - 1
         do while (j >= 1)
            if (llt(names(j), t) .or. names(j) == t) exit
            names(j + 1) = names(j)
            j = j - 1
         end do
         names(j + 1) = t
      end do
   end subroutine sort_names

   !> Whether `name` matches the shell-style `pattern` (`*` any run, `?` one character, `[abc]`,
   !> `[a-z]`, `[!abc]` one of a set or not), letters compared without regard to case.
   pure recursive logical function pattern_matches(pattern, name) result(yes)
      !> Pattern and name.
      character(len=*), intent(in) :: pattern, name
      integer :: close, k

      yes = .false.
      if (len(pattern) == 0) then
         yes = len(name) == 0
         return
      end if
      select case (pattern(1:1))
      case ('*')
         do k = 0, len(name)
            if (pattern_matches(pattern(2:), name(k + 1:))) then
               yes = .true.
               return
            end if
         end do
      case ('?')
         if (len(name) > 0) yes = pattern_matches(pattern(2:), name(2:))
      case ('[')
         close = index(pattern(3:), ']') + 2
         if (close == 2 .or. len(name) == 0) then
            if (len(name) > 0) then
               if (lower(name(1:1)) == '[') yes = pattern_matches(pattern(2:), name(2:))
            end if
            return
         end if
         if (in_set(pattern(2:close - 1), name(1:1))) yes = pattern_matches(pattern(close + 1:), name(2:))
      case default
         if (len(name) > 0) then
            if (lower(pattern(1:1)) == lower(name(1:1))) yes = pattern_matches(pattern(2:), name(2:))
         end if
      end select
   end function pattern_matches

   !> Whether character `c` is in the bracket set `set` (without its brackets).
   pure logical function in_set(set, c) result(yes)
      character(len=*), intent(in) :: set
      character, intent(in) :: c
      logical :: negate
      integer :: i, first

      negate = set(1:1) == '!' .or. set(1:1) == '^'
      first = merge(2, 1, negate)
      yes = .false.
      i = first
      do while (i <= len(set))
         if (i + 2 <= len(set) .and. set(i + 1:i + 1) == '-') then
            if (lge(lower(c), lower(set(i:i))) .and. lle(lower(c), lower(set(i + 2:i + 2)))) yes = .true.
            i = i + 3
         else
            if (lower(c) == lower(set(i:i))) yes = .true.
            i = i + 1
         end if
      end do
      if (negate) yes = .not. yes
   end function in_set


end module pound_folder
