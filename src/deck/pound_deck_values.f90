!> The type check of a deck value's text before gfortran reads it (`value_problem`: a real,
!> an integer, a logical or a character value, with its repeat count `r*v` and null values),
!> and the ASCII lower case the deck's names are compared in (`lower`).
module pound_deck_values
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_strings, only: decimal_exponent, lower, number_end, shorten, str
   implicit none
   private

   public :: lower, value_problem

contains

   !> values it stands for (repeat count), `null` when it is `r*` alone (r null values).
   pure subroutine value_problem(t, vtype, rep, null, why)
      !> The token as written.
      character(len=*), intent(in) :: t
      !> Variable type.
      character, intent(in) :: vtype
      !> Number of values the token stands for.
      integer, intent(out) :: rep
      !> Whether it stands for null values (the variable keeps its default).
      logical, intent(out) :: null
      !> Empty when the token fits; otherwise the rule broken.
      character(len=:), allocatable, intent(out) :: why
      character(len=:), allocatable :: v, r
      integer :: star, k

      rep = 1
      null = .false.
      why = ''
      do k = 1, len(t)
         if (iachar(t(k:k)) < 32 .or. iachar(t(k:k)) == 127) then
            if (iachar(t(k:k)) == 0) then
               why = 'contains a NUL byte (character code 0) at character '//str(k)// &
                     '; a deck is plain text'
            else
               why = 'contains the control character code '//str(iachar(t(k:k)))// &
                     ' at character '//str(k)//'; a deck is plain text'
            end if
            return
         end if
      end do
      v = t
      star = 0
      if (t(1:1) /= "'" .and. t(1:1) /= '"') star = index(t, '*')
      if (star > 0) then
         r = t(1:star - 1)
         if (len(r) > 0 .and. verify(r, '0123456789') == 0) then
            if (len(r) - verify(r, '0') + 1 > 9 .and. verify(r, '0') > 0) then
               why = 'repeat count '//r//' is too large'
               return
            end if
            read (r, *) rep
            if (rep == 0) then
               why = 'repeat count 0, must be >= 1 (r*value stands for r equal values)'
               return
            end if
            v = t(star + 1:)
            if (len(v) == 0) then
               null = .true.
               return
            end if
         end if
      end if
      select case (vtype)
      case ('r')
         if (v(1:1) == "'" .or. v(1:1) == '"' .or. star > 0 .and. len(v) == len(t)) then
            why = 'expected a real number'
         else if (number_end(v) == len(v)) then
            if (decimal_exponent(v) >= 300) then
               why = 'out of range, the magnitude of a deck value must be below 1e300'
            end if
         else if (.not. is_special_real(v)) then
            why = 'expected a real number'
         end if
      case ('i')
         call integer_problem(v, why)
      case ('l')
         select case (lower(v))
         case ('t', 'f', '.t', '.f', '.t.', '.f.', 'true', 'false', '.true.', '.false.')
         case default
            why = 'expected a logical: .true. or .false.'
         end select
      end select
   end subroutine value_problem


   !> What is wrong with `v` as a deck integer: '' when it is one in -999999999..2147483647.
   pure subroutine integer_problem(v, why)
      !> The value as written (repeat count removed).
      character(len=*), intent(in) :: v
      !> Empty when `v` fits.
      character(len=:), allocatable, intent(out) :: why
      character(len=:), allocatable :: digits
      integer :: b

      why = ''
      b = 1
      if (v(1:1) == '+' .or. v(1:1) == '-') b = 2
      if (len(v) < b .or. verify(v(b:), '0123456789') /= 0) then
         why = 'expected an integer'
         return
      end if
      digits = v(b:)
      if (verify(digits, '0') == 0) return
      digits = digits(verify(digits, '0'):)
      if (v(1:1) == '-') then
         if (len(digits) > 9) why = 'integer out of range, must be >= -999999999'
      else if (len(digits) > 10 .or. (len(digits) == 10 .and. digits > '2147483647')) then
         why = 'integer out of range, must be <= 2147483647'
      end if
   end subroutine integer_problem


   !> NaN, with an optional sign); the range checks then refuse it by name.
   pure logical function is_special_real(v)
      !> The value as written.
      character(len=*), intent(in) :: v
      character(len=:), allocatable :: s

      s = lower(v)
      if (s(1:1) == '+' .or. s(1:1) == '-') s = s(2:)
      is_special_real = s == 'inf' .or. s == 'infinity' .or. s == 'nan'
   end function is_special_real

end module pound_deck_values
