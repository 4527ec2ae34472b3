!> Shear building model: rigid beams, one lateral degree of freedom per floor.
!>
!> Floor i (1 = lowest) carries the lumped mass m_i; storey j joins floor j-1 and floor j
!> (floor 0 is the ground). First-order stiffness K and, where the deck asks for P-Delta,
!> the constant geometric stiffness G with storey term -P_j/h_j (P_j = gravity load at and
!> above floor j) are assembled in LAPACK upper band storage with kd = 1. The natural
!> periods come from the banded generalized eigenproblem (K+G) phi = omega^2 M phi (dsbgv),
!> and Rayleigh damping C = a0 M + a1 (K+G) is fitted at two chosen modes.
module pound_shear_building
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_config, only: building_config
   use pound_band, only: band_add_storey
   implicit none
   private

   public :: shear_building, build_shear_building, rayleigh_coefficients

   real(dp), parameter :: pi = acos(-1.0_dp)

   !> A shear building ready for time integration.
   type :: shear_building
      !> Name (from the deck).
      character(len=:), allocatable :: name
      !> Number of floors = number of storeys.
      integer :: n = 0
      !> Storey heights (m).
      real(dp), allocatable :: height(:)
      !> Floor masses (t).
      real(dp), allocatable :: mass(:)
      !> First-order storey stiffness k_j (kN/m).
      real(dp), allocatable :: storey_stiffness(:)
      !> Geometric storey stiffness P_j/h_j (kN/m), subtracted from k_j; zero without P-Delta.
      real(dp), allocatable :: geometric_stiffness(:)
      !> Storey axial (gravity) load P_j (kN); zero without P-Delta.
      real(dp), allocatable :: axial_load(:)
      !> Whether P-Delta is modelled.
      logical :: p_delta = .false.
      !> Tangent stiffness K+G in upper band storage, shape (2, n).
      real(dp), allocatable :: kt(:, :)
      !> Circular natural frequencies (rad/s), ascending.
      real(dp), allocatable :: omega(:)
      !> Natural periods (s), descending.
      real(dp), allocatable :: period(:)
      !> Damping ratio and the modes it is fitted at.
      real(dp) :: damping_ratio = 0.0_dp
      integer :: damping_modes(2) = [1, 2]
      !> Rayleigh coefficients: C = a0 M + a1 (K+G).
      real(dp) :: a0 = 0.0_dp, a1 = 0.0_dp
   end type shear_building

   interface
      subroutine dsbgv(jobz, uplo, n, ka, kb, ab, ldab, bb, ldbb, w, z, ldz, work, info)
         import :: dp
         character, intent(in) :: jobz, uplo
         integer, intent(in) :: n, ka, kb, ldab, ldbb, ldz
         real(dp), intent(inout) :: ab(ldab, *), bb(ldbb, *)
         real(dp), intent(out) :: w(*), z(ldz, *), work(*)
         integer, intent(out) :: info
      end subroutine dsbgv
   end interface

contains

   !> Build the model of one building from its deck entry.
   !>
   !> Fails if K+G is not positive definite: the building buckles under its own gravity
   !> loads (the message names the storey and its load ratio theta_j = P_j / (h_j k_j)).
   subroutine build_shear_building(cfg, b, error)
      !> Validated deck entry.
      type(building_config), intent(in) :: cfg
      !> The model.
      type(shear_building), intent(out) :: b
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: n, j, jmax
      real(dp) :: theta, theta_max

      n = cfg%n_storeys
      b%name = cfg%name
      b%n = n
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
                          ' kN/m, load ratio P/(h k) = '//str(theta_max))
         return
      end if

      allocate (b%kt(2, n))
      b%kt = 0.0_dp
      do j = 1, n
         call band_add_storey(b%kt, j, b%storey_stiffness(j) - b%geometric_stiffness(j))
      end do

      call natural_frequencies(b, error)
      if (allocated(error)) return
      call rayleigh_coefficients(b%omega, b%damping_ratio, b%damping_modes, b%a0, b%a1)
   end subroutine build_shear_building

   !> Natural frequencies from the banded generalized eigenproblem (K+G, M) by dsbgv.
   subroutine natural_frequencies(b, error)
      type(shear_building), intent(inout) :: b
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: ab(:, :), bb(:, :), w(:), work(:)
      real(dp) :: z(1, 1)
      integer :: info

      allocate (ab(2, b%n), bb(1, b%n), w(b%n), work(3*b%n))
      ab = b%kt
      bb(1, :) = b%mass
      call dsbgv('N', 'U', b%n, 1, 0, ab, 2, bb, 1, w, z, 1, work, info)
      if (info /= 0 .or. any(w <= 0.0_dp)) then
         call fatal_error(error, 'building '//b%name//': eigenvalue solver dsbgv failed (info = '// &
                          str(info)//')')
         return
      end if
      b%omega = sqrt(w)
      b%period = 2.0_dp*pi/b%omega
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
