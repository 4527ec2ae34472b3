# Nonsense never looks like a result: an absurd but finite ground motion stops the run with one
# message naming the building, the energy term, time and step; no output is left. Joints far
# stiffer than dt can follow run, and the listing warns about the audit residual, naming the
# joints and the dt that would resolve them.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/two_frames_elastic.nml seed)

string(REPLACE "x0 = 0.010 " "x0 = 1.0e300 " huge_pulse "${seed}")
file(WRITE ${WORK_DIR}/huge_pulse.nml "${huge_pulse}")
run_pound(r huge_pulse.nml)
string(FIND "${r_err}" "SIGFPE" trapped)
if(trapped EQUAL -1)
  expect_equal("exit status" 1 "${r_rc}")
  expect_contains("message" "${r_err}" "building A: the input energy is not finite at t = 1.0000000E-3 s (step 1)")
  expect_contains("message" "${r_err}" "check the size of the ground motion (&ground)")
else()
  # A Debug build (-ffpe-trap=overflow) stops at the overflow itself.
  message(STATUS "floating-point traps on: the overflow is trapped before it can be checked")
endif()
expect_no_outputs(huge_pulse.nml)

string(REPLACE "stiffness = 1.0e6 " "stiffness = 1.0e10 " stiff "${seed}")
file(WRITE ${WORK_DIR}/stiff_joints.nml "${stiff}")
run_pound(s stiff_joints.nml)
expect_equal("exit status" 0 "${s_rc}")
file(READ ${WORK_DIR}/stiff_joints.out listing)
expect_contains("listing" "${listing}" "WARNING: energy audit (coupled): relative residual ")
expect_contains("listing" "${listing}" "> 1.0000000E-2: joint A:3-B:3 (k0 = 1.0000000E+10 kN/m")
expect_contains("listing" "${listing}" "dt = 8.8857659E-6 s (a tenth of it) would resolve it")
