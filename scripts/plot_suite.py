#!/usr/bin/python3
"""Plots of the /suite group of a pound results file (a deck with several &ground).

    plot_suite.py FILE.h5 [--outdir DIR]

Writes <stem>_suite_spectra, <stem>_suite_lambda, <stem>_suite_separation and, with a gap
sweep, <stem>_suite_sweep (.png and .pdf): the 5 %-damped Sa of every scaled motion (thin) with
the suite mean (thick), the scaling targets (stars) and the buildings' fundamental periods; the
lambda of the storey shear per storey per motion (thin) with the mean of the lambdas (thick) per
building; the separation rules per contact pair as computed (ABS, SRSS, DDC, and ASCE 7,
EN 1998, IS 1893 with the codes' factors where the deck gives them; the title says which
peaks they used) against the time-history threshold gap of the sweep and the exact no-contact
gap, per motion and for the suite; the sweep's suite mean and
maximum of the largest |lambda| against the gap (each motion thin) with the target and the
refined thresholds. Failed cases (/suite/failed): a failed motion's spectrum is dotted and
named FAILED, it is left out of the lambda, separation and sweep plots (as of the means); a
failed suite gap is left out of the sweep curves and marked by a red dotted line.
`scripts/plot FILE.h5` draws the same plots for a file with /suite
(plot_results.py calls `plot_all`). Run with /usr/bin/python3 (numpy, h5py, matplotlib). Exit
status 1 with one 'plot_suite: error: ...' line on a bad file.
"""
import argparse
import os
import sys


# The separation rules drawn per pair, as pound computed them (with the codes' factors):
# (dataset under /suite/separation, marker, legend label).
RULES = (("abs", "^", "ABS = u1 + u2"), ("srss", "v", "SRSS"), ("ddc", "x", "DDC (CQC rho)"),
         ("asce7", "s", "ASCE 7: SRSS of Cd u / Ie"),
         ("en1998", "D", "EN 1998: SRSS of q u, x0.7 only for floors at one level"),
         ("is1893", "P", "IS 1893: R1 u1 + R2 u2, x0.5 only for floors at one level"))


def fail(message):
    sys.stderr.write("plot_suite: error: " + message + "\n")
    sys.exit(1)


def _cols(a, n, np):
    """A (n_x, n) view of a per-motion dataset: pound stores them with one row per motion,
    (n, n_x) as h5py reads them (issue 27); n is checked."""
    a = np.atleast_2d(a)
    if a.shape[0] != n:
        fail(f"a /suite dataset has {a.shape[0]} rows, expected {n} (one per motion): "
             "a file written before issue 27 (transposed /suite arrays)?")
    return a.T


def suite_answer(s, nm):
    """The suite's answer, the first line of every suite plot's title: the root attribute
    `suite_answer` that pound writes, or (older files) the refined thresholds of /suite/sweep."""
    text = s.file.attrs.get("suite_answer", None)
    if text is not None:
        return text.decode() if isinstance(text, bytes) else str(text)
    text = f"suite of {nm} motions"
    if "sweep/refined_gap_mean" in s:
        def gap(key):
            g = float(s["sweep/" + key][()])
            return f"{1e3 * g:.2f} mm" if g >= 0 else "none"
        text += f": gap {gap('refined_gap_mean')} on the mean, {gap('refined_gap_every')} on every motion"
    return text


