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
   use pound_error, only: fatal_error
   use pound_contact_law, only: contact_law, rate_trapezoidal, rate_backward_euler, scale_law_force
   use pound_law_registry, only: law_from_config
   use pound_contact_settings, only: contact_config
   use pound_structure, only: recovery_rows, recover, structure_model, plan_point_row
   use pound_plan_geometry, only: plane_x, plane_y, plan_dof, plan_ux
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
      !> Constraint law (of a contact point: the pair's law with its force scaled by `share`,
      !> a smooth law's own force too: `scale_law_force`).
      type(contact_law) :: law
      !> Buildings in plan: the share of its pair this contact point takes (1/2 of two points,
      !> 1 of one; `scale_law_force`), the DOF whose lumped mass times `share` is the end's mass
      !> for the restitution (the floor's u_x: two points of a symmetric pair calibrate the
      !> pair's dashpot, halved; 0: `end_mass`), and the point's site y (m).
      real(dp) :: share = 1.0_dp
      integer :: mass_dof(2) = 0
      real(dp) :: site_y = 0.0_dp
      !> Coulomb friction at the point: coefficient mu (0: none, no tangential rows) and the
      !> point's tangential stiffness kt (kN/m, the pair's `shear_stiffness` times `share`).
      real(dp) :: friction = 0.0_dp, shear_stiffness = 0.0_dp
      !> Each end's displacement along the facade (site y) as a sparse row (`plan_point_row`
      !> of u_y); unset (n = 0) without friction.
      type(recovery_rows) :: tan_row(2)
   end type contact_pair

