!> The energy terms of the inelastic buildings (`pound_storey_yield`): the work W_L of the
!> plastic loads in the integrators' balance, and the strain and hysteretic energies of the
!> storeys' springs and of the frames' hinges in the energy samples.
submodule(pound_storey_yield) pound_storey_yield_energy
   implicit none

contains

   !> The energy terms of the step (after the integrators' commits and the sample of the
   !> energies): an output sample `stored` (and `sample`, its copy) or the coupled step's
   !> `sample` gets the storeys' strain and hysteretic energies (`yield_energy_terms`, at the
   !> positions `i_strain`, `i_plastic`); an uncoupled step's integrator sum `e_out` loses W_L.
   module procedure yield_energy_step
      if (output) then
         call yield_energy_terms(ys, stored(i_strain), stored(i_plastic))
         ! (The sample may hold more terms than the stored history: HHT's numerical dissipation.)
         sample(1:size(stored)) = stored
      else if (coupled) then
         call yield_energy_terms(ys, sample(i_strain), sample(i_plastic))
      else
         e_out = e_out - yield_load_work(ys)
      end if
   end procedure yield_energy_step

   !> Total work W_L of the plastic loads of every building (kJ): what the integrators'
   !> balance counts beyond the elastic structure.
   pure module real(dp) function yield_load_work(ys) result(w)
      !> The buildings' storeys.
      type(storey_yield_set), intent(in) :: ys(:)
      integer :: ib

      w = 0.0_dp
      do ib = 1, size(ys)
         w = w + ys(ib)%load_work
      end do
   end function yield_load_work

   !> Turn an energy sample of the elastic integrators into that of the bilinear storeys:
   !> strain energy sum k (d - p)^2 / 2 in place of sum k d^2 / 2, hysteretic energy added to
   !> the plastic work.
   pure module subroutine yield_energy_terms(ys, strain, plastic)
      !> The buildings' storeys.
      type(storey_yield_set), intent(in) :: ys(:)
      !> The sample's strain energy and plastic work (kJ).
      real(dp), intent(inout) :: strain, plastic
      integer :: ib

      do ib = 1, size(ys)
         call storey_energy(ys(ib), strain, plastic)
      end do
   end subroutine yield_energy_terms

   !> The set's energy terms (`complementarity_set%energy`): strain energy sum k (d - p)^2 / 2
   !> in place of sum k d^2 / 2 (hinges: with the coupling kc to the element's other end),
   !> hysteretic energy added to the dissipated energy.
   pure module subroutine storey_energy(set, strain, dissipated)
      class(storey_yield_set), intent(in) :: set
      real(dp), intent(inout) :: strain, dissipated
      integer :: j

      do j = 1, set%n
         associate (k => set%k(j), d => set%d(j), p => set%p(j))
            strain = strain + 0.5_dp*k*((d - p)**2 - d**2)
            if (set%hinges) strain = strain + 0.5_dp*set%kc(j)*((d - p)*(set%d(set%mate(j)) - set%p(set%mate(j))) - &
                                                               d*set%d(set%mate(j)))
         end associate
      end do
      dissipated = dissipated + set%hysteretic
   end subroutine storey_energy

end submodule pound_storey_yield_energy
