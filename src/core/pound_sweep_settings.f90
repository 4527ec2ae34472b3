!> What `&sweep` asks: the gap range, the target and its quantities. Plain data that the deck
!> fills (`pound_config` names the type too, as part of `deck_type`) and the sweep kernel
!> (`pound_sweep`) reads, so that the kernel does not depend on the deck's configuration.
module pound_sweep_settings
   use pound_kinds, only: dp
   use pound_quantities, only: n_history_quantities, n_target_quantities
   implicit none
   private

   public :: sweep_config

   !> `&sweep`: the coupled analysis repeated for a range of seismic-joint gaps.
   type :: sweep_config
      !> Whether the deck asks for a sweep.
      logical :: active = .false.
      !> First and last gap (m), applied to every contact pair.
      real(dp) :: gap_from = 0.0_dp, gap_to = 0.0_dp
      !> Number of gaps, evenly spaced from gap_from to gap_to.
      integer :: n_gaps = 0
      !> Target for the largest |lambda| (%); negative when none is given.
      real(dp) :: target = -1.0_dp
      !> Quantities the target applies to (same order as `target_names`: the history quantities,
      !> then the frames' column-segment shear and moment and the bilinear storeys' ductility,
      !> off unless the deck names them).
      logical :: target_quantities(n_target_quantities) = &
         [spread(.true., 1, n_history_quantities), .false., .false., .false.]
      !> Tolerance (m) of the bisection refinement of a suite's threshold gaps (pound_suite).
      real(dp) :: refine_tolerance = 1.0e-5_dp
      !> What the sweep varies: 'gap' (the gap sweep above, `active`), 'stiffness' or
      !> 'restitution' (a joint study, `pound_joint_study`: `active` stays false).
      character(len=16) :: parameter = 'gap'
      !> The values of a stiffness (kN/m) or restitution sweep, in the deck's order (listed or
      !> spaced from `value_from` to `value_to`); unallocated for a gap sweep.
      real(dp), allocatable :: values(:)
   end type sweep_config

end module pound_sweep_settings
