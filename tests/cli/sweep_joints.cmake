# Issue 27: a deck with two independent joints (input/three_buildings_joints.nml, A|B|C with
# joints A-B and B-C): besides the common sweep, each joint's own sweep (its pairs at the gaps,
# the other joint at its deck gap) gives the time-history gap of its pairs, in the summary's
# pair lines, the separation table, /separation/time_history and /sweep/joint/<left>-<right>/;
# the listing's tables parse (tests/cli/listing_columns.py). The thresholds themselves are
# checked against coupled runs in tests/test_sweep_joints.pf.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
run_pound(r ${SOURCE_DIR}/input/three_buildings_joints.nml)
expect_equal("exit status (${r_err})" 0 "${r_rc}")
expect_contains("stdout" "${r_out}" "time-history: sweep threshold of joint A-B (its pairs swept")
expect_contains("stdout" "${r_out}" "time-history: sweep threshold of joint B-C (its pairs swept")
expect_contains("stdout" "${r_out}" "(every joint at this gap; each joint's own: the pair lines)")
file(READ ${WORK_DIR}/three_buildings_joints.out listing)
expect_contains("listing" "${listing}" "Gap study per joint: the joint's pairs at the gaps, every other pair at its deck gap")
expect_contains("listing" "${listing}" "  Joint A-B (2 pairs: A:1-B:1 A:2-B:2)")
expect_contains("listing" "${listing}" "  Joint B-C (2 pairs: B:1-C:1 B:2-C:2)")
expect_contains("listing" "${listing}" "time-hist. per joint: the threshold of the pair's joint's own sweep")
execute_process(COMMAND ${PY} ${CMAKE_CURRENT_LIST_DIR}/listing_columns.py ${WORK_DIR}/three_buildings_joints.out
                        ${WORK_DIR}/three_buildings_joints.h5 20
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("listing and results (${out}${err})" 0 "${rc}")
# The results file: each pair's time-history gap is its joint's safe gap, the joints' thresholds
# differ, each is the smallest grid gap from which on every larger gap meets the target.
file(WRITE ${WORK_DIR}/check.py "
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], 'r')
th = f['/separation/time_history'][()]
pairs = [p.decode() if isinstance(p, bytes) else p for p in f['/separation/pair'][()]]
safe = {}
for j in ('A-B', 'B-C'):
    g = f['/sweep/joint/' + j]
    s = float(g['safe_gap'][()])
    assert g['safe_gap'].attrs['units'] == 'm', 'units of safe_gap'
    assert s == g.attrs['safe_gap'], j + ': dataset and attribute differ'
    gap, meets = g['gap'][()], g['meets'][()]
    assert np.array_equal(gap, f['/sweep/gap'][()]), j + ': not the common grid'
    i = int(np.argmin(np.abs(gap - s)))
    assert gap[i] == s and meets[i:].all() and not meets[i - 1], j + ': not the smallest safe grid gap'
    jp = [p.decode() if isinstance(p, bytes) else p for p in g['pairs'][()]]
    for p in jp:
        assert th[pairs.index(p)] == s, p + ': time_history is not its joint threshold'
    safe[j] = s
assert safe['A-B'] != safe['B-C'], 'the joints have the same threshold'
assert 'joint' in f['/separation/time_history'].attrs['rule']
print('ok', safe)
")
execute_process(COMMAND ${PY} ${WORK_DIR}/check.py ${WORK_DIR}/three_buildings_joints.h5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("results file (${out}${err})" 0 "${rc}")
expect_equal("stderr" "" "${r_err}")
