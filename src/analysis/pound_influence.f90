!> Influence coefficients of pounding on the response (eq. 7 of the seed paper): the one
!> place where they are computed.
!>
!> For a response quantity Q with absolute maxima Qc (coupled) and Qu (uncoupled):
!> lambda = (Qc - Qu) / Qu * 100 (%). Positive: pounding raises the response.
!> `influence_of` gives lambda per building, floor/storey and history quantity from the
!> peaks of two analyses; the run driver keeps them in its results, the listing and the
!> HDF5 writer print them as they are, and the gap sweep reduces them with
!> `max_abs_influence`, or with `max_abs_target`, which adds a frame's column segments.
module pound_influence
   use pound_kinds, only: dp
   use pound_quantities, only: n_history_quantities, n_target_quantities, q_column_shear, q_column_moment, q_ductility
   use pound_analysis, only: analysis_result
   use pound_structure, only: structure_model, structure_yields
   implicit none
   private

   public :: influence_coefficient, building_influence, influence_of, max_abs_influence, max_abs_target, &
             column_maxima

   !> Influence coefficients of one building.
   type :: building_influence
      !> lambda (%) per floor/storey and history quantity (n, n_history_quantities), columns
      !> in the order of `history_names` (pound_response's q_u ... q_shear); +huge where
      !> only the coupled peak is non-zero, 0 where both are.
      real(dp), allocatable :: lambda(:, :)
      !> lambda (%) of each member row (`structure_model%member`, e.g. a frame's column end
      !> forces), the same rule; unallocated without member rows.
      real(dp), allocatable :: member_lambda(:)
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

   !> Influence coefficients of every building, from the peaks of the uncoupled run `unc` and
   !> of the coupled run `cpl` (the same buildings in the same order).
   pure function influence_of(unc, cpl) result(infl)
      !> Uncoupled result.
      type(analysis_result), intent(in) :: unc
      !> Coupled result.
      type(analysis_result), intent(in) :: cpl
      type(building_influence) :: infl(size(unc%building))
      integer :: ib

      do ib = 1, size(infl)
         infl(ib)%lambda = influence_coefficient(cpl%building(ib)%peak, unc%building(ib)%peak)
         if (allocated(cpl%building(ib)%member_peak) .and. allocated(unc%building(ib)%member_peak)) &
            infl(ib)%member_lambda = influence_coefficient(cpl%building(ib)%member_peak, &
                                                           unc%building(ib)%member_peak)
      end do
   end function influence_of

   !> Largest |lambda| over the floors/storeys, (n_history_quantities, n_buildings).
   pure function max_abs_influence(infl) result(m)
      !> Influence coefficients of every building.
      type(building_influence), intent(in) :: infl(:)
      real(dp) :: m(n_history_quantities, size(infl))
      integer :: ib, q

      do ib = 1, size(infl)
         do q = 1, n_history_quantities
            m(q, ib) = maxval(abs(infl(ib)%lambda(:, q)))
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
         m(q_ductility, ib) = maxval(abs(influence_coefficient(cpl%yielding(ib)%ductility, unc%yielding(ib)%ductility)))
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
            m(1) = max(m(1), maxval(abs(member_lambda(k::nq))))
         case ('moment_bottom', 'moment_top')
            m(2) = max(m(2), maxval(abs(member_lambda(k::nq))))
         end select
      end do
   end function column_maxima

end module pound_influence
