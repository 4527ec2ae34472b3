!> Reader of `&analysis`: title, dt, t_end, t_free, output_every, history, stepping, impact_substeps,
!> compress, node_histories, lcp_solver, free_steps, integrator, hht_alpha, collapse_drift.
module pound_deck_analysis
   use pound_config, only: analysis_config
   use pound_deck_checks, only: check_real, fail, group_input, parse_history, read_failed, require_real, site, &
                                site_text, unset_real
   use pound_deck_lexer, only: base_name, group_ref, lower
   use pound_deck_variables, only: max_steps, max_substeps, path_len, title_len, word_len
   use pound_error, only: error_type
   use pound_kinds, only: dp
   use pound_strings, only: str
   implicit none
   private

   public :: read_analysis

contains

   !> `&analysis`: title, time step, duration, history output.
   subroutine read_analysis(path, text, g, cfg, error)
      !> Deck path as given (named in messages).
      character(len=*), intent(in) :: path
      !> Deck text, lines separated by LF.
      character(len=*), intent(in) :: text
      !> The group occurrence.
      type(group_ref), intent(in) :: g
      !> Resolved `&analysis`.
      type(analysis_config), intent(out) :: cfg
      !> Unallocated on success; otherwise the first problem found.
      type(error_type), allocatable, intent(out) :: error
      character(len=title_len) :: title
      character(len=path_len) :: history
      character(len=word_len) :: stepping, lcp_solver, free_steps, integrator
      real(dp) :: dt, t_end, t_free, hht_alpha, collapse_drift
      integer :: output_every, ios, impact_substeps
      logical :: compress, node_histories
      character(len=:), allocatable :: buf
      character(len=512) :: msg
      type(site) :: at
      namelist /analysis/ title, dt, t_end, t_free, output_every, history, stepping, impact_substeps, compress, &
                          node_histories, lcp_solver, free_steps, integrator, hht_alpha, collapse_drift

      title = ' '
      history = ' '
      dt = unset_real
      t_end = unset_real
      t_free = 0.0_dp
      output_every = 1
      stepping = 'uniform'
      impact_substeps = 0
      compress = .false.
      node_histories = .false.
      lcp_solver = 'auto'
      free_steps = 'newmark'
      integrator = 'newmark'
      hht_alpha = unset_real
      collapse_drift = 0.10_dp
      call group_input(path, text, g, at, buf, msg)
      read (buf, nml=analysis, iostat=ios, iomsg=msg)
      call read_failed(at, ios, msg, error)
      if (allocated(error)) return

      if (len_trim(title) == len(title)) then
         call fail(at, 'title', 'title is longer than '//str(len(title) - 1)//' characters', error)
         return
      end if
      if (len_trim(title) > 0) then
         cfg%title = trim(title)
      else
         cfg%title = base_name(path)
      end if

      call require_real(at, 'dt', dt, 'time step in s', error, '>', 0.0_dp)
      if (allocated(error)) return
      call require_real(at, 't_end', t_end, 'duration in s', error, '>=', dt, 'dt = '//str(dt))
      if (allocated(error)) return
      if (t_end > dt*real(max_steps, dp)) then
         call fail(at, 't_end', 't_end/dt = '//str(t_end/dt)//' steps, must be <= '// &
                   str(max_steps), error)
         return
      end if
      call check_real(at, 't_free', t_free, '>=', 0.0_dp, error)
      if (allocated(error)) return
      if (t_end + t_free > dt*real(max_steps, dp)) then
         call fail(at, 't_free', '(t_end + t_free)/dt = '//str((t_end + t_free)/dt)//' steps, must be <= '// &
                   str(max_steps), error)
         return
      end if
      if (output_every < 1) then
         call fail(at, 'output_every', 'output_every = '//str(output_every)//', must be >= 1', error)
         return
      end if
      cfg%dt = dt
      ! The analysis runs to t_end + t_free, the ground at rest after t_end (t_free = 0: t_end
      ! itself, bit for bit).
      cfg%t_end = t_end + t_free
      cfg%t_free = t_free
      cfg%output_every = output_every
      call one_of('stepping', stepping, 'uniform', 'impact', cfg%stepping)
      if (allocated(error)) return
      if (impact_substeps < 0 .or. impact_substeps > max_substeps) then
         call fail(at, 'impact_substeps', 'impact_substeps = '//str(impact_substeps)//', must be 1..'// &
                   str(max_substeps)//' (or 0 or not given: chosen from the joints'' contact half-periods)', error)
         return
      end if
      if (impact_substeps > 0 .and. cfg%stepping /= 'impact') then
         call fail(at, 'impact_substeps', "impact_substeps is only for stepping = 'impact' (stepping = '"// &
                   trim(cfg%stepping)//"')", error)
         return
      end if
      cfg%impact_substeps = impact_substeps
      cfg%compress = compress
      cfg%node_histories = node_histories
      call one_of('lcp_solver', lcp_solver, 'auto', 'lemke', cfg%lcp_solver)
      if (allocated(error)) return
      call one_of('free_steps', free_steps, 'newmark', 'exact', cfg%free_steps)
      if (allocated(error)) return
      ! Where a refusal of the exact free steps (a model with too many DOFs, known once the
      ! models are built) points.
      cfg%free_steps_site = site_text(at, 'free_steps')
      call one_of('integrator', integrator, 'newmark', 'hht', cfg%integrator)
      if (allocated(error)) return
      call read_hht(error)
      if (allocated(error)) return
      call check_real(at, 'collapse_drift', collapse_drift, '>', 0.0_dp, error)
      if (allocated(error)) return
      cfg%collapse_drift = collapse_drift
      call parse_history(at, history, cfg%store, error)

   contains

      !> `hht_alpha` (only with integrator = 'hht'; default `cfg%hht_alpha`) in [-1/3, 0], and
      !> HHT-alpha without exact free steps.
      subroutine read_hht(error)
         type(error_type), allocatable, intent(out) :: error

         if (cfg%integrator /= 'hht') then
            if (hht_alpha /= unset_real) call fail(at, 'hht_alpha', "hht_alpha is only for integrator = 'hht' "// &
                                                   "(integrator = '"//trim(cfg%integrator)//"')", error)
            return
         end if
         if (hht_alpha /= unset_real) then
            if (.not. (hht_alpha >= -1.0_dp/3.0_dp .and. hht_alpha <= 0.0_dp)) then
               call fail(at, 'hht_alpha', 'hht_alpha = '//str(hht_alpha)//', must be in [-1/3, 0]', error)
               return
            end if
            cfg%hht_alpha = hht_alpha
         end if
         if (cfg%free_steps == 'exact') call fail(at, 'free_steps', "free_steps = 'exact' is for integrator = "// &
                                                 "'newmark' only (integrator = 'hht': every step is HHT-alpha's)", &
                                                 error)
      end subroutine read_hht

      !> A text variable that must be `a` or `b` (any case, blanks around): `word` set, or
      !> `error`.
      subroutine one_of(name, value, a, b, word)
         !> Variable name, value as read, the two choices (lower case).
         character(len=*), intent(in) :: name, value, a, b
         !> The choice (lower case).
         character(len=*), intent(inout) :: word
         character(len=:), allocatable :: v

         v = lower(trim(adjustl(value)))
         if (v /= a .and. v /= b) then
            call fail(at, name, name//" = '"//trim(adjustl(value))//"', must be '"//a//"' or '"//b//"'", error)
            return
         end if
         word = v
      end subroutine one_of
   end subroutine read_analysis

end module pound_deck_analysis
