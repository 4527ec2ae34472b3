!> What the smooth joint laws of the pounding literature share (`kelvin`, `hertz`,
!> `hertz_damp`, `jankowski`; one module each, pound_law_<name>): an extension of
!> `joint_law` with a force of its own, f(d, d'; v0), clipped to r = max(0, f) while the
!> penetration d = v - gap > 0 and r = 0 at d <= 0. The step solves them exactly (Newton on
!> the tangent rows of the step's LCP, pound_contact_smooth); the rows (`contact_law`) carry
!> only the tangent of the current iterate, no dashpot and no yield rows.
!>
!> Here: the abstract type (stiffness, restitution, effective mass of the facing ends), the
!> rows a smooth law starts with (`make_smooth`), the deck reader of `stiffness` and
!> `restitution` (`smooth_take`, with the plausible range of a Hertz-type stiffness), and the
!> listing lines with the realised restitution of the joint's calibration (`law_impact`).
module pound_law_smooth
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_joint_law, only: joint_law, law_text, law_input, add_line
   use pound_contact_law, only: contact_law
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site, require_real, check_real, fail, is_set
   use pound_law_impact, only: law_impact, impact_result, typical_impact_speed, pair_mass
   implicit none
   private

   public :: smooth_law, make_smooth, smooth_take, hertz_stiffness_range

   !> Plausible range of a Hertz-type stiffness kh, beta (kN/m^(3/2)): outside it the deck
   !> is refused (the literature's values for concrete floors: about 1e6 to 1e9).
   real(dp), parameter :: hertz_stiffness_range(2) = [1.0e3_dp, 1.0e10_dp]

   !> A smooth joint law.
   type, abstract, extends(joint_law) :: smooth_law
      !> The law's stiffness as given: k (kN/m) or kh, beta (kN/m^(3/2)).
      real(dp) :: k = 0.0_dp
      !> Coefficient of restitution of the calibration (0: none, `hertz`).
      real(dp) :: e = 0.0_dp
      !> Masses of the facing ends (t; 0: rigid or not known), m_eff = m1 m2/(m1 + m2).
      real(dp) :: m1 = 0.0_dp, m2 = 0.0_dp, meff = 0.0_dp
      !> Its deck name.
      character(len=16) :: deck_name = ''
      !> The central impact of its calibration (`law_impact` of the facing masses, unit masses
      !> where none are known, at `typical_impact_speed`), computed once when the masses are
      !> set (`set_masses`); `impact_known` false before.
      type(impact_result) :: impact
      logical :: impact_known = .false.
      !> Trial state of a step: the slope of the row at the current iterate (kN/m), while
      !> `in_trial`; committed, the row's slope is `k`.
      real(dp) :: k_trial = 0.0_dp
      logical :: in_trial = .false.
   contains
      !> The deck name.
      procedure :: name => smooth_name
      !> Solved by Newton (pound_contact_smooth).
      procedure :: iterates => smooth_iterates
      !> The facing masses (the calibration of the damping, the realised restitution).
      procedure :: set_masses => smooth_set_masses
      !> The stiffness as given.
      procedure :: shown_stiffness => smooth_shown_stiffness
      !> Listing lines: the stiffness, restitution and the realised restitution.
      procedure :: describe => smooth_describe
      !> The unit of the stiffness as given.
      procedure :: stiffness_unit => smooth_stiffness_unit
      !> A force of its own.
      procedure :: has_force => smooth_has_force
      !> The contact duration of a central impact (`law_impact`).
      procedure :: contact_duration => smooth_contact_duration
      !> The realised restitution of its calibration (stored by `set_masses`).
      procedure :: realised_restitution => smooth_realised_restitution
      !> The row's slope at the step's current iterate.
      procedure :: set_trial => smooth_set_trial
      !> Back to the committed row (slope k).
      procedure :: commit => smooth_commit_state
      !> The trial slope during a step, else k.
      procedure :: row_stiffness => smooth_row_stiffness
      !> The force scaled by s: the stiffness k scaled (`smooth_scale_force`).
      procedure :: scale_force => smooth_scale_force
   end type smooth_law

contains

   !> The rows a smooth law `given` (deck name `name`) starts with: elastic, of stiffness k
   !> (each step sets the tangent), no dashpot, no yield nodes; k > 0 and finite, and when
   !> `with_restitution` 0 < e < 1 (else e is ignored: 0).
   pure subroutine make_smooth(law, given, name, k, e, with_restitution, error)
      !> The rows.
      type(contact_law), intent(out) :: law
      !> The law.
      class(smooth_law), intent(in) :: given
      !> Its deck name.
      character(len=*), intent(in) :: name
      !> Stiffness as given and restitution.
      real(dp), intent(in) :: k, e
      !> The law is calibrated to a restitution.
      logical, intent(in) :: with_restitution
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      if (.not. (k > 0.0_dp .and. k <= huge(1.0_dp))) then
         call fatal_error(error, "law '"//name//"': stiffness = "//str(k)//' must be > 0 and finite')
         return
      end if
      if (with_restitution .and. .not. (e > 0.0_dp .and. e < 1.0_dp)) then
         call fatal_error(error, "law '"//name//"': restitution = "//str(e)//' must be > 0 and < 1')
         return
      end if
      allocate (law%given, source=given)
      select type (g => law%given)
      class is (smooth_law)
         g%k = k
         g%e = merge(e, 0.0_dp, with_restitution)
         g%deck_name = name
      end select
      law%stiffness = k
      law%dashpot = 0.0_dp
      law%env_d = [real(dp) ::]
      law%env_r = [real(dp) ::]
      law%tail_slope = k
      law%yp = [real(dp) ::]
      law%yr = [real(dp) ::]
      law%yh = [real(dp) ::]
   end subroutine make_smooth

   !> The deck's variables of a smooth law: `stiffness` (required, > 0; a Hertz-type one in
   !> `hertz_stiffness_range`), `restitution` (required when `with_restitution`; its range
   !> is the deck's common check), no `dashpot` (the damping follows from the restitution).
   pure subroutine smooth_take(at, raw, cfg, name, hertz_type, with_restitution, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Deck name of the law.
      character(len=*), intent(in) :: name
      !> The stiffness is a Hertz-type kh (kN/m^(3/2)); else k (kN/m).
      logical, intent(in) :: hertz_type, with_restitution
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error

      if (hertz_type) then
         call require_real(at, 'stiffness', raw%stiffness, "Hertz stiffness of law = '"//name// &
                           "' in kN/m^(3/2)", error)
      else
         call require_real(at, 'stiffness', raw%stiffness, "joint stiffness k of law = '"//name//"' in kN/m", error)
      end if
      if (allocated(error)) return
      call check_real(at, 'stiffness', raw%stiffness, '>', 0.0_dp, error)
      if (allocated(error)) return
      if (hertz_type .and. .not. (raw%stiffness >= hertz_stiffness_range(1) .and. &
                                  raw%stiffness <= hertz_stiffness_range(2))) then
         call fail(at, 'stiffness', 'stiffness = '//str(raw%stiffness)//" kN/m^(3/2) of law = '"//name// &
                   "' is outside its plausible range "//str(hertz_stiffness_range(1))//' to '// &
                   str(hertz_stiffness_range(2))//' kN/m^(3/2) (concrete floors: about 1e6 to 1e9; '// &
                   'a Hertz stiffness is in kN/m^(3/2), not kN/m)', error)
         return
      end if
      if (is_set(raw%dashpot)) then
         if (with_restitution) then
            call fail(at, 'dashpot', "dashpot is not a variable of law = '"//name//"': its damping "// &
                      'follows from restitution (remove dashpot)', error)
         else
            call fail(at, 'dashpot', "dashpot is not a variable of law = '"//name//"', an elastic "// &
                      "impact (a damped one: law = 'hertz_damp' or 'jankowski' with restitution)", error)
         end if
         return
      end if
      if (with_restitution .and. .not. is_set(raw%restitution)) then
         call fail(at, 'restitution', "law = '"//name//"' needs restitution, the coefficient of "// &
                   'restitution e (0 < e < 1) its damping is calibrated to', error)
         return
      end if
      cfg%stiffness = raw%stiffness
   end subroutine smooth_take

   pure function smooth_name(law) result(name)
      class(smooth_law), intent(in) :: law
      character(len=:), allocatable :: name

      name = trim(law%deck_name)
   end function smooth_name

   pure logical function smooth_iterates(law) result(it)
      class(smooth_law), intent(in) :: law

      associate (unused => law)
      end associate
      it = .true.
   end function smooth_iterates

   pure subroutine smooth_set_masses(law, m1, m2)
      class(smooth_law), intent(inout) :: law
      real(dp), intent(in) :: m1, m2

      if (law%impact_known .and. m1 == law%m1 .and. m2 == law%m2) return
      law%m1 = m1
      law%m2 = m2
      law%meff = pair_mass(m1, m2)
      law%impact = calibration_impact(law)
      law%impact_known = .true.
   end subroutine smooth_set_masses

   !> The central impact of the law's calibration: its facing masses (unit masses where it
   !> was given none: the laws here deliver the same e_r at any masses and speed) at
   !> `typical_impact_speed`, finely integrated (`law_impact`).
   pure function calibration_impact(law) result(imp)
      class(smooth_law), intent(in) :: law
      type(impact_result) :: imp

      if (law%meff > 0.0_dp) then
         imp = law_impact(law, law%m1, law%m2, typical_impact_speed)
      else
         imp = law_impact(law, 1.0_dp, 1.0_dp, typical_impact_speed)
      end if
   end function calibration_impact

   pure logical function smooth_has_force(law) result(has)
      class(smooth_law), intent(in) :: law

      associate (unused => law)
      end associate
      has = .true.
   end function smooth_has_force

   pure real(dp) function smooth_contact_duration(law, m1, m2, v) result(t)
      class(smooth_law), intent(in) :: law
      real(dp), intent(in) :: m1, m2, v
      type(impact_result) :: imp

      imp = law_impact(law, m1, m2, v)
      t = imp%duration
   end function smooth_contact_duration

   !> The realised coefficient of restitution of the calibration (`calibration_impact`, as
   !> stored by `set_masses`; computed here only for a law whose masses were never set).
   pure real(dp) function smooth_realised_restitution(law) result(e_r)
      class(smooth_law), intent(in) :: law
      type(impact_result) :: imp

      if (law%impact_known) then
         e_r = law%impact%restitution
      else
         imp = calibration_impact(law)
         e_r = imp%restitution
      end if
   end function smooth_realised_restitution

   pure subroutine smooth_set_trial(law, k)
      class(smooth_law), intent(inout) :: law
      real(dp), intent(in) :: k

      law%k_trial = k
      law%in_trial = .true.
   end subroutine smooth_set_trial

   pure subroutine smooth_commit_state(law)
      class(smooth_law), intent(inout) :: law

      law%in_trial = .false.
   end subroutine smooth_commit_state

   pure real(dp) function smooth_row_stiffness(law, k_rows) result(k)
      class(smooth_law), intent(in) :: law
      real(dp), intent(in) :: k_rows

      associate (unused => k_rows)
      end associate
      k = law%k
      if (law%in_trial) k = law%k_trial
   end function smooth_row_stiffness

   !> Scale the law's force by s > 0 (a contact point that takes the share s of its pair):
   !> its stiffness k (k or kh, beta) becomes s k. Every smooth law's force is homogeneous of
   !> degree one in its stiffness and the facing masses together, f(d, d'; s k, s m1, s m2) =
   !> s f(d, d'; k, m1, m2) (the dashpots c = 2 xi sqrt(k m_eff) of `kelvin` and `jankowski`
   !> scale by s; the constant a of `hertz_damp` is e's alone), and the point's masses are the
   !> share s of the floors' (pound_contact_system `calibrate_dashpot`): the point's force is
   !> s times the pair's law's, its tangent s times the tangent, its calibration (the realised
   !> restitution, the contact duration) the pair's.
   pure subroutine smooth_scale_force(law, s)
      class(smooth_law), intent(inout) :: law
      real(dp), intent(in) :: s

      law%k = s*law%k
      law%impact_known = .false.
   end subroutine smooth_scale_force

   pure real(dp) function smooth_shown_stiffness(law) result(k)
      class(smooth_law), intent(in) :: law

      k = law%k
   end function smooth_shown_stiffness

   pure function smooth_stiffness_unit(law) result(u)
      class(smooth_law), intent(in) :: law
      character(len=:), allocatable :: u

      associate (unused => law)
      end associate
      u = 'kN/m^(3/2)'
   end function smooth_stiffness_unit

   pure function smooth_describe(law) result(lines)
      class(smooth_law), intent(in) :: law
      type(law_text), allocatable :: lines(:)
      type(impact_result) :: imp

      allocate (lines(0))
      call add_line(lines, 'stiffness = '//str(law%k)//' '//law%stiffness_unit())
      if (law%e > 0.0_dp) call add_line(lines, 'restitution e = '//str(law%e)//' (calibration)')
      if (law%meff > 0.0_dp) then
         if (law%impact_known) then
            imp = law%impact
         else
            imp = law_impact(law, law%m1, law%m2, typical_impact_speed)
         end if
         call add_line(lines, 'realised e = '//str(imp%restitution)//' (central impact of the facing masses, '// &
                       'm_eff = '//str(law%meff)//' t, at '//str(typical_impact_speed)//' m/s: max. penetration '// &
                       str(1.0e3_dp*imp%max_penetration)//' mm, duration '//str(imp%duration)//' s, peak force '// &
                       str(imp%peak_force)//' kN)')
      end if
   end function smooth_describe

end module pound_law_smooth
