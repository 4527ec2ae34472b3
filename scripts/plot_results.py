"""Plots of a pound results file (.h5), written as PNG and PDF beside it (called by scripts/plot).

    plot_results.py FILE.h5 [--only LIST] [--outdir DIR] [--format png,pdf] [--t-max T]

Plots (names for --only): displacement (facing floors, gap shaded), force (contact force
histories), loops (force-penetration loops of each joint), shear (storey-shear envelopes, coupled
against uncoupled), influence (influence coefficients, storeys x buildings as in the paper's
Table 1), ground (ground motion), sweep (largest |lambda| against the joint gap, when the file
holds a gap study), suite (a file with /suite, from a deck with several &ground: the plots of
scripts/plot_suite.py, <stem>_suite_spectra, _suite_lambda, _suite_separation, _suite_sweep),
frame (the buildings' geometry side by side, frames with their nodes and elements, with the
contact points: only when the file holds a frame model), deformed (each frame's deformed shape,
scaled, at the peak storey shear of its most affected storey (largest |lambda| of the storey
shear), uncoupled and coupled side by side: only for frames with /<analysis>/<b>/deformed and a
coupled analysis), columns (influence coefficients of the column segments of each frame, shear
and end moment, against the segment's mid-height, one line per column line facing a neighbour,
the contact elevations marked: only for frames with /influence/<b>/columns), study (the studies of
the joint, scripts/plot_studies.py: <stem>_stiffness_sweep or _restitution_sweep, the largest
|lambda| and every pair's peak force against the swept value; <stem>_law_study, one bar per
variant: only when the file holds /stiffness_sweep, /restitution_sweep or /law_study), risk (a file
with /risk, from a deck with &stripes and &hazard: the plots of scripts/plot_risk.py,
<stem>_risk_fragility, the fragility curves with the stripe fractions at a few gaps, and
_risk_probability, P in `years` against the gap with the target), separation
(the separation rules of every contact pair as computed, with the codes' factors, n/a not drawn,
and each building's property-line setback; the title says which peaks they used: only for a
single-motion run with contact, /separation). Files are named <stem>_<plot>.png / .pdf.

Any problem with the file (missing, not HDF5, not a pound results file) gives one line
"plot: error: ..." on stderr and exit status 1; usage errors exit 2. POUND_DEBUG=1 shows
the traceback of unexpected failures.
"""
import argparse
import os
import re
import sys
import tempfile

PLOTS = ("displacement", "force", "loops", "shear", "influence", "ground", "sweep", "suite", "frame",
         "deformed", "columns", "study", "hysteresis", "risk", "separation", "plan")
# The sweep's column-segment target quantities of frames (/sweep/max_abs_lambda/<b>/<q>, where targeted).
COLUMN_TARGETS = {"column_shear": "column segment shear V", "column_moment": "column segment end moment M"}
CONTACT_PLOTS = ("displacement", "force", "loops")
QUANTITY_LABEL = {
    "storey_shear": ("storey shear Q", "storey"),
    "drift": ("storey drift", "storey"),
    "u": ("floor displacement u", "floor"),
    "v": ("floor velocity v", "floor"),
    "a_abs": ("floor absolute acceleration", "floor"),
}
# The acceleration of gravity (m/s^2) of files that predate the root attribute `g` (pound has
# always used 9.81); a file that has the attribute gives its own (Results.g).
G_DEFAULT = 9.81

# Black-and-white friendly styles: every series differs in line style and marker, colour is extra.
COLOURS = ("black", "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00")
LINESTYLES = ("-", "--", ":", "-.", (0, (5, 1, 1, 1, 1, 1)), (0, (1, 1)))
MARKERS = ("o", "s", "^", "D", "v", "x")
HATCHES = ("", "////", "xxxx", "....", "\\\\\\\\", "++++")
FILLS = ("0.35", "white", "0.8", "white", "0.6", "white")


class PlotError(Exception):
    """A problem with the input that is reported as one line."""


# --------------------------------------------------------------------------------------------
# Reading


class Results:
    """Everything the plots need, read from the file into memory."""

    def __init__(self):
        self.path = ""
        self.title = ""
        self.dt = None
        self.g = G_DEFAULT             # acceleration of gravity (m/s^2), root attribute g
        self.units = ""              # the file's units, root attribute units
        self.buildings = []          # names, left to right when the deck tells
        self.model = {}              # name -> dict of arrays
        self.analyses = {}           # 'uncoupled'/'coupled' -> {'time', name -> {q: hist}, 'peak'}
        self.ground = {}
        self.contact = None          # dict or None
        self.influence = {}          # name -> {q: array}
        self.columns = {}            # frame name -> {'line', 'z_mid', 'z_bottom', 'z_top', member q: lambda}
        self.sweep = None            # gap study: {'gap', 'lambda': name -> {q: array}, 'target', 'safe_gap'}


def _deck_building_order(deck_text, names):
    """Building names in deck order (left to right), when the deck text gives them."""
    found = []
    for group in re.finditer(r"&building\b(.*?)(?:^\s*/|/\s*$)", deck_text, re.S | re.I | re.M):
        m = re.search(r"\bname\s*=\s*(['\"])(.*?)\1", group.group(1), re.I)
        if m and m.group(2).strip() in names and m.group(2).strip() not in found:
            found.append(m.group(2).strip())
    return found if sorted(found) == sorted(names) else sorted(names)


