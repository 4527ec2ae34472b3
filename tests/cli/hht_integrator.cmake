# &analysis integrator = 'hht': alpha = 0 gives the plain run's files bit for bit (seed example,
# a suite, the bilinear-storey and plastic-hinge examples); alpha = -0.1 on the seed example and
# the yielding examples runs, names its numerical dissipation in the listing and the HDF5 file,
# and its energy audit closes as Newmark's does.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
function(hht_deck src name alpha)
  file(READ ${src} deck)
  string(REPLACE "&analysis" "&analysis\n   integrator = 'hht', hht_alpha = ${alpha}" deck "${deck}")
  get_filename_component(dir ${src} DIRECTORY)
  file(WRITE ${dir}/${name} "${deck}")
endfunction()
function(same_h5 what a b)
  execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/h5_compare.py ${a} ${b} --ignore-attr deck
                  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE c_rc OUTPUT_VARIABLE c_out ERROR_VARIABLE c_err)
  expect_equal("${what}: ${c_out}${c_err}" 0 "${c_rc}")
endfunction()

# The decks are written beside the originals' copies (records are found relative to the deck).
file(MAKE_DIRECTORY ${WORK_DIR}/in ${WORK_DIR}/plain ${WORK_DIR}/zero ${WORK_DIR}/damped)
configure_file(${SOURCE_DIR}/input/two_frames_pdelta.nml ${WORK_DIR}/in/seed.nml COPYONLY)
configure_file(${SOURCE_DIR}/tests/data/small_suite.nml ${WORK_DIR}/in/suite.nml COPYONLY)
hht_deck(${WORK_DIR}/in/seed.nml seed_zero.nml 0.0)
hht_deck(${WORK_DIR}/in/seed.nml seed_damped.nml -0.1)
hht_deck(${WORK_DIR}/in/suite.nml suite_zero.nml 0.0)
hht_deck(${WORK_DIR}/in/suite.nml suite_damped.nml -0.1)

run_pound(p in/seed.nml -o plain --quiet)
expect_equal("seed exit" 0 "${p_rc}")
run_pound(z in/seed_zero.nml -o zero --quiet)
expect_equal("seed alpha 0 exit" 0 "${z_rc}")
same_h5("seed, alpha = 0 against newmark" plain/seed.h5 zero/seed_zero.h5)
run_pound(d in/seed_damped.nml -o damped --quiet)
expect_equal("seed alpha -0.1 exit" 0 "${d_rc}")
file(READ ${WORK_DIR}/damped/seed_damped.out listing)
expect_contains("listing" "${listing}" "numerical dissipation of the integrator (HHT-alpha)")
execute_process(COMMAND /usr/bin/python3 -c "
import h5py, sys
p = h5py.File('plain/seed.h5', 'r'); d = h5py.File('damped/seed_damped.h5', 'r')
for g in ('uncoupled', 'coupled'):
    assert g + '/energy_numerical' in d, g
    assert g + '/energy_numerical' not in p, g
    ep, ed = p[g + '/energy'].attrs['relative_error'], d[g + '/energy'].attrs['relative_error']
    # closes as Newmark's audit does on the same deck (the coupled residual is the joints')
    assert ed <= max(1e-12, 1.05 * ep), (g, ed, ep)
# the impacts excite the stiff modes: HHT dissipates there
assert d['coupled/energy_numerical'][-1] > 1e-6 * d['coupled/energy'][0, -1], d['coupled/energy_numerical'][-1]
" WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE a_rc OUTPUT_VARIABLE a_out ERROR_VARIABLE a_err)
expect_equal("audit of the damped seed: ${a_out}${a_err}" 0 "${a_rc}")

run_pound(sp in/suite.nml -o plain --quiet)
expect_equal("suite exit" 0 "${sp_rc}")
run_pound(sz in/suite_zero.nml -o zero --quiet)
expect_equal("suite alpha 0 exit" 0 "${sz_rc}")
same_h5("suite, alpha = 0 against newmark" plain/suite.h5 zero/suite_zero.h5)
run_pound(sd in/suite_damped.nml -o damped --quiet)
expect_equal("suite alpha -0.1 exit: ${sd_err}" 0 "${sd_rc}")

# HHT-alpha with yielding buildings: the bilinear-storey example (input/seed_bilinear.nml) and
# the plastic-hinge example (input/seed_frame_hinges.nml), shortened to 2 s: hht_alpha = 0
# gives the Newmark run's files bit for bit; hht_alpha = -0.1 runs, books its numerical
# dissipation, and its energy audit closes as Newmark's does on the same deck.
foreach(stem seed_bilinear seed_frame_hinges)
  file(READ ${SOURCE_DIR}/input/${stem}.nml deck)
  string(REGEX REPLACE "t_end = [0-9.]+" "t_end = 2.0" deck "${deck}")
  file(WRITE ${WORK_DIR}/in/${stem}.nml "${deck}")
  hht_deck(${WORK_DIR}/in/${stem}.nml ${stem}_zero.nml 0.0)
  hht_deck(${WORK_DIR}/in/${stem}.nml ${stem}_damped.nml -0.1)

  run_pound(p in/${stem}.nml -o plain --quiet)
  expect_equal("${stem} exit: ${p_err}" 0 "${p_rc}")
  run_pound(z in/${stem}_zero.nml -o zero --quiet)
  expect_equal("${stem} alpha 0 exit: ${z_err}" 0 "${z_rc}")
  same_h5("${stem}, alpha = 0 against newmark" plain/${stem}.h5 zero/${stem}_zero.h5)
  run_pound(d in/${stem}_damped.nml -o damped --quiet)
  expect_equal("${stem} alpha -0.1 exit: ${d_err}" 0 "${d_rc}")
  file(READ ${WORK_DIR}/damped/${stem}_damped.out listing)
  expect_contains("${stem} listing" "${listing}" "numerical dissipation of the integrator (HHT-alpha)")
  execute_process(COMMAND /usr/bin/python3 -c "
import h5py
p = h5py.File('plain/${stem}.h5', 'r'); d = h5py.File('damped/${stem}_damped.h5', 'r')
for g in ('uncoupled', 'coupled'):
    assert g + '/energy_numerical' in d and g + '/energy_numerical' not in p, g
    ep, ed = p[g + '/energy'].attrs['relative_error'], d[g + '/energy'].attrs['relative_error']
    print(g, ep, ed, d[g + '/energy_numerical'][-1])
    # closes as Newmark's audit does on the same deck (the coupled residual is the joints')
    assert ed <= max(1e-10, 2.0 * ep), (g, ed, ep)
    # HHT dissipates (the yielding excites the stiff modes)
    assert d[g + '/energy_numerical'][-1] > 0.0, g
" WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE a_rc OUTPUT_VARIABLE a_out ERROR_VARIABLE a_err)
  expect_equal("audit of ${stem} with alpha = -0.1: ${a_out}${a_err}" 0 "${a_rc}")
  message(STATUS "${stem}: ${a_out}")
endforeach()
