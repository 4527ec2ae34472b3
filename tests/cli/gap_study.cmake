# The shipped gap-study deck: the listing reports the gap table and the smallest gap meeting the target.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
run_pound(r ${SOURCE_DIR}/input/two_frames_gap_study.nml)
expect_equal("exit status" 0 "${r_rc}")
file(READ ${WORK_DIR}/two_frames_gap_study.out listing)
expect_contains("listing" "${listing}" "Gap study: largest |lambda| [%]")
expect_contains("listing" "${listing}" "Smallest gap with every targeted |lambda| <=   10.00 %")
expect_contains("stdout" "${r_out}" "gap sweep: 50 gaps")
# Nothing on stderr: in the Debug build (-fcheck=all) an array temporary made for a
# non-contiguous section passed to the HDF5 writers would be reported there.
expect_equal("stderr" "" "${r_err}")
