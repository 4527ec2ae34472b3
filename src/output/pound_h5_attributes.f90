!> The attribute writers of pound_h5 (generic `h5_write_attr`): an attribute goes on the
!> root, a group or a dataset named by its path and replaces one of the same name. Scalars
!> are written as HDF5 scalars (h5py reads a number, not shape (1,)), strings as
!> variable-length UTF-8, real 1-D attributes by H5LT.
submodule(pound_h5) pound_h5_attributes
   use hdf5, only: size_t, h5oopen_f, h5acreate_f, h5awrite_f, h5aexists_f, h5adelete_f, &
                   H5T_NATIVE_INTEGER, H5T_STD_I32LE
   use h5lt, only: h5ltset_attribute_double_f
   implicit none

contains

   !> String attribute (variable-length UTF-8, stored exactly as given).
   module subroutine write_attr_string(file, path, name, value, error)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Path of the object carrying the attribute ('/' for the root).
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> Text; may be long and contain newlines.
      character(len=*), intent(in) :: value
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(h5_ids) :: ids
      character(len=:), allocatable :: what
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), allocatable, target :: ptrs(:)
      integer(hsize_t) :: dims(0)
      integer :: hdferr

      what = "attribute '"//name//"' of"
      call string_type(ids%ftype, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'write', what, path, 'h5tcopy_f/h5tset_size_f failed')
      else
         call new_attribute(file, path, name, ids%ftype, dims, ids, error)
      end if
      if (.not. allocated(error)) then
         call pack_strings([len(value)], [value], chars, ptrs)
         call h5awrite_f(ids%attr, ids%ftype, c_loc(ptrs), hdferr)
         if (hdferr /= 0) call fail(error, file, 'write', what, path, 'h5awrite_f failed')
      end if
      call release(ids, file, 'write', what, path, error)
   end subroutine write_attr_string

   !> Real scalar attribute.
   module subroutine write_attr_real_0d(file, path, name, value, error)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Path of the object carrying the attribute ('/' for the root).
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> Value.
      real(dp), intent(in) :: value
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(h5_ids) :: ids
      integer(hsize_t) :: dims(0)
      integer :: hdferr

      call new_attribute(file, path, name, H5T_IEEE_F64LE, dims, ids, error)
      if (.not. allocated(error)) then
         call h5awrite_f(ids%attr, H5T_NATIVE_DOUBLE, value, [1_hsize_t], hdferr)
         if (hdferr /= 0) call fail(error, file, 'write', "attribute '"//name//"' of", path, &
                                    'h5awrite_f failed')
      end if
      call release(ids, file, 'write', "attribute '"//name//"' of", path, error)
   end subroutine write_attr_real_0d

   !> Real 1-D attribute (H5LT).
   module subroutine write_attr_real_1d(file, path, name, value, error)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Path of the object carrying the attribute ('/' for the root).
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> Values.
      real(dp), intent(in) :: value(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(h5_ids) :: ids
      character(len=:), allocatable :: p
      integer :: hdferr

      call open_carrier(file, path, .true., 'write', "attribute '"//name//"' of", ids, p, error)
      call release(ids, file, 'write', "attribute '"//name//"' of", p, error)
      if (allocated(error)) return
      call h5ltset_attribute_double_f(file%id, p, name, value, size(value, kind=size_t), hdferr)
      if (hdferr /= 0) call fail(error, file, 'write', "attribute '"//name//"' of", p, &
                                 'h5ltset_attribute_double_f failed')
   end subroutine write_attr_real_1d

   !> Integer scalar attribute (stored as 32-bit signed).
   module subroutine write_attr_int_0d(file, path, name, value, error)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Path of the object carrying the attribute ('/' for the root).
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> Value.
      integer, intent(in) :: value
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(h5_ids) :: ids
      integer(hsize_t) :: dims(0)
      integer :: hdferr

      call new_attribute(file, path, name, H5T_STD_I32LE, dims, ids, error)
      if (.not. allocated(error)) then
         call h5awrite_f(ids%attr, H5T_NATIVE_INTEGER, value, [1_hsize_t], hdferr)
         if (hdferr /= 0) call fail(error, file, 'write', "attribute '"//name//"' of", path, &
                                    'h5awrite_f failed')
      end if
      call release(ids, file, 'write', "attribute '"//name//"' of", path, error)
   end subroutine write_attr_int_0d

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
      call new_space(dims, ids, file, 'write', what, p, error)
      if (allocated(error)) return
      call h5acreate_f(ids%obj, name, ftype, ids%space, ids%attr, hdferr)
      if (hdferr /= 0) then
         ids%attr = -1_hid_t
         call fail(error, file, 'write', what, p, 'h5acreate_f failed')
      end if
   end subroutine new_attribute

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
      call path_exists(file, p, there, error)
      if (allocated(error)) return
      if (.not. there) then
         call fail(error, file, action, what, p, 'no such object')
         return
      end if
      call h5oopen_f(file%id, p, ids%obj, hdferr)
      if (hdferr /= 0) then
         ids%obj = -1_hid_t
         call fail(error, file, action, what, p, 'h5oopen_f failed')
      end if
   end subroutine open_carrier

end submodule pound_h5_attributes
