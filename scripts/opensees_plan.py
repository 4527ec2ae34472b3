"""Buildings in plan against OpenSeesPy: the same pair of plan buildings, given by a pound deck,
as an OpenSees model (optional: needs `openseespy`, not a dependency of pound; run with a Python
that has it, numpy and h5py, e.g. python3 -m venv /tmp/venv-os; /tmp/venv-os/bin/pip install
openseespy numpy h5py).

    opensees_plan.py DECK                  the OpenSees run: periods, peaks, lambdas
    opensees_plan.py --compare POUND_EXE DECK [REPEATS]
                                           pound on the deck against this model: agreement of the
                                           periods, peaks and lambdas; both whole processes timed,
                                           interleaved (REPEATS, default 5), medians and ratio
    opensees_plan.py --verify              checks of the OpenSees side alone (no pound): a
                                           one-storey eccentric building against the closed form
                                           of the 2x2 x-theta problem, and a symmetric plan pair
                                           along x against the planar model of
                                           scripts/bench_suite_opensees.py
    opensees_plan.py --one DECK            one run, nothing printed (the timed process)
    opensees_plan.py --write-decks DIR RECORD
                                           writes the comparison decks (the seed pair in plan
                                           along x; the eccentric pair of scripts/bench_plan.py
                                           without and with friction at 30 degrees; 10 s of
                                           RECORD, an AT2 file) into DIR

The deck is read by a small namelist reader of this script (groups &analysis, &ground,
&building, &plane, &contact; repeat counts `3*3.0`, `name(i) = v`, quoted strings, `!`
comments). The model (the deck syntax and the mechanics of pound's buildings in plan):

- per floor a master node at the centre of mass (ndm 3, ndf 6; z, rx, ry fixed) with mass
  m, m, I (about z), and the floor's plane points and contact points tied to it by
  `rigidDiaphragm` (exact: u_x(P) = u_x - theta (py - ym), u_y(P) = u_y + theta (px - xm));
  every floor of a building at z = 0 (distinct nodes), so the storey elements have zero length;
- a plane's storey j: a `zeroLength` spring (`Elastic`, the storey stiffness) along the plane's
  direction between the plane's points of floor j-1 (the ground: fixed nodes) and floor j;
- p_delta: per storey a `zeroLength` between the masters of floors j-1 and j along x, y and
  rotation with -W_j/h_j, -W_j/h_j, -R_j/h_j (the chord geometric stiffness of pound);
- Rayleigh damping C = a0 M + a1 (K + G) per building, a0 and a1 fitted at the deck's
  damping_modes of the building's 3D modes (x, y and torsion counted alike, ascending), from
  an eigen analysis of the same K + G and M here (numpy); mass part on the masters
  (`region -node`), stiffness part on the storey and P-Delta springs (`region -eleOnly`);
- contact: a pair joins A's right facade and B's left facade over their y-overlap; two points
  (y_lo, y_hi) with half of the pair's stiffness and shear stiffness each, or one point with all.
  Normal law: pound's elastic law, N = k max(0, u_x,A(P) - u_x,B(P) - gap).
  * friction = 0 (`--joint auto` picks `gap`): a `zeroLength` of `ElasticPPGap` along x
    (E = k, compression, gap) between the two diaphragm points: exactly pound's law, with
    the exact `Transformation` constraint handler.
  * friction > 0 (`--joint auto` picks `impact3d`): `zeroLengthImpact3D` (direction 1,
    initGap = gap, frictionRatio = mu, Kt = kt, Kn = Kn2 = k (so its bilinear normal law is
    linear), Delta_y 1, cohesion 0) between 3-DOF nodes, A's point the primary (its plane's
    normal points to +x), B's the secondary: its gap is u_x,A - u_x,B - gap. The 3-DOF nodes
    are tied to the 6-DOF diaphragm points by `equalDOF` 1 2; OpenSees' Transformation handler
    does not carry that chain (the 3-DOF node stays at 0) and its Lagrange handler refuses
    nodes of different DOF counts, so this variant uses the `Penalty` handler (1e12 on every
    constraint: ties to about 1e-7 of the structure's flexibility). Its friction is Coulomb
    with a tangential penalty, but NOT pound's elastic-plastic law: after a slipping step the
    element sets its stick point to the current tangential displacement, so the elastic part
    mu N / kt of the tangential displacement is dropped (pound keeps T = kt (s - s_p) at mu N);
    with a stiff kt the difference is of order mu N / kt per slip reversal. The normal force
    is pound's. The element's normal-law state is initialised by `reset` (its constructor
    leaves it unset).
- ground: a_gx = a_g cos(angle) - a_2 sin(angle), a_gy = a_g sin(angle) + a_2 cos(angle), each
  component linearly interpolated at the analysis steps on its own time step and zero after
  its end (pound's rule), given to OpenSees as `Path` series at dt with `UniformExcitation`
  in x and y; the relative accelerations start in equilibrium with the ground, a = -r a_g(0)
  (`setNodeAccel`), as pound starts.
- Newmark average acceleration, Newton (NormDispIncr 1e-10, 50 iterations; a step that fails
  is retaken with Krylov-Newton), the deck's dt and t_end; `RCM` numberer, `UmfPack` (sparse; with Penalty ties a band
  solver of the plain numbering costs 15x more).
- outputs (envelope recorders: OpenSees' own loop over the steps): per building and floor
  the peak |u_x|, |u_y|, |theta| at the centre of mass, per plane and storey the peak storey
  shear, per contact point the peak normal force (and the peak friction force with
  impact3d), uncoupled and coupled; lambda = (Qc - Qu)/Qu 100 of the plane shears (NaN
  where Qu is round-off: below 1e-9 of the building's largest plane shear; --compare leaves
  those entries out on both sides).
"""
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

