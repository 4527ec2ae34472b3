!> The joint laws pound knows, by deck name: one line per law (name, constructor from the
!> deck's `&contact` group, reader of its variables, the `&contact` variables it declares
!> (`law_variable`: name, type, size, unit; each law module declares its own), whether it
!> calibrates its dashpot to a coefficient of restitution). The deck's variable table of
!> `&contact` is generated from it (`law_variables`, pound_deck_variables), the deck checks
!> the law name and refuses the variables of other laws from it; `pairs_from_config` builds
!> each group's law through it. Adding a law: its module (pound_joint_law explains what it
!> supplies) and one line in `registered_laws`.
module pound_law_registry
   use pound_error, only: error_type, fatal_error
   use pound_contact_settings, only: contact_config
   use pound_contact_law, only: contact_law
   use pound_joint_law, only: law_input, law_variable
   use pound_input_checks, only: input_site
   use pound_law_elastic, only: elastic_from_config, elastic_take, elastic_variables
   use pound_law_bilinear, only: bilinear_from_config, elastic_plastic_from_config, bilinear_take, elastic_plastic_take, &
                                 bilinear_variables, elastic_plastic_variables
   use pound_law_piecewise, only: piecewise_from_config, piecewise_take, piecewise_variables
   use pound_law_parabola_cubic, only: parabola_cubic_from_config, parabola_cubic_take, parabola_cubic_variables
   use pound_law_kelvin, only: kelvin_from_config, kelvin_take, kelvin_variables
   use pound_law_hertz, only: hertz_from_config, hertz_take, hertz_variables
   use pound_law_hertz_damp, only: hertz_damp_from_config, hertz_damp_take, hertz_damp_variables
   use pound_law_jankowski, only: jankowski_from_config, jankowski_take, jankowski_variables
   implicit none
   private

   public :: law_entry, registered_laws, law_from_config, law_is_registered, law_reads, law_restitution, &
             registered_law_names, law_take_deck, restitution_law_names, law_variables, law_stiffness_linear

   abstract interface
      !> Build the law of a `&contact` group (its parameters already checked by the deck).
      pure subroutine law_constructor(c, law, error)
         import :: contact_config, contact_law, error_type
         !> The deck's group.
         type(contact_config), intent(in) :: c
         !> The compiled law.
         type(contact_law), intent(out) :: law
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine law_constructor

      !> Check the law's own `&contact` variables as read and put them into the group's
      !> configuration (messages name the deck line, group and variable).
      pure subroutine law_deck_reader(at, raw, cfg, error)
         import :: input_site, law_input, contact_config, error_type
         !> Where messages point.
         class(input_site), intent(in) :: at
         !> The law variables as read.
         type(law_input), intent(in) :: raw
         !> The group's configuration.
         type(contact_config), intent(inout) :: cfg
         !> Error state.
         type(error_type), allocatable, intent(out) :: error
      end subroutine law_deck_reader
   end interface

   !> One registered law.
   type :: law_entry
      !> Deck name (`law = '...'`).
      character(len=24) :: name = ''
      !> Its constructor from the deck's group.
      procedure(law_constructor), pointer, nopass :: make => null()
      !> Its reader of the deck's variables.
      procedure(law_deck_reader), pointer, nopass :: take => null()
      !> The `&contact` variables it reads (beside the joint's: left, right, floors,
      !> elevations, gap, law, restitution, variant), as its module declares them.
      type(law_variable), allocatable :: variables(:)
      !> It may calibrate its dashpot to `restitution`.
      logical :: restitution = .false.
   end type law_entry

