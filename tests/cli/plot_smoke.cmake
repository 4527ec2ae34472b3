# scripts/plot on a small results file: every plot as a valid PNG and PDF; a missing or
# malformed HDF5 file gives one clear error line and exit 1, never a traceback.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(PLOT ${SOURCE_DIR}/scripts/plot_results.py)
run_pound(r ${SOURCE_DIR}/tests/data/small_pounding.nml)
expect_equal("pound exit" 0 "${r_rc}")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/small_pounding.h5 RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
foreach(p displacement force loops shear influence ground sweep)
  set(png ${WORK_DIR}/small_pounding_${p}.png)
  set(pdf ${WORK_DIR}/small_pounding_${p}.pdf)
  if(NOT EXISTS ${png} OR NOT EXISTS ${pdf})
    message(FATAL_ERROR "plot ${p}: missing PNG or PDF\n${out}\n${err}")
  endif()
  expect_png("plot ${p}" ${png})
  file(READ ${pdf} head LIMIT 5 HEX)
  expect_equal("PDF header of ${p} (%PDF-)" "255044462d" "${head}")
  file(SIZE ${pdf} n)
  math(EXPR off "${n} - 8")
  file(READ ${pdf} tail OFFSET ${off} HEX)
  expect_contains("PDF end of ${p} (%%EOF)" "${tail}" "2525454f46")
endforeach()
file(GLOB partial ${WORK_DIR}/.*.partial)
if(partial)
  message(FATAL_ERROR "partial plot files left: ${partial}")
endif()

# Missing file.
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/no_such.h5 RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("missing file exit" 1 "${rc}")
expect_contains("missing file" "${err}" "plot: error:")
expect_contains("missing file" "${err}" "no_such.h5")
string(FIND "${err}" "Traceback" tb)
expect_equal("no traceback (missing)" -1 "${tb}")
# Not an HDF5 file.
file(WRITE ${WORK_DIR}/garbage.h5 "this is not HDF5\n")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/garbage.h5 RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("garbage file exit" 1 "${rc}")
expect_contains("garbage file" "${err}" "plot: error:")
string(FIND "${err}" "Traceback" tb)
expect_equal("no traceback (garbage)" -1 "${tb}")
# An HDF5 file that is not a pound results file (the deck echo alone).
execute_process(COMMAND ${PY} -c "import h5py; h5py.File('${WORK_DIR}/other.h5', 'w').attrs['x'] = 1")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/other.h5 RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("foreign HDF5 exit" 1 "${rc}")
expect_contains("foreign HDF5" "${err}" "plot: error:")
string(FIND "${err}" "Traceback" tb)
expect_equal("no traceback (foreign)" -1 "${tb}")
