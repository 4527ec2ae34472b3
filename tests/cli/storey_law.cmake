# Bilinear storeys (issue 25): the example deck runs and lists its storeys; each bad input of
# the storey law gets one message naming deck file:line, group, variable and rule; exit 1.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/seed_bilinear.nml good)

file(WRITE ${WORK_DIR}/seed_bilinear.nml "${good}")
run_pound(r seed_bilinear.nml)
expect_equal("exit status of the example" 0 "${r_rc}")
expect_equal("standard error of the example" "" "${r_err}")
file(READ ${WORK_DIR}/seed_bilinear.out listing)
expect_contains("listing" "${listing}" "Bilinear storeys of A")
expect_contains("listing" "${listing}" "Bilinear storeys of B")
expect_contains("listing" "${listing}" "hysteretic energy: uncoupled")
# The engineering summary: each bilinear building's largest ductility and residual drift.
expect_contains("summary" "${r_out}" "B: largest storey ductility, coupled:")
expect_contains("summary" "${r_out}" "B: largest residual drift, coupled:")
file(READ ${WORK_DIR}/seed_bilinear_summary.csv csv)
expect_contains("summary CSV" "${csv}" "building,B,ductility,")
expect_contains("summary CSV" "${csv}" "building,B,residual_drift,")
file(REMOVE ${WORK_DIR}/seed_bilinear.out ${WORK_DIR}/seed_bilinear.h5 ${WORK_DIR}/seed_bilinear_summary.csv)

# A gap sweep targeting the ductility lists its largest |lambda| beside the other quantities.
file(WRITE ${WORK_DIR}/sweep_mu.nml "${good}\n&sweep gap_from = 0.0, gap_to = 0.006, n_gaps = 3, target_lambda = 10.0, target_quantities = 'ductility' /\n")
run_pound(r sweep_mu.nml)
expect_equal("sweep_mu: exit status" 0 "${r_rc}")
file(READ ${WORK_DIR}/sweep_mu.out listing)
expect_contains("sweep_mu: listing" "${listing}" "      gap [mm]    impacts         Q     drift         u     a_abs  ductility  target")
expect_contains("sweep_mu: listing" "${listing}" "        6.0000          0      0.00      0.00      0.00      0.00       0.00     met")
file(REMOVE ${WORK_DIR}/sweep_mu.out ${WORK_DIR}/sweep_mu.h5 ${WORK_DIR}/sweep_mu_summary.csv)

# bad(<name> <from> <to> <message>): the example deck with <from> replaced by <to> fails with <message>.
function(bad name from to needle)
  string(REPLACE "${from}" "${to}" deck "${good}")
  if("${deck}" STREQUAL "${good}")
    message(FATAL_ERROR "${name}: '${from}' not in the deck")
  endif()
  file(WRITE ${WORK_DIR}/${name}.nml "${deck}")
  run_pound(r ${name}.nml)
  expect_equal("${name}: exit status" 1 "${r_rc}")
  expect_contains("${name}: message" "${r_err}" "${name}.nml:")
  expect_contains("${name}: message" "${r_err}" "${needle}")
  expect_no_outputs(${name}.nml)
endfunction()

bad(missing_yield "yield_shear = 200.0, 150.0, 100.0" ""
    "&building #1 (A): yield_shear is missing: storey_law = 'bilinear' needs the yield shear of every storey")
bad(r_one "hardening_ratio = 0.05" "hardening_ratio = 1.0"
    "&building #1 (A): hardening_ratio(1) = 1.000000, must be > -1 and < 1")
bad(r_below "hardening_ratio = 0.02" "hardening_ratio = -1.5"
    "&building #2 (B): hardening_ratio(1) = -1.500000, must be > -1 and < 1")
bad(yield_elastic "storey_law = 'bilinear'" "storey_law = 'elastic'"
    "&building #1 (A): yield_shear applies only with storey_law = 'bilinear'")
bad(count "yield_shear = 200.0, 150.0, 100.0" "yield_shear = 200.0, 150.0"
    "&building #1 (A): yield_shear has 2 values, must have n_storeys = 3")
bad(zero_yield "yield_shear = 200.0, 150.0, 100.0" "yield_shear = 200.0, 0.0, 100.0"
    "&building #1 (A): yield_shear(2) = 0.000000, must be > 0")
bad(law_name "storey_law = 'bilinear'  ! yielding storeys\n   yield_shear = 200.0" "storey_law = 'plastic'\n   yield_shear = 200.0"
    "&building #1 (A): storey_law = 'plastic', must be 'elastic' or 'bilinear'")
bad(hardening_count "hardening_ratio = 0.05" "hardening_ratio = 0.05, 0.05"
    "&building #1 (A): hardening_ratio has 2 values, must have one (for every storey) or n_storeys = 3")

# collapse_drift: > 0; a collapse is a result (exit 0, the listing says which storey when).
bad(collapse_zero "history = 'all'" "history = 'all', collapse_drift = 0.0"
    "&analysis: collapse_drift = 0")
string(REPLACE "history = 'all'" "history = 'all', collapse_drift = 1.0e-4" deck "${good}")
file(WRITE ${WORK_DIR}/collapse.nml "${deck}")
run_pound(r collapse.nml)
expect_equal("collapse: exit status" 0 "${r_rc}")
file(READ ${WORK_DIR}/collapse.out listing)
expect_contains("collapse: listing" "${listing}" "COLLAPSE: collapsed in the uncoupled analysis (storey 1, t = ")
file(REMOVE ${WORK_DIR}/collapse.out ${WORK_DIR}/collapse.h5 ${WORK_DIR}/collapse_summary.csv)

# HHT-alpha with bilinear storeys runs: tests/cli/hht_integrator.cmake.

# A frame takes no storey law (plastic hinges of frames are not available).
file(READ ${SOURCE_DIR}/input/two_frames_fe.nml good)
bad(frame_law "model = 'frame'" "model = 'frame'\n   storey_law = 'bilinear'"
    "&building #1 (A): storey_law = 'bilinear' applies only to a shear building (model = 'shear')")
