!> Output files that appear complete, as a pair, or not at all.
!>
!> A run's outputs (`<stem>.out`, `<stem>.h5`, `<stem>_summary.csv`) are written under temporary
!> names that are unique to the process, `.<stem>.out.<pid>-<tag>.partial`,
!> `.<stem>.h5.<pid>-<tag>.partial` and `.<stem>_summary.csv.<pid>-<tag>.partial` beside the
!> final ones, created exclusively when the run starts (which also proves the folder writable
!> before anything is computed). When all are complete they are published together
!> (`publish_outputs`) while the run holds an exclusive lock (flock) on the output folder:
!>
!> 1. the final names are checked again (not a folder, not the deck or the record);
!> 2. an existing `<stem>.h5` and `<stem>_summary.csv` are set aside as
!>    `.<stem>.h5.<pid>-<tag>.previous.partial` and `.<stem>_summary.csv.<pid>-<tag>.previous.partial`;
!> 3. the new `.h5` is renamed into place, then the new `_summary.csv`, then the new `.out`;
!> 4. if a later rename fails, the new files already in place are removed and the previous
!>    ones restored.
!>
!> So runs writing the same stem into one folder publish one after the other: the final
!> pair always comes from one run (the last to publish), and a run either publishes both of
!> its files or none and fails. Where the file system offers no flock the renames are made
!> without the lock: each run still publishes both or none, but two runs publishing at the
!> same instant may then interleave. SIGINT and SIGTERM remove the temporaries and end the run
!> with status 130 or 143; a signal that arrives during the renames is acted on after them.
!> SIGKILL cannot be caught: it may leave `.<stem>.*.partial` files in the output folder.
module pound_files
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_int64_t, c_null_char, c_ptr, c_funloc, c_funptr
   use pound_error, only: error_type, fatal_error, status_input, status_io, status_exists
   use pound_strings, only: str
   use pound_posix, only: posix_rename, posix_unlink, posix_unlink_c, posix_mkdir, posix_file_id, &
                          posix_is_directory, posix_lock_directory, posix_unlock_directory, &
                          posix_exit_now, posix_strerror, posix_getpid, posix_set_handler, &
                          posix_ignore_signal, posix_write_stderr_c, sig_int, sig_term, sig_xfsz, sig_pipe, &
                          errno_enoent, errno_eexist
   implicit none
   private

   public :: delete_file, file_stem, file_exists, directory_of, join_path
   public :: output_set, plan_outputs, publish_outputs, discard_outputs, install_signal_cleanup
   public :: make_directories, same_file

   !> The outputs of one run: final and temporary names, and the files they must not replace.
   type :: output_set
      !> Output folder, as given.
      character(len=:), allocatable :: dir
      !> Final names.
      character(len=:), allocatable :: listing, h5, summary
      !> This run's temporaries and the names an existing `.h5` and `_summary.csv` are set aside under.
      character(len=:), allocatable :: listing_tmp, h5_tmp, previous, summary_tmp, summary_previous
      !> Input files an output must never be (deck, record); '' entries are ignored.
      character(len=:), allocatable :: inputs(:)
   end type output_set

   !> Longest temporary name the signal handler can remove.
   integer, parameter :: max_name = 4096
   !> Temporaries registered for removal by the signal handler (NUL-terminated).
   character(kind=c_char), volatile, save :: registered(max_name, 3)
   logical, volatile, save :: in_use(3) = .false.
   !> Inside the renames of a publication: a signal is only recorded.
   logical, volatile, save :: critical = .false.
   integer, volatile, save :: deferred_signal = 0

