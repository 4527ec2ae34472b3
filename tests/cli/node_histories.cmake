# The program with &analysis node_histories on a frame deck: the histories are then held in
# memory (not streamed), /coupled/<b>/u_nodes holds every DOF, its floor rows equal u, and the
# floor histories equal those of the same deck without node histories (streamed) bit for bit.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(PY /usr/bin/python3)
file(READ ${SOURCE_DIR}/input/two_frames_fe.nml deck)
string(REPLACE "&analysis" "&analysis node_histories = .true.," deck "${deck}")
file(WRITE ${WORK_DIR}/nodes.nml "${deck}")
run_pound(n ${WORK_DIR}/nodes.nml)
expect_equal("pound exit with node histories (${n_err})" 0 "${n_rc}")
run_pound(p ${SOURCE_DIR}/input/two_frames_fe.nml)
expect_equal("pound exit without (${p_err})" 0 "${p_rc}")
execute_process(COMMAND ${PY} -c "
import h5py, numpy as np
a = h5py.File('${WORK_DIR}/nodes.h5', 'r'); b = h5py.File('${WORK_DIR}/two_frames_fe.h5', 'r')
for an in ('uncoupled', 'coupled'):
    for bl in ('A', 'B'):
        un, u = a[an + '/' + bl + '/u_nodes'][...], a[an + '/' + bl + '/u'][...]
        dofs = a['model/' + bl + '/dofs'][...]
        assert un.shape[0] == u.shape[0] and un.shape[1] == dofs.shape[1], (un.shape, dofs.shape)
        for q in ('u', 'v', 'a_abs', 'drift', 'storey_shear'):
            assert (a[an + '/' + bl + '/' + q][...] == b[an + '/' + bl + '/' + q][...]).all(), q
        rows = [np.where((un == u[:, [j]]).all(axis=0))[0] for j in range(u.shape[1])]
        assert all(len(r) > 0 for r in rows), 'a floor history is not among the DOF histories'
    assert 'u_nodes' not in b[an + '/A']
print('ok')
" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
expect_equal("HDF5 checks (${err})" 0 "${rc}")
