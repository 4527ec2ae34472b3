"""Speed of bilinear storeys (issue 25; called by scripts/bench_inelastic).

    bench_inelastic.py EXE REPEATS RECORDS_DIR

1. The seed example: the coupled loop of input/seed_bilinear.nml (bilinear storeys in both
   buildings) against that of input/two_frames_elastic.nml (the elastic seed), both with
   t_end = 60 s in place of 5 s (60000 steps: a loop of tens of milliseconds, not one), run
   interleaved (elastic, bilinear, elastic, ...): medians and the median of the pairwise ratios.
2. A 1000-storey stick under El Centro (IELC180, dt 0.01 s, 40 s, 4000 steps): elastic and with
   bilinear storeys (uniform yield shear 4000 kN, r = 0.05: about 10 % of the storeys yield),
   interleaved: uncoupled-loop DOF-steps/s, medians.
The loop times are those the program prints (set-up and output excluded).
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STICK_STEPS = 4000


def stick(n, records, bilinear):
    law = ", storey_law='bilinear', yield_shear=%d*4000.0, hardening_ratio=0.05" % n if bilinear else ""
    return f"""&analysis title='{n}-storey stick, El Centro', dt=0.01, t_end=40.0, output_every=10,
          history='drift' /
&ground kind='record', file='{records}/IELC180.AT2' /
&building name='S', n_storeys={n}, height={n}*3.0, mass={n}*10.0, stiffness={n}*1.0e7,
          damping_ratio=0.05, damping_modes=1,2, p_delta=.false.{law} /
"""


def longer(deck, tmp):
    """A copy of `deck` in `tmp` with t_end = 60 s (its time line is 't_end = 5.0')."""
    with open(deck) as f:
        text = f.read()
    if "t_end = 5.0 " not in text:
        sys.exit(f"bench_inelastic: {deck} has no 't_end = 5.0' line")
    path = os.path.join(tmp, os.path.basename(deck))
    with open(path, "w") as f:
        f.write(text.replace("t_end = 5.0 ", "t_end = 60.0 "))
    return path


def loop_time(exe, deck, out_dir, which):
    out = subprocess.run([exe, deck, "-o", out_dir], check=True, capture_output=True, text=True,
                         cwd=os.path.dirname(deck)).stdout
    m = re.search(which + r" integration:\s+([0-9.Ee+-]+) s", out)
    if m is None:
        sys.exit(f"bench_inelastic: {exe} printed no '{which} integration' time for {deck}")
    return float(m.group(1))


def pairs(exe, a, b, which, count, out_dir):
    ta, tb = [], []
    for _ in range(count):
        ta.append(loop_time(exe, a, out_dir, which))
        tb.append(loop_time(exe, b, out_dir, which))
    return ta, tb


def main():
    exe, repeats, records = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    with tempfile.TemporaryDirectory() as tmp:
        ela, bil = (longer(os.path.join(ROOT, "input", name), tmp)
                    for name in ("two_frames_elastic.nml", "seed_bilinear.nml"))
        te, tb = pairs(exe, ela, bil, "coupled", repeats, tmp)
        ratios = [b / a for a, b in zip(te, tb)]
        print("| seed example, coupled loop | repeats | elastic [s] (median) | bilinear [s] (median) "
              "| bilinear/elastic (median of pairwise ratios) | (min, max) |")
        print("|--|--:|--:|--:|--:|--:|")
        print(f"| two_frames_elastic.nml vs seed_bilinear.nml, t_end = 60 s | {repeats} | {statistics.median(te):.3e} "
              f"| {statistics.median(tb):.3e} | {statistics.median(ratios):.2f} | {min(ratios):.2f}, {max(ratios):.2f} |")
        n = 1000
        paths = []
        for bilinear in (False, True):
            p = os.path.join(tmp, f"stick{n}_{'bilinear' if bilinear else 'elastic'}.nml")
            with open(p, "w") as f:
                f.write(stick(n, records, bilinear))
            paths.append(p)
        te, tb = pairs(exe, paths[0], paths[1], "uncoupled", repeats, tmp)
        ratios = [b / a for a, b in zip(te, tb)]
        print()
        print("| 1000-storey stick, El Centro, 4000 steps | repeats | elastic [s] | bilinear [s] "
              "| elastic DOF-steps/s | bilinear DOF-steps/s | bilinear/elastic (median of pairwise ratios) |")
        print("|--|--:|--:|--:|--:|--:|--:|")
        ma, mb = statistics.median(te), statistics.median(tb)
        print(f"| uniform yield shear 4000 kN, r = 0.05 | {repeats} | {ma:.3e} | {mb:.3e} | {n * STICK_STEPS / ma:.3e} "
              f"| {n * STICK_STEPS / mb:.3e} | {statistics.median(ratios):.2f} |")


if __name__ == "__main__":
    main()
