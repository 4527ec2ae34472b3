!> The storey law of a `&building` (issue 25): `storey_law = 'elastic'` (default) or
!> `'bilinear'` with `yield_shear(:)` (kN, > 0, one per storey, required) and
!> `hardening_ratio(:)` (-1 < r < 1, one value for all storeys or one per storey, default 0).
!> Only shear buildings take a bilinear law (frames: `hinge_law`, pound_deck_hinge_law).
module pound_deck_storey_law
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use pound_config, only: building_config
   use pound_deck_checks, only: fail, given_count, is_set, site, take_reals
   use pound_deck_lexer, only: lower
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: take_storey_law

contains

   !> Check the storey-law variables of one `&building` and put them into `cfg`
   !> (`cfg%model` and `cfg%n_storeys` already set).
   pure subroutine take_storey_law(at, storey_law, yield_shear, hardening_ratio, cfg, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> `storey_law` as read (blank: not given).
      character(len=*), intent(in) :: storey_law
      !> `yield_shear` and `hardening_ratio` as read (`unset_real` where not given).
      real(dp), intent(in) :: yield_shear(:), hardening_ratio(:)
      !> The building being read.
      type(building_config), intent(inout) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      real(dp), allocatable :: r(:)
      integer :: n, k, i

      n = cfg%n_storeys
      select case (lower(trim(adjustl(storey_law))))
      case ('', 'elastic')
         cfg%storey_law = 'elastic'
         if (given_count(yield_shear) > 0) then
            call fail(at, 'yield_shear', "yield_shear applies only with storey_law = 'bilinear' "// &
                      "(this building's storeys are elastic)", error)
         else if (given_count(hardening_ratio) > 0) then
            call fail(at, 'hardening_ratio', "hardening_ratio applies only with storey_law = 'bilinear' "// &
                      "(this building's storeys are elastic)", error)
         end if
         return
      case ('bilinear')
         cfg%storey_law = 'bilinear'
      case default
         call fail(at, 'storey_law', "storey_law = '"//trim(adjustl(storey_law))// &
                   "', must be 'elastic' or 'bilinear'", error)
         return
      end select
      if (cfg%model /= 'shear') then
         call fail(at, 'storey_law', "storey_law = 'bilinear' applies only to a shear building "// &
                   "(model = 'shear'); a frame yields in plastic hinges: hinge_law = 'elastic_plastic'", error)
         return
      end if
      if (given_count(yield_shear) == 0) then
         call fail(at, 'yield_shear', "yield_shear is missing: storey_law = 'bilinear' needs the yield "// &
                   'shear of every storey (kN, > 0, n_storeys = '//str(n)//' values)', error)
         return
      end if
      call take_reals(at, 'yield_shear', yield_shear, n, '>', cfg%yield_shear, error)
      if (allocated(error)) return
      k = given_count(hardening_ratio)
      if (k == 0) then
         cfg%hardening_ratio = [(0.0_dp, i=1, n)]
         return
      end if
      if (k /= 1 .and. k /= n) then
         call fail(at, 'hardening_ratio', 'hardening_ratio has '//str(k)//' values, must have one (for '// &
                   'every storey) or n_storeys = '//str(n), error)
         return
      end if
      r = hardening_ratio(1:k)
      do i = 1, k
         if (.not. is_set(r(i))) then
            call fail(at, 'hardening_ratio', 'hardening_ratio('//str(i)//') is missing; give one value or '// &
                      str(n), error)
            return
         end if
         if (.not. ieee_is_finite(r(i)) .or. .not. (r(i) > -1.0_dp .and. r(i) < 1.0_dp)) then
            call fail(at, 'hardening_ratio', 'hardening_ratio('//str(i)//') = '//str(r(i))// &
                      ', must be > -1 and < 1 (post-yield stiffness r k over initial k)', error)
            return
         end if
      end do
      if (k == 1) then
         cfg%hardening_ratio = [(r(1), i=1, n)]
      else
         cfg%hardening_ratio = r
      end if
   end subroutine take_storey_law

end module pound_deck_storey_law
