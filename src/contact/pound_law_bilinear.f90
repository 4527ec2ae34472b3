!> The `bilinear` and `elastic_plastic` joint laws: k0 up to the yield force, then a second
!> slope k2 < k0 of either sign (`elastic_plastic`: k2 = 0). One module of the
!> piecewise-linear family (pound_joint_law).
module pound_law_bilinear
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_envelope_rules, only: check_law_constants
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_joint_law, only: joint_law, law_text, law_input, add_line, law_variable, dashpot_variables
   use pound_contact_law, only: contact_law, compile_envelope
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site, require_real, check_real, check_plausible, fail
   use pound_law_elastic, only: take_stiffness
   implicit none
   private

   public :: bilinear_law, make_bilinear, make_elastic_plastic, bilinear_from_config, &
             elastic_plastic_from_config, bilinear_take, elastic_plastic_take, &
             elastic_plastic_variables, bilinear_variables

   !> The `&contact` variables of law = 'elastic_plastic' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: elastic_plastic_variables(4) = [law_variable('stiffness', 'r', 0, 'kN/m'), &
      law_variable('yield_force', 'r', 0, 'kN'), dashpot_variables]

   !> The `&contact` variables of law = 'bilinear' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: bilinear_variables(5) = [law_variable('stiffness', 'r', 0, 'kN/m'), &
      law_variable('yield_force', 'r', 0, 'kN'), law_variable('second_slope', 'r', 0, 'kN/m'), dashpot_variables]

   !> Bilinear law: its yield force and second slope as given.
   type, extends(joint_law) :: bilinear_law
      !> Yield force (kN) and second slope (kN/m).
      real(dp) :: yield_force = 0.0_dp, second_slope = 0.0_dp
      !> Given as `elastic_plastic` (second slope 0).
      logical :: perfectly_plastic = .false.
   contains
      !> 'bilinear' or 'elastic_plastic'.
      procedure :: name => bilinear_name
      !> The yield force (and the second slope).
      procedure :: describe => bilinear_describe
   end type bilinear_law

contains

   !> Elastic-perfectly-plastic: k0 up to the yield force, flat beyond.
   pure subroutine make_elastic_plastic(law, k0, fy, dashpot, error)
      !> The law.
      type(contact_law), intent(out) :: law
      !> Stiffness k0 (kN/m), > 0.
      real(dp), intent(in) :: k0
      !> Yield force (kN), > 0.
      real(dp), intent(in) :: fy
      !> Dashpot c (kN s/m), >= 0.
      real(dp), intent(in) :: dashpot
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_bilinear(law, k0, fy, 0.0_dp, dashpot, error)
      if (allocated(error)) return
      law%given = bilinear_law(yield_force=fy, second_slope=0.0_dp, perfectly_plastic=.true.)
   end subroutine make_elastic_plastic

   !> Bilinear: k0 up to the yield force, then the second slope k2 < k0 (either sign).
   pure subroutine make_bilinear(law, k0, fy, k2, dashpot, error)
      !> The law.
      type(contact_law), intent(out) :: law
      !> Stiffness k0 (kN/m), > 0.
      real(dp), intent(in) :: k0
      !> Yield force (kN), > 0.
      real(dp), intent(in) :: fy
      !> Second slope (kN/m), < k0.
      real(dp), intent(in) :: k2
      !> Dashpot c (kN s/m), >= 0.
      real(dp), intent(in) :: dashpot
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call check_law_constants(k0, dashpot, error)
      if (allocated(error)) return
      if (.not. (fy > 0.0_dp)) then
         call fatal_error(error, 'yield force must be > 0, got '//str(fy))
         return
      end if
      if (.not. (k2 < k0)) then
         call fatal_error(error, 'second slope '//str(k2)//' must be < the stiffness k0 = '//str(k0))
         return
      end if
      law%given = bilinear_law(yield_force=fy, second_slope=k2)
      law%stiffness = k0
      law%dashpot = dashpot
      call compile_envelope(law, [fy/k0], [fy], k2, 1)
   end subroutine make_bilinear

   !> The law of a `&contact` group with law = 'bilinear' (`stiffness`, `yield_force`,
   !> `second_slope`, `dashpot`).
   pure subroutine bilinear_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_bilinear(law, c%stiffness, c%yield_force, c%second_slope, c%dashpot, error)
   end subroutine bilinear_from_config

   !> The law of a `&contact` group with law = 'elastic_plastic' (`stiffness`, `yield_force`,
   !> `dashpot`).
   pure subroutine elastic_plastic_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_elastic_plastic(law, c%stiffness, c%yield_force, c%dashpot, error)
   end subroutine elastic_plastic_from_config

   !> The deck's variables of law = 'elastic_plastic' (`stiffness`, `yield_force` > 0).
   pure subroutine elastic_plastic_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call take_stiffness(at, raw, cfg, error)
      if (allocated(error)) return
      call require_real(at, 'yield_force', raw%yield_force, 'yield force in kN', error)
      if (allocated(error)) return
      call check_real(at, 'yield_force', raw%yield_force, '>', 0.0_dp, error)
      if (allocated(error)) return
      cfg%yield_force = raw%yield_force
   end subroutine elastic_plastic_take

   !> The deck's variables of law = 'bilinear' (those of `elastic_plastic` and
   !> `second_slope` < stiffness).
   pure subroutine bilinear_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      call elastic_plastic_take(at, raw, cfg, error)
      if (allocated(error)) return
      call require_real(at, 'second_slope', raw%second_slope, 'slope after yielding in kN/m, '// &
                        '< stiffness, negative for softening', error)
      if (allocated(error)) return
      if (.not. (raw%second_slope < raw%stiffness .and. ieee_is_finite(raw%second_slope))) then
         call fail(at, 'second_slope', 'second_slope = '//str(raw%second_slope)//', must be < '// &
                   'stiffness = '//str(raw%stiffness), error)
         return
      end if
      call check_plausible(at, 'second_slope', raw%second_slope, 'second_slope', error)
      if (allocated(error)) return
      cfg%second_slope = raw%second_slope
   end subroutine bilinear_take

   pure function bilinear_name(law) result(name)
      class(bilinear_law), intent(in) :: law
      character(len=:), allocatable :: name

      if (law%perfectly_plastic) then
         name = 'elastic_plastic'
      else
         name = 'bilinear'
      end if
   end function bilinear_name

   pure function bilinear_describe(law) result(lines)
      class(bilinear_law), intent(in) :: law
      type(law_text), allocatable :: lines(:)
      character(len=80) :: buf

      if (law%perfectly_plastic) then
         write (buf, '(a,es11.4,a)') 'yield force ', law%yield_force, ' kN'
      else
         write (buf, '(a,es11.4,a,es11.4,a)') 'yield force ', law%yield_force, ' kN, second slope ', &
            law%second_slope, ' kN/m'
      end if
      call add_line(lines, trim(buf))
   end function bilinear_describe

end module pound_law_bilinear