def plot_all(s, plt, np, save):
    """Every suite plot of the /suite group `s`; save(fig, what) writes and closes a figure.
    Every figure's title leads with the suite's answer (`suite_answer`)."""
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in s["names"][...]]
    nm = len(names)
    answer = suite_answer(s, nm)
    # Failed motions (their run failed: left out of every statistic) and suite gaps.
    failed = s["motion_failed"][...].astype(bool) if "motion_failed" in s else np.zeros(nm, bool)
    used = [k for k in range(nm) if not failed[k]]

    # Spectra: (n_motions, n_periods) as stored -> (n_periods, n_motions) for plotting.
    period = s["spectrum/period"][...]
    sa = _cols(s["spectrum/sa"][...], nm, np)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, name in enumerate(names):
        if failed[k]:
            ax.loglog(period, sa[:, k], ":", lw=0.8, alpha=0.7, label=f"{name} (FAILED, not in the mean)")
        else:
            ax.loglog(period, sa[:, k], lw=0.8, alpha=0.7, label=name)
    ax.loglog(period, s["spectrum/mean_sa"][...], "k", lw=2.5, label="mean")
    if "target" in s:
        shown = False
        for t, tp in zip(s["target"][...], s["target_period"][...]):
            if t > 0 and tp >= 0:
                ax.plot(tp if tp > 0 else period[0], t, "r*", ms=12, label=None if shown else
                        ("target Sa(T)" if tp > 0 else "target PGA (rigid limit)"))
                shown = True
    for t in s["building_period"][...]:
        ax.axvline(t, color="grey", ls="--", lw=0.8)
    ax.set_xlabel("period T (s)")
    ax.set_ylabel("Sa (m/s$^2$), 5 % damping")
    ax.set_title("Spectra of the scaled motions; dashed: fundamental periods")
    ax.legend(fontsize=7, ncol=2)
    fig.suptitle(answer, fontsize=9)
    fig.tight_layout()
    save(fig, "spectra")

    # Lambda of the storey shear per storey: per motion (thin) and the mean (thick).
    if "influence" in s:
        buildings = list(s["influence"].keys())
        fig, axes = plt.subplots(1, len(buildings), figsize=(4 * len(buildings), 5), squeeze=False)
        for ax, b in zip(axes[0], buildings):
            lam = _cols(s[f"influence/{b}/storey_shear"][...], nm, np)   # (n, n_motions)
            storeys = np.arange(1, lam.shape[0] + 1)
            for k in used:
                ax.plot(lam[:, k], storeys, lw=0.8, alpha=0.7, label=names[k])
            ax.plot(s[f"mean/influence/{b}/storey_shear"][...], storeys, "k", lw=2.5, label="mean of lambdas")
            ax.plot(s[f"lambda_of_means/{b}/storey_shear"][...], storeys, "r--", lw=1.5, label="lambda of means")
            ax.axvline(0, color="grey", lw=0.5)
            ax.set_title(f"building {b}: storey shear")
            ax.set_xlabel("lambda (%)")
            ax.set_ylabel("storey")
            ax.legend(fontsize=6)
        fig.suptitle(answer, fontsize=9)
        fig.tight_layout()
        save(fig, "lambda")

    # Separation rules against the time-history threshold gap and the no-contact gap, per pair.
    if "separation" in s:
        nc = _cols(s["separation/no_contact"][...], nm + 1, np)             # (n_pairs, nm + 1)
        th = None
        if "separation/time_history" in s:
            th = _cols(s["separation/time_history"][...], nm + 1, np)
        n_pairs = nc.shape[0]
        pairs = s["separation"].attrs.get("pairs", "")
        if not len(pairs) and "/coupled/contact" in s.file:
            pairs = s.file["/coupled/contact"].attrs.get("pairs", "")
        pair_names = (pairs.decode() if isinstance(pairs, bytes) else str(pairs)).split()
        fig, axes = plt.subplots(1, n_pairs, figsize=(3.2 * n_pairs + 1, 4), squeeze=False)
        x = np.arange(nm + 1)
        # A failed motion has no rules (its row is not plotted); a rule or gap that is n/a (-1: no
        # history of an end, or an end between floors without node_histories) is not drawn.
        gone = np.append(failed, False)
        nc = np.where(gone[None, :] | (nc < 0), np.nan, nc)
        if th is not None:
            th = np.where(gone[None, :], -1.0, th)
        for p, ax in enumerate(axes[0]):
            if th is not None and (th[p] >= 0).any():
                ok = th[p] >= 0
                ax.plot(x[ok], 1e3 * th[p][ok], "rs-", lw=2.5, label="time-history threshold")
            ax.plot(x, 1e3 * nc[p], "ko-", lw=2, label="no-contact gap")
            # The rules as computed, with the codes' factors (n/a: NaN or -1, not drawn); the
            # legacy ec8 (SRSS x 0.7 without q) is not a code check and is left out.
            for r, m, label in RULES:
                if f"separation/{r}" not in s:
                    continue
                v = _cols(s[f"separation/{r}"][...], nm + 1, np)
                v = np.where(gone[None, :] | ~(v >= 0), np.nan, v)
                if not np.isfinite(v[p]).any():
                    continue
                ax.plot(x, 1e3 * v[p], marker=m, lw=0.8, ms=4, label=label)
            ax.set_xticks(x)
            ax.set_xticklabels([n + (" (FAILED)" if f else "") for n, f in zip(names, failed)] + ["suite"],
                               rotation=90, fontsize=7)
            ax.set_title(f"pair {pair_names[p]}" if p < len(pair_names) else f"pair {p + 1}", fontsize=7)
            ax.set_ylabel("separation (mm)")
        axes[0][0].legend(fontsize=7)
        peaks = s["separation"].attrs.get("peaks", "the rules use the uncoupled peaks")
        peaks = peaks.decode() if isinstance(peaks, bytes) else str(peaks)
        fig.suptitle(answer + "\nCode rules as computed, with their factors, vs the time-history gap (" + peaks + ")",
                     fontsize=8)
        fig.tight_layout()
        save(fig, "separation")

    # The sweep: suite mean and maximum of the largest |lambda| against the gap.
    if "sweep/gap" in s:
        sw = s["sweep"]
        gap = 1e3 * sw["gap"][...]
        per = _cols(sw["max_abs_lambda"][...], nm, np)                    # (n_gaps, n_motions)
        if "failed" in sw:                                                # a motion's failed gaps
            per = np.where(_cols(sw["failed"][...], nm, np) != 0, np.nan, per)
        gap_failed = sw["gap_failed"][...].astype(bool) if "gap_failed" in sw else np.zeros(len(gap), bool)
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for k in used:
            ax.plot(gap, per[:, k], lw=0.6, alpha=0.6, color="grey")
        ax.plot(gap, np.where(gap_failed, np.nan, sw["mean"][...]), "k-", lw=2.5, label="suite mean")
        ax.plot(gap, np.where(gap_failed, np.nan, sw["max"][...]), "k--", lw=1.5, label="maximum over the motions")
        for i, g in enumerate(gap[gap_failed]):
            ax.axvline(g, color="r", ls=":", lw=1, label="FAILED suite gap (left out)" if i == 0 else None)
        root = s.file
        target = float(root["sweep"].attrs.get("target_lambda", -1.0)) if "sweep" in root else -1.0
        if target > 0:
            ax.axhline(target, color="grey", lw=1, label=f"target {target:g} %")
        for key, style, label in (("refined_gap_mean", "b:", "refined threshold, mean"),
                                  ("refined_gap_every", "r-.", "refined threshold, every motion")):
            g = float(sw[key][()])
            if g >= 0:
                ax.axvline(1e3 * g, color=style[0], ls=style[1:], lw=1.5, label=f"{label}: {1e3 * g:.3f} mm")
        ax.set_xlabel("gap (mm)")
        ax.set_ylabel("largest |lambda| (%), targeted quantities")
        ax.set_title("Gap sweep over the suite (thin: each motion)")
        ax.legend(fontsize=7)
        fig.suptitle(answer, fontsize=9)
        fig.tight_layout()
        save(fig, "sweep")


