!> The low-level helpers of pound_h5: HDF5 started once with its error printing off, the
!> handle and path checks, groups created along a path, dataspaces, variable-length UTF-8
!> string types and buffers, identifiers released together, and the one-line error text
!> (naming the file, the object and the HDF5 call, with the system's reason from errno).
submodule(pound_h5) pound_h5_support
   use, intrinsic :: iso_c_binding, only: c_null_char
   use, intrinsic :: ieee_exceptions, only: ieee_status_type, ieee_get_status, ieee_set_status, &
                                            ieee_set_halting_mode, ieee_all
   use hdf5, only: size_t, h5open_f, h5eset_auto_f, h5pset_fclose_degree_f, H5P_FILE_ACCESS_F, &
                   H5F_CLOSE_STRONG_F, h5lexists_f, h5oopen_f, h5oclose_f, h5iget_type_f, H5I_GROUP_F, &
                   h5gcreate_f, h5gclose_f, h5screate_f, h5screate_simple_f, h5sclose_f, H5S_SCALAR_F, &
                   h5aclose_f, h5tcopy_f, h5tclose_f, h5tset_size_f, h5tset_cset_f, H5T_C_S1, H5T_CSET_UTF8_F
   use pound_posix, only: posix_errno, posix_strerror, posix_storage_error
   implicit none

   !> State of one link on a path.
   integer, parameter :: link_missing = 0, link_group = 1, link_other = 2

   !> H5T_VARIABLE: the size that makes a string type variable-length ((size_t)-1 in C).
   integer(size_t), parameter :: variable_size = -1_size_t

   !> HDF5 initialised and its error printing silenced.
   logical :: library_ready = .false.

contains

   !> Initialise HDF5 once and check that the handle is free.
   module procedure start
      type(ieee_status_type) :: fp_status
      integer :: hdferr

      if (file%id >= 0) then
         call fatal_error(error, "cannot open HDF5 file '"//path//"': the handle is still open on '"// &
                          h5_file_name(file)//"'")
         return
      end if
      known_file = -1_hid_t
      if (library_ready) return
      ! HDF5's start-up code must not meet the program's floating-point traps; the
      ! floating-point state, flags included, is restored afterwards.
      call ieee_get_status(fp_status)
      call ieee_set_halting_mode(ieee_all, .false.)
      call h5open_f(hdferr)
      call ieee_set_status(fp_status)
      if (hdferr /= 0) then
         call fatal_error(error, "cannot open HDF5 file '"//path//"': h5open_f failed (HDF5 library)", status_io)
         return
      end if
      call h5eset_auto_f(0, hdferr)
      if (hdferr /= 0) then
         call fatal_error(error, "cannot open HDF5 file '"//path//"': h5eset_auto_f failed (HDF5 library)", status_io)
         return
      end if
      library_ready = .true.
   end procedure start

   !> File access list that closes every object with the file.
   module procedure file_access_list
      integer :: hdferr, ignore

      call h5pcreate_f(H5P_FILE_ACCESS_F, fapl, hdferr)
      if (hdferr /= 0) then
         call fatal_error(error, "cannot open HDF5 file '"//path//"': h5pcreate_f failed", status_io)
         return
      end if
      call h5pset_fclose_degree_f(fapl, H5F_CLOSE_STRONG_F, hdferr)
      if (hdferr /= 0) then
         call h5pclose_f(fapl, ignore)
         call fatal_error(error, "cannot open HDF5 file '"//path//"': h5pset_fclose_degree_f failed", status_io)
      end if
   end procedure file_access_list

   !> Check the handle (open; writable if `write`) and normalise `path` to '/a/b'.
   module procedure check_path
      p = trim(adjustl(path))
      if (len(p) == 0) p = '/'
      if (p(1:1) /= '/') p = '/'//p
      do while (len(p) > 1)
         if (p(len(p):len(p)) /= '/') exit
         p = p(:len(p) - 1)
      end do
      if (file%id < 0) then
         call fatal_error(error, "cannot "//action//" '"//p//"': no HDF5 file is open")
      else if (write .and. .not. file%writable) then
         call fail(error, file, action, 'object', p, 'the file is open read-only')
      else if (index(p, '//') > 0) then
         call fail(error, file, action, 'object', p, 'invalid path (empty name)')
      end if
   end procedure check_path

   !> State of the link `prefix` (an absolute path other than '/'), whose parent is a group;
   !> with `any_parent`, of any path: missing when a group above it is missing (h5lexists_f
   !> fails there).
   subroutine link_state(file, prefix, state, error, any_parent)
      type(h5_file), intent(in) :: file
      character(len=*), intent(in) :: prefix
      integer, intent(out) :: state
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: any_parent
      logical :: there
      integer(hid_t) :: obj
      integer :: hdferr, obj_type, ignore

      state = link_missing
      call h5lexists_f(file%id, prefix, there, hdferr)
      if (hdferr /= 0) then
         if (present(any_parent)) then
            if (any_parent) return
         end if
         call fail(error, file, 'look up', 'object', prefix, 'h5lexists_f failed')
         return
      end if
      if (.not. there) return
      call h5oopen_f(file%id, prefix, obj, hdferr)
      if (hdferr /= 0) then
         call fail(error, file, 'look up', 'object', prefix, 'h5oopen_f failed')
         return
      end if
      call h5iget_type_f(obj, obj_type, hdferr)
      call h5oclose_f(obj, ignore)
      if (hdferr /= 0) then
         call fail(error, file, 'look up', 'object', prefix, 'h5iget_type_f failed')
         return
      end if
      state = merge(link_group, link_other, obj_type == H5I_GROUP_F)
   end subroutine link_state

   !> Whether every component of the normalised path `p` exists (all but the last as groups).
   module procedure path_exists
      integer :: i, state

      exists = .true.
      if (p == '/') return
      do i = 2, len(p) + 1
         if (i <= len(p)) then
            if (p(i:i) /= '/') cycle
         end if
         call link_state(file, p(:i - 1), state, error)
         if (allocated(error)) exists = .false.
         if (allocated(error)) return
         if (state == link_missing .or. (i <= len(p) .and. state /= link_group)) then
            exists = .false.
            return
         end if
      end do
   end procedure path_exists

   !> Create the missing groups of the normalised path `p` (the last component too if `whole`).
   module procedure make_groups
      integer(hid_t) :: gid
      integer :: i, last, state, hdferr

      if (p == '/') return
      last = len(p)
      if (.not. whole) last = index(p, '/', back=.true.) - 1
      if (last <= 1) return
      ! The group of the previous dataset: nothing to look up.
      if (file%id == known_file) then
         if (known_group == p(:last)) return
      end if
      ! Most paths go into a group that exists already: one look-up, no walk (a group above
      ! it missing: the walk below creates it).
      call link_state(file, p(:last), state, error, any_parent=.true.)
      if (allocated(error)) return
      if (state == link_group) call remember(p(:last))
      if (state == link_group) return
      do i = 2, last + 1
         if (i <= last) then
            if (p(i:i) /= '/') cycle
         end if
         call link_state(file, p(:i - 1), state, error)
         if (allocated(error)) return
         select case (state)
         case (link_other)
            call fail(error, file, 'create', 'group', p(:i - 1), 'an object that is not a group has this path')
            return
         case (link_missing)
            call h5gcreate_f(file%id, p(:i - 1), gid, hdferr)
            if (hdferr /= 0) then
               call fail(error, file, 'create', 'group', p(:i - 1), 'h5gcreate_f failed')
               return
            end if
            call h5gclose_f(gid, hdferr)
            if (hdferr /= 0) then
               call fail(error, file, 'create', 'group', p(:i - 1), 'h5gclose_f failed')
               return
            end if
         end select
      end do
      call remember(p(:last))

   contains

      !> The group `g` of this file exists.
      subroutine remember(g)
         character(len=*), intent(in) :: g

         known_file = file%id
         known_group = g
      end subroutine remember

   end procedure make_groups

   !> Check the handle and `path` for a new dataset and create the groups above it; `p` is
   !> the normalised path. An object already at `p` is not looked for here (one look-up per
   !> dataset saved): h5dcreate_f refuses it before creating anything, and `create_failed`
   !> then names it.
   module procedure dataset_path
      call check_path(file, path, .true., 'write', p, error)
      if (allocated(error)) return
      if (p == '/') then
         call fail(error, file, 'write', 'dataset', p, 'the root is a group')
         return
      end if
      call make_groups(file, p, .false., error)
   end procedure dataset_path

   !> The error of a failed h5dcreate_f at `p`: an object already there, else the call's failure.
   module procedure create_failed
      integer :: state

      call link_state(file, p, state, error)
      if (allocated(error)) return
      if (state /= link_missing) then
         call fail(error, file, 'write', 'dataset', p, 'an object with this path already exists')
      else
         call fail(error, file, 'write', 'dataset', p, 'h5dcreate_f failed')
      end if
   end procedure create_failed

   !> Scalar (empty `dims`) or simple dataspace.
   module procedure new_space
      integer :: hdferr

      if (size(dims) == 0) then
         call h5screate_f(H5S_SCALAR_F, ids%space, hdferr)
         if (hdferr /= 0) call fail(error, file, action, what, path, 'h5screate_f failed')
      else
         call h5screate_simple_f(size(dims), dims, ids%space, hdferr)
         if (hdferr /= 0) call fail(error, file, action, what, path, 'h5screate_simple_f failed')
      end if
      if (hdferr /= 0) ids%space = -1_hid_t
   end procedure new_space

   !> New variable-length UTF-8 C string datatype.
   module procedure string_type
      integer :: ignore

      call h5tcopy_f(H5T_C_S1, type_id, hdferr)
      if (hdferr /= 0) then
         type_id = -1_hid_t
         return
      end if
      call h5tset_size_f(type_id, variable_size, hdferr)
      if (hdferr == 0) call h5tset_cset_f(type_id, H5T_CSET_UTF8_F, hdferr)
      if (hdferr /= 0) then
         call h5tclose_f(type_id, ignore)
         type_id = -1_hid_t
      end if
   end procedure string_type

   !> NUL-terminated copies of `values(i)(1:lengths(i))` in `chars`, addressed by `ptrs`.
   module procedure pack_strings
      integer :: i, j, pos

      allocate (chars(sum(lengths) + size(lengths)), ptrs(size(values)))
      pos = 1
      do i = 1, size(values)
         do j = 1, lengths(i)
            chars(pos + j - 1) = values(i) (j:j)
         end do
         chars(pos + lengths(i)) = c_null_char
         ptrs(i) = c_loc(chars(pos))
         pos = pos + lengths(i) + 1
      end do
   end procedure pack_strings

   !> Close every identifier held; report the first failure unless an error is already set.
   module procedure release
      character(len=:), allocatable :: failed
      integer :: hdferr

      if (ids%attr >= 0) then
         call h5aclose_f(ids%attr, hdferr)
         if (hdferr /= 0 .and. .not. allocated(failed)) failed = 'h5aclose_f'
      end if
      if (ids%obj >= 0) then
         call h5oclose_f(ids%obj, hdferr)
         if (hdferr /= 0 .and. .not. allocated(failed)) failed = 'h5oclose_f'
      end if
      if (ids%space >= 0) then
         call h5sclose_f(ids%space, hdferr)
         if (hdferr /= 0 .and. .not. allocated(failed)) failed = 'h5sclose_f'
      end if
      if (ids%ftype >= 0) then
         call h5tclose_f(ids%ftype, hdferr)
         if (hdferr /= 0 .and. .not. allocated(failed)) failed = 'h5tclose_f'
      end if
      if (ids%mtype >= 0) then
         call h5tclose_f(ids%mtype, hdferr)
         if (hdferr /= 0 .and. .not. allocated(failed)) failed = 'h5tclose_f'
      end if
      ids = h5_ids()
      if (allocated(failed) .and. .not. allocated(error)) then
         call fail(error, file, action, what, path, failed//' failed')
      end if
   end procedure release

   !> Error "HDF5 file '<file>': cannot <action> <what> '<path>': <detail>".
   module procedure fail
      call fatal_error(error, "HDF5 file '"//h5_file_name(file)//"': cannot "//action//" "//what// &
                       " '"//path//"': "//detail//system_reason(), status_io)
   end procedure fail

   !> ': <strerror>' for any errno left by a failed create (errno is cleared before it).
   module procedure create_reason
      text = ''
      if (posix_errno() /= 0) text = ': '//posix_strerror(posix_errno())
   end procedure create_reason

   !> ': <strerror>' when errno holds a storage or permission failure, '' otherwise: HDF5
   !> reports a failed write only as a failed call, the system's reason is in errno.
   module procedure system_reason
      text = posix_storage_error()
      if (len(text) > 0) text = ': '//text
   end procedure system_reason

end submodule pound_h5_support
