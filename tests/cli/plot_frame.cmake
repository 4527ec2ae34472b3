# input/frame_to_column.nml runs from a fresh clone and scripts/plot draws its frame geometry
# with the six contact points (floors facing columns between floors); the listing names the
# column ends by elevation and has the column-segment table. The results file holds the
# column segments' peaks and lambdas and each frame's deformed shapes at the storey-shear
# peaks; the `deformed` plot (most affected storey, uncoupled and coupled side by side) runs, and
# the `columns` plot (column-segment lambdas along the facing column lines) too.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
set(PLOT ${SOURCE_DIR}/scripts/plot_results.py)
run_pound(r ${SOURCE_DIR}/input/frame_to_column.nml)
expect_equal("pound exit (${r_err})" 0 "${r_rc}")
file(READ ${WORK_DIR}/frame_to_column.out listing)
expect_contains("listing pair label" "${listing}" "A:3-B:z=10.50m")
expect_contains("listing pair label" "${listing}" "A:z=3.00m-B:1")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/frame_to_column.h5 --only frame --format png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
expect_png("plot frame (${out} ${err})" ${WORK_DIR}/frame_to_column_frame.png)
expect_contains("listing column table" "${listing}" "Column segments: peak first-order end forces")
execute_process(COMMAND ${PY} -c "
import h5py, numpy as np
f = h5py.File('${WORK_DIR}/frame_to_column.h5', 'r')
for b in ('A', 'B'):
    seg = f['model/' + b + '/columns'][...]
    n = seg.shape[1]
    for an in ('uncoupled', 'coupled'):
        for q in ('shear', 'moment_bottom', 'moment_top', 'axial'):
            assert f[an + '/' + b + '/columns/' + q].shape == (n,), (an, b, q)
        d = f[an + '/' + b + '/deformed'][...]
        assert d.shape == (len(f['model/' + b + '/height']), f['model/' + b + '/dofs'].shape[1]), d.shape
        assert np.all(f[an + '/' + b + '/deformed_time'][...] == f[an + '/' + b + '/peak_time/storey_shear'][...])
    lam = f['influence/' + b + '/columns/shear'][...]
    qc, qu = f['coupled/' + b + '/columns/shear'][...], f['uncoupled/' + b + '/columns/shear'][...]
    assert np.allclose(lam, (qc - qu) / qu * 100, rtol=1e-12, atol=0), b
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("HDF5 checks (${err})" 0 "${rc}")
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/frame_to_column.h5 --only deformed --format png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
expect_png("plot deformed (${out} ${err})" ${WORK_DIR}/frame_to_column_deformed.png)
execute_process(COMMAND ${PY} ${PLOT} ${WORK_DIR}/frame_to_column.h5 --only columns --format png
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("plot exit (${err})" 0 "${rc}")
expect_png("plot columns (${out} ${err})" ${WORK_DIR}/frame_to_column_columns.png)
