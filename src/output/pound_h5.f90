!> pound's result files over HDF5's Fortran API (datasets, attributes, groups; the library
!> does not use the high-level H5LT layer, which only the tests' reader links).
!>
!> A file is reached through a handle, `type(h5_file)`: `h5_create` (truncates), `h5_open`
!> (read-only) and `h5_close`. Objects are named by absolute paths such as
!> '/uncoupled/A/peak'; a path without the leading '/' is taken from the root. Writing a
!> dataset creates the missing groups on its path. Attributes go on the root ('/'), a group
!> or a dataset, given by its path; writing an attribute that exists replaces it.
!>
!> **What this module adds to HDF5.** Numeric datasets (real(dp) scalar, 1-D and 2-D;
!> default integer 1-D and 2-D) with their `units` attribute written on the new dataset's
!> own identifier (`new_dataset`: no second look-up by path); parent groups created on
!> demand (one look-up when the parent exists); scalar attributes (h5py reads a number,
!> not shape (1,)); variable-length UTF-8 strings (with a conversion buffer sized to the
!> strings: HDF5's default zeroes 1 MiB for every write); HDF5's error stack kept quiet,
!> with a failure turned into one message naming the file, the object and the call.
!> Readers are not part of the library: the tests read files back through
!> `tests/support/pound_test_h5.f90` (with `h5_file_id`).
!>
!> **Dimension convention.** Arrays are written exactly as they are held in Fortran, with no
!> transposition. HDF5 records dimensions in C (row-major) order, so C, h5py, h5dump and
!> NumPy see a Fortran array of shape (n1, n2) as shape (n2, n1), with the same numbers in
!> memory order: Fortran `a(i, j)` is h5py `a[j-1, i-1]`. pound therefore keeps histories
!> in Fortran as `hist(n_floors, n_out)`, so that h5py reads them as shape
!> (n_out, n_floors): one row per output time.
!>
!> Storage: reals as IEEE 64-bit little-endian (the native double on the little-endian
!> machines pound runs on), integers as 32-bit signed little-endian, strings as
!> variable-length UTF-8 strings (h5py reads those attributes as `str`, and there is no
!> 64 KiB object-header limit on long attributes such as the deck text). String array
!> elements lose their trailing blanks (Fortran padding); a string attribute is stored
!> exactly as given. Strings must not contain NUL characters. Datasets are contiguous,
!> without chunking or compression, and are written once: writing a dataset whose path
!> exists is an error. Histories can instead be created chunked, optionally compressed,
!> at their final shape (`h5_create_history`) and filled a block of columns (output samples)
!> at a time (`h5_write_columns`): chunks of whole columns, at most `chunk_bytes` each,
!> shuffle + deflate level `deflate_level` when compressed.
!>
!> Every HDF5 return code is checked; a failure comes back as an `error_type` naming the
!> file, the object and the HDF5 call. HDF5's automatic error-stack printing is switched
!> off, so a failure is reported once, by the caller; a failure that comes from the system
!> (no space left, file too large, no permission) carries its reason from errno. The library
!> is initialised on the first `h5_create`/`h5_open` (with floating-point traps held off
!> during `h5open_f`) and shut down by HDF5 itself at program exit. After a write failed
!> because the disk filled up, HDF5 1.10's exit handler can crash on the dataset whose close
!> failed: the program should then end with `_exit` (as pound does).
!>
!> This module holds the handle, the generic interfaces, the files, groups, datasets and
!> histories; the attribute writers are in submodule `pound_h5_attributes`
!> (src/output/pound_h5_attributes.f90), the low-level helpers (HDF5 start-up, path checks,
!> group creation, dataspaces, string buffers, identifier release, error text) in submodule
!> `pound_h5_support` (src/output/pound_h5_support.f90).
module pound_h5
   use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char
   use hdf5, only: hid_t, hsize_t, h5fcreate_f, h5fopen_f, h5fclose_f, H5F_ACC_TRUNC_F, H5F_ACC_EXCL_F, H5F_ACC_RDONLY_F, &
                   H5F_ACC_RDWR_F, h5pcreate_f, h5pclose_f, h5dcreate_f, h5dwrite_f, h5dopen_f, &
                   h5dget_space_f, h5sselect_hyperslab_f, H5S_SELECT_SET_F, H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, &
                   H5T_IEEE_F64LE, H5P_DATASET_CREATE_F, h5pset_chunk_f, h5pset_shuffle_f, h5pset_deflate_f, &
                   H5P_DATASET_XFER_F, h5pset_buffer_f
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, status_io
   use pound_posix, only: posix_set_errno, posix_unlink, posix_is_empty_file
   implicit none
   private

   public :: h5_file, h5_create, h5_open, h5_close, h5_is_open, h5_file_id, h5_file_name
   public :: h5_create_group, h5_exists
   public :: h5_write, h5_write_attr, h5_create_history, h5_write_columns

   !> An open HDF5 file (or none: the default state).
   type :: h5_file
      private
      !> HDF5 file identifier, negative when closed.
      integer(hid_t) :: id = -1_hid_t
      !> File name, for messages.
      character(len=:), allocatable :: name
      !> Opened by `h5_create` (read-write) rather than `h5_open` (read-only).
      logical :: writable = .false.
   end type h5_file

   !> The group `make_groups` last found or made, in the open file `known_file` (-1: none). A
   !> writer puts the datasets of one group one after another, so this spares their parent
   !> look-ups (an h5lexists and an h5oopen each). Nothing in pound deletes or moves a group;
   !> opening, creating or closing a file forgets it (`forget_group`).
   integer(hid_t), save :: known_file = -1_hid_t
   !> Its path (normalised), allocated whenever `known_file` >= 0.
   character(len=:), allocatable, save :: known_group

   !> Write a new dataset at a path, creating missing groups:
   !> `call h5_write(file, path, values, error[, units])` with `values` real(dp) scalar, 1-D
   !> or 2-D, default integer 1-D or 2-D, or character 1-D (trailing blanks dropped);
   !> `units` becomes the dataset's string attribute `units`.
   interface h5_write
      module procedure write_real_0d, write_real_1d, write_real_2d, write_int_1d, write_int_2d, &
         write_int_3d, write_string_1d
   end interface h5_write

   !> Set an attribute of the object at a path ('/' is the root), replacing an existing one:
   !> `call h5_write_attr(file, path, name, value, error)` with `value` a character string,
   !> real(dp) scalar or 1-D, or default integer scalar (submodule pound_h5_attributes).
   interface h5_write_attr
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
      end subroutine write_attr_real_0d
      !> Real 1-D attribute.
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
      end subroutine write_attr_int_0d
   end interface h5_write_attr

   !> HDF5 identifiers held by one operation, closed together by `release`.
   type :: h5_ids
      integer(hid_t) :: obj = -1_hid_t
      integer(hid_t) :: attr = -1_hid_t
      integer(hid_t) :: space = -1_hid_t
      integer(hid_t) :: ftype = -1_hid_t
      integer(hid_t) :: mtype = -1_hid_t
   end type h5_ids

   !> Largest chunk of a history dataset (bytes), and the deflate level of compressed ones.
   integer, parameter :: chunk_bytes = 2**20, deflate_level = 4

   !> The low-level helpers (submodule pound_h5_support), for this module and its submodules.
   interface
      !> Initialise HDF5 once and check that the handle is free.
      module subroutine start(file, path, error)
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: path
         type(error_type), allocatable, intent(out) :: error
      end subroutine start
      !> File access list that closes every object with the file.
      module subroutine file_access_list(path, fapl, error)
         character(len=*), intent(in) :: path
         integer(hid_t), intent(out) :: fapl
         type(error_type), allocatable, intent(out) :: error
      end subroutine file_access_list
      !> Check the handle (open; writable if `write`) and normalise `path` to '/a/b'.
      module subroutine check_path(file, path, write, action, p, error)
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: path
         logical, intent(in) :: write
         character(len=*), intent(in) :: action
         character(len=:), allocatable, intent(out) :: p
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_path
      !> Whether every component of the normalised path `p` exists (all but the last as groups).
      module subroutine path_exists(file, p, exists, error)
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: p
         logical, intent(out) :: exists
         type(error_type), allocatable, intent(out) :: error
      end subroutine path_exists
      !> Create the missing groups of the normalised path `p` (the last component too if `whole`).
      module subroutine make_groups(file, p, whole, error)
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: p
         logical, intent(in) :: whole
         type(error_type), allocatable, intent(out) :: error
      end subroutine make_groups
      !> String attribute `name` (variable-length UTF-8) of the open object `obj` at `p`, which
      !> has none of that name.
      module subroutine string_attribute_on(obj, file, p, name, value, error)
         integer(hid_t), intent(in) :: obj
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: p, name, value
         type(error_type), allocatable, intent(inout) :: error
      end subroutine string_attribute_on
      !> Check the handle and `path` for a new dataset and create the groups above it; `p` is
      !> the normalised path (an object already there makes h5dcreate_f fail: `create_failed`).
      module subroutine dataset_path(file, path, p, error)
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: path
         character(len=:), allocatable, intent(out) :: p
         type(error_type), allocatable, intent(out) :: error
      end subroutine dataset_path
      !> The error of a failed h5dcreate_f at `p`: an object already there (`dataset_path`
      !> does not look), else the call's failure.
      module subroutine create_failed(file, p, error)
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: p
         type(error_type), allocatable, intent(out) :: error
      end subroutine create_failed
      !> Scalar (empty `dims`) or simple dataspace.
      module subroutine new_space(dims, ids, file, action, what, path, error)
         integer(hsize_t), intent(in) :: dims(:)
         type(h5_ids), intent(inout) :: ids
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: action, what, path
         type(error_type), allocatable, intent(out) :: error
      end subroutine new_space
      !> New variable-length UTF-8 C string datatype.
      module subroutine string_type(type_id, hdferr)
         integer(hid_t), intent(out) :: type_id
         integer, intent(out) :: hdferr
      end subroutine string_type
      !> NUL-terminated copies of `values(i)(1:lengths(i))` in `chars`, addressed by `ptrs`.
      module subroutine pack_strings(lengths, values, chars, ptrs)
         integer, intent(in) :: lengths(:)
         character(len=*), intent(in) :: values(:)
         character(kind=c_char), allocatable, target, intent(out) :: chars(:)
         type(c_ptr), allocatable, intent(out) :: ptrs(:)
      end subroutine pack_strings
      !> Close every identifier held; report the first failure unless an error is already set.
      module subroutine release(ids, file, action, what, path, error)
         type(h5_ids), intent(inout) :: ids
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: action, what, path
         type(error_type), allocatable, intent(inout) :: error
      end subroutine release
      !> Error "HDF5 file '<file>': cannot <action> <what> '<path>': <detail>".
      module subroutine fail(error, file, action, what, path, detail)
         type(error_type), allocatable, intent(out) :: error
         type(h5_file), intent(in) :: file
         character(len=*), intent(in) :: action, what, path, detail
      end subroutine fail
      !> ': <strerror>' for any errno left by a failed create (errno is cleared before it).
      module function create_reason() result(text)
         character(len=:), allocatable :: text
      end function create_reason
      !> ': <strerror>' when errno holds a storage or permission failure, '' otherwise: HDF5
      !> reports a failed write only as a failed call, the system's reason is in errno.
      module function system_reason() result(text)
         character(len=:), allocatable :: text
      end function system_reason
   end interface

contains

   ! ------------------------------------------------------------------ files

   !> Create `path` (replacing an existing file) and open it for writing.
   subroutine h5_create(file, path, error)
      !> Handle; must not be open already.
      type(h5_file), intent(inout) :: file
      !> File name.
      character(len=*), intent(in) :: path
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: fapl
      integer :: hdferr, ignore, access

      call start(file, path, error)
      if (allocated(error)) return
      call file_access_list(path, fapl, error)
      if (allocated(error)) return
      ! An empty regular file there (the run's temporary, reserved empty; not a link, a device
      ! or a file with another name) is replaced, not truncated:
      ! ext4 writes a file truncated to empty back when it is closed (auto_da_alloc), in the
      ! process, before the program can end (about 0.25 ms for a 5 MB results file).
      access = H5F_ACC_TRUNC_F
      if (posix_is_empty_file(path)) then
         if (posix_unlink(path) == 0) access = H5F_ACC_EXCL_F
      end if
      call posix_set_errno(0)
      call h5fcreate_f(path, access, file%id, hdferr, access_prp=fapl)
      call h5pclose_f(fapl, ignore)
      if (hdferr /= 0) then
         file%id = -1_hid_t
         call fatal_error(error, "cannot create HDF5 file '"//path//"': h5fcreate_f failed"//create_reason(), status_io)
         return
      end if
      file%name = path
      file%writable = .true.
   end subroutine h5_create

   !> Open an existing HDF5 file read-only (or for writing, to append, when `writable`).
   subroutine h5_open(file, path, error, writable)
      !> Handle; must not be open already.
      type(h5_file), intent(inout) :: file
      !> File name.
      character(len=*), intent(in) :: path
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Open for reading and writing (default: read-only).
      logical, intent(in), optional :: writable
      integer(hid_t) :: fapl
      integer :: hdferr, ignore, access
      logical :: there, rw

      call start(file, path, error)
      if (allocated(error)) return
      inquire (file=path, exist=there)
      if (.not. there) then
         call fatal_error(error, "cannot open HDF5 file '"//path//"': no such file", status_io)
         return
      end if
      call file_access_list(path, fapl, error)
      if (allocated(error)) return
      rw = .false.
      if (present(writable)) rw = writable
      access = H5F_ACC_RDONLY_F
      if (rw) access = H5F_ACC_RDWR_F
      call h5fopen_f(path, access, file%id, hdferr, access_prp=fapl)
      call h5pclose_f(fapl, ignore)
      if (hdferr /= 0) then
         file%id = -1_hid_t
         call fatal_error(error, "cannot open HDF5 file '"//path// &
                          "': h5fopen_f failed (not an HDF5 file, or unreadable)", status_io)
         return
      end if
      file%name = path
      file%writable = rw
   end subroutine h5_open

   !> Close the file (all its objects are closed with it). Closing a closed handle does nothing.
   subroutine h5_close(file, error)
      !> Handle; closed on return, even on failure.
      type(h5_file), intent(inout) :: file
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: hdferr

      if (file%id < 0) return
      known_file = -1_hid_t
      call h5fclose_f(file%id, hdferr)
      file%id = -1_hid_t
      file%writable = .false.
      if (hdferr /= 0) then
         call fatal_error(error, "cannot close HDF5 file '"//h5_file_name(file)//"': h5fclose_f failed"// &
                          system_reason(), status_io)
      end if
   end subroutine h5_close

   !> Whether the handle refers to an open file.
   pure function h5_is_open(file) result(is_open)
      !> Handle.
      type(h5_file), intent(in) :: file
      logical :: is_open

      is_open = file%id >= 0
   end function h5_is_open

   !> HDF5 identifier of an open file (negative when closed), for HDF5 calls outside this
   !> module such as the H5LT readers of the tests.
   pure function h5_file_id(file) result(id)
      !> Handle.
      type(h5_file), intent(in) :: file
      integer(hid_t) :: id

      id = file%id
   end function h5_file_id

   ! ------------------------------------------------------------------ groups and paths

   !> Create the group at `path` and any missing groups above it (existing ones are kept).
   subroutine h5_create_group(file, path, error)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Group path, e.g. '/uncoupled/A'.
      character(len=*), intent(in) :: path
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: p

      call check_path(file, path, .true., 'create group', p, error)
      if (allocated(error)) return
      call make_groups(file, p, .true., error)
   end subroutine h5_create_group

   !> Whether an object (group or dataset) exists at `path`. The root always exists.
   subroutine h5_exists(file, path, exists, error)
      !> Open file.
      type(h5_file), intent(in) :: file
      !> Object path.
      character(len=*), intent(in) :: path
      !> True if every group on the path and the final object exist.
      logical, intent(out) :: exists
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: p

      exists = .false.
      call check_path(file, path, .false., 'look up', p, error)
      if (allocated(error)) return
      call path_exists(file, p, exists, error)
   end subroutine h5_exists

   ! ------------------------------------------------------------------ datasets

   !> Real scalar dataset.
   subroutine write_real_0d(file, path, values, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Value.
      real(dp), intent(in) :: values
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute ('m', 'kN m', '1': dimensionless, '-': text); none when absent.
      character(len=*), intent(in), optional :: units
      character(len=:), allocatable :: p
      integer(hsize_t) :: dims(0)
      real(dp), allocatable, target :: packed(:)

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      packed = [values]
      call new_dataset(file, p, dims, H5T_NATIVE_DOUBLE, c_loc(packed), error, units)
   end subroutine write_real_0d

   !> Real 1-D dataset.
   subroutine write_real_1d(file, path, values, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Values.
      real(dp), intent(in), target :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute ('m', 'kN m', '1': dimensionless, '-': text); none when absent.
      character(len=*), intent(in), optional :: units
      character(len=:), allocatable :: p
      real(dp), allocatable, target :: packed(:)

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      ! Contiguous values are written where they are (no copy: the histories are most of the
      ! file); a section or a component of a derived-type array through a contiguous copy.
      if (is_contiguous(values)) then
         call new_dataset(file, p, shape(values, kind=hsize_t), H5T_NATIVE_DOUBLE, c_loc(values), error, units)
         return
      end if
      packed = values
      call new_dataset(file, p, shape(values, kind=hsize_t), H5T_NATIVE_DOUBLE, c_loc(packed), error, units)
   end subroutine write_real_1d

   !> Real 2-D dataset, written as given: Fortran (n1, n2) is seen by h5py as (n2, n1).
   subroutine write_real_2d(file, path, values, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Values, e.g. hist(n_floors, n_out).
      real(dp), intent(in), target :: values(:, :)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute ('m', 'kN m', '1': dimensionless, '-': text); none when absent.
      character(len=*), intent(in), optional :: units
      character(len=:), allocatable :: p
      real(dp), allocatable, target :: packed(:, :)

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      ! As write_real_1d: contiguous values in place, a section through a contiguous copy.
      if (is_contiguous(values)) then
         call new_dataset(file, p, shape(values, kind=hsize_t), H5T_NATIVE_DOUBLE, c_loc(values), error, units)
         return
      end if
      packed = values
      call new_dataset(file, p, shape(values, kind=hsize_t), H5T_NATIVE_DOUBLE, c_loc(packed), error, units)
   end subroutine write_real_2d

   !> Integer 1-D dataset (stored as 32-bit signed).
   subroutine write_int_1d(file, path, values, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Values.
      integer, intent(in) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute ('m', 'kN m', '1': dimensionless, '-': text); none when absent.
      character(len=*), intent(in), optional :: units
      character(len=:), allocatable :: p
      integer, allocatable, target :: packed(:)

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      packed = values
      call new_dataset(file, p, shape(values, kind=hsize_t), H5T_NATIVE_INTEGER, c_loc(packed), error, units)
   end subroutine write_int_1d

   !> Integer 2-D dataset (stored as 32-bit signed; h5py sees the transpose, see the notes).
   subroutine write_int_2d(file, path, values, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Values, e.g. state(n_pairs, n_out).
      integer, intent(in) :: values(:, :)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute ('m', 'kN m', '1': dimensionless, '-': text); none when absent.
      character(len=*), intent(in), optional :: units
      character(len=:), allocatable :: p
      integer, allocatable, target :: packed(:, :)

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      packed = values
      call new_dataset(file, p, shape(values, kind=hsize_t), H5T_NATIVE_INTEGER, c_loc(packed), error, units)
   end subroutine write_int_2d

   !> Integer 3-D dataset (stored as 32-bit signed; h5py sees the dimensions reversed).
   subroutine write_int_3d(file, path, values, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Values, e.g. outcome(n_motions, n_stripes, n_gaps).
      integer, intent(in) :: values(:, :, :)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute; none when absent.
      character(len=*), intent(in), optional :: units
      character(len=:), allocatable :: p
      integer, allocatable, target :: packed(:, :, :)

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      packed = values
      call new_dataset(file, p, shape(values, kind=hsize_t), H5T_NATIVE_INTEGER, c_loc(packed), error, units)
   end subroutine write_int_3d

   ! ------------------------------------------------------------------ chunked histories

   !> Create the 2-D real dataset `path` of Fortran shape (rows, columns) (h5py: (columns,
   !> rows)), chunked by whole columns, compressed (shuffle + deflate) when `compress`; its
   !> columns are written by `h5_write_columns` (columns never written read as 0).
   subroutine h5_create_history(file, path, rows, columns, compress, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Rows (floors) and columns (output samples), both >= 1.
      integer, intent(in) :: rows, columns
      !> Whether to compress.
      logical, intent(in) :: compress
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute ('m', 'kN m', '1': dimensionless, '-': text); none when absent.
      character(len=*), intent(in), optional :: units
      type(h5_ids) :: ids
      character(len=:), allocatable :: p
      integer(hid_t) :: dcpl
      integer(hsize_t) :: chunk(2)
      integer :: hdferr, ignore

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      chunk = [int(rows, hsize_t), int(max(1, min(columns, chunk_bytes/(8*max(1, rows)))), hsize_t)]
      call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'write', 'dataset', p, 'h5pcreate_f failed')
         return
      end if
      call h5pset_chunk_f(dcpl, 2, chunk, hdferr)
      if (hdferr == 0 .and. compress) call h5pset_shuffle_f(dcpl, hdferr)
      if (hdferr == 0 .and. compress) call h5pset_deflate_f(dcpl, deflate_level, hdferr)
      if (hdferr /= 0) then
         call h5pclose_f(dcpl, ignore)
         call fail(error, file, 'write', 'dataset', p, 'h5pset_chunk_f/h5pset_deflate_f failed')
         return
      end if
      call new_space([int(rows, hsize_t), int(columns, hsize_t)], ids, file, 'write', 'dataset', p, error)
      if (.not. allocated(error)) then
         call h5dcreate_f(file%id, p, H5T_IEEE_F64LE, ids%space, ids%obj, hdferr, dcpl_id=dcpl)
         if (hdferr /= 0) then
            ids%obj = -1_hid_t
            call create_failed(file, p, error)
         end if
      end if
      call h5pclose_f(dcpl, ignore)
      if (present(units) .and. .not. allocated(error)) call string_attribute_on(ids%obj, file, p, 'units', units, error)
      call release(ids, file, 'write', 'dataset', p, error)
   end subroutine h5_create_history

   !> Write `values` (rows, k) into columns first .. first+k-1 of the history `path`
   !> (made by `h5_create_history`).
   subroutine h5_write_columns(file, path, first, values, error)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> First column written (1-based).
      integer, intent(in) :: first
      !> The columns.
      real(dp), intent(in), target, contiguous :: values(:, :)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(h5_ids) :: ids, mem
      character(len=:), allocatable :: p
      integer(hsize_t) :: count(2)
      integer :: hdferr

      if (size(values) == 0) return
      call check_path(file, path, .true., 'write', p, error)
      if (allocated(error)) return
      count = shape(values, kind=hsize_t)
      call h5dopen_f(file%id, p, ids%obj, hdferr)
      if (hdferr /= 0) then
         ids%obj = -1_hid_t
         call fail(error, file, 'write', 'dataset', p, 'h5dopen_f failed')
         return
      end if
      call h5dget_space_f(ids%obj, ids%space, hdferr)
      if (hdferr /= 0) then
         ids%space = -1_hid_t
         call fail(error, file, 'write', 'dataset', p, 'h5dget_space_f failed')
      end if
      if (.not. allocated(error)) then
         call h5sselect_hyperslab_f(ids%space, H5S_SELECT_SET_F, [0_hsize_t, int(first - 1, hsize_t)], count, hdferr)
         if (hdferr /= 0) call fail(error, file, 'write', 'dataset', p, 'h5sselect_hyperslab_f failed')
      end if
      if (.not. allocated(error)) call new_space(count, mem, file, 'write', 'dataset', p, error)
      if (.not. allocated(error)) then
         call h5dwrite_f(ids%obj, H5T_NATIVE_DOUBLE, c_loc(values), hdferr, mem_space_id=mem%space, &
                         file_space_id=ids%space)
         if (hdferr /= 0) call fail(error, file, 'write', 'dataset', p, 'h5dwrite_f failed')
      end if
      call release(mem, file, 'write', 'dataset', p, error)
      call release(ids, file, 'write', 'dataset', p, error)
   end subroutine h5_write_columns

   ! ------------------------------------------------------------------ histories, strings, helpers

   !> The `units` attribute of the dataset just written at `path` (nothing when `units` is
   !> A new dataset at the normalised path `p` (its groups made, no object there: see
   !> `dataset_path`) of element type `mtype` (stored as that type), filled from `buf`, with
   !> its `units` attribute when given.
   subroutine new_dataset(file, p, dims, mtype, buf, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Normalised dataset path.
      character(len=*), intent(in) :: p
      !> Shape (none: a scalar).
      integer(hsize_t), intent(in) :: dims(:)
      !> Element type, in memory and in the file (H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER).
      integer(hid_t), intent(in) :: mtype
      !> Address of the contiguous values.
      type(c_ptr), intent(in) :: buf
      !> Error state (kept when set).
      type(error_type), allocatable, intent(inout) :: error
      !> Its `units` attribute, if any.
      character(len=*), intent(in), optional :: units
      type(h5_ids) :: ids
      integer :: hdferr

      if (allocated(error)) return
      call new_space(dims, ids, file, 'write', 'dataset', p, error)
      if (.not. allocated(error)) then
         call h5dcreate_f(file%id, p, mtype, ids%space, ids%obj, hdferr)
         if (hdferr /= 0) then
            ids%obj = -1_hid_t
            call create_failed(file, p, error)
         end if
      end if
      if (.not. allocated(error)) then
         call h5dwrite_f(ids%obj, mtype, buf, hdferr)
         if (hdferr /= 0) call fail(error, file, 'write', 'dataset', p, 'h5dwrite_f failed')
      end if
      if (present(units) .and. .not. allocated(error)) call string_attribute_on(ids%obj, file, p, 'units', units, error)
      call release(ids, file, 'write', 'dataset', p, error)
   end subroutine new_dataset

   !> 1-D dataset of variable-length UTF-8 strings; trailing blanks of each element are dropped.
   subroutine write_string_1d(file, path, values, error, units)
      !> File open for writing.
      type(h5_file), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Strings.
      character(len=*), intent(in) :: values(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Its `units` attribute ('m', 'kN m', '1': dimensionless, '-': text); none when absent.
      character(len=*), intent(in), optional :: units
      type(h5_ids) :: ids
      character(len=:), allocatable :: p
      character(kind=c_char), allocatable, target :: chars(:)
      type(c_ptr), allocatable, target :: ptrs(:)
      integer(hid_t) :: xfer
      integer :: hdferr, i, ignore

      call dataset_path(file, path, p, error)
      if (allocated(error)) return
      call string_type(ids%ftype, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'write', 'dataset', p, 'h5tcopy_f/h5tset_size_f failed')
         return
      end if
      call new_space(shape(values, kind=hsize_t), ids, file, 'write', 'dataset', p, error)
      if (.not. allocated(error)) then
         call h5dcreate_f(file%id, p, ids%ftype, ids%space, ids%obj, hdferr)
         if (hdferr /= 0) then
            ids%obj = -1_hid_t
            call create_failed(file, p, error)
         end if
      end if
      if (.not. allocated(error) .and. size(values) > 0) then
         call pack_strings([(len_trim(values(i)), i=1, size(values))], values, chars, ptrs)
         ! A conversion buffer for these strings only: HDF5's default (1 MiB, zeroed) costs
         ! more than the whole write of a short list.
         call h5pcreate_f(H5P_DATASET_XFER_F, xfer, hdferr)
         if (hdferr == 0) call h5pset_buffer_f(xfer, int(max(4096, 64*size(values)), hsize_t), hdferr)
         if (hdferr == 0) call h5dwrite_f(ids%obj, ids%ftype, c_loc(ptrs), hdferr, xfer_prp=xfer)
         if (hdferr /= 0) call fail(error, file, 'write', 'dataset', p, 'h5dwrite_f failed')
         call h5pclose_f(xfer, ignore)
      end if
      if (present(units) .and. .not. allocated(error)) call string_attribute_on(ids%obj, file, p, 'units', units, error)
      call release(ids, file, 'write', 'dataset', p, error)
   end subroutine write_string_1d

   !> File name of a handle, for messages ('(none)' before the first open).
   pure function h5_file_name(file) result(name)
      !> Handle.
      type(h5_file), intent(in) :: file
      character(len=:), allocatable :: name

      if (allocated(file%name)) then
         name = file%name
      else
         name = '(none)'
      end if
   end function h5_file_name

end module pound_h5
