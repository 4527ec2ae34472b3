!> The attribute writers of pound_h5 (generic `h5_write_attr`): an attribute goes on the
!> root, a group or a dataset named by its path and replaces one of the same name. Scalars
!> are written as HDF5 scalars (h5py reads a number, not shape (1,)), strings as
!> variable-length UTF-8, real 1-D attributes as native doubles.
submodule(pound_h5) pound_h5_attributes
   use hdf5, only: h5lexists_f, h5oopen_f, h5acreate_f, h5awrite_f, h5aexists_f, h5adelete_f, H5T_STD_I32LE
   implicit none

contains

   !> String attribute (variable-length UTF-8, stored exactly as given).
   module procedure write_attr_string
      type(h5_ids) :: ids
      character(len=:), allocatable :: what
      integer(hsize_t) :: dims(0)
      integer :: hdferr

      what = "attribute '"//name//"' of"
      call string_type(ids%ftype, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'write', what, path, 'h5tcopy_f/h5tset_size_f failed')
      else
         call new_attribute(file, path, name, ids%ftype, dims, ids, error)
      end if
      if (.not. allocated(error)) call put_string(ids, file, what, path, value, error)
      call release(ids, file, 'write', what, path, error)
   end procedure write_attr_string

   !> String attribute `name` (variable-length UTF-8) of the open object `obj` at `p`, which
   !> has none of that name (a dataset just created): no path walk.
   module procedure string_attribute_on
      type(h5_ids) :: ids
      character(len=:), allocatable :: what
      integer(hsize_t) :: dims(0)
      integer :: hdferr

      if (allocated(error)) return
      what = "attribute '"//name//"' of"
      call string_type(ids%ftype, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'write', what, p, 'h5tcopy_f/h5tset_size_f failed')
      else
         call create_attribute(obj, file, p, name, ids%ftype, dims, ids, error)
      end if
      if (.not. allocated(error)) call put_string(ids, file, what, p, value, error)
      call release(ids, file, 'write', what, p, error)
   end procedure string_attribute_on

   !> Write `value` into the open variable-length string attribute of `ids`.
   subroutine put_string(ids, file, what, path, value, error)
      type(h5_ids), intent(in) :: ids
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: what, path, value
      type(error_type), allocatable, intent(inout) :: error
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), allocatable, target :: ptrs(:)
      integer :: hdferr

      call pack_strings([len(value)], [value], chars, ptrs)
      call h5awrite_f(ids%attr, ids%ftype, c_loc(ptrs), hdferr)
      if (hdferr /= 0) call fail(error, file, 'write', what, path, 'h5awrite_f failed')
   end subroutine put_string

   !> Real scalar attribute.
   module procedure write_attr_real_0d
      real(dp), target :: v(1)
      integer(hsize_t) :: dims(0)

      v(1) = value
      call numeric_attribute(file, path, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dims, c_loc(v), error)
   end procedure write_attr_real_0d

   !> Real 1-D attribute (native doubles).
   module procedure write_attr_real_1d
      real(dp), allocatable, target :: packed(:)

      packed = value
      call numeric_attribute(file, path, name, H5T_NATIVE_DOUBLE, H5T_NATIVE_DOUBLE, shape(value, kind=hsize_t), &
                             c_loc(packed), error)
   end procedure write_attr_real_1d

   !> Integer scalar attribute (stored as 32-bit signed).
   module procedure write_attr_int_0d
      integer, target :: v(1)
      integer(hsize_t) :: dims(0)

      v(1) = value
      call numeric_attribute(file, path, name, H5T_STD_I32LE, H5T_NATIVE_INTEGER, dims, c_loc(v), error)
   end procedure write_attr_int_0d

   !> Numeric attribute `name` of file type `ftype` and shape `dims` (none: a scalar) on the
   !> object at `path`, written from `buffer` of memory type `mtype`.
   subroutine numeric_attribute(file, path, name, ftype, mtype, dims, buffer, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, name
      integer(hid_t), intent(in) :: ftype, mtype
      integer(hsize_t), intent(in) :: dims(:)
      type(c_ptr), intent(in) :: buffer
      type(error_type), allocatable, intent(out) :: error
      type(h5_ids) :: ids
      integer :: hdferr

      call new_attribute(file, path, name, ftype, dims, ids, error)
      if (.not. allocated(error)) then
         call h5awrite_f(ids%attr, mtype, buffer, hdferr)
         if (hdferr /= 0) call fail(error, file, 'write', "attribute '"//name//"' of", path, 'h5awrite_f failed')
      end if
      call release(ids, file, 'write', "attribute '"//name//"' of", path, error)
   end subroutine numeric_attribute

   !> Open the object at `path`; delete attribute `name` if present; create it anew.
   subroutine new_attribute(file, path, name, ftype, dims, ids, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, name
      integer(hid_t), intent(in) :: ftype
      integer(hsize_t), intent(in) :: dims(:)
      type(h5_ids), intent(inout) :: ids
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: p, what
      logical :: there
      integer :: hdferr

      what = "attribute '"//name//"' of"
      call open_carrier(file, path, .true., 'write', what, ids, p, error)
      if (allocated(error)) return
      call h5aexists_f(ids%obj, name, there, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'write', what, p, 'h5aexists_f failed')
         return
      end if
      if (there) then
         call h5adelete_f(ids%obj, name, hdferr)
         if (hdferr /= 0) then
            call fail(error, file, 'write', what, p, 'h5adelete_f failed (replacing it)')
            return
         end if
      end if
      call create_attribute(ids%obj, file, p, name, ftype, dims, ids, error)
   end subroutine new_attribute

   !> Create attribute `name` of type `ftype` and shape `dims` on the open object `obj` (at
   !> `p`, for messages), which has none of that name: its space and identifier into `ids`.
   subroutine create_attribute(obj, file, p, name, ftype, dims, ids, error)
      integer(hid_t), intent(in) :: obj
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: p, name
      integer(hid_t), intent(in) :: ftype
      integer(hsize_t), intent(in) :: dims(:)
      type(h5_ids), intent(inout) :: ids
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: what
      integer :: hdferr

      what = "attribute '"//name//"' of"
      call new_space(dims, ids, file, 'write', what, p, error)
      if (allocated(error)) return
      call h5acreate_f(obj, name, ftype, ids%space, ids%attr, hdferr)
      if (hdferr /= 0) then
         ids%attr = -1_hid_t
         call fail(error, file, 'write', what, p, 'h5acreate_f failed')
      end if
   end subroutine create_attribute

   !> Open the group or dataset at `path` that carries attributes.
   subroutine open_carrier(file, path, write, action, what, ids, p, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      logical, intent(in) :: write
      character(len=*), intent(in) :: action, what
      type(h5_ids), intent(inout) :: ids
      character(len=:), allocatable, intent(out) :: p
      type(error_type), allocatable, intent(out) :: error
      logical :: there
      integer :: hdferr

      call check_path(file, path, write, action, p, error)
      if (allocated(error)) return
      ! Opened at once (one look-up); why it failed is asked afterwards (h5lexists_f fails
      ! when a group above it is missing).
      call h5oopen_f(file%id, p, ids%obj, hdferr)
      if (hdferr == 0) return
      ids%obj = -1_hid_t
      there = p == '/'
      if (.not. there) then
         call h5lexists_f(file%id, p, there, hdferr)
         if (hdferr /= 0) there = .false.
      end if
      if (there) then
         call fail(error, file, action, what, p, 'h5oopen_f failed')
      else
         call fail(error, file, action, what, p, 'no such object')
      end if
   end subroutine open_carrier

end submodule pound_h5_attributes
