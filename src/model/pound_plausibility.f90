!> Plausibility of a model (warnings, not errors): a fundamental period far from the code
!> estimate for the building's height, which usually means a unit mistake, and the inputs to
!> check when a building buckles under its gravity loads.
!>
!> The estimate is EN 1998-1:2004 4.3.3.2.2(3), T = Ct H^(3/4) (H in m above the base, T in
!> s), with Ct from 0.050 (other structures) to 0.085 (steel moment frames). A fundamental
!> period T1 above `period_high` times the largest estimate (0.085 H^0.75) or below
!> `period_low` times the smallest (0.050 H^0.75) is reported. Masses in kg instead of t, or
!> E (or the storey stiffness) in MPa instead of kN/m^2 (kN/m), make T1 sqrt(1000) = 31.6
!> times too long; both together 1000 times; E or stiffness in N/m^2 (N/m) 31.6 times too short.
!>
!> The ground motion as run: a PGA above `pga_high` (2 g) (a record in cm/s^2 read as g is
!> 981 times too strong; a record scaled to Sa(T1) of a period 31.6 times too long gets a
!> huge factor), and a factor of `scale_to` outside `factor_low`..`factor_high` (0.1..10).
module pound_plausibility
   use pound_kinds, only: dp
   use pound_building_spec, only: building_spec
   use pound_strings, only: plain_real, plain_significant
   use pound_constants, only: g_accel
   implicit none
   private

   public :: period_estimate, period_warning, unit_suspects, pga_warning, scale_warning

   !> Ct of EN 1998-1 4.3.3.2.2(3): the smallest (other structures) and the largest (steel
   !> moment-resisting frames).
   real(dp), parameter, public :: ct_low = 0.050_dp, ct_high = 0.085_dp
   !> T1 above `period_high` Ct_high H^0.75 or below `period_low` Ct_low H^0.75 warns.
   real(dp), parameter, public :: period_high = 5.0_dp, period_low = 0.2_dp
   !> A floor mass (t) from this on looks like kg; an E (kN/m^2) below this looks like MPa
   !> (structural steel 2.1e8, concrete 3e7, timber 1e7 kN/m^2; in MPa 2.1e5, 3e4, 1e4).
   real(dp), parameter, public :: kg_like_mass = 1.0e4_dp, mpa_like_e = 1.0e6_dp
   !> A PGA as run above this (in g) is warned.
   real(dp), parameter, public :: pga_high = 2.0_dp
   !> A factor of `scale_to` outside factor_low..factor_high is warned.
   real(dp), parameter, public :: factor_low = 0.1_dp, factor_high = 10.0_dp
   !> The cause named for a period more than 3000 times off the estimate.
   character(len=*), parameter :: beyond_units = 'more than a unit slip: check every mass, load and '// &
      'stiffness input (masses t, E kN/m^2, I m^4, stiffness kN/m, heights m)'
   !> What a buckling refusal asks the user to check (appended to its message).
   character(len=*), parameter, public :: buckling_hint = '; check the units of the inputs (masses in t, '// &
      'gravity loads in kN, E in kN/m^2 (not MPa), I in m^4, storey stiffness in kN/m, heights in m) and '// &
      'whether p_delta is meant: with wrong units P-Delta reports buckling'

