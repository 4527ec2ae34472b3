"""Uncoupled integration speed against model size (called by scripts/bench_uncoupled)."""
import os
import re
import statistics
import subprocess
import sys
import tempfile

STEPS = 20000
DT = 1.0e-3


def deck(n):
    return f"""&analysis title='stick model, {n} storeys', dt={DT}, t_end={STEPS * DT},
          output_every=10, history='all' /
&ground kind='pulse', x0=0.010, a=2.0, b=12.566370614359172 /
&building name='S', n_storeys={n}, height={n}*3.0, mass={n}*10.0, stiffness={n}*1.0e5,
          damping_ratio=0.05, damping_modes=1,2, p_delta=.false. /
"""


def main():
    exe, repeats = sys.argv[1], int(sys.argv[2])
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in (10, 100, 1000, 10000):
            path = os.path.join(tmp, f"stick{n}.nml")
            with open(path, "w") as f:
                f.write(deck(n))
            times = []
            for _ in range(repeats if n < 10000 else max(3, repeats // 2)):
                out = subprocess.run([exe, path, "-o", tmp], check=True, capture_output=True, text=True).stdout
                m = re.search(r"uncoupled integration:\s+([0-9.Ee+-]+) s", out)
                times.append(float(m.group(1)))
            t = statistics.median(times)
            rows.append((n, t, n * STEPS / t))
    print(f"| storeys | integration time [s] (median) | DOF-steps/s | time per DOF-step [ns] |")
    print(f"|--:|--:|--:|--:|")
    for n, t, rate in rows:
        print(f"| {n} | {t:.4f} | {rate:.3e} | {1e9 / rate:.2f} |")


if __name__ == "__main__":
    main()
