"""Optional comparison with OpenSeesPy (issue 25): shear buildings with bilinear storeys
(`storey_law = 'bilinear'`) and elastic joints, pound against the same discrete model in
OpenSees, and the speed of both whole processes. Never a project requirement: run it with an
interpreter that has openseespy, numpy and h5py, e.g. a virtual environment outside the repo:

    python3 -m venv /tmp/venv-os && /tmp/venv-os/bin/pip install openseespy numpy h5py
    scripts/opensees_inelastic [REPEATS]          (the wrapper; POUND_OPENSEES_PYTHON, default /tmp/venv-os/bin/python)
    /tmp/venv-os/bin/python scripts/opensees_inelastic.py POUND_EXE DECK [RECORDS_DIR] [REPEATS]

The OpenSees model (issue 25, "Checks you can make"), built from pound's own results file so
the two models are the same: per building a chain of nodes (floor masses /model/<b>/mass), per
storey a zeroLength with Steel01(Fy, k, r) (/model/<b>/yield_shear, storey_stiffness,
hardening_ratio; no isotropic hardening) and a zeroLength with Elastic(-P/h)
(/model/<b>/geometric_stiffness) in parallel; Rayleigh damping C = a0 M + a1 (K0 + G) on the
initial stiffness (/model/<b>/rayleigh): one region per building, its storey elements (and
through them their nodes, which carry the masses) with `-rayleigh a0 0 a1 0`; the storey
zeroLength elements need `-doRayleigh 1` (a zeroLength element ignores Rayleigh's stiffness
part without it: the damping then is a0 M alone); per contact pair a
zeroLength of ElasticPPGap(p, -1e12, -gap) from the left building's floor to the right one's
(pound's elastic joint: force p x penetration in compression, never yielding); Newmark 0.5 0.25,
Newton, NormDispIncr 1e-12; the initial acceleration of every floor -a_g(0) (pound's a(0));
UniformExcitation of a Path series.

Ground motion: the pulse is given to OpenSees as pound's own samples a_g(t_n)
(/ground/acceleration, every step). A record is given as the record itself (values x g,
`-dt` of the record) and OpenSees interpolates it, as a user would; the script also runs the
variant fed with pound's samples at every step (see "Known differences" in
docs/verification.md, "OpenSeesPy comparison of inelastic shear buildings"). The deck under El Centro is the same deck with
`&ground kind = 'record', file = IELC180.AT2` and t_end = 40 s (the whole record); it is skipped when the records are absent.

Compared: peak storey drifts, peak storey shears (the Steel01 force), residual drifts,
ductilities, impacts (count, peak force) and the influence coefficients of drift, storey
shear, ductility and residual drift, uncoupled and coupled. Speed: the whole process of
each (pound: the program from the deck to its listing and HDF5 file; OpenSees: a new
interpreter that imports openseespy, builds both analyses, runs them and writes the histories
of drift, storey shear and joint force to files), interleaved, medians and the median of the
pairwise ratios.
"""
import json
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

G_ACCEL = 9.81