G = 9.81
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# pound's HDF5 datasets read by --compare (h5py paths; {a} = uncoupled/coupled, {b} = building).
# Pinned by the deck contract of buildings in plan: periods, plane_shear, rotation, the
# per-point contact peaks. The others (marked) are this script's guesses of names the program's
# plan support has not fixed yet: a missing dataset is reported as absent, never an error;
# correct them here once the program's names are known.
H5 = {
    "periods": "/model/{b}/periods",                  # pinned: 3D periods, longest first
    "plane_shear": "/{a}/{b}/peak/plane_shear",       # pinned: (n_planes, n_storeys)
    "rotation": "/{a}/{b}/peak/rotation",             # pinned: (n_storeys)
    "lambda_plane_shear": "/influence/{b}/plane_shear",  # pinned: (n_planes, n_storeys)
    "peak_force": "/coupled/contact/peak_force",      # pinned: per contact point
    "peak_friction": "/coupled/contact/peak_friction",  # pinned: per contact point
    "u_x": "/{a}/{b}/peak/u_x",                       # guess: peak |u_x| at the centre of mass
    "u_y": "/{a}/{b}/peak/u_y",                       # guess: peak |u_y| at the centre of mass
    "loop_seconds": "/{a}",                           # attribute integration_seconds
}


# A plane shear below SMALL times the building's largest is round-off (the y planes of a
# symmetric pair shaken along x): its lambda is taken as NaN here and left out of --compare.
SMALL = 1.0e-9

# ------------------------------------------------------------------------------------------
# The deck: a small namelist reader
# ------------------------------------------------------------------------------------------
TOKEN = re.compile(r"'(?:[^']|'')*'|\"(?:[^\"]|\"\")*\"|=|,|[^\s,=]+")


def _strip_comment(line):
    out, quote = [], None
    for ch in line:
        if quote:
            out.append(ch)
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
            out.append(ch)
        elif ch == "!":
            break
        else:
            out.append(ch)
    return "".join(out)


def _value(tok):
    if tok[0] in "'\"":
        return tok[1:-1].replace(tok[0] * 2, tok[0])
    low = tok.lower()
    if low in (".true.", "t", ".t.", "true"):
        return True
    if low in (".false.", "f", ".f.", "false"):
        return False
    try:
        return int(tok)
    except ValueError:
        return float(low.replace("d", "e"))


def _values(tokens):
    out = []
    for tok in tokens:
        m = re.fullmatch(r"(\d+)\*(.+)", tok) if tok[0] not in "'\"" else None
        if m:
            out.extend([_value(m.group(2))] * int(m.group(1)))
        else:
            out.append(_value(tok))
    return out


def read_namelists(text):
    """[(group name, {variable: [values]})] in deck order; names in lower case."""
    text = "\n".join(_strip_comment(line) for line in text.replace("\r\n", "\n").replace("\r", "\n").split("\n"))
    groups, i = [], 0
    while True:
        m = re.compile(r"&(\w+)").search(text, i)
        if not m:
            return groups
        j, quote = m.end(), None
        while j < len(text):  # the group ends at the first '/' outside quotes
            ch = text[j]
            if quote:
                quote = None if ch == quote else quote
            elif ch in "'\"":
                quote = ch
            elif ch == "/":
                break
            j += 1
        tokens = [t for t in TOKEN.findall(text[m.end():j]) if t != ","]
        body, key, vals = {}, None, []
        for k, tok in enumerate(tokens):
            if tok == "=":
                continue
            if k + 1 < len(tokens) and tokens[k + 1] == "=":
                if key:
                    _assign(body, key, vals)
                key, vals = tok.lower(), []
            else:
                vals.append(tok)
        if key:
            _assign(body, key, vals)
        groups.append((m.group(1).lower(), body))
        i = j + 1


def _assign(body, key, toks):
    vals = _values(toks)
    m = re.fullmatch(r"(\w+)\((\d+)\)", key)
    if m:  # name(i) = v, ...: elements from i on
        name, start = m.group(1), int(m.group(2)) - 1
        cur = body.setdefault(name, [])
        cur.extend([None] * (start + len(vals) - len(cur)))
        cur[start:start + len(vals)] = vals
    else:
        body[key] = vals


def per_storey(body, name, n, default=None):
    vals = body.get(name)
    if vals is None:
        return None if default is None else np.full(n, float(default))
    if len(vals) == 1 and n > 1:
        vals = vals * n
    if len(vals) != n:
        sys.exit(f"opensees_plan: {name} has {len(vals)} values, the building has {n}")
    return np.array(vals, dtype=float)


def scalar(body, name, default=None):
    vals = body.get(name)
    return default if vals is None else vals[0]


