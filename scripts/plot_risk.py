#!/usr/bin/python3
"""Plots of the /risk group of a pound results file (a deck with &stripes and &hazard).

    plot_risk.py FILE.h5 [--outdir DIR]

Writes <stem>_risk_fragility and <stem>_risk_probability (.png and .pdf):
- fragility: one panel per outcome (contact, lambda_exceeded and, where buildings yield,
  collapse and collapse_due_to_pounding), at a few gaps of the sweep (at most four: the first,
  the last, and those nearest the risk-targeted gaps): the fraction of the motions with the
  outcome at each stripe (points) and the fitted lognormal fragility Phi(ln(im/theta)/beta)
  (line); where the fit is n/a (the `na` attribute of /risk/fragility/<outcome>/median says
  why) the points alone, the legend naming the reason;
- probability: P(outcome) in `years` against the gap, one line per outcome, the target
  probability as a horizontal line and each outcome's risk-targeted gap as a vertical one.
The layout read (h5py shapes): /risk/stripes/levels (n_stripes), /risk/motions (n_motions),
/risk/gaps (n_gaps, m), /risk/outcomes/<outcome> (n_gaps, n_stripes, n_motions) 0/1,
/risk/fragility/<outcome>/median and /beta (n_gaps, NaN where n/a), /risk/maf/<outcome> and
/risk/probability/<outcome> (n_gaps), /risk/gap/<outcome> (scalar, m, NaN where none), and the
attributes `years` and `target_probability` of /risk (optional: `answer`, the sentence leading
the titles; `measure`, and `units` of the levels).
`scripts/plot FILE.h5` draws the same plots for a file with /risk (plot_results.py calls
`plot_all`). Run with /usr/bin/python3 (numpy, h5py, matplotlib). Exit status 1 with one
'plot_risk: error: ...' line on a bad file.
"""
import argparse
import math
import os
import sys

OUTCOMES = ("contact", "lambda_exceeded", "collapse", "collapse_due_to_pounding")
LABELS = {"contact": "contact", "lambda_exceeded": "lambda exceeded", "collapse": "collapse",
          "collapse_due_to_pounding": "collapse due to pounding"}


# Lines differ by style and marker, not colour alone (the figures print in black and white).
STYLES = ("-", "--", "-.", ":")
MARKERS = ("o", "s", "^", "D")


class RiskError(Exception):
    pass


# The exceptions of plot_all that name a problem of the file (plot_results.py: one error line).
ERRORS = (RiskError,)


def _text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def _na_reasons(ds, n):
    """The `na` attribute of a fragility dataset as one reason per gap ('' where identified)."""
    na = ds.attrs.get("na", None)
    if na is None:
        return [""] * n
    if isinstance(na, (bytes, str)):
        return [_text(na)] * n
    items = [_text(x).strip() for x in list(na)]
    return items if len(items) == n else [" ".join(items)] * n


def read_risk(rk, np):
    """The /risk group as plain arrays; RiskError naming what is missing or misshapen."""
    for key in ("stripes/levels", "gaps"):
        if key not in rk:
            raise RiskError(f"/risk/{key} missing")
    levels = np.asarray(rk["stripes/levels"][...], float).ravel()
    gaps = np.asarray(rk["gaps"][...], float).ravel()
    outcomes = [o for o in OUTCOMES if f"outcomes/{o}" in rk]
    if not outcomes:
        raise RiskError("no /risk/outcomes/<outcome> (contact, lambda_exceeded, collapse, "
                        "collapse_due_to_pounding)")
    d = {"levels": levels, "gaps": gaps, "outcomes": outcomes, "years": float(rk.attrs.get("years", 50.0)),
         "target": float(rk.attrs.get("target_probability", float("nan"))), "o": {}}
    for o in outcomes:
        x = np.asarray(rk[f"outcomes/{o}"][...], float)
        if x.ndim != 3 or x.shape[:2] != (gaps.size, levels.size):
            raise RiskError(f"/risk/outcomes/{o} has shape {x.shape}, expected "
                            f"({gaps.size}, {levels.size}, n_motions)")
        e = {"fraction": x.mean(axis=2)}
        for key in ("median", "beta"):
            path = f"fragility/{o}/{key}"
            e[key] = np.asarray(rk[path][...], float).ravel() if path in rk else np.full(gaps.size, np.nan)
        e["na"] = (_na_reasons(rk[f"fragility/{o}/median"], gaps.size) if f"fragility/{o}/median" in rk
                   else [""] * gaps.size)
        e["p"] = (np.asarray(rk[f"probability/{o}"][...], float).ravel() if f"probability/{o}" in rk
                  else np.full(gaps.size, np.nan))
        e["gap"] = float(rk[f"gap/{o}"][()]) if f"gap/{o}" in rk else float("nan")
        d["o"][o] = e
    answer = rk.attrs.get("answer", None)
    if answer is None:
        parts = []
        for o in outcomes:
            g = d["o"][o]["gap"]
            parts.append(f"{LABELS[o]}: {1e3 * g:.1f} mm" if math.isfinite(g) else f"{LABELS[o]}: none")
        answer = (f"risk-targeted gaps (P <= {d['target']:.3g} in {d['years']:g} years): " + ", ".join(parts)
                  if math.isfinite(d["target"]) else f"P of each outcome in {d['years']:g} years")
    d["answer"] = _text(answer)
    unit = _text(rk["stripes/levels"].attrs.get("units", "m/s^2"))
    measure = _text(rk.attrs.get("measure", "sa")).strip().lower()
    d["xlabel"] = ("Sa(T1)" if measure == "sa" else "PGA" if measure == "pga" else measure) + f" ({unit})"
    return d