def read_model(h5path):
    """The model data of pound's results file: buildings, pairs, ground, dt, n_steps."""
    with h5py.File(h5path, "r") as f:
        dt = float(f.attrs["dt"])
        names = [n for n in f["model"].keys()]
        order = [n for n in re.findall(r"name\s*=\s*'([^']+)'", f.attrs["deck"])
                 if n in names]
        buildings = []
        for n in order:
            g = f[f"model/{n}"]
            buildings.append(dict(
                name=n, mass=g["mass"][()].tolist(), k=g["storey_stiffness"][()].tolist(),
                pk=g["geometric_stiffness"][()].tolist(), fy=g["yield_shear"][()].tolist(),
                r=g["hardening_ratio"][()].tolist(), a0=float(g["rayleigh"][0]),
                a1=float(g["rayleigh"][1])))
        pairs = []
        if "coupled" in f:
            c = f["coupled/contact"]
            for label, gap, k in zip(f["separation/pair"][()], c["gap"][()], c["stiffness"][()]):
                left, right = label.decode().split("-")
                (bl, fl), (br, fr) = left.split(":"), right.split(":")
                pairs.append(dict(left=bl, fl=int(fl), right=br, fr=int(fr), gap=float(gap),
                                  k=float(k)))
        ag = f["ground/acceleration"][()]
        n_steps = len(f["uncoupled/time"][()]) - 1
        # A collapse stops pound's analysis at the end of its step: OpenSees stops there too.
        stop = {}
        for an in ("uncoupled", "coupled"):
            times = [float(f[f"{an}/{b['name']}"].attrs["collapse_time"]) for b in buildings
                     if an in f and int(f[f"{an}/{b['name']}"].attrs.get("collapse_storey", 0)) > 0]
            stop[an] = int(round(min(times) / dt)) if times else n_steps
    return dict(dt=dt, buildings=buildings, pairs=pairs, ag_steps=ag.tolist(), n_steps=n_steps,
                stop=stop)


def read_pound(h5path, stop):
    """pound's results to compare: {analysis: {building: {quantity: array}}}, joints, influence
    (histories up to the step `stop[analysis]`)."""
    out = {}
    with h5py.File(h5path, "r") as f:
        for an in ("uncoupled", "coupled"):
            if an not in f:
                continue
            out[an] = {}
            for b in f["model"].keys():
                g = f[f"{an}/{b}"]
                out[an][b] = dict(drift=np.abs(g["peak/drift"][()]),
                                  storey_shear=g["peak/storey_shear"][()],
                                  ductility=g["peak/ductility"][()],
                                  residual_drift=g["residual_drift"][()],
                                  history=g["drift"][1:stop[an] + 1])
        if "coupled/contact" in f:
            out["joints"] = dict(impacts=f["coupled/contact/impacts"][()].astype(float),
                                 peak_force=f["coupled/contact/peak_force"][()])
        out["influence"] = {b: {q: f[f"influence/{b}/{q}"][()] for q in
                                ("drift", "storey_shear", "ductility", "residual_drift")}
                            for b in f["influence"].keys()} if "influence" in f else {}
    return out


def opensees_run(model, ground, coupled, outdir, tag):
    """One analysis in OpenSees; the histories of drift, storey shear (Steel01 force) and joint
    force go to recorder files in outdir (OpenSees' own loop over the steps)."""
    import openseespy.opensees as ops
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    dt = model["dt"]
    floor = {}
    steel = {}
    ele = 0
    reg = 0
    for ib, b in enumerate(model["buildings"]):
        base = 10000 * (ib + 1)
        ops.node(base, 0.0)
        ops.fix(base, 1)
        nodes, eles, sels = [], [], []
        for j in range(len(b["k"])):
            nd = base + j + 1
            ops.node(nd, 0.0)
            ops.mass(nd, b["mass"][j])
            ops.uniaxialMaterial("Steel01", nd, b["fy"][j], b["k"][j], b["r"][j])
            ele += 1
            ops.element("zeroLength", ele, nd - 1, nd, "-mat", nd, "-dir", 1, "-doRayleigh", 1)
            sels.append(ele)
            eles.append(ele)
            if b["pk"][j] != 0.0:
                ops.uniaxialMaterial("Elastic", 5000000 + nd, -b["pk"][j])
                ele += 1
                ops.element("zeroLength", ele, nd - 1, nd, "-mat", 5000000 + nd, "-dir", 1,
                            "-doRayleigh", 1)
                eles.append(ele)
            nodes.append(nd)
        # One region per building: its storey elements and, through them, its nodes.
        reg += 1
        ops.region(reg, "-ele", *eles, "-rayleigh", b["a0"], 0.0, b["a1"], 0.0)
        floor[b["name"]] = nodes
        steel[b["name"]] = sels
    jels = []
    if coupled:
        for ip, p in enumerate(model["pairs"]):
            mat = 9000000 + ip
            ops.uniaxialMaterial("ElasticPPGap", mat, p["k"], -1.0e12, -p["gap"])
            ele += 1
            ops.element("zeroLength", ele, floor[p["left"]][p["fl"] - 1],
                        floor[p["right"]][p["fr"] - 1], "-mat", mat, "-dir", 1)
            jels.append(ele)
    values, gdt = ground
    ops.timeSeries("Path", 1, "-dt", gdt, "-values", *values)
    ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
    a0 = values[0]
    for nodes in floor.values():
        for nd in nodes:
            ops.setNodeAccel(nd, 1, -a0, "-commit")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("BandGeneral")
    ops.test("NormDispIncr", 1.0e-12, 50)
    ops.algorithm("Newton")
    ops.integrator("Newmark", 0.5, 0.25)
    ops.analysis("Transient")
    for b in model["buildings"]:
        n = b["name"]
        ops.recorder("Element", "-file", f"{outdir}/{tag}_{n}_drift.out", "-precision", 17, "-ele", *steel[n],
                     "deformation")
        ops.recorder("Element", "-file", f"{outdir}/{tag}_{n}_shear.out", "-precision", 17, "-ele", *steel[n],
                     "basicForce")
    if jels:
        ops.recorder("Element", "-file", f"{outdir}/{tag}_joints.out", "-precision", 17, "-ele", *jels, "basicForce")
    if ops.analyze(model["stop"][tag], dt) != 0:
        raise RuntimeError(f"OpenSees analysis {tag} failed")
    ops.wipe()


