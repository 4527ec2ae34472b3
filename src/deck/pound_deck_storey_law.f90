!> The storey law of a `&building` (issue 25): `storey_law = 'elastic'` (default) or
!> `'bilinear'` with `yield_shear(:)` (kN, > 0, one per storey, required) and
!> `hardening_ratio(:)` (-1 < r < 1, one value for all storeys or one per storey, default 0).
!> Only shear buildings and the planes of buildings in plan (`&plane`, pound_deck_plane) take
!> a bilinear law (frames: `hinge_law`, pound_deck_hinge_law).
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

   public :: take_storey_law, take_law_values

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

      call take_law_values(at, storey_law, yield_shear, hardening_ratio, cfg%n_storeys, &
                           "this building's storeys are elastic", cfg%storey_law, cfg%yield_shear, &
                           cfg%hardening_ratio, error, cfg%model == 'shear')
   end subroutine take_storey_law

   !> Check the storey-law variables of a group with `n` storeys (a shear `&building`, a
   !> `&plane`): the law ('elastic' or 'bilinear'), and for 'bilinear' the yield shears
   !> (required) and the hardening ratios (default 0), `n` values each; for 'elastic' both
   !> arrays stay unallocated.
   pure subroutine take_law_values(at, storey_law, yield_shear, hardening_ratio, n, elastic_what, law, &
                                   ys, r_out, error, bilinear_allowed)
      !> Where messages point.
      type(site), intent(in) :: at
      !> `storey_law` as read (blank: not given).
      character(len=*), intent(in) :: storey_law
      !> `yield_shear` and `hardening_ratio` as read (`unset_real` where not given).
      real(dp), intent(in) :: yield_shear(:), hardening_ratio(:)
      !> Number of storeys.
      integer, intent(in) :: n
      !> What is elastic, for the refusal of yield_shear without 'bilinear'.
      character(len=*), intent(in) :: elastic_what
      !> The law: 'elastic' or 'bilinear'.
      character(len=*), intent(out) :: law
      !> 'bilinear': yield shear (kN) and hardening ratio of each storey.
      real(dp), allocatable, intent(out) :: ys(:), r_out(:)
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      !> Whether 'bilinear' applies (false: refused, a frame's storeys yield in hinges).
      logical, intent(in) :: bilinear_allowed
      real(dp), allocatable :: r(:)
      integer :: k, i

      select case (lower(trim(adjustl(storey_law))))
      case ('', 'elastic')
         law = 'elastic'
         if (given_count(yield_shear) > 0) then
            call fail(at, 'yield_shear', "yield_shear applies only with storey_law = 'bilinear' "// &
                      '('//elastic_what//')', error)
         else if (given_count(hardening_ratio) > 0) then
            call fail(at, 'hardening_ratio', "hardening_ratio applies only with storey_law = 'bilinear' "// &
                      '('//elastic_what//')', error)
         end if
         return
      case ('bilinear')
         law = 'bilinear'
      case default
         call fail(at, 'storey_law', "storey_law = '"//trim(adjustl(storey_law))// &
                   "', must be 'elastic' or 'bilinear'", error)
         return
      end select
      if (.not. bilinear_allowed) then
         call fail(at, 'storey_law', "storey_law = 'bilinear' applies only to a shear building "// &
                   "(model = 'shear'); a frame yields in plastic hinges: hinge_law = 'elastic_plastic'", error)
         return
      end if
      if (given_count(yield_shear) == 0) then
         call fail(at, 'yield_shear', "yield_shear is missing: storey_law = 'bilinear' needs the yield "// &
                   'shear of every storey (kN, > 0, n_storeys = '//str(n)//' values)', error)
         return
      end if
      call take_reals(at, 'yield_shear', yield_shear, n, '>', ys, error)
      if (allocated(error)) return
      k = given_count(hardening_ratio)
      if (k == 0) then
         r_out = [(0.0_dp, i=1, n)]
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
         r_out = [(r(1), i=1, n)]
      else
         r_out = r
      end if
   end subroutine take_law_values

end module pound_deck_storey_law
