# The `hysteresis` plot draws the storeys' force-drift loops and residual drift profiles of the
# yielding buildings: bilinear storeys (input/seed_bilinear.nml) and frames with plastic hinges
# (input/seed_frame_hinges.nml); an elastic deck has none, and naming the plot says so.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(PLOT ${SOURCE_DIR}/scripts/plot_results.py)
foreach(deck seed_bilinear seed_frame_hinges)
  run_pound(r ${SOURCE_DIR}/input/${deck}.nml)
  expect_equal("${deck}: pound exit (${r_err})" 0 "${r_rc}")
  execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/${deck}.h5 --only hysteresis --format png
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_equal("${deck}: plot exit (${err})" 0 "${rc}")
  expect_png("${deck}: plot hysteresis (${out} ${err})" ${WORK_DIR}/${deck}_hysteresis.png)
endforeach()
run_pound(r ${SOURCE_DIR}/input/two_frames_elastic.nml)
expect_equal("elastic: pound exit (${r_err})" 0 "${r_rc}")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/two_frames_elastic.h5 --only hysteresis --format png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_contains("elastic: note" "${out}${err}" "hysteresis: skipped (no building with bilinear storeys or plastic hinges in this file)")
