# The case scheduler on synthetic cases under mpirun -np 2 (tests/mpi/cases_check.f90): a
# failed case is marked with its message, the others are computed; every rank holds every
# column by case index; nested and consecutive calls.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
run(r ${MPIRUN} ${CHECK_EXE})
expect_equal("exit status (${r_out}${r_err})" 0 "${r_rc}")
expect_equal("stdout" "cases: ok, 2 ranks\n" "${r_out}")
