"""Speed against error for a pound deck (called by scripts/work_precision).

For each time step of a ladder the deck is run (dt, output_every and history replaced in
&analysis so that every run stores u at the same output times) and compared with a reference
run at dt_min / ref_factor. The reference is itself checked against the run at
dt_min / (ref_factor / 2). Errors, for the coupled and the uncoupled analysis separately:
  shear  relative error of the peak storey shears, max over storeys and buildings
  force  relative error of the peak contact forces, max over pairs (coupled only)
  lambda absolute error of the storey-shear influence coefficients, percentage points
  L2     relative L2 error of the floor displacement histories (all floors, common times)
plus the integration time (median of several runs) and the observed order between
neighbouring steps. With --stepping uniform,impact the ladder is run once per time stepping
(`&analysis stepping`; --substeps sets impact_substeps); the reference is always uniform.
Columns stepping and steps taken (base steps plus substeps) tell the series apart.

With --converged the script instead measures the settings against a converged reference of
the influence coefficients (lambda, pp) that it computes itself: uniform runs at h, 2h and 4h
(h = --ref-dt), Richardson-extrapolated at order 2, L = l(h) + (l(h) - l(2h))/3; its own
uncertainty is the largest change of that extrapolation from (2h, 4h) to (h, 2h), stated with
the observed order. Each time step of --dts is run with each setting of --stepping, the
settings interleaved --repeats times (medians of the coupled-loop time), and each time is
also given against the plain run (uniform, Newmark) at --base-dt, as the ratio of the medians
and of the fastest runs (less disturbed on a loaded machine). Errors: lambda of the
storey shears (the figure of the accurate setting's target), of every quantity and member row
(a_abs and the column end forces included), and of the peak contact forces.
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile


def analysis_group_span(text):
    m = re.search(r"&analysis\b", text, re.I)
    if not m:
        raise SystemExit("work_precision: the deck has no &analysis group")
    i, quote = m.end(), None
    while i < len(text):
        ch = text[i]
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            j = text.find("\n", i)
            i = len(text) if j < 0 else j
            continue
        elif ch == "/":
            return m.end(), i
        i += 1
    raise SystemExit("work_precision: &analysis is not closed")


def with_step(text, dt, output_every, stepping="uniform", substeps=0, free="newmark"):
    a, b = analysis_group_span(text)
    body = text[a:b]
    value = r"""('[^']*'|"[^"]*"|[^,\s/]+)"""
    body = re.sub(r"\b(dt|output_every|history|stepping|impact_substeps|free_steps)\s*=\s*" + value + r"\s*,?", " ",
                  body, flags=re.I)
    extra = f" stepping = '{stepping}',"
    if free != "newmark":
        extra += f" free_steps = '{free}',"
    if stepping == "impact" and substeps > 0:
        extra += f" impact_substeps = {substeps},"
    body = f" dt = {dt!r}, output_every = {output_every}, history = 'u'," + extra + body
    return text[:a] + body + text[b:]


def run(exe, deck_text, deck_dir, tag, outdir, dt, out_every, repeats, stepping="uniform", substeps=0,
        free="newmark"):
    path = os.path.join(deck_dir, f".work_precision_{tag}.nml")
    with open(path, "w") as f:
        f.write(with_step(deck_text, dt, out_every, stepping, substeps, free))
    steps = None
    try:
        times_u, times_c = [], []
        for _ in range(repeats):
            p = subprocess.run([exe, path, "-o", outdir], capture_output=True, text=True)
            if p.returncode != 0:
                raise SystemExit(f"work_precision: pound failed at dt = {dt}:\n{p.stderr}")
            times_u.append(float(re.search(r"uncoupled integration:\s+([0-9.Ee+-]+)", p.stdout).group(1)))
            m = re.search(r"\n\s*coupled integration:\s+([0-9.Ee+-]+)", p.stdout)
            times_c.append(float(m.group(1)) if m else float("nan"))
            m = re.search(r"impact stepping:.*\((\d+) steps in all\)", p.stdout) or \
                re.search(r"contact \(LCP\) time:.*, steps (\d+)", p.stdout)
            steps = int(m.group(1)) if m else None
    finally:
        os.remove(path)
    return (os.path.join(outdir, f".work_precision_{tag}.h5"), statistics.median(times_u), statistics.median(times_c),
            steps)


