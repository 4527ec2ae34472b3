!> The response quantities of pound: the history quantities (stored per floor or storey,
!> in `&analysis history=` and in HDF5) and the target quantities of a sweep.
!>
!> Plain constants, so that the kernels (pound_response, pound_influence, the analysis plan)
!> and the deck (pound_config, which names them too) share them without depending on each other.
module pound_quantities
   implicit none
   private

   public :: n_history_quantities, history_names, n_target_quantities, target_names, q_column_shear, q_column_moment
   public :: q_ductility

   !> Number of history quantities that can be stored.
   integer, parameter :: n_history_quantities = 5
   !> Names of the history quantities, as written in `&analysis history=` and in HDF5.
   character(len=*), parameter :: history_names(n_history_quantities) = &
      [character(len=12) :: 'u', 'v', 'a_abs', 'drift', 'storey_shear']

   !> Number of quantities a sweep's target can apply to: the history quantities, then the
   !> column-segment quantities of frames (`q_column_shear`, `q_column_moment`), the peak
   !> ductility of bilinear storeys (`q_ductility`).
   integer, parameter :: n_target_quantities = n_history_quantities + 3
   !> Index of the largest |lambda| of a column segment's shear among the target quantities.
   integer, parameter :: q_column_shear = n_history_quantities + 1
   !> Index of the largest |lambda| of a column segment's end moments (bottom and top).
   integer, parameter :: q_column_moment = n_history_quantities + 2
   !> Index of the largest |lambda| of the storeys' peak ductility (bilinear storeys).
   integer, parameter :: q_ductility = n_history_quantities + 3
   !> Names of the target quantities, as written in `&sweep target_quantities` and in HDF5.
   character(len=*), parameter :: target_names(n_target_quantities) = &
      [character(len=13) :: history_names, 'column_shear', 'column_moment', 'ductility']

end module pound_quantities
