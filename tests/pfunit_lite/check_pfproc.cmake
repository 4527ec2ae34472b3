# Checks that pfunit_lite refuses what the real pFUnit refuses, and accepts what it accepts.
#
#   cmake -DPYTHON=<python3> -DPFPROC=<pfproc.py> -DDATA_DIR=<dir of .pf files> -DWORK_DIR=<dir>
#         [-DFUNITPROC=<python>|<funitproc> -DFORTRAN=<gfortran> -DPFUNIT_INCLUDE=<dir>] -P check_pfproc.cmake
#
# Every DATA_DIR/*.pf starts with a line `! pfproc: ok` (pfproc.py must accept it) or
# `! pfproc: <regular expression>` (pfproc.py must fail with a message matching it, e.g.
# `bad_x\.pf:10: error: ...`). With FUNITPROC (the real pFUnit is installed), each file also
# goes through the real funitproc and the Fortran compiler (-fsyntax-only): the file must
# compile exactly when pfproc.py accepts it, so that the two runners cannot drift apart.
cmake_minimum_required(VERSION 3.25)

foreach(var PYTHON PFPROC DATA_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_pfproc.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
file(GLOB cases ${DATA_DIR}/*.pf)
if(NOT cases)
  message(FATAL_ERROR "check_pfproc.cmake: no .pf file in ${DATA_DIR}")
endif()

set(problems "")
set(compiled)
set(n 0)
foreach(pf IN LISTS cases)
  math(EXPR n "${n} + 1")
  get_filename_component(stem ${pf} NAME_WE)
  file(STRINGS ${pf} first LIMIT_COUNT 1)
  if(NOT first MATCHES "^! pfproc: (.+)$")
    string(APPEND problems "${stem}.pf: first line must be '! pfproc: ok' or '! pfproc: <regex>'\n")
    continue()
  endif()
  set(expect "${CMAKE_MATCH_1}")

  execute_process(COMMAND ${PYTHON} ${PFPROC} module ${pf} ${WORK_DIR}/lite_${stem}.F90
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(lite_ok FALSE)
  if(status EQUAL 0)
    set(lite_ok TRUE)
  endif()
  if(expect STREQUAL "ok")
    if(NOT status EQUAL 0)
      string(APPEND problems "${stem}.pf: pfproc.py refused a valid file:\n${err}")
    else()
      file(STRINGS ${WORK_DIR}/lite_${stem}.F90 generated)
      foreach(line IN LISTS generated)
        string(LENGTH "${line}" len)
        if(len GREATER 132 AND NOT line MATCHES "^#line ")
          string(APPEND problems "${stem}.pf: pfproc.py wrote a line of ${len} columns\n")
        endif()
      endforeach()
    endif()
  else()
    if(status EQUAL 0)
      string(APPEND problems "${stem}.pf: pfproc.py accepted it, expected: ${expect}\n")
    elseif(NOT err MATCHES "${expect}")
      string(APPEND problems "${stem}.pf: expected a message matching '${expect}', got:\n${err}")
    else()
      message(STATUS "${stem}.pf refused: ${err}")
    endif()
  endif()

  set(lite_ok_${stem} ${lite_ok})

  if(DEFINED FUNITPROC)
    # The real pFUnit's preprocessor; what it writes is compiled below.
    string(REPLACE "|" ";" funitproc "${FUNITPROC}")  # '|'-separated command
    execute_process(COMMAND ${funitproc} -quiet ${pf} ${WORK_DIR}/real_${stem}.F90
                    RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
    if(status EQUAL 0)
      list(APPEND compiled ${stem})
    endif()
  endif()
endforeach()

if(DEFINED FUNITPROC)
  # The compiler on everything funitproc wrote, all at once (one pipeline of independent
  # processes: loading pFUnit's modules takes seconds per file).
  set(commands)
  foreach(stem IN LISTS compiled)
    file(MAKE_DIRECTORY ${WORK_DIR}/mod_${stem})
    list(APPEND commands COMMAND ${FORTRAN} -fsyntax-only -J ${WORK_DIR}/mod_${stem} -I${PFUNIT_INCLUDE}
                         ${WORK_DIR}/real_${stem}.F90)
  endforeach()
  set(results)
  if(commands)
    execute_process(${commands} RESULTS_VARIABLE results OUTPUT_QUIET ERROR_QUIET)
  endif()
  foreach(pf IN LISTS cases)
    get_filename_component(stem ${pf} NAME_WE)
    if(NOT DEFINED lite_ok_${stem})
      continue()
    endif()
    set(real_ok FALSE)
    list(FIND compiled ${stem} k)
    if(k GREATER_EQUAL 0)
      list(GET results ${k} status)
      if(status EQUAL 0)
        set(real_ok TRUE)
      endif()
    endif()
    if(NOT real_ok STREQUAL lite_ok_${stem})
      if(real_ok)
        string(APPEND problems "${stem}.pf: the real pFUnit accepts it, pfunit_lite refuses it\n")
      else()
        string(APPEND problems "${stem}.pf: the real pFUnit refuses it, pfunit_lite accepts it\n")
      endif()
    endif()
  endforeach()
endif()

if(problems)
  message(FATAL_ERROR "pfunit_lite refusals:\n${problems}")
endif()
if(DEFINED FUNITPROC)
  message(STATUS "${n} files: pfunit_lite and the real pFUnit agree on every one")
else()
  message(STATUS "${n} files: pfunit_lite refuses and accepts as expected")
endif()
