!> The `parabola_cubic` joint law, the seed paper's Fig. 1b: a parabola from 0 (slope k0) to
!> the peak rB = k0 dB/2 at dB (slope 0), a cubic falling to 0 at dF (slope 0 at both ends,
!> inflexion midway), nothing beyond (fracture). Each curved branch is replaced by
!> `n_segments` chords (equal steps in d). One module of the piecewise-linear family
!> (pound_joint_law).
module pound_law_parabola_cubic
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_envelope_rules, only: check_law_constants, max_segments
   use pound_joint_law, only: joint_law, law_text, law_input, add_line, law_variable, dashpot_variables
   use pound_contact_law, only: contact_law, compile_envelope
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site, require_real, check_real, check_plausible, fail, is_set, unset_int
   implicit none
   private

   public :: parabola_cubic_law, make_parabola_cubic, parabola_cubic_force, parabola_cubic_from_config, &
             parabola_cubic_take, parabola_cubic_variables

   !> The `&contact` variables of law = 'parabola_cubic' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: parabola_cubic_variables(7) = [law_variable('stiffness', 'r', 0, 'kN/m'), &
      law_variable('peak_force', 'r', 0, 'kN'), law_variable('peak_penetration', 'r', 0, 'm'), &
      law_variable('fracture_penetration', 'r', 0, 'm'), law_variable('n_segments', 'i', 0, ''), dashpot_variables]

   !> The Fig. 1b law: its parameters as given.
   type, extends(joint_law) :: parabola_cubic_law
      !> Peak force rB (kN), peak and fracture penetrations dB, dF (m).
      real(dp) :: peak_force = 0.0_dp, peak_penetration = 0.0_dp, fracture_penetration = 0.0_dp
      !> Chords per curved branch.
      integer :: n_segments = 0
   contains
      !> 'parabola_cubic'.
      procedure :: name => parabola_cubic_name
      !> rB, dB, dF and the chords.
      procedure :: describe => parabola_cubic_describe
   end type parabola_cubic_law

