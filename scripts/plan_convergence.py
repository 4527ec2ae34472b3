"""Buildings in plan: how the plane-shear influence coefficients move as dt halves, at the
default setting and at the accurate setting (called by scripts/plan_convergence).

    plan_convergence.py EXE [DECK] [--dts 1e-3,5e-4,2.5e-4,1.25e-4] [--storeys 10]
                        [--record elCentro_Peknold.AT2 | pulse] [--records DIR] [--t-end 20]

DECK: a plan deck (its &analysis is rewritten for each run: dt, stepping, free_steps; every
other variable kept, history = 'none'). Without DECK: the eccentric plan pair of
scripts/bench_plan.py (centre of mass at 0.6 Lx, 0.6 Ly, partial facade overlap, friction 0.3,
ground at 30 degrees) with --storeys storeys under --record (skipped cleanly when the record
is absent). Settings:
- default: stepping = 'uniform', free_steps = 'newmark';
- accurate: stepping = 'impact', free_steps = 'exact' (docs/manual.md, "The accurate setting").
For each setting and dt: the largest |lambda| change of /influence/<b>/plane_shear over every
building, plane and storey, in percentage points (NaN entries, an uncoupled peak of 0, left
out): against the next halving, against the same setting's finest dt, and against the accurate
setting's finest dt (the reference); the program's coupled loop time (HDF5
/coupled@integration_seconds) and the process cpu time, each as a ratio to the default
setting's run at the largest dt (medians of --repeats runs of each deck, default 3; the loop
time is wall time: run on a quiet machine).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bench_plan import decks  # noqa: E402
from opensees_plan import read_namelists  # noqa: E402

SETTINGS = {"default": dict(stepping="uniform", free_steps="newmark"),
            "accurate": dict(stepping="impact", free_steps="exact")}


def group_span(text, name):
    """(start, end) of the first &name group in the deck text: from '&' to its closing '/'
    (outside quotes and '!' comments)."""
    low = text.lower()
    i = 0
    while True:
        i = low.find("&" + name, i)
        if i < 0:
            raise SystemExit(f"plan_convergence: no &{name} in the deck")
        line_start = text.rfind("\n", 0, i) + 1
        if "!" not in text[line_start:i]:
            break
        i += 1
    j, quote = i + len(name) + 1, None
    while j < len(text):
        ch = text[j]
        if quote:
            quote = None if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            j = text.find("\n", j)
            if j < 0:
                break
        elif ch == "/":
            return i, j + 1
        j += 1
    raise SystemExit(f"plan_convergence: &{name} is not closed")


def fmt(v):
    if isinstance(v, bool):
        return ".true." if v else ".false."
    if isinstance(v, str):
        return "'" + v.replace("'", "''") + "'"
    return repr(v)


def rewrite(text, name, drop, put):
    """The deck with its first &name group written anew: its variables less `drop`, plus `put`."""
    i, j = group_span(text, name)
    body = dict(read_namelists(text[i:j])[0][1])
    for k in drop:
        body.pop(k, None)
    body.update({k: [v] for k, v in put.items()})
    new = f"&{name}\n" + "".join(f"   {k} = {', '.join(fmt(v) for v in vals)}\n" for k, vals in body.items()) + "/"
    return text[:i] + new + text[j:]


def with_analysis(text, dt, setting):
    """The deck with its &analysis rewritten: dt, the setting's options, history = 'none'."""
    return rewrite(text, "analysis", ("dt", "stepping", "free_steps", "impact_substeps", "history", "output_every"),
                   dict(dt=dt, history="none", **SETTINGS[setting]))


def absolute_records(text, folder):
    """The deck with &ground's record files as absolute paths (the runs are elsewhere)."""
    i, j = group_span(text, "ground")
    body = read_namelists(text[i:j])[0][1]
    put = {k: os.path.normpath(os.path.join(folder, body[k][0])) for k in ("file", "file_2")
           if k in body and not os.path.isabs(body[k][0])}
    return rewrite(text, "ground", (), put) if put else text


