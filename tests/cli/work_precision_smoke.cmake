# scripts/work_precision on the small deck with a short ladder: tables for both analyses and
# the plot files; exit 0 also says the reference converged (its check error is below half the
# error of the finest run of the ladder, for peak shears and displacement histories).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(COPY ${SOURCE_DIR}/tests/data/small_pounding.nml DESTINATION ${WORK_DIR})
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/work_precision.py --exe ${POUND_EXE}
                        ${WORK_DIR}/small_pounding.nml --dts 4e-3,2e-3,1e-3 --ref-factor 4 --repeats 1
                        --outdir ${WORK_DIR}/wp
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("work_precision exit (${err})" 0 "${rc}")
expect_contains("table" "${out}" "**uncoupled** — reference check")
expect_contains("table" "${out}" "**coupled** — reference check")
expect_contains("table" "${out}" "| 0.001 |")
foreach(f wp/small_pounding_wp.md wp/small_pounding_wp.png wp/small_pounding_wp.pdf)
  if(NOT EXISTS ${WORK_DIR}/${f})
    message(FATAL_ERROR "missing ${f}")
  endif()
endforeach()
file(GLOB left ${WORK_DIR}/.work_precision_*)
if(left)
  message(FATAL_ERROR "temporary decks left behind: ${left}")
endif()
