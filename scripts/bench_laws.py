"""Cost of the joint laws on the seed example (called by scripts/bench_laws).

Two tables: the piecewise-linear family (elastic against the paper's Fig. 1b law), and the
smooth laws of issue 26 (kelvin, hertz, hertz_damp, jankowski, solved exactly per step by
Newton on the step's LCP) against law = 'elastic' on the same seed pair at the same dt, under
the pulse and, where shared/records is beside the clone, under El Centro (20 s): medians of
the coupled integration time and their ratio to elastic (the issue's bound: 2x)."""
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile


def run(exe, deck, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    text = subprocess.run([exe, deck, "-o", out], check=True, capture_output=True, text=True).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    coupled = float(re.search(r"(?m)^\s*coupled integration:\s+([0-9.Ee+-]+) s", text).group(1))
    return cpu, coupled


def listing_stats(path):
    text = open(path).read()
    solves = int(re.search(r"solves (\d+)", text).group(1))
    # LCPs solved by the active-set method (elastic steps) count as solves too.
    active = re.search(r"active-set method .*: solves (\d+),", text)
    if active:
        failed = int(re.search(r"(\d+) failed and were solved by Lemke", text).group(1))
        solves += int(active.group(1)) - failed
    pivots = int(re.search(r"pivots total (\d+)", text).group(1))
    largest = int(re.search(r"largest LCP \(contact \+ yield \+ segment-end rows\): (\d+)", text).group(1))
    steps = int(re.search(r"steps = (\d+)", text).group(1))
    return steps, solves, pivots, largest


def main():
    exe, root, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
    decks = [("elastic", os.path.join(root, "input", "two_frames_elastic.nml")),
             ("parabola_cubic (Fig. 1b, 8 chords)", os.path.join(root, "input", "two_frames_pdelta.nml"))]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for name, deck in decks:
            cpu, cpl = [], []
            for _ in range(repeats):
                a, b = run(exe, deck, tmp)
                cpu.append(a)
                cpl.append(b)
            stem = os.path.splitext(os.path.basename(deck))[0]
            steps, solves, pivots, largest = listing_stats(os.path.join(tmp, stem + ".out"))
            rows.append((name, statistics.median(cpu), statistics.median(cpl), steps, solves, pivots, largest))
    print(f"seed example, 5000 steps, medians of {repeats} runs")
    print("| law | process time [ms] | coupled integration [ms] | LCP solves | pivots | pivots/step | largest LCP |")
    print("|---|--:|--:|--:|--:|--:|--:|")
    for name, cpu, cpl, steps, solves, pivots, largest in rows:
        print(f"| {name} | {1e3 * cpu:.1f} | {1e3 * cpl:.2f} | {solves} | {pivots} | {pivots / steps:.4f} | {largest} |")
    extra = rows[1][2] - rows[0][2]
    print(f"extra complementarity pairs: coupled integration +{1e3 * extra:.2f} ms "
          f"({100 * extra / rows[0][2]:+.0f} %), process time {1e3 * (rows[1][1] - rows[0][1]):+.1f} ms")
    smooth_table(exe, root, repeats)


SMOOTH_LAWS = [
    ("elastic", "law = 'elastic'\n   stiffness = 1.0e6\n   dashpot = 0.0"),
    ("kelvin", "law = 'kelvin'\n   stiffness = 1.0e6\n   restitution = 0.65"),
    ("hertz", "law = 'hertz'\n   stiffness = 3.16e7"),
    ("hertz_damp", "law = 'hertz_damp'\n   stiffness = 3.16e7\n   restitution = 0.65"),
    ("jankowski", "law = 'jankowski'\n   stiffness = 3.16e7\n   restitution = 0.65"),
]


def smooth_decks(root, tmp):
    """The seed deck with each law of SMOOTH_LAWS (Hertz-type kh = 3.16e7 kN/m^(3/2): the
    secant of 1e6 kN/m at 1 mm), under the pulse and under El Centro (if the record is there)."""
    base = open(os.path.join(root, "input", "two_frames_elastic.nml")).read()
    old = "law = 'elastic'          ! constraint law\n   stiffness = 1.0e6        ! joint stiffness p (kN/m)\n" \
          "   dashpot = 0.0            ! joint dashpot c (kN s/m): none"
    assert old in base
    record = os.path.abspath(os.path.join(root, "..", "shared", "records", "elCentro_Peknold.AT2"))
    motions = [("pulse, 5 s", None)]
    if os.path.exists(record):
        motions.append(("El Centro, 20 s", record))
    decks = []
    for motion, rec in motions:
        for name, law in SMOOTH_LAWS:
            text = base.replace(old, law)
            if rec:
                text = re.sub(r"(?s)&ground.*?\n/", "&ground\n   kind = 'record'\n   file = '" + rec + "'\n/", text, 1)
                text = text.replace("t_end = 5.0", "t_end = 20.0")
            path = os.path.join(tmp, f"{name}_{len(decks)}.nml")
            open(path, "w").write(text)
            decks.append((motion, name, path))
    return decks


def smooth_table(exe, root, repeats):
    with tempfile.TemporaryDirectory() as tmp:
        decks = smooth_decks(root, tmp)
        times = {deck: [] for _, _, deck in decks}
        # Interleaved (every deck once per round): a load on the machine falls on all alike.
        for _ in range(repeats):
            for _, _, deck in decks:
                times[deck].append(run(exe, deck, tmp)[1])
        rows = []
        for motion, name, deck in decks:
            stem = os.path.splitext(os.path.basename(deck))[0]
            text = open(os.path.join(tmp, stem + ".out")).read()
            # LCP solves of the run: Lemke's and the active-set method's (Newton iterates).
            solves = int(re.search(r"(?m)^\s+solves (\d+)", text).group(1))
            active = re.search(r"active-set method .*: solves (\d+),", text)
            if active:
                solves += int(active.group(1))
            rows.append((motion, name, statistics.median(times[deck]), solves))
    print(f"\nsmooth laws on the seed pair, dt = 1 ms, medians of {repeats} runs of the coupled integration")
    print("| motion | law | coupled integration [ms] | ratio to elastic | LCP solves (Newton iterates) |")
    print("|---|---|--:|--:|--:|")
    ref = {}
    for motion, name, t, solves in rows:
        if name == "elastic":
            ref[motion] = t
        print(f"| {motion} | {name} | {1e3 * t:.2f} | {t / ref[motion]:.2f} | {solves} |")


if __name__ == "__main__":
    main()
