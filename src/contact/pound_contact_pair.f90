!> What a unilateral constraint is, as data: which DOFs of which buildings it joins, its
!> initial gap and its law. Nothing here changes during an analysis (the state of a joint is
!> `pound_joint_state`).
!>
!> Constraint k joins end 1 (the left building, whose displacement to the right closes the
!> joint) and end 2 (the right building); building 0 stands for a rigid, fixed neighbour.
!> With B the constraint incidence (+1 left, -1 right, `end_sign`), the closing displacement
!> is v = B^T u. Each end is a sparse row over its model's DOFs (`end_row`, the model's
!> `recovery_rows`): the displacement of the end is the row's value, so an end may be any
!> point of a model (a floor, a column node, a weighted point between DOFs); an end that is one
!> DOF with coefficient 1 (every end the deck gives today) is also kept as `dof`, the fast path
!> of the step.
module pound_contact_pair
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str
   use pound_contact_law, only: contact_law, rate_trapezoidal, rate_backward_euler
   use pound_law_registry, only: law_from_config
   use pound_contact_settings, only: contact_config
   use pound_structure, only: recovery_rows, recover
   implicit none
   private

   public :: contact_pair, pairs_from_config, end_sign, end_value, end_load, end_mass, end_single_dof, pair_label

   !> One unilateral constraint: its two ends, its gap and its law.
   type :: contact_pair
      !> Name of the pair in messages, the listing and the HDF5 file (`pair_label`), e.g.
      !> 'RC:3-STEEL:z=7.50m'.
      character(len=:), allocatable :: label
      !> Building index of each end (1 = left, 2 = right); 0 = rigid fixed neighbour.
      integer :: building(2) = 0
      !> Floor of each end (labels, messages, listing); 0: a point between floors at `elevation`.
      integer :: floor(2) = 0
      !> Elevation of the pair (m) when given by elevation (locates ends between floors).
      real(dp) :: elevation = 0.0_dp
      !> Each end as a sparse row over its building's DOFs (one row). Given by the caller, or
      !> set by `contact_init` from the floor or elevation (the model says which DOF a floor is:
      !> `structure_end_row`).
      type(recovery_rows) :: end_row(2)
      !> The DOF of an end whose row is that DOF alone with coefficient 1 (the step's fast
      !> path; set by `contact_init`); 0 for an end of several DOFs.
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
               pairs(n)%label = pair_label(pairs(n), names(c%left_index), names(c%right_index))
               pairs(n)%gap = c%gap(k)
               pairs(n)%law = law
            end do
         end associate
      end do
   end function pairs_from_config

   !> The name of a pair wherever one is named (listing, messages, HDF5 attributes and
   !> paths): '<left building>:<end>-<right building>:<end>', an end being the floor number
   !> ('3') or, for a point between floors, its elevation above the common base in metres
   !> with at least two and at most three decimals ('z=7.50m', 'z=3.255m'); e.g.
   !> 'RC:3-STEEL:z=7.50m'. The whole names are kept; the label has no blank (building
   !> names are letters, digits, '_' and '-'), and the '-' after the left end is the
   !> separator (an end never holds a '-').
   pure function pair_label(p, left, right) result(s)
      !> The pair (its floors and elevation set).
      type(contact_pair), intent(in) :: p
      !> Names of its left and right buildings (trailing blanks dropped).
      character(len=*), intent(in) :: left, right
      character(len=:), allocatable :: s

      s = trim(left)//':'//end_text(p, 1)//'-'//trim(right)//':'//end_text(p, 2)
   end function pair_label

   !> A pair end in labels: its floor, or its elevation for a point between floors ('z=3.25m').
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
         if (s(len(s):len(s)) == '0') s = s(1:len(s) - 1)
         s = 'z='//s//'m'
      end if
   end function end_text

   !> The DOF of a row that is one DOF with coefficient and scale 1; 0 otherwise.
   pure integer function end_single_dof(row) result(dof)
      !> The row (one row).
      type(recovery_rows), intent(in) :: row

      dof = 0
      if (row%n /= 1) return
      if (row%start(2) - row%start(1) /= 1) return
      if (row%coef(row%start(1)) == 1.0_dp .and. row%scale(1) == 1.0_dp) dof = row%dof(row%start(1))
   end function end_single_dof

   !> The displacement of end e for the DOF values x of its building: x(dof) on the fast
   !> path, else the value of its row.
   pure real(dp) function end_value(p, e, x) result(u)
      !> The pair (its ends located).
      type(contact_pair), intent(in) :: p
      !> End: 1 or 2.
      integer, intent(in) :: e
      !> DOF values of the end's building.
      real(dp), intent(in) :: x(:)

      if (p%dof(e) > 0) then
         u = x(p%dof(e))
      else
         u = recover(p%end_row(e), 1, x)
      end if
   end function end_value

   !> Add a unit load along end e to the load vector x of its building (x(dof) = x(dof) + 1
   !> on the fast path, else the row's coefficients times its scale).
   pure subroutine end_load(p, e, x)
      !> The pair (its ends located).
      type(contact_pair), intent(in) :: p
      !> End: 1 or 2.
      integer, intent(in) :: e
      !> Load vector of the end's building.
      real(dp), intent(inout) :: x(:)
      integer :: i

      if (p%dof(e) > 0) then
         x(p%dof(e)) = x(p%dof(e)) + 1.0_dp
         return
      end if
      associate (r => p%end_row(e))
         do i = r%start(1), r%start(2) - 1
            x(r%dof(i)) = x(r%dof(i)) + r%scale(1)*r%coef(i)
         end do
      end associate
   end subroutine end_load

   !> The mass (t) end e moves with: the lumped mass of its DOF, or for a row of weights w_i
   !> on DOFs of masses m_i, 1 / sum w_i^2/m_i; 0 when a DOF it moves has no mass.
   pure real(dp) function end_mass(p, e, mass) result(m)
      !> The pair (its ends located).
      type(contact_pair), intent(in) :: p
      !> End: 1 or 2.
      integer, intent(in) :: e
      !> Lumped masses of the end's building (t).
      real(dp), intent(in) :: mass(:)
      real(dp) :: s, w
      integer :: i

      if (p%dof(e) > 0) then
         m = mass(p%dof(e))
         return
      end if
      s = 0.0_dp
      m = 0.0_dp
      associate (r => p%end_row(e))
         do i = r%start(1), r%start(2) - 1
            w = r%scale(1)*r%coef(i)
            if (w == 0.0_dp) cycle
            if (.not. (mass(r%dof(i)) > 0.0_dp)) return
            s = s + w*w/mass(r%dof(i))
         end do
      end associate
      if (s > 0.0_dp) m = 1.0_dp/s
   end function end_mass

   !> Sign of a constraint end in B: +1 on the left, -1 on the right.
   pure real(dp) function end_sign(e)
      !> The end (1 left, 2 right).
      integer, intent(in) :: e

      end_sign = merge(1.0_dp, -1.0_dp, e == 1)
   end function end_sign

end module pound_contact_pair
