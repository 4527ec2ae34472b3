"""The multiple-stripe analysis against single runs (cli.risk_stripes).

usage: risk_stripes.py POUND WORK_DIR DECK

1. DECK (tests/data/risk_stripes.nml: pulses, a sweep, stripes, hazard) is run; every
   (stripe, motion, gap) outcome in /risk/outcomes must equal a single run of that motion
   scaled by `scale_to = 'sa'` to the stripe's level at that gap (contact: an impact;
   lambda_exceeded: the largest |lambda| of storey_shear over the buildings and storeys from the
   single run's own peaks > 10 %), and the demand files must hold the single run's coupled peaks
   at the deck gap (PID = drift / height, PFA in g).
2. /risk/probability = 1 - exp(-maf years); /risk/gap is the smallest grid gap from which on
   P <= target_probability; the answer line leads the summary.
3. A record_set: records in a folder, a pattern with another case, named by stem, sorted.
"""
import csv, math, os, re, subprocess, sys
import h5py
import numpy as np

pound, work, deck = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
fail = []


def run(path, out):
    r = subprocess.run([pound, path, '-o', out], cwd=work, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f'{path}: exit {r.returncode}: {r.stderr}')
    return r.stdout


stdout = run(deck, 'risk')
stem = os.path.splitext(os.path.basename(deck))[0]
h = h5py.File(os.path.join(work, 'risk', stem + '.h5'), 'r')
levels = h['/risk/stripes/levels'][()]
motions = [m.decode() if isinstance(m, bytes) else m for m in h['/risk/motions'][()]]
gaps = h['/risk/gaps'][()]
years = h['/risk'].attrs['years']
target = h['/risk'].attrs['target_probability']
contact = h['/risk/outcomes/contact'][()]
lam = h['/risk/outcomes/lambda_exceeded'][()]
assert contact.shape == (len(gaps), len(levels), len(motions)), contact.shape
assert 'collapse' not in h['/risk/outcomes'], 'collapse outcomes without yielding buildings'

text = open(deck).read()
grounds = re.findall(r"^&ground name = '(\w+)', (kind = 'pulse'.*?) /$", text, re.M)
rest = [l for l in text.splitlines() if l.startswith(('&analysis', '&building'))]
contact_line = [l for l in text.splitlines() if l.startswith('&contact')][0]
heights = {'A': [3.0, 3.0], 'B': [3.0, 3.0, 3.0]}


def single(name, pulse, level, gap, tag):
    lines = list(rest)
    lines.insert(1, f"&ground {pulse}, scale_to = 'sa', target = {level!r} /")
    lines.append(re.sub(r'gap = [0-9.eE+-]+', f'gap = {gap!r}', contact_line))
    path = os.path.join(work, f'one_{tag}.nml')
    open(path, 'w').write('\n'.join(lines) + '\n')
    run(path, 'one')
    f = h5py.File(os.path.join(work, 'one', f'one_{tag}.h5'), 'r')
    impacts = int(np.sum(f['/coupled/contact/impacts'][()]))
    worst = 0.0
    peaks = {}
    for b in ('A', 'B'):
        qc = f[f'/coupled/{b}/peak/storey_shear'][()]
        qu = f[f'/uncoupled/{b}/peak/storey_shear'][()]
        worst = max(worst, float(np.max(np.abs((qc - qu) / qu * 100.0))))
        peaks[b] = (f[f'/coupled/{b}/peak/drift'][()], f[f'/coupled/{b}/peak/a_abs'][()])
    f.close()
    return int(impacts > 0), int(worst > 10.0), peaks


deck_gap = float(h['/risk'].attrs['deck_gap'])
for s, level in enumerate(levels):
    rows = list(csv.reader(open(os.path.join(work, 'risk', f'{stem}_demands_stripe{s + 1}.csv'))))
    assert rows[1][0] == 'Units', rows[1]
    header = rows[0]
    for k, (name, pulse) in enumerate(grounds):
        assert motions[k] == name, (motions, name)
        for g, gap in enumerate(gaps):
            c, l, _ = single(name, pulse, float(level), float(gap), f'{s}_{k}_{g}')
            if (c, l) != (contact[g, s, k], lam[g, s, k]):
                fail.append(f'stripe {s + 1} motion {name} gap {gap}: single run {(c, l)}, '
                            f'stripes {(contact[g, s, k], lam[g, s, k])}')
        _, _, peaks = single(name, pulse, float(level), deck_gap, f'{s}_{k}_deck')
        row = dict(zip(header, rows[2 + k]))
        assert row['motion'] == name
        for b, (drift, acc) in peaks.items():
            for j in range(len(drift)):
                pid = float(row[f'{b}/1-PID-{j + 1}-1'])
                if not math.isclose(pid, drift[j] / heights[b][j], rel_tol=1e-12):
                    fail.append(f'{name} stripe {s + 1} {b} PID {j + 1}: {pid} vs {drift[j] / heights[b][j]}')
                pfa = float(row[f'{b}/1-PFA-{j + 1}-1'])
                if not math.isclose(pfa, acc[j] / 9.81, rel_tol=1e-12):
                    fail.append(f'{name} stripe {s + 1} {b} PFA {j + 1}: {pfa} vs {acc[j] / 9.81}')

