"""The plan view of buildings in plan (called by scripts/plot_results.py as the `plan` plot):
each building's outline placed along the row (x from the left, the deck gaps between the
facades), its centre of mass, its planes (x planes as horizontal lines, y planes as vertical
lines, each labelled with its largest |lambda| of the plane shear over the storeys), and the
contact points on the facades with the largest peak normal force over the floors at each
point (and, with friction, the largest peak friction force)."""
import re


def _names(f):
    return [b for b in f["model"].keys() if "plan_size" in f["model"][b]]


def has_plan(f):
    return "model" in f and len(_names(f)) > 0


def _point_y(label):
    m = re.search(r"@y=(neg)?([0-9.]+)m", label)
    if not m:
        return None
    return (-1.0 if m.group(1) else 1.0) * float(m.group(2))


def plot_all(f, plt, np, save):
    names = _names(f)
    order = [n for n in f.attrs.get("buildings", "").split()] if "buildings" in f.attrs else []
    names = [n for n in order if n in names] or names
    contact = f["coupled/contact"] if "coupled/contact" in f else None
    labels = []
    if contact is not None:
        labels = str(contact.attrs.get("pairs", b"").decode() if isinstance(contact.attrs.get("pairs", ""), bytes)
                     else contact.attrs.get("pairs", "")).split()
    gap = {}
    if contact is not None and "gap" in contact:
        for lab, g in zip(labels, contact["gap"][...].ravel()):
            left, right = lab.split("@")[0].split("-")[0].split(":")[0], lab.split("@")[0].split("-")[1].split(":")[0]
            gap[(left, right)] = min(g, gap.get((left, right), g))
    x0, place = 0.0, {}
    for i, b in enumerate(names):
        if i > 0:
            x0 += gap.get((names[i - 1], b), 0.0)
        place[b] = x0
        x0 += float(f["model"][b]["plan_size"][0])
    fig, ax = plt.subplots(figsize=(8, 6))
    for i, b in enumerate(names):
        m = f["model"][b]
        lx, ly = (float(v) for v in m["plan_size"][...])
        y0 = float(m["plan_origin_y"][...].ravel()[0])
        xa = place[b]
        ax.add_patch(plt.Rectangle((xa, y0), lx, ly, fill=False, lw=1.5, color=f"C{i}"))
        xm, ym = (float(v) for v in m["mass_centre"][...])
        ax.plot(xa + xm, y0 + ym, "+", color=f"C{i}", ms=12, mew=2)
        ax.annotate(b, (xa + lx / 2, y0 + ly), textcoords="offset points", xytext=(0, 6), ha="center",
                    color=f"C{i}", weight="bold")
        direction = m["plane_direction"][...].ravel()
        position = m["plane_position"][...].ravel()
        lam = None
        if f"influence/{b}/plane_shear" in f:
            lam = np.atleast_2d(f[f"influence/{b}/plane_shear"][...])
        for p, (d, c) in enumerate(zip(direction, position)):
            if d == 1:
                xs, ys = [xa, xa + lx], [y0 + c, y0 + c]
            else:
                xs, ys = [xa + c, xa + c], [y0, y0 + ly]
            ax.plot(xs, ys, "--", color=f"C{i}", lw=0.8)
            if lam is not None and p < lam.shape[0]:
                row = lam[p][np.isfinite(lam[p])]
                text = f"P{p + 1}: " + (f"{row[np.argmax(abs(row))]:+.0f} %" if row.size else "n/m")
                ax.annotate(text, ((xs[0] + xs[1]) / 2, (ys[0] + ys[1]) / 2), fontsize=7, color=f"C{i}",
                            ha="center", va="bottom")
    if contact is not None and "peak_force" in contact and labels:
        force = contact["peak_force"][...].ravel()
        friction = contact["peak_friction"][...].ravel() if "peak_friction" in contact else None
        points = {}
        for k, lab in enumerate(labels):
            y = _point_y(lab)
            left = lab.split("@")[0].split("-")[0].split(":")[0]
            if y is None or left not in place:
                continue
            x = place[left] + float(f["model"][left]["plan_size"][0])
            key = (round(x, 6), round(y, 6))
            best = points.get(key, (0.0, 0.0))
            points[key] = (max(best[0], force[k]), max(best[1], friction[k] if friction is not None else 0.0))
        for (x, y), (n, t) in points.items():
            ax.plot(x, y, "o", color="k" if n > 0 else "0.6", ms=8)
            text = f"N {n:.0f} kN" + (f", T {t:.0f} kN" if friction is not None else "")
            ax.annotate(text, (x, y), textcoords="offset points", xytext=(6, -12), fontsize=8)
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.margins(0.15)
    ax.set_xlabel("site x (m)")
    ax.set_ylabel("site y (m)")
    ax.set_title("Plan view: outlines, centres of mass (+), planes (dashed, largest |lambda| of the plane "
                 "shear),\ncontact points (largest peak normal force N and friction T over the floors)",
                 fontsize=9)
    save(fig, "view")
