# A suite with a failing motion (tests/data/suite_failed.nml; POUND_TEST_OVERFLOW=big makes the
# pulse 'big' overflow, see src/main/pound.f90): the other motions go on, the listing and the
# HDF5 file are written, the failure is named in the listing, the summary and on stderr, and
# the exit status is 3. The same deck without the hook runs cleanly (status 0).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(COPY ${SOURCE_DIR}/tests/data/suite_failed.nml DESTINATION ${WORK_DIR})
run_shell(r "POUND_TEST_OVERFLOW=big \"$POUND\" suite_failed.nml -o failed --quiet")
expect_equal("exit status (${r_err})" 3 "${r_rc}")
expect_published(failed suite_failed)
expect_contains("stderr" "${r_err}" "pound: error: 1 case of the suite failed (1 of 3 motions left out")
# Singular for one ("1 failed case", "1 motion left out"), as the counts are worded everywhere.
expect_contains("stdout" "${r_out}" "suite: 3 motions, statistics over 2, 1 failed case (FAILED in the listing)")
expect_contains("stdout" "${r_out}" "(1 motion left out; named in the listing and /suite/failed)")
expect_contains("stdout" "${r_out}" "wrote failed/suite_failed.out and failed/suite_failed.h5")
file(READ ${WORK_DIR}/failed/suite_failed.out listing)
expect_contains("listing" "${listing}" "Failed cases of the suite (1)")
expect_contains("listing" "${listing}" "  big                     -  5.0000E-03         1  ")
expect_contains("listing" "${listing}" "(2 of 3 motions used, 1 FAILED and left out)")
# One line on stderr: the status-3 message, no crash report nor a Debug build's runtime warning.
string(REGEX MATCHALL "\n" lines "${r_err}")
list(LENGTH lines n)
expect_equal("lines on stderr (${r_err})" 1 "${n}")

run_pound(c suite_failed.nml -o clean --quiet)
expect_equal("exit status without the hook (${c_err})" 0 "${c_rc}")
file(READ ${WORK_DIR}/clean/suite_failed.out listing)
string(FIND "${listing}" "FAILED" pos)
expect_equal("FAILED in the listing without the hook" -1 "${pos}")

# The file names the failure, and scripts/plot draws the suite plots of it (the failed motion
# left out, named FAILED).
execute_process(COMMAND /usr/bin/python3 -c "
import h5py
f = h5py.File('${WORK_DIR}/failed/suite_failed.h5', 'r')
d = f['suite/failed']
assert [m.decode().strip() for m in d['motion'][...]] == ['big'], d['motion'][...]
assert list(d['gap'][...]) == [-1.0] and list(d['step'][...]) == [1], (d['gap'][...], d['step'][...])
assert d.attrs['n_motions_used'] == 2 and d.attrs['n_motions'] == 3
assert list(f['suite/motion_failed'][...]) == [0, 1, 0]
assert not f['suite/sweep/gap_failed'][...].any()
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("HDF5 checks (${err})" 0 "${rc}")
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/plot_results.py ${WORK_DIR}/failed/suite_failed.h5
                        --only suite --format png RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
foreach(p spectra lambda separation sweep)
  expect_png("suite plot ${p}" ${WORK_DIR}/failed/suite_failed_suite_${p}.png)
endforeach()
