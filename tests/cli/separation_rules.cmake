# The code separation rules of a single run where every pair is a floor facing a column between
# floors (input/frame_to_column.nml with cd = behaviour_factor = response_reduction = 1 and node
# histories): the HDF5 file's peaks of the two facing points are the floors' uncoupled peaks and
# the split column nodes' largest |u| (every step stored), and SRSS, ABS, EN 1998 (= SRSS: no
# x 0.7 for a floor facing a column), IS 1893 (= ABS), ASCE 7 and the setbacks follow from them;
# no warning for factors 1. With the codes' factors as printed (cd 5.5, q 3.9, R 5) each gives one
# warning (value, mistake, fix) and the setback is Cd u. The labels say which peaks: elastic here,
# the yielding buildings' own for input/seed_bilinear.nml (listing, CSV, HDF5 attribute). The
# separation plot is drawn; a suite of floor-to-column pairs likewise (below).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
file(READ ${SOURCE_DIR}/input/frame_to_column.nml deck)
string(REPLACE "&analysis" "&analysis node_histories = .true.," deck "${deck}")
string(REPLACE "damping_modes = 1, 2" "damping_modes = 1, 2, cd = 1.0, behaviour_factor = 1.0, response_reduction = 1.0"
       ones "${deck}")
file(WRITE ${WORK_DIR}/ones.nml "${ones}")
run_pound(o ${WORK_DIR}/ones.nml)
expect_equal("pound exit, factors 1 (${o_err})" 0 "${o_rc}")
string(FIND "${o_err}${o_out}" "with motions at full intensity" w)
expect_equal("no factor warning for factors 1" -1 "${w}")
string(REPLACE "damping_modes = 1, 2" "damping_modes = 1, 2, cd = 5.5, behaviour_factor = 3.9, response_reduction = 5.0"
       codes "${deck}")
