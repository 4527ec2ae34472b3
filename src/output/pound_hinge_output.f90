!> Outputs of a frame's plastic hinges (issue 25, `hinge_law = 'elastic_plastic'`,
!> pound_storey_yield_hinges): beside the datasets every inelastic building gets
!> (`residual_drift`, `hysteretic_energy`, the collapse attributes: pound_yield_output),
!>
!>     /<analysis>/<b>/hinges/plastic_rotation   (n_hinges) rad, peak |plastic rotation|
!>     /<analysis>/<b>/hinges/moment_ratio       (n_hinges) -, peak |end moment| / yield moment
!>     /influence/<b>/plastic_rotation           (n_hinges) %, lambda of the peak |plastic rotation|
!>     /model/<b>/hinges/element, kind (1 column, 2 beam), level (storey or floor), line, end
!>                                               (1 bottom/left, 2 top/right)  (n_hinges)
!>     /model/<b>/hinges/yield_moment            (n_hinges) kN m; attribute hinge_law of /model/<b>
!>     /model/<b>/hinges/hardening_modulus       (n_hinges) kN m/rad, H of |m - H p| <= My
!>
!> Hinge h is end 2 - mod(h, 2) of element (h + 1)/2 (the frame's element order). The listing's
!> table lists the hinges that yielded in some analysis.
module pound_hinge_output
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: fixed_cell, right_cell, str
   use pound_structure, only: structure_model
   use pound_storey_yield, only: storey_yield_result
   use pound_influence, only: influences
   use pound_influence_output, only: lambda_cell
   use pound_h5, only: h5_file, h5_write, h5_write_attr
   use pound_text_writer, only: text_writer
   implicit none
   private

   public :: write_hinge_model_h5, write_hinge_h5, hinge_influence, write_hinge_table

contains

   !> The hinges of a frame under its model group `g` ('/model/<b>/'); nothing without hinges.
   subroutine write_hinge_model_h5(h5, g, b, error)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> The building's model group, with a trailing '/'.
      character(len=*), intent(in) :: g
      !> The building.
      type(structure_model), intent(in) :: b
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      if (.not. allocated(b%hinge_moment)) return
      call h5_write(h5, g//'hinges/element', b%hinge_element, error, units='1')
      if (.not. allocated(error)) call h5_write(h5, g//'hinges/kind', b%hinge_kind, error, units='1')
      if (.not. allocated(error)) call h5_write_attr(h5, g//'hinges/kind', 'description', '1 column, 2 beam', error)
      if (.not. allocated(error)) call h5_write(h5, g//'hinges/level', b%hinge_level, error, units='1')
      if (.not. allocated(error)) call h5_write_attr(h5, g//'hinges/level', 'description', &
                                                    'storey of a column, floor of a beam', error)
      if (.not. allocated(error)) call h5_write(h5, g//'hinges/line', b%hinge_line, error, units='1')
      if (.not. allocated(error)) call h5_write(h5, g//'hinges/end', b%hinge_end, error, units='1')
      if (.not. allocated(error)) call h5_write_attr(h5, g//'hinges/end', 'description', &
                                                    '1 bottom (column) or left (beam) end, 2 top or right', error)
      if (.not. allocated(error)) call h5_write(h5, g//'hinges/yield_moment', b%hinge_moment, error, units='kN m')
      if (.not. allocated(error)) call h5_write(h5, g//'hinges/hardening_modulus', b%hinge_hardening, error, &
                                                units='kN m/rad')
      if (.not. allocated(error)) call h5_write_attr(h5, g//'hinges/hardening_modulus', 'description', &
                                                    'kinematic hardening H: |m - H p| <= My (0: elastic-perfectly plastic)', &
                                                    error)
      if (.not. allocated(error)) call h5_write_attr(h5, g(1:len(g) - 1), 'hinge_law', 'elastic_plastic', error)
   end subroutine write_hinge_model_h5

   !> The hinge results of one analysis of one building under `gb` ('/<analysis>/<b>/').
   subroutine write_hinge_h5(h5, gb, y, error)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> The building's analysis group, with a trailing '/'.
      character(len=*), intent(in) :: gb
      !> The building's hinge results.
      type(storey_yield_result), intent(in) :: y
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call h5_write(h5, gb//'hinges/plastic_rotation', y%rotation, error, units='rad')
      if (.not. allocated(error)) call h5_write_attr(h5, gb//'hinges/plastic_rotation', 'description', &
                                                    'peak |plastic rotation| of each hinge', error)
      if (.not. allocated(error)) call h5_write(h5, gb//'hinges/moment_ratio', y%moment_ratio, error, units='-')
      if (.not. allocated(error)) call h5_write_attr(h5, gb//'hinges/moment_ratio', 'description', &
                                                    'peak |end moment| / yield moment of each hinge', error)
   end subroutine write_hinge_h5

   !> lambda of each hinge's peak |plastic rotation|: (Qc - Qu)/Qu * 100.
   pure function hinge_influence(unc, cpl) result(lam)
      !> The building's hinges, uncoupled and coupled.
      type(storey_yield_result), intent(in) :: unc, cpl
      real(dp), allocatable :: lam(:)

      lam = influences(cpl%rotation, unc%rotation)
   end function hinge_influence

   !> The listing's table of a frame's hinges that yielded in some analysis.
   subroutine write_hinge_table(lst, b, unc, cpl)
      !> The listing writer.
      type(text_writer), intent(inout) :: lst
      !> The building.
      type(structure_model), intent(in) :: b
      !> The hinges, uncoupled and (when `both`) coupled.
      type(storey_yield_result), intent(in) :: unc
      type(storey_yield_result), intent(in), optional :: cpl
      character(len=:), allocatable :: line
      real(dp), allocatable :: lam(:)
      logical :: yielded
      integer :: h, k

      call lst%put('')
      if (any(b%hinge_hardening > 0.0_dp)) then
         line = 'kinematic hardening |m - H p| <= My'
      else
         line = 'elastic-perfectly plastic'
      end if
      call lst%put('  Plastic hinges of '//b%name//' that yielded ('//line//'; theta_p = peak '// &
                   '|plastic rotation|, m/My = peak |end moment| / yield moment)')
      line = '  '//right_cell('hinge', 6)//right_cell('member', 8)//right_cell('level', 6)//right_cell('line', 5)// &
             right_cell('end', 7)//right_cell('My [kNm]', 10)//right_cell('theta_p unc [mrad]', 20)// &
             right_cell('m/My unc', 9)
      if (present(cpl)) then
         line = line//right_cell('theta_p cpl [mrad]', 20)//right_cell('m/My cpl', 9)//right_cell('lambda [%]', 12)
         lam = hinge_influence(unc, cpl)
      end if
      call lst%put(line)
      k = 0
      do h = 1, unc%n_hinges
         yielded = unc%rotation(h) > 0.0_dp
         if (present(cpl)) yielded = yielded .or. cpl%rotation(h) > 0.0_dp
         if (.not. yielded) cycle
         k = k + 1
         line = '  '//right_cell(str(h), 6)//right_cell(trim(merge('column', 'beam  ', b%hinge_kind(h) == 1)), 8)// &
                right_cell(str(b%hinge_level(h)), 6)//right_cell(str(b%hinge_line(h)), 5)// &
                right_cell(trim(end_name(b%hinge_kind(h), b%hinge_end(h))), 7)//fixed_cell(b%hinge_moment(h), 10, 1)// &
                fixed_cell(1.0e3_dp*unc%rotation(h), 20, 4)//fixed_cell(unc%moment_ratio(h), 9, 3)
         if (present(cpl)) line = line//fixed_cell(1.0e3_dp*cpl%rotation(h), 20, 4)// &
                                  fixed_cell(cpl%moment_ratio(h), 9, 3)//lambda_text(lam(h))
         call lst%put(line)
      end do
      if (k == 0) call lst%put('  (none yielded)')
      line = '  residual drift [mm] by storey (1 first): uncoupled'
      do h = 1, unc%n
         line = line//' '//str(1.0e3_dp*unc%residual_drift(h))
      end do
      if (present(cpl)) then
         line = line//'; coupled'
         do h = 1, cpl%n
            line = line//' '//str(1.0e3_dp*cpl%residual_drift(h))
         end do
      end if
      call lst%put(line)

   contains

      pure function end_name(kind, e) result(s)
         integer, intent(in) :: kind, e
         character(len=6) :: s

         if (kind == 1) then
            s = merge('bottom', 'top   ', e == 1)
         else
            s = merge('left  ', 'right ', e == 1)
         end if
      end function end_name

      function lambda_text(x) result(s)
         real(dp), intent(in) :: x
         character(len=:), allocatable :: s

         s = lambda_cell(x, 12, 2)
      end function lambda_text
   end subroutine write_hinge_table

end module pound_hinge_output
