!> The engineering summary (`pound_summary`) as a file and in the results file.
!>
!> `<stem>_summary.csv` (`write_summary_csv`; RFC 4180: comma-separated, a field holding a
!> comma, a double quote or a line end is quoted, its quotes doubled), one header line then one
!> row per item, in the summary's order:
!>
!>     kind,subject,quantity,value,unit,location,time
!>
!> * kind: `suite`, `building`, `pair`, `collapse`, `failed` or `warning`;
!> * subject: the building's name, the pair's label (`A:1-B:1`), or `suite` / `run`;
!> * quantity: the item's machine name (`refined_gap_mean`, `lambda_storey_shear`, ...);
!> * value: the number in `unit` with 17 significant digits, `n/a` when it cannot be given
!>   (`location` says why), `inf` for a lambda whose uncoupled peak is 0, `n/m` for a lambda
!>   that is not meaningful (its uncoupled peak below 1e-6 of the building's largest);
!> * unit: `mm`, `%`, `kN`, `-` (a count or a ratio) or empty (a text item);
!> * location: where (storey, column segment, joint, motion), or why the value is n/a, or the
!>   text of a warning;
!> * time: the time of the peak (s; coupled run), empty when none.
!>
!> HDF5 root attributes (`write_summary_attributes`), every run: `summary` (the summary's text
!> lines); a suite (several `&ground`) adds its answer: `suite_answer` (one line),
!> `suite_refined_gap_mean`, `suite_refined_gap_every`, `suite_safe_gap_mean`,
!> `suite_safe_gap_every` (m, as `/suite/sweep`, -1: none), `suite_motions`,
!> `suite_motions_used`, `suite_failed_cases`, with contact per building in deck order the
!> signed storey-shear lambda (%) of largest |lambda| over the storeys of the suite mean of the
!> lambdas, of any one motion and of the mean peaks (`suite_mean_lambda_storey_shear`,
!> `suite_max_lambda_storey_shear`, `suite_lambda_of_means_storey_shear`), and the
!> single-motion case of `/uncoupled`, `/coupled`, `/sweep`: `single_motion` (its name),
!> `single_motion_index` (1-based), `single_motion_heading` ('motion k of n: NAME').
module pound_summary_output
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_text_writer, only: text_writer, open_text, close_text
   use pound_h5, only: h5_file, h5_open, h5_close, h5_write_attr
   use pound_suite_statistics, only: suite_result
   use pound_summary, only: summary_item, motion_heading, suite_answer_line
   implicit none
   private

   public :: write_summary_csv, write_summary_attributes, summary_attribute_text, csv_header, csv_row

   !> The header line of the CSV file.
   character(len=*), parameter :: csv_header = 'kind,subject,quantity,value,unit,location,time'

contains

   !> One CSV row of an item (no line end).
   pure function csv_row(it) result(row)
      !> The item.
      type(summary_item), intent(in) :: it
      character(len=:), allocatable :: row
      character(len=32) :: buf

      if (.not. it%available) then
         buf = 'n/a'
      else if (ieee_is_nan(it%value)) then
         buf = 'n/m'
      else if (it%value >= huge(1.0_dp)) then
         buf = 'inf'
      else if (it%unit == '-' .and. it%value == aint(it%value) .and. abs(it%value) < 1.0e9_dp) then
         write (buf, '(i0)') nint(it%value)
      else
         write (buf, '(es24.16e3)') it%value
         buf = adjustl(buf)
      end if
      row = field(it%kind)//','//field(it%subject)//','//field(it%quantity)//','//trim(buf)//','// &
            field(it%unit)//','//field(it%location)//','
      if (it%time >= 0.0_dp) then
         write (buf, '(es24.16e3)') it%time
         row = row//trim(adjustl(buf))
      end if

   contains

      pure function field(text) result(f)
         character(len=*), intent(in) :: text
         character(len=:), allocatable :: f
         integer :: i

         f = trim(text)
         if (scan(f, ',"'//achar(10)//achar(13)) == 0) return
         f = '"'
         do i = 1, len_trim(text)
            if (text(i:i) == '"') then
               f = f//'""'
            else
               f = f//text(i:i)
            end if
         end do
         f = f//'"'
      end function field

   end function csv_row

   !> Write the items to `path` (this run's temporary): every write checked, and the file's
   !> size checked against what was written (a buffer the system refused is an error).
   subroutine write_summary_csv(path, items, error)
      !> File (created or truncated).
      character(len=*), intent(in) :: path
      !> The summary.
      type(summary_item), intent(in) :: items(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(text_writer) :: w
      integer :: i

      call open_text(path, 'summary', w, error)
      if (allocated(error)) return
      call w%put(csv_header)
      do i = 1, size(items)
         if (w%ios /= 0) exit
         call w%put(csv_row(items(i)))
      end do
      call close_text(w, error)
   end subroutine write_summary_csv

   !> Root attributes of the results file at `path` (written and closed): `summary`, and with
   !> The summary's text lines as one text (the root attribute `summary`), each line ended
   !> by a line feed.
   pure function summary_attribute_text(lines) result(text)
      !> The summary's text lines (`summary_lines`).
      character(len=*), intent(in) :: lines(:)
      character(len=:), allocatable :: text
      integer :: i

      text = ''
      do i = 1, size(lines)
         text = text//trim(lines(i))//new_line('a')
      end do
   end function summary_attribute_text

   !> `suite` its answer and single-motion case (see the module notes).
   subroutine write_summary_attributes(path, items, lines, error, suite)
      !> Results file.
      character(len=*), intent(in) :: path
      !> The summary's items (`build_summary`).
      type(summary_item), intent(in) :: items(:)
      !> The summary's text lines (`summary_lines`).
      character(len=*), intent(in) :: lines(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The suite, for a deck with several `&ground`.
      type(suite_result), intent(in), optional :: suite
      type(error_type), allocatable :: close_error
      type(h5_file) :: h5
      character(len=:), allocatable :: text

      text = summary_attribute_text(lines)
      call h5_open(h5, path, error, writable=.true.)
      if (allocated(error)) return
      call h5_write_attr(h5, '/', 'summary', text, error)
      if (present(suite) .and. .not. allocated(error)) call suite_attributes(suite)
      call h5_close(h5, close_error)
      if (allocated(close_error) .and. .not. allocated(error)) call move_alloc(close_error, error)

   contains

      subroutine suite_attributes(s)
         type(suite_result), intent(in) :: s

         call h5_write_attr(h5, '/', 'suite_answer', suite_answer_line(s), error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'suite_refined_gap_mean', s%refined_gap_mean, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'suite_refined_gap_every', s%refined_gap_every, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'suite_safe_gap_mean', s%safe_gap_mean, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'suite_safe_gap_every', s%safe_gap_every, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'suite_motions', size(s%names), error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'suite_motions_used', s%n_used, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'suite_failed_cases', size(s%failures), error)
         if (s%first < 1 .or. s%first > size(s%names)) return
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'single_motion', trim(s%names(s%first)), error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'single_motion_index', s%first, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/', 'single_motion_heading', motion_heading(s), error)
         if (.not. allocated(error)) call per_building('mean_lambda_storey_shear')
         if (.not. allocated(error)) call per_building('max_lambda_storey_shear')
         if (.not. allocated(error)) call per_building('lambda_of_means_storey_shear')
      end subroutine suite_attributes

      !> Root attribute suite_<quantity>: the suite items of that quantity, one per building in
      !> deck order (none without contact).
      subroutine per_building(quantity)
         character(len=*), intent(in) :: quantity
         real(dp), allocatable :: v(:)
         integer :: k

         allocate (v(0))
         do k = 1, size(items)
            if (items(k)%kind == 'suite' .and. items(k)%quantity == quantity) v = [v, items(k)%value]
         end do
         if (size(v) > 0) call h5_write_attr(h5, '/', 'suite_'//quantity, v, error)
      end subroutine per_building

   end subroutine write_summary_attributes

end module pound_summary_output