def group_main(argv, group, prog, plot_fn, absent, errors=()):
    """The command line of a group's plots (plot_suite.py, plot_risk.py): FILE.h5 [--outdir DIR];
    writes <stem>_<group>_<what>.png and .pdf through plot_fn(f[group], plt, np, save); one
    '<prog>: error: ...' line and exit status 1 on a bad file (`absent`: why /<group> may be
    missing; `errors`: exceptions of plot_fn that name a problem of the file)."""
    def fail(message):
        sys.stderr.write(f"{prog}: error: {message}\n")
        sys.exit(1)

    ap = argparse.ArgumentParser(prog=prog, description=f"Plots of /{group} in a pound results file")
    ap.add_argument("file")
    ap.add_argument("--outdir", default=None)
    args = ap.parse_args(argv)
    try:
        import h5py
        import numpy as np
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        fail(f"{e}: run with /usr/bin/python3 (numpy, h5py, matplotlib)")
    try:
        f = h5py.File(args.file, "r")
    except OSError as e:
        fail(f"cannot open {args.file}: {e}")
    if group not in f:
        fail(f"{args.file}: no /{group} ({absent})")
    outdir = args.outdir or os.path.dirname(os.path.abspath(args.file))
    stem = os.path.join(outdir, os.path.splitext(os.path.basename(args.file))[0])
    written = []

    def save(fig, what):
        for ext in ("png", "pdf"):
            path = f"{stem}_{group}_{what}.{ext}"
            fig.savefig(path, dpi=150)
            written.append(path)
        plt.close(fig)

    try:
        plot_fn(f[group], plt, np, save)
    except errors as e:
        fail(f"{args.file}: {e}")
    for path in written:
        print("wrote " + path)


def main(argv=None):
    group_main(argv, "suite", "plot_suite", plot_all, "the deck has one ground motion")


if __name__ == "__main__":
    main()
