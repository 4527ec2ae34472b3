# A suite (tests/data/small_suite.nml, two motions, a gap sweep): the listing's suite sections,
# /suite/separation/time_history and the per-motion histories in the HDF5 file, and
# scripts/plot drawing the four suite plots (spectra with the targets, lambda per motion with
# the mean, separation rules against the time-history gap, the sweep's mean and maximum with
# the refined thresholds) as valid PNG and PDF files.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(PLOT ${SOURCE_DIR}/scripts/plot_results.py)
run_pound(r ${SOURCE_DIR}/tests/data/small_suite.nml)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/small_suite.out listing)
expect_contains("listing" "${listing}" "Ground-motion suite (2 motions)")
expect_contains("listing" "${listing}" "Separation rules per contact pair [mm]")
expect_contains("listing" "${listing}" "EN1998 = EN 1998-1 4.4.2.7")
expect_contains("listing" "${listing}" "    no-contact    time-hist.")
expect_contains("listing" "${listing}" "Suite gap sweep")
expect_contains("listing" "${listing}" "the threshold on its own largest |lambda| (the time_history rule)")
execute_process(COMMAND ${PY} -c "
import h5py, numpy as np
f = h5py.File('${WORK_DIR}/small_suite.h5', 'r')
th = f['suite/separation/time_history'][...]
assert th.shape == (3, 2), th.shape   # h5py: (n_motions + 1, n_pairs), one row per motion
assert f['suite/spectrum/sa'].shape == (2, f['suite/spectrum/period'].shape[0])
assert f['suite/influence/A/u'].shape == (2, f['suite/mean/influence/A/u'].shape[0])
assert f['suite/sweep/max_abs_lambda'].shape == (2, f['suite/sweep/gap'].shape[0])
assert f['suite/separation/time_history'].attrs['units'] == 'm' and f['suite/influence/A/u'].attrs['units'] == '%'
ref, safe = f['suite/sweep/refined_gap_motion'][...], f['suite/sweep/safe_gap_motion'][...]
assert (th[:2, :] == np.where(ref >= 0, ref, safe)[:, None]).all(), th
assert (th[2, :] == f['suite/sweep/refined_gap_mean'][()]).all() and (th > 0).all()
assert 'p' in f['suite'] and 's1' not in f['suite']
assert f['suite/p/uncoupled/A/u'].shape == f['uncoupled/A/u'].shape
assert (f['suite/p/coupled/B/u'][...] == f['coupled/B/u'][...]).all()
sw = f['sweep']
assert (sw['suite_mean'][...] == f['suite/sweep/mean'][...]).all()
assert (sw['suite_max'][...] == f['suite/sweep/max'][...]).all()
assert (sw['suite_max'][...] >= sw['suite_mean'][...]).all()
assert sw.attrs['suite_refined_gap_mean'] == f['suite/sweep/refined_gap_mean'][()]
assert sw.attrs['suite_safe_gap_every'] == f['suite/sweep/safe_gap_every'][()]
m = sw.attrs['motion']; m = m.decode() if isinstance(m, bytes) else m
assert m == f['suite/names'][0].decode().strip(), m
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("HDF5 checks (${err})" 0 "${rc}")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/small_suite.h5 --only suite RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
foreach(p spectra lambda separation sweep)
  set(png ${WORK_DIR}/small_suite_suite_${p}.png)
  set(pdf ${WORK_DIR}/small_suite_suite_${p}.pdf)
  if(NOT EXISTS ${png} OR NOT EXISTS ${pdf})
    message(FATAL_ERROR "suite plot ${p}: missing PNG or PDF\n${out}\n${err}")
  endif()
  file(READ ${png} sig LIMIT 8 HEX)
  expect_equal("PNG signature of ${p}" "89504e470d0a1a0a" "${sig}")
  file(SIZE ${png} n)
  if(n LESS 5000)
    message(FATAL_ERROR "suite plot ${p}: PNG of only ${n} bytes")
  endif()
  file(READ ${pdf} head LIMIT 5 HEX)
  expect_equal("PDF header of ${p} (%PDF-)" "255044462d" "${head}")
endforeach()
