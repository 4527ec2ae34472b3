"""Suite benchmarks (called by scripts/bench_suite).

    bench_suite.py EXE SEED_DECK REPEATS [--opensees PYTHON]

1. The study of a design office: the seed pair (the buildings and joints of SEED_DECK) under 11
   synthetic motions of 10 s at dt = 1 ms, each scaled to a common Sa(T1), swept over 50 gaps
   (550 coupled runs and 11 uncoupled runs of the pair): the whole `pound` run, process time
   (user + system) and wall time, medians of REPEATS runs.
2. Batched uncoupled integration: a 1000-storey stick, 20 000 steps, histories off, under 8
   motions (one batch of lanes) and under 1 motion, run interleaved (8, 1, 8, 1, ...): the
   uncoupled integration's DOF-steps/s per motion as the program reports it (the batch's loop
   time shared by its motions), medians and the median of the pairwise ratios.
3. With --mpi MPI_EXE (pound built with -DPOUND_MPI=ON): strong scaling of the study of 1, the
   whole `mpirun -np 1` and `mpirun -np 2` commands run interleaved (wall time, medians and the
   median of the pairwise ratios), and this machine's own ceiling for two processes: one serial
   run of the study against two serial runs of it at once (if the two cores were independent,
   the pair would take as long as one run; the ratio bounds what any program gains from a second
   core here). Open MPI is started with the settings for one node (`OMPI_MCA_pml=ob1`,
   `OMPI_MCA_btl=self,vader`: no probing of network transports, 0.13 s instead of 0.35 s).
4. With --opensees PYTHON (an interpreter with openseespy, numpy, h5py): the study of 1 with
   OpenSeesPy on the same model (scripts/bench_suite_opensees.py: every motion uncoupled and at
   5 of the 50 gaps, the time per coupled run extrapolated to the 550) and its ratio to pound's
   median process time. Only reported when the interpreter has openseespy.
"""
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

MOTIONS = 11
GAPS = 50
STICK = 1000
STICK_STEPS = 20000
BATCH = 8


def seed_groups(path):
    """The &building and &contact groups of the seed deck, comments removed."""
    text = open(path).read()
    lines = [line.split("!", 1)[0].rstrip() for line in text.splitlines()]
    groups, current = [], None
    for line in lines:
        s = line.strip()
        if current is None and (s.startswith("&building") or s.startswith("&contact")):
            current = [s]
        elif current is not None:
            current.append(s)
        if current is not None and s == "/":
            groups.append("\n".join(x for x in current if x) + "\n")
            current = None
    return "".join(groups)


def synthetic(name, seed, duration, target=None):
    scale = f", scale_to='sa', target={target}" if target else ""
    return (f"&ground name='{name}', kind='synthetic', duration={duration}, pga=2.0, seed={seed}, "
            f"rise_time=1.0, plateau_end=7.0, decay_rate=0.5{scale} /\n")


def suite_deck(seed, histories=False):
    deck = ("&analysis title='seed pair, 11 motions x 50 gaps', dt=1.0e-3, t_end=10.0, output_every=1, "
            "history='u' /\n")
    for k in range(1, MOTIONS + 1):
        ground = synthetic(f"m{k}", k, 10.0, 3.0)
        deck += ground.replace(" /", ", histories=.true. /") if histories else ground
    deck += seed_groups(seed)
    deck += f"&sweep gap_from=0.0, gap_to=0.010, n_gaps={GAPS} /\n"
    return deck


def stick_deck(motions):
    deck = (f"&analysis title='stick, {STICK} storeys, {motions} motions', dt=1.0e-3, "
            f"t_end={STICK_STEPS * 1.0e-3}, output_every=10, history='none' /\n")
    # Every motion keeps its (empty) histories: the motions run whole are batched among
    # themselves, so that the 8 motions are one batch and the first motion's reported time is
    # its share of the batch's loop (without, the first motion runs alone and the other 7 in a
    # batch of their own).
    for k in range(1, motions + 1):
        deck += synthetic(f"m{k}", k, STICK_STEPS * 1.0e-3).replace(" /", ", histories=.true. /")
    deck += (f"&building name='S', n_storeys={STICK}, height={STICK}*3.0, mass={STICK}*10.0, "
             f"stiffness={STICK}*1.0e5, damping_ratio=0.05, damping_modes=1,2 /\n")
    return deck


