!> Sorting of short real arrays.
module pound_sort
   use pound_kinds, only: dp
   implicit none
   private

   public :: sort_ascending

contains

   !> Sort `x` ascending in place by insertion (short arrays: a few hundred values at most;
   !> already sorted ones in one pass).
   pure subroutine sort_ascending(x)
      !> The values.
      real(dp), intent(inout) :: x(:)
      real(dp) :: key
      integer :: i, k

      do k = 2, size(x)
         key = x(k)
         i = k - 1
         do while (i >= 1)
            if (x(i) <= key) exit
            x(i + 1) = x(i)
            i = i - 1
         end do
         x(i + 1) = key
      end do
   end subroutine sort_ascending

end module pound_sort
