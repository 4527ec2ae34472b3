"""Check that every HDF5 path docs/manual.md documents exists in the files pound writes.

usage: /usr/bin/python3 scripts/check_manual_h5_paths.py [FILE.h5 ...]
Without files, runs build/release/pound on every input/*.nml (into a temporary folder) and
checks their results. Prints each documented path and a file that has it; exit status 1 when a
documented path is in none of the files (paths written only when a case fails, such as
/sweep/failed, need a file of such a run)."""
import glob, os, re, subprocess, sys, tempfile
import h5py
root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
manual, files = os.path.join(root, 'docs', 'manual.md'), sys.argv[1:]
if not files:
    out = tempfile.mkdtemp(prefix='pound_paths_')
    for deck in sorted(glob.glob(os.path.join(root, 'input', '*.nml'))):
        subprocess.run([os.path.join(root, 'build', 'release', 'pound'), deck, '-o', out, '--quiet'],
                       stdout=subprocess.DEVNULL, check=False)
    files = sorted(glob.glob(os.path.join(out, '*.h5')))
text = open(manual).read()
tops = r'(?:model|uncoupled|coupled|influence|sweep|suite|ground|<analysis>)'
word = r'[A-Za-z_<>][A-Za-z0-9_<>/]*'
paths = set()
# a path, then optional ", sibling" items (bare words, possibly with a slash, in backticks or not,
# each optionally followed by a parenthesis)
pat_prose = re.compile(r'(?<![\w.])(/' + tops + r'(?:/' + word + r')*)`?((?:\s*(?:\([^)]*\))?\s*,\s*`(?!/)' + word + r'`)*)')
pat_code = re.compile(r'(?<![\w.])(/' + tops + r'(?:/' + word + r')*)((?:\s*(?:\([^)]*\))?\s*,\s*(?!/)' + word + r'(?=[\s,(]|$))*)')
for line in text.splitlines():
    code = line.startswith('    ')
    for m in (pat_code if code else pat_prose).finditer(line):
        base = m.group(1).rstrip('/')
        if base.endswith('...'):
            continue
        paths.add(base)
        for sib in re.findall(r',\s*`?(' + word + r')', m.group(2)):
            k = sib.count('/') + 1
            parts = base.split('/')
            paths.add('/'.join(parts[:-k] + sib.split('/')))
subst = {'<b>': None, '<q>': ['u', 'v', 'a_abs', 'drift', 'storey_shear'],
         '<c>': ['shear', 'moment_bottom', 'moment_top', 'axial'],
         '<rule>': ['abs', 'srss', 'ec8', 'ddc', 'no_contact', 'time_history'],
         '<analysis>': ['uncoupled', 'coupled'], '<pair>': None, '<motion>': None, '<name>': None}
handles = [h5py.File(f, 'r') for f in files]
def exists(h, parts, i=0, node=None):
    node = h if node is None else node
    if i == len(parts):
        return True
    p = parts[i]
    if p in subst:
        names = subst[p] if subst[p] is not None else (list(node.keys()) if isinstance(node, h5py.Group) else [])
        return any(n in node and exists(h, parts, i + 1, node[n]) for n in names) if isinstance(node, h5py.Group) else False
    m = re.fullmatch(r'(<\w+>)(_\w+)', p)
    if m:  # e.g. <c>_time
        names = subst.get(m.group(1)) or []
        return any((n + m.group(2)) in node and exists(h, parts, i + 1, node[n + m.group(2)]) for n in names)
    return isinstance(node, h5py.Group) and p in node and exists(h, parts, i + 1, node[p])
# artefacts of the prose parser (not paths): '(3, n_segments)', 'rule = abs ...', '.../whose'
noise = {'/model/<b>/n_segments', '/suite/separation/rule', '/whose'}
paths -= noise
bad = 0
for p in sorted(paths):
    parts = [x for x in p.split('/') if x]
    where = [f.split('/')[-1] for f, h in zip(files, handles) if exists(h, parts)]
    print(('ok      ' if where else 'MISSING ') + p + ('  [' + where[0] + (' +%d' % (len(where) - 1) if len(where) > 1 else '') + ']' if where else ''))
    bad += not where
print(f'{len(paths)} documented paths, {bad} not found in any file')
sys.exit(1 if bad else 0)
