!> The motions of a suite: each `&ground` built and scaled as it is run.
!>
!> Per motion k:
!> 1. the motion: a pulse or a record (`deck_ground_motion`'s kinds), or a synthetic motion
!>    (`pound_synthetic_motion`, sampled at the analysis step `dt`);
!> 2. its scaling: the factor `scale` (records: applied on reading; synthetic: applied here), or
!>    `scale_to = 'pga'` / `'sa'`: the factor f = target/PGA or target/Sa(T) (5 % damping,
!>    T = `period`, by default the fundamental period of the most flexible building) of the
!>    motion as the solver samples it, a_g(n dt), n = 0..n_steps. A scaled motion is run as
!>    the samples f a_g(n dt) (a record of step dt, linear between samples: what the solver saw
!>    before scaling, times f), so it meets its target up to rounding. A motion with a second
!>    component is scaled on component 1 (its samples along the motion's direction), and the
!>    factor scales component 2 too, which keeps its own samples. A pulse or record without
!>    `scale_to` is run as it is: a suite of one is today's single run, bit for bit.
module pound_suite_motions
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_config, only: deck_type, ground_config
   use pound_deck_variables, only: word_len
   use pound_strings, only: str
   use pound_ground_motion, only: ground_motion_t, sample_ground, stop_ground, first_component, set_ground_angle, &
                                  take_second_component
   use pound_synthetic_motion, only: synthetic_config, synthetic_motion
   use pound_structure, only: structure_model, structure_names
   use pound_contact, only: contact_pair, pairs_from_config
   use pound_spectrum, only: scale_to_pga, scale_to_sa
   use pound_run_case, only: configured_motion
   use pound_building, only: build_building, building_model
   use pound_analysis_plan, only: steps_of
   implicit none
   private

   public :: suite_motion_setup
   public :: suite_motion, suite_motion_samples, single_motion, motion_names, motion_sources, n_spectrum, spectrum_damping

   !> Log-spaced periods of the suite spectra (before the buildings' periods are added).
   integer, parameter :: n_spectrum = 60
   !> Damping ratio of the spectra and of `scale_to = 'sa'`.
   real(dp), parameter :: spectrum_damping = 0.05_dp

contains

   !> The ground motion k of the suite as it is run, and the factor the suite applied to it.
   subroutine suite_motion(deck, k, models, gm, factor, error)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Motion index in `deck%motions`.
      integer, intent(in) :: k
      !> The buildings (their fundamental periods give the default period of `scale_to = 'sa'`).
      type(structure_model), intent(in) :: models(:)
      !> The motion as run.
      type(ground_motion_t), intent(out) :: gm
      !> Scale factor applied by the suite (1: none, or `scale` of a synthetic motion).
      real(dp), intent(out) :: factor
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(ground_config) :: g
      type(ground_motion_t) :: base
      real(dp), allocatable :: ag(:)
      real(dp) :: dt, period
      integer :: n_steps, i, ib

      g = deck%motions(k)
      dt = deck%analysis%dt
      ! The motion's steps (t_free's free vibration after them does not enter the scaling).
      n_steps = steps_of(deck%analysis%t_end - deck%analysis%t_free, dt)
      factor = 1.0_dp
      if (g%kind == 'synthetic') then
         call synthetic(base, error)
         factor = g%scale
      else
         call configured_motion(g, base, error)
      end if
      if (allocated(error)) then
         error%message = "&ground '"//g%name//"': "//error%message
         return
      end if
      if (len(g%scale_to) == 0 .and. g%kind /= 'synthetic') then
         gm = base
         gm%name = g%name
         if (deck%analysis%t_free > 0.0_dp) call stop_ground(gm, deck%analysis%t_end - deck%analysis%t_free, dt)
         return
      end if
      if (g%kind == 'synthetic') call set_ground_angle(base, g%angle)
      allocate (ag(0:n_steps))
      ! The factor is found on component 1 and scales both.
      call sample_ground(first_component(base), dt, n_steps, ag)
      select case (g%scale_to)
      case ('pga')
         call scale_to_pga(ag, g%target, factor, error)
      case ('sa')
         period = g%period
         if (.not. (period > 0.0_dp)) then
            period = 0.0_dp
            do ib = 1, size(models)
               period = max(period, models(ib)%period(1))
            end do
         end if
         call scale_to_sa(ag, dt, period, spectrum_damping, g%target, factor, error)
      end select
      if (allocated(error)) then
         error%message = "&ground '"//g%name//"': "//error%message
         return
      end if
      gm%kind = 'record'
      gm%path = g%name
      gm%format = g%kind
      gm%title = g%name
      gm%scale = factor
      gm%dt = dt
      gm%time = [(real(i, dp)*dt, i=0, n_steps)]
      gm%accel = factor*ag
      gm%name = g%name
      gm%scaled = len(g%scale_to) > 0
      call take_second_component(gm, base, factor)
      if (deck%analysis%t_free > 0.0_dp) call stop_ground(gm, deck%analysis%t_end - deck%analysis%t_free, dt)

   contains

      subroutine synthetic(s, error)
         type(ground_motion_t), intent(out) :: s
         type(error_type), allocatable, intent(out) :: error
         type(synthetic_config) :: c

         c%filter = g%filter
         c%wg = g%ground_frequency
         c%zg = g%ground_damping
         c%wf = g%filter_frequency
         c%zf = g%filter_damping
         c%envelope = g%envelope
         c%t1 = g%rise_time
         c%t2 = g%plateau_end
         c%c = g%decay_rate
         c%eps = g%peak_fraction
         c%eta = g%end_level
         c%duration = g%duration
         c%pga = g%pga
         c%seed = g%seed
         s%kind = 'record'
         s%path = g%name
         s%format = 'synthetic'
         s%title = g%name
         s%dt = dt
         call synthetic_motion(c, dt, s%accel, error)
         if (allocated(error)) return
         s%time = [(real(i, dp)*dt, i=0, size(s%accel) - 1)]
      end subroutine synthetic

   end subroutine suite_motion

   !> The deck's one motion as run when it is scaled (`scale_to`) or synthetic (`suite_motion`
   !> of motion 1, with the deck's buildings built for the period of `scale_to = 'sa'`): a deck
   !> with a joint study runs it as one case.
   subroutine single_motion(deck, gm, error)
      !> A validated configuration with one `&ground`.
      type(deck_type), intent(in) :: deck
      !> The motion as run.
      type(ground_motion_t), intent(out) :: gm
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(structure_model), allocatable :: models(:)
      type(building_model), allocatable :: kinds(:)
      real(dp) :: factor
      integer :: ib

      allocate (models(size(deck%buildings)), kinds(size(deck%buildings)))
      do ib = 1, size(models)
         call build_building(deck%buildings(ib), models(ib), kinds(ib), error)
         if (allocated(error)) return
      end do
      call suite_motion(deck, 1, models, gm, factor, error)
   end subroutine single_motion

   !> Motion k as run (`suite_motion`) and its ground accelerations at t_n = n dt,
   !> n = 0..size(ag) - 1 (m/s^2).
   subroutine suite_motion_samples(deck, k, models, gm, factor, ag, error)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Motion index in `deck%motions`.
      integer, intent(in) :: k
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The motion as run.
      type(ground_motion_t), intent(out) :: gm
      !> Scale factor applied by the suite.
      real(dp), intent(out) :: factor
      !> The samples.
      real(dp), intent(out) :: ag(0:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error

      call suite_motion(deck, k, models, gm, factor, error)
      if (allocated(error)) return
      call sample_ground(gm, deck%analysis%dt, size(ag) - 1, ag)
   end subroutine suite_motion_samples

   !> "&ground 'name'" and `suffix` for every motion of the deck (the names of its cases).
   !> With `which`, those motions only; with `bare`, blank names (the cases' messages name their
   !> motion themselves).
   pure function motion_names(deck, suffix, which, bare) result(names)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Put after each name.
      character(len=*), intent(in) :: suffix
      !> Motion indices (default: every motion).
      integer, intent(in), optional :: which(:)
      !> Blank names.
      logical, intent(in), optional :: bare
      character(len=word_len + 12 + len(suffix)), allocatable :: names(:)
      integer, allocatable :: m(:)
      integer :: i

      if (present(which)) then
         allocate (m(size(which)))
         m = which
      else
         allocate (m(size(deck%motions)))
         m = [(i, i=1, size(deck%motions))]
      end if
      allocate (names(size(m)))
      names = ''
      if (present(bare)) then
         if (bare) return
      end if
      do i = 1, size(m)
         names(i) = "&ground '"//deck%motions(m(i))%name//"'"//suffix
      end do
   end function motion_names

   !> Where each motion of the deck comes from and its scaling target, as the writers name them:
   !> its name, its source (the record file as resolved, 'synthetic, seed N' or 'pulse'), the
   !> target (m/s^2; -1: scaled by a factor) and its period (s: a Sa target's, by default the
   !> longest of the buildings' fundamental periods; 0 for a PGA target, the rigid limit of the
   !> spectrum; -1: none).
   pure subroutine motion_sources(deck, building_period, names, source, target, target_period)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Fundamental period of every building (s).
      real(dp), intent(in) :: building_period(:)
      !> Per motion: name and source.
      character(len=*), intent(out) :: names(:), source(:)
      !> Per motion: target and its period.
      real(dp), intent(out) :: target(:), target_period(:)
      integer :: k

      do k = 1, size(deck%motions)
         names(k) = deck%motions(k)%name
         select case (deck%motions(k)%kind)
         case ('record')
            source(k) = deck%motions(k)%file
         case ('synthetic')
            source(k) = 'synthetic, seed '//str(deck%motions(k)%seed)
         case default
            source(k) = deck%motions(k)%kind
         end select
         target(k) = -1.0_dp
         target_period(k) = -1.0_dp
         select case (deck%motions(k)%scale_to)
         case ('pga')
            target(k) = deck%motions(k)%target
            target_period(k) = 0.0_dp
         case ('sa')
            target(k) = deck%motions(k)%target
            target_period(k) = deck%motions(k)%period
            if (.not. (target_period(k) > 0.0_dp)) target_period(k) = maxval(building_period)
         end select
      end do
   end subroutine motion_sources

   !> Motion k of the deck set up for its coupled runs at other gaps (a sweep's, the joints'):
   !> its ground motion and samples at every step (`suite_motion_samples`, indices 0..n_steps)
   !> and the deck's contact pairs.
   subroutine suite_motion_setup(deck, k, models, gm, ag, pairs, error)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> Motion index.
      integer, intent(in) :: k
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The motion as run.
      type(ground_motion_t), intent(out) :: gm
      !> Its ground acceleration at t_n = n dt (m/s^2).
      real(dp), allocatable, intent(out) :: ag(:)
      !> The contact pairs of the deck.
      type(contact_pair), allocatable, intent(out) :: pairs(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: factor

      allocate (ag(0:steps_of(deck%analysis%t_end, deck%analysis%dt)))
      call suite_motion_samples(deck, k, models, gm, factor, ag, error)
      if (allocated(error)) return
      pairs = pairs_from_config(deck%contacts, structure_names(models), error, models)
   end subroutine suite_motion_setup

end module pound_suite_motions
