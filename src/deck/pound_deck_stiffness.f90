!> The default joint stiffness of a `&contact` group that gives none (issue 26): the axial
!> stiffness of the facing floors, each a frame's floor beam line E A / L over the frame's
!> width L (the sum of its bay widths: the length of the colliding slab in the pounding
!> direction), the two sides in series; a side that is a shear building (no floor section) or
!> a column point between floors counts as rigid; the smallest over the group's pairs. A group
!> none of whose pairs faces a frame's floor must give its stiffness.
module pound_deck_stiffness
   use pound_config, only: building_config, contact_config, is_frame
   use pound_deck_checks, only: fail, site
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: stiffness_has_default, default_joint_stiffness, floor_axial_stiffness

contains

   !> Whether law `law` gets the default when the deck gives no `stiffness`: the laws whose
   !> `stiffness` is a linear joint stiffness k0 in kN/m.
   pure logical function stiffness_has_default(law)
      !> The law's deck name.
      character(len=*), intent(in) :: law

      select case (law)
      case ('elastic', 'elastic_plastic', 'bilinear', 'kelvin')
         stiffness_has_default = .true.
      case default
         stiffness_has_default = .false.
      end select
   end function stiffness_has_default

   !> Axial stiffness E A / L (kN/m) of floor `floor` of frame `b`: its beams' E and A at that
   !> floor over the frame's width L = sum of the bay widths; 0 when `b` is not a frame or the
   !> point is not a floor (`floor` < 1).
   pure real(dp) function floor_axial_stiffness(b, floor) result(k)
      !> The building.
      type(building_config), intent(in) :: b
      !> The floor (0: a column point between floors).
      integer, intent(in) :: floor

      k = 0.0_dp
      if (.not. is_frame(b) .or. floor < 1) return
      if (.not. (allocated(b%beam_e) .and. allocated(b%beam_area) .and. allocated(b%bay_width))) return
      k = b%beam_e(min(floor, size(b%beam_e)))*b%beam_area(min(floor, size(b%beam_area)))/sum(b%bay_width)
   end function floor_axial_stiffness

   !> The default stiffness of group `c` (its buildings and pairs resolved) and its rule for the
   !> listing; an error naming the group when no pair faces a frame's floor.
   pure subroutine default_joint_stiffness(at, c, buildings, k0, rule, error)
      !> Where messages point.
      type(site), intent(in) :: at
      !> The group (buildings and floors resolved).
      type(contact_config), intent(in) :: c
      !> The deck's buildings.
      type(building_config), intent(in) :: buildings(:)
      !> The default stiffness (kN/m).
      real(dp), intent(out) :: k0
      !> How it was found.
      character(len=:), allocatable, intent(out) :: rule
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: kl, kr, kp
      integer :: p, worst

      k0 = huge(1.0_dp)
      worst = 0
      do p = 1, size(c%floor_left)
         kl = floor_axial_stiffness(buildings(c%left_index), c%floor_left(p))
         kr = floor_axial_stiffness(buildings(c%right_index), c%floor_right(p))
         if (kl > 0.0_dp .and. kr > 0.0_dp) then
            kp = 1.0_dp/(1.0_dp/kl + 1.0_dp/kr)
         else
            kp = max(kl, kr)
         end if
         if (kp > 0.0_dp .and. kp < k0) then
            k0 = kp
            worst = p
         end if
      end do
      if (worst == 0) then
         call fail(at, 'stiffness', 'stiffness is missing (joint stiffness k0 in kN/m), and no default: the '// &
                   "default is the axial stiffness E A / L of the facing floors' beams of frames (model = "// &
                   "'frame'), and no pair of this group faces a frame's floor (shear buildings have no floor "// &
                   'section); give stiffness, e.g. E A / L of the struck floor slab', error)
         return
      end if
      kl = floor_axial_stiffness(buildings(c%left_index), c%floor_left(worst))
      kr = floor_axial_stiffness(buildings(c%right_index), c%floor_right(worst))
      rule = 'stiffness by default: E A / L of the facing floor beams over each frame''s width (sum of its '// &
             'bays), in series, a shear building or a column point rigid; smallest over the group''s pairs, pair '// &
             str(worst)//': '//side(c%left, kl)//', '//side(c%right, kr)//' -> k0 = '//str(k0)//' kN/m'
   contains

      pure function side(name, k) result(t)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: k
         character(len=:), allocatable :: t

         if (k > 0.0_dp) then
            t = name//' '//str(k)//' kN/m'
         else
            t = name//' rigid'
         end if
      end function side
   end subroutine default_joint_stiffness

end module pound_deck_stiffness
