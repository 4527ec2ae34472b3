!> The column segments of a suite's frames: per motion the influence coefficients lambda (%)
!> of every member row of every frame (`structure_model%member`: per segment its shear, bottom
!> and top moment, axial force; `building_influence%member_lambda`), and over the motions of
!> the statistics (those whose run did not fail) their mean and maximum per row, as
!> `pound_suite` does for the floors and storeys.
!>
!> A motion's case carries its member lambdas and its uncoupled member peaks in a block of its
!> column (`column_block_width` reals: the frames' member rows, building after building, the
!> lambdas then the peaks, `columns_to_block`); the suite gathers the lambdas
!> (`columns_gather`) and reduces them (`columns_finish`); the runs at the sweep's gaps and at
!> a refinement's trial gaps compare with the uncoupled peaks (`member_peaks_from_block`: the
!> column segments' lambdas of the suite's sweep, `column_shear` and `column_moment`). Shear
!> buildings have no member rows: nothing is carried or written.
!> Reductions: the mean is sum_k lambda_k / n_used (+huge where a motion's lambda is +huge:
!> pounding created a response from nothing), the maximum the largest lambda (signed, as for
!> the storeys). `column_target_maxima` gives per motion the largest |lambda| of the segments'
!> shear and end moments (the sweep's `column_shear`, `column_moment`).
module pound_suite_columns
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_structure, only: structure_model
   use pound_influence, only: building_influence, column_maxima, max_meaningful, created_by_pounding, not_meaningful
   use pound_analysis, only: analysis_result
   implicit none
   private

   public :: column_suite, column_block_width, columns_to_block, columns_init, columns_gather, columns_finish
   public :: column_target_maxima, member_peaks_from_block

   !> The column segments of one building over the suite (member rows unallocated for a
   !> building without them).
   type :: column_suite
      !> Per member row and motion, lambda (%), (n_rows, n_motions); 0 for a failed motion.
      real(dp), allocatable :: lambda(:, :)
      !> Per member row: mean and maximum over the motions used (%).
      real(dp), allocatable :: mean_lambda(:), max_lambda(:)
   end type column_suite

contains

   !> Reals of a motion's column block: every building's member rows, twice (lambdas, peaks).
   pure integer function column_block_width(models) result(width)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)

      width = 2*sum(models%member%n)
   end function column_block_width

   !> A motion's member lambdas and uncoupled member peaks into its block
   !> (`column_block_width` reals).
   pure subroutine columns_to_block(models, infl, unc, block)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The motion's influence coefficients.
      type(building_influence), intent(in) :: infl(:)
      !> Its uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> The block.
      real(dp), intent(out) :: block(:)
      integer :: ib, o, n, half

      block = 0.0_dp
      half = size(block)/2
      o = 0
      do ib = 1, size(models)
         n = models(ib)%member%n
         if (n == 0) cycle
         if (allocated(infl(ib)%member_lambda)) block(o + 1:o + n) = infl(ib)%member_lambda
         if (allocated(unc%building(ib)%member_peak)) block(half + o + 1:half + o + n) = unc%building(ib)%member_peak
         o = o + n
      end do
   end subroutine columns_to_block

   !> A motion's uncoupled member peaks from its block (`columns_to_block`) into `unc` (its
   !> uncoupled peaks, `building` allocated): what the coupled runs at other gaps compare with.
   pure subroutine member_peaks_from_block(models, block, unc)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The motion's block.
      real(dp), intent(in) :: block(:)
      !> Its uncoupled peaks.
      type(analysis_result), intent(inout) :: unc
      integer :: ib, o, n, half

      half = size(block)/2
      o = 0
      do ib = 1, size(models)
         n = models(ib)%member%n
         if (n == 0) cycle
         unc%building(ib)%member_peak = block(half + o + 1:half + o + n)
         o = o + n
      end do
   end subroutine member_peaks_from_block

   !> The suite's column data for n_motions motions, zero.
   pure subroutine columns_init(models, n_motions, cols)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Number of motions.
      integer, intent(in) :: n_motions
      !> Per building.
      type(column_suite), allocatable, intent(out) :: cols(:)
      integer :: ib, n

      allocate (cols(size(models)))
      do ib = 1, size(models)
         n = models(ib)%member%n
         if (n == 0) cycle
         allocate (cols(ib)%lambda(n, n_motions), cols(ib)%mean_lambda(n), cols(ib)%max_lambda(n), source=0.0_dp)
      end do
   end subroutine columns_init

   !> Motion k's member lambdas from its block (`columns_to_block`).
   pure subroutine columns_gather(models, k, block, cols)
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Motion index.
      integer, intent(in) :: k
      !> Its block.
      real(dp), intent(in) :: block(:)
      !> Per building.
      type(column_suite), intent(inout) :: cols(:)
      integer :: ib, o, n

      o = 0
      do ib = 1, size(models)
         n = models(ib)%member%n
         if (n == 0) cycle
         cols(ib)%lambda(:, k) = block(o + 1:o + n)
         o = o + n
      end do
   end subroutine columns_gather

   !> Mean and maximum over the motions `used` (those of the statistics, in order).
   pure subroutine columns_finish(used, cols)
      !> The motions used.
      integer, intent(in) :: used(:)
      !> Per building.
      type(column_suite), intent(inout) :: cols(:)
      integer :: ib, k

      do ib = 1, size(cols)
         if (.not. allocated(cols(ib)%lambda)) cycle
         associate (c => cols(ib))
            c%mean_lambda = 0.0_dp
            c%max_lambda = -huge(1.0_dp)
            do k = 1, size(used)
               c%mean_lambda = c%mean_lambda + c%lambda(:, used(k))/size(used)
               c%max_lambda = max_meaningful(c%max_lambda, c%lambda(:, used(k)))
            end do
            ! Not meaningful (NaN) in every motion: NaN; +huge in one: +huge (`pound_influence`).
            if (size(used) > 0) then
               where (all(ieee_is_nan(c%lambda(:, used)), dim=2)) c%max_lambda = not_meaningful()
            end if
            where (any(created_by_pounding(c%lambda(:, used)), dim=2)) c%mean_lambda = huge(1.0_dp)
         end associate
      end do
   end subroutine columns_finish

   !> Largest |lambda| of motion k's column segments per building (`column_maxima`): (1, ib)
   !> of the shears, (2, ib) of the end moments (bottom and top); 0 for a building without
   !> column rows.
   pure function column_target_maxima(models, cols, k) result(m)
      !> The buildings (their member rows' names).
      type(structure_model), intent(in) :: models(:)
      !> Per building.
      type(column_suite), intent(in) :: cols(:)
      !> Motion index.
      integer, intent(in) :: k
      real(dp) :: m(2, size(models))
      integer :: ib

      m = 0.0_dp
      do ib = 1, size(models)
         if (allocated(cols(ib)%lambda)) m(:, ib) = column_maxima(cols(ib)%lambda(:, k), models(ib))
      end do
   end function column_target_maxima

end module pound_suite_columns
