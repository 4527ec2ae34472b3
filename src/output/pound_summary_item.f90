!> One item of the engineering summary (`pound_summary`): the type the terminal summary, the
!> listing's top and `<stem>_summary.csv` share, its constructor and the small text helpers of
!> the items (`pound_summary`, `pound_summary_yield`).
module pound_summary_item
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   implicit none
   private

   public :: summary_item, item, append, largest, fixed2, lambda_word

   !> Length of the text fields of an item.
   integer, parameter, public :: summary_text_len = 1024

   !> One line of the summary (one row of the CSV file).
   type :: summary_item
      !> 'suite', 'building', 'pair', 'collapse', 'failed' or 'warning'.
      character(len=16) :: kind = ''
      !> Building name, pair label, or 'suite' / 'run'.
      character(len=summary_text_len) :: subject = ''
      !> Machine name of the quantity, e.g. 'refined_gap_mean', 'lambda_storey_shear'.
      character(len=40) :: quantity = ''
      !> Human description for the text lines.
      character(len=summary_text_len) :: label = ''
      !> Value in `unit` (valid when `available`).
      real(dp) :: value = 0.0_dp
      !> Whether the value exists ('n/a' otherwise).
      logical :: available = .true.
      !> 'mm', '%', 'kN', 's', '-' (a count or a ratio), '' (text only).
      character(len=8) :: unit = ''
      !> Where (storey, segment, joint, motion), or why n/a.
      character(len=summary_text_len) :: location = ''
      !> Time of the peak (s); negative: none.
      real(dp) :: time = -1.0_dp
   end type summary_item

contains

   !> Append `it` to `items`.
   pure subroutine append(items, it)
      !> The items so far.
      type(summary_item), allocatable, intent(inout) :: items(:)
      !> The new item.
      type(summary_item), intent(in) :: it

      items = [items, it]
   end subroutine append

   !> An item.
   pure function item(kind, subject, quantity, label, value, unit, location, time, available) result(it)
      character(len=*), intent(in) :: kind, subject, quantity, label
      real(dp), intent(in), optional :: value, time
      character(len=*), intent(in), optional :: unit, location
      logical, intent(in), optional :: available
      type(summary_item) :: it

      it%kind = kind
      it%subject = subject
      it%quantity = quantity
      it%label = label
      if (present(value)) it%value = value
      if (present(unit)) it%unit = unit
      if (present(location)) it%location = location
      if (present(time)) it%time = time
      if (present(available)) it%available = available
   end function item

   !> x with 2 decimals ('2.08').
   pure function fixed2(x) result(text)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf

      write (buf, '(f0.2)') x
      text = trim(adjustl(buf))
      if (text(1:1) == '.') text = '0'//text
      if (text(1:min(2, len(text))) == '-.') text = '-0'//text(2:)
   end function fixed2

   !> A lambda as a word: 'inf', 'n/m' or the signed number with 1 decimal ('+39.0').
   pure function lambda_word(x) result(text)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf

      if (ieee_is_nan(x)) then
         text = 'n/m'
      else if (x >= huge(1.0_dp)) then
         text = 'inf'
      else
         write (buf, '(sp,f0.1)') x
         text = trim(adjustl(buf))
         if (text(2:2) == '.') text = text(1:1)//'0'//text(2:)
      end if
   end function lambda_word

   !> Index of the largest |x| (the first of equals); 1 for an empty array.
   pure integer function largest(x) result(j)
      real(dp), intent(in) :: x(:)

      j = 1
      if (size(x) > 0) j = maxloc(abs(x), dim=1)
   end function largest

end module pound_summary_item
