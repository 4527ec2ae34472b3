"""The suite study of scripts/bench_suite with OpenSeesPy on the same model (optional
comparison, called by `scripts/bench_suite --opensees`; run with an interpreter that has
`openseespy`, e.g. a virtual environment: python3 -m venv /tmp/venv; /tmp/venv/bin/pip install
openseespy numpy h5py).

    bench_suite_opensees.py MOTIONS.h5 GAPS_RUN GAPS_ALL

MOTIONS.h5 is a pound results file of the suite deck with `histories = .true.` on every motion
(its /suite/<motion>/ground/acceleration at every step, dt from the root attribute `dt`). The
model: per building a chain of zeroLength springs in one dimension, floor masses, storey
stiffness k_j (minus P_j/h_j with P-Delta, the chord geometric stiffness pound uses), Rayleigh
damping from the building's modes 1 and 2 on its own nodes and springs; per contact pair a
zeroLength element of ElasticPPGap (compression, the pair's gap, the joint stiffness); Newmark
average acceleration, Newton, dt of the deck. The seed pair's data are those of
input/two_frames_elastic.nml (written below). Each motion is run uncoupled once and coupled at
GAPS_RUN gaps evenly spread over the GAPS_ALL gaps of the sweep; the time per coupled run is
extrapolated to the whole study. Prints one line: `opensees_seconds <estimated study time>`.
"""
import os
import sys
import tempfile
import time

import h5py
import numpy as np
import openseespy.opensees as ops

G = 9.81
# The seed pair (input/two_frames_elastic.nml): storeys, storey height, floor load (kN),
# storey stiffness 2 x 12 E I / h^3 (kN/m), damping ratio, P-Delta.
BUILDINGS = [
    dict(n=3, h=3.0, load=4.0 * 98.1, k=2 * 12 * 3.4e7 * 3.2e-3 / 27.0, zeta=0.05, pdelta=False),
    dict(n=8, h=3.0, load=1.0 * 98.1, k=2 * 12 * 2.1e8 * 1.072e-3 / 27.0, zeta=0.03, pdelta=True),
]
PAIRS = [(1, 1), (2, 2), (3, 3)]
JOINT_K = 1.0e6
ENVELOPE = os.path.join(tempfile.gettempdir(), f"pound_bench_opensees_{os.getpid()}.out")


def storey_stiffness(b):
    k = np.full(b["n"], b["k"])
    if b["pdelta"]:
        above = b["load"] * np.arange(b["n"], 0, -1)
        k = k - above / b["h"]
    return k


def rayleigh(b):
    """a0, a1 from the modes 1 and 2 of (K+G, M)."""
    k = storey_stiffness(b)
    n = b["n"]
    kk = np.zeros((n, n))
    for j in range(n):
        kk[j, j] += k[j]
        if j + 1 < n:
            kk[j, j] += k[j + 1]
            kk[j, j + 1] = kk[j + 1, j] = -k[j + 1]
    m = b["load"] / G
    w = np.sqrt(np.sort(np.linalg.eigvalsh(kk / m)))
    w1, w2 = w[0], w[1]
    a0 = b["zeta"] * 2.0 * w1 * w2 / (w1 + w2)
    a1 = b["zeta"] * 2.0 / (w1 + w2)
    return a0, a1


def run(ag, dt, gap, joint=None, series_dt=None, steps=None, test=("NormDispIncr", 1.0e-10, 20), algorithm="Newton"):
    """One analysis (gap None: uncoupled); the peak floor displacements go to an envelope
    recorder (OpenSees' own loop over the steps, no Python per step). `joint(ip, tag)` makes
    pair ip's material (default ElasticPPGap of JOINT_K and the gap); the ground motion is
    sampled at `series_dt` (default dt); `steps` steps of dt (default all of ag); `test` and
    `algorithm` those of OpenSees."""
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    floor_node = []
    ele = 0
    for ib, b in enumerate(BUILDINGS):
        base = 1000 * (ib + 1)
        ops.node(base, 0.0)
        ops.fix(base, 1)
        nodes, eles = [], []
        k = storey_stiffness(b)
        for j in range(1, b["n"] + 1):
            ops.node(base + j, 0.0)
            ops.mass(base + j, b["load"] / G)
            ops.uniaxialMaterial("Elastic", base + j, float(k[j - 1]))
            ele += 1
            # -doRayleigh 1: without it a zeroLength element has no Rayleigh stiffness part.
            ops.element("zeroLength", ele, base + j - 1, base + j, "-mat", base + j, "-dir", 1,
                        "-doRayleigh", 1)
            nodes.append(base + j)
            eles.append(ele)
        a0, a1 = rayleigh(b)
        # One region of the springs: it sets alphaM on their nodes too (a second region of the
        # elements would reset the nodes' alphaM of a region of the nodes to 0).
        ops.region(10 * ib + 1, "-ele", *eles, "-rayleigh", a0, a1, 0.0, 0.0)
        floor_node.append(nodes)
    if gap is not None:
        for ip, (fl, fr) in enumerate(PAIRS):
            mat = 9000 + ip
            if joint is None:
                ops.uniaxialMaterial("ElasticPPGap", mat, JOINT_K, -1.0e12, -gap)
            else:
                joint(ip, mat)
            ele += 1
            ops.element("zeroLength", ele, floor_node[0][fl - 1], floor_node[1][fr - 1], "-mat", mat, "-dir", 1)
    ops.timeSeries("Path", 1, "-dt", series_dt or dt, "-values", *ag.tolist())
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test(*test)
    ops.algorithm(algorithm)
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    every = [n for nodes in floor_node for n in nodes]
    ops.recorder("EnvelopeNode", "-file", ENVELOPE, "-node", *every, "-dof", 1, "disp")
    if ops.analyze(steps or len(ag) - 1, dt) != 0:
        raise RuntimeError("OpenSees analysis failed")
    ops.wipe()


def main():
    path, gaps_run, gaps_all = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    with h5py.File(path, "r") as f:
        dt = float(f.attrs["dt"])
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f["suite/names"][()]]
        motions = [f[f"suite/{n.strip()}/ground/acceleration"][()] for n in names]
    all_gaps = np.linspace(0.0, 0.010, gaps_all)
    chosen = all_gaps[np.linspace(0, gaps_all - 1, gaps_run).round().astype(int)]
    t_unc = t_cpl = 0.0
    for ag in motions:
        start = time.process_time()
        run(ag, dt, None)
        t_unc += time.process_time() - start
        start = time.process_time()
        for gap in chosen:
            run(ag, dt, float(gap))
        t_cpl += time.process_time() - start
    per_coupled = t_cpl / (len(motions) * len(chosen))
    total = t_unc + per_coupled * len(motions) * gaps_all
    print(f"opensees_per_coupled_run {per_coupled:.4f}")
    print(f"opensees_seconds {total:.2f}")


if __name__ == "__main__":
    main()
