!> Outputs of the column segments of a suite's frames (`pound_suite_columns`): a listing
!> section and datasets under `/suite`, only for frames (buildings with member rows).
!>
!> HDF5 (h5py shapes; rows = motions; attribute units = '%'):
!>
!>     /suite/influence/<b>/columns/<c>          (n_motions, n_segments) lambda of motion k
!>                                               (0 for a failed motion)
!>     /suite/mean/influence/<b>/columns/<c>     (n_segments) mean over the motions used
!>     /suite/max/influence/<b>/columns/<c>      (n_segments) maximum over the motions used
!>
!> with <c> the member quantities of the frame (`member_names`: shear, moment_bottom,
!> moment_top, axial) and the segments as in /model/<b>/columns.
module pound_suite_columns_output
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_structure, only: structure_model
   use pound_h5, only: h5_file, h5_write, h5_write_attr
   use pound_text_writer, only: text_writer
   use pound_listing, only: write_section
   use pound_suite_columns, only: column_suite, column_target_maxima
   implicit none
   private

   public :: write_suite_columns_listing, write_suite_columns_h5

contains

   !> Listing: per motion and frame the largest |lambda| of the column segments' shear and end
   !> moments (the sweep's column_shear, column_moment), then their mean and maximum over the
   !> motions used. Nothing without frames.
   subroutine write_suite_columns_listing(lst, models, names, failed, cols)
      !> The listing writer (unit, first write failure: the caller asks it).
      type(text_writer), intent(inout) :: lst
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Motion names.
      character(len=*), intent(in) :: names(:)
      !> Whether each motion's run failed (left out of the mean and maximum).
      logical, intent(in) :: failed(:)
      !> Per building (`pound_suite_columns`).
      type(column_suite), intent(in) :: cols(:)
      real(dp) :: m(2, size(models)), mean(2, size(models)), most(2, size(models))
      character(len=:), allocatable :: line
      character(len=14) :: cell
      integer :: k, ib, q, n_used

      if (all(models%member%n == 0)) return
      call write_section(lst, 'Suite: largest |lambda| [%] over the column segments per motion and frame')
      call lst%put( &
         '  column_shear: segment shear V; column_moment: end moments '// &
         'M1, M2 (the &sweep target quantities); mean and max over the motions that did not fail')
      line = '  '//'motion'//repeat(' ', 14)
      do ib = 1, size(models)
         if (models(ib)%member%n == 0) cycle
         line = line//'  '//trim(models(ib)%name)//':column_shear  '//trim(models(ib)%name)//':column_moment'
      end do
      if (lst%ios == 0) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) line
      call lst%note()
      mean = 0.0_dp
      most = 0.0_dp
      n_used = count(.not. failed)
      do k = 1, size(names)
         if (failed(k)) then
            if (lst%ios == 0) write (lst%unit, '(2x,a20,a)', iostat=lst%ios, iomsg=lst%msg) names(k), '   FAILED'
            call lst%note()
            cycle
         end if
         m = column_target_maxima(models, cols, k)
         mean = mean + m/n_used
         most = max(most, m)
         call row(names(k), m)
      end do
      call row('mean', mean)
      call row('max', most)

   contains

      !> One row: its name and each frame's two values.
      subroutine row(name, v)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: v(:, :)

         line = '  '//name(1:min(len(name), 20))//repeat(' ', max(0, 20 - len(name)))
         do ib = 1, size(models)
            if (models(ib)%member%n == 0) cycle
            do q = 1, 2
               write (cell, '(es14.4)') v(q, ib)
               line = line//repeat(' ', len_trim(models(ib)%name) + merge(1, 2, q == 1))//cell
            end do
         end do
         if (lst%ios == 0) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) line
         call lst%note()
      end subroutine row

   end subroutine write_suite_columns_listing

   !> `/suite/influence/<b>/columns/<c>`, `/suite/mean/...` and `/suite/max/...` of every frame
   !> (see the module's table), each with units = '%'.
   subroutine write_suite_columns_h5(h5, models, cols, error)
      !> The open results file.
      type(h5_file), intent(inout) :: h5
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Per building (`pound_suite_columns`).
      type(column_suite), intent(in) :: cols(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: per_motion(:, :), row(:)
      character(len=:), allocatable :: tail
      integer :: ib, q, nq

      do ib = 1, size(models)
         if (.not. allocated(cols(ib)%lambda)) cycle
         nq = size(models(ib)%member_names)
         do q = 1, nq
            tail = models(ib)%name//'/'//models(ib)%member_group//'/'//trim(models(ib)%member_names(q))
            ! Fortran (n_segments, n_motions): h5py (n_motions, n_segments), rows = motions.
            per_motion = cols(ib)%lambda(q::nq, :)
            call put2('/suite/influence/'//tail, per_motion)
            row = cols(ib)%mean_lambda(q::nq)
            call put1('/suite/mean/influence/'//tail, row)
            row = cols(ib)%max_lambda(q::nq)
            call put1('/suite/max/influence/'//tail, row)
            if (allocated(error)) return
         end do
      end do

   contains

      !> A 2-D dataset with its units.
      subroutine put2(path, a)
         character(len=*), intent(in) :: path
         real(dp), intent(in) :: a(:, :)

         if (allocated(error)) return
         call h5_write(h5, path, a, error)
         if (.not. allocated(error)) call h5_write_attr(h5, path, 'units', '%', error)
      end subroutine put2

      !> A 1-D dataset with its units.
      subroutine put1(path, a)
         character(len=*), intent(in) :: path
         real(dp), intent(in) :: a(:)

         if (allocated(error)) return
         call h5_write(h5, path, a, error)
         if (.not. allocated(error)) call h5_write_attr(h5, path, 'units', '%', error)
      end subroutine put1

   end subroutine write_suite_columns_h5

end module pound_suite_columns_output
