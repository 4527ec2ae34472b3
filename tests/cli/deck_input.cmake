# Decks that are not plain regular files: read from a pipe (`pound /dev/stdin < deck`,
# `pound <(sed ...)`) until their end; a deck of 50 000 lines plus one 100 000-character
# line read in memory proportional to its size (under a 300 MB address-space limit; the
# old reader asked for lines x longest line = 5 GB).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(deck "&analysis dt = 0.01, t_end = 0.5 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.0 /
&building name = 'A', n_storeys = 2, height = 2*3.0, mass = 2*10.0, stiffness = 2*1.0e4 /
")
file(WRITE ${WORK_DIR}/d.nml "${deck}")

execute_process(COMMAND sh -c "exec \"$0\" /dev/stdin < d.nml" ${POUND_EXE}
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("exit status, deck on stdin (${err})" 0 "${rc}")
expect_contains("summary, deck on stdin" "${out}" "building A: 2 storeys")
if(NOT EXISTS ${WORK_DIR}/stdin.out OR NOT EXISTS ${WORK_DIR}/stdin.h5)
  message(FATAL_ERROR "deck on stdin: stdin.out and stdin.h5 not written")
endif()

# A broken deck through a pipe: the message names the line.
execute_process(COMMAND sh -c "sed 's/n_storeys = 2/n_storeys = 2.5/' d.nml | \"$0\" /dev/stdin" ${POUND_EXE}
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("exit status, broken deck through a pipe" 1 "${rc}")
expect_contains("message" "${err}" "/dev/stdin:3: &building #1 (A): n_storeys = 2.5: expected an integer")

find_program(BASH bash)
if(BASH)
  execute_process(COMMAND ${BASH} -c "exec \"$0\" <(sed 's/t_end = 0.5/t_end = 0.25/' d.nml)" ${POUND_EXE}
                  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_equal("exit status, deck from a process substitution (${err})" 0 "${rc}")
  expect_contains("summary, process substitution" "${out}" "building A: 2 storeys")
endif()

string(REPEAT "! a comment line\n" 50000 comments)
string(REPEAT "x" 100000 long)
file(WRITE ${WORK_DIR}/big.nml "${deck}${comments}! ${long}\n")
execute_process(COMMAND sh -c "ulimit -v 300000 && exec \"$0\" big.nml" ${POUND_EXE}
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("exit status, 50 000-line deck under a 300 MB limit (${err})" 0 "${rc}")
