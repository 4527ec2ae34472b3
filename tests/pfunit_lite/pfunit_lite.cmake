# pfunit_lite: a small stand-in for pFUnit's add_pfunit_ctest, used when the real pFUnit
# is not installed.  The same .pf files work with both.
#
#   add_pfunit_ctest(<name>
#                    TEST_SOURCES <file.pf>...
#                    [LINK_LIBRARIES <lib>...]
#                    [OTHER_SOURCES <src>...]
#                    [EXTRA_USE <module>] [EXTRA_INITIALIZE <sub>] [EXTRA_FINALIZE <sub>]
#                    [LABELS <label>...]
#                    [WORKING_DIRECTORY <dir>])
#
# Each .pf file is turned into a Fortran module (pfproc.py, at build time, so editing a
# .pf regenerates it) and all of them into one executable <name> with a generated driver.
# Every @test becomes its own CTest test `<name>.<test>` running `<name> <test>`; the
# executable without arguments runs all its tests, with `--list` prints their names.
# It exits non-zero if an assertion failed. pfproc.py refuses (file.pf:LINE: error: ...)
# what the real pFUnit refuses: see pfproc.py.
#
# As in the real pFUnit, the driver uses EXTRA_USE and calls EXTRA_INITIALIZE before the
# tests (in every test's own run) and EXTRA_FINALIZE after them. REGISTRY and MAX_PES of
# the real add_pfunit_ctest are accepted and ignored (with a warning).

include_guard(GLOBAL)

find_package(Python3 REQUIRED COMPONENTS Interpreter)

set(PFUNIT_LITE_DIR ${CMAKE_CURRENT_LIST_DIR} CACHE INTERNAL "pfunit_lite sources")
set(PFUNIT_LITE_PFPROC ${CMAKE_CURRENT_LIST_DIR}/pfproc.py CACHE INTERNAL "pfunit_lite preprocessor")

# The support library: module `funit` (assertions and runner), built once.
if(NOT TARGET funit)
  add_library(funit STATIC ${PFUNIT_LITE_DIR}/funit.f90)
  set_target_properties(funit PROPERTIES Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/pfunit_lite/mod)
  target_include_directories(funit PUBLIC ${CMAKE_CURRENT_BINARY_DIR}/pfunit_lite/mod)
  if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
    # Hundreds of small generic specifics: optimisation only costs compile time.
    target_compile_options(funit PRIVATE -O0)
  endif()
endif()

function(add_pfunit_ctest name)
  cmake_parse_arguments(PF_TEST ""
    "REGISTRY;MAX_PES;EXTRA_USE;EXTRA_INITIALIZE;EXTRA_FINALIZE;WORKING_DIRECTORY"
    "TEST_SOURCES;OTHER_SOURCES;LINK_LIBRARIES;LABELS" ${ARGN})
  if(PF_TEST_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "add_pfunit_ctest(${name}): unexpected arguments: ${PF_TEST_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT PF_TEST_TEST_SOURCES)
    message(FATAL_ERROR "add_pfunit_ctest(${name}): TEST_SOURCES is required")
  endif()
  foreach(opt REGISTRY MAX_PES)
    if(PF_TEST_${opt})
      message(WARNING "add_pfunit_ctest(${name}): ${opt} is ignored by pfunit_lite")
    endif()
  endforeach()

  set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/pfunit_lite/${name})
  set(pf_files)
  set(generated)
  foreach(pf IN LISTS PF_TEST_TEST_SOURCES)
    get_filename_component(pf ${pf} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    get_filename_component(stem ${pf} NAME_WE)
    list(APPEND pf_files ${pf})
    add_custom_command(
      OUTPUT ${gen_dir}/${stem}.F90
      COMMAND ${Python3_EXECUTABLE} ${PFUNIT_LITE_PFPROC} module ${pf} ${gen_dir}/${stem}.F90
      DEPENDS ${pf} ${PFUNIT_LITE_PFPROC}
      COMMENT "pfunit_lite: preprocessing ${stem}.pf"
      VERBATIM)
    list(APPEND generated ${gen_dir}/${stem}.F90)
  endforeach()
  set(extra)
  foreach(opt USE INITIALIZE FINALIZE)
    if(PF_TEST_EXTRA_${opt})
      string(TOLOWER ${opt} lower)
      list(APPEND extra --extra-${lower} ${PF_TEST_EXTRA_${opt}})
    endif()
  endforeach()
  add_custom_command(
    OUTPUT ${gen_dir}/${name}_driver.F90
    COMMAND ${Python3_EXECUTABLE} ${PFUNIT_LITE_PFPROC} driver --out ${gen_dir}/${name}_driver.F90 ${extra} ${pf_files}
    DEPENDS ${pf_files} ${PFUNIT_LITE_PFPROC}
    COMMENT "pfunit_lite: generating the driver of ${name}"
    VERBATIM)

  add_executable(${name} ${generated} ${gen_dir}/${name}_driver.F90 ${PF_TEST_OTHER_SOURCES})
  set_target_properties(${name} PROPERTIES Fortran_MODULE_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}/mod/${name})
  target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/mod/${name})
  target_link_libraries(${name} PRIVATE funit ${PF_TEST_LINK_LIBRARIES})

  # The test names are needed now, at configure time: read them with the same parser, and
  # configure again whenever a .pf file changes (so added or renamed tests are registered).
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${pf_files} ${PFUNIT_LITE_PFPROC})
  execute_process(
    COMMAND ${Python3_EXECUTABLE} ${PFUNIT_LITE_PFPROC} list ${pf_files}
    OUTPUT_VARIABLE test_names
    ERROR_VARIABLE errors
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "add_pfunit_ctest(${name}):\n${errors}")
  endif()
  string(REGEX REPLACE "\n$" "" test_names "${test_names}")
  string(REPLACE "\n" ";" test_names "${test_names}")
  if(NOT test_names)
    message(WARNING "add_pfunit_ctest(${name}): no @test in ${PF_TEST_TEST_SOURCES}")
  endif()
  foreach(test IN LISTS test_names)
    add_test(NAME ${name}.${test} COMMAND ${name} ${test})
    if(PF_TEST_WORKING_DIRECTORY)
      set_tests_properties(${name}.${test} PROPERTIES WORKING_DIRECTORY ${PF_TEST_WORKING_DIRECTORY})
    endif()
    if(PF_TEST_LABELS)
      set_tests_properties(${name}.${test} PROPERTIES LABELS "${PF_TEST_LABELS}")
    endif()
  endforeach()
endfunction()
