!> The element set of the complementarity core: a set of rows, each a sparse vector b_i over
!> the DOFs of one model, whose multipliers z_i >= 0 are complementary to w_i >= 0 in each
!> step. An extension (the bilinear storeys and the plastic hinges of `pound_storey_yield`)
!> supplies
!>
!> - its rows: how many (`set_rows`), each row's values b_i^T x of a DOF vector
!>   (`row_value`) and its scatter x += s b_i (`row_scatter`); the column Khat^{-1} a_i of a
!>   row comes from the integrator's `solve` of the row's load (`set_column`);
!> - its LCP block over the rows in the step's LCP: the diagonal block M_AA and the vector
!>   q_A (`lcp_block`), assembled from those columns into the set's own dense LCP (`lcp`);
!> - the check of a solved step over every row (the natural residual, `check`);
!> - the commit of an accepted step (`commit`) and its energy terms (`energy`: the strain
!>   energy beyond the elastic structure's and the dissipated energy).
!>
!> The couplings between sets (and with the joints' rows) are B_i^T Khat^{-1} B_j, formed
!> from the same columns. The solvers the sets' LCPs use live beside this module in
!> `src/lcp/` (`pound_lemke`, `pound_lcp_active_set`, `pound_lcp_enumerate`, and the dense
!> problem with its storage `pound_lcp_dense`).
module pound_complementarity_set
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_integrator, only: integrator
   use pound_lcp_dense, only: dense_lcp
   implicit none
   private

   public :: complementarity_set

   !> An element set of complementarity rows (abstract).
   type, abstract :: complementarity_set
      !> The set's own LCP (its rows in the step's LCP: `lcp_block` assembles it).
      type(dense_lcp) :: lcp
   contains
      !> Rows of the set.
      procedure(set_rows_i), deferred :: set_rows
      !> b_i^T x: row i's value of a DOF vector.
      procedure(row_value_i), deferred :: row_value
      !> x += s b_i: row i scattered into a DOF vector.
      procedure(row_scatter_i), deferred :: row_scatter
      !> Khat^{-1} a_i: the response to row i's load per unit multiplier.
      procedure(set_column_i), deferred :: set_column
      !> The diagonal block and the vector of the rows in the step's LCP.
      procedure(lcp_block_i), deferred :: lcp_block
      !> The natural residual of a solved step over every row.
      procedure(check_i), deferred :: check
      !> Commit an accepted step.
      procedure(commit_i), deferred :: commit
      !> The set's energy terms.
      procedure(energy_i), deferred :: energy
   end type complementarity_set

   abstract interface
      pure integer function set_rows_i(set)
         import :: complementarity_set
         class(complementarity_set), intent(in) :: set
      end function set_rows_i

      pure real(dp) function row_value_i(set, i, x)
         import :: complementarity_set, dp
         class(complementarity_set), intent(in) :: set
         !> The row and the DOF vector.
         integer, intent(in) :: i
         real(dp), intent(in) :: x(:)
      end function row_value_i

      pure subroutine row_scatter_i(set, i, s, x)
         import :: complementarity_set, dp
         class(complementarity_set), intent(in) :: set
         !> The row and its factor.
         integer, intent(in) :: i
         real(dp), intent(in) :: s
         !> The DOF vector (s b_i added).
         real(dp), intent(inout) :: x(:)
      end subroutine row_scatter_i

      subroutine set_column_i(set, st, i, x)
         import :: complementarity_set, integrator, dp
         class(complementarity_set), intent(inout) :: set
         !> The building's integrator (its factored Khat).
         class(integrator), intent(in) :: st
         !> The row.
         integer, intent(in) :: i
         !> Khat^{-1} a_i.
         real(dp), intent(out) :: x(:)
      end subroutine set_column_i

      subroutine lcp_block_i(set, st, m)
         import :: complementarity_set, integrator
         !> The set (its LCP's mat(1:m, 1:m) and q(1:m) set).
         class(complementarity_set), intent(inout) :: set
         !> The building's integrator (the columns).
         class(integrator), intent(in) :: st
         !> Rows of the set in the step's LCP.
         integer, intent(in) :: m
      end subroutine lcp_block_i

      subroutine check_i(set, t, step, label, error)
         import :: complementarity_set, error_type, dp
         class(complementarity_set), intent(inout) :: set
         !> Time, step and the model's name, for the message.
         real(dp), intent(in) :: t
         integer, intent(in) :: step
         character(len=*), intent(in) :: label
         !> Error state: the residual is above the set's limit.
         type(error_type), allocatable, intent(out) :: error
      end subroutine check_i

      pure subroutine commit_i(set, u, t, shear)
         import :: complementarity_set, dp
         class(complementarity_set), intent(inout) :: set
         !> Committed displacements and time.
         real(dp), intent(in) :: u(:)
         real(dp), intent(in) :: t
         !> An output step's history column that the set's forces replace.
         real(dp), intent(inout), optional :: shear(:)
      end subroutine commit_i

      pure subroutine energy_i(set, strain, dissipated)
         import :: complementarity_set, dp
         class(complementarity_set), intent(in) :: set
         !> Strain energy (the set's change to the elastic structure's) and dissipated energy
         !> (kJ), added to.
         real(dp), intent(inout) :: strain, dissipated
      end subroutine energy_i
   end interface

end module pound_complementarity_set
