!> The contact points of buildings in plan as results: the facade corners that are joint ends
!> become each plan building's result group `corner_ux` (the point's u_x, the joint's end row),
!> so that both analyses record their peaks (`peak/corner_ux`, `/influence/<b>/corner_ux`)
!> and the code separation rules of every point are taken from the uncoupled peaks of its two
!> corners: torsion enters through the rotation term of the rows.
module pound_contact_corners
   use pound_kinds, only: dp
   use pound_structure, only: structure_model, recovery_rows, result_group, result_rows_of
   use pound_contact_pair, only: contact_pair
   implicit none
   private

   public :: add_corner_rows

   !> Name of the result group of the contact points' u_x.
   character(len=*), parameter, public :: corner_group = 'corner_ux'

contains

   !> Append to every building in plan that is a joint end the group `corner_ux`: one row per
   !> joint end on it, in joint order (the end's row, `contact_pair%end_row`). `row(e, k)` is
   !> the index of end e of joint k in its building's result rows (0: not a building in plan,
   !> or the rigid neighbour).
   pure subroutine add_corner_rows(models, pairs, row)
      !> The buildings (groups appended to those in plan).
      type(structure_model), intent(inout) :: models(:)
      !> The joints (their ends' rows set: `pairs_from_config` with the models).
      type(contact_pair), intent(in) :: pairs(:)
      !> Row of each end in its building's result rows (2, number of joints).
      integer, allocatable, intent(out) :: row(:, :)
      type(recovery_rows), allocatable :: parts(:)
      type(result_group) :: g
      integer :: ib, k, e, n, first

      allocate (row(2, size(pairs)))
      row = 0
      do ib = 1, size(models)
         if (.not. allocated(models(ib)%plan)) cycle
         n = count(pairs%building(1) == ib) + count(pairs%building(2) == ib)
         if (n == 0) cycle
         allocate (parts(n + 1))
         parts(1) = models(ib)%result_rows
         first = models(ib)%result_rows%n + 1
         n = 0
         do k = 1, size(pairs)
            do e = 1, 2
               if (pairs(k)%building(e) /= ib) cycle
               n = n + 1
               parts(n + 1) = pairs(k)%end_row(e)
               row(e, k) = first + n - 1
            end do
         end do
         models(ib)%result_rows = result_rows_of(parts)
         g%name = corner_group
         g%units = 'm'
         g%first = first
         g%extent = [n]
         g%description = 'u_x of each contact point on this building (a facade corner: the joint''s end), '// &
                         'in the order of the joints (/coupled/contact)'
         g%arm = 0.0_dp
         if (allocated(models(ib)%result)) then
            models(ib)%result = [models(ib)%result, g]
         else
            models(ib)%result = [g]
         end if
         deallocate (parts)
      end do
   end subroutine add_corner_rows

end module pound_contact_corners
