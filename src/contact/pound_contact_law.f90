!> Constitutive laws of the unilateral constraints between facing floors.
!>
!> A law relates the compression d of the joint (penetration beyond the gap) to the
!> compressive force r >= 0 of its spring, with an optional dashpot in parallel. Every law
!> is an envelope in the (d, r) plane, loaded from the virgin state along the envelope and
!> unloaded and reloaded inside it elastically at the initial stiffness k0; the plastic
!> penetration d_p (d at r = 0 on the unloading line) is remembered, so a crushed joint
!> reopens at a larger gap.
!>
!> | kind | envelope |
!> |---|---|
!> | `elastic` | r = k0 d |
!> | `elastic_plastic` | k0 up to the yield force, then flat |
!> | `bilinear` | k0 up to the yield force, then a second slope k2 < k0 of either sign |
!> | `piecewise` | the polygon through the origin and the given points; k0 is its first slope |
!> | `parabola_cubic` | the paper's Fig. 1b: a parabola from 0 (slope k0) to the peak rB at dB (slope 0), a cubic falling to 0 at dF (slope 0 at both ends, inflexion midway), nothing beyond (fracture) |
!>
!> Curved branches are replaced by `n_segments` chords each (equal steps in d). Beyond the
!> last point the polygon goes on with its last slope; a falling envelope that reaches
!> r = 0 ends there: the joint is fractured and carries nothing for the rest of the analysis.
!>
!> For the per-step LCP (pound_contact) every envelope is stored as the yield force as a
!> function of the plastic penetration, r_y(d_p), piecewise linear with nodes
!> (p_i, ry_i), i = 0..ns, p_i = d_i - r_i/k0, and plastic moduli h_i = k0 s/(k0 - s) for an
!> envelope slope s (segment i runs from node i to node i+1; h_ns is the tail beyond the
!> last node). Yield segment i+1 (1-based, as reported) is segment i here.
module pound_contact_law
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_envelope_rules, only: max_law_points, check_piecewise_envelope, check_law_constants
   implicit none
   private

   public :: contact_law, law_name, law_elastic, law_elastic_plastic, law_bilinear, law_piecewise
   public :: law_parabola_cubic, rate_trapezoidal, rate_backward_euler, rate_name
   public :: make_elastic, make_elastic_plastic, make_bilinear, make_piecewise, make_parabola_cubic
   public :: envelope_force, yield_force, yield_segment, is_plastic, plastic_modulus
   public :: parabola_cubic_force, max_law_points
   public :: restitution_of_ratio, ratio_of_restitution, dashpot_of_restitution

   !> Elastic compression-only spring: r = k0 d.
   integer, parameter :: law_elastic = 1
   !> Elastic-perfectly-plastic: k0 up to the yield force, then flat.
   integer, parameter :: law_elastic_plastic = 2
   !> Bilinear: k0 up to the yield force, then a second slope (hardening or softening).
   integer, parameter :: law_bilinear = 3
   !> General piecewise-linear envelope through given points.
   integer, parameter :: law_piecewise = 4
   !> The seed paper's Fig. 1b: parabola to the peak, cubic down to fracture.
   integer, parameter :: law_parabola_cubic = 5

   !> Dashpot rate by the trapezoidal rule (Newmark's own): d'_{n+1} = (2/dt) (d_{n+1} - d_n) - d'_n.
   integer, parameter :: rate_trapezoidal = 1
   !> Dashpot rate by backward Euler: d'_{n+1} = (d_{n+1} - d_n)/dt (dissipative, no ringing).
   integer, parameter :: rate_backward_euler = 2


   !> A constraint law and its parameters.
   type :: contact_law
      !> Kind of law (`law_elastic`, ...).
      integer :: kind = law_elastic
      !> Initial (elastic, unloading and reloading) stiffness k0 (kN/m).
      real(dp) :: stiffness = 0.0_dp
      !> Dashpot coefficient c (kN s/m), in parallel with the spring.
      real(dp) :: dashpot = 0.0_dp
      !> How the dashpot rate is integrated (`rate_backward_euler` or `rate_trapezoidal`).
      integer :: dashpot_rate = rate_backward_euler
      !> Coefficient of restitution e the dashpot is calibrated to (0 < e < 1; 0: the
      !> dashpot is given as it is). `contact_init` sets `dashpot` from it and the masses of
      !> the two facing points (`dashpot_of_restitution`).
      real(dp) :: restitution = 0.0_dp
      !> Envelope nodes (d, r) after the origin, as used (chords of curved branches).
      real(dp), allocatable :: env_d(:), env_r(:)
      !> Envelope slope beyond the last node (kN/m).
      real(dp) :: tail_slope = 0.0_dp
      !> Yield function nodes: plastic penetration p(0:ns) (m) and yield force ry(0:ns) (kN).
      real(dp), allocatable :: yp(:), yr(:)
      !> Plastic modulus of yield segment i (from node i on), i = 0..ns (kN/m).
      real(dp), allocatable :: yh(:)
      !> The envelope ends at r = 0 in its last node: beyond it the joint is fractured.
      logical :: fractures = .false.
      !> Parameters as given, for the listing: yield force (kN), second slope (kN/m),
      !> peak force rB (kN), peak and fracture penetrations dB, dF (m).
      real(dp) :: yield_force = 0.0_dp, second_slope = 0.0_dp
      real(dp) :: peak_force = 0.0_dp, peak_penetration = 0.0_dp, fracture_penetration = 0.0_dp
      !> Chords per curved branch (`parabola_cubic`).
      integer :: n_segments = 0
   end type contact_law

contains

   !> Name of a law kind, as written in the deck.
   pure function law_name(kind) result(name)
      !> Law kind.
      integer, intent(in) :: kind
      character(len=:), allocatable :: name

      select case (kind)
      case (law_elastic)
         name = 'elastic'
      case (law_elastic_plastic)
         name = 'elastic_plastic'
      case (law_bilinear)
         name = 'bilinear'
      case (law_piecewise)
         name = 'piecewise'
      case (law_parabola_cubic)
         name = 'parabola_cubic'
      case default
         name = 'unknown'
      end select
   end function law_name

   !> Name of a dashpot rate rule, as written in the deck.
   pure function rate_name(rule) result(name)
      !> `rate_trapezoidal` or `rate_backward_euler`.
      integer, intent(in) :: rule
      character(len=:), allocatable :: name

      select case (rule)
      case (rate_trapezoidal)
         name = 'trapezoidal'
      case (rate_backward_euler)
         name = 'backward_euler'
      case default
         name = 'unknown'
      end select
   end function rate_name

   !> The law has yield segments (anything but `elastic`).
   pure logical function is_plastic(law)
      !> The law.
      type(contact_law), intent(in) :: law

      is_plastic = law%kind /= law_elastic
   end function is_plastic

   !> Plastic modulus h = k0 s/(k0 - s) of an envelope slope s < k0 (kN/m).
   pure real(dp) function plastic_modulus(k0, s)
      !> Elastic stiffness.
      real(dp), intent(in) :: k0
      !> Envelope slope, < k0.
      real(dp), intent(in) :: s

      plastic_modulus = k0*s/(k0 - s)
   end function plastic_modulus

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
      law%kind = law_elastic
      law%stiffness = k0
      law%dashpot = dashpot
      law%env_d = [real(dp) ::]
      law%env_r = [real(dp) ::]
      law%tail_slope = k0
      law%yp = [real(dp) ::]
      law%yr = [real(dp) ::]
      law%yh = [real(dp) ::]
   end subroutine make_elastic

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
      law%kind = law_elastic_plastic
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
      law%kind = law_bilinear
      law%stiffness = k0
      law%dashpot = dashpot
      law%yield_force = fy
      law%second_slope = k2
      call finish_envelope(law, [fy/k0], [fy], k2, 1)
   end subroutine make_bilinear

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
      law%kind = law_piecewise
      law%stiffness = k0
      law%dashpot = dashpot
      tail = (r(n) - r(n - 1))/(d(n) - d(n - 1))
      call finish_envelope(law, d, r, tail, 1)
   end subroutine make_piecewise

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
      real(dp) :: d(2*nseg), r(2*nseg)
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
      law%kind = law_parabola_cubic
      law%stiffness = k0
      law%dashpot = dashpot
      law%peak_force = 0.5_dp*k0*db
      law%peak_penetration = db
      law%fracture_penetration = df
      law%n_segments = nseg
      do i = 1, nseg
         d(i) = db*real(i, dp)/real(nseg, dp)
         d(nseg + i) = db + (df - db)*real(i, dp)/real(nseg, dp)
      end do
      d(nseg) = db
      d(2*nseg) = df
      do i = 1, 2*nseg
         r(i) = parabola_cubic_force(law%peak_force, db, df, d(i))
      end do
      r(nseg) = law%peak_force
      r(2*nseg) = 0.0_dp
      call finish_envelope(law, d, r, 0.0_dp, 0)
   end subroutine make_parabola_cubic

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

   !> Envelope force at penetration d on monotonic loading from the virgin state (kN).
   pure real(dp) function envelope_force(law, d) result(r)
      !> The law.
      type(contact_law), intent(in) :: law
      !> Penetration (m).
      real(dp), intent(in) :: d
      integer :: i, n
      real(dp) :: d0, r0

      n = size(law%env_d)
      if (d <= 0.0_dp) then
         r = 0.0_dp
         return
      end if
      d0 = 0.0_dp
      r0 = 0.0_dp
      do i = 1, n
         if (d <= law%env_d(i)) then
            r = r0 + (law%env_r(i) - r0)*(d - d0)/(law%env_d(i) - d0)
            return
         end if
         d0 = law%env_d(i)
         r0 = law%env_r(i)
      end do
      if (law%fractures) then
         r = 0.0_dp
      else
         r = r0 + law%tail_slope*(d - d0)
      end if
   end function envelope_force

   !> Yield segment (0-based, see the module notes) holding plastic penetration p:
   !> the last node i with yp(i) <= p (0 for the elastic law).
   pure integer function yield_segment(law, p) result(seg)
      !> The law.
      type(contact_law), intent(in) :: law
      !> Plastic penetration (m).
      real(dp), intent(in) :: p
      integer :: ns

      seg = 0
      ns = size(law%yp) - 1
      do while (seg < ns)
         if (law%yp(seg + 1) > p) exit
         seg = seg + 1
      end do
   end function yield_segment

   !> Yield force r_y(p) at plastic penetration p (kN); huge for the elastic law.
   pure real(dp) function yield_force(law, p) result(ry)
      !> The law.
      type(contact_law), intent(in) :: law
      !> Plastic penetration (m), >= 0.
      real(dp), intent(in) :: p
      integer :: seg

      if (.not. is_plastic(law)) then
         ry = huge(1.0_dp)
         return
      end if
      seg = yield_segment(law, p)
      ry = law%yr(seg) + law%yh(seg)*(p - law%yp(seg))
   end function yield_force


   !> Store the envelope nodes (d, r) (origin implied) and derive the yield function.
   !> Nodes first..n yield (node `first` is the elastic limit; 0 = the origin); a falling
   !> tail that reaches r = 0 adds the fracture node.
   pure subroutine finish_envelope(law, d, r, tail, first)
      type(contact_law), intent(inout) :: law
      real(dp), intent(in) :: d(:), r(:), tail
      integer, intent(in) :: first
      real(dp) :: dd(0:size(d) + 1), rr(0:size(d) + 1)
      real(dp) :: k0
      integer :: n, i, ns

      k0 = law%stiffness
      n = size(d)
      dd(0) = 0.0_dp
      rr(0) = 0.0_dp
      dd(1:n) = d
      rr(1:n) = r
      law%tail_slope = tail
      law%fractures = rr(n) == 0.0_dp
      if (.not. law%fractures .and. tail < 0.0_dp) then
         ! A falling tail ends where it reaches r = 0: the fracture node.
         dd(n + 1) = dd(n) + rr(n)/(-tail)
         rr(n + 1) = 0.0_dp
         n = n + 1
         law%fractures = .true.
      end if
      if (law%fractures) law%tail_slope = 0.0_dp
      law%env_d = dd(1:n)
      law%env_r = rr(1:n)
      ! Yield nodes: envelope nodes first..n.
      ns = n - first
      allocate (law%yp(0:ns), law%yr(0:ns), law%yh(0:ns))
      do i = 0, ns
         law%yp(i) = dd(first + i) - rr(first + i)/k0
         law%yr(i) = rr(first + i)
      end do
      law%yp(0) = 0.0_dp
      do i = 0, ns - 1
         law%yh(i) = (law%yr(i + 1) - law%yr(i))/(law%yp(i + 1) - law%yp(i))
      end do
      law%yh(ns) = plastic_modulus(k0, law%tail_slope)
   end subroutine finish_envelope

   !> Coefficient of restitution e of the joint pound integrates, as a function of the damping
   !> ratio xi = c / (2 sqrt(k m_eff)) of the impact oscillator.
   !>
   !> The joint is a Kelvin-Voigt element with a tension cut-off: m_eff x'' + c x' + k x = 0,
   !> started at x = 0, x' = v0, ends when its force k x + c x' reaches zero (not when x
   !> returns to 0, which the classic formula assumes). With w = sqrt(k/m_eff),
   !> s = sqrt(1 - xi^2), theta = w s t, the force is proportional to
   !> sin(theta + 2 asin(xi)), which vanishes first at theta = pi - 2 asin(xi), and there
   !> x' = -v0 exp(-xi theta / s) exactly. With beta = acos(xi):
   !>
   !>   e = exp(-2 beta cot(beta))           (xi < 1)
   !>   e = exp(-2)                           (xi = 1)
   !>   e = exp(-2 gamma coth(gamma)), gamma = acosh(xi)   (xi > 1, by continuation)
   !>
   !> e falls monotonically from 1 (xi = 0) to 0 (xi -> infinity). The classic relation
   !> e = exp(-pi xi / s) gives less rebound for the same xi (it ignores that the dashpot
   !> pulls the joint open earlier).
   pure real(dp) function restitution_of_ratio(xi) result(e)
      !> Damping ratio xi >= 0.
      real(dp), intent(in) :: xi

      e = exp(-decay_exponent(xi))
   end function restitution_of_ratio

   !> -ln(e) of `restitution_of_ratio`: 2 beta cot(beta) or 2 gamma coth(gamma).
   pure real(dp) function decay_exponent(xi) result(l)
      !> Damping ratio xi >= 0.
      real(dp), intent(in) :: xi
      real(dp) :: b

      if (xi <= 0.0_dp) then
         l = 0.0_dp
      else if (xi < 1.0_dp) then
         b = acos(xi)
         l = 2.0_dp*b*xi/sqrt((1.0_dp - xi)*(1.0_dp + xi))
      else if (xi == 1.0_dp) then
         l = 2.0_dp
      else
         b = acosh(xi)
         l = 2.0_dp*b*xi/sqrt((xi - 1.0_dp)*(xi + 1.0_dp))
      end if
   end function decay_exponent

   !> The damping ratio xi whose joint returns the coefficient of restitution `e`
   !> (inverse of `restitution_of_ratio`, by bisection on the monotone -ln e(xi); relative
   !> accuracy near machine precision).
   pure real(dp) function ratio_of_restitution(e) result(xi)
      !> Coefficient of restitution, 0 < e < 1.
      real(dp), intent(in) :: e
      real(dp) :: target, lo, hi
      integer :: it

      target = -log(e)
      lo = 0.0_dp
      hi = 1.0_dp
      do while (decay_exponent(hi) < target)
         lo = hi
         hi = 2.0_dp*hi
      end do
      do it = 1, 200
         xi = 0.5_dp*(lo + hi)
         if (xi <= lo .or. xi >= hi) exit
         if (decay_exponent(xi) < target) then
            lo = xi
         else
            hi = xi
         end if
      end do
      xi = 0.5_dp*(lo + hi)
   end function ratio_of_restitution

   !> Dashpot c (kN s/m) that gives a joint of stiffness `k0` between the masses `m1` and
   !> `m2` the coefficient of restitution `e`: c = 2 xi sqrt(k0 m_eff), m_eff = m1 m2/(m1 + m2)
   !> (a rigid fixed end has infinite mass: m2 <= 0 stands for it, m_eff = m1), xi from
   !> `ratio_of_restitution`.
   pure real(dp) function dashpot_of_restitution(e, k0, m1, m2) result(c)
      !> Coefficient of restitution, 0 < e < 1.
      real(dp), intent(in) :: e
      !> Joint stiffness (kN/m).
      real(dp), intent(in) :: k0
      !> Lumped masses (t) of the facing DOFs; <= 0 for a rigid fixed end.
      real(dp), intent(in) :: m1, m2
      real(dp) :: m_eff

      if (m1 <= 0.0_dp) then
         m_eff = m2
      else if (m2 <= 0.0_dp) then
         m_eff = m1
      else
         m_eff = m1*m2/(m1 + m2)
      end if
      c = 2.0_dp*ratio_of_restitution(e)*sqrt(k0*m_eff)
   end function dashpot_of_restitution

end module pound_contact_law
