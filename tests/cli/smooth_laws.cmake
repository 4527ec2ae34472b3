# The smooth joint laws of issue 26 from the command line: the example deck runs, its listing
# shows each joint's calibration and realised restitution, its results file the dataset; bad
# inputs (a Hertz-family law with a dashpot, restitution outside (0, 1), a Hertz stiffness out
# of its plausible range, restitution with 'hertz', a law without its restitution) give one
# message each and exit 1 without outputs.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/seed_jankowski.nml deck)
string(REPLACE "t_end = 5.0" "t_end = 1.0" deck "${deck}")
file(WRITE ${WORK_DIR}/seed_jankowski.nml "${deck}")
run_pound(r seed_jankowski.nml)
expect_equal("exit status (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/seed_jankowski.out listing)
expect_contains("listing" "${listing}" "A:1-B:1       1.000  jankowski")
expect_contains("listing" "${listing}" "    stiffness = 2750000. kN/m^(3/2)")
expect_contains("listing" "${listing}" "    realised e = 0.64702")
if(NOT EXISTS ${WORK_DIR}/seed_jankowski.h5)
  message(FATAL_ERROR "seed_jankowski.h5 not written")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

set(head "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.0 /
&building name = 'A', n_storeys = 2, height = 2*3.0, mass = 2*10.0, stiffness = 2*1.0e4 /
&building name = 'B', n_storeys = 3, height = 3*3.0, mass = 3*10.0, stiffness = 3*1.0e4 /
&contact left = 'A', right = 'B', floors_left = 1, floors_right = 1, gap = 0.001,
")
function(refused name line message)
  file(WRITE ${WORK_DIR}/${name}.nml "${head}  ${line} /\n")
  run_pound(b ${name}.nml)
  expect_equal("exit status of ${name}" 1 "${b_rc}")
  expect_contains("message of ${name}" "${b_err}" "${name}.nml:${message}")
  expect_no_outputs(${name}.nml)
endfunction()
refused(hertz_dashpot "law = 'hertz', stiffness = 1.0e7, dashpot = 50.0"
        "6: &contact #1 (A, B): dashpot is not a variable of law = 'hertz', an elastic impact")
refused(jankowski_dashpot "law = 'jankowski', stiffness = 1.0e7, restitution = 0.6, dashpot = 50.0"
        "6: &contact #1 (A, B): dashpot is not a variable of law = 'jankowski': its damping follows from restitution")
refused(kelvin_e_zero "law = 'kelvin', stiffness = 1.0e6, restitution = 0.0"
        "6: &contact #1 (A, B): restitution = 0.000000, must be > 0 and < 1")
refused(hertz_damp_e_one "law = 'hertz_damp', stiffness = 1.0e7, restitution = 1.0"
        "6: &contact #1 (A, B): restitution = 1.000000, must be > 0 and < 1")
refused(hertz_soft "law = 'hertz', stiffness = 500.0"
        "6: &contact #1 (A, B): stiffness = 500.0000 kN/m^(3/2) of law = 'hertz' is outside its plausible range")
refused(hertz_restitution "law = 'hertz', stiffness = 1.0e7, restitution = 0.65"
        "6: &contact #1 (A, B): restitution is not a variable of law = 'hertz'")
refused(jankowski_no_e "law = 'jankowski', stiffness = 1.0e7"
        "5: &contact #1 (A, B): law = 'jankowski' needs restitution")

# Impact-aware substeps from the law's contact duration: Hertz between two 10 t floors
# (m_eff = 5 t), kh = 1e7 kN/m^(3/2), at 1 m/s: dmax = (5 m_eff v^2/(4 kh))^(2/5) = 3.2988 mm,
# t_c = 2.9432 dmax/v = 9.709 ms; 40 substeps per duration at dt = 2 ms: m = ceil(8.24) = 9.
file(WRITE ${WORK_DIR}/hertz_impact.nml "&analysis dt = 0.002, t_end = 1.0, stepping = 'impact' /
&ground kind = 'pulse', x0 = 0.02, a = 2.0, b = 12.0 /
&building name = 'A', n_storeys = 1, height = 3.0, mass = 10.0, stiffness = 1.0e4 /
&building name = 'B', n_storeys = 1, height = 3.0, mass = 10.0, stiffness = 3.0e4 /
&contact left = 'A', right = 'B', floors_left = 1, floors_right = 1, gap = 0.001,
  law = 'hertz', stiffness = 1.0e7 /
")
run_pound(h hertz_impact.nml)
expect_equal("exit status of hertz_impact (${h_err})" 0 "${h_rc}")
expect_contains("substeps" "${h_out}" "impact stepping:       m = 9 substeps")

# A damped smooth law at column points between floors (no mass to calibrate to): refused, and
# the message says why and points to 'hertz', an elastic law with a dashpot, or floors (not to a
# dashpot of this law, which these laws refuse).
file(READ ${SOURCE_DIR}/input/frame_to_column.nml deck)
string(REPLACE "law = 'elastic'\n   stiffness = 5.0e5        ! kN/m"
       "law = 'jankowski'\n   stiffness = 1.0e8\n   restitution = 0.6" deck "${deck}")
file(WRITE ${WORK_DIR}/jankowski_columns.nml "${deck}")
run_pound(c jankowski_columns.nml)
expect_equal("exit status of jankowski_columns" 1 "${c_rc}")
expect_contains("message of jankowski_columns" "${c_err}"
                "jankowski_columns.nml:89: &contact #1 (A, B): restitution = 0.6 (law = 'jankowski') needs the masses of both facing points")
expect_contains("reason of jankowski_columns" "${c_err}"
                "elevations(1) = 3 m is a column point between floors of A, which has no mass of its own (no impact to calibrate); instead use law = 'hertz' (the same contact without damping), law = 'elastic' with a dashpot (kN s/m) given directly")
