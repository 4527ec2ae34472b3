# Nonsense never looks like a result: an absurd but finite ground motion is refused with one
# message naming the deck, line, group and variable; no output is left. Joints far
# stiffer than dt can follow run, and the listing warns about the audit residual, naming the
# joints and the dt that would resolve them.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/two_frames_elastic.nml seed)

string(REPLACE "x0 = 0.010 " "x0 = 1.0e300 " huge_pulse "${seed}")
file(WRITE ${WORK_DIR}/huge_pulse.nml "${huge_pulse}")
run_pound(r huge_pulse.nml)
# Refused by the reader's plausible ranges before anything is computed (the run's own
# finiteness checks, for values that get past the reader, are unit-tested in test_finite_checks).
expect_equal("exit status" 1 "${r_rc}")
expect_contains("message" "${r_err}" "huge_pulse.nml:19: &ground: x0 = 1.0e300: out of range")
expect_no_outputs(huge_pulse.nml)

string(REPLACE "stiffness = 1.0e6 " "stiffness = 1.0e10 " stiff "${seed}")
file(WRITE ${WORK_DIR}/stiff_joints.nml "${stiff}")
run_pound(s stiff_joints.nml)
expect_equal("exit status" 0 "${s_rc}")
file(READ ${WORK_DIR}/stiff_joints.out listing)
expect_contains("listing" "${listing}" "WARNING: energy audit (coupled): relative residual ")
expect_contains("listing" "${listing}" "> 1.0000000E-2: joint A:3-B:3 (k0 = 1.0000000E+10 kN/m")
expect_contains("listing" "${listing}" "dt = 8.8857659E-6 s (a tenth of it) would resolve it")
