# Two runs writing the same stem into one folder (two decks named run.nml from different
# folders, as parameter studies do), 20 rounds at the same time: each run succeeds or fails
# with one message, no temporary is left, and the published pair comes from one run (the
# listing's title and deck are those in the HDF5 file, the other run's title is not there).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
execute_process(COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/files_concurrent.sh ${POUND_EXE} ${SOURCE_DIR} ${WORK_DIR}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "concurrent runs: ${err}${out}")
endif()
message("${out}")
