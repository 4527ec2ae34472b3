# Issue 27: the listing holds up with real names. Two decks with 64-character building (and
# motion) names, frames, floors striking columns given by `elevations`, a gap sweep, and a
# suite (tests/data/listing/): every table row of each listing splits into exactly its
# heading's columns, every numeric cell is one number (tests/cli/listing_columns.py, on
# /usr/bin/python3), the pairs are named in full ('<building>:<floor>-<building>:z=<m>m'),
# gaps are in mm, every dataset of the results files has a 'units' attribute and the
# per-motion /suite arrays have one row per motion. The same checks on example decks with
# other contact laws and on a suite with a failed motion.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(CHECK ${CMAKE_CURRENT_LIST_DIR}/listing_columns.py)
set(RC REINFORCED_CONCRETE_FRAME_OF_THE_OLD_HOSPITAL_WING_BUILT_1990_AB)
set(ST STEEL-FRAME-OF-THE-NEW-LABORATORY-BUILDING-ON-THE-EAST-SIDE-1234)

run_pound(f ${SOURCE_DIR}/tests/data/listing/long_names_frames.nml)
expect_equal("pound exit, frames (${f_err})" 0 "${f_rc}")
file(READ ${WORK_DIR}/long_names_frames.out listing)
expect_contains("full pair label, floor to column" "${listing}" "  ${RC}:3-${ST}:z=10.50m ")
expect_contains("full pair label, column to floor" "${listing}" "  ${RC}:z=3.00m-${ST}:1 ")
expect_contains("contact table in mm" "${listing}" "    gap [mm]  law")
expect_contains("whole names in the influence tables" "${listing}" "  ${RC}  ${ST}\n")
expect_contains("peak tables in mm" "${listing}" "|u| [mm]")
execute_process(COMMAND ${PY} ${CHECK} ${WORK_DIR}/long_names_frames.out ${WORK_DIR}/long_names_frames.h5 20
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("frames listing and results (${out}${err})" 0 "${rc}")

run_pound(s ${SOURCE_DIR}/tests/data/listing/long_names_suite.nml)
expect_equal("pound exit, suite (${s_err})" 0 "${s_rc}")
file(READ ${WORK_DIR}/long_names_suite.out listing)
expect_contains("separation table named by pair" "${listing}"
                "  pair ${RC}:2-${ST}:2  (u1 elastic, u2 elastic; floor levels coincide: EN 1998 x 0.7, IS 1893 x 0.5)\n")
expect_contains("separation table in mm" "${listing}" "Separation rules per contact pair [mm]")
execute_process(COMMAND ${PY} ${CHECK} ${WORK_DIR}/long_names_suite.out ${WORK_DIR}/long_names_suite.h5 30 2
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("suite listing and results (${out}${err})" 0 "${rc}")
execute_process(COMMAND ${PY} -c "
import h5py
f = h5py.File('${WORK_DIR}/long_names_suite.h5', 'r')
pairs = f['suite/separation'].attrs['pairs'].split()
assert pairs == f['coupled/contact'].attrs['pairs'].split(), pairs
assert pairs == ['${RC}:%d-${ST}:%d' % (k, k) for k in (1, 2, 3)], pairs
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("/suite/separation pairs attribute (${err})" 0 "${rc}")
expect_contains("whole motion names" "${listing}"
                "\n  SYNTHETIC_MOTION_WITH_A_VERY_LONG_NAME_FOR_THE_LISTING_COLUMNS_2  ")

# The example decks with other laws (parabola_cubic, bilinear, restitution) and floors
# striking columns, and a suite with a failed motion (FAILED rows, the failed-case table).
foreach(deck input/two_frames_pdelta.nml input/frame_to_column.nml tests/data/good_decks/bounds_edges.nml
        tests/data/good_decks/restitution.nml)
  get_filename_component(stem ${deck} NAME_WE)
  run_pound(e ${SOURCE_DIR}/${deck})
  expect_equal("pound exit, ${deck} (${e_err})" 0 "${e_rc}")
  execute_process(COMMAND ${PY} ${CHECK} ${WORK_DIR}/${stem}.out ${WORK_DIR}/${stem}.h5 15
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  expect_equal("${deck}: listing and results (${out}${err})" 0 "${rc}")
endforeach()
file(COPY ${SOURCE_DIR}/tests/data/suite_failed.nml DESTINATION ${WORK_DIR})
run_shell(sf "POUND_TEST_OVERFLOW=big \"$POUND\" suite_failed.nml --quiet")
expect_equal("failed suite exit (${sf_err})" 3 "${sf_rc}")
execute_process(COMMAND ${PY} ${CHECK} ${WORK_DIR}/suite_failed.out ${WORK_DIR}/suite_failed.h5 30 3
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("failed suite: listing and results (${out}${err})" 0 "${rc}")
