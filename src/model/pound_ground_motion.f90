!> Ground motion: the ground acceleration a_g(t) (m/s^2) that drives the buildings.
!>
!> Two kinds.
!>
!> * `pulse`: the seed paper's ground displacement x_g(t) = x0 exp(-a t) sin(b t) for t >= 0
!>   (paper: x0 = 0.010 m, a = 2 1/s, b = 4 pi rad/s), applied through its exact second
!>   derivative x_g'' = x0 exp(-a t) [(a^2 - b^2) sin(b t) - 2 a b cos(b t)]. Note that the
!>   pulse starts with x_g'(0) = b x0 and x_g''(0) = -2 a b x0, not from rest: in the relative
!>   formulation only a_g enters, so the buildings start moving with the ground.
!>   Before t = 0 the ground is at rest.
!> * `record`: an accelerogram (values in g) times a scale factor times `g_accel`,
!>   linearly interpolated between its samples. Outside the record, before its first sample
!>   and after its last one, a_g = 0: after the end of the record the buildings vibrate
!>   freely.
!>
!> **Two horizontal components at an angle.** Component 1 (the pulse or the record above) acts
!> along `angle` (degrees from +x toward +y), an optional second record (`second_component`)
!> along `angle` + 90 degrees. The ground along the site axes is
!> a_gx = a_g cos(alpha) - a_2 sin(alpha), a_gy = a_g sin(alpha) + a_2 cos(alpha); each component
!> is interpolated on its own samples and is zero after its end. `ground_accel` (and
!> `sample_ground`) give a_gx, the ground every x DOF of a model feels (a planar building's
!> load -M r a_gx); `ground_accel_y` gives a_gy. With angle 0 and no second component a_gx is
!> a_g itself, bit for bit.
!>
!> Free vibration after the motion (`&analysis t_free`): `stop_ground` sets the time after which
!> a_g = 0 whatever the motion (the pulse, or a record longer than the deck's t_end).
!>
!> The solver does not call `ground_accel` in its time loop: `sample_ground` fills an array
!> a_g(t_n), t_n = n dt, once before integration.
module pound_ground_motion
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error, error_at
   use pound_strings, only: str
   use pound_constants, only: g_accel, pi
   use pound_accelerogram, only: accelerogram_t, read_accelerogram
   implicit none
   private

   public :: ground_motion_t
   public :: pulse_motion, record_motion, sample_ground, ground_accel, check_ground_samples
   public :: pulse_displacement, pulse_velocity, pulse_acceleration
   public :: peak_ground_accel, describe_ground, stop_ground
   public :: set_ground_angle, second_component, take_second_component, first_component, ground_accel_y, &
             ground_moves_y, degree_cos_sin

   !> Two times closer than this fraction of the record's step count as the same sample
   !> (absorbs rounding in n*dt, so solver steps that fall on samples get them exactly).
   real(dp), parameter :: snap = 1.0e-9_dp

   !> A ground motion, ready to be evaluated at any time.
   type :: ground_motion_t
      !> 'pulse', 'record', or blank (no motion: a_g = 0).
      character(len=6) :: kind = ''
      !> Pulse: amplitude x0 (m), decay a (1/s), circular frequency b (rad/s).
      real(dp) :: x0 = 0.0_dp, a = 0.0_dp, b = 0.0_dp
      !> Record: file, its format ('at2' or 'columns') and first header line (AT2).
      character(len=:), allocatable :: path, format, title
      !> Record: scale factor applied to the values in g.
      real(dp) :: scale = 1.0_dp
      !> Record: constant sample step (s) for AT2 records; 0 when times are explicit.
      real(dp) :: dt = 0.0_dp
      !> Record: sample times (s), strictly increasing.
      real(dp), allocatable :: time(:)
      !> Record: ground acceleration at the samples (m/s^2), scale and g applied.
      real(dp), allocatable :: accel(:)
      !> The ground is at rest after this time (s; `stop_ground`; default: never).
      real(dp) :: t_stop = huge(1.0_dp)
      !> The `&ground`'s name (blank: not known) and whether `scale` was computed by its
      !> `scale_to` (for the plausibility warnings of pound_plausibility).
      character(len=:), allocatable :: name
      logical :: scaled = .false.
      !> Direction of component 1 (degrees from +x toward +y) and its cosine and sine
      !> (`set_ground_angle`: exact at multiples of 30 and 45 degrees).
      real(dp) :: angle = 0.0_dp, cos_angle = 1.0_dp, sin_angle = 0.0_dp
      !> Component 2 (`second_component`; unallocated `time_2`: none), a record acting at
      !> `angle` + 90 degrees: file, format, first header line, scale factor, sample step (0:
      !> explicit times), sample times (s) and accelerations (m/s^2, scale and g applied).
      character(len=:), allocatable :: path_2, format_2, title_2
      real(dp) :: scale_2 = 1.0_dp, dt_2 = 0.0_dp
      real(dp), allocatable :: time_2(:), accel_2(:)
   end type ground_motion_t

contains

   !> The pulse x_g(t) = x0 exp(-a t) sin(b t). The deck checks a >= 0 and b > 0.
   pure subroutine pulse_motion(gm, x0, a, b)
      !> Ground motion to define.
      type(ground_motion_t), intent(out) :: gm
      !> Amplitude x0 (m).
      real(dp), intent(in) :: x0
      !> Decay rate a (1/s).
      real(dp), intent(in) :: a
      !> Circular frequency b (rad/s).
      real(dp), intent(in) :: b

      gm%kind = 'pulse'
      gm%x0 = x0
      gm%a = a
      gm%b = b
   end subroutine pulse_motion

   !> A recorded ground motion from the accelerogram `path`: a_g = value * scale * g.
   subroutine record_motion(gm, path, format, scale, error)
      !> Ground motion to define.
      type(ground_motion_t), intent(out) :: gm
      !> Accelerogram file.
      character(len=*), intent(in) :: path
      !> 'at2', 'columns' or 'auto' (see `pound_accelerogram`).
      character(len=*), intent(in) :: format
      !> Factor applied to the file's values, which are in g (e.g. 1/9.81 for a two-column
      !> file in m/s^2, or a scaling to a target PGA).
      real(dp), intent(in) :: scale
      !> Set if the file cannot be read or the scale is not a finite number.
      type(error_type), allocatable, intent(out) :: error
      type(accelerogram_t) :: rec

      call read_scaled(path, format, scale, 'scale', rec, error)
      if (allocated(error)) return
      gm%kind = 'record'
      gm%path = rec%path
      gm%format = rec%format
      gm%title = rec%title
      gm%scale = scale
      gm%dt = rec%dt
      gm%time = rec%time
      gm%accel = rec%accel
   end subroutine record_motion

   !> The record `path` with its values (in g) times `scale` times g; `name` is the scale's
   !> deck variable, for the message on a scale that is not finite.
   subroutine read_scaled(path, format, scale, name, rec, error)
      character(len=*), intent(in) :: path, format
      real(dp), intent(in) :: scale
      character(len=*), intent(in) :: name
      type(accelerogram_t), intent(out) :: rec
      type(error_type), allocatable, intent(out) :: error

      if (.not. ieee_is_finite(scale)) then
         call fatal_error(error, path//': record scale factor ('//name//') is not a finite number')
         return
      end if
      call read_accelerogram(path, format, rec, error)
      if (allocated(error)) return
      rec%accel = rec%accel*(scale*g_accel)
   end subroutine read_scaled

   !> The ground at rest after step nint(t_ground/dt) (the deck's t_end, when `t_free` appends
   !> free vibration): a_g = 0 from the next step on, and at the impact substeps after that step.
   pure subroutine stop_ground(gm, t_ground, dt)
      !> Ground motion.
      type(ground_motion_t), intent(inout) :: gm
      !> End of the motion (s).
      real(dp), intent(in) :: t_ground
      !> Solver time step (s).
      real(dp), intent(in) :: dt

      ! A millionth of a step beyond the step, so that a substep time rounded onto it still
      ! gets the motion.
      gm%t_stop = (real(nint(t_ground/dt), dp) + 1.0e-6_dp)*dt
   end subroutine stop_ground

   !> The direction of component 1, `angle` degrees from +x toward +y (component 2 at
   !> `angle` + 90).
   pure subroutine set_ground_angle(gm, angle)
      !> Ground motion.
      type(ground_motion_t), intent(inout) :: gm
      !> Degrees.
      real(dp), intent(in) :: angle

      gm%angle = angle
      call degree_cos_sin(angle, gm%cos_angle, gm%sin_angle)
   end subroutine set_ground_angle

   !> cos and sin of an angle in degrees, exact at the multiples of 30 and 45 degrees (0, +-1,
   !> +-1/2, +-sqrt(1/2), +-sqrt(3/4) rounded once), so that a motion at 90 degrees has no x
   !> part, one at 60 degrees is half the motion along x, and two equal components at 45
   !> degrees have equal factors. The angle is reduced to (-45, 45] about the nearest
   !> multiple of 90 degrees before the radians are taken.
   elemental subroutine degree_cos_sin(angle, c, s)
      !> Degrees.
      real(dp), intent(in) :: angle
      !> Cosine and sine.
      real(dp), intent(out) :: c, s
      real(dp) :: r, cr, sr
      integer :: q

      q = nint(angle/90.0_dp)
      r = angle - 90.0_dp*real(q, dp)
      if (abs(r) == 45.0_dp) then
         cr = sqrt(0.5_dp)
         sr = sign(sqrt(0.5_dp), r)
      else if (abs(r) == 30.0_dp) then
         cr = sqrt(0.75_dp)
         sr = sign(0.5_dp, r)
      else
         cr = cos(r*(pi/180.0_dp))
         sr = sin(r*(pi/180.0_dp))
      end if
      select case (modulo(q, 4))
      case (0)
         c = cr
         s = sr
      case (1)
         c = -sr
         s = cr
      case (2)
         c = -cr
         s = -sr
      case default
         c = sr
         s = -cr
      end select
   end subroutine degree_cos_sin

   !> Component 2 of the motion: the record `path` (values in g, in the same formats as
   !> component 1's) times `scale` times g, acting at `angle` + 90 degrees.
   subroutine second_component(gm, path, format, scale, error)
      !> Ground motion (its component 1 already set).
      type(ground_motion_t), intent(inout) :: gm
      !> Accelerogram file.
      character(len=*), intent(in) :: path
      !> 'at2', 'columns' or 'auto' (see `pound_accelerogram`).
      character(len=*), intent(in) :: format
      !> Factor applied to the file's values.
      real(dp), intent(in) :: scale
      !> Set if the file cannot be read or the scale is not a finite number.
      type(error_type), allocatable, intent(out) :: error
      type(accelerogram_t) :: rec

      call read_scaled(path, format, scale, 'scale_2', rec, error)
      if (allocated(error)) return
      gm%path_2 = rec%path
      gm%format_2 = rec%format
      gm%title_2 = rec%title
      gm%scale_2 = scale
      gm%dt_2 = rec%dt
      gm%time_2 = rec%time
      gm%accel_2 = rec%accel
   end subroutine second_component

   !> `from`'s angle and component 2 given to `gm`, component 2 times `factor` (a motion
   !> scaled by `scale_to`: the factor found on component 1 scales both).
   pure subroutine take_second_component(gm, from, factor)
      !> The motion as run (its component 1 set).
      type(ground_motion_t), intent(inout) :: gm
      !> The motion as configured.
      type(ground_motion_t), intent(in) :: from
      !> Factor applied to component 2.
      real(dp), intent(in) :: factor

      call set_ground_angle(gm, from%angle)
      if (.not. allocated(from%time_2)) return
      gm%path_2 = from%path_2
      gm%format_2 = from%format_2
      gm%title_2 = from%title_2
      gm%scale_2 = factor*from%scale_2
      gm%dt_2 = from%dt_2
      gm%time_2 = from%time_2
      gm%accel_2 = factor*from%accel_2
   end subroutine take_second_component

   !> Component 1 alone, along x (what `scale_to` measures).
   pure function first_component(gm) result(g1)
      !> Ground motion.
      type(ground_motion_t), intent(in) :: gm
      type(ground_motion_t) :: g1

      g1 = gm
      call set_ground_angle(g1, 0.0_dp)
      if (allocated(g1%time_2)) deallocate (g1%time_2, g1%accel_2)
   end function first_component

   !> Whether the ground moves along y (a_gy not identically zero): an angle that is not a
   !> multiple of 180 degrees, or a second component.
   elemental function ground_moves_y(gm) result(moves)
      !> Ground motion.
      type(ground_motion_t), intent(in) :: gm
      logical :: moves

      moves = (gm%sin_angle /= 0.0_dp .and. len_trim(gm%kind) > 0) .or. allocated(gm%time_2)
   end function ground_moves_y

   !> Ground acceleration at the solver's steps: ag(n) = a_g(n dt), n = 0..n_steps.
   !> With `error`, the samples are checked (`check_ground_samples`).
   pure subroutine sample_ground(gm, dt, n_steps, ag, error)
      !> Ground motion.
      type(ground_motion_t), intent(in) :: gm
      !> Solver time step (s).
      real(dp), intent(in) :: dt
      !> Number of steps N.
      integer, intent(in) :: n_steps
      !> Preallocated with lower bound 0 and at least n_steps+1 elements; on return
      !> ag(0:n_steps) holds a_g(t_n) (m/s^2). Elements beyond n_steps are left alone.
      real(dp), intent(inout) :: ag(0:)
      !> Error state: a sample that is not finite.
      type(error_type), allocatable, intent(out), optional :: error
      integer :: n

      do n = 0, n_steps
         ag(n) = ground_accel(gm, real(n, dp)*dt)
      end do
      if (present(error)) call check_ground_samples(ag(0:n_steps), dt, error, gm)
   end subroutine sample_ground

   !> Fail on the first ground acceleration sample that is not finite, naming its time and
   !> the `&ground` variables it comes from (those of `gm` when given).
   pure subroutine check_ground_samples(ag, dt, error, gm)
      !> Samples a_g(n dt), n = 0.. (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> Solver time step (s).
      real(dp), intent(in) :: dt
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The ground motion the samples came from.
      type(ground_motion_t), intent(in), optional :: gm
      character(len=:), allocatable :: origin
      integer :: n

      do n = 0, ubound(ag, 1)
         if (ieee_is_finite(ag(n))) cycle
         origin = 'x0, a, b (pulse) or the record''s values times scale'
         if (present(gm)) then
            select case (gm%kind)
            case ('pulse')
               origin = 'x0 = '//str(gm%x0)//' m, a = '//str(gm%a)//' 1/s, b = '//str(gm%b)// &
                        ' rad/s (x0 exp(-a t) ((a^2 - b^2) sin(b t) - 2 a b cos(b t)))'
            case ('record')
               origin = 'the values of record '//gm%path//' (in g) times scale = '//str(gm%scale)// &
                        ' times '//str(g_accel)//' m/s^2'
            end select
            if (allocated(gm%time_2)) origin = origin//', and those of record '//gm%path_2// &
                                                 ' times scale_2 = '//str(gm%scale_2)
         end if
         call fatal_error(error, '&ground: the ground acceleration at t = '//str(real(n, dp)*dt)// &
                          ' s (step '//str(n)//') is not finite ('//str(ag(n))//' m/s^2): it comes from '// &
                          origin)
         call error_at(error, real(n, dp)*dt, n)
         return
      end do
   end subroutine check_ground_samples

   !> Ground acceleration along x, a_gx(t) = a_g cos(alpha) - a_2 sin(alpha) (m/s^2): with
   !> angle 0 and no second component, a_g(t) itself.
   elemental function ground_accel(gm, t) result(ag)
      !> Ground motion.
      type(ground_motion_t), intent(in) :: gm
      !> Time (s).
      real(dp), intent(in) :: t
      real(dp) :: ag

      ag = component_1(gm, t)
      if (gm%angle == 0.0_dp .and. .not. allocated(gm%time_2)) return
      ag = gm%cos_angle*ag - gm%sin_angle*component_2(gm, t)
   end function ground_accel

   !> Ground acceleration along y, a_gy(t) = a_g sin(alpha) + a_2 cos(alpha) (m/s^2).
   elemental function ground_accel_y(gm, t) result(ag)
      !> Ground motion.
      type(ground_motion_t), intent(in) :: gm
      !> Time (s).
      real(dp), intent(in) :: t
      real(dp) :: ag

      ag = gm%sin_angle*component_1(gm, t) + gm%cos_angle*component_2(gm, t)
   end function ground_accel_y

   !> Component 1's acceleration a_g(t) (m/s^2).
   elemental function component_1(gm, t) result(ag)
      type(ground_motion_t), intent(in) :: gm
      real(dp), intent(in) :: t
      real(dp) :: ag

      if (t > gm%t_stop) then
         ag = 0.0_dp
         return
      end if
      select case (gm%kind)
      case ('pulse')
         ag = pulse_acceleration(gm%x0, gm%a, gm%b, t)
      case ('record')
         ag = record_value(gm%time, gm%accel, gm%dt, t)
      case default
         ag = 0.0_dp
      end select
   end function component_1

   !> Component 2's acceleration a_2(t) (m/s^2; 0 without one).
   elemental function component_2(gm, t) result(ag)
      type(ground_motion_t), intent(in) :: gm
      real(dp), intent(in) :: t
      real(dp) :: ag

      ag = 0.0_dp
      if (t > gm%t_stop .or. .not. allocated(gm%time_2)) return
      ag = record_value(gm%time_2, gm%accel_2, gm%dt_2, t)
   end function component_2

   !> Pulse ground displacement x0 exp(-a t) sin(b t) (m); 0 for t < 0.
   elemental function pulse_displacement(x0, a, b, t) result(x)
      !> Amplitude (m).
      real(dp), intent(in) :: x0
      !> Decay rate (1/s).
      real(dp), intent(in) :: a
      !> Circular frequency (rad/s).
      real(dp), intent(in) :: b
      !> Time (s).
      real(dp), intent(in) :: t
      real(dp) :: x

      x = 0.0_dp
      if (t >= 0.0_dp) x = x0*exp(-a*t)*sin(b*t)
   end function pulse_displacement

   !> Pulse ground velocity x0 exp(-a t) [b cos(b t) - a sin(b t)] (m/s); 0 for t < 0.
   elemental function pulse_velocity(x0, a, b, t) result(v)
      !> Amplitude (m).
      real(dp), intent(in) :: x0
      !> Decay rate (1/s).
      real(dp), intent(in) :: a
      !> Circular frequency (rad/s).
      real(dp), intent(in) :: b
      !> Time (s).
      real(dp), intent(in) :: t
      real(dp) :: v

      v = 0.0_dp
      if (t >= 0.0_dp) v = x0*exp(-a*t)*(b*cos(b*t) - a*sin(b*t))
   end function pulse_velocity

   !> Pulse ground acceleration x0 exp(-a t) [(a^2 - b^2) sin(b t) - 2 a b cos(b t)] (m/s^2);
   !> 0 for t < 0.
   elemental function pulse_acceleration(x0, a, b, t) result(acc)
      !> Amplitude (m).
      real(dp), intent(in) :: x0
      !> Decay rate (1/s).
      real(dp), intent(in) :: a
      !> Circular frequency (rad/s).
      real(dp), intent(in) :: b
      !> Time (s).
      real(dp), intent(in) :: t
      real(dp) :: acc

      acc = 0.0_dp
      if (t >= 0.0_dp) acc = x0*exp(-a*t)*((a*a - b*b)*sin(b*t) - 2.0_dp*a*b*cos(b*t))
   end function pulse_acceleration

   !> Peak ground acceleration |a_g| (m/s^2) and the time it occurs (s), for t >= 0.
   !>
   !> Pulse (a >= 0): x_g'' = x0 (a^2+b^2) exp(-a t) sin(b t - phi), phi = atan2(2ab, a^2-b^2);
   !> its extrema are at b t = phi + atan2(b, a) + k pi, the first one at t >= 0 being the
   !> largest; it is compared with |x_g''(0)| = 2 a b |x0|. Record: the largest sample
   !> (exact for the piecewise linear a_g); the earliest if several are equal.
   pure subroutine peak_ground_accel(gm, pga, t_pga)
      !> Ground motion.
      type(ground_motion_t), intent(in) :: gm
      !> Peak |a_g| (m/s^2).
      real(dp), intent(out) :: pga
      !> Time of the peak (s).
      real(dp), intent(out) :: t_pga
      real(dp) :: theta, tk, ak
      integer :: i

      pga = 0.0_dp
      t_pga = 0.0_dp
      select case (gm%kind)
      case ('pulse')
         pga = abs(pulse_acceleration(gm%x0, gm%a, gm%b, 0.0_dp))
         if (gm%b <= 0.0_dp) return
         theta = atan2(2.0_dp*gm%a*gm%b, gm%a**2 - gm%b**2) + atan2(gm%b, gm%a)
         theta = theta - pi*real(floor(theta/pi), dp)
         tk = theta/gm%b
         ak = abs(pulse_acceleration(gm%x0, gm%a, gm%b, tk))
         if (ak > pga) then
            pga = ak
            t_pga = tk
         end if
      case ('record')
         i = maxloc(abs(gm%accel), dim=1)
         pga = abs(gm%accel(i))
         t_pga = gm%time(i)
      end select
   end subroutine peak_ground_accel

   !> One line describing the ground motion, for the listing.
   function describe_ground(gm) result(text)
      !> Ground motion.
      type(ground_motion_t), intent(in) :: gm
      character(len=:), allocatable :: text
      real(dp) :: pga, t_pga
      integer :: n

      call peak_ground_accel(gm, pga, t_pga)
      select case (gm%kind)
      case ('pulse')
         text = 'pulse x_g(t) = '//str(gm%x0)//' m * exp(-'//str(gm%a)//' t) * sin('// &
                str(gm%b)//' t)'
      case ('record')
         n = size(gm%time)
         text = 'record '//gm%path//' ('//gm%format//', '//str(n)//' points'
         if (gm%dt > 0.0_dp) text = text//', dt = '//str(gm%dt)//' s'
         text = text//', '//str(gm%time(1))//' to '//str(gm%time(n))//' s, zero after), '// &
                'scale '//str(gm%scale)
      case default
         text = 'no ground motion'
         return
      end select
      text = text//'; PGA '//str(pga)//' m/s^2 = '//str(pga/g_accel)//' g at t = '// &
             str(t_pga)//' s'
      if (gm%angle /= 0.0_dp .or. allocated(gm%time_2)) text = text//'; along '//str(gm%angle)//' degrees from x'
      if (allocated(gm%time_2)) then
         n = size(gm%time_2)
         pga = maxval(abs(gm%accel_2))
         text = text//'; component 2 (at '//str(gm%angle + 90.0_dp)//' degrees): record '//gm%path_2// &
                ' ('//gm%format_2//', '//str(n)//' points'
         if (gm%dt_2 > 0.0_dp) text = text//', dt = '//str(gm%dt_2)//' s'
         text = text//', '//str(gm%time_2(1))//' to '//str(gm%time_2(n))//' s, zero after), scale '// &
                str(gm%scale_2)//'; PGA '//str(pga)//' m/s^2 = '//str(pga/g_accel)//' g'
      end if
   end function describe_ground

   !> Linear interpolation of a record (sample times `time`, accelerations `accel`, even step
   !> `dt` or 0 for explicit times) at t; 0 outside [first sample, last sample].
   pure function record_value(time, accel, dt, t) result(ag)
      real(dp), intent(in) :: time(:), accel(:)
      real(dp), intent(in) :: dt, t
      real(dp) :: ag
      real(dp) :: s, w
      integer :: n, i, lo, hi, mid

      ag = 0.0_dp
      n = size(time)
      if (dt > 0.0_dp) then
         ! Even steps: fractional sample index s, sample i+1 at s = i.
         s = (t - time(1))/dt
         if (.not. (s > -1.0_dp .and. s < real(n, dp))) return
         i = nint(s)
         if (abs(s - real(i, dp)) <= snap) then
            if (i >= 0 .and. i <= n - 1) ag = accel(i + 1)
            return
         end if
         if (s < 0.0_dp .or. s > real(n - 1, dp)) return
         i = min(int(s), n - 2)
         w = s - real(i, dp)
         ag = (1.0_dp - w)*accel(i + 1) + w*accel(i + 2)
      else
         ! Explicit times: bisection for time(lo) <= t < time(hi).
         if (t < time(1) - snap*(time(2) - time(1))) return
         if (t > time(n) + snap*(time(n) - time(n - 1))) return
         if (t <= time(1)) then
            ag = accel(1)
            return
         end if
         if (t >= time(n)) then
            ag = accel(n)
            return
         end if
         lo = 1
         hi = n
         do while (hi - lo > 1)
            mid = (lo + hi)/2
            if (time(mid) <= t) then
               lo = mid
            else
               hi = mid
            end if
         end do
         w = (t - time(lo))/(time(hi) - time(lo))
         ag = (1.0_dp - w)*accel(lo) + w*accel(hi)
      end if
   end function record_value

end module pound_ground_motion