def run(exe, text, path):
    """(lambdas {building: array}, coupled loop seconds, process cpu seconds)."""
    import h5py
    with open(path, "w") as f:
        f.write(text)
    out = os.path.dirname(path)
    with open(os.devnull, "wb") as null:
        proc = subprocess.Popen([exe, path, "-o", out], stdout=null, stderr=subprocess.PIPE)
        _, status, usage = os.wait4(proc.pid, 0)
        err = proc.stderr.read().decode(errors="replace")
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(err.strip())
    stem = os.path.splitext(os.path.basename(path))[0]
    with h5py.File(os.path.join(out, stem + ".h5"), "r") as f:
        lam = {b: np.asarray(f[f"/influence/{b}/plane_shear"][()]) for b in f["/influence"].keys()
               if f"/influence/{b}/plane_shear" in f}
        loop = float(f["/coupled"].attrs["integration_seconds"])
    return lam, loop, usage.ru_utime + usage.ru_stime


def max_change(a, b):
    return max(float(np.nanmax(np.abs(a[k] - b[k]))) for k in a)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("deck", nargs="?")
    ap.add_argument("--dts", default="1e-3,5e-4,2.5e-4,1.25e-4")
    ap.add_argument("--storeys", type=int, default=10)
    ap.add_argument("--record", default="elCentro_Peknold.AT2", help="a file of --records, or 'pulse'")
    ap.add_argument("--records", default=os.path.join(os.path.dirname(HERE), "..", "shared", "records"))
    ap.add_argument("--t-end", type=float, default=20.0)
    ap.add_argument("--repeats", type=int, default=3, help="runs of each deck; times are their medians")
    a = ap.parse_intermixed_args()
    dts = sorted((float(x) for x in a.dts.split(",")), reverse=True)
    if a.deck:
        text = absolute_records(open(a.deck).read(), os.path.dirname(os.path.abspath(a.deck)))
        name = os.path.basename(a.deck)
    else:
        record = None
        if a.record != "pulse":
            record = os.path.abspath(os.path.join(a.records, a.record))
            if not os.path.isfile(record):
                print(f"plan_convergence: skipped: no record {record} (shared/records beside the clone; or --record pulse)")
                return
        text = decks(a.storeys, record, "eccentric", dts[0], a.t_end)[0]
        name = f"eccentric plan pair, {a.storeys} storeys, friction 0.3, {os.path.basename(record) if record else 'pulse'}"
    exe = os.path.abspath(a.exe)
    res, settings = {}, []
    with tempfile.TemporaryDirectory() as tmp:
        for setting in SETTINGS:
            try:
                for dt in dts:
                    runs = [run(exe, with_analysis(text, dt, setting), os.path.join(tmp, f"plan_{setting}_{len(res)}.nml"))
                            for _ in range(max(1, a.repeats))]
                    res[setting, dt] = (runs[0][0], statistics.median(r[1] for r in runs),
                                        statistics.median(r[2] for r in runs))
                settings.append(setting)
            except RuntimeError as exc:  # e.g. a setting the program refuses for this deck
                if setting == "default":
                    raise SystemExit(f"plan_convergence: pound failed at the default setting:\n{exc}")
                print(f"{setting} setting: pound failed (left out): {exc}")
    best = "accurate" if "accurate" in settings else "default"
    ref = res[best, dts[-1]][0]
    base = res["default", dts[0]]
    print(f"deck: {name}")
    print(f"reference: the {best} setting at dt = {1e3 * dts[-1]:g} ms")
    print("| setting | dt [ms] | change to dt/2 [pp] | against the setting's finest [pp] | against the reference [pp] | "
          f"coupled loop [s] | loop / default at {1e3 * dts[0]:g} ms | process cpu / default |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|")
    for setting in settings:
        finest = res[setting, dts[-1]][0]
        for i, dt in enumerate(dts):
            lam, loop, cpu = res[setting, dt]
            half = f"{max_change(lam, res[setting, dts[i + 1]][0]):.3f}" if i + 1 < len(dts) else "-"
            own = f"{max_change(lam, finest):.3f}" if i + 1 < len(dts) else "-"
            print(f"| {setting} | {1e3 * dt:g} | {half} | {own} | {max_change(lam, ref):.3f} | {loop:.3f} | "
                  f"{loop / base[1]:.2f} | {cpu / base[2]:.2f} |")


if __name__ == "__main__":
    main()
