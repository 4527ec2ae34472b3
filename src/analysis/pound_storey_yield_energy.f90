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
   pure module subroutine yield_energy_step(ys, output, coupled, i_strain, i_plastic, stored, sample, e_out)
      !> The buildings' storeys after the step's commit.
      type(storey_yield_set), intent(in) :: ys(:)
      !> An output step; a coupled analysis.
      logical, intent(in) :: output, coupled
      !> Positions of the strain energy and of the plastic work in a sample.
      integer, intent(in) :: i_strain, i_plastic
      !> The stored output sample, the step's sample (kJ; at least as long).
      real(dp), intent(inout) :: stored(:), sample(:)
      !> The integrators' sum kinetic + strain + damping of an uncoupled step (kJ).
      real(dp), intent(inout) :: e_out

      if (output) then
         call yield_energy_terms(ys, stored(i_strain), stored(i_plastic))
         ! (The sample may hold more terms than the stored history: HHT's numerical dissipation.)
         sample(1:size(stored)) = stored
      else if (coupled) then
         call yield_energy_terms(ys, sample(i_strain), sample(i_plastic))
      else
         e_out = e_out - yield_load_work(ys)
      end if
   end subroutine yield_energy_step

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
      integer :: ib, j

      do ib = 1, size(ys)
         do j = 1, ys(ib)%n
            associate (k => ys(ib)%k(j), d => ys(ib)%d(j), p => ys(ib)%p(j))
               strain = strain + 0.5_dp*k*((d - p)**2 - d**2)
               if (ys(ib)%hinges) strain = strain + 0.5_dp*ys(ib)%kc(j)* &
                                           ((d - p)*(ys(ib)%d(ys(ib)%mate(j)) - ys(ib)%p(ys(ib)%mate(j))) - &
                                            d*ys(ib)%d(ys(ib)%mate(j)))
            end associate
         end do
         plastic = plastic + ys(ib)%hysteretic
      end do
   end subroutine yield_energy_terms

end submodule pound_storey_yield_energy