def load(h5path):
    import h5py
    import numpy as np

    out = {}
    with h5py.File(h5path, "r") as f:
        names = list(f["/model"].keys())
        for an in ("uncoupled", "coupled"):
            if an not in f:
                continue
            d = {"shear": {}, "u": {}}
            for b in names:
                d["shear"][b] = np.asarray(f[f"/{an}/{b}/peak/storey_shear"][()])
                d["u"][b] = np.asarray(f[f"/{an}/{b}/u"][()])
            if an == "coupled" and "/coupled/contact/peak_force" in f:
                d["force"] = np.asarray(f["/coupled/contact/peak_force"][()])
            out[an] = d
        out["lambda"] = {b: np.asarray(f[f"/influence/{b}/storey_shear"][()]) for b in names
                         if f"/influence/{b}/storey_shear" in f}
    return out


def errors(run_, ref):
    import numpy as np

    e = {}
    for an in ("uncoupled", "coupled"):
        if an not in ref:
            continue
        r, x = ref[an], run_[an]
        shear = max(float(np.max(np.abs(x["shear"][b] - r["shear"][b]) / np.maximum(np.abs(r["shear"][b]), 1e-300)))
                    for b in r["shear"])
        num = sum(float(np.sum((x["u"][b] - r["u"][b]) ** 2)) for b in r["u"])
        den = sum(float(np.sum(r["u"][b] ** 2)) for b in r["u"])
        e[an] = {"shear": shear, "L2": math.sqrt(num / den) if den > 0 else 0.0}
        if an == "coupled" and "force" in r:
            pos = r["force"] > 0
            e[an]["force"] = float(np.max(np.abs(x["force"][pos] - r["force"][pos]) / r["force"][pos])) \
                if np.any(pos) else 0.0
            e[an]["lambda"] = max((float(np.max(np.abs(run_["lambda"][b] - ref["lambda"][b]))) for b in ref["lambda"]),
                                  default=0.0)
    return e


def order(e1, e2, dt1, dt2):
    if e1 <= 0 or e2 <= 0:
        return float("nan")
    return math.log(e1 / e2) / math.log(dt1 / dt2)


def fmt(x, spec=".2e"):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, spec)


