!> The `jankowski` joint law: Jankowski's nonlinear viscoelastic impact (2005, 2006),
!> r = beta d^(3/2) + c d' while d' > 0, r = beta d^(3/2) while d' <= 0, c = 2 xi
!> sqrt(beta sqrt(d) m_eff), xi = 9 sqrt(5) (1 - e^2)/(2 e (e (9 pi - 16) + 16)).
!> One module of the smooth laws (pound_law_smooth; solved exactly per step by
!> pound_contact_smooth).
module pound_law_jankowski
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

   public :: jankowski_law, jankowski_from_config, jankowski_take, jankowski_variables

   !> The `&contact` variables of law = 'jankowski' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: jankowski_variables(1) = [law_variable('stiffness', 'r', 0, 'kN/m^(3/2)')]

   !> The jankowski law.
   type, extends(smooth_law) :: jankowski_law
   contains
      !> f = beta d^(3/2) + c d' (d' > 0), c = 2 xi sqrt(beta sqrt(d) m_eff).
      procedure :: force => jankowski_force
   end type jankowski_law

contains

   !> The law of a `&contact` group with law = 'jankowski'.
   pure subroutine jankowski_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_smooth(law, jankowski_law(), 'jankowski', c%stiffness, c%restitution, .true., error)
   end subroutine jankowski_from_config

   !> The deck's variables of law = 'jankowski'.
   pure subroutine jankowski_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call smooth_take(at, raw, cfg, 'jankowski', .true., .true., error)
   end subroutine jankowski_take

   !> f = beta d^(3/2) + c d' (d' > 0), c = 2 xi sqrt(beta sqrt(d) m_eff).
   pure subroutine jankowski_force(law, d, ddot, v0, f, df_dd, df_dv, defined)
      class(jankowski_law), intent(in) :: law
      real(dp), intent(in) :: d, ddot, v0
      real(dp), intent(out) :: f, df_dd, df_dv
      logical, intent(out) :: defined
      real(dp) :: xi, c, e

      associate (unused => v0)
      end associate
      e = law%e
      f = law%k*d*sqrt(d)
      df_dd = 1.5_dp*law%k*sqrt(d)
      df_dv = 0.0_dp
      defined = .true.
      if (.not. (ddot > 0.0_dp .and. d > 0.0_dp)) return
      xi = 9.0_dp*sqrt(5.0_dp)*(1.0_dp - e*e)/(2.0_dp*e*(e*(9.0_dp*pi - 16.0_dp) + 16.0_dp))
      c = 2.0_dp*xi*sqrt(law%k*sqrt(d)*law%meff)
      f = f + c*ddot
      df_dd = df_dd + 0.25_dp*c/d*ddot
      df_dv = c
   end subroutine jankowski_force

end module pound_law_jankowski
