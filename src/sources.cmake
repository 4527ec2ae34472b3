# The library's sources, by step (paths relative to src/). The program is src/main/pound.f90.
set(POUND_SOURCES
  # core: kinds, physical constants, the response quantities, the analysis plan, the sweep, code-factor and contact settings, errors, strings, whole-file reading, version, POSIX calls, the progress line, sorting
  core/pound_kinds.f90 core/pound_constants.f90 core/pound_quantities.f90 core/pound_analysis_plan.f90
  core/pound_sweep_settings.f90 core/pound_risk_settings.f90 core/pound_code_factors.f90 core/pound_contact_settings.f90
  core/pound_error.f90 core/pound_model_sink.f90 core/pound_strings.f90 core/pound_text_file.f90
  core/pound_version.f90 core/pound_posix.f90 core/pound_progress.f90
  core/pound_sort.f90 core/pound_folder.f90
  # core: pound's own pseudo-random numbers
  core/pound_random.f90
  # core: exchanging values and allocatable arrays without copies
  core/pound_swap.f90
  # core: the case scheduler (independent cases into a table; its implementation below)
  core/pound_cases.f90
  # core: the exponential of a small matrix, and the exact step of a linear oscillator under
  # piecewise-linear forcing (used by the models' synthetic motions, the spectra and the exact
  # free steps: core, so that no model module uses the solver)
  core/pound_expm.f90 core/pound_sdof.f90
  # core: the rules of a joint envelope (shared by the deck reader and the contact law)
  core/pound_envelope_rules.f90
  # core: checks of input values that know no configuration (where a value comes from, required, rules, plausible ranges)
  core/pound_input_checks.f90
  # deck: configuration types, variable table, lexer, checks, one reader per group, the reader, records
  deck/pound_config.f90 deck/pound_deck_variables.f90 deck/pound_deck_values.f90 deck/pound_deck_lexer.f90 deck/pound_deck_checks.f90
  deck/pound_deck_analysis.f90 deck/pound_deck_ground.f90 deck/pound_deck_storey_law.f90 deck/pound_deck_hinge_law.f90 deck/pound_deck_building.f90 deck/pound_deck_plane.f90
  deck/pound_deck_stiffness.f90 deck/pound_deck_contact.f90 deck/pound_deck_study.f90 deck/pound_deck_targets.f90 deck/pound_deck_sweep.f90 deck/pound_deck_risk.f90 deck/pound_deck_record_set.f90 deck/pound_deck.f90 deck/pound_accelerogram.f90
  # models: band storage, shear building, ground motion
  model/pound_band.f90 model/pound_plan_geometry.f90 model/pound_padded_rows.f90 model/pound_structure.f90 model/pound_storey_properties.f90
  model/pound_shear_building.f90 model/pound_ground_motion.f90
  # models: plausibility (period against the code estimate for the height, buckling hint)
  model/pound_plausibility.f90
  # models: synthetic ground motions (filtered white noise)
  model/pound_synthetic_motion.f90
  # models: what a building is made of, as the builders take it (the deck fills it)
  model/pound_building_spec.f90
  # models: planar frames (beam-column element, frame assembly, gravity analysis, banded eigenpairs)
  model/pound_band_lapack.f90 model/pound_band_solve.f90 model/pound_band_eigen.f90 model/pound_frame_element.f90
  model/pound_frame.f90 model/pound_frame_gravity.f90 model/pound_frame_hinges.f90 model/pound_frame_building.f90 model/pound_building_kind.f90
  model/pound_shear_kind.f90 model/pound_frame_kind.f90 model/pound_plan_building.f90 model/pound_plan_kind.f90
  model/pound_building.f90
  # solver: Newmark average acceleration
  solver/pound_integrator.f90 solver/pound_newmark.f90 solver/pound_newmark_step.f90 solver/pound_newmark_band.f90
  # solver: exact free steps (modes of (K+G, M), each mode's exact step)
  solver/pound_modal_step.f90 solver/pound_newmark_exact.f90
  # solver: several ground motions of one shear building at once (motion-fastest lanes)
  solver/pound_newmark_batch.f90
  # solver: HHT-alpha; the integrator an analysis plan names
  solver/pound_hht.f90 solver/pound_integrators.f90
  # lcp: the complementarity solvers (Lemke, the active-set method, enumeration of the
  # complementary bases), their tallies, and a dense LCP with its storage
  lcp/pound_lemke.f90 lcp/pound_lcp_statistics.f90 lcp/pound_lcp_enumerate.f90 lcp/pound_lcp_active_set.f90
  lcp/pound_lcp_dense.f90
  # lcp: the element set of the complementarity core (rows over the model's DOFs, LCP block,
  # check, commit, energy terms)
  lcp/pound_complementarity_set.f90
  # contact: joint laws, condensation and the per-step LCP
  contact/pound_joint_law.f90 contact/pound_contact_law.f90 contact/pound_law_elastic.f90
  contact/pound_law_bilinear.f90 contact/pound_law_piecewise.f90 contact/pound_law_parabola_cubic.f90
  contact/pound_law_impact.f90 contact/pound_law_smooth.f90 contact/pound_law_kelvin.f90 contact/pound_law_hertz.f90
  contact/pound_law_hertz_damp.f90 contact/pound_law_jankowski.f90
  contact/pound_law_registry.f90 contact/pound_contact_pair.f90 contact/pound_contact_corners.f90
  contact/pound_joint_state.f90 contact/pound_contact_lcp.f90
  contact/pound_contact_friction.f90 contact/pound_contact_system.f90 contact/pound_contact_friction_lcp.f90 contact/pound_contact_smooth.f90 contact/pound_contact.f90
  # contact: the contact half-period of a joint (substep count), ends without mass condensed
  contact/pound_contact_period.f90
  # analyses: response records, uncoupled and coupled runs, influence coefficients, gap sweep
  analysis/pound_response.f90
  # elements: the bilinear storeys and the frames' plastic hinges, element sets of the
  # complementarity core (their rows, LCP block and check; the stick's active set; the
  # coupled LCP with the joints; energy terms)
  elements/pound_storey_yield.f90 elements/pound_storey_yield_rows.f90 elements/pound_storey_yield_stick.f90
  elements/pound_storey_yield_coupled.f90 elements/pound_storey_yield_hinges.f90 elements/pound_storey_yield_energy.f90
  analysis/pound_storey_collapse.f90 analysis/pound_residual_settle.f90
  # stepping: the step policies (how the time loop takes a step: uniform, exact free steps,
  # impact substeps, closed steps and their kernels, the retry around any of them)
  stepping/pound_step_policy.f90 stepping/pound_step_retry.f90 stepping/pound_step_exact.f90 stepping/pound_step_impact.f90
  stepping/pound_closed_kernels.f90 stepping/pound_closed_steps.f90 stepping/pound_step_closed.f90
  # analyses: the time loop, influence coefficients
  analysis/pound_analysis.f90 analysis/pound_analysis_reports.f90 analysis/pound_analysis_loop.f90 analysis/pound_influence.f90
  analysis/pound_sweep.f90 analysis/pound_sweep_joints.f90 analysis/pound_joint_study.f90
  # analyses: the uncoupled runs of several motions at once
  analysis/pound_analysis_batch.f90
  # analyses: response spectra and scaling, code separation rules
  analysis/pound_spectrum.f90 analysis/pound_separation.f90
  # results: what a case, a suite and the multiple-stripe analysis compute, as the writers read it
  # (the suite's statistics and outcomes are reductions of results)
  results/pound_case_result.f90 results/pound_suite_columns.f90 results/pound_suite_outcome.f90
  results/pound_suite_statistics.f90 results/pound_stripes_result.f90
  # driver: one case from a validated configuration to all results (program, tests, suites)
  driver/pound_case_studies.f90 driver/pound_run_case.f90
  # driver: the memory a deck's run needs (estimated from the deck) and what the machine gives
  driver/pound_memory.f90
  # driver: a suite of ground motions (scaling, one case per motion, suite statistics, rules)
  driver/pound_suite_context.f90
  driver/pound_suite_motions.f90 driver/pound_suite_refine.f90 driver/pound_suite_joints.f90 driver/pound_planned_runs.f90
  driver/pound_suite.f90
  # risk: the normal distribution's tails, lognormal fragility fits (binomial maximum
  # likelihood over stripes), the hazard curve and the risk integral
  risk/pound_normal.f90 risk/pound_fragility.f90 risk/pound_hazard.f90
  # driver: the multiple-stripe analysis (the risk-targeted joint)
  driver/pound_stripes.f90
  # outputs: files, HDF5 layer (its attribute writers and low-level helpers in submodules),
  # results file, the text writer (unit + first failure), listing
  output/pound_files.f90 output/pound_h5.f90 output/pound_h5_sink.f90 output/pound_h5_support.f90 output/pound_h5_attributes.f90
  output/pound_results_h5.f90 output/pound_text_writer.f90
  output/pound_influence_output.f90 output/pound_result_groups_output.f90 output/pound_summary_item.f90 output/pound_summary_plan.f90 output/pound_summary_yield.f90 output/pound_hinge_output.f90 output/pound_yield_output.f90 output/pound_listing.f90
  # outputs: the separation rules' listing table and datasets (a run and a suite)
  output/pound_separation_output.f90 output/pound_sweep_joints_output.f90
  # outputs: the suite's listing sections and /suite
  output/pound_suite_output.f90 output/pound_suite_columns_output.f90 output/pound_suite_yield_output.f90 output/pound_study_output.f90
  # outputs: the engineering summary (terminal, top of the listing, <stem>_summary.csv, root attributes)
  output/pound_summary.f90 output/pound_summary_output.f90
  output/pound_stripes_output.f90
)
# The case scheduler's implementation (a submodule of pound_cases): the cases in order by
# default, shared over MPI ranks with -DPOUND_MPI=ON (the top CMakeLists.txt picks one).
set(POUND_SOURCES_SERIAL core/pound_cases_serial.f90)
set(POUND_SOURCES_MPI core/pound_cases_mpi.f90)
# The structural model's recovery rows and storey-by-storey strain energy are summed without
# fused multiply-adds, so that they give the same numbers with and without -march=native.
if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  set_source_files_properties(${PROJECT_SOURCE_DIR}/src/model/pound_structure.f90
                              ${PROJECT_SOURCE_DIR}/src/model/pound_padded_rows.f90
                              PROPERTIES COMPILE_OPTIONS -ffp-contract=off)
endif()