def ground_of(model, record):
    """Path series (values, dt): the record itself (values x g) or pound's samples."""
    if record is None:
        # One more value past the end: OpenSees' time after n steps is n dt accumulated and
        # may pass n dt by round-off, where a Path without a next value gives 0.
        return model["ag_steps"] + model["ag_steps"][-1:], model["dt"]
    return record, model["record_dt"]


def opensees_process(model_path, outdir, variant):
    """The whole OpenSees process (a new interpreter runs this): both analyses."""
    model = json.load(open(model_path))
    record = model.get("record") if variant == "record" else None
    ground = ground_of(model, record)
    opensees_run(model, ground, False, outdir, "uncoupled")
    if model["pairs"]:
        opensees_run(model, ground, True, outdir, "coupled")


def read_opensees(model, outdir):
    """Peaks as pound reports them, from the recorder files."""
    out = {}
    for an in ("uncoupled", "coupled"):
        if not os.path.exists(f"{outdir}/{an}_{model['buildings'][0]['name']}_drift.out"):
            continue
        out[an] = {}
        for b in model["buildings"]:
            n = b["name"]
            d = np.atleast_2d(np.loadtxt(f"{outdir}/{an}_{n}_drift.out"))
            q = np.atleast_2d(np.loadtxt(f"{outdir}/{an}_{n}_shear.out"))
            out[an][n] = dict(drift=np.abs(d).max(axis=0), storey_shear=np.abs(q).max(axis=0),
                              ductility=np.abs(d).max(axis=0) / (np.array(b["fy"]) / np.array(b["k"])),
                              residual_drift=d[-1], history=d)
        if an == "coupled":
            # ElasticPPGap's basic force: negative in compression.
            r = -np.atleast_2d(np.loadtxt(f"{outdir}/coupled_joints.out"))
            r = np.vstack([np.zeros((1, r.shape[1])), np.maximum(r, 0.0)])
            onset = (r[1:] > 0.0) & (r[:-1] == 0.0)
            out["joints"] = dict(impacts=onset.sum(axis=0).astype(float), peak_force=r.max(axis=0))
    if "coupled" in out:
        out["influence"] = {}
        for b in model["buildings"]:
            n = b["name"]
            out["influence"][n] = {}
            for q in ("drift", "storey_shear", "ductility", "residual_drift"):
                u, c = np.abs(out["uncoupled"][n][q]), np.abs(out["coupled"][n][q])
                with np.errstate(divide="ignore", invalid="ignore"):
                    out["influence"][n][q] = np.where(u > 0.0, (c - u) / u * 100.0, 0.0)
    return out


