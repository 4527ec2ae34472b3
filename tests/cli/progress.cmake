# The progress line: never on a standard error that is not a terminal unless --progress asks
# for it (then it ends with every run done); --quiet silences it. (Standard error is compared
# for the progress text only: the Debug build adds its runtime warnings there.)
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
function(expect_no_progress what text)
  string(FIND "${text}" " runs (" pos)
  if(NOT pos EQUAL -1)
    message(FATAL_ERROR "${what}: a progress line on stderr:\n${text}")
  endif()
endfunction()
run_pound(r ${SOURCE_DIR}/input/two_frames_gap_study.nml)
expect_equal("exit status" 0 "${r_rc}")
expect_no_progress("stderr without a terminal" "${r_err}")
run_pound(q ${SOURCE_DIR}/input/two_frames_gap_study.nml --quiet)
expect_equal("exit status --quiet" 0 "${q_rc}")
expect_no_progress("stderr with --quiet" "${q_err}")
run_pound(p ${SOURCE_DIR}/input/two_frames_gap_study.nml --progress)
expect_equal("exit status --progress" 0 "${p_rc}")
# Uncoupled, coupled, the sweep's run without contact and 50 gaps (a gap beyond the closing
# counts as done without a run of its own): 53 runs.
expect_contains("stderr with --progress" "${p_err}" "pound: 53/53 runs (100.0 %), ")
string(REGEX MATCHALL "pound: [0-9]+/[0-9]+ runs[^\n]*\n" lines "${p_err}")
list(GET lines -1 last)
expect_contains("last progress line" "${last}" "53/53 runs (100.0 %)")