contains

   !> The registration table, in the order the deck's messages name the laws.
   pure subroutine registered_laws(laws)
      !> The table.
      type(law_entry), allocatable, intent(out) :: laws(:)

      laws = [law_entry('elastic', elastic_from_config, elastic_take, elastic_variables, .true.), &
              law_entry('elastic_plastic', elastic_plastic_from_config, elastic_plastic_take, &
                        elastic_plastic_variables, .false.), &
              law_entry('bilinear', bilinear_from_config, bilinear_take, bilinear_variables, .false.), &
              law_entry('piecewise', piecewise_from_config, piecewise_take, piecewise_variables, .false.), &
              law_entry('parabola_cubic', parabola_cubic_from_config, parabola_cubic_take, &
                        parabola_cubic_variables, .false.), &
              law_entry('kelvin', kelvin_from_config, kelvin_take, kelvin_variables, .true.), &
              law_entry('hertz', hertz_from_config, hertz_take, hertz_variables, .false.), &
              law_entry('hertz_damp', hertz_damp_from_config, hertz_damp_take, hertz_damp_variables, .true.), &
              law_entry('jankowski', jankowski_from_config, jankowski_take, jankowski_variables, .true.)]
   end subroutine registered_laws

   !> The table's entry of law `name` (0: none).
   pure integer function law_index(name) result(i)
      character(len=*), intent(in) :: name
      type(law_entry), allocatable :: laws(:)

      call registered_laws(laws)
      do i = 1, size(laws)
         if (trim(laws(i)%name) == name) return
      end do
      i = 0
   end function law_index

   !> The table's entry of law `name` (a blank entry for an unknown law).
   pure function law_entry_of(name) result(e)
      character(len=*), intent(in) :: name
      type(law_entry) :: e
      type(law_entry), allocatable :: laws(:)
      integer :: i

      i = law_index(name)
      if (i == 0) return
      call registered_laws(laws)
      e = laws(i)
   end function law_entry_of

   !> `name` is a registered law.
   pure logical function law_is_registered(name)
      !> Deck name.
      character(len=*), intent(in) :: name

      law_is_registered = law_index(name) > 0
   end function law_is_registered

   !> Registered law `name` reads the `&contact` variable `var` (false for an unknown law).
   pure logical function law_reads(name, var)
      !> Deck name of the law.
      character(len=*), intent(in) :: name
      !> Variable name.
      character(len=*), intent(in) :: var
      type(law_entry) :: e

      integer :: i

      law_reads = .false.
      e = law_entry_of(name)
      if (len_trim(e%name) == 0) return
      do i = 1, size(e%variables)
         if (e%variables(i)%name == var) law_reads = .true.
      end do
   end function law_reads

   !> Whether the stiffness of registered law `name` (`contact_config%stiffness` once its
   !> variables are read: given, or derived as k0) is a linear joint stiffness in kN/m: every
   !> law but those that declare `stiffness` in another unit (the Hertz family's kN/m^(3/2));
   !> false for an unknown law.
   pure logical function law_stiffness_linear(name)
      !> Deck name of the law.
      character(len=*), intent(in) :: name
      type(law_entry) :: e
      integer :: i

      law_stiffness_linear = .false.
      e = law_entry_of(name)
      if (len_trim(e%name) == 0) return
      law_stiffness_linear = .true.
      do i = 1, size(e%variables)
         if (e%variables(i)%name == 'stiffness' .and. e%variables(i)%unit /= 'kN/m') law_stiffness_linear = .false.
      end do
   end function law_stiffness_linear

   !> Every `&contact` variable of the registered laws, once each, in the order the laws
   !> declare them (the table's order), then `restitution` (the laws that calibrate their
   !> dashpot to it; its refusal is the deck's own): what the deck's variable table lists
   !> for `&contact` beside the joint's variables.
   pure function law_variables() result(vars)
      type(law_variable), allocatable :: vars(:)
      type(law_entry), allocatable :: laws(:)
      integer :: i, j

      call registered_laws(laws)
      allocate (vars(0))
      do i = 1, size(laws)
         do j = 1, size(laws(i)%variables)
            if (any(vars%name == laws(i)%variables(j)%name)) cycle
            vars = [vars, laws(i)%variables(j)]
         end do
      end do
      if (any(laws%restitution)) vars = [vars, law_variable('restitution', 'r', 0, '', .false.)]
   end function law_variables

   !> Registered law `name` may calibrate its dashpot to a coefficient of restitution.
   pure logical function law_restitution(name)
      !> Deck name of the law.
      character(len=*), intent(in) :: name
      type(law_entry) :: e

      e = law_entry_of(name)
      law_restitution = e%restitution
   end function law_restitution

   !> The registered names for messages: "'a', 'b' or 'c'".
   pure function registered_law_names() result(s)
      character(len=:), allocatable :: s
      type(law_entry), allocatable :: laws(:)
      integer :: i

      call registered_laws(laws)
      s = ''
      do i = 1, size(laws)
         if (i > 1 .and. i < size(laws)) s = s//', '
         if (i > 1 .and. i == size(laws)) s = s//' or '
         s = s//"'"//trim(laws(i)%name)//"'"
      end do
   end function registered_law_names

   !> The names of the laws that read `restitution`, for messages: "'a', 'b' or 'c'".
   pure function restitution_law_names() result(s)
      character(len=:), allocatable :: s
      type(law_entry), allocatable :: laws(:)
      integer :: i, n, j

      call registered_laws(laws)
      n = count(laws%restitution)
      s = ''
      j = 0
      do i = 1, size(laws)
         if (.not. laws(i)%restitution) cycle
         j = j + 1
         if (j > 1 .and. j < n) s = s//', '
         if (j > 1 .and. j == n) s = s//' or '
         s = s//"'"//trim(laws(i)%name)//"'"
      end do
   end function restitution_law_names

   !> Check the `&contact` variables of law `name` (registered) as read and put them into the
   !> group's configuration, by the law's own reader.
   pure subroutine law_take_deck(name, at, raw, cfg, error)
      !> Deck name of the law.
      character(len=*), intent(in) :: name
      !> Where messages point.
      class(input_site), intent(in) :: at
      !> The law variables as read.
      type(law_input), intent(in) :: raw
      !> The group's configuration.
      type(contact_config), intent(inout) :: cfg
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      type(law_entry) :: e

      e = law_entry_of(name)
      if (.not. associated(e%take)) then
         call fatal_error(error, "unknown law '"//name//"', must be "//registered_law_names())
         return
      end if
      call e%take(at, raw, cfg, error)
   end subroutine law_take_deck

   !> The law of a `&contact` group, by its `law` name.
   pure subroutine law_from_config(c, law, error)
      !> The deck's group.
      type(contact_config), intent(in) :: c
      !> The compiled law.
      type(contact_law), intent(out) :: law
      !> Error state (an unknown name, or a law that cannot be built).
      type(error_type), allocatable, intent(out) :: error
      type(law_entry), allocatable :: laws(:)
      integer :: i

      i = law_index(c%law)
      if (i == 0) then
         call fatal_error(error, "unknown law '"//c%law//"', must be "//registered_law_names())
         return
      end if
      call registered_laws(laws)
      call laws(i)%make(c, law, error)
   end subroutine law_from_config

end module pound_law_registry
