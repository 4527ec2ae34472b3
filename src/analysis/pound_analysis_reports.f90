!> The cold part of pound_analysis: the result copy (`analysis_copy`), the warnings and their
!> text (the uncoupled audit warning, the substep and exact-step lines, the warning lines of a
!> listing, the coupled audit's unresolved joints) and the diagnostics of a step whose energy
!> sum is not finite (`state_failure`, `locate_nonfinite`). Nothing here runs in a step
!> that succeeds: the time loop and what it calls stay in the parent module.
submodule(pound_analysis) pound_analysis_reports
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_strings, only: mm_text
   use pound_structure, only: building_label => structure_label
   use pound_contact_pair, only: end_mass
   implicit none

contains

   !> dst = src, component by component, every one of them (the warnings, an array of
   !> deferred-length strings, line by line: gfortran 12 does not copy such a component of a
   !> derived type reliably). Whatever a result holds must be copied here: a suite hands its
   !> motions' uncoupled results to their runs at other gaps by this copy, and a part left
   !> out (the bilinear storeys' and hinges' `yielding` was) is silently missing there.
   module procedure analysis_copy
      integer :: i

      dst%n_steps = src%n_steps
      dst%n_out = src%n_out
      dst%time = src%time
      dst%building = src%building
      dst%energy = src%energy
      if (allocated(src%numerical)) dst%numerical = src%numerical
      if (allocated(src%integrator)) dst%integrator = src%integrator
      dst%energy_error = src%energy_error
      dst%joints = src%joints
      dst%seconds = src%seconds
      dst%contact_seconds = src%contact_seconds
      dst%write_seconds = src%write_seconds
      dst%substep_factor = src%substep_factor
      dst%substepped = src%substepped
      dst%substeps = src%substeps
      dst%substep = src%substep
      dst%exact_steps = src%exact_steps
      dst%closed_steps = src%closed_steps
      if (allocated(src%yielding)) dst%yielding = src%yielding
      allocate (character(len=1) :: dst%warnings(0))
      if (.not. allocated(src%warnings)) return
      do i = 1, size(src%warnings)
         call add_warning(dst%warnings, trim(src%warnings(i)))
      end do
   end procedure analysis_copy

   !> The warning of an uncoupled run whose relative audit residual `err` exceeds
   !> `audit_warning_limit`.
   module procedure uncoupled_audit_warning
      text = 'energy audit (uncoupled): relative residual '//str(err)//' > '//str(audit_warning_limit)// &
             ' without contact: the integration is not trustworthy; reduce dt'
   end procedure uncoupled_audit_warning

   !> The substeps an analysis with `stepping = 'impact'` took, as one line of text.
   module procedure substep_text
      text = 'm = '//str(res%substep_factor)//' substeps of '//str(res%substep)//' s; '// &
             str(res%substepped)//' of '//str(res%n_steps)//' steps substepped, '//str(res%substeps)// &
             ' substeps taken ('//str(res%n_steps - res%substepped + res%substeps)//' steps in all)'
   end procedure substep_text

   !> The steps an analysis with `free_steps = 'exact'` took exactly, as one line of text.
   module procedure exact_text
      text = str(res%exact_steps)//' of '//str(res%n_steps)//' steps exact (no joint acting), '// &
             str(res%n_steps - res%exact_steps)//" by Newmark's method"
      if (res%substep_factor > 0) text = text//' in substeps'
      if (res%closed_steps > 0) text = str(res%exact_steps - res%closed_steps)//' of '//str(res%n_steps)// &
                                       ' steps exact with no joint acting, '//str(res%closed_steps)// &
                                       ' exact with elastic joints closed, '//str(res%n_steps - res%exact_steps)// &
                                       " by Newmark's method in substeps"
   end procedure exact_text

   !> Write each warning of a list (e.g. `res%warnings`, `sweep%warnings`) as one line, `prefix`
   !> first (e.g. 'pound: warning: '); nothing for an empty or unallocated list.
   module procedure write_warnings
      integer :: i

      if (.not. allocated(warnings)) return
      do i = 1, size(warnings)
         write (unit, '(a)') prefix//trim(warnings(i))
      end do
   end procedure write_warnings

   !> m_eff = m1 m2/(m1 + m2) of a joint's facing floor masses (the mass of the one
   !> building against a rigid neighbour) (t).
   module procedure effective_mass
      real(dp) :: m(2)
      integer :: e

      do e = 1, 2
         m(e) = 0.0_dp
         if (p%building(e) > 0) m(e) = end_mass(p, e, models(p%building(e))%mass)
      end do
      if (m(1) > 0.0_dp .and. m(2) > 0.0_dp) then
         meff = m(1)*m(2)/(m(1) + m(2))
      else
         meff = max(m(1), m(2))
      end if
      ! A contact point of buildings in plan with the share s of its pair (its law's force
      ! scaled by s) against the share s of the masses: the pair's half-period.
      meff = p%share*meff
   end procedure effective_mass

   !> The audit residual is large: name the joints whose contact half-period pi sqrt(m_eff/k0)
   !> (m_eff = m1 m2/(m1 + m2) of the facing floor masses) spans fewer than `resolved_steps`
   !> steps, and the dt that would resolve them (a tenth of the half-period).
   module procedure warn_unresolved_joints
      real(dp) :: meff, half, worst
      integer :: k, found, kw
      character(len=:), allocatable :: head

      head = 'energy audit (coupled): relative residual '//str(res%energy_error)//' > '// &
             str(audit_warning_limit)
      found = 0
      worst = huge(1.0_dp)
      kw = 0
      do k = 1, cs%m
         associate (p => cs%pair(k))
            if (cs%joint(k)%impacts == 0) cycle
            meff = effective_mass(p, models)
            half = contact_half_period(p, models)
            if (half < worst) then
               worst = half
               kw = k
            end if
            if (half >= resolved_steps*dt) cycle
            found = found + 1
            if (allocated(p%law%given)) then
               if (p%law%given%has_force()) then
                  ! A smooth law (issue 26): its contact duration (`contact_half_period`).
                  call add_warning(res%warnings, head//': joint '//p%label//' (law '''//p%law%title()// &
                                   ''', m_eff = '//str(meff)//' t of the facing floors) has a contact duration '// &
                                   str(half)//' s at '//str(substep_impact_speed)//' m/s, '//str(half/dt)// &
                                   ' steps of dt = '//str(dt)//' s: not resolved by dt; dt = '//str(0.1_dp*half)// &
                                   ' s (a tenth of it) would resolve it')
                  cycle
               end if
            end if
            call add_warning(res%warnings, head//': joint '//p%label//' (k0 = '//str(p%law%stiffness)// &
                             ' kN/m, m_eff = '//str(meff)//' t of the facing floors) has a contact '// &
                             'half-period pi sqrt(m_eff/k0) = '//str(half)//' s, '//str(half/dt)// &
                             ' steps of dt = '//str(dt)//' s: not resolved by dt; dt = '//str(0.1_dp*half)// &
                             ' s (a tenth of it) would resolve it; k0 itself is uncertain: a stiffness '// &
                             "study (&sweep parameter = 'stiffness', or a law study, &contact variant) "// &
                             'shows how much the lambdas and impact forces depend on it')
         end associate
      end do
      if (found > 0) return
      if (kw > 0) then
         call add_warning(res%warnings, head//': the impacts are resolved (shortest contact half-period '// &
                          str(worst)//' s at joint '//cs%pair(kw)%label//', '//str(worst/dt)// &
                          ' steps); contact opening and closing inside the steps dominates: reduce dt')
      else
         call add_warning(res%warnings, head//': reduce dt')
      end if
   end procedure warn_unresolved_joints

   !> The energy sum of a step is not finite: name the first non-finite value (building and
   !> floor, or joint), or else the building and energy term that overflowed, with the largest
   !> ground acceleration so far.
   module procedure state_failure
      character(len=*), parameter :: term(n_integrator_energies) = [character(len=21) :: 'input', 'kinetic', &
                                                                    'strain', 'damping', 'numerical dissipation']
      real(dp) :: e(n_integrator_energies), t
      integer :: ib, i
      character(len=:), allocatable :: hint

      t = real(step, dp)*dt
      call locate_nonfinite(st, models, cs, t, step, error)
      if (allocated(error)) return
      hint = ': the response overflows (ground acceleration up to '//str(maxval(abs(ag(0:step))))// &
             ' m/s^2 so far); check the size of the ground motion (&ground), the masses and the stiffnesses'
      do ib = 1, size(st)
         e = st(ib)%energies()
         do i = 1, n_integrator_energies
            if (ieee_is_finite(e(i))) cycle
            call fatal_error(error, building_label(models(ib))//': the '//trim(term(i))// &
                             ' energy is not finite at t = '//str(t)//' s (step '//str(step)//') ('// &
                             str(e(i))//' kJ, largest |u| '//mm_text(maxval(abs(st(ib)%u_view())))//')'//hint)
            call error_at(error, t, step, building=ib)
            return
         end do
      end do
      do i = 1, n_energy
         if (ieee_is_finite(sample(i))) cycle
         call fatal_error(error, 'energy audit failed at t = '//str(t)//' s (step '//str(step)//'): the '// &
                          trim(energy_names(i))//' energy is not finite ('//str(sample(i))//' kJ)'//hint)
         call error_at(error, t, step)
         return
      end do
      call fatal_error(error, 'energy audit failed at t = '//str(t)//' s (step '//str(step)//'): the '// &
                       'energy total overflows'//hint)
      call error_at(error, t, step)
   end procedure state_failure

   !> Set `error` to the first value of the state that is not finite, if there is one: u, v,
   !> a (and, if `predicted`, the step's increment du) of every building by floor, then every
   !> joint's force, compression, rate, plastic penetration and closing displacement. An
   !> `error` passed in is kept when everything is finite.
   module procedure locate_nonfinite
      character(len=*), parameter :: names(4) = ['u ', 'v ', 'a ', 'du']
      character(len=*), parameter :: joint(5) = [character(len=20) :: 'force r', 'compression d', &
                                                 'compression rate', 'plastic penetration', &
                                                 'closing displacement']
      real(dp) :: x(5)
      real(dp), pointer, contiguous :: col(:)
      integer :: ib, i, q, nq, k
      character(len=:), allocatable :: at

      at = ' is not finite at t = '//str(t)//' s (step '//str(step)//')'
      nq = 3
      if (present(predicted)) then
         if (predicted) nq = 4
      end if
      ! The state first (u, v, a of every floor), then the step's increment it feeds.
      do q = 1, nq
         do ib = 1, size(st)
            select case (q)
            case (1)
               col => st(ib)%u_view()
            case (2)
               col => st(ib)%v_view()
            case (3)
               col => st(ib)%a_view()
            case default
               col => st(ib)%du_view()
            end select
            do i = 1, st(ib)%dofs()
               x(1) = col(i)
               if (ieee_is_finite(x(1))) cycle
               if (allocated(error)) deallocate (error)
               call fatal_error(error, building_label(models(ib))//': floor '//str(i)//': '//trim(names(q))// &
                                ' = '//str(x(1))//at//': the first value of the run that is not finite '// &
                                '(check the size of the ground motion, masses, stiffnesses and joints)')
               call error_at(error, t, step, building=ib)
               return
            end do
         end do
      end do
      do k = 1, cs%m
         associate (p => cs%joint(k))
            x = [p%r, p%d, p%ddot, p%plastic, p%v]
            do q = 1, 5
               if (ieee_is_finite(x(q))) cycle
               if (allocated(error)) deallocate (error)
               call fatal_error(error, 'contact '//cs%pair(k)%label//': joint '//trim(joint(q))//' = '//str(x(q))//at// &
                                ': the first value of the run that is not finite (check the joint''s '// &
                                'stiffness, dashpot and law)')
               call error_at(error, t, step, joint=k)
               return
            end do
         end associate
      end do
   end procedure locate_nonfinite

end submodule pound_analysis_reports
