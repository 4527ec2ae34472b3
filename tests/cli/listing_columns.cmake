# Issue 27: the listing holds up with real names. Two decks with 64-character building (and
# motion) names, frames, floors striking columns given by `elevations`, a gap sweep, and a
# suite (tests/data/listing/): every table row of each listing splits into exactly its
# heading's columns, every numeric cell is one number (tests/cli/listing_columns.py, on
# /usr/bin/python3), the pairs are named in full ('<building>:<floor>-<building>:z=<m>m'),
# gaps are in mm, every dataset of the results files has a 'units' attribute and the
# per-motion /suite arrays have one row per motion.
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
expect_contains("separation table named by pair" "${listing}" "  pair ${RC}:2-${ST}:2\n")
expect_contains("separation table in mm" "${listing}" "Separation rules per contact pair [mm]")
execute_process(COMMAND ${PY} ${CHECK} ${WORK_DIR}/long_names_suite.out ${WORK_DIR}/long_names_suite.h5 30 2
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("suite listing and results (${out}${err})" 0 "${rc}")
