!> Outputs of the studies of the joint (issue 26, `pound_joint_study`): the listing's tables of
!> a stiffness or restitution sweep and of a law study, the rule of each default joint
!> stiffness, and their HDF5 groups:
!>
!>     /stiffness_sweep or /restitution_sweep     (attributes parameter, units, target_lambda)
!>         value                    (n) the swept values (kN/m, or 1 for e)
!>         impacts, meets, failed   (n) every joint's impacts; 1 where every targeted |lambda| <=
!>                                  target_lambda (no target: 1 unless failed); 1 where the run failed
!>         energy_error             (n) relative energy residual of each run
!>         max_abs_lambda/<b>/<q>   (n) as /sweep/max_abs_lambda (the column quantities of frames
!>                                  where targeted)
!>         peak_force/<pair>        (n) kN
!>         realised_restitution/<pair> (n) -1 where not computed
!>     /law_study                   (attributes variants: 'base v1 v2 ...', target_lambda)
!>         <variant>/impacts, energy_error, failed   scalars (the base: /law_study/base)
!>         <variant>/max_abs_lambda/<b>/<q>         scalar, %
!>         <variant>/peak_force, realised_restitution   (n_pairs) kN, 1 (-1: not computed)
!>         <variant>  attribute law: the laws of its groups; pairs: the pair labels
module pound_study_output
   use pound_kinds, only: dp
   use pound_error, only: error_type
   use pound_strings, only: str, fixed_cell, right_cell
   use pound_config, only: deck_type, contact_config
   use pound_quantities, only: n_history_quantities, history_names, target_names, q_column_moment
   use pound_structure, only: structure_model
   use pound_response, only: q_u, q_a_abs, q_drift, q_shear
   use pound_joint_study, only: joint_study_result, realised_not_computed
   use pound_text_writer, only: text_writer
   use pound_listing, only: write_section
   use pound_influence_output, only: lambda_cell
   use pound_h5, only: h5_file, h5_open, h5_close, h5_write, h5_write_attr
   implicit none
   private

   public :: write_study_tables, write_stiffness_rules, write_study_h5

   !> The quantities of the listing's tables (as the gap study's).
   integer, parameter :: shown(4) = [q_shear, q_drift, q_u, q_a_abs]
   character(len=*), parameter :: heads(4) = [character(len=9) :: 'Q', 'drift', 'u', 'a_abs']

