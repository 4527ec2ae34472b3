!> The result rows of a model (`structure_model%result_rows` in its named groups
!> `structure_model%result`: a building in plan's plane shears and floor rotations) in the
!> results file and the listing: `/<analysis>/<b>/peak/<name>` and `peak_time/<name>` and
!> `/influence/<b>/<name>`, each of the group's shape (`result_group%extent`, Fortran order:
!> h5py reads it reversed), and a listing table per building and group.
module pound_result_groups_output
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str, fixed_cell, right_cell
   use pound_structure, only: structure_model
   use pound_h5, only: h5_file, h5_write, h5_write_attr
   use pound_text_writer, only: text_writer
   use pound_analysis, only: analysis_result
   use pound_influence, only: building_influence
   use pound_influence_output, only: lambda_cell
   implicit none
   private

   public :: write_result_groups_h5, write_result_groups_listing

contains

   !> The values `x` of model `b`'s result rows, group by group, as the datasets
   !> `base`//<name> of the group's shape, in the group's units (`units` when given); entries
   !> that are NaN get the attribute `not_meaningful`.
   subroutine write_result_groups_h5(h5, base, b, x, error, units)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> Path prefix (e.g. '/coupled/A/peak/').
      character(len=*), intent(in) :: base
      !> The model.
      type(structure_model), intent(in) :: b
      !> One value per result row.
      real(dp), intent(in) :: x(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Units of every group (e.g. 's', '%'); absent: the group's own.
      character(len=*), intent(in), optional :: units
      character(len=:), allocatable :: path, u
      real(dp), allocatable :: v1(:), v2(:, :)
      integer :: g, i0, nv

      if (.not. allocated(b%result)) return
      do g = 1, size(b%result)
         associate (grp => b%result(g))
            path = base//trim(grp%name)
            u = trim(grp%units)
            if (present(units)) u = units
            i0 = grp%first
            nv = product(grp%extent)
            if (size(grp%extent) == 2) then
               v2 = reshape(x(i0:i0 + nv - 1), [grp%extent(1), grp%extent(2)])
               call h5_write(h5, path, v2, error, units=u)
            else
               v1 = x(i0:i0 + nv - 1)
               call h5_write(h5, path, v1, error, units=u)
            end if
            if (allocated(error)) return
            call h5_write_attr(h5, path, 'description', trim(grp%description), error)
            if (allocated(error)) return
            if (any(ieee_is_nan(x(i0:i0 + nv - 1)))) then
               call h5_write_attr(h5, path, 'not_meaningful', 'NaN where the uncoupled peak is 0 (or below '// &
                                  'the meaningful fraction of the group''s largest)', error)
               if (allocated(error)) return
            end if
         end associate
      end do
   end subroutine write_result_groups_h5

   !> Per building with result rows and per group: the peaks, uncoupled and (with `cpl`)
   !> coupled with lambda, one line per entry (a two-index group: first index the group's
   !> slow one, e.g. the plane, then the storey).
   subroutine write_result_groups_listing(lst, models, unc, cpl, infl)
      !> The listing writer.
      type(text_writer), intent(inout) :: lst
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> Coupled result and the influence coefficients.
      type(analysis_result), intent(in), optional :: cpl
      type(building_influence), intent(in), optional :: infl(:)
      character(len=:), allocatable :: line, title
      integer :: ib, g, i, k, n1, n2
      logical :: both, first

      first = .true.
      do ib = 1, size(models)
         if (.not. allocated(models(ib)%result) .or. .not. allocated(unc%building(ib)%result_peak)) cycle
         both = present(cpl) .and. present(infl)
         if (both) both = allocated(cpl%building(ib)%result_peak) .and. allocated(infl(ib)%result_lambda)
         if (first) then
            title = 'Result rows: peak absolute values (buildings in plan: plane storey shears, floor rotations)'
            if (both) title = title//', uncoupled (u), coupled (c), lambda [%]'
            write (lst%unit, '(/,a,/,a)', iostat=lst%ios, iomsg=lst%msg) title, repeat('-', len(title))
            call lst%note()
         end if
         first = .false.
         do g = 1, size(models(ib)%result)
            associate (grp => models(ib)%result(g))
               write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Building '//models(ib)%name//': '// &
                  trim(grp%name)//' ['//trim(grp%units)//']: '//trim(grp%description)
               call lst%note()
               n1 = grp%extent(1)
               n2 = 1
               if (size(grp%extent) == 2) n2 = grp%extent(2)
               if (size(grp%extent) == 2) then
                  line = '      i      j'
               else
                  line = '      i'
               end if
               line = line//'           u'
               if (both) line = line//'           c    lambda'
               write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) line
               call lst%note()
               do i = 1, n2
                  do k = 1, n1
                     associate (r => grp%first + (i - 1)*n1 + k - 1)
                        if (size(grp%extent) == 2) then
                           line = '  '//right_cell(str(i), 5)//'  '//right_cell(str(k), 5)
                        else
                           line = '  '//right_cell(str(k), 5)
                        end if
                        line = line//'  '//fixed_cell(unc%building(ib)%result_peak(r), 10, 5, .true.)
                        if (both) line = line//'  '//fixed_cell(cpl%building(ib)%result_peak(r), 10, 5, .true.)// &
                                         lambda_cell(infl(ib)%result_lambda(r), 10, 2)
                        write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) line
                        call lst%note()
                     end associate
                  end do
               end do
            end associate
         end do
      end do
   end subroutine write_result_groups_listing

end module pound_result_groups_output
