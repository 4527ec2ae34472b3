"""Add a synthetic /risk group to a pound results file (the layout of scripts/plot_risk.py), for
the plot test: 8 stripes, 6 motions, 5 gaps; contact likelier at higher stripes and smaller gaps;
one n/a fit per outcome (all zero at the largest gap, with its `na` attribute); contact, lambda
exceeded and collapse, whose probability stays above the target (no risk-targeted gap: NaN).

usage: /usr/bin/python3 plot_risk_fixture.py FILE.h5"""
import math, sys
import h5py
import numpy as np

levels = np.array([0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0])
gaps = np.array([0.0, 0.01, 0.02, 0.03, 0.04])
motions = [f"FF{k:02d}a" for k in range(1, 7)]
rng = np.random.default_rng(7)
with h5py.File(sys.argv[1], "a") as f:
    r = f.create_group("risk")
    r.attrs["years"] = 50.0
    r.attrs["target_probability"] = 0.1
    r.create_dataset("stripes/levels", data=levels).attrs["units"] = "m/s^2"
    r.create_dataset("motions", data=np.array(motions, dtype="S"))
    r.create_dataset("gaps", data=gaps).attrs["units"] = "m"
    for o, scale in (("contact", 1.0), ("lambda_exceeded", 2.5), ("collapse", 100.0)):
        med = scale * (1.0 + 60.0 * gaps)
        x = np.zeros((gaps.size, levels.size, len(motions)), dtype=np.int8)
        for g in range(gaps.size):
            p = np.array([0.5 * math.erfc(-math.log(l / med[g]) / 0.5 / math.sqrt(2)) for l in levels])
            x[g] = (rng.random((levels.size, len(motions))) < p[:, None]).astype(np.int8)
        x[-1] = 0
        r.create_dataset(f"outcomes/{o}", data=x)
        beta = np.full(gaps.size, 0.5)
        med[-1] = beta[-1] = np.nan
        d = r.create_dataset(f"fragility/{o}/median", data=med)
        d.attrs["na"] = np.array(["", "", "", "", "all zero"], dtype="S")
        r.create_dataset(f"fragility/{o}/beta", data=beta)
        maf = scale * 1e-3 / (1.0 + 100.0 * gaps) ** 2
        r.create_dataset(f"maf/{o}", data=maf)
        r.create_dataset(f"probability/{o}", data=1.0 - np.exp(-50.0 * maf))
        r.create_dataset(f"gap/{o}", data={"contact": 0.0, "lambda_exceeded": 0.01}.get(o, np.nan))
