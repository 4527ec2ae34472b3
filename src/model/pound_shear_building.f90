!> Shear building model: rigid beams, one lateral degree of freedom per floor.
!>
!> Floor i (1 = lowest) carries the lumped mass m_i; storey j joins floor j-1 and floor j
!> (floor 0 is the ground). First-order stiffness K and, where the deck asks for P-Delta,
!> the constant geometric stiffness G with storey term -P_j/h_j (P_j = gravity load at and
!> above floor j) are assembled in LAPACK upper band storage with kd = 1. The lowest natural
!> periods (those the listing shows and the two Rayleigh modes) come from the banded
!> generalized eigenproblem (K+G) phi = omega^2 M phi (dsbgvx, eigenvalues il..iu only), and
!> Rayleigh damping C = a0 M + a1 (K+G) is fitted at two chosen modes.
module pound_shear_building
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_constants, only: pi
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_plausibility, only: buckling_hint
   use pound_building_spec, only: building_spec
   use pound_storey_properties, only: storey_properties
   use pound_band, only: band_add_storey
   use pound_band_lapack, only: dsbgvx, dlamch
   use pound_sort, only: sort_ascending
   use pound_structure, only: structure_model, structure_label, chain_rows, structure_finish, modes_listed
   implicit none
   private

   public :: shear_building, build_shear_building, rayleigh_coefficients, building_label

   !> `&building #k (name)` when the occurrence is known, else `building name`.
   interface building_label
      module procedure structure_label
   end interface building_label


   !> A shear building ready for time integration: the structural model (kd = 1, floor i
   !> on DOF i, every DOF moved by the ground) and its storey table for the writers.
   type, extends(structure_model) :: shear_building
      !> Storey heights (m).
      real(dp), allocatable :: height(:)
      !> First-order storey stiffness k_j (kN/m).
      real(dp), allocatable :: storey_stiffness(:)
      !> Geometric storey stiffness P_j/h_j (kN/m), subtracted from k_j; zero without P-Delta.
      real(dp), allocatable :: geometric_stiffness(:)
      !> Storey axial (gravity) load P_j (kN); zero without P-Delta.
      real(dp), allocatable :: axial_load(:)
      !> Whether P-Delta is modelled.
      logical :: p_delta = .false.
   end type shear_building

