!> The outcome of one motion's case of a suite, typed, and the one pack/unpack pair that
!> turns it into the column of reals that crosses the ranks (`pound_cases`) and back.
!>
!> A motion's case (`pound_suite`'s `motion_run`) gives its scaling, its spectra, and unless
!> its run failed its influence coefficients, uncoupled and coupled peaks, per contact pair the
!> uncoupled peak displacement at each end and the no-contact gap, the frames' member block
!> (`pound_suite_columns`) and, with the motions' sweeps, its sweep's probe. A failed run
!> carries its failure (message, time and step) instead of the results. `outcome_pack` and
!> `outcome_unpack` are the only code that knows where each of these lies in the column
!> (`outcome_width` reals, from the `outcome_layout` of the suite); a refinement's failed trial
!> gaps travel the same way (`failure_pack`, `failure_unpack`). Packing copies reals (and the
!> message's character codes) and unpacking copies them back: the numbers are the same bits
!> on every rank.
module pound_suite_outcome
   use pound_kinds, only: dp
   use pound_config, only: n_history_quantities
   use pound_cases, only: case_message_len, text_to_column, column_to_text
   implicit none
   private

   public :: suite_failure, outcome_layout, motion_outcome, outcome_building
   public :: outcome_width, outcome_pack, outcome_unpack, outcome_init, outcome_fail
   public :: failure_width, failure_pack, failure_unpack

   !> Reals of one failure in a column: gap, time, step, then the message (`text_to_column`).
   integer, parameter :: failure_width = 4 + case_message_len

   !> A failed case of a suite: a motion's run at the deck's gaps (uncoupled or coupled), at a
   !> gap of its sweep, or at a trial gap of a threshold refinement.
   type :: suite_failure
      !> Motion index.
      integer :: motion = 0
      !> Gap of every joint (m); -1: the motion's run at the deck's gaps.
      real(dp) :: gap = -1.0_dp
      !> The error message.
      character(len=case_message_len) :: message = ''
      !> Time (s) and step at which the integration failed (-1: not known).
      real(dp) :: time = -1.0_dp
      integer :: step = -1
   end type suite_failure

   !> The sizes of a suite's motion outcomes (the same on every rank).
   type :: outcome_layout
      !> Periods of the spectra; storeys of each building (its number of buildings).
      integer :: n_periods = 0
      integer, allocatable :: n_storeys(:)
      !> Contact pairs.
      integer :: n_pairs = 0
      !> Whether the motions' sweeps run (each outcome carries its sweep's probe), the reals of
      !> the probe's column (`gap_cases_probe`) and of the member block.
      logical :: sweep = .false.
      integer :: n_probe = 0, n_member = 0
   end type outcome_layout

   !> One building's part of an outcome, each (n_storeys, n_history_quantities).
   type :: outcome_building
      !> Influence coefficients (%), uncoupled and coupled peaks.
      real(dp), allocatable :: lambda(:, :), unc(:, :), cpl(:, :)
      !> Bilinear storeys (zeros for elastic ones), (n_storeys, 4): peak ductility uncoupled,
      !> coupled, residual drift (m) uncoupled, coupled; the storey that collapsed in each
      !> analysis (0: none).
      real(dp), allocatable :: yield(:, :)
      real(dp) :: collapse(2) = 0.0_dp
   end type outcome_building

   !> What one motion's case gives the suite.
   type :: motion_outcome
      !> Scale factor applied by the suite, PGA (m/s^2) of the motion as run.
      real(dp) :: scale_factor = 1.0_dp, pga = 0.0_dp
      !> Sa at the spectra's periods and at the buildings' periods (m/s^2).
      real(dp), allocatable :: sa(:), sa_building(:)
      !> Whether the influence exists (the run did not fail and has both analyses).
      logical :: has_influence = .false.
      !> Per building.
      type(outcome_building), allocatable :: building(:)
      !> Per pair: the uncoupled peak displacement at each end, (2, n_pairs) (m; -1: not kept,
      !> a point between floors without its DOF's history), and the no-contact gap (m; -1: no
      !> history).
      real(dp), allocatable :: pair_peak(:, :), no_contact(:)
      !> Whether the run failed, and its failure (gap -1).
      logical :: failed = .false.
      type(suite_failure) :: failure
      !> With the motions' sweeps: whether the probe ran, the joints' largest closing
      !> displacements and the probe's column (`gap_cases_probe`).
      logical :: has_probe = .false.
      real(dp), allocatable :: closing_max(:), probe(:)
      !> The frames' member block (`pound_suite_columns`' `columns_to_block`).
      real(dp), allocatable :: member(:)
   end type motion_outcome