contains

   !> One constraint per facing floor pair of the deck's `&contact` groups, in deck order;
   !> between buildings in plan (`models` given, a building's `plan` allocated), one or two
   !> contact points per floor pair (`plan_points`).
   function pairs_from_config(contacts, names, error, models) result(pairs)
      !> The deck's contact groups.
      type(contact_config), intent(in) :: contacts(:)
      !> Building names, in deck order.
      character(len=*), intent(in) :: names(:)
      !> Error state (a law that cannot be built, facades that do not overlap).
      type(error_type), allocatable, intent(out) :: error
      !> The structural models, in deck order (needed for buildings in plan).
      type(structure_model), intent(in), optional :: models(:)
      type(contact_pair), allocatable :: pairs(:)
      type(contact_law) :: law
      real(dp) :: ys(2)
      integer :: i, k, n, np, ip

      n = 0
      do i = 1, size(contacts)
         np = 1
         if (plan_contact(contacts(i), models)) then
            call plan_points(contacts(i), i, names, models, ys, np, error)
            if (allocated(error)) then
               allocate (pairs(0))
               return
            end if
         end if
         n = n + np*size(contacts(i)%floor_left)
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
            if (.not. plan_contact(c, models)) then
               if (c%friction > 0.0_dp) then
                  call fatal_error(error, '&contact #'//str(i)//' ('//pair_names(c, names)//'): friction = '// &
                                   str(c%friction)//' needs buildings in plan (model = ''plan''): a planar '// &
                                   'pair has no displacement along the facades; set friction = 0')
                  return
               end if
               do k = 1, size(c%floor_left)
                  n = n + 1
                  pairs(n)%building = [c%left_index, c%right_index]
                  pairs(n)%floor = [c%floor_left(k), c%floor_right(k)]
                  if (allocated(c%elevation)) pairs(n)%elevation = c%elevation(k)
                  pairs(n)%label = pair_label(pairs(n), names(c%left_index), names(c%right_index))
                  pairs(n)%gap = c%gap(k)
                  pairs(n)%law = law
               end do
               cycle
            end if
            call plan_points(c, i, names, models, ys, np, error)
            if (allocated(error)) return
            do k = 1, size(c%floor_left)
               do ip = 1, np
                  n = n + 1
                  call plan_point(pairs(n), c, k, ys(ip), np, law, names, models)
               end do
            end do
         end associate
      end do
   end function pairs_from_config

   !> Whether a contact group joins buildings in plan (either end a building with `plan`).
   logical function plan_contact(c, models) result(plan)
      type(contact_config), intent(in) :: c
      type(structure_model), intent(in), optional :: models(:)

      plan = .false.
      if (.not. present(models)) return
      if (c%left_index > 0) plan = allocated(models(c%left_index)%plan)
      if (c%right_index > 0) plan = plan .or. allocated(models(c%right_index)%plan)
   end function plan_contact

   !> 'A-B' of a contact group, for messages ('wall' for a rigid neighbour).
   function pair_names(c, names) result(s)
      type(contact_config), intent(in) :: c
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: s

      s = side_name(names, c%left_index)//'-'//side_name(names, c%right_index)
   end function pair_names

   !> The name of building b ('wall' for 0, a rigid neighbour).
   pure function side_name(names, b) result(t)
      character(len=*), intent(in) :: names(:)
      integer, intent(in) :: b
      character(len=:), allocatable :: t

      t = 'wall'
      if (b > 0) t = trim(names(b))
   end function side_name

   !> The site y of the contact points of a group between buildings in plan: the overlap
   !> [y_lo, y_hi] = [max(y0_A, y0_B), min(y0_A + Ly_A, y0_B + Ly_B)] of A's right facade and
   !> B's left facade (a rigid neighbour spans the other's facade); y_lo > y_hi is refused,
   !> y_lo = y_hi is one point, else two (y_lo, y_hi).
   subroutine plan_points(c, i, names, models, ys, np, error)
      type(contact_config), intent(in) :: c
      integer, intent(in) :: i
      character(len=*), intent(in) :: names(:)
      type(structure_model), intent(in) :: models(:)
      real(dp), intent(out) :: ys(2)
      integer, intent(out) :: np
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: lo, hi
      character(len=:), allocatable :: spans
      integer :: e, b

      lo = -huge(1.0_dp)
      hi = huge(1.0_dp)
      spans = ''
      np = 0
      ys = 0.0_dp
      do e = 1, 2
         b = merge(c%left_index, c%right_index, e == 1)
         if (b == 0) cycle
         if (.not. allocated(models(b)%plan)) then
            call fatal_error(error, '&contact #'//str(i)//' ('//pair_names(c, names)//'): building '// &
                             trim(names(b))//' is not in plan; in a deck with a ''plan'' building every '// &
                             'building is ''plan''')
            return
         end if
         associate (g => models(b)%plan)
            lo = max(lo, g%y0)
            hi = min(hi, g%y0 + g%ly)
            if (len(spans) > 0) spans = spans//', '
            spans = spans//trim(names(b))//' spans y = '//str(g%y0)//' .. '//str(g%y0 + g%ly)//' m'
         end associate
      end do
      if (lo > hi) then
         call fatal_error(error, '&contact #'//str(i)//' ('//pair_names(c, names)//'): the facing facades '// &
                          'do not overlap along y ('//spans//'): no contact point; move plan_origin_y or '// &
                          'drop the &contact')
         return
      end if
      if (lo == hi) then
         np = 1
         ys(1) = lo
      else
         np = 2
         ys = [lo, hi]
      end if
   end subroutine plan_points

   !> Contact point of floor pair k of group c at site y: its ends (u_x and u_y rows of A's
   !> right facade x = Lx_A and B's left facade x = 0), the pair's law with its force scaled
   !> by the point's share (1/np), its friction and tangential stiffness, its label.
   subroutine plan_point(p, c, k, y, np, law, names, models)
      type(contact_pair), intent(inout) :: p
      type(contact_config), intent(in) :: c
      integer, intent(in) :: k, np
      real(dp), intent(in) :: y
      type(contact_law), intent(in) :: law
      character(len=*), intent(in) :: names(:)
      type(structure_model), intent(in) :: models(:)
      real(dp) :: px
      integer :: e, b, f

      p%building = [c%left_index, c%right_index]
      p%floor = [c%floor_left(k), c%floor_right(k)]
      p%label = pair_label(p, side_name(names, c%left_index), side_name(names, c%right_index))//'@y='//site_text(y)
      p%gap = c%gap(k)
      p%share = 1.0_dp/real(np, dp)
      p%site_y = y
      p%law = law
      if (np > 1) call scale_law_force(p%law, p%share)
      p%friction = c%friction
      if (c%friction > 0.0_dp) then
         if (c%shear_stiffness > 0.0_dp) then
            p%shear_stiffness = p%share*c%shear_stiffness
         else
            p%shear_stiffness = p%law%stiffness
         end if
      end if
      do e = 1, 2
         b = p%building(e)
         f = p%floor(e)
         if (b == 0) cycle
         px = merge(models(b)%plan%lx, 0.0_dp, e == 1)
         p%end_row(e) = plan_point_row(models(b), f, px, y - models(b)%plan%y0, plane_x)
         if (c%friction > 0.0_dp) p%tan_row(e) = plan_point_row(models(b), f, px, y - models(b)%plan%y0, plane_y)
         p%mass_dof(e) = plan_dof(f, plan_ux)
      end do
   end subroutine plan_point

   !> A site y in labels: metres with at least two and at most three decimals, a negative
   !> value written 'neg' (a label holds no '-' but its separator): '2.50m', 'neg1.25m'.
   pure function site_text(y) result(s)
      real(dp), intent(in) :: y
      character(len=:), allocatable :: s
      character(len=32) :: buf

      write (buf, '(f0.3)') abs(y)
      s = trim(adjustl(buf))
      if (s(1:1) == '.') s = '0'//s
      if (s(len(s):len(s)) == '0') s = s(1:len(s) - 1)
      s = s//'m'
      if (y < 0.0_dp) s = 'neg'//s
   end function site_text

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