class Building:
    """A plan building of the deck: floors' masses and inertias, planes, gravity loads."""

    def __init__(self, body, planes):
        self.name = scalar(body, "name")
        if str(scalar(body, "model", "shear")).lower() != "plan":
            sys.exit(f"opensees_plan: building {self.name} is not model = 'plan'")
        n = self.n = int(scalar(body, "n_storeys"))
        self.height = per_storey(body, "height", n)
        if "mass" in body:
            self.mass = per_storey(body, "mass", n)
            loads = self.mass * G
        else:
            loads = per_storey(body, "load_coeff", n) * float(scalar(body, "ref_floor_load"))
            self.mass = loads / G
        self.gravity = per_storey(body, "gravity_load", n) if "gravity_load" in body else loads
        self.lx, self.ly = (float(v) for v in body["plan_size"])
        self.y0 = float(scalar(body, "plan_origin_y", 0.0))
        mc = body.get("mass_centre", [self.lx / 2, self.ly / 2])
        self.xm, self.ym = float(mc[0]), float(mc[1])
        self.inertia = (per_storey(body, "rot_inertia", n) if "rot_inertia" in body
                        else self.mass * (self.lx ** 2 + self.ly ** 2) / 12.0)
        self.zeta = float(scalar(body, "damping_ratio", 0.05))
        self.modes = [int(v) for v in body.get("damping_modes", [1, 2])]
        self.pdelta = bool(scalar(body, "p_delta", False))
        self.planes = []
        for p in planes:
            if str(scalar(p, "storey_law", "elastic")).lower() != "elastic":
                sys.exit(f"opensees_plan: building {self.name}: only elastic planes are modelled")
            self.planes.append(dict(direction=str(scalar(p, "direction")).lower(),
                                    position=float(scalar(p, "position")),
                                    k=per_storey(p, "stiffness", n)))
        if not any(p["direction"] == "x" for p in self.planes) or not any(p["direction"] == "y" for p in self.planes):
            sys.exit(f"opensees_plan: building {self.name} needs a plane in each direction")

    def point_row(self, j, px, py, direction):
        """The row of u_x(P) ('x') or u_y(P) ('y') of floor j (1-based; 0: the ground) in the
        building's DOFs (floor j: 3j-3 u_x, 3j-2 u_y, 3j-1 theta)."""
        row = np.zeros(3 * self.n)
        if j > 0:
            if direction == "x":
                row[3 * j - 3], row[3 * j - 1] = 1.0, -(py - self.ym)
            else:
                row[3 * j - 2], row[3 * j - 1] = 1.0, px - self.xm
        return row

    def plane_point(self, plane):
        c = plane["position"]
        return (self.xm, c) if plane["direction"] == "x" else (c, self.ym)

    def matrices(self):
        """K + G and M of the building (3n x 3n), pound's DOF order."""
        n = self.n
        k = np.zeros((3 * n, 3 * n))
        for p in self.planes:
            px, py = self.plane_point(p)
            for j in range(1, n + 1):
                a = self.point_row(j, px, py, p["direction"]) - self.point_row(j - 1, px, py, p["direction"])
                k += p["k"][j - 1] * np.outer(a, a)
        if self.pdelta:
            w = self.gravity
            r = self.gravity * self.inertia / self.mass
            for j in range(1, n + 1):
                wj, rj = w[j - 1:].sum(), r[j - 1:].sum()
                for c, s in ((0, wj), (1, wj), (2, rj)):
                    a = np.zeros(3 * n)
                    a[3 * j - 3 + c] = 1.0
                    if j > 1:
                        a[3 * j - 6 + c] = -1.0
                    k -= s / self.height[j - 1] * np.outer(a, a)
        m = np.zeros(3 * n)
        m[0::3], m[1::3], m[2::3] = self.mass, self.mass, self.inertia
        return k, m

    def omegas(self):
        k, m = self.matrices()
        s = 1.0 / np.sqrt(m)
        lam = np.linalg.eigvalsh(k * s[:, None] * s[None, :])
        if lam[0] <= 0.0:
            sys.exit(f"opensees_plan: building {self.name}: K + G is not positive definite")
        return np.sqrt(lam)

    def rayleigh(self):
        w = self.omegas()
        if len(self.modes) == 1:
            wi = w[self.modes[0] - 1]
            return self.zeta * wi, self.zeta / wi
        wi, wj = w[self.modes[0] - 1], w[self.modes[1] - 1]
        return self.zeta * 2.0 * wi * wj / (wi + wj), self.zeta * 2.0 / (wi + wj)


def read_at2(path):
    lines = open(path).read().splitlines()
    head = lines[3]
    m = re.search(r"NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([0-9.Ee+-]+)", head, re.I)
    if m:
        npts, dt = int(m.group(1)), float(m.group(2))
    else:
        parts = head.replace(",", " ").split()
        npts, dt = int(parts[0]), float(parts[1])
    values = [float(x) for line in lines[4:] for x in line.split()]
    return dt, np.array(values[:npts])


class Deck:
    def __init__(self, path):
        self.path = os.path.abspath(path)
        groups = read_namelists(open(path).read())
        ana = [b for g, b in groups if g == "analysis"][0]
        self.dt = float(scalar(ana, "dt"))
        self.t_end = float(scalar(ana, "t_end"))
        self.steps = int(round(self.t_end / self.dt))
        grounds = [b for g, b in groups if g == "ground"]
        if len(grounds) != 1:
            sys.exit("opensees_plan: one &ground only (no suites)")
        self.ground = grounds[0]
        planes = [b for g, b in groups if g == "plane"]
        self.buildings = []
        for g, b in groups:
            if g == "building":
                name = scalar(b, "name")
                self.buildings.append(Building(b, [p for p in planes if scalar(p, "building") == name]))
        self.x_offset = {}
        off = 0.0
        for b in self.buildings:  # buildings side by side in the row: facing facades coincide
            self.x_offset[b.name] = off
            off += b.lx
        self.pairs = [b for g, b in groups if g == "contact"]
        for c in self.pairs:
            law = str(scalar(c, "law", "elastic")).lower()
            if law != "elastic" or float(scalar(c, "dashpot", 0.0)) != 0.0 or "restitution" in c:
                sys.exit("opensees_plan: only law = 'elastic' without dashpot is modelled")

    def building(self, name):
        return next(b for b in self.buildings if b.name == name)

    def contact_points(self):
        """[(A, floor A, B, floor B, y_site, gap, k_point, kt_point, mu)] pair by pair, y_lo
        then y_hi (one point when they coincide)."""
        pts = []
        for c in self.pairs:
            a, b = self.building(scalar(c, "left")), self.building(scalar(c, "right"))
            fl, fr = c["floors_left"], c["floors_right"]
            gaps = c["gap"] * len(fl) if len(c["gap"]) == 1 else c["gap"]
            k = float(scalar(c, "stiffness"))
            kt = float(scalar(c, "shear_stiffness", 0.0)) or k
            mu = float(scalar(c, "friction", 0.0))
            lo, hi = max(a.y0, b.y0), min(a.y0 + a.ly, b.y0 + b.ly)
            if lo > hi:
                sys.exit(f"opensees_plan: {a.name} and {b.name} do not overlap in y")
            ys = [lo] if lo == hi else [lo, hi]
            for i in range(len(fl)):
                for y in ys:
                    pts.append((a, int(fl[i]), b, int(fr[i]), y, float(gaps[i]), k / len(ys), kt / len(ys), mu))
        return pts

    def ground_xy(self):
        """a_gx, a_gy (m/s^2) at t = 0, dt, ..., t_end."""
        t = self.dt * np.arange(self.steps + 1)
        g = self.ground
        kind = str(scalar(g, "kind")).lower()
        if "scale_to" in g:
            sys.exit("opensees_plan: scale_to is not modelled (give scale)")
        if kind == "pulse":
            x0, a, b = (float(scalar(g, v)) for v in ("x0", "a", "b"))
            e = np.exp(-a * t)
            ag = x0 * e * ((a * a - b * b) * np.sin(b * t) - 2.0 * a * b * np.cos(b * t))
            a2 = np.zeros_like(t)
        elif kind == "record":
            ag = self._component(t, scalar(g, "file"), float(scalar(g, "scale", 1.0)))
            a2 = (self._component(t, scalar(g, "file_2"), float(scalar(g, "scale_2", scalar(g, "scale", 1.0))))
                  if "file_2" in g else np.zeros_like(t))
        else:
            sys.exit(f"opensees_plan: ground kind = '{kind}' is not modelled (pulse, record)")
        alpha = math.radians(float(scalar(g, "angle", 0.0)))
        return ag * math.cos(alpha) - a2 * math.sin(alpha), ag * math.sin(alpha) + a2 * math.cos(alpha)

    def _component(self, t, name, scale):
        path = name if os.path.isabs(name) else os.path.join(os.path.dirname(self.path), name)
        rdt, values = read_at2(path)
        tr = rdt * np.arange(len(values))
        return np.interp(t, tr, values * G * scale, right=0.0)

    def has_friction(self):
        return any(p[8] > 0.0 for p in self.contact_points())


