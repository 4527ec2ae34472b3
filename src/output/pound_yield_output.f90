!> Outputs of bilinear storeys (issue 25, pound_storey_yield): the HDF5 datasets
!>
!>     /<analysis>/<b>/peak/ductility     (n_storeys) mu = max|drift| / (Fy/k)
!>     /<analysis>/<b>/residual_drift     (n_storeys) m, the storey drift at the end
!>     /<analysis>/<b>/hysteretic_energy  ()          kJ, dissipated by the storeys
!>     /influence/<b>/ductility           (n_storeys) %, lambda of the ductility
!>     /influence/<b>/residual_drift      (n_storeys) %, lambda of |residual drift|
!>
!> and the attributes `collapse_storey` (0: none) and `collapse_time` (s) of `/<analysis>/<b>`,
!> and `meaningful` of `/influence/<b>` ('no: ...') when the building collapsed in an analysis
!>
!>     /model/<b>/yield_shear             (n_storeys) kN; attribute storey_law = 'bilinear'
!>     /model/<b>/hardening_ratio         (n_storeys) -
!>
!> (the storey-shear histories and peaks of such a building are its spring forces), and the
!> listing's table of the storeys. Only buildings with bilinear storeys get them.
!>
!> A building in plan with bilinear planes (its yielding rows are its planes' storeys,
!> `structure_model%yield_k`) gets them per plane and storey, h5py shape (n_planes,
!> n_storeys), planes in deck order, an elastic plane's rows included:
!>
!>     /<analysis>/<b>/peak/plane_ductility   mu = max|plane storey drift| / (Fy/k); 0: elastic plane
!>     /<analysis>/<b>/plane_residual_drift   m, the plane's storey drift at the end
!>     /influence/<b>/plane_ductility, /influence/<b>/plane_residual_drift   %
!>     /model/<b>/plane_yield_shear           kN, inf for an elastic plane
!>     /model/<b>/plane_hardening_ratio       -, 0 for an elastic plane
!>     /model/<b>/plane_storey_law            (n_planes) 'elastic' or 'bilinear'
!>
!> (`hysteretic_energy` as above; `peak/plane_shear` and the storey shears are the planes'
!> spring forces), and the listing's table of the bilinear planes' storeys.
module pound_yield_output
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: fixed_cell, right_cell, str
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_is_nan
   use pound_structure, only: structure_model, never_yields
   use pound_analysis, only: analysis_result
   use pound_storey_yield, only: storey_yield_result
   use pound_influence, only: influences
   use pound_influence_output, only: write_lambda_h5, lambda_text => lambda_cell
   use pound_h5, only: h5_file, h5_write, h5_write_attr
   use pound_text_writer, only: text_writer
   use pound_hinge_output, only: write_hinge_model_h5, write_hinge_h5, hinge_influence, write_hinge_table
   implicit none
   private

   public :: write_yield_model_h5, write_yield_h5, write_yield_influence_h5, write_yield_tables, yield_influence, collapse_text

