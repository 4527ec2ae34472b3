!> The target quantities of `&sweep` and `&stripes` (`target_quantities`): parsed against
!> `target_names`, the column-segment quantities only where a building is a frame and the
!> ductility only where one yields ('all' names only what exists), and not 'none'.
module pound_deck_targets
   use pound_config, only: target_names, q_column_shear, q_column_moment, q_ductility, n_target_quantities
   use pound_deck_checks, only: fail, parse_history, site
   use pound_deck_lexer, only: lower
   use pound_error, only: error_type
   implicit none
   private

   public :: take_target_quantities

contains

   !> `targets` from the text `spec` of `target_quantities` (see the module notes).
   pure subroutine take_target_quantities(at, spec, has_frame, yields, targets, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> The text as given.
      character(len=*), intent(in) :: spec
      !> Whether a building of the deck is a frame, and whether one yields.
      logical, intent(in) :: has_frame, yields
      !> The quantities (order of `target_names`).
      logical, intent(inout) :: targets(n_target_quantities)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      call parse_history(at, spec, targets, error, 'target_quantities', target_names)
      if (allocated(error)) return
      if (.not. has_frame .and. any(targets([q_column_shear, q_column_moment]))) then
         ! 'all' (or blank) names every quantity that exists: no column segments without a frame.
         if (index(lower(spec), 'column_') > 0) then
            call fail(at, 'target_quantities', "target_quantities = '"//trim(adjustl(spec))// &
                      "': column_shear and column_moment are the column segments' lambdas of frames, "// &
                      "and no building of the deck is a frame (model = 'frame')", error)
            return
         end if
         targets([q_column_shear, q_column_moment]) = .false.
      end if
      if (targets(q_ductility) .and. .not. yields) then
         ! 'all' names it only where it exists.
         if (index(lower(spec), 'ductility') > 0) then
            call fail(at, 'target_quantities', "target_quantities = '"//trim(adjustl(spec))// &
                      "': ductility is the peak ductility of bilinear storeys (the peak plastic rotation of "// &
                      "a frame's hinges), and no building of the deck has storey_law = 'bilinear' or "// &
                      "hinge_law = 'elastic_plastic'", error)
            return
         end if
         targets(q_ductility) = .false.
      end if
      if (.not. any(targets)) then
         call fail(at, 'target_quantities', "target_quantities = 'none' leaves nothing to check", error)
         return
      end if
   end subroutine take_target_quantities

end module pound_deck_targets
