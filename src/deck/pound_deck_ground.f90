!> Reader of `&ground`: a pulse, or a record file resolved relative to the deck.
module pound_deck_ground
   use pound_config, only: ground_config
   use pound_deck_checks, only: check_real, fail, is_set, read_failed, require_real, site, site_of, &
                                unset_real
   use pound_deck_lexer, only: group_ref, group_text, lower
   use pound_deck_variables, only: path_len, word_len
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: read_ground

contains

   !> `&ground`: a pulse or a record file.
   subroutine read_ground(path, text, g, cfg, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Resolved `&ground`.
      type(ground_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=word_len) :: kind, format
      character(len=path_len) :: file
      real(dp) :: x0, a, b, scale
      integer :: ios
      logical :: exists
      character(len=:), allocatable :: buf
      character(len=:), allocatable :: resolved
      character(len=512) :: msg
      type(site) :: at
      namelist /ground/ kind, x0, a, b, file, format, scale

      kind = ' '
      format = ' '
      file = ' '
      x0 = unset_real
      a = unset_real
      b = unset_real
      scale = unset_real
      at = site_of(path, g)
      call group_text(text, g, buf)
      msg = ' '
      read (buf, nml=ground, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      cfg%kind = lower(trim(adjustl(kind)))
      select case (cfg%kind)
      case ('')
         call fail(at, 'kind', "kind is missing, must be 'pulse' or 'record'", error)
      case ('pulse')
         if (len_trim(file) > 0) then
            call fail(at, 'file', "file applies only to kind = 'record'", error)
         else if (len_trim(format) > 0) then
            call fail(at, 'format', "format applies only to kind = 'record'", error)
         else if (is_set(scale)) then
            call fail(at, 'scale', "scale applies only to kind = 'record'", error)
         end if
         if (allocated(error)) return
         call require_real(at, 'x0', x0, 'pulse amplitude in m', error)
         if (allocated(error)) return
         call check_real(at, 'x0', x0, '/=', 0.0_dp, error)
         if (allocated(error)) return
         call require_real(at, 'a', a, 'pulse decay in 1/s', error)
         if (allocated(error)) return
         call check_real(at, 'a', a, '>=', 0.0_dp, error)
         if (allocated(error)) return
         call require_real(at, 'b', b, 'pulse circular frequency in rad/s', error)
         if (allocated(error)) return
         call check_real(at, 'b', b, '>', 0.0_dp, error)
         if (allocated(error)) return
         cfg%x0 = x0
         cfg%a = a
         cfg%b = b
         cfg%file = ''
         cfg%format = ''
      case ('record')
         if (is_set(x0)) then
            call fail(at, 'x0', "x0 applies only to kind = 'pulse'", error)
         else if (is_set(a)) then
            call fail(at, 'a', "a applies only to kind = 'pulse'", error)
         else if (is_set(b)) then
            call fail(at, 'b', "b applies only to kind = 'pulse'", error)
         end if
         if (allocated(error)) return
         if (len_trim(file) == 0) then
            call fail(at, 'file', 'file is missing (record file, relative to the deck''s '// &
                      'directory unless absolute)', error)
            return
         end if
         if (len_trim(file) == len(file)) then
            call fail(at, 'file', 'file is longer than '//str(len(file) - 1)//' characters', error)
            return
         end if
         resolved = resolve_path(path, trim(adjustl(file)))
         inquire (file=resolved, exist=exists)
         if (.not. exists) then
            call fail(at, 'file', "file = '"//trim(adjustl(file))//"': record file '"// &
                      resolved//"' does not exist", error)
            return
         end if
         cfg%file = resolved
         cfg%format = lower(trim(adjustl(format)))
         if (len(cfg%format) == 0) cfg%format = 'auto'
         select case (cfg%format)
         case ('auto', 'at2', 'columns')
         case default
            call fail(at, 'format', "format = '"//trim(adjustl(format))//"', must be 'auto', "// &
                      "'at2' or 'columns'", error)
            return
         end select
         if (.not. is_set(scale)) scale = 1.0_dp
         call check_real(at, 'scale', scale, '/=', 0.0_dp, error)
         if (allocated(error)) return
         cfg%scale = scale
      case default
         call fail(at, 'kind', "kind = '"//trim(adjustl(kind))//"', must be 'pulse' or 'record'", error)
      end select
   end subroutine read_ground

   !> `file` as given if absolute, else relative to the directory of the deck `deck_path`.
   pure function resolve_path(deck_path, file) result(resolved)
      !> Deck path and record file as given.
      character(len=*), intent(in) :: deck_path, file
      character(len=:), allocatable :: resolved
      integer :: slash

      slash = index(deck_path, '/', back=.true.)
      if (file(1:1) == '/' .or. slash == 0) then
         resolved = file
      else
         resolved = deck_path(1:slash)//file
      end if
   end function resolve_path

end module pound_deck_ground
