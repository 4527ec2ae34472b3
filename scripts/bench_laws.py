"""Cost of the joint laws on the seed example (called by scripts/bench_laws)."""
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


if __name__ == "__main__":
    main()
