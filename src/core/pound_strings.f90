!> Number-to-text conversion for messages and listings.
module pound_strings
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   implicit none
   private

   public :: str

   !> Shortest readable text of a number.
   interface str
      module procedure str_int, str_real, str_logical
   end interface str

contains

   !> Integer as text, no blanks.
   pure function str_int(i) result(s)
      !> Value to format.
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buf

      write (buf, '(i0)') i
      s = trim(buf)
   end function str_int

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

end module pound_strings
