# Column demands as targets over a suite (tests/data/column_target_suite.nml: two frames floor
# to floor, two pulses and a synthetic motion, gaps 0..10 mm in 11 steps, target 222 % on
# storey_shear and column_shear; no records needed). Checked from the HDF5 datasets:
# - the suite's safe gaps on the mean and on every motion are the smallest grid gaps from
#   which on /suite/sweep/mean and /suite/sweep/max stay <= the target; max is the largest
#   over the motions of /suite/sweep/max_abs_lambda;
# - the first motion's row of /suite/sweep/max_abs_lambda is the largest of its own sweep's
#   targeted quantities (/sweep/max_abs_lambda/<b>/storey_shear and column_shear);
# - targeting column_shear moves the safe gap on every motion from 6 mm (storey shear alone)
#   to 9 mm, and its refinement from (5, 6] to (8, 9] mm;
# - the suite statistics of the column segments: /suite/influence/<b>/columns/<c> (rows =
#   motions; the first row is /influence/<b>/columns/<c>), their mean and max over the
#   motions, units '%'; at the deck's gap (10 mm, the last of the sweep) each motion's
#   suite-sweep value is at least the largest |lambda| of its segment shears.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
include(${CMAKE_CURRENT_LIST_DIR}/column_target.cmake.inc)
run_target_variants(column_target_suite.nml)
file(READ ${WORK_DIR}/col.out listing)
expect_contains("listing" "${listing}" "Suite: largest |lambda| [%] over the column segments per motion and frame")
execute_process(COMMAND ${PY} -c "
import h5py, numpy as np
def safe(gap, worst, target):
    s = -1.0
    for i in range(len(gap) - 1, -1, -1):
        if worst[i] > target:
            break
        s = gap[i]
    return s
def check(path, qs):
    f = h5py.File(path, 'r')
    gap = f['suite/sweep/gap'][...]
    target = float(f['sweep'].attrs['target_lambda'])
    assert target == 222.0
    per = f['suite/sweep/max_abs_lambda'][...]
    if per.shape[0] != 3:
        per = per.T
    assert per.shape == (3, len(gap)), per.shape
    mx = f['suite/sweep/max'][...]
    assert np.array_equal(mx, per.max(axis=0))
    assert safe(gap, mx, target) == f['suite/sweep/safe_gap_every'][()]
    assert safe(gap, f['suite/sweep/mean'][...], target) == f['suite/sweep/safe_gap_mean'][()]
    own = np.zeros(len(gap))
    for b in ('A', 'B'):
        for q in qs:
            own = np.maximum(own, f['sweep/max_abs_lambda/' + b + '/' + q][...])
    assert np.array_equal(per[0], own), (per[0], own)
    return f, per
f, per = check('${WORK_DIR}/col.h5', ('storey_shear', 'column_shear'))
g, per_q = check('${WORK_DIR}/storey.h5', ('storey_shear',))
se, sq = f['suite/sweep/safe_gap_every'][()], g['suite/sweep/safe_gap_every'][()]
re, rq = f['suite/sweep/refined_gap_every'][()], g['suite/sweep/refined_gap_every'][()]
assert abs(se - 0.009) < 1e-15 and abs(sq - 0.006) < 1e-15, (se, sq)
assert 0.008 < re <= 0.009 and 0.005 < rq <= 0.006, (re, rq)
assert np.all(per >= per_q)
for b in ('A', 'B'):
    assert 'sweep/max_abs_lambda/' + b + '/column_shear' not in g
    nseg = f['model/' + b + '/columns'].shape[1]
    for c in ('shear', 'moment_bottom', 'moment_top', 'axial'):
        d = f['suite/influence/' + b + '/columns/' + c]
        lam = d[...]
        assert lam.shape == (3, nseg), lam.shape
        assert d.attrs['units'] in ('%', b'%')
        assert np.array_equal(lam[0], f['influence/' + b + '/columns/' + c][...]), (b, c)
        mean = f['suite/mean/influence/' + b + '/columns/' + c][...]
        assert np.allclose(mean, lam.mean(axis=0), rtol=1e-13, atol=1e-12), (b, c)
        assert np.array_equal(f['suite/max/influence/' + b + '/columns/' + c][...], lam.max(axis=0))
    shear = np.abs(f['suite/influence/' + b + '/columns/shear'][...]).max(axis=1)
    assert np.all(per[:, -1] >= shear * (1 - 1e-12)), (per[:, -1], shear)
# the column shears decide the last gap of some motion: equality with a segment's shear
best = np.max([np.abs(f['suite/influence/' + b + '/columns/shear'][...]).max(axis=1) for b in ('A', 'B')], axis=0)
assert np.any(np.abs(per[:, -1] - best) <= 1e-9 * best), (per[:, -1], best)
print('ok', se, sq)
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("HDF5 checks (${out} ${err})" 0 "${rc}")
expect_contains("HDF5 checks" "${out}" "ok 0.009 0.006")
# Every plot of the suite's file (frames, a sweep with column_shear, the suite group): among
# them the influence plot, whose quantity with every lambda 0 (v) once made an image of
# 259588823 pixels' width.
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/plot_results.py ${WORK_DIR}/col.h5 --format png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
foreach(p influence sweep columns suite_sweep)
  expect_png("plot ${p} (${out} ${err})" ${WORK_DIR}/col_${p}.png)
endforeach()
