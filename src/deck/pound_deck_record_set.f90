!> `&ground kind = 'record_set'`: a folder of records as one group. Each file of the folder
!> that matches the pattern (pound_folder: shell-style, letters without regard to case) becomes
!> one motion of kind 'record', named by its file stem, in sorted order, with the group's
!> format, scale and scaling. The other `&ground` groups keep their place: the suite holds
!> every motion of every group, in deck order.
module pound_deck_record_set
   use pound_config, only: ground_config
   use pound_deck_checks, only: fail, site_of
   use pound_deck_lexer, only: group_ref
   use pound_error, only: error_type, fatal_error, status_input
   use pound_folder, only: folder_files
   use pound_strings, only: str
   implicit none
   private

   public :: expand_record_sets, file_stem

contains

   !> Every record set of `motions` (motion k read from `groups(k)`) replaced by its files' motions;
   !> an error names the group when its folder cannot be read or no file matches, and when two
   !> motions of the suite end up with the same name.
   subroutine expand_record_sets(path, groups, motions, error)
      !> Deck path as given.
      character(len=*), intent(in) :: path
      !> The `&ground` group of each motion.
      type(group_ref), intent(in) :: groups(:)
      !> The motions (expanded on return).
      type(ground_config), allocatable, intent(inout) :: motions(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      type(ground_config), allocatable :: out(:)
      integer, allocatable :: origin(:)
      character(len=:), allocatable :: message
      character(len=256), allocatable :: names(:)
      integer :: k, j, n, i

      if (.not. any([(motions(k)%kind == 'record_set', k=1, size(motions))])) return
      allocate (out(0), origin(0))
      do k = 1, size(motions)
         if (motions(k)%kind /= 'record_set') then
            out = [out, motions(k)]
            origin = [origin, k]
            cycle
         end if
         call folder_files(motions(k)%folder, motions(k)%pattern, names, error)
         if (allocated(error)) then
            message = error%message
            call fail(site_of(path, groups(k)), 'folder', message, error)
            return
         end if
         if (size(names) == 0) then
            call fail(site_of(path, groups(k)), 'pattern', "no file of folder '"//motions(k)%folder// &
                      "' matches pattern = '"//motions(k)%pattern//"'", error)
            return
         end if
         do j = 1, size(names)
            block
               type(ground_config) :: m

               m = motions(k)
               m%kind = 'record'
               m%file = trim(motions(k)%folder)//'/'//trim(names(j))
               m%name = file_stem(trim(names(j)))
               deallocate (m%folder, m%pattern)
               out = [out, m]
               origin = [origin, k]
            end block
         end do
      end do
      n = size(out)
      do i = 2, n
         do j = 1, i - 1
            if (out(i)%name == out(j)%name) then
               call fatal_error(error, path//':'//str(groups(origin(i))%line1)//': &ground #'// &
                                str(groups(origin(i))%occurrence)//": motion '"//out(i)%name// &
                                "' (of a record set: named by its file stem) is already the name of a motion of "// &
                                '&ground #'//str(groups(origin(j))%occurrence)//'; the motions of a suite need '// &
                                'distinct names', status_input)
               return
            end if
         end do
      end do
      call move_alloc(out, motions)
   end subroutine expand_record_sets

   !> The file name without its last extension ('FF01_1.AT2' -> 'FF01_1'; a leading dot kept).
   pure function file_stem(name) result(stem)
      !> File name (no folder).
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: stem
      integer :: dot

      dot = index(name, '.', back=.true.)
      if (dot > 1) then
         stem = name(1:dot - 1)
      else
         stem = name
      end if
   end function file_stem

end module pound_deck_record_set
