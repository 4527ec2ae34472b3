# SIGINT and SIGTERM while the outputs are being written (the test hook
# POUND_TEST_PAUSE_WRITING holds the run after its listing temporary is complete, before the
# HDF5 file): the run removes its temporaries and ends with 130 / 143; an earlier pair in the
# folder is untouched.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(deck ${SOURCE_DIR}/input/two_frames_pdelta.nml)
run_pound(first ${deck} -o out)
expect_equal("first run" 0 "${first_rc}")
file(SHA256 ${WORK_DIR}/out/two_frames_pdelta.h5 h5_before)
file(SHA256 ${WORK_DIR}/out/two_frames_pdelta.out out_before)
foreach(sig INT TERM)
  # Wait until the listing temporary has its content (the run is then writing), signal it.
  run_shell(s "POUND_TEST_PAUSE_WRITING=30 \"$POUND\" ${deck} -o out & pid=$!
for i in $(seq 1 300); do
  f=$(ls out/.two_frames_pdelta.out.*.partial 2>/dev/null)
  [ -n \"$f\" ] && [ $(stat -c %s $f) -gt 10000 ] && break
  sleep 0.1
done
echo \"seen: $f\"
kill -${sig} $pid; wait $pid")
  if(sig STREQUAL "INT")
    expect_equal("SIGINT exit status" 130 "${s_rc}")
    expect_contains("SIGINT" "${s_err}" "pound: interrupted (SIGINT), temporary files removed")
  else()
    expect_equal("SIGTERM exit status" 143 "${s_rc}")
    expect_contains("SIGTERM" "${s_err}" "pound: terminated (SIGTERM), temporary files removed")
  endif()
  expect_contains("${sig}: the signal landed while writing" "${s_out}" "seen: out/.two_frames_pdelta.out.")
  file(GLOB partial ${WORK_DIR}/out/.*.partial)
  expect_equal("${sig}: temporaries left" "" "${partial}")
  file(SHA256 ${WORK_DIR}/out/two_frames_pdelta.h5 h5_after)
  file(SHA256 ${WORK_DIR}/out/two_frames_pdelta.out out_after)
  expect_equal("${sig}: earlier .h5 kept" "${h5_before}" "${h5_after}")
  expect_equal("${sig}: earlier .out kept" "${out_before}" "${out_after}")
endforeach()
