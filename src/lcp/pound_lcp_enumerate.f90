!> Brute-force solution of small linear complementarity problems by enumeration.
!>
!> LCP(M, q): z >= 0, w = M z + q >= 0, z.w = 0. Every complementary basis is tried:
!> for each active set A (in order of increasing size, then lexicographically) the
!> principal system M_AA z_A = -q_A is solved and kept if the natural residual
!> ||min(z, w)||_inf / ||q||_inf of the result is within tolerance. Costs up to
!> 2^m LU factorisations, so m is limited to `lcp_enum_max_m`. It finds every solution
!> that is a vertex (nonsingular M_AA), whatever the class of M: a reference for tests
!> and a fallback for small non-convex problems on which Lemke's method fails.
module pound_lcp_enumerate
   use pound_kinds, only: dp
   use pound_error, only: error_type, fatal_error
   use pound_strings, only: str
   use pound_lemke, only: lemke_workspace, lemke_init, lcp_principal_solve
   implicit none
   private

   public :: lcp_enumerate, lcp_enum_max_m

   !> Largest problem accepted (2^24 bases).
   integer, parameter :: lcp_enum_max_m = 24

contains

   !> All vertex solutions of LCP(mat, q), m = size(q), by enumerating the 2^m active sets.
   !>
   !> Solutions closer than 1e-9 relative (inf-norm) count once. z receives the first
   !> solution found (the one with the fewest active constraints, ties in lexicographic
   !> order of the active sets), or the one nearest to `reference` if given; z = 0 if none.
   subroutine lcp_enumerate(mat, q, n_solutions, z, solutions, reference, first_only, tol, error)
      !> The matrix M (at least m x m; the leading part is used).
      real(dp), intent(in) :: mat(:, :)
      !> The vector q; its size is the problem size m.
      real(dp), intent(in) :: q(:)
      !> Number of distinct solutions found (0: no vertex solution).
      integer, intent(out) :: n_solutions
      !> Selected solution (first, or nearest to `reference`).
      real(dp), intent(out), optional :: z(:)
      !> All distinct solutions, one per column (m x n_solutions).
      real(dp), allocatable, intent(out), optional :: solutions(:, :)
      !> Point to which the returned z is nearest (inf-norm).
      real(dp), intent(in), optional :: reference(:)
      !> Stop at the first solution found (default false).
      logical, intent(in), optional :: first_only
      !> Acceptance threshold on the natural residual (default 1e-10).
      real(dp), intent(in), optional :: tol
      !> Set if m exceeds `lcp_enum_max_m` or the array sizes do not match.
      type(error_type), allocatable, intent(out) :: error
      type(lemke_workspace) :: ws
      real(dp), allocatable :: found(:, :), grown(:, :), zc(:), wc(:)
      logical, allocatable :: active(:)
      integer, allocatable :: comb(:)
      integer :: m, k, i, j, nearest
      real(dp) :: acc_tol, res, dist, best
      logical :: nonsingular, stop_first, more

      m = size(q)
      n_solutions = 0
      if (m > lcp_enum_max_m) then
         call fatal_error(error, 'lcp_enumerate: m = '//str(m)//' exceeds the limit of '// &
                          str(lcp_enum_max_m))
         return
      end if
      if (size(mat, 1) < m .or. size(mat, 2) < m) then
         call fatal_error(error, 'lcp_enumerate: matrix smaller than '//str(m)//' x '//str(m))
         return
      end if
      if (present(z)) then
         if (size(z) < m) then
            call fatal_error(error, 'lcp_enumerate: z has fewer than '//str(m)//' entries')
            return
         end if
      end if
      if (present(reference)) then
         if (size(reference) < m) then
            call fatal_error(error, 'lcp_enumerate: reference has fewer than '//str(m)//' entries')
            return
         end if
      end if
      acc_tol = 1.0e-10_dp
      if (present(tol)) acc_tol = tol
      stop_first = .false.
      if (present(first_only)) stop_first = first_only

      call lemke_init(ws, m, error)
      if (allocated(error)) return
      allocate (found(m, 4), zc(m), wc(m), active(m), comb(m))

      outer: do k = 0, m
         do i = 1, k
            comb(i) = i
         end do
         more = .true.
         do while (more)
            active = .false.
            active(comb(1:k)) = .true.
            call lcp_principal_solve(ws, m, mat, q, active, zc, wc, res, nonsingular)
            if (nonsingular .and. res <= acc_tol) then
               if (is_new(zc)) then
                  n_solutions = n_solutions + 1
                  if (n_solutions > size(found, 2)) then
                     allocate (grown(m, 2*size(found, 2)))
                     grown(:, 1:size(found, 2)) = found
                     call move_alloc(grown, found)
                  end if
                  found(:, n_solutions) = zc
                  if (stop_first) exit outer
               end if
            end if
            call next_combination(comb, k, m, more)
         end do
      end do outer

      if (present(z)) then
         z(1:m) = 0.0_dp
         if (n_solutions > 0) then
            nearest = 1
            if (present(reference)) then
               best = huge(1.0_dp)
               do j = 1, n_solutions
                  dist = 0.0_dp
                  if (m > 0) dist = maxval(abs(found(:, j) - reference(1:m)))
                  if (dist < best) then
                     best = dist
                     nearest = j
                  end if
               end do
            end if
            z(1:m) = found(:, nearest)
         end if
      end if
      if (present(solutions)) solutions = found(:, 1:n_solutions)

   contains

      !> zc differs from every solution stored so far.
      logical function is_new(cand)
         real(dp), intent(in) :: cand(:)
         integer :: l
         real(dp) :: scale

         is_new = .true.
         do l = 1, n_solutions
            if (m == 0) then
               is_new = .false.
               return
            end if
            scale = max(maxval(abs(cand)), maxval(abs(found(:, l))), tiny(1.0_dp))
            if (maxval(abs(cand - found(:, l))) <= 1.0e-9_dp*scale) then
               is_new = .false.
               return
            end if
         end do
      end function is_new

   end subroutine lcp_enumerate

   !> Advance comb(1:k) to the next k-subset of 1..n in lexicographic order.
   pure subroutine next_combination(comb, k, n, more)
      integer, intent(inout) :: comb(:)
      integer, intent(in) :: k, n
      logical, intent(out) :: more
      integer :: i, j

      more = .false.
      do i = k, 1, -1
         if (comb(i) < n - k + i) then
            comb(i) = comb(i) + 1
            do j = i + 1, k
               comb(j) = comb(j - 1) + 1
            end do
            more = .true.
            return
         end if
      end do
   end subroutine next_combination

end module pound_lcp_enumerate
