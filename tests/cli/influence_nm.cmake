# Influence coefficients that are not meaningful, end to end (tests/data/influence_nm_suite.nml:
# a suite of two pulses, building A's storey 2 so stiff that its uncoupled drift is ~1e-9 of
# storey 1's): the drift lambda of that storey is NaN in /influence/A/drift with the attribute
# not_meaningful, n/m in the listing, left out of the suite's maximum (NaN only where every motion's
# is) and of the sweep's largest |lambda| (finite); storey 1 keeps its number.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
run_pound(r ${SOURCE_DIR}/tests/data/influence_nm_suite.nml --quiet)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/influence_nm_suite.out listing)
expect_contains("n/m in the listing" "${listing}" "       2           n/m ")
execute_process(COMMAND ${PY} -c "
import h5py, numpy as np
f = h5py.File('${WORK_DIR}/influence_nm_suite.h5', 'r')
d = f['influence/A/drift']
lam = d[()]
assert np.isnan(lam[1]) and np.isfinite(lam[0]) and lam[0] > 100, lam
assert 'below 1e-6' in d.attrs['not_meaningful'], dict(d.attrs)
pu, pc = f['uncoupled/A/peak/drift'][()], f['coupled/A/peak/drift'][()]
assert pu[1] < 1e-6 * pu[0] and pu[1] > 0, pu
assert abs(lam[0] - (pc[0] - pu[0]) / pu[0] * 100) <= 1e-9 * abs(lam[0]), lam
assert 'not_meaningful' not in f['influence/B/drift'].attrs
mx = f['suite/max/influence/A/drift'][()]
per = f['suite/influence/A/drift'][()]
assert np.isnan(mx[1]) and mx[0] == np.max(per[:, 0]), (mx, per)
sw = f['sweep/max_abs_lambda/A/drift'][()]
assert np.all(np.isfinite(sw)), sw
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("n/m in the results (${out}${err})" 0 "${rc}")
