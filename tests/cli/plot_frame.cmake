# input/frame_to_column.nml runs from a fresh clone and scripts/plot draws its frame geometry
# with the six contact points (floors facing columns between floors); the listing names the
# column ends by elevation.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(PLOT ${SOURCE_DIR}/scripts/plot_results.py)
run_pound(r ${SOURCE_DIR}/input/frame_to_column.nml)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/frame_to_column.out listing)
expect_contains("listing pair label" "${listing}" "A:3-B:z10.5m")
expect_contains("listing pair label" "${listing}" "A:z3m-B:1")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/frame_to_column.h5 --only frame --format png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
expect_png("plot frame (${out} ${err})" ${WORK_DIR}/frame_to_column_frame.png)
