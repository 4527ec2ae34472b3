!> pound: seismic pounding of adjacent buildings.
!>
!>     pound DECK.nml [-o DIR]     writes DIR/<stem>.out (listing) and DIR/<stem>.h5 (histories)
!>     pound --help | --version
!>
!> Every analysis runs the buildings uncoupled and, when the deck declares contact, coupled.
!> Outputs are written under temporary names and renamed at the end; on any error nothing
!> is left behind and the exit status is non-zero.
program pound
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_version, only: program_name, program_version
   use pound_config, only: deck_type
   use pound_deck, only: read_deck
   use pound_ground_motion, only: ground_motion_t, pulse_motion, record_motion, sample_ground, &
                                  describe_ground
   use pound_shear_building, only: shear_building, build_shear_building
   use pound_analysis, only: analysis_result, run_uncoupled, run_coupled
   use pound_contact, only: contact_system, contact_pair, pairs_from_config
   use pound_listing, only: write_listing_header, write_model_summary, write_peak_tables, &
                            write_contact_summary, write_influence_tables, write_sweep_table
   use pound_sweep, only: sweep_result, run_sweep
   use pound_results_h5, only: write_results_h5
   use pound_files, only: rename_file, delete_file, file_stem, temporary_name, join_path
   implicit none

   interface
      subroutine c_exit(status) bind(C, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   character(len=:), allocatable :: deck_path, out_dir, listing_path, h5_path
   type(deck_type) :: deck
   type(ground_motion_t) :: gm
   type(shear_building), allocatable :: models(:)
   type(analysis_result) :: unc, cpl
   type(contact_system) :: cs
   type(contact_pair), allocatable :: pairs(:)
   type(sweep_result) :: sweep
   character(len=64), allocatable :: names(:)
   logical :: coupled
   type(error_type), allocatable :: error
   real(dp), allocatable :: ag(:)
   character(len=512) :: ground_text(1)
   integer :: n_steps, ib, u

   call parse_arguments()
   call read_deck(deck_path, deck, error)
   call check(error)

   ! Ground motion at the solver's steps.
   select case (deck%ground%kind)
   case ('pulse')
      call pulse_motion(gm, deck%ground%x0, deck%ground%a, deck%ground%b)
   case default
      call record_motion(gm, deck%ground%file, deck%ground%format, deck%ground%scale, error)
      call check(error)
   end select
   n_steps = nint(deck%analysis%t_end/deck%analysis%dt)
   allocate (ag(0:n_steps))
   call sample_ground(gm, deck%analysis%dt, n_steps, ag)
   ground_text(1) = describe_ground(gm)

   ! Models.
   allocate (models(size(deck%buildings)))
   do ib = 1, size(models)
      call build_shear_building(deck%buildings(ib), models(ib), error)
      if (allocated(error)) error%message = deck_path//': '//error%message
      call check(error)
   end do

   call run_uncoupled(deck%analysis, models, ag, unc, error)
   call check(error)
   coupled = size(deck%contacts) > 0
   if (coupled) then
      allocate (names(size(models)))
      do ib = 1, size(models)
         names(ib) = models(ib)%name
      end do
      pairs = pairs_from_config(deck%contacts, names, error)
      if (allocated(error)) error%message = deck_path//': '//error%message
      call check(error)
      call run_coupled(deck%analysis, models, ag, pairs, cpl, cs, error)
      if (allocated(error)) error%message = deck_path//': '//error%message
      call check(error)
      if (deck%sweep%active) then
         call run_sweep(deck%analysis, deck%sweep, models, ag, pairs, unc, sweep, error)
         if (allocated(error)) error%message = deck_path//': '//error%message
         call check(error)
      end if
   end if

   ! Outputs: temporary names first, renamed when complete.
   listing_path = join_path(out_dir, file_stem(deck_path)//'.out')
   h5_path = join_path(out_dir, file_stem(deck_path)//'.h5')
   open (newunit=u, file=temporary_name(listing_path), status='replace', action='write', iostat=ib)
   if (ib /= 0) then
      call fatal_error(error, 'cannot write '//temporary_name(listing_path)//' (does the directory '// &
                       out_dir//' exist and is it writable?)')
      call check(error)
   end if
   call write_listing_header(u, deck, ground_text)
   call write_model_summary(u, models)
   call write_peak_tables(u, 'Uncoupled', models, unc)
   if (coupled) then
      call write_peak_tables(u, 'Coupled', models, cpl)
      call write_contact_summary(u, cs)
      call write_influence_tables(u, models, unc, cpl)
      if (deck%sweep%active) call write_sweep_table(u, models, deck%sweep, sweep)
   end if
   write (u, '(/,a,es10.3,a)') '  uncoupled integration: ', unc%seconds, ' s'
   if (coupled) write (u, '(a,es10.3,a,es10.3,a)') '  coupled integration:   ', cpl%seconds, &
      ' s, of which contact (LCP) ', cpl%contact_seconds, ' s'
   close (u)
   if (deck%sweep%active) then
      call write_results_h5(temporary_name(h5_path), deck, models, trim(ground_text(1)), &
                            ag(0:n_steps:deck%analysis%output_every), unc, error, cpl, cs, sweep)
   else if (coupled) then
      call write_results_h5(temporary_name(h5_path), deck, models, trim(ground_text(1)), &
                            ag(0:n_steps:deck%analysis%output_every), unc, error, cpl, cs)
   else
      call write_results_h5(temporary_name(h5_path), deck, models, trim(ground_text(1)), &
                            ag(0:n_steps:deck%analysis%output_every), unc, error)
   end if
   call check(error)
   call rename_file(temporary_name(h5_path), h5_path, error)
   call check(error)
   call rename_file(temporary_name(listing_path), listing_path, error)
   call check(error)

   write (output_unit, '(a)') program_name//' '//program_version//': '//deck%analysis%title
   do ib = 1, size(models)
      write (output_unit, '(a,i0,a,f9.5,a)') '  building '//models(ib)%name//': ', models(ib)%n, &
         ' storeys, T1 = ', models(ib)%period(1), ' s'
   end do
   write (output_unit, '(a,es10.3,a,es9.2)') '  uncoupled integration: ', unc%seconds, &
      ' s, energy balance error ', unc%energy_error
   if (coupled) then
      write (output_unit, '(a,es10.3,a,es9.2,a,i0,a,i0,a)') '  coupled integration:   ', cpl%seconds, &
         ' s, energy balance error ', cpl%energy_error, ', ', sum(cs%pair(:)%impacts), ' impacts, ', &
         cs%pivots_total, ' LCP pivots'
      write (output_unit, '(a,es10.3,a,i0,a,i0,a,i0)') '  contact (LCP) time:    ', cpl%contact_seconds, &
         ' s, LCP solves ', cs%solves, ', pivots max ', cs%pivots_max, ', steps ', cpl%n_steps
   end if
   if (deck%sweep%active) then
      write (output_unit, '(a,i0,a,es10.3,a)') '  gap sweep: ', size(sweep%gap), ' gaps in ', sweep%seconds, ' s'
      if (sweep%found) write (output_unit, '(a,f10.4,a)') '  smallest gap meeting the target: ', &
         1000.0_dp*sweep%safe_gap, ' mm'
   end if
   write (output_unit, '(a)') '  wrote '//listing_path//' and '//h5_path

contains

   !> Stop with the message and a non-zero status if `err` is set; remove partial outputs.
   subroutine check(err)
      type(error_type), allocatable, intent(in) :: err

      if (.not. allocated(err)) return
      write (error_unit, '(a)') program_name//': error: '//err%message
      if (allocated(listing_path)) call delete_file(temporary_name(listing_path))
      if (allocated(h5_path)) call delete_file(temporary_name(h5_path))
      flush (error_unit)
      flush (output_unit)
      call c_exit(1_c_int)
   end subroutine check

   subroutine usage(unit)
      integer, intent(in) :: unit

      write (unit, '(a)') 'usage: pound DECK.nml [-o DIR]'
      write (unit, '(a)') '       pound --help | --version'
      write (unit, '(a)') 'Seismic pounding of adjacent buildings: runs the deck''s buildings uncoupled and'
      write (unit, '(a)') 'coupled by unilateral contact and writes DIR/<deck>.out (listing) and'
      write (unit, '(a)') 'DIR/<deck>.h5 (histories, HDF5). DIR defaults to the current directory.'
   end subroutine usage

   subroutine parse_arguments()
      integer :: i, n, length
      character(len=:), allocatable :: arg

      n = command_argument_count()
      out_dir = '.'
      i = 0
      do while (i < n)
         i = i + 1
         call get_command_argument(i, length=length)
         if (allocated(arg)) deallocate (arg)
         allocate (character(len=length) :: arg)
         call get_command_argument(i, arg)
         select case (arg)
         case ('-h', '--help')
            call usage(output_unit)
            call c_exit(0_c_int)
         case ('-V', '--version')
            write (output_unit, '(a)') program_name//' '//program_version
            call c_exit(0_c_int)
         case ('-o', '--output')
            if (i == n) call bad_usage('option '//arg//' needs a directory')
            i = i + 1
            call get_command_argument(i, length=length)
            deallocate (out_dir)
            allocate (character(len=length) :: out_dir)
            call get_command_argument(i, out_dir)
         case default
            if (len(arg) > 0) then
               if (arg(1:1) == '-') call bad_usage('unknown option '//arg)
            end if
            if (allocated(deck_path)) call bad_usage('more than one deck given: '//deck_path//', '//arg)
            deck_path = arg
         end select
      end do
      if (.not. allocated(deck_path)) call bad_usage('no deck given')
   end subroutine parse_arguments

   subroutine bad_usage(message)
      character(len=*), intent(in) :: message

      write (error_unit, '(a)') program_name//': error: '//message
      call usage(error_unit)
      call c_exit(2_c_int)
   end subroutine bad_usage

end program pound
