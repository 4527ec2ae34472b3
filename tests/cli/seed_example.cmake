# The shipped example runs and writes a complete listing and HDF5 file, nothing partial.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(MAKE_DIRECTORY ${WORK_DIR}/out)
run_pound(r ${SOURCE_DIR}/input/two_frames_pdelta.nml -o out)
expect_equal("exit status" 0 "${r_rc}")
expect_published(out two_frames_pdelta)
file(READ ${WORK_DIR}/out/two_frames_pdelta.out listing)
foreach(s "units: kN, m, s, t (tonne)" "Deck echo" "T [s]" "Uncoupled response" "Coupled response"
          "Influence coefficients" "storey shear Q" "LCP (Lemke, lexicographic) statistics" "Energy audit")
  expect_contains("listing" "${listing}" "${s}")
endforeach()
# Output folder that cannot be created (a file is in the way): clear message, exit 1.
file(WRITE ${WORK_DIR}/plain "not a folder\n")
run_pound(d ${SOURCE_DIR}/input/two_frames_pdelta.nml -o plain/sub)
expect_equal("exit status, bad -o" 1 "${d_rc}")
expect_contains("bad -o" "${d_err}" "cannot create the output folder plain/sub: plain exists and is not a folder")
# Nothing on stderr (Debug: no array temporaries in the writers of the contact results).
expect_equal("stderr" "" "${r_err}")
