"""The sweep's ductility |lambda| at the deck's gap equals the run's: for every building with
bilinear storeys, max |/influence/<b>/ductility| == /sweep/max_abs_lambda/<b>/ductility at the
sweep gap equal to GAP (m), bit for bit, and it is not 0 (pounding changes the ductility).

usage: sweep_ductility.py FILE.h5 GAP
"""
import sys

import h5py
import numpy as np


def main(path, gap):
    with h5py.File(path, "r") as f:
        gaps = f["/sweep/gap"][()]
        i = int(np.argmin(np.abs(gaps - gap)))
        if abs(gaps[i] - gap) > 1e-12:
            print(f"no sweep gap at {gap} m: {gaps}")
            return 1
        checked = 0
        for b in f["/influence"]:
            if "ductility" not in f[f"/influence/{b}"]:
                continue
            run = float(np.max(np.abs(f[f"/influence/{b}/ductility"][()])))
            swept = float(f[f"/sweep/max_abs_lambda/{b}/ductility"][()][i])
            print(f"{b}: run {run!r}, sweep at {gaps[i]} m {swept!r}")
            if run != swept:
                return 1
            checked += 1 if run > 0.0 else 0
        if checked == 0:
            print("no building whose ductility pounding changes")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], float(sys.argv[2])))
