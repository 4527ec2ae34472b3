"""Pounding benchmarks (called by scripts/bench_contact).

Scale cases: the structure's cost per step is the uncoupled loop's (the same buildings without
joints); the contact's is what the coupled loop costs more (LCP solves, the closing
displacements, the response to the contact forces, the joints' update); the LCP solves are
clocked inside the program (only in the steps that have an LCP). Times are wall-clock medians:
run on a quiet machine."""
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile


def building(name, n, mass, k, zeta=0.05):
    return (f"&building name='{name}', n_storeys={n}, height={n}*3.0, mass={n}*{mass}, "
            f"stiffness={n}*{k}, damping_ratio={zeta}, damping_modes=1,2, p_delta=.true. /\n")


def contact(left, right, n, gap=0.005, every=1):
    floors = ", ".join(str(i) for i in range(every, n + 1, every))
    return (f"&contact left='{left}', right='{right}', floors_left={floors}, floors_right={floors}, "
            f"gap={gap}, law='elastic', stiffness=1.0e6 /\n")


HEAD = """&analysis title='{title}', dt=1.0e-3, t_end=20.0, output_every=10, history='u' /
&ground kind='pulse', x0=0.05, a=0.25, b=6.283185307179586 /
"""


def scale_decks():
    two = HEAD.format(title="two 40-storey buildings, 40 constraints")
    two += building("A", 40, 20.0, 6.0e5) + building("B", 40, 20.0, 3.0e5) + contact("A", "B", 40)
    three = HEAD.format(title="three 20-storey buildings in a row, 40 constraints")
    three += (building("A", 20, 20.0, 5.0e5) + building("B", 20, 20.0, 2.5e5)
              + building("C", 20, 20.0, 4.0e5) + contact("A", "B", 20) + contact("B", "C", 20))
    cases = {"two 40-storey, every floor": two, "three 20-storey in a row": three}
    # Many joints: two 200-storey buildings touching at every 5th floor (40 joints) and at
    # every floor (200 joints).
    for every, joints in ((5, 40), (1, 200)):
        deck = HEAD.format(title=f"two 200-storey buildings, {joints} constraints")
        deck += (building("A", 200, 20.0, 6.0e5) + building("B", 200, 20.0, 3.0e5)
                 + contact("A", "B", 200, every=every))
        cases[f"two 200-storey, {joints} joints"] = deck
    return cases


def run(exe, deck, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    stdout = subprocess.run([exe, deck, "-o", out], check=True, capture_output=True, text=True).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    num = r"([0-9.Ee+-]+)"
    m = re.search(r"coupled integration:\s+" + num + r" s, energy balance error\s+" + num
                  + r", (\d+) impacts, (\d+) LCP pivots", stdout)
    c = re.search(r"contact \(LCP\) time:\s+" + num + r" s, LCP solves (\d+), pivots max (\d+), steps (\d+)",
                  stdout)
    u = re.search(r"uncoupled integration:\s+" + num + " s", stdout)
    # Active-set solves (absent before the active-set solver: all solves were Lemke's).
    a = re.search(r"active-set solves (\d+), iterations (\d+) \(max (\d+)\), fallbacks to Lemke (\d+)", stdout)
    active = [int(g) for g in a.groups()] if a else [0, 0, 0, 0]
    return dict(as_solves=active[0], as_iterations=active[1], as_iterations_max=active[2],
                as_fallbacks=active[3],cpu=cpu, coupled=float(m.group(1)), energy=float(m.group(2)), impacts=int(m.group(3)),
                pivots=int(m.group(4)), contact=float(c.group(1)), solves=int(c.group(2)),
                pivots_max=int(c.group(3)), steps=int(c.group(4)), uncoupled=float(u.group(1)))


def median_of(runs, key):
    return statistics.median(r[key] for r in runs)


def main():
    exe, seed, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
    # Optional: run only the scale cases whose name contains this text (no gap study, no seed).
    only = sys.argv[4] if len(sys.argv) > 4 else ""
    sweep_deck = os.path.join(os.path.dirname(seed), "two_frames_gap_study.nml")
    with tempfile.TemporaryDirectory() as tmp:
        if not only:
            seed_and_sweep(exe, seed, sweep_deck, repeats, tmp)
        print("| case | steps | structure (uncoupled loop) [us/step] | coupled loop [us/step] | "
              "contact = coupled - uncoupled [us/step] | of which LCP solves [us/step] | contact / structure | "
              "LCP / structure | LCP solves | Lemke pivots/solve (max) | active-set solves | "
              "iterations/solve (max) | fallbacks to Lemke | impacts | process time [s] |")
        print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
        for name, text in scale_decks().items():
            if only and only not in name:
                continue
            path = os.path.join(tmp, "scale.nml")
            with open(path, "w") as f:
                f.write(text)
            runs = [run(exe, path, tmp) for _ in range(max(3, repeats // 2))]
            steps = runs[0]["steps"]
            lcp = median_of(runs, "contact")
            structure = median_of(runs, "uncoupled")
            coupled = median_of(runs, "coupled")
            contact = coupled - structure
            r = runs[0]
            lemke_solves = r["solves"] - r["as_solves"] + r["as_fallbacks"]
            us = 1e6 / steps
            print(f"| {name} | {steps} | {us * structure:.2f} | {us * coupled:.2f} | {us * contact:.2f} | "
                  f"{us * lcp:.2f} | {contact / structure:.2f} | {lcp / structure:.2f} | {r['solves']} | "
                  f"{r['pivots'] / max(lemke_solves, 1):.2f} ({r['pivots_max']}) | "
                  f"{r['as_solves']} | {r['as_iterations'] / max(r['as_solves'], 1):.2f} ({r['as_iterations_max']}) | "
                  f"{r['as_fallbacks']} | {r['impacts']} | {median_of(runs, 'cpu'):.3f} |")


def seed_and_sweep(exe, seed, sweep_deck, repeats, tmp):
    cpu = []
    for _ in range(repeats):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        out = subprocess.run([exe, sweep_deck, "-o", tmp], check=True, capture_output=True, text=True).stdout
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu.append((after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime))
    m = re.search(r"gap sweep: (\d+) gaps in\s+([0-9.Ee+-]+) s", out)
    print(f"Gap study ({os.path.basename(sweep_deck)}): {m.group(1)} gaps, total process time median "
          f"{1e3 * statistics.median(cpu):.1f} ms (sweep loop {1e3 * float(m.group(2)):.1f} ms in the last run)")
    print()
    runs = [run(exe, seed, tmp) for _ in range(repeats)]
    print(f"Seed example ({os.path.basename(seed)}), {repeats} runs:")
    print(f"  total process time (CPU, uncoupled + coupled + outputs), median: "
          f"{1e3 * median_of(runs, 'cpu'):.1f} ms")
    print(f"  integration loops, median: uncoupled {1e3 * median_of(runs, 'uncoupled'):.2f} ms, "
          f"coupled {1e3 * median_of(runs, 'coupled'):.2f} ms "
          f"(LCP solves {1e3 * median_of(runs, 'contact'):.2f} ms)")
    r = runs[0]
    print(f"  {r['impacts']} impacts, {r['solves']} LCP solves in {r['steps']} steps, "
          f"{r['pivots']} pivots (max {r['pivots_max']} per solve), energy balance error {r['energy']:.2e}")
    print()


if __name__ == "__main__":
    main()