contains

   !> Code estimate Ct H^0.75 of the fundamental period (s), H (m) >= 0.
   elemental real(dp) function period_estimate(ct, height) result(t)
      !> Ct (s/m^0.75).
      real(dp), intent(in) :: ct
      !> Building height above its base (m).
      real(dp), intent(in) :: height

      t = ct*height**0.75_dp
   end function period_estimate

   !> The warning for building `name` of height `height` (m) whose fundamental period is
   !> `t1` (s): empty when T1 lies within period_low*0.050 H^0.75 .. period_high*0.085 H^0.75.
   pure function period_warning(name, t1, height, suspects) result(text)
      !> Building name.
      character(len=*), intent(in) :: name
      !> Fundamental period (s) > 0.
      real(dp), intent(in) :: t1
      !> Height above the base (m) > 0.
      real(dp), intent(in) :: height
      !> The inputs that look like a unit mistake (`unit_suspects`; empty: none).
      character(len=*), intent(in), optional :: suspects
      character(len=:), allocatable :: text
      real(dp) :: lo, hi, ratio
      character(len=:), allocatable :: cause, head

      text = ''
      lo = period_estimate(ct_low, height)
      hi = period_estimate(ct_high, height)
      if (.not. (height > 0.0_dp .and. t1 > 0.0_dp)) return
      head = 'building '//name//': fundamental period T1 = '//sig(t1)//' s is '
      if (t1 > period_high*hi) then
         ratio = t1/hi
         if (ratio > 3000.0_dp) then
            cause = beyond_units
         else if (ratio > 300.0_dp) then
            cause = 'masses in kg instead of t and E (or stiffness) in MPa instead of kN/m^2 together '// &
                    '(T x 1000)'
         else if (ratio > 10.0_dp) then
            cause = 'masses in kg instead of t (T x 31.6), or E in MPa (N/mm^2) instead of kN/m^2 or '// &
                    'storey stiffness in kN/mm instead of kN/m (T x 31.6)'
         else
            cause = 'masses too large or stiffness too small (units of mass t, E kN/m^2, I m^4, '// &
                    'stiffness kN/m), or a very flexible structure'
         end if
         if (present(suspects)) then
            if (len(suspects) > 0) cause = suspects//' (each makes T 31.6 times too long)'
         end if
         text = head//sig(ratio)//' times the code estimate Ct H^0.75 = '//sig(hi)//' s (EN 1998-1 '// &
                '4.3.3.2.2, Ct = 0.085, H = '//sig(height)//' m; warned above '//sig(period_high)// &
                ' times): is it real? likely '//cause
      else if (t1 < period_low*lo) then
         ratio = lo/t1
         if (ratio > 3000.0_dp) then
            cause = beyond_units
         else if (ratio > 10.0_dp) then
            cause = 'E in N/m^2 (Pa) instead of kN/m^2 or stiffness in N/m instead of kN/m (T / 31.6), '// &
                    'or masses in t/1000'
         else
            cause = 'masses too small or stiffness too large (units of mass t, E kN/m^2, I m^4, '// &
                    'stiffness kN/m), or a very stiff structure'
         end if
         text = head//'1/'//sig(ratio)//' of the code estimate Ct H^0.75 = '//sig(lo)// &
                ' s (EN 1998-1 4.3.3.2.2, Ct = 0.050, H = '//sig(height)//' m; warned below '// &
                sig(period_low)//' times): is it real? likely '//cause
      end if
   end function period_warning

   !> The inputs of building `cfg` that look like a unit mistake: floor masses of
   !> `kg_like_mass` t or more (kg instead of t), an E below `mpa_like_e` kN/m^2 (MPa instead
   !> of kN/m^2); empty when none does.
   pure function unit_suspects(cfg) result(text)
      !> A building of the deck.
      type(building_spec), intent(in) :: cfg
      character(len=:), allocatable :: text
      real(dp) :: e_min

      text = ''
      if (allocated(cfg%mass)) then
         if (maxval(cfg%mass) >= kg_like_mass) text = 'masses in kg instead of t (mass up to '// &
                                                      plain_real(maxval(cfg%mass))//' t per floor)'
      end if
      e_min = huge(1.0_dp)
      if (allocated(cfg%e_modulus)) e_min = min(e_min, minval(cfg%e_modulus))
      if (allocated(cfg%column_e)) e_min = min(e_min, minval(cfg%column_e))
      if (allocated(cfg%beam_e)) e_min = min(e_min, minval(cfg%beam_e))
      if (e_min < mpa_like_e) then
         if (len(text) > 0) text = text//' and '
         text = text//'E in MPa instead of kN/m^2 (E = '//plain_real(e_min)//' kN/m^2)'
      end if
   end function unit_suspects

   !> The warning for a motion whose PGA as run, `pga` (m/s^2), is above `pga_high` g: empty
   !> otherwise.
   pure function pga_warning(name, pga, scale, scaled, record) result(text)
      !> The `&ground`'s name (blank: not known).
      character(len=*), intent(in) :: name
      !> Peak |a_g| of the motion as run (m/s^2).
      real(dp), intent(in) :: pga
      !> Its scale factor (of `scale`, or computed by `scale_to`).
      real(dp), intent(in) :: scale
      !> Whether the factor was computed by `scale_to`.
      logical, intent(in) :: scaled
      !> Whether the motion is a record or a synthetic motion (not the pulse).
      logical, intent(in) :: record
      character(len=:), allocatable :: text, cause

      text = ''
      if (.not. (pga > pga_high*g_accel)) return
      if (scaled) then
         cause = 'likely a target in the wrong unit (target in m/s^2, target_g in g), or a building period '// &
                 'far too long (masses in kg: see the period warning) that makes Sa(T1) tiny and the factor huge; '// &
                 'check target and the buildings'' units'
      else if (record) then
         cause = 'likely a record in cm/s^2 (gal) read as g (its values are taken in g: give scale = '// &
                 '0.00102 = 1/981 for cm/s^2, 0.102 = 1/9.81 for m/s^2) or a scale in the wrong unit'
      else
         cause = 'likely x0 (m), a (1/s) or b (rad/s) in the wrong unit'
      end if
      text = ground_name(name)//'PGA of the motion as run = '//sig3(pga/g_accel)//' g ('//sig3(pga)// &
             ' m/s^2, scale factor '//sig3(scale)//') is above '//sig3(pga_high)//' g: '//cause
   end function pga_warning

   !> The warning for a factor `factor` of `scale_to` outside factor_low..factor_high: empty
   !> otherwise.
   pure function scale_warning(name, factor) result(text)
      !> The `&ground`'s name (blank: not known).
      character(len=*), intent(in) :: name
      !> The factor `scale_to` computed.
      real(dp), intent(in) :: factor
      character(len=:), allocatable :: text

      text = ''
      if (factor >= factor_low .and. factor <= factor_high) return
      text = ground_name(name)//'scale_to needs a scale factor of '//sig3(factor)//' (outside '// &
             sig3(factor_low)//' to '//sig3(factor_high)//'): likely a unit mistake in the record (cm/s^2 '// &
             'read as g: factor about 0.001), in target (g given as m/s^2: factor 9.81 times too small) '// &
             'or in the buildings (masses in kg: T1 31.6 times too long); check them, or choose a record '// &
             'closer to the target'
   end function scale_warning

   !> "&ground 'name': " ('&ground: ' without a name).
   pure function ground_name(name) result(s)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: s

      if (len_trim(name) > 0) then
         s = "&ground '"//trim(name)//"': "
      else
         s = '&ground: '
      end if
   end function ground_name

   !> `x` with 3 significant digits in plain decimals ('266', '0.00113').
   pure function sig3(x) result(s)
      !> A positive number.
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s

      s = plain_significant(x, 3)
   end function sig3

   !> `x` with 3 significant digits ('18.2', '0.321', '0.659E+07').
   pure function sig(x) result(s)
      !> A positive number.
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=32) :: buf

      write (buf, '(g0.3)') x
      s = trim(adjustl(buf))
   end function sig

end module pound_plausibility
