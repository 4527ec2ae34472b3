!> The listing (`.out`): a fixed-width report readable in a terminal and on paper.
!>
!> Every write is checked: the first failure (no space left, file too large, ...) is kept
!> and reported by `listing_io_error`, which the caller asks after the last write.
module pound_listing
   use pound_kinds, only: dp
   use pound_strings, only: counted, fixed_cell, left_cell, right_cell
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_error, only: error_type, fatal_error
   use pound_posix, only: posix_set_errno, posix_storage_error
   use pound_version, only: program_name, program_version
   use pound_config, only: deck_type
   use pound_building, only: building_model
   use pound_structure, only: structure_model, modes_listed
   use pound_response, only: q_u, q_v, q_a_abs, q_drift, q_shear
   use pound_analysis, only: analysis_result
   use pound_contact, only: contact_system
   use pound_contact_law, only: contact_law, rate_name
   use pound_joint_law, only: law_text
   use pound_lemke, only: lemke_status_name
   use pound_influence, only: building_influence
   use pound_config, only: sweep_config, target_names, q_column_shear, q_column_moment
   use pound_sweep, only: sweep_result
   implicit none
   private

   public :: write_listing_header, write_model_summary, write_peak_tables, write_section
   public :: write_contact_summary, write_influence_tables, write_sweep_table, write_column_tables
   public :: write_sweep_column_table
   public :: listing_io_error, open_listing, close_listing, gap_cell, mm, write_warning_lines

   !> Millimetres per metre: gaps, displacements, drifts and penetrations are listed in mm.
   real(dp), parameter :: mm = 1000.0_dp

   !> Modes listed in the model summary (the HDF5 file has every mode the builder computed).
   integer, parameter :: max_listed_modes = modes_listed

   !> Status and message of the last write, and the first failure since the last check.
   integer, save :: ios = 0
   character(len=256), save :: msg = ''
   integer, save :: first_ios = 0
   character(len=256), save :: first_msg = ''

