!> Readers of pound's HDF5 files, for the tests only (the library writes, it never reads).
!>
!> Numbers through H5LT (`h5ltget_dataset_info_f`, `h5ltread_dataset_double_f`,
!> `h5ltget_attribute_double_f`, ...), variable-length strings through the plain API (H5LT
!> reads only fixed-length ones). Values come back in the Fortran shape they were written
!> with (see pound_h5); `h5_dataset_dims` gives the C-order shape h5py reports. A failure
!> is one message naming the file, the object and the reason, as pound_h5's are.
module pound_test_h5
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char, c_null_ptr, c_associated, &
                                          c_f_pointer, c_size_t
   use hdf5, only: hid_t, hsize_t, size_t, h5oopen_f, h5oclose_f, h5iget_type_f, H5I_DATASET_F, &
                   h5aexists_by_name_f, h5aopen_by_name_f, h5aclose_f, h5aread_f, h5aget_space_f, &
                   h5dopen_f, h5dclose_f, h5dread_f, h5dget_space_f, h5sclose_f, &
                   h5sget_simple_extent_npoints_f, h5dvlen_reclaim_f, h5tcopy_f, h5tclose_f, &
                   h5tset_size_f, h5tset_cset_f, H5T_C_S1, H5T_CSET_UTF8_F, H5P_DEFAULT_F, &
                   H5T_FLOAT_F, H5T_INTEGER_F, H5T_STRING_F
   use h5lt, only: h5ltget_dataset_ndims_f, h5ltget_dataset_info_f, h5ltread_dataset_double_f, &
                   h5ltread_dataset_int_f, h5ltget_attribute_ndims_f, h5ltget_attribute_info_f, &
                   h5ltget_attribute_double_f, h5ltget_attribute_int_f
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_h5, only: h5_file, h5_file_id, h5_file_name, h5_exists
   implicit none
   private

   public :: h5_read, h5_read_attr, h5_dataset_dims

   !> Read a whole dataset: `call h5_read(file, path, values, error)` with `values` real(dp)
   !> scalar, or allocatable real(dp) 1-D / 2-D, integer 1-D or character(len=:) 1-D.
   interface h5_read
      module procedure read_real_0d, read_real_1d, read_real_2d, read_int_1d, read_string_1d
   end interface h5_read

   !> Get an attribute: `call h5_read_attr(file, path, name, value, error)` with `value` an
   !> allocatable character(len=:), real(dp) scalar, allocatable real(dp) 1-D, or integer.
   interface h5_read_attr
      module procedure read_attr_string, read_attr_real_0d, read_attr_real_1d, read_attr_int_0d
   end interface h5_read_attr

   interface
      !> C `strlen`.
      function c_strlen(s) bind(C, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen
   end interface

contains

   !> Dimensions of the dataset at `path` in HDF5's C order (h5py's shape); empty for a scalar.
   subroutine h5_dataset_dims(file, path, dims, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      integer, allocatable, intent(out) :: dims(:)
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t), allocatable :: fdims(:)
      character(len=:), allocatable :: p
      integer :: class

      call dataset_info(file, path, -1, p, fdims, class, error)
      if (allocated(error)) return
      dims = int(fdims(size(fdims):1:-1))
   end subroutine h5_dataset_dims

   !> Real scalar dataset (any dataset holding exactly one number).
   subroutine read_real_0d(file, path, values, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      real(dp), intent(out) :: values
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: buf(1)
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p
      integer :: class, hdferr

      values = 0.0_dp
      call dataset_info(file, path, -1, p, dims, class, error)
      if (allocated(error)) return
      call need_numbers(class, file, 'dataset', p, error)
      if (allocated(error)) return
      if (product(dims) /= 1) then
         call fail(error, file, 'dataset', p, 'holds '//str(int(product(dims)))//' values, expected one')
         return
      end if
      call h5ltread_dataset_double_f(h5_file_id(file), p, buf, [1_hsize_t], hdferr)
      if (hdferr /= 0) call fail(error, file, 'dataset', p, 'h5ltread_dataset_double_f failed')
      values = buf(1)
   end subroutine read_real_0d

   !> Real 1-D dataset.
   subroutine read_real_1d(file, path, values, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      real(dp), allocatable, intent(out) :: values(:)
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p
      integer :: class, hdferr

      call dataset_info(file, path, 1, p, dims, class, error)
      if (.not. allocated(error)) call need_numbers(class, file, 'dataset', p, error)
      if (allocated(error)) dims = 0
      allocate (values(dims(1)))
      if (allocated(error) .or. size(values) == 0) return
      call h5ltread_dataset_double_f(h5_file_id(file), p, values, dims, hdferr)
      if (hdferr /= 0) call fail(error, file, 'dataset', p, 'h5ltread_dataset_double_f failed')
   end subroutine read_real_1d

   !> Real 2-D dataset, in the Fortran shape it was written with.
   subroutine read_real_2d(file, path, values, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      real(dp), allocatable, intent(out) :: values(:, :)
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p
      integer :: class, hdferr

      call dataset_info(file, path, 2, p, dims, class, error)
      if (.not. allocated(error)) call need_numbers(class, file, 'dataset', p, error)
      if (allocated(error)) dims = 0
      allocate (values(dims(1), dims(2)))
      if (allocated(error) .or. size(values) == 0) return
      call h5ltread_dataset_double_f(h5_file_id(file), p, values, dims, hdferr)
      if (hdferr /= 0) call fail(error, file, 'dataset', p, 'h5ltread_dataset_double_f failed')
   end subroutine read_real_2d

   !> Integer 1-D dataset.
   subroutine read_int_1d(file, path, values, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      integer, allocatable, intent(out) :: values(:)
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p
      integer :: class, hdferr

      call dataset_info(file, path, 1, p, dims, class, error)
      if (.not. allocated(error) .and. class /= H5T_INTEGER_F) &
         call fail(error, file, 'dataset', p, 'the stored values are not integers')
      if (allocated(error)) dims = 0
      allocate (values(dims(1)))
      if (allocated(error) .or. size(values) == 0) return
      call h5ltread_dataset_int_f(h5_file_id(file), p, values, dims, hdferr)
      if (hdferr /= 0) call fail(error, file, 'dataset', p, 'h5ltread_dataset_int_f failed')
   end subroutine read_int_1d

   !> 1-D dataset of variable-length strings.
   subroutine read_string_1d(file, path, values, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: values(:)
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p, text
      integer, allocatable :: lengths(:)
      integer(hid_t) :: dset
      integer :: class, hdferr, i, pos

      call dataset_info(file, path, 1, p, dims, class, error)
      if (allocated(error)) then
         allocate (character(len=0) :: values(0))
         return
      end if
      call h5dopen_f(h5_file_id(file), p, dset, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'dataset', p, 'h5dopen_f failed')
         allocate (character(len=0) :: values(0))
         return
      end if
      call read_vlen(dset, .false., class, int(dims(1)), file, 'dataset', p, text, lengths, error)
      call h5dclose_f(dset, hdferr)
      if (allocated(error)) then
         allocate (character(len=0) :: values(0))
         return
      end if
      allocate (character(len=maxval([0, lengths])) :: values(size(lengths)))
      pos = 0
      do i = 1, size(lengths)
         values(i) = text(pos + 1:pos + lengths(i))
         pos = pos + lengths(i)
      end do
   end subroutine read_string_1d

   !> String attribute (variable-length).
   subroutine read_attr_string(file, path, name, value, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, name
      character(len=:), allocatable, intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p
      integer, allocatable :: lengths(:)
      integer(hid_t) :: attr
      integer :: class, hdferr

      value = ''
      call attribute_info(file, path, name, p, dims, class, error)
      if (allocated(error)) return
      call h5aopen_by_name_f(h5_file_id(file), p, name, attr, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, "attribute '"//name//"' of", p, 'h5aopen_by_name_f failed')
         return
      end if
      call read_vlen(attr, .true., class, 1, file, "attribute '"//name//"' of", p, value, lengths, error)
      call h5aclose_f(attr, hdferr)
   end subroutine read_attr_string

   !> Real scalar attribute.
   subroutine read_attr_real_0d(file, path, name, value, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, name
      real(dp), intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: values(:)

      value = 0.0_dp
      call read_attr_real_1d(file, path, name, values, error, one=.true.)
      if (.not. allocated(error)) value = values(1)
   end subroutine read_attr_real_0d

   !> Real 1-D attribute (`one`: exactly one value required).
   subroutine read_attr_real_1d(file, path, name, value, error, one)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, name
      real(dp), allocatable, intent(out) :: value(:)
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: one
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p
      integer :: class, hdferr

      call attribute_info(file, path, name, p, dims, class, error)
      if (.not. allocated(error)) call need_numbers(class, file, "attribute '"//name//"' of", p, error)
      if (.not. allocated(error) .and. present(one)) then
         if (product(dims) /= 1) call fail(error, file, "attribute '"//name//"' of", p, &
                                           'holds '//str(int(product(dims)))//' values, expected one')
      end if
      if (allocated(error)) then
         allocate (value(0))
         return
      end if
      allocate (value(product(dims)))
      if (size(value) == 0) return
      call h5ltget_attribute_double_f(h5_file_id(file), p, name, value, hdferr)
      if (hdferr /= 0) call fail(error, file, "attribute '"//name//"' of", p, 'h5ltget_attribute_double_f failed')
   end subroutine read_attr_real_1d

   !> Integer scalar attribute.
   subroutine read_attr_int_0d(file, path, name, value, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, name
      integer, intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t), allocatable :: dims(:)
      character(len=:), allocatable :: p
      integer :: class, hdferr, buf(1)

      value = 0
      call attribute_info(file, path, name, p, dims, class, error)
      if (allocated(error)) return
      if (class /= H5T_INTEGER_F) then
         call fail(error, file, "attribute '"//name//"' of", p, 'the stored values are not integers')
      else if (product(dims) /= 1) then
         call fail(error, file, "attribute '"//name//"' of", p, &
                   'holds '//str(int(product(dims)))//' values, expected one')
      else
         call h5ltget_attribute_int_f(h5_file_id(file), p, name, buf, hdferr)
         if (hdferr /= 0) call fail(error, file, "attribute '"//name//"' of", p, 'h5ltget_attribute_int_f failed')
         value = buf(1)
      end if
   end subroutine read_attr_int_0d

   ! ------------------------------------------------------------------ internals

   !> Normalised path `p` of an existing object; `dataset`: it must be a dataset.
   subroutine locate(file, path, what, dataset, p, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, what
      logical, intent(in) :: dataset
      character(len=:), allocatable, intent(out) :: p
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: obj
      integer :: obj_type, hdferr, ignore
      logical :: there

      p = trim(adjustl(path))
      if (len(p) == 0) p = '/'
      if (p(1:1) /= '/') p = '/'//p
      call h5_exists(file, p, there, error)
      if (allocated(error)) return
      if (.not. there) then
         call fail(error, file, what, p, 'no such object')
         return
      end if
      if (.not. dataset) return
      call h5oopen_f(h5_file_id(file), p, obj, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, what, p, 'h5oopen_f failed')
         return
      end if
      call h5iget_type_f(obj, obj_type, hdferr)
      call h5oclose_f(obj, ignore)
      if (hdferr /= 0 .or. obj_type /= H5I_DATASET_F) call fail(error, file, what, p, 'the object is not a dataset')
   end subroutine locate

   !> Fortran-order dimensions and type class of a dataset whose rank must be `rank` (-1: any).
   subroutine dataset_info(file, path, rank, p, dims, class, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path
      integer, intent(in) :: rank
      character(len=:), allocatable, intent(out) :: p
      integer(hsize_t), allocatable, intent(out) :: dims(:)
      integer, intent(out) :: class
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t) :: buf(32)
      integer(size_t) :: type_size
      integer :: r, hdferr

      class = -1
      allocate (dims(max(rank, 0)), source=0_hsize_t)
      call locate(file, path, 'dataset', .true., p, error)
      if (allocated(error)) return
      call h5ltget_dataset_ndims_f(h5_file_id(file), p, r, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'dataset', p, 'h5ltget_dataset_ndims_f failed')
      else if (rank >= 0 .and. r /= rank) then
         call fail(error, file, 'dataset', p, 'has rank '//str(r)//', expected '//str(rank))
      else
         buf = 0
         call h5ltget_dataset_info_f(h5_file_id(file), p, buf, class, type_size, hdferr)
         if (hdferr /= 0) call fail(error, file, 'dataset', p, 'h5ltget_dataset_info_f failed')
         dims = buf(1:r)
      end if
   end subroutine dataset_info

   !> Dimensions (empty for a scalar) and type class of attribute `name` of the object at `path`.
   subroutine attribute_info(file, path, name, p, dims, class, error)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: path, name
      character(len=:), allocatable, intent(out) :: p
      integer(hsize_t), allocatable, intent(out) :: dims(:)
      integer, intent(out) :: class
      type(error_type), allocatable, intent(out) :: error
      integer(hsize_t) :: buf(32)
      integer(size_t) :: type_size
      integer :: r, hdferr
      logical :: there

      class = -1
      allocate (dims(0))
      call locate(file, path, "attribute '"//name//"' of", .false., p, error)
      if (allocated(error)) return
      call h5aexists_by_name_f(h5_file_id(file), p, name, there, hdferr)
      if (hdferr /= 0 .or. .not. there) then
         call fail(error, file, "attribute '"//name//"' of", p, 'no such attribute')
         return
      end if
      call h5ltget_attribute_ndims_f(h5_file_id(file), p, name, r, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, "attribute '"//name//"' of", p, 'h5ltget_attribute_ndims_f failed')
         return
      end if
      buf = 0
      call h5ltget_attribute_info_f(h5_file_id(file), p, name, buf, class, type_size, hdferr)
      if (hdferr /= 0) call fail(error, file, "attribute '"//name//"' of", p, 'h5ltget_attribute_info_f failed')
      dims = buf(1:r)
   end subroutine attribute_info

   !> Require a numeric type class.
   subroutine need_numbers(class, file, what, p, error)
      integer, intent(in) :: class
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: what, p
      type(error_type), allocatable, intent(out) :: error

      if (class /= H5T_FLOAT_F .and. class /= H5T_INTEGER_F) &
         call fail(error, file, what, p, 'the stored values are not numbers')
   end subroutine need_numbers

   !> Read `n` variable-length strings of a dataset or attribute, concatenated in `text`.
   subroutine read_vlen(id, is_attr, class, n, file, what, p, text, lengths, error)
      integer(hid_t), intent(in) :: id
      logical, intent(in) :: is_attr
      integer, intent(in) :: class, n
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: what, p
      character(len=:), allocatable, intent(out) :: text
      integer, allocatable, intent(out) :: lengths(:)
      type(error_type), allocatable, intent(out) :: error
      type(c_ptr), allocatable, target :: ptrs(:)
      type(c_ptr), target :: buf
      character(kind=c_char), pointer :: cstr(:)
      integer(hid_t) :: mtype, space
      integer :: hdferr, i, j, pos, ignore

      text = ''
      allocate (lengths(n))
      lengths = 0
      if (class /= H5T_STRING_F) then
         call fail(error, file, what, p, 'the stored values are not strings')
         return
      end if
      if (n == 0) return
      call h5tcopy_f(H5T_C_S1, mtype, hdferr)
      call h5tset_size_f(mtype, -1_size_t, hdferr)
      call h5tset_cset_f(mtype, H5T_CSET_UTF8_F, hdferr)
      allocate (ptrs(n))
      ptrs = c_null_ptr
      buf = c_loc(ptrs)
      if (is_attr) then
         call h5aread_f(id, mtype, buf, hdferr)
         call h5aget_space_f(id, space, ignore)
      else
         call h5dread_f(id, mtype, buf, hdferr)
         call h5dget_space_f(id, space, ignore)
      end if
      if (hdferr /= 0) then
         call fail(error, file, what, p, merge('h5aread_f', 'h5dread_f', is_attr)//' failed')
      else
         do i = 1, n
            if (c_associated(ptrs(i))) lengths(i) = int(c_strlen(ptrs(i)))
         end do
         deallocate (text)
         allocate (character(len=sum(lengths)) :: text)
         pos = 0
         do i = 1, n
            if (lengths(i) == 0) cycle
            call c_f_pointer(ptrs(i), cstr, [lengths(i)])
            do j = 1, lengths(i)
               text(pos + j:pos + j) = cstr(j)
            end do
            pos = pos + lengths(i)
         end do
         call h5dvlen_reclaim_f(mtype, space, H5P_DEFAULT_F, buf, ignore)
      end if
      call h5sclose_f(space, ignore)
      call h5tclose_f(mtype, ignore)
   end subroutine read_vlen

   !> Error "HDF5 file '<file>': cannot read <what> '<path>': <detail>".
   subroutine fail(error, file, what, path, detail)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: what, path, detail

      call fatal_error(error, "HDF5 file '"//h5_file_name(file)//"': cannot read "//what//" '"//path// &
                       "': "//detail)
   end subroutine fail

end module pound_test_h5
