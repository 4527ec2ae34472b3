# A deck whose histories do not fit (dt = 1e-6, t_end = 200: about 47 GB; the floor histories
# are streamed to the file, time, energy, contact histories and the ground motion are held) is
# refused before anything is allocated or written: status 1, the estimate and the variables to
# change.
# The address-space limit (ulimit -v, 8 GB) makes the outcome independent of the machine.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/two_frames_pdelta.nml text)
string(REPLACE "dt = 1.0e-3 " "dt = 1.0e-6 " text "${text}")
string(REPLACE "t_end = 5.0 " "t_end = 200.0 " text "${text}")
file(WRITE ${WORK_DIR}/long.nml "${text}")
run_shell(m "ulimit -v 8000000; exec \"$POUND\" long.nml -o out")
expect_clean_failure("memory" m "pound: error: long.nml: &analysis: the run needs about 47.35 GB of memory" out)
foreach(s "histories 22.48 GB for 200000001 output times x 2 analyses, floor histories streamed to the file in blocks"
          "the address-space limit (RLIMIT_AS, ulimit -v)"
          "raise output_every (now 1), store fewer history quantities (now u v a_abs drift storey_shear), shorten t_end (now 200 s) or enlarge dt (now 1e-06 s)")
  expect_contains("memory" "${m_err}" "${s}")
endforeach()
if(EXISTS ${WORK_DIR}/out)
  message(FATAL_ERROR "memory: the output folder was created although the run was refused")
endif()
