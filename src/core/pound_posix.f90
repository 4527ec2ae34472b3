!> The few POSIX (Linux, glibc) calls that Fortran has no statement for: errno and its text,
!> process id, rename/unlink/mkdir, file identity (device and inode), directory test and lock,
!> signal dispositions, `_exit`, the standard descriptors (open, a terminal) and the address-space limit.
!>
!> Every procedure is a thin wrapper that returns the C result or errno; the callers turn
!> failures into messages. Paths are Fortran strings (a NUL is appended here).
module pound_posix
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_int64_t, c_ptr, c_funptr, &
                                          c_null_char, c_null_ptr, c_associated, c_f_pointer, &
                                          c_size_t, c_intptr_t
   implicit none
   private

   public :: posix_errno, posix_set_errno, posix_strerror, posix_getpid, posix_storage_error
   public :: posix_rename, posix_unlink, posix_mkdir, posix_file_id, posix_is_directory
   public :: posix_lock_directory, posix_unlock_directory, posix_exit_now, posix_directory_names
   public :: posix_ignore_signal, posix_set_handler, posix_std_fd_open, posix_reserve_fd
   public :: posix_address_space_limit, posix_unlink_c, posix_write_stderr_c, posix_write, posix_sleep
   public :: posix_isatty, posix_keep_freed_memory, posix_is_empty_file
   public :: sig_int, sig_term, sig_xfsz, sig_pipe, errno_enoent, errno_eexist, errno_eintr

   !> Signal numbers (Linux).
   integer, parameter :: sig_int = 2, sig_pipe = 13, sig_term = 15, sig_xfsz = 25
   !> errno values used by the callers (Linux).
   integer, parameter :: errno_enoent = 2, errno_eintr = 4, errno_eexist = 17

   integer(c_int), parameter :: lock_ex = 2, o_rdwr = 2, rlimit_as = 9

   interface
      function c_errno_location() bind(C, name='__errno_location') result(p)
         import :: c_ptr
         type(c_ptr) :: p
      end function c_errno_location

      function c_strerror(errnum) bind(C, name='strerror') result(p)
         import :: c_int, c_ptr
         integer(c_int), value :: errnum
         type(c_ptr) :: p
      end function c_strerror

      function c_strlen(s) bind(C, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen

      function c_getpid() bind(C, name='getpid') result(pid)
         import :: c_int
         integer(c_int) :: pid
      end function c_getpid

      function c_rename(old, new) bind(C, name='rename') result(stat)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: stat
      end function c_rename

      function c_unlink(path) bind(C, name='unlink') result(stat)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: stat
      end function c_unlink

      function c_mkdir(path, mode) bind(C, name='mkdir') result(stat)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
         integer(c_int) :: stat
      end function c_mkdir

      function c_stat(path, buf) bind(C, name='stat') result(stat)
         import :: c_char, c_int, c_int64_t
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int64_t), intent(out) :: buf(*)
         integer(c_int) :: stat
      end function c_stat

      function c_lstat(path, buf) bind(C, name='lstat') result(stat)
         import :: c_char, c_int, c_int64_t
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int64_t), intent(out) :: buf(*)
         integer(c_int) :: stat
      end function c_lstat

      function c_opendir(path) bind(C, name='opendir') result(dir)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*)
         type(c_ptr) :: dir
      end function c_opendir

      function c_readdir(dir) bind(C, name='readdir') result(entry)
         import :: c_ptr
         type(c_ptr), value :: dir
         type(c_ptr) :: entry
      end function c_readdir

      function c_closedir(dir) bind(C, name='closedir') result(stat)
         import :: c_ptr, c_int
         type(c_ptr), value :: dir
         integer(c_int) :: stat
      end function c_closedir

      function c_dirfd(dir) bind(C, name='dirfd') result(fd)
         import :: c_ptr, c_int
         type(c_ptr), value :: dir
         integer(c_int) :: fd
      end function c_dirfd

      function c_flock(fd, operation) bind(C, name='flock') result(stat)
         import :: c_int
         integer(c_int), value :: fd, operation
         integer(c_int) :: stat
      end function c_flock

      subroutine c_exit_now(status) bind(C, name='_exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit_now

      function c_mallopt(param, value) bind(C, name='mallopt') result(ok)
         import :: c_int
         integer(c_int), value :: param, value
         integer(c_int) :: ok
      end function c_mallopt

      function c_signal(sig, handler) bind(C, name='signal') result(previous)
         import :: c_int, c_funptr
         integer(c_int), value :: sig
         type(c_funptr), value :: handler
         type(c_funptr) :: previous
      end function c_signal

      function c_isatty(fd) bind(C, name='isatty') result(yes)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: yes
      end function c_isatty

      function c_dup(fd) bind(C, name='dup') result(new_fd)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: new_fd
      end function c_dup

      function c_close(fd) bind(C, name='close') result(stat)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: stat
      end function c_close

      ! open(2) is variadic; with two arguments (no O_CREAT) the mode is never read.
      function c_open(path, flags) bind(C, name='open') result(fd)
         import :: c_char, c_int
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: flags
         integer(c_int) :: fd
      end function c_open

      function c_write(fd, buf, n) bind(C, name='write') result(written)
         import :: c_int, c_char, c_size_t, c_intptr_t
         integer(c_int), value :: fd
         character(kind=c_char), intent(in) :: buf(*)
         integer(c_size_t), value :: n
         integer(c_intptr_t) :: written
      end function c_write

      function c_sleep(seconds) bind(C, name='sleep') result(left)
         import :: c_int
         integer(c_int), value :: seconds
         integer(c_int) :: left
      end function c_sleep

      function c_getrlimit(resource, rlim) bind(C, name='getrlimit') result(stat)
         import :: c_int, c_int64_t
         integer(c_int), value :: resource
         integer(c_int64_t), intent(out) :: rlim(2)
         integer(c_int) :: stat
      end function c_getrlimit
   end interface

contains

   !> The calling thread's errno.
   function posix_errno() result(e)
      integer :: e
      integer(c_int), pointer :: p

      call c_f_pointer(c_errno_location(), p)
      e = int(p)
   end function posix_errno

   !> Set errno (to 0 before a sequence of calls whose failure is to be explained).
   subroutine posix_set_errno(e)
      !> New value.
      integer, intent(in) :: e
      integer(c_int), pointer :: p

      call c_f_pointer(c_errno_location(), p)
      p = int(e, c_int)
   end subroutine posix_set_errno

   !> strerror(e), e.g. 'No space left on device'.
   function posix_strerror(e) result(text)
      !> errno value.
      integer, intent(in) :: e
      character(len=:), allocatable :: text
      type(c_ptr) :: p
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i

      p = c_strerror(int(e, c_int))
      if (.not. c_associated(p)) then
         text = 'error '
         return
      end if
      n = int(c_strlen(p))
      call c_f_pointer(p, chars, [n])
      allocate (character(len=n) :: text)
      do i = 1, n
         text(i:i) = chars(i)
      end do
   end function posix_strerror

   !> strerror(errno) when errno holds a storage or permission failure (EPERM, EIO, EACCES,
   !> EFBIG, ENOSPC, EROFS, EDQUOT), '' otherwise: for libraries that report a failed write
   !> only as a failed call.
   function posix_storage_error() result(text)
      character(len=:), allocatable :: text
      integer, parameter :: storage_errors(7) = [1, 5, 13, 27, 28, 30, 122]
      integer :: e

      e = posix_errno()
      text = ''
      if (any(storage_errors == e)) text = posix_strerror(e)
   end function posix_storage_error

   !> Process id.
   function posix_getpid() result(pid)
      integer :: pid

      pid = int(c_getpid())
   end function posix_getpid

   !> rename(2): 0 on success, else errno.
   function posix_rename(old, new) result(e)
      !> Existing name.
      character(len=*), intent(in) :: old
      !> New name (replaced atomically if it exists).
      character(len=*), intent(in) :: new
      integer :: e

      e = 0
      if (c_rename(old//c_null_char, new//c_null_char) /= 0) e = posix_errno()
   end function posix_rename

   !> unlink(2): 0 on success, else errno. Safe in a signal handler for a NUL-terminated name.
   function posix_unlink(path) result(e)
      !> File to remove.
      character(len=*), intent(in) :: path
      integer :: e

      e = 0
      if (c_unlink(path//c_null_char) /= 0) e = posix_errno()
   end function posix_unlink

   !> unlink(2) of a NUL-terminated name held in a character array (no allocation: usable
   !> in a signal handler). Errors are ignored.
   subroutine posix_unlink_c(name)
      !> NUL-terminated path.
      character(kind=c_char), intent(in) :: name(*)
      integer(c_int) :: ignore

      ignore = c_unlink(name)
   end subroutine posix_unlink_c

   !> write(2) of `n` characters to standard error (no allocation: usable in a signal handler).
   subroutine posix_write_stderr_c(text, n)
      !> Characters.
      character(kind=c_char), intent(in) :: text(*)
      !> How many.
      integer, intent(in) :: n
      integer(c_intptr_t) :: ignore

      ignore = c_write(2_c_int, text, int(n, c_size_t))
   end subroutine posix_write_stderr_c

   !> Write all of `text` to descriptor `fd` with write(2), bypassing any buffer; 0 on
   !> success, else errno (EBADF: closed, ENOSPC: /dev/full, EPIPE: reader gone).
   function posix_write(fd, text) result(e)
      !> Descriptor.
      integer, intent(in) :: fd
      !> Bytes to write.
      character(len=*), intent(in) :: text
      integer :: e
      integer(c_intptr_t) :: done, n

      e = 0
      done = 0
      do while (done < len(text))
         n = c_write(int(fd, c_int), text(done + 1:), int(len(text) - done, c_size_t))
         if (n < 0) then
            e = posix_errno()
            if (e == errno_eintr) cycle
            return
         end if
         done = done + n
      end do
   end function posix_write

   !> Sleep `seconds` (a signal may end the sleep early).
   subroutine posix_sleep(seconds)
      !> Whole seconds.
      integer, intent(in) :: seconds
      integer(c_int) :: left

      left = c_sleep(int(seconds, c_int))
   end subroutine posix_sleep

   !> mkdir(2) with mode 0777 (less the umask): 0 on success, else errno.
   function posix_mkdir(path) result(e)
      !> Directory to create.
      character(len=*), intent(in) :: path
      integer :: e

      e = 0
      if (c_mkdir(path//c_null_char, int(o'777', c_int)) /= 0) e = posix_errno()
   end function posix_mkdir

   !> Device and inode of the file `path` names (symbolic links followed); `e` = 0 on
   !> success, else errno (ENOENT: no such file).
   subroutine posix_file_id(path, device, inode, e)
      !> File.
      character(len=*), intent(in) :: path
      !> st_dev and st_ino.
      integer(c_int64_t), intent(out) :: device, inode
      !> 0 or errno.
      integer, intent(out) :: e
      ! struct stat begins with st_dev and st_ino (8 bytes each) on 64-bit Linux; the
      ! buffer is larger than the whole structure.
      integer(c_int64_t) :: buf(64)

      device = -1
      inode = -1
      e = 0
      buf = 0
      if (c_stat(path//c_null_char, buf) /= 0) then
         e = posix_errno()
         return
      end if
      device = buf(1)
      inode = buf(2)
   end subroutine posix_file_id

   !> Whether `path` itself (not what a link points to) is an empty regular file with no
   !> other name: one that may be removed and made again instead of being truncated.
   function posix_is_empty_file(path) result(empty)
      !> Path.
      character(len=*), intent(in) :: path
      logical :: empty
      ! struct stat on 64-bit Linux: st_nlink at bytes 16-23, st_mode at 24-27, st_size at
      ! 48-55 (as for posix_file_id, the buffer is larger than the whole structure).
      integer(c_int64_t), parameter :: s_ifmt = int(o'170000', c_int64_t), s_ifreg = int(o'100000', c_int64_t)
      integer(c_int64_t) :: buf(64)

      buf = 0
      empty = .false.
      if (c_lstat(path//c_null_char, buf) /= 0) return
      empty = iand(iand(buf(4), int(z'FFFFFFFF', c_int64_t)), s_ifmt) == s_ifreg .and. buf(3) == 1 .and. buf(7) == 0
   end function posix_is_empty_file

   !> Whether `path` is a directory that can be opened.
   function posix_is_directory(path) result(is_dir)
      !> Path.
      character(len=*), intent(in) :: path
      logical :: is_dir
      type(c_ptr) :: dir
      integer(c_int) :: ignore

      dir = c_opendir(path//c_null_char)
      is_dir = c_associated(dir)
      if (is_dir) ignore = c_closedir(dir)
   end function posix_is_directory

   !> Take an exclusive flock(2) on directory `path` (waits for other holders). `handle`
   !> is released by `posix_unlock_directory` or by the end of the process; `e` = 0 or errno.
   subroutine posix_lock_directory(path, handle, e)
      !> Directory.
      character(len=*), intent(in) :: path
      !> Lock handle (the open directory stream).
      type(c_ptr), intent(out) :: handle
      !> 0 or errno.
      integer, intent(out) :: e
      integer(c_int) :: ignore

      e = 0
      handle = c_opendir(path//c_null_char)
      if (.not. c_associated(handle)) then
         e = posix_errno()
         return
      end if
      do
         if (c_flock(c_dirfd(handle), lock_ex) == 0) return
         e = posix_errno()
         if (e /= errno_eintr) exit
      end do
      ignore = c_closedir(handle)
      handle = c_null_ptr
   end subroutine posix_lock_directory

   !> The names of the entries of directory `path` (readdir's order, '.' and '..' among them;
   !> names longer than `len(names)` left out), or `e` the errno of opendir. glibc's `struct
   !> dirent` on 64-bit Linux holds the name at byte 19.
   subroutine posix_directory_names(path, names, e)
      !> Directory.
      character(len=*), intent(in) :: path
      !> Its entries' names.
      character(len=*), allocatable, intent(out) :: names(:)
      !> 0 or errno.
      integer, intent(out) :: e
      character(kind=c_char), pointer :: raw(:)
      character(len=len(names)), allocatable :: grown(:)
      type(c_ptr) :: dir, entry
      integer(c_int) :: ignore
      integer :: n, k

      e = 0
      allocate (names(16))
      n = 0
      dir = c_opendir(path//c_null_char)
      if (.not. c_associated(dir)) then
         e = posix_errno()
         names = names(1:0)
         return
      end if
      do
         entry = c_readdir(dir)
         if (.not. c_associated(entry)) exit
         call c_f_pointer(entry, raw, [19 + len(names) + 1])
         k = 0
         do while (k <= len(names))
            if (raw(20 + k) == c_null_char) exit
            k = k + 1
         end do
         if (k > len(names)) cycle
         if (n == size(names)) then
            allocate (grown(2*n))
            grown(1:n) = names(1:n)
            call move_alloc(grown, names)
         end if
         n = n + 1
         names(n) = transfer(raw(20:19 + k), names(n)(1:k))
      end do
      ignore = c_closedir(dir)
      names = names(1:n)
   end subroutine posix_directory_names

   !> Release a lock taken by `posix_lock_directory` (nothing if none is held).
   subroutine posix_unlock_directory(handle)
      !> Lock handle; null on return.
      type(c_ptr), intent(inout) :: handle
      integer(c_int) :: ignore

      if (c_associated(handle)) ignore = c_closedir(handle)
      handle = c_null_ptr
   end subroutine posix_unlock_directory

   !> Keep freed memory in the process (glibc's malloc): blocks below 32 MiB come from the heap
   !> and up to 64 MiB freed at its top stay there (glibc's defaults start at 128 KiB and grow
   !> only after such blocks were freed). So the second analysis' histories take the pages
   !> of the first's, already mapped, instead of new ones the kernel must fault in and zero.
   !> Nothing changes in any result; with another C library the call is only refused.
   subroutine posix_keep_freed_memory()
      integer(c_int), parameter :: m_trim_threshold = -1, m_mmap_threshold = -3
      integer(c_int) :: ok

      ok = c_mallopt(m_mmap_threshold, 32*2**20)
      ok = c_mallopt(m_trim_threshold, 64*2**20)
   end subroutine posix_keep_freed_memory

   !> _exit(2): end the process now, without exit handlers (async-signal-safe).
   subroutine posix_exit_now(status)
      !> Exit status.
      integer, intent(in) :: status

      call c_exit_now(int(status, c_int))
   end subroutine posix_exit_now

   !> Ignore signal `sig` (SIG_IGN), e.g. SIGXFSZ so that an over-large write fails with EFBIG.
   subroutine posix_ignore_signal(sig)
      !> Signal number.
      integer, intent(in) :: sig
      type(c_funptr) :: ignore, previous

      ignore = transfer(1_c_intptr_t, ignore)
      previous = c_signal(int(sig, c_int), ignore)
   end subroutine posix_ignore_signal

   !> Install `handler` (a bind(C) procedure taking the signal number by value) for `sig`.
   subroutine posix_set_handler(sig, handler)
      !> Signal number.
      integer, intent(in) :: sig
      !> C function pointer of the handler.
      type(c_funptr), intent(in) :: handler
      type(c_funptr) :: previous

      previous = c_signal(int(sig, c_int), handler)
   end subroutine posix_set_handler

   !> Whether file descriptor `fd` (0, 1 or 2) is open.
   function posix_std_fd_open(fd) result(is_open)
      !> Descriptor.
      integer, intent(in) :: fd
      logical :: is_open
      integer(c_int) :: copy, ignore

      copy = c_dup(int(fd, c_int))
      is_open = copy >= 0
      if (is_open) ignore = c_close(copy)
   end function posix_std_fd_open

   !> Whether file descriptor `fd` is a terminal (isatty(3)).
   function posix_isatty(fd) result(is_tty)
      !> Descriptor.
      integer, intent(in) :: fd
      logical :: is_tty

      is_tty = c_isatty(int(fd, c_int)) == 1
   end function posix_isatty

   !> Occupy the lowest free descriptor with /dev/null, so that a closed standard
   !> descriptor is never reused by a file of the run; returns the descriptor (or -1).
   function posix_reserve_fd() result(fd)
      integer :: fd

      fd = int(c_open('/dev/null'//c_null_char, o_rdwr))
   end function posix_reserve_fd

   !> RLIMIT_AS soft limit in bytes, or -1 when unlimited or unknown.
   function posix_address_space_limit() result(limit)
      integer(c_int64_t) :: limit
      integer(c_int64_t) :: rlim(2)

      limit = -1
      if (c_getrlimit(rlimit_as, rlim) /= 0) return
      ! RLIM_INFINITY is all ones: -1 as a signed 64-bit integer.
      if (rlim(1) >= 0) limit = rlim(1)
   end function posix_address_space_limit

end module pound_posix
