# Disk full on a real file system: a tiny tmpfs as the output folder (needs mount, i.e. root
# with CAP_SYS_ADMIN; skipped where that is not possible). 64 KiB: the HDF5 file does not
# fit (the histories are streamed into it during the run); 8 KiB: the listing does not. One
# message with "No space left on device", status 1, no crash in exit handlers, nothing left
# in the folder.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(deck ${SOURCE_DIR}/input/two_frames_pdelta.nml)
# 8 KiB: a copy of the deck with two output times of u only, so that the streamed histories
# fit and the listing is what fails.
file(READ ${deck} text)
string(REPLACE "output_every = 1 " "output_every = 5000 " text "${text}")
string(REPLACE "history = 'all'" "history = 'u'" text "${text}")
file(WRITE ${WORK_DIR}/few/two_frames_pdelta.nml "${text}")
set(deck64 ${deck})
set(deck8 ${WORK_DIR}/few/two_frames_pdelta.nml)
foreach(size 64 8)
  file(MAKE_DIRECTORY ${WORK_DIR}/fs${size})
  execute_process(COMMAND mount -t tmpfs -o size=${size}k tmpfs ${WORK_DIR}/fs${size}
                  RESULT_VARIABLE mrc OUTPUT_QUIET ERROR_QUIET)
  if(NOT mrc EQUAL 0)
    message("SKIPPED: cannot mount a tmpfs here (not root, or no CAP_SYS_ADMIN)")
    return()
  endif()
  run_pound(r${size} ${deck${size}} -o fs${size})
  # Unmount before any assertion can stop the script.
  file(GLOB left ${WORK_DIR}/fs${size}/* ${WORK_DIR}/fs${size}/.*.partial)
  execute_process(COMMAND umount ${WORK_DIR}/fs${size})
  if(left)
    message(FATAL_ERROR "tmpfs ${size} KiB: outputs left behind: ${left}")
  endif()
endforeach()
expect_clean_failure("tmpfs 64 KiB" r64 "cannot write fs64/two_frames_pdelta.h5: HDF5 file" fs64)
expect_contains("tmpfs 64 KiB" "${r64_err}" "No space left on device")
expect_clean_failure("tmpfs 8 KiB" r8 "cannot write the listing fs8/.two_frames_pdelta.out." fs8)
expect_contains("tmpfs 8 KiB" "${r8_err}" "No space left on device")
