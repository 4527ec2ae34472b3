# The analyses' warnings reach the summary on standard output as well as the listing:
# joints far stiffer than dt can follow (k0 = 1e10 kN/m at dt = 1 ms).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/two_frames_elastic.nml seed)
string(REPLACE "stiffness = 1.0e6 " "stiffness = 1.0e10 " stiff "${seed}")
file(WRITE ${WORK_DIR}/stiff_joints.nml "${stiff}")
run_pound(s stiff_joints.nml)
expect_equal("exit status" 0 "${s_rc}")
expect_contains("summary" "${s_out}" "  WARNING: energy audit (coupled): relative residual ")
expect_contains("summary" "${s_out}" "joint A:3-B:3 (k0 = 1.0000000E+10 kN/m")
file(READ ${WORK_DIR}/stiff_joints.out listing)
string(REGEX MATCHALL "WARNING: [^\n]*" in_listing "${listing}")
string(REGEX MATCHALL "WARNING: [^\n]*" in_summary "${s_out}")
expect_equal("the same warnings in the listing and the summary" "${in_listing}" "${in_summary}")
