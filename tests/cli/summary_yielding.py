"""Checks of the summary of yielding buildings (tests/cli/summary_yielding.cmake) against the
results file it is made from: summary_yielding.py KIND CSV H5 [STDOUT]; KIND is 'storeys',
'hinges' or 'suite'. Exit 1 with one line per failure."""
import csv
import math
import re
import sys

import h5py
import numpy as np

fails = []


def check(ok, what):
    if not ok:
        fails.append(what)


def rows(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def row(rs, subject, quantity, kind=None):
    hit = [r for r in rs if r["subject"] == subject and r["quantity"] == quantity and (kind is None or r["kind"] == kind)]
    check(len(hit) == 1, f"{subject}/{quantity}: {len(hit)} rows")
    return hit[0] if hit else None


def close(a, b, rel=1e-9):
    return abs(a - b) <= rel * max(abs(a), abs(b), 1e-300)


def largest(lam, mask=None):
    ok = np.isfinite(lam) if mask is None else mask & np.isfinite(lam)
    j = int(np.argmax(np.where(ok, np.abs(lam), -1.0)))
    return j, lam[j]


def order(rs, b):
    return [r["quantity"] for r in rs if r["subject"] == b and r["kind"] == "building"]


def storeys(rs, f):
    for b in ("A", "B"):
        lam = f[f"/influence/{b}/drift"][()]
        j, v = largest(lam)
        r = row(rs, b, "lambda_storey_drift")
        check(close(float(r["value"]), v) and r["location"] == f"storey {j + 1}", f"{b} drift lambda {r}")
        mu_u = f[f"/uncoupled/{b}/peak/ductility"][()]
        mu_c = f[f"/coupled/{b}/peak/ductility"][()]
        lam = f[f"/influence/{b}/ductility"][()]
        j, v = largest(lam)
        r = row(rs, b, "lambda_ductility")
        check(close(float(r["value"]), v), f"{b} ductility lambda {r['value']} != {v}")
        check(r["location"].startswith(f"storey {j + 1}: mu uncoupled {mu_u[j]:.2f}, coupled {mu_c[j]:.2f}; "),
              f"{b} ductility lambda location {r['location']}")
        check(r["location"].count(" -> ") == len(mu_u) + 1, f"{b}: every storey on the ductility line")
        jc = int(np.argmax(mu_c))
        r = row(rs, b, "ductility")
        m = re.search(r"uncoupled \(same storey\) (\S+)", r["location"])
        check(close(float(r["value"]), mu_c[jc]) and m is not None and close(float(m.group(1)), mu_u[jc], 1e-6),
              f"{b} ductility coupled against the same storey uncoupled {r}")
        new = [k + 1 for k in range(len(mu_u)) if mu_c[k] > 1.0 >= mu_u[k]]
        r = row(rs, b, "storeys_yielding_only_with_pounding")
        check(int(r["value"]) == len(new), f"{b} new yielding {r['value']} != {new}")
        if new:
            check(r["location"].startswith("storeys " + ", ".join(map(str, new)) + " ("), f"{b} new storeys {r}")
        q = order(rs, b)
        check(q.index("lambda_storey_drift") == 0 and q.index("lambda_storey_shear") > q.index("lambda_ductility"),
              f"{b} order {q}")
    for a in ("uncoupled", "coupled"):
        n = sum(int(f[f"/{a}/{b}"].attrs["collapse_storey"]) > 0 for b in ("A", "B"))
        check(int(row(rs, "run", f"collapses_{a}")["value"]) == n, f"collapses {a}")


def hinges(rs, f):
    for b in ("A", "B"):
        pu = f[f"/uncoupled/{b}/hinges/plastic_rotation"][()]
        pc = f[f"/coupled/{b}/hinges/plastic_rotation"][()]
        lam = f[f"/influence/{b}/plastic_rotation"][()]
        new = [h for h in range(len(pu)) if pc[h] > 0 and (pu[h] <= 0 or np.isnan(lam[h]))]
        r = row(rs, b, "hinges_forming_only_with_pounding")
        check(int(r["value"]) == len(new), f"{b} new hinges {r['value']} != {len(new)}")
        for h in new[:8]:
            check(f"hinge {h + 1} (" in r["location"], f"{b} new hinge {h + 1} named")
        both = (pu > 0) & np.isfinite(lam)
        r = row(rs, b, "lambda_plastic_rotation")
        if both.any():
            j, v = largest(lam, both)
            check(close(float(r["value"]), v) and r["location"].startswith(f"hinge {j + 1} ("),
                  f"{b} plastic-rotation lambda {r} != {j + 1} {v}")
        r = row(rs, b, "plastic_rotation")
        h = int(np.argmax(pc))
        m = re.search(r"uncoupled \(same hinge\) (\S+) mrad", r["location"])
        check(m is not None and close(float(m.group(1)), 1e3 * pu[h], 1e-6), f"{b} same hinge {r}")


def suite(rs, f):
    tot = np.zeros(2, int)
    per = None
    for b in ("A", "B"):
        cs = f[f"/suite/yielding/{b}/collapse_storey"][()]     # (n_motions, 2)
        c = (cs > 0).astype(int)
        tot += c.sum(axis=0)
        per = c.sum(axis=1) if per is None else per + c.sum(axis=1)
        mu_u, mu_c = f[f"/suite/yielding/{b}/mean_ductility"][()]   # (2: uncoupled, coupled; n_storeys)
        lam = (mu_c - mu_u) / mu_u * 100
        j, v = largest(lam)
        r = row(rs, b, "lambda_mean_ductility", "suite")
        check(close(float(r["value"]), v, 1e-9) and r["location"].startswith(f"storey {j + 1}:"),
              f"{b} suite ductility lambda {r} != {j + 1} {v}")
        lam = f[f"/suite/lambda_of_means/{b}/drift"][()]
        j, v = largest(lam)
        r = row(rs, b, "lambda_of_means_storey_drift", "suite")
        check(close(float(r["value"]), v), f"{b} suite drift lambda of means {r}")
        lam = f[f"/suite/mean/influence/{b}/drift"][()]
        j, v = largest(lam)
        r = row(rs, b, "mean_lambda_storey_drift", "suite")
        check(close(float(r["value"]), v), f"{b} suite mean drift lambda {r}")
    check(int(row(rs, "suite", "collapses", "suite")["value"]) == tot.sum(), f"suite collapses != {tot.sum()}")
    check(int(row(rs, "suite", "collapses_uncoupled", "suite")["value"]) == tot[0], "suite collapses uncoupled")
    check(int(row(rs, "suite", "collapses_coupled", "suite")["value"]) == tot[1], "suite collapses coupled")
    check(tot.sum() > 0, "the test deck collapses somewhere")
    mot = [r for r in rs if r["quantity"] == "collapses_motion"]
    check([int(r["value"]) for r in mot] == list(per), f"per motion collapses {[r['value'] for r in mot]} != {per}")


kind, path_csv, path_h5 = sys.argv[1:4]
rs = rows(path_csv)
with h5py.File(path_h5, "r") as f:
    {"storeys": storeys, "hinges": hinges, "suite": suite}[kind](rs, f)
if fails:
    print("\n".join(fails))
    sys.exit(1)
