!> What a model writes through without knowing the file: `model_sink`, an abstract sink of
!> named datasets (the HDF5 writer extends it: `pound_h5_sink`), and `text_lines`, the lines
!> of a description (the listing writes them). A building kind (`pound_building_kind`) answers
!> "describe yourself" and "write your data" through these two, so the writers do not
!> branch on the kind and the model does not use the output layer.
module pound_model_sink
   use pound_kinds, only: dp
   use pound_error, only: error_type
   implicit none
   private

   public :: model_sink, text_line, text_lines

   !> One line of text.
   type :: text_line
      !> The text (no trailing newline).
      character(len=:), allocatable :: text
   end type text_line

   !> A growing list of lines.
   type :: text_lines
      !> The lines, in order (`n` of them are used).
      type(text_line), allocatable :: line(:)
      !> Number of lines.
      integer :: n = 0
   contains
      !> Append one line.
      procedure :: add => lines_add
   end type text_lines

   !> A sink of named datasets, each with its units and, for tables, a `columns` attribute
   !> naming the columns. Names are relative to the sink's place (e.g. the building's group).
   type, abstract :: model_sink
   contains
      !> A vector of reals.
      procedure(put_reals), deferred :: reals
      !> A table of reals, (rows, columns).
      procedure(put_real_table), deferred :: real_table
      !> A table of integers, (rows, columns).
      procedure(put_int_table), deferred :: int_table
   end type model_sink

   abstract interface
      !> Write a vector of reals.
      subroutine put_reals(sink, name, values, units, error)
         import :: model_sink, dp, error_type
         !> The sink.
         class(model_sink), intent(inout) :: sink
         !> Dataset name.
         character(len=*), intent(in) :: name
         !> Values.
         real(dp), intent(in) :: values(:)
         !> Units.
         character(len=*), intent(in) :: units
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine put_reals

      !> Write a table of reals and its column names.
      subroutine put_real_table(sink, name, values, units, columns, error)
         import :: model_sink, dp, error_type
         !> The sink.
         class(model_sink), intent(inout) :: sink
         !> Dataset name.
         character(len=*), intent(in) :: name
         !> Values (rows, columns).
         real(dp), intent(in) :: values(:, :)
         !> Units, and the names of the columns.
         character(len=*), intent(in) :: units, columns
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine put_real_table

      !> Write a table of integers and its column names.
      subroutine put_int_table(sink, name, values, units, columns, error)
         import :: model_sink, error_type
         !> The sink.
         class(model_sink), intent(inout) :: sink
         !> Dataset name.
         character(len=*), intent(in) :: name
         !> Values (rows, columns).
         integer, intent(in) :: values(:, :)
         !> Units, and the names of the columns.
         character(len=*), intent(in) :: units, columns
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine put_int_table
   end interface

contains

   !> Append `text` (capacity doubles when full).
   pure subroutine lines_add(lines, text)
      !> The list.
      class(text_lines), intent(inout) :: lines
      !> The line.
      character(len=*), intent(in) :: text
      type(text_line), allocatable :: grown(:)
      integer :: k

      if (.not. allocated(lines%line)) allocate (lines%line(16))
      if (lines%n == size(lines%line)) then
         allocate (grown(2*size(lines%line)))
         do k = 1, lines%n
            call move_alloc(lines%line(k)%text, grown(k)%text)
         end do
         call move_alloc(grown, lines%line)
      end if
      lines%n = lines%n + 1
      lines%line(lines%n)%text = text
   end subroutine lines_add

end module pound_model_sink
