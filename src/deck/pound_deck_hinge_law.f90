!> The hinge law of a frame `&building` (issue 25): `hinge_law = 'none'` (default) or
!> `'elastic_plastic'` with `column_yield_moment(:)` (kN m, > 0: one value for every storey or
!> one per storey) and `beam_yield_moment(:)` (kN m, > 0: one value for every floor or one per
!> floor), both required with 'elastic_plastic', and `hinge_hardening(:)` (ratio r, 0 <= r < 1:
!> one value or one per storey, default 0: elastic-perfectly plastic). Only frames
!> (model = 'frame') take hinges.
module pound_deck_hinge_law
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_config, only: building_config
   use pound_deck_checks, only: fail, given_count, is_set, site
   use pound_deck_lexer, only: lower
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: take_hinge_law

contains

   !> Check the hinge-law variables of one `&building` and put them into `cfg`
   !> (`cfg%model` and `cfg%n_storeys` already set).
   pure subroutine take_hinge_law(at, hinge_law, column_yield_moment, beam_yield_moment, hinge_hardening, &
                                  cfg, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> `hinge_law` as read (blank: not given).
      character(len=*), intent(in) :: hinge_law
      !> `column_yield_moment` and `beam_yield_moment` as read (`unset_real` where not given).
      real(dp), intent(in) :: column_yield_moment(:), beam_yield_moment(:)
      !> `hinge_hardening` as read (`unset_real` where not given).
      real(dp), intent(in) :: hinge_hardening(:)
      !> The building being read.
      type(building_config), intent(inout) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error

      select case (lower(trim(adjustl(hinge_law))))
      case ('', 'none')
         cfg%hinge_law = 'none'
         if (given_count(column_yield_moment) > 0) then
            call fail(at, 'column_yield_moment', "column_yield_moment applies only with hinge_law = "// &
                      "'elastic_plastic' (this building has hinge_law = 'none')", error)
         else if (given_count(beam_yield_moment) > 0) then
            call fail(at, 'beam_yield_moment', "beam_yield_moment applies only with hinge_law = "// &
                      "'elastic_plastic' (this building has hinge_law = 'none')", error)
         else if (given_count(hinge_hardening) > 0) then
            call fail(at, 'hinge_hardening', "hinge_hardening applies only with hinge_law = "// &
                      "'elastic_plastic' (this building has hinge_law = 'none')", error)
         end if
         return
      case ('elastic_plastic')
         cfg%hinge_law = 'elastic_plastic'
      case default
         call fail(at, 'hinge_law', "hinge_law = '"//trim(adjustl(hinge_law))// &
                   "', must be 'none' or 'elastic_plastic'", error)
         return
      end select
      if (cfg%model /= 'frame') then
         call fail(at, 'hinge_law', "hinge_law = 'elastic_plastic' applies only to a frame (model = 'frame'); "// &
                   "a shear building yields in its storeys: storey_law = 'bilinear'", error)
         return
      end if
      call take_values(at, 'column_yield_moment', 'storey', column_yield_moment, cfg%n_storeys, .false., &
                       cfg%column_yield_moment, error)
      if (allocated(error)) return
      call take_values(at, 'beam_yield_moment', 'floor', beam_yield_moment, cfg%n_storeys, .false., &
                       cfg%beam_yield_moment, error)
      if (allocated(error)) return
      call take_values(at, 'hinge_hardening', 'storey', hinge_hardening, cfg%n_storeys, .true., &
                       cfg%hinge_hardening_ratio, error)
   end subroutine take_hinge_law

   !> One variable given as one value (for all) or `n`: a yield moment (finite, > 0; required)
   !> or, with `ratio`, the hardening ratio (0 <= r < 1; default 0).
   pure subroutine take_values(at, var, per, raw, n, ratio, values, error)
      type(site), intent(in) :: at
      character(len=*), intent(in) :: var, per
      real(dp), intent(in) :: raw(:)
      integer, intent(in) :: n
      logical, intent(in) :: ratio
      real(dp), allocatable, intent(out) :: values(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: k, i

      k = given_count(raw)
      if (k == 0 .and. ratio) then
         values = [(0.0_dp, i=1, n)]
         return
      end if
      if (k == 0) then
         call fail(at, var, var//" is missing: hinge_law = 'elastic_plastic' needs the yield moment (kN m, > 0) "// &
                   'of every '//per//' (one value for all or n_storeys = '//str(n)//' values)', error)
         return
      end if
      if (k /= 1 .and. k /= n) then
         call fail(at, var, var//' has '//str(k)//' values, must have one (for every '//per// &
                   ') or n_storeys = '//str(n), error)
         return
      end if
      do i = 1, k
         if (.not. is_set(raw(i))) then
            call fail(at, var, var//'('//str(i)//') is missing; give one value or '//str(n), error)
            return
         end if
         if (ratio) then
            if (ieee_is_finite(raw(i)) .and. raw(i) >= 0.0_dp .and. raw(i) < 1.0_dp) cycle
            call fail(at, var, var//'('//str(i)//') = '//str(raw(i))// &
                      ', must be >= 0 and < 1 (kinematic hardening of the hinges)', error)
            return
         end if
         if (.not. ieee_is_finite(raw(i)) .or. .not. raw(i) > 0.0_dp) then
            call fail(at, var, var//'('//str(i)//') = '//str(raw(i))//', must be a finite yield moment > 0 (kN m)', &
                      error)
            return
         end if
      end do
      if (k == 1) then
         values = [(raw(1), i=1, n)]
      else
         values = raw(1:n)
      end if
   end subroutine take_values

end module pound_deck_hinge_law
