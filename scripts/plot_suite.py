#!/usr/bin/python3
"""Plots of the /suite group of a pound results file (a deck with several &ground).

    plot_suite.py FILE.h5 [--outdir DIR]

Writes <stem>_suite_spectra, <stem>_suite_lambda and <stem>_suite_separation (.png and .pdf):
the 5 %-damped Sa of every scaled motion (thin) with the suite mean (thick) and the buildings'
fundamental periods; the largest |lambda| per storey of storey shear per motion (thin) with
the mean of the lambdas (thick) per building; the separation rules per contact pair against the
exact no-contact gap, per motion and for the suite. Run with /usr/bin/python3 (numpy, h5py,
matplotlib). Exit status 1 with one 'plot_suite: error: ...' line on a bad file.
"""
import argparse
import os
import sys


def fail(message):
    sys.stderr.write("plot_suite: error: " + message + "\n")
    sys.exit(1)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Plots of /suite in a pound results file")
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
    if "suite" not in f:
        fail(f"{args.file}: no /suite (the deck has one ground motion)")
    s = f["suite"]
    names = [n.decode() if isinstance(n, bytes) else str(n) for n in s["names"][...]]
    outdir = args.outdir or os.path.dirname(os.path.abspath(args.file))
    stem = os.path.join(outdir, os.path.splitext(os.path.basename(args.file))[0])
    written = []

    def save(fig, what):
        for ext in ("png", "pdf"):
            path = f"{stem}_suite_{what}.{ext}"
            fig.savefig(path, dpi=150)
            written.append(path)
        plt.close(fig)

    # Spectra: (n_motions, n_periods) in Fortran order -> h5py (n_periods, n_motions).
    period = s["spectrum/period"][...]
    sa = np.atleast_2d(s["spectrum/sa"][...])
    if sa.shape[0] != len(period):
        sa = sa.T
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, name in enumerate(names):
        ax.loglog(period, sa[:, k], lw=0.8, alpha=0.7, label=name)
    ax.loglog(period, s["spectrum/mean_sa"][...], "k", lw=2.5, label="mean")
    for t in s["building_period"][...]:
        ax.axvline(t, color="grey", ls="--", lw=0.8)
    ax.set_xlabel("period T (s)")
    ax.set_ylabel("Sa (m/s$^2$), 5 % damping")
    ax.set_title("Spectra of the scaled motions; dashed: fundamental periods")
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    save(fig, "spectra")

    # Lambda of the storey shear per storey: per motion (thin) and the mean (thick).
    if "influence" in s:
        buildings = list(s["influence"].keys())
        fig, axes = plt.subplots(1, len(buildings), figsize=(4 * len(buildings), 5), squeeze=False)
        for ax, b in zip(axes[0], buildings):
            lam = np.atleast_2d(s[f"influence/{b}/storey_shear"][...])   # (n, n_motions)
            if lam.shape[1] != len(names):
                lam = lam.T
            storeys = np.arange(1, lam.shape[0] + 1)
            for k in range(len(names)):
                ax.plot(lam[:, k], storeys, lw=0.8, alpha=0.7)
            ax.plot(s[f"mean/influence/{b}/storey_shear"][...], storeys, "k", lw=2.5, label="mean of lambdas")
            ax.plot(s[f"lambda_of_means/{b}/storey_shear"][...], storeys, "r--", lw=1.5, label="lambda of means")
            ax.axvline(0, color="grey", lw=0.5)
            ax.set_title(f"building {b}: storey shear")
            ax.set_xlabel("lambda (%)")
            ax.set_ylabel("storey")
            ax.legend(fontsize=7)
        fig.tight_layout()
        save(fig, "lambda")

    # Separation rules against the no-contact gap, per pair.
    if "separation" in s:
        rules = ["abs", "srss", "ec8", "ddc"]
        nc = np.atleast_2d(s["separation/no_contact"][...])
        if nc.shape[1] != len(names) + 1:
            nc = nc.T
        n_pairs = nc.shape[0]
        fig, axes = plt.subplots(1, n_pairs, figsize=(3.2 * n_pairs, 4), squeeze=False)
        for p, ax in enumerate(axes[0]):
            x = np.arange(len(names) + 1)
            ax.plot(x, 1e3 * nc[p], "ko-", lw=2, label="no-contact gap")
            for r in rules:
                v = np.atleast_2d(s[f"separation/{r}"][...])
                if v.shape[1] != len(names) + 1:
                    v = v.T
                ax.plot(x, 1e3 * v[p], "o-", lw=0.8, ms=3, label=r.upper())
            ax.set_xticks(x)
            ax.set_xticklabels(names + ["suite"], rotation=90, fontsize=7)
            ax.set_title(f"pair {p + 1}")
            ax.set_ylabel("separation (mm)")
        axes[0][0].legend(fontsize=7)
        fig.suptitle("Code rules on elastic peaks (no amplification) vs the exact no-contact gap", fontsize=9)
        fig.tight_layout()
        save(fig, "separation")

    for path in written:
        print("wrote " + path)


if __name__ == "__main__":
    main()
