!> Outputs of the separation rules (`pound_separation`): the listing table of one pair (rows:
!> the run, or a suite's motions and the suite) and the HDF5 datasets of the rules.
!>
!> HDF5, under a group `g` ('/separation' for a run, '/suite/separation' for a suite), one
!> dataset per rule, (n_pairs) for a run or (n_motions + 1, n_pairs) for a suite:
!>
!>     g/abs, g/srss, g/ddc              m, combinations of the uncoupled peaks
!>     g/ec8                             m, SRSS x 0.7 (coinciding floors) of the peaks,
!>                                       without q_d (legacy; the EN 1998 rule is g/en1998)
!>     g/peak_left, g/peak_right         m, the uncoupled peaks u1, u2 the rules used
!>     g/setback_left, g/setback_right   m, each building's property-line setback at its
!>                                       facing point: Cd u / Ie with cd, else u
!>     g/setback_amplified_left, _right  1 where Cd/Ie was applied to that building's setback
!>     g/building_setback                m, (n_buildings) a run only: each building's largest
!>                                       setback over its facing points, NaN without any; with
!>                                       g/building_name
!>     g/rho                             1, CQC correlation of the DDC
!>     g/asce7, g/en1998, g/is1893       m, design-code rules, NaN where n/a (factor not given)
!>     g/no_contact                      m; a run: NaN without &sweep (its probe gives it)
!>     g/time_history                    m; a run: NaN where n/a; a suite: -1 where n/a (the
!>                                       layout of earlier files), with g/time_history_valid (0/1)
!>     g/pair                            (n_pairs) labels 'A:3-B:3', 'A:z4.5m-B:2'
!>
!> every dataset with the attribute `units` and, where a value can be n/a, `na` saying how it
!> is marked; the group has the attribute `peaks`: which peaks the rules used
!> (`peaks_label`: 'uncoupled elastic peaks' or 'uncoupled peaks of the yielding buildings
!> (inelastic)', ...).
module pound_separation_output
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: fixed_cell, left_cell, right_cell
   use pound_contact, only: contact_system
   use pound_h5, only: h5_file, h5_write, h5_write_attr
   use pound_separation, only: separation_t, not_computed, peaks_label, building_setbacks
   use pound_listing, only: write_section
   use pound_text_writer, only: text_writer
   implicit none
   private

   public :: write_separation_h5, write_separation_rows, write_separation_head, pair_labels, &
             write_separation_legend, write_run_separation, write_setbacks

   !> Width of a value column of the listing table.
   integer, parameter :: cw = 14
   !> NaN marks of the new datasets.
   character(len=*), parameter :: na_nan = 'NaN where not computed (n/a: a factor of either '// &
                                           'building not given, or a facing point whose peak is not known)'

contains

   !> The labels of the contact pairs (`pair_label` of `pound_contact_pair`, e.g.
   !> 'A:3-B:z=7.50m'), in the order of the contact system's pairs.
   pure function pair_labels(cs) result(labels)
      !> The contact system.
      type(contact_system), intent(in) :: cs
      character(len=:), allocatable :: labels(:)
      integer :: k, length

      length = 1
      do k = 1, cs%m
         length = max(length, len(cs%pair(k)%label))
      end do
      allocate (character(len=length) :: labels(cs%m))
      do k = 1, cs%m
         labels(k) = cs%pair(k)%label
      end do
   end function pair_labels

   !> The legend of the separation tables (`suite`: the time-history gap of a suite's sweep;
   !> `sep`: the rules, for which peaks they used, `peaks_label`).
   subroutine write_separation_legend(lst, suite, sep)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The suite's table (else a run's).
      logical, intent(in) :: suite
      !> The rules (any rows, every pair).
      type(separation_t), intent(in) :: sep(:)

      write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
         '  From the '//peaks_label(sep)//' u1, u2 at the facing points (floors, or points between '// &
         'floors: a column''s node); n/a: not computed.', &
         '  ABS = u1 + u2; SRSS = sqrt(u1^2 + u2^2); DDC = sqrt(u1^2 + u2^2 - 2 rho u1 u2), rho: CQC '// &
         'correlation of the two buildings'' first modes;', &
         '  ASCE7 = ASCE 7-16 12.12.3: sqrt(dM1^2 + dM2^2), dM = Cd u / Ie (n/a without &building cd);', &
         '  EN1998 = EN 1998-1 4.4.2.7: SRSS of q u, x 0.7 only where both points are floors at the same '// &
         'level, within 0.01 m (n/a without behaviour_factor);', &
         '  IS1893 = IS 1893-1:2016 7.11.3: R1 u1 + R2 u2, x 0.5 only where both points are floors at the '// &
         'same level (n/a without response_reduction);', &
         '  the factors take u as the codes'' elastic displacement under the design action reduced by q, '// &
         'R or R/Ie: with unreduced records the peak itself is the codes'' estimate (equal displacements): '// &
         'then enter factors 1 (docs/manual.md, Design-code separation rules).'
      call lst%note()
      if (suite) then
         write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
            '  no-contact = max_t (u1(t) - u2(t)) of the uncoupled histories;', &
            '  time-hist. = the threshold gap of the gap sweep (the same gap at every pair): per motion', &
            '  its own largest |lambda|, for the suite the mean, against the target, refined by bisection', &
            '  (n/a: no &sweep, no target_lambda, or no gap of the range meets it).'
         call lst%note()
      else
         write (lst%unit, '(a)', iostat=lst%ios, iomsg=lst%msg) &
            '  no-contact = the largest closing displacement u1 - u2 of the '// &
            'uncoupled motion, from the sweep''s probe (n/a without &sweep);', &
            '  time-hist. = the smallest gap of the sweep meeting target_lambda (n/a: no &sweep, no '// &
            'target_lambda, or no gap of the range meets it).'
         call lst%note()
      end if
   end subroutine write_separation_legend

   !> The listing section of a run's separation rules: one table row per pair.
   subroutine write_run_separation(lst, labels, sep, per_joint, names)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> Pair labels (`pair_labels`).
      character(len=*), intent(in) :: labels(:)
      !> The rules per pair.
      type(separation_t), intent(in) :: sep(:)
      !> Whether the time-history gaps are the joints' own thresholds (several independent
      !> joints, `pound_sweep_joints`; default: the common sweep's, one gap for every pair).
      logical, intent(in), optional :: per_joint
      !> Building names (deck order): the property-line setbacks follow the table.
      character(len=*), intent(in), optional :: names(:)
      integer :: ip

      if (size(sep) == 0) return
      call write_section(lst, 'Separation rules per contact pair [mm]')
      call write_separation_legend(lst, .false., sep)
      if (present(per_joint)) then
         if (per_joint) then
            call lst%put('  time-hist. per joint: the threshold of '// &
               'the pair''s joint''s own sweep (its pairs at the gaps, the other pairs at their deck gaps; Gap '// &
               'study per joint).')
         end if
      end if
      do ip = 1, size(sep)
         call write_separation_head(lst, trim(labels(ip)), 'run', 3, sep(ip))
         call write_separation_rows(lst, 'run', sep(ip), 3)
      end do
      if (present(names)) call write_setbacks(lst, names, labels, sep)
   end subroutine write_run_separation

   !> The property-line setbacks of a run's buildings (ASCE 7-16 12.12.2 style): per building
   !> its largest own delta_M over its facing points, with each point's peak (`building_setbacks`).
   subroutine write_setbacks(lst, names, labels, sep, which)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> Building names (deck order).
      character(len=*), intent(in) :: names(:)
      !> Pair labels (`pair_labels`).
      character(len=*), intent(in) :: labels(:)
      !> The rules per pair (their buildings `left`, `right` by index in `names`).
      type(separation_t), intent(in) :: sep(:)
      !> Put before the peaks' label (e.g. 'the suite''s mean '); default none.
      character(len=*), intent(in), optional :: which
      character(len=:), allocatable :: what
      real(dp) :: setback
      integer :: ib, ip, e

      if (size(sep) == 0) return
      what = ''
      if (present(which)) what = which
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Property-line setback per building (ASCE 7-16 '// &
         '12.12.2 style: the building''s own delta_M at its facade = Cd u / Ie of '//what//peaks_label(sep)// &
         ' u at its facing points, the largest; without cd, u itself: the peak of an unreduced motion is the '// &
         'displacement):'
      call lst%note()
      do ib = 1, size(names)
         setback = building_setbacks(sep, ib, size(names))
         if (.not. (setback >= 0.0_dp)) cycle
         call lst%put('  '//left_cell(trim(names(ib)), 12)// &
            fixed_cell(1000.0_dp*setback, cw, 3)//' mm  '//trim(where(ib, setback)))
      end do

   contains

      !> Where building ib's setback is found: the pair, the peak there and the rule.
      function where(ib, setback) result(text)
         integer, intent(in) :: ib
         real(dp), intent(in) :: setback
         character(len=:), allocatable :: text

         text = ''
         do ip = 1, size(sep)
            if (.not. sep(ip)%computed) cycle
            do e = 1, 2
               if (sep(ip)%building(e) /= ib .or. sep(ip)%setback(e) /= setback .or. len(text) > 0) cycle
               text = 'at '//trim(labels(ip))//' (u = '//trim(adjustl(fixed_cell(1000.0_dp*sep(ip)%u(e), cw, 3)))// &
                      ' mm, '//trim(merge('Cd u / Ie', 'u (no cd)', sep(ip)%setback_amplified(e)))//')'
            end do
         end do
      end function where

   end subroutine write_setbacks

   !> The head of the listing table of one pair: its label, which peaks and whether its floor
   !> levels coincide (from `sep`), and the column names (the row column `w` characters wide:
   !> the longest row name; every other column `cw`).
   subroutine write_separation_head(lst, label, row_title, w, sep)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The pair's label.
      character(len=*), intent(in) :: label
      !> Title of the row column ('motion' or 'run').
      character(len=*), intent(in) :: row_title
      !> Width of the row column.
      integer, intent(in) :: w
      !> The pair's rules (a run's, or a suite's mean row).
      type(separation_t), intent(in) :: sep
      character(len=10), parameter :: heads(9) = [character(len=10) :: 'ABS', 'SRSS', 'DDC', 'rho', 'ASCE7', &
                                                  'EN1998', 'IS1893', 'no-contact', 'time-hist.']
      character(len=:), allocatable :: line
      integer :: q

      line = 'floor levels do not coincide: no reduction'
      if (sep%coincide) line = 'floor levels coincide: EN 1998 x 0.7, IS 1893 x 0.5'
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  pair '//label//'  (u1 '// &
         trim(merge('inelastic', 'elastic  ', sep%inelastic(1)))//', u2 '// &
         trim(merge('inelastic', 'elastic  ', sep%inelastic(2)))//'; '//line//')'
      call lst%note()
      line = '  '//left_cell(row_title, w)
      do q = 1, size(heads)
         line = line//right_cell(trim(heads(q)), cw)
      end do
      call lst%put(line)
   end subroutine write_separation_head

   !> One row of a pair's table: the rules in mm (n/a where not computed) and rho.
   subroutine write_separation_rows(lst, name, sep, w)
      !> The listing writer (unit, first write failure).
      type(text_writer), intent(inout) :: lst
      !> The row's name (a motion, 'mean' or 'run').
      character(len=*), intent(in) :: name
      !> The rules of the pair.
      type(separation_t), intent(in) :: sep
      !> Width of the row column.
      integer, intent(in) :: w

      call lst%put( &
         '  '//left_cell(name, w)//mm(sep%abs, sep%computed)//mm(sep%srss, sep%computed)// &
         mm(sep%ddc, sep%computed)//ratio(sep%rho, sep%computed)//mm(sep%asce7, sep%asce7_valid)// &
         mm(sep%en1998, sep%en1998_valid)//mm(sep%is1893, sep%is1893_valid)// &
         mm(sep%no_contact, sep%no_contact_valid)//mm(sep%time_history, sep%time_history_valid))

   contains

      !> A gap (m) in mm, 3 decimals, or 'n/a'.
      pure function mm(x, valid) result(cell)
         !> The gap (m).
         real(dp), intent(in) :: x
         !> Whether it was computed.
         logical, intent(in) :: valid
         character(len=cw) :: cell

         if (valid) then
            cell = fixed_cell(1000.0_dp*x, cw, 3)
         else
            cell = repeat(' ', cw - 3)//'n/a'
         end if
      end function mm

      !> A ratio, 4 decimals, or 'n/a'.
      pure function ratio(x, valid) result(cell)
         !> The value.
         real(dp), intent(in) :: x
         !> Whether it was computed.
         logical, intent(in) :: valid
         character(len=cw) :: cell

         if (valid) then
            cell = fixed_cell(x, cw, 4)
         else
            cell = repeat(' ', cw - 3)//'n/a'
         end if
      end function ratio

   end subroutine write_separation_rows

   !> The new datasets of the rules under `g` (rho, asce7, en1998, is1893, pair; for a run
   !> also abs, srss, ec8, ddc and time_history), with their attributes. `sep` is
   !> (n_rows, n_pairs): one row for a run, n_motions + 1 for a suite (`suite` true: the suite
   !> writes abs, srss, ec8, ddc, no_contact and time_history itself, in their earlier layout;
   !> here their attributes and time_history_valid).
   subroutine write_separation_h5(h5, g, sep, labels, suite, error, names)
      !> Open file.
      type(h5_file), intent(inout) :: h5
      !> Group path ('/separation' or '/suite/separation').
      character(len=*), intent(in) :: g
      !> The rules (n_rows, n_pairs).
      type(separation_t), intent(in) :: sep(:, :)
      !> Pair labels (n_pairs).
      character(len=*), intent(in) :: labels(:)
      !> The suite's group (see above).
      logical, intent(in) :: suite
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Building names (deck order): g/building_setback (n_rows, n_buildings) and
      !> g/building_name are written with them.
      character(len=*), intent(in), optional :: names(:)
      real(dp), allocatable :: per_building(:, :)
      integer :: ib, k

      if (.not. suite) then
         call put('abs', nan_where(sep%abs, sep%computed), 'm', 'ABS = u1 + u2 of the uncoupled peaks')
         call put('srss', nan_where(sep%srss, sep%computed), 'm', 'SRSS = sqrt(u1^2 + u2^2) of the uncoupled peaks')
         call put('ec8', nan_where(sep%ec8, sep%computed), 'm', 'SRSS x 0.7 where both points are floors at the '// &
                  'same level, of the uncoupled peaks without q_d (legacy; the EN 1998-1 4.4.2.7 rule is en1998)')
         call put('ddc', nan_where(sep%ddc, sep%computed), 'm', 'DDC = sqrt(u1^2 + u2^2 - 2 rho u1 u2)')
         call put('no_contact', nan_where(sep%no_contact, sep%no_contact_valid), 'm', &
                  'largest closing displacement of the uncoupled motion (the sweep probe)')
         call put('time_history', nan_where(sep%time_history, sep%time_history_valid), 'm', &
                  'smallest gap of the sweep meeting target_lambda')
      else
         call attrs('abs', '', 'ABS = u1 + u2 of the uncoupled peaks', '')
         call attrs('srss', '', 'SRSS = sqrt(u1^2 + u2^2) of the uncoupled peaks', '')
         call attrs('ec8', '', 'SRSS x 0.7 where both points are floors at the same level, of the uncoupled '// &
                    'peaks without q_d (legacy; the EN 1998-1 4.4.2.7 rule is en1998)', '')
         call attrs('ddc', '', 'DDC = sqrt(u1^2 + u2^2 - 2 rho u1 u2)', '')
         call attrs('no_contact', '', 'max_t (u1(t) - u2(t)) of the uncoupled histories; the suite row: the '// &
                    'largest over the motions (no motion makes contact)', '')
         call attrs('time_history', '', 'threshold gap of the gap sweep', '-1 where not computed '// &
                    '(time_history_valid = 0)')
         if (.not. allocated(error)) call h5_write(h5, g//'/time_history_valid', &
                                                   transpose(merge(1, 0, sep%time_history_valid)), error, &
                                                   units='1')
      end if
      call put('rho', nan_where(sep%rho, sep%computed), '1', 'CQC correlation coefficient used by the DDC')
      call put('asce7', nan_where(sep%asce7, sep%asce7_valid), 'm', 'ASCE 7-16 12.12.3: sqrt(dM1^2 + dM2^2), '// &
               'dM = Cd delta / Ie')
      call put('en1998', nan_where(sep%en1998, sep%en1998_valid), 'm', 'EN 1998-1 4.4.2.7: SRSS of q_d d_e, '// &
               'x 0.7 only where both points are floors at the same level (within 0.01 m)')
      call put('is1893', nan_where(sep%is1893, sep%is1893_valid), 'm', 'IS 1893-1:2016 7.11.3: R1 D1 + R2 D2, '// &
               'x 0.5 only where both points are floors at the same level (within 0.01 m)')
      if (.not. allocated(error)) call h5_write(h5, g//'/pair', labels, error, units='-')
      call put('peak_left', nan_where(sep%u(1), sep%computed), 'm', 'u1: the uncoupled peak |u| of the left '// &
               'building at its facing point (floor or point between floors) that the rules use')
      call put('peak_right', nan_where(sep%u(2), sep%computed), 'm', 'u2: the uncoupled peak |u| of the right '// &
               'building at its facing point that the rules use')
      call put('setback_left', nan_where(sep%setback(1), sep%computed), 'm', 'property-line setback of the left '// &
               'building at its facing point (ASCE 7-16 12.12.2 style): delta_M = Cd u1 / Ie with cd, else u1')
      call put('setback_right', nan_where(sep%setback(2), sep%computed), 'm', 'property-line setback of the '// &
               'right building at its facing point: delta_M = Cd u2 / Ie with cd, else u2')
      call put_flag('setback_amplified_left', merge(1, 0, sep%setback_amplified(1)), 'left')
      call put_flag('setback_amplified_right', merge(1, 0, sep%setback_amplified(2)), 'right')
      if (present(names) .and. .not. allocated(error)) then
         allocate (per_building(size(sep, 1), size(names)))
         do k = 1, size(sep, 1)
            do ib = 1, size(names)
               per_building(k, ib) = building_setbacks(sep(k, :), ib, size(names))
            end do
         end do
         call put('building_setback', per_building, 'm', 'property-line setback of each building (ASCE 7-16 '// &
                  '12.12.2 style): its largest setback over its facing points (building_name)')
         if (.not. allocated(error)) call h5_write(h5, g//'/building_name', names, error, units='-')
      end if
      if (.not. allocated(error)) call h5_write_attr(h5, g, 'peaks', 'the rules and setbacks use the '// &
                                                     peaks_label(reshape(sep, [size(sep)])), error)

   contains

      !> A new dataset with its attributes (its NaN marks n/a).
      subroutine put(name, values, units, rule)
         character(len=*), intent(in) :: name, units, rule
         real(dp), intent(in) :: values(:, :)

         if (allocated(error)) return
         if (suite) then
            call h5_write(h5, g//'/'//name, transpose(values), error)
         else
            call h5_write(h5, g//'/'//name, values(1, :), error)
         end if
         call attrs(name, units, rule, na_nan)
      end subroutine put

      !> A 0/1 dataset of the setbacks (1: Cd/Ie applied to the `side` building's setback).
      subroutine put_flag(name, values, side)
         character(len=*), intent(in) :: name, side
         integer, intent(in) :: values(:, :)

         if (allocated(error)) return
         if (suite) then
            call h5_write(h5, g//'/'//name, transpose(values), error, units='1')
         else
            call h5_write(h5, g//'/'//name, values(1, :), error, units='1')
         end if
         if (.not. allocated(error)) call h5_write_attr(h5, g//'/'//name, 'rule', '1 where Cd/Ie was applied '// &
                                                        'to the '//side//' building''s setback (its cd given), 0: '// &
                                                        'the peak itself', error)
      end subroutine put_flag

      subroutine attrs(name, units, rule, na)
         character(len=*), intent(in) :: name, units, rule, na

         if (allocated(error)) return
         ! units = '': the dataset was written with its units (the suite's legacy rules)
         if (len(units) > 0) call h5_write_attr(h5, g//'/'//name, 'units', units, error)
         if (.not. allocated(error)) call h5_write_attr(h5, g//'/'//name, 'rule', rule, error)
         if (.not. allocated(error) .and. len(na) > 0) call h5_write_attr(h5, g//'/'//name, 'na', na, error)
      end subroutine attrs

   end subroutine write_separation_h5

   !> `x` where `valid`, NaN elsewhere.
   elemental real(dp) function nan_where(x, valid) result(y)
      !> Value.
      real(dp), intent(in) :: x
      !> Whether it is computed.
      logical, intent(in) :: valid

      y = x
      if (.not. valid) y = not_computed(x)
   end function nan_where

end module pound_separation_output
