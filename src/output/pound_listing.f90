!> The listing (`.out`): a fixed-width report readable in a terminal and on paper.
!>
!> Every write is checked: the writers take a `text_writer` (pound_text_writer), which
!> keeps the first failure (no space left, file too large, ...); the caller asks it once.
module pound_listing
   use pound_kinds, only: dp
   use pound_strings, only: counted, fixed_cell, left_cell, right_cell, plain_real
   use pound_text_writer, only: text_writer
   use pound_analysis_plan, only: steps_of
   use pound_version, only: program_name, program_version
   use pound_config, only: deck_type
   use pound_building, only: building_model
   use pound_model_sink, only: text_lines
   use pound_structure, only: structure_model, modes_listed, structure_yields
   use pound_response, only: q_u, q_v, q_a_abs, q_drift, q_shear
   use pound_analysis, only: analysis_result
   use pound_contact, only: contact_system
   use pound_contact_law, only: contact_law, rate_name
   use pound_joint_law, only: law_text
   use pound_lemke, only: lemke_status_name
   use pound_influence, only: building_influence
   use pound_influence_output, only: lambda_cell
   use pound_config, only: sweep_config, target_names, q_column_shear, q_column_moment, q_ductility
   use pound_sweep, only: sweep_result
   implicit none
   private

   public :: write_listing_header, write_model_summary, write_peak_tables, write_section
   public :: write_contact_summary, write_influence_tables, write_sweep_table, write_column_tables
   public :: write_sweep_column_table
   public :: gap_cell, mm, write_warning_lines

   !> Millimetres per metre: gaps, displacements, drifts and penetrations are listed in mm.
   real(dp), parameter :: mm = 1000.0_dp

   !> Modes listed in the model summary (the HDF5 file has every mode the builder computed).
   integer, parameter :: max_listed_modes = modes_listed

