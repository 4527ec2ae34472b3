!> Storey and floor properties of a shear building from the deck's values as given: the
!> engineering derivations the deck reader does not make.
!>
!> | property | from |
!> |---|---|
!> | floor mass m_i | `mass`, or `load_coeff` a_i times `ref_floor_load` m0 g, divided by g = 9.81 m/s^2 |
!> | storey stiffness k_j | `stiffness`, or n_columns c E I / h^3 of the columns (rigid beams; c = 12 fixed-fixed, 3 fixed-pinned) |
!> | floor gravity load | `gravity_load`, or the floor's weight: m_i g (`mass`) or a_i m0 g (`load_coeff`) |
!>
!> The values are not checked here: build_shear_building checks every one where it uses it,
!> naming the deck variables it came from (`mass_source`, `stiffness_source`).
module pound_storey_properties
   use pound_kinds, only: dp
   use pound_building_spec, only: building_spec
   use pound_constants, only: g_accel
   implicit none
   private

   public :: storey_properties, column_factor

contains

   !> The building entry with `mass`, `stiffness` and `gravity_load` all present: those the
   !> deck gave are kept, the others derived (see the module notes).
   pure function storey_properties(cfg) result(full)
      !> Validated deck entry, values as given.
      type(building_spec), intent(in) :: cfg
      type(building_spec) :: full
      real(dp), allocatable :: weight(:)

      full = cfg
      if (allocated(cfg%mass)) then
         weight = cfg%mass*g_accel
      else if (allocated(cfg%load_coeff)) then
         weight = cfg%load_coeff*cfg%ref_floor_load
         full%mass = weight/g_accel
      end if
      if (.not. allocated(cfg%gravity_load) .and. allocated(weight)) full%gravity_load = weight
      if (.not. allocated(cfg%stiffness) .and. allocated(cfg%n_columns) .and. allocated(cfg%e_modulus) &
          .and. allocated(cfg%inertia) .and. allocated(cfg%height)) then
         full%stiffness = real(cfg%n_columns, dp)*column_factor(cfg%column_ends)*cfg%e_modulus* &
                          cfg%inertia/cfg%height**3
      end if
   end function storey_properties

   !> The factor c of a column's lateral stiffness c E I / h^3 between rigid beams: 12 for
   !> 'fixed-fixed' (also when not given), 3 for 'fixed-pinned'.
   pure function column_factor(column_ends) result(factor)
      !> End conditions as validated by the reader (may be unallocated).
      character(len=:), allocatable, intent(in) :: column_ends
      real(dp) :: factor

      factor = 12.0_dp
      if (allocated(column_ends)) then
         if (column_ends == 'fixed-pinned') factor = 3.0_dp
      end if
   end function column_factor

end module pound_storey_properties
