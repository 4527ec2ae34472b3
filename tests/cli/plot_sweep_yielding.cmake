# scripts/plot on a gap sweep of yielding buildings (tests/data/sweep_yielding.nml: bilinear
# storeys, target_quantities = 'drift ductility'): the sweep plot and the yielding buildings'
# plot of the drift and ductility lambdas against the gap (/sweep/max_abs_lambda/<b>/drift,
# /ductility) as valid PNG and PDF files; the sweep plot's legend names storey shear and
# storey drift apart (they differ once storeys yield).
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(PLOT ${SOURCE_DIR}/scripts/plot_results.py)
run_pound(r ${SOURCE_DIR}/tests/data/sweep_yielding.nml --quiet)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/sweep_yielding.h5 --only sweep RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
foreach(p sweep sweep_yielding)
  set(png ${WORK_DIR}/sweep_yielding_${p}.png)
  set(pdf ${WORK_DIR}/sweep_yielding_${p}.pdf)
  if(NOT EXISTS ${png} OR NOT EXISTS ${pdf})
    message(FATAL_ERROR "plot ${p}: missing PNG or PDF\n${out}\n${err}")
  endif()
  expect_png("plot ${p}" ${png})
  file(READ ${pdf} head LIMIT 5 HEX)
  expect_equal("PDF header of ${p} (%PDF-)" "255044462d" "${head}")
endforeach()
# The legends, from the figures as drawn (matplotlib's Agg backend, no display).
execute_process(COMMAND ${PY} -c "
import sys, matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
sys.path.insert(0, '${SOURCE_DIR}/scripts')
import plot_results as pr
seen = {}
def keep(fig, r, name, args, written):
    seen[name] = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
pr.save = keep
r = pr.read_results('${WORK_DIR}/sweep_yielding.h5')
pr.plot_sweep(plt, r, None, [], [])
assert 'storey shear Q' in seen['sweep'] and 'storey drift' in seen['sweep'], seen['sweep']
assert not any('(= storey drift)' in t for t in seen['sweep']), seen['sweep']
assert 'storey drift' in seen['sweep_yielding'] and 'storey ductility mu' in seen['sweep_yielding'], seen
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("legends (${out}${err})" 0 "${rc}")