contains

   !> Warnings of an analysis or a sweep, one line each after '  WARNING: '.
   subroutine write_warning_lines(lst, warnings)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The warnings (none when unallocated).
      character(len=:), allocatable, intent(in) :: warnings(:)
      integer :: i

      if (.not. allocated(warnings)) return
      do i = 1, size(warnings)
         call lst%put('  WARNING: '//trim(warnings(i)))
      end do
   end subroutine write_warning_lines

   !> Program, version, date, deck, title, units, the summary (when given) and the deck echo.
   subroutine write_listing_header(lst, deck, ground_text, summary)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
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
      call lst%put(repeat('=', 78))
      call lst%put(program_name//' '//program_version// &
         ' - seismic pounding of adjacent buildings (unilateral contact, LCP)')
      call lst%put( &
         'run on '//date(1:4)//'-'//date(5:6)//'-'//date(7:8)//' '// &
         time(1:2)//':'//time(3:4)//':'//time(5:6))
      call lst%put('deck:  '//deck%path)
      call lst%put('title: '//deck%analysis%title)
      call lst%put( &
         'units: kN, m, s, t (tonne); accelerations m/s^2; energies kJ; '// &
         'gaps, displacements, drifts and penetrations in mm')
      call lst%put(repeat('=', 78))
      if (present(summary)) then
         call write_section(lst, 'Summary')
         do i = 1, size(summary)
            call lst%put('  '//trim(summary(i)))
         end do
      end if
      call write_section(lst, 'Deck echo')
      start = 1
      do i = 1, len(deck%text)
         if (deck%text(i:i) == new_line('a')) then
            call lst%put('  | '//deck%text(start:i - 1))
            start = i + 1
         end if
      end do
      if (start <= len(deck%text)) write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) '  | '//deck%text(start:)
      call lst%note()
      call write_section(lst, 'Analysis and ground motion')
      write (lst%unit, '(a,es12.4,a,f10.4,a,i0,a,i0)', iostat=lst%ios, iomsg=lst%msg) &
         '  dt =', deck%analysis%dt, ' s   t_end =', &
         deck%analysis%t_end - deck%analysis%t_free, ' s   steps = ', steps_of(deck%analysis%t_end, deck%analysis%dt), &
         '   history every ', deck%analysis%output_every
      call lst%note()
      if (deck%analysis%t_free > 0.0_dp) then
         call lst%put('  t_free = '//plain_real(deck%analysis%t_free)// &
            ' s of free vibration after t_end, the ground at rest: the analysis ends at '// &
            plain_real(deck%analysis%t_end)//' s (the steps above include it; residual drift read there)')
      end if
      do i = 1, size(ground_text)
         call lst%put('  '//trim(ground_text(i)))
      end do
   end subroutine write_listing_header

   !> A section heading.
   subroutine write_section(lst, title)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> Heading text.
      character(len=*), intent(in) :: title

      write (lst%unit, '(/,a,/,a)', iostat=lst%ios, iomsg=lst%msg) title, repeat('-', len(title))
      call lst%note()
   end subroutine write_section

   !> Per building: storey data, periods and Rayleigh coefficients.
   subroutine write_model_summary(lst, models, buildings)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The buildings' structural models.
      type(structure_model), intent(in) :: models(:)
      !> Their per-kind data (storey table, frame).
      type(building_model), intent(in) :: buildings(:)
      type(text_lines) :: lines
      character(len=128) :: buf
      integer :: ib, j

      call write_section(lst, 'Models (shear buildings: rigid beams, one lateral DOF per floor; '// &
                         'frames: planar beam-column elements)')
      do ib = 1, size(models)
         associate (b => models(ib), s => buildings(ib)%kind)
            lines = text_lines()
            call s%describe(b, lines)
            do j = 1, lines%n
               call lst%put(lines%line(j)%text)
            end do
            ! The mode table, with the modal participation where the kind computes it.
            if (allocated(s%participation)) then
               call lst%put('    mode      T [s]      f [Hz]  omega [rad/s]'// &
                            '  Gamma [t^0.5]  eff. mass [%]  cumulative [%]')
            else
               call lst%put('    mode      T [s]      f [Hz]  omega [rad/s]')
            end if
            do j = 1, min(size(b%period), max_listed_modes)
               write (buf, '(2x,i6,a11,a12,a15)') j, fixed_cell(b%period(j), 11, 5, .true.), &
                  fixed_cell(1.0_dp/b%period(j), 12, 5, .true.), fixed_cell(b%omega(j), 15, 4, .true.)
               if (allocated(s%participation)) then
                  write (lst%unit, '(a,es15.5,2a15)', iostat=lst%ios, iomsg=lst%msg) trim(buf), &
                     s%participation(j), fixed_cell(100.0_dp*s%effective_mass(j), 15, 3), &
                     fixed_cell(100.0_dp*sum(s%effective_mass(1:j)), 15, 3)
                  call lst%note()
               else
                  call lst%put(trim(buf))
               end if
            end do
            if (size(b%period) > max_listed_modes) write (lst%unit, '(a,i0,a)', iostat=lst%ios, iomsg=lst%msg) &
               '    (', &
               size(b%period) - max_listed_modes, &
               ' more modes in the HDF5 file)'
            call lst%note()
            write (lst%unit, '(a,f6.2,a,i0,a,i0,a,es12.5,a,es12.5,a)', iostat=lst%ios, iomsg=lst%msg) &
               '  Rayleigh damping ', &
               100.0_dp*b%damping_ratio, ' % at modes ', b%damping_modes(1), ' and ', &
               b%damping_modes(2), ': a0 = ', b%a0, ' 1/s, a1 = ', b%a1, ' s'
            call lst%note()
         end associate
      end do
   end subroutine write_model_summary

   !> Peak tables of an analysis: floors (u, v, a_abs) and storeys (drift, shear).
   subroutine write_peak_tables(lst, label, models, res)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> Analysis label, e.g. 'Uncoupled'.
      character(len=*), intent(in) :: label
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The analysis result.
      type(analysis_result), intent(in) :: res
      integer :: ib, j

      call write_section(lst, label//' response: absolute maxima and the time they occur')
      do ib = 1, size(models)
         associate (b => models(ib), p => res%building(ib)%peak, t => res%building(ib)%peak_time)
            write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Building '//b%name
            call lst%note()
            call lst%put('   floor    |u| [mm]    t [s]   |v| [m/s]    t [s]  |a_abs| [m/s2]    t [s]')
            do j = size(b%floor_dof), 1, -1
               write (lst%unit, '(2x,i6,es12.4,a9,es12.4,a9,es16.4,a9)', iostat=lst%ios, iomsg=lst%msg) &
                  j, mm*p(j, q_u), fixed_cell(t(j, q_u), 9, 3), &
                  p(j, q_v), fixed_cell(t(j, q_v), 9, 3), p(j, q_a_abs), fixed_cell(t(j, q_a_abs), 9, 3)
               call lst%note()
            end do
            call lst%put('  storey  |drift| [mm]    t [s]    |Q| [kN]    t [s]')
            do j = size(b%floor_dof), 1, -1
               write (lst%unit, '(2x,i6,es14.4,a9,es12.4,a9)', iostat=lst%ios, iomsg=lst%msg) j, mm*p(j, q_drift), &
                  fixed_cell(t(j, q_drift), 9, 3), p(j, q_shear), fixed_cell(t(j, q_shear), 9, 3)
               call lst%note()
            end do
         end associate
      end do
      if (allocated(res%numerical)) then
         write (lst%unit, '(/,a,es10.3)', iostat=lst%ios, iomsg=lst%msg) &
            '  Energy audit (input = kinetic + strain + damping + contact + plastic + numerical), '// &
            'max relative error over time: ', res%energy_error
      else
         write (lst%unit, '(/,a,es10.3)', iostat=lst%ios, iomsg=lst%msg) &
            '  Energy audit (input = kinetic + strain + damping + contact + plastic), '// &
            'max relative error over time: ', res%energy_error
      end if
      call lst%note()
      call write_warning_lines(lst, res%warnings)
      j = res%n_out
      call lst%put('  energies at the end [kJ]:')
      call lst%put('         input     kinetic      strain     damping     contact     plastic')
      write (lst%unit, '(a,6es12.4)', iostat=lst%ios, iomsg=lst%msg) '  ', res%energy(:, j)
      call lst%note()
      if (allocated(res%numerical)) then
         write (lst%unit, '(a,es12.4)', iostat=lst%ios, iomsg=lst%msg) &
            '  numerical dissipation of the integrator ('//res%integrator//') [kJ], in the audit beside the above:', &
            res%numerical(j)
         call lst%note()
      end if
   end subroutine write_peak_tables

   !> Contact pairs and laws, impacts, time in contact, peak forces, plastic penetration
   !> left, fracture, and the LCP statistics with every fallback event.
   subroutine write_contact_summary(lst, cs)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> Contact system at the end of the coupled run.
      type(contact_system), intent(in) :: cs
      integer, parameter :: max_listed_events = 20
      integer :: k, w
      real(dp) :: mean_pivots
      character(len=12) :: fractured
      type(law_text), allocatable :: lines(:)

      call write_section(lst, 'Contact (unilateral constraints between facing floors)')
      w = 4
      do k = 1, cs%m
         w = max(w, len(cs%pair(k)%label))
      end do
      call lst%put( &
         '  '//left_cell('pair', w)//'    gap [mm]  '//left_cell('law', 16)// &
         right_cell('k0 [kN/m]', 12)//right_cell('c [kNs/m]', 12)//'  dashpot_rate')
      do k = 1, cs%m
         associate (p => cs%pair(k))
            write (lst%unit, '(2x,a,a12,2x,a16,es12.3,es12.3,2x,a)', iostat=lst%ios, iomsg=lst%msg) &
               left_cell(p%label, w), fixed_cell(mm*p%gap, 12, 3), left_cell(p%law%title(), 16), &
               p%law%stiffness, p%law%dashpot, rate_name(p%law%dashpot_rate)
            call lst%note()
         end associate
      end do
      ! The parameters of the laws beyond k0 and c, after the table (not between its rows).
      do k = 1, cs%m
         associate (p => cs%pair(k))
            call p%law%lines(lines)
            if (p%law%restitution <= 0.0_dp .and. size(lines) == 0) cycle
            call lst%put('  '//p%label//':')
            if (p%law%restitution > 0.0_dp) then
               write (lst%unit, '(4x,a,f6.3,a)', iostat=lst%ios, iomsg=lst%msg) 'c calibrated to the restitution e =', &
                  p%law%restitution, ' (exact relation of the joint: docs/verification.md)'
               call lst%note()
            end if
            call law_parameters(p%law)
         end associate
      end do
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  '//left_cell('pair', w)// &
         '   impacts  in_contact [s]  peak r [kN]     t [s]  max_pen. [mm]'// &
         '  plastic_left [mm]  fractured_at [s]'
      call lst%note()
      do k = 1, cs%m
         associate (p => cs%joint(k))
            fractured = '          no'
            if (p%fractured) fractured = fixed_cell(p%fracture_time, 12, 4)
            write (lst%unit, '(2x,a,i10,a16,es13.4,a10,es15.4,es19.4,6x,a12)', iostat=lst%ios, iomsg=lst%msg) &
               left_cell(cs%pair(k)%label, w), p%impacts, fixed_cell(p%contact_time, 16, 4), &
               p%peak_force, fixed_cell(p%peak_time, 10, 4), mm*p%peak_penetration, mm*p%plastic, fractured
            call lst%note()
         end associate
      end do
      do k = 1, cs%m
         if (cs%joint(k)%fractured) write (lst%unit, '(a,f10.4,a)', iostat=lst%ios, iomsg=lst%msg) &
            '  joint '//cs%pair(k)%label// &
            ' FRACTURED at t = ', cs%joint(k)%fracture_time, ' s: it carries nothing for the rest of the analysis'
         call lst%note()
      end do
      if (cs%fr%n > 0) then
         ! Coulomb friction at the contact points (pound_contact_friction).
         write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  '//left_cell('contact point', w)// &
            '        mu   kt [kN/m]  peak |T| [kN]     t [s]  slip_final [mm]'
         call lst%note()
         do k = 1, cs%fr%n
            associate (p => cs%fr%p(k))
               write (lst%unit, '(2x,a,f10.3,es12.4,es15.4,a10,es17.4)', iostat=lst%ios, iomsg=lst%msg) &
                  left_cell(cs%pair(cs%fr%joint(k))%label, w), cs%fr%mu(k), cs%fr%kt(k), p%peak, &
                  fixed_cell(p%peak_time, 10, 4), mm*p%slip
               call lst%note()
            end associate
         end do
         write (lst%unit, '(a,es12.4,a)', iostat=lst%ios, iomsg=lst%msg) '  friction work (dissipated): ', &
            cs%fr%work, ' kJ'
         call lst%note()
      end if
      mean_pivots = 0.0_dp
      if (cs%stats%solves > 0) mean_pivots = real(cs%stats%pivots_total, dp)/real(cs%stats%solves, dp)
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  LCP (Lemke, lexicographic) statistics:'
      call lst%note()
      write (lst%unit, '(a,i0,a,i0,a,i0,a)', iostat=lst%ios, iomsg=lst%msg) &
         '    solves ', cs%stats%solves, ' (q >= 0 without pivoting: ', cs%stats%trivial, &
         '; warm start accepted: ', cs%stats%warm, ')'
      call lst%note()
      write (lst%unit, '(a,i0,a,i0,a,f8.3)', iostat=lst%ios, iomsg=lst%msg) &
         '    pivots total ', cs%stats%pivots_total, ', max per solve ', &
         cs%stats%pivots_max, ', mean per solve ', mean_pivots
      call lst%note()
      write (lst%unit, '(a,i0)', iostat=lst%ios, iomsg=lst%msg) &
         '    re-solves (a left-out constraint would close, a segment end was passed): ', &
         cs%stats%resolves
      call lst%note()
      if (cs%stats%active_solves > 0) then
         write (lst%unit, '(a,i0,a,i0,a,f8.3,a,i0,a,i0,a)', iostat=lst%ios, iomsg=lst%msg) &
            '    active-set method (elastic steps, from the previous step''s set): solves ', &
            cs%stats%active_solves, ', iterations ', cs%stats%active_iterations, ' (mean ', &
            real(cs%stats%active_iterations, dp)/real(cs%stats%active_solves, dp), ', max ', &
            cs%stats%active_iterations_max, '), factor updates ', cs%stats%active_updates, ','
         call lst%note()
         write (lst%unit, '(a,i0,a)', iostat=lst%ios, iomsg=lst%msg) '      ', cs%stats%active_fallbacks, &
            ' failed and were solved by Lemke (counted above)'
         call lst%note()
      end if
      write (lst%unit, '(a,i0)', iostat=lst%ios, iomsg=lst%msg) &
         '    largest LCP (contact + yield + segment-end rows): ', cs%stats%largest_lcp
      call lst%note()
      write (lst%unit, '(a,i0)', iostat=lst%ios, iomsg=lst%msg) &
         '    non-convex steps (softening rows in the LCP): ', cs%stats%nonconvex
      call lst%note()
      write (lst%unit, '(a,i0)', iostat=lst%ios, iomsg=lst%msg) &
         '    Lemke failures solved by enumeration (nearest the previous state): ', cs%stats%fallbacks
      call lst%note()
      do k = 1, min(cs%stats%n_events, max_listed_events)
         associate (e => cs%stats%events(k))
            write (lst%unit, '(a,f10.5,a,i0,a,a,a,i0,a,i0,a)', iostat=lst%ios, iomsg=lst%msg) &
               '      t = ', e%time, ' s, step ', e%step, ': Lemke ', &
               lemke_status_name(e%status), ', ', e%rows, ' rows, ', e%solutions, ' solutions; pairs '//e%pairs
            call lst%note()
         end associate
      end do
      if (cs%stats%n_events > max_listed_events) write (lst%unit, '(a,i0,a)', iostat=lst%ios, iomsg=lst%msg) &
         '      ... ', cs%stats%n_events - max_listed_events, &
         ' more in the HDF5 file (/coupled/contact/events)'
      call lst%note()
      write (lst%unit, '(a,es10.3)', iostat=lst%ios, iomsg=lst%msg) &
         '    max natural residual ||min(z, w)|| / ||q||: ', cs%stats%residual_max
      call lst%note()

   contains

      subroutine law_parameters(law)
         type(contact_law), intent(in) :: law
         type(law_text), allocatable :: lines(:)
         integer :: i

         call law%lines(lines)
         do i = 1, size(lines)
            write (lst%unit, '(4x,a)', iostat=lst%ios, iomsg=lst%msg) lines(i)%line
            call lst%note()
         end do
      end subroutine law_parameters

   end subroutine write_contact_summary

   !> Per column segment of every frame (one line each, top storey first): storey, column
   !> line, bottom and top elevation, and the peaks of the member rows (shear |V|, bottom and
   !> top end moments |M1|, |M2|, axial force variation |N - N_gravity|), uncoupled and, with
   !> `cpl`, coupled with the influence coefficient lambda (%).
   subroutine write_column_tables(lst, models, buildings, unc, cpl, infl)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
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
      integer :: ib, s, q, nq
      logical :: both, first

      both = present(cpl) .and. present(infl)
      first = .true.
      do ib = 1, size(models)
         if (buildings(ib)%kind%n_segments() == 0 .or. .not. allocated(unc%building(ib)%member_peak)) cycle
         if (first) then
            line = 'Column segments: peak first-order end forces (V shear, M1 bottom and M2 top end moment, '// &
                   'dN = N - N_gravity axial)'
            if (both) line = line//', uncoupled (u), coupled (c), lambda [%]'
            call write_section(lst, line)
         end if
         first = .false.
         nq = size(models(ib)%member_names)
         write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Building '//models(ib)%name
         call lst%note()
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
            call lst%put(trim(line))
            line = trim(head)
         else
            line = head(1:46)//trim(line(47:))
         end if
         call lst%put(line)
         associate (kind => buildings(ib)%kind)
            do s = kind%n_segments(), 1, -1
               write (head, '(2x,i6,i8,i6,2a12)') s, kind%segment_storey(s), kind%segment_line(s), &
                  fixed_cell(kind%segment_z(1, s), 12, 3), fixed_cell(kind%segment_z(2, s), 12, 3)
               line = head(1:46)
               do q = 1, nq
                  associate (k => (s - 1)*nq + q)
                     if (both) then
                        line = line//'  '//fixed_cell(unc%building(ib)%member_peak(k), 10, 3, .true.)// &
                               fixed_cell(cpl%building(ib)%member_peak(k), 10, 3, .true.)// &
                               lambda_cell(infl(ib)%member_lambda(k), 9, 1)
                     else
                        line = line//'  '//fixed_cell(unc%building(ib)%member_peak(k), 10, 3, .true.)
                     end if
                  end associate
               end do
               call lst%put(line)
            end do
         end associate
      end do
   end subroutine write_column_tables

   !> Influence coefficients lambda = (Qc - Qu)/Qu * 100 (%), storey (floor) rows and one
   !> column per building, for storey shear, storey drift, floor displacement and
   !> floor absolute acceleration.
   subroutine write_influence_tables(lst, models, infl)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Influence coefficients of every building (`pound_influence`).
      type(building_influence), intent(in) :: infl(:)

      call write_section(lst, 'Influence coefficients lambda = (Qc - Qu) / Qu * 100 [%]')
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

         write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  '//title
         call lst%note()
         line = '  '//right_cell(row, 6)
         do ib = 1, size(models)
            line = line//right_cell(models(ib)%name, column_width(ib))
         end do
         call lst%put(line)
         do j = maxval([(size(models(ib)%floor_dof), ib=1, size(models))]), 1, -1
            write (number, '(i6)') j
            line = '  '//number
            do ib = 1, size(models)
               w = column_width(ib)
               if (j > size(models(ib)%floor_dof)) then
                  line = line//right_cell('-', w)
               else
                  line = line//repeat(' ', w - 14)//lambda_cell(infl(ib)%lambda(j, q), 14, 2)
               end if
            end do
            call lst%put(line)
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
   subroutine write_sweep_table(lst, models, cfg, res)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
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
      logical :: mu

      call write_section(lst, 'Gap study: largest |lambda| [%] over the storeys (floors) against the gap')
      write (lst%unit, '(a,i0,a,f10.4,a)', iostat=lst%ios, iomsg=lst%msg) &
         '  ', size(res%gap), ' gaps applied to every contact pair; ', &
         res%seconds, ' s for all coupled runs'
      call lst%note()
      if (allocated(res%closing_max)) then
         write (lst%unit, '(a,f10.4,a,/,a,i0,a,i0,a)', iostat=lst%ios, iomsg=lst%msg) &
            '  largest closing displacement of any joint without contact: ', 1000.0_dp*maxval(res%closing_max), &
            ' mm;', '  the ', count(res%beyond), ' of ', size(res%gap), &
            ' gaps beyond it have no contact: one run without contact stands for them'
         call lst%note()
      end if
      do ib = 1, size(models)
         write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Building '//models(ib)%name
         call lst%note()
         line = '      gap [mm]    impacts'
         do k = 1, size(shown)
            line = line//right_cell(trim(heads(k)), 10)
         end do
         ! The peak ductility of bilinear storeys (plastic rotation of hinges), where targeted.
         mu = cfg%target_quantities(q_ductility) .and. structure_yields(models(ib))
         if (mu) line = line//right_cell('ductility', 11)
         if (cfg%target > 0.0_dp) line = line//'  target'
         call lst%put(line)
         do i = 1, size(res%gap)
            line = '  '//fixed_cell(mm*res%gap(i), 12, 4)
            if (res%failed(i)) then
               call lst%put(line//'   FAILED (see the failed gaps below)')
               cycle
            end if
            write (cell, '(i11)') res%impacts(i)
            line = line//cell
            do k = 1, size(shown)
               line = line//lambda_cell(res%max_abs_lambda(shown(k), ib, i), 10, 2)
            end do
            if (mu) line = line//lambda_cell(res%max_abs_lambda(q_ductility, ib, i), 11, 2)
            if (cfg%target > 0.0_dp) line = line//merge('     met', '      no', res%meets(i))
            call lst%put(line)
         end do
      end do
      if (cfg%target > 0.0_dp) then
         if (res%found) then
            write (lst%unit, '(/,a,f7.2,a,f10.4,a)', iostat=lst%ios, iomsg=lst%msg) &
               '  Smallest gap with every targeted |lambda| <= ', cfg%target, &
               ' % at it and at every larger gap of the sweep: ', 1000.0_dp*res%safe_gap, ' mm'
            call lst%note()
         else
            write (lst%unit, '(/,a,f7.2,a)', iostat=lst%ios, iomsg=lst%msg) &
               '  No gap of the sweep range keeps every targeted |lambda| <= ', &
               cfg%target, ' % from there to the end of the range.'
            call lst%note()
         end if
      end if
      if (any(res%failed)) then
         write (lst%unit, '(/,a,i0,a,i0,a)', iostat=lst%ios, iomsg=lst%msg) &
            '  Failed gaps (', count(res%failed), ' of ', &
            size(res%gap), '; left out, counted as not meeting the target):'
         call lst%note()
         call lst%put('    case      gap [mm]       t [s]      step  message')
         do i = 1, size(res%gap)
            if (.not. res%failed(i)) cycle
            write (lst%unit, '(i8,a14,es12.4,i10,2x,a)', iostat=lst%ios, iomsg=lst%msg) i, fixed_cell(mm*res%gap(i), 14, 4), &
               res%time(i), res%step(i), &
               trim(res%messages(i))
            call lst%note()
         end do
      end if
      call write_warning_lines(lst, res%warnings)
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
   subroutine write_sweep_column_table(lst, models, cfg, res)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
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
      call write_section(lst, 'Gap study: largest |lambda| [%] over the column segments of the frames '// &
                         'against the gap')
      call lst%put('  one column per frame and targeted column quantity: '// &
         '<building>:column_shear (segment shear V), <building>:column_moment (end moments M1, M2)')
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
      call lst%put(line)
      do i = 1, size(res%gap)
         write (cell, '(f12.4)') 1000.0_dp*res%gap(i)
         line = cell
         if (res%failed(i)) then
            call lst%put(line//'   FAILED (see the failed gaps above)')
            cycle
         end if
         write (cell, '(i9)') res%impacts(i)
         line = line//cell(1:9)
         do ib = 1, size(models)
            if (models(ib)%member%n == 0) cycle
            do q = q_column_shear, q_column_moment
               if (.not. cfg%target_quantities(q)) cycle
               w = max(12, len_trim(models(ib)%name) + len_trim(target_names(q)) + 3)
               line = line//lambda_cell(res%max_abs_lambda(q, ib, i), w, 2)
            end do
         end do
         if (cfg%target > 0.0_dp) line = line//merge('     met', '      no', res%meets(i))
         call lst%put(line)
      end do
   end subroutine write_sweep_column_table

end module pound_listing
