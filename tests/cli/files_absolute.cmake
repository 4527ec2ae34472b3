# Absolute paths: a record given by an absolute path (in a folder with a 200+ character
# name, longer than the deck's path) is read and protected from being overwritten, in a
# single run and as the second record of a suite; an absolute output folder works.
# (gfortran 12 sized the list of input paths by the deck's path: the record's path was cut
# short, so it was not protected, and the copy wrote past its heap block and crashed.)
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

# A successful run: status 0 and no crash report or runtime error on stderr.
function(expect_clean_success what prefix)
  expect_equal("${what}: exit status" 0 "${${prefix}_rc}")
  foreach(bad "Backtrace" "Segmentation" "SIGSEGV" "malloc" "free()" "HDF5-DIAG" "runtime error")
    string(FIND "${${prefix}_err}" "${bad}" pos)
    if(NOT pos EQUAL -1)
      message(FATAL_ERROR "${what}: '${bad}' in stderr:\n${${prefix}_err}")
    endif()
  endforeach()
endfunction()

# A PEER AT2 record of 7 points, dt = 0.02 s, peak |a| = 0.3 g at t = 0.1 s.
set(at2 "PEER STRONG MOTION DATABASE RECORD. SYNTHETIC TEST.
TEST EVENT, TEST STATION, 000
ACCELERATION TIME HISTORY IN UNITS OF G
NPTS=     7, DT= .02000 SEC
  .1000000E-01  -.6028715E-02   .1234567E+00  -.2500000E-03   .0000000E+00
  -.3000000E+00   .5000000E-02
")
string(REPEAT "long_folder_name_" 13 long)
set(rec_dir ${WORK_DIR}/records_${long})
file(MAKE_DIRECTORY ${rec_dir})
set(record ${rec_dir}/synthetic_record.AT2)
file(WRITE ${record} "${at2}")
string(LENGTH "${record}" record_len)
if(record_len LESS 200)
  message(FATAL_ERROR "the record path should be 200+ characters, is ${record_len}")
endif()
set(building "&building name = 'A', n_storeys = 2, height = 2*3.0, mass = 2*10.0, stiffness = 2*1.0e4 /")

# The record by absolute path, the deck by a short relative one.
file(WRITE ${WORK_DIR}/a.nml "&analysis dt = 0.01, t_end = 0.2 /
&ground kind = 'record', file = '${record}' /
${building}
")
run_pound(a a.nml -o out)
expect_clean_success("absolute record" a)
file(READ ${WORK_DIR}/out/a.out listing)
expect_contains("absolute record: listing" "${listing}" "record ${record} (at2, 7 points, dt = 2.0000000E-2 s")
expect_contains("absolute record: PGA" "${listing}" "= 0.3000000 g at t = 0.1000000 s")
if(NOT EXISTS ${WORK_DIR}/out/a.h5)
  message(FATAL_ERROR "absolute record: out/a.h5 missing")
endif()

# The same deck with an absolute output folder (created like mkdir -p).
run_pound(o a.nml -o ${WORK_DIR}/abs_out/nested)
expect_clean_success("absolute output folder" o)
foreach(f a.out a.h5)
  if(NOT EXISTS ${WORK_DIR}/abs_out/nested/${f})
    message(FATAL_ERROR "absolute output folder: missing ${f}")
  endif()
endforeach()
expect_contains("absolute output folder: summary" "${o_out}" "wrote ${WORK_DIR}/abs_out/nested/a.out")

# A record by absolute path named like the HDF5 output, the output folder its own folder:
# refused, the record intact.
configure_file(${record} ${rec_dir}/q.h5 COPYONLY)
file(SHA256 ${rec_dir}/q.h5 rec_before)
file(WRITE ${WORK_DIR}/q.nml "&analysis dt = 0.01, t_end = 0.2 /
&ground kind = 'record', file = '${rec_dir}/q.h5', format = 'at2' /
${building}
")
run_pound(q q.nml -o ${rec_dir})
expect_clean_failure("absolute record as output" q "would replace the input file ${rec_dir}/q.h5" nothing)
file(SHA256 ${rec_dir}/q.h5 rec_after)
expect_equal("absolute record as output: record intact" "${rec_before}" "${rec_after}")

# The same as the second record of a suite (every record is protected, not only the first).
file(WRITE ${WORK_DIR}/q.nml "&analysis dt = 0.01, t_end = 0.2 /
&ground name = 'one', kind = 'record', file = '${record}' /
&ground name = 'two', kind = 'record', file = '${rec_dir}/q.h5', format = 'at2' /
${building}
")
run_pound(s q.nml -o ${rec_dir})
expect_clean_failure("suite record as output" s "would replace the input file ${rec_dir}/q.h5" nothing)
file(SHA256 ${rec_dir}/q.h5 rec_after)
expect_equal("suite record as output: record intact" "${rec_before}" "${rec_after}")