def differences(p, o):
    """Rows (quantity, largest |difference|, largest relative difference, where)."""
    rows = []
    for an in ("uncoupled", "coupled"):
        if an not in p:
            continue
        for q in ("drift", "storey_shear", "ductility", "residual_drift", "history"):
            worst = (0.0, 0.0, "")
            scale = 0.0
            for b in p[an]:
                a, c = np.asarray(p[an][b][q]), np.asarray(o[an][b][q])
                scale = max(scale, np.abs(a).max())
                d = np.abs(a - c)
                if d.max() >= worst[0]:
                    idx = np.unravel_index(int(d.argmax()), d.shape)
                    at = f", step {idx[0] + 1}" if d.ndim == 2 else ""
                    worst = (d.max(), 0.0, f"{b} storey {idx[-1] + 1}{at}")
            name = "drift history (every step)" if q == "history" else q
            rows.append((f"{an} {name}", worst[0], worst[0] / scale, worst[2]))
    if "joints" in p:
        for q in ("impacts", "peak_force"):
            d = np.abs(p["joints"][q] - o["joints"][q])
            i = int(d.argmax())
            rows.append((f"joints {q}", d[i], d[i] / max(np.abs(p["joints"][q]).max(), 1e-300),
                         f"pair {i + 1}"))
        for q in ("drift", "storey_shear", "ductility", "residual_drift"):
            worst, scale = (0.0, ""), 0.0
            for b in p["influence"]:
                d = np.abs(p["influence"][b][q] - o["influence"][b][q])
                scale = max(scale, np.abs(p["influence"][b][q]).max())
                i = int(d.argmax())
                if d[i] >= worst[0]:
                    worst = (d[i], f"{b} storey {i + 1}")
            rows.append((f"influence {q} (%)", worst[0], worst[0] / scale, worst[1]))
    return rows


def run_pound(exe, deck, outdir):
    """Run pound on the deck; the path of its results file."""
    subprocess.run([exe, deck, "-o", outdir, "--quiet"], check=True, capture_output=True)
    return os.path.join(outdir, os.path.splitext(os.path.basename(deck))[0] + ".h5")


def el_centro_deck(deck, records, tmp, t_end=40.0):
    """The deck with its &ground replaced by El Centro (IELC180, the whole record: 40 s)."""
    text = open(deck).read()
    rec = os.path.join(records, "IELC180.AT2")
    text = re.sub(r"&ground\b.*?\n/", f"&ground\n   kind = 'record'\n   file = '{rec}'\n/",
                  text, flags=re.S)
    text = re.sub(r"t_end\s*=\s*[0-9.eE+-]+", f"t_end = {t_end}", text)
    path = os.path.join(tmp, os.path.splitext(os.path.basename(deck))[0] + "_elcentro.nml")
    open(path, "w").write(text)
    return path, rec


def read_at2(path):
    """A PEER AT2 record of the old form (line 4 `NPTS=  N, DT= .0x SEC`): values x g, dt."""
    lines = open(path).read().splitlines()
    m = re.search(r"NPTS=\s*(\d+),\s*DT=\s*([0-9.Ee+-]+)", lines[3])
    npts, dt = int(m.group(1)), float(m.group(2))
    vals = [float(x) * G_ACCEL for line in lines[4:] for x in line.split()]
    return vals[:npts], dt