file(WRITE ${WORK_DIR}/codes.nml "${codes}")
run_pound(c ${WORK_DIR}/codes.nml)
expect_equal("pound exit, codes' factors (${c_err})" 0 "${c_rc}")
expect_contains("cd warning" "${c_err}${c_out}" "&building #1 (A): cd = 5.5 > 1 with motions at full intensity")
expect_contains("q warning" "${c_err}${c_out}" "set behaviour_factor = 1, unless the motions are scaled down")
expect_contains("R warning" "${c_err}${c_out}" "&building #2 (B): response_reduction = 5 > 1")
file(READ ${WORK_DIR}/ones.out listing)
expect_contains("listing label" "${listing}" "From the uncoupled elastic peaks u1, u2 at the facing points")
expect_contains("listing pair" "${listing}" "pair A:1-B:z=3.50m  (u1 elastic, u2 elastic; floor levels do not coincide")
expect_contains("listing setbacks" "${listing}" "Property-line setback per building")
execute_process(COMMAND ${PY} -c "
import csv, h5py, numpy as np
def peaks(path):
    f = h5py.File(path, 'r')
    g = f['separation']
    out = []
    for p, label in enumerate(g['pair'][...]):
        ends = label.decode().split('-')
        u = []
        for e, end in enumerate(ends):
            b, where = end.split(':')
            if where.startswith('z='):
                z = float(where[2:-1])
                nodes = f['model/%s/nodes' % b][...]
                x = nodes[0].max() if e == 0 else nodes[0].min()
                k = [i for i in range(nodes.shape[1]) if abs(nodes[1, i] - z) < 1e-9 and nodes[0, i] == x]
                assert len(k) == 1, (label, k)
                dofs = f['model/%s/dofs' % b][...]
                d = [j for j in range(dofs.shape[1]) if dofs[0, j] == k[0] + 1 and dofs[1, j] == 1]
                assert len(d) == 1, (label, d)
                u.append(np.abs(f['uncoupled/%s/u_nodes' % b][:, d[0]]).max())
            else:
                u.append(f['uncoupled/%s/peak/u' % b][int(where) - 1])
        out.append(u)
    return f, g, np.array(out)
f, g, u = peaks('${WORK_DIR}/ones.h5')
assert u.shape == (6, 2) and (u > 0).all(), u
assert (g['peak_left'][...] == u[:, 0]).all() and (g['peak_right'][...] == u[:, 1]).all(), (g['peak_left'][...], u)
srss = np.hypot(u[:, 0], u[:, 1])
tol = 1e-15
assert np.allclose(g['srss'][...], srss, rtol=tol, atol=0), (g['srss'][...], srss)
assert np.allclose(g['abs'][...], u.sum(axis=1), rtol=tol, atol=0)
assert np.allclose(g['en1998'][...], srss, rtol=tol, atol=0), ('EN 1998 must equal SRSS for floor-to-column', g['en1998'][...], srss)
assert np.allclose(g['asce7'][...], srss, rtol=tol, atol=0)
assert np.allclose(g['is1893'][...], u.sum(axis=1), rtol=tol, atol=0)
assert (g['setback_left'][...] == u[:, 0]).all() and (g['setback_right'][...] == u[:, 1]).all()
assert list(g['building_setback'][...]) == [u[:, 0].max(), u[:, 1].max()]
assert [n.decode() for n in g['building_name'][...]] == ['A', 'B']
assert g.attrs['peaks'] == 'the rules and setbacks use the uncoupled elastic peaks', g.attrs['peaks']
rows = list(csv.DictReader(open('${WORK_DIR}/ones_summary.csv')))
en = [r for r in rows if r['quantity'] == 'code_gap_en1998']
assert len(en) == 6 and all('uncoupled elastic peaks' in r['location'] for r in en), en
sb = {r['subject']: float(r['value']) for r in rows if r['quantity'] == 'setback'}
assert sb == {'A': 1e3 * u[:, 0].max(), 'B': 1e3 * u[:, 1].max()}, sb
f, g, u = peaks('${WORK_DIR}/codes.h5')
assert np.allclose(g['setback_left'][...], 5.5 * u[:, 0], rtol=tol, atol=0)
assert np.allclose(g['en1998'][...], 3.9 * np.hypot(u[:, 0], u[:, 1]), rtol=tol, atol=0)
assert np.allclose(g['is1893'][...], 5.0 * u.sum(axis=1), rtol=tol, atol=0)
assert (g['setback_amplified_left'][...] == 1).all() and (g['setback_amplified_right'][...] == 1).all()
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("HDF5 and CSV checks (${err})" 0 "${rc}")

# A yielding pair: the labels say the yielding buildings' own (inelastic) peaks.
run_pound(y ${SOURCE_DIR}/input/seed_bilinear.nml)
expect_equal("pound exit, seed_bilinear (${y_err})" 0 "${y_rc}")
file(READ ${WORK_DIR}/seed_bilinear.out listing)
expect_contains("listing label, yielding" "${listing}"
                "From the uncoupled peaks of the yielding buildings (inelastic) u1, u2")
execute_process(COMMAND ${PY} -c "
import csv, h5py
g = h5py.File('${WORK_DIR}/seed_bilinear.h5', 'r')['separation']
assert g.attrs['peaks'] == 'the rules and setbacks use the uncoupled peaks of the yielding buildings (inelastic)'
rows = list(csv.DictReader(open('${WORK_DIR}/seed_bilinear_summary.csv')))
srss = [r for r in rows if r['quantity'] == 'code_gap_srss']
assert srss and all('yielding buildings (inelastic)' in r['location'] for r in srss), srss
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("yielding labels (${err})" 0 "${rc}")

# The separation plot of a single run.
execute_process(COMMAND ${PY} ${SOURCE_DIR}/scripts/plot_results.py ${WORK_DIR}/ones.h5 --only separation
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
expect_png("separation plot" ${WORK_DIR}/ones_separation.png)

# A suite whose pairs are all floor-to-column (tests/data/suite_elevations.nml without its sweep
# and node histories, factors 1): every motion's and the suite's EN 1998 = SRSS and IS 1893 =
# ABS (no x 0.7, x 0.5), computed from the column nodes' peaks without node histories; the
# suite plot draws the rules with their factors.
file(READ ${SOURCE_DIR}/tests/data/suite_elevations.nml deck)
string(REGEX REPLACE "&sweep[^\n]*" "" deck "${deck}")
string(REPLACE "node_histories = .true." "node_histories = .false." deck "${deck}")
string(REPLACE "damping_modes = 1, 2" "damping_modes = 1, 2, cd = 1.0, behaviour_factor = 1.0, response_reduction = 1.0"
       deck "${deck}")
file(WRITE ${WORK_DIR}/suite_ones.nml "${deck}")
run_pound(s ${WORK_DIR}/suite_ones.nml)
expect_equal("pound exit, suite (${s_err})" 0 "${s_rc}")
execute_process(COMMAND ${PY} -c "
import h5py, numpy as np
g = h5py.File('${WORK_DIR}/suite_ones.h5', 'r')['suite/separation']
srss, ab = g['srss'][...], g['abs'][...]
assert srss.shape == (4, 4) and (srss > 0).all(), srss
assert (g['en1998'][...] == srss).all(), (g['en1998'][...], srss)
assert (g['is1893'][...] == ab).all() and (g['ec8'][...] == srss).all()
u1, u2 = g['peak_left'][...], g['peak_right'][...]
assert np.allclose(srss, np.hypot(u1, u2), rtol=1e-15, atol=0) and (g['setback_left'][...] == u1).all()
assert (g['setback_amplified_left'][...] == 1).all() and g['setback_amplified_left'].shape == (4, 4)
assert g.attrs['peaks'] == 'the rules and setbacks use the uncoupled elastic peaks'
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("suite checks (${err})" 0 "${rc}")
execute_process(COMMAND ${PY} ${SOURCE_DIR}/scripts/plot_suite.py ${WORK_DIR}/suite_ones.h5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot_suite exit (${err})" 0 "${rc}")
expect_png("suite separation plot" ${WORK_DIR}/suite_ones_suite_separation.png)