# ------------------------------------------------------------------------------------------
# The OpenSees model
# ------------------------------------------------------------------------------------------
class Model:
    """Builds the deck's plan pair in OpenSees and runs one analysis."""

    def __init__(self, deck, coupled, joint="auto", files=None):
        self.deck, self.coupled = deck, coupled
        self.joint = ("impact3d" if deck.has_friction() else "gap") if joint == "auto" else joint
        self.files = files or tempfile.mkdtemp(prefix="opensees_plan_")

    def build(self):
        import openseespy.opensees as ops
        self.ops = ops
        ops.wipe()
        ops.model("basic", "-ndm", 3, "-ndf", 6)
        self.tag = 0
        self.masters, self.springs, self.points = {}, {}, []
        self.point_nodes, self.point_mu = [], []  # impact3d: (A's, B's) 3-DOF node of each point
        for ib, b in enumerate(self.deck.buildings):
            self._building(ib, b)
        if self.coupled:
            self._contacts()

    def _new(self):
        self.tag += 1
        return self.tag

    def _site(self, b, px, py):
        return self.deck.x_offset[b.name] + px, b.y0 + py

    def _building(self, ib, b):
        ops = self.ops
        masters = [None]
        for j in range(1, b.n + 1):
            node = self._new()
            ops.node(node, *self._site(b, b.xm, b.ym), 0.0)
            ops.fix(node, 0, 0, 1, 1, 1, 0)
            ops.mass(node, b.mass[j - 1], b.mass[j - 1], 0.0, 0.0, 0.0, b.inertia[j - 1])
            masters.append(node)
        self.masters[b.name] = masters
        eles = []
        self.springs[b.name] = []
        for p in b.planes:
            px, py = b.plane_point(p)
            below = self._new()
            ops.node(below, *self._site(b, px, py), 0.0)
            ops.fix(below, 1, 1, 1, 1, 1, 1)
            row = []
            for j in range(1, b.n + 1):
                above = self._point(b, j, px, py)
                mat = self._new()
                ops.uniaxialMaterial("Elastic", mat, float(p["k"][j - 1]))
                ele = self._new()
                ops.element("zeroLength", ele, below, above, "-mat", mat, "-dir", 1 if p["direction"] == "x" else 2,
                            "-doRayleigh", 1)
                eles.append(ele)
                row.append(ele)
                below = above
            self.springs[b.name].append(row)
        if b.pdelta:
            w = b.gravity
            r = b.gravity * b.inertia / b.mass
            ground = self._new()
            ops.node(ground, *self._site(b, b.xm, b.ym), 0.0)
            ops.fix(ground, 1, 1, 1, 1, 1, 1)
            for j in range(1, b.n + 1):
                h = b.height[j - 1]
                mats = []
                for s in (w[j - 1:].sum(), w[j - 1:].sum(), r[j - 1:].sum()):
                    mat = self._new()
                    ops.uniaxialMaterial("Elastic", mat, -float(s) / h)
                    mats.append(mat)
                ele = self._new()
                ops.element("zeroLength", ele, ground if j == 1 else masters[j - 1], masters[j], "-mat", *mats,
                            "-dir", 1, 2, 6, "-doRayleigh", 1)
                eles.append(ele)
        a0, a1 = b.rayleigh()
        ops.region(self._new(), "-node", *masters[1:], "-rayleigh", a0, 0.0, 0.0, 0.0)
        ops.region(self._new(), "-eleOnly", *eles, "-rayleigh", 0.0, a1, 0.0, 0.0)

    def _point(self, b, j, px, py):
        """A new node of floor j of b at outline point (px, py), tied to the floor's master."""
        ops = self.ops
        node = self._new()
        ops.node(node, *self._site(b, px, py), 0.0)
        ops.fix(node, 0, 0, 1, 1, 1, 0)
        ops.rigidDiaphragm(3, self.masters[b.name][j], node)
        return node

    def _contacts(self):
        ops = self.ops
        for (a, fa, b, fb, y, gap, k, kt, mu) in self.deck.contact_points():
            na = self._point(a, fa, a.lx, y - a.y0)
            nb = self._point(b, fb, 0.0, y - b.y0)
            ele = self._new()
            if self.joint == "gap":
                mat = self._new()
                ops.uniaxialMaterial("ElasticPPGap", mat, k, -1.0e15, -gap)
                ops.element("zeroLength", ele, na, nb, "-mat", mat, "-dir", 1)
            else:
                ops.model("basic", "-ndm", 3, "-ndf", 3)
                ca, cb = self._new(), self._new()
                xa, ya = self._site(a, a.lx, y - a.y0)
                ops.node(ca, xa, ya, 0.0)
                ops.node(cb, xa, ya, 0.0)  # coincident: the facing facades meet at A's right facade
                ops.fix(ca, 0, 0, 1)
                ops.fix(cb, 0, 0, 1)
                ops.equalDOF(na, ca, 1, 2)
                ops.equalDOF(nb, cb, 1, 2)
                # secondary (B) first, primary (A) second: gap = X_A - X_B - initGap
                ops.element("zeroLengthImpact3D", ele, cb, ca, 1, gap, mu, kt, k, k, 1.0, 0.0)
                ops.model("basic", "-ndm", 3, "-ndf", 6)
                self.point_nodes += [ca, cb]
                self.point_mu.append(mu)
            self.points.append(ele)

    def eigen_omegas(self, n):
        """The model's n lowest circular frequencies (OpenSees eigen, full LAPACK)."""
        lam = self.ops.eigen("-fullGenLapack", n)
        return np.sqrt(np.array(lam))

    def run(self):
        """Analyse; returns the peaks (dict)."""
        ops, deck = self.ops, self.deck
        agx, agy = deck.ground_xy()
        ops.timeSeries("Path", 1, "-dt", deck.dt, "-values", *agx.tolist())
        ops.timeSeries("Path", 2, "-dt", deck.dt, "-values", *agy.tolist())
        ops.pattern("UniformExcitation", 1, 1, "-accel", 1)
        ops.pattern("UniformExcitation", 2, 2, "-accel", 2)
        if self.joint == "impact3d" and self.coupled:
            ops.constraints("Penalty", 1.0e12, 1.0e12)
        else:
            ops.constraints("Transformation")
        ops.numberer("RCM")
        ops.system("UmfPack")  # sparse: the Penalty variant keeps every tied DOF as an equation
        ops.test("NormDispIncr", 1.0e-10, 50)
        ops.algorithm("Newton")
        ops.integrator("Newmark", 0.5, 0.25)
        ops.analysis("Transient")
        if self.joint == "impact3d" and self.coupled:
            ops.reset()  # the impact elements' committed normal state starts at zero
        for b in deck.buildings:  # start at rest, in equilibrium with the ground: a = -r a_g(0)
            for node in self.masters[b.name][1:]:
                ops.setNodeAccel(node, 1, -float(agx[0]), "-commit")
                ops.setNodeAccel(node, 2, -float(agy[0]), "-commit")
        f = self.files
        nodes = [n for b in deck.buildings for n in self.masters[b.name][1:]]
        ops.recorder("EnvelopeNode", "-file", f"{f}/masters.out", "-precision", 17, "-node", *nodes, "-dof", 1, 2, 6, "disp")
        springs = [e for b in deck.buildings for row in self.springs[b.name] for e in row]
        ops.recorder("EnvelopeElement", "-file", f"{f}/springs.out", "-precision", 17, "-ele", *springs, "basicForce")
        if self.points and self.joint == "gap":
            ops.recorder("EnvelopeElement", "-file", f"{f}/points.out", "-precision", 17, "-ele", *self.points,
                         "basicForce")
        elif self.points:
            # Recorders run after the step's commit, and zeroLengthImpact3D then evaluates its
            # force again: the normal force is the step's, but after a slipping step its stick
            # point has moved onto the tangential displacement, so it reports T = 0. Every
            # step's force and the points' y displacements are kept: a step with N > 0, T = 0
            # and a tangential displacement that moved slipped, with |T| = mu N.
            ops.recorder("Element", "-file", f"{f}/points.out", "-precision", 17, "-ele", *self.points, "force")
            ops.recorder("Node", "-file", f"{f}/points_y.out", "-precision", 17, "-node", *self.point_nodes,
                         "-dof", 2, "disp")
        done = 0
        while done < deck.steps:
            t0 = ops.getTime()
            if ops.analyze(deck.steps - done, deck.dt) == 0:
                break
            done = int(round(ops.getTime() / deck.dt))
            ops.algorithm("KrylovNewton")
            ops.test("NormDispIncr", 1.0e-10, 200)
            if ops.analyze(1, deck.dt) != 0:
                raise RuntimeError(f"OpenSees: no convergence at t = {ops.getTime():.4f} s (from {t0:.4f} s)")
            done += 1
            ops.algorithm("Newton")
            ops.test("NormDispIncr", 1.0e-10, 50)
        ops.wipe()  # writes the envelopes
        return self._peaks()

    def _peaks(self):
        f, deck = self.files, self.deck
        env = np.max(np.abs(np.atleast_2d(np.loadtxt(f"{f}/masters.out"))), axis=0)
        out, i = {}, 0
        for b in deck.buildings:
            blk = env[i:i + 3 * b.n].reshape(b.n, 3)
            i += 3 * b.n
            out[b.name] = dict(u_x=blk[:, 0], u_y=blk[:, 1], rotation=blk[:, 2])
        shear = np.max(np.abs(np.atleast_2d(np.loadtxt(f"{f}/springs.out"))), axis=0)
        i = 0
        for b in deck.buildings:
            np_ = len(b.planes)
            out[b.name]["plane_shear"] = shear[i:i + np_ * b.n].reshape(np_, b.n)
            i += np_ * b.n
        if self.points and self.joint == "gap":
            pts = np.max(np.abs(np.atleast_2d(np.loadtxt(f"{f}/points.out"))), axis=0)
            out["peak_force"], out["peak_friction"] = pts, np.zeros_like(pts)
        elif self.points:  # force: (x, y, z) at the secondary (B), then at the primary (A)
            hist = np.abs(np.atleast_2d(np.loadtxt(f"{f}/points.out")))
            n, t = hist[:, 0::6], hist[:, 1::6]
            y = np.atleast_2d(np.loadtxt(f"{f}/points_y.out"))
            s = y[:, 0::2] - y[:, 1::2]
            ds = np.abs(np.diff(s, axis=0, prepend=0.0))
            slipped = (n > 0.0) & (t == 0.0) & (ds > 1.0e-14)
            t = np.where(slipped, np.array(self.point_mu)[None, :] * n, t)
            out["peak_force"], out["peak_friction"] = n.max(axis=0), t.max(axis=0)
            out["slipping_steps"] = slipped.sum(axis=0)
        return out


