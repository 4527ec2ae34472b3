!> How an influence coefficient lambda (pound_influence) is shown: `lambda_cell`, the text of a
!> listing's cell ('inf' for a response created by pounding, 'n/m' for a lambda that is not
!> meaningful, else the number), and `write_lambda_h5`, a dataset of lambdas with the
!> attribute `not_meaningful` (why an entry is NaN) when it holds one.
module pound_influence_output
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: fixed_cell, right_cell
   use pound_influence, only: not_meaningful_note
   use pound_h5, only: h5_file, h5_write, h5_write_attr
   implicit none
   private

   public :: lambda_cell, write_lambda_h5

contains

   !> lambda right-aligned in `w` columns with `d` decimals: 'inf' (+huge), 'n/m' (NaN), or
   !> the number (`fixed_cell`).
   pure function lambda_cell(x, w, d) result(cell)
      !> The coefficient (%).
      real(dp), intent(in) :: x
      !> Field width and decimals.
      integer, intent(in) :: w, d
      character(len=:), allocatable :: cell

      if (ieee_is_nan(x)) then
         cell = right_cell('n/m', w)
      else if (x >= huge(1.0_dp)) then
         cell = right_cell('inf', w)
      else
         cell = fixed_cell(x, w, d)
      end if
   end function lambda_cell

   !> The lambdas `x` as the dataset `path` (%), with the attribute `not_meaningful` when an
   !> entry is NaN.
   subroutine write_lambda_h5(h5, path, x, error)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The coefficients (%).
      real(dp), intent(in) :: x(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call h5_write(h5, path, x, error, units='%')
      if (allocated(error)) return
      if (any(ieee_is_nan(x))) call h5_write_attr(h5, path, 'not_meaningful', not_meaningful_note, error)
   end subroutine write_lambda_h5

end module pound_influence_output
