# Suite first (issue 27): input/suite_records.nml (four real records of shared/records) run as a
# user runs it; the first gap on the terminal and the first gap at the top of the listing are
# the suite's refined sweep threshold on the mean (/suite/sweep/refined_gap_mean of the HDF5
# file), labelled as the suite's; the first motion's own gap comes later, labelled with its
# motion; the listing's single-motion sections sit under 'motion 1 of 4: ielc180'; the root
# attributes and <stem>_summary.csv lead with the same answer. Without shared/records the test
# prints SKIPPED: and is reported skipped (tests/CMakeLists.txt).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(records "$ENV{POUND_SHARED_DIR}/records")
if(NOT EXISTS "${records}/IELC180.AT2")
  message("SKIPPED: no records in ${records}")
  return()
endif()
# The shipped deck, its record paths pointed at the tests' records folder.
file(READ ${SOURCE_DIR}/input/suite_records.nml deck)
string(REPLACE "'../../shared/records/" "'${records}/" deck "${deck}")
file(WRITE ${WORK_DIR}/suite_records.nml "${deck}")
run_shell(r "\"$POUND\" suite_records.nml -o out --quiet > terminal.txt")
expect_equal("exit status (${r_err})" 0 "${r_rc}")
expect_published(out suite_records)
if(NOT EXISTS ${WORK_DIR}/out/suite_records_summary.csv)
  message(FATAL_ERROR "missing out/suite_records_summary.csv")
endif()
execute_process(COMMAND /usr/bin/python3 -c "
import re, csv, h5py
def first_gap(lines, what):
    for i, line in enumerate(lines):
        m = re.search(r'(-?[0-9]+[.][0-9]+) mm', line)
        if m:
            assert 'suite gap' in line and 'on the mean' in line, (what, line)
            return i, float(m.group(1))
    raise AssertionError(what + ': no gap in mm')
f = h5py.File('${WORK_DIR}/out/suite_records.h5', 'r')
mean = 1e3 * float(f['suite/sweep/refined_gap_mean'][()])
every = 1e3 * float(f['suite/sweep/refined_gap_every'][()])
assert mean > 0 and every >= mean, (mean, every)
term = open('${WORK_DIR}/terminal.txt').read().splitlines()
i, gap = first_gap(term, 'terminal')
assert abs(gap - mean) <= 0.5e-4, (gap, mean)
own = [l for l in term if 'smallest gap meeting the target' in l]
assert len(own) == 1 and own[0].strip().startswith('motion 1 of 4: ielc180,'), own
assert term.index(own[0]) > i
listing = open('${WORK_DIR}/out/suite_records.out').read().splitlines()
top = listing.index('Summary')
assert top < 12 and listing.index('Deck echo') > top, top
j, gap = first_gap(listing, 'listing')
assert top < j < listing.index('Deck echo'), (top, j)
assert abs(gap - mean) <= 0.5e-4, (gap, mean)
assert 'every motion' in listing[j + 1] and abs(float(re.search(r'([0-9]+[.][0-9]+) mm', listing[j + 1]).group(1)) - every) <= 0.5e-4
head = [k for k, l in enumerate(listing) if l.startswith('motion 1 of 4: ielc180: the single-motion results')]
assert len(head) == 1 and head[0] < listing.index('Uncoupled response: absolute maxima and the time they occur'), head
assert head[0] < listing.index('Ground-motion suite (4 motions)')
assert f.attrs['suite_refined_gap_mean'] == f['suite/sweep/refined_gap_mean'][()]
assert f.attrs['single_motion_heading'] == 'motion 1 of 4: ielc180', f.attrs['single_motion_heading']
rows = list(csv.DictReader(open('${WORK_DIR}/out/suite_records_summary.csv')))
assert (rows[0]['kind'], rows[0]['quantity'], rows[0]['unit']) == ('suite', 'refined_gap_mean', 'mm'), rows[0]
assert abs(float(rows[0]['value']) - mean) <= 1e-12 * mean, (rows[0], mean)
print('suite first: %.4f mm on the mean, %.4f mm on every motion' % (mean, every))
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("suite-first checks (${err})" 0 "${rc}")
message("${out}")