def analyse(deck, joint="auto"):
    """Uncoupled and coupled runs, the periods and the lambdas of the plane shears."""
    res = {}
    for name, coupled in (("uncoupled", False), ("coupled", True)):
        m = Model(deck, coupled, joint)
        m.build()
        res[name] = m.run()
    res["periods"] = {b.name: 2.0 * math.pi / b.omegas() for b in deck.buildings}  # longest first
    res["lambda"] = {}
    for b in deck.buildings:
        qu, qc = res["uncoupled"][b.name]["plane_shear"], res["coupled"][b.name]["plane_shear"]
        with np.errstate(divide="ignore", invalid="ignore"):
            res["lambda"][b.name] = np.where(qu > SMALL * qu.max(), (qc - qu) / qu * 100.0, np.nan)
    return res


def report(deck, res):
    for b in deck.buildings:
        print(f"building {b.name}: periods [s] " + " ".join(f"{t:.5f}" for t in res["periods"][b.name][:6]))
        for a in ("uncoupled", "coupled"):
            r = res[a][b.name]
            print(f"  {a}: floor |u_x| [mm] |u_y| [mm] |theta| [mrad]")
            for j in range(b.n - 1, -1, -1):
                print(f"    {j + 1:3d} {1e3 * r['u_x'][j]:10.4f} {1e3 * r['u_y'][j]:10.4f} {1e3 * r['rotation'][j]:10.5f}")
        print("  plane  storey  Qu [kN]  Qc [kN]  lambda [%]")
        for ip in range(len(b.planes)):
            for j in range(b.n - 1, -1, -1):
                print(f"    {ip + 1:3d} {j + 1:3d} {res['uncoupled'][b.name]['plane_shear'][ip, j]:12.3f} "
                      f"{res['coupled'][b.name]['plane_shear'][ip, j]:12.3f} {res['lambda'][b.name][ip, j]:9.3f}")
    if "peak_force" in res["coupled"]:
        print("contact points: peak N [kN], peak |T| [kN]")
        for i, (n, t) in enumerate(zip(res["coupled"]["peak_force"], res["coupled"]["peak_friction"])):
            print(f"  {i + 1:3d} {n:12.3f} {t:12.3f}")


