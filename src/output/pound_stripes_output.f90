!> The outputs of the multiple-stripe analysis (`pound_stripes`): the answer lines (terminal,
!> top of the listing, summary CSV), the listing's tables (per-gap fragility and probabilities,
!> per-stripe fractions), the HDF5 group /risk and the demand files for loss tools.
!>
!> HDF5 (names pinned): /risk/stripes/levels (n_stripes, m/s^2), /risk/motions (names),
!> /risk/gaps (n_gaps, m), /risk/outcomes/<outcome> (h5py shape (n_gaps, n_stripes,
!> n_motions), 0/1), /risk/fragility/<outcome>/median (m/s^2) and /beta (n_gaps; NaN with an
!> attribute `na` holding the reasons where the fit is n/a; /bracket_lo and /bracket_hi, the
!> bracket of the median), /risk/maf/<outcome> (1/year) and
!> /risk/probability/<outcome> (n_gaps), /risk/gap/<outcome> (scalar, m; NaN where none); on
!> /risk the attributes `years`, `target_probability` (NaN: none), `measure`, `period`,
!> `target_lambda`, `deck_gap` and `answer` (the first answer line). The collapse outcomes only
!> where a building can yield.
!>
!> Demand files, one per stripe k: `<deck>_demands_stripe<k>.csv`, one row per motion, the
!> coupled peaks at the deck gap in pelicun's column naming `event-type-location-direction`:
!> `1-PFA-<floor>-1` (floors 0..n, floor 0 the ground: PGA; in g) and `1-PID-<storey>-1`
!> (storeys 1..n; peak interstorey drift / storey height, rad). The second row is pelicun's
!> `Units` row. With several buildings, each building's columns carry its name and a slash
!> before them (`A/1-PID-1-1`): a loss model takes one building's columns and drops the prefix.
module pound_stripes_output
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
   use pound_kinds, only: dp
   use pound_constants, only: g_accel
   use pound_error, only: error_type
   use pound_config, only: deck_type, target_names
   use pound_strings, only: str, fixed_cell, plain_real, mm_text
   use pound_h5, only: h5_file, h5_open, h5_close, h5_write, h5_write_attr
   use pound_text_writer, only: text_writer, open_text, close_text
   use pound_summary, only: summary_item, summary_text_len
   use pound_stripes_result, only: stripes_result, outcome_names, n_outcomes, o_contact, o_lambda, o_due
   implicit none
   private

   public :: risk_answer_lines, risk_summary_items, write_stripes_listing, write_stripes_h5, write_demand_files, &
             demand_file_name

