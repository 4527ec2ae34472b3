!> Exchange two values or two allocatable arrays without copying their elements
!> (`move_alloc`), e.g. the data of two step sizes held by the integrators.
module pound_swap
   use pound_kinds, only: dp
   implicit none
   private

   public :: swap

   !> Exchange a and b.
   interface swap
      module procedure swap_real, swap_logical, swap_vector, swap_matrix
   end interface swap

contains

   !> Exchange two reals.
   pure subroutine swap_real(a, b)
      !> The values exchanged.
      real(dp), intent(inout) :: a, b
      real(dp) :: x

      x = a
      a = b
      b = x
   end subroutine swap_real

   !> Exchange two logicals.
   pure subroutine swap_logical(a, b)
      !> The values exchanged.
      logical, intent(inout) :: a, b
      logical :: x

      x = a
      a = b
      b = x
   end subroutine swap_logical

   !> Exchange two allocatable vectors (either may be unallocated).
   pure subroutine swap_vector(a, b)
      !> The vectors exchanged.
      real(dp), allocatable, intent(inout) :: a(:), b(:)
      real(dp), allocatable :: x(:)

      call move_alloc(a, x)
      call move_alloc(b, a)
      call move_alloc(x, b)
   end subroutine swap_vector

   !> Exchange two allocatable matrices (either may be unallocated).
   pure subroutine swap_matrix(a, b)
      !> The matrices exchanged.
      real(dp), allocatable, intent(inout) :: a(:, :), b(:, :)
      real(dp), allocatable :: x(:, :)

      call move_alloc(a, x)
      call move_alloc(b, a)
      call move_alloc(x, b)
   end subroutine swap_matrix

end module pound_swap
