# The progress line: never on a standard error that is not a terminal unless --progress asks
# for it (then it ends with every run done); --quiet silences it.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
run_pound(r ${SOURCE_DIR}/input/two_frames_gap_study.nml)
expect_equal("exit status" 0 "${r_rc}")
expect_equal("stderr without a terminal" "" "${r_err}")
run_pound(q ${SOURCE_DIR}/input/two_frames_gap_study.nml --quiet)
expect_equal("exit status --quiet" 0 "${q_rc}")
expect_equal("stderr with --quiet" "" "${q_err}")
run_pound(p ${SOURCE_DIR}/input/two_frames_gap_study.nml --progress)
expect_equal("exit status --progress" 0 "${p_rc}")
# Uncoupled, coupled and 50 gaps: 52 runs.
expect_contains("stderr with --progress" "${p_err}" "pound: 52/52 runs (100.0 %), ")
string(REGEX MATCH "[^\n]*\n$" last "${p_err}")
expect_contains("last progress line" "${last}" "52/52 runs (100.0 %)")
