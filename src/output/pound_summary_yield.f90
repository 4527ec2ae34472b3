!> The engineering summary's items of yielding buildings (`pound_summary`): bilinear storeys
!> (`storey_law = 'bilinear'`) and a frame's plastic hinges (`hinge_law = 'elastic_plastic'`).
!>
!> A single-motion case (`yield_items`): the largest storey-drift lambda; bilinear storeys: the
!> ductility lambda of largest |lambda| with the uncoupled and coupled mu of that same storey
!> and every storey's, the largest coupled ductility beside the same storey's uncoupled, the
!> storeys that yield only with pounding (mu > 1 coupled, <= 1 uncoupled); hinges: the hinges
!> that form only with pounding (rotation > 0 coupled, 0 or n/m uncoupled) and where, the largest
!> plastic-rotation lambda over the column and beam hinges that yield in both analyses, the
!> largest coupled rotation beside the same hinge's uncoupled; the residual drift. A suite
!> (`suite_lambdas`, `suite_yield_items`, `suite_collapses`): the statistics of the lambdas of a
!> history quantity, the lambda of the mean ductility (rotation) per storey, the storeys that
!> yield only with pounding in some motion, the collapses over the motions and per motion.
!> Lambdas that are not meaningful (NaN, `pound_influence`) are left out of every largest.
module pound_summary_yield
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use pound_kinds, only: dp
   use pound_strings, only: counted, plain_real, str
   use pound_response, only: q_drift
   use pound_influence, only: influences, largest_meaningful
   use pound_storey_yield, only: storey_yield_result
   use pound_structure, only: structure_model, structure_yields, never_yields
   use pound_plan_geometry, only: plane_x
   use pound_case_result, only: case_result
   use pound_suite_statistics, only: suite_result
   use pound_suite_yield_output, only: suite_ductility_statistics
   use pound_summary_item, only: summary_item, item, append, largest, fixed2, lambda_word
   implicit none
   private

   public :: lambda_item, yield_items, suite_lambdas, suite_yield_items, suite_collapses

