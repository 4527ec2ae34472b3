# Plastic hinges against an independent reference (issue 25): a portal with flexible beam and
# column and beam hinges yielding under a pulse, 5 % Rayleigh damping; scripts/reference_frame_hinges.py integrates
# the same portal by Newmark with Newton iterations and an element return mapping (nothing
# shared with pound's LCP) and compares the floor displacement history and the residual drift
# (to 1e-9 m; they agree to about 4e-14 m).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(WRITE ${WORK_DIR}/portal.nml "&analysis
   title = 'portal with plastic hinges (reference)'
   dt = 1.0e-3
   t_end = 2.0
   output_every = 1
   history = 'u'
/
&ground
   kind = 'pulse'
   x0 = 0.05
   a = 2.0
   b = 12.566370614359172
/
&building
   name = 'P'
   n_storeys = 1
   height = 3.0
   mass = 10.0
   model = 'frame'
   bay_width = 6.0
   column_e = 3.0e7
   column_area = 0.16
   column_inertia = 3.75e-4
   beam_e = 3.0e7
   beam_area = 0.15
   beam_inertia = 1.0e-3
   base = 'fixed'
   damping_ratio = 0.05
   hinge_law = 'elastic_plastic'
   column_yield_moment = 45.0
   beam_yield_moment = 30.0
/
")
# check(<name> <deck> <listing text> [gravity]): pound runs <deck>, its listing holds the text, the
# reference agrees.
function(check name deck needle)
  run_pound(r ${deck})
  expect_equal("${name}: pound exit (${r_err})" 0 "${r_rc}")
  string(REPLACE ".nml" "" stem "${deck}")
  file(READ ${WORK_DIR}/${stem}.out listing)
  expect_contains("${name}: listing" "${listing}" "${needle}")
  execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/reference_frame_hinges.py ${WORK_DIR}/${stem}.h5 ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_equal("${name}: reference comparison (${out} ${err})" 0 "${rc}")
  expect_contains("${name}: reference output" "${out}" "largest difference of u")
endfunction()

# Column bases and both beam ends yield (the beam's left end is hinge 5).
check(plain portal.nml "beam     1    1   left      30.0")

# With P-Delta (gravity_load 2000 kN: the mechanism's tangent is negative, the LCP rows
# non-convex) the portal collapses; the histories agree up to pound's collapse step.
file(READ ${WORK_DIR}/portal.nml deck)
string(REPLACE "   hinge_law" "   p_delta = .true.\n   gravity_load = 2000.0\n   hinge_law" pdelta "${deck}")
file(WRITE ${WORK_DIR}/portal_pdelta.nml "${pdelta}")
check(pdelta portal_pdelta.nml "COLLAPSE: collapsed in the uncoupled analysis (storey 1, t = " 2000)

# Kinematic hardening of the hinges (hinge_hardening = 0.05: H = r/(1-r) 6EI/L per hinge, read
# by the reference from the file): the moments pass My, the histories agree.
string(REPLACE "   hinge_law" "   hinge_hardening = 0.05\n   hinge_law" hardening "${deck}")
file(WRITE ${WORK_DIR}/portal_hardening.nml "${hardening}")
check(hardening portal_hardening.nml "Plastic hinges of P that yielded (kinematic hardening |m - H p| <= My;")
