!> Program name and version (the single source of the version number;
!> CMakeLists.txt reads it from here).
module pound_version
   implicit none
   private

   !> Program name.
   character(len=*), parameter, public :: program_name = 'pound'
   !> Semantic version.
   character(len=*), parameter, public :: program_version = '0.1.0'

end module pound_version
