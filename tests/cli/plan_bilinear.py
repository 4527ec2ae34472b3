"""Checks of bilinear planes (tests/cli/plan_bilinear.cmake).

centre PLAN.h5 SHEAR.h5: the plan building's single bilinear 'x' plane through the centre of
    mass equals the bilinear shear building's storey, both analyses, to round-off.
eccentric PLAN.h5 SUMMARY.csv: every bilinear plane's peak force within Fy (1 - r + |r| mu)
    (|f - r k d| <= (1 - r) Fy at every step), an elastic plane's ductility 0, the energy
    audit closed with the plastic work equal to the planes' hysteretic energy, the summary's
    largest plane-storey ductility the largest of /coupled/A/peak/plane_ductility.
"""
import csv
import sys

import h5py
import numpy as np


def close(what, a, b, rtol=1e-9, atol=0.0):
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    if a.shape != b.shape or not np.allclose(a, b, rtol=rtol, atol=atol):
        sys.exit(f"{what}: {a} != {b}")


def centre(plan, shear):
    p = h5py.File(plan, "r")
    s = h5py.File(shear, "r")
    for an in ("uncoupled", "coupled"):
        a, b = p[an]["A"], s[an]["A"]
        if p[f"{an}/A/peak/plane_ductility"].shape != (3, 1):
            sys.exit(f"{an}: plane_ductility shape {p[an + '/A/peak/plane_ductility'].shape}, not (3, 1)")
        close(f"{an} peak plane shear", a["peak/plane_shear"][0, 0], b["peak/storey_shear"][0])
        close(f"{an} peak storey shear", a["peak/storey_shear"][()], b["peak/storey_shear"][()])
        close(f"{an} ductility", a["peak/plane_ductility"][0, 0], b["peak/ductility"][0])
        close(f"{an} residual drift", a["plane_residual_drift"][0, 0], b["residual_drift"][0])
        close(f"{an} hysteretic energy", a["hysteretic_energy"][()], b["hysteretic_energy"][()])
        close(f"{an} peak drift", a["peak/drift"][()], b["peak/drift"][()])
        if not b["peak/ductility"][0] > 2.0:
            sys.exit(f"{an}: the storey does not yield enough to test anything (mu {b['peak/ductility'][0]})")
        # The elastic 'y' planes: no ductility, no residual drift.
        close(f"{an} elastic planes' ductility", a["peak/plane_ductility"][1:, 0], [0.0, 0.0])
        close(f"{an} elastic planes' residual drift", a["plane_residual_drift"][1:, 0], [0.0, 0.0], atol=1e-15)
    if list(p["/model/A/plane_storey_law"].asstr()[()]) != ["bilinear", "elastic", "elastic"]:
        sys.exit("plane_storey_law")
    close("plane_yield_shear", p["/model/A/plane_yield_shear"][()], [[60.0], [np.inf], [np.inf]])


def eccentric(plan, summary):
    f = h5py.File(plan, "r")
    fy = f["/model/A/plane_yield_shear"][()]
    r = f["/model/A/plane_hardening_ratio"][()]
    law = list(f["/model/A/plane_storey_law"].asstr()[()])
    if law != ["bilinear", "elastic", "bilinear", "elastic"]:
        sys.exit(f"plane_storey_law {law}")
    bil = np.isfinite(fy)
    for an in ("uncoupled", "coupled"):
        g = f[an]["A"]
        mu = g["peak/plane_ductility"][()]
        ps = g["peak/plane_shear"][()]
        if mu.shape != (4, 2) or ps.shape != (4, 2) or g["plane_residual_drift"].shape != (4, 2):
            sys.exit(f"{an}: shapes {mu.shape} {ps.shape}")
        env = fy[bil] * (1.0 - r[bil] + np.abs(r[bil]) * mu[bil])
        if np.any(ps[bil] > env * (1.0 + 1e-9)):
            sys.exit(f"{an}: plane force beyond the bilinear envelope: {ps[bil]} > {env}")
        if not np.all(mu[bil] > 1.0):
            sys.exit(f"{an}: every bilinear plane storey should yield here: mu {mu}")
        if np.any(mu[~bil] != 0.0):
            sys.exit(f"{an}: an elastic plane has a ductility {mu}")
        e = g.parent["energy"]
        comp = e.attrs["components"].split() if isinstance(e.attrs["components"], str) else \
            e.attrs["components"].decode().split()
        plastic = e[-1, comp.index("plastic")]
        close(f"{an} plastic work = hysteretic energy", plastic, g["hysteretic_energy"][()], rtol=1e-9)
        limit = 1e-10 if an == "uncoupled" else 1e-3
        if not e.attrs["relative_error"] < limit:
            sys.exit(f"{an}: energy audit {e.attrs['relative_error']} >= {limit}")
    rows = list(csv.reader(open(summary)))
    hit = [row for row in rows if "plane_ductility" in row]
    if not hit:
        sys.exit(f"no plane_ductility item in {summary}")
    value = float(hit[0][hit[0].index("plane_ductility") + 1])
    mu = f["coupled/A/peak/plane_ductility"][()]
    close("summary's largest plane ductility", value, mu.max(), rtol=1e-3)
    p, j = np.unravel_index(np.argmax(mu), mu.shape)
    if f"plane {p + 1} " not in ",".join(hit[0]) or f"storey {j + 1}" not in ",".join(hit[0]):
        sys.exit(f"summary item does not name plane {p + 1} storey {j + 1}: {hit[0]}")


if __name__ == "__main__":
    if sys.argv[1] == "centre":
        centre(sys.argv[2], sys.argv[3])
    else:
        eccentric(sys.argv[2], sys.argv[3])
    print("ok")
