"""Uncoupled integration speed of frame models against size and against the equivalent shear
building (called by scripts/bench_frames).

    bench_frames.py EXE BARE REPEATS

Frames of n storeys (3.0 m) x b bays (5.0 m) of 40/40 cm columns and 30/50 cm beams
(E = 3.1e7 kN/m^2), fixed bases, no constraints (3 DOFs per node, massless rotations), no
P-Delta, 20 t per floor and bay; the equivalent shear building (the rigid limit: rigid beams,
diaphragms and columns) has storey stiffness (b + 1) 12 E I / h^3 and the same floor masses.
Each run integrates 20 000 steps of 1 ms, output every 10 steps; the time is the program's
printed 'uncoupled integration' (set-up, eigenvalues and output excluded). For each size the
frame, its shear building and BARE (scripts/bench_frames_bare.f90: dpbtrf once, then one
dpbtrs per step with the frame's order and half-bandwidth, nothing else) run interleaved
(F S B F S B ...), REPEATS times; medians.
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_uncoupled import integration_time  # noqa: E402

STEPS = 20000
DT = 1.0e-3
SIZES = ((10, 1), (10, 3), (40, 3), (100, 1), (100, 3), (100, 5), (1000, 1), (1000, 3))
E, A_C, I_C, A_B, I_B, H, BAY, M_BAY = 3.1e7, 0.16, 2.1333e-3, 0.15, 3.125e-3, 3.0, 5.0, 20.0


def head(n, what):
    return f"""&analysis title='{what}', dt={DT}, t_end={STEPS * DT}, output_every=10, history='all' /
&ground kind='pulse', x0=0.010, a=2.0, b=12.566370614359172 /
"""


def frame_deck(n, b):
    return head(n, f"frame {n} x {b}") + f"""&building name='F', n_storeys={n}, height={n}*{H}, mass={n}*{M_BAY * b},
          model='frame', n_bays={b}, bay_width={BAY}, column_e={E}, column_area={A_C},
          column_inertia={I_C}, beam_e={E}, beam_area={A_B}, beam_inertia={I_B}, base='fixed',
          damping_ratio=0.05, damping_modes=1,2, p_delta=.false. /
"""


def shear_deck(n, b):
    k = (b + 1) * 12.0 * E * I_C / H**3
    return head(n, f"shear building {n} x {b}") + f"""&building name='S', n_storeys={n}, height={n}*{H},
          mass={n}*{M_BAY * b}, stiffness={n}*{k!r}, damping_ratio=0.05, damping_modes=1,2,
          p_delta=.false. /
"""


def bare_time(bare, dofs, kd):
    out = subprocess.run([bare, str(dofs), str(kd), str(STEPS)], check=True, capture_output=True, text=True)
    return float(out.stdout.split()[0])


def frame_layout(path):
    """(DOFs, half-bandwidth) of the frame, from its listing."""
    with open(path) as f:
        listing = f.read()
    return (int(re.search(r"elements, (\d+) DOFs", listing).group(1)),
            int(re.search(r"half-bandwidth (\d+)", listing).group(1)))


def main():
    exe, bare, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n, b in SIZES:
            paths = []
            for name, text in (("frame", frame_deck(n, b)), ("shear", shear_deck(n, b))):
                paths.append(os.path.join(tmp, f"{name}{n}x{b}.nml"))
                with open(paths[-1], "w") as f:
                    f.write(text)
            tf, ts, tb = [], [], []
            for _ in range(repeats):
                tf.append(integration_time(exe, paths[0], tmp))
                dofs, kd = frame_layout(os.path.join(tmp, f"frame{n}x{b}.out"))
                ts.append(integration_time(exe, paths[1], tmp))
                tb.append(bare_time(bare, dofs, kd))
            rows.append((n, b, dofs, kd, *(statistics.median(t) for t in (tf, ts, tb))))
    print(f"{STEPS} steps, {repeats} interleaved runs per model, medians\n")
    print("| storeys x bays | frame DOFs | kd | frame time [s] | frame DOF-steps/s | frame per step [us] "
          "| bare dpbtrs per step [us] | bare/frame | shear building per step [us] | frame/shear |")
    print("|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for n, b, dofs, kd, tf, ts, tb in rows:
        print(f"| {n} x {b} | {dofs} | {kd} | {tf:.3f} | {dofs * STEPS / tf:.3e} | {1e6 * tf / STEPS:.2f} "
              f"| {1e6 * tb / STEPS:.2f} | {tb / tf:.2f} | {1e6 * ts / STEPS:.3f} | {tf / ts:.0f} |")


if __name__ == "__main__":
    main()
