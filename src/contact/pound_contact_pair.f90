!> What a unilateral constraint is, as data: which DOFs of which buildings it joins, its
!> initial gap and its law. Nothing here changes during an analysis (the state of a joint is
!> `pound_joint_state`).
!>
!> Constraint k joins end 1 (the left building, whose displacement to the right closes the
!> joint) and end 2 (the right building); building 0 stands for a rigid, fixed neighbour.
!> With B the constraint incidence (+1 left, -1 right, `end_sign`), the closing displacement
!> is v = B^T u.
module pound_contact_pair
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str
   use pound_contact_law, only: contact_law, rate_trapezoidal, rate_backward_euler
   use pound_law_registry, only: law_from_config
   use pound_config, only: contact_config
   implicit none
   private

   public :: contact_pair, pairs_from_config, end_sign

   !> One unilateral constraint: its two ends, its gap and its law.
   type :: contact_pair
      !> Text for messages and the listing, e.g. 'A:2-B:2'.
      character(len=:), allocatable :: label
      !> Building index of each end (1 = left, 2 = right); 0 = rigid fixed neighbour.
      integer :: building(2) = 0
      !> Floor of each end (labels, messages, listing); 0: a point between floors at `elevation`.
      integer :: floor(2) = 0
      !> Elevation of the pair (m) when given by elevation (locates ends between floors).
      real(dp) :: elevation = 0.0_dp
      !> DOF of each end in its building's model (set by `contact_init` from the model's
      !> response points: the model says which DOF a floor is).
      integer :: dof(2) = 0
      !> Initial gap g (m).
      real(dp) :: gap = 0.0_dp
      !> Constraint law.
      type(contact_law) :: law
   end type contact_pair

contains

   !> One constraint per facing floor pair of the deck's `&contact` groups, in deck order.
   function pairs_from_config(contacts, names, error) result(pairs)
      !> The deck's contact groups.
      type(contact_config), intent(in) :: contacts(:)
      !> Building names, in deck order.
      character(len=*), intent(in) :: names(:)
      !> Error state (a law that cannot be built).
      type(error_type), allocatable, intent(out) :: error
      type(contact_pair), allocatable :: pairs(:)
      type(contact_law) :: law
      integer :: i, k, n

      n = 0
      do i = 1, size(contacts)
         n = n + size(contacts(i)%floor_left)
      end do
      allocate (pairs(n))
      n = 0
      do i = 1, size(contacts)
         associate (c => contacts(i))
            call law_from_config(c, law, error)
            if (allocated(error)) then
               error%message = '&contact #'//str(i)//': '//error%message
               return
            end if
            if (c%dashpot_rate == 'trapezoidal') then
               law%dashpot_rate = rate_trapezoidal
            else
               law%dashpot_rate = rate_backward_euler
            end if
            law%restitution = c%restitution
            do k = 1, size(c%floor_left)
               n = n + 1
               pairs(n)%building = [c%left_index, c%right_index]
               pairs(n)%floor = [c%floor_left(k), c%floor_right(k)]
               if (allocated(c%elevation)) pairs(n)%elevation = c%elevation(k)
               pairs(n)%label = trim(names(c%left_index))//':'//end_text(pairs(n), 1)//'-'// &
                                trim(names(c%right_index))//':'//end_text(pairs(n), 2)
               pairs(n)%gap = c%gap(k)
               pairs(n)%law = law
            end do
         end associate
      end do
   end function pairs_from_config

   !> A pair end in labels: its floor, or its elevation for a point between floors ('z3.25m').
   pure function end_text(p, e) result(s)
      !> The pair (its floors and elevation set).
      type(contact_pair), intent(in) :: p
      !> End: 1 (left building) or 2 (right building).
      integer, intent(in) :: e
      character(len=:), allocatable :: s
      character(len=32) :: buf

      if (p%floor(e) > 0) then
         s = str(p%floor(e))
      else
         write (buf, '(f0.3)') p%elevation
         s = trim(adjustl(buf))
         if (s(1:1) == '.') s = '0'//s
         do while (s(len(s):len(s)) == '0')
            s = s(1:len(s) - 1)
         end do
         if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
         s = 'z'//s//'m'
      end if
   end function end_text

   !> Sign of a constraint end in B: +1 on the left, -1 on the right.
   pure real(dp) function end_sign(e)
      !> The end (1 left, 2 right).
      integer, intent(in) :: e

      end_sign = merge(1.0_dp, -1.0_dp, e == 1)
   end function end_sign

end module pound_contact_pair
