# A building that buckles under its own gravity loads: named storey and load ratio; no outputs.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(WRITE ${WORK_DIR}/buckle.nml "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566 /
&building name = 'T', n_storeys = 2, height = 2*3.0, mass = 2*10.0, stiffness = 1.0e3, 1.0e5,
          p_delta = .true., gravity_load = 2000.0, 1000.0 /
")
run_pound(r buckle.nml)
expect_equal("exit status" 1 "${r_rc}")
expect_contains("message" "${r_err}" "buckle.nml: building T: buckles under its own gravity loads")
expect_contains("message" "${r_err}" "at storey 1")
expect_contains("message" "${r_err}" "load ratio P/(h k) = 1.000000")
expect_no_outputs(buckle.nml)
# The refusal says which inputs to check.
expect_contains("message" "${r_err}" "check the units of the inputs (masses in t, gravity loads in kN, E in kN/m^2 (not MPa)")
expect_contains("message" "${r_err}" "whether p_delta is meant")
