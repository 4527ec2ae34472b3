!> The `hertz` joint law: Hertz's elastic contact, r = kh d^(3/2) while d > 0.
!> One module of the smooth laws (pound_law_smooth; solved exactly per step by
!> pound_contact_smooth).
module pound_law_hertz
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_joint_law, only: law_input, law_variable
   use pound_contact_law, only: contact_law
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site
   use pound_law_smooth, only: smooth_law, make_smooth, smooth_take
   implicit none
   private

   public :: hertz_law, hertz_from_config, hertz_take, hertz_variables

   !> The `&contact` variables of law = 'hertz' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: hertz_variables(1) = [law_variable('stiffness', 'r', 0, 'kN/m^(3/2)')]

   !> The hertz law.
   type, extends(smooth_law) :: hertz_law
   contains
      !> f = kh d^(3/2).
      procedure :: force => hertz_force
   end type hertz_law

contains

   !> The law of a `&contact` group with law = 'hertz'.
   pure subroutine hertz_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_smooth(law, hertz_law(), 'hertz', c%stiffness, c%restitution, .false., error)
   end subroutine hertz_from_config

   !> The deck's variables of law = 'hertz'.
   pure subroutine hertz_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call smooth_take(at, raw, cfg, 'hertz', .true., .false., error)
   end subroutine hertz_take

   !> f = kh d^(3/2).
   pure subroutine hertz_force(law, d, ddot, v0, f, df_dd, df_dv, defined)
      class(hertz_law), intent(in) :: law
      real(dp), intent(in) :: d, ddot, v0
      real(dp), intent(out) :: f, df_dd, df_dv
      logical, intent(out) :: defined

      associate (unused => [ddot, v0])
      end associate
      f = law%k*d*sqrt(d)
      df_dd = 1.5_dp*law%k*sqrt(d)
      df_dv = 0.0_dp
      defined = .true.
   end subroutine hertz_force

end module pound_law_hertz
