!> Reader of `&sweep`: the range of seismic-joint gaps and the optional target for |lambda|.
module pound_deck_sweep
   use pound_config, only: sweep_config
   use pound_deck_checks, only: fail, take_real, given_count, group_input, is_set, read_failed, require_real, &
                                site, unset_int, unset_real
   use pound_deck_lexer, only: group_ref, lower
   use pound_deck_study, only: take_parameter_sweep, max_study_values
   use pound_deck_targets, only: take_target_quantities
   use pound_deck_variables, only: path_len
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: read_sweep

contains

   !> `&sweep`: range of seismic-joint gaps and the optional target for |lambda|.
   subroutine read_sweep(path, text, g, n_contacts, has_frame, cfg, error, has_bilinear)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Number of `&contact` groups in the deck.
      integer, intent(in) :: n_contacts
      !> Whether any building of the deck is a frame (has column segments).
      logical, intent(in) :: has_frame
      !> Some building yields: bilinear storeys or plastic hinges (`ductility` can be targeted).
      logical, intent(in), optional :: has_bilinear
      !> Resolved sweep.
      type(sweep_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: gap_from, gap_to, target_lambda, refine_tolerance, value_from, value_to
      real(dp), allocatable :: values(:)
      integer :: n_gaps, ios, n_values
      character(len=path_len) :: target_quantities
      character(len=64) :: parameter, spacing
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      namelist /sweep/ gap_from, gap_to, n_gaps, target_lambda, target_quantities, refine_tolerance, &
         parameter, values, value_from, value_to, n_values, spacing

      gap_from = unset_real
      gap_to = unset_real
      target_lambda = unset_real
      refine_tolerance = unset_real
      n_gaps = unset_int
      target_quantities = 'u a_abs drift storey_shear'
      parameter = 'gap'
      spacing = ' '
      value_from = unset_real
      value_to = unset_real
      n_values = unset_int
      ! One slot more than allowed, so that too many values get our message.
      allocate (values(max_study_values + 1))
      values = unset_real
      call group_input(path, text, g, at, buf, msg)
      read (buf, nml=sweep, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return
      if (n_contacts == 0) then
         call fail(at, 'gap_from', 'a sweep varies the gaps of the &contact groups, and the deck '// &
                   'has none', error)
         return
      end if
      if (lower(trim(adjustl(parameter))) /= 'gap') then
         ! A stiffness or restitution sweep (pound_deck_study): the gap variables are refused.
         call take_parameter_sweep(at, parameter, values, value_from, value_to, n_values, spacing, &
                                   is_set(gap_from) .or. is_set(gap_to) .or. n_gaps /= unset_int, cfg, error)
         if (allocated(error)) return
         call take_target(error)
         return
      end if
      if (given_count(values) > 0 .or. is_set(value_from) .or. is_set(value_to) .or. n_values /= unset_int .or. &
          len_trim(spacing) > 0) then
         call fail(at, 'parameter', "values, value_from, value_to, n_values and spacing are for parameter = "// &
                   "'stiffness' or 'restitution'; a gap sweep (parameter = 'gap', the default) takes gap_from, "// &
                   'gap_to and n_gaps', error)
         return
      end if
      call require_real(at, 'gap_from', gap_from, 'first gap in m', error, '>=', 0.0_dp)
      if (allocated(error)) return
      call require_real(at, 'gap_to', gap_to, 'last gap in m', error, '>', gap_from, 'gap_from = '//str(gap_from))
      if (allocated(error)) return
      if (n_gaps == unset_int) then
         call fail(at, 'n_gaps', 'n_gaps is missing (number of gaps from gap_from to gap_to)', error)
         return
      end if
      if (n_gaps < 2 .or. n_gaps > 10000) then
         call fail(at, 'n_gaps', 'n_gaps = '//str(n_gaps)//', must be in 2..10000', error)
         return
      end if
      call take_target(error)
      if (allocated(error)) return
      cfg%active = .true.
      cfg%gap_from = gap_from
      cfg%gap_to = gap_to
      cfg%n_gaps = n_gaps

   contains

      !> The target and its quantities, the refinement tolerance (every kind of sweep).
      subroutine take_target(error)
         type(error_type), allocatable, intent(out) :: error

         call take_real(at, 'target_lambda', target_lambda, '>', 0.0_dp, cfg%target, error)
         if (allocated(error)) return
         call take_real(at, 'refine_tolerance', refine_tolerance, '>', 0.0_dp, cfg%refine_tolerance, error)
         if (allocated(error)) return
         call take_target_quantities(at, target_quantities, has_frame, bilinear(), cfg%target_quantities, error)
      end subroutine take_target

      !> Whether some building has bilinear storeys or plastic hinges.
      logical function bilinear()
         bilinear = .false.
         if (present(has_bilinear)) bilinear = has_bilinear
      end function bilinear

   end subroutine read_sweep

end module pound_deck_sweep
