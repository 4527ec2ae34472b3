!> Accelerogram files: a recorded ground acceleration as time and acceleration arrays.
!>
!> Two formats are read.
!>
!> * PEER `.AT2`: four header lines, then NPTS acceleration values in g, any number per
!>   line, separated by blanks. Line 4 gives NPTS and DT in either the old PEER form
!>   `NPTS=  4000, DT= .01000 SEC` (any text may follow, e.g. the NGA-West2 trailing comma)
!>   or the NGA form `4096    0.0100    NPTS, DT`. Sample i (1-based) is at t = (i-1) DT,
!>   the first sample at t = 0. The count of values must equal NPTS.
!> * Two columns (`columns`): each data line holds the time (s) and the acceleration.
!>   The acceleration is taken to be in g, like an AT2 file, unless the deck says otherwise
!>   through its scale factor (`pound_ground_motion::record_motion` multiplies by it).
!>   Lines whose first non-blank character is `#` or `!` are comments; blank lines are
!>   skipped. Times must increase strictly; they need not be evenly spaced.
!>
!> Values are separated by blanks, tabs or commas and may be written in any Fortran real
!> form: `-.6028715E-02`, `0.0123`, `1.5D-3`, `.1234-100` (exponent without letter).
!> Every acceleration must be at most 1e6 in magnitude (`max_record_value`: in g, or in the
!> file's unit converted by the deck's scale), every other value a finite number below 1e301.
!> Sizes are checked before anything is allocated: an AT2 header's NPTS must fit in the
!> bytes that follow it (at least two per value) and be at most `max_record_points`; DT must
!> lie in 1e-5..10 s.
!>
!> Line endings: LF, CR LF, CR CR LF (as in some PEER files) and a lone CR all end one line;
!> a missing newline after the last line and trailing blanks are accepted. Line numbers in
!> messages count lines in that sense (so CR CR LF is one line end, not two).
module pound_accelerogram
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, status_input
   use pound_text_file, only: read_whole_file
   use pound_strings, only: counted, str, number_end, decimal_exponent, is_digit, shorten, short_real, lower
   implicit none
   private

   public :: accelerogram_t, read_accelerogram, accelerogram_format

   character(len=*), parameter :: cr = achar(13), lf = achar(10), tab = achar(9)

   !> Largest magnitude of a record value: in g, or in the file's own unit when the deck's
   !> `scale` converts (1e6 covers 100 g written in mm/s^2).
   real(dp), parameter, public :: max_record_value = 1.0e6_dp
   !> Plausible range of an AT2 file's DT (s).
   real(dp), parameter, public :: record_dt_range(2) = [1.0e-5_dp, 10.0_dp]
   !> Largest number of samples in a record (800 MB of values).
   integer, parameter, public :: max_record_points = 100000000

   !> An accelerogram as read from its file.
   type :: accelerogram_t
      !> File it was read from.
      character(len=:), allocatable :: path
      !> Format actually read: 'at2' or 'columns'.
      character(len=:), allocatable :: format
      !> AT2: first header line (trimmed), for the listing; columns: empty.
      character(len=:), allocatable :: title
      !> Number of samples.
      integer :: npts = 0
      !> AT2: time step DT from the header (s). Columns: 0 (times are given explicitly).
      real(dp) :: dt = 0.0_dp
      !> Sample times (s), strictly increasing; AT2: (i-1) DT.
      real(dp), allocatable :: time(:)
      !> Acceleration values as in the file (g for AT2 and, by convention, for columns).
      real(dp), allocatable :: accel(:)
   end type accelerogram_t

   !> A line of the file: text between `first` and `last` (possibly empty), number `line`.
   type :: line_cursor
      integer :: pos = 1
      integer :: line = 0
      integer :: first = 1
      integer :: last = 0
   end type line_cursor

