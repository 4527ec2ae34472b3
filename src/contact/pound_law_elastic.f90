!> The `elastic` joint law: a compression-only spring r = k0 d (with the joint's dashpot in
!> parallel), no yield nodes. One module of the piecewise-linear family (pound_joint_law).
module pound_law_elastic
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_envelope_rules, only: check_law_constants
   use pound_joint_law, only: joint_law, law_text, law_input, law_variable, dashpot_variables
   use pound_contact_law, only: contact_law
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site, require_real, check_real
   implicit none
   private

   public :: elastic_law, make_elastic, elastic_from_config, elastic_take, take_stiffness, elastic_variables

   !> The `&contact` variables of law = 'elastic' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: elastic_variables(3) = [law_variable('stiffness', 'r', 0, 'kN/m'), dashpot_variables]

   !> The elastic law (k0 alone: nothing of its own to list).
   type, extends(joint_law) :: elastic_law
   contains
      !> 'elastic'.
      procedure :: name => elastic_name
      !> No lines.
      procedure :: describe => elastic_describe
   end type elastic_law

contains

   !> Elastic law r = k0 d.
   pure subroutine make_elastic(law, k0, dashpot, error)
      !> The law.
      type(contact_law), intent(out) :: law
      !> Stiffness k0 (kN/m), > 0.
      real(dp), intent(in) :: k0
      !> Dashpot c (kN s/m), >= 0.
      real(dp), intent(in) :: dashpot
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call check_law_constants(k0, dashpot, error)
      if (allocated(error)) return
      allocate (law%given, source=elastic_law())
      law%stiffness = k0
      law%dashpot = dashpot
      law%env_d = [real(dp) ::]
      law%env_r = [real(dp) ::]
      law%tail_slope = k0
      law%yp = [real(dp) ::]
      law%yr = [real(dp) ::]
      law%yh = [real(dp) ::]
   end subroutine make_elastic

   !> The law of a `&contact` group with law = 'elastic' (`stiffness`, `dashpot`).
   pure subroutine elastic_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_elastic(law, c%stiffness, c%dashpot, error)
   end subroutine elastic_from_config

   !> The deck's `stiffness` (required, > 0) into the group's configuration.
   pure subroutine take_stiffness(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call require_real(at, 'stiffness', raw%stiffness, 'joint stiffness k0 in kN/m', error)
      if (allocated(error)) return
      call check_real(at, 'stiffness', raw%stiffness, '>', 0.0_dp, error)
      if (allocated(error)) return
      cfg%stiffness = raw%stiffness
   end subroutine take_stiffness

   !> The deck's variables of law = 'elastic' (`stiffness`).
   pure subroutine elastic_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call take_stiffness(at, raw, cfg, error)
   end subroutine elastic_take

   pure function elastic_name(law) result(name)
      class(elastic_law), intent(in) :: law
      character(len=:), allocatable :: name

      associate (unused => law)
      end associate

      name = 'elastic'
   end function elastic_name

   pure function elastic_describe(law) result(lines)
      class(elastic_law), intent(in) :: law
      type(law_text), allocatable :: lines(:)

      associate (unused => law)
      end associate

      allocate (lines(0))
   end function elastic_describe

end module pound_law_elastic
