# A broken deck: one message naming deck, group, occurrence, variable and rule; exit 1; no outputs.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/two_frames_pdelta.nml deck)
# Break frame B's 5th storey: no columns.
string(REPLACE "n_columns = 8*2" "n_columns = 4*2, 0, 3*2" deck "${deck}")
file(WRITE ${WORK_DIR}/two_frames.nml "${deck}")
run_pound(r two_frames.nml)
expect_equal("exit status" 1 "${r_rc}")
expect_contains("message" "${r_err}" "two_frames.nml:")
expect_contains("message" "${r_err}" "&building #2 (B): n_columns(5) = 0, must be >= 1")
expect_no_outputs(two_frames.nml)
