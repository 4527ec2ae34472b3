!> What `&stripes` and `&hazard` ask (the risk-targeted joint): the stripes' measure, period,
!> levels and target, the site's hazard curve, the exposure time and the target probability.
!> Plain data that the deck fills (`pound_config` names the type, as part of `deck_type`) and
!> the multiple-stripe driver (`pound_stripes`) reads.
module pound_risk_settings
   use pound_kinds, only: dp
   use pound_quantities, only: n_target_quantities
   implicit none
   private

   public :: risk_config

   !> `&stripes` and `&hazard` (both or neither).
   type :: risk_config
      !> Whether the deck has `&stripes` (and `&hazard`).
      logical :: active = .false.
      !> Intensity measure: 'sa' (5 %-damped Sa at `period`) or 'pga'.
      character(len=8) :: measure = 'sa'
      !> Period of Sa (s); 0: T1 of the most flexible building.
      real(dp) :: period = 0.0_dp
      !> The stripes' intensity levels (m/s^2), ascending.
      real(dp), allocatable :: levels(:)
      !> Target of |lambda| (%) and the quantities it applies to (order of `target_names`).
      real(dp) :: target_lambda = 10.0_dp
      !> (Default: storey_shear alone, the fifth quantity.)
      logical :: target_quantities(n_target_quantities) = &
         [.false., .false., .false., .false., .true., .false., .false., .false.]
      !> Hazard curve: intensities (m/s^2, ascending) and annual rates of exceedance (decreasing).
      real(dp), allocatable :: im(:), rate(:)
      !> Exposure time of the probabilities (years).
      real(dp) :: years = 50.0_dp
      !> Target probability in `years` of the risk-targeted gap; negative: none given.
      real(dp) :: target_probability = -1.0_dp
   end type risk_config

end module pound_risk_settings
