"""Plots of the studies of the joint (issue 26) in a pound results file, for plot_results.py
(plot name `study`): a stiffness or restitution sweep (/stiffness_sweep, /restitution_sweep: the
largest |lambda| of each building and every pair's peak force against the swept value, log axis for
a stiffness) and a law study (/law_study: the same, one group of bars per variant)."""

STUDY_GROUPS = ("stiffness_sweep", "restitution_sweep")
SHOWN = (("storey_shear", "storey shear Q"), ("drift", "storey drift"), ("u", "floor displacement u"),
         ("a_abs", "floor absolute acceleration"))


def has_study(f):
    """Whether the open file holds a study of the joint."""
    return any(g in f for g in STUDY_GROUPS + ("law_study",))


def plot_all(f, plt, np, save, styles):
    """Every study of the open file `f`; `save(fig, name)` writes a figure; `styles` =
    (colours, linestyles, markers)."""
    colours, linestyles, markers = styles
    for g in STUDY_GROUPS:
        if g in f:
            save(_sweep(f[g], g, plt, np, colours, linestyles, markers), g)
    if "law_study" in f:
        save(_law(f["law_study"], plt, np, colours), "law_study")


def _buildings(group):
    return list(group["max_abs_lambda"].keys()) if "max_abs_lambda" in group else []


def _sweep(g, name, plt, np, colours, linestyles, markers):
    x = np.asarray(g["value"][()], dtype=float)
    failed = np.asarray(g["failed"][()], dtype=bool)
    stiffness = name == "stiffness_sweep"
    names = _buildings(g)
    fig, axes = plt.subplots(1, len(names) + 1, figsize=(3.6 * (len(names) + 1) + 0.6, 4.2), squeeze=False)
    fig.subplots_adjust(top=0.80, wspace=0.3)
    xlabel = "joint stiffness k0 [kN/m]" if stiffness else "coefficient of restitution e"
    target = float(g.attrs.get("target_lambda", -1.0))
    for i, b in enumerate(names):
        ax = axes[0, i]
        for j, (q, label) in enumerate(SHOWN):
            if q not in g["max_abs_lambda"][b]:
                continue
            y = np.asarray(g["max_abs_lambda"][b][q][()], dtype=float)
            y[failed] = np.nan
            ax.plot(x, y, color=colours[j], linestyle=linestyles[j], marker=markers[j], markersize=3,
                    linewidth=1.0, label=label)
        if target > 0:
            ax.axhline(target, color="black", linestyle=":", linewidth=0.9, label=f"target {target:.4g} %")
        if stiffness:
            ax.set_xscale("log")
        ax.set_title(f"building {b}", loc="left", fontsize=9)
        ax.set_xlabel(xlabel)
        if i == 0:
            ax.set_ylabel("largest |lambda| over the storeys [%]")
        ax.grid(True, color="0.85", linewidth=0.5)
        ax.legend(fontsize=7)
    ax = axes[0, -1]
    pairs = list(g["peak_force"].keys())
    for k, p in enumerate(pairs):
        y = np.asarray(g["peak_force"][p][()], dtype=float)
        y[failed] = np.nan
        ax.plot(x, y, color=colours[k % len(colours)], linestyle=linestyles[k % len(linestyles)],
                marker=markers[k % len(markers)], markersize=3, linewidth=1.0, label=p)
    if stiffness:
        ax.set_xscale("log")
    ax.set_title("peak impact force per pair", loc="left", fontsize=9)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("peak force [kN]")
    ax.grid(True, color="0.85", linewidth=0.5)
    ax.legend(fontsize=7)
    what = "stiffness" if stiffness else "restitution"
    fig.suptitle(f"Joint {what} study: every &contact group at each value, against one uncoupled run")
    return fig


def _law(g, plt, np, colours):
    variants = str(g.attrs["variants"]).split()
    first = g[variants[0]]
    names = _buildings(first)
    pairs = str(first.attrs.get("pairs", "")).split()
    fig, axes = plt.subplots(1, len(names) + 1, figsize=(3.6 * (len(names) + 1) + 0.6, 4.2), squeeze=False)
    fig.subplots_adjust(top=0.80, bottom=0.22, wspace=0.3)
    width = 0.8 / max(1, len(variants))
    for i, b in enumerate(names):
        ax = axes[0, i]
        qs = [q for q, _ in SHOWN if q in first["max_abs_lambda"][b]]
        for v, name in enumerate(variants):
            y = [float(g[name]["max_abs_lambda"][b][q][()]) for q in qs]
            ax.bar(np.arange(len(qs)) + v * width, y, width, color=colours[v % len(colours)], edgecolor="black",
                   linewidth=0.5, label=name)
        ax.set_xticks(np.arange(len(qs)) + 0.4 - width / 2)
        ax.set_xticklabels(qs, fontsize=7)
        ax.set_title(f"building {b}: largest |lambda| [%]", loc="left", fontsize=9)
        ax.grid(True, axis="y", color="0.85", linewidth=0.5)
        ax.legend(fontsize=7)
    ax = axes[0, -1]
    for v, name in enumerate(variants):
        y = np.asarray(g[name]["peak_force"][()], dtype=float)
        ax.bar(np.arange(len(y)) + v * width, y, width, color=colours[v % len(colours)], edgecolor="black",
               linewidth=0.5, label=name)
    ax.set_xticks(np.arange(len(pairs)) + 0.4 - width / 2)
    ax.set_xticklabels(pairs, fontsize=7, rotation=30)
    ax.set_title("peak impact force per pair [kN]", loc="left", fontsize=9)
    ax.grid(True, axis="y", color="0.85", linewidth=0.5)
    ax.legend(fontsize=7)
    fig.suptitle("Law study: the deck's joints (base) and each &contact variant, one uncoupled run")
    return fig
