# Joint studies with one motion scaled by scale_to (a single motion, not a suite): the stiffness
# sweep and the law study run. The motion is the suite's scaling (its PGA as run is the target),
# and the sweep's row at the deck's own stiffness is the deck's own coupled run.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

set(scaled "   b = 12.566370614359172   ! rad/s (4 pi)\n   scale_to = 'pga'\n   target = 2.5\n")
file(READ ${SOURCE_DIR}/input/joint_stiffness_study.nml deck)
string(REPLACE "   b = 12.566370614359172   ! rad/s (4 pi)\n" "${scaled}" deck "${deck}")
string(REGEX REPLACE "&sweep.*$" "&sweep parameter = 'stiffness', values = 1e5, 1e6, 1e7, target_lambda = 10.0 /" deck "${deck}")
file(WRITE ${WORK_DIR}/stiffness_scaled.nml "${deck}")
run_pound(s stiffness_scaled.nml --quiet)
expect_equal("stiffness_scaled: exit status (${s_err})" 0 "${s_rc}")
file(READ ${WORK_DIR}/stiffness_scaled.out listing)
expect_contains("stiffness listing" "${listing}" "Stiffness sweep: largest |lambda| [%] over the storeys (floors) against the joint stiffness k0")
file(WRITE ${WORK_DIR}/check.py "
import h5py, numpy as np
f = h5py.File('stiffness_scaled.h5', 'r')
ag = f['/ground/acceleration'][:]
assert abs(np.abs(ag).max() - 2.5) < 0.005, np.abs(ag).max()          # the target PGA, at the output samples
v = list(f['/stiffness_sweep/value'][:])
k = v.index(1.0e6)
for b in ('A', 'B'):
    own = np.abs(f['/influence/' + b + '/storey_shear'][:]).max()
    row = f['/stiffness_sweep/max_abs_lambda/' + b + '/storey_shear'][k]
    assert abs(own - row) <= 1e-12 * max(1.0, own), (b, own, row)
print('ok')
")
execute_process(COMMAND /usr/bin/python3 check.py WORKING_DIRECTORY ${WORK_DIR}
                RESULT_VARIABLE py_rc OUTPUT_VARIABLE py_out ERROR_VARIABLE py_err)
expect_equal("scaled stiffness sweep (${py_out}${py_err})" 0 "${py_rc}")

file(READ ${SOURCE_DIR}/input/joint_law_study.nml deck)
string(REPLACE "   b = 12.566370614359172   ! rad/s (4 pi)\n" "${scaled}" deck "${deck}")
file(WRITE ${WORK_DIR}/law_scaled.nml "${deck}")
run_pound(l law_scaled.nml --quiet)
expect_equal("law_scaled: exit status (${l_err})" 0 "${l_rc}")
file(READ ${WORK_DIR}/law_scaled.out listing)
expect_contains("law listing" "${listing}" "Law study: the deck's joints (base) and each &contact variant")

# Two motions are still a suite: refused, saying how many.
string(REPLACE "&ground\n   kind = 'pulse'" "&ground\n   name = 'p1'\n   kind = 'pulse'" two "${deck}")
string(REPLACE "! Frame A," "&ground name = 'p2', kind = 'pulse', x0 = 0.005, a = 2.0, b = 12.566370614359172 /\n\n! Frame A,"
       two "${two}")
file(MAKE_DIRECTORY ${WORK_DIR}/two)
file(WRITE ${WORK_DIR}/two/two.nml "${two}")
run_pound(t two/two.nml -o two)
expect_clean_failure("two motions" t "a law study (&contact variant) runs with one ground motion; this deck is a suite of 2 motions (several &ground)" two)
