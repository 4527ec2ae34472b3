"""Uncoupled integration speed against model size (called by scripts/bench_uncoupled).

    bench_uncoupled.py EXE REPEATS [--vs OTHER_EXE] [--hht ALPHA]

With --vs, EXE (A) and OTHER_EXE (B) run interleaved (A B A B ...) on the same decks, so that
the load of a shared machine falls on both alike; the table gives the median of each and the
median of the pairwise ratios A/B of DOF-steps/s. With --hht ALPHA, A is EXE with
`integrator = 'hht', hht_alpha = ALPHA` and B the same EXE with Newmark, interleaved: the cost of
HHT-alpha against Newmark's (B/A of DOF-steps/s = HHT's time over Newmark's).
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

STEPS = 20000
DT = 1.0e-3
SIZES = tuple(int(s) for s in os.environ.get("POUND_BENCH_SIZES", "10,100,1000,10000").split(","))


def deck(n, hht=None):
    method = "" if hht is None else f", integrator='hht', hht_alpha={hht}"
    return f"""&analysis title='stick model, {n} storeys', dt={DT}, t_end={STEPS * DT},
          output_every=10, history='all'{method} /
&ground kind='pulse', x0=0.010, a=2.0, b=12.566370614359172 /
&building name='S', n_storeys={n}, height={n}*3.0, mass={n}*10.0, stiffness={n}*1.0e5,
          damping_ratio=0.05, damping_modes=1,2, p_delta=.false. /
"""


def integration_time(exe, path, out_dir):
    out = subprocess.run([exe, path, "-o", out_dir], check=True, capture_output=True, text=True).stdout
    m = re.search(r"uncoupled integration:\s+([0-9.Ee+-]+) s", out)
    if m is None:
        sys.exit(f"bench_uncoupled: {exe} printed no 'uncoupled integration' time")
    return float(m.group(1))


def option(args, name):
    """The value of option `name` in args (removed from it), or None."""
    if name not in args:
        return None
    i = args.index(name)
    value = args[i + 1]
    del args[i:i + 2]
    return value


def parse_args(argv):
    """EXE REPEATS [--vs OTHER_EXE] -> (EXE, REPEATS, OTHER_EXE or None); shared by bench_eigen.py."""
    args = list(argv)
    option(args, "--hht")
    other = option(args, "--vs")
    return args[0], int(args[1]), other


def interleaved(measure, exe, other, path, count, dir_a, dir_b, path_b=None):
    """measure(EXE, deck, out_dir) count times, alternating with OTHER_EXE when given (on deck
    path_b when given): (A times, B times)."""
    times_a, times_b = [], []
    for _ in range(count):
        times_a.append(measure(exe, path, dir_a))
        if other is not None:
            times_b.append(measure(other, path_b or path, dir_b))
    return times_a, times_b


def main():
    exe, repeats, other = parse_args(sys.argv[1:])
    hht = option(list(sys.argv[1:]), "--hht")
    if hht is not None:
        other = exe
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        dir_a, dir_b = os.path.join(tmp, "a"), os.path.join(tmp, "b")
        os.mkdir(dir_a)
        os.mkdir(dir_b)
        for n in SIZES:
            path = os.path.join(tmp, f"stick{n}.nml")
            with open(path, "w") as f:
                f.write(deck(n, hht))
            path_b = None
            if hht is not None:
                path_b = os.path.join(tmp, f"stick{n}_newmark.nml")
                with open(path_b, "w") as f:
                    f.write(deck(n))
            count = repeats if other is not None or n < 10000 else max(3, repeats // 2)
            rows.append((n, *interleaved(integration_time, exe, other, path, count, dir_a, dir_b, path_b)))
    if other is None:
        print("| storeys | integration time [s] (median) | DOF-steps/s | time per DOF-step [ns] |")
        print("|--:|--:|--:|--:|")
        for n, times_a, _ in rows:
            t = statistics.median(times_a)
            rate = n * STEPS / t
            print(f"| {n} | {t:.4f} | {rate:.3e} | {1e9 / rate:.2f} |")
        return
    if hht is not None:
        print(f"A = {exe} with integrator = 'hht', hht_alpha = {hht}\nB = the same with Newmark\n")
    else:
        print(f"A = {exe}\nB = {other}\n")
    print("| storeys | repeats | A time [s] (median) | B time [s] (median) | A DOF-steps/s | B DOF-steps/s "
          "| A/B (ratio of medians) | A/B (median of pairwise ratios) | A/B (min, max pairwise) |")
    print("|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for n, times_a, times_b in rows:
        ta, tb = statistics.median(times_a), statistics.median(times_b)
        ratios = [b / a for a, b in zip(times_a, times_b)]
        print(f"| {n} | {len(ratios)} | {ta:.4f} | {tb:.4f} | {n * STEPS / ta:.3e} | {n * STEPS / tb:.3e} "
              f"| {tb / ta:.3f} | {statistics.median(ratios):.3f} | {min(ratios):.3f}, {max(ratios):.3f} |")


if __name__ == "__main__":
    main()
