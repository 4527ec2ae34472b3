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
run_pound(r portal.nml)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/portal.out listing)
expect_contains("listing" "${listing}" "Plastic hinges of P that yielded")
# Column bases and both beam ends yield (the beam's left end is hinge 5).
expect_contains("listing" "${listing}" "beam     1    1   left      30.0")
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/reference_frame_hinges.py ${WORK_DIR}/portal.h5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("reference comparison (${out} ${err})" 0 "${rc}")
expect_contains("reference output" "${out}" "largest difference of u")

# With P-Delta (gravity_load 2000 kN: the mechanism's tangent is negative, the LCP rows
# non-convex) the portal collapses; the histories agree up to pound's collapse step.
file(READ ${WORK_DIR}/portal.nml deck)
string(REPLACE "   hinge_law" "   p_delta = .true.\n   gravity_load = 2000.0\n   hinge_law" deck "${deck}")
file(WRITE ${WORK_DIR}/portal_pdelta.nml "${deck}")
run_pound(r portal_pdelta.nml)
expect_equal("pound exit, P-Delta (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/portal_pdelta.out listing)
expect_contains("listing, P-Delta" "${listing}" "COLLAPSE: collapsed in the uncoupled analysis (storey 1, t = ")
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/reference_frame_hinges.py ${WORK_DIR}/portal_pdelta.h5 2000
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("reference comparison, P-Delta (${out} ${err})" 0 "${rc}")
expect_contains("reference output, P-Delta" "${out}" "compared up to it")