contains

   !> Read the accelerogram `path` in `format` ('at2', 'columns' or 'auto').
   !>
   !> With 'auto' a file whose name ends in `.at2` (any case) is read as AT2, anything else
   !> as two columns.
   subroutine read_accelerogram(path, format, rec, error)
      !> File to read.
      character(len=*), intent(in) :: path
      !> 'at2', 'columns' or 'auto' (case-insensitive).
      character(len=*), intent(in) :: format
      !> The accelerogram read.
      type(accelerogram_t), intent(out) :: rec
      !> Set on failure: unreadable file, bad header, bad value, wrong count, ...
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: fmt, buf

      fmt = accelerogram_format(path, format)
      if (len(fmt) == 0) then
         call fatal_error(error, path//": unknown accelerogram format '"//trim(format)// &
                          "' (expected 'at2', 'columns' or 'auto')", status_input)
         return
      end if
      call read_whole_file(path, 'accelerogram file', buf, error)
      if (allocated(error)) return

      rec%path = path
      rec%format = fmt
      if (fmt == 'at2') then
         call parse_at2(path, buf, rec, error)
      else
         call parse_columns(path, buf, rec, error)
      end if
   end subroutine read_accelerogram

   !> The format `format` resolves to for `path`: 'at2' or 'columns', or '' if `format` is
   !> none of 'at2', 'columns', 'auto' (case-insensitive, surrounding blanks ignored).
   pure function accelerogram_format(path, format) result(fmt)
      !> File name (only its extension matters, for 'auto').
      character(len=*), intent(in) :: path
      !> Requested format.
      character(len=*), intent(in) :: format
      character(len=:), allocatable :: fmt
      character(len=:), allocatable :: f
      integer :: n

      f = lower(trim(adjustl(format)))
      select case (f)
      case ('at2', 'columns')
         fmt = f
      case ('auto')
         n = len_trim(path)
         fmt = 'columns'
         if (n >= 4) then
            if (lower(path(n - 3:n)) == '.at2') fmt = 'at2'
         end if
      case default
         fmt = ''
      end select
   end function accelerogram_format

   ! ---------------------------------------------------------------------------------------
   ! AT2

   subroutine parse_at2(path, buf, rec, error)
      character(len=*), intent(in) :: path, buf
      type(accelerogram_t), intent(inout) :: rec
      type(error_type), allocatable, intent(out) :: error
      type(line_cursor) :: c
      integer :: i, npts, count, p, q, b, e, stat
      integer(int64) :: npts_header, room
      logical :: found
      real(dp) :: dt, x
      character(len=:), allocatable :: hdr4, shown

      c = start_cursor(buf)
      do i = 1, 4
         call next_line(buf, c, found)
         if (.not. found) then
            call fatal_error(error, path//': only '//str(c%line)//' line(s); an AT2 file has 4 '// &
                             'header lines and then the values', status_input)
            return
         end if
         if (i == 1) rec%title = trim(buf(c%first:c%last))
      end do
      hdr4 = buf(c%first:c%last)
      call parse_at2_counts(hdr4, npts_header, dt, error)
      if (allocated(error)) then
         error%message = path//':4: '//error%message
         return
      end if
      if (npts_header < 2) then
         call fatal_error(error, path//':4: NPTS = '//str(npts_header)//'; at least 2 samples are needed', status_input)
         return
      end if
      ! Size checks before allocating: every value takes at least 2 bytes (digit, separator).
      room = (int(len(buf), int64) - c%pos + 2)/2
      if (npts_header > room) then
         shown = str(npts_header)
         if (npts_header == huge(npts_header)) shown = 'a number of more than 18 digits'
         call fatal_error(error, path//':4: NPTS = '//shown//' values, but the '// &
                          str(max(len(buf) - c%pos + 1, 0))//' bytes after the header hold at most '// &
                          str(room)//'; the header does not match the file', status_input)
         return
      end if
      if (npts_header > max_record_points) then
         call fatal_error(error, path//':4: NPTS = '//str(npts_header)//' values, more than '// &
                          'the '//str(max_record_points)//' a record may have', status_input)
         return
      end if
      npts = int(npts_header)
      if (.not. (dt > 0.0_dp)) then
         call fatal_error(error, path//':4: DT = '//str(dt)//' s; DT must be > 0', status_input)
         return
      end if
      if (dt < record_dt_range(1) .or. dt > record_dt_range(2)) then
         call fatal_error(error, path//':4: DT = '//str(dt)//' s, outside the plausible range '// &
                          short_real(record_dt_range(1))//'..'//short_real(record_dt_range(2))//' s', status_input)
         return
      end if

      rec%npts = npts
      rec%dt = dt
      allocate (rec%accel(npts), stat=stat)
      if (stat /= 0) then
         call fatal_error(error, path//': cannot allocate memory for NPTS = '//str(npts)//' values ('// &
                          str(npts/131072)//' MiB)')
         return
      end if
      count = 0
      do
         call next_line(buf, c, found)
         if (.not. found) exit
         p = c%first
         do
            call next_token(buf, p, c%last, b, e, found)
            if (.not. found) exit
            q = number_end(buf(b:e))
            if (q /= e - b + 1) then
               call bad_token(path, c%line, buf(b:e), error)
               return
            end if
            call to_real(buf(b:e), x, error)
            if (.not. allocated(error)) call check_value(buf(b:e), x, error)
            if (allocated(error)) then
               error%message = path//':'//str(c%line)//': '//error%message
               return
            end if
            count = count + 1
            if (count <= npts) rec%accel(count) = x
            p = e + 1
         end do
      end do
      if (count /= npts) then
         call fatal_error(error, path//': header line 4 gives NPTS = '//str(npts)//' but the file holds '// &
                          counted(count, 'value'), status_input)
         return
      end if
      rec%time = [(real(i - 1, dp)*dt, i=1, npts)]
   end subroutine parse_at2

   !> NPTS and DT from AT2 header line 4: old PEER form (`NPTS= n, DT= dt SEC`, where
   !> `NPTS` is followed by `=`) or else NGA form (`n dt NPTS, DT`: the first two fields).
   subroutine parse_at2_counts(s, npts, dt, error)
      character(len=*), intent(in) :: s
      integer(int64), intent(out) :: npts
      real(dp), intent(out) :: dt
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: u
      integer :: p, q, b, e
      logical :: ok

      npts = 0
      dt = 0.0_dp
      u = lower(s)
      p = index(u, 'npts')
      ok = .false.
      if (p > 0) call value_after_equals(s, p + 4, b, e, ok)
      if (ok) then
         ! Old PEER form.
         ok = is_integer(s(b:e))
         if (ok) then
            npts = count_value(s(b:e))
            q = index(u(e + 1:), 'dt')
            ok = q > 0
         end if
         if (ok) call value_after_equals(s, e + q + 2, b, e, ok)
         if (ok) then
            e = b + number_end(s(b:e)) - 1
            ok = e >= b
         end if
      else
         ! NGA form.
         p = 1
         call next_token(s, p, len(s), b, e, ok)
         if (ok) ok = is_integer(s(b:e))
         if (ok) then
            npts = count_value(s(b:e))
            p = e + 1
            call next_token(s, p, len(s), b, e, ok)
         end if
         if (ok) ok = number_end(s(b:e)) == e - b + 1
      end if
      if (.not. ok) then
         call fatal_error(error, "cannot read NPTS and DT from header line 4 '"//shorten(trim(s))// &
                          "' (expected 'NPTS= n, DT= dt SEC' or 'n dt NPTS, DT')", status_input)
         return
      end if
      call to_real(s(b:e), dt, error)
   end subroutine parse_at2_counts

   !> After position `p` in `s`: blanks, '=', blanks, then a field [b:e] up to a blank or comma.
   pure subroutine value_after_equals(s, p, b, e, ok)
      character(len=*), intent(in) :: s
      integer, intent(in) :: p
      integer, intent(out) :: b, e
      logical, intent(out) :: ok
      integer :: i

      ok = .false.
      b = 1
      e = 0
      i = p
      do while (i <= len(s))
         if (s(i:i) /= ' ' .and. s(i:i) /= tab) exit
         i = i + 1
      end do
      if (i > len(s)) return
      if (s(i:i) /= '=') return
      i = i + 1
      call next_token(s, i, len(s), b, e, ok)
   end subroutine value_after_equals

   ! ---------------------------------------------------------------------------------------
   ! Two columns

   subroutine parse_columns(path, buf, rec, error)
      character(len=*), intent(in) :: path, buf
      type(accelerogram_t), intent(inout) :: rec
      type(error_type), allocatable, intent(out) :: error
      type(line_cursor) :: c
      real(dp), allocatable :: t(:), a(:), tmp(:)
      real(dp) :: x(2)
      integer :: n, p, b, e, ntok, first, prev_line, stat
      logical :: found
      character :: ch

      allocate (t(1024), a(1024))
      n = 0
      prev_line = 0
      rec%title = ''
      c = start_cursor(buf)
      do
         call next_line(buf, c, found)
         if (.not. found) exit
         p = c%first
         first = verify(buf(c%first:c%last), ' '//tab)
         if (first == 0) cycle
         ch = buf(c%first + first - 1:c%first + first - 1)
         if (ch == '#' .or. ch == '!') cycle
         ntok = 0
         do
            call next_token(buf, p, c%last, b, e, found)
            if (.not. found) exit
            ntok = ntok + 1
            if (ntok <= 2) then
               if (number_end(buf(b:e)) /= e - b + 1) then
                  call bad_token(path, c%line, buf(b:e), error)
                  return
               end if
               call to_real(buf(b:e), x(ntok), error)
               if (ntok == 2 .and. .not. allocated(error)) call check_value(buf(b:e), x(ntok), error)
               if (allocated(error)) then
                  error%message = path//':'//str(c%line)//': '//error%message
                  return
               end if
            end if
            p = e + 1
         end do
         if (ntok /= 2) then
            call fatal_error(error, path//':'//str(c%line)//': expected 2 numbers (time in s, '// &
                             'acceleration), found '//str(ntok)//' fields', status_input)
            return
         end if
         if (n > 0) then
            if (.not. (x(1) > t(n))) then
               call fatal_error(error, path//':'//str(c%line)//': time '//str(x(1))// &
                                ' s does not increase (previous time '//str(t(n))// &
                                ' s on line '//str(prev_line)//')', status_input)
               return
            end if
         end if
         if (n == size(t)) then
            if (n >= max_record_points) then
               call fatal_error(error, path//':'//str(c%line)//': more than '//str(max_record_points)// &
                                ' samples, more than a record may have', status_input)
               return
            end if
            allocate (tmp(2*n), stat=stat)
            if (stat == 0) then
               tmp(1:n) = t
               call move_alloc(tmp, t)
               allocate (tmp(2*n), stat=stat)
            end if
            if (stat /= 0) then
               call fatal_error(error, path//': cannot allocate memory for '//str(2*n)//' samples ('// &
                                str(n/32768)//' MiB)')
               return
            end if
            tmp(1:n) = a
            call move_alloc(tmp, a)
         end if
         n = n + 1
         t(n) = x(1)
         a(n) = x(2)
         prev_line = c%line
      end do
      if (n < 2) then
         call fatal_error(error, path//': '//str(n)//' data line(s); at least 2 samples '// &
                          '(time, acceleration) are needed', status_input)
         return
      end if
      rec%npts = n
      rec%dt = 0.0_dp
      rec%time = t(1:n)
      rec%accel = a(1:n)
   end subroutine parse_columns

   ! ---------------------------------------------------------------------------------------
   ! Text handling


   !> Cursor before the first line, skipping a UTF-8 byte-order mark.
   pure function start_cursor(buf) result(c)
      character(len=*), intent(in) :: buf
      type(line_cursor) :: c

      c%pos = 1
      if (len(buf) >= 3) then
         if (buf(1:3) == char(239)//char(187)//char(191)) c%pos = 4
      end if
   end function start_cursor

   !> Advance `c` to the next line of `buf`; false at the end. A line ends at LF, at a run
   !> of CRs followed by an optional LF, or at the end of the text.
   pure subroutine next_line(buf, c, found)
      character(len=*), intent(in) :: buf
      type(line_cursor), intent(inout) :: c
      logical, intent(out) :: found
      integer :: k, n

      n = len(buf)
      found = c%pos <= n
      if (.not. found) return
      c%line = c%line + 1
      c%first = c%pos
      k = scan(buf(c%pos:), cr//lf)
      if (k == 0) then
         c%last = n
         c%pos = n + 1
         return
      end if
      k = c%pos + k - 1
      c%last = k - 1
      do while (k <= n)
         if (buf(k:k) /= cr) exit
         k = k + 1
      end do
      if (k <= n) then
         if (buf(k:k) == lf) k = k + 1
      end if
      c%pos = k
   end subroutine next_line

   !> Next field of s(p:last) separated by blanks, tabs or commas: s(b:e); false if none.
   pure subroutine next_token(s, p, last, b, e, found)
      character(len=*), intent(in) :: s
      integer, intent(in) :: p, last
      integer, intent(out) :: b, e
      logical, intent(out) :: found
      integer :: k

      found = .false.
      b = p
      e = p - 1
      if (p > last) return
      k = verify(s(p:last), ' ,'//tab)
      if (k == 0) return
      b = p + k - 1
      k = scan(s(b:last), ' ,'//tab)
      if (k == 0) then
         e = last
      else
         e = b + k - 2
      end if
      found = .true.
   end subroutine next_token


   !> Convert a token already checked by `number_end`; reject magnitudes of 1e301 and more
   !> before converting (the conversion itself would overflow).
   subroutine to_real(s, x, error)
      character(len=*), intent(in) :: s
      real(dp), intent(out) :: x
      type(error_type), allocatable, intent(out) :: error
      integer :: ios

      x = 0.0_dp
      if (decimal_exponent(s) > 300) then
         call fatal_error(error, "'"//shorten(s)//"' is out of range (magnitude 1e301 or more)", status_input)
         return
      end if
      read (s, '(f'//str(len(s))//'.0)', iostat=ios) x
      if (ios /= 0) then
         call fatal_error(error, "'"//shorten(s)//"' is not a finite number", status_input)
      end if
   end subroutine to_real


   !> The count written in digits `s`; counts of more than 18 digits read as huge.
   pure function count_value(s) result(n)
      character(len=*), intent(in) :: s
      integer(int64) :: n

      n = huge(n)
      if (len(s) <= 18) read (s, *) n
   end function count_value

   !> A record value must be at most `max_record_value` in magnitude.
   subroutine check_value(s, x, error)
      character(len=*), intent(in) :: s
      real(dp), intent(in) :: x
      type(error_type), allocatable, intent(out) :: error

      if (abs(x) <= max_record_value) return
      call fatal_error(error, "acceleration '"//shorten(s)//"' is outside the plausible range: "// &
                       '|value| <= 1e6 (in g, or in the file''s unit converted by the deck''s scale)', status_input)
   end subroutine check_value

   subroutine bad_token(path, line, token, error)
      character(len=*), intent(in) :: path, token
      integer, intent(in) :: line
      type(error_type), allocatable, intent(out) :: error

      call fatal_error(error, path//':'//str(line)//": '"//shorten(token)//"' is not a number", status_input)
   end subroutine bad_token


   pure logical function is_integer(s)
      character(len=*), intent(in) :: s
      integer :: i

      is_integer = len(s) > 0
      do i = 1, len(s)
         if (.not. is_integer) return
         is_integer = is_digit(s(i:i))
      end do
   end function is_integer

end module pound_accelerogram
