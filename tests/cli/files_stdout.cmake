# The summary on standard output is never lost silently: /dev/full and a closed standard
# output end with status 1 and a message on standard error (the files are published).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(deck ${SOURCE_DIR}/input/two_frames_pdelta.nml)
run_shell(full "exec \"$POUND\" ${deck} -o full >/dev/full")
expect_equal("/dev/full: exit" 1 "${full_rc}")
expect_contains("/dev/full" "${full_err}"
  "pound: error: cannot write the summary to standard output: No space left on device (the results were written to full/two_frames_pdelta.out and full/two_frames_pdelta.h5)")
run_shell(closed "exec \"$POUND\" ${deck} -o closed >&-")
expect_equal("closed stdout: exit" 1 "${closed_rc}")
expect_contains("closed stdout" "${closed_err}" "pound: error: cannot write the summary: standard output is closed")
# The closed descriptor 1 was not reused by an output file: the listing is clean.
file(READ ${WORK_DIR}/closed/two_frames_pdelta.out listing)
string(FIND "${listing}" "wrote closed/" pos)
expect_equal("summary inside the listing" -1 "${pos}")
file(READ ${WORK_DIR}/full/two_frames_pdelta.out ref)
string(LENGTH "${ref}" n_ref)
string(LENGTH "${listing}" n_listing)
expect_equal("listing length with stdout closed" "${n_ref}" "${n_listing}")
