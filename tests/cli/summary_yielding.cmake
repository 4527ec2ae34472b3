# The summary of yielding buildings (terminal, listing, <stem>_summary.csv): for bilinear
# storeys the largest storey-drift lambda first, the ductility coupled against uncoupled of the
# same storey with its lambda (every storey's on the line), the storeys that yield only with
# pounding, and the storey-shear line after them; for frame hinges the hinges that form only
# with pounding and the largest plastic-rotation lambda (column and beam hinges); collapse
# counts per analysis, and a suite's totals over its motions and per motion. Every number is
# checked against the results file it comes from (tests/cli/summary_yielding.py). An elastic
# deck's collapse line says the buildings of the deck are elastic.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(CHECK ${CMAKE_CURRENT_LIST_DIR}/summary_yielding.py)

# Bilinear storeys.
run_pound(b ${SOURCE_DIR}/input/seed_bilinear.nml)
expect_equal("pound exit, bilinear (${b_err})" 0 "${b_rc}")
expect_contains("drift lambda on the terminal" "${b_out}" "  B: largest storey-drift lambda:")
expect_contains("ductility of the same storey" "${b_out}"
                "B: storey ductility lambda, largest |lambda|:            112.68 %  (storey 8: mu uncoupled 0.82, coupled 1.75;")
expect_contains("new yielding" "${b_out}" "  B: storeys that yield only with pounding:                2  (storeys 7, 8 (")
expect_contains("collapses per analysis" "${b_out}" "  collapses, coupled:                                      0  (buildings)")
string(FIND "${b_out}" "B: storeys that yield only with pounding" p_new)
string(FIND "${b_out}" "B: largest storey-shear lambda" p_shear)
if(p_shear LESS p_new)
  message(FATAL_ERROR "the storey-shear line comes before the yielding lines:\n${b_out}")
endif()
file(READ ${WORK_DIR}/seed_bilinear.out listing)
expect_contains("summary at the top of the listing" "${listing}" "  B: storeys that yield only with pounding:")
execute_process(COMMAND ${PY} ${CHECK} storeys ${WORK_DIR}/seed_bilinear_summary.csv ${WORK_DIR}/seed_bilinear.h5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("bilinear summary against the results (${out}${err})" 0 "${rc}")

# Frame hinges: two hinges of B form only with pounding (lambda inf).
run_pound(h ${SOURCE_DIR}/input/seed_frame_hinges.nml)
expect_equal("pound exit, hinges (${h_err})" 0 "${h_rc}")
expect_contains("new hinges" "${h_out}" "  B: hinges that form only with pounding:                  2  (hinge 24 (column, storey 4, line 1, top)")
expect_contains("plastic-rotation lambda" "${h_out}" "  B: largest plastic-rotation lambda:")
execute_process(COMMAND ${PY} ${CHECK} hinges ${WORK_DIR}/seed_frame_hinges_summary.csv ${WORK_DIR}/seed_frame_hinges.h5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("hinge summary against the results (${out}${err})" 0 "${rc}")

# A bilinear suite of three pulses whose stronger two collapse storeys.
run_pound(s ${SOURCE_DIR}/tests/data/summary_yield_suite.nml)
expect_equal("pound exit, suite (${s_err})" 0 "${s_rc}")
expect_contains("suite collapse total" "${s_out}" "  collapses, suite total over 3 motions:                   7  (")
expect_contains("suite collapses per motion" "${s_out}" "  collapses, motion p30:                                   3  (uncoupled 1, coupled 2)")
expect_contains("motion 1's collapses labelled" "${s_out}" "  collapses (motion 1 of 3: p10):")
expect_contains("suite ductility" "${s_out}" "  B: lambda of the mean storey ductility mu:")
file(READ ${WORK_DIR}/summary_yield_suite_summary.csv csv)
expect_contains("CSV: suite total" "${csv}" "suite,suite,collapses,7,-,")
expect_contains("CSV: motion 1's count says its motion" "${csv}" "collapse,run,collapse,0,-,motion 1 of 3: p10 only: ")
execute_process(COMMAND ${PY} ${CHECK} suite ${WORK_DIR}/summary_yield_suite_summary.csv ${WORK_DIR}/summary_yield_suite.h5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("suite summary against the results (${out}${err})" 0 "${rc}")

# An elastic deck: no collapse can happen, and the line says why.
run_pound(e ${SOURCE_DIR}/tests/data/small_pounding.nml)
expect_equal("pound exit, elastic (${e_err})" 0 "${e_rc}")
file(READ ${WORK_DIR}/small_pounding.out listing)
expect_contains("elastic deck" "${listing}" "not modelled: the buildings of this deck are elastic and cannot collapse")
