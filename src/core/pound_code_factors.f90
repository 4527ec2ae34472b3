!> The design-code factors of a building for the separation rules (ASCE 7 Cd and Ie, EN 1998
!> q, IS 1893 R). Plain data that the deck fills (`pound_config` names the type too, as part of
!> `building_config`) and the separation kernel (`pound_separation`) reads, so that the kernel
!> does not depend on the deck's configuration.
module pound_code_factors
   use pound_kinds, only: dp
   implicit none
   private

   public :: code_factors

   !> The design-code factors of one building for the separation rules (pound_separation);
   !> 0 where the deck does not give them (the rule that needs the factor is then n/a).
   type :: code_factors
      !> ASCE 7 deflection amplification factor Cd (`cd`).
      real(dp) :: cd = 0.0_dp
      !> ASCE 7 importance factor Ie (`importance`; default 1).
      real(dp) :: importance = 1.0_dp
      !> EN 1998-1 behaviour factor q, used as the displacement behaviour factor q_d (`behaviour_factor`).
      real(dp) :: behaviour_factor = 0.0_dp
      !> IS 1893 response reduction factor R (`response_reduction`).
      real(dp) :: response_reduction = 0.0_dp
   end type code_factors

end module pound_code_factors
