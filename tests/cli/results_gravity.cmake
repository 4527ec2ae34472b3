# The acceleration of gravity in the results file (issue 24): root attribute g = 9.81 m/s^2
# (pound_constants::g_accel, float64), and scripts/plot_results.py takes g from the file, not
# from a constant of its own: a file whose attribute says 9.80665 is read as 9.80665, a file
# without it (written before the attribute existed) as 9.81, a non-positive g is a clear error.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
run_pound(r ${SOURCE_DIR}/tests/data/small_pounding.nml)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
execute_process(COMMAND ${PY} -c "
import shutil, sys
import h5py, numpy as np
sys.path.insert(0, '${SOURCE_DIR}/scripts')
import plot_results as p
path = '${WORK_DIR}/small_pounding.h5'
with h5py.File(path, 'r') as f:
    g = f.attrs['g']
    assert np.asarray(g).dtype == np.float64, np.asarray(g).dtype
    assert float(g) == 9.81, g
    assert f['/ground/acceleration'].attrs['units'] in (b'm/s^2', 'm/s^2')
r = p.read_results(path)
assert r.g == 9.81 and r.ground['units'] == 'm/s^2' and 'm/s^2' in r.units, (r.g, r.ground['units'], r.units)
copy = '${WORK_DIR}/copy.h5'
shutil.copy(path, copy)
with h5py.File(copy, 'r+') as f:
    f.attrs['g'] = 9.80665
assert p.read_results(copy).g == 9.80665
with h5py.File(copy, 'r+') as f:
    del f.attrs['g']
assert p.read_results(copy).g == 9.81
with h5py.File(copy, 'r+') as f:
    f.attrs['g'] = -1.0
try:
    p.read_results(copy)
    raise SystemExit('a negative g was accepted')
except p.PlotError as e:
    assert 'root attribute g' in str(e), e
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("gravity in the results file and the plot script (${out}${err})" 0 "${rc}")
expect_contains("checks ran" "${out}" "ok")
