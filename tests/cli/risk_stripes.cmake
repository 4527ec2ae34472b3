# The multiple-stripe analysis (&stripes, &hazard, &ground kind = 'record_set'): every
# (stripe, motion, gap) outcome equals a single run of that motion scaled by scale_to to the
# stripe's level at that gap, the demand files hold that run's coupled peaks, the probabilities
# and the risk-targeted gap follow from the frequencies, the answer leads the terminal and the
# summary CSV, a record set is named by stem in sorted order (tests/cli/risk_stripes.py).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
execute_process(COMMAND /usr/bin/python3 ${CMAKE_CURRENT_LIST_DIR}/risk_stripes.py ${POUND_EXE} ${WORK_DIR}
                        ${SOURCE_DIR}/tests/data/risk_stripes.nml
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("risk_stripes.py (${out}${err})" 0 "${rc}")