contains

   !> Whether outcome o is reported (the collapse outcomes only where a building can yield).
   pure logical function reported(res, o)
      type(stripes_result), intent(in) :: res
      integer, intent(in) :: o

      reported = o <= 2 .or. res%yields
   end function reported

   !> 'P(lambda > 10 %)', 'P(contact)', 'P(collapse)', 'P(collapse due to pounding)'.
   pure function event_text(deck, o) result(s)
      type(deck_type), intent(in) :: deck
      integer, intent(in) :: o
      character(len=:), allocatable :: s

      select case (o)
      case (o_contact)
         s = 'P(contact)'
      case (o_lambda)
         s = 'P(lambda > '//plain_real(deck%risk%target_lambda)//' %)'
      case (o_due)
         s = 'P(collapse due to pounding)'
      case default
         s = 'P(collapse)'
      end select
   end function event_text

   !> A probability in percent for the text lines ('12.34 %', 'n/a').
   pure function percent_text(p) result(s)
      real(dp), intent(in) :: p
      character(len=:), allocatable :: s

      if (ieee_is_nan(p)) then
         s = 'n/a'
      else
         s = trim(adjustl(fixed_cell(100.0_dp*p, 12, 2)))//' %'
      end if
   end function percent_text

   !> The answer, first: the risk-targeted gap for lambda_exceeded (or its probability at the
   !> deck gap when no target probability is given), beside P(contact) and, where a building
   !> yields, P(collapse due to pounding) at the deck gap.
   pure function risk_answer_lines(deck, res) result(lines)
      !> The configuration.
      type(deck_type), intent(in) :: deck
      !> The results.
      type(stripes_result), intent(in) :: res
      character(len=2*summary_text_len), allocatable :: lines(:)
      character(len=:), allocatable :: in_years, at_deck
      integer :: n

      in_years = ' in '//plain_real(deck%risk%years)//' years'
      at_deck = ' at the deck gap '//mm_text(res%deck_gap)
      allocate (lines(0))
      if (deck%risk%target_probability > 0.0_dp) then
         n = size(res%gaps)
         if (ieee_is_nan(res%risk_gap(o_lambda))) then
            lines = [character(len=2*summary_text_len) :: lines, 'risk-targeted gap: none up to '// &
                     mm_text(res%gaps(n))//' for '//event_text(deck, o_lambda)//' <= '// &
                     percent_text(deck%risk%target_probability)//in_years//' ('// &
                     percent_text(res%probability(o_lambda, n))//' at '//mm_text(res%gaps(n))//')']
         else
            lines = [character(len=2*summary_text_len) :: lines, 'risk-targeted gap: '// &
                     trim(adjustl(fixed_cell(1000.0_dp*res%risk_gap(o_lambda), 12, 1)))//' mm for '// &
                     event_text(deck, o_lambda)//' <= '//percent_text(deck%risk%target_probability)//in_years// &
                     ' (sweep grid, not refined)']
         end if
      end if
      lines = [character(len=2*summary_text_len) :: lines, event_text(deck, o_lambda)//in_years//at_deck//': '// &
               percent_text(res%deck_probability(o_lambda))]
      lines = [character(len=2*summary_text_len) :: lines, event_text(deck, o_contact)//in_years//at_deck//': '// &
               percent_text(res%deck_probability(o_contact))]
      if (res%yields) lines = [character(len=2*summary_text_len) :: lines, event_text(deck, o_due)//in_years// &
                               at_deck//': '//percent_text(res%deck_probability(o_due))]
   end function risk_answer_lines

   !> The summary CSV's risk rows (kind 'risk', subject 'run'): per reported outcome its
   !> risk-targeted gap (mm; n/a where none or without a target probability) and its probability
   !> at the deck gap (%).
   pure function risk_summary_items(deck, res) result(items)
      !> The configuration.
      type(deck_type), intent(in) :: deck
      !> The results.
      type(stripes_result), intent(in) :: res
      type(summary_item), allocatable :: items(:)
      type(summary_item) :: it
      integer :: o

      allocate (items(0))
      do o = 1, n_outcomes
         if (.not. reported(res, o)) cycle
         it = summary_item()
         it%kind = 'risk'
         it%subject = 'run'
         it%quantity = 'risk_targeted_gap_'//trim(outcome_names(o))
         it%label = 'risk-targeted gap for '//event_text(deck, o)
         it%unit = 'mm'
         it%available = .not. ieee_is_nan(res%risk_gap(o))
         if (it%available) then
            it%value = 1000.0_dp*res%risk_gap(o)
            it%location = 'P <= '//percent_text(deck%risk%target_probability)//' in '//plain_real(deck%risk%years)// &
                          ' years'
         else if (deck%risk%target_probability > 0.0_dp) then
            it%location = 'none in the sweep'
         else
            it%location = 'no target_probability'
         end if
         items = [items, it]
         it = summary_item()
         it%kind = 'risk'
         it%subject = 'run'
         it%quantity = 'probability_'//trim(outcome_names(o))
         it%label = event_text(deck, o)//' in '//plain_real(deck%risk%years)//' years at the deck gap'
         it%unit = '%'
         it%available = .not. ieee_is_nan(res%deck_probability(o))
         if (it%available) it%value = 100.0_dp*res%deck_probability(o)
         it%location = 'deck gap '//mm_text(res%deck_gap)
         items = [items, it]
      end do
   end function risk_summary_items

   !> The listing's section: the answer, the settings, the per-gap fragility and probabilities
   !> and the per-stripe fractions (at every gap of the sweep is in the HDF5 file; here at the
   !> deck gap).
   subroutine write_stripes_listing(lst, deck, res)
      !> The listing.
      type(text_writer), intent(inout) :: lst
      !> The configuration.
      type(deck_type), intent(in) :: deck
      !> The results.
      type(stripes_result), intent(in) :: res
      character(len=:), allocatable :: line, measure
      character(len=2*summary_text_len), allocatable :: answer(:)
      integer :: o, g, s, i

      if (deck%risk%measure == 'sa') then
         measure = 'Sa(T = '//plain_real(res%period)//' s, 5 %)'
      else
         measure = 'PGA'
      end if
      call put('')
      call put('Risk-targeted joint: multiple-stripe analysis')
      call put('=============================================')
      answer = risk_answer_lines(deck, res)
      do i = 1, size(answer)
         call put('  '//trim(answer(i)))
      end do
      call put('  measure: '//measure//'; '//str(size(res%levels))//' stripes x '//str(size(res%motions))// &
               ' motions, '//str(size(res%gaps))//' gaps; target lambda '//plain_real(deck%risk%target_lambda)// &
               ' % on '//targets()//'; hazard curve of '//str(size(deck%risk%im))//' points, exposure '// &
               plain_real(deck%risk%years)//' years')
      call put('  fragility: lognormal, binomial maximum likelihood over the stripes; n/a where the counts do '// &
               'not identify it (the bracket of the median given instead)')
      call put('')
      call put('  Per gap: fragility median [m/s^2], beta, probability in '//plain_real(deck%risk%years)//' years [%]')
      do o = 1, n_outcomes
         if (.not. reported(res, o)) cycle
         call put('  '//trim(outcome_names(o))//':')
         call put('     gap [mm]    median      beta     P [%]   maf [1/yr]')
         do g = 1, size(res%gaps)
            line = '  '//fixed_cell(1000.0_dp*res%gaps(g), 11, 3)
            if (res%fit(o, g)%identified) then
               line = line//fixed_cell(res%fit(o, g)%median, 10, 4)//fixed_cell(res%fit(o, g)%beta, 10, 4)
            else
               line = line//'       n/a       n/a'
            end if
            line = line//fixed_cell(100.0_dp*res%probability(o, g), 10, 3)//' '//sci(res%maf(o, g))
            if (.not. res%fit(o, g)%identified) line = line//'  ('//trim(res%fit(o, g)%reason)//bracket(o, g)//')'
            if (res%fit(o, g)%lower_bound) line = line//'  P a lower bound'
            call put(line)
         end do
      end do
      call put('')
      call put('  Per stripe: fraction of the motions with each outcome at the deck gap '//mm_text(res%deck_gap))
      line = '  stripe  level [m/s^2]  level [g]'
      do o = 1, n_outcomes
         if (reported(res, o)) line = line//'  '//trim(outcome_names(o))
      end do
      call put(line)
      do s = 1, size(res%levels)
         line = '  '//repeat(" ", 6 - len(str(s)))//str(s)//fixed_cell(res%levels(s), 15, 4)// &
                fixed_cell(res%levels(s)/g_accel, 11, 4)
         do o = 1, n_outcomes
            if (.not. reported(res, o)) cycle
            line = line//fixed_cell(real(sum(res%deck_outcome(o, :, s)), dp)/real(size(res%motions), dp), &
                                    len_trim(outcome_names(o)) + 2, 3)
         end do
         call put(line)
      end do
      write (line, '(es10.3)') res%seconds
      call put('  multiple-stripe analysis: '//trim(adjustl(line))//' s')

   contains

      subroutine put(text)
         character(len=*), intent(in) :: text

         if (lst%ios /= 0) return
         call lst%put(text)
      end subroutine put

      function targets() result(s)
         character(len=:), allocatable :: s
         integer :: q

         s = ''
         do q = 1, size(target_names)
            if (.not. deck%risk%target_quantities(q)) cycle
            if (len(s) > 0) s = s//' '
            s = s//trim(target_names(q))
         end do
      end function targets

      function sci(x) result(s)
         real(dp), intent(in) :: x
         character(len=:), allocatable :: s
         character(len=16) :: buf

         write (buf, '(es11.4)') x
         s = buf(1:11)
      end function sci

      function bracket(o, g) result(s)
         integer, intent(in) :: o, g
         character(len=:), allocatable :: s, hi

         if (res%fit(o, g)%bracket_hi >= huge(1.0_dp)) then
            hi = 'inf'
         else
            hi = plain_real(res%fit(o, g)%bracket_hi)
         end if
         s = '; median in ['//plain_real(res%fit(o, g)%bracket_lo)//', '//hi//'] m/s^2'
      end function bracket

   end subroutine write_stripes_listing

   !> The group /risk of the results file at `path` (written and closed).
   subroutine write_stripes_h5(path, deck, res, error)
      !> Results file.
      character(len=*), intent(in) :: path
      !> The configuration.
      type(deck_type), intent(in) :: deck
      !> The results.
      type(stripes_result), intent(in) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: close_error
      type(h5_file) :: h5

      call h5_open(h5, path, error, writable=.true.)
      if (allocated(error)) return
      call write_all()
      call h5_close(h5, close_error)
      if (allocated(close_error) .and. .not. allocated(error)) call move_alloc(close_error, error)

   contains

      subroutine write_all()
         real(dp) :: nan, median(size(res%gaps)), beta(size(res%gaps))
         character(len=2*summary_text_len), allocatable :: answer(:)
         integer :: o, g
         character(len=:), allocatable :: p, na

         nan = ieee_value(1.0_dp, ieee_quiet_nan)
         call h5_write(h5, '/risk/stripes/levels', res%levels, error, units='m/s^2')
         if (.not. allocated(error)) call h5_write(h5, '/risk/motions', res%motions, error, units='-')
         if (.not. allocated(error)) call h5_write(h5, '/risk/gaps', res%gaps, error, units='m')
         if (allocated(error)) return
         call h5_write_attr(h5, '/risk', 'years', deck%risk%years, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/risk', 'target_probability', &
                                                        merge(deck%risk%target_probability, nan, &
                                                              deck%risk%target_probability > 0.0_dp), error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/risk', 'measure', trim(deck%risk%measure), error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/risk', 'period', res%period, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/risk', 'target_lambda', deck%risk%target_lambda, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/risk', 'deck_gap', res%deck_gap, error)
         if (.not. allocated(error)) then
            answer = risk_answer_lines(deck, res)
            call h5_write_attr(h5, '/risk', 'answer', trim(answer(1)), error)
         end if
         if (.not. allocated(error)) call h5_write(h5, '/risk/hazard/im', deck%risk%im, error, units='m/s^2')
         if (.not. allocated(error)) call h5_write(h5, '/risk/hazard/rate', deck%risk%rate, error, units='1/year')
         if (allocated(error)) return
         do o = 1, n_outcomes
            if (.not. reported(res, o)) cycle
            p = trim(outcome_names(o))
            call h5_write(h5, '/risk/outcomes/'//p, res%outcome(o, :, :, :), error, units='1')
            if (allocated(error)) return
            na = ''
            do g = 1, size(res%gaps)
               if (res%fit(o, g)%identified) then
                  median(g) = res%fit(o, g)%median
                  beta(g) = res%fit(o, g)%beta
               else
                  median(g) = nan
                  beta(g) = nan
                  if (len(na) > 0) na = na//'; '
                  na = na//'gap '//mm_text(res%gaps(g))//': '//trim(res%fit(o, g)%reason)
               end if
            end do
            call h5_write(h5, '/risk/fragility/'//p//'/median', median, error, units='m/s^2')
            if (.not. allocated(error)) call h5_write(h5, '/risk/fragility/'//p//'/beta', beta, error, units='1')
            if (.not. allocated(error)) call h5_write(h5, '/risk/fragility/'//p//'/bracket_lo', &
                                                      res%fit(o, :)%bracket_lo, error, units='m/s^2')
            if (.not. allocated(error)) call h5_write(h5, '/risk/fragility/'//p//'/bracket_hi', &
                                                      res%fit(o, :)%bracket_hi, error, units='m/s^2')
            if (len(na) > 0 .and. .not. allocated(error)) then
               call h5_write_attr(h5, '/risk/fragility/'//p//'/median', 'na', na, error)
               if (.not. allocated(error)) call h5_write_attr(h5, '/risk/fragility/'//p//'/beta', 'na', na, error)
            end if
            if (.not. allocated(error)) call h5_write(h5, '/risk/maf/'//p, res%maf(o, :), error, units='1/year')
            if (.not. allocated(error)) call h5_write(h5, '/risk/probability/'//p, res%probability(o, :), error, &
                                                      units='1')
            if (.not. allocated(error)) call h5_write(h5, '/risk/gap/'//p, res%risk_gap(o), error, units='m')
            if (allocated(error)) return
         end do
      end subroutine write_all

   end subroutine write_stripes_h5

   !> The demand file of stripe k beside the listing `listing` ('DIR/deck.out' ->
   !> 'DIR/deck_demands_stripe<k>.csv').
   pure function demand_file_name(listing, k) result(path)
      !> The listing's path.
      character(len=*), intent(in) :: listing
      !> Stripe.
      integer, intent(in) :: k
      character(len=:), allocatable :: path
      integer :: dot

      dot = index(listing, '.', back=.true.)
      if (dot <= index(listing, '/', back=.true.)) dot = len(listing) + 1
      path = listing(1:dot - 1)//'_demands_stripe'//str(k)//'.csv'
   end function demand_file_name

   !> The demand files, one per stripe (see the module notes), beside the listing.
   subroutine write_demand_files(listing, deck, res, error)
      !> The listing's path.
      character(len=*), intent(in) :: listing
      !> The configuration.
      type(deck_type), intent(in) :: deck
      !> The results.
      type(stripes_result), intent(in) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(text_writer) :: w
      character(len=:), allocatable :: header, units, row, prefix
      character(len=32) :: buf
      integer :: s, k, ib, j, nb

      nb = size(deck%buildings)
      header = 'motion'
      units = 'Units'
      do ib = 1, nb
         prefix = ''
         if (nb > 1) prefix = deck%buildings(ib)%name//'/'
         do j = 0, size(res%demand(ib)%pid, 1)
            header = header//','//prefix//'1-PFA-'//str(j)//'-1'
            units = units//',g'
         end do
         do j = 1, size(res%demand(ib)%pid, 1)
            header = header//','//prefix//'1-PID-'//str(j)//'-1'
            units = units//',rad'
         end do
      end do
      do s = 1, size(res%levels)
         call open_text(demand_file_name(listing, s), 'demands', w, error)
         if (allocated(error)) return
         call w%put(header)
         call w%put(units)
         do k = 1, size(res%motions)
            row = trim(res%motions(k))
            do ib = 1, nb
               do j = 0, size(res%demand(ib)%pid, 1)
                  write (buf, '(es24.16e3)') res%demand(ib)%pfa(j, k, s)/g_accel
                  row = row//','//trim(adjustl(buf))
               end do
               do j = 1, size(res%demand(ib)%pid, 1)
                  write (buf, '(es24.16e3)') res%demand(ib)%pid(j, k, s)
                  row = row//','//trim(adjustl(buf))
               end do
            end do
            if (w%ios /= 0) exit
            call w%put(row)
         end do
         call close_text(w, error)
         if (allocated(error)) return
      end do
   end subroutine write_demand_files

end module pound_stripes_output
