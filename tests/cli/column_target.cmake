# Column demands as sweep targets (&sweep target_quantities = 'storey_shear column_shear') on a
# small floor-to-column deck (tests/data/column_target.nml: the frames of
# input/frame_to_column.nml under a tenth of its pulse, gaps 0..10 mm in 21 steps, target
# 100 %). Checked from the HDF5 datasets the sweep itself writes:
# - the safe gap is the smallest gap from which on every targeted |lambda| (storey shear and
#   column shear of both frames) is <= the target: 8.0 mm;
# - the same deck targeting the storey shear alone gives 7.0 mm (the struck column segments
#   decide the safe gap) and writes no column datasets;
# - column_shear is the largest |lambda| of the segment shears: at 5 mm it equals
#   max |/influence/<b>/columns/shear| of a plain run of the deck at a 5 mm gap;
# - the new datasets carry units = '%'; column_moment, not targeted, is not written.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
include(${CMAKE_CURRENT_LIST_DIR}/column_target.cmake.inc)
run_target_variants(column_target.nml)
# A plain run at a 5 mm gap (no sweep): its column-segment lambdas.
string(REPLACE "gap = 6*0.010" "gap = 6*0.005" deck_5 "${deck}")
string(FIND "${deck_5}" "&sweep" at)
string(SUBSTRING "${deck_5}" 0 ${at} deck_5)
expect_contains("deck" "${deck_5}" "gap = 6*0.005")
file(WRITE ${WORK_DIR}/plain5.nml "${deck_5}")
run_pound(r plain5.nml)
expect_equal("pound plain5 exit (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/col.out listing)
expect_contains("listing" "${listing}" "Gap study: largest |lambda| [%] over the column segments of the frames")
expect_contains("listing" "${listing}" "A:column_shear  B:column_shear  target")
expect_contains("listing" "${listing}" "at it and at every larger gap of the sweep:     8.0000 mm")
file(READ ${WORK_DIR}/storey.out listing_q)
string(FIND "${listing_q}" "over the column segments of the frames against the gap" pos)
expect_equal("no column sweep table without column targets" -1 "${pos}")
execute_process(COMMAND ${PY} -c "
import h5py, numpy as np
def safe(f, qs):
    gap = f['sweep/gap'][...]
    target = float(f['sweep'].attrs['target_lambda'])
    worst = np.zeros(len(gap))
    for b in ('A', 'B'):
        for q in qs:
            worst = np.maximum(worst, np.abs(f['sweep/max_abs_lambda/' + b + '/' + q][...]))
    ok = worst <= target
    s = -1.0
    for i in range(len(gap) - 1, -1, -1):
        if not ok[i]:
            break
        s = gap[i]
    assert np.array_equal(f['sweep/meets'][...] == 1, ok), (f['sweep/meets'][...], ok)
    return s, worst
f = h5py.File('${WORK_DIR}/col.h5', 'r')
s_col, worst = safe(f, ('storey_shear', 'column_shear'))
assert s_col == f['sweep'].attrs['safe_gap'], (s_col, f['sweep'].attrs['safe_gap'])
assert abs(s_col - 0.008) < 1e-15, s_col
for b in ('A', 'B'):
    d = f['sweep/max_abs_lambda/' + b + '/column_shear']
    assert d.attrs['units'] in ('%', b'%'), d.attrs['units']
    assert d.shape == (21,), d.shape
    assert 'sweep/max_abs_lambda/' + b + '/column_moment' not in f
# the gap below the safe one fails on a column segment, not on the storey shears
i = int(np.argmin(np.abs(f['sweep/gap'][...] - 0.0075)))
col = max(abs(f['sweep/max_abs_lambda/' + b + '/column_shear'][i]) for b in ('A', 'B'))
q = max(abs(f['sweep/max_abs_lambda/' + b + '/storey_shear'][i]) for b in ('A', 'B'))
assert col > 100.0 and q <= 100.0, (col, q)
g = h5py.File('${WORK_DIR}/storey.h5', 'r')
s_q, _ = safe(g, ('storey_shear',))
assert s_q == g['sweep'].attrs['safe_gap'], (s_q, g['sweep'].attrs['safe_gap'])
assert abs(s_q - 0.007) < 1e-15, s_q
assert s_col > s_q
for b in ('A', 'B'):
    assert 'sweep/max_abs_lambda/' + b + '/column_shear' not in g
    assert np.array_equal(g['sweep/max_abs_lambda/' + b + '/storey_shear'][...],
                          f['sweep/max_abs_lambda/' + b + '/storey_shear'][...])
# column_shear = largest |lambda| over the segments, against a plain run at the 5 mm gap
p = h5py.File('${WORK_DIR}/plain5.h5', 'r')
k = int(np.argmin(np.abs(f['sweep/gap'][...] - 0.005)))
for b in ('A', 'B'):
    want = np.max(np.abs(p['influence/' + b + '/columns/shear'][...]))
    got = f['sweep/max_abs_lambda/' + b + '/column_shear'][k]
    assert want > 1.0 and abs(got - want) <= 1e-9 * want, (b, got, want)
print('ok', s_col, s_q)
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("HDF5 checks (${out} ${err})" 0 "${rc}")
expect_contains("HDF5 checks" "${out}" "ok 0.008 0.007")
# The plots: the sweep with the targeted column quantity, the column segments' lambdas.
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/plot_results.py ${WORK_DIR}/col.h5
                --only sweep,columns --format png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
expect_png("plot sweep (${out} ${err})" ${WORK_DIR}/col_sweep.png)
expect_png("plot columns (${out} ${err})" ${WORK_DIR}/col_columns.png)
