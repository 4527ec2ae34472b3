# Values at the edges of the plausible input ranges (a 1e9 t floor on 1e-3 kN/m, a 1e-6 t
# floor on 1e9 kN/m) run, and neither the listing nor the summary shows '****' or a period
# of zero: every column switches to scientific notation where the fixed form cannot show it.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(WRITE ${WORK_DIR}/edge.nml "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566 /
&building name = 'A', n_storeys = 2, height = 2*3.0, mass = 2*1.0e9, stiffness = 2*1.0e-3 /
&building name = 'B', n_storeys = 1, height = 3.0, mass = 1.0e-6, stiffness = 1.0e9 /
&contact left = 'A', right = 'B', floors_left = 1, floors_right = 1, gap = 0.0,
         law = 'elastic', stiffness = 1.0e9 /
")
run_pound(r edge.nml)
expect_equal("exit status" 0 "${r_rc}")
file(READ ${WORK_DIR}/edge.out listing)
foreach(text IN ITEMS "${listing}" "${r_out}")
  string(FIND "${text}" "***" stars)
  if(NOT stars EQUAL -1)
    message(FATAL_ERROR "'***' in the output:\n${text}")
  endif()
endforeach()
# T1 of a uniform 2-storey stick: 2 pi / (2 sqrt(k/m) sin(pi/10)) = 1.017e7 s; of B 2 pi sqrt(m/k).
expect_contains("summary" "${r_out}" "building A: 2 storeys, T1 = 1.017E+07 s")
# Singular for one storey, on the terminal and in the listing.
expect_contains("summary" "${r_out}" "building B: 1 storey, T1 = 1.987E-07 s")
expect_contains("listing" "${listing}" "  Building B: 1 storey, P-Delta off")
expect_contains("listing" "${listing}" " 1.0000E+09")
