!> Constitutive laws of the unilateral constraints between facing floors.
!>
!> A law relates the compression d of the joint (penetration beyond the gap) to the
!> compressive force r >= 0. Per time step the contact solver needs, for every closed
!> joint, the effective compliance 1/phat and the offset that the law adds to the
!> step's LCP; the law is a choice in the deck, each kind with its own parameters.
module pound_contact_law
   use pound_kinds, only: dp
   implicit none
   private

   public :: contact_law, law_elastic, law_name

   !> Elastic compression-only spring, optional dashpot in parallel: r = p d + c d'.
   integer, parameter :: law_elastic = 1

   !> A constraint law and its parameters.
   type :: contact_law
      !> Kind of law (`law_elastic`).
      integer :: kind = law_elastic
      !> Initial (elastic) stiffness p (kN/m).
      real(dp) :: stiffness = 0.0_dp
      !> Dashpot coefficient c (kN s/m).
      real(dp) :: dashpot = 0.0_dp
   end type contact_law

contains

   !> Name of a law kind, as written in the deck.
   pure function law_name(kind) result(name)
      !> Law kind.
      integer, intent(in) :: kind
      character(len=:), allocatable :: name

      select case (kind)
      case (law_elastic)
         name = 'elastic'
      case default
         name = 'unknown'
      end select
   end function law_name

end module pound_contact_law
