# Unit mistakes that used to pass silently (warnings, not errors: exit 0, one line each naming
# the value, the likely mistake and the fix): a record in cm/s^2 read as g (PGA as run above
# 2 g), a scale_to factor outside 0.1..10, masses in kg making scale_to = 'sa' blow a pulse up
# past 2 g, a target below 2 m/s^2 that reads as g, a gap above 1 m or a tenth of the lower
# building's height. None of them on the cheap shipped decks.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)

# A two-column record in cm/s^2 (peak about 266 cm/s^2), which pound reads in g.
set(rows "")
foreach(i RANGE 0 500)
  math(EXPR ms "${i} * 10")
  # A triangle wave of amplitude 300 and period 0.5 s (cmake's math is integer).
  math(EXPR phase "${i} % 50")
  if(phase LESS 13)
    math(EXPR v "${phase} * 300 / 12")
  elseif(phase LESS 38)
    math(EXPR v "300 - (${phase} - 12) * 600 / 25")
  else()
    math(EXPR v "-300 + (${phase} - 37) * 300 / 12")
  endif()
  math(EXPR sec "${ms} / 1000")
  math(EXPR frac "${ms} % 1000 + 1000")
  string(SUBSTRING "${frac}" 1 3 frac)
  string(APPEND rows "${sec}.${frac} ${v}\n")
endforeach()
file(WRITE ${WORK_DIR}/gal.txt "${rows}")
set(b "&building name = 'T', n_storeys = 2, height = 2*3.0, mass = 2*10.0, stiffness = 2*1.0e4 /")

# warned(<name> <deck text> <needle>...): exit 0, every needle on the terminal and in the listing.
function(warned name text)
  file(WRITE ${WORK_DIR}/${name}.nml "${text}")
  run_pound(r ${name}.nml)
  expect_equal("${name}: exit status (${r_err})" 0 "${r_rc}")
  file(READ ${WORK_DIR}/${name}.out listing)
  foreach(needle ${ARGN})
    expect_contains("${name}: terminal" "${r_out}" "${needle}")
    expect_contains("${name}: listing" "${listing}" "${needle}")
  endforeach()
endfunction()

warned(gal "&analysis dt = 0.01, t_end = 5.0 /
&ground kind = 'record', file = 'gal.txt', format = 'columns' /
${b}
" "WARNING: &ground 'ground': PGA of the motion as run = 300 g (2940 m/s^2, scale factor 1) is above 2 g: likely a record in cm/s^2 (gal) read as g")

warned(gal_scaled "&analysis dt = 0.01, t_end = 5.0 /
&ground kind = 'record', file = 'gal.txt', format = 'columns', scale_to = 'pga', target_g = 0.3 /
${b}
" "WARNING: &ground 'ground': scale_to needs a scale factor of 0.001 (outside 0.1 to 10): likely a unit mistake in the record (cm/s^2 read as g")

# Masses in kg (T1 = 10.2 s): Sa(T1) of the pulse is tiny and scale_to = 'sa' blows it up.
warned(kg "&analysis dt = 0.01, t_end = 5.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566, scale_to = 'sa', target = 3.0 /
&building name = 'T', n_storeys = 2, height = 2*3.0, mass = 2*10000.0, stiffness = 2*1.0e4 /
" "likely masses in kg instead of t"
  "WARNING: &ground 'ground': PGA of the motion as run = 5.69 g (55.9 m/s^2, scale factor 41.6)"
  "scale_to needs a scale factor of 41.6 (outside 0.1 to 10)"
  ") is above 2 g: likely a target in the wrong unit (target in m/s^2, target_g in g), or a building period far too long (masses in kg")

warned(target "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566, scale_to = 'pga', target = 0.43 /
${b}
" "WARNING: target.nml:2: &ground: target = 0.43 m/s^2 = 0.0438 g with scale_to = 'pga' would be a plausible value in g, while the deck's accelerations are in m/s^2: did you mean target_g = 0.43 (4.22 m/s^2)?")

warned(gap "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566 /
${b}
&building name = 'U', n_storeys = 3, height = 3*3.0, mass = 3*10.0, stiffness = 3*1.0e4 /
&contact left = 'T', right = 'U', floors_left = 1, 2, floors_right = 1, 2, gap = 4.0, law = 'elastic', stiffness = 1e6 /
" "WARNING: gap.nml:5: &contact #1 (T, U): gap = 4 m is above 0.6 m (1 m, or a tenth of the lower building's height 6 m): gaps are in m; did you mean 0.04 m (cm) or 0.004 m (mm)?")
# 0.7 m between 30 m buildings: below 1 m, above a tenth of 6 m.
warned(gap_height "&analysis dt = 0.01, t_end = 1.0 /
&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566 /
${b}
&building name = 'U', n_storeys = 3, height = 3*3.0, mass = 3*10.0, stiffness = 3*1.0e4 /
&contact left = 'T', right = 'U', floors_left = 1, 2, floors_right = 1, 2, gap = 0.7, law = 'elastic', stiffness = 1e6 /
" "&contact #1 (T, U): gap = 0.7 m is above 0.6 m")

# The cheap shipped decks give none of these warnings (the suites' motions: scale factors in
# range, PGAs below 2 g, targets of 3 m/s^2).
file(GLOB shipped ${SOURCE_DIR}/input/*.nml)
foreach(deck ${shipped})
  get_filename_component(stem ${deck} NAME_WE)
  if(stem MATCHES "^suite_")
    continue()
  endif()
  # A deck that reads the records of ../shared runs only where they are (a fresh clone may
  # stand without them).
  file(READ ${deck} deck_text)
  if(deck_text MATCHES "shared/records" AND NOT EXISTS ${SOURCE_DIR}/../shared/records)
    continue()
  endif()
  run_pound(s ${deck} -o shipped --quiet)
  expect_equal("${stem}: exit status (${s_err})" 0 "${s_rc}")
  file(READ ${WORK_DIR}/shipped/${stem}.out listing)
  foreach(needle "is above 2 g" "scale_to needs a scale factor" "did you mean target_g" "gaps are in m")
    string(FIND "${s_out}${listing}" "${needle}" pos)
    expect_equal("${stem}: no '${needle}'" -1 "${pos}")
  endforeach()
endforeach()
