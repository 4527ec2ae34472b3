!> The interface of a joint law: what a complementarity element's constitutive part tells
!> the rest of pound (its deck name, its listing lines, whether the step must iterate on it)
!> without anyone reading its internals or dispatching on its kind.
!>
!> A joint (a complementarity element of the per-step LCP, `pound_contact`) is
!>
!> - its ends: a sparse row of DOFs on each model it joins (`pound_contact_pair`,
!>   `contact_pair%end_row`), the closing displacement v = B^T u;
!> - its LCP rows: a piecewise-linear law compiled once into `contact_law` (pound_contact_law:
!>   initial stiffness k0, dashpot, yield function r_y(d_p) as nodes and plastic moduli, the
!>   envelope for the writers); the step assembles one contact row, one yield row and the
!>   hinge rows of the segment ends it passes from those tables (`pound_contact_lcp`);
!> - its state and its energy terms (`pound_joint_state`: advance after an accepted step,
!>   work of the force, work in the joint, plastic work), written once for every law of the
!>   family in terms of the compiled rows;
!> - its description, an extension of `joint_law` (this module) kept in `contact_law%given`:
!>   the deck name (`name`), the listing lines of its own parameters (`describe`), and the
!>   iteration hook (`iterates`, `relinearise`).
!>
!> **Adding a piecewise-linear law** is one module (an extension of `joint_law` with `name`
!> and `describe`, a constructor `make_*` that checks its parameters and compiles its envelope
!> polygon with `compile_envelope`, and a constructor from the deck's `&contact` group) plus
!> one line in `pound_law_registry` (deck name, constructor, the `&contact` variables it
!> reads). See docs/architecture.md, "How to add a joint law".
!>
!> **Smooth laws (Kelvin, Hertz, Hertz-damp, Jankowski).** A law whose `iterates` is true is
!> listed once by `contact_init` (`contact_system%iterating`). One that gives its force
!> (`force`: f(d, d'; v0) before the clip and its derivatives; the laws of pound_law_smooth)
!> is solved exactly per step by Newton, each iterate one LCP with the law's tangent row
!> (pound_contact_smooth); it also takes the facing masses (`set_masses`) and shows its
!> stiffness as given (`shown_stiffness`). One without a force re-linearises a secant after
!> each solve (`relinearise`: a law that moves its secant by more than its own tolerance says
!> so, `changed`, and the LCP is solved again), at most `max_law_iterations` solves.
!> Piecewise-linear laws keep the defaults (no iteration, nothing listed): the loop is empty
!> and costs nothing; `contact_solve` has no branch on a law.
module pound_joint_law
   use pound_kinds, only: dp
   use pound_input_checks, only: is_set, given_count, unset_int
   implicit none
   private

   public :: joint_law, law_text, law_input, add_line, max_law_iterations, law_iteration_limit, law_variable, &
             dashpot_variables

   !> Largest number of LCP solves of one step while iterating laws ask for another.
   integer, parameter :: max_law_iterations = 50
   !> The limit `contact_solve` applies: `max_law_iterations`, lowered only by tests (a test
   !> hook that forces a step that does not converge, pound_step_retry); no deck sets it.
   integer :: law_iteration_limit = max_law_iterations

   !> One line of text (a law's listing lines).
   type :: law_text
      !> The line, without the listing's indentation.
      character(len=:), allocatable :: line
   end type law_text

   !> A `&contact` variable a law reads: what the deck's variable table (pound_deck_variables,
   !> generated from pound_law_registry) and its refusals know of it.
   type :: law_variable
      !> Name (lower case).
      character(len=20) :: name = ''
      !> Type: 'r' real, 'i' integer, 'c' character.
      character :: vtype = 'r'
      !> Number of elements, 0 for a scalar.
      integer :: vsize = 0
      !> Unit, for the documentation of the table ('' for a number or a word).
      character(len=12) :: unit = ''
      !> Given to a law that does not read it: refused by the deck ("... is not used by law =
      !> ..."); false for a variable whose refusal is the laws' own (`dashpot` of a smooth
      !> law) or that is not refused (`dashpot_rate`).
      logical :: refused = .true.
   end type law_variable

   !> The variables of the joint's dashpot in parallel, which every piecewise-linear law reads.
   type(law_variable), parameter :: dashpot_variables(2) = [law_variable('dashpot', 'r', 0, 'kN s/m', .false.), &
                                                            law_variable('dashpot_rate', 'c', 0, '', .false.)]

   !> The `&contact` variables of the laws as the deck read them (unset values: the deck's
   !> sentinels, pound_input_checks `is_set`), handed to the law's deck reader
   !> (`pound_law_registry`: `law_take_deck`), which checks those it reads.
   type :: law_input
      !> Scalars: stiffness k0 (kN/m), yield force (kN), second slope (kN/m), peak force rB
      !> (kN), peak and fracture penetrations dB, dF (m).
      real(dp) :: stiffness = 0.0_dp, yield_force = 0.0_dp, second_slope = 0.0_dp, peak_force = 0.0_dp, &
                  peak_penetration = 0.0_dp, fracture_penetration = 0.0_dp
      !> Chords per curved branch.
      integer :: n_segments = 0
      !> Envelope points as read (the namelist's whole arrays: unset beyond those given).
      real(dp), allocatable :: envelope_d(:), envelope_r(:)
      !> The common `dashpot` (kN s/m) and `restitution` as read (a smooth law refuses a
      !> dashpot and may require a restitution; the deck's own checks of them follow).
      real(dp) :: dashpot = 0.0_dp, restitution = 0.0_dp
   contains
      !> The deck gave the law variable `name` (a value, or an array's value); false for a
      !> name that is not one of them.
      procedure :: given => law_input_given
   end type law_input

   !> A joint law, as described to the listing, the HDF5 writer and the step.
   type, abstract :: joint_law
   contains
      !> Its name as written in the deck (`law = '...'`).
      procedure(law_name_i), deferred :: name
      !> The listing lines of its own parameters (none for a law of k0 alone).
      procedure(law_describe_i), deferred :: describe
      !> The step must iterate on this law (a smooth law linearised around the LCP); the
      !> default: piecewise linear, no iteration.
      procedure :: iterates => law_no_iteration
      !> Re-linearise around the compression and force of the last solve; the default:
      !> piecewise linear, nothing changes.
      procedure :: relinearise => law_keep_linearisation
      !> A smooth law's force f(d, d'; v0) before the clip r = max(0, f) and its partial
      !> derivatives (`defined` false by default: the law has no force of its own and is
      !> solved by its rows, or re-linearised by `relinearise`). The step solves such a law
      !> exactly by Newton on its tangent (pound_contact_smooth).
      procedure :: force => law_no_force
      !> Set the masses of the two facing ends (t; 0: rigid) where the law needs them (a
      !> dashpot calibrated to a restitution); default: nothing.
      procedure :: set_masses => law_ignore_masses
      !> The stiffness the law shows in the joints' table (kN/m or kN/m^(3/2)); default 0:
      !> the rows' own.
      procedure :: shown_stiffness => law_no_shown_stiffness
      !> The unit of the stiffness the law shows (`shown_stiffness`, or the rows' k0); default
      !> 'kN/m'.
      procedure :: stiffness_unit => law_stiffness_unit
      !> The law has a force of its own (`force`): a smooth law, solved by Newton around the
      !> step's LCP (pound_contact_smooth); default false (solved by its rows).
      procedure :: has_force => law_has_no_force
      !> Duration (s) of a central impact of masses m1, m2 (t; 0: rigid) at the approach speed
      !> v (m/s) on the law's own force; default 0: none of its own (the rows' half-period
      !> pi sqrt(m_eff/k0) applies).
      procedure :: contact_duration => law_no_contact_duration
      !> The realised coefficient of restitution of the law's calibration (computed once, when
      !> the facing masses are set); default 0: not a smooth law.
      procedure :: realised_restitution => law_no_realised_restitution
      !> Trial state: the slope (kN/m) of the law's row at the current iterate of the step
      !> (a smooth law's tangent or secant, pound_contact_smooth); default: nothing kept.
      procedure :: set_trial => law_no_trial
      !> Commit the step: the trial state is dropped and the row's slope is the committed one
      !> (`committed_stiffness`); default: nothing kept.
      procedure :: commit => law_no_commit
      !> The slope (kN/m) of the law's row: the trial one during a step, else the committed
      !> one; `k_rows` (the rows' own k0) for a law without trial state.
      procedure :: row_stiffness => law_rows_stiffness
      !> Scale the law's own force by s > 0 (a contact point that takes the share s of its
      !> pair, pound_contact_pair; `contact_law`'s `scale_law_force` scales the rows); default:
      !> nothing (a piecewise-linear law's force is its rows').
      procedure :: scale_force => law_no_scale
   end type joint_law

   abstract interface
      !> Deck name of a law.
      pure function law_name_i(law) result(name)
         import :: joint_law
         !> The law.
         class(joint_law), intent(in) :: law
         character(len=:), allocatable :: name
      end function law_name_i

      !> Listing lines of a law's parameters.
      pure function law_describe_i(law) result(lines)
         import :: joint_law, law_text
         !> The law.
         class(joint_law), intent(in) :: law
         type(law_text), allocatable :: lines(:)
      end function law_describe_i
   end interface

contains

   !> Append the line `s` to `lines` (element by element: no array constructor of strings
   !> of different lengths).
   pure subroutine add_line(lines, s)
      !> The lines (allocated, possibly empty, on return).
      type(law_text), allocatable, intent(inout) :: lines(:)
      !> The new line.
      character(len=*), intent(in) :: s
      type(law_text), allocatable :: more(:)
      integer :: i, n

      n = 0
      if (allocated(lines)) n = size(lines)
      allocate (more(n + 1))
      do i = 1, n
         more(i)%line = lines(i)%line
      end do
      more(n + 1)%line = s
      call move_alloc(more, lines)
   end subroutine add_line

   !> Default `iterates`: a piecewise-linear law is solved exactly by one LCP.
   pure logical function law_no_iteration(law) result(it)
      !> The law.
      class(joint_law), intent(in) :: law

      associate (unused => law)
      end associate
      it = .false.
   end function law_no_iteration

   !> Default `relinearise`: the rows of a piecewise-linear law do not depend on the state.
   pure subroutine law_keep_linearisation(law, d, r, stiffness, changed)
      !> The law.
      class(joint_law), intent(in) :: law
      !> Joint compression (m) and force (kN) the last solve of the step gave.
      real(dp), intent(in) :: d, r
      !> Stiffness of the joint's elastic row (kN/m): the secant a smooth law sets.
      real(dp), intent(inout) :: stiffness
      !> The stiffness moved beyond the law's tolerance: solve the step again.
      logical, intent(out) :: changed

      associate (unused => [d, r, stiffness])
      end associate
      associate (unused => law)
      end associate
      changed = .false.
   end subroutine law_keep_linearisation

   !> Default `force`: not a smooth law with a force of its own.
   pure subroutine law_no_force(law, d, ddot, v0, f, df_dd, df_dv, defined)
      !> The law.
      class(joint_law), intent(in) :: law
      !> Penetration d = v - gap (m), its rate (m/s) and the closing speed latched at the
      !> impact's start (m/s).
      real(dp), intent(in) :: d, ddot, v0
      !> Force before the clip (kN) and its derivatives by d (kN/m) and d' (kN s/m).
      real(dp), intent(out) :: f, df_dd, df_dv
      !> The law has a force of its own.
      logical, intent(out) :: defined

      associate (unused => [d, ddot, v0])
      end associate
      associate (unused => law)
      end associate
      f = 0.0_dp
      df_dd = 0.0_dp
      df_dv = 0.0_dp
      defined = .false.
   end subroutine law_no_force

   !> Default `set_masses`: the law needs no mass.
   pure subroutine law_ignore_masses(law, m1, m2)
      !> The law.
      class(joint_law), intent(inout) :: law
      !> Masses of the two ends (t; 0: rigid, infinite).
      real(dp), intent(in) :: m1, m2

      associate (unused => [m1, m2])
      end associate
      associate (unused => law)
      end associate
   end subroutine law_ignore_masses

   !> Default `shown_stiffness`: none (the rows' stiffness is shown).
   pure real(dp) function law_no_shown_stiffness(law) result(k)
      !> The law.
      class(joint_law), intent(in) :: law

      associate (unused => law)
      end associate
      k = 0.0_dp
   end function law_no_shown_stiffness

   !> The deck gave the law variable `name` (not the unset marker, pound_input_checks).
   pure logical function law_input_given(raw, name) result(given)
      !> The law variables as read.
      class(law_input), intent(in) :: raw
      !> Variable name.
      character(len=*), intent(in) :: name

      select case (name)
      case ('stiffness')
         given = is_set(raw%stiffness)
      case ('yield_force')
         given = is_set(raw%yield_force)
      case ('second_slope')
         given = is_set(raw%second_slope)
      case ('peak_force')
         given = is_set(raw%peak_force)
      case ('peak_penetration')
         given = is_set(raw%peak_penetration)
      case ('fracture_penetration')
         given = is_set(raw%fracture_penetration)
      case ('n_segments')
         given = raw%n_segments /= unset_int
      case ('envelope_d')
         given = .false.
         if (allocated(raw%envelope_d)) given = given_count(raw%envelope_d) > 0
      case ('envelope_r')
         given = .false.
         if (allocated(raw%envelope_r)) given = given_count(raw%envelope_r) > 0
      case ('dashpot')
         given = is_set(raw%dashpot)
      case ('restitution')
         given = is_set(raw%restitution)
      case default
         given = .false.
      end select
   end function law_input_given

   !> Default `stiffness_unit`: kN/m.
   pure function law_stiffness_unit(law) result(u)
      !> The law.
      class(joint_law), intent(in) :: law
      character(len=:), allocatable :: u

      associate (unused => law)
      end associate
      u = 'kN/m'
   end function law_stiffness_unit

   !> Default `has_force`: solved by its rows.
   pure logical function law_has_no_force(law) result(has)
      !> The law.
      class(joint_law), intent(in) :: law

      associate (unused => law)
      end associate
      has = .false.
   end function law_has_no_force

   !> Default `contact_duration`: none of its own (0).
   pure real(dp) function law_no_contact_duration(law, m1, m2, v) result(t)
      !> The law.
      class(joint_law), intent(in) :: law
      !> Masses of the two ends (t; 0: rigid) and the approach speed (m/s).
      real(dp), intent(in) :: m1, m2, v

      associate (unused => [m1, m2, v])
      end associate
      associate (unused => law)
      end associate
      t = 0.0_dp
   end function law_no_contact_duration

   !> Default `realised_restitution`: not a smooth law (0).
   pure real(dp) function law_no_realised_restitution(law) result(e_r)
      !> The law.
      class(joint_law), intent(in) :: law

      associate (unused => law)
      end associate
      e_r = 0.0_dp
   end function law_no_realised_restitution

   !> Default `set_trial`: no trial state.
   pure subroutine law_no_trial(law, k)
      !> The law.
      class(joint_law), intent(inout) :: law
      !> Slope of the row at the iterate (kN/m).
      real(dp), intent(in) :: k

      associate (unused => k)
      end associate
      associate (unused => law)
      end associate
   end subroutine law_no_trial

   !> Default `commit`: no trial state.
   pure subroutine law_no_commit(law)
      !> The law.
      class(joint_law), intent(inout) :: law

      associate (unused => law)
      end associate
   end subroutine law_no_commit

   !> Default `row_stiffness`: the rows' own k0.
   pure real(dp) function law_rows_stiffness(law, k_rows) result(k)
      !> The law.
      class(joint_law), intent(in) :: law
      !> The rows' k0 (kN/m).
      real(dp), intent(in) :: k_rows

      associate (unused => law)
      end associate
      k = k_rows
   end function law_rows_stiffness

   !> Default `scale_force`: the law has no force of its own (its rows are scaled).
   pure subroutine law_no_scale(law, s)
      !> The law.
      class(joint_law), intent(inout) :: law
      !> The factor.
      real(dp), intent(in) :: s

      associate (unused => s)
      end associate
      associate (unused => law)
      end associate
   end subroutine law_no_scale

end module pound_joint_law