# ------------------------------------------------------------------------------------------
# --compare: pound on the same deck
# ------------------------------------------------------------------------------------------
def h5_get(f, key, **kw):
    path = H5[key].format(**kw)
    return np.asarray(f[path][()]) if path in f else None


def pound_results(exe, deck_path, out):
    import h5py
    subprocess.run([exe, deck_path, "-o", out], check=True, capture_output=True)
    stem = os.path.splitext(os.path.basename(deck_path))[0]
    return h5py.File(os.path.join(out, stem + ".h5"), "r")


def compare(exe, deck_path, repeats):
    deck = Deck(deck_path)
    res = analyse(deck)
    print(f"OpenSees joints: {Model(deck, True).joint}")
    worst = {}

    def diff(label, p, o, scale=None):
        if p is None:
            print(f"  {label}: absent in pound's file")
            return
        p, o = np.asarray(p, dtype=float), np.asarray(o, dtype=float)
        if p.shape != o.shape:
            print(f"  {label}: shapes differ, pound {p.shape}, OpenSees {o.shape}")
            return
        d = np.abs(p - o)
        # relative: the largest difference over the largest |value| of the quantity (a peak near
        # zero, e.g. u_y of a symmetric pair along x, does not inflate it); lambdas in pp
        big = np.nanmax(np.abs(p)) if np.any(np.isfinite(p)) else 0.0
        rel = (np.nanmax(d) / big if big > 0 else np.nanmax(d)) if scale is None else np.nanmax(d)
        worst[label.split(" ")[0]] = max(worst.get(label.split(" ")[0], 0.0), float(rel))
        unit = "of the largest" if scale is None else scale
        print(f"  {label}: max difference {rel:.3e} ({unit})")

    with tempfile.TemporaryDirectory() as tmp:
        with pound_results(exe, deck.path, tmp) as f:
            for b in deck.buildings:
                print(f"building {b.name}")
                tp = h5_get(f, "periods", b=b.name)
                to = res["periods"][b.name]
                if tp is not None:
                    to = to[:len(tp)]
                diff("periods", tp, to)
                for a in ("uncoupled", "coupled"):
                    for q in ("plane_shear", "rotation", "u_x", "u_y"):
                        diff(f"{q} {a}", h5_get(f, q, a=a, b=b.name), res[a][b.name][q])
                lam = h5_get(f, "lambda_plane_shear", b=b.name)
                qu = h5_get(f, "plane_shear", a="uncoupled", b=b.name)
                if lam is not None and qu is not None and qu.shape == lam.shape:
                    lam = np.where(np.abs(qu) > SMALL * np.max(np.abs(qu)), lam, np.nan)
                diff("lambda plane_shear", lam, res["lambda"][b.name], "pp")
            if "peak_force" in res["coupled"]:
                print("contact points")
                diff("peak_force", h5_get(f, "peak_force"), res["coupled"]["peak_force"])
                if deck.has_friction():
                    diff("peak_friction", h5_get(f, "peak_friction"), res["coupled"]["peak_friction"])
        print("largest differences: " + ", ".join(f"{k} {v:.3e}" for k, v in worst.items()))
        t_p, t_o = [], []
        for _ in range(repeats):
            t_p.append(wall([exe, deck.path, "-o", tmp]))
            t_o.append(wall([sys.executable, os.path.abspath(__file__), "--one", deck.path]))
        mp, mo = statistics.median(t_p), statistics.median(t_o)
        print(f"whole processes, {repeats} interleaved runs, medians: pound {mp:.3f} s, "
              f"OpenSeesPy {mo:.3f} s, ratio OpenSees/pound {mo / mp:.1f}")


def wall(cmd):
    start = time.perf_counter()
    subprocess.run(cmd, check=True, capture_output=True)
    return time.perf_counter() - start


