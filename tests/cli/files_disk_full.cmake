# Disk full as a file-size limit (ulimit -f): SIGXFSZ is ignored, the write fails with EFBIG
# and the run ends with one message naming the file and "File too large", status 1, nothing left.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(deck ${SOURCE_DIR}/input/two_frames_pdelta.nml)
# 12 KiB: the listing (about 15 kB) cannot be written. The histories are streamed to the HDF5
# file during the run, before the listing: with two output times of u only (a copy of the
# deck), the file stays under 12 KiB until the listing is written (the histories' `units`
# attributes, variable-length strings in HDF5's global heap, take it beyond 8 KiB).
file(READ ${deck} text)
string(REPLACE "output_every = 1 " "output_every = 5000 " text "${text}")
string(REPLACE "history = 'all'" "history = 'u'" text "${text}")
file(WRITE ${WORK_DIR}/few/two_frames_pdelta.nml "${text}")
run_shell(l "ulimit -f 12; exec \"$POUND\" ${WORK_DIR}/few/two_frames_pdelta.nml -o out")
expect_clean_failure("listing beyond ulimit -f" l "cannot write the listing out/.two_frames_pdelta.out." out)
expect_contains("listing beyond ulimit -f" "${l_err}" "File too large")
# 64 KiB: the listing fits, the HDF5 file (about 5.6 MB) does not.
run_shell(h "ulimit -f 64; exec \"$POUND\" ${deck} -o out")
expect_clean_failure("HDF5 beyond ulimit -f" h "cannot write out/two_frames_pdelta.h5: HDF5 file" out)
expect_contains("HDF5 beyond ulimit -f" "${h_err}" "File too large")
# An earlier pair in the folder is left as it was by a failing run.
run_pound(ok ${deck} -o keep)
expect_equal("first run" 0 "${ok_rc}")
file(SHA256 ${WORK_DIR}/keep/two_frames_pdelta.h5 h5_before)
file(SHA256 ${WORK_DIR}/keep/two_frames_pdelta.out out_before)
run_shell(k "ulimit -f 64; exec \"$POUND\" ${deck} -o keep")
expect_equal("second run, exit status" 1 "${k_rc}")
file(SHA256 ${WORK_DIR}/keep/two_frames_pdelta.h5 h5_after)
file(SHA256 ${WORK_DIR}/keep/two_frames_pdelta.out out_after)
expect_equal("earlier .h5 kept" "${h5_before}" "${h5_after}")
expect_equal("earlier .out kept" "${out_before}" "${out_after}")
file(GLOB partial ${WORK_DIR}/keep/.*.partial)
expect_equal("partial files in keep/" "" "${partial}")
