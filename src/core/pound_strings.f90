!> Number-to-text conversion for messages and listings.
module pound_strings
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   implicit none
   private

   public :: str, number_end, decimal_exponent, is_digit, shorten, short_real, fixed_cell, fit_with_suffix, left_cell, right_cell
   public :: add_warning, plain_real, plain_significant, counted, mm_text, lower

   !> Shortest readable text of a number.
   interface str
      module procedure str_int, str_int64, str_real, str_logical
   end interface str

contains

   !> Integer as text, no blanks.
   pure function str_int(i) result(s)
      !> Value to format.
      integer, intent(in) :: i
      character(len=:), allocatable :: s

      s = str_int64(int(i, int64))
   end function str_int

   !> 64-bit integer as text, no blanks.
   pure function str_int64(i) result(s)
      !> Value to format.
      integer(int64), intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buf

      write (buf, '(i0)') i
      s = trim(buf)
   end function str_int64

   !> Real as text: `g0` with up to 7 significant digits, no blanks.
   pure function str_real(x) result(s)
      !> Value to format.
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf

      if (ieee_is_nan(x)) then
         s = 'NaN'
         return
      end if
      write (buf, '(1pg0.7)') x
      s = trim(adjustl(buf))
   end function str_real

   !> Logical as `T`/`F`.
   pure function str_logical(l) result(s)
      !> Value to format.
      logical, intent(in) :: l
      character(len=:), allocatable :: s

      if (l) then
         s = 'T'
      else
         s = 'F'
      end if
   end function str_logical

   !> Length of the longest Fortran real constant at the start of `s` (0 if none):
   !> [sign] digits [. digits] [(E|D) [sign] digits | sign digits], at least one mantissa digit.
   pure function number_end(s) result(q)
      !> Text to scan.
      character(len=*), intent(in) :: s
      integer :: q
      integer :: i, j, nd, n

      n = len(s)
      q = 0
      i = 1
      if (i <= n) then
         if (s(i:i) == '+' .or. s(i:i) == '-') i = i + 1
      end if
      nd = 0
      call skip_digits(s, i, nd)
      if (i <= n) then
         if (s(i:i) == '.') then
            i = i + 1
            call skip_digits(s, i, nd)
         end if
      end if
      if (nd == 0) return
      q = i - 1
      if (i > n) return
      j = i
      if (index('EeDd', s(j:j)) > 0) j = j + 1
      if (j <= n) then
         if (s(j:j) == '+' .or. s(j:j) == '-') then
            j = j + 1
         else if (j == i) then
            return
         end if
      end if
      nd = 0
      call skip_digits(s, j, nd)
      if (nd > 0) q = j - 1
   end function number_end

   !> Move `i` past the decimal digits of `s` that start at `i`, adding their count to `nd`.
   pure subroutine skip_digits(s, i, nd)
      !> Text scanned.
      character(len=*), intent(in) :: s
      !> Position: the first digit on entry, the first character after the digits on return.
      integer, intent(inout) :: i
      !> Digits counted so far.
      integer, intent(inout) :: nd

      do while (i <= len(s))
         if (.not. is_digit(s(i:i))) exit
         i = i + 1
         nd = nd + 1
      end do
   end subroutine skip_digits

   !> Decimal exponent of the leading significant digit of a valid real constant `s`
   !> (-huge for zero; +-huge when the exponent field has more than 6 significant digits).
   pure function decimal_exponent(s) result(e10)
      !> A real constant accepted by `number_end`.
      character(len=*), intent(in) :: s
      integer :: e10
      integer :: i, n, ndigits, nbefore, kfirst, nexp, expo, sgn
      logical :: seen_point

      n = len(s)
      i = 1
      if (s(1:1) == '+' .or. s(1:1) == '-') i = 2
      seen_point = .false.
      ndigits = 0
      nbefore = -1
      kfirst = 0
      do while (i <= n)
         if (s(i:i) == '.') then
            seen_point = .true.
            nbefore = ndigits
         else if (is_digit(s(i:i))) then
            ndigits = ndigits + 1
            if (kfirst == 0 .and. s(i:i) /= '0') kfirst = ndigits
         else
            exit
         end if
         i = i + 1
      end do
      if (kfirst == 0) then
         e10 = -huge(1)
         return
      end if
      if (.not. seen_point) nbefore = ndigits
      ! The first nonzero mantissa digit is digit kfirst; nbefore digits precede the point.
      e10 = nbefore - kfirst
      expo = 0
      if (i <= n) then
         if (index('EeDd', s(i:i)) > 0) i = i + 1
         sgn = 1
         if (s(i:i) == '-') sgn = -1
         if (s(i:i) == '-' .or. s(i:i) == '+') i = i + 1
         do while (i < n)
            if (s(i:i) /= '0') exit
            i = i + 1
         end do
         nexp = n - i + 1
         if (nexp > 6) then
            e10 = sgn*huge(1)
            return
         end if
         read (s(i:n), *) expo
         expo = sgn*expo
      end if
      e10 = e10 + expo
   end function decimal_exponent

   !> Whether `ch` is a decimal digit.
   pure logical function is_digit(ch)
      !> Character to classify.
      character, intent(in) :: ch

      is_digit = ch >= '0' .and. ch <= '9'
   end function is_digit

   !> At most 40 characters of `s`, for messages (longer text ends in '...').
   pure function shorten(s) result(t)
      !> Text to show.
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: t

      if (len(s) <= 40) then
         t = s
      else
         t = s(1:37)//'...'
      end if
   end function shorten

   !> `text` with `suffix` after it in at most `width` characters: `text` is cut (never the
   !> suffix) so that the suffix survives a later cut to `width`.
   pure function fit_with_suffix(text, suffix, width) result(t)
      !> Text (trailing blanks dropped).
      character(len=*), intent(in) :: text
      !> What must survive (e.g. a count).
      character(len=*), intent(in) :: suffix
      !> Characters kept.
      integer, intent(in) :: width
      character(len=:), allocatable :: t

      t = text(1:min(len_trim(text), max(0, width - len(suffix))))//suffix
   end function fit_with_suffix

   !> `x` in short form for bounds: '0', '10', '1e-7', '2.5e3'.
   pure function short_real(x) result(s)
      !> A bound.
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=16) :: buf
      integer :: e, k

      if (.not. (abs(x) > 0.0_dp)) then
         s = '0'
         return
      end if
      write (buf, '(es16.6e3)') x
      buf = adjustl(buf)
      k = index(buf, 'E')
      read (buf(k + 1:), *) e
      s = buf(1:k - 1)
      do while (s(len(s):len(s)) == '0')
         s = s(1:len(s) - 1)
      end do
      if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
      if (e == 1) then
         s = str(nint(x))
      else if (e /= 0) then
         s = s//'e'//str(e)
      end if
   end function short_real

   !> `x` right-aligned in a field of width `w`: fixed point with `d` decimals (Fw.d) when it
   !> fits, scientific (ESw.k, as many digits as fit) when the fixed form would overflow the
   !> field (asterisks) or fill it to its first character (no blank before the next cell
   !> to its left) or, with `nonzero`, print a non-zero value as zero (a period or a mass of
   !> 0.00000). A listing column never shows '****' or a misleading 0, and the cell always
   !> starts with a blank (w >= 10), so cells side by side never run into each other.
   pure function fixed_cell(x, w, d, nonzero) result(cell)
      !> Value.
      real(dp), intent(in) :: x
      !> Field width (>= 10 for the scientific form to keep 2 digits).
      integer, intent(in) :: w
      !> Decimals of the fixed form.
      integer, intent(in) :: d
      !> The value is a physical quantity that is never zero: show its digits however small.
      logical, intent(in), optional :: nonzero
      character(len=w) :: cell
      character(len=16) :: fmt
      logical :: lost

      write (fmt, '(a,i0,a,i0,a)') '(f', w, '.', d, ')'
      write (cell, fmt) x
      lost = .false.
      if (present(nonzero)) lost = nonzero .and. x /= 0.0_dp .and. abs(x) < 0.5_dp*10.0_dp**(-d)
      if (index(cell, '*') == 0 .and. cell(1:1) == ' ' .and. .not. lost) return
      write (fmt, '(a,i0,a,i0,a)') '(es', w, '.', max(1, w - 8), ')'
      write (cell, fmt) x
   end function fixed_cell

   !> `text` left-aligned in a field of at least `w` characters (longer text kept whole).
   pure function left_cell(text, w) result(cell)
      !> The text (a name or a label).
      character(len=*), intent(in) :: text
      !> Field width.
      integer, intent(in) :: w
      character(len=:), allocatable :: cell

      cell = text//repeat(' ', max(0, w - len(text)))
   end function left_cell

   !> `text` right-aligned in a field of at least `w` characters (longer text kept whole,
   !> after one blank).
   pure function right_cell(text, w) result(cell)
      !> The text (a heading or a name).
      character(len=*), intent(in) :: text
      !> Field width.
      integer, intent(in) :: w
      character(len=:), allocatable :: cell

      cell = repeat(' ', max(1, w - len(text)))//text
   end function right_cell

   !> A count with its noun, singular for 1: counted(1, 'motion') = '1 motion', counted(3,
   !> 'failed case') = '3 failed cases' (the plural adds 's').
   pure function counted(n, noun) result(s)
      !> The count.
      integer, intent(in) :: n
      !> The noun in the singular.
      character(len=*), intent(in) :: noun
      character(len=:), allocatable :: s

      s = str_int(n)//' '//noun
      if (n /= 1) s = s//'s'
   end function counted

   !> A length given in m, for messages in mm (as the listing shows gaps, displacements and
   !> penetrations): `plain_real(1000 x)//' mm'`, e.g. mm_text(0.01) = '10 mm'; a value that is
   !> not finite as `str` gives it ('NaN mm', 'Infinity mm').
   pure function mm_text(x) result(s)
      !> The length (m).
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s

      if (.not. ieee_is_finite(x)) then
         s = str_real(x)//' mm'
      else
         s = plain_real(1000.0_dp*x)//' mm'
      end if
   end function mm_text

   !> `x` rounded to `digits` significant digits, in plain decimals (`plain_real`): '266',
   !> '0.00113', '1.99'.
   pure function plain_significant(x, digits) result(s)
      !> Value to format.
      real(dp), intent(in) :: x
      !> Significant digits kept (1..15).
      integer, intent(in) :: digits
      character(len=:), allocatable :: s
      real(dp) :: p

      if (.not. (abs(x) > 0.0_dp .and. abs(x) <= huge(1.0_dp))) then
         s = plain_real(x)
         return
      end if
      p = 10.0_dp**(digits - 1 - floor(log10(abs(x))))
      s = plain_real(real(nint(x*p, int64), dp)/p)
   end function plain_significant

   !> `x` for messages in plain decimals: 7 significant digits, trailing zeros dropped ('12',
   !> '0.04', '1.25') when 1e-4 <= |x| < 1e7; otherwise as `str` ('1.000000E-5').
   pure function plain_real(x) result(s)
      !> Value to format.
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=40) :: buf
      character(len=12) :: fmt
      integer :: decimals

      if (.not. (abs(x) >= 1.0e-4_dp .and. abs(x) < 1.0e7_dp)) then
         s = str_real(x)
         if (.not. (abs(x) > 0.0_dp)) s = '0'
         return
      end if
      decimals = max(0, 6 - floor(log10(abs(x))))
      write (fmt, '(a,i0,a)') '(f0.', decimals, ')'
      write (buf, fmt) x
      s = trim(adjustl(buf))
      if (index(s, '.') > 0) then
         do while (s(len(s):len(s)) == '0')
            s = s(1:len(s) - 1)
         end do
         if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
      end if
      if (s(1:1) == '.') s = '0'//s
      if (len(s) > 1) then
         if (s(1:2) == '-.') s = '-0'//s(2:)
      end if
   end function plain_real

   !> Append a warning to a list of warnings (e.g. `res%warnings`).
   pure subroutine add_warning(warnings, text)
      !> The list (unallocated: empty).
      character(len=:), allocatable, intent(inout) :: warnings(:)
      !> One line of text.
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: grown(:)
      integer :: i, n, length

      n = 0
      length = len(text)
      if (allocated(warnings)) then
         n = size(warnings)
         length = max(length, len(warnings))
      end if
      allocate (character(len=length) :: grown(n + 1))
      do i = 1, n
         grown(i) = warnings(i)
      end do
      grown(n + 1) = text
      call move_alloc(grown, warnings)
   end subroutine add_warning

   !> Lower-case copy of `s` (ASCII letters; the rest as it is).
   pure function lower(s) result(t)
      !> Text.
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: i

      t = s
      do i = 1, len(s)
         if (s(i:i) >= 'A' .and. s(i:i) <= 'Z') t(i:i) = achar(iachar(s(i:i)) + 32)
      end do
   end function lower

end module pound_strings
