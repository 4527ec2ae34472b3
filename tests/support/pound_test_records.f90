!> The real accelerograms in `shared/records/` beside the project, for the tests that need
!> them. Those tests live in their own files (tests/test_records*.pf), whose test program
!> calls `require_records` before any test runs: without the records it exits with status 77,
!> which CTest reports as skipped, so a skip can never hide a failure of another test.
module pound_test_records
   use, intrinsic :: iso_fortran_env, only: output_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use pound_test_support, only: shared_dir
   implicit none
   private

   public :: require_records, record_file, records_skip_status

   !> Exit status of a test program skipped for want of the records (CTest SKIP_RETURN_CODE).
   integer, parameter :: records_skip_status = 77

   interface
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

contains

   !> The records directory: `shared_dir()/records`.
   function records_dir() result(dir)
      character(len=:), allocatable :: dir

      dir = shared_dir()//'/records'
   end function records_dir

   !> Run before any test of a records file (pFUnit's EXTRA_INITIALIZE): when the records
   !> directory is absent, say so and end the program with `records_skip_status`.
   subroutine require_records()
      logical :: there

      inquire (file=records_dir()//'/.', exist=there)
      if (there) return
      write (output_unit, '(a)') 'SKIPPED: '//records_dir()//' not present: every test of '// &
         'this program needs the records'
      flush (output_unit)
      call c_exit(int(records_skip_status, c_int))
   end subroutine require_records

   !> Path of the record `name` in the records directory; a test asserts that it exists
   !> (the directory is there, see require_records: a missing file is a failure).
   function record_file(name) result(path)
      !> File name, e.g. 'IELC180.AT2'.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path

      path = records_dir()//'/'//name
   end function record_file

end module pound_test_records