contains

   !> An empty outcome of `layout` (zeros; peaks and gaps -1 where not kept).
   pure subroutine outcome_init(layout, o)
      !> The sizes.
      type(outcome_layout), intent(in) :: layout
      !> The outcome.
      type(motion_outcome), intent(out) :: o
      integer :: ib, n

      allocate (o%sa(layout%n_periods), o%sa_building(size(layout%n_storeys)), o%building(size(layout%n_storeys)))
      o%sa = 0.0_dp
      o%sa_building = 0.0_dp
      do ib = 1, size(layout%n_storeys)
         n = layout%n_storeys(ib)
         allocate (o%building(ib)%lambda(n, n_history_quantities), o%building(ib)%unc(n, n_history_quantities), &
                   o%building(ib)%cpl(n, n_history_quantities))
         o%building(ib)%lambda = 0.0_dp
         o%building(ib)%unc = 0.0_dp
         o%building(ib)%cpl = 0.0_dp
         allocate (o%building(ib)%yield(n, 4), source=0.0_dp)
      end do
      allocate (o%pair_peak(2, layout%n_pairs), o%no_contact(layout%n_pairs), o%closing_max(layout%n_pairs), &
                o%probe(layout%n_probe), o%member(layout%n_member))
      o%pair_peak = 0.0_dp
      o%no_contact = 0.0_dp
      o%closing_max = 0.0_dp
      o%probe = 0.0_dp
      o%member = 0.0_dp
   end subroutine outcome_init

   !> Mark `o` as its failed run's, with `message`, `time` and `step` (-1: not known): the
   !> scaling and the spectra kept, its results (influence, peaks, no-contact gaps, member
   !> block) zero; the probe kept.
   pure subroutine outcome_fail(o, message, time, step)
      !> The outcome.
      type(motion_outcome), intent(inout) :: o
      !> The error message.
      character(len=*), intent(in) :: message
      !> Time (s) and step of the failure.
      real(dp), intent(in) :: time
      integer, intent(in) :: step
      integer :: ib

      o%has_influence = .false.
      do ib = 1, size(o%building)
         o%building(ib)%lambda = 0.0_dp
         o%building(ib)%unc = 0.0_dp
         o%building(ib)%cpl = 0.0_dp
         o%building(ib)%yield = 0.0_dp
         o%building(ib)%collapse = 0.0_dp
      end do
      o%pair_peak = 0.0_dp
      o%no_contact = 0.0_dp
      o%member = 0.0_dp
      o%failed = .true.
      o%failure = suite_failure(0, -1.0_dp, message, time, step)
   end subroutine outcome_fail

   !> Reals of an outcome's column.
   pure integer function outcome_width(layout) result(width)
      !> The sizes.
      type(outcome_layout), intent(in) :: layout

      width = 3 + layout%n_periods + size(layout%n_storeys) + 3*n_history_quantities*sum(layout%n_storeys) + &
              3*layout%n_pairs + 1 + failure_width + layout%n_member + 4*sum(layout%n_storeys) + 2*size(layout%n_storeys)
      if (layout%sweep) width = width + 1 + layout%n_pairs + layout%n_probe
   end function outcome_width

   !> `o` into its column `col` (`outcome_width` reals).
   pure subroutine outcome_pack(o, layout, col)
      !> The outcome.
      type(motion_outcome), intent(in) :: o
      !> The sizes.
      type(outcome_layout), intent(in) :: layout
      !> The column.
      real(dp), intent(out) :: col(:)
      type(motion_outcome) :: w
      integer :: at

      col = 0.0_dp
      w = o
      at = 0
      call walk(col, at, layout, w, .true.)
   end subroutine outcome_pack

   !> The outcome `outcome_pack` put in `col`.
   pure subroutine outcome_unpack(col, layout, o)
      !> The column.
      real(dp), intent(in) :: col(:)
      !> The sizes.
      type(outcome_layout), intent(in) :: layout
      !> The outcome.
      type(motion_outcome), intent(out) :: o
      real(dp) :: c(size(col))
      integer :: at

      call outcome_init(layout, o)
      c = col
      at = 0
      call walk(c, at, layout, o, .false.)
   end subroutine outcome_unpack

   !> The one walk over the column's layout, both ways: `put` copies `o` into `col`, else
   !> `col` into `o`.
   pure subroutine walk(col, at, layout, o, put)
      real(dp), intent(inout) :: col(:)
      integer, intent(inout) :: at
      type(outcome_layout), intent(in) :: layout
      type(motion_outcome), intent(inout) :: o
      logical, intent(in) :: put
      real(dp) :: flag
      integer :: ib

      call move_scalar(col, at, put, o%scale_factor)
      call move_scalar(col, at, put, o%pga)
      flag = merge(1.0_dp, 0.0_dp, o%has_influence)
      call move_scalar(col, at, put, flag)
      o%has_influence = flag > 0.0_dp
      call move_vector(col, at, put, o%sa)
      call move_vector(col, at, put, o%sa_building)
      do ib = 1, size(layout%n_storeys)
         call move_matrix(col, at, put, o%building(ib)%lambda)
      end do
      do ib = 1, size(layout%n_storeys)
         call move_matrix(col, at, put, o%building(ib)%unc)
      end do
      do ib = 1, size(layout%n_storeys)
         call move_matrix(col, at, put, o%building(ib)%cpl)
      end do
      call move_matrix(col, at, put, o%pair_peak)
      call move_vector(col, at, put, o%no_contact)
      flag = merge(1.0_dp, 0.0_dp, o%failed)
      call move_scalar(col, at, put, flag)
      o%failed = flag > 0.0_dp
      if (put) then
         call failure_pack(o%failure, col(at + 1:at + failure_width))
      else
         o%failure = failure_unpack(col(at + 1:at + failure_width), 0)
      end if
      at = at + failure_width
      if (layout%sweep) then
         flag = merge(1.0_dp, 0.0_dp, o%has_probe)
         call move_scalar(col, at, put, flag)
         o%has_probe = flag > 0.0_dp
         call move_vector(col, at, put, o%closing_max)
         call move_vector(col, at, put, o%probe)
      end if
      call move_vector(col, at, put, o%member)
      do ib = 1, size(layout%n_storeys)
         call move_matrix(col, at, put, o%building(ib)%yield)
         call move_vector(col, at, put, o%building(ib)%collapse)
      end do
   end subroutine walk

   !> A vector between the column and `x` (`put`: into the column, else out of it), `at`
   !> moved past it.
   pure subroutine move_vector(col, at, put, x)
      !> The column.
      real(dp), intent(inout) :: col(:)
      !> Reals of the column walked so far.
      integer, intent(inout) :: at
      !> Direction: into the column, or out of it.
      logical, intent(in) :: put
      !> The values.
      real(dp), intent(inout) :: x(:)

      if (put) then
         col(at + 1:at + size(x)) = x
      else
         x = col(at + 1:at + size(x))
      end if
      at = at + size(x)
   end subroutine move_vector

   !> One real between the column and `x`, as `move_vector`.
   pure subroutine move_scalar(col, at, put, x)
      !> The column.
      real(dp), intent(inout) :: col(:)
      !> Reals of the column walked so far.
      integer, intent(inout) :: at
      !> Direction: into the column, or out of it.
      logical, intent(in) :: put
      !> The value.
      real(dp), intent(inout) :: x
      real(dp) :: v(1)

      v(1) = x
      call move_vector(col, at, put, v)
      x = v(1)
   end subroutine move_scalar

   !> A matrix between the column and `x` (column-major), as `move_vector`.
   pure subroutine move_matrix(col, at, put, x)
      !> The column.
      real(dp), intent(inout) :: col(:)
      !> Reals of the column walked so far.
      integer, intent(inout) :: at
      !> Direction: into the column, or out of it.
      logical, intent(in) :: put
      !> The values.
      real(dp), intent(inout) :: x(:, :)
      real(dp) :: v(size(x))

      v = reshape(x, [size(x)])
      call move_vector(col, at, put, v)
      x = reshape(v, shape(x))
   end subroutine move_matrix

   !> A failure into `values` (`failure_width` reals): gap, time, step, message (cut to
   !> `case_message_len`).
   pure subroutine failure_pack(f, values)
      !> The failure.
      type(suite_failure), intent(in) :: f
      !> The column's part.
      real(dp), intent(out) :: values(:)

      values(1) = f%gap
      values(2) = f%time
      values(3) = real(f%step, dp)
      call text_to_column(trim(f%message), values(4:failure_width))
   end subroutine failure_pack

   !> The failure of motion k that `failure_pack` put in `values`.
   pure function failure_unpack(values, k) result(f)
      !> The column's part.
      real(dp), intent(in) :: values(:)
      !> Motion index.
      integer, intent(in) :: k
      type(suite_failure) :: f

      f%motion = k
      f%gap = values(1)
      f%time = values(2)
      f%step = nint(values(3))
      f%message = column_to_text(values(4:failure_width))
   end function failure_unpack

end module pound_suite_outcome
