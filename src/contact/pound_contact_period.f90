!> The contact half-period of a joint for the automatic substep count of `stepping = 'impact'`,
!> also where a joint end is a DOF without mass (a split column node of `&contact elevations`,
!> struck by a floor mid-storey).
!>
!> An end with a mass m is a mass on the contact spring k0: half = pi sqrt(m_eff/k0),
!> m_eff = m1 m2/(m1 + m2) (the mass of the one building against a rigid neighbour), as
!> before. An end at a DOF d without mass has no mass of its own: it is held by the
!> building's massless DOFs s (d among them) with the masses held, the point stiffness
!> k_p = 1/(K_ss^-1)_dd, and follows the massive DOFs statically by u_d = t^T u_m,
!> t = -(K_ss^-1 K_sm)^T e_d; the least kinetic energy of the masses that moves d by one,
!> min u_m^T M u_m s.t. t^T u_m = 1, is that of the mass m_d = 1/(t^T M_m^-1 t) (the mass of
!> the one floor d follows when t is a unit vector). The joint is then the chain m1 -- k0 --
!> [k_p] -- m2 with the springs of the massless ends in series: omega^2 = k (1/m1 + 1/m2),
!> 1/k = 1/k0 + sum 1/k_p, half = pi/omega.
module pound_contact_period
   use pound_kinds, only: dp
   use pound_constants, only: pi
   use pound_structure, only: structure_model
   use pound_contact_pair, only: contact_pair, end_mass
   use pound_band, only: band_symv
   use pound_band_lapack, only: dpbtrf, dpbtrs
   implicit none
   private

   public :: joint_half_period, massless_end, substep_impact_speed

   !> The approach speed (m/s) at which a smooth law's contact duration sets the impact-aware
   !> substep count: a fast pounding impact (the duration of a Hertz-type contact falls as
   !> v^(-1/5), so slower impacts are resolved better).
   real(dp), parameter :: substep_impact_speed = 1.0_dp

contains

   !> The mass of end e for the contact period: a contact point of buildings in plan takes the
   !> share of its floor's mass (`mass_dof`), as its law takes the share of the pair's (so two
   !> points give the pair's period); an end at one DOF its lumped mass; an end on a row of
   !> several DOFs the row's mass (`end_mass`).
   pure real(dp) function end_period_mass(p, e, mass) result(m)
      !> The constraint, its DOFs located.
      type(contact_pair), intent(in) :: p
      !> End: 1 or 2.
      integer, intent(in) :: e
      !> Lumped masses of the end's building (t).
      real(dp), intent(in) :: mass(:)

      if (p%mass_dof(e) > 0) then
         m = p%share*mass(p%mass_dof(e))
      else
         m = end_mass(p, e, mass)
      end if
   end function end_period_mass

   !> The contact half-period pi/omega of a joint (s), see the module doc (the facing floor
   !> masses' pi sqrt(m_eff/k0) when both ends have a mass).
   function joint_half_period(p, models) result(half)
      !> The constraint, its DOFs located.
      type(contact_pair), intent(in) :: p
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      real(dp) :: half
      real(dp) :: m(2), kp, minv, flex
      integer :: e

      m = 0.0_dp
      do e = 1, 2
         if (p%building(e) > 0) m(e) = end_period_mass(p, e, models(p%building(e))%mass)
      end do
      if (all(m > 0.0_dp .or. p%building <= 0)) then
         ! A smooth law: its contact duration at `substep_impact_speed` (pound_law_impact).
         if (smooth_duration(m(1), m(2), half)) return
         ! Both ends with a mass (or a rigid neighbour): the facing masses.
         if (m(1) > 0.0_dp .and. m(2) > 0.0_dp) then
            half = pi*sqrt(m(1)*m(2)/(m(1) + m(2))/p%law%stiffness)
         else
            half = pi*sqrt(max(m(1), m(2))/p%law%stiffness)
         end if
         return
      end if
      flex = 1.0_dp/p%law%stiffness
      minv = 0.0_dp
      do e = 1, 2
         if (p%building(e) <= 0) cycle
         if (m(e) > 0.0_dp) then
            minv = minv + 1.0_dp/m(e)
         else if (p%dof(e) > 0) then
            call massless_end(models(p%building(e)), p%dof(e), m(e), kp)
            flex = flex + 1.0_dp/kp
            if (m(e) > 0.0_dp) minv = minv + 1.0_dp/m(e)
         end if
      end do
      half = huge(1.0_dp)
      if (minv > 0.0_dp) then
         ! A smooth law: against the condensed masses (its ends' flexibility left out: a shorter
         ! contact, more substeps).
         if (smooth_duration(1.0_dp/minv, 0.0_dp, half)) return
         half = pi*sqrt(flex/minv)
      end if

   contains

      !> The contact duration of a smooth law between masses m1 and m2 (0: rigid) at
      !> `substep_impact_speed`; false for a law that is not smooth.
      logical function smooth_duration(m1, m2, t) result(smooth)
         real(dp), intent(in) :: m1, m2
         real(dp), intent(inout) :: t

         smooth = .false.
         if (.not. allocated(p%law%given)) return
         if (.not. p%law%given%has_force()) return
         t = p%law%given%contact_duration(m1, m2, substep_impact_speed)
         smooth = .true.
      end function smooth_duration
   end function joint_half_period

   !> The mass m_d and the point stiffness k_p of a DOF d without mass (see the module doc):
   !> K_ss^-1 e_d from the band of K+G with the massive DOFs held (their rows and columns
   !> replaced by the identity; one band factorisation), t from K_ms K_ss^-1 e_d.
   subroutine massless_end(b, d, md, kp)
      !> The structural model.
      type(structure_model), intent(in) :: b
      !> The DOF (mass 0).
      integer, intent(in) :: d
      !> Its mass m_d (t; 0 when it follows no mass) and point stiffness k_p (kN/m).
      real(dp), intent(out) :: md, kp
      real(dp), allocatable :: ab(:, :), x(:), y(:)
      real(dp) :: s
      integer :: i, j, kd, info

      kd = b%kd
      ab = b%kt
      do j = 1, b%n
         do i = max(1, j - kd), j
            if (b%mass(i) > 0.0_dp .or. b%mass(j) > 0.0_dp) ab(kd + 1 + i - j, j) = 0.0_dp
         end do
         if (b%mass(j) > 0.0_dp) ab(kd + 1, j) = 1.0_dp
      end do
      allocate (x(b%n), y(b%n))
      x = 0.0_dp
      x(d) = 1.0_dp
      call dpbtrf('U', b%n, kd, ab, kd + 1, info)
      if (info /= 0) then
         md = 0.0_dp
         kp = huge(1.0_dp)
         return
      end if
      call dpbtrs('U', b%n, kd, 1, ab, kd + 1, x, b%n, info)
      kp = 1.0_dp/x(d)
      where (b%mass > 0.0_dp) x = 0.0_dp
      call band_symv(b%kt, x, y)
      s = 0.0_dp
      do i = 1, b%n
         if (b%mass(i) > 0.0_dp) s = s + y(i)**2/b%mass(i)
      end do
      md = 0.0_dp
      if (s > 0.0_dp) md = 1.0_dp/s
   end subroutine massless_end

end module pound_contact_period
