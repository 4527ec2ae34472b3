!> How much memory a run needs, estimated from the deck before anything large is allocated,
!> and how much the machine can give it.
!>
!> The estimate counts what grows with the run (8-byte reals, 4-byte integers):
!>
!> - ground motion: the acceleration at every step, n_steps + 1 values, and the samples at
!>   the output times written to the HDF5 file;
!> - histories, per analysis (uncoupled; coupled when the deck has contact; one more coupled
!>   result while a `&sweep` runs): output times and the 6 energy terms (7 n_out), and
!>   n_out x floors x stored quantities for every building, and with `node_histories`
!>   n_out x DOFs of every frame (the frame's DOF bound below); when the histories of the
!>   uncoupled and coupled runs are streamed to the file (`streamed`: the program's one
!>   deck, one motion, without node histories), one block of output samples
!>   (`history_block`) instead of n_out;
!> - contact histories (coupled analyses): force, closing, penetration, plastic penetration
!>   and state per joint, 36 bytes x joints x n_out;
!> - models and contact systems: a few hundred bytes per floor and per joint (banded
!>   matrices), plus a fixed 64 MiB for the program, its libraries and HDF5; a frame
!>   (`model = 'frame'`) counts its DOFs, 3 per node (3 n_lines (n_storeys column_elements + 1)),
!>   each with 8 band matrices of half-bandwidth 3 n_lines + 2 (K+G, M, C, factors, work),
!>   and per analysis its deformed shapes (DOFs x n_storeys, at most `deformed_limit`) and
!>   column-segment peaks; with `free_steps = 'exact'`, 5 n^2 reals per building of n floors
!>   (its modes in up to three integrators and the dense eigenproblem of their set-up), and
!>   12 n^2 per frame of n DOFs (shapes and coordinate rows, the condensed set-up); a
!>   building in plan (`model = 'plan'`) counts its 3 n_storeys DOFs with 8 band matrices
!>   of half-bandwidth 5, per analysis its result rows' peaks ((n_planes + 1) n_storeys,
!>   3 reals each), with `node_histories` its DOFs, and 5 (3 n)^2 reals for exact free steps.
!>
!> The memory available is the smallest of: MemAvailable of /proc/meminfo, the memory
!> limit less the current use of the process's cgroup and of each of its ancestors
!> (cgroup v2 memory.max, v1 memory.limit_in_bytes; the mount's root inside a container),
!> and the address-space limit (RLIMIT_AS, `ulimit -v`) less the address space already in
!> use (VmSize). A run may use `usable_fraction` (80 %) of it.
module pound_memory
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_response, only: deformed_limit
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_config, only: deck_type, n_history_quantities, history_names, is_frame
   use pound_building_spec, only: is_plan
   use pound_posix, only: posix_address_space_limit
   use pound_analysis_plan, only: steps_of_int64
   use pound_response, only: history_block
   implicit none
   private

   public :: memory_estimate, estimate_memory, memory_available, memory_refusal, format_bytes
   public :: usable_fraction

   !> Share of the available memory a run may plan to use.
   real(dp), parameter :: usable_fraction = 0.8_dp
   !> Fixed allowance for the program, its libraries and HDF5 (bytes).
   real(dp), parameter :: base_bytes = 64.0_dp*1024.0_dp**2
   !> Bytes per floor for a model and its integrator (banded matrices, modes, work arrays).
   real(dp), parameter :: model_bytes_per_floor = 512.0_dp

   !> The memory a deck needs, in bytes, by part.
   type :: memory_estimate
      !> Time steps and output samples (t = 0 included), as reals: they may exceed integers.
      real(dp) :: n_steps = 0.0_dp, n_out = 0.0_dp
      !> Number of analyses whose histories are held at once (1 to 3).
      integer :: n_analyses = 0
      !> Floors x stored quantities, summed over the buildings.
      integer :: history_columns = 0
      !> DOF histories (`node_histories`): the frames' DOFs (an upper bound), summed.
      real(dp) :: node_columns = 0.0_dp
      !> The uncoupled and coupled histories are streamed (one block held).
      logical :: streamed = .false.
      !> Parts (bytes).
      real(dp) :: ground = 0.0_dp, histories = 0.0_dp, contact = 0.0_dp, models = 0.0_dp
      !> Sum of the parts and the fixed allowance (bytes).
      real(dp) :: total = 0.0_dp
   end type memory_estimate

contains

   !> Estimate the memory the run of `deck` needs (see the module notes).
   pure function estimate_memory(deck, streamed) result(est)
      !> A validated deck.
      type(deck_type), intent(in) :: deck
      !> The uncoupled and coupled histories are streamed to the file (default no).
      logical, intent(in), optional :: streamed
      type(memory_estimate) :: est
      real(dp) :: joints, floors, every, frame_bytes, lines, dofs, blocks
      integer :: ib, ic, n_stored, n_held

      est%n_steps = real(steps_of_int64(deck%analysis%t_end, deck%analysis%dt), dp)
      every = real(max(deck%analysis%output_every, 1), dp)
      est%n_out = aint(est%n_steps/every) + 1.0_dp
      n_stored = count(deck%analysis%store)
      floors = 0.0_dp
      est%history_columns = 0
      if (allocated(deck%buildings)) then
         do ib = 1, size(deck%buildings)
            floors = floors + real(deck%buildings(ib)%n_storeys, dp)
            est%history_columns = est%history_columns + deck%buildings(ib)%n_storeys*n_stored
         end do
      end if
      frame_bytes = 0.0_dp
      if (allocated(deck%buildings)) then
         do ib = 1, size(deck%buildings)
            if (is_plan(deck%buildings(ib))) then
               associate (b => deck%buildings(ib))
                  dofs = 3.0_dp*real(b%n_storeys, dp)
                  lines = 0.0_dp
                  if (allocated(b%planes)) lines = real(size(b%planes), dp)
                  frame_bytes = frame_bytes + 8.0_dp*8.0_dp*6.0_dp*dofs + &
                                2.0_dp*8.0_dp*3.0_dp*(lines + 1.0_dp)*real(b%n_storeys, dp)
                  if (deck%analysis%node_histories) est%node_columns = est%node_columns + dofs
                  if (deck%analysis%free_steps == 'exact') frame_bytes = frame_bytes + 5.0_dp*8.0_dp*dofs**2
               end associate
            end if
            if (.not. is_frame(deck%buildings(ib))) cycle
            associate (b => deck%buildings(ib))
               lines = real(size(b%bay_width) + 1, dp)
               dofs = 3.0_dp*lines*(real(b%n_storeys, dp)*real(b%column_elements, dp) + 1.0_dp)
               frame_bytes = frame_bytes + 8.0_dp*8.0_dp*dofs*(3.0_dp*lines + 3.0_dp)
               ! Per analysis: the deformed shapes at the storey-shear peaks (within
               ! deformed_limit: the pool of n_storeys + 1 vectors and, at the end, the shapes in
               ! storey order) and the column segments' member rows (peak, time, work; 4 each).
               frame_bytes = frame_bytes + 2.0_dp*8.0_dp*(min(dofs*real(2*b%n_storeys + 1, dp), &
                                                              2.0_dp*real(deformed_limit, dp)) + &
                             12.0_dp*lines*real(b%n_storeys, dp)*real(b%column_elements, dp))
               if (deck%analysis%node_histories) est%node_columns = est%node_columns + dofs
               ! Exact free steps of a frame (DOFs without mass): the n x n shapes and
               ! coordinate rows in up to three integrators, and the dense set-up (K, the
               ! condensed eigenproblem and its blocks), 12 n^2 reals in all.
               if (deck%analysis%free_steps == 'exact') frame_bytes = frame_bytes + 12.0_dp*8.0_dp*dofs**2
            end associate
         end do
         ! Exact free steps: the n x n modes of each building, held by up to three integrators
         ! at once (the uncoupled one, the coupled model's, its run's copy), and the dense
         ! eigenproblem of their set-up.
         if (deck%analysis%free_steps == 'exact') then
            do ib = 1, size(deck%buildings)
               if (is_frame(deck%buildings(ib)) .or. is_plan(deck%buildings(ib))) cycle
               frame_bytes = frame_bytes + 5.0_dp*8.0_dp*real(deck%buildings(ib)%n_storeys, dp)**2
            end do
         end if
      end if
      joints = 0.0_dp
      if (allocated(deck%contacts)) then
         do ic = 1, size(deck%contacts)
            if (allocated(deck%contacts(ic)%floor_left)) &
               joints = joints + real(size(deck%contacts(ic)%floor_left), dp)
         end do
      end if
      est%n_analyses = 1
      if (joints > 0.0_dp) est%n_analyses = 2
      if (joints > 0.0_dp .and. deck%sweep%active) est%n_analyses = 3

      est%ground = 8.0_dp*(est%n_steps + 1.0_dp) + 8.0_dp*est%n_out
      est%histories = real(est%n_analyses, dp)*8.0_dp*est%n_out*(7.0_dp + real(est%history_columns, dp) + &
                                                                  est%node_columns)
      if (present(streamed)) est%streamed = streamed
      if (est%streamed .and. allocated(deck%buildings)) then
         ! One block per building and stored quantity for the uncoupled and coupled runs; a
         ! sweep's gap runs hold their whole histories.
         blocks = 0.0_dp
         do ib = 1, size(deck%buildings)
            associate (n => deck%buildings(ib)%n_storeys)
               blocks = blocks + real(n, dp)*real(n_stored, dp)* &
                        real(history_block(n, int(min(est%n_out, real(huge(1), dp))), 0), dp)
            end associate
         end do
         n_held = est%n_analyses - min(est%n_analyses, 2)
         est%histories = real(est%n_analyses, dp)*8.0_dp*est%n_out*7.0_dp + &
                         real(min(est%n_analyses, 2), dp)*8.0_dp*blocks + &
                         real(n_held, dp)*8.0_dp*est%n_out*real(est%history_columns, dp)
      end if
      est%contact = real(est%n_analyses - 1, dp)*36.0_dp*joints*est%n_out
      est%models = model_bytes_per_floor*floors + 8.0_dp*(4.0_dp*joints*floors + 16.0_dp*joints**2) + frame_bytes
      est%total = base_bytes + est%ground + est%histories + est%contact + est%models
   end function estimate_memory

   !> Memory the machine can give this process (bytes), and where that figure comes from.
   subroutine memory_available(bytes, source)
      !> Available bytes (a huge value when nothing can be read).
      real(dp), intent(out) :: bytes
      !> E.g. 'MemAvailable' or 'the address-space limit (ulimit -v)'.
      character(len=:), allocatable, intent(out) :: source
      real(dp) :: value, used
      integer(int64) :: limit
      logical :: found

      bytes = huge(1.0_dp)
      source = 'no limit found'
      call read_keyed_kib('/proc/meminfo', 'MemAvailable:', value, found)
      if (found) call lower(value, 'MemAvailable (/proc/meminfo)')
      call cgroup_limit('', '/sys/fs/cgroup', 'memory.max', 'memory.current', &
                        'the cgroup memory limit (memory.max)')
      call cgroup_limit('memory', '/sys/fs/cgroup/memory', 'memory.limit_in_bytes', 'memory.usage_in_bytes', &
                        'the cgroup memory limit (memory.limit_in_bytes)')
      limit = posix_address_space_limit()
      if (limit >= 0) then
         call read_keyed_kib('/proc/self/status', 'VmSize:', used, found)
         if (.not. found) used = 0.0_dp
         call lower(real(limit, dp) - used, 'the address-space limit (RLIMIT_AS, ulimit -v)')
      end if

   contains

      !> The tightest limit less use of the process's cgroup and its ancestors (the group's
      !> path from /proc/self/cgroup for controllers `controllers`, under `root`; the root
      !> itself when the path is not visible, as inside a container).
      subroutine cgroup_limit(controllers, root, limit_file, usage_file, name)
         character(len=*), intent(in) :: controllers, root, limit_file, usage_file, name
         character(len=:), allocatable :: group
         real(dp) :: cap, use
         logical :: has_cap, has_use
         integer :: slash

         group = cgroup_path(controllers)
         do
            call read_number(root//group//'/'//limit_file, cap, has_cap)
            if (has_cap) then
               call read_number(root//group//'/'//usage_file, use, has_use)
               if (.not. has_use) use = 0.0_dp
               call lower(cap - use, name)
            end if
            if (len(group) == 0) exit
            slash = index(group, '/', back=.true.)
            group = group(:max(slash - 1, 0))
         end do
      end subroutine cgroup_limit

      subroutine lower(candidate, name)
         real(dp), intent(in) :: candidate
         character(len=*), intent(in) :: name

         if (candidate < bytes) then
            bytes = max(candidate, 0.0_dp)
            source = name
         end if
      end subroutine lower

   end subroutine memory_available

   !> The refusal when `est` exceeds `usable_fraction` of `available` bytes (unallocated
   !> otherwise): one message naming the deck, the estimate by part and the variables to change.
   pure subroutine memory_refusal(deck, est, available, source, error)
      !> The deck (its path, &analysis values).
      type(deck_type), intent(in) :: deck
      !> Its estimate.
      type(memory_estimate), intent(in) :: est
      !> Available bytes and where the figure comes from.
      real(dp), intent(in) :: available
      character(len=*), intent(in) :: source
      !> Error state: set when the run does not fit.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: stored, parts, nodes
      integer :: q

      if (est%total <= usable_fraction*available) return
      stored = ''
      do q = 1, n_history_quantities
         if (.not. deck%analysis%store(q)) cycle
         if (len(stored) > 0) stored = stored//' '
         stored = stored//trim(history_names(q))
      end do
      if (len(stored) == 0) stored = 'none'
      nodes = ''
      if (est%node_columns > 0.0_dp) nodes = ' + '//str_count(est%node_columns)//' DOF histories (node_histories)'
      if (est%streamed) then
         parts = ' for '//str_count(est%n_out)//' output times x '//str(est%n_analyses)// &
                 ' analyses, floor histories streamed to the file in blocks'
      else
         parts = ' = '//str_count(est%n_out)//' output times x '//str(est%history_columns)// &
                 ' floor histories'//nodes//' x '//str(est%n_analyses)//' analyses'
      end if
      call fatal_error(error, deck_label(deck)//'&analysis: the run needs about '// &
                       format_bytes(est%total)//' of memory (histories '//format_bytes(est%histories)// &
                       parts//'; contact histories '// &
                       format_bytes(est%contact)//'; ground motion '//format_bytes(est%ground)// &
                       ' for '//str_count(est%n_steps)//' steps), more than the '// &
                       format_bytes(usable_fraction*available)//' a run may use ('// &
                       str(nint(100*usable_fraction))//' % of '//format_bytes(available)//', '// &
                       source//'): raise output_every (now '//str(deck%analysis%output_every)// &
                       '), store fewer history quantities (now '//stored//')'//trim(merge(' or no DOF histories', &
                       '                    ', est%node_columns > 0.0_dp))//', shorten t_end (now '// &
                       short_real(deck%analysis%t_end)//' s) or enlarge dt (now '// &
                       short_real(deck%analysis%dt)//' s)')
   end subroutine memory_refusal

   !> Bytes in readable units: '512 B', '1.50 MB', '7.20 GB' (powers of 1000).
   pure function format_bytes(bytes) result(text)
      !> A number of bytes.
      real(dp), intent(in) :: bytes
      character(len=:), allocatable :: text
      character(len=*), parameter :: units(5) = ['kB', 'MB', 'GB', 'TB', 'PB']
      character(len=32) :: buf
      real(dp) :: x
      integer :: k

      if (bytes < 1000.0_dp) then
         write (buf, '(i0,a)') nint(max(bytes, 0.0_dp)), ' B'
      else
         x = bytes
         k = 0
         do while (x >= 1000.0_dp .and. k < size(units))
            x = x/1000.0_dp
            k = k + 1
         end do
         write (buf, '(f0.2,1x,a)') x, units(k)
      end if
      text = trim(buf)
   end function format_bytes

   !> A real in few characters: '20', '0.25', '1e-06', '1.5e+09'.
   pure function short_real(x) result(text)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf
      integer :: e

      if (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e7_dp) then
         write (buf, '(f0.6)') x
         text = trim(buf)
         do while (text(len(text):len(text)) == '0')
            text = text(:len(text) - 1)
         end do
         if (text(len(text):len(text)) == '.') text = text(:len(text) - 1)
         if (text(1:1) == '.') text = '0'//text
      else
         write (buf, '(es12.5e2)') x
         text = trim(adjustl(buf))
         e = index(text, 'E')
         do while (text(e - 1:e - 1) == '0')
            text = text(:e - 2)//text(e:)
            e = e - 1
         end do
         if (text(e - 1:e - 1) == '.') text = text(:e - 2)//text(e:)
         e = index(text, 'E')
         text = text(:e - 1)//'e'//text(e + 1:)
      end if
   end function short_real

   !> A whole count held as a real, without exponent up to 1e18.
   pure function str_count(x) result(text)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf

      if (x < 1.0e18_dp) then
         write (buf, '(i0)') nint(x, int64)
      else
         write (buf, '(es10.3)') x
      end if
      text = trim(adjustl(buf))
   end function str_count

   !> 'path: ' when the deck has a path, '' otherwise.
   pure function deck_label(deck) result(label)
      type(deck_type), intent(in) :: deck
      character(len=:), allocatable :: label

      label = ''
      if (allocated(deck%path)) label = deck%path//': '
   end function deck_label

   !> The cgroup path ('' for the root, else '/a/b') of this process in /proc/self/cgroup
   !> (lines id:controllers:path) for `controllers` ('' is cgroup v2, 'memory' v1).
   function cgroup_path(controllers) result(path)
      character(len=*), intent(in) :: controllers
      character(len=:), allocatable :: path
      character(len=4096) :: line
      integer :: u, ios, c1, c2

      path = ''
      open (newunit=u, file='/proc/self/cgroup', status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         c1 = index(line, ':')
         if (c1 == 0) cycle
         c2 = index(line(c1 + 1:), ':') + c1
         if (c2 == c1) cycle
         if (line(c1 + 1:c2 - 1) /= controllers) cycle
         path = trim(line(c2 + 1:))
         if (path == '/') path = ''
         exit
      end do
      close (u, iostat=ios)
   end function cgroup_path

   !> Value (kiB, returned in bytes) of the line starting with `key` in a /proc file.
   subroutine read_keyed_kib(path, key, bytes, found)
      character(len=*), intent(in) :: path, key
      real(dp), intent(out) :: bytes
      logical, intent(out) :: found
      character(len=256) :: line
      integer :: u, ios
      real(dp) :: kib

      found = .false.
      bytes = 0.0_dp
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      do
         read (u, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, key) == 1) then
            read (line(len(key) + 1:), *, iostat=ios) kib
            if (ios == 0) then
               bytes = 1024.0_dp*kib
               found = .true.
            end if
            exit
         end if
      end do
      close (u, iostat=ios)
   end subroutine read_keyed_kib

   !> A file holding one number of bytes ('max' or anything unreadable: not found).
   subroutine read_number(path, bytes, found)
      character(len=*), intent(in) :: path
      real(dp), intent(out) :: bytes
      logical, intent(out) :: found
      character(len=64) :: line
      integer :: u, ios

      found = .false.
      bytes = 0.0_dp
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) return
      read (u, '(a)', iostat=ios) line
      close (u)
      if (ios /= 0) return
      if (verify(trim(line), '0123456789') /= 0 .or. len_trim(line) == 0) return
      read (line, *, iostat=ios) bytes
      ! cgroup v1 reports "no limit" as a huge page-rounded number.
      found = ios == 0 .and. bytes < 1.0e18_dp
   end subroutine read_number

end module pound_memory