def main():
    ap = argparse.ArgumentParser(prog="work_precision", description=__doc__.splitlines()[0])
    ap.add_argument("deck")
    ap.add_argument("--exe", required=True)
    ap.add_argument("--dts", default="8e-3,4e-3,2e-3,1e-3,5e-4,2.5e-4,1.25e-4")
    ap.add_argument("--ref-factor", type=int, default=8, help="reference dt = smallest dt / this (power of 2)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--outdir", default="out")
    ap.add_argument("--stepping", default="uniform",
                    help="comma separated: uniform, impact, uniform-exact, impact-exact (one ladder each; "
                         "-exact: free_steps = 'exact')")
    ap.add_argument("--substeps", type=int, default=0, help="impact_substeps of the impact ladder (0: automatic)")
    ap.add_argument("--converged", action="store_true",
                    help="errors of lambda against a Richardson-extrapolated reference (see the module doc)")
    ap.add_argument("--ref-dt", type=float, default=3.125e-5, help="--converged: finest reference step h")
    ap.add_argument("--base-dt", type=float, default=1e-3, help="--converged: dt of the plain run the times are "
                    "compared with")
    a = ap.parse_args()
    if a.converged:
        with open(a.deck) as f:
            text = f.read()
        os.makedirs(a.outdir, exist_ok=True)
        return converged(a, text, os.path.dirname(os.path.abspath(a.deck)),
                         os.path.splitext(os.path.basename(a.deck))[0])
    steppings = [x.strip() for x in a.stepping.split(",") if x.strip()]
    kinds = ("uniform", "impact", "uniform-exact", "impact-exact")
    if not steppings or any(x not in kinds for x in steppings):
        raise SystemExit("work_precision: --stepping takes " + ", ".join(kinds))
    dts = sorted((float(s) for s in a.dts.split(",")), reverse=True)
    if len(dts) < 2:
        raise SystemExit("work_precision: give at least two time steps")
    dt_ref = dts[-1] / a.ref_factor
    dt_check = dts[-1] / (a.ref_factor // 2)
    t_out = dts[0]
    every = lambda dt: max(1, round(t_out / dt))
    for dt in dts + [dt_ref, dt_check]:
        if abs(every(dt) * dt - t_out) > 1e-9 * t_out:
            raise SystemExit(f"work_precision: dt = {dt} does not divide the largest dt {t_out}")
    with open(a.deck) as f:
        text = f.read()
    deck_dir = os.path.dirname(os.path.abspath(a.deck))
    stem = os.path.splitext(os.path.basename(a.deck))[0]
    os.makedirs(a.outdir, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        ref_path, _, _, _ = run(a.exe, text, deck_dir, "ref", tmp, dt_ref, every(dt_ref), 1)
        ref = load(ref_path)
        chk_path, _, _, _ = run(a.exe, text, deck_dir, "check", tmp, dt_check, every(dt_check), 1)
        check = errors(load(chk_path), ref)
        series = {}
        for sp in steppings:
            rows = []
            for i, dt in enumerate(dts):
                stepping, _, free = sp.partition("-")
                p, tu, tc, steps = run(a.exe, text, deck_dir, f"{sp}{i}", tmp, dt, every(dt), a.repeats, stepping,
                                       a.substeps, free or "newmark")
                rows.append((dt, tu, tc, errors(load(p), ref), steps))
            series[sp] = rows
    coupled = "coupled" in ref
    lines = [f"Deck `{os.path.basename(a.deck)}`; reference dt = {dt_ref:g} s (uniform); outputs compared every "
             f"{t_out:g} s; times: median of {a.repeats} runs of the time-step loop.", ""]
    for an in ("uncoupled", "coupled") if coupled else ("uncoupled",):
        c = check[an]
        note = f"reference check (dt = {dt_check:g} against {dt_ref:g}): shear {fmt(c['shear'])}, L2 {fmt(c['L2'])}"
        if an == "coupled":
            note += f", force {fmt(c.get('force'))}, lambda {fmt(c.get('lambda'), '.3f')} pp"
        lines += [f"**{an}** — {note}", ""]
        head = "| stepping | dt [s] | steps taken | time [ms] | peak shear err | order | L2 u err | order |"
        sep = "|---|--:|--:|--:|--:|--:|--:|--:|"
        if an == "coupled":
            head += " peak force err | order | lambda err [pp] |"
            sep += "--:|--:|--:|"
        lines += [head, sep]
        shown_free = set()
        for sp, rows in series.items():
            free = sp.partition("-")[2] or "newmark"
            if an == "uncoupled" and free in shown_free:
                continue  # the uncoupled analysis is uniform whatever the stepping (exact or not)
            shown_free.add(free)
            for i, (dt, tu, tc, e, steps) in enumerate(rows):
                t = tc if an == "coupled" else tu
                prev = rows[i - 1] if i > 0 else None
                o_s = order(prev[3][an]["shear"], e[an]["shear"], prev[0], dt) if prev else None
                o_l = order(prev[3][an]["L2"], e[an]["L2"], prev[0], dt) if prev else None
                shown = sp if an == "coupled" else ("uniform-exact" if free == "exact" else "uniform")
                taken = steps if (an == "coupled" and steps is not None) else "-"
                line = (f"| {shown} | {dt:g} | {taken} | {1e3 * t:.2f} | {fmt(e[an]['shear'])} | {fmt(o_s, '.2f')} | "
                        f"{fmt(e[an]['L2'])} | {fmt(o_l, '.2f')} |")
                if an == "coupled":
                    o_f = order(prev[3][an]["force"], e[an]["force"], prev[0], dt) if prev else None
                    line += f" {fmt(e[an].get('force'))} | {fmt(o_f, '.2f')} | {fmt(e[an].get('lambda'), '.3f')} |"
                lines.append(line)
        lines.append("")
    md = "\n".join(lines)
    print(md)
    with open(os.path.join(a.outdir, f"{stem}_wp.md"), "w") as f:
        f.write(md + "\n")
    plot(series, coupled, os.path.join(a.outdir, f"{stem}_wp"), os.path.basename(a.deck))
    # The reference must be much closer to the limit than the finest run of the ladder.
    status = 0
    rows = series[steppings[0]]
    for an in ("uncoupled", "coupled") if coupled else ("uncoupled",):
        finest = rows[-1][3][an]
        for key in ("shear", "L2"):
            if check[an][key] > 0.5 * finest[key]:
                print(f"work_precision: warning: the reference has not converged for {an} {key}: "
                      f"{check[an][key]:.2e} between the two finest steps, {finest[key]:.2e} at dt = {rows[-1][0]:g}",
                      file=sys.stderr)
                status = 3
    return status


def lambdas(h5path):
    """Every influence coefficient of a result file: {dataset path: array} (sweep groups left out)."""
    import h5py
    import numpy as np

    out = {}
    with h5py.File(h5path, "r") as f:
        if "/influence" not in f:
            return out

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
                out[name] = np.asarray(obj[()], dtype=float)
        f["/influence"].visititems(visit)
    return out


def lambda_error(x, ref, keys):
    import numpy as np

    vals = [float(np.max(np.abs(x[k] - ref[k]))) for k in keys if k in ref and ref[k].size]
    return max(vals) if vals else float("nan")


def converged(a, text, deck_dir, stem):
    """--converged: the settings at each dt against the Richardson-extrapolated reference."""
    import numpy as np

    steppings = [x.strip() for x in a.stepping.split(",") if x.strip()]
    dts = sorted((float(s) for s in a.dts.split(",")), reverse=True)
    h = a.ref_dt
    t_out = max(dts + [a.base_dt])
    every = lambda dt: max(1, round(t_out / dt))
    with tempfile.TemporaryDirectory() as tmp:
        lam = []
        for k, hh in enumerate((h, 2 * h, 4 * h)):
            p, _, tc, _ = run(a.exe, text, deck_dir, f"{stem}_ref{k}", tmp, hh, every(hh), 1)
            lam.append(lambdas(p))
        keys = sorted(lam[0])
        rich = {k: lam[0][k] + (lam[0][k] - lam[1][k]) / 3.0 for k in keys}
        rich2 = {k: lam[1][k] + (lam[1][k] - lam[2][k]) / 3.0 for k in keys}
        unc = {k: float(np.max(np.abs(rich[k] - rich2[k]))) for k in keys}
        orders = []
        for k in keys:
            d1, d2 = np.abs(lam[2][k] - lam[1][k]), np.abs(lam[1][k] - lam[0][k])
            ok = (d2 > 1e-9) & (d1 > 1e-9)
            orders += list(np.log2(d1[ok] / d2[ok]))
        shear_keys = [k for k in keys if k.endswith("/storey_shear") and k.count("/") == 1]
        results = {}
        runs = [(sp, dt) for dt in dts for sp in steppings]
        if ("uniform", a.base_dt) not in runs:
            runs.append(("uniform", a.base_dt))
        times = {r: [] for r in runs}
        info = {}
        for rep in range(a.repeats):
            for i, (sp, dt) in enumerate(runs):
                stepping, _, free = sp.partition("-")
                p, _, tc, steps = run(a.exe, text, deck_dir, f"{stem}_c{i}", tmp, dt, every(dt), 1, stepping, a.substeps,
                                      free or "newmark")
                times[(sp, dt)].append(tc)
                if rep == 0:
                    x = lambdas(p)
                    info[(sp, dt)] = (steps, lambda_error(x, rich, shear_keys), lambda_error(x, rich, keys),
                                      lambda_error(x, rich, [k for k in keys if k.endswith("/a_abs")]))
    base = statistics.median(times[("uniform", a.base_dt)])
    u_shear = max((unc[k] for k in shear_keys), default=float("nan"))
    u_all = max(unc.values(), default=float("nan"))
    lines = [f"Deck `{os.path.basename(a.deck)}`: converged reference of the influence coefficients by Richardson "
             f"extrapolation of uniform runs at h = {h:g}, 2h, 4h s (observed order median "
             f"{fmt(float(np.median(orders)) if orders else float('nan'), '.2f')}); its uncertainty (change of the "
             f"extrapolation from (2h, 4h) to (h, 2h)): storey-shear lambda {u_shear:.1e} pp, every lambda "
             f"{u_all:.1e} pp. Times: medians of {a.repeats} interleaved runs of the coupled time-step loop; "
             f"ratio against the plain run (uniform, Newmark) at dt = {a.base_dt:g} s ({1e3 * base:.2f} ms).", "",
             "| setting | dt [s] | steps taken | coupled loop [ms] | x plain | x plain (fastest runs) | "
             "lambda err, storey shear [pp] | lambda err, every quantity [pp] | of which a_abs [pp] |",
             "|---|--:|--:|--:|--:|--:|--:|--:|--:|"]
    for (sp, dt) in runs:
        steps, e_s, e_a, e_acc = info[(sp, dt)]
        t = statistics.median(times[(sp, dt)])
        fastest = min(times[(sp, dt)]) / min(times[("uniform", a.base_dt)])
        lines.append(f"| {sp} | {dt:g} | {steps if steps is not None else '-'} | {1e3 * t:.2f} | {t / base:.2f} | "
                     f"{fastest:.2f} | {e_s:.4f} | {e_a:.4f} | {e_acc:.4f} |")
    md = "\n".join(lines)
    print(md)
    with open(os.path.join(a.outdir, f"{stem}_converged.md"), "w") as f:
        f.write(md + "\n")
    return 0


def plot(all_rows, coupled, base, title):
    """Error against time, one front per stepping (the uniform and the impact-aware side by side)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    colours = {"uniform": "black", "impact": "tab:red", "uniform-exact": "tab:blue", "impact-exact": "tab:green"}
    first = next(iter(all_rows))
    for sp, rows in all_rows.items():
        lines = []
        if sp == first:
            lines += [("uncoupled", "shear", "uncoupled: peak storey shear", "-", "o"),
                      ("uncoupled", "L2", "uncoupled: L2 of u", ":", "s")]
        if coupled:
            lines += [("coupled", "shear", f"coupled ({sp}): peak storey shear", "-", "^"),
                      ("coupled", "L2", f"coupled ({sp}): L2 of u", ":", "D"),
                      ("coupled", "force", f"coupled ({sp}): peak contact force", "--", "v")]
        for an, key, label, ls, mk in lines:
            t = [1e3 * (r[2] if an == "coupled" else r[1]) for r in rows]
            e = [r[3][an][key] for r in rows]
            colour = colours[sp] if an == "coupled" else "0.5"
            ax.loglog(t, e, color=colour, linestyle=ls, marker=mk, markersize=4, label=label)
    ax.set_xlabel("time of the time-step loop [ms]")
    ax.set_ylabel("relative error against the reference")
    ax.set_title(f"Speed against error: {title}", fontsize=10)
    ax.grid(True, which="both", color="0.85", linewidth=0.5)
    ax.legend(fontsize=6)
    fig.tight_layout()
    for ext in ("png", "pdf"):
        fig.savefig(f"{base}.{ext}", dpi=150)
    print(f"wrote {base}.png and {base}.pdf")


if __name__ == "__main__":
    sys.exit(main())
