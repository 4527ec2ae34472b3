#!/usr/bin/env python3
"""Independent reference for src/model/pound_synthetic_motion.f90 (run once; its output is
pasted into tests/test_synthetic_motion.pf). The filters use the closed-form Nigam-Jennings
coefficients (Chopra, Dynamics of Structures, Table 5.2.1) instead of pound's matrix
exponential; the white noise comes from random_reference.py."""
import math
import sys

from random_reference import Xoshiro


def nigam_jennings(w, z, h):
    wd = w * math.sqrt(1 - z * z)
    ex, sn, cs = math.exp(-z * w * h), math.sin(wd * h), math.cos(wd * h)
    r, k = z / math.sqrt(1 - z * z), w * w
    a = ex * (r * sn + cs)
    b = ex * sn / wd
    c = (2 * z / (w * h) + ex * (((1 - 2 * z * z) / (wd * h) - r) * sn - (1 + 2 * z / (w * h)) * cs)) / k
    d = (1 - 2 * z / (w * h) + ex * ((2 * z * z - 1) / (wd * h) * sn + 2 * z / (w * h) * cs)) / k
    a2 = -ex * w / math.sqrt(1 - z * z) * sn
    b2 = ex * (cs - r * sn)
    c2 = (-1 / h + ex * ((w / math.sqrt(1 - z * z) + r / h) * sn + cs / h)) / k
    d2 = (1 - ex * (r * sn + cs)) / (k * h)
    return a, b, c, d, a2, b2, c2, d2


def filtered(force, w, z, h, through):
    """Response outputs of u'' + 2 z w u' + w^2 u = force: x'' (+ force if `through`)."""
    a, b, c, d, a2, b2, c2, d2 = nigam_jennings(w, z, h)
    u = v = 0.0
    out = [force[0] if through else 0.0]
    for i in range(1, len(force)):
        u, v = (a * u + b * v + c * force[i - 1] + d * force[i],
                a2 * u + b2 * v + c2 * force[i - 1] + d2 * force[i])
        out.append(-(2 * z * w * v + w * w * u) + (force[i] if through else 0.0))
    return out


def envelope(cfg, t):
    if cfg["envelope"] == "saragoni_hart":
        eps, eta = cfg["eps"], cfg["eta"]
        b = -eps * math.log(eta) / (1 + eps * (math.log(eps) - 1))
        tp = eps * cfg["duration"]
        return 0.0 if t <= 0 else (t / tp) ** b * math.exp(b * (1 - t / tp))
    if t < cfg["t1"]:
        return (t / cfg["t1"]) ** 2
    if t <= cfg["t2"]:
        return 1.0
    return math.exp(-cfg["c"] * (t - cfg["t2"]))


def end_state(a, h):
    v = u = 0.0
    for i in range(len(a) - 1):
        s = a[i] + a[i + 1]
        u += h * v + 0.25 * h * h * s
        v += 0.5 * h * s
    return v, u


def synthetic(cfg, h):
    n = int(math.floor(cfg["duration"] / h + 1e-9))
    g = Xoshiro(cfg["seed"])
    noise = [g.normal() for _ in range(n + 1)]
    s = filtered([-x for x in noise], cfg["wg"], cfg["zg"], h, through=False)
    if cfg["filter"] == "clough_penzien":
        s = filtered(s, cfg["wf"], cfg["zf"], h, through=True)
    env = [envelope(cfg, i * h) for i in range(n + 1)]
    ramp = [env[i] * (i * h / (n * h)) for i in range(n + 1)]
    a = [s[i] * env[i] for i in range(n + 1)]
    (v1, d1), (v2, d2), (v3, d3) = end_state(a, h), end_state(env, h), end_state(ramp, h)
    det = v2 * d3 - v3 * d2
    c1 = (v1 * d3 - v3 * d1) / det
    c2 = (v2 * d1 - v1 * d2) / det
    a = [a[i] - c1 * env[i] - c2 * ramp[i] for i in range(n + 1)]
    peak = max(abs(x) for x in a)
    return [x * cfg["pga"] / peak for x in a]


CASES = {
    "kt_jennings": dict(filter="kanai_tajimi", wg=15.0, zg=0.6, envelope="jennings", t1=1.0,
                        t2=3.0, c=0.5, duration=5.0, pga=2.943, seed=2026),
    "cp_saragoni_hart": dict(filter="clough_penzien", wg=12.0, zg=0.4, wf=1.5, zf=0.6,
                             envelope="saragoni_hart", eps=0.2, eta=0.05, duration=5.0,
                             pga=1.0, seed=-3),
}

if __name__ == "__main__":
    dt = 0.01
    for name, cfg in CASES.items():
        a = synthetic(cfg, dt)
        ipk = max(range(len(a)), key=lambda i: abs(a[i]))
        idx = [2, 3, 4, 101, 251, 401, len(a)]
        print(name, "n =", len(a), "peak index", ipk + 1)
        for i in idx:
            print(f"  a({i}) = {a[i - 1]!r}")
    sys.exit(0)
