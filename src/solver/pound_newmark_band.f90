!> The banded path of the Newmark step (half-bandwidth > 1, or a ground-influence vector
!> that is not all ones): right-hand side and dpbtrs, the update, C v by a band product and
!> the energies. A unit of its own, so that it does not change how the tridiagonal step
!> (pound_newmark_step) is compiled.
submodule(pound_newmark) pound_newmark_band
   implicit none

contains

   !> The general (banded) path of `newmark_predict`: the right-hand side, then dpbtrs.
   module subroutine predict_general(st, b, dag)
      type(newmark_state), intent(inout) :: st
      type(structure_model), intent(in) :: b
      real(dp), intent(in) :: dag
      integer :: info

      st%du = b%mass*(2.0_dp*st%c2*st%v + 2.0_dp*st%a - b%ground*dag) + 2.0_dp*st%cv
      call dpbtrs('U', st%n, st%kd, 1, st%chol, st%kd + 1, st%du, st%n, info)
   end subroutine predict_general

   !> The general (banded) path of `newmark_commit`: the Newmark update, C v by a band
   !> product, sum(m r du), du.(Cv_old + Cv_new) and the kinetic and strain energy.
   module subroutine commit_general(st, b, mdu, ddamp)
      type(newmark_state), intent(inout) :: st
      type(structure_model), intent(in) :: b
      real(dp), intent(out) :: mdu, ddamp

      st%a = st%c1*st%du - 2.0_dp*st%c2*st%v - st%a
      st%v = st%c2*st%du - st%v
      st%u = st%u + st%du
      mdu = sum(b%mass*b%ground*st%du)
      call band_symv(b%kt, st%v, st%work)
      st%work = b%a0*b%mass*st%v + b%a1*st%work
      ddamp = dot_product(st%du, st%cv + st%work)
      st%cv = st%work
      st%kinetic = 0.5_dp*sum(b%mass*st%v**2)
      if (allocated(b%strain_weight)) then
         st%strain = structure_strain_energy(b, st%u)
      else
         call band_symv(b%kt, st%u, st%work)
         st%strain = 0.5_dp*dot_product(st%u, st%work)
      end if
   end subroutine commit_general

end submodule pound_newmark_band
