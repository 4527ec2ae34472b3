!> Coulomb friction at the contact points of buildings in plan: what the contact system keeps
!> of it (`friction_set`). A contact point with friction mu > 0 (pound_contact_pair) has a
!> tangential spring kt in series with a Coulomb slider along the facades (site y): with s the
!> tangential displacement u_y,A(P_A) - u_y,B(P_B) and s_p the committed slip,
!>
!>   T = kt (s - s_p)  on B (-T on A),  |T| <= mu N,  s_p = s_p,n + l+ - l-,
!>   (mu N - T) >= 0 _|_ l+ >= 0,  (mu N + T) >= 0 _|_ l- >= 0,
!>
!> N the point's end-of-step normal force; an open point has T = 0 (its slip follows s). The
!> rows are those of the step's LCP (pound_contact_friction_lcp); C is the incidence of the
!> tangential ends (`contact_pair%tan_row`), as B is of the normal ones.
module pound_contact_friction
   use pound_kinds, only: dp
   use pound_joint_state, only: joint_history
   implicit none
   private

   public :: friction_set, friction_point, friction_vector, friction_history_record

   !> A vector of its own length (Khat^{-1} c of one tangential end).
   type :: friction_vector
      real(dp), allocatable :: x(:)
   end type friction_vector

   !> The state of one point's friction and its tallies.
   type :: friction_point
      !> Tangential force T on B (kN) and committed slip s_p (m) at the end of the last step.
      real(dp) :: force = 0.0_dp, slip = 0.0_dp
      !> Tangential displacement s at the start of the step (m).
      real(dp) :: s = 0.0_dp
      !> Direction of the last slip increment (+1, -1; 0: stuck or open): the warm start.
      integer :: direction = 0
      !> Peak |T| (kN) and its time (s).
      real(dp) :: peak = 0.0_dp, peak_time = 0.0_dp
   end type friction_point

   !> The contact points with friction of a contact system.
   type :: friction_set
      !> Number of points with friction (0: no tangential rows at all).
      integer :: n = 0
      !> The joint of each point (n) and the point of each joint (m; 0: none).
      integer, allocatable :: joint(:), index(:)
      !> Coefficient mu and tangential stiffness kt of each point.
      real(dp), allocatable :: mu(:), kt(:)
      !> Khat^{-1} c of each tangential end, (2, n).
      type(friction_vector), allocatable :: y(:, :)
      !> Condensed flexibilities: C^T Khat^{-1} C (n, n), C^T Khat^{-1} B (n, m) and
      !> B^T Khat^{-1} C (m, n).
      real(dp), allocatable :: gtt(:, :), gtn(:, :), gnt(:, :)
      !> Each point's state.
      type(friction_point), allocatable :: p(:)
      !> The step: released tangential displacement minus the committed slip e (n), the
      !> forces and slip increments of the solution (n), the points in the LCP (`sub(1:nt)`)
      !> and the contact row of each, the first friction row (rows row0+1 .. row0+2 nt).
      real(dp), allocatable :: e(:), force_new(:), slip_new(:)
      integer, allocatable :: sub(:), jrow(:)
      integer :: nt = 0, row0 = 0
      !> The step's dense work: S = diag(1/kt) + C^T Khat^{-1} C of the points in the LCP and
      !> S^{-1} [C^T Khat^{-1} B, e, I] (n, m + 1 + n); the contact q with the tangential
      !> forces' opening (m).
      real(dp), allocatable :: s_mat(:, :), x_mat(:, :), qx(:)
      !> The step was solved with the rows (`contact_step`); `contact_commit` takes its forces.
      logical :: solved = .false.
      !> Friction work, sum T_avg ds_p (kJ).
      real(dp) :: work = 0.0_dp
   end type friction_set

contains

   !> Store the points' tangential force and slip as output sample k of the joints'
   !> histories (allocated at the first sample stored, zero before it: the start at rest).
   pure subroutine friction_history_record(h, k, fr, m)
      !> The joints' histories (force allocated).
      type(joint_history), intent(inout) :: h
      !> Output sample.
      integer, intent(in) :: k
      !> The friction set.
      type(friction_set), intent(in) :: fr
      !> Number of joints.
      integer, intent(in) :: m
      integer :: i

      if (.not. allocated(h%force)) return
      if (.not. allocated(h%friction)) then
         allocate (h%friction(m, size(h%force, 2)), h%slip(m, size(h%force, 2)))
         h%friction = 0.0_dp
         h%slip = 0.0_dp
      end if
      do i = 1, fr%n
         h%friction(fr%joint(i), k) = fr%p(i)%force
         h%slip(fr%joint(i), k) = fr%p(i)%slip
      end do
   end subroutine friction_history_record

end module pound_contact_friction
