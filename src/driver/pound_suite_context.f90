!> What the cases of a suite share (`pound_suite`, `pound_suite_refine`): the deck (and the
!> same without its sweep), the buildings, the spectra's periods, the contact pairs as the
!> suite's rules see them, the targeted quantities, the sweep's grid, the motions of the
!> statistics and their uncoupled peaks, and the layout of a motion's outcome.
!>
!> The pairs are indexed by pair, in deck order (every pair of every `&contact`): each end is
!> a building and either a floor or a point between floors (a frame's column node, `&contact
!> elevations`), with its DOF; the levels of the two ends (a floor's: the sum of the storey
!> heights below it; a point's: its elevation) decide whether the floors coincide (EC8; both
!> ends floors, `levels_coincide`).
module pound_suite_context
   use pound_kinds, only: dp
   use pound_config, only: deck_type, n_target_quantities
   use pound_structure, only: structure_model, structure_end_dof
   use pound_analysis, only: analysis_result
   use pound_suite_outcome, only: outcome_layout
   use pound_separation, only: levels_coincide
   implicit none
   private

   public :: suite_context, suite_pair, suite_pairs

   !> One contact pair of the suite: its two ends.
   type :: suite_pair
      !> Building at each end (left, right).
      integer :: building(2) = 0
      !> Floor at each end (0: a point between floors).
      integer :: floor(2) = 0
      !> DOF of each end in its building's model.
      integer :: dof(2) = 0
      !> Whether the two ends are floors whose levels coincide (EC8 4.4.2.7's factor 0.7).
      logical :: coincide = .false.
   end type suite_pair

   !> What the suite's cases share.
   type :: suite_context
      !> The deck as given, and the same without its sweep (the runs at a trial gap).
      type(deck_type), pointer :: deck => null()
      type(deck_type) :: plain
      !> The buildings (periods for `scale_to = 'sa'`).
      type(structure_model), pointer :: models(:) => null()
      !> Quantities the target applies to (`target_names`).
      logical :: targeted(n_target_quantities) = .true.
      !> The sweep's gaps (m).
      real(dp), allocatable :: gap(:)
      !> Put before the messages (may be empty).
      character(len=:), allocatable :: label
      !> Periods of the spectra and the buildings' fundamental periods (s).
      real(dp), allocatable :: period(:), building_period(:)
      !> Contact pairs in deck order.
      type(suite_pair), allocatable :: pair(:)
      !> The motions the statistics are over (those whose run did not fail), in order.
      integer, allocatable :: used(:)
      !> With `&sweep`: each motion's uncoupled peaks (from its outcome), and whether they are
      !> there (its run did not fail); the runs at the sweep's gaps and at a refinement's trial
      !> gaps compare with them instead of running the uncoupled analysis again (it does not
      !> depend on the gap).
      type(analysis_result), allocatable :: unc(:)
      logical, allocatable :: has_unc(:)
      !> Whether the motions' sweeps run (`&sweep` and contact): each motion's case then makes
      !> its sweep's probe, and the gaps of every motion are the cases of one loop.
      logical :: sweep = .false.
      !> The sizes of a motion's outcome (`pound_suite_outcome`).
      type(outcome_layout) :: layout
   end type suite_context

contains

   !> The contact pairs of the deck in order (every pair of every `&contact`), their ends'
   !> DOFs in `models`.
   pure function suite_pairs(deck, models) result(pair)
      !> A validated configuration.
      type(deck_type), intent(in) :: deck
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      type(suite_pair), allocatable :: pair(:)
      real(dp) :: level(2), z
      integer :: ic, k, e, n

      allocate (pair(sum([(size(deck%contacts(ic)%floor_left), ic=1, size(deck%contacts))])))
      n = 0
      do ic = 1, size(deck%contacts)
         associate (c => deck%contacts(ic))
            do k = 1, size(c%floor_left)
               n = n + 1
               pair(n)%building = [c%left_index, c%right_index]
               pair(n)%floor = [c%floor_left(k), c%floor_right(k)]
               z = 0.0_dp
               if (allocated(c%elevation)) z = c%elevation(k)
               do e = 1, 2
                  associate (b => pair(n)%building(e), f => pair(n)%floor(e))
                     pair(n)%dof(e) = structure_end_dof(models(b), e, f, z)
                     if (f > 0) then
                        level(e) = sum(deck%buildings(b)%height(1:f))
                     else
                        level(e) = z
                     end if
                  end associate
               end do
               pair(n)%coincide = levels_coincide(level(1), level(2), pair(n)%floor(1), pair(n)%floor(2))
            end do
         end associate
      end do
   end function suite_pairs

end module pound_suite_context