# ------------------------------------------------------------------------------------------
# --verify: the OpenSees side alone
# ------------------------------------------------------------------------------------------
def plan_deck(buildings, contacts, ground, dt=1.0e-3, t_end=5.0, title="plan pair"):
    """A plan deck's text. buildings: dicts (name, n, h, mass | load_coeff+ref, k_x planes
    [(position, k)], k_y planes [(position, k)], lx, ly, y0, xm, ym, zeta, pdelta);
    contacts: dicts (left, right, floors, gap, k, mu, kt); ground: the &ground body."""
    out = [f"&analysis title = '{title}', dt = {dt!r}, t_end = {t_end!r}, history = 'none' /", ground]
    for b in buildings:
        n = b["n"]
        mass = (f"mass = {n}*{b['mass']!r}" if "mass" in b
                else f"load_coeff = {n}*{b['load_coeff']!r}, ref_floor_load = {b['ref']!r}")
        extra = f", mass_centre = {b['xm']!r}, {b['ym']!r}" if "xm" in b else ""
        extra += f", rot_inertia = {n}*{b['inertia']!r}" if "inertia" in b else ""
        out.append(f"&building name = '{b['name']}', model = 'plan', n_storeys = {n}, height = {n}*{b['h']!r}, "
                   f"{mass}, plan_size = {b['lx']!r}, {b['ly']!r}, plan_origin_y = {b.get('y0', 0.0)!r}{extra}, "
                   f"damping_ratio = {b.get('zeta', 0.05)!r}, damping_modes = 1, 2, "
                   f"p_delta = {'.true.' if b.get('pdelta') else '.false.'} /")
        for d in ("x", "y"):
            for pos, k in b[f"planes_{d}"]:
                out.append(f"&plane building = '{b['name']}', direction = '{d}', position = {pos!r}, "
                           f"stiffness = {n}*{k!r} /")
    for c in contacts:
        fl = ", ".join(str(i) for i in c["floors"])
        fr = ", ".join(str(i) for i in c.get("floors_right", c["floors"]))
        fric = f", friction = {c['mu']!r}" if c.get("mu") else ""
        fric += f", shear_stiffness = {c['kt']!r}" if c.get("kt") else ""
        out.append(f"&contact left = '{c['left']}', right = '{c['right']}', floors_left = {fl}, floors_right = {fr}, "
                   f"gap = {c['gap']!r}, law = 'elastic', stiffness = {c['k']!r}{fric} /")
    return "\n".join(out) + "\n"


def seed_plan_buildings(lx=12.0, ly=12.0, y_factor=20.0):
    """The seed pair (input/two_frames_elastic.nml) as symmetric plan buildings: two x planes
    at the outline's edges y = 0, Ly with half the storey stiffness each, two y planes at
    x = 0, Lx with y_factor times it (so that the 3D modes 1 and 2 are the x modes 1 and 2)."""
    from bench_suite_opensees import BUILDINGS
    out = []
    for name, b in zip("AB", BUILDINGS):
        k = b["k"]
        out.append(dict(name=name, n=b["n"], h=b["h"], load_coeff=b["load"] / 98.1, ref=98.1, lx=lx, ly=ly,
                        planes_x=[(0.0, k / 2), (ly, k / 2)], planes_y=[(0.0, y_factor * k / 2), (lx, y_factor * k / 2)],
                        zeta=b["zeta"], pdelta=b["pdelta"]))
    return out


def write_at2(path, dt, values_g):
    with open(path, "w") as f:
        f.write("opensees_plan test motion\n0 0 0\nACCELERATION IN G\n")
        f.write(f"NPTS= {len(values_g)}, DT= {dt:.5f} SEC\n")
        for i in range(0, len(values_g), 5):
            f.write(" ".join(f"{v:.8e}" for v in values_g[i:i + 5]) + "\n")