contains

   !> The first write failure since the previous call (unallocated if none), naming `path`;
   !> the record is cleared.
   subroutine listing_io_error(path, error)
      !> File the unit writes to, for the message.
      character(len=*), intent(in) :: path
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      if (first_ios /= 0) call fatal_error(error, 'cannot write the listing '//path//': '//trim(first_msg))
      first_ios = 0
      first_msg = ''
      ios = 0
   end subroutine listing_io_error

   !> Open `path` (created or truncated) for the listing, as a formatted stream so that
   !> `close_listing` can check that every byte reached the file.
   subroutine open_listing(path, u, error)
      !> File.
      character(len=*), intent(in) :: path
      !> Unit opened.
      integer, intent(out) :: u
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      first_ios = 0
      ios = 0
      call posix_set_errno(0)
      open (newunit=u, file=path, status='replace', action='write', access='stream', form='formatted', &
            iostat=ios, iomsg=msg)
      if (ios /= 0) call fatal_error(error, 'cannot write the listing '//path//': '//trim(msg))
   end subroutine open_listing

   !> Close the listing and check it: a failed write, or a file shorter than what was
   !> written (the Fortran run-time can drop a buffer the system refused: no space, file
   !> too large), is an error naming the system's reason.
   subroutine close_listing(u, path, error)
      !> Unit of `open_listing`.
      integer, intent(in) :: u
      !> Its file.
      character(len=*), intent(in) :: path
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      integer(int64) :: written, size_on_disk
      character(len=:), allocatable :: reason
      character(len=80) :: counts

      call listing_io_error(path, error)
      inquire (unit=u, pos=written, iostat=stat)
      if (stat /= 0) written = -1
      close (u, iostat=ios, iomsg=msg)
      if (allocated(error)) return
      if (ios /= 0) then
         call fatal_error(error, 'cannot write the listing '//path//': '//trim(msg))
         return
      end if
      inquire (file=path, size=size_on_disk, iostat=stat)
      if (stat /= 0 .or. written < 1 .or. size_on_disk /= written - 1) then
         reason = posix_storage_error()
         if (len(reason) == 0) reason = 'the file system did not take every byte'
         write (counts, '(a,i0,a,i0,a)') ' (the file holds ', size_on_disk, ' of ', written - 1, ' bytes)'
         call fatal_error(error, 'cannot write the listing '//path//': '//reason//trim(counts))
      end if
   end subroutine close_listing

   !> Warnings of an analysis or a sweep, one line each after '  WARNING: '.
   subroutine write_warning_lines(u, warnings)
      !> Open unit.
      integer, intent(in) :: u
      !> The warnings (none when unallocated).
      character(len=:), allocatable, intent(in) :: warnings(:)
      integer :: i

      if (.not. allocated(warnings)) return
      do i = 1, size(warnings)
         write (u, '(a)', iostat=ios, iomsg=msg) '  WARNING: '//trim(warnings(i))
         call note_io()
      end do
   end subroutine write_warning_lines

   !> Keep the first failed write.
   subroutine note_io()
      if (ios /= 0 .and. first_ios == 0) then
         first_ios = ios
         first_msg = msg
      end if
   end subroutine note_io

   !> Program, version, date, deck, title, units, the summary (when given) and the deck echo.
   subroutine write_listing_header(u, deck, ground_text, summary)
      !> Open unit.
      integer, intent(in) :: u
      !> The deck.
      type(deck_type), intent(in) :: deck
      !> Ground motion summary lines.
      character(len=*), intent(in) :: ground_text(:)
      !> The engineering summary's lines (`pound_summary`), a section of their own after the title block.
      character(len=*), intent(in), optional :: summary(:)
      character(len=8) :: date
      character(len=10) :: time
      integer :: i, start

      call date_and_time(date=date, time=time)
      write (u, '(a)', iostat=ios, iomsg=msg) repeat('=', 78)
      call note_io()
      write (u, '(a)', iostat=ios, iomsg=msg) program_name//' '//program_version// &
         ' - seismic pounding of adjacent buildings (unilateral contact, LCP)'
      call note_io()
      write (u, '(a)', iostat=ios, iomsg=msg) 'run on '//date(1:4)//'-'//date(5:6)//'-'//date(7:8)//' '// &
         time(1:2)//':'//time(3:4)//':'//time(5:6)
      call note_io()
      write (u, '(a)', iostat=ios, iomsg=msg) 'deck:  '//deck%path
      call note_io()
      write (u, '(a)', iostat=ios, iomsg=msg) 'title: '//deck%analysis%title
      call note_io()
      write (u, '(a)', iostat=ios, iomsg=msg) 'units: kN, m, s, t (tonne); accelerations m/s^2; energies kJ; '// &
         'gaps, displacements, drifts and penetrations in mm'
      call note_io()
      write (u, '(a)', iostat=ios, iomsg=msg) repeat('=', 78)
      call note_io()
      if (present(summary)) then
         call write_section(u, 'Summary')
         do i = 1, size(summary)
            write (u, '(a)', iostat=ios, iomsg=msg) '  '//trim(summary(i))
            call note_io()
         end do
      end if
      call write_section(u, 'Deck echo')
      start = 1
      do i = 1, len(deck%text)
         if (deck%text(i:i) == new_line('a')) then
            write (u, '(a)', iostat=ios, iomsg=msg) '  | '//deck%text(start:i - 1)
            call note_io()
            start = i + 1
         end if
      end do
      if (start <= len(deck%text)) write (u, '(a)', iostat=ios, iomsg=msg) '  | '//deck%text(start:)
      call note_io()
      call write_section(u, 'Analysis and ground motion')
      write (u, '(a,es12.4,a,f10.4,a,i0,a,i0)', iostat=ios, iomsg=msg) '  dt =', deck%analysis%dt, ' s   t_end =', &
         deck%analysis%t_end, ' s   steps = ', nint(deck%analysis%t_end/deck%analysis%dt), &
         '   history every ', deck%analysis%output_every
      call note_io()
      do i = 1, size(ground_text)
         write (u, '(a)', iostat=ios, iomsg=msg) '  '//trim(ground_text(i))
         call note_io()
      end do
   end subroutine write_listing_header

   !> A section heading.
   subroutine write_section(u, title)
      !> Open unit.
      integer, intent(in) :: u
      !> Heading text.
      character(len=*), intent(in) :: title

      write (u, '(/,a,/,a)', iostat=ios, iomsg=msg) title, repeat('-', len(title))
      call note_io()
   end subroutine write_section

   !> Per building: storey data, periods and Rayleigh coefficients.
   subroutine write_model_summary(u, models, buildings)
      !> Open unit.
      integer, intent(in) :: u
      !> The buildings' structural models.
      type(structure_model), intent(in) :: models(:)
      !> Their per-kind data (storey table, frame).
      type(building_model), intent(in) :: buildings(:)
      integer :: ib, j
      character(len=3) :: pd

      call write_section(u, 'Models (shear buildings: rigid beams, one lateral DOF per floor; '// &
                         'frames: planar beam-column elements)')
      do ib = 1, size(models)
         associate (b => models(ib), s => buildings(ib))
            pd = 'off'
            if (s%p_delta) pd = 'on'
            if (allocated(s%frame)) then
               call write_frame_summary(u, b, s)
            else
               write (u, '(/,a)', iostat=ios, iomsg=msg) &
                  '  Building '//b%name//': '//counted(b%n, 'storey')//', P-Delta '//trim(pd)
               call note_io()
               write (u, '(a)', iostat=ios, iomsg=msg) &
                  '  storey    h [m]    mass [t]     k [kN/m]      P [kN]   P/h [kN/m]  theta=P/(hk)'
               call note_io()
               do j = 1, b%n
                  write (u, '(2x,i6,a9,a12,es13.5,es12.4,es13.5,a14)', iostat=ios, iomsg=msg) &
                     j, fixed_cell(s%height(j), 9, 3, .true.), fixed_cell(s%floor_mass(j), 12, 4, .true.), &
                     s%storey_stiffness(j), s%axial_load(j), s%geometric_stiffness(j), &
                     fixed_cell(s%geometric_stiffness(j)/s%storey_stiffness(j), 14, 5)
                  call note_io()
               end do
            end if
            if (allocated(s%frame)) then
               write (u, '(a)', iostat=ios, iomsg=msg) '    mode      T [s]      f [Hz]  omega [rad/s]'// &
                  '  Gamma [t^0.5]  eff. mass [%]  cumulative [%]'
            else
               write (u, '(a)', iostat=ios, iomsg=msg) '    mode      T [s]      f [Hz]  omega [rad/s]'
            end if
            call note_io()
            do j = 1, min(size(b%period), max_listed_modes)
               if (allocated(s%frame)) then
                  write (u, '(2x,i6,a11,a12,a15,es15.5,2a15)', iostat=ios, iomsg=msg) j, &
                     fixed_cell(b%period(j), 11, 5, .true.), fixed_cell(1.0_dp/b%period(j), 12, 5, .true.), &
                     fixed_cell(b%omega(j), 15, 4, .true.), s%frame%participation(j), &
                     fixed_cell(100.0_dp*s%frame%effective_mass(j), 15, 3), &
                     fixed_cell(100.0_dp*sum(s%frame%effective_mass(1:j)), 15, 3)
               else
                  write (u, '(2x,i6,a11,a12,a15)', iostat=ios, iomsg=msg) j, fixed_cell(b%period(j), 11, 5, .true.), &
                     fixed_cell(1.0_dp/b%period(j), 12, 5, .true.), fixed_cell(b%omega(j), 15, 4, .true.)
               end if
               call note_io()
            end do
            if (size(b%period) > max_listed_modes) write (u, '(a,i0,a)', iostat=ios, iomsg=msg) '    (', &
               size(b%period) - max_listed_modes, &
               ' more modes in the HDF5 file)'
            call note_io()
            write (u, '(a,f6.2,a,i0,a,i0,a,es12.5,a,es12.5,a)', iostat=ios, iomsg=msg) '  Rayleigh damping ', &
               100.0_dp*b%damping_ratio, ' % at modes ', b%damping_modes(1), ' and ', &
               b%damping_modes(2), ': a0 = ', b%a0, ' 1/s, a1 = ', b%a1, ' s'
            call note_io()
         end associate
      end do
   end subroutine write_model_summary

   !> A frame's geometry, sections, DOFs and (with P-Delta) its gravity analysis.
   subroutine write_frame_summary(u, b, s)
      !> Open unit.
      integer, intent(in) :: u
      !> Its structural model.
      type(structure_model), intent(in) :: b
      !> The building (a frame).
      type(building_model), intent(in) :: s
      character(len=:), allocatable :: cons
      integer :: j, e, ln, eb

      associate (f => s%frame%frame)
         cons = ''
         if (s%frame%rigid_beams) cons = cons//' rigid_beams'
         if (s%frame%rigid_diaphragm) cons = cons//' rigid_diaphragm'
         if (s%frame%rigid_columns) cons = cons//' rigid_columns'
         if (len(cons) == 0) cons = ' none'
         write (u, '(/,a,i0,a,i0,a,i0,a,i0,a,i0,a)', iostat=ios, iomsg=msg) '  Building '//b%name// &
            ' (frame): ', f%n_storeys, ' storeys, ', f%n_lines, ' column lines, ', f%n_nodes, ' nodes, ', &
            f%n_elements, ' elements, ', b%n, ' DOFs'
         call note_io()
         write (u, '(a,i0,a)', iostat=ios, iomsg=msg) '  half-bandwidth ', b%kd, ', constraints:'//cons// &
            ', base '//s%frame%base
         call note_io()
         if (s%p_delta) then
            write (u, '(a)', iostat=ios, iomsg=msg) "  P-Delta on, geometric stiffness '"//s%frame%geometric// &
               "' of the gravity analysis (unconstrained frame)"
         else
            write (u, '(a)', iostat=ios, iomsg=msg) '  P-Delta off'
         end if
         call note_io()
         write (u, '(a)', iostat=ios, iomsg=msg) '  x of the column lines [m]:'
         call note_io()
         write (u, '(4x,*(a))', iostat=ios, iomsg=msg) (fixed_cell(f%line_x(j), 10, 3), j=1, size(f%line_x))
         call note_io()
         write (u, '(a)', iostat=ios, iomsg=msg) '  storey    h [m]    mass [t]  column E [kN/m2]'// &
            '   A [m2]     I [m4]  beam E [kN/m2]   A [m2]     I [m4]'
         call note_io()
         do j = 1, f%n_storeys
            e = first_element(j, 1)
            eb = first_element(j, 2)
            if (eb == 0) eb = e
            write (u, '(2x,i6,a9,a12,es18.5,2es11.3,es16.5,2es11.3)', iostat=ios, iomsg=msg) j, &
               fixed_cell(s%height(j), 9, 3, .true.), fixed_cell(s%floor_mass(j), 12, 4, .true.), &
               f%element_e(e), f%element_a(e), f%element_i(e), f%element_e(eb), f%element_a(eb), &
               f%element_i(eb)
            call note_io()
         end do
         if (s%p_delta) then
            write (u, '(a,es12.4,a)', iostat=ios, iomsg=msg) '  gravity analysis: total load ', &
               s%frame%gravity%total_load, ' kN; base reactions per column line (H [kN], V [kN], M [kN m]):'
            call note_io()
            do ln = 1, f%n_lines
               write (u, '(4x,i6,3es13.4)', iostat=ios, iomsg=msg) ln, s%frame%gravity%reactions(:, ln)
               call note_io()
            end do
            write (u, '(a)', iostat=ios, iomsg=msg) '  column axial force N [kN] (tension +) at the '// &
               'bottom of each storey, column lines 1.. (at most 8):'
            call note_io()
            do j = 1, f%n_storeys
               write (u, '(4x,i6,8es13.4)', iostat=ios, iomsg=msg) j, &
                  (s%frame%gravity%axial(bottom_column(j, ln)), ln=1, min(f%n_lines, 8))
               call note_io()
            end do
         end if
      end associate

   contains

      !> First element of storey/floor j of kind k (1 column, 2 beam); 0 if none.
      integer function first_element(j, k) result(e)
         integer, intent(in) :: j, k

         do e = 1, s%frame%frame%n_elements
            if (s%frame%frame%element_group(e) == j .and. s%frame%frame%element_kind(e) == k) return
         end do
         e = 0
      end function first_element

      !> The lowest column element of storey j on column line `line`.
      integer function bottom_column(j, line) result(e)
         integer, intent(in) :: j, line

         do e = 1, s%frame%frame%n_elements
            if (s%frame%frame%element_kind(e) == 1 .and. s%frame%frame%element_group(e) == j .and. &
                s%frame%frame%node_line(s%frame%frame%element_nodes(1, e)) == line) return
         end do
         e = 1
      end function bottom_column

   end subroutine write_frame_summary

   !> Peak tables of an analysis: floors (u, v, a_abs) and storeys (drift, shear).
   subroutine write_peak_tables(u, label, models, res)
      !> Open unit.
      integer, intent(in) :: u
      !> Analysis label, e.g. 'Uncoupled'.
      character(len=*), intent(in) :: label
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The analysis result.
      type(analysis_result), intent(in) :: res
      integer :: ib, j

      call write_section(u, label//' response: absolute maxima and the time they occur')
      do ib = 1, size(models)
         associate (b => models(ib), p => res%building(ib)%peak, t => res%building(ib)%peak_time)
            write (u, '(/,a)', iostat=ios, iomsg=msg) '  Building '//b%name
            call note_io()
            write (u, '(a)', iostat=ios, iomsg=msg) &
               '   floor    |u| [mm]    t [s]   |v| [m/s]    t [s]  |a_abs| [m/s2]    t [s]'
            call note_io()
            do j = size(b%floor_dof), 1, -1
               write (u, '(2x,i6,es12.4,a9,es12.4,a9,es16.4,a9)', iostat=ios, iomsg=msg) &
                  j, mm*p(j, q_u), fixed_cell(t(j, q_u), 9, 3), &
                  p(j, q_v), fixed_cell(t(j, q_v), 9, 3), p(j, q_a_abs), fixed_cell(t(j, q_a_abs), 9, 3)
               call note_io()
            end do
            write (u, '(a)', iostat=ios, iomsg=msg) '  storey  |drift| [mm]    t [s]    |Q| [kN]    t [s]'
            call note_io()
            do j = size(b%floor_dof), 1, -1
               write (u, '(2x,i6,es14.4,a9,es12.4,a9)', iostat=ios, iomsg=msg) j, mm*p(j, q_drift), &
                  fixed_cell(t(j, q_drift), 9, 3), p(j, q_shear), fixed_cell(t(j, q_shear), 9, 3)
               call note_io()
            end do
         end associate
      end do
      write (u, '(/,a,es10.3)', iostat=ios, iomsg=msg) &
         '  Energy audit (input = kinetic + strain + damping + contact + plastic), '// &
         'max relative error over time: ', res%energy_error
      call note_io()
      call write_warning_lines(u, res%warnings)
      j = res%n_out
      write (u, '(a)', iostat=ios, iomsg=msg) '  energies at the end [kJ]:'
      call note_io()
      write (u, '(a)', iostat=ios, iomsg=msg) &
         '         input     kinetic      strain     damping     contact     plastic'
      call note_io()
      write (u, '(a,6es12.4)', iostat=ios, iomsg=msg) '  ', res%energy(:, j)
      call note_io()
   end subroutine write_peak_tables

   !> Contact pairs and laws, impacts, time in contact, peak forces, plastic penetration
   !> left, fracture, and the LCP statistics with every fallback event.
   subroutine write_contact_summary(u, cs)
      !> Open unit.
      integer, intent(in) :: u
      !> Contact system at the end of the coupled run.
      type(contact_system), intent(in) :: cs
      integer, parameter :: max_listed_events = 20
      integer :: k, w
      real(dp) :: mean_pivots
      character(len=12) :: fractured
      type(law_text), allocatable :: lines(:)

      call write_section(u, 'Contact (unilateral constraints between facing floors)')
      w = 4
      do k = 1, cs%m
         w = max(w, len(cs%pair(k)%label))
      end do
      write (u, '(a)', iostat=ios, iomsg=msg) '  '//left_cell('pair', w)//'    gap [mm]  '//left_cell('law', 16)// &
         right_cell('k0 [kN/m]', 12)//right_cell('c [kNs/m]', 12)//'  dashpot_rate'
      call note_io()
      do k = 1, cs%m
         associate (p => cs%pair(k))
            write (u, '(2x,a,a12,2x,a16,es12.3,es12.3,2x,a)', iostat=ios, iomsg=msg) &
               left_cell(p%label, w), fixed_cell(mm*p%gap, 12, 3), left_cell(p%law%title(), 16), &
               p%law%stiffness, p%law%dashpot, rate_name(p%law%dashpot_rate)
            call note_io()
         end associate
      end do
      ! The parameters of the laws beyond k0 and c, after the table (not between its rows).
      do k = 1, cs%m
         associate (p => cs%pair(k))
            call p%law%lines(lines)
            if (p%law%restitution <= 0.0_dp .and. size(lines) == 0) cycle
            write (u, '(a)', iostat=ios, iomsg=msg) '  '//p%label//':'
            call note_io()
            if (p%law%restitution > 0.0_dp) then
               write (u, '(4x,a,f6.3,a)', iostat=ios, iomsg=msg) 'c calibrated to the restitution e =', &
                  p%law%restitution, ' (exact relation of the joint: docs/verification.md)'
               call note_io()
            end if
            call law_parameters(p%law)
         end associate
      end do
      write (u, '(/,a)', iostat=ios, iomsg=msg) '  '//left_cell('pair', w)// &
         '   impacts  in_contact [s]  peak r [kN]     t [s]  max_pen. [mm]'// &
         '  plastic_left [mm]  fractured_at [s]'
      call note_io()
      do k = 1, cs%m
         associate (p => cs%joint(k))
            fractured = '          no'
            if (p%fractured) fractured = fixed_cell(p%fracture_time, 12, 4)
            write (u, '(2x,a,i10,a16,es13.4,a10,es15.4,es19.4,6x,a12)', iostat=ios, iomsg=msg) &
               left_cell(cs%pair(k)%label, w), p%impacts, fixed_cell(p%contact_time, 16, 4), &
               p%peak_force, fixed_cell(p%peak_time, 10, 4), mm*p%peak_penetration, mm*p%plastic, fractured
            call note_io()
         end associate
      end do
      do k = 1, cs%m
         if (cs%joint(k)%fractured) write (u, '(a,f10.4,a)', iostat=ios, iomsg=msg) '  joint '//cs%pair(k)%label// &
            ' FRACTURED at t = ', cs%joint(k)%fracture_time, ' s: it carries nothing for the rest of the analysis'
         call note_io()
      end do
      mean_pivots = 0.0_dp
      if (cs%stats%solves > 0) mean_pivots = real(cs%stats%pivots_total, dp)/real(cs%stats%solves, dp)
      write (u, '(/,a)', iostat=ios, iomsg=msg) '  LCP (Lemke, lexicographic) statistics:'
      call note_io()
      write (u, '(a,i0,a,i0,a,i0,a)', iostat=ios, iomsg=msg) &
         '    solves ', cs%stats%solves, ' (q >= 0 without pivoting: ', cs%stats%trivial, &
         '; warm start accepted: ', cs%stats%warm, ')'
      call note_io()
      write (u, '(a,i0,a,i0,a,f8.3)', iostat=ios, iomsg=msg) '    pivots total ', cs%stats%pivots_total, ', max per solve ', &
         cs%stats%pivots_max, ', mean per solve ', mean_pivots
      call note_io()
      write (u, '(a,i0)', iostat=ios, iomsg=msg) &
         '    re-solves (a left-out constraint would close, a segment end was passed): ', &
         cs%stats%resolves
      call note_io()
      if (cs%stats%active_solves > 0) then
         write (u, '(a,i0,a,i0,a,f8.3,a,i0,a,i0,a)', iostat=ios, iomsg=msg) &
            '    active-set method (elastic steps, from the previous step''s set): solves ', &
            cs%stats%active_solves, ', iterations ', cs%stats%active_iterations, ' (mean ', &
            real(cs%stats%active_iterations, dp)/real(cs%stats%active_solves, dp), ', max ', &
            cs%stats%active_iterations_max, '), factor updates ', cs%stats%active_updates, ','
         call note_io()
         write (u, '(a,i0,a)', iostat=ios, iomsg=msg) '      ', cs%stats%active_fallbacks, &
            ' failed and were solved by Lemke (counted above)'
         call note_io()
      end if
      write (u, '(a,i0)', iostat=ios, iomsg=msg) &
         '    largest LCP (contact + yield + segment-end rows): ', cs%stats%largest_lcp
      call note_io()
      write (u, '(a,i0)', iostat=ios, iomsg=msg) '    non-convex steps (softening rows in the LCP): ', cs%stats%nonconvex
      call note_io()
      write (u, '(a,i0)', iostat=ios, iomsg=msg) &
         '    Lemke failures solved by enumeration (nearest the previous state): ', cs%stats%fallbacks
      call note_io()
      do k = 1, min(cs%stats%n_events, max_listed_events)
         associate (e => cs%stats%events(k))
            write (u, '(a,f10.5,a,i0,a,a,a,i0,a,i0,a)', iostat=ios, iomsg=msg) &
               '      t = ', e%time, ' s, step ', e%step, ': Lemke ', &
               lemke_status_name(e%status), ', ', e%rows, ' rows, ', e%solutions, ' solutions; pairs '//e%pairs
            call note_io()
         end associate
      end do
      if (cs%stats%n_events > max_listed_events) write (u, '(a,i0,a)', iostat=ios, iomsg=msg) &
         '      ... ', cs%stats%n_events - max_listed_events, &
         ' more in the HDF5 file (/coupled/contact/events)'
      call note_io()
      write (u, '(a,es10.3)', iostat=ios, iomsg=msg) '    max natural residual ||min(z, w)|| / ||q||: ', cs%stats%residual_max
      call note_io()

   contains

      subroutine law_parameters(law)
         type(contact_law), intent(in) :: law
         type(law_text), allocatable :: lines(:)
         integer :: i

         call law%lines(lines)
         do i = 1, size(lines)
            write (u, '(4x,a)', iostat=ios, iomsg=msg) lines(i)%line
            call note_io()
         end do
      end subroutine law_parameters

   end subroutine write_contact_summary

   !> Per column segment of every frame (one line each, top storey first): storey, column
   !> line, bottom and top elevation, and the peaks of the member rows (shear |V|, bottom and
   !> top end moments |M1|, |M2|, axial force variation |N - N_gravity|), uncoupled and, with
   !> `cpl`, coupled with the influence coefficient lambda (%).
   subroutine write_column_tables(u, models, buildings, unc, cpl, infl)
      !> Open unit.
      integer, intent(in) :: u
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Their per-kind data (the frames' column segments).
      type(building_model), intent(in) :: buildings(:)
      !> Uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> Coupled result and the influence coefficients.
      type(analysis_result), intent(in), optional :: cpl
      type(building_influence), intent(in), optional :: infl(:)
      character(len=*), parameter :: heads(4) = ['|V| [kN]  ', '|M1| [kNm]', '|M2| [kNm]', '|dN| [kN] ']
      character(len=:), allocatable :: line
      character(len=256) :: head
      integer :: ib, s, q, e, nq
      logical :: both, first

      both = present(cpl) .and. present(infl)
      first = .true.
      do ib = 1, size(models)
         if (.not. allocated(buildings(ib)%frame) .or. .not. allocated(unc%building(ib)%member_peak)) cycle
         if (first) then
            line = 'Column segments: peak first-order end forces (V shear, M1 bottom and M2 top end moment, '// &
                   'dN = N - N_gravity axial)'
            if (both) line = line//', uncoupled (u), coupled (c), lambda [%]'
            call write_section(u, line)
         end if
         first = .false.
         nq = size(models(ib)%member_names)
         write (u, '(/,a)', iostat=ios, iomsg=msg) '  Building '//models(ib)%name
         call note_io()
         line = repeat(' ', 46)
         head = '     seg  storey  line      z1 [m]      z2 [m]'
         do q = 1, nq
            if (both) then
               line = line//'  '//heads(q)//repeat(' ', 19)
               head = trim(head)//'           u         c   lambda'
            else
               line = line//'  '//adjustr(heads(q))
            end if
         end do
         if (both) then
            write (u, '(a)', iostat=ios, iomsg=msg) trim(line)
            call note_io()
            line = trim(head)
         else
            line = head(1:46)//trim(line(47:))
         end if
         write (u, '(a)', iostat=ios, iomsg=msg) line
         call note_io()
         associate (f => buildings(ib)%frame%frame, ce => buildings(ib)%frame%column_element)
            do s = size(ce), 1, -1
               e = ce(s)
               write (head, '(2x,i6,i8,i6,2a12)') s, f%element_group(e), f%node_line(f%element_nodes(1, e)), &
                  fixed_cell(f%node_z(f%element_nodes(1, e)), 12, 3), fixed_cell(f%node_z(f%element_nodes(2, e)), 12, 3)
               line = head(1:46)
               do q = 1, nq
                  associate (k => (s - 1)*nq + q)
                     if (both) then
                        line = line//'  '//fixed_cell(unc%building(ib)%member_peak(k), 10, 3, .true.)// &
                               fixed_cell(cpl%building(ib)%member_peak(k), 10, 3, .true.)// &
                               lambda_cell(infl(ib)%member_lambda(k))
                     else
                        line = line//'  '//fixed_cell(unc%building(ib)%member_peak(k), 10, 3, .true.)
                     end if
                  end associate
               end do
               write (u, '(a)', iostat=ios, iomsg=msg) line
               call note_io()
            end do
         end associate
      end do

   contains

      !> lambda in 9 columns ('inf' for a response created by pounding).
      pure function lambda_cell(x) result(cell)
         real(dp), intent(in) :: x
         character(len=9) :: cell

         if (x >= huge(1.0_dp)) then
            cell = '      inf'
         else
            cell = fixed_cell(x, 9, 1)
         end if
      end function lambda_cell

   end subroutine write_column_tables

   !> Influence coefficients lambda = (Qc - Qu)/Qu * 100 (%), storey (floor) rows and one
   !> column per building, for storey shear, storey drift, floor displacement and
   !> floor absolute acceleration.
   subroutine write_influence_tables(u, models, infl)
      !> Open unit.
      integer, intent(in) :: u
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Influence coefficients of every building (`pound_influence`).
      type(building_influence), intent(in) :: infl(:)

      call write_section(u, 'Influence coefficients lambda = (Qc - Qu) / Qu * 100 [%]')
      call table('storey shear Q', 'storey', q_shear)
      call table('storey drift', 'storey', q_drift)
      call table('floor displacement u', 'floor', q_u)
      call table('floor absolute acceleration a_abs', 'floor', q_a_abs)

   contains

      !> One column per building, as wide as its whole name and two blanks (at least 14);
      !> a building without the storey (floor) shows '-'.
      subroutine table(title, row, q)
         character(len=*), intent(in) :: title, row
         integer, intent(in) :: q
         character(len=6) :: number
         character(len=:), allocatable :: line
         integer :: j, ib, w
         real(dp) :: lambda

         write (u, '(/,a)', iostat=ios, iomsg=msg) '  '//title
         call note_io()
         line = '  '//right_cell(row, 6)
         do ib = 1, size(models)
            line = line//right_cell(models(ib)%name, column_width(ib))
         end do
         write (u, '(a)', iostat=ios, iomsg=msg) line
         call note_io()
         do j = maxval([(size(models(ib)%floor_dof), ib=1, size(models))]), 1, -1
            write (number, '(i6)') j
            line = '  '//number
            do ib = 1, size(models)
               w = column_width(ib)
               if (j > size(models(ib)%floor_dof)) then
                  line = line//right_cell('-', w)
               else
                  lambda = infl(ib)%lambda(j, q)
                  if (lambda >= huge(1.0_dp)) then
                     line = line//right_cell('inf', w)
                  else
                     line = line//repeat(' ', w - 14)//fixed_cell(lambda, 14, 2)
                  end if
               end if
            end do
            write (u, '(a)', iostat=ios, iomsg=msg) line
            call note_io()
         end do
      end subroutine table

      !> Width of building ib's column.
      pure integer function column_width(ib)
         integer, intent(in) :: ib

         column_width = max(14, len(models(ib)%name) + 2)
      end function column_width

   end subroutine write_influence_tables

   !> Gap study: largest |lambda| per building and quantity against the gap, and the smallest
   !> gap meeting the target.
   subroutine write_sweep_table(u, models, cfg, res)
      !> Open unit.
      integer, intent(in) :: u
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> `&sweep`.
      type(sweep_config), intent(in) :: cfg
      !> The sweep result.
      type(sweep_result), intent(in) :: res
      integer, parameter :: shown(4) = [q_shear, q_drift, q_u, q_a_abs]
      character(len=*), parameter :: heads(4) = [character(len=9) :: 'Q', 'drift', 'u', 'a_abs']
      character(len=:), allocatable :: line
      character(len=11) :: cell
      integer :: i, ib, k

      call write_section(u, 'Gap study: largest |lambda| [%] over the storeys (floors) against the gap')
      write (u, '(a,i0,a,f10.4,a)', iostat=ios, iomsg=msg) &
         '  ', size(res%gap), ' gaps applied to every contact pair; ', &
         res%seconds, ' s for all coupled runs'
      call note_io()
      if (allocated(res%closing_max)) then
         write (u, '(a,f10.4,a,/,a,i0,a,i0,a)', iostat=ios, iomsg=msg) &
            '  largest closing displacement of any joint without contact: ', 1000.0_dp*maxval(res%closing_max), &
            ' mm;', '  the ', count(res%beyond), ' of ', size(res%gap), &
            ' gaps beyond it have no contact: one run without contact stands for them'
         call note_io()
      end if
      do ib = 1, size(models)
         write (u, '(/,a)', iostat=ios, iomsg=msg) '  Building '//models(ib)%name
         call note_io()
         line = '      gap [mm]    impacts'
         do k = 1, size(shown)
            line = line//right_cell(trim(heads(k)), 10)
         end do
         if (cfg%target > 0.0_dp) line = line//'  target'
         write (u, '(a)', iostat=ios, iomsg=msg) line
         call note_io()
         do i = 1, size(res%gap)
            line = '  '//fixed_cell(mm*res%gap(i), 12, 4)
            if (res%failed(i)) then
               write (u, '(a)', iostat=ios, iomsg=msg) line//'   FAILED (see the failed gaps below)'
               call note_io()
               cycle
            end if
            write (cell, '(i11)') res%impacts(i)
            line = line//cell
            do k = 1, size(shown)
               if (res%max_abs_lambda(shown(k), ib, i) >= huge(1.0_dp)) then
                  line = line//right_cell('inf', 10)
               else
                  line = line//fixed_cell(res%max_abs_lambda(shown(k), ib, i), 10, 2)
               end if
            end do
            if (cfg%target > 0.0_dp) line = line//merge('     met', '      no', res%meets(i))
            write (u, '(a)', iostat=ios, iomsg=msg) line
            call note_io()
         end do
      end do
      if (cfg%target > 0.0_dp) then
         if (res%found) then
            write (u, '(/,a,f7.2,a,f10.4,a)', iostat=ios, iomsg=msg) &
               '  Smallest gap with every targeted |lambda| <= ', cfg%target, &
               ' % at it and at every larger gap of the sweep: ', 1000.0_dp*res%safe_gap, ' mm'
            call note_io()
         else
            write (u, '(/,a,f7.2,a)', iostat=ios, iomsg=msg) &
               '  No gap of the sweep range keeps every targeted |lambda| <= ', &
               cfg%target, ' % from there to the end of the range.'
            call note_io()
         end if
      end if
      if (any(res%failed)) then
         write (u, '(/,a,i0,a,i0,a)', iostat=ios, iomsg=msg) '  Failed gaps (', count(res%failed), ' of ', &
            size(res%gap), '; left out, counted as not meeting the target):'
         call note_io()
         write (u, '(a)', iostat=ios, iomsg=msg) '    case      gap [mm]       t [s]      step  message'
         call note_io()
         do i = 1, size(res%gap)
            if (.not. res%failed(i)) cycle
            write (u, '(i8,a14,es12.4,i10,2x,a)', iostat=ios, iomsg=msg) i, fixed_cell(mm*res%gap(i), 14, 4), &
               res%time(i), res%step(i), &
               trim(res%messages(i))
            call note_io()
         end do
      end if
      call write_warning_lines(u, res%warnings)
   end subroutine write_sweep_table

   !> A gap in mm (3 decimals) in a field of width `w` (>= 10), or 'n/a' for a negative value
   !> (the -1 of a gap that was not computed or does not exist).
   pure function gap_cell(x, w) result(cell)
      !> The gap (m), negative when there is none.
      real(dp), intent(in) :: x
      !> Field width.
      integer, intent(in) :: w
      character(len=w) :: cell

      if (x < 0.0_dp) then
         cell = repeat(' ', w - 3)//'n/a'
      else
         cell = fixed_cell(mm*x, w, 3)
      end if
   end function gap_cell

   !> Gap study of the column segments (only where `&sweep target_quantities` names
   !> column_shear or column_moment and a building is a frame): per frame and targeted column
   !> quantity the largest |lambda| over its column segments against the gap, and whether the
   !> gap meets the target on every targeted quantity (`sweep_result%meets`).
   subroutine write_sweep_column_table(u, models, cfg, res)
      !> Open unit.
      integer, intent(in) :: u
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> `&sweep`.
      type(sweep_config), intent(in) :: cfg
      !> The sweep result.
      type(sweep_result), intent(in) :: res
      character(len=:), allocatable :: line, head
      character(len=12) :: cell
      integer :: i, ib, q, w

      if (.not. any(cfg%target_quantities(q_column_shear:q_column_moment))) return
      if (all(models%member%n == 0)) return
      call write_section(u, 'Gap study: largest |lambda| [%] over the column segments of the frames '// &
                         'against the gap')
      write (u, '(a)', iostat=ios, iomsg=msg) '  one column per frame and targeted column quantity: '// &
         '<building>:column_shear (segment shear V), <building>:column_moment (end moments M1, M2)'
      call note_io()
      line = '    gap [mm]  impacts'
      do ib = 1, size(models)
         if (models(ib)%member%n == 0) cycle
         do q = q_column_shear, q_column_moment
            if (.not. cfg%target_quantities(q)) cycle
            head = trim(models(ib)%name)//':'//trim(target_names(q))
            w = max(12, len(head) + 2)
            line = line//repeat(' ', w - len(head))//head
         end do
      end do
      if (cfg%target > 0.0_dp) line = line//'  target'
      write (u, '(a)', iostat=ios, iomsg=msg) line
      call note_io()
      do i = 1, size(res%gap)
         write (cell, '(f12.4)') 1000.0_dp*res%gap(i)
         line = cell
         if (res%failed(i)) then
            write (u, '(a)', iostat=ios, iomsg=msg) line//'   FAILED (see the failed gaps above)'
            call note_io()
            cycle
         end if
         write (cell, '(i9)') res%impacts(i)
         line = line//cell(1:9)
         do ib = 1, size(models)
            if (models(ib)%member%n == 0) cycle
            do q = q_column_shear, q_column_moment
               if (.not. cfg%target_quantities(q)) cycle
               w = max(12, len_trim(models(ib)%name) + len_trim(target_names(q)) + 3)
               if (res%max_abs_lambda(q, ib, i) >= huge(1.0_dp)) then
                  line = line//repeat(' ', w - 3)//'inf'
               else
                  line = line//fixed_cell(res%max_abs_lambda(q, ib, i), w, 2)
               end if
            end do
         end do
         if (cfg%target > 0.0_dp) line = line//merge('     met', '      no', res%meets(i))
         write (u, '(a)', iostat=ios, iomsg=msg) line
         call note_io()
      end do
   end subroutine write_sweep_column_table

end module pound_listing
