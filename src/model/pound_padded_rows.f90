!> The padded layout of short recovery rows (`recovery_rows%pad_width`): every row's entries
!> in one column of `dof(pad_width, n)` and `coef(pad_width, n)`, a row of fewer entries
!> completed with exact zero coefficients on its own last DOF (DOF 1 for a row without
!> entries). A building in plan's rows (storey drifts and shears, plane shears, rotations,
!> contact corners) have one to four entries each: the padded kernels evaluate a row without
!> a loop of its own, which the compressed rows' kernel (`rows_kernel`) pays per row.
!>
!> **Same numbers.** A row's sum starts at +0 and takes its entries in their order, as
!> `rows_kernel`'s; a padded entry adds 0 u = +-0 to it. Round to nearest never yields -0 from
!> the sum of +0 and a product or of two nonzero numbers, so the running sum is never -0, and
!> x + (+-0) = x for every such x: the values are those of `rows_kernel` bit for bit while u is
!> finite (a DOF that is not finite may turn a row's +-Inf into NaN; the time loop stops on
!> such a state).
module pound_padded_rows
   use pound_kinds, only: dp
   implicit none
   private

   public :: pad_width, pad_layout, padded_kernel, padded_peaks_kernel

   !> Entries of a padded row.
   integer, parameter :: pad_width = 4

contains

   !> The padded layout of compressed rows; `ok` false (arrays unallocated) when a row has
   !> more than `pad_width` entries.
   pure subroutine pad_layout(n, start, dof, coef, pdof, pcoef, ok)
      !> Number of rows.
      integer, intent(in) :: n
      !> Compressed rows (`recovery_rows`: start(n+1), dof, coef).
      integer, intent(in) :: start(:), dof(:)
      real(dp), intent(in) :: coef(:)
      !> The padded layout (pad_width, n).
      integer, allocatable, intent(out) :: pdof(:, :)
      real(dp), allocatable, intent(out) :: pcoef(:, :)
      !> Whether every row fits.
      logical, intent(out) :: ok
      integer :: j, len

      ok = .false.
      if (n < 1) return
      if (maxval(start(2:n + 1) - start(1:n)) > pad_width) return
      allocate (pdof(pad_width, n), pcoef(pad_width, n))
      pcoef = 0.0_dp
      do j = 1, n
         len = start(j + 1) - start(j)
         pdof(:, j) = 1
         if (len > 0) then
            pdof(1:len, j) = dof(start(j):start(j + 1) - 1)
            pcoef(1:len, j) = coef(start(j):start(j + 1) - 1)
            pdof(len + 1:, j) = dof(start(j + 1) - 1)
         end if
      end do
      ok = .true.
   end subroutine pad_layout

   !> y = the rows' values for u (explicit shapes: one pass, no loop per row).
   pure subroutine padded_kernel(n, nu, dof, coef, scale, u, y)
      integer, intent(in) :: n, nu, dof(pad_width, n)
      real(dp), intent(in) :: coef(pad_width, n), scale(n), u(nu)
      real(dp), intent(out) :: y(n)
      integer :: j

      do j = 1, n
         y(j) = scale(j)*((((0.0_dp + coef(1, j)*u(dof(1, j))) + coef(2, j)*u(dof(2, j))) + &
                           coef(3, j)*u(dof(3, j))) + coef(4, j)*u(dof(4, j)))
      end do
   end subroutine padded_kernel

   !> The running absolute maxima of the rows' values for u (where |y(j)| exceeds peak(j),
   !> peak(j) = |y(j)| and peak_time(j) = t), the values not stored.
   pure subroutine padded_peaks_kernel(n, nu, dof, coef, scale, u, t, peak, peak_time)
      integer, intent(in) :: n, nu, dof(pad_width, n)
      real(dp), intent(in) :: coef(pad_width, n), scale(n), u(nu), t
      real(dp), intent(inout) :: peak(n), peak_time(n)
      real(dp) :: y
      integer :: j

      do j = 1, n
         y = abs(scale(j)*((((0.0_dp + coef(1, j)*u(dof(1, j))) + coef(2, j)*u(dof(2, j))) + &
                            coef(3, j)*u(dof(3, j))) + coef(4, j)*u(dof(4, j))))
         if (y > peak(j)) then
            peak(j) = y
            peak_time(j) = t
         end if
      end do
   end subroutine padded_peaks_kernel

end module pound_padded_rows