contains

   !> The default joint stiffness of each `&contact` group that gives none, with its rule
   !> (nothing when every group gives its stiffness).
   subroutine write_stiffness_rules(lst, contacts)
      !> The listing writer.
      type(text_writer), intent(inout) :: lst
      !> The deck's `&contact` groups.
      type(contact_config), intent(in) :: contacts(:)
      integer :: ic

      if (.not. any([(has_rule(contacts(ic)), ic=1, size(contacts))])) return
      call write_section(lst, 'Joint stiffness by default (groups without stiffness)')
      do ic = 1, size(contacts)
         if (.not. has_rule(contacts(ic))) cycle
         call lst%put('  &contact #'//str(ic)//' ('// &
            contacts(ic)%left//', '//contacts(ic)%right//'): '//contacts(ic)%stiffness_rule)
      end do
      call lst%put('  The impact stiffness is uncertain by an '// &
         "order of magnitude: a &sweep parameter = 'stiffness' shows how much every lambda and impact force "// &
         'depends on it.')
   contains
      pure logical function has_rule(c)
         type(contact_config), intent(in) :: c

         has_rule = .false.
         if (allocated(c%stiffness_rule)) has_rule = len(c%stiffness_rule) > 0
      end function has_rule
   end subroutine write_stiffness_rules

   !> A joint study's tables: per building the largest |lambda| of the shown quantities per
   !> configuration, then the peak force and the realised restitution of each pair.
   subroutine write_study_tables(lst, models, res, target, targeted)
      !> The listing writer.
      type(text_writer), intent(inout) :: lst
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> The study.
      type(joint_study_result), intent(in) :: res
      !> `&sweep target_lambda` (<= 0: none).
      real(dp), intent(in) :: target
      !> `&sweep target_quantities`: a frame's column quantities are listed where targeted.
      logical, intent(in) :: targeted(:)
      character(len=:), allocatable :: line, head
      integer :: i, ib, k, n, q

      n = size(res%label)
      select case (res%kind)
      case ('stiffness')
         call write_section(lst, 'Stiffness sweep: largest |lambda| [%] over the storeys (floors) against the '// &
                            'joint stiffness k0 of every &contact group')
         head = '   k0 [kN/m]'
      case ('restitution')
         call write_section(lst, 'Restitution sweep: largest |lambda| [%] over the storeys (floors) against '// &
                            'the coefficient of restitution e of every &contact group')
         head = '           e'
      case default
         call write_section(lst, 'Law study: the deck''s joints (base) and each &contact variant, the same '// &
                            'pairs, against the same uncoupled run')
         head = '     variant'
      end select
      write (lst%unit, '(a,i0,a)', iostat=lst%ios, iomsg=lst%msg) '  ', n, ' coupled runs at the deck''s gaps; '// &
         'no threshold (a target is judged per row: met/no; the safe gap is a gap sweep''s answer)'
      call lst%note()
      if (res%kind == 'law') then
         do i = 1, n
            call lst%put('  '//trim(res%label(i))//': law '//trim(res%law(i)))
         end do
      end if
      do ib = 1, size(models)
         write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Building '//models(ib)%name
         call lst%note()
         line = head//'    impacts'
         do k = 1, size(shown)
            line = line//right_cell(trim(heads(k)), 10)
         end do
         do q = n_history_quantities + 1, q_column_moment
            if (column_listed(ib, q)) line = line//right_cell(trim(target_names(q)), 15)
         end do
         if (target > 0.0_dp) line = line//'  target'
         call lst%put(line)
         do i = 1, n
            line = right_cell(trim(res%label(i)), 12)
            if (res%failed(i)) then
               call lst%put(line//'   FAILED: '//trim(res%messages(i)))
               cycle
            end if
            line = line//right_cell(str(res%impacts(i)), 11)
            do k = 1, size(shown)
               line = line//lambda_cell(res%max_abs_lambda(shown(k), ib, i), 10, 2)
            end do
            do q = n_history_quantities + 1, q_column_moment
               if (column_listed(ib, q)) line = line//'     '//lambda_cell(res%max_abs_lambda(q, ib, i), 10, 2)
            end do
            if (target > 0.0_dp) line = line//merge('     met', '      no', res%meets(i))
            call lst%put(line)
         end do
      end do
      write (lst%unit, '(/,a)', iostat=lst%ios, iomsg=lst%msg) '  Peak force [kN] and realised coefficient of '// &
         'restitution e_r of each pair (n/a: the law has no calibration, or an end without mass)'
      call lst%note()
      line = head
      do k = 1, size(res%pair)
         line = line//right_cell(trim(res%pair(k)), 16)//right_cell('e_r', 7)
      end do
      call lst%put(line)
      do i = 1, n
         line = right_cell(trim(res%label(i)), 12)
         if (res%failed(i)) cycle
         do k = 1, size(res%pair)
            line = line//right_cell(trim(fixed_cell(res%peak_force(k, i), 16, 1)), 16)
            if (res%realised_e(k, i) == realised_not_computed) then
               line = line//right_cell('n/a', 7)
            else
               line = line//fixed_cell(res%realised_e(k, i), 7, 3)
            end if
         end do
         call lst%put(line)
      end do
   contains
      !> Whether a frame's column quantity q (column_shear, column_moment) of building ib is listed.
      pure logical function column_listed(ib, q)
         integer, intent(in) :: ib, q

         column_listed = models(ib)%member%n > 0 .and. targeted(q)
      end function column_listed
   end subroutine write_study_tables

   !> The studies' groups appended to the results file `path` (see the module doc).
   subroutine write_study_h5(path, deck, models, error, sweep, law)
      !> Results file (written and closed).
      character(len=*), intent(in) :: path
      !> The configuration (its `&sweep` and `&contact` variants).
      type(deck_type), intent(in) :: deck
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Error state.
      type(error_type), allocatable, intent(out) :: error
      !> The stiffness or restitution sweep, the law study (absent: not run).
      type(joint_study_result), intent(in), optional :: sweep, law
      type(error_type), allocatable :: close_error
      type(h5_file) :: h5

      call h5_open(h5, path, error, writable=.true.)
      if (allocated(error)) return
      if (present(sweep)) call write_sweep(sweep)
      if (present(law) .and. .not. allocated(error)) call write_law(law)
      call h5_close(h5, close_error)
      if (allocated(close_error) .and. .not. allocated(error)) call move_alloc(close_error, error)

   contains

      subroutine write_sweep(r)
         type(joint_study_result), intent(in) :: r
         character(len=:), allocatable :: g, units
         real(dp), allocatable :: row(:)
         integer :: ib, q, k

         g = '/'//trim(r%kind)//'_sweep'
         units = merge('kN/m', '1   ', r%kind == 'stiffness')
         units = trim(units)
         call h5_write(h5, g//'/value', r%value, error, units=units)
         if (.not. allocated(error)) call h5_write(h5, g//'/impacts', r%impacts, error, units='1')
         if (.not. allocated(error)) call h5_write(h5, g//'/meets', merge(1, 0, r%meets), error, units='1')
         if (.not. allocated(error)) call h5_write(h5, g//'/failed', merge(1, 0, r%failed), error, units='1')
         if (.not. allocated(error)) call h5_write(h5, g//'/energy_error', r%energy_error, error, units='1')
         if (allocated(error)) return
         do ib = 1, size(models)
            do q = 1, q_column_moment
               if (.not. written(ib, q)) cycle
               row = r%max_abs_lambda(q, ib, :)
               call h5_write(h5, g//'/max_abs_lambda/'//models(ib)%name//'/'//trim(target_names(q)), row, error, &
                             units='%')
               if (allocated(error)) return
            end do
         end do
         do k = 1, size(r%pair)
            row = r%peak_force(k, :)
            call h5_write(h5, g//'/peak_force/'//trim(r%pair(k)), row, error, units='kN')
            if (allocated(error)) return
            row = r%realised_e(k, :)
            call h5_write(h5, g//'/realised_restitution/'//trim(r%pair(k)), row, error, units='1')
            if (allocated(error)) return
         end do
         call h5_write_attr(h5, g, 'parameter', trim(r%kind), error)
         if (.not. allocated(error)) call h5_write_attr(h5, g, 'units', units, error)
         if (.not. allocated(error)) call h5_write_attr(h5, g, 'target_lambda', deck%sweep%target, error)
      end subroutine write_sweep

      subroutine write_law(r)
         type(joint_study_result), intent(in) :: r
         character(len=:), allocatable :: g, names, pairs
         integer :: i, ib, q, k

         names = ''
         do i = 1, size(r%label)
            names = names//' '//trim(r%label(i))
         end do
         pairs = ''
         do k = 1, size(r%pair)
            pairs = pairs//' '//trim(r%pair(k))
         end do
         do i = 1, size(r%label)
            g = '/law_study/'//trim(r%label(i))
            call h5_write(h5, g//'/impacts', real(r%impacts(i), dp), error, units='1')
            if (.not. allocated(error)) call h5_write(h5, g//'/energy_error', r%energy_error(i), error, units='1')
            if (.not. allocated(error)) call h5_write(h5, g//'/failed', merge(1.0_dp, 0.0_dp, r%failed(i)), error, &
                                                      units='1')
            if (.not. allocated(error)) call h5_write(h5, g//'/peak_force', r%peak_force(:, i), error, units='kN')
            if (.not. allocated(error)) call h5_write(h5, g//'/realised_restitution', r%realised_e(:, i), error, &
                                                      units='1')
            if (allocated(error)) return
            do ib = 1, size(models)
               do q = 1, q_column_moment
                  if (.not. written(ib, q)) cycle
                  call h5_write(h5, g//'/max_abs_lambda/'//models(ib)%name//'/'//trim(target_names(q)), &
                                r%max_abs_lambda(q, ib, i), error, units='%')
                  if (allocated(error)) return
               end do
            end do
            call h5_write_attr(h5, g, 'law', trim(r%law(i)), error)
            if (.not. allocated(error)) call h5_write_attr(h5, g, 'pairs', pairs(2:), error)
            if (allocated(error)) return
         end do
         call h5_write_attr(h5, '/law_study', 'variants', names(2:), error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/law_study', 'target_lambda', deck%sweep%target, error)
         if (.not. allocated(error)) call h5_write_attr(h5, '/law_study', 'history_quantities', &
                                                        join_names(), error)
      end subroutine write_law

      !> Whether quantity q of building ib has a dataset: the history quantities, and the
      !> column quantities of a frame where the deck targets them (as /sweep).
      pure logical function written(ib, q)
         integer, intent(in) :: ib, q

         written = q <= n_history_quantities
         if (.not. written) written = models(ib)%member%n > 0 .and. deck%sweep%target_quantities(q)
      end function written

      pure function join_names() result(s)
         character(len=:), allocatable :: s
         integer :: q

         s = trim(history_names(1))
         do q = 2, n_history_quantities
            s = s//' '//trim(history_names(q))
         end do
      end function join_names
   end subroutine write_study_h5

end module pound_study_output