contains

   ! ------------------------------------------------------------------ planning and publishing

   !> Prepare the outputs of the deck at `deck_path` in `dir`: create `dir` like `mkdir -p`,
   !> refuse final names that are folders or one of `inputs` (same device and inode), and
   !> create this run's two temporaries (empty, exclusively). Nothing is published.
   subroutine plan_outputs(dir, deck_path, inputs, set, error)
      !> Output folder.
      character(len=*), intent(in) :: dir
      !> The deck (its stem names the outputs).
      character(len=*), intent(in) :: deck_path
      !> Input files (deck, record) that an output must not be; blank entries are ignored.
      character(len=*), intent(in) :: inputs(:)
      !> The planned outputs.
      type(output_set), intent(out) :: set
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: stem, tag
      integer :: attempt, i, n

      n = 0
      do i = 1, size(inputs)
         n = max(n, len_trim(inputs(i)))
      end do
      ! Element by element into the allocated length: no reallocation on assignment.
      allocate (character(len=n) :: set%inputs(size(inputs)))
      do i = 1, size(inputs)
         set%inputs(i) = inputs(i)
      end do
      set%dir = dir
      call make_directories(dir, error)
      if (allocated(error)) return
      stem = file_stem(deck_path)
      set%listing = join_path(dir, stem//'.out')
      set%h5 = join_path(dir, stem//'.h5')
      set%summary = join_path(dir, stem//'_summary.csv')
      call check_targets(set, error)
      if (allocated(error)) return
      do attempt = 1, 100
         tag = unique_tag(attempt)
         set%listing_tmp = join_path(dir, '.'//stem//'.out.'//tag//'.partial')
         set%h5_tmp = join_path(dir, '.'//stem//'.h5.'//tag//'.partial')
         set%previous = join_path(dir, '.'//stem//'.h5.'//tag//'.previous.partial')
         set%summary_tmp = join_path(dir, '.'//stem//'_summary.csv.'//tag//'.partial')
         set%summary_previous = join_path(dir, '.'//stem//'_summary.csv.'//tag//'.previous.partial')
         if (len(set%h5_tmp) >= max_name .or. len(set%listing_tmp) >= max_name .or. &
             len(set%summary_tmp) >= max_name) then
            call fatal_error(error, 'output path too long: '//set%summary_tmp, status_input)
            return
         end if
         call create_new(set%listing_tmp, 1, error)
         if (allocated(error)) then
            if (error%status == status_exists) cycle
            return
         end if
         call create_new(set%h5_tmp, 2, error)
         if (.not. allocated(error)) call create_new(set%summary_tmp, 3, error)
         if (.not. allocated(error)) return
         call discard_outputs(set)
         if (error%status /= status_exists) return
      end do
   end subroutine plan_outputs

   !> Publish both temporaries under their final names, or neither (see the module notes).
   !> On failure the temporaries are removed and an existing pair is left as it was.
   subroutine publish_outputs(set, error)
      !> Planned outputs whose temporaries are complete.
      type(output_set), intent(in) :: set
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(c_ptr) :: lock
      integer :: e
      logical :: had_previous, had_summary, summary_published

      ! Without flock (some network file systems) the pair is still published as a pair,
      ! only not serialised with other runs.
      call posix_lock_directory(set%dir, lock, e)
      critical = .true.
      had_previous = .false.
      had_summary = .false.
      summary_published = .false.
      call check_targets(set, error)
      if (.not. allocated(error)) then
         e = posix_rename(set%h5, set%previous)
         had_previous = e == 0
         if (e /= 0 .and. e /= errno_enoent) then
            call fatal_error(error, 'cannot replace '//set%h5//': '//posix_strerror(e), status_io)
         end if
      end if
      if (.not. allocated(error)) then
         e = posix_rename(set%summary, set%summary_previous)
         had_summary = e == 0
         if (e /= 0 .and. e /= errno_enoent) then
            call fatal_error(error, 'cannot replace '//set%summary//': '//posix_strerror(e), status_io)
            call restore_previous(.false.)
         end if
      end if
      call publish(set%h5_tmp, set%h5, .false.)
      call publish(set%summary_tmp, set%summary, .true.)
      summary_published = .not. allocated(error)
      call publish(set%listing_tmp, set%listing, .true.)
      if (.not. allocated(error)) then
         if (had_previous) e = posix_unlink(set%previous)
         if (had_summary) e = posix_unlink(set%summary_previous)
      end if
      call discard_outputs(set)
      call posix_unlock_directory(lock)
      call leave_critical()

   contains

      !> Rename the temporary `tmp` to its final name `final` unless an error came before; on
      !> failure the error and the undo (`h5_in_place`: the new `.h5` is in place already).
      subroutine publish(tmp, final, h5_in_place)
         character(len=*), intent(in) :: tmp, final
         logical, intent(in) :: h5_in_place
         character(len=:), allocatable :: text

         if (allocated(error)) return
         e = posix_rename(tmp, final)
         if (e == 0) return
         text = 'cannot publish '//final//' (renaming '//tmp//'): '//posix_strerror(e)
         if (h5_in_place) text = text//'; '//set%h5//' was not published either'
         call fatal_error(error, text, status_io)
         call restore_previous(h5_in_place)
      end subroutine publish

      !> Undo: the new files in place removed (`published`: the new `.h5`, and the new
      !> `_summary.csv` if it was renamed), the previous ones renamed back.
      subroutine restore_previous(published)
         logical, intent(in) :: published
         integer :: ignore

         if (published) ignore = posix_unlink(set%h5)
         if (summary_published) ignore = posix_unlink(set%summary)
         if (had_previous) ignore = posix_rename(set%previous, set%h5)
         if (had_summary) ignore = posix_rename(set%summary_previous, set%summary)
      end subroutine restore_previous

   end subroutine publish_outputs

   !> Remove this run's temporaries (errors ignored: used on the way out of a failure).
   subroutine discard_outputs(set)
      !> Planned outputs.
      type(output_set), intent(in) :: set
      integer :: ignore

      in_use = .false.
      if (allocated(set%listing_tmp)) ignore = posix_unlink(set%listing_tmp)
      if (allocated(set%h5_tmp)) ignore = posix_unlink(set%h5_tmp)
      if (allocated(set%summary_tmp)) ignore = posix_unlink(set%summary_tmp)
   end subroutine discard_outputs

   !> Refuse final names that are folders or the same file as one of the inputs.
   subroutine check_targets(set, error)
      type(output_set), intent(in) :: set
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: target
      integer :: i, k

      do k = 1, 3
         if (k == 1) then
            target = set%h5
         else if (k == 2) then
            target = set%listing
         else
            target = set%summary
         end if
         if (posix_is_directory(target)) then
            call fatal_error(error, 'output '//target//' is a folder: remove or rename it', status_io)
            return
         end if
         do i = 1, size(set%inputs)
            if (len_trim(set%inputs(i)) == 0) cycle
            if (same_file(target, trim(set%inputs(i)))) then
               call fatal_error(error, 'output '//target//' would replace the input file '// &
                                trim(set%inputs(i))//': choose another output folder (-o) or rename the deck', status_input)
               return
            end if
         end do
      end do
   end subroutine check_targets

   !> Create `path` empty and exclusively, and register it for removal on a signal (slot).
   subroutine create_new(path, slot, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: slot
      type(error_type), allocatable, intent(out) :: error
      integer :: u, ios
      character(len=512) :: msg
      logical :: there

      open (newunit=u, file=path, status='new', action='write', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         inquire (file=path, exist=there)
         if (there) then
            call fatal_error(error, 'cannot create '//path//': it exists', status_exists)
         else
            call fatal_error(error, 'cannot write in the output folder '//directory_of(path)//': '//trim(msg), status_io)
         end if
         return
      end if
      close (u, iostat=ios)
      call register(path, slot)
   end subroutine create_new

   !> '<pid>-<tag>' for a temporary name; `attempt` varies it after a collision.
   function unique_tag(attempt) result(tag)
      integer, intent(in) :: attempt
      character(len=:), allocatable :: tag
      character(len=*), parameter :: digits = '0123456789abcdefghijklmnopqrstuvwxyz'
      integer(c_int64_t) :: count, x
      integer :: i
      character(len=6) :: t

      ! Clock ticks mixed by a multiplicative step that stays within 64 bits; uniqueness
      ! comes from the pid and the exclusive creation, the tag only makes reuse unlikely.
      call system_clock(count)
      x = mod(abs(count), 2147483647_c_int64_t)*48271_c_int64_t + int(attempt, c_int64_t)*7919_c_int64_t
      do i = 1, len(t)
         t(i:i) = digits(mod(x, 36_c_int64_t) + 1:mod(x, 36_c_int64_t) + 1)
         x = x/36
      end do
      tag = str(posix_getpid())//'-'//t
   end function unique_tag

   ! ------------------------------------------------------------------ signals

   !> Ignore SIGXFSZ and SIGPIPE (a write beyond `ulimit -f` then fails with EFBIG, a write to
   !> a pipe whose reader is gone with EPIPE, and both are reported) and make SIGINT and
   !> SIGTERM remove this run's temporaries and exit with 128 + signal.
   subroutine install_signal_cleanup()
      type(c_funptr), volatile :: handler

      handler = c_funloc(on_signal)
      call posix_ignore_signal(sig_xfsz)
      call posix_ignore_signal(sig_pipe)
      call posix_set_handler(sig_int, handler)
      call posix_set_handler(sig_term, handler)
   end subroutine install_signal_cleanup

   !> Handler of SIGINT and SIGTERM (async-signal-safe: unlink, write, _exit).
   subroutine on_signal(sig) bind(C)
      integer(c_int), value :: sig

      if (critical) then
         deferred_signal = int(sig)
         return
      end if
      call leave_on_signal(int(sig))
   end subroutine on_signal

   !> End of the renames: act on a signal that arrived during them.
   subroutine leave_critical()
      critical = .false.
      if (deferred_signal /= 0) call leave_on_signal(deferred_signal)
   end subroutine leave_critical

   subroutine leave_on_signal(sig)
      integer, intent(in) :: sig
      character(len=*, kind=c_char), parameter :: &
         msg_int = 'pound: interrupted (SIGINT), temporary files removed'//achar(10), &
         msg_term = 'pound: terminated (SIGTERM), temporary files removed'//achar(10)
      integer :: k

      do k = 1, size(in_use)
         if (in_use(k)) call posix_unlink_c(registered(:, k))
      end do
      if (sig == sig_int) then
         call posix_write_stderr_c(msg_int, len(msg_int))
      else
         call posix_write_stderr_c(msg_term, len(msg_term))
      end if
      call posix_exit_now(128 + sig)
   end subroutine leave_on_signal

   subroutine register(path, slot)
      character(len=*), intent(in) :: path
      integer, intent(in) :: slot
      integer :: i

      in_use(slot) = .false.
      do i = 1, len(path)
         registered(i, slot) = path(i:i)
      end do
      registered(len(path) + 1, slot) = c_null_char
      in_use(slot) = .true.
   end subroutine register

   ! ------------------------------------------------------------------ paths and files

   !> Create folder `path` and its missing parents, like `mkdir -p`.
   subroutine make_directories(path, error)
      !> Folder.
      character(len=*), intent(in) :: path
      !> Error state: a component exists and is not a folder, or cannot be created.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, e

      if (len(path) == 0) then
         call fatal_error(error, 'the output folder name is empty', status_input)
         return
      end if
      do i = 2, len(path) + 1
         if (i <= len(path)) then
            if (path(i:i) /= '/') cycle
            if (path(i - 1:i - 1) == '/') cycle
         end if
         if (posix_is_directory(path(:i - 1))) cycle
         e = posix_mkdir(path(:i - 1))
         if (e == 0) cycle
         if (e == errno_eexist) then
            if (posix_is_directory(path(:i - 1))) cycle
            call fatal_error(error, 'cannot create the output folder '//path//': '//path(:i - 1)// &
                             ' exists and is not a folder', status_exists)
         else
            call fatal_error(error, 'cannot create the output folder '//path//': '//path(:i - 1)// &
                             ': '//posix_strerror(e), status_io)
         end if
         return
      end do
   end subroutine make_directories

   !> Whether two paths name the same existing file (same device and inode).
   function same_file(a, b) result(same)
      !> Paths.
      character(len=*), intent(in) :: a, b
      logical :: same
      integer(c_int64_t) :: dev_a, ino_a, dev_b, ino_b
      integer :: ea, eb

      call posix_file_id(a, dev_a, ino_a, ea)
      call posix_file_id(b, dev_b, ino_b, eb)
      same = ea == 0 .and. eb == 0 .and. dev_a == dev_b .and. ino_a == ino_b
   end function same_file

   !> Delete a file if it exists (errors ignored: used on the way out of a failure).
   subroutine delete_file(path)
      !> File to delete.
      character(len=*), intent(in) :: path
      integer :: ignore

      ignore = posix_unlink(path)
   end subroutine delete_file

   !> Whether a file exists.
   function file_exists(path) result(exists)
      !> Path to test.
      character(len=*), intent(in) :: path
      logical :: exists

      inquire (file=path, exist=exists)
   end function file_exists

   !> File name without directory and without its last extension: 'in/deck.nml' -> 'deck'.
   pure function file_stem(path) result(stem)
      !> A path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: stem
      integer :: slash, dot

      slash = index(path, '/', back=.true.)
      stem = path(slash + 1:)
      dot = index(stem, '.', back=.true.)
      if (dot > 1) stem = stem(:dot - 1)
   end function file_stem

   !> Directory part of a path ('.' when there is none): 'in/deck.nml' -> 'in'.
   pure function directory_of(path) result(dir)
      !> A path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: slash

      slash = index(path, '/', back=.true.)
      if (slash == 0) then
         dir = '.'
      else if (slash == 1) then
         dir = '/'
      else
         dir = path(:slash - 1)
      end if
   end function directory_of

   !> `dir/name`, or `name` itself when it is absolute.
   pure function join_path(dir, name) result(path)
      !> Directory.
      character(len=*), intent(in) :: dir
      !> File name, relative or absolute.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path

      if (len(name) > 0) then
         if (name(1:1) == '/') then
            path = name
            return
         end if
      end if
      if (dir == '.' .or. len(dir) == 0) then
         path = name
      else if (dir(len(dir):len(dir)) == '/') then
         path = dir//name
      else
         path = dir//'/'//name
      end if
   end function join_path

end module pound_files