def run(exe, deck, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    stdout = subprocess.run([exe, deck, "-o", out], check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    m = re.search(r"uncoupled integration:\s+([0-9.Ee+-]+) s", stdout)
    return cpu, wall, (float(m.group(1)) if m else None)


def wall(cmd, env=None):
    start = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True, env=env)
    return time.perf_counter() - start


def mpi_scaling(exe, mpi_exe, deck, tmp, repeats):
    """Strong scaling of the study on 1 and 2 ranks, and the machine's ceiling for 2 processes."""
    env = dict(os.environ, OMPI_MCA_pml="ob1", OMPI_MCA_btl="self,vader")
    mpirun = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np"]
    out = [os.path.join(tmp, f"mpi{i}") for i in range(3)]
    one = mpirun + ["1", mpi_exe, deck, "-o", out[0], "--quiet"]
    two = mpirun + ["2", mpi_exe, deck, "-o", out[1], "--quiet"]
    start = mpirun + ["2", mpi_exe, "--version"]
    serial = [exe, deck, "-o", out[2], "--quiet"]
    pair = ["sh", "-c", f"'{exe}' '{deck}' -o '{out[0]}' --quiet & '{exe}' '{deck}' -o '{out[1]}' --quiet; wait"]
    wall(one, env)  # warm-up
    t = {"one": [], "two": [], "start": [], "serial": [], "pair": []}
    for _ in range(repeats):
        t["one"].append(wall(one, env))
        t["two"].append(wall(two, env))
        t["start"].append(wall(start, env))
        t["serial"].append(wall(serial))
        t["pair"].append(wall(pair))
    med = {k: statistics.median(v) for k, v in t.items()}
    speedup = [a / b for a, b in zip(t["one"], t["two"])]
    pair_ratio = [b / a for a, b in zip(t["serial"], t["pair"])]
    print(f"MPI strong scaling of the study (wall time of the whole command, {repeats} interleaved runs each, "
          f"medians):\n")
    print("| command | wall [s] (median) | min, max |")
    print("|---|--:|--:|")
    for key, name in (("one", "mpirun -np 1 pound"), ("two", "mpirun -np 2 pound"),
                      ("start", "mpirun -np 2 pound --version (start-up alone)"),
                      ("serial", "pound (serial build)"), ("pair", "two serial runs at once")):
        print(f"| {name} | {med[key]:.3f} | {min(t[key]):.3f}, {max(t[key]):.3f} |")
    ceiling = 2.0 / statistics.median(pair_ratio)
    print(f"\n2 ranks against 1: median of pairwise speed-ups {statistics.median(speedup):.2f}x "
          f"(min {min(speedup):.2f}, max {max(speedup):.2f}); target 1.8x")
    print(f"This machine's ceiling for two processes: two serial runs at once take "
          f"{statistics.median(pair_ratio):.3f}x the time of one (median of pairwise ratios), "
          f"so two cores give at most {ceiling:.2f}x the throughput of one")


def opensees(python, exe, seed, tmp, pound_seconds):
    """The OpenSeesPy study and its ratio to pound's process time (nothing without openseespy)."""
    try:
        ok = subprocess.run([python, "-c", "import openseespy.opensees, numpy, h5py"],
                            capture_output=True).returncode == 0
    except OSError:
        ok = False
    if not ok:
        print(f"OpenSeesPy: {python} has no openseespy (or numpy, h5py): no comparison")
        return
    deck = os.path.join(tmp, "motions.nml")
    with open(deck, "w") as f:
        f.write(suite_deck(seed, histories=True))
    subprocess.run([exe, deck, "-o", tmp], check=True, capture_output=True)
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bench_suite_opensees.py")
    out = subprocess.run([python, script, os.path.join(tmp, "motions.h5"), "5", str(GAPS)], check=True,
                         capture_output=True, text=True).stdout
    per_run = float(re.search(r"opensees_per_coupled_run\s+([0-9.]+)", out).group(1))
    total = float(re.search(r"opensees_seconds\s+([0-9.]+)", out).group(1))
    print(f"OpenSeesPy, the same study (11 uncoupled runs, 55 coupled runs timed, {per_run:.3f} s of process "
          f"time per 10 s coupled run, extrapolated to {MOTIONS * GAPS}):\n")
    print("| OpenSeesPy [s] (estimate) | pound [s] (median) | OpenSeesPy / pound |")
    print("|--:|--:|--:|")
    print(f"| {total:.1f} | {pound_seconds:.3f} | {total / pound_seconds:.0f} |")


def main():
    exe, seed, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
    python = sys.argv[sys.argv.index("--opensees") + 1] if "--opensees" in sys.argv else None
    mpi_exe = sys.argv[sys.argv.index("--mpi") + 1] if "--mpi" in sys.argv else None
    with tempfile.TemporaryDirectory() as tmp:
        suite = os.path.join(tmp, "suite.nml")
        with open(suite, "w") as f:
            f.write(suite_deck(seed))
        run(exe, suite, tmp)  # warm-up
        runs = [run(exe, suite, tmp) for _ in range(repeats)]
        cpu = statistics.median(r[0] for r in runs)
        wall = statistics.median(r[1] for r in runs)
        print(f"Seed pair, {MOTIONS} synthetic motions of 10 s at dt = 1 ms x {GAPS} gaps "
              f"({MOTIONS * GAPS} coupled runs + {MOTIONS} uncoupled runs of the pair), whole program, "
              f"{repeats} runs:\n")
        print("| process time [s] (median) | min, max | wall time [s] (median) | target |")
        print("|--:|--:|--:|--:|")
        print(f"| {cpu:.3f} | {min(r[0] for r in runs):.3f}, {max(r[0] for r in runs):.3f} | {wall:.3f} "
              f"| <= 2 s |\n")

        decks = {}
        for motions in (BATCH, 1):
            decks[motions] = os.path.join(tmp, f"stick{motions}.nml")
            with open(decks[motions], "w") as f:
                f.write(stick_deck(motions))
        rates = {BATCH: [], 1: []}
        for _ in range(repeats):
            for motions in (BATCH, 1):
                rates[motions].append(STICK * STICK_STEPS / run(exe, decks[motions], tmp)[2])
        ratios = [a / b for a, b in zip(rates[BATCH], rates[1])]
        print(f"Uncoupled integration of a {STICK}-storey stick, {STICK_STEPS} steps, DOF-steps/s per motion "
              f"(interleaved, {repeats} runs each):\n")
        print(f"| motions | DOF-steps/s (median) | min, max |")
        print("|--:|--:|--:|")
        for motions in (1, BATCH):
            r = rates[motions]
            print(f"| {motions} | {statistics.median(r):.3e} | {min(r):.3e}, {max(r):.3e} |")
        print(f"\n{BATCH} motions / 1 motion: median of pairwise ratios {statistics.median(ratios):.2f} "
              f"(min {min(ratios):.2f}, max {max(ratios):.2f})")
        if mpi_exe is not None:
            print()
            mpi_scaling(exe, mpi_exe, suite, tmp, repeats)
        if python is not None:
            print()
            opensees(python, exe, seed, tmp, cpu)


if __name__ == "__main__":
    main()
