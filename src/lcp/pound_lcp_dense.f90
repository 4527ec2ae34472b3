!> A dense LCP with its storage: the matrix, the vector, the solution and w, the warm-start
!> guess and the reference point, and the Lemke workspace, sized for the largest problem seen
!> (grown, rarely, by doubling). Every element set that assembles a dense per-step LCP holds
!> one (the storeys' and the hinges' LCP, the coupled LCP of joints and inelastic elements):
!> the storage and its growth are written once here.
module pound_lcp_dense
   use pound_kinds, only: dp
   use pound_lemke, only: lemke_workspace, lemke_report, lemke_init, lemke_solve
   implicit none
   private

   public :: dense_lcp, dense_lcp_init, dense_lcp_reserve, dense_lcp_solve

   !> A dense LCP(mat(1:m, 1:m), q(1:m)) and its storage (`m_max` rows).
   type :: dense_lcp
      !> Lemke's workspace (its `m_max`: the rows the storage holds; -1 before `dense_lcp_init`).
      type(lemke_workspace) :: ws
      !> Matrix, vector, solution, w and the reference point (for the choice among solutions).
      real(dp), allocatable :: mat(:, :), q(:), z(:), w(:), ref(:)
      !> Warm-start guess of the active set.
      logical, allocatable :: guess(:)
   end type dense_lcp

contains

   !> Storage for problems of up to `m_max` rows.
   pure subroutine dense_lcp_init(p, m_max)
      !> The problem (storage replaced).
      type(dense_lcp), intent(inout) :: p
      !> Rows it holds.
      integer, intent(in) :: m_max

      call lemke_init(p%ws, m_max)
      if (allocated(p%mat)) deallocate (p%mat, p%q, p%z, p%w, p%ref, p%guess)
      allocate (p%mat(m_max, m_max), p%q(m_max), p%z(m_max), p%w(m_max), p%ref(m_max), p%guess(m_max))
   end subroutine dense_lcp_init

   !> Room for m rows: a problem without storage gets max(m, `first`) rows, a full one grows
   !> to max(m, twice its rows). `grew`: the storage was replaced (its contents lost).
   pure subroutine dense_lcp_reserve(p, m, first, grew)
      !> The problem.
      type(dense_lcp), intent(inout) :: p
      !> Rows needed; rows of a first allocation.
      integer, intent(in) :: m, first
      !> The storage was (re)allocated.
      logical, intent(out), optional :: grew

      if (present(grew)) grew = .false.
      if (p%ws%m_max >= 0 .and. m <= p%ws%m_max) return
      if (present(grew)) grew = .true.
      if (p%ws%m_max < 0) then
         call dense_lcp_init(p, max(m, first))
      else
         call dense_lcp_init(p, max(m, 2*p%ws%m_max))
      end if
   end subroutine dense_lcp_reserve

   !> Lemke's method on the problem's first m rows, warm-started from `guess(1:m)`.
   pure subroutine dense_lcp_solve(p, m, rep)
      !> The assembled problem (z, w set).
      type(dense_lcp), intent(inout) :: p
      !> Rows.
      integer, intent(in) :: m
      !> Lemke's report.
      type(lemke_report), intent(out) :: rep

      call lemke_solve(p%ws, m, p%mat, p%q, p%z, p%w, rep, active_guess=p%guess(1:m))
   end subroutine dense_lcp_solve

end module pound_lcp_dense
