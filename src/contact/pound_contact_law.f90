!> The rows of the piecewise-linear joint laws: what every law of the family compiles into
!> once (`contact_law`), and what the per-step LCP, the joint update and the writers read.
!> The laws themselves (their parameters, deck names and listing lines) are extensions of
!> `joint_law` (pound_joint_law), one module each (pound_law_*), registered by deck name in
!> pound_law_registry; `contact_law%given` holds the law a row set was compiled from.
!>
!> A law relates the compression d of the joint (penetration beyond the gap) to the
!> compressive force r >= 0 of its spring, with an optional dashpot in parallel. Every law
!> is an envelope in the (d, r) plane, loaded from the virgin state along the envelope and
!> unloaded and reloaded inside it elastically at the initial stiffness k0; the plastic
!> penetration d_p (d at r = 0 on the unloading line) is remembered, so a crushed joint
!> reopens at a larger gap.
!>
!> The family: `elastic` (pound_law_elastic), `elastic_plastic` and `bilinear`
!> (pound_law_bilinear), `piecewise` (pound_law_piecewise), `parabola_cubic`
!> (pound_law_parabola_cubic). Beyond the last point the polygon goes on with its last slope; a falling envelope that reaches
!> r = 0 ends there: the joint is fractured and carries nothing for the rest of the analysis.
!>
!> For the per-step LCP (pound_contact) every envelope is stored as the yield force as a
!> function of the plastic penetration, r_y(d_p), piecewise linear with nodes
!> (p_i, ry_i), i = 0..ns, p_i = d_i - r_i/k0, and plastic moduli h_i = k0 s/(k0 - s) for an
!> envelope slope s (segment i runs from node i to node i+1; h_ns is the tail beyond the
!> last node). Yield segment i+1 (1-based, as reported) is segment i here.
module pound_contact_law
   use pound_kinds, only: dp
   use pound_envelope_rules, only: max_law_points
   use pound_joint_law, only: joint_law, law_text, add_line
   implicit none
   private

   public :: contact_law, compile_envelope, rate_trapezoidal, rate_backward_euler, rate_name
   public :: envelope_force, yield_force, yield_segment, is_plastic, plastic_modulus, max_law_points
   public :: restitution_of_ratio, ratio_of_restitution, dashpot_of_restitution, stiffness_units, add_stiffness_unit
   public :: scale_law_force

   !> Dashpot rate by the trapezoidal rule (Newmark's own): d'_{n+1} = (2/dt) (d_{n+1} - d_n) - d'_n.
   integer, parameter :: rate_trapezoidal = 1
   !> Dashpot rate by backward Euler: d'_{n+1} = (d_{n+1} - d_n)/dt (dissipative, no ringing).
   integer, parameter :: rate_backward_euler = 2


   !> A joint law compiled into the rows of the per-step LCP (piecewise linear).
   type :: contact_law
      !> The law these rows were compiled from (its name, listing lines, iteration hook);
      !> unallocated: a plain elastic spring set up field by field (tests).
      class(joint_law), allocatable :: given
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
   contains
      !> The law's deck name ('elastic' for rows without a `given` law).
      procedure :: title => law_title
      !> The listing lines of its parameters (with the fracture point of a fracturing law).
      procedure :: lines => law_lines
      !> The envelope as used, (2, n+1) points (d, r) from the origin; (2, 0) for a law
      !> without yield nodes (the HDF5 writer's `envelope/` datasets).
      procedure :: envelope_points => law_envelope_points
      !> Set the dashpot from the coefficient of restitution (when one is given) and the
      !> masses of the two ends (`dashpot_of_restitution`).
      procedure :: calibrate => law_calibrate
      !> A step's iterate: the law's trial state takes the row slope `k` (kN/m), and the rows
      !> follow it (`stiffness`, what the LCP reads; `joint_law%set_trial`).
      procedure :: set_trial => law_set_trial
      !> The step is committed: the law drops its trial state and the rows take its committed
      !> slope (`joint_law%commit`).
      procedure :: commit => law_commit
      !> The unit of the stiffness shown for these rows (the law's `stiffness_unit`; kN/m).
      procedure :: stiffness_unit => law_rows_unit
   end type contact_law

contains

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

   !> The law has yield segments (anything but an elastic spring).
   pure logical function is_plastic(law)
      !> The law.
      type(contact_law), intent(in) :: law

      is_plastic = .false.
      if (allocated(law%yp)) is_plastic = size(law%yp) > 0
   end function is_plastic

   !> Plastic modulus h = k0 s/(k0 - s) of an envelope slope s < k0 (kN/m).
   pure real(dp) function plastic_modulus(k0, s)
      !> Elastic stiffness.
      real(dp), intent(in) :: k0
      !> Envelope slope, < k0.
      real(dp), intent(in) :: s

      plastic_modulus = k0*s/(k0 - s)
   end function plastic_modulus

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


   !> Compile a law's envelope polygon into its rows: store the nodes (d, r) (origin implied)
   !> and derive the yield function. Nodes first..n yield (node `first` is the elastic limit;
   !> 0 = the origin); a falling tail that reaches r = 0 adds the fracture node. The law's
   !> `stiffness` k0 is set before.
   pure subroutine compile_envelope(law, d, r, tail, first)
      !> The rows (stiffness set).
      type(contact_law), intent(inout) :: law
      !> Envelope nodes after the origin: penetrations (m) and forces (kN).
      real(dp), intent(in) :: d(:), r(:)
      !> Envelope slope beyond the last node (kN/m).
      real(dp), intent(in) :: tail
      !> The node where yielding starts (0: the origin, 1: the first node).
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
   end subroutine compile_envelope

   !> Scale the force axis of the rows by `s` > 0: the force at every compression and rate
   !> becomes s times the law's (stiffness, dashpot, envelope forces, yield forces and plastic
   !> moduli; the penetrations stay), and so does the force of the `given` law where it has one
   !> of its own (a smooth law: `joint_law%scale_force`, its stiffness scaled). A contact point
   !> that takes a share s of its pair (pound_contact_pair, buildings in plan).
   pure subroutine scale_law_force(law, s)
      !> The rows.
      type(contact_law), intent(inout) :: law
      !> The factor.
      real(dp), intent(in) :: s

      if (allocated(law%given)) call law%given%scale_force(s)
      law%stiffness = s*law%stiffness
      law%dashpot = s*law%dashpot
      law%tail_slope = s*law%tail_slope
      if (allocated(law%env_r)) law%env_r = s*law%env_r
      if (allocated(law%yr)) law%yr = s*law%yr
      if (allocated(law%yh)) law%yh = s*law%yh
   end subroutine scale_law_force

   !> The law's deck name ('elastic' for rows without a `given` law).
   pure function law_title(law) result(name)
      !> The rows.
      class(contact_law), intent(in) :: law
      character(len=:), allocatable :: name

      if (allocated(law%given)) then
         name = law%given%name()
      else
         name = 'elastic'
      end if
   end function law_title

   !> The listing lines of the law's parameters, and the fracture point of a fracturing law.
   pure subroutine law_lines(law, lines)
      !> The rows.
      class(contact_law), intent(in) :: law
      !> The lines, without the listing's indentation.
      type(law_text), allocatable, intent(out) :: lines(:)
      character(len=64) :: buf

      if (allocated(law%given)) then
         lines = law%given%describe()
      else
         allocate (lines(0))
      end if
      if (is_plastic(law) .and. law%fractures) then
         write (buf, '(a,es11.4,a)') 'fractures at d = ', 1000.0_dp*law%env_d(size(law%env_d)), ' mm'
         call add_line(lines, trim(buf))
      end if
   end subroutine law_lines

   !> Set the dashpot from `restitution` (when > 0) and the end masses m1, m2 (t; <= 0: a
   !> rigid fixed end), by the exact relation of the joint (`dashpot_of_restitution`).
   pure subroutine law_calibrate(law, m1, m2)
      !> The rows.
      class(contact_law), intent(inout) :: law
      !> Masses of the two ends (t).
      real(dp), intent(in) :: m1, m2

      ! A smooth law calibrates its own damping from the masses (no dashpot in its rows).
      if (allocated(law%given)) then
         if (law%given%iterates()) then
            call law%given%set_masses(m1, m2)
            ! Its restitution is the law's own (the rows have no dashpot to calibrate).
            law%restitution = 0.0_dp
            return
         end if
      end if
      if (law%restitution > 0.0_dp) law%dashpot = dashpot_of_restitution(law%restitution, law%stiffness, m1, m2)
   end subroutine law_calibrate

   !> The law's trial row slope k (kN/m), which the rows take.
   pure subroutine law_set_trial(law, k)
      !> The rows (their law allocated).
      class(contact_law), intent(inout) :: law
      !> Slope of the row at the iterate (kN/m).
      real(dp), intent(in) :: k

      call law%given%set_trial(k)
      law%stiffness = law%given%row_stiffness(law%stiffness)
   end subroutine law_set_trial

   !> Commit the law's state; the rows take its committed slope.
   pure subroutine law_commit(law)
      !> The rows (their law allocated).
      class(contact_law), intent(inout) :: law

      call law%given%commit()
      law%stiffness = law%given%row_stiffness(law%stiffness)
   end subroutine law_commit

   !> The unit of the rows' shown stiffness: the law's (kN/m without a law).
   pure function law_rows_unit(law) result(u)
      !> The rows.
      class(contact_law), intent(in) :: law
      character(len=:), allocatable :: u

      if (allocated(law%given)) then
         u = law%given%stiffness_unit()
      else
         u = 'kN/m'
      end if
   end function law_rows_unit

   !> The units of the stiffnesses of the joints `laws` (one dataset): their common unit
   !> (`stiffness_unit`), or each distinct one in joint order, ' or ' separated (joints of
   !> laws of different families); kN/m for none.
   pure function stiffness_units(laws) result(u)
      !> The joints' rows.
      type(contact_law), intent(in) :: laws(:)
      character(len=:), allocatable :: u
      integer :: k

      u = ''
      do k = 1, size(laws)
         call add_stiffness_unit(u, laws(k))
      end do
   end function stiffness_units

   !> Add the unit of `law`'s stiffness to the list `u` ('kN/m or kN/m^(3/2)'), once.
   pure subroutine add_stiffness_unit(u, law)
      !> The units so far ('' for none).
      character(len=:), allocatable, intent(inout) :: u
      !> A joint's rows.
      type(contact_law), intent(in) :: law
      character(len=:), allocatable :: w

      w = law%stiffness_unit()
      if (index(' or '//u//' or ', ' or '//w//' or ') > 0) return
      if (len(u) > 0) u = u//' or '
      u = u//w
   end subroutine add_stiffness_unit

   !> The envelope as used, (2, n+1) points (d, r) from the origin; (2, 0) without nodes.
   pure function law_envelope_points(law) result(pts)
      !> The rows.
      class(contact_law), intent(in) :: law
      real(dp), allocatable :: pts(:, :)
      integer :: i, n

      n = 0
      if (allocated(law%env_d)) n = size(law%env_d)
      if (n == 0) then
         allocate (pts(2, 0))
         return
      end if
      allocate (pts(2, n + 1))
      pts(:, 1) = 0.0_dp
      do i = 1, n
         pts(:, i + 1) = [law%env_d(i), law%env_r(i)]
      end do
   end function law_envelope_points

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
