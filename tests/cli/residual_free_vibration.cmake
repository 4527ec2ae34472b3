# Residual drift after the shaking (&analysis t_free): free vibration with the ground at rest
# after t_end, the residual drift read at t_end + t_free. Closed form: a bilinear one-storey
# building (no P-Delta) that no longer yields after t_end vibrates on its last elastic branch
# Q = k (d - d0), damped, about d0 = d - Q/k (the same at every sample after t_end); the residual
# drift it settles to is d0, while the drift at t_end (0.6 s, still vibrating) is 50 % off.
# The warning that the residual is read while the ground or the building still moves appears
# without t_free and disappears with it; t_free = 0 is the deck without t_free.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

set(building "&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566370614359172 /
&building name = 'A', n_storeys = 1, height = 3.0, mass = 10.0, stiffness = 1.0e4,
   storey_law = 'bilinear', yield_shear = 10.0, hardening_ratio = 0.05, damping_ratio = 0.05 /
")
file(WRITE ${WORK_DIR}/free.nml "&analysis dt = 0.002, t_end = 0.6, t_free = 20.0 /\n${building}")
file(WRITE ${WORK_DIR}/short.nml "&analysis dt = 0.002, t_end = 0.6 /\n${building}")
file(WRITE ${WORK_DIR}/zero.nml "&analysis dt = 0.002, t_end = 0.6, t_free = 0.0 /\n${building}")
file(WRITE ${WORK_DIR}/neg/negative.nml "&analysis dt = 0.002, t_end = 0.6, t_free = -1.0 /\n${building}")

run_pound(f free.nml)
expect_equal("free: exit status (${f_err})" 0 "${f_rc}")
string(FIND "${f_out}" "residual drift of A read" pos)
expect_equal("free: no residual warning" -1 "${pos}")
file(READ ${WORK_DIR}/free.out listing)
expect_contains("free: listing" "${listing}" "t_end =    0.6000 s   steps = 10300")
expect_contains("free: listing" "${listing}" "t_free = 20 s of free vibration after t_end, the ground at rest: the analysis ends at 20.6 s")

# The closed form, the ground at rest after t_end, the histories grown by the free steps.
file(WRITE ${WORK_DIR}/check.py "
import h5py, numpy as np
f = h5py.File('free.h5', 'r')
d = f['/uncoupled/A/drift'][:, 0]; q = f['/uncoupled/A/storey_shear'][:, 0]
ag = f['/ground/acceleration'][:]; t = f['/uncoupled/time'][:]
i = 300                                  # t = t_end = 0.6 s
assert len(t) == 10301 and len(ag) == 10301 and abs(t[-1] - 20.6) < 1e-9, (len(t), t[-1])
assert abs(t[i] - 0.6) < 1e-12
d0 = d[i] - q[i] / 1.0e4                 # centre of the last elastic branch
assert np.ptp(d[i:] - q[i:] / 1.0e4) < 1e-15, np.ptp(d[i:] - q[i:] / 1.0e4)   # no yielding after t_end
res = f['/uncoupled/A/residual_drift'][0]
assert abs(res - d0) < 1e-12 * abs(d0), (res, d0)
assert abs(d[i] - d0) > 0.4 * abs(d0), (d[i], d0)   # at t_end the drift is not the residual
assert np.all(ag[i + 1:] == 0.0) and abs(ag[i]) > 0.0
assert abs(f.attrs['t_free'] - 20.0) == 0.0
print('ok', res, d[i])
")
execute_process(COMMAND /usr/bin/python3 check.py WORKING_DIRECTORY ${WORK_DIR}
                RESULT_VARIABLE py_rc OUTPUT_VARIABLE py_out ERROR_VARIABLE py_err)
expect_equal("closed form (${py_out}${py_err})" 0 "${py_rc}")

# Without t_free: read at t = 0.6 s while the pulse still shakes: the warning says what to set.
run_pound(s short.nml)
expect_equal("short: exit status" 0 "${s_rc}")
expect_contains("short: warning" "${s_out}" "WARNING: residual drift of A read at t = 0.6 s while the ground still shakes (|a_g| up to 100 % of the PGA in the last 1 s): it is a drift of the vibration, not the permanent set; set &analysis t_free = 2 (s of free vibration with the ground at rest after t_end; 10 T1 = 1.99 s)")

# t_free = 0 is the deck without it, to the last digit.
run_pound(z zero.nml)
expect_equal("zero: exit status" 0 "${z_rc}")
file(READ ${WORK_DIR}/short_summary.csv a)
file(READ ${WORK_DIR}/zero_summary.csv b)
string(REPLACE "short" "x" a "${a}")
string(REPLACE "zero" "x" b "${b}")
expect_equal("t_free = 0: the same summary" "${a}" "${b}")

run_pound(n neg/negative.nml -o neg)
expect_clean_failure("negative" n "negative.nml:1: &analysis: t_free = -1.000000, must be >= 0" neg)