def chosen_gaps(d, np, most=4):
    """At most `most` gap indices: the first, the last and those nearest the risk-targeted gaps."""
    n = d["gaps"].size
    picks = [0, n - 1]
    for o in d["outcomes"]:
        g = d["o"][o]["gap"]
        if math.isfinite(g):
            picks.append(int(np.argmin(np.abs(d["gaps"] - g))))
    picks = sorted(set(picks))
    if len(picks) > most:
        picks = [picks[0]] + picks[1:-1][:most - 2] + [picks[-1]]
    return picks


def normal_cdf(z):
    return 0.5 * math.erfc(-z / math.sqrt(2.0))


def plot_all(rk, plt, np, save):
    """Both risk plots of the /risk group `rk`; save(fig, what) writes and closes a figure."""
    d = read_risk(rk, np)
    levels, gaps = d["levels"], d["gaps"]
    picks = chosen_gaps(d, np)
    n_o = len(d["outcomes"])
    lo, hi = levels.min() / 3.0, levels.max() * 2.0
    im = np.geomspace(lo, hi, 200)
    cols = min(n_o, 2)
    rows = (n_o + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.6 * cols + 0.4, 3.6 * rows + 0.4), squeeze=False)
    for ax in axes.ravel()[n_o:]:
        ax.set_visible(False)
    for ax, o in zip(axes.ravel(), d["outcomes"]):
        e = d["o"][o]
        for c, g in enumerate(picks):
            colour, style, marker = f"C{c}", STYLES[c % 4], MARKERS[c % 4]
            label = f"gap {1e3 * gaps[g]:.1f} mm"
            th, be = e["median"][g], e["beta"][g]
            if math.isfinite(th) and math.isfinite(be) and th > 0 and be > 0:
                ax.plot(im, [normal_cdf(math.log(x / th) / be) for x in im], color=colour, ls=style, lw=1.4,
                        label=f"{label}: theta {th:.3g}, beta {be:.2f}")
            else:
                why = e["na"][g] or "n/a"
                label += f": fit n/a ({why})"
            ax.plot(levels, e["fraction"][g], marker, color=colour, ms=4,
                    label=None if math.isfinite(th) and math.isfinite(be) else label)
        ax.set_xscale("log")
        ax.set_xlim(lo, hi)
        ax.set_ylim(-0.03, 1.03)
        ax.set_xlabel(d["xlabel"])
        ax.set_ylabel(f"P({LABELS[o]} | im)")
        ax.set_title(LABELS[o])
        ax.legend(fontsize=6, loc="upper left")
    fig.suptitle(d["answer"] + "\nfragility: fraction of the motions at each stripe (points), "
                 "lognormal fit (lines), at a few gaps", fontsize=9)
    fig.tight_layout()
    save(fig, "fragility")

    fig, ax = plt.subplots(figsize=(7, 4.5))
    positive = [e["p"][np.isfinite(e["p"])] for e in d["o"].values()]
    positive = np.concatenate(positive) if positive else np.array([])
    log = positive.size > 0 and (positive > 0).all() and positive.max() > 100 * positive.min()
    for c, o in enumerate(d["outcomes"]):
        e = d["o"][o]
        ax.plot(1e3 * gaps, e["p"], color=f"C{c}", ls=STYLES[c % 4], marker=MARKERS[c % 4], ms=3,
                label=f"P({LABELS[o]})")
        if math.isfinite(e["gap"]):
            ax.axvline(1e3 * e["gap"], color=f"C{c}", ls=":", lw=1.2,
                       label=f"risk-targeted gap, {LABELS[o]}: {1e3 * e['gap']:.1f} mm")
    if math.isfinite(d["target"]):
        ax.axhline(d["target"], color="r", ls="--", lw=1.2, label=f"target {d['target']:.3g}")
    if log:
        ax.set_yscale("log")
    ax.set_xlabel("gap (mm)")
    ax.set_ylabel(f"P in {d['years']:g} years")
    ax.set_title(f"Probability of each outcome in {d['years']:g} years against the gap")
    ax.legend(fontsize=7)
    fig.suptitle(d["answer"], fontsize=9)
    fig.tight_layout()
    save(fig, "probability")


def main(argv=None):
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import plot_suite
    plot_suite.group_main(argv, "risk", "plot_risk", plot_all, "the deck has no &stripes", (RiskError,))


if __name__ == "__main__":
    main()
