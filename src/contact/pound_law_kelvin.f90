!> The `kelvin` joint law: the Kelvin-Voigt impact element (Anagnostopoulos 1988),
!> r = max(0, k d + c d') while d > 0, c = 2 xi sqrt(k m_eff),
!> xi = -ln e / sqrt(pi^2 + ln^2 e).
!> One module of the smooth laws (pound_law_smooth; solved exactly per step by
!> pound_contact_smooth).
module pound_law_kelvin
   use pound_kinds, only: dp
   use pound_constants, only: pi
   use pound_error, only: error_type
   use pound_joint_law, only: law_input, law_variable
   use pound_contact_law, only: contact_law
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site
   use pound_law_smooth, only: smooth_law, make_smooth, smooth_take
   implicit none
   private

   public :: kelvin_law, kelvin_from_config, kelvin_take, kelvin_variables

   !> The `&contact` variables of law = 'kelvin' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: kelvin_variables(1) = [law_variable('stiffness', 'r', 0, 'kN/m')]

   !> The kelvin law.
   type, extends(smooth_law) :: kelvin_law
   contains
      !> f = k d + c d', c = 2 xi sqrt(k m_eff) (no mass known: c = 0).
      procedure :: force => kelvin_force
      !> kN/m.
      procedure :: stiffness_unit => kelvin_stiffness_unit
   end type kelvin_law

contains

   !> The law of a `&contact` group with law = 'kelvin'.
   pure subroutine kelvin_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_smooth(law, kelvin_law(), 'kelvin', c%stiffness, c%restitution, .true., error)
   end subroutine kelvin_from_config

   !> The deck's variables of law = 'kelvin'.
   pure subroutine kelvin_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call smooth_take(at, raw, cfg, 'kelvin', .false., .true., error)
   end subroutine kelvin_take

   !> f = k d + c d', c = 2 xi sqrt(k m_eff) (no mass known: c = 0).
   pure subroutine kelvin_force(law, d, ddot, v0, f, df_dd, df_dv, defined)
      class(kelvin_law), intent(in) :: law
      real(dp), intent(in) :: d, ddot, v0
      real(dp), intent(out) :: f, df_dd, df_dv
      logical, intent(out) :: defined
      real(dp) :: xi, c

      associate (unused => v0)
      end associate
      xi = -log(law%e)/sqrt(pi**2 + log(law%e)**2)
      c = 2.0_dp*xi*sqrt(law%k*law%meff)
      f = law%k*d + c*ddot
      df_dd = law%k
      df_dv = c
      defined = .true.
   end subroutine kelvin_force

   pure function kelvin_stiffness_unit(law) result(u)
      class(kelvin_law), intent(in) :: law
      character(len=:), allocatable :: u

      associate (unused => law)
      end associate
      u = 'kN/m'
   end function kelvin_stiffness_unit

end module pound_law_kelvin
