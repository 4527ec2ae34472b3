!> The analyses a deck asks for: the buildings uncoupled (no contact) and coupled.
!>
!> Each building is integrated with Newmark's average acceleration method; in the
!> coupled analysis the contact forces of every step come from the step's LCP
!> (pound_contact). The response record keeps peaks at every step and histories at
!> output steps, and the energy balance
!> W_input = E_kinetic + E_strain + E_damping + E_contact + E_plastic is audited at every
!> output step (E_contact: energy stored in the joints' springs and dissipated by their
!> dashpots; E_plastic: dissipated by the joints' plastic flow).
module pound_analysis
   use iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_config, only: analysis_config
   use pound_shear_building, only: shear_building
   use pound_newmark, only: newmark_state, newmark_init, newmark_predict, newmark_commit, &
                            kinetic_energy, strain_energy
   use pound_response, only: response_record, response_init, response_sample, response_finish
   use pound_contact, only: contact_system, contact_pair, contact_init, contact_step, contact_commit
   implicit none
   private

   public :: analysis_result, run_uncoupled, run_coupled, output_steps
   public :: coupled_model, coupled_prepare, coupled_integrate
   public :: e_input, e_kinetic, e_strain, e_damping, e_contact, e_plastic, n_energy, energy_names

   !> Energy history components.
   integer, parameter :: e_input = 1, e_kinetic = 2, e_strain = 3, e_damping = 4, e_contact = 5
   integer, parameter :: e_plastic = 6
   integer, parameter :: n_energy = 6
   !> Energy component names (HDF5 attribute, listing).
   character(len=*), parameter :: energy_names(n_energy) = &
      [character(len=8) :: 'input', 'kinetic', 'strain', 'damping', 'contact', 'plastic']

   !> Result of one analysis (all buildings).
   type :: analysis_result
      !> Number of steps and of output samples.
      integer :: n_steps = 0, n_out = 0
      !> Output times (s).
      real(dp), allocatable :: time(:)
      !> One record per building, in deck order.
      type(response_record), allocatable :: building(:)
      !> Energy history (n_energy, n_out), summed over the buildings (kJ).
      real(dp), allocatable :: energy(:, :)
      !> Audit: max over output steps of |W_in - sum of the other terms| / max energy scale.
      real(dp) :: energy_error = 0.0_dp
      !> Contact force, closing displacement, joint compression (penetration) and plastic
      !> penetration histories (n_pairs, n_out); coupled only.
      real(dp), allocatable :: contact_force(:, :), contact_closing(:, :)
      real(dp), allocatable :: contact_penetration(:, :), contact_plastic(:, :)
      !> Joint state history (n_pairs, n_out): see `pound_contact` (state_open, ...).
      integer, allocatable :: contact_state(:, :)
      !> Wall-clock time of the time-step loops (s; set-up and output excluded), and the part
      !> of it spent on contact
      !> (forming and solving the step's LCP, applying and committing the forces).
      real(dp) :: seconds = 0.0_dp, contact_seconds = 0.0_dp
   end type analysis_result

   !> What the coupled analysis needs that does not depend on the gaps: the factored
   !> integrators at rest and the condensed constraints (Khat^{-1} B, F). Prepared once,
   !> reused for every gap of a sweep.
   type :: coupled_model
      !> Integrators at t = 0.
      type(newmark_state), allocatable :: st(:)
      !> Contact system at t = 0.
      type(contact_system) :: cs
   end type coupled_model

contains

   !> Number of output samples for n_steps steps stored every `every` steps (t = 0 included).
   pure integer function output_steps(n_steps, every)
      !> Number of time steps.
      integer, intent(in) :: n_steps
      !> Output interval in steps.
      integer, intent(in) :: every

      output_steps = n_steps/every + 1
   end function output_steps

   !> Integrate every building without contact.
   subroutine run_uncoupled(cfg, models, ag, res, error)
      !> `&analysis` settings.
      type(analysis_config), intent(in) :: cfg
      !> The buildings.
      type(shear_building), intent(in) :: models(:)
      !> Ground acceleration at t_n = n dt, n = 0..n_steps (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The result.
      type(analysis_result), intent(out) :: res
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(newmark_state) :: st
      integer :: ib, step, k, every
      integer(int64) :: c0, c1, rate
      logical :: out

      res%seconds = 0.0_dp
      call start_result(res, cfg, size(ag) - 1, size(models))
      every = cfg%output_every

      do ib = 1, size(models)
         call newmark_init(st, models(ib), cfg%dt, ag(0), error)
         if (allocated(error)) return
         call response_init(res%building(ib), models(ib)%n, cfg%store, res%n_out)
         call response_sample(res%building(ib), models(ib), st%u, st%v, st%a, ag(0), 0.0_dp, .true.)
         k = 1
         call system_clock(c0, rate)
         do step = 1, res%n_steps
            call newmark_predict(st, models(ib), ag(step) - ag(step - 1))
            call newmark_commit(st, models(ib), ag(step - 1), ag(step))
            out = mod(step, every) == 0
            call response_sample(res%building(ib), models(ib), st%u, st%v, st%a, ag(step), &
                                 real(step, dp)*cfg%dt, out)
            if (out) then
               k = k + 1
               call add_structure_energy(res%energy(:, k), st, models(ib))
            end if
         end do
         call system_clock(c1)
         res%seconds = res%seconds + real(c1 - c0, dp)/real(rate, dp)
         call response_finish(res%building(ib), models(ib))
      end do
      res%energy_error = energy_balance_error(res%energy)
   end subroutine run_uncoupled

   !> Integrate all buildings together with the unilateral constraints `pairs`.
   subroutine run_coupled(cfg, models, ag, pairs, res, cs, error)
      !> `&analysis` settings.
      type(analysis_config), intent(in) :: cfg
      !> The buildings.
      type(shear_building), intent(in) :: models(:)
      !> Ground acceleration at t_n = n dt, n = 0..n_steps (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The constraints, at rest and open at t = 0.
      type(contact_pair), intent(in) :: pairs(:)
      !> The result.
      type(analysis_result), intent(out) :: res
      !> The contact system at the end (statistics per pair and of the LCPs).
      type(contact_system), intent(out) :: cs
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(coupled_model) :: prep

      call coupled_prepare(cfg, models, ag(0), pairs, prep, error)
      if (allocated(error)) return
      call coupled_integrate(cfg, models, ag, prep, res, cs, error)
   end subroutine run_coupled

   !> Factor every building's Khat and condense the structure onto the constraints.
   subroutine coupled_prepare(cfg, models, ag0, pairs, prep, error)
      !> `&analysis` settings.
      type(analysis_config), intent(in) :: cfg
      !> The buildings.
      type(shear_building), intent(in) :: models(:)
      !> Ground acceleration at t = 0 (m/s^2).
      real(dp), intent(in) :: ag0
      !> The constraints, at rest and open at t = 0.
      type(contact_pair), intent(in) :: pairs(:)
      !> The prepared model.
      type(coupled_model), intent(out) :: prep
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      integer :: ib

      allocate (prep%st(size(models)))
      do ib = 1, size(models)
         call newmark_init(prep%st(ib), models(ib), cfg%dt, ag0, error)
         if (allocated(error)) return
      end do
      call contact_init(prep%cs, pairs, prep%st, error)
   end subroutine coupled_prepare

   !> The coupled time integration from a prepared model (left unchanged, so that it can be
   !> reused); `gaps`, when given, replace the gaps of the constraints.
   subroutine coupled_integrate(cfg, models, ag, prep, res, cs, error, gaps)
      !> `&analysis` settings.
      type(analysis_config), intent(in) :: cfg
      !> The buildings.
      type(shear_building), intent(in) :: models(:)
      !> Ground acceleration at t_n = n dt, n = 0..n_steps (m/s^2).
      real(dp), intent(in) :: ag(0:)
      !> The prepared model.
      type(coupled_model), intent(in) :: prep
      !> The result.
      type(analysis_result), intent(out) :: res
      !> The contact system at the end (statistics per pair and of the LCPs).
      type(contact_system), intent(out) :: cs
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> Gaps of the constraints (m), one per constraint.
      real(dp), intent(in), optional :: gaps(:)
      type(newmark_state), allocatable :: st(:)
      integer :: ib, step, k, every, nb, ip
      integer(int64) :: c0, c1, rate, ca, cb, c_contact
      real(dp) :: t
      logical :: out

      nb = size(models)
      st = prep%st
      cs = prep%cs
      if (present(gaps)) cs%pair(:)%gap = gaps
      call start_result(res, cfg, size(ag) - 1, nb)
      every = cfg%output_every
      allocate (res%contact_force(cs%m, res%n_out), res%contact_closing(cs%m, res%n_out), &
                res%contact_penetration(cs%m, res%n_out), res%contact_plastic(cs%m, res%n_out), &
                res%contact_state(cs%m, res%n_out))
      res%contact_force(:, 1) = 0.0_dp
      res%contact_closing(:, 1) = 0.0_dp
      res%contact_penetration(:, 1) = 0.0_dp
      res%contact_plastic(:, 1) = 0.0_dp
      res%contact_state(:, 1) = 0
      do ib = 1, nb
         call response_init(res%building(ib), models(ib)%n, cfg%store, res%n_out)
         call response_sample(res%building(ib), models(ib), st(ib)%u, st(ib)%v, st(ib)%a, ag(0), &
                              0.0_dp, .true.)
      end do
      k = 1
      c_contact = 0
      call system_clock(c0, rate)
      do step = 1, res%n_steps
         t = real(step, dp)*cfg%dt
         do ib = 1, nb
            call newmark_predict(st(ib), models(ib), ag(step) - ag(step - 1))
         end do
         call system_clock(ca)
         call contact_step(cs, st, t, step, error)
         call system_clock(cb)
         c_contact = c_contact + (cb - ca)
         if (allocated(error)) return
         out = mod(step, every) == 0
         do ib = 1, nb
            call newmark_commit(st(ib), models(ib), ag(step - 1), ag(step))
            call response_sample(res%building(ib), models(ib), st(ib)%u, st(ib)%v, st(ib)%a, ag(step), &
                                 t, out)
         end do
         call system_clock(ca)
         call contact_commit(cs, st, t, cfg%dt)
         call system_clock(cb)
         c_contact = c_contact + (cb - ca)
         if (out) then
            k = k + 1
            do ib = 1, nb
               call add_structure_energy(res%energy(:, k), st(ib), models(ib))
            end do
            res%energy(e_contact, k) = cs%element_work - cs%plastic_work
            res%energy(e_plastic, k) = cs%plastic_work
            do ip = 1, cs%m
               res%contact_force(ip, k) = cs%pair(ip)%r
               res%contact_closing(ip, k) = cs%pair(ip)%v
               res%contact_penetration(ip, k) = cs%pair(ip)%d
               res%contact_plastic(ip, k) = cs%pair(ip)%plastic
               res%contact_state(ip, k) = cs%pair(ip)%state
            end do
         end if
      end do
      do ib = 1, nb
         call response_finish(res%building(ib), models(ib))
      end do
      res%energy_error = energy_balance_error(res%energy)
      call system_clock(c1)
      res%seconds = real(c1 - c0, dp)/real(rate, dp)
      res%contact_seconds = real(c_contact, dp)/real(rate, dp)
   end subroutine coupled_integrate

   !> Sizes, output times and a zero energy history of a result for `n_steps` steps.
   pure subroutine start_result(res, cfg, n_steps, n_buildings)
      !> The result (set up).
      type(analysis_result), intent(inout) :: res
      !> `&analysis` settings.
      type(analysis_config), intent(in) :: cfg
      !> Number of time steps.
      integer, intent(in) :: n_steps
      !> Number of buildings.
      integer, intent(in) :: n_buildings
      integer :: k

      res%n_steps = n_steps
      res%n_out = output_steps(n_steps, cfg%output_every)
      allocate (res%time(res%n_out), res%building(n_buildings), res%energy(n_energy, res%n_out))
      res%time = [(real((k - 1)*cfg%output_every, dp)*cfg%dt, k=1, res%n_out)]
      res%energy = 0.0_dp
   end subroutine start_result

   !> Add one building's input work and kinetic, strain and damping energy to an energy sample.
   pure subroutine add_structure_energy(sample, st, b)
      !> Energy sample (n_energy).
      real(dp), intent(inout) :: sample(:)
      !> Integrator state.
      type(newmark_state), intent(in) :: st
      !> The building.
      type(shear_building), intent(in) :: b

      sample(e_input) = sample(e_input) + st%input_work
      sample(e_kinetic) = sample(e_kinetic) + kinetic_energy(st, b)
      sample(e_strain) = sample(e_strain) + strain_energy(st, b)
      sample(e_damping) = sample(e_damping) + st%damping_energy
   end subroutine add_structure_energy

   !> Relative energy balance error: max_t |W_in - E_k - E_s - E_d - E_c - E_p| / max_t max(|W_in|, E_k + ... + E_p).
   pure function energy_balance_error(energy) result(err)
      real(dp), intent(in) :: energy(:, :)
      real(dp) :: err, scale, resid
      integer :: k

      scale = 0.0_dp
      resid = 0.0_dp
      do k = 1, size(energy, 2)
         resid = max(resid, abs(energy(e_input, k) - sum(energy(e_kinetic:n_energy, k))))
         scale = max(scale, abs(energy(e_input, k)), sum(energy(e_kinetic:n_energy, k)))
      end do
      if (scale > 0.0_dp) then
         err = resid/scale
      else
         err = 0.0_dp
      end if
   end function energy_balance_error

end module pound_analysis
