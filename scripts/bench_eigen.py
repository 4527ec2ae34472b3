"""Cost of the natural periods against model size (called by scripts/bench_eigen).

    bench_eigen.py EXE REPEATS [--vs OTHER_EXE]

Runs stick models of 1000, 10 000 and 20 000 storeys for one time step without histories, so
that the process time is the set-up: deck, model and its natural periods (the eigen
analysis dominates at these sizes). With --vs, EXE (A) and OTHER_EXE (B) run interleaved
(A B A B ...) on the same decks: medians of each, their difference (the eigen analysis that
one of them saves) and the median of the pairwise ratios B/A.
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

from bench_uncoupled import interleaved, parse_args

SIZES = (1000, 10000, 20000)


def deck(n):
    return f"""&analysis title='stick model, {n} storeys', dt=1.0e-3, t_end=1.0e-3, history='none' /
&ground kind='pulse', x0=0.010, a=2.0, b=12.566370614359172 /
&building name='S', n_storeys={n}, height={n}*3.0, mass={n}*10.0, stiffness={n}*1.0e5,
          damping_ratio=0.05, damping_modes=1,2, p_delta=.false. /
"""


def run_time(exe, path, out_dir):
    t0 = time.perf_counter()
    subprocess.run([exe, path, "-o", out_dir], check=True, capture_output=True)
    return time.perf_counter() - t0


def main():
    exe, repeats, other = parse_args(sys.argv[1:])
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in SIZES:
            path = os.path.join(tmp, f"stick{n}.nml")
            with open(path, "w") as f:
                f.write(deck(n))
            rows.append((n, *interleaved(run_time, exe, other, path, repeats, tmp, tmp)))
    if other is None:
        print("| storeys | set-up time [s] (median) |")
        print("|--:|--:|")
        for n, ta, _ in rows:
            print(f"| {n} | {statistics.median(ta):.3f} |")
        return
    print(f"A = {exe}\nB = {other}\n")
    print("| storeys | repeats | A set-up [s] (median) | B set-up [s] (median) | B - A [s] "
          "| B/A (median of pairwise ratios) |")
    print("|--:|--:|--:|--:|--:|--:|")
    for n, ta, tb in rows:
        ma, mb = statistics.median(ta), statistics.median(tb)
        ratios = [b / a for a, b in zip(ta, tb)]
        print(f"| {n} | {len(ta)} | {ma:.3f} | {mb:.3f} | {mb - ma:.3f} | {statistics.median(ratios):.2f} |")


if __name__ == "__main__":
    main()
