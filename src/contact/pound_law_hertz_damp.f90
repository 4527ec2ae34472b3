!> The `hertz_damp` joint law: Hertz with nonlinear damping (Muthukumar & DesRoches 2006 with Ye, Li
!> & Zhu 2009's constant), r = max(0, kh d^(3/2) (1 + a d'/v0)) while d > 0,
!> a = 8 (1 - e)/(5 e), v0 the closing speed latched at the impact's start.
!> One module of the smooth laws (pound_law_smooth; solved exactly per step by
!> pound_contact_smooth).
module pound_law_hertz_damp
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_joint_law, only: law_input, law_variable
   use pound_contact_law, only: contact_law
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site
   use pound_law_smooth, only: smooth_law, make_smooth, smooth_take
   implicit none
   private

   public :: hertz_damp_law, hertz_damp_from_config, hertz_damp_take, hertz_damp_variables

   !> The `&contact` variables of law = 'hertz_damp' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: hertz_damp_variables(1) = [law_variable('stiffness', 'r', 0, 'kN/m^(3/2)')]

   !> The hertz_damp law.
   type, extends(smooth_law) :: hertz_damp_law
   contains
      !> f = kh d^(3/2) (1 + a d'/v0), a = 8 (1 - e)/(5 e).
      procedure :: force => hertz_damp_force
   end type hertz_damp_law

contains

   !> The law of a `&contact` group with law = 'hertz_damp'.
   pure subroutine hertz_damp_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_smooth(law, hertz_damp_law(), 'hertz_damp', c%stiffness, c%restitution, .true., error)
   end subroutine hertz_damp_from_config

   !> The deck's variables of law = 'hertz_damp'.
   pure subroutine hertz_damp_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call smooth_take(at, raw, cfg, 'hertz_damp', .true., .true., error)
   end subroutine hertz_damp_take

   !> f = kh d^(3/2) (1 + a d'/v0), a = 8 (1 - e)/(5 e).
   pure subroutine hertz_damp_force(law, d, ddot, v0, f, df_dd, df_dv, defined)
      class(hertz_damp_law), intent(in) :: law
      real(dp), intent(in) :: d, ddot, v0
      real(dp), intent(out) :: f, df_dd, df_dv
      logical, intent(out) :: defined
      real(dp) :: a, s

      a = 8.0_dp*(1.0_dp - law%e)/(5.0_dp*law%e)
      s = law%k*d*sqrt(d)
      f = s*(1.0_dp + a*ddot/v0)
      df_dd = 1.5_dp*law%k*sqrt(d)*(1.0_dp + a*ddot/v0)
      df_dv = s*a/v0
      defined = .true.
   end subroutine hertz_damp_force

end module pound_law_hertz_damp
