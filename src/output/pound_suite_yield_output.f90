!> The suite's results of bilinear storeys (issue 25): per building with `storey_law =
!> 'bilinear'`, the collapses counted per motion and the statistics of the peak ductility and
!> residual drift over the motions (those that did not fail). Written only for bilinear
!> buildings of a suite with contact (elastic decks are unchanged):
!>
!>     /suite/yielding/<b>/ductility_uncoupled, ductility_coupled     (n_storeys, n_motions)  -
!>     /suite/yielding/<b>/residual_drift_uncoupled, _coupled         (n_storeys, n_motions)  m
!>     /suite/yielding/<b>/mean_ductility, max_ductility              (n_storeys, 2: uncoupled, coupled)
!>     /suite/yielding/<b>/collapse_storey                            (2: uncoupled, coupled; n_motions), 0: none
!>     /suite/yielding/<b>/collapses                                  (2): motions in which it collapsed
!>
!> A frame with plastic hinges (`hinge_law = 'elastic_plastic'`) gets the same group with
!> `plastic_rotation` in place of `ductility` (rad): per storey, the largest peak |plastic
!> rotation| of the storey's column hinges and of the beam hinges of the floor at its top
!> (`storey_yield_result%ductility` of a frame).
module pound_suite_yield_output
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str, fixed_cell
   use pound_structure, only: structure_model, structure_yields
   use pound_text_writer, only: text_writer
   use pound_h5, only: h5_file, h5_write
   use pound_suite_statistics, only: suite_result
   implicit none
   private

   public :: write_suite_yield_listing, write_suite_yield_h5, suite_ductility_statistics

contains

   !> Mean and maximum over the motions used of the peak ductility (n_storeys, 2: uncoupled,
   !> coupled) and the motions in which the building collapsed (2), of building ib.
   pure subroutine suite_ductility_statistics(suite, ib, mean, maxi, collapses)
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> Building.
      integer, intent(in) :: ib
      !> Mean and largest ductility of each storey, uncoupled and coupled.
      real(dp), allocatable, intent(out) :: mean(:, :), maxi(:, :)
      !> Motions (used) in which the building collapsed, uncoupled and coupled.
      integer, intent(out) :: collapses(2)
      integer :: k, a, nu

      associate (s => suite%building(ib))
         allocate (mean(size(s%yield, 2), 2), maxi(size(s%yield, 2), 2), source=0.0_dp)
         collapses = 0
         nu = max(count(.not. suite%motion_failed), 1)
         do k = 1, size(s%yield, 1)
            if (suite%motion_failed(k)) cycle
            do a = 1, 2
               mean(:, a) = mean(:, a) + s%yield(k, :, a)/nu
               maxi(:, a) = max(maxi(:, a), s%yield(k, :, a))
               if (s%collapse(k, a) > 0) collapses(a) = collapses(a) + 1
            end do
         end do
      end associate
   end subroutine suite_ductility_statistics

   !> Listing: per bilinear building, the collapses (how many motions, which motion, storey)
   !> and per storey the mean and largest peak ductility over the motions.
   subroutine write_suite_yield_listing(lst, models, suite)
      !> The listing.
      type(text_writer), intent(inout) :: lst
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The suite.
      type(suite_result), intent(in) :: suite
      real(dp), allocatable :: mean(:, :), maxi(:, :)
      character(len=:), allocatable :: line
      character(len=*), parameter :: analysis(2) = [character(len=9) :: 'uncoupled', 'coupled']
      integer :: ib, k, a, j, collapses(2)
      real(dp) :: f

      if (.not. suite%has_coupled) return
      do ib = 1, size(models)
         if (.not. structure_yields(models(ib))) cycle
         call suite_ductility_statistics(suite, ib, mean, maxi, collapses)
         call lst%put('')
         call lst%put('  Suite, '//trim(merge('plastic hinges  ', 'bilinear storeys', allocated(models(ib)%hinge_moment)))// &
                      ' of '//models(ib)%name//': collapses uncoupled '//str(collapses(1))// &
                  ', coupled '//str(collapses(2))//' of '//str(count(.not. suite%motion_failed))//' motions')
         do k = 1, size(suite%names)
            do a = 1, 2
               if (suite%building(ib)%collapse(k, a) == 0) cycle
               call lst%put('    COLLAPSE: motion '//trim(suite%names(k))//', '//trim(analysis(a))//' analysis, storey '// &
                        str(suite%building(ib)%collapse(k, a)))
            end do
         end do
         f = 1.0_dp
         if (allocated(models(ib)%hinge_moment)) then
            ! The storey's largest peak plastic rotation of its column hinges and its top floor's beam hinges, in mrad.
            f = 1.0e3_dp
            call lst%put('    storey  (largest hinge plastic rotation: its columns, the beams above; mrad) mean unc, max unc, '// &
                         'mean cpl, max cpl')
         else
            call lst%put('    storey   mean mu unc   max mu unc   mean mu cpl   max mu cpl')
         end if
         do j = 1, size(mean, 1)
            line = '    '//repeat(' ', max(0, 5 - len(str(j))))//str(j)// &
                   fixed_cell(f*mean(j, 1), 14, 3)//fixed_cell(f*maxi(j, 1), 13, 3)// &
                   fixed_cell(f*mean(j, 2), 14, 3)//fixed_cell(f*maxi(j, 2), 13, 3)
            call lst%put(line)
         end do
      end do

   end subroutine write_suite_yield_listing

   !> HDF5: the datasets of the module comment, for every bilinear building.
   subroutine write_suite_yield_h5(h5, models, suite, error)
      !> The results file (open).
      type(h5_file), intent(inout) :: h5
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: mean(:, :), maxi(:, :)
      character(len=:), allocatable :: g, q, u
      integer :: ib, collapses(2)

      if (.not. suite%has_coupled) return
      do ib = 1, size(models)
         if (.not. structure_yields(models(ib))) cycle
         g = '/suite/yielding/'//models(ib)%name//'/'
         q = 'ductility'
         u = '-'
         if (allocated(models(ib)%hinge_moment)) then
            q = 'plastic_rotation'
            u = 'rad'
         end if
         call suite_ductility_statistics(suite, ib, mean, maxi, collapses)
         associate (s => suite%building(ib))
            call h5_write(h5, g//q//'_uncoupled', transpose(s%yield(:, :, 1)), error, units=u)
            if (.not. allocated(error)) call h5_write(h5, g//q//'_coupled', transpose(s%yield(:, :, 2)), error, &
                                                      units=u)
            if (.not. allocated(error)) call h5_write(h5, g//'residual_drift_uncoupled', transpose(s%yield(:, :, 3)), &
                                                      error, units='m')
            if (.not. allocated(error)) call h5_write(h5, g//'residual_drift_coupled', transpose(s%yield(:, :, 4)), &
                                                      error, units='m')
            if (.not. allocated(error)) call h5_write(h5, g//'mean_'//q, mean, error, units=u)
            if (.not. allocated(error)) call h5_write(h5, g//'max_'//q, maxi, error, units=u)
            if (.not. allocated(error)) call h5_write(h5, g//'collapse_storey', transpose(s%collapse), error, units='-')
            if (.not. allocated(error)) call h5_write(h5, g//'collapses', collapses, error, units='-')
         end associate
         if (allocated(error)) return
      end do
   end subroutine write_suite_yield_h5

end module pound_suite_yield_output