def _text(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if hasattr(value, "shape") and getattr(value, "shape", None) == ():
        return _text(value[()])
    if hasattr(value, "tolist") and not isinstance(value, str):
        v = value.tolist()
        return _text(v[0]) if isinstance(v, list) and v else str(v)
    return str(value)


def parse_pair(label, names):
    """'A:1-B:3' -> ('A', 1, 'B', 3), building names checked against the model (a contact point of
    buildings in plan, 'A:1-B:3@y=2.50m', is its pair's)."""
    label = label.split("@")[0]
    for m in re.finditer(r"-", label):
        left, right = label[: m.start()], label[m.end():]
        lm = re.fullmatch(r"(.+):(\d+)", left)
        rm = re.fullmatch(r"(.+):(\d+)", right)
        if lm and rm and lm.group(1) in names and rm.group(1) in names:
            return lm.group(1), int(lm.group(2)), rm.group(1), int(rm.group(2))
    return None


def pair_elevations(label, names, heights):
    """'A:z=3.00m-B:1' -> ('A', 3.0, 'B', z of B's floor 1): each end's elevation (m) from its floor
    (the building's storey heights) or from the 'z=<metres>m' of a column point (pound before
    issue 27 wrote 'z<metres>m', also read); None if unknown."""
    import numpy as np

    def end(text):
        m = re.fullmatch(r"(.+):(?:(\d+)|z=?([0-9.]+)m)", text)
        if not m or m.group(1) not in names:
            return None
        if m.group(2) is not None:
            j = int(m.group(2))
            h = heights[m.group(1)]
            return (m.group(1), float(np.sum(h[:j]))) if 1 <= j <= len(h) else None
        return m.group(1), float(m.group(3))

    label = label.split("@")[0]
    for m in re.finditer(r"-", label):
        a, b = end(label[: m.start()]), end(label[m.end():])
        if a and b:
            return a[0], a[1], b[0], b[1]
    return None


def single_motion_heading(f):
    """'motion k of n: NAME' of a suite's file (several &ground): the motion whose results are
    /uncoupled, /coupled, /sweep (root attribute `single_motion_heading`; older files: the first
    motion that did not fail)."""
    heading = _text(f.attrs.get("single_motion_heading", "")).strip()
    if heading:
        return heading
    names = [_text(n).strip() for n in f["suite/names"][...]]
    failed = list(f["suite/motion_failed"][...]) if "suite/motion_failed" in f else [0] * len(names)
    k = next((i for i, x in enumerate(failed) if not x), 0)
    return f"motion {k + 1} of {len(names)}: {names[k]}" if names else "motion ?"


def read_results(path):
    import h5py
    import numpy as np

    if not os.path.exists(path):
        raise PlotError(f"{path}: no such file")
    if os.path.isdir(path):
        raise PlotError(f"{path}: is a directory, not a results file")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        reason = str(e).split("(")[0].strip().rstrip(",") or "cannot open"
        raise PlotError(f"{path}: not a readable HDF5 file ({reason})") from None

    def need(name):
        if name not in f:
            raise PlotError(f"{path}: not a pound results file (no {name})")
        obj = f[name]
        return obj

    def arr(name, ndim=None):
        obj = need(name)
        if not isinstance(obj, h5py.Dataset):
            raise PlotError(f"{path}: {name} is not a dataset")
        try:
            a = np.asarray(obj[()], dtype=float)
        except (TypeError, ValueError, OSError) as e:
            raise PlotError(f"{path}: cannot read {name}: {e}") from None
        if ndim is not None and a.ndim != ndim:
            raise PlotError(f"{path}: {name} has {a.ndim} dimensions, expected {ndim}")
        return a

    r = Results()
    r.path = path
    with f:
        r.title = _text(f.attrs.get("title", os.path.basename(path))).strip()
        if "suite" in f:
            answer = _text(f.attrs.get("suite_answer", "")).strip()
            r.title += "\n" + single_motion_heading(f) + " (this motion alone; " + \
                (answer if answer else "the suite's answer: the suite plots") + ")"
        if "dt" in f.attrs:
            r.dt = float(np.asarray(f.attrs["dt"]).ravel()[0])
        if "g" in f.attrs:
            r.g = float(np.asarray(f.attrs["g"]).ravel()[0])
            if not (np.isfinite(r.g) and r.g > 0.0):
                raise PlotError(f"{path}: root attribute g = {r.g} is not a positive acceleration")
        r.units = _text(f.attrs.get("units", "")).strip()
        model = need("/model")
        names = list(model.keys())
        if not names:
            raise PlotError(f"{path}: /model holds no building")
        r.buildings = _deck_building_order(_text(f.attrs.get("deck", "")), names)
        for b in r.buildings:
            r.model[b] = {"height": arr(f"/model/{b}/height", 1)}
            for k in ("periods", "mass", "storey_stiffness"):
                if f"/model/{b}/{k}" in f:
                    r.model[b][k] = arr(f"/model/{b}/{k}", 1)
            if f"/model/{b}/nodes" in f and f"/model/{b}/elements" in f:
                r.model[b]["nodes"] = arr(f"/model/{b}/nodes", 2)
                r.model[b]["elements"] = arr(f"/model/{b}/elements", 2)
                if f"/model/{b}/node_dofs" in f and f"/model/{b}/node_coefficients" in f:
                    r.model[b]["node_dofs"] = arr(f"/model/{b}/node_dofs", 2).astype(int)
                    r.model[b]["node_coefficients"] = arr(f"/model/{b}/node_coefficients", 2)
        r.ground["time"] = arr("/ground/time", 1)
        r.ground["acceleration"] = arr("/ground/acceleration", 1)
        if r.ground["time"].shape != r.ground["acceleration"].shape:
            raise PlotError(f"{path}: /ground/time and /ground/acceleration differ in length")
        r.ground["description"] = _text(f["/ground"].attrs.get("description", "")).strip()
        r.ground["units"] = _text(f["/ground/acceleration"].attrs.get("units", "m/s^2")).strip() or "m/s^2"
        need("/uncoupled/time")
        for an in ("uncoupled", "coupled"):
            if an not in f:
                continue
            time = arr(f"/{an}/time", 1)
            data = {"time": time}
            for b in r.buildings:
                n = len(r.model[b]["height"])
                d = {"peak": {}}
                for q in QUANTITY_LABEL:
                    name = f"/{an}/{b}/{q}"
                    if name in f:
                        h = arr(name, 2)
                        if h.shape != (len(time), n):
                            raise PlotError(f"{path}: {name} has shape {h.shape}, expected ({len(time)}, {n})")
                        d[q] = h
                    pname = f"/{an}/{b}/peak/{q}"
                    if pname in f:
                        d["peak"][q] = arr(pname, 1)
                for y in ("peak/ductility", "residual_drift"):
                    if f"/{an}/{b}/{y}" in f:
                        d[y] = arr(f"/{an}/{b}/{y}", 1)
                if f"/{an}/{b}/deformed" in f and f"/{an}/{b}/deformed_time" in f:
                    d["deformed"] = arr(f"/{an}/{b}/deformed", 2)
                    d["deformed_time"] = arr(f"/{an}/{b}/deformed_time", 1)
                    if d["deformed"].shape[0] != n or len(d["deformed_time"]) != n:
                        raise PlotError(f"{path}: /{an}/{b}/deformed has shape {d['deformed'].shape}, "
                                        f"expected ({n}, n_dofs)")
                data[b] = d
            r.analyses[an] = data
        if "/coupled/contact/force" in f:
            t = r.analyses["coupled"]["time"]
            c = {"force": arr("/coupled/contact/force", 2), "closing": arr("/coupled/contact/closing", 2),
                 "gap": arr("/coupled/contact/gap", 1)}
            m = c["force"].shape[1]
            if c["force"].shape[0] != len(t) or c["closing"].shape != c["force"].shape or len(c["gap"]) != m:
                raise PlotError(f"{path}: /coupled/contact datasets have inconsistent shapes")
            for k in ("peak_force", "peak_time", "impacts"):
                if f"/coupled/contact/{k}" in f:
                    c[k] = arr(f"/coupled/contact/{k}", 1)
            labels = _text(f["/coupled/contact"].attrs.get("pairs", "")).split()
            if len(labels) != m:
                raise PlotError(f"{path}: /coupled/contact attribute 'pairs' names {len(labels)} pairs, "
                                f"the histories hold {m}")
            c["labels"] = labels
            c["pairs"] = [parse_pair(lab, r.buildings) for lab in labels]
            heights = {b: r.model[b]["height"] for b in r.buildings}
            c["elevations"] = [pair_elevations(lab, r.buildings, heights) for lab in labels]
            c["penetration"] = None
            c["notes"] = []
            if "/coupled/contact/penetration" in f:
                obj = f["/coupled/contact/penetration"]
                if isinstance(obj, h5py.Dataset) and obj.shape == c["force"].shape:
                    c["penetration"] = np.asarray(obj[()], dtype=float)
                else:
                    c["notes"].append(f"/coupled/contact/penetration {getattr(obj, 'shape', '(group)')} "
                                      "not used; penetration taken as closing - gap")
            c["envelope"] = {}
            for lab in labels:
                name = f"/coupled/contact/envelope/{lab}"
                if name in f and isinstance(f[name], h5py.Dataset) and f[name].ndim == 2 and f[name].shape[1] == 2:
                    c["envelope"][lab] = np.asarray(f[name][()], dtype=float)
            r.contact = c
        if "/sweep/gap" in f:
            sw = {"gap": arr("/sweep/gap", 1), "lambda": {}}
            for b in r.buildings:
                sw["lambda"][b] = {q: arr(f"/sweep/max_abs_lambda/{b}/{q}", 1)
                                   for q in list(QUANTITY_LABEL) + list(COLUMN_TARGETS) + ["ductility"]
                                   if f"/sweep/max_abs_lambda/{b}/{q}" in f}
            # Yielding buildings: 'bilinear' (storeys) or 'hinges' (a frame's plastic hinges).
            sw["yielding"] = {b: ("hinges" if f"/model/{b}/hinges/yield_moment" in f else
                                  "bilinear" if f"/model/{b}/yield_shear" in f else None) for b in r.buildings}
            sw["target"] = float(f["/sweep"].attrs.get("target_lambda", -1.0))
            sw["safe_gap"] = float(f["/sweep"].attrs.get("safe_gap", -1.0))
            # Failed gaps (results left out, zeros in the file): not drawn as values.
            sw["failed"] = (np.asarray(arr("/sweep/failed/case", 1), dtype=int) - 1
                            if "/sweep/failed/case" in f else np.zeros(0, dtype=int))
            # Several independent joints: each joint's own sweep (/sweep/joint/<left>-<right>).
            sw["joints"] = {}
            for j in (f["/sweep/joint"].keys() if "/sweep/joint" in f else []):
                g = f"/sweep/joint/{j}"
                sw["joints"][j] = {"gap": arr(g + "/gap", 1), "meets": arr(g + "/meets", 1).astype(bool),
                                   "safe_gap": float(f[g + "/safe_gap"][()]),
                                   "lambda": {b: arr(f"{g}/max_abs_lambda/{b}/storey_shear", 1) for b in r.buildings
                                              if f"{g}/max_abs_lambda/{b}/storey_shear" in f}}
            r.sweep = sw
        if "/influence" in f:
            for b in r.buildings:
                if f"/influence/{b}" in f:
                    r.influence[b] = {q: arr(f"/influence/{b}/{q}", 1) for q in QUANTITY_LABEL
                                      if f"/influence/{b}/{q}" in f}
            for b in r.buildings:
                m = r.model[b]
                if f"/influence/{b}/columns/shear" not in f or "elements" not in m or f"/model/{b}/columns" not in f:
                    continue
                seg = arr(f"/model/{b}/columns", 2).astype(int)     # element, storey, line (1-based)
                z = m["nodes"][1]
                ends = m["elements"][:2, seg[0] - 1].astype(int) - 1
                c = {"line": seg[2], "z_bottom": np.minimum(z[ends[0]], z[ends[1]]),
                     "z_top": np.maximum(z[ends[0]], z[ends[1]])}
                c["z_mid"] = 0.5 * (c["z_bottom"] + c["z_top"])
                for q in ("shear", "moment_bottom", "moment_top"):
                    name = f"/influence/{b}/columns/{q}"
                    if name in f:
                        c[q] = arr(name, 1)
                        if len(c[q]) != seg.shape[1]:
                            raise PlotError(f"{path}: {name} has {len(c[q])} values, /model/{b}/columns "
                                            f"names {seg.shape[1]} segments")
                r.columns[b] = c
    return r


# --------------------------------------------------------------------------------------------
# Plotting helpers


def setup_matplotlib():
    if not os.environ.get("MPLCONFIGDIR"):
        home = os.path.expanduser("~")
        if not os.access(home, os.W_OK):
            os.environ["MPLCONFIGDIR"] = tempfile.mkdtemp(prefix="pound-mpl-")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams.update({
        "font.size": 9, "axes.titlesize": 9, "axes.labelsize": 9, "legend.fontsize": 8,
        "xtick.labelsize": 8, "ytick.labelsize": 8, "figure.titlesize": 10,
        "axes.grid": True, "grid.color": "0.85", "grid.linewidth": 0.6,
        "lines.linewidth": 1.2, "hatch.linewidth": 0.6, "legend.framealpha": 0.9,
        "pdf.fonttype": 42, "savefig.bbox": "tight",
    })
    return plt


def style(i):
    return dict(color=COLOURS[i % len(COLOURS)], linestyle=LINESTYLES[i % len(LINESTYLES)])


def contact_window(r, t_max):
    """Time range of the contact plots: up to the last contact plus two fundamental periods."""
    import numpy as np

    t = r.analyses["coupled"]["time"]
    if t_max is not None:
        return t[0], min(t_max, t[-1]), f"t <= {t_max:g} s"
    active = np.nonzero(np.any(r.contact["force"] > 0.0, axis=1))[0]
    if len(active) == 0:
        return t[0], t[-1], ""
    last = t[active[-1]]
    t1 = max(float(r.model[b]["periods"][0]) for b in r.buildings if "periods" in r.model[b]) \
        if any("periods" in r.model[b] for b in r.buildings) else 0.1 * (t[-1] - t[0])
    end = min(t[-1], last + 2.0 * t1)
    note = f"last contact at {last:.3f} s; shown to {end:.3f} s" if end < t[-1] else ""
    return t[0], end, note


def suptitle(fig, r, what, note=""):
    text = f"{r.title}\n{what}"
    if note:
        text += f"  ({note})"
    # A suite's file adds a line (the motion): raised by it, above the axes' own titles (the
    # saved figure's tight box takes it in).
    extra = text.count("\n") - 1
    if extra > 0:
        fig.suptitle(text, y=0.98 + extra * 13.0 / (72.0 * fig.get_figheight()))
    else:
        fig.suptitle(text)


def save(fig, r, name, args, written):
    stem = os.path.splitext(os.path.basename(r.path))[0]
    outdir = args.outdir or os.path.dirname(os.path.abspath(r.path))
    for fmt in args.formats:
        final = os.path.join(outdir, f"{stem}_{name}.{fmt}")
        tmp = os.path.join(outdir, f".{stem}_{name}.{fmt}.partial")
        kw = {"metadata": {"CreationDate": None}} if fmt == "pdf" else {"dpi": args.dpi}
        try:
            fig.savefig(tmp, format=fmt, **kw)
            os.replace(tmp, final)
        except OSError as e:
            if os.path.exists(tmp):
                os.remove(tmp)
            raise PlotError(f"cannot write {final}: {e.strerror or e}") from None
        written.append(final)


def pair_caption(c, k):
    p = c["pairs"][k]
    gap_mm = 1e3 * c["gap"][k]
    if p is None:
        return f"pair {c['labels'][k]}, gap {gap_mm:.3g} mm"
    return f"{p[0]} floor {p[1]} / {p[2]} floor {p[3]}, gap {gap_mm:.3g} mm"


# --------------------------------------------------------------------------------------------
# The plots


def plot_displacement(plt, r, args, written, notes):
    import numpy as np

    c = r.contact
    cp = r.analyses["coupled"]
    t = cp["time"]
    usable = [k for k, p in enumerate(c["pairs"])
              if p is not None and "u" in cp[p[0]] and "u" in cp[p[2]]]
    if not usable:
        notes.append("displacement: skipped (no floor displacement history 'u' of facing floors stored; "
                     "set history to include u)")
        return
    t0, t1, note = contact_window(r, args.t_max)
    sel = (t >= t0) & (t <= t1)
    n = len(usable)
    fig, axes = plt.subplots(n, 1, sharex=True, figsize=(7.0, 1.2 + 1.9 * n), squeeze=False)
    for row, k in enumerate(usable):
        ax = axes[row, 0]
        lb, i, rb, j = c["pairs"][k]
        g = c["gap"][k]
        ul = 1e3 * cp[lb]["u"][sel, i - 1]
        ur = 1e3 * (cp[rb]["u"][sel, j - 1] + g)
        ts = t[sel]
        ax.fill_between(ts, ul, ur, where=ul <= ur, interpolate=True, facecolor="0.85", edgecolor="none",
                        label="open gap")
        ax.fill_between(ts, ul, ur, where=ul > ur, interpolate=True, facecolor="white", edgecolor="black",
                        hatch="xxxx", linewidth=0.0, label="in contact (penetration)")
        ax.plot(ts, ul, color="black", linestyle="-", label=f"{lb} floor {i}: u")
        ax.plot(ts, ur, color="#D55E00", linestyle="--", label=f"{rb} floor {j}: u + gap")
        ax.set_ylabel("displacement [mm]")
        ax.set_title(pair_caption(c, k), loc="left")
        ax.legend(loc="upper right", ncol=2)
    axes[-1, 0].set_xlabel("time t [s]")
    axes[-1, 0].set_xlim(t[sel][0], t[sel][-1])
    suptitle(fig, r, "Facing floors: displacement relative to the ground (positive: left to right), "
             "gap shaded", note)
    save(fig, r, "displacement", args, written)
    plt.close(fig)


def plot_force(plt, r, args, written, notes):
    import numpy as np

    c = r.contact
    t = r.analyses["coupled"]["time"]
    t0, t1, note = contact_window(r, args.t_max)
    sel = (t >= t0) & (t <= t1)
    m = len(c["labels"])
    fig, axes = plt.subplots(m, 1, sharex=True, sharey=True, figsize=(7.0, 1.2 + 1.5 * m), squeeze=False)
    for k in range(m):
        ax = axes[k, 0]
        ax.plot(t[sel], c["force"][sel, k], color="black", linestyle="-", label="contact force r")
        if "peak_force" in c and c["peak_force"][k] > 0.0:
            pt = c["peak_time"][k] if "peak_time" in c else None
            label = f"peak {c['peak_force'][k]:.4g} kN" + (f" at {pt:.3f} s" if pt is not None else "")
            if pt is not None:
                ax.plot([pt], [c["peak_force"][k]], linestyle="none", marker="v", color="black",
                        markerfacecolor="white", label=label)
        impacts = f", {int(c['impacts'][k])} impacts" if "impacts" in c else ""
        ax.set_title(pair_caption(c, k) + impacts, loc="left")
        ax.set_ylabel("force [kN]")
        if np.any(c["force"][:, k] > 0):
            ax.legend(loc="upper right")
        else:
            ax.text(0.5, 0.5, "no contact", transform=ax.transAxes, ha="center", va="center")
    axes[-1, 0].set_xlabel("time t [s]")
    axes[-1, 0].set_xlim(t[sel][0], t[sel][-1])
    axes[0, 0].set_ylim(bottom=0.0)
    suptitle(fig, r, "Contact force histories (compression positive)", note)
    save(fig, r, "force", args, written)
    plt.close(fig)


def plot_loops(plt, r, args, written, notes):
    import numpy as np

    c = r.contact
    m = len(c["labels"])
    ncol = min(3, m)
    nrow = (m + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.2 * ncol, 1.4 + 2.8 * nrow), squeeze=False)
    fig.subplots_adjust(top=1.0 - 1.1 / (1.4 + 2.8 * nrow), wspace=0.3, hspace=0.45)
    if c["penetration"] is not None:
        pen = c["penetration"]
        source = "penetration d as stored"
    else:
        pen = c["closing"] - c["gap"][None, :]
        source = "penetration d = closing - gap"
    notes.extend(c["notes"])
    for k in range(nrow * ncol):
        ax = axes[k // ncol, k % ncol]
        if k >= m:
            ax.set_visible(False)
            continue
        d = 1e3 * pen[:, k]
        rk = c["force"][:, k]
        ax.axhline(0.0, color="0.5", linewidth=0.6)
        ax.axvline(0.0, color="0.5", linewidth=0.6)
        ax.set_title(pair_caption(c, k), loc="left", fontsize=8)
        ax.set_xlabel("penetration d [mm]")
        if k % ncol == 0:
            ax.set_ylabel("contact force r [kN]")
        if not np.any(rk > 0.0):
            ax.text(0.5, 0.5, "no contact", transform=ax.transAxes, ha="center", va="center")
            ax.set_xlim(-0.1, 0.1)
            ax.set_ylim(0.0, 1.0)
            continue
        dmax = max(float(np.max(d)), 1e-9)
        # Keep the loops and the approach to the joint; the open branch (d << 0) runs off the axes.
        near = d > -0.3 * dmax
        ax.plot(np.where(near, d, np.nan), np.where(near, rk, np.nan), color="black", linestyle="-",
                marker="o", markersize=2.0, markevery=1, linewidth=0.8, label="response")
        ax.set_xlim(-0.3 * dmax, 1.1 * dmax)
        ax.set_ylim(0.0, 1.1 * max(float(np.max(rk)), float(c.get("peak_force", rk)[k])))
        env = c.get("envelope", {}).get(c["labels"][k])
        if env is not None and len(env) > 1:
            ax.plot(1e3 * env[:, 0], env[:, 1], color="0.45", linestyle="--", linewidth=1.2,
                    label="envelope (as linearised)")
            ax.set_xlim(-0.3 * dmax, 1.1 * max(dmax, 1e3 * float(env[-1, 0])))
            ax.set_ylim(0.0, 1.1 * max(float(np.max(rk)), float(np.max(env[:, 1]))))
        elif "peak_force" in c:
            ax.axhline(c["peak_force"][k], color="black", linestyle=":", linewidth=0.8,
                       label=f"peak {c['peak_force'][k]:.4g} kN")
        ax.legend(loc="upper right", fontsize=7)
    suptitle(fig, r, f"Force-penetration loops of the joints ({source})")
    save(fig, r, "loops", args, written)
    plt.close(fig)


def _storey_profile(values):
    """Staircase through the storeys: value j constant from floor j-1 to floor j."""
    import numpy as np

    n = len(values)
    x = np.repeat(values, 2)
    y = np.empty(2 * n)
    y[0::2] = np.arange(n)
    y[1::2] = np.arange(1, n + 1)
    return x, y


def plot_shear(plt, r, args, written, notes):
    import numpy as np

    names = [b for b in r.buildings if "storey_shear" in r.analyses["uncoupled"][b]["peak"]]
    if not names:
        notes.append("shear: skipped (no peak storey shears in the file)")
        return
    coupled = "coupled" in r.analyses
    nb = len(names)
    nmax = max(len(r.model[b]["height"]) for b in names)
    fig, axes = plt.subplots(1, nb, figsize=(min(7.0, 1.2 + 2.9 * nb), 1.5 + 0.42 * nmax), squeeze=False)
    for ib, b in enumerate(names):
        ax = axes[0, ib]
        qu = r.analyses["uncoupled"][b]["peak"]["storey_shear"]
        n = len(qu)
        qc = None
        x, y = _storey_profile(qu)
        ax.plot(x, y, color="0.45", linestyle="--", linewidth=1.2, label="uncoupled")
        ax.plot(qu, np.arange(n) + 0.5, color="0.45", linestyle="none", marker="s", markerfacecolor="white",
                markersize=4.5)
        if coupled and "storey_shear" in r.analyses["coupled"][b]["peak"]:
            qc = r.analyses["coupled"][b]["peak"]["storey_shear"]
            x, y = _storey_profile(qc)
            ax.plot(x, y, color="black", linestyle="-", linewidth=1.4, label="coupled (pounding)")
            ax.plot(qc, np.arange(n) + 0.5, color="black", linestyle="none", marker="o", markersize=4.0)
        # One legend entry per analysis with line and marker.
        handles = [plt.Line2D([], [], color="0.45", linestyle="--", marker="s", markerfacecolor="white",
                              label="uncoupled")]
        if qc is not None:
            handles.append(plt.Line2D([], [], color="black", linestyle="-", marker="o", label="coupled"))
        ax.legend(handles=handles, loc="upper right")
        ax.set_yticks(np.arange(n) + 0.5)
        ax.set_yticklabels([str(j) for j in range(1, n + 1)])
        ax.set_yticks(np.arange(n + 1), minor=True)
        ax.grid(False, axis="y")
        ax.grid(True, axis="y", which="minor", color="0.85")
        ax.set_ylim(0.0, n)
        ax.set_xlim(left=0.0, right=1.18 * max(np.max(qu), np.max(qc) if qc is not None else 0.0))
        ax.set_xlabel("peak storey shear |Q| [kN]")
        if ib == 0:
            ax.set_ylabel("storey")
        ax.set_title(f"building {b} ({n} storeys)")
    what = "Storey-shear envelopes, coupled against uncoupled" if coupled else \
        "Storey-shear envelopes (uncoupled only: no contact in this file)"
    suptitle(fig, r, what)
    save(fig, r, "shear", args, written)
    plt.close(fig)


def bilinear_buildings(r):
    """The yielding buildings: bilinear storeys (a ductility) or a frame's plastic hinges (a
    residual drift without a ductility), in the uncoupled analysis."""
    return [b for b in r.buildings if "residual_drift" in r.analyses["uncoupled"][b]]


def hysteresis_storey(d):
    """The storey whose loop is drawn and its label: the most ductile bilinear storey; for a frame
    with plastic hinges the storey of the largest peak |drift|."""
    import numpy as np

    if "peak/ductility" in d:
        j = int(np.argmax(d["peak/ductility"]))
        return j, "mu"
    peak = d["peak"].get("drift")
    if peak is None and "drift" in d:
        peak = np.max(np.abs(d["drift"]), axis=0)
    return (int(np.argmax(np.abs(peak))) if peak is not None else 0), "drift"


def plot_hysteresis(plt, r, args, written, notes):
    """Yielding buildings: the force-drift loop of each building's most ductile storey (bilinear
    storeys) or the storey of its largest drift (frames with plastic hinges), uncoupled against
    coupled, and the residual drift profile."""
    import numpy as np

    names = bilinear_buildings(r)
    coupled = "coupled" in r.analyses
    fig, axes = plt.subplots(len(names), 2, figsize=(9.0, 3.6 * len(names)), squeeze=False)
    for ib, b in enumerate(names):
        ax, ax2 = axes[ib, 0], axes[ib, 1]
        runs = [("uncoupled", "0.45", "--")] + ([("coupled", "black", "-")] if coupled else [])
        j, kind = hysteresis_storey(r.analyses["coupled" if coupled else "uncoupled"][b])
        for an, color, ls in runs:
            d = r.analyses[an][b]
            if "drift" in d and "storey_shear" in d:
                if kind == "mu":
                    label = f"{an} (mu = {d['peak/ductility'][j]:.2f})"
                else:
                    label = f"{an} (peak drift {1.0e3 * np.max(np.abs(d['drift'][:, j])):.1f} mm)"
                ax.plot(1.0e3 * d["drift"][:, j], d["storey_shear"][:, j], color=color, linestyle=ls,
                        linewidth=1.0, label=label)
            res = d["residual_drift"]
            n = len(res)
            x, y = _storey_profile(1.0e3 * res)
            ax2.plot(x, y, color=color, linestyle=ls, linewidth=1.3, label=an)
        if not ax.lines:
            notes.append(f"hysteresis: building {b}: no drift and storey_shear histories (history = 'all')")
        ax.set_xlabel(f"storey {j + 1} drift [mm]")
        ax.set_ylabel("storey shear Q [kN]")
        ax.set_title(f"building {b}: storey {j + 1}")
        ax.legend(loc="upper left")
        ax2.axvline(0.0, color="0.7", linewidth=0.8)
        ax2.set_ylim(0.0, n)
        ax2.set_xlabel("residual drift [mm]")
        ax2.set_ylabel("storey")
        ax2.set_title(f"building {b}: residual drift")
        ax2.legend(loc="upper right")
    suptitle(fig, r, "Yielding buildings: hysteresis loops and residual drifts")
    save(fig, r, "hysteresis", args, written)
    plt.close(fig)


def plot_influence(plt, r, args, written, notes):
    import numpy as np

    names = [b for b in r.buildings if b in r.influence and r.influence[b]]
    if not names:
        notes.append("influence: skipped (no /influence in the file: uncoupled-only run)")
        return
    qs = [q for q in QUANTITY_LABEL if all(q in r.influence[b] for b in names)]
    same_drift = "drift" in qs and "storey_shear" in qs and all(
        np.allclose(r.influence[b]["drift"], r.influence[b]["storey_shear"], rtol=0, atol=1e-9) for b in names)
    if same_drift:
        qs.remove("drift")
    nmax = max(len(r.model[b]["height"]) for b in names)
    nq = len(qs)
    ncol = min(2, nq)
    nrow = (nq + ncol - 1) // ncol
    nb = len(names)
    fig, axes = plt.subplots(nrow, ncol, figsize=(7.0, 0.9 + nrow * (0.8 + 0.16 * nb * nmax + 0.1 * nmax)),
                             squeeze=False)
    hgt = 0.8 / nb
    for iq in range(nrow * ncol):
        ax = axes[iq // ncol, iq % ncol]
        if iq >= nq:
            ax.set_visible(False)
            continue
        q = qs[iq]
        vmax = max(float(np.max(np.abs(r.influence[b][q]))) for b in names) or 1.0
        for ib, b in enumerate(names):
            lam = r.influence[b][q]
            pos = np.arange(1, len(lam) + 1) + (ib - (nb - 1) / 2) * hgt
            ax.barh(pos, lam, height=hgt * 0.95, color=FILLS[ib % len(FILLS)], edgecolor="black",
                    hatch=HATCHES[ib % len(HATCHES)], linewidth=0.6, label=f"building {b}")
            for p, v in zip(pos, lam):
                ax.text(v + (0.02 if v >= 0 else -0.02) * vmax, p, f"{v:.1f}", va="center",
                        ha="left" if v >= 0 else "right", fontsize=6.5)
        ax.axvline(0.0, color="black", linewidth=0.8)
        title, axis = QUANTITY_LABEL[q]
        if q == "storey_shear" and same_drift:
            title += " (= storey drift)"
        ax.set_title(title, loc="left")
        ax.set_yticks(np.arange(1, nmax + 1))
        ax.set_ylim(0.4, nmax + 0.6)
        ax.grid(False, axis="y")
        lo = min(0.0, min(float(np.min(r.influence[b][q])) for b in names))
        hi = max(0.0, max(float(np.max(r.influence[b][q])) for b in names))
        span = hi - lo if hi > lo else 5.0 * vmax   # all zero: labels inside the axes
        ax.set_xlim(lo - (0.22 * span if lo < 0 else 0.02 * span), hi + (0.22 * span if hi > 0 else 0.02 * span))
        ax.set_xlabel("influence coefficient lambda [%]")
        ax.set_ylabel(axis)
        if iq == 0:
            ax.legend(loc="best")
    suptitle(fig, r, "Influence coefficients lambda = (Qc - Qu) / Qu x 100 (storeys x buildings)")
    save(fig, r, "influence", args, written)
    plt.close(fig)


def plot_ground(plt, r, args, written, notes):
    import numpy as np

    t, ag = r.ground["time"], r.ground["acceleration"]
    g = r.g                                   # m/s^2, from the file
    unit = r.ground.get("units", "m/s^2").replace("^2", "²")
    fig, ax = plt.subplots(figsize=(7.0, 2.9))
    ax.plot(t, ag, color="black", linestyle="-", label="ground acceleration a_g")
    if len(ag):
        i = int(np.argmax(np.abs(ag)))
        ax.plot([t[i]], [ag[i]], linestyle="none", marker="o", markerfacecolor="white", color="black",
                label=f"PGA {abs(ag[i]):.4g} {unit} = {abs(ag[i]) / g:.3g} g at {t[i]:.3f} s")
    ax.axhline(0.0, color="0.5", linewidth=0.6)
    ax.set_xlabel("time t [s]")
    ax.set_ylabel(f"a_g [{unit}]")
    ax.set_xlim(t[0], t[-1]) if len(t) > 1 else None
    sec = ax.secondary_yaxis("right", functions=(lambda a: a / g, lambda x: x * g))
    sec.set_ylabel("a_g [g]")
    ax.legend(loc="upper right")
    desc = r.ground.get("description", "")
    if len(desc) > 100:
        desc = desc[:97] + "..."
    if desc:
        ax.set_title(desc, loc="left", fontsize=7.5)
    suptitle(fig, r, "Ground motion (at the output times)")
    save(fig, r, "ground", args, written)
    plt.close(fig)


def plot_sweep(plt, r, args, written, notes):
    """Largest |lambda| over the storeys against the joint gap, one panel per building."""
    import numpy as np

    sw = r.sweep
    names = [b for b in r.buildings if sw["lambda"].get(b)]
    fig, axes = plt.subplots(1, len(names), figsize=(3.6 * len(names) + 0.6, 4.2), squeeze=False, sharey=True)
    fig.subplots_adjust(top=0.80, wspace=0.08)
    # Storey drift has the same lambda as storey shear only for elastic shear buildings (Q = k
    # drift, k constant): drawn once there, as two curves otherwise (frames, yielding storeys).
    same = {b: "drift" in sw["lambda"][b] and "storey_shear" in sw["lambda"][b] and np.allclose(
        sw["lambda"][b]["drift"], sw["lambda"][b]["storey_shear"], rtol=0, atol=1e-9) for b in names}
    order = [q for q in ("storey_shear", "drift", "u", "a_abs") + tuple(COLUMN_TARGETS)
             if any(q in sw["lambda"][b] for b in names)]
    for i, b in enumerate(names):
        ax = axes[0, i]
        labels = {"storey_shear": "storey shear Q (= storey drift)" if same[b] else "storey shear Q",
                  **COLUMN_TARGETS}
        for j, q in enumerate(order):
            if q not in sw["lambda"][b] or (q == "drift" and same[b]):
                continue
            y = np.array(sw["lambda"][b][q], dtype=float)
            y[sw["failed"]] = np.nan
            ax.plot(1e3 * sw["gap"], y, color=COLOURS[j], linestyle=LINESTYLES[j], marker=MARKERS[j],
                    markersize=3, markevery=max(1, len(y) // 12), linewidth=1.0,
                    label=labels[q] if q in labels else QUANTITY_LABEL[q][0])
        if sw["target"] > 0:
            ax.axhline(sw["target"], color="black", linestyle=":", linewidth=0.9,
                       label=f"target {sw['target']:.4g} %")
        for k, g in enumerate(sw["gap"][sw["failed"]]):
            ax.axvline(1e3 * g, color="red", linestyle=":", linewidth=0.9,
                       label="failed gap (left out)" if k == 0 else None)
        if sw["safe_gap"] >= 0:
            every = " (every joint)" if sw["joints"] else ""
            ax.axvline(1e3 * sw["safe_gap"], color="black", linestyle="-.", linewidth=0.9,
                       label=f"smallest gap meeting it{every}: {1e3 * sw['safe_gap']:.3g} mm")
        ax.set_yscale("symlog", linthresh=1.0)
        ax.set_title(f"building {b}", loc="left", fontsize=9)
        ax.set_xlabel("joint gap [mm]")
        if i == 0:
            ax.set_ylabel("largest |lambda| over the storeys (segments) [%]")
        ax.grid(True, color="0.85", linewidth=0.5)
    axes[0, -1].legend(loc="center right", fontsize=7)
    suptitle(fig, r, "Gap study: largest influence coefficient against the seismic joint gap")
    save(fig, r, "sweep", args, written)
    plt.close(fig)
    if sw["joints"]:
        plot_sweep_joints(plt, r, args, written)
    if any(sw["yielding"].get(b) for b in names):
        plot_sweep_yielding(plt, r, args, written)


def plot_sweep_yielding(plt, r, args, written):
    """Yielding buildings: the largest |lambda| of the storey drift and of the ductility
    (bilinear storeys) or plastic rotation (a frame's hinges, the largest of each storey) against
    the gap (/sweep/max_abs_lambda/<b>/drift and /ductility; the latter where targeted)."""
    import numpy as np

    sw = r.sweep
    names = [b for b in r.buildings if sw["yielding"].get(b) and sw["lambda"].get(b)]
    fig, axes = plt.subplots(1, len(names), figsize=(3.6 * len(names) + 0.6, 4.2), squeeze=False, sharey=True)
    fig.subplots_adjust(top=0.80, wspace=0.08)
    for i, b in enumerate(names):
        ax = axes[0, i]
        hinges = sw["yielding"][b] == "hinges"
        series = [("drift", "storey drift")]
        series.append(("ductility", "plastic rotation (largest hinge of each storey, columns and beams)"
                       if hinges else "storey ductility mu"))
        for j, (q, label) in enumerate(series):
            if q not in sw["lambda"][b]:
                continue
            y = np.array(sw["lambda"][b][q], dtype=float)
            y[sw["failed"]] = np.nan
            ax.plot(1e3 * sw["gap"], y, color=COLOURS[j], linestyle=LINESTYLES[j], marker=MARKERS[j],
                    markersize=3, markevery=max(1, len(y) // 12), linewidth=1.0, label=label)
        if "ductility" not in sw["lambda"][b]:
            ax.text(0.02, 0.02, "ductility / rotation: not targeted by the sweep\n(target_quantities = 'ductility')",
                    transform=ax.transAxes, fontsize=6.5, va="bottom")
        if sw["target"] > 0:
            ax.axhline(sw["target"], color="black", linestyle=":", linewidth=0.9,
                       label=f"target {sw['target']:.4g} %")
        ax.set_yscale("symlog", linthresh=1.0)
        ax.set_title(f"building {b} ({'plastic hinges' if hinges else 'bilinear storeys'})", loc="left",
                     fontsize=9)
        ax.set_xlabel("joint gap [mm]")
        if i == 0:
            ax.set_ylabel("largest |lambda| over the storeys [%]")
        ax.grid(True, color="0.85", linewidth=0.5)
        ax.legend(loc="best", fontsize=7)
    suptitle(fig, r, "Gap study of the yielding buildings: drift, ductility and plastic-rotation lambdas")
    save(fig, r, "sweep_yielding", args, written)
    plt.close(fig)


def plot_sweep_joints(plt, r, args, written):
    """Each independent joint's own sweep (its pairs at the gaps, the other joints at their deck
    gaps): the storey-shear |lambda| of every building against the joint's gap, and its threshold."""
    import numpy as np

    joints = r.sweep["joints"]
    fig, axes = plt.subplots(1, len(joints), figsize=(3.6 * len(joints) + 0.6, 5.0), squeeze=False, sharey=True)
    fig.subplots_adjust(top=0.82, bottom=0.30, wspace=0.08)
    for i, (name, jt) in enumerate(joints.items()):
        ax = axes[0, i]
        for k, (b, y) in enumerate(jt["lambda"].items()):
            ax.plot(1e3 * jt["gap"], np.asarray(y, dtype=float), color=COLOURS[k % len(COLOURS)],
                    linestyle=LINESTYLES[k % len(LINESTYLES)], linewidth=1.0, label=f"building {b}")
        if r.sweep["target"] > 0:
            ax.axhline(r.sweep["target"], color="black", linestyle=":", linewidth=0.9,
                       label=f"target {r.sweep['target']:.4g} %")
        if jt["safe_gap"] >= 0:
            ax.axvline(1e3 * jt["safe_gap"], color="black", linestyle="-.", linewidth=0.9,
                       label=f"joint threshold: {1e3 * jt['safe_gap']:.3g} mm")
        ax.set_yscale("symlog", linthresh=1.0)
        ax.set_title(f"joint {name}", loc="left", fontsize=9)
        ax.set_xlabel(f"gap of joint {name} [mm]")
        if i == 0:
            ax.set_ylabel("largest storey-shear |lambda| [%]")
        ax.grid(True, color="0.85", linewidth=0.5)
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2, fontsize=7)
    suptitle(fig, r, "Gap study per joint: each joint swept alone, the other joints at their deck gaps")
    save(fig, r, "sweep_joints", args, written)
    plt.close(fig)


def plot_group(plt, r, args, written, module, group):
    """The plots of /<group> drawn by scripts/<module>.py's plot_all(f[group], plt, np, save),
    written as <stem>_<group>_<what>; a problem of the file it names (its RiskError or the like,
    the module's ERRORS) becomes a PlotError."""
    import importlib
    import h5py
    import numpy as np
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    plots = importlib.import_module(module)

    def save_group(fig, what):
        save(fig, r, group + "_" + what, args, written)
        plt.close(fig)

    with h5py.File(r.path, "r") as f:
        try:
            plots.plot_all(f[group], plt, np, save_group)
        except getattr(plots, "ERRORS", ()) as e:
            raise PlotError(f"{r.path}: {e}") from None


def plot_suite_group(plt, r, args, written, notes):
    """The suite plots (scripts/plot_suite.py: spectra, lambda, separation, sweep) of /suite."""
    plot_group(plt, r, args, written, "plot_suite", "suite")


def plot_risk_group(plt, r, args, written, notes):
    """The risk plots (scripts/plot_risk.py: fragility, probability) of /risk."""
    plot_group(plt, r, args, written, "plot_risk", "risk")


def plot_study_group(plt, r, args, written, notes):
    """The studies of the joint (scripts/plot_studies.py) of /stiffness_sweep,
    /restitution_sweep and /law_study."""
    import h5py
    import numpy as np
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plot_studies

    def save_study(fig, what):
        save(fig, r, what, args, written)
        plt.close(fig)

    with h5py.File(r.path, "r") as f:
        plot_studies.plot_all(f, plt, np, save_study, (COLOURS, LINESTYLES, MARKERS))


def has_study(path):
    import h5py
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plot_studies
    with h5py.File(path, "r") as f:
        return plot_studies.has_study(f)


def has_risk(path):
    import h5py
    with h5py.File(path, "r") as f:
        return "risk" in f


def has_suite(path):
    import h5py
    with h5py.File(path, "r") as f:
        return "suite" in f


# The rules of /separation (a single-motion run) as the program computed them, with the codes'
# factors: (dataset, marker, label).
SEPARATION_RULES = (("abs", "^", "ABS = u1 + u2"), ("srss", "v", "SRSS"), ("ddc", "x", "DDC (CQC rho)"),
                    ("asce7", "s", "ASCE 7 12.12.3: SRSS of Cd u / Ie"),
                    ("en1998", "D", "EN 1998 4.4.2.7: SRSS of q u, x0.7 only for floors at one level"),
                    ("is1893", "P", "IS 1893 7.11.3: R1 u1 + R2 u2, x0.5 only for floors at one level"),
                    ("no_contact", "o", "no-contact gap (uncoupled histories)"),
                    ("time_history", "*", "time-history threshold gap (sweep)"))


def has_separation(path):
    import h5py

    with h5py.File(path, "r") as f:
        return "separation/srss" in f


def plot_separation(plt, r, args, written, notes):
    """The separation rules of every pair as computed (with the codes' factors; n/a not drawn),
    the two buildings' setbacks, and which peaks they used (/separation attribute peaks)."""
    import h5py
    import numpy as np

    with h5py.File(r.path, "r") as f:
        g = f["separation"]
        pairs = [_text(p) for p in g["pair"][...]]
        rules = {k: np.array(g[k][...], dtype=float) for k, _, _ in SEPARATION_RULES if k in g}
        setback = [np.array(g[k][...], dtype=float) if k in g else None for k in ("setback_left", "setback_right")]
        peaks = _text(g.attrs.get("peaks", "the rules use the uncoupled peaks"))
    x = np.arange(len(pairs))
    fig, ax = plt.subplots(figsize=(max(6.0, 1.1 * len(pairs) + 3.0), 4.8))
    fig.subplots_adjust(top=0.80, bottom=0.28, right=0.62)
    for j, (k, m, label) in enumerate(SEPARATION_RULES):
        if k not in rules or not np.isfinite(rules[k]).any():
            continue
        ax.plot(x, 1e3 * rules[k], marker=m, linestyle="none", markersize=6, color=COLOURS[j % len(COLOURS)],
                label=label)
    for e, (v, m) in enumerate(zip(setback, ("<", ">"))):
        if v is not None and np.isfinite(v).any():
            ax.plot(x, 1e3 * v, marker=m, linestyle="none", markersize=5, color="0.45",
                    label=f"setback of the {('left', 'right')[e]} building (Cd u / Ie, u without cd)")
    ax.set_xticks(x)
    ax.set_xticklabels(pairs, rotation=60, ha="right", fontsize=7)
    ax.set_ylabel("separation [mm]")
    ax.grid(True, color="0.85", linewidth=0.5)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=7)
    suptitle(fig, r, "Separation rules per pair, as computed with the codes' factors", peaks)
    save(fig, r, "separation", args, written)
    plt.close(fig)


PLOTTERS = {"displacement": plot_displacement, "force": plot_force, "loops": plot_loops,
            "shear": plot_shear, "influence": plot_influence, "ground": plot_ground, "sweep": plot_sweep,
            "suite": plot_suite_group, "study": plot_study_group, "hysteresis": plot_hysteresis,
            "risk": plot_risk_group, "separation": plot_separation}


def plot_plan_group(plt, r, args, written, notes):
    """The plan view of buildings in plan (scripts/plot_plan.py), written as <stem>_plan_view."""
    import h5py
    import numpy as np
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plot_plan

    def save_plan(fig, what):
        save(fig, r, "plan_" + what, args, written)
        plt.close(fig)

    with h5py.File(r.path, "r") as f:
        plot_plan.plot_all(f, plt, np, save_plan)


def has_plan(path):
    import h5py
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plot_plan
    with h5py.File(path, "r") as f:
        return plot_plan.has_plan(f)


PLOTTERS["plan"] = plot_plan_group


# --------------------------------------------------------------------------------------------


def plot_frame(plt, r, args, written, notes):
    """The buildings side by side (frames: elements and nodes; shear buildings: a stick with its
    floors), the contact points marked on the facing column lines and joined across the joint."""
    import numpy as np

    fig, ax = plt.subplots(figsize=(8.0, 6.0))
    widths = []
    for b in r.buildings:
        m = r.model[b]
        widths.append(float(np.ptp(m["nodes"][0])) if "nodes" in m else 0.0)
    space = max(2.0, 0.4 * max(widths))
    x0, faces = 0.0, {}
    for i, b in enumerate(r.buildings):
        m = r.model[b]
        if "nodes" in m:
            x, z = m["nodes"][0] + x0, m["nodes"][1]
            for e in m["elements"].T.astype(int):
                n1, n2, kind = e[0] - 1, e[1] - 1, e[2]
                ax.plot([x[n1], x[n2]], [z[n1], z[n2]], color="black" if kind == 1 else COLOURS[1],
                        lw=2.0 if kind == 1 else 1.5, ls="-" if kind == 1 else "--")
            ax.plot(x, z, "o", color="black", ms=3)
        else:
            zf = np.concatenate([[0.0], np.cumsum(m["height"])])
            ax.plot(np.full_like(zf, x0), zf, "-", color="black", lw=2.0)
            ax.plot(np.full_like(zf[1:], x0), zf[1:], "s", color="black", ms=6)
        faces[b] = (x0, x0 + widths[i])
        ax.text(x0 + 0.5 * widths[i], -0.6, b, ha="center", va="top", fontsize=11)
        x0 += widths[i] + space
    count = 0
    if r.contact is not None:
        for k, pe in enumerate(r.contact.get("elevations", [])):
            if pe is None:
                continue
            bl, zl, br, zr = pe
            xl, xr = faces[bl][1], faces[br][0]
            ax.plot([xl, xr], [zl, zr], ":", color=COLOURS[2], lw=1.2)
            ax.plot([xl, xr], [zl, zr], "x", color=COLOURS[2], ms=8, mew=2)
            count += 1
    ax.set_aspect("equal")
    ax.set_xlabel("x [m] (buildings drawn apart; the joint is not to scale)")
    ax.set_ylabel("elevation z [m]")
    ax.plot([], [], "-", color="black", lw=2.0, label="column")
    ax.plot([], [], "--", color=COLOURS[1], lw=1.5, label="beam")
    ax.plot([], [], "x:", color=COLOURS[2], ms=8, mew=2, label=f"contact pair ({count})")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    suptitle(fig, r, "geometry and contact points")
    save(fig, r, "frame", args, written)
    plt.close(fig)


PLOTTERS["frame"] = plot_frame


def node_displacements(m, q):
    """Physical node displacements (3, n_nodes): horizontal, vertical, rotation, from the DOF
    vector q through the constraints' map (/model/<b>/node_dofs, node_coefficients)."""
    import numpy as np

    nd, nc = m["node_dofs"], m["node_coefficients"]
    qq = np.concatenate([[0.0], q])              # DOF 0: no term
    terms = nc * qq[nd]                          # (6, n_nodes)
    return terms[0::2] + terms[1::2]


def deformed_element(x, z, d, n1, n2, scale, points=11):
    """Points of an element from node n1 to n2 deformed by the node displacements d (3, n_nodes)
    times scale: axial displacement linear, transverse cubic Hermite with the end rotations
    (Euler-Bernoulli, no load between nodes: exact)."""
    import numpy as np

    dx, dz = x[n2] - x[n1], z[n2] - z[n1]
    length = np.hypot(dx, dz)
    c, s = dx / length, dz / length
    xi = np.linspace(0.0, 1.0, points)
    a1, a2 = c * d[0, n1] + s * d[1, n1], c * d[0, n2] + s * d[1, n2]
    v1, v2 = -s * d[0, n1] + c * d[1, n1], -s * d[0, n2] + c * d[1, n2]
    t1, t2 = d[2, n1], d[2, n2]
    a = (1 - xi) * a1 + xi * a2
    v = ((1 - 3 * xi**2 + 2 * xi**3) * v1 + length * (xi - 2 * xi**2 + xi**3) * t1
         + (3 * xi**2 - 2 * xi**3) * v2 + length * (-xi**2 + xi**3) * t2)
    px = x[n1] + xi * dx + scale * (c * a - s * v)
    pz = z[n1] + xi * dz + scale * (s * a + c * v)
    return px, pz


def most_affected_storey(r, b):
    """The storey of b with the largest finite |lambda| of the storey shear (1-based), or None."""
    import numpy as np

    lam = r.influence.get(b, {}).get("storey_shear")
    if lam is None or len(lam) == 0:
        return None
    a = np.where(np.isfinite(lam) & (np.abs(lam) < 1e300), np.abs(lam), -1.0)
    return int(np.argmax(a)) + 1


def deformed_buildings(r):
    """Frames whose deformed shapes are in both analyses."""
    return [b for b in r.buildings if "node_dofs" in r.model[b] and "coupled" in r.analyses
            and all("deformed" in r.analyses[an].get(b, {}) for an in ("uncoupled", "coupled"))]


def plot_deformed(plt, r, args, written, notes):
    """Each frame's deformed shape (scaled) at the instant of the peak storey shear of its most
    affected storey, uncoupled and coupled side by side; the undeformed frame in grey, contact
    points marked on the coupled side."""
    import numpy as np

    frames = [b for b in deformed_buildings(r) if most_affected_storey(r, b) is not None]
    if not frames:
        notes.append("deformed: skipped (no frame with deformed shapes and influence coefficients)")
        return
    fig, axes = plt.subplots(len(frames), 2, figsize=(8.0, 4.5 * len(frames)), squeeze=False)
    for row, b in enumerate(frames):
        m = r.model[b]
        x, z = m["nodes"][0], m["nodes"][1]
        j = most_affected_storey(r, b)
        shapes = {an: node_displacements(m, r.analyses[an][b]["deformed"][j - 1]) for an in ("uncoupled", "coupled")}
        umax = max(float(np.max(np.abs(d[:2]))) for d in shapes.values())
        size = max(float(np.ptp(z)), float(np.ptp(x)), 1.0)
        scale = 0.15 * size / umax if umax > 0 else 1.0
        lam = r.influence[b]["storey_shear"][j - 1]
        for col, an in enumerate(("uncoupled", "coupled")):
            ax = axes[row][col]
            d = shapes[an]
            t = r.analyses[an][b]["deformed_time"][j - 1]
            q = r.analyses[an][b]["peak"].get("storey_shear")
            for e in m["elements"].T.astype(int):
                n1, n2, kind = e[0] - 1, e[1] - 1, e[2]
                ax.plot([x[n1], x[n2]], [z[n1], z[n2]], color="0.75", lw=1.0, ls="-" if kind == 1 else "--")
                px, pz = deformed_element(x, z, d, n1, n2, scale)
                ax.plot(px, pz, color="black" if kind == 1 else COLOURS[1], lw=2.0 if kind == 1 else 1.5,
                        ls="-" if kind == 1 else "--")
            ax.plot(x + scale * d[0], z + scale * d[1], "o", color="black", ms=3)
            if an == "coupled" and r.contact is not None:
                for pe in r.contact.get("elevations", []):
                    if pe is None:
                        continue
                    bl, zl, br, zr = pe
                    for bb, ze, xe in ((bl, zl, np.max(x)), (br, zr, np.min(x))):
                        if bb != b:
                            continue
                        k = int(np.argmin(np.hypot(x - xe, z - ze)))
                        ax.plot(x[k] + scale * d[0, k], z[k] + scale * d[1, k], "x", color=COLOURS[2],
                                ms=8, mew=2)
            qtxt = f"|Q| = {q[j - 1]:.1f} kN, " if q is not None else ""
            lamtxt = f" (lambda {lam:+.1f} %)" if an == "coupled" else ""
            ax.set_title(f"{b} {an}: storey {j}, t = {t:.3f} s\n{qtxt}displacements x {scale:.3g}{lamtxt}",
                         fontsize=9)
            ax.set_aspect("equal")
            ax.set_xlabel("x [m]")
            if col == 0:
                ax.set_ylabel("elevation z [m]")
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    suptitle(fig, r, "deformed shape at the peak storey shear of the most affected storey")
    save(fig, r, "deformed", args, written)
    plt.close(fig)


PLOTTERS["deformed"] = plot_deformed


def facing_lines(r, b):
    """The column lines of frame b that face a neighbour: its rightmost where it stands on the
    left of a contact pair, its leftmost (line 1) where on the right; without contact pairs, by
    the order of the buildings (left to right)."""
    lines = r.columns[b]["line"]
    left, right = False, False
    pairs = [pe for pe in (r.contact or {}).get("elevations", []) if pe is not None]
    if pairs:
        left = any(pe[0] == b for pe in pairs)
        right = any(pe[2] == b for pe in pairs)
    else:
        k = r.buildings.index(b)
        left, right = k < len(r.buildings) - 1, k > 0
    out = []
    if right:
        out.append(int(lines.min()))
    if left and int(lines.max()) not in out:
        out.append(int(lines.max()))
    return out or [int(lines.min())]


def plot_columns(plt, r, args, written, notes):
    """Influence coefficients of the column segments of every frame against the segment's
    mid-height: the shear's and the end moment's (of the two ends, the one with the larger
    |lambda|: the sweep's column_moment), one line per facing column line; the contact
    elevations of the frame dotted."""
    import numpy as np

    names = list(r.columns)
    fig, axes = plt.subplots(len(names), 2, figsize=(7.6, 0.6 + 3.6 * len(names)), squeeze=False)
    fig.subplots_adjust(hspace=0.45, wspace=0.3)
    for i, b in enumerate(names):
        c = r.columns[b]
        mom = None
        if "moment_bottom" in c and "moment_top" in c:
            mom = np.where(np.abs(c["moment_top"]) > np.abs(c["moment_bottom"]), c["moment_top"], c["moment_bottom"])
        contact_z = sorted({pe[1] if pe[0] == b else pe[3] for pe in (r.contact or {}).get("elevations", [])
                            if pe is not None and b in (pe[0], pe[2])})
        for j, (q, title) in enumerate((("shear", "segment shear V"),
                                         ("moment", "segment end moment M (end of larger |lambda|)"))):
            ax = axes[i, j]
            lam = c.get("shear") if q == "shear" else mom
            if lam is None:
                ax.set_visible(False)
                continue
            for k, line in enumerate(facing_lines(r, b)):
                sel = np.nonzero(c["line"] == line)[0]
                sel = sel[np.argsort(c["z_mid"][sel])]
                y = np.array(lam[sel], dtype=float)
                y[np.abs(y) >= 1e300] = np.nan       # +huge: a response from nothing, not drawn
                ax.plot(y, c["z_mid"][sel], marker=MARKERS[k], markersize=4, **style(k),
                        label=f"column line {line}")
            for n, zc in enumerate(contact_z):
                ax.axhline(zc, color=COLOURS[2], linestyle=":", linewidth=0.9,
                           label="contact elevation" if n == 0 else None)
            ax.axvline(0.0, color="black", linewidth=0.8)
            ax.set_title(f"building {b}: {title}", loc="left", fontsize=8.5)
            ax.set_xlabel("influence coefficient lambda [%]")
            ax.set_ylabel("segment mid-height z [m]")
            ax.set_ylim(0.0, float(np.max(c["z_top"])) * 1.02)
            ax.legend(loc="best", fontsize=7)
    suptitle(fig, r, "Column segments: influence coefficients along the facing column lines")
    save(fig, r, "columns", args, written)
    plt.close(fig)


PLOTTERS["columns"] = plot_columns


def parse_args(argv):
    ap = argparse.ArgumentParser(prog="plot", description="Plots of a pound results file (PNG and PDF).")
    ap.add_argument("h5file", help="results file written by pound (DECK.h5)")
    ap.add_argument("--only", metavar="LIST",
                    help="comma-separated subset of: " + ", ".join(PLOTS) + " (default: all)")
    ap.add_argument("--outdir", metavar="DIR", help="where to write (default: beside the file)")
    ap.add_argument("--format", default="png,pdf", help="comma-separated formats (default png,pdf)")
    ap.add_argument("--t-max", type=float, metavar="T",
                    help="end of the time axis of the contact plots in s (default: last contact + 2 T1)")
    ap.add_argument("--dpi", type=int, default=150, help="PNG resolution (default 150)")
    args = ap.parse_args(argv)
    args.explicit = () if not args.only else tuple(s.strip() for s in args.only.split(",") if s.strip())
    args.only = PLOTS if not args.only else args.explicit
    bad = [s for s in args.only if s not in PLOTS]
    if bad:
        ap.error(f"--only: unknown plot {', '.join(bad)}; known: {', '.join(PLOTS)}")
    args.formats = tuple(s.strip().lower() for s in args.format.split(",") if s.strip())
    bad = [s for s in args.formats if s not in ("png", "pdf", "svg")]
    if bad or not args.formats:
        ap.error(f"--format: unknown format {', '.join(bad) or '(none)'}; use png, pdf, svg")
    if args.outdir and not os.path.isdir(args.outdir):
        ap.error(f"--outdir {args.outdir}: no such directory")
    return args


def run(argv):
    args = parse_args(argv)
    try:
        import numpy  # noqa: F401
        import h5py  # noqa: F401
        import matplotlib  # noqa: F401
    except ImportError as e:
        raise PlotError(f"needs numpy, h5py and matplotlib (Debian python3-numpy python3-h5py "
                        f"python3-matplotlib; run with /usr/bin/python3): {e}") from None
    r = read_results(args.h5file)
    plt = setup_matplotlib()
    written, notes = [], []
    for name in args.only:
        if name in CONTACT_PLOTS and r.contact is None:
            why = "uncoupled-only file" if "coupled" not in r.analyses else "no /coupled/contact"
            notes.append(f"{name}: skipped ({why}: no contact pairs)")
            continue
        if name == "suite" and not has_suite(r.path):
            if "suite" in args.explicit:
                notes.append("suite: skipped (no /suite in this file: the deck has one &ground)")
            continue
        if name == "risk" and not has_risk(r.path):
            if "risk" in args.explicit:
                notes.append("risk: skipped (no /risk in this file: the deck has no &stripes)")
            continue
        if name == "frame" and not any("nodes" in r.model[b] for b in r.buildings):
            if "frame" in args.explicit:
                notes.append("frame: skipped (no frame model in this file)")
            continue
        if name == "deformed" and not deformed_buildings(r):
            if "deformed" in args.explicit:
                notes.append("deformed: skipped (no frame with deformed shapes in both analyses)")
            continue
        if name == "columns" and not r.columns:
            if "columns" in args.explicit:
                notes.append("columns: skipped (no frame with column-segment influence in this file)")
            continue
        if name == "hysteresis" and not bilinear_buildings(r):
            if "hysteresis" in args.explicit:
                notes.append("hysteresis: skipped (no building with bilinear storeys or plastic hinges in this file)")
            continue
        if name == "study" and not has_study(r.path):
            if "study" in args.explicit:
                notes.append("study: skipped (no /stiffness_sweep, /restitution_sweep or /law_study in this file)")
            continue
        if name == "separation" and not has_separation(r.path):
            if "separation" in args.explicit:
                notes.append("separation: skipped (no /separation in this file: no contact, or a suite)")
            continue
        if name == "plan" and not has_plan(r.path):
            if "plan" in args.explicit:
                notes.append("plan: skipped (no building in plan in this file)")
            continue
        if name == "sweep" and r.sweep is None:
            if "sweep" in args.explicit:
                notes.append("sweep: skipped (no /sweep in this file: the deck has no &sweep)")
            continue
        PLOTTERS[name](plt, r, args, written, notes)
    for w in written:
        print(f"wrote {w}")
    for n in notes:
        print(f"note: {n}")
    return 0


def main(argv=None):
    try:
        return run(sys.argv[1:] if argv is None else argv)
    except PlotError as e:
        print(f"plot: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("plot: interrupted", file=sys.stderr)
        return 130
    except Exception as e:  # one line, not a traceback, unless asked for
        if os.environ.get("POUND_DEBUG"):
            raise
        msg = str(e).splitlines()[0] if str(e) else ""
        print(f"plot: error: unexpected failure ({type(e).__name__}: {msg}); POUND_DEBUG=1 shows "
              "the traceback", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
