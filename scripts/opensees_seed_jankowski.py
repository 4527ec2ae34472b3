"""Speed of pound against OpenSeesPy on the seed pair with Jankowski joints under El Centro
(issue 26; optional: needs `openseespy`, not a dependency of pound; run with a Python that has
it, numpy and h5py, e.g. python3 -m venv /tmp/venv; /tmp/venv/bin/pip install openseespy numpy
h5py):

    /path/to/python scripts/opensees_seed_jankowski.py POUND_EXE [REPEATS]

The deck is input/seed_jankowski.nml (beta = 2.75e6 kN/m^(3/2), e = 0.65, gaps 1 mm) under
El Centro (Peknold, 20 s, shared/records beside the clone). pound runs at the accurate setting
(stepping = 'impact', free_steps = 'exact', impact_substeps = 20) at dt = 1 ms; its error is
measured against its own run at dt = 0.125 ms (same setting). The OpenSees model is the one of
scripts/bench_suite_opensees.py (per building a chain of zeroLength storey springs, floor
masses, storey stiffness minus P/h with P-Delta, Rayleigh damping of modes 1 and 2 on each
building's own nodes and springs) with a zeroLength JankowskiImpact element per pair (beta, xi
of e, m_eff of the facing floors, gap), Newmark average acceleration, Krylov-Newton (NormDispIncr
1e-9, 100 iterations: plain Newton fails to converge in some impact steps), the record as a
Path series; its error is measured against its own run at the finest dt of the ladder. Error:
the largest relative error of the coupled peak floor displacements |u| over both buildings.
The OpenSees dt is the largest of the ladder whose error is at most pound's (else the finest but one). Then both whole
processes are timed, interleaved, REPEATS times (default 5): pound on the deck, and this
script's own OpenSees run in a fresh interpreter (`--one DT`), wall time, medians, ratio.
"""
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from bench_suite_opensees import BUILDINGS, ENVELOPE, G, run  # noqa: E402  (the same model)

RECORD = os.path.abspath(os.path.join(ROOT, "..", "shared", "records", "elCentro_Peknold.AT2"))
BETA, E, GAP = 2.75e6, 0.65, 1.0e-3
T_END = 20.0


def record():
    text = open(RECORD).read().splitlines()
    dt = float(re.search(r"DT=\s*([0-9.]+)", text[3]).group(1))
    values = [float(x) for line in text[4:] for x in line.split()]
    return dt, np.array(values) * G


def opensees_peaks(dt):
    """The coupled run at dt: peak |u| of every floor (A then B)."""
    import openseespy.opensees as ops

    rdt, ag = record()
    xi = 9.0 * math.sqrt(5.0) * (1.0 - E * E) / (2.0 * E * (E * (9.0 * math.pi - 16.0) + 16.0))
    m1, m2 = BUILDINGS[0]["load"] / G, BUILDINGS[1]["load"] / G

    def joint(ip, tag):
        ops.uniaxialMaterial("JankowskiImpact", tag, BETA, xi, m1 * m2 / (m1 + m2), -GAP)

    run(ag, dt, GAP, joint=joint, series_dt=rdt, steps=int(round(T_END / dt)), test=("NormDispIncr", 1.0e-9, 100),
        algorithm="KrylovNewton")
    rows = np.loadtxt(ENVELOPE)
    os.remove(ENVELOPE)
    return np.max(np.abs(rows), axis=0)


def pound_deck(tmp, dt):
    text = open(os.path.join(ROOT, "input", "seed_jankowski.nml")).read()
    text = re.sub(r"(?s)&ground.*?\n/", "&ground\n   kind = 'record'\n   file = '" + RECORD + "'\n/", text, 1)
    text = text.replace("t_end = 5.0", f"t_end = {T_END}")
    text = text.replace("dt = 1.0e-3              ! time step (s)",
                        f"dt = {dt!r}\n   stepping = 'impact'\n   free_steps = 'exact'\n   impact_substeps = 20")
    text = text.replace("history = 'all'          ! u v a_abs drift storey_shear", "history = 'none'")
    path = os.path.join(tmp, f"seed_jankowski_ec_{dt:g}.nml".replace(".", "p", 1))
    open(path, "w").write(text)
    return path


def pound_peaks(exe, tmp, dt):
    import h5py

    path = pound_deck(tmp, dt)
    subprocess.run([exe, path, "-o", tmp], check=True, capture_output=True)
    with h5py.File(path[:-4] + ".h5", "r") as f:
        return np.concatenate([np.asarray(f[f"/coupled/{b}/peak/u"][()]) for b in ("A", "B")])


def rel_error(x, ref):
    return float(np.max(np.abs(x - ref) / np.abs(ref)))


def wall(cmd):
    start = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True)
    return time.perf_counter() - start


def main():
    if sys.argv[1] == "--one":
        opensees_peaks(float(sys.argv[2]))
        return
    exe = os.path.abspath(sys.argv[1])
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    with tempfile.TemporaryDirectory() as tmp:
        ref = pound_peaks(exe, tmp, 1.25e-4)
        acc = pound_peaks(exe, tmp, 1.0e-3)
        e_pound = rel_error(acc, ref)
        print(f"pound, impact + exact + 20 substeps, dt = 1 ms: peak |u| error {e_pound:.2e} (against dt = 0.125 ms)")
        ladder = [1e-3, 5e-4, 2.5e-4, 1.25e-4, 6.25e-5, 3.125e-5]
        peaks = {}
        for dt in ladder:
            try:
                peaks[dt] = opensees_peaks(dt)
            except RuntimeError as exc:
                print(f"OpenSees: {exc} (Newton did not converge in a step; left out)")
        ladder = [dt for dt in ladder if dt in peaks]
        os_ref = peaks[ladder[-1]]
        print("| OpenSees dt [ms] | peak |u| error (against the finest) | against pound's reference |")
        print("|--:|--:|--:|")
        chosen = None
        for dt in ladder[:-1]:
            e = rel_error(peaks[dt], os_ref)
            print(f"| {1e3 * dt:g} | {e:.2e} | {rel_error(peaks[dt], ref):.2e} |")
            if e <= e_pound and chosen is None:
                chosen = dt
        print(f"OpenSees finest ({1e3 * ladder[-1]:g} ms) against pound's reference: {rel_error(os_ref, ref):.2e}")
        if chosen is None:
            chosen = ladder[-2]
            print("no OpenSees dt of the ladder reaches pound's error; timing the finest but one")
        deck = pound_deck(tmp, 1.0e-3)
        t_p, t_o = [], []
        for _ in range(repeats):
            t_p.append(wall([exe, deck, "-o", tmp]))
            t_o.append(wall([sys.executable, os.path.abspath(__file__), "--one", repr(chosen)]))
        mp, mo = statistics.median(t_p), statistics.median(t_o)
        print(f"whole processes, {repeats} interleaved runs, medians: pound (dt = 1 ms, accurate setting) "
              f"{mp:.3f} s, OpenSeesPy (dt = {1e3 * chosen:g} ms) {mo:.3f} s, ratio {mo / mp:.1f}")


if __name__ == "__main__":
    main()
