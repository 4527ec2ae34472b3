"""Convergence of the influence coefficients of the seed pair with each joint law (issue 26)
(called by scripts/law_convergence).

The seed pair (input/two_frames_elastic.nml) with law = elastic (k = 1e6 kN/m), kelvin (k =
1e6 kN/m, e = 0.65), hertz, hertz_damp, jankowski (kh = 3.16e7 kN/m^(3/2), e = 0.65), under
its pulse (5 s) and under El Centro (Peknold, 20 s, when shared/records is beside the clone),
at the accurate setting (stepping = 'impact', free_steps = 'exact', impact_substeps = M, 20 by
default) and, with --settings, others, at each dt of --dts. For each halving of dt the
largest change of the influence coefficients, in percentage points: of the storey shears
(the issue's figure: 0.02 pp, Kelvin 0.08 pp), of the drifts, of the displacements u and of
a_abs, and where the largest storey-shear change is (building, storey). Markdown on stdout.

Last column: the storey-shear (= drift) coefficients with each peak refined between the
samples: pound takes a peak at the step ends (and at the substeps' ends), so a peak inside a
free step is missed by O((omega dt)^2); the column takes, for every storey, the largest |drift|
of the cubic Hermite interpolant through the stored drifts and their rates (histories u, v at
every step) and the tracked peak, whichever is larger, in both analyses.

    scripts/law_convergence [--dts 2e-3,1e-3,5e-4] [--laws elastic,kelvin,...]
                            [--motions pulse,elcentro] [--settings impact-exact-20,...]

A setting is uniform | uniform-exact | impact-exact-M | impact-M.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from work_precision import lambdas  # noqa: E402

LAWS = {
    "elastic": "law = 'elastic'\n   stiffness = 1.0e6\n   dashpot = 0.0",
    "kelvin": "law = 'kelvin'\n   stiffness = 1.0e6\n   restitution = 0.65",
    "hertz": "law = 'hertz'\n   stiffness = 3.16e7",
    "hertz_damp": "law = 'hertz_damp'\n   stiffness = 3.16e7\n   restitution = 0.65",
    "jankowski": "law = 'jankowski'\n   stiffness = 3.16e7\n   restitution = 0.65",
}
OLD = ("law = 'elastic'          ! constraint law\n   stiffness = 1.0e6        ! joint stiffness p (kN/m)\n"
       "   dashpot = 0.0            ! joint dashpot c (kN s/m): none")


def deck_text(root, law, motion, dt, setting, every):
    text = open(os.path.join(root, "input", "two_frames_elastic.nml")).read()
    assert OLD in text
    text = text.replace(OLD, LAWS[law])
    if motion == "elcentro":
        rec = os.path.abspath(os.path.join(root, "..", "shared", "records", "elCentro_Peknold.AT2"))
        text = re.sub(r"(?s)&ground.*?\n/", "&ground\n   kind = 'record'\n   file = '" + rec + "'\n/", text, 1)
        text = text.replace("t_end = 5.0", "t_end = 20.0")
    parts = setting.split("-")
    extra = f"   stepping = '{parts[0]}'\n"
    if "exact" in parts:
        extra += "   free_steps = 'exact'\n"
    if parts[0] == "impact" and parts[-1].isdigit():
        extra += f"   impact_substeps = {parts[-1]}\n"
    text = text.replace("dt = 1.0e-3              ! time step (s)", f"dt = {dt!r}\n" + extra)
    text = text.replace("output_every = 1         ! store every step", f"output_every = {every}")
    text = text.replace("history = 'all'          ! u v a_abs drift storey_shear", "history = 'u v'")
    return text


def run(exe, root, law, motion, dt, setting, every, tmp):
    stem = f"{law}_{motion}_{setting}_{dt:g}".replace(".", "p")
    path = os.path.join(tmp, stem + ".nml")
    with open(path, "w") as f:
        f.write(deck_text(root, law, motion, dt, setting, every))
    p = subprocess.run([exe, path, "-o", tmp], capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"law_convergence: pound failed ({law}, {motion}, {setting}, dt = {dt}):\n{p.stderr}")
    out = lambdas(os.path.join(tmp, stem + ".h5"))
    out.update(refined(os.path.join(tmp, stem + ".h5"), dt))
    return out


def hermite_peak(x, xd, h):
    """Largest |p(s)| of the cubic Hermite interpolants through samples x (rates xd) h apart."""
    import numpy as np

    x0, x1, d0, d1 = x[:-1], x[1:], xd[:-1] * h, xd[1:] * h
    a = 2 * x0 - 2 * x1 + d0 + d1
    b = -3 * x0 + 3 * x1 - 2 * d0 - d1
    c = d0
    best = np.maximum(np.abs(x0), np.abs(x1))
    disc = b * b - 3 * a * c
    ok = disc >= 0
    sq = np.sqrt(np.where(ok, disc, 0.0))
    for sgn in (1.0, -1.0):
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(np.abs(a) > 1e-300, (-b + sgn * sq) / (3 * a), -c / (2 * b))
        inside = ok & (s > 0) & (s < 1)
        best = np.where(inside, np.maximum(best, np.abs(((a * s + b) * s + c) * s + x0)), best)
    return float(best.max())


def refined(h5path, dt):
    """{'B/refined_shear': lambda} of each building, the drift peaks refined between samples
    (the run stores u and v at every step)."""
    import h5py
    import numpy as np

    out = {}
    with h5py.File(h5path, "r") as f:
        for b in f["/model"].keys():
            pk = {}
            for an in ("uncoupled", "coupled"):
                u, v = np.asarray(f[f"/{an}/{b}/u"][()]), np.asarray(f[f"/{an}/{b}/v"][()])
                if u.shape[0] < u.shape[1]:
                    u, v = u.T, v.T
                zero = np.zeros((u.shape[0], 1))
                dr, dv = np.diff(np.hstack([zero, u]), axis=1), np.diff(np.hstack([zero, v]), axis=1)
                tracked = np.asarray(f[f"/{an}/{b}/peak/drift"][()])
                pk[an] = np.maximum(tracked, [hermite_peak(dr[:, j], dv[:, j], dt) for j in range(dr.shape[1])])
            out[f"{b}/refined_shear"] = 100.0 * (pk["coupled"] / pk["uncoupled"] - 1.0)
    return out


def change(a, b, suffix):
    import numpy as np

    best, where = 0.0, "-"
    for k in a:
        if not k.endswith(suffix) or k.count("/") != 1:
            continue
        d = np.abs(a[k] - b[k])
        if d.size and float(d.max()) > best:
            best = float(d.max())
            where = f"{k.split('/')[0]} storey {int(d.argmax()) + 1}"
    return best, where


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", required=True)
    ap.add_argument("--root", required=True)
    ap.add_argument("--dts", default="2e-3,1e-3,5e-4")
    ap.add_argument("--laws", default=",".join(LAWS))
    ap.add_argument("--motions", default="pulse,elcentro")
    ap.add_argument("--settings", default="impact-exact-20")
    a = ap.parse_args()
    dts = sorted((float(x) for x in a.dts.split(",")), reverse=True)
    every = lambda dt: 1
    print("| motion | law | setting | dt -> dt/2 [ms] | storey shear [pp] (where) | drift [pp] | u [pp] | "
          "a_abs [pp] | storey shear, peaks refined [pp] |")
    print("|---|---|---|---|--:|--:|--:|--:|--:|")
    with tempfile.TemporaryDirectory() as tmp:
        for motion in a.motions.split(","):
            for law in a.laws.split(","):
                for setting in a.settings.split(","):
                    lam = [run(a.exe, a.root, law, motion, dt, setting, every(dt), tmp) for dt in dts]
                    for i in range(len(dts) - 1):
                        s, where = change(lam[i], lam[i + 1], "storey_shear")
                        dr, _ = change(lam[i], lam[i + 1], "drift")
                        u, _ = change(lam[i], lam[i + 1], "/u")
                        acc, _ = change(lam[i], lam[i + 1], "a_abs")
                        ref, _ = change(lam[i], lam[i + 1], "refined_shear")
                        print(f"| {motion} | {law} | {setting} | {1e3 * dts[i]:g} -> {1e3 * dts[i + 1]:g} | "
                              f"{s:.4f} ({where}) | {dr:.4f} | {u:.4f} | {acc:.4f} | {ref:.4f} |", flush=True)


if __name__ == "__main__":
    main()