for o in ('contact', 'lambda_exceeded'):
    maf = h[f'/risk/maf/{o}'][()]
    p = h[f'/risk/probability/{o}'][()]
    if not np.allclose(p, 1.0 - np.exp(-maf * years), rtol=1e-12, atol=0):
        fail.append(f'{o}: P != 1 - exp(-maf years)')
    ok = [g for g in range(len(gaps)) if all(p[j] <= target for j in range(g, len(gaps)))]
    expect = gaps[ok[0]] if ok else float('nan')
    got = h[f'/risk/gap/{o}'][()]
    if not (got == expect or (math.isnan(got) and math.isnan(expect))):
        fail.append(f'{o}: risk-targeted gap {got}, expected {expect}')
    med = h[f'/risk/fragility/{o}/median'][()]
    if np.any(np.isnan(med)) and 'na' not in h[f'/risk/fragility/{o}/median'].attrs:
        fail.append(f'{o}: NaN median without an na attribute')
if not str(h['/risk'].attrs.get('answer', '')).startswith('risk-targeted gap: '):
    fail.append('/risk has no attribute answer holding the answer line')
first = stdout.splitlines()[3]
if not first.startswith('  risk-targeted gap: '):
    fail.append(f'answer not first on the terminal: {first!r}')
if not open(os.path.join(work, 'risk', stem + '_summary.csv')).read().splitlines()[1].startswith(
        'risk,run,risk_targeted_gap_contact,'):
    fail.append('summary CSV does not start with the risk rows')

# A record set: 'M1.TXT' and 'm2.txt' match '*.txt' (case-insensitive), 'x.dat' does not.
rec = os.path.join(work, 'recs')
os.makedirs(rec, exist_ok=True)
for name, w in (('m2.txt', 9.0), ('M1.TXT', 12.0), ('x.dat', 5.0)):
    with open(os.path.join(rec, name), 'w') as f:
        for i in range(301):
            t = 0.01 * i
            f.write(f'{t:.2f} {0.2 * math.exp(-t) * math.sin(w * t):.8e}\n')
lines = [l for l in text.splitlines() if not l.startswith('&ground')]
lines.insert(1, "&ground kind = 'record_set', folder = 'recs', pattern = '*.txt', format = 'columns' /")
open(os.path.join(work, 'set.nml'), 'w').write('\n'.join(lines) + '\n')
run('set.nml', 'set')
names = [m.decode() if isinstance(m, bytes) else m for m in h5py.File(os.path.join(work, 'set', 'set.h5'))['/risk/motions'][()]]
if names != ['M1', 'm2']:
    fail.append(f'record set motions {names}, expected M1, m2')

# Yielding storeys: the collapse outcomes exist, collapse due to pounding implies collapse.
lines = text.replace("&building name = 'A', n_storeys = 2,",
                     "&building name = 'A', n_storeys = 2, storey_law = 'bilinear', yield_shear = 2*10.0, "
                     "hardening_ratio = 2*0.0,").replace("&analysis ", "&analysis collapse_drift = 0.005, ").splitlines()
open(os.path.join(work, 'yield.nml'), 'w').write('\n'.join(lines) + '\n')
out = run('yield.nml', 'yield')
y = h5py.File(os.path.join(work, 'yield', 'yield.h5'), 'r')
names = sorted(y['/risk/outcomes'])
if names != ['collapse', 'collapse_due_to_pounding', 'contact', 'lambda_exceeded']:
    fail.append(f'outcomes with yielding storeys: {names}')
else:
    col, due = y['/risk/outcomes/collapse'][()], y['/risk/outcomes/collapse_due_to_pounding'][()]
    if np.any(due > col):
        fail.append('collapse_due_to_pounding without collapse')
    if not np.any(col):
        fail.append('no collapse in the yielding deck (the check would be empty)')
if 'P(collapse due to pounding)' not in out:
    fail.append('no P(collapse due to pounding) line with yielding storeys')

if fail:
    print('\n'.join(fail))
    sys.exit(1)
print('ok')
