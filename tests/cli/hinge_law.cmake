# Plastic hinges of frames (issue 25): the example deck runs, lists its hinge table and writes
# the hinge datasets; each bad input of the hinge law gets one message naming deck file:line,
# group, variable and rule; exit 1.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/seed_frame_hinges.nml good)
string(REPLACE "../../shared" "${SOURCE_DIR}/../shared" good "${good}")

file(WRITE ${WORK_DIR}/seed_frame_hinges.nml "${good}")
run_pound(r seed_frame_hinges.nml)
expect_equal("exit status of the example" 0 "${r_rc}")
expect_equal("standard error of the example" "" "${r_err}")
file(READ ${WORK_DIR}/seed_frame_hinges.out listing)
expect_contains("listing" "${listing}" "Plastic hinges of A that yielded")
expect_contains("listing" "${listing}" "Plastic hinges of B that yielded")
expect_contains("listing" "${listing}" "residual drift [mm] by storey")
expect_contains("listing" "${listing}" "hysteretic energy: uncoupled")
expect_contains("summary" "${r_out}" "B: largest hinge plastic rotation, coupled:")
expect_contains("summary" "${r_out}" "B: largest residual drift, coupled:")
file(READ ${WORK_DIR}/seed_frame_hinges_summary.csv csv)
expect_contains("summary CSV" "${csv}" "building,B,plastic_rotation,")
file(REMOVE ${WORK_DIR}/seed_frame_hinges.out ${WORK_DIR}/seed_frame_hinges.h5 ${WORK_DIR}/seed_frame_hinges_summary.csv)

# A gap sweep may target the hinges' plastic rotation (target 'ductility': per storey the
# largest column-hinge plastic rotation) and lists its largest |lambda|.
file(WRITE ${WORK_DIR}/sweep_rot.nml "${good}\n&sweep gap_from = 0.0, gap_to = 0.006, n_gaps = 3, target_lambda = 10.0, target_quantities = 'ductility' /\n")
run_pound(r sweep_rot.nml)
expect_equal("sweep_rot: exit status" 0 "${r_rc}")
file(READ ${WORK_DIR}/sweep_rot.out listing)
expect_contains("sweep_rot: listing" "${listing}" "      gap [mm]    impacts         Q     drift         u     a_abs  ductility  target")
file(REMOVE ${WORK_DIR}/sweep_rot.out ${WORK_DIR}/sweep_rot.h5 ${WORK_DIR}/sweep_rot_summary.csv)
# Without a yielding building the target is refused.
file(READ ${SOURCE_DIR}/input/two_frames_fe.nml elastic)
string(REPLACE "../../shared" "${SOURCE_DIR}/../shared" elastic "${elastic}")
file(WRITE ${WORK_DIR}/sweep_elastic.nml "${elastic}\n&sweep gap_from = 0.0, gap_to = 0.006, n_gaps = 3, target_lambda = 10.0, target_quantities = 'ductility' /\n")
run_pound(r sweep_elastic.nml)
expect_equal("sweep_elastic: exit status" 1 "${r_rc}")
expect_contains("sweep_elastic: message" "${r_err}" "no building of the deck has storey_law = 'bilinear' or hinge_law = 'elastic_plastic'")
expect_no_outputs(sweep_elastic.nml)

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

bad(missing_column "column_yield_moment = 250.0, 200.0, 150.0" ""
    "&building #1 (A): column_yield_moment is missing: hinge_law = 'elastic_plastic' needs the yield moment")
bad(missing_beam "beam_yield_moment = 100.0" ""
    "&building #2 (B): beam_yield_moment is missing: hinge_law = 'elastic_plastic' needs the yield moment")
bad(zero_moment "column_yield_moment = 250.0, 200.0, 150.0" "column_yield_moment = 250.0, 0.0, 150.0"
    "&building #1 (A): column_yield_moment(2) = 0.000000, must be a finite yield moment > 0 (kN m)")
bad(negative_moment "beam_yield_moment = 100.0" "beam_yield_moment = -100.0"
    "&building #2 (B): beam_yield_moment(1) = -100.0000, must be a finite yield moment > 0 (kN m)")
bad(count_moment "column_yield_moment = 250.0, 200.0, 150.0" "column_yield_moment = 250.0, 200.0"
    "&building #1 (A): column_yield_moment has 2 values, must have one (for every storey) or n_storeys = 3")
bad(moments_none "hinge_law = 'elastic_plastic'             ! rigid" "hinge_law = 'none'             ! rigid"
    "&building #1 (A): column_yield_moment applies only with hinge_law = 'elastic_plastic'")
bad(hardening_one "beam_yield_moment = 100.0" "beam_yield_moment = 100.0, hinge_hardening = 1.0"
    "&building #2 (B): hinge_hardening(1) = 1.000000, must be >= 0 and < 1 (kinematic hardening of the hinges)")
bad(hardening_count "beam_yield_moment = 100.0" "beam_yield_moment = 100.0, hinge_hardening = 0.1, 0.1"
    "&building #2 (B): hinge_hardening has 2 values, must have one (for every storey) or n_storeys = 4")
bad(law_name "hinge_law = 'elastic_plastic'             ! rigid" "hinge_law = 'plastic'             ! rigid"
    "&building #1 (A): hinge_law = 'plastic', must be 'none' or 'elastic_plastic'")

# HHT-alpha with plastic hinges runs: tests/cli/hht_integrator.cmake.

# A shear building takes no hinge law.
file(READ ${SOURCE_DIR}/input/seed_bilinear.nml good)
bad(shear_hinges "storey_law = 'bilinear'  ! yielding storeys\n   yield_shear = 200.0"
    "storey_law = 'bilinear'\n   hinge_law = 'elastic_plastic'\n   yield_shear = 200.0"
    "&building #1 (A): hinge_law = 'elastic_plastic' applies only to a frame (model = 'frame')")
bad(shear_hardening "hardening_ratio = 0.05" "hardening_ratio = 0.05, hinge_hardening = 0.05"
    "&building #1 (A): hinge_hardening applies only with hinge_law = 'elastic_plastic'")
