# Install the build tree into a scratch prefix, then configure, build and run a consumer
# project that finds it with find_package(pound). Variables: BUILD_DIR, SOURCE_DIR, WORK_DIR.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed (${rc})")
endif()
foreach(f bin/pound lib/libpoundlib.a include/pound/pound_band.mod lib/cmake/pound/poundConfig.cmake)
  if(NOT EXISTS ${WORK_DIR}/prefix/${f})
    message(FATAL_ERROR "install tree lacks ${f}")
  endif()
endforeach()
file(GLOB strays ${WORK_DIR}/prefix/include/pound/pound_test*.mod ${WORK_DIR}/prefix/include/pound/funit*.mod)
if(strays)
  message(FATAL_ERROR "test modules installed: ${strays}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/package -B ${WORK_DIR}/build
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the consumer failed:\n${out}${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "building the consumer failed:\n${out}${err}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/pound_consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "band_symv:  1.0  0.0  1.0")
  message(FATAL_ERROR "consumer: exit ${rc}, output '${out}'")
endif()
message(STATUS "find_package(pound) consumer: ${out}")
