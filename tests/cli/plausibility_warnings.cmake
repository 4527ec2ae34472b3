# Plausibility warnings (accepted, warned on the terminal and in the listing): a fundamental
# period far above the code estimate Ct H^0.75 names the likely unit mistake (masses in kg,
# E in MPa); a scaling target below 0.05 m/s^2 suggests target_g; target_g scales in g; a
# shipped deck warns of none of these.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

# Masses in kg (10 t floors given as 10000): T1 = 10.17 s for 6 m, 31.2 x 0.085 6^0.75 s.
file(WRITE ${WORK_DIR}/kg.nml "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566, scale_to = 'pga', target = 0.04 /
&building name = 'T', n_storeys = 2, height = 2*3.0, mass = 2*10000.0, stiffness = 2*1.0e4 /
")
run_pound(k kg.nml)
expect_equal("exit status" 0 "${k_rc}")
expect_contains("summary" "${k_out}" "WARNING: building T: fundamental period T1 = 10.2 s is 31.2 times the code estimate Ct H^0.75 = 0.326 s (EN 1998-1 4.3.3.2.2")
expect_contains("summary" "${k_out}" "likely masses in kg instead of t (mass up to 10000 t per floor)")
expect_contains("summary" "${k_out}" "WARNING: kg.nml:2: &ground: target = 0.04 m/s^2 is below 0.05 m/s^2")
expect_contains("summary" "${k_out}" "did you mean g?")
file(READ ${WORK_DIR}/kg.out listing)
string(REGEX MATCHALL "WARNING: [^\n]*" in_listing "${listing}")
string(REGEX MATCHALL "WARNING: [^\n]*" in_summary "${k_out}")
expect_equal("the same warnings in the listing and the summary" "${in_listing}" "${in_summary}")

# E in MPa (3.4e4 instead of 3.4e7 kN/m^2) in frame A of the shipped elastic deck: T1 x 31.6.
file(READ ${SOURCE_DIR}/input/two_frames_elastic.nml seed)
string(REPLACE "e_modulus = 3*3.4e7" "e_modulus = 3*3.4e4" mpa "${seed}")
file(WRITE ${WORK_DIR}/mpa.nml "${mpa}")
run_pound(m mpa.nml)
expect_equal("exit status" 0 "${m_rc}")
expect_contains("summary" "${m_out}" "WARNING: building A: fundamental period T1 = 9.08 s is 20.6 times")
expect_contains("summary" "${m_out}" "likely E in MPa instead of kN/m^2 (E = 34000 kN/m^2)")

# The shipped deck itself: no plausibility warning; target_g = 0.3 scales the PGA to 0.3 g.
file(WRITE ${WORK_DIR}/elastic.nml "${seed}")
run_pound(e elastic.nml)
expect_equal("exit status" 0 "${e_rc}")
string(FIND "${e_out}" "WARNING" pos)
expect_equal("no warning for the shipped deck" -1 "${pos}")
file(WRITE ${WORK_DIR}/in_g.nml "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566, scale_to = 'pga', target_g = 0.3 /
&building name = 'T', n_storeys = 2, height = 2*3.0, mass = 2*10.0, stiffness = 2*1.0e4 /
")
run_pound(g in_g.nml)
expect_equal("exit status" 0 "${g_rc}")
string(FIND "${g_out}" "WARNING" pos)
expect_equal("no warning for target_g" -1 "${pos}")
file(READ ${WORK_DIR}/in_g.out listing)
expect_contains("listing" "${listing}" "PGA 2.943000 m/s^2 = 0.3000000 g")