def timed(cmd):
    """Wall time and process time (user + system of the child) of one whole process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def compare_case(exe, deck, label, tmp, repeats, record=None):
    """pound, then OpenSees (each variant of the ground motion) compared, then both timed."""
    pdir = os.path.join(tmp, label + "_pound")
    os.makedirs(pdir, exist_ok=True)
    h5 = run_pound(exe, deck, pdir)
    model = read_model(h5)
    variants = ["steps"]
    if record is not None:
        model["record"], model["record_dt"] = read_at2(record)
        variants = ["record", "steps"]
    mpath = os.path.join(tmp, label + "_model.json")
    json.dump(model, open(mpath, "w"))
    p = read_pound(h5, model["stop"])
    results = {}
    for v in variants:
        odir = os.path.join(tmp, f"{label}_opensees_{v}")
        os.makedirs(odir, exist_ok=True)
        subprocess.run([sys.executable, os.path.abspath(__file__), "--opensees", mpath, odir, v],
                       check=True, capture_output=True)
        results[v] = differences(p, read_opensees(model, odir))
    # Speed: whole processes, interleaved.
    tp, to = [], []
    odir = os.path.join(tmp, f"{label}_opensees_time")
    os.makedirs(odir, exist_ok=True)
    ocmd = [sys.executable, os.path.abspath(__file__), "--opensees", mpath, odir, variants[0]]
    pcmd = [exe, deck, "-o", pdir, "--quiet"]
    for _ in range(repeats):
        tp.append(timed(pcmd))
        to.append(timed(ocmd))
    return model, results, (tp, to)


def report(label, model, results, speed):
    """The Markdown tables of one case."""
    print(f"\n## {label}: {model['n_steps']} steps of {model['dt']} s")
    for an, n in model["stop"].items():
        if n < model["n_steps"]:
            print(f"\n{an}: pound reports a collapse at step {n} (t = {n * model['dt']:.3f} s): "
                  "both stop there; peaks and the residual drift are up to that step")
    for v, rows in results.items():
        what = {"steps": "OpenSees fed pound's a_g(t_n) at every step",
                "record": "OpenSees fed the record (its own interpolation)"}[v]
        print(f"\n{what}\n")
        print("| quantity | largest abs. difference | relative to largest value | where |")
        print("|---|--:|--:|---|")
        for q, d, rel, where in rows:
            print(f"| {q} | {d:.2e} | {rel:.1e} | {where} |")
    tp, to = speed
    print(f"\nwhole process, {len(tp)} interleaved runs of each (medians, min ... max):\n")
    print("| time | pound (s) | OpenSees (s) | OpenSees / pound: median of pairwise ratios (min ... max) | ratio of medians |")
    print("|---|--:|--:|--:|--:|")
    for i, what in ((0, "wall"), (1, "process (user + sys)")):
        a, b = [x[i] for x in tp], [x[i] for x in to]
        r = [y / max(x, 1e-6) for x, y in zip(a, b)]
        print(f"| {what} | {statistics.median(a):.4f} ({min(a):.4f} ... {max(a):.4f}) | "
              f"{statistics.median(b):.3f} ({min(b):.3f} ... {max(b):.3f}) | "
              f"**{statistics.median(r):.1f}** ({min(r):.1f} ... {max(r):.1f}) | "
              f"{statistics.median(b) / max(statistics.median(a), 1e-6):.1f} |")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--opensees":
        opensees_process(sys.argv[2], sys.argv[3], sys.argv[4])
        return
    here = os.path.dirname(os.path.abspath(__file__))
    exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "build", "release", "pound")
    deck = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "input", "seed_bilinear.nml")
    records = sys.argv[3] if len(sys.argv) > 3 else os.path.join(here, "..", "..", "shared", "records")
    repeats = int(sys.argv[4]) if len(sys.argv) > 4 else 7
    tmp = tempfile.mkdtemp(prefix="pound_os25_")
    try:
        model, res, speed = compare_case(exe, deck, "pulse", tmp, repeats)
        report(f"{os.path.basename(deck)} (its pulse)", model, res, speed)
        if os.path.exists(os.path.join(records, "IELC180.AT2")):
            edeck, rec = el_centro_deck(deck, records, tmp)
            model, res, speed = compare_case(exe, edeck, "elcentro", tmp, repeats, rec)
            report(f"{os.path.basename(deck)} under El Centro (IELC180, 40 s)", model, res, speed)
        else:
            print(f"\nEl Centro skipped: no {records}/IELC180.AT2")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
