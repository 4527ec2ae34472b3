!> Influence coefficients of pounding on the response (eq. 7 of the seed paper): the one
!> place where they are computed.
!>
!> For a response quantity Q with absolute maxima Qc (coupled) and Qu (uncoupled):
!> lambda = (Qc - Qu) / Qu * 100 (%). Positive: pounding raises the response.
!> `influence_of` gives lambda per building, floor/storey and history quantity from the
!> peaks of two analyses; the run driver keeps them in its results, the listing and the
!> HDF5 writer print them as they are, and the gap sweep reduces them with
!> `max_abs_influence`, or with `max_abs_target`, which adds a frame's column segments.
!>
!> Not meaningful ("n/m"): a lambda whose uncoupled peak is positive but below
!> `meaningful_fraction` (1e-6) of the largest uncoupled peak of that quantity in the building
!> (over its floors/storeys, member rows of the same name, storeys' ductilities or hinges) is
!> NaN (`influences`): the listing, summary and CSV show "n/m", the HDF5 datasets hold NaN
!> (attribute `not_meaningful`), and the maxima (`max_abs_meaningful`: largest |lambda|, sweep
!> targets) leave it out. An uncoupled peak of exactly 0 keeps its rule (+huge or 0).
module pound_influence
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
   use pound_kinds, only: dp
   use pound_quantities, only: n_history_quantities, n_target_quantities, q_column_shear, q_column_moment, q_ductility
   use pound_analysis, only: analysis_result
   use pound_structure, only: structure_model, structure_yields, result_noise
   use pound_response, only: q_u
   implicit none
   private

   public :: influence_coefficient, building_influence, influence_of, max_abs_influence, max_abs_target, &
             column_maxima, influences, max_abs_meaningful, largest_meaningful, meaningful_fraction, &
             not_meaningful_note, created_by_pounding, max_meaningful, not_meaningful

   !> A lambda whose uncoupled peak is below this fraction of the quantity's largest uncoupled
   !> peak in the building is not meaningful (NaN).
   real(dp), parameter :: meaningful_fraction = 1.0e-6_dp
   !> Why a lambda is NaN (the HDF5 attribute `not_meaningful` of a dataset holding one).
   character(len=*), parameter :: not_meaningful_note = 'NaN: not meaningful (n/m), the uncoupled peak is '// &
                                                        'below 1e-6 of the largest uncoupled peak of this quantity '// &
                                                        'in the building'

   !> Influence coefficients of one building.
   type :: building_influence
      !> lambda (%) per floor/storey and history quantity (n, n_history_quantities), columns
      !> in the order of `history_names` (pound_response's q_u ... q_shear); +huge where
      !> only the coupled peak is non-zero, 0 where both are, NaN where not meaningful.
      real(dp), allocatable :: lambda(:, :)
      !> lambda (%) of each member row (`structure_model%member`, e.g. a frame's column end
      !> forces), the same rule; unallocated without member rows.
      real(dp), allocatable :: member_lambda(:)
      !> lambda (%) of each result row (`structure_model%result_rows`, e.g. a building in plan's
      !> plane shears and floor rotations), the same rule within each group, and NaN where the
      !> uncoupled peak is 0; unallocated without result rows.
      real(dp), allocatable :: result_lambda(:)
   end type building_influence

contains

   !> lambda = (Qc - Qu)/Qu * 100; 0 where both maxima are zero (nothing to compare) and
   !> +huge where only the uncoupled one is (pounding creates a response from nothing).
   elemental function influence_coefficient(qc, qu) result(lambda)
      !> Absolute maximum, coupled.
      real(dp), intent(in) :: qc
      !> Absolute maximum, uncoupled.
      real(dp), intent(in) :: qu
      real(dp) :: lambda

      if (qu > 0.0_dp) then
         lambda = (qc - qu)/qu*100.0_dp
      else if (qc > 0.0_dp) then
         lambda = huge(1.0_dp)
      else
         lambda = 0.0_dp
      end if
   end function influence_coefficient

   !> lambda of the peaks of one quantity at the points of one building (`influence_coefficient`),
   !> NaN (not meaningful) where the uncoupled peak is positive but below `meaningful_fraction`
   !> of the largest uncoupled peak of `qu`.
   pure function influences(qc, qu) result(lambda)
      !> Absolute maxima, coupled.
      real(dp), intent(in) :: qc(:)
      !> Absolute maxima, uncoupled (the same points).
      real(dp), intent(in) :: qu(:)
      real(dp) :: lambda(size(qu))
      real(dp) :: floor_

      lambda = influence_coefficient(qc, qu)
      if (size(qu) == 0) return
      floor_ = meaningful_fraction*maxval(abs(qu))
      where (qu > 0.0_dp .and. abs(qu) < floor_) lambda = not_meaningful()
   end function influences

   !> The value of a lambda that is not meaningful (NaN).
   pure real(dp) function not_meaningful()
      not_meaningful = ieee_value(0.0_dp, ieee_quiet_nan)
   end function not_meaningful

   !> Whether lambda is +huge (the uncoupled peak is 0: pounding created the response); false
   !> for a lambda that is not meaningful (no comparison touches a NaN).
   elemental logical function created_by_pounding(lambda)
      !> Influence coefficient (%).
      real(dp), intent(in) :: lambda

      created_by_pounding = .false.
      if (.not. ieee_is_nan(lambda)) created_by_pounding = lambda >= huge(1.0_dp)
   end function created_by_pounding

   !> The larger of two lambdas leaving out one that is not meaningful (NaN when both are).
   elemental real(dp) function max_meaningful(a, b) result(m)
      !> Influence coefficients (%).
      real(dp), intent(in) :: a, b

      if (ieee_is_nan(a)) then
         m = b
      else if (ieee_is_nan(b)) then
         m = a
      else
         m = max(a, b)
      end if
   end function max_meaningful

   !> Largest |lambda| of the meaningful entries (not NaN) of `x`; 0 when there are none.
   pure real(dp) function max_abs_meaningful(x) result(m)
      !> Influence coefficients (%).
      real(dp), intent(in) :: x(:)

      m = 0.0_dp
      if (any(.not. ieee_is_nan(x))) m = maxval(abs(x), mask=.not. ieee_is_nan(x))
   end function max_abs_meaningful

   !> Index of the largest |lambda| of the meaningful entries of `x` (the first of equals);
   !> 0 when none is meaningful (or `x` is empty).
   pure integer function largest_meaningful(x) result(j)
      !> Influence coefficients (%).
      real(dp), intent(in) :: x(:)

      j = 0
      if (any(.not. ieee_is_nan(x))) j = maxloc(abs(x), dim=1, mask=.not. ieee_is_nan(x))
   end function largest_meaningful

   !> Influence coefficients of every building, from the peaks of the uncoupled run `unc` and
   !> of the coupled run `cpl` (the same buildings in the same order).
   pure function influence_of(unc, cpl, models) result(infl)
      !> Uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> Coupled result.
      type(analysis_result), intent(in) :: cpl
      !> The buildings (their member rows' names: rows of one name are one quantity for the
      !> n/m rule); absent: every member row of a building is one quantity.
      type(structure_model), intent(in), optional :: models(:)
      type(building_influence) :: infl(size(unc%building))
      integer :: ib, q, nq, k

      do ib = 1, size(infl)
         associate (pc => cpl%building(ib)%peak, pu => unc%building(ib)%peak)
            allocate (infl(ib)%lambda(size(pu, 1), size(pu, 2)))
            do q = 1, size(pu, 2)
               infl(ib)%lambda(:, q) = influences(pc(:, q), pu(:, q))
            end do
         end associate
         if (allocated(cpl%building(ib)%member_peak) .and. allocated(unc%building(ib)%member_peak)) then
            associate (mc => cpl%building(ib)%member_peak, mu => unc%building(ib)%member_peak)
               allocate (infl(ib)%member_lambda(size(mu)))
               ! Member rows of the same name are one quantity (`structure_model%member_names`).
               nq = 1
               if (present(models)) then
                  if (allocated(models(ib)%member_names)) nq = max(1, size(models(ib)%member_names))
               end if
               if (mod(size(mu), nq) /= 0) nq = 1
               do k = 1, nq
                  infl(ib)%member_lambda(k::nq) = influences(mc(k::nq), mu(k::nq))
               end do
            end associate
         end if
         if (allocated(cpl%building(ib)%result_peak) .and. allocated(unc%building(ib)%result_peak) .and. &
             present(models)) then
            if (allocated(models(ib)%result)) infl(ib)%result_lambda = &
               result_influences(cpl%building(ib)%result_peak, unc%building(ib)%result_peak, models(ib), &
                                 maxval(unc%building(ib)%peak(:, q_u)))
         end if
      end do
   end function influence_of

   !> lambda of the result rows group by group (`influences` within a group), NaN where the
   !> uncoupled peak is 0 or round-off (`result_group%arm`).
   pure function result_influences(qc, qu, model, u_peak) result(lambda)
      !> Absolute maxima, coupled and uncoupled (the model's result rows).
      real(dp), intent(in) :: qc(:), qu(:)
      !> The model (its result groups).
      type(structure_model), intent(in) :: model
      !> The building's largest uncoupled floor displacement peak (m).
      real(dp), intent(in) :: u_peak
      real(dp) :: lambda(size(qu))
      integer :: g, i0, i1

      do g = 1, size(model%result)
         i0 = model%result(g)%first
         i1 = i0 + product(model%result(g)%extent) - 1
         lambda(i0:i1) = influences(qc(i0:i1), qu(i0:i1))
         if (model%result(g)%arm > 0.0_dp) then
            where (qu(i0:i1)*model%result(g)%arm < result_noise*u_peak) lambda(i0:i1) = not_meaningful()
         end if
      end do
      where (.not. qu > 0.0_dp) lambda = not_meaningful()
   end function result_influences

   !> Largest |lambda| over the floors/storeys, (n_history_quantities, n_buildings).
   pure function max_abs_influence(infl) result(m)
      !> Influence coefficients of every building.
      type(building_influence), intent(in) :: infl(:)
      real(dp) :: m(n_history_quantities, size(infl))
      integer :: ib, q

      do ib = 1, size(infl)
         do q = 1, n_history_quantities
            m(q, ib) = max_abs_meaningful(infl(ib)%lambda(:, q))
         end do
      end do
   end function max_abs_influence

   !> Largest |lambda| per target quantity (`target_names`) and building, (n_target_quantities,
   !> n_buildings): the history quantities' over the floors/storeys (`max_abs_influence`), then
   !> over a frame's column segments the shear's (`q_column_shear`) and the end moments'
   !> (bottom and top, `q_column_moment`, `column_maxima`); 0 for a building without column
   !> segments.
   pure function max_abs_target(infl, models, unc, cpl) result(m)
      !> Influence coefficients of every building.
      type(building_influence), intent(in) :: infl(:)
      !> The buildings (their member rows' group and names), in the same order.
      type(structure_model), intent(in) :: models(:)
      !> The uncoupled and coupled analyses (their bilinear storeys' or hinges' peak ductility:
      !> the largest |lambda| of the ductility over the storeys, `q_ductility`; 0 for an
      !> elastic building, +huge for a yielding one whose runs do not carry it).
      type(analysis_result), intent(in), optional :: unc, cpl
      real(dp) :: m(n_target_quantities, size(infl))
      integer :: ib

      m(1:n_history_quantities, :) = max_abs_influence(infl)
      m(q_column_shear:q_ductility, :) = 0.0_dp
      do ib = 1, size(infl)
         if (allocated(infl(ib)%member_lambda)) &
            m(q_column_shear:q_column_moment, ib) = column_maxima(infl(ib)%member_lambda, models(ib))
      end do
      do ib = 1, size(infl)
         if (.not. structure_yields(models(ib))) cycle
         ! A yielding building whose runs do not both carry its storeys' ductility (a result
         ! rebuilt without them) is never safe: +huge, not a silent 0.
         m(q_ductility, ib) = huge(1.0_dp)
         if (.not. (present(unc) .and. present(cpl))) cycle
         if (.not. (allocated(unc%yielding) .and. allocated(cpl%yielding))) cycle
         if (cpl%yielding(ib)%n == 0 .or. unc%yielding(ib)%n == 0) cycle
         if (size(cpl%yielding(ib)%ductility) /= size(unc%yielding(ib)%ductility)) cycle
         m(q_ductility, ib) = max_abs_meaningful(influences(cpl%yielding(ib)%ductility, unc%yielding(ib)%ductility))
      end do
   end function max_abs_target

   !> Largest |lambda| over a frame's column segments of their shear (1) and of their end
   !> moments, bottom and top (2), from the lambdas of its member rows (`member_lambda`, in the
   !> layout of `structure_model%member`); 0 without column rows (`member_group` 'columns').
   pure function column_maxima(member_lambda, model) result(m)
      !> lambda (%) of each member row.
      real(dp), intent(in) :: member_lambda(:)
      !> The building.
      type(structure_model), intent(in) :: model
      real(dp) :: m(2)
      integer :: k, nq

      m = 0.0_dp
      if (.not. allocated(model%member_names) .or. .not. allocated(model%member_group)) return
      if (model%member_group /= 'columns') return
      nq = size(model%member_names)
      do k = 1, nq
         select case (trim(model%member_names(k)))
         case ('shear')
            m(1) = max(m(1), max_abs_meaningful(member_lambda(k::nq)))
         case ('moment_bottom', 'moment_top')
            m(2) = max(m(2), max_abs_meaningful(member_lambda(k::nq)))
         end select
      end do
   end function column_maxima

end module pound_influence
