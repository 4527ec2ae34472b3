!> The analysis plan: what `&analysis` asks of the time integration, decided once (by the
!> driver, `pound_run_case::analysis_plan_of`) and passed down to the kernels, which never
!> read the deck's configuration nor compare its option strings.
!>
!> | field | from `&analysis` |
!> |---|---|
!> | `dt`, `t_end` | `dt`, `t_end` |
!> | `n_steps` | nint(t_end/dt) (`steps_of`) |
!> | `output_every`, outputs() | `output_every`; n_steps/output_every + 1 samples (`output_steps`) |
!> | `store`, `node_histories` | `history`, `node_histories` |
!> | `stepping` | `stepping`: `stepping_uniform` ('uniform') or `stepping_impact` ('impact') |
!> | `impact_substeps` | `impact_substeps` (0: from the joints' contact half-periods) |
!> | `free_steps` | `free_steps`: `free_newmark` ('newmark') or `free_exact` ('exact') |
!> | `lcp_solver` | `lcp_solver`: `lcp_auto` ('auto') or `lcp_lemke` ('lemke') |
!> | `integrator`, `hht_alpha` | `integrator`: `integrator_newmark` ('newmark') or `integrator_hht` ('hht'); `hht_alpha` |
module pound_analysis_plan
   use, intrinsic :: iso_fortran_env, only: int64
   use pound_kinds, only: dp
   use pound_quantities, only: n_history_quantities
   implicit none
   private

   public :: analysis_plan, steps_of, steps_of_int64, output_steps
   public :: stepping_uniform, stepping_impact, free_newmark, free_exact, lcp_auto, lcp_lemke
   public :: integrator_newmark, integrator_hht

   !> Stepping policy of the coupled analysis: every step dt, or a step in which a joint is
   !> closed or predicted to close taken as `impact_substeps` substeps.
   integer, parameter :: stepping_uniform = 1, stepping_impact = 2
   !> Steps in which no joint acts: Newmark average acceleration, or the exact step of the
   !> linear structure.
   integer, parameter :: free_newmark = 1, free_exact = 2
   !> LCP method of the coupled steps: the active-set method where it applies (Lemke
   !> otherwise), or Lemke at every step.
   integer, parameter :: lcp_auto = 1, lcp_lemke = 2
   !> Time integrator: Newmark average acceleration or HHT-alpha.
   integer, parameter :: integrator_newmark = 1, integrator_hht = 2

   !> What the time integration does, decided once from `&analysis`.
   type :: analysis_plan
      !> Time step (s).
      real(dp) :: dt = 0.0_dp
      !> Duration (s).
      real(dp) :: t_end = 0.0_dp
      !> Number of time steps, nint(t_end/dt).
      integer :: n_steps = 0
      !> History output every `output_every` steps.
      integer :: output_every = 1
      !> Which history quantities are stored (order of `history_names`).
      logical :: store(n_history_quantities) = .true.
      !> Every DOF's displacement history of each frame building.
      logical :: node_histories = .false.
      !> Stepping policy (`stepping_uniform`, `stepping_impact`).
      integer :: stepping = stepping_uniform
      !> Substeps per impact step; 0: chosen from the joints' contact half-periods.
      integer :: impact_substeps = 0
      !> Free steps (`free_newmark`, `free_exact`).
      integer :: free_steps = free_newmark
      !> LCP method (`lcp_auto`, `lcp_lemke`).
      integer :: lcp_solver = lcp_auto
      !> A building with bilinear storeys collapses when a storey's drift / height passes this.
      real(dp) :: collapse_drift = 0.10_dp
      !> Time integrator (`integrator_newmark`, `integrator_hht`) and HHT-alpha's alpha.
      integer :: integrator = integrator_newmark
      real(dp) :: hht_alpha = 0.0_dp
      !> The ground component along y at t_n = n dt (0:n_steps, m/s^2): allocated by run_case
      !> when the ground moves along y and a building has DOFs along y (a plan building);
      !> such a building then takes -M (r_x a_gx + r_y a_gy).
      real(dp), allocatable :: ground_y(:)
   contains

      !> Number of output samples of a whole history (t = 0 included).
      procedure :: outputs => plan_outputs
      !> Whether the steps are Newmark's average acceleration (HHT-alpha with alpha = 0 is).
      procedure :: average_acceleration => plan_average_acceleration
   end type analysis_plan

contains

   !> Whether the steps are Newmark's average acceleration: integrator = 'newmark', or 'hht'
   !> with alpha = 0 (beta = 1/4, gamma = 1/2 and no alpha term: the same method, so the same
   !> code and the same numbers).
   pure logical function plan_average_acceleration(plan)
      !> The plan.
      class(analysis_plan), intent(in) :: plan

      plan_average_acceleration = plan%integrator == integrator_newmark .or. plan%hht_alpha == 0.0_dp
   end function plan_average_acceleration

   !> Number of time steps of a run of duration `t_end` with step `dt`: nint(t_end/dt), the
   !> one place this is computed (a validated deck has at most 10^9 steps: a default integer).
   pure integer function steps_of(t_end, dt)
      !> Duration (s).
      real(dp), intent(in) :: t_end
      !> Time step (s), > 0.
      real(dp), intent(in) :: dt

      steps_of = int(steps_of_int64(t_end, dt))
   end function steps_of

   !> nint(t_end/dt) as a 64-bit integer: the steps of a deck not yet checked (the memory
   !> estimate counts beyond the default integers).
   pure integer(int64) function steps_of_int64(t_end, dt)
      !> Duration (s).
      real(dp), intent(in) :: t_end
      !> Time step (s), > 0.
      real(dp), intent(in) :: dt

      steps_of_int64 = nint(t_end/dt, int64)
   end function steps_of_int64

   !> Number of output samples for n_steps steps stored every `every` steps (t = 0 included).
   pure integer function output_steps(n_steps, every)
      !> Number of time steps.
      integer, intent(in) :: n_steps
      !> Output interval in steps.
      integer, intent(in) :: every

      output_steps = n_steps/every + 1
   end function output_steps

   !> Number of output samples of a whole history of the plan (t = 0 included).
   pure integer function plan_outputs(plan)
      !> The plan.
      class(analysis_plan), intent(in) :: plan

      plan_outputs = output_steps(plan%n_steps, plan%output_every)
   end function plan_outputs

end module pound_analysis_plan