def verify():
    ok = True
    with tempfile.TemporaryDirectory() as tmp:
        # 1. One storey, planes offset from the centre of mass: closed-form x-theta frequencies.
        m, lx, ly, xm, ym = 50.0, 10.0, 8.0, 4.0, 3.0
        inertia = m * (lx ** 2 + ly ** 2) / 12.0
        planes_x = [(0.0, 3.0e4), (ly, 1.0e4)]
        planes_y = [(xm - 3.0, 2.0e4), (xm + 3.0, 2.0e4)]  # symmetric about xm: y decouples
        deck_path = os.path.join(tmp, "one_storey.nml")
        open(deck_path, "w").write(plan_deck(
            [dict(name="A", n=1, h=3.0, mass=m, lx=lx, ly=ly, xm=xm, ym=ym, planes_x=planes_x, planes_y=planes_y)],
            [], "&ground kind = 'pulse', x0 = 0.01, a = 2.0, b = 12.566370614359172 /", title="one storey"))
        deck = Deck(deck_path)
        kxx = sum(k for _, k in planes_x)
        kxt = -sum(k * (c - ym) for c, k in planes_x)
        ktt = sum(k * (c - ym) ** 2 for c, k in planes_x) + sum(k * (c - xm) ** 2 for c, k in planes_y)
        kyy = sum(k for _, k in planes_y)
        p, q = kxx / m, ktt / inertia
        root = math.sqrt((p - q) ** 2 + 4.0 * kxt ** 2 / (m * inertia))
        closed = np.sort([math.sqrt((p + q - root) / 2), math.sqrt(kyy / m), math.sqrt((p + q + root) / 2)])
        model = Model(deck, coupled=False)
        model.build()
        w_os = np.sort(model.eigen_omegas(3))
        model.ops.wipe()
        w_np = deck.buildings[0].omegas()
        e1 = np.max(np.abs(w_os - closed) / closed)
        e2 = np.max(np.abs(w_np - closed) / closed)
        print(f"one storey, eccentric: omega closed form {' '.join(f'{w:.6f}' for w in closed)} rad/s")
        print(f"  OpenSees eigen {' '.join(f'{w:.6f}' for w in w_os)}: max relative difference {e1:.2e}")
        print(f"  this script's K, M (Rayleigh fit) {' '.join(f'{w:.6f}' for w in w_np)}: {e2:.2e}")
        ok &= e1 < 1e-9 and e2 < 1e-12

        # 2. The seed pair as symmetric plan buildings along x against the planar OpenSees model.
        import bench_suite_opensees as planar
        dt, t_end, gap = 1.0e-3, 5.0, 1.0e-3
        t = dt * np.arange(int(round(t_end / dt)) + 1)
        ag_g = 0.35 * np.sin(2.0 * math.pi * t / 0.4) * np.sin(math.pi * t / t_end)  # zero at t = 0
        at2 = os.path.join(tmp, "motion.at2")
        write_at2(at2, dt, ag_g)
        bs = seed_plan_buildings()
        ground = f"&ground kind = 'record', file = '{at2}' /"
        contacts = [dict(left="A", right="B", floors=[1, 2, 3], gap=gap, k=planar.JOINT_K)]
        deck_path = os.path.join(tmp, "seed_plan.nml")
        open(deck_path, "w").write(plan_deck(bs, contacts, ground, dt, t_end, "seed pair in plan"))
        deck = Deck(deck_path)
        for b, pb in zip(deck.buildings, planar.BUILDINGS):
            a_plan, a_planar = np.array(b.rayleigh()), np.array(planar.rayleigh(pb))
            e = np.max(np.abs(a_plan - a_planar) / a_planar)
            print(f"seed pair in plan, building {b.name}: Rayleigh a0, a1 from the 3D modes against the planar "
                  f"model's: {e:.2e}")
            ok &= e < 1e-10
        res = analyse(deck, joint="gap")
        real = planar.ops

        class Precise:  # the planar script's envelope at full precision (its default: 6 digits)
            def __getattr__(self, name):
                return getattr(real, name)

            def recorder(self, kind, *args):
                return real.recorder(kind, "-precision", 17, *args)

        planar.ops = Precise()
        for label, g in (("uncoupled", None), ("coupled", gap)):
            planar.run(G * read_at2(at2)[1], dt, g)
            ref = np.max(np.abs(np.atleast_2d(np.loadtxt(planar.ENVELOPE))), axis=0)
            os.remove(planar.ENVELOPE)
            ux = np.concatenate([res[label][b.name]["u_x"] for b in deck.buildings])
            side = max(float(np.max(res[label][b.name][q])) for b in deck.buildings for q in ("u_y", "rotation"))
            e = np.max(np.abs(ux - ref) / ref)
            print(f"  {label}: peak u_x of the floors against the planar model: max relative difference {e:.2e}; "
                  f"largest |u_y|, |theta| {side:.1e}")
            ok &= e < 1e-9 and side < 1e-12
        planar.ops = real
        # The contact points take half the pair's stiffness each: the points' force sums to the
        # planar pair's (two per pair, equal by symmetry).
        f = res["coupled"]["peak_force"].reshape(-1, 2)
        print(f"  contact points' peak forces (kN), per pair: " + "; ".join(f"{a:.2f} {b:.2f}" for a, b in f))
        ok &= bool(np.allclose(f[:, 0], f[:, 1], rtol=1e-8))
        # 3. zeroLengthImpact3D (Penalty ties) against ElasticPPGap (exact ties) with mu = 0 on
        # the eccentric pair of scripts/bench_plan.py (partial overlap, ground at 30 degrees;
        # gap 0.5 mm, so that the points strike under the test motion):
        # the 3-DOF contact nodes follow the floors' rotation, the normal law is the same.
        from bench_plan import decks
        ecc = decks(3, at2, "eccentric", dt, t_end)[0].replace("gap = 0.005", "gap = 0.0005")
        deck_path = os.path.join(tmp, "eccentric_mu0.nml")
        open(deck_path, "w").write(ecc.replace(", friction = 0.3, shear_stiffness = 1000000.0", ""))
        deck = Deck(deck_path)
        r_gap, r_imp = analyse(deck, joint="gap"), analyse(deck, joint="impact3d")
        n_gap, n_imp = r_gap["coupled"]["peak_force"], r_imp["coupled"]["peak_force"]
        e = np.max(np.abs(n_imp - n_gap)) / np.max(n_gap)
        e2 = max(np.max(np.abs(r_imp["coupled"][b.name][q] - r_gap["coupled"][b.name][q]) / np.max(r_gap["coupled"][b.name][q]))
                 for b in deck.buildings for q in ("u_x", "u_y", "rotation"))
        print(f"eccentric pair, mu = 0, ground at 30 degrees: peak N of the points (kN) "
              + " ".join(f"{v:.2f}" for v in n_gap))
        print(f"  zeroLengthImpact3D (Penalty) against ElasticPPGap: peak N {e:.2e}, peak u_x, u_y, theta {e2:.2e} "
              f"(of the largest); peak |T| {np.max(r_imp['coupled']['peak_friction']):.1e} kN")
        ok &= bool(np.count_nonzero(n_gap) >= 2) and e < 1e-5 and e2 < 1e-5 and np.max(r_imp["coupled"]["peak_friction"]) == 0.0
        # 4. The same with friction 0.3: every point's peak |T| within mu times its peak N.
        deck_path = os.path.join(tmp, "eccentric_mu.nml")
        open(deck_path, "w").write(ecc)
        deck = Deck(deck_path)
        r = analyse(deck)
        n, t_ = r["coupled"]["peak_force"], r["coupled"]["peak_friction"]
        print(f"eccentric pair, mu = 0.3: peak N " + " ".join(f"{v:.2f}" for v in n) + ", peak |T| "
              + " ".join(f"{v:.2f}" for v in t_) + " kN; slipping steps "
              + " ".join(str(int(v)) for v in r["coupled"]["slipping_steps"]))
        ok &= bool(np.all(t_ <= 0.3 * n * (1 + 1e-9))) and bool(np.max(t_) > 0.0)
    print("OpenSees side: " + ("all checks pass" if ok else "CHECKS FAILED"))
    return ok


def write_decks(folder, record, t_end=10.0):
    """The comparison decks under `record`: the seed pair in plan (symmetric, along x), the
    eccentric pair of scripts/bench_plan.py without and with friction (ground at 30 degrees)."""
    from bench_plan import decks
    os.makedirs(folder, exist_ok=True)
    record = os.path.abspath(record)
    contacts = [dict(left="A", right="B", floors=[1, 2, 3], gap=1.0e-3, k=1.0e6)]
    texts = {"seed_plan.nml": plan_deck(seed_plan_buildings(), contacts, f"&ground kind = 'record', file = '{record}' /",
                                        1.0e-3, t_end, "seed pair in plan, along x"),
             "eccentric_plan_friction.nml": decks(3, record, "eccentric", 1.0e-3, t_end)[0]}
    texts["eccentric_plan.nml"] = texts["eccentric_plan_friction.nml"].replace(
        ", friction = 0.3, shear_stiffness = 1000000.0", "")
    for name, text in texts.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
        print(os.path.join(folder, name))


def main():
    sys.path.insert(0, HERE)
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    if sys.argv[1] == "--write-decks":
        write_decks(sys.argv[2], sys.argv[3])
        return
    if sys.argv[1] == "--verify":
        sys.exit(0 if verify() else 1)
    if sys.argv[1] == "--one":
        analyse(Deck(sys.argv[2]))
        return
    if sys.argv[1] == "--compare":
        compare(os.path.abspath(sys.argv[2]), sys.argv[3], int(sys.argv[4]) if len(sys.argv) > 4 else 5)
        return
    deck = Deck(sys.argv[1])
    report(deck, analyse(deck, sys.argv[2] if len(sys.argv) > 2 else "auto"))


if __name__ == "__main__":
    main()
