# Output paths: the deck or the record as an output is refused with the input intact, a
# folder named <stem>.out fails before anything is published, -o creates missing folders
# before computing, pound '' is a usage error.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(seed ${SOURCE_DIR}/input/two_frames_pdelta.nml)

# A deck named victim.out, run with -o its own folder: the listing would replace it.
file(MAKE_DIRECTORY ${WORK_DIR}/v)
configure_file(${seed} ${WORK_DIR}/v/victim.out COPYONLY)
run_pound(v v/victim.out -o v)
expect_clean_failure("deck as listing" v "output v/victim.out would replace the input file v/victim.out" nothing)
file(SHA256 ${seed} want)
file(SHA256 ${WORK_DIR}/v/victim.out got)
expect_equal("deck intact" "${want}" "${got}")
file(GLOB left ${WORK_DIR}/v/*.h5 ${WORK_DIR}/v/.*.partial)
expect_equal("nothing written beside the deck" "" "${left}")
# The same through another spelling of the folder (compared by device and inode).
run_pound(v2 ./v/../v/victim.out -o ${WORK_DIR}/v/.)
expect_equal("deck as listing, other spelling" 1 "${v2_rc}")
expect_contains("deck as listing, other spelling" "${v2_err}" "would replace the input file")

# A record named like the HDF5 output: quake.nml reading quake.h5 (two columns), -o its folder.
file(MAKE_DIRECTORY ${WORK_DIR}/r)
file(WRITE ${WORK_DIR}/r/quake.h5 "0.00 0.0\n0.01 0.1\n0.02 -0.1\n0.03 0.0\n")
file(WRITE ${WORK_DIR}/r/quake.nml "&analysis title = 'quake', dt = 0.01, t_end = 0.05 /
&ground kind = 'record', file = 'quake.h5', format = 'columns' /
&building name = 'A', n_storeys = 1, height = 3.0, mass = 10.0, stiffness = 1.0e4 /
")
file(SHA256 ${WORK_DIR}/r/quake.h5 rec_before)
run_pound(r r/quake.nml -o r)
expect_equal("record as output" 1 "${r_rc}")
expect_contains("record as output" "${r_err}" "output r/quake.h5 would replace the input file")
file(SHA256 ${WORK_DIR}/r/quake.h5 rec_after)
expect_equal("record intact" "${rec_before}" "${rec_after}")

# <stem>.out is a folder: fail before anything is published; an earlier .h5 is kept.
file(MAKE_DIRECTORY ${WORK_DIR}/f/two_frames_pdelta.out)
file(WRITE ${WORK_DIR}/f/two_frames_pdelta.h5 "earlier")
run_pound(f ${seed} -o f)
expect_equal("<stem>.out folder: exit" 1 "${f_rc}")
expect_contains("<stem>.out folder" "${f_err}" "output f/two_frames_pdelta.out is a folder")
file(READ ${WORK_DIR}/f/two_frames_pdelta.h5 h5)
expect_equal("<stem>.out folder: earlier .h5 kept" "earlier" "${h5}")
file(GLOB partial ${WORK_DIR}/f/.*.partial)
expect_equal("<stem>.out folder: temporaries" "" "${partial}")

# -o with missing nested folders: created like mkdir -p.
run_pound(n ${seed} -o new/nested/dir)
expect_equal("-o nested: exit" 0 "${n_rc}")
foreach(f two_frames_pdelta.out two_frames_pdelta.h5)
  if(NOT EXISTS ${WORK_DIR}/new/nested/dir/${f})
    message(FATAL_ERROR "-o nested: missing ${f}")
  endif()
endforeach()
# -o that cannot be created is refused (before computing).
file(WRITE ${WORK_DIR}/plain "x")
run_pound(p ${seed} -o plain/sub)
expect_clean_failure("-o through a file" p "cannot create the output folder plain/sub: plain exists and is not a folder" plain)

# An empty deck name is a usage error.
run_shell(e "exec \"$POUND\" ''")
expect_equal("pound '': exit" 2 "${e_rc}")
expect_contains("pound ''" "${e_err}" "pound: error: the deck name is empty")
expect_contains("pound ''" "${e_err}" "usage: pound DECK.nml [-o DIR]")
