!> Explicit interfaces to the LAPACK routines used by the frame models: band Cholesky and
!> LU, the tridiagonal L D L^T factorization and solve (the integrators' tridiagonal kernels),
!> the small dense generalized eigenproblem of a Rayleigh-Ritz step and the selected
!> eigenvalues of a banded generalized eigenproblem (a building in plan's periods)
!> (pound is compiled with -Wimplicit-interface).
module pound_band_lapack
   use pound_kinds, only: dp
   implicit none
   private

   public :: dpbtrf, dpbtrs, dpttrf, dpttrs, dsygv, dgbtrf, dgbtrs, dsbgvx, dlamch

   interface
      !> L D L^T factorization of a symmetric positive definite tridiagonal matrix.
      subroutine dpttrf(n, d, e, info)
         import :: dp
         integer, intent(in) :: n
         real(dp), intent(inout) :: d(*), e(*)
         integer, intent(out) :: info
      end subroutine dpttrf
      !> Solve with the factors of `dpttrf`.
      subroutine dpttrs(n, nrhs, d, e, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, ldb
         real(dp), intent(in) :: d(*), e(*)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpttrs
      !> Cholesky factorization of a symmetric positive definite band matrix.
      subroutine dpbtrf(uplo, n, kd, ab, ldab, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: info
      end subroutine dpbtrf
      !> Solve with the Cholesky factor of dpbtrf.
      subroutine dpbtrs(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
         import :: dp
         character, intent(in) :: uplo
         integer, intent(in) :: n, kd, nrhs, ldab, ldb
         real(dp), intent(in) :: ab(ldab, *)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpbtrs
      !> All eigenpairs of a small dense symmetric-definite generalized eigenproblem.
      subroutine dsygv(itype, jobz, uplo, n, a, lda, b, ldb, w, work, lwork, info)
         import :: dp
         integer, intent(in) :: itype, n, lda, ldb, lwork
         character, intent(in) :: jobz, uplo
         real(dp), intent(inout) :: a(lda, *), b(ldb, *)
         real(dp), intent(out) :: w(*), work(*)
         integer, intent(out) :: info
      end subroutine dsygv
      !> LU factorization of a general band matrix with partial pivoting.
      subroutine dgbtrf(m, n, kl, ku, ab, ldab, ipiv, info)
         import :: dp
         integer, intent(in) :: m, n, kl, ku, ldab
         real(dp), intent(inout) :: ab(ldab, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgbtrf
      !> Solve with the LU factors of dgbtrf.
      subroutine dgbtrs(trans, n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
         import :: dp
         character, intent(in) :: trans
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(dp), intent(in) :: ab(ldab, *)
         integer, intent(in) :: ipiv(*)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dgbtrs
      !> Selected eigenvalues (and optionally eigenvectors) of a symmetric-definite banded
      !> generalized eigenproblem A x = lambda B x.
      subroutine dsbgvx(jobz, range, uplo, n, ka, kb, ab, ldab, bb, ldbb, q, ldq, vl, vu, il, iu, &
                        abstol, m, w, z, ldz, work, iwork, ifail, info)
         import :: dp
         character, intent(in) :: jobz, range, uplo
         integer, intent(in) :: n, ka, kb, ldab, ldbb, ldq, il, iu, ldz
         real(dp), intent(inout) :: ab(ldab, *), bb(ldbb, *)
         real(dp), intent(in) :: vl, vu, abstol
         real(dp), intent(out) :: q(ldq, *), w(*), z(ldz, *), work(*)
         integer, intent(out) :: m, iwork(*), ifail(*), info
      end subroutine dsbgvx
      !> Machine parameters ('S': safe minimum).
      function dlamch(cmach) result(r)
         import :: dp
         character, intent(in) :: cmach
         real(dp) :: r
      end function dlamch
   end interface

end module pound_band_lapack
