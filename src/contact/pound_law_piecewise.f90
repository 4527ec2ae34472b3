!> The `piecewise` joint law: the envelope polygon through the origin and given points; k0 is
!> its first slope. One module of the piecewise-linear family (pound_joint_law).
module pound_law_piecewise
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_envelope_rules, only: check_piecewise_envelope, check_law_constants, max_envelope_points => max_law_points
   use pound_strings, only: str
   use pound_joint_law, only: joint_law, law_text, law_input, add_line, law_variable, dashpot_variables
   use pound_contact_law, only: contact_law, compile_envelope
   use pound_contact_settings, only: contact_config
   use pound_input_checks, only: input_site, check_real, check_plausible, fail, given_count, is_set, values_text
   implicit none
   private

   public :: piecewise_law, make_piecewise, piecewise_from_config, piecewise_take, piecewise_variables

   !> The `&contact` variables of law = 'piecewise' (the deck's table and refusals: pound_law_registry).
   type(law_variable), parameter :: piecewise_variables(4) = [law_variable('envelope_d', 'r', max_envelope_points, 'm'), &
      law_variable('envelope_r', 'r', max_envelope_points, 'kN'), dashpot_variables]

   !> Piecewise law: its points as given.
   type, extends(joint_law) :: piecewise_law
      !> Penetrations (m) and forces (kN) of the points after the origin.
      real(dp), allocatable :: d(:), r(:)
   contains
      !> 'piecewise'.
      procedure :: name => piecewise_name
      !> The points, four per line.
      procedure :: describe => piecewise_describe
   end type piecewise_law

contains

   !> Piecewise-linear envelope through the origin and the points (d(i), r(i)); k0 = r(1)/d(1).
   !>
   !> d strictly increasing and > 0, r(1) > 0, r >= 0, only the last r may be 0, every slope
   !> after the first below k0. Beyond the last point the last slope goes on (a falling
   !> envelope ends, fractured, where it reaches r = 0).
   pure subroutine make_piecewise(law, d, r, dashpot, error)
      !> The law.
      type(contact_law), intent(out) :: law
      !> Penetrations of the points (m).
      real(dp), intent(in) :: d(:)
      !> Forces of the points (kN).
      real(dp), intent(in) :: r(:)
      !> Dashpot c (kN s/m), >= 0.
      real(dp), intent(in) :: dashpot
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: n
      real(dp) :: k0, tail

      n = size(d)
      call check_piecewise_envelope(d, r, k0, error)
      if (allocated(error)) return
      call check_law_constants(k0, dashpot, error)
      if (allocated(error)) return
      law%given = piecewise_law(d=d, r=r)
      law%stiffness = k0
      law%dashpot = dashpot
      tail = (r(n) - r(n - 1))/(d(n) - d(n - 1))
      call compile_envelope(law, d, r, tail, 1)
   end subroutine make_piecewise

   !> The law of a `&contact` group with law = 'piecewise' (`envelope_d`, `envelope_r`,
   !> `dashpot`).
   pure subroutine piecewise_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The law.
      type(contact_law), intent(out) :: law
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call make_piecewise(law, c%envelope_d, c%envelope_r, c%dashpot, error)
   end subroutine piecewise_from_config

   !> The deck's variables of law = 'piecewise': the envelope points, checked by the law's own
   !> rules (pound_envelope_rules).
   pure subroutine piecewise_take(at, raw, cfg, error)
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state (the deck's message).
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: why
      real(dp) :: k0
      integer :: nd, nr, j

      nd = given_count(raw%envelope_d)
      nr = given_count(raw%envelope_r)
      if (nd < 2) then
         call fail(at, 'envelope_d', 'envelope_d has '//values_text(nd)//', needs at least 2 '// &
                   'penetrations (m) of the envelope points after the origin', error)
         return
      end if
      if (nd > max_envelope_points) then
         call fail(at, 'envelope_d', 'envelope_d has '//values_text(nd)//', must have at most '// &
                   str(max_envelope_points), error)
         return
      end if
      if (nr /= nd) then
         call fail(at, 'envelope_r', 'envelope_r has '//values_text(nr)//', envelope_d has '// &
                   values_text(nd)//'; both need one value per point', error)
         return
      end if
      do j = 1, nd
         if (.not. is_set(raw%envelope_d(j))) then
            call fail(at, 'envelope_d', 'envelope_d('//str(j)//') is missing', error)
            return
         end if
         if (.not. is_set(raw%envelope_r(j))) then
            call fail(at, 'envelope_r', 'envelope_r('//str(j)//') is missing', error)
            return
         end if
         call check_real(at, 'envelope_d', raw%envelope_d(j), '>', 0.0_dp, error, &
                         name='envelope_d('//str(j)//')')
         if (allocated(error)) return
         call check_real(at, 'envelope_r', raw%envelope_r(j), '>=', 0.0_dp, error, &
                         name='envelope_r('//str(j)//')')
         if (allocated(error)) return
      end do
      call check_piecewise_envelope(raw%envelope_d(1:nd), raw%envelope_r(1:nd), k0, error)
      if (allocated(error)) then
         why = error%message
         call fail(at, 'envelope_r', 'envelope points: '//why, error)
         return
      end if
      cfg%envelope_d = raw%envelope_d(1:nd)
      cfg%envelope_r = raw%envelope_r(1:nd)
      call check_plausible(at, 'stiffness', k0, &
                           'k0 = envelope_r(1)/envelope_d(1)', error, line_of='envelope_r')
      if (allocated(error)) return
      cfg%stiffness = k0
   end subroutine piecewise_take

   pure function piecewise_name(law) result(name)
      class(piecewise_law), intent(in) :: law
      character(len=:), allocatable :: name

      associate (unused => law)
      end associate

      name = 'piecewise'
   end function piecewise_name

   pure function piecewise_describe(law) result(lines)
      class(piecewise_law), intent(in) :: law
      type(law_text), allocatable :: lines(:)
      character(len=160) :: buf
      integer :: i, j, n

      n = size(law%d)
      write (buf, '(a,i0,a)') 'envelope through ', n, ' points (d [mm], r [kN]):'
      call add_line(lines, trim(buf))
      do i = 1, n, 4
         write (buf, '(4(a,es10.3,a,es10.3,a))') ('(', 1000.0_dp*law%d(j), ', ', law%r(j), ') ', j=i, min(i + 3, n))
         call add_line(lines, trim(buf))
      end do
   end function piecewise_describe

end module pound_law_piecewise