contains

   !> The paper's Fig. 1b law from k0, dB, dF (rB = k0 dB/2), `nseg` chords per branch.
   pure subroutine make_parabola_cubic(law, k0, db, df, nseg, dashpot, error)
      !> The law.
      type(contact_law), intent(out) :: law
      !> Initial stiffness k0 = 2 rB/dB (kN/m), > 0.
      real(dp), intent(in) :: k0
      !> Penetration at the peak dB (m), > 0.
      real(dp), intent(in) :: db
      !> Penetration at fracture dF (m), > dB.
      real(dp), intent(in) :: df
      !> Chords per curved branch, >= 1.
      integer, intent(in) :: nseg
      !> Dashpot c (kN s/m), >= 0.
      real(dp), intent(in) :: dashpot
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: d(2*nseg), r(2*nseg), rb
      integer :: i

      call check_law_constants(k0, dashpot, error)
      if (allocated(error)) return
      if (.not. (db > 0.0_dp .and. df > db)) then
         call fatal_error(error, 'need 0 < dB < dF, got dB = '//str(db)//', dF = '//str(df))
         return
      end if
      if (nseg < 1) then
         call fatal_error(error, 'n_segments must be >= 1, got '//str(nseg))
         return
      end if
      rb = 0.5_dp*k0*db
      law%given = parabola_cubic_law(peak_force=rb, peak_penetration=db, fracture_penetration=df, &
                                     n_segments=nseg)
      law%stiffness = k0
      law%dashpot = dashpot
      do i = 1, nseg
         d(i) = db*real(i, dp)/real(nseg, dp)
         d(nseg + i) = db + (df - db)*real(i, dp)/real(nseg, dp)
      end do
      d(nseg) = db
      d(2*nseg) = df
      do i = 1, 2*nseg
         r(i) = parabola_cubic_force(rb, db, df, d(i))
      end do
      r(nseg) = rb
      r(2*nseg) = 0.0_dp
      call compile_envelope(law, d, r, 0.0_dp, 0)
   end subroutine make_parabola_cubic

   !> The law of a `&contact` group with law = 'parabola_cubic' (`stiffness`,
   !> `peak_penetration`, `fracture_penetration`, `n_segments`, `dashpot`).
   pure subroutine parabola_cubic_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_parabola_cubic(law, c%stiffness, c%peak_penetration, c%fracture_penetration, c%n_segments, &
                               c%dashpot, error)
   end subroutine parabola_cubic_from_config

   !> The smooth Fig. 1b envelope (not linearised) at penetration d.
   pure real(dp) function parabola_cubic_force(rb, db, df, d) result(r)
      !> Peak force rB (kN).
      real(dp), intent(in) :: rb
      !> Peak and fracture penetrations (m).
      real(dp), intent(in) :: db, df
      !> Penetration (m).
      real(dp), intent(in) :: d
      real(dp) :: xi

      if (d <= 0.0_dp) then
         r = 0.0_dp
      else if (d <= db) then
         xi = d/db
         r = rb*xi*(2.0_dp - xi)
      else if (d < df) then
         xi = (d - db)/(df - db)
         r = rb*(1.0_dp - xi*xi*(3.0_dp - 2.0_dp*xi))
      else
         r = 0.0_dp
      end if
   end function parabola_cubic_force

   !> The deck's variables of law = 'parabola_cubic': dB, dF, and k0 or rB (k0 = 2 rB/dB),
   !> chords per branch.
   pure subroutine parabola_cubic_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: k0
      integer :: n_segments

      call require_real(at, 'peak_penetration', raw%peak_penetration, 'penetration dB at the peak force, m', &
                        error)
      if (allocated(error)) return
      call check_real(at, 'peak_penetration', raw%peak_penetration, '>', 0.0_dp, error)
      if (allocated(error)) return
      call require_real(at, 'fracture_penetration', raw%fracture_penetration, &
                        'penetration dF at fracture, m', error)
      if (allocated(error)) return
      call check_real(at, 'fracture_penetration', raw%fracture_penetration, '>', raw%peak_penetration, error, &
                      bound_text='peak_penetration = '//str(raw%peak_penetration))
      if (allocated(error)) return
      if (is_set(raw%stiffness)) then
         call check_real(at, 'stiffness', raw%stiffness, '>', 0.0_dp, error)
         if (allocated(error)) return
         k0 = raw%stiffness
         if (is_set(raw%peak_force)) then
            if (abs(raw%peak_force - 0.5_dp*k0*raw%peak_penetration) > 1.0e-9_dp*raw%peak_force) then
               call fail(at, 'peak_force', 'peak_force = '//str(raw%peak_force)//' contradicts stiffness = '// &
                         str(raw%stiffness)//' and peak_penetration = '//str(raw%peak_penetration)// &
                         ' (the parabola needs stiffness = 2 peak_force/peak_penetration); give one '// &
                         'of stiffness and peak_force', error)
               return
            end if
         end if
      else
         call require_real(at, 'peak_force', raw%peak_force, 'peak force rB in kN, or give stiffness '// &
                           'k0 = 2 rB/dB', error)
         if (allocated(error)) return
         call check_real(at, 'peak_force', raw%peak_force, '>', 0.0_dp, error)
         if (allocated(error)) return
         k0 = 2.0_dp*raw%peak_force/raw%peak_penetration
         call check_plausible(at, 'stiffness', k0, 'k0 = 2 peak_force/peak_penetration', error, &
                              line_of='peak_force')
         if (allocated(error)) return
      end if
      n_segments = raw%n_segments
      if (n_segments == unset_int) n_segments = 8
      if (n_segments < 1 .or. n_segments > max_segments) then
         call fail(at, 'n_segments', 'n_segments = '//str(n_segments)//', must be 1..'//str(max_segments)// &
                   ' (chords per curved branch)', error)
         return
      end if
      cfg%stiffness = k0
      cfg%peak_force = 0.5_dp*k0*raw%peak_penetration
      cfg%peak_penetration = raw%peak_penetration
      cfg%fracture_penetration = raw%fracture_penetration
      cfg%n_segments = n_segments
   end subroutine parabola_cubic_take

   pure function parabola_cubic_name(law) result(name)
      class(parabola_cubic_law), intent(in) :: law
      character(len=:), allocatable :: name

      associate (unused => law)
      end associate

      name = 'parabola_cubic'
   end function parabola_cubic_name

   pure function parabola_cubic_describe(law) result(lines)
      class(parabola_cubic_law), intent(in) :: law
      type(law_text), allocatable :: lines(:)
      character(len=120) :: buf

      write (buf, '(a,es11.4,a,es11.4,a,es11.4,a,i0,a)') 'rB = ', law%peak_force, ' kN, dB = ', &
         1000.0_dp*law%peak_penetration, ' mm, dF = ', 1000.0_dp*law%fracture_penetration, ' mm, ', law%n_segments, &
         ' chords per curved branch'
      call add_line(lines, trim(buf))
   end function parabola_cubic_describe

end module pound_law_parabola_cubic
