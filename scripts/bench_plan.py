"""Buildings in plan: the cost of a plan pair against the planar pair of the same storeys
(called by scripts/bench_plan).

    bench_plan.py EXE REPEATS [--storeys 3,10,40] [--record elCentro_Peknold.AT2 | pulse]
                  [--records DIR] [--t-end 20] [--dt 1e-3]

For each storey count n two decks are generated:
- the plan pair: buildings A (12 m x 12 m) and B (12 m x 15 m, plan_origin_y = 2 m: the facades
  overlap over 10 m, two contact points per floor), n storeys of 3 m, 30 t and 30 x (Lx^2 + Ly^2)/12
  t m^2 a floor, two x planes at y = 0 and y = Ly with half of the storey stiffness each and two y
  planes at x = 0 and x = Lx, joints at every floor (gap 5 mm, elastic, 1e6 kN/m). Two variants:
  `symmetric` (centre of mass at the outline's centre, friction 0, ground along x) and
  `eccentric` (centre of mass at (0.6 Lx, 0.6 Ly), friction 0.3, shear stiffness 1e6 kN/m,
  ground at 30 degrees);
- the planar pair: the same buildings as shear buildings (storey stiffness = the sum of the x
  planes', the same masses, damping and joints), the same ground along x.
Each deck runs as a whole process, plan and planar interleaved (one warm-up pair, then REPEATS
pairs), each writing its outputs into a scratch folder of its own. Per run: the cpu time of the
process (user + system, os.wait4) and the program's own wall time of its coupled loop (the HDF5
attribute /coupled@integration_seconds). The table gives the medians and the median of the
pairwise ratios plan/planar; the target of the coupled loop's ratio is <= 3.5 (three DOFs a floor).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from opensees_plan import plan_deck  # noqa: E402  (the deck writer shared with the OpenSees comparison)

TARGET = 3.5
K_STOREY, MASS, H, GAP, K_JOINT = 4.0e5, 30.0, 3.0, 5.0e-3, 1.0e6


def ground(record, angle):
    if record is None:
        turn = f", angle = {angle!r}" if angle else ""
        return f"&ground kind = 'pulse', x0 = 0.05, a = 0.25, b = 6.283185307179586{turn} /"
    return f"&ground kind = 'record', file = '{record}', angle = {angle!r} /"


def decks(n, record, variant, dt, t_end):
    """(plan deck text, planar deck text)."""
    ecc = variant == "eccentric"
    bs = []
    for name, k, ly, y0 in (("A", K_STOREY, 12.0, 0.0), ("B", 0.5 * K_STOREY, 15.0, 2.0)):
        b = dict(name=name, n=n, h=H, mass=MASS, lx=12.0, ly=ly, y0=y0, zeta=0.05, pdelta=True,
                 planes_x=[(0.0, k / 2), (ly, k / 2)], planes_y=[(0.0, 2.0 * k), (12.0, 2.0 * k)])
        if ecc:
            b.update(xm=round(0.6 * 12.0, 6), ym=round(0.6 * ly, 6))
        bs.append(b)
    joint = dict(left="A", right="B", floors=list(range(1, n + 1)), gap=GAP, k=K_JOINT)
    if ecc:
        joint.update(mu=0.3, kt=K_JOINT)
    plan = plan_deck(bs, [joint], ground(record, 30.0 if ecc else 0.0), dt, t_end, f"plan pair, {n} storeys, {variant}")
    planar = [f"&analysis title = 'planar pair, {n} storeys', dt = {dt!r}, t_end = {t_end!r}, history = 'none' /",
              ground(record, 0.0).replace(", angle = 0.0", "")]
    for b in bs:
        k = sum(kp for _, kp in b["planes_x"])
        planar.append(f"&building name = '{b['name']}', n_storeys = {n}, height = {n}*{H!r}, mass = {n}*{MASS!r}, "
                      f"stiffness = {n}*{k!r}, damping_ratio = 0.05, damping_modes = 1, 2, p_delta = .true. /")
    fl = ", ".join(str(i) for i in range(1, n + 1))
    planar.append(f"&contact left = 'A', right = 'B', floors_left = {fl}, floors_right = {fl}, gap = {GAP!r}, "
                  f"law = 'elastic', stiffness = {K_JOINT!r} /")
    return plan, "\n".join(planar) + "\n"


def run(exe, deck, out):
    """One whole process: (cpu seconds, the coupled loop's seconds)."""
    import h5py
    with open(os.devnull, "wb") as null:
        proc = subprocess.Popen([exe, deck, "-o", out], cwd=out, stdout=null, stderr=subprocess.PIPE)
        _, status, usage = os.wait4(proc.pid, 0)
        err = proc.stderr.read().decode(errors="replace")
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"bench_plan: {exe} {deck} failed:\n{err}")
    stem = os.path.splitext(os.path.basename(deck))[0]
    with h5py.File(os.path.join(out, stem + ".h5"), "r") as f:
        loop = float(f["/coupled"].attrs["integration_seconds"])
    return usage.ru_utime + usage.ru_stime, loop


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe")
    ap.add_argument("repeats", type=int)
    ap.add_argument("--storeys", default="3,10,40")
    ap.add_argument("--record", default="elCentro_Peknold.AT2", help="a file of --records, or 'pulse'")
    ap.add_argument("--records", default=os.path.join(os.path.dirname(HERE), "..", "shared", "records"))
    ap.add_argument("--t-end", type=float, default=20.0)
    ap.add_argument("--dt", type=float, default=1.0e-3)
    ap.add_argument("--variants", default="symmetric,eccentric")
    a = ap.parse_args()
    record = None
    if a.record != "pulse":
        record = os.path.abspath(os.path.join(a.records, a.record))
        if not os.path.isfile(record):
            print(f"bench_plan: skipped: no record {record} (shared/records beside the clone; or --record pulse)")
            return
    exe = os.path.abspath(a.exe)
    print(f"motion: {os.path.basename(record) if record else 'pulse'}, t_end = {a.t_end:g} s, dt = {a.dt:g} s; "
          f"{a.repeats} interleaved pairs (after one warm-up pair), medians")
    print("| storeys | plan variant | DOFs plan / planar | coupled loop plan [ms] | planar [ms] | ratio (median of pairs) | "
          "process cpu plan [ms] | planar [ms] | ratio | target <= 3.5 |")
    print("|--:|---|--:|--:|--:|--:|--:|--:|--:|---|")
    worst = 0.0
    with tempfile.TemporaryDirectory() as tmp:
        for n in (int(s) for s in a.storeys.split(",")):
            for variant in a.variants.split(","):
                plan_text, planar_text = decks(n, record, variant, a.dt, a.t_end)
                paths = []
                for kind, text in (("plan", plan_text), ("planar", planar_text)):
                    d = os.path.join(tmp, kind)
                    os.makedirs(d, exist_ok=True)
                    path = os.path.join(d, f"bench_{kind}_{n}.nml")
                    open(path, "w").write(text)
                    paths.append(path)
                rows = {"plan": [], "planar": []}
                for i in range(a.repeats + 1):
                    p = run(exe, paths[0], os.path.dirname(paths[0]))
                    q = run(exe, paths[1], os.path.dirname(paths[1]))
                    if i > 0:
                        rows["plan"].append(p)
                        rows["planar"].append(q)
                loop_ratio = statistics.median(p[1] / q[1] for p, q in zip(rows["plan"], rows["planar"]))
                cpu_ratio = statistics.median(p[0] / q[0] for p, q in zip(rows["plan"], rows["planar"]))
                worst = max(worst, loop_ratio)
                med = {k: (statistics.median(r[0] for r in v), statistics.median(r[1] for r in v)) for k, v in rows.items()}
                print(f"| {n} | {variant} | {6 * n} / {2 * n} | {1e3 * med['plan'][1]:.1f} | {1e3 * med['planar'][1]:.1f} | "
                      f"{loop_ratio:.2f} | {1e3 * med['plan'][0]:.1f} | {1e3 * med['planar'][0]:.1f} | {cpu_ratio:.2f} | "
                      f"{'met' if loop_ratio <= TARGET else 'NOT met'} |")
    print(f"largest coupled-loop ratio {worst:.2f} (target <= {TARGET})")


if __name__ == "__main__":
    main()
