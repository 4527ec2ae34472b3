"""Whole-process cost of pound on decks, against another build (called by scripts/bench_run).

    bench_run.py EXE OTHER_EXE REPEATS DECK [DECK ...]

Each deck runs with EXE (A) and OTHER_EXE (B) in turn, A B A B ..., after one warm-up pair,
every run a whole process writing its outputs into a scratch folder of its own. The cpu time
(user + system) of each run is read from the operating system's accounting of the finished
child (os.wait4). The table gives the median cpu time of each and the median of the pairwise
ratios A/B: on a shared machine the load falls on both runs of a pair alike.
"""
import os
import statistics
import subprocess
import sys
import tempfile


def cpu_seconds(argv, cwd):
    """Run argv in cwd, discard its output; the child's user + system seconds."""
    with open(os.devnull, "wb") as null:
        proc = subprocess.Popen(argv, cwd=cwd, stdout=null, stderr=null)
        _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        sys.exit(f"bench_run: {' '.join(argv)} exited with status {proc.returncode}")
    return usage.ru_utime + usage.ru_stime


def main(argv):
    if len(argv) < 5:
        sys.exit(__doc__)
    exe_a, exe_b, repeats, decks = os.path.abspath(argv[1]), os.path.abspath(argv[2]), int(argv[3]), argv[4:]
    print(f"{'deck':<36} {'A cpu [ms]':>11} {'B cpu [ms]':>11} {'A/B (median of pairs)':>22} {'pairs':>6}")
    with tempfile.TemporaryDirectory() as scratch:
        out_a, out_b = os.path.join(scratch, "a"), os.path.join(scratch, "b")
        os.mkdir(out_a)
        os.mkdir(out_b)
        for deck in decks:
            path = os.path.abspath(deck)
            where = os.path.dirname(path)
            a, b = [], []
            for i in range(repeats + 1):
                ta = cpu_seconds([exe_a, path, "-o", out_a], where)
                tb = cpu_seconds([exe_b, path, "-o", out_b], where)
                if i > 0:
                    a.append(ta)
                    b.append(tb)
            ratio = statistics.median(x / y for x, y in zip(a, b))
            print(f"{os.path.basename(deck):<36} {1e3 * statistics.median(a):>11.2f} "
                  f"{1e3 * statistics.median(b):>11.2f} {ratio:>22.3f} {repeats:>6}")


if __name__ == "__main__":
    main(sys.argv)
