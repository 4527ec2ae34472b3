# The risk plots (scripts/plot_risk.py) on a synthetic /risk group (plot_risk_fixture.py: the
# layout the multiple-stripe analysis writes) added to a real results file
# (tests/data/small_pounding.nml): standalone, and through scripts/plot_results.py (--only risk),
# each writing <stem>_risk_fragility and <stem>_risk_probability as valid PNG and PDF files;
# a file without /risk: plot_results notes the skip, plot_risk.py refuses it (exit 1, one line).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
run_pound(r ${SOURCE_DIR}/tests/data/small_pounding.nml --quiet)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
execute_process(COMMAND ${PY} ${SOURCE_DIR}/scripts/plot_results.py ${WORK_DIR}/small_pounding.h5 --only risk
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot_results without /risk (${err})" 0 "${rc}")
expect_contains("plot_results without /risk" "${out}" "risk: skipped (no /risk in this file")
execute_process(COMMAND ${PY} ${SOURCE_DIR}/scripts/plot_risk.py ${WORK_DIR}/small_pounding.h5
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot_risk without /risk" 1 "${rc}")
expect_contains("plot_risk without /risk" "${err}" "plot_risk: error:")
file(COPY_FILE ${WORK_DIR}/small_pounding.h5 ${WORK_DIR}/risk.h5)
execute_process(COMMAND ${PY} ${CMAKE_CURRENT_LIST_DIR}/plot_risk_fixture.py ${WORK_DIR}/risk.h5
                RESULT_VARIABLE rc ERROR_VARIABLE err)
expect_equal("fixture (${err})" 0 "${rc}")
file(MAKE_DIRECTORY ${WORK_DIR}/alone)
execute_process(COMMAND ${PY} ${SOURCE_DIR}/scripts/plot_risk.py ${WORK_DIR}/risk.h5 --outdir ${WORK_DIR}/alone
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot_risk exit (${err})" 0 "${rc}")
execute_process(COMMAND ${PY} ${SOURCE_DIR}/scripts/plot_results.py ${WORK_DIR}/risk.h5 --only risk
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot_results --only risk (${err})" 0 "${rc}")
foreach(dir alone .)
  foreach(p fragility probability)
    expect_png("risk plot ${p} (${dir})" ${WORK_DIR}/${dir}/risk_risk_${p}.png)
    set(pdf ${WORK_DIR}/${dir}/risk_risk_${p}.pdf)
    if(NOT EXISTS ${pdf})
      message(FATAL_ERROR "risk plot ${p} (${dir}): missing PDF\n${out}\n${err}")
    endif()
    file(READ ${pdf} head LIMIT 5 HEX)
    expect_equal("PDF header of ${p} (%PDF-)" "255044462d" "${head}")
  endforeach()
endforeach()