contains

   !> The largest |lambda| of history quantity q over the storeys (n/m ones left out), with its
   !> storey and the time of the coupled peak.
   subroutine lambda_item(items, res, ib, b, q, quantity, what, motion)
      !> The summary so far.
      type(summary_item), allocatable, intent(inout) :: items(:)
      !> The case.
      type(case_result), intent(in) :: res
      !> Building, history quantity (`pound_response`).
      integer, intent(in) :: ib, q
      !> Building name, CSV quantity, what the label calls it, the motion's suffix ('' or ' (motion k of n: NAME)').
      character(len=*), intent(in) :: b, quantity, what, motion
      integer :: j

      j = largest_meaningful(res%influence(ib)%lambda(:, q))
      if (j > 0) then
         call append(items, item('building', b, quantity, b//': largest '//what//' lambda'//motion, &
                       res%influence(ib)%lambda(j, q), '%', 'storey '//str(j), res%cpl%building(ib)%peak_time(j, q)))
      else
         call append(items, item('building', b, quantity, b//': largest '//what//' lambda'//motion, unit='%', &
                       location='n/m: no storey''s uncoupled peak is meaningful', available=.false.))
      end if
   end subroutine lambda_item

   !> A yielding building (bilinear storeys or plastic hinges): the largest storey-drift
   !> lambda, the storeys' ductility or the hinges' plastic rotation (coupled against
   !> uncoupled of the same storey or hinge), new yielding, the residual drift.
   subroutine yield_items(items, res, ib, motion)
      !> The summary so far.
      type(summary_item), allocatable, intent(inout) :: items(:)
      !> The case.
      type(case_result), intent(in) :: res
      !> Building.
      integer, intent(in) :: ib
      !> The motion's suffix of the labels ('' or ' (motion k of n: NAME)').
      character(len=*), intent(in) :: motion
      character(len=:), allocatable :: b
      integer :: j

      if (.not. allocated(res%cpl%yielding) .or. .not. allocated(res%unc%yielding)) return
      if (res%cpl%yielding(ib)%n == 0) return
      b = trim(res%models(ib)%name)
      call lambda_item(items, res, ib, b, q_drift, 'lambda_storey_drift', 'storey-drift', motion)
      associate (yc => res%cpl%yielding(ib), yu => res%unc%yielding(ib))
         if (yc%n_hinges > 0) then
            call hinge_items(items, res%models(ib), b, yc, yu, motion)
         else
            call storey_items(items, res%models(ib), b, yc, yu, motion)
         end if
         if (allocated(res%models(ib)%yield_k)) then
            j = largest(yc%residual_drift)
            call append(items, item('building', b, 'plane_residual_drift', b//': largest plane residual drift, '// &
                          'coupled'//motion, 1000.0_dp*abs(yc%residual_drift(j)), 'mm', row_where(res%models(ib), j)// &
                          '; uncoupled (same plane storey) '//plain_real(1000.0_dp*abs(yu%residual_drift(j)))//' mm'))
         else
            j = largest(yc%residual_drift)
            call append(items, item('building', b, 'residual_drift', b//': largest residual drift, coupled'//motion, &
                          1000.0_dp*abs(yc%residual_drift(j)), 'mm', 'storey '//str(j)//'; uncoupled (same storey) '// &
                          plain_real(1000.0_dp*abs(yu%residual_drift(j)))//' mm'))
         end if
      end associate

   end subroutine yield_items

   !> Bilinear storeys: ductility lambda of largest |lambda| (every storey's on the line),
   !> the largest coupled ductility, the storeys that yield only with pounding. Bilinear
   !> planes (a building in plan): the same per plane storey (the bilinear planes' storeys on
   !> the line, 'p/j' for plane p, storey j; the CSV quantities `lambda_plane_ductility`,
   !> `plane_ductility`, `plane_storeys_yielding_only_with_pounding`).
   subroutine storey_items(items, m, b, yc, yu, motion)
      type(summary_item), allocatable, intent(inout) :: items(:)
      type(structure_model), intent(in) :: m
      character(len=*), intent(in) :: b, motion
      type(storey_yield_result), intent(in) :: yc, yu
      real(dp), allocatable :: lam(:)
      character(len=:), allocatable :: list, pre, what, same
      integer :: j, k, n_new, n_list
      logical :: planes

      planes = allocated(m%yield_k)
      pre = trim(merge('plane_', '      ', planes))
      what = trim(merge('plane storey', 'storey      ', planes))
      same = trim(merge('same plane storey', 'same storey      ', planes))
      lam = influences(yc%ductility, yu%ductility)
      list = ''
      n_list = 0
      do k = 1, yc%n
         if (.not. yields(k)) cycle
         n_list = n_list + 1
         if (n_list > 1) list = list//', '
         list = list//key(k)//': '//fixed2(yu%ductility(k))//' -> '//fixed2(yc%ductility(k))//' ('// &
                lambda_word(lam(k))//')'
      end do
      j = largest_meaningful(lam)
      if (j > 0) then
         call append(items, item('building', b, 'lambda_'//pre//'ductility', b//': '//what//' ductility lambda, '// &
                       'largest |lambda|'//motion, lam(j), '%', row_where(m, j)//': mu uncoupled '// &
                       fixed2(yu%ductility(j))//', coupled '//fixed2(yc%ductility(j))//'; per '//what// &
                       ' mu unc -> cpl (lambda %): '//list))
      else
         call append(items, item('building', b, 'lambda_'//pre//'ductility', b//': '//what//' ductility lambda, '// &
                       'largest |lambda|'//motion, unit='%', available=.false., location='n/m: no '//what// &
                       '''s uncoupled ductility is meaningful; per '//what//' mu unc -> cpl (lambda %): '//list))
      end if
      j = largest(yc%ductility)
      call append(items, item('building', b, pre//'ductility', b//': largest '//what//' ductility, coupled'//motion, &
                    yc%ductility(j), '-', row_where(m, j)//'; uncoupled ('//same//') '// &
                    plain_real(yu%ductility(j))))
      n_new = 0
      list = ''
      do k = 1, yc%n
         if (.not. (yc%ductility(k) > 1.0_dp .and. yu%ductility(k) <= 1.0_dp)) cycle
         n_new = n_new + 1
         if (n_new > 1) list = list//', '
         list = list//key(k)
      end do
      if (n_new == 0) list = 'none'
      if (n_new > 0) list = trim(merge('plane storeys', 'storeys      ', planes))//' '//list
      call append(items, item('building', b, pre//'storeys_yielding_only_with_pounding', b//': '//what// &
                    's that yield only with pounding'//motion, real(n_new, dp), '-', list// &
                    ' (mu > 1 coupled, mu <= 1 uncoupled)'))

   contains

      !> Row k can yield (an elastic plane's rows cannot).
      pure logical function yields(k)
         integer, intent(in) :: k

         yields = m%yield_shear(k) < never_yields
      end function yields

      !> Row k in a list: 'k' (storey) or 'p/j' (plane p, storey j).
      pure function key(k) result(text)
         integer, intent(in) :: k
         character(len=:), allocatable :: text

         if (planes) then
            text = str(m%yield_plane(k))//'/'//str(m%yield_storey(k))
         else
            text = str(k)
         end if
      end function key
   end subroutine storey_items

   !> Plastic hinges (columns and beams): the hinges that form only with pounding, the
   !> largest plastic-rotation lambda of the hinges that yield in both analyses, the largest
   !> coupled rotation (the same hinge's uncoupled beside it).
   subroutine hinge_items(items, m, b, yc, yu, motion)
      type(summary_item), allocatable, intent(inout) :: items(:)
      type(structure_model), intent(in) :: m
      character(len=*), intent(in) :: b, motion
      type(storey_yield_result), intent(in) :: yc, yu
      real(dp), allocatable :: lam(:)
      character(len=:), allocatable :: list
      integer :: h, n_new
      logical, allocatable :: both(:)

      lam = influences(yc%rotation, yu%rotation)
      n_new = 0
      list = ''
      do h = 1, yc%n_hinges
         if (.not. (yc%rotation(h) > 0.0_dp .and. (yu%rotation(h) <= 0.0_dp .or. ieee_is_nan(lam(h))))) cycle
         n_new = n_new + 1
         if (n_new <= 8) then
            if (n_new > 1) list = list//'; '
            list = list//hinge_where(m, h)//' '//plain_real(1000.0_dp*yc%rotation(h))//' mrad'
         end if
      end do
      if (n_new > 8) list = list//'; and '//str(n_new - 8)//' more (the listing''s hinge table)'
      if (n_new == 0) list = 'none'
      call append(items, item('building', b, 'hinges_forming_only_with_pounding', b//': hinges that form only '// &
                    'with pounding'//motion, real(n_new, dp), '-', list))
      both = yu%rotation > 0.0_dp .and. .not. ieee_is_nan(lam)
      if (any(both)) then
         h = maxloc(abs(lam), dim=1, mask=both)
         call append(items, item('building', b, 'lambda_plastic_rotation', b//': largest plastic-rotation lambda'// &
                       motion, lam(h), '%', hinge_where(m, h)//': uncoupled '// &
                       plain_real(1000.0_dp*yu%rotation(h))//' mrad, coupled '// &
                       plain_real(1000.0_dp*yc%rotation(h))//' mrad (hinges that yield in both analyses)'))
      else
         call append(items, item('building', b, 'lambda_plastic_rotation', b//': largest plastic-rotation lambda'// &
                       motion, unit='%', available=.false., &
                       location='no hinge yields (meaningfully) in both analyses'))
      end if
      h = largest(yc%rotation)
      call append(items, item('building', b, 'plastic_rotation', b//': largest hinge plastic rotation, coupled'// &
                    motion, 1000.0_dp*yc%rotation(h), 'mrad', 'hinge '//str(h)//'; uncoupled (same hinge) '// &
                    plain_real(1000.0_dp*yu%rotation(h))//' mrad'))
   end subroutine hinge_items

   !> Where yielding row k of model m is: 'storey k', or 'plane p (x, y = c m) storey j' of
   !> a building in plan.
   pure function row_where(m, k) result(text)
      type(structure_model), intent(in) :: m
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      integer :: p

      if (.not. allocated(m%yield_k)) then
         text = 'storey '//str(k)
         return
      end if
      p = m%yield_plane(k)
      if (m%plan%plane_direction(p) == plane_x) then
         text = 'plane '//str(p)//' (x, y = '//plain_real(m%plan%plane_position(p))//' m) storey '// &
                str(m%yield_storey(k))
      else
         text = 'plane '//str(p)//' (y, x = '//plain_real(m%plan%plane_position(p))//' m) storey '// &
                str(m%yield_storey(k))
      end if
   end function row_where

   !> 'hinge h (column, storey 2, line 1, bottom)' or '(beam, floor 3, line 2, right)'.
   pure function hinge_where(m, h) result(text)
      type(structure_model), intent(in) :: m
      integer, intent(in) :: h
      character(len=:), allocatable :: text

      if (m%hinge_kind(h) == 1) then
         text = 'hinge '//str(h)//' (column, storey '//str(m%hinge_level(h))//', line '// &
                str(m%hinge_line(h))//', '//trim(merge('bottom', 'top   ', m%hinge_end(h) == 1))//')'
      else
         text = 'hinge '//str(h)//' (beam, floor '//str(m%hinge_level(h))//', line '// &
                str(m%hinge_line(h))//', '//trim(merge('left ', 'right', m%hinge_end(h) == 1))//')'
      end if
   end function hinge_where

   !> The suite's lambdas of history quantity q of building ib: the largest |lambda| over the
   !> storeys of the suite mean of the lambdas, of the lambda of the mean peaks and of any
   !> one motion (n/m ones left out).
   subroutine suite_lambdas(items, suite, models, ib, q, name, what)
      !> The summary so far.
      type(summary_item), allocatable, intent(inout) :: items(:)
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Building, history quantity (`pound_response`).
      integer, intent(in) :: ib, q
      !> The CSV quantity's suffix ('storey_drift') and what the label calls it.
      character(len=*), intent(in) :: name, what
      character(len=:), allocatable :: b
      integer :: j, k, kk, jk
      real(dp) :: v, best

      b = trim(models(ib)%name)
      associate (sb => suite%building(ib), s => suite)
         j = max(1, largest_meaningful(sb%mean_lambda(:, q)))
         call append(items, item('suite', b, 'mean_lambda_'//name, b//': suite mean of the '//what//' lambdas', &
                       sb%mean_lambda(j, q), '%', 'storey '//str(j)))
         j = max(1, largest_meaningful(sb%lambda_of_means(:, q)))
         call append(items, item('suite', b, 'lambda_of_means_'//name, b//': '//what//' lambda of the mean peaks', &
                       sb%lambda_of_means(j, q), '%', 'storey '//str(j)))
         best = -1.0_dp
         j = 1
         kk = 0
         do k = 1, size(s%names)
            if (s%motion_failed(k)) cycle
            jk = largest_meaningful(sb%lambda(k, :, q))
            if (jk == 0) cycle
            v = abs(sb%lambda(k, jk, q))
            if (v > best) then
               best = v
               kk = k
               j = jk
            end if
         end do
         if (kk > 0) then
            call append(items, item('suite', b, 'max_lambda_'//name, b//': largest '//what//' lambda of any motion', &
                          sb%lambda(kk, j, q), '%', 'storey '//str(j)//', motion '//trim(s%names(kk))))
         end if
      end associate
   end subroutine suite_lambdas

   !> A yielding building of the suite: per storey the mean over the motions of the peak
   !> ductility (bilinear storeys) or of the storey's largest hinge plastic rotation (frames),
   !> uncoupled against coupled of the same storey with the lambda of the means (the storey
   !> of largest |lambda| first, every storey's on the line), and the storeys that yield only
   !> with pounding in some motion.
   subroutine suite_yield_items(items, suite, models, ib)
      !> The summary so far.
      type(summary_item), allocatable, intent(inout) :: items(:)
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      !> Building (yielding).
      integer, intent(in) :: ib
      real(dp), allocatable :: mean(:, :), maxi(:, :), lam(:)
      character(len=:), allocatable :: b, list, what, q, u
      integer :: collapses(2), j, k, n_new, nk
      real(dp) :: f
      logical :: hinges

      b = trim(models(ib)%name)
      hinges = allocated(models(ib)%hinge_moment)
      call suite_ductility_statistics(suite, ib, mean, maxi, collapses)
      f = 1.0_dp
      what = 'mean storey ductility mu'
      q = 'ductility'
      u = ''
      if (hinges) then
         f = 1000.0_dp
         what = 'mean storey plastic rotation (largest hinge, columns and beams, mrad)'
         q = 'plastic_rotation'
         u = ' mrad'
      end if
      lam = influences(mean(:, 2), mean(:, 1))
      list = ''
      do j = 1, size(lam)
         if (j > 1) list = list//', '
         list = list//str(j)//': '//fixed2(f*mean(j, 1))//' -> '//fixed2(f*mean(j, 2))//' ('//lambda_word(lam(j))//')'
      end do
      j = largest_meaningful(lam)
      if (j > 0) then
         call append(items, item('suite', b, 'lambda_mean_'//q, b//': lambda of the '//what, lam(j), '%', &
                       'storey '//str(j)//': uncoupled '//fixed2(f*mean(j, 1))//u//', coupled '// &
                       fixed2(f*mean(j, 2))//u//'; per storey unc -> cpl (lambda %): '//list))
      else
         call append(items, item('suite', b, 'lambda_mean_'//q, b//': lambda of the '//what, unit='%', available=.false., &
                       location='n/m: no storey''s uncoupled mean is meaningful; per storey unc -> cpl '// &
                       '(lambda %): '//list))
      end if
      ! Storeys (hinges: with a hinge) that yield coupled but not uncoupled in some motion.
      n_new = 0
      list = ''
      do j = 1, size(mean, 1)
         nk = 0
         do k = 1, size(suite%names)
            if (suite%motion_failed(k)) cycle
            associate (y => suite%building(ib)%yield)
               if (hinges) then
                  if (y(k, j, 2) > 0.0_dp .and. y(k, j, 1) <= 0.0_dp) nk = nk + 1
               else
                  if (y(k, j, 2) > 1.0_dp .and. y(k, j, 1) <= 1.0_dp) nk = nk + 1
               end if
            end associate
         end do
         if (nk == 0) cycle
         n_new = n_new + 1
         if (n_new > 1) list = list//', '
         list = list//str(j)//' ('//counted(nk, 'motion')//')'
      end do
      if (n_new == 0) list = 'none'
      if (n_new > 0) list = 'storeys '//list
      call append(items, item('suite', b, 'storeys_yielding_only_with_pounding', b//': storeys that yield only with '// &
                    'pounding in some motion', real(n_new, dp), '-', list// &
                    trim(merge(' (a hinge forms coupled, none uncoupled)', ' (mu > 1 coupled, <= 1 uncoupled)       ', &
                               hinges))))
   end subroutine suite_yield_items

   !> The suite's collapses: totals over the motions (buildings x analyses), per analysis
   !> and per motion.
   subroutine suite_collapses(items, suite, models)
      !> The summary so far.
      type(summary_item), allocatable, intent(inout) :: items(:)
      !> The suite.
      type(suite_result), intent(in) :: suite
      !> The buildings.
      type(structure_model), intent(in) :: models(:)
      integer :: k, a, ib, n(2), nk(2)

      n = 0
      do ib = 1, size(models)
         if (.not. structure_yields(models(ib))) cycle
         do k = 1, size(suite%names)
            if (suite%motion_failed(k)) cycle
            do a = 1, 2
               if (suite%building(ib)%collapse(k, a) > 0) n(a) = n(a) + 1
            end do
         end do
      end do
      call append(items, item('suite', 'suite', 'collapses', 'collapses, suite total over '// &
                    counted(suite%n_used, 'motion'), real(sum(n), dp), '-', &
                    'buildings x analyses x motions whose storey drift / height passed collapse_drift'))
      call append(items, item('suite', 'suite', 'collapses_uncoupled', 'collapses, suite total, uncoupled', real(n(1), dp), &
                    '-', 'buildings x motions'))
      call append(items, item('suite', 'suite', 'collapses_coupled', 'collapses, suite total, coupled', real(n(2), dp), &
                    '-', 'buildings x motions'))
      do k = 1, size(suite%names)
         if (suite%motion_failed(k)) cycle
         nk = 0
         do ib = 1, size(models)
            if (.not. structure_yields(models(ib))) cycle
            do a = 1, 2
               if (suite%building(ib)%collapse(k, a) > 0) nk(a) = nk(a) + 1
            end do
         end do
         call append(items, item('suite', 'suite', 'collapses_motion', 'collapses, motion '//trim(suite%names(k)), &
                       real(sum(nk), dp), '-', 'uncoupled '//str(nk(1))//', coupled '//str(nk(2))))
      end do
   end subroutine suite_collapses

end module pound_summary_yield
