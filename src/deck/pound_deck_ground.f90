!> Reader of `&ground`: a pulse, a record file resolved relative to the deck, or a synthetic
!> motion (pound_synthetic_motion), each with a name and a scaling for a suite, its direction
!> (`angle`) and, for a record, an optional second horizontal component (`file_2`, `scale_2`).
module pound_deck_ground
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_config, only: ground_config, deck_warning_len
   use pound_constants, only: g_accel
   use pound_deck_checks, only: check_real, fail, group_input, take_real, take_sa_period, is_set, read_failed, &
                                require_real, site, unset_int, unset_real, warn
   use pound_deck_lexer, only: group_ref, lower
   use pound_deck_variables, only: path_len, word_len
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: plain_real, plain_significant, str
   implicit none
   private

   public :: read_ground, resolve_path

   !> A scaling `target` (m/s^2) below this is suspicious (probably given in g): a warning.
   real(dp), parameter, public :: low_target = 0.05_dp
   !> A scaling `target` below this (m/s^2, about 0.2 g) reads as a plausible value in g.
   real(dp), parameter, public :: g_like_target = 2.0_dp

contains

   !> `&ground`: a pulse, a record file, a synthetic motion, or a folder of records
   !> (`kind = 'record_set'`: `folder`, `pattern`; its files become motions in pound_deck_record_set).
   subroutine read_ground(path, text, g, n_motions, cfg, error, warnings)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Number of `&ground` groups in the deck (more than one: a suite, labelled `&ground #k`).
      integer, intent(in) :: n_motions
      !> Resolved `&ground`.
      type(ground_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> The deck's plausibility warnings, this group's appended.
      character(len=deck_warning_len), allocatable, intent(inout) :: warnings(:)
      character(len=word_len) :: kind, format, name, scale_to, filter, envelope
      character(len=path_len) :: file, folder, pattern, file_2
      real(dp) :: x0, a, b, scale, target, target_g, period, angle, scale_2
      real(dp) :: ground_frequency, ground_damping, filter_frequency, filter_damping
      real(dp) :: rise_time, plateau_end, decay_rate, peak_fraction, end_level, duration, pga
      integer :: ios, seed
      logical :: exists, histories
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      namelist /ground/ kind, x0, a, b, file, format, scale, name, scale_to, target, period, &
         filter, ground_frequency, ground_damping, filter_frequency, filter_damping, envelope, &
         rise_time, plateau_end, decay_rate, peak_fraction, end_level, duration, pga, seed, histories, target_g, &
         folder, pattern, angle, file_2, scale_2

      kind = ' '
      format = ' '
      file = ' '
      folder = ' '
      pattern = ' '
      name = ' '
      scale_to = ' '
      filter = ' '
      envelope = ' '
      x0 = unset_real
      a = unset_real
      b = unset_real
      scale = unset_real
      target = unset_real
      target_g = unset_real
      period = unset_real
      ground_frequency = unset_real
      ground_damping = unset_real
      filter_frequency = unset_real
      filter_damping = unset_real
      rise_time = unset_real
      plateau_end = unset_real
      decay_rate = unset_real
      peak_fraction = unset_real
      end_level = unset_real
      duration = unset_real
      pga = unset_real
      seed = unset_int
      histories = .false.
      angle = unset_real
      file_2 = ' '
      scale_2 = unset_real
      call group_input(path, text, g, at, buf, msg)
      if (n_motions > 1) at%label = at%label//' #'//str(g%occurrence)
      read (buf, nml=ground, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      cfg%name = trim(adjustl(name))
      cfg%histories = histories
      if (len(cfg%name) == 0) then
         if (n_motions > 1 .and. lower(trim(adjustl(kind))) /= 'record_set') then
            call fail(at, 'name', 'name is missing: every motion of a suite (a deck with more '// &
                      'than one &ground) needs a name', error)
            return
         end if
         cfg%name = 'ground'
         ! A record set's motions take their files' stems (pound_deck_record_set).
         if (lower(trim(adjustl(kind))) == 'record_set') cfg%name = '(record set #'//str(g%occurrence)//')'
      end if
      if (n_motions > 1) at%label = at%label//' ('//cfg%name//')'
      call read_scaling(error)
      if (allocated(error)) return
      cfg%kind = lower(trim(adjustl(kind)))
      if (cfg%kind /= 'synthetic') call no_synthetic(error)
      if (allocated(error)) return
      if (cfg%kind /= 'record_set') then
         if (len_trim(folder) > 0) then
            call fail(at, 'folder', "folder applies only to kind = 'record_set'", error)
         else if (len_trim(pattern) > 0) then
            call fail(at, 'pattern', "pattern applies only to kind = 'record_set'", error)
         end if
         if (allocated(error)) return
      end if
      select case (cfg%kind)
      case ('')
         call fail(at, 'kind', "kind is missing, must be 'pulse', 'record', 'record_set' or 'synthetic'", error)
      case ('synthetic')
         call read_synthetic(error)
      case ('pulse')
         if (len_trim(file) > 0) then
            call fail(at, 'file', "file applies only to kind = 'record'", error)
         else if (len_trim(format) > 0) then
            call fail(at, 'format', "format applies only to kind = 'record'", error)
         else if (is_set(scale)) then
            call fail(at, 'scale', "scale applies only to kind = 'record'", error)
         end if
         if (allocated(error)) return
         call require_real(at, 'x0', x0, 'pulse amplitude in m', error, '/=', 0.0_dp)
         if (allocated(error)) return
         call require_real(at, 'a', a, 'pulse decay in 1/s', error, '>=', 0.0_dp)
         if (allocated(error)) return
         call require_real(at, 'b', b, 'pulse circular frequency in rad/s', error, '>', 0.0_dp)
         if (allocated(error)) return
         cfg%x0 = x0
         cfg%a = a
         cfg%b = b
         cfg%file = ''
         cfg%format = ''
      case ('record_set')
         call no_pulse(error)
         if (allocated(error)) return
         if (len_trim(file) > 0) then
            call fail(at, 'file', "file applies only to kind = 'record' (a record_set takes folder and "// &
                      'pattern)', error)
            return
         end if
         if (len_trim(folder) == 0) then
            call fail(at, 'folder', 'folder is missing (the folder of the records, relative to the deck''s '// &
                      'directory unless absolute)', error)
            return
         end if
         if (len_trim(folder) == len(folder)) then
            call fail(at, 'folder', 'folder is longer than '//str(len(folder) - 1)//' characters', error)
            return
         end if
         cfg%folder = resolve_path(path, trim(adjustl(folder)))
         cfg%pattern = trim(adjustl(pattern))
         if (len(cfg%pattern) == 0) cfg%pattern = '*.AT2'
         if (index(cfg%pattern, '/') > 0) then
            call fail(at, 'pattern', "pattern = '"//cfg%pattern//"': a pattern matches file names in the "// &
                      'folder and holds no /', error)
            return
         end if
         cfg%file = ''
         call record_format(error)
      case ('record')
         call no_pulse(error)
         if (allocated(error)) return
         if (len_trim(file) == 0) then
            call fail(at, 'file', 'file is missing (record file, relative to the deck''s '// &
                      'directory unless absolute)', error)
            return
         end if
         call existing_record('file', file, cfg%file, error)
         if (allocated(error)) return
         call record_format(error)
      case default
         call fail(at, 'kind', "kind = '"//trim(adjustl(kind))//"', must be 'pulse', 'record', "// &
                   "'record_set' or 'synthetic'", error)
      end select
      if (allocated(error)) return
      call take_components(error)

   contains

      !> A record file `var` as given (`raw`, not blank): resolved relative to the deck's
      !> directory unless absolute; it must exist.
      subroutine existing_record(var, raw, resolved, error)
         character(len=*), intent(in) :: var, raw
         character(len=:), allocatable, intent(out) :: resolved
         type(error_type), allocatable, intent(out) :: error
         character(len=:), allocatable :: where

         if (len_trim(raw) == len(raw)) then
            call fail(at, var, var//' is longer than '//str(len(raw) - 1)//' characters', error)
            return
         end if
         where = resolve_path(path, trim(adjustl(raw)))
         inquire (file=where, exist=exists)
         if (.not. exists) then
            call fail(at, var, var//" = '"//trim(adjustl(raw))//"': record file '"//where//"' does not exist", error)
            return
         end if
         resolved = where
      end subroutine existing_record

      !> `angle` (degrees, default 0, finite; beyond one turn a warning), and for a record the
      !> second component `file_2` (resolved like `file`, must exist) with `scale_2` (default
      !> `scale`; not with `scale_to`, whose factor scales both components).
      subroutine take_components(error)
         type(error_type), allocatable, intent(out) :: error

         if (is_set(angle)) then
            if (.not. ieee_is_finite(angle)) then
               call fail(at, 'angle', 'angle = '//str(angle)//', must be a finite number (degrees from +x '// &
                         'toward +y)', error)
               return
            end if
            cfg%angle = angle
            if (abs(angle) > 360.0_dp) call warn(at, 'angle', 'angle = '//plain_real(angle)//' degrees is more '// &
               'than a full turn: the direction is '//plain_real(modulo(angle, 360.0_dp))//' degrees; angle is '// &
               'in degrees from +x toward +y (not radians): check the value', warnings)
         end if
         cfg%scale_2 = cfg%scale
         if (len_trim(file_2) == 0) then
            if (is_set(scale_2)) call fail(at, 'scale_2', 'scale_2 applies only with file_2 (the scale factor '// &
                                           "of the second horizontal component's record)", error)
            return
         end if
         if (cfg%kind == 'record_set') then
            call fail(at, 'file_2', "file_2 applies only to kind = 'record': each file of a record set is a "// &
                      "motion of one component; give a two-component record as a &ground kind = 'record' with "// &
                      'file and file_2', error)
            return
         end if
         if (cfg%kind /= 'record') then
            call fail(at, 'file_2', "file_2 applies only to kind = 'record' (the second horizontal component's "// &
                      "record file; this motion is kind = '"//cfg%kind//"')", error)
            return
         end if
         call existing_record('file_2', file_2, cfg%file_2, error)
         if (allocated(error)) return
         if (.not. is_set(scale_2)) return
         if (len(cfg%scale_to) > 0) then
            call fail(at, 'scale_2', "scale_2 and scale_to exclude each other: scale_to's factor, computed on "// &
                      'the first component (file), scales both components', error)
            return
         end if
         call check_real(at, 'scale_2', scale_2, '/=', 0.0_dp, error)
         if (allocated(error)) return
         cfg%scale_2 = scale_2
         cfg%scale_2_given = .true.
      end subroutine take_components

      !> `format` and `scale` of a record (or of every record of a set).
      subroutine record_format(error)
         type(error_type), allocatable, intent(out) :: error

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
      end subroutine record_format

      !> `scale_to`, `target`, `period`.
      subroutine read_scaling(error)
         type(error_type), allocatable, intent(out) :: error

         cfg%scale_to = lower(trim(adjustl(scale_to)))
         select case (cfg%scale_to)
         case ('')
            if (is_set(target)) then
               call fail(at, 'target', "target applies only with scale_to = 'pga' or 'sa'", error)
            else if (is_set(target_g)) then
               call fail(at, 'target_g', "target_g applies only with scale_to = 'pga' or 'sa'", error)
            else if (is_set(period)) then
               call fail(at, 'period', "period applies only with scale_to = 'sa'", error)
            end if
         case ('pga', 'sa')
            if (is_set(scale)) then
               call fail(at, 'scale', 'scale and scale_to exclude each other: give one', error)
               return
            end if
            if (is_set(target_g)) then
               if (is_set(target)) then
                  call fail(at, 'target_g', 'target and target_g exclude each other: give one (target '// &
                            'in m/s^2, target_g in g)', error)
                  return
               end if
               call check_real(at, 'target_g', target_g, '>', 0.0_dp, error)
               if (allocated(error)) return
               cfg%target = target_g*g_accel
            else
               call required_positive('target', target, 'target of scale_to in m/s^2, or target_g in g', &
                                      cfg%target, error)
               if (allocated(error)) return
               if (cfg%target < low_target) call warn(at, 'target', 'target = '//plain_real(target)// &
                  ' m/s^2 is below '//plain_real(low_target)//' m/s^2 (about 0.005 g): did you mean g? '// &
                  'target is in m/s^2; for a target in g use target_g = '//plain_real(target), &
                  warnings)
               if (cfg%target >= low_target .and. cfg%target < g_like_target) call warn(at, 'target', &
                  'target = '//plain_real(target)//' m/s^2 = '//plain_significant(target/g_accel, 3)//' g with scale_to = '''// &
                  cfg%scale_to//''' would be a plausible value in g, while the deck''s accelerations are in m/s^2: '// &
                  'did you mean target_g = '//plain_real(target)//' ('//plain_significant(target*g_accel, 3)//' m/s^2)? '// &
                  'if '//plain_real(target)//' m/s^2 is meant, target_g = '//plain_significant(target/g_accel, 3)// &
                  ' says so without this warning', warnings)
            end if
            call take_sa_period(at, 'scale_to', cfg%scale_to, period, cfg%period, error)
         case default
            call fail(at, 'scale_to', "scale_to = '"//trim(adjustl(scale_to))//"', must be 'pga' "// &
                      "or 'sa' (or absent: the factor scale)", error)
         end select
      end subroutine read_scaling

      !> The variables of `kind = 'synthetic'` must not appear with another kind.
      subroutine no_synthetic(error)
         type(error_type), allocatable, intent(out) :: error
         character(len=20), parameter :: names(15) = [character(len=20) :: 'filter', 'envelope', &
            'ground_frequency', 'ground_damping', 'filter_frequency', 'filter_damping', 'rise_time', &
            'plateau_end', 'decay_rate', 'peak_fraction', 'end_level', 'duration', 'pga', 'seed', '']
         logical :: given(14)
         integer :: i

         given = [len_trim(filter) > 0, len_trim(envelope) > 0, is_set(ground_frequency), &
                  is_set(ground_damping), is_set(filter_frequency), is_set(filter_damping), &
                  is_set(rise_time), is_set(plateau_end), is_set(decay_rate), is_set(peak_fraction), &
                  is_set(end_level), is_set(duration), is_set(pga), seed /= unset_int]
         do i = 1, size(given)
            if (given(i)) then
               call fail(at, trim(names(i)), trim(names(i))//" applies only to kind = 'synthetic'", error)
               return
            end if
         end do
      end subroutine no_synthetic

      !> `kind = 'synthetic'`: filter, envelope, duration, target PGA, seed (defaults of
      !> `ground_config`); the rules of pound_synthetic_motion.
      subroutine read_synthetic(error)
         type(error_type), allocatable, intent(out) :: error

         if (len_trim(file) > 0) then
            call fail(at, 'file', "file applies only to kind = 'record'", error)
         else if (len_trim(format) > 0) then
            call fail(at, 'format', "format applies only to kind = 'record'", error)
         else
            call no_pulse(error)
         end if
         if (allocated(error)) return
         cfg%filter = lower(trim(adjustl(filter)))
         if (len(cfg%filter) == 0) cfg%filter = 'kanai_tajimi'
         if (cfg%filter /= 'kanai_tajimi' .and. cfg%filter /= 'clough_penzien') then
            call fail(at, 'filter', "filter = '"//trim(adjustl(filter))//"', must be "// &
                      "'kanai_tajimi' or 'clough_penzien'", error)
            return
         end if
         cfg%envelope = lower(trim(adjustl(envelope)))
         if (len(cfg%envelope) == 0) cfg%envelope = 'jennings'
         if (cfg%envelope /= 'jennings' .and. cfg%envelope /= 'saragoni_hart') then
            call fail(at, 'envelope', "envelope = '"//trim(adjustl(envelope))//"', must be "// &
                      "'jennings' or 'saragoni_hart'", error)
            return
         end if
         call required_positive('duration', duration, 'duration of the motion in s', cfg%duration, error)
         if (.not. allocated(error)) call required_positive('pga', pga, 'peak ground acceleration '// &
                                                            'of the generator in m/s^2', cfg%pga, error)
         if (allocated(error)) return
         if (seed /= unset_int) cfg%seed = seed
         call optional_real('ground_frequency', ground_frequency, .false., cfg%ground_frequency, error)
         if (.not. allocated(error)) call optional_real('ground_damping', ground_damping, .true., &
                                                        cfg%ground_damping, error)
         if (.not. allocated(error)) call optional_real('filter_frequency', filter_frequency, .false., &
                                                        cfg%filter_frequency, error)
         if (.not. allocated(error)) call optional_real('filter_damping', filter_damping, .true., &
                                                        cfg%filter_damping, error)
         if (.not. allocated(error)) call optional_real('rise_time', rise_time, .false., cfg%rise_time, error)
         if (.not. allocated(error)) call optional_real('decay_rate', decay_rate, .false., cfg%decay_rate, error)
         if (.not. allocated(error)) call optional_real('peak_fraction', peak_fraction, .true., &
                                                        cfg%peak_fraction, error)
         if (.not. allocated(error)) call optional_real('end_level', end_level, .true., cfg%end_level, error)
         if (allocated(error)) return
         if (is_set(plateau_end)) cfg%plateau_end = plateau_end
         if (cfg%envelope == 'jennings') then
            if (.not. is_set(plateau_end)) cfg%plateau_end = min(cfg%plateau_end, cfg%duration)
            call check_real(at, 'plateau_end', cfg%plateau_end, '>=', cfg%rise_time, error, &
                            bound_text='rise_time = '//str(cfg%rise_time))
            if (allocated(error)) return
            if (cfg%plateau_end > cfg%duration) then
               call fail(at, 'plateau_end', 'plateau_end = '//str(cfg%plateau_end)// &
                         ', must be <= duration = '//str(cfg%duration), error)
               return
            end if
         end if
         call take_real(at, 'scale', scale, '/=', 0.0_dp, cfg%scale, error)
         if (allocated(error)) return
      end subroutine read_synthetic

      !> The variables of `kind = 'pulse'` must not appear with another kind.
      subroutine no_pulse(error)
         type(error_type), allocatable, intent(out) :: error

         if (is_set(x0)) then
            call fail(at, 'x0', "x0 applies only to kind = 'pulse'", error)
         else if (is_set(a)) then
            call fail(at, 'a', "a applies only to kind = 'pulse'", error)
         else if (is_set(b)) then
            call fail(at, 'b', "b applies only to kind = 'pulse'", error)
         end if
      end subroutine no_pulse

      !> A required variable > 0.
      subroutine required_positive(var, x, what, value, error)
         character(len=*), intent(in) :: var, what
         real(dp), intent(in) :: x
         real(dp), intent(inout) :: value
         type(error_type), allocatable, intent(out) :: error

         call require_real(at, var, x, what, error, '>', 0.0_dp)
         if (.not. allocated(error)) value = x
      end subroutine required_positive

      !> A variable > 0 (and < 1 for a ratio) that keeps its default when not given.
      subroutine optional_real(var, x, is_ratio, value, error)
         character(len=*), intent(in) :: var
         real(dp), intent(in) :: x
         logical, intent(in) :: is_ratio
         real(dp), intent(inout) :: value
         type(error_type), allocatable, intent(out) :: error

         if (.not. is_set(x)) return
         call check_real(at, var, x, '>', 0.0_dp, error)
         if (allocated(error)) return
         if (is_ratio .and. .not. (x < 1.0_dp)) then
            call fail(at, var, var//' = '//str(x)//', must be < 1', error)
            return
         end if
         value = x
      end subroutine optional_real

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
