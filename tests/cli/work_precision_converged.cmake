# scripts/work_precision --converged on frame_to_column.nml (1 s): the Richardson reference with
# its uncertainty, one row per setting and time step with both time ratios and the lambda
# errors, the accurate setting (impact + exact) at 1 ms closer to the reference than the plain
# run, the table file, no temporary deck left.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/frame_to_column.nml deck)
string(REPLACE "t_end = 5.0" "t_end = 1.0" deck "${deck}")
file(WRITE ${WORK_DIR}/ftc.nml "${deck}")
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/work_precision.py --exe ${POUND_EXE}
                        ${WORK_DIR}/ftc.nml --converged --dts 2e-3,1e-3 --ref-dt 2.5e-4 --repeats 1
                        --stepping uniform,impact,impact-exact --outdir ${WORK_DIR}/wp
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("work_precision --converged exit (${err})" 0 "${rc}")
expect_contains("reference" "${out}" "Richardson extrapolation of uniform runs at h = 0.00025")
expect_contains("uncertainty" "${out}" "its uncertainty")
# | setting | dt | steps | ms | x plain | x plain (fastest) | shear err | every err | a_abs err |
set(num "[0-9.]+")
foreach(setting uniform impact impact-exact)
  foreach(dt 0.002 0.001)
    if(NOT out MATCHES "\\| ${setting} \\| ${dt} \\| [0-9]+ \\| ${num} \\| ${num} \\| ${num} \\| ${num} \\| ${num} \\| ${num} \\|")
      message(FATAL_ERROR "no row for ${setting} at ${dt}:\n${out}")
    endif()
  endforeach()
endforeach()
string(REGEX MATCH "\\| uniform \\| 0.001 \\| [0-9]+ \\| ${num} \\| 1.00 \\| ${num} \\| (${num}) \\|" row "${out}")
set(plain_err "${CMAKE_MATCH_1}")
string(REGEX MATCH "\\| impact-exact \\| 0.001 \\| [0-9]+ \\| ${num} \\| ${num} \\| ${num} \\| (${num}) \\|" row "${out}")
set(exact_err "${CMAKE_MATCH_1}")
if(NOT plain_err OR NOT exact_err OR NOT exact_err LESS plain_err)
  message(FATAL_ERROR "impact + exact (${exact_err} pp) not closer than plain (${plain_err} pp):\n${out}")
endif()
if(NOT EXISTS ${WORK_DIR}/wp/ftc_converged.md)
  message(FATAL_ERROR "missing wp/ftc_converged.md")
endif()
file(GLOB left ${WORK_DIR}/.work_precision_*)
if(left)
  message(FATAL_ERROR "temporary decks left behind: ${left}")
endif()
