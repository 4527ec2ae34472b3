!> The results file as a `model_sink`: a building kind's datasets go to one group of the
!> open HDF5 file (`/model/<b>/`), tables with their `columns` attribute.
module pound_h5_sink
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_model_sink, only: model_sink
   use pound_h5, only: h5_file, h5_write, h5_write_attr
   implicit none
   private

   public :: h5_sink

   !> A group of an open HDF5 file.
   type, extends(model_sink) :: h5_sink
      !> The file (open for writing).
      type(h5_file) :: file
      !> The group's path, with its trailing '/'.
      character(len=:), allocatable :: group
   contains
      procedure :: reals => sink_reals
      procedure :: real_table => sink_real_table
      procedure :: int_table => sink_int_table
   end type h5_sink

contains

   !> A vector of reals.
   subroutine sink_reals(sink, name, values, units, error)
      !> The sink.
      class(h5_sink), intent(inout) :: sink
      !> Dataset name.
      character(len=*), intent(in) :: name
      !> Values.
      real(dp), intent(in) :: values(:)
      !> Units.
      character(len=*), intent(in) :: units
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call h5_write(sink%file, sink%group//name, values, error, units=units)
   end subroutine sink_reals

   !> A table of reals and its `columns` attribute.
   subroutine sink_real_table(sink, name, values, units, columns, error)
      !> The sink.
      class(h5_sink), intent(inout) :: sink
      !> Dataset name.
      character(len=*), intent(in) :: name
      !> Values (rows, columns).
      real(dp), intent(in) :: values(:, :)
      !> Units, and the names of the columns.
      character(len=*), intent(in) :: units, columns
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call h5_write(sink%file, sink%group//name, values, error, units=units)
      if (allocated(error)) return
      call h5_write_attr(sink%file, sink%group//name, 'columns', columns, error)
   end subroutine sink_real_table

   !> A table of integers and its `columns` attribute.
   subroutine sink_int_table(sink, name, values, units, columns, error)
      !> The sink.
      class(h5_sink), intent(inout) :: sink
      !> Dataset name.
      character(len=*), intent(in) :: name
      !> Values (rows, columns).
      integer, intent(in) :: values(:, :)
      !> Units, and the names of the columns.
      character(len=*), intent(in) :: units, columns
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call h5_write(sink%file, sink%group//name, values, error, units=units)
      if (allocated(error)) return
      call h5_write_attr(sink%file, sink%group//name, 'columns', columns, error)
   end subroutine sink_int_table

end module pound_h5_sink
