!> The `piecewise` joint law: the envelope polygon through the origin and given points; k0 is
!> its first slope. One module of the piecewise-linear family (pound_joint_law).
module pound_law_piecewise
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_envelope_rules, only: check_piecewise_envelope, check_law_constants
   use pound_joint_law, only: joint_law, law_text, add_line
   use pound_contact_law, only: contact_law, compile_envelope
   use pound_config, only: contact_config
   implicit none
   private

   public :: piecewise_law, make_piecewise, piecewise_from_config

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
      write (buf, '(a,i0,a)') 'envelope through ', n, ' points (d [m], r [kN]):'
      call add_line(lines, trim(buf))
      do i = 1, n, 4
         write (buf, '(4(a,es10.3,a,es10.3,a))') ('(', law%d(j), ', ', law%r(j), ') ', j=i, min(i + 3, n))
         call add_line(lines, trim(buf))
      end do
   end function piecewise_describe

end module pound_law_piecewise
