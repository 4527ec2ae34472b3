# Refusals that used to be made when the run started, naming only "building A": now each names
# the deck file, the line, the group and the variable (exit 1, one line, no outputs).
# HHT-alpha with yielding buildings is accepted (no longer a refusal); free_steps = 'exact'
# on a building of 2001 DOFs; a stiffness sweep whose value makes no valid Hertz-family law.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

set(bilinear "&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566 /
&building name = 'A', n_storeys = 2, height = 2*3.0, mass = 2*10.0, stiffness = 2*1.0e4,
   storey_law = 'bilinear', yield_shear = 2*10.0 /
")
# integrator = 'hht' without hht_alpha (its default -0.05) and with hht_alpha = 0, with
# bilinear storeys: accepted (HHT-alpha runs yielding buildings).
foreach(alpha "" ", hht_alpha = 0.0")
  file(WRITE ${WORK_DIR}/hht_yield.nml "&analysis dt = 0.01, t_end = 1.0, integrator = 'hht'${alpha} /\n${bilinear}")
  run_pound(z hht_yield.nml)
  expect_equal("hht_yield${alpha}: exit status (${z_err})" 0 "${z_rc}")
endforeach()

# Exact free steps on a shear building of 2001 storeys (2001 DOFs).
refused(exact_dofs "&analysis dt = 0.01, t_end = 0.1,
   free_steps = 'exact' /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566 /
&building name = 'A', n_storeys = 2001, height = 2001*3.0, mass = 2001*10.0, stiffness = 2001*1.0e7 /
"
  "exact_dofs.nml:2: &analysis: free_steps = 'exact' takes at most 2000 DOFs a building (it holds the n x n modes and costs O(n^2) a step); building A has 2001: use free_steps = 'newmark'")

# A stiffness sweep of a Hertz joint with a value outside the range the deck refuses for
# `stiffness` (1e3..1e10 kN/m^(3/2)).
file(READ ${SOURCE_DIR}/input/joint_stiffness_study.nml deck)
string(REPLACE "   law = 'elastic'\n   stiffness = 1.0e6" "   law = 'hertz'\n   stiffness = 1.0e8" deck "${deck}")
string(REGEX REPLACE "&sweep.*$" "&sweep parameter = 'stiffness', values = 1e6, 1e11 /" deck "${deck}")
refused(hertz_sweep "${deck}"
  "hertz_sweep.nml:64: &sweep: stiffness = 1.0000000E+11 (value 2) makes no valid law of &contact #1 (A, B): law 'hertz': a Hertz-type stiffness must be in 1000.000 to 1.0000000E+10 kN/m^(3/2)")