contains

   !> Build the model of one building from its deck entry.
   !>
   !> Fails if K+G is not positive definite: the building buckles under its own gravity
   !> loads (the message names the storey and its load ratio theta_j = P_j / (h_j k_j)).
   !>
   !> Every derived quantity is checked where it is computed (masses, storey stiffnesses,
   !> axial loads, P/h, the entries of K+G, the frequencies and the Rayleigh coefficients):
   !> a value that is not finite (or not positive where it must be) fails with a message
   !> naming the building, the storey or floor and the deck variables it came from, before
   !> any solver sees it.
   subroutine build_shear_building(deck_entry, b, error, number)
      !> Validated deck entry (values as given; masses, stiffnesses and loads derived here).
      type(building_spec), intent(in) :: deck_entry
      !> The model.
      type(shear_building), intent(out) :: b
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Occurrence of the `&building` group in the deck, for messages.
      integer, intent(in), optional :: number
      integer :: n, j, jmax
      real(dp) :: theta, theta_max
      type(building_spec) :: cfg

      cfg = storey_properties(deck_entry)
      n = cfg%n_storeys
      b%name = cfg%name
      if (present(number)) b%number = number
      b%n = n
      call check_inputs(cfg, b, error)
      if (allocated(error)) return
      b%height = cfg%height
      b%mass = cfg%mass
      b%storey_stiffness = cfg%stiffness
      b%p_delta = cfg%p_delta
      b%damping_ratio = cfg%damping_ratio
      b%damping_modes = cfg%damping_modes
      allocate (b%axial_load(n), b%geometric_stiffness(n))
      b%axial_load = 0.0_dp
      b%geometric_stiffness = 0.0_dp
      if (b%p_delta) then
         b%axial_load(n) = cfg%gravity_load(n)
         do j = n - 1, 1, -1
            b%axial_load(j) = b%axial_load(j + 1) + cfg%gravity_load(j)
         end do
         b%geometric_stiffness = b%axial_load/b%height
         do j = 1, n
            if (.not. ieee_is_finite(b%axial_load(j))) then
               call not_finite(error, b, 'storey '//str(j)//': axial load P (the gravity loads at and above '// &
                               'floor '//str(j)//') from gravity_load', b%axial_load(j))
               return
            end if
            if (.not. ieee_is_finite(b%geometric_stiffness(j))) then
               call not_finite(error, b, 'storey '//str(j)//': geometric stiffness P/h from gravity_load, '// &
                               'height', b%geometric_stiffness(j))
               return
            end if
         end do
      end if

      ! Stability under gravity: K+G = D^T diag(k_j - P_j/h_j) D with D the (invertible)
      ! drift operator, so it is positive definite iff every storey keeps k_j > P_j/h_j.
      theta_max = -1.0_dp
      jmax = 0
      do j = 1, n
         theta = b%geometric_stiffness(j)/b%storey_stiffness(j)
         if (theta > theta_max) then
            theta_max = theta
            jmax = j
         end if
      end do
      if (theta_max >= 1.0_dp - 1.0e-12_dp) then
         call fatal_error(error, 'building '//b%name//': buckles under its own gravity loads '// &
                          '(K+G not positive definite) at storey '//str(jmax)//': P/h = '// &
                          str(b%geometric_stiffness(jmax))//' kN/m >= k = '//str(b%storey_stiffness(jmax))// &
                          ' kN/m, load ratio P/(h k) = '//str(theta_max)//buckling_hint)
         return
      end if

      allocate (b%kt(2, n))
      b%kt = 0.0_dp
      do j = 1, n
         call band_add_storey(b%kt, j, b%storey_stiffness(j) - b%geometric_stiffness(j))
      end do
      do j = 1, n
         if (.not. (ieee_is_finite(b%kt(1, j)) .and. ieee_is_finite(b%kt(2, j)))) then
            call not_finite(error, b, 'floor '//str(j)//': stiffness matrix entry K+G (k - P/h of the '// &
                            'storeys below and above) from '//origin(cfg, 'stiffness')//trim(merge( &
                            ', height, gravity_load', '                      ', b%p_delta)), &
                            merge(b%kt(1, j), b%kt(2, j), .not. ieee_is_finite(b%kt(1, j))))
            return
         end if
      end do

      call natural_frequencies(b, cfg, error)
      if (allocated(error)) return
      call rayleigh_coefficients(b%omega, b%damping_ratio, b%damping_modes, b%a0, b%a1)
      b%kd = 1
      b%ground = [(1.0_dp, j=1, n)]
      b%floor_dof = [(j, j=1, n)]
      call chain_rows(b%floor_dof, b%storey_stiffness, b%drift, b%shear)
      b%strain_weight = b%storey_stiffness - b%geometric_stiffness
      call structure_finish(b)
      if (.not. (ieee_is_finite(b%a0) .and. ieee_is_finite(b%a1))) then
         call fatal_error(error, building_label(b)//': Rayleigh coefficients a0 = '//str(b%a0)//', a1 = '// &
                          str(b%a1)//' from damping_ratio, damping_modes and the natural frequencies ('// &
                          'mass, '//origin(cfg, 'stiffness')//') are not finite')
      end if
   end subroutine build_shear_building

   !> The deck variables the storey stiffnesses (`what` = 'stiffness') or the floor masses
   !> (`what` = 'mass') come from, as recorded by the reader.
   pure function origin(cfg, what) result(s)
      type(building_spec), intent(in) :: cfg
      character(len=*), intent(in) :: what
      character(len=:), allocatable :: s

      s = what
      if (what == 'mass' .and. allocated(cfg%mass_source)) then
         if (cfg%mass_source == 'load_coeff') s = 'load_coeff, ref_floor_load'
      else if (what == 'stiffness' .and. allocated(cfg%stiffness_source)) then
         if (cfg%stiffness_source == 'columns') s = 'n_columns, e_modulus, inertia, height'
      end if
   end function origin

   !> Error: `what` (a derived quantity and the deck variables it came from) is `x`, not finite.
   pure subroutine not_finite(error, b, what, x)
      type(error_type), allocatable, intent(out) :: error
      type(shear_building), intent(in) :: b
      character(len=*), intent(in) :: what
      real(dp), intent(in) :: x

      call fatal_error(error, building_label(b)//': '//what//' is not finite ('//str(x)//')')
   end subroutine not_finite

   !> The storey and floor data as derived by the reader: masses positive and finite,
   !> stiffnesses positive and finite, gravity loads finite.
   pure subroutine check_inputs(cfg, b, error)
      type(building_spec), intent(in) :: cfg
      type(shear_building), intent(in) :: b
      type(error_type), allocatable, intent(out) :: error
      integer :: j

      do j = 1, cfg%n_storeys
         if (.not. (cfg%mass(j) > 0.0_dp .and. ieee_is_finite(cfg%mass(j)))) then
            call fatal_error(error, building_label(b)//': floor '//str(j)//': mass from '//origin(cfg, 'mass')// &
                             ' is not positive and finite ('//str(cfg%mass(j))//' t)')
            return
         end if
         if (.not. (cfg%stiffness(j) > 0.0_dp .and. ieee_is_finite(cfg%stiffness(j)))) then
            if (origin(cfg, 'stiffness') == 'stiffness') then
               call fatal_error(error, building_label(b)//': storey '//str(j)//': stiffness is not '// &
                                'positive and finite ('//str(cfg%stiffness(j))//' kN/m)')
            else
               call fatal_error(error, building_label(b)//': storey '//str(j)//': stiffness n_columns '// &
                                '12 E I / h^3 (3 E I / h^3 fixed-pinned) from n_columns, e_modulus, inertia, '// &
                                'height is not positive and finite ('//str(cfg%stiffness(j))//' kN/m)')
            end if
            return
         end if
         if (cfg%p_delta) then
            if (.not. ieee_is_finite(cfg%gravity_load(j))) then
               call fatal_error(error, building_label(b)//': floor '//str(j)//': gravity_load (default: '// &
                                'the floor load from '//origin(cfg, 'mass')//') is not finite ('// &
                                str(cfg%gravity_load(j))//' kN)')
               return
            end if
         end if
      end do
   end subroutine check_inputs

   !> The lowest natural frequencies from the banded generalized eigenproblem (K+G, M) by
   !> dsbgvx: modes 1 .. min(n, max(modes_listed, damping modes)). With every mode wanted
   !> dsbgvx takes the same path as dsbgv (QL on the tridiagonal form, dsterf); with fewer it
   !> bisects for the wanted ones only (dstebz, O(n) per eigenvalue instead of O(n^2) for all),
   !> to full relative precision (abstol = 2 x the safe minimum).
   !>
   !> Guarded: the largest omega^2 is bounded by max_i sum_j |(K+G)_ij| / m_i (Gershgorin);
   !> if that bound overflows, or the frequencies come out zero (underflow) or not finite,
   !> the message names the masses and stiffnesses instead of the solver.
   subroutine natural_frequencies(b, cfg, error)
      type(shear_building), intent(inout) :: b
      type(building_spec), intent(in) :: cfg
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: ab(:, :), bb(:, :), w(:), work(:)
      integer, allocatable :: iwork(:), ifail(:)
      real(dp) :: z(1, 1), q(1, 1), bound
      integer :: info, i, stat, m, n_wanted
      character(len=:), allocatable :: sources

      sources = 'mass ('//origin(cfg, 'mass')//') and storey stiffness ('//origin(cfg, 'stiffness')//')'
      do i = 1, b%n
         bound = abs(b%kt(2, i))
         if (i > 1) bound = bound + abs(b%kt(1, i))
         if (i < b%n) bound = bound + abs(b%kt(1, i + 1))
         bound = bound/b%mass(i)
         if (.not. ieee_is_finite(bound)) then
            call fatal_error(error, building_label(b)//': floor '//str(i)//': the natural frequencies '// &
                             'overflow: (K+G)/M up to '//str(bound)//' 1/s^2 from '//sources)
            return
         end if
      end do
      n_wanted = min(b%n, max(modes_listed, maxval(b%damping_modes)))
      allocate (ab(2, b%n), bb(1, b%n), w(b%n), work(7*b%n), iwork(5*b%n), ifail(b%n), stat=stat)
      if (stat /= 0) then
         call fatal_error(error, building_label(b)//': cannot allocate the eigenvalue workspace ('// &
                          str(11*b%n)//' reals; n_storeys = '//str(b%n)//')')
         return
      end if
      ab = b%kt
      bb(1, :) = b%mass
      ! abstol <= 0 on the full range keeps dsbgv's path (dsterf); bisection gets 2 x safe minimum.
      call dsbgvx('N', 'I', 'U', b%n, 1, 0, ab, 2, bb, 1, q, 1, 0.0_dp, 0.0_dp, 1, n_wanted, &
                  merge(0.0_dp, 2.0_dp*dlamch('S'), n_wanted == b%n), m, w, z, 1, work, iwork, ifail, info)
      if (info /= 0 .or. m /= n_wanted) then
         call fatal_error(error, building_label(b)//': eigenvalue solver dsbgvx failed (info = '// &
                          str(info)//', '//str(m)//' of '//str(n_wanted)//' eigenvalues); check '//sources)
         return
      end if
      ! Without eigenvectors dsbgvx leaves them in order within each split-off block only.
      call sort_ascending(w(1:m))
      if (.not. (w(1) > 0.0_dp .and. ieee_is_finite(w(m)))) then
         call fatal_error(error, building_label(b)//': natural frequencies out of range (omega^2 from '// &
                          str(w(1))//' to '//str(w(m))//' 1/s^2) from '//sources)
         return
      end if
      b%omega = sqrt(w(1:m))
      b%period = 2.0_dp*pi/b%omega
      if (.not. (ieee_is_finite(b%period(1)) .and. b%period(m) > 0.0_dp)) then
         call fatal_error(error, building_label(b)//': natural periods out of range ('//str(b%period(m))// &
                          ' to '//str(b%period(1))//' s) from '//sources)
      end if
   end subroutine natural_frequencies

   !> Rayleigh coefficients giving damping ratio `zeta` at modes i and j.
   !>
   !> a0 = 2 zeta w_i w_j / (w_i + w_j), a1 = 2 zeta / (w_i + w_j). With one storey
   !> (i = j = 1) this gives a0 = zeta w, a1 = zeta / w: half mass-, half stiffness-proportional.
   pure subroutine rayleigh_coefficients(omega, zeta, modes, a0, a1)
      !> Circular frequencies, ascending.
      real(dp), intent(in) :: omega(:)
      !> Damping ratio.
      real(dp), intent(in) :: zeta
      !> The two modes to fit (equal when the building has one mode).
      integer, intent(in) :: modes(2)
      !> Mass-proportional coefficient (1/s).
      real(dp), intent(out) :: a0
      !> Stiffness-proportional coefficient (s).
      real(dp), intent(out) :: a1
      real(dp) :: wi, wj

      wi = omega(min(modes(1), size(omega)))
      wj = omega(min(modes(2), size(omega)))
      a0 = 2.0_dp*zeta*wi*wj/(wi + wj)
      a1 = 2.0_dp*zeta/(wi + wj)
   end subroutine rayleigh_coefficients

end module pound_shear_building