contains

   !> The storey law of a building with bilinear storeys under its model group `g` ('/model/<b>/').
   subroutine write_yield_model_h5(h5, g, b, error)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> The building's model group, with a trailing '/'.
      character(len=*), intent(in) :: g
      !> The building.
      type(structure_model), intent(in) :: b
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      real(dp), allocatable :: fy(:)
      integer :: p

      if (allocated(b%hinge_moment)) call write_hinge_model_h5(h5, g, b, error)
      if (.not. allocated(b%yield_shear)) return
      if (allocated(b%yield_k)) then
         ! Bilinear planes: per plane and storey.
         fy = b%yield_shear
         where (fy >= never_yields) fy = ieee_value(1.0_dp, ieee_positive_inf)
         call h5_write(h5, g//'plane_yield_shear', plane_table(b, fy), error, units='kN')
         if (.not. allocated(error)) call h5_write(h5, g//'plane_hardening_ratio', plane_table(b, b%hardening), &
                                                   error, units='-')
         if (.not. allocated(error)) &
            call h5_write(h5, g//'plane_storey_law', [character(len=8) :: (merge('bilinear', 'elastic ', &
                          any(b%yield_plane == p .and. b%yield_shear < never_yields)), p=1, maxval(b%yield_plane))], &
                          error)
         if (.not. allocated(error)) call h5_write_attr(h5, g(1:len(g) - 1), 'storey_law', 'bilinear planes', error)
         return
      end if
      call h5_write(h5, g//'yield_shear', b%yield_shear, error, units='kN')
      if (.not. allocated(error)) call h5_write(h5, g//'hardening_ratio', b%hardening, error, units='-')
      if (.not. allocated(error)) call h5_write_attr(h5, g(1:len(g) - 1), 'storey_law', 'bilinear', error)
   end subroutine write_yield_model_h5

   !> The storey results of analysis `g` (e.g. '/uncoupled') of every building with bilinear storeys.
   subroutine write_yield_h5(h5, g, models, res, error)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> Group path of the analysis.
      character(len=*), intent(in) :: g
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The analysis.
      type(analysis_result), intent(in) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: ib

      if (.not. allocated(res%yielding)) return
      do ib = 1, size(models)
         associate (y => res%yielding(ib), gb => g//'/'//models(ib)%name//'/')
            if (y%n == 0) cycle
            if (allocated(models(ib)%yield_k)) then
               call h5_write(h5, gb//'peak/plane_ductility', plane_table(models(ib), y%ductility), error, units='-')
               if (.not. allocated(error)) call h5_write_attr(h5, gb//'peak/plane_ductility', 'description', &
                                                             'max |plane storey drift| / (yield_shear / k) per '// &
                                                             'plane (row, deck order) and storey (column); 0: '// &
                                                             'an elastic plane', error)
               if (.not. allocated(error)) call h5_write(h5, gb//'plane_residual_drift', &
                                                         plane_table(models(ib), y%residual_drift), error, units='m')
            else if (y%n_hinges > 0) then
               call write_hinge_h5(h5, gb, y, error)
            else
               call h5_write(h5, gb//'peak/ductility', y%ductility, error, units='-')
               if (.not. allocated(error)) call h5_write_attr(h5, gb//'peak/ductility', 'description', &
                                                             'max |storey drift| / (yield_shear / k) per storey', error)
            end if
            if (.not. allocated(error) .and. .not. allocated(models(ib)%yield_k)) &
               call h5_write(h5, gb//'residual_drift', y%residual_drift, error, units='m')
            if (.not. allocated(error)) call h5_write(h5, gb//'hysteretic_energy', y%hysteretic, error, units='kJ')
            if (.not. allocated(error)) call h5_write_attr(h5, gb//'hysteretic_energy', 'lcp_residual', &
                                                          y%residual, error)
            if (.not. allocated(error)) call h5_write_attr(h5, g//'/'//models(ib)%name, 'collapse_storey', &
                                                          y%collapse_storey, error)
            if (.not. allocated(error) .and. y%collapse_storey > 0) &
               call h5_write_attr(h5, g//'/'//models(ib)%name, 'collapse_time', y%collapse_time, error)
            if (allocated(error)) return
         end associate
      end do
   end subroutine write_yield_h5

   !> lambda of the ductility and of |residual drift| of storey j: (Qc - Qu)/Qu * 100.
   pure subroutine yield_influence(unc, cpl, lam_mu, lam_res)
      !> The building's storeys, uncoupled and coupled.
      type(storey_yield_result), intent(in) :: unc, cpl
      !> The coefficients (n_storeys each, %).
      real(dp), allocatable, intent(out) :: lam_mu(:), lam_res(:)

      lam_mu = influences(cpl%ductility, unc%ductility)
      lam_res = influences(abs(cpl%residual_drift), abs(unc%residual_drift))
   end subroutine yield_influence

   !> /influence/<b>/ductility and /influence/<b>/residual_drift of every building with
   !> bilinear storeys.
   subroutine write_yield_influence_h5(h5, models, unc, cpl, error)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The uncoupled and coupled analyses.
      type(analysis_result), intent(in) :: unc, cpl
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: lam_mu(:), lam_res(:)
      integer :: ib

      if (.not. (allocated(unc%yielding) .and. allocated(cpl%yielding))) return
      do ib = 1, size(models)
         if (unc%yielding(ib)%n == 0) cycle
         call yield_influence(unc%yielding(ib), cpl%yielding(ib), lam_mu, lam_res)
         if (allocated(models(ib)%yield_k)) then
            call write_lambda_table_h5(h5, '/influence/'//models(ib)%name//'/plane_ductility', &
                                       plane_table(models(ib), lam_mu), error)
            if (.not. allocated(error)) &
               call write_lambda_table_h5(h5, '/influence/'//models(ib)%name//'/plane_residual_drift', &
                                          plane_table(models(ib), lam_res), error)
            if (.not. allocated(error) .and. max(unc%yielding(ib)%collapse_storey, &
                                                 cpl%yielding(ib)%collapse_storey) > 0) &
               call h5_write_attr(h5, '/influence/'//models(ib)%name, 'meaningful', 'no: '// &
                                  collapse_text(unc%yielding(ib), cpl%yielding(ib)), error)
            if (allocated(error)) return
            cycle
         else if (unc%yielding(ib)%n_hinges > 0) then
            call write_lambda_h5(h5, '/influence/'//models(ib)%name//'/plastic_rotation', &
                                 hinge_influence(unc%yielding(ib), cpl%yielding(ib)), error)
         else
            call write_lambda_h5(h5, '/influence/'//models(ib)%name//'/ductility', lam_mu, error)
         end if
         if (.not. allocated(error)) call write_lambda_h5(h5, '/influence/'//models(ib)%name//'/residual_drift', &
                                                          lam_res, error)
         if (.not. allocated(error) .and. max(unc%yielding(ib)%collapse_storey, cpl%yielding(ib)%collapse_storey) > 0) &
            call h5_write_attr(h5, '/influence/'//models(ib)%name, 'meaningful', 'no: '// &
                               collapse_text(unc%yielding(ib), cpl%yielding(ib)), error)
         if (allocated(error)) return
      end do
   end subroutine write_yield_influence_h5

   !> Where and when a building collapsed, in which analyses (empty: no collapse).
   pure function collapse_text(unc, cpl) result(text)
      !> The building's storeys, uncoupled and coupled (n = 0: not run).
      type(storey_yield_result), intent(in) :: unc, cpl
      character(len=:), allocatable :: text

      text = ''
      if (unc%collapse_storey > 0) text = 'collapsed in the uncoupled analysis (storey '//str(unc%collapse_storey)// &
                                         ', t = '//str(unc%collapse_time)//' s)'
      if (cpl%collapse_storey > 0) then
         if (len(text) > 0) text = text//'; '
         text = text//'collapsed in the coupled analysis (storey '//str(cpl%collapse_storey)//', t = '// &
                str(cpl%collapse_time)//' s)'
      end if
   end function collapse_text

   !> The listing's table of every building with bilinear storeys: yield shear, hardening,
   !> ductility, residual drift (uncoupled, coupled and their lambdas) and hysteretic energy.
   subroutine write_yield_tables(lst, models, unc, cpl)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The uncoupled analysis.
      type(analysis_result), intent(in) :: unc
      !> The coupled analysis, when there is one.
      type(analysis_result), intent(in), optional :: cpl
      real(dp), allocatable :: lam_mu(:), lam_res(:)
      character(len=:), allocatable :: line
      logical :: both
      integer :: ib, j

      if (.not. allocated(unc%yielding)) return
      both = .false.
      if (present(cpl)) both = allocated(cpl%yielding)
      do ib = 1, size(models)
         if (unc%yielding(ib)%n == 0) cycle
         if (unc%yielding(ib)%n_hinges > 0) then
            if (both) then
               call write_hinge_table(lst, models(ib), unc%yielding(ib), cpl%yielding(ib))
            else
               call write_hinge_table(lst, models(ib), unc%yielding(ib))
            end if
            call lcp_lines()
            cycle
         end if
         call lst%put('')
         if (allocated(models(ib)%yield_k)) then
            call lst%put('  Bilinear planes of '//models(ib)%name//' (plane shear = spring force; mu = max|plane '// &
                         'storey drift| / (Fy/k), residual drift at the end; elastic planes not listed)')
         else
            call lst%put('  Bilinear storeys of '//models(ib)%name//' (storey shear Q = spring force; mu = '// &
                         'max|drift| / (Fy/k), residual drift at the end)')
         end if
         line = '  '//right_cell(trim(merge('plane storey', 'storey      ', allocated(models(ib)%yield_k))), &
                                 merge(13, 6, allocated(models(ib)%yield_k)))// &
                right_cell('Fy [kN]', 12)//right_cell('r', 8)// &
                right_cell('mu unc', 10)//right_cell('resid unc [mm]', 16)
         if (both) line = line//right_cell('mu cpl', 10)//right_cell('resid cpl [mm]', 16)// &
                          right_cell('lambda mu [%]', 15)//right_cell('lambda res [%]', 16)
         call lst%put(line)
         if (both) call yield_influence(unc%yielding(ib), cpl%yielding(ib), lam_mu, lam_res)
         do j = unc%yielding(ib)%n, 1, -1
            if (allocated(models(ib)%yield_k)) then
               if (models(ib)%yield_shear(j) >= never_yields) cycle
               line = '  '//right_cell(str(models(ib)%yield_plane(j)), 5)//right_cell(str(models(ib)%yield_storey(j)), 8)
            else
               line = '  '//right_cell(str(j), 6)
            end if
            line = line//fixed_cell(models(ib)%yield_shear(j), 12, 2)// &
                   fixed_cell(models(ib)%hardening(j), 8, 3)//fixed_cell(unc%yielding(ib)%ductility(j), 10, 3)// &
                   fixed_cell(1.0e3_dp*unc%yielding(ib)%residual_drift(j), 16, 4)
            if (both) line = line//fixed_cell(cpl%yielding(ib)%ductility(j), 10, 3)// &
                             fixed_cell(1.0e3_dp*cpl%yielding(ib)%residual_drift(j), 16, 4)// &
                             lambda_cell(lam_mu(j), 15)//lambda_cell(lam_res(j), 16)
            call lst%put(line)
         end do
         call lcp_lines()
      end do

   contains

      !> The building's hysteretic energy, LCP figures and collapse lines.
      subroutine lcp_lines()
         line = '  hysteretic energy: uncoupled '//str(unc%yielding(ib)%hysteretic)//' kJ'
         if (both) line = line//', coupled '//str(cpl%yielding(ib)%hysteretic)//' kJ'
         call lst%put(line)
         line = '  '//trim(merge('hinge LCPs: ', 'storey LCPs:', unc%yielding(ib)%n_hinges > 0))//' uncoupled '// &
                str(unc%yielding(ib)%solves)//' solves ('// &
                str(unc%yielding(ib)%lcp_rows)//' rows), largest residual '//str(unc%yielding(ib)%residual)
         if (both) line = line//'; coupled '//str(cpl%yielding(ib)%solves)//' solves ('// &
                          str(cpl%yielding(ib)%lcp_rows)//' rows), largest residual '//str(cpl%yielding(ib)%residual)// &
                          ', steps yielding with joints acting '//str(cpl%yielding(ib)%joint_steps)// &
                          ', LCP re-solves in a step at most (rows added; smooth joints: alternations) '// &
                          str(cpl%yielding(ib)%alternations)
         call lst%put(line)
         if (both) then
            line = collapse_text(unc%yielding(ib), cpl%yielding(ib))
         else
            line = collapse_text(unc%yielding(ib), storey_yield_result())
         end if
         if (len(line) > 0) call lst%put('  COLLAPSE: '//line//': storey drift / height passed collapse_drift, '// &
                                     'the building was frozen at the end of that step (no longer integrated, later '// &
                                     'samples hold the last, its joints opened; the other buildings went on); '// &
                                     'the influence coefficients of '//models(ib)%name//' are not meaningful')
      end subroutine lcp_lines

      !> A lambda right-aligned in `w` columns ('inf', 'n/m' or the number).
      function lambda_cell(lambda, w) result(cell)
         real(dp), intent(in) :: lambda
         integer, intent(in) :: w
         character(len=:), allocatable :: cell

         cell = lambda_text(lambda, w, 2)
      end function lambda_cell
   end subroutine write_yield_tables

   !> A building in plan's per-row values (planes in deck order, storey fastest) as the
   !> table (n_storeys, n_planes): h5py (n_planes, n_storeys).
   pure function plane_table(b, x) result(t)
      !> The building (`yield_k` allocated).
      type(structure_model), intent(in) :: b
      !> One value per yielding row.
      real(dp), intent(in) :: x(:)
      real(dp), allocatable :: t(:, :)
      integer :: ns

      ns = maxval(b%yield_storey)
      t = reshape(x, [ns, size(x)/ns])
   end function plane_table

   !> A table of lambdas (%) with the `not_meaningful` note where some are NaN.
   subroutine write_lambda_table_h5(h5, path, lam, error)
      type(h5_file), intent(inout) :: h5
      character(len=*), intent(in) :: path
      real(dp), intent(in) :: lam(:, :)
      type(error_type), allocatable, intent(out) :: error

      call h5_write(h5, path, lam, error, units='%')
      if (.not. allocated(error) .and. any(ieee_is_nan(lam))) &
         call h5_write_attr(h5, path, 'not_meaningful', 'NaN where the uncoupled value is 0 (an elastic plane, '// &
                            'or below the meaningful fraction of the largest)', error)
   end subroutine write_lambda_table_h5

end module pound_yield_output
