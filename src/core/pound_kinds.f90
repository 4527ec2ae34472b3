!> The single real kind used throughout pound.
module pound_kinds
   use iso_fortran_env, only: real64
   implicit none
   private

   !> Working precision (IEEE double).
   integer, parameter, public :: dp = real64

end module pound_kinds
