# Bad inputs of the studies of the joint (issue 26): a stiffness or restitution sweep, a law
# study's variants, the default joint stiffness. One clear message each, exit 1, no outputs.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
file(READ ${SOURCE_DIR}/input/joint_stiffness_study.nml sweep_deck)
file(READ ${SOURCE_DIR}/input/joint_law_study.nml law_deck)
set(sweep_group "&sweep
   parameter = 'stiffness'
   value_from = 1.0e5       ! kN/m
   value_to = 1.0e7         ! kN/m
   n_values = 5             ! log-spaced: 1e5, 3.16e5, 1e6, 3.16e6, 1e7
   target_lambda = 10.0     ! %
   target_quantities = 'storey_shear drift'
/")

# The sweep group replaced by `group`.
function(sweep_refused name group needle)
  string(REPLACE "${sweep_group}" "${group}" text "${sweep_deck}")
  refused(${name} "${text}" "${needle}")
endfunction()

sweep_refused(unknown_parameter "&sweep parameter = 'damping', values = 1, 2 /"
  "&sweep: parameter = 'damping', must be 'gap' (the default), 'stiffness' or 'restitution'")
sweep_refused(gap_with_stiffness "&sweep parameter = 'stiffness', gap_from = 0, gap_to = 0.01, n_gaps = 5 /"
  "gap_from, gap_to and n_gaps are for parameter = 'gap'")
sweep_refused(list_and_range "&sweep parameter = 'stiffness', values = 1e5, 1e6, value_from = 1e5 /"
  "values and value_from/value_to/n_values are both given")
sweep_refused(no_values "&sweep parameter = 'stiffness' /"
  "parameter = 'stiffness' needs its values")
sweep_refused(range_incomplete "&sweep parameter = 'stiffness', value_from = 1e5, n_values = 3 /"
  "a range needs value_from, value_to and n_values")
sweep_refused(restitution_above_one "&sweep parameter = 'restitution', values = 0.5, 1.5 /"
  "values(2) = 1.500000, must be > 0 and < 1")
sweep_refused(stiffness_zero "&sweep parameter = 'stiffness', values = 1e6, 0 /"
  "values(2) = 0.000000, must be a joint stiffness in 1.0000000E-3..1.0000000E+13 kN/m")
sweep_refused(bad_spacing "&sweep parameter = 'stiffness', value_from = 1e5, value_to = 1e7, n_values = 3, spacing = 'geometric' /"
  "spacing = 'geometric', must be 'log' or 'linear'")
sweep_refused(values_with_gap_sweep "&sweep gap_from = 0, gap_to = 0.01, n_gaps = 5, values = 1e5 /"
  "values, value_from, value_to, n_values and spacing are for parameter = 'stiffness' or 'restitution'")
# A restitution sweep of a group with a dashpot (the dashpot would be replaced).
string(REPLACE "   stiffness = 1.0e6\n/" "   stiffness = 1.0e6\n   dashpot = 50.0\n/" dashpot_deck "${sweep_deck}")
string(REPLACE "${sweep_group}" "&sweep parameter = 'restitution', values = 0.5, 0.7 /" dashpot_deck "${dashpot_deck}")
refused(restitution_with_dashpot "${dashpot_deck}" "gives a dashpot, which the restitution would replace")
# A value that makes no valid law: a bilinear's second slope must stay below k0.
string(REPLACE "   law = 'elastic'\n   stiffness = 1.0e6\n/"
       "   law = 'bilinear'\n   stiffness = 1.0e6\n   yield_force = 500\n   second_slope = 2.0e5\n/" bilinear_deck "${sweep_deck}")
string(REPLACE "${sweep_group}" "&sweep parameter = 'stiffness', values = 1e6, 1e5 /" bilinear_deck "${bilinear_deck}")
refused(value_breaks_law "${bilinear_deck}" "stiffness = 100000.0 (value 2) makes no valid law of &contact #1 (A, B)")
# A suite (two &ground) cannot sweep the stiffness.
string(REPLACE "&ground\n   kind = 'pulse'" "&ground\n   name = 'p1'\n   kind = 'pulse'" suite_deck "${sweep_deck}")
string(REPLACE "! Frame A," "&ground name = 'p2', kind = 'pulse', x0 = 0.005, a = 2.0, b = 12.566370614359172 /\n\n! Frame A,"
       suite_deck "${suite_deck}")
refused(suite_sweep "${suite_deck}" "parameter = 'stiffness' runs with one ground motion; this deck is a suite")

# Law study.
string(REPLACE "variant = 'damped'" "variant = 'base'" text "${law_deck}")
refused(variant_base "${text}" "variant = 'base': 'base' names the study's base")
string(REPLACE "variant = 'damped'" "variant = 'dam/ped'" text "${law_deck}")
refused(variant_slash "${text}" "variant = 'dam/ped': a variant's name is letters, digits, '_' and '-'")
string(REPLACE "variant = 'damped'" "variant = 'stiff'" text "${law_deck}")
refused(variant_twice "${text}" "variant = 'stiff' defines 6 pairs, the base (the &contact groups without a variant) 3")
string(REPLACE "variant = 'crushing'\n   left = 'A'\n   right = 'B'\n   floors_left = 1, 2, 3\n   floors_right = 1, 2, 3\n   gap = 0.001"
       "variant = 'crushing'\n   left = 'A'\n   right = 'B'\n   floors_left = 1, 2, 3\n   floors_right = 1, 2, 3\n   gap = 0.002"
       text "${law_deck}")
refused(variant_other_gap "${text}" "variant = 'crushing': its pair 1 is A:1-B:1 gap 2.0000000E-3 m, the base's pair 1 is A:1-B:1 gap 1.0000000E-3 m")
string(REPLACE "! The base: the joint as designed" "! x" text "${law_deck}")
string(REPLACE "&contact\n   left = 'A'" "&contact\n   variant = 'first'\n   left = 'A'" text "${text}")
refused(no_base "${text}" "every &contact group has a variant: a law study compares its variants with the base")

# The default joint stiffness needs a frame's floor: two shear buildings must give it.
string(REPLACE "   law = 'elastic'\n   stiffness = 1.0e6\n/" "   law = 'elastic'\n/" text "${sweep_deck}")
refused(no_default_stiffness "${text}" "&contact #1 (A, B): stiffness is missing (joint stiffness k0 in kN/m), and no default")
