"""The risk-targeted joint's benchmark (called by scripts/bench_risk).

    bench_risk.py POUND RECORDS DT [--mpi MPI_POUND] [--opensees PYTHON]

Writes the deck (input/risk_seed.nml's seed shear pair and joints, `&ground kind =
'record_set'` over every AT2 file of RECORDS, 8 stripes Sa(T1) = 0.1 g ... 0.8 g, a sweep of 21
gaps from 0 to 40 mm, the power-law hazard of input/risk_seed.nml, t_end 30 s, time step DT) and
times the whole program once serially and, with --mpi, once under `mpirun -np 2` (wall time, and
the CPU time of the processes: on a busy machine the CPU time is the fairer figure).

OpenSeesPy (--opensees, optional): the same discrete model as scripts/bench_suite_opensees.py
(zeroLength storey springs, ElasticPPGap joints, Newmark average acceleration, Newton; its `run`
is reused). A sample of (stripe, motion) cases, every 11th motion at the lowest, a middle and
the highest stripe, is run uncoupled, coupled at the deck gap and at 5 of the 21 gaps; the CPU
time per uncoupled and per coupled run is multiplied by the study's runs (per case 1 uncoupled,
1 + 21 coupled: OpenSees has no run without contact that stands for the gaps beyond closing).
The motion of a sampled case is the record scaled to the stripe by its 5 %-damped Sa at T1 of
pound's listing, as pound scales it (linear interpolation at DT). Prints key value lines.
"""
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def deck_text(records, dt):
    seed = open(os.path.join(HERE, '..', 'input', 'risk_seed.nml')).read()
    body = seed[seed.index('&building'):seed.index('&sweep')]
    hazard = seed[seed.index('&hazard'):]
    return f"""&analysis title = 'bench_risk: P-695 far-field x 8 stripes x 21 gaps', dt = {dt}, t_end = 30.0,
   history = 'none' /
&ground kind = 'record_set', folder = '{records}', pattern = '*.AT2' /
{body}&sweep gap_from = 0.0, gap_to = 0.040, n_gaps = 21 /
&stripes levels_g = 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, target_lambda = 10.0, target_quantities = 'storey_shear' /
{hazard}"""


def timed(cmd):
    """Wall time and the CPU time (user + system) of the command and its children."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)}: exit {r.returncode}\n{r.stderr}")
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    timed.cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, r.stdout


def read_at2(path):
    lines = open(path).read().splitlines()
    dt = float(re.search(r'DT=\s*([0-9.Ee+-]+)', lines[3]).group(1))
    values = [float(x) for line in lines[4:] for x in line.split()]
    return dt, values


def sa(ag, dt, period, zeta=0.05):
    """5 %-damped pseudo-spectral acceleration by Newmark average acceleration (ag in m/s^2)."""
    w = 2 * math.pi / period
    k, c = w * w, 2 * zeta * w
    u = v = 0.0
    a = -ag[0]
    peak = 0.0
    kh = k + 2 * c / dt + 4 / dt ** 2
    for i in range(1, len(ag)):
        p = -ag[i] + (4 / dt ** 2 * u + 4 / dt * v + a) + c * (2 / dt * u + v)
        un = p / kh
        vn = 2 / dt * (un - u) - v
        a = 4 / dt ** 2 * (un - u) - 4 / dt * v - a
        u, v = un, vn
        peak = max(peak, abs(u))
    return w * w * peak


def main():
    pound, records, dt = sys.argv[1], sys.argv[2], float(sys.argv[3])
    args = sys.argv[4:]
    mpi = args[args.index('--mpi') + 1] if '--mpi' in args else None
    opensees = args[args.index('--opensees') + 1] if '--opensees' in args else None
    work = tempfile.mkdtemp(prefix='pound_bench_risk_')
    deck = os.path.join(work, 'bench_risk.nml')
    open(deck, 'w').write(deck_text(os.path.abspath(records), dt))
    seconds, out = timed([pound, deck, '-o', os.path.join(work, 'serial'), '--quiet'])
    print(f'serial_seconds {seconds:.2f}')
    print(f'serial_cpu_seconds {timed.cpu:.2f}')
    for line in out.splitlines()[:6]:
        print('#', line)
    if mpi:
        two, _ = timed(['mpirun', '--allow-run-as-root', '--oversubscribe', '-np', '2', mpi, deck, '-o',
                        os.path.join(work, 'mpi2'), '--quiet'])
        print(f'mpi2_seconds {two:.2f}')
        print(f'mpi2_cpu_seconds {timed.cpu:.2f}')
    if opensees:
        period = max(float(t) for t in re.findall(r'T1 = ([0-9.]+) s', out))
        r = subprocess.run([opensees, __file__, '--sample', records, str(dt), str(period)], capture_output=True,
                           text=True)
        print(r.stdout, end='')
        if r.returncode != 0:
            sys.exit(r.stderr)


def sample(records, dt, period):
    sys.path.insert(0, HERE)
    from bench_suite_opensees import run
    import numpy as np
    files = sorted(f for f in os.listdir(records) if f.upper().endswith('.AT2'))
    levels = [0.1 * 9.81, 0.4 * 9.81, 0.8 * 9.81]
    gaps = np.linspace(0.0, 0.040, 21)[::5]
    t_unc = t_cpl = 0.0
    n_unc = n_cpl = 0
    for name in files[::11]:
        rdt, acc = read_at2(os.path.join(records, name))
        t = np.arange(0.0, 30.0 + dt / 2, dt)
        ag = np.interp(t, rdt * np.arange(len(acc)), 9.81 * np.array(acc), right=0.0)
        base = sa(ag, dt, period)
        for level in levels:
            scaled = ag * (level / base)
            start = time.process_time()
            run(scaled, dt, None)
            t_unc += time.process_time() - start
            n_unc += 1
            start = time.process_time()
            for gap in [0.001, *gaps]:
                run(scaled, dt, float(gap))
                n_cpl += 1
            t_cpl += time.process_time() - start
    cases = len(files) * 8
    total = cases * (t_unc / n_unc + 22 * t_cpl / n_cpl)
    print(f'opensees_sample_runs {n_unc + n_cpl}')
    print(f'opensees_per_uncoupled_run {t_unc / n_unc:.4f}')
    print(f'opensees_per_coupled_run {t_cpl / n_cpl:.4f}')
    print(f'opensees_seconds {total:.1f}')


if __name__ == '__main__':
    if sys.argv[1] == '--sample':
        sample(sys.argv[2], float(sys.argv[3]), float(sys.argv[4]))
    else:
        main()
