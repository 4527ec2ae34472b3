# The engineering summary of a single-motion run (input/two_frames_gap_study.nml): the listing
# still starts with its title block (rule, program, date, deck, title, units, rule), then the
# Summary section, then the deck echo; on the terminal the summary comes before the solver
# statistics; <stem>_summary.csv is published with the listing and the HDF5 file, its columns
# as documented, its numbers those of the HDF5 file (the largest storey-shear lambda per
# building as /influence, the largest impact force as /coupled/contact/peak_force, the
# threshold gap as /sweep safe_gap, the no-contact gap as /sweep/closing_max, ABS as the sum of
# the facing floors' uncoupled peaks), and the root attribute `summary` holds the listing's
# Summary lines.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
run_shell(r "\"$POUND\" ${SOURCE_DIR}/input/two_frames_gap_study.nml -o out --quiet > terminal.txt")
expect_equal("exit status (${r_err})" 0 "${r_rc}")
expect_published(out two_frames_gap_study)
execute_process(COMMAND /usr/bin/python3 -c "
import csv, h5py, numpy as np
out = '${WORK_DIR}/out/two_frames_gap_study'
listing = open(out + '.out').read().splitlines()
assert listing[0] == '=' * 78 and listing[6] == '=' * 78, listing[:7]
assert listing[1].startswith('pound ') and listing[2].startswith('run on ') and listing[3].startswith('deck:  ')
assert listing[4] == 'title: Two frames: seismic joint gap study' and listing[5].startswith('units: ')
assert listing[7:10] == ['', 'Summary', '-------'], listing[7:10]
echo = listing.index('Deck echo')
summary = [l[2:] for l in listing[10:echo - 1]]
assert summary and all(l for l in summary), summary
term = open('${WORK_DIR}/terminal.txt').read().splitlines()
k = term.index('  ' + summary[0])
assert term[k:k + len(summary)] == ['  ' + l for l in summary]
assert k < min(i for i, l in enumerate(term) if 'uncoupled integration' in l)
assert term[-1].endswith('(summary: out/two_frames_gap_study_summary.csv)'), term[-1]
f = h5py.File(out + '.h5', 'r')
assert f.attrs['summary'].splitlines() == summary
rows = list(csv.DictReader(open(out + '_summary.csv')))
assert open(out + '_summary.csv').readline().strip() == 'kind,subject,quantity,value,unit,location,time'
def row(subject, quantity):
    r = [x for x in rows if x['subject'] == subject and x['quantity'] == quantity]
    assert len(r) == 1, (subject, quantity, r)
    return r[0]
force = f['coupled/contact/peak_force'][...]
for b in ('A', 'B'):
    lam = f['influence/%s/storey_shear' % b][...]
    j = int(np.argmax(np.abs(lam)))
    r = row(b, 'lambda_storey_shear')
    assert float(r['value']) == lam[j] and r['location'] == 'storey %d' % (j + 1) and r['unit'] == '%', r
    assert float(r['time']) == f['coupled/%s/peak_time/storey_shear' % b][j], r
    r = row(b, 'impact_force')
    assert float(r['value']) == force.max() and r['unit'] == 'kN', r
safe = 1e3 * float(f['sweep'].attrs['safe_gap'])
closing = f['sweep/closing_max'][...]
pair_rows = [x for x in rows if x['kind'] == 'pair' and x['quantity'] == 'time_history_gap']
assert len(pair_rows) == 3
for p, r in enumerate(pair_rows):
    assert float(r['value']) == safe, (r, safe)
    nc = row(r['subject'], 'no_contact_gap')
    assert float(nc['value']) == 1e3 * max(0.0, closing[p]), (nc, closing)
    a = row(r['subject'], 'code_gap_abs')
    ua = f['uncoupled/A/peak/u'][p]
    ub = f['uncoupled/B/peak/u'][p]
    assert abs(float(a['value']) - 1e3 * (ua + ub)) <= 1e-12 * 1e3 * (ua + ub), (a, ua, ub)
assert row('run', 'collapse')['value'] == 'n/a'
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("summary checks (${err})" 0 "${rc}")
