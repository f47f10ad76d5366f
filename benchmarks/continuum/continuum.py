#!/usr/bin/python3
"""The arch as a two-dimensional body: CalculiX's H/V beside the beam models' (docs/model.md, "The beam's
validity").

The half arch (the scene is symmetric) is meshed with quadratic quadrilaterals (CPS8 plane stress or CPE8
plane strain) between its intrados and extrados, springing to the crown's vertical line x = L/2; the
springing face is fixed (clamped: every node of the face held) or turns freely about its axis point as a
rigid line (pinned: the face's nodes tied to the axis node's rotation by linear equations, the axis node
held); the crown's line is a plane of symmetry (ux = 0); the self-weight is a body force (rho g on every
element). H is the springing face's horizontal reaction, V its vertical one (half the weight). Each H/V
is extrapolated from three meshes (n, 2n, 4n elements through the thickness, the same aspect) by
Richardson's rule, its estimated discretisation error the difference to the finest mesh.

Usage (from the repository's top, after the build):
  /usr/bin/python3 benchmarks/continuum/continuum.py check     # the clamped semicircle, t/L 0.08
  /usr/bin/python3 benchmarks/continuum/continuum.py reference # CalculiX: benchmarks/continuum/reference.csv
  /usr/bin/python3 benchmarks/continuum/continuum.py table     # the beams beside it: continuum.csv
  /usr/bin/python3 benchmarks/continuum/continuum.py poisson   # nu 0 against 0.2: poisson.csv
  /usr/bin/python3 benchmarks/continuum/continuum.py ends      # the held face against one free laterally
  /usr/bin/python3 benchmarks/continuum/continuum.py spread    # no weight, the springings spread apart
  /usr/bin/python3 benchmarks/continuum/continuum.py crown     # the pointed crown against a beam's crown
  /usr/bin/python3 benchmarks/continuum/continuum.py strip     # a held face's compliance, a straight strip
  /usr/bin/python3 benchmarks/continuum/continuum.py joint     # the pointed crown's joint, a local problem
  /usr/bin/python3 benchmarks/continuum/continuum.py wedge     # a pointed crown's wedge over its angle
  /usr/bin/python3 benchmarks/continuum/continuum.py trial     # the curved bar with both terms (beam.py)
  /usr/bin/python3 benchmarks/continuum/continuum.py components # the clamped catenary's weight, part by part
  /usr/bin/python3 benchmarks/continuum/continuum.py ring      # a curved bar's held face: ring.csv
  /usr/bin/python3 benchmarks/continuum/continuum.py figure    # docs/figures/continuum.png from the CSV
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

# The paper's travertine (docs/model.md): H/V depends on E and rho only through nothing (no support moves).
E, NU, RHO, G_ACC = 14.8e9, 0.20, 2348.0, 9.81
SPAN = 10.0
HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))


# ---- geometry: each face of the half arch as a function of xi in [0, 1], springing to the crown line ----

class Pointed:
    """Two circular arcs of radius R = (0.5 + eps) L centred on the springing line eps L beyond mid-span
    (eps 0: the semicircle). The left half is the left arc's annulus up to x = L/2."""

    def __init__(self, eps, t):
        self.eps, self.t = eps, t
        self.R = (0.5 + eps) * SPAN
        self.cx = SPAN / 2 + eps * SPAN  # the left arc's centre (on y = 0)
        self.name = "semicircular" if eps == 0 else "pointed"

    def face(self, side, xi):
        # side -1: intrados, +1: extrados; angle from pi (left springing) down to where x = L/2.
        r = self.R + side * self.t / 2
        end = math.acos((SPAN / 2 - self.cx) / r)
        phi = math.pi + xi * (end - math.pi)
        return (self.cx + r * math.cos(phi), r * math.sin(phi))

    def axis_length(self):
        return self.R * (math.pi - math.acos(-self.eps * SPAN / self.R))

    def ogive_args(self):
        return ["--curve", "pointed", "--eccentricity", repr(self.eps)]


class OffsetCurve:
    """A smooth symmetric axis y(x) (the crown's tangent horizontal): each face is the axis offset by t/2
    along the normal, sampled at the same arc length, so the mesh's lines across are the beam's sections."""

    def __init__(self, t, n=4000):
        self.t = t
        xs = [self.x_start() + (SPAN / 2 - self.x_start()) * (i / n) for i in range(n + 1)]
        self.pts = [(x, self.y(x)) for x in xs]
        self.s = [0.0]
        for (x0, y0), (x1, y1) in zip(self.pts, self.pts[1:]):
            self.s.append(self.s[-1] + self.chord(x0, x1))

    def chord(self, x0, x1):
        # arc length by Gauss-Legendre (3 points) of sqrt(1 + y'^2)
        g = [(-math.sqrt(0.6), 5 / 9), (0.0, 8 / 9), (math.sqrt(0.6), 5 / 9)]
        h = (x1 - x0) / 2
        return sum(w * math.hypot(1, self.dy(x0 + h * (1 + u))) for u, w in g) * h

    def axis_length(self):
        return self.s[-1]

    def face(self, side, xi):
        target = xi * self.s[-1]
        lo, hi = 0, len(self.s) - 1
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if self.s[mid] <= target:
                lo = mid
            else:
                hi = mid
        # x at arc length target, by Newton from the bracket
        x = self.pts[lo][0]
        for _ in range(30):
            f = self.s[lo] + self.chord(self.pts[lo][0], x) - target
            x -= f / math.hypot(1, self.dy(x))
        d = self.dy(x)
        n = (-d / math.hypot(1, d), 1 / math.hypot(1, d))  # the normal towards the extrados
        return (x + side * self.t / 2 * n[0], self.y(x) + side * self.t / 2 * n[1])


class Segmental(OffsetCurve):
    """One circular arc of rise h through both springings (h < L/2)."""

    def __init__(self, rise_ratio, t):
        h = rise_ratio * SPAN
        self.rise_ratio = rise_ratio
        self.R = (SPAN ** 2 / 4 + h ** 2) / (2 * h)
        self.yc = h - self.R
        self.name = "segmental"
        super().__init__(t)

    def x_start(self):
        return 0.0

    def y(self, x):
        return self.yc + math.sqrt(self.R ** 2 - (x - SPAN / 2) ** 2)

    def dy(self, x):
        return -(x - SPAN / 2) / math.sqrt(self.R ** 2 - (x - SPAN / 2) ** 2)

    def ogive_args(self):
        return ["--curve", "segmental", "--rise-ratio", repr(self.rise_ratio)]


class Catenary(OffsetCurve):
    """y = h - a (cosh((x - L/2) / a) - 1), a (cosh(L / (2a)) - 1) = h."""

    def __init__(self, rise_ratio, t):
        h = rise_ratio * SPAN
        self.rise_ratio = rise_ratio
        lo, hi = 1e-3, 1e3
        for _ in range(200):
            mid = math.sqrt(lo * hi)
            if mid * (math.cosh(SPAN / (2 * mid)) - 1) > h:
                lo = mid
            else:
                hi = mid
        self.a, self.h = math.sqrt(lo * hi), h
        self.name = "catenary"
        super().__init__(t)

    def x_start(self):
        return 0.0

    def y(self, x):
        return self.h - self.a * (math.cosh((x - SPAN / 2) / self.a) - 1)

    def dy(self, x):
        return -math.sinh((x - SPAN / 2) / self.a)

    def ogive_args(self):
        return ["--curve", "catenary", "--rise-ratio", repr(self.rise_ratio)]


def make_arch(kind, t):
    if kind == "semicircular":
        return Pointed(0.0, t)
    if kind == "equilateral":
        return Pointed(0.5, t)
    if kind == "segmental":
        return Segmental(0.25, t)
    if kind == "catenary":
        return Catenary(0.5, t)
    raise ValueError(kind)


# ---- the CalculiX model ----

def mesh(arch, n_across, aspect=2.0):
    """Nodes and 8-node elements of a structured mesh: n_across elements through the thickness, elements
    about aspect times as long as deep. Node (i, j) on the grid of half-steps; xi along, eta across."""
    t = arch.t
    n_along = max(4, round(arch.axis_length() / (aspect * t / n_across)))
    I, J = 2 * n_along, 2 * n_across
    nodes, ids = [], {}
    faces = {}
    for i in range(I + 1):
        xi = i / I
        faces[i] = (arch.face(-1, xi), arch.face(+1, xi))
    for i in range(I + 1):
        (xa, ya), (xb, yb) = faces[i]
        for j in range(J + 1):
            if i % 2 == 1 and j % 2 == 1:
                continue  # serendipity: no centre node
            f = j / J
            ids[(i, j)] = len(nodes) + 1
            nodes.append((xa + f * (xb - xa), ya + f * (yb - ya)))
    elements = []
    for a in range(n_along):
        for b in range(n_across):
            i, j = 2 * a, 2 * b
            # CalculiX's 8-node order: corners counter-clockwise, then the mid-sides (1-2, 2-3, 3-4, 4-1).
            corners = [(i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2)]
            mids = [(i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1)]
            elements.append([ids[c] for c in corners + mids])
    springing = [ids[(0, j)] for j in range(J + 1)]
    crown = [ids[(I, j)] for j in range(J + 1)]
    # The xi-direction runs from the springing to the crown and eta from intrados to extrados: with the
    # arch rising to the right, (xi, eta) is counter-clockwise.
    return nodes, elements, springing, crown


def ccx_input(arch, n_across, plane_strain, supports, nu=NU):
    nodes, elements, springing, crown = mesh(arch, n_across)
    lines = ["*HEADING", "ogive continuum benchmark", "*NODE"]
    lines += [f"{k + 1}, {x:.13f}, {y:.13f}, 0" for k, (x, y) in enumerate(nodes)]
    etype = "CPE8" if plane_strain else "CPS8"
    lines.append(f"*ELEMENT, TYPE={etype}, ELSET=EALL")
    lines += [f"{k + 1}, " + ", ".join(map(str, e)) for k, e in enumerate(elements)]
    lines += ["*NSET, NSET=NSPRING"] + [str(n) for n in springing]
    lines += ["*NSET, NSET=NCROWN"] + [str(n) for n in crown]
    lines += ["*MATERIAL, NAME=STONE", "*ELASTIC", f"{E:.15g}, {nu:.15g}", "*DENSITY", f"{RHO:.15g}"]
    lines += ["*SOLID SECTION, ELSET=EALL, MATERIAL=STONE", f"{section_thickness(arch):.15g}"]
    lines += ["*BOUNDARY", "NCROWN, 1, 1, 0."]
    if supports == "clamped":
        lines += ["NSPRING, 1, 2, 0."]
    elif supports == "lateral":
        lines += springing_free_laterally(nodes, springing)
    else:
        # The springing face a rigid line that turns about its axis node (held): with the face's direction
        # d and node k at distance r_k along it from the axis node, u_k = r_k / r_e u_e (a rotation: the
        # extrados node e's displacement along d is zero, so the face neither stretches nor bends).
        mid = springing[len(springing) // 2]
        e_node = springing[-1]
        (x0, y0), (xe, ye) = nodes[mid - 1], nodes[e_node - 1]
        re = math.hypot(xe - x0, ye - y0)
        d = ((xe - x0) / re, (ye - y0) / re)
        lines += [f"{mid}, 1, 2, 0."]
        lines.append("*EQUATION")
        lines += ["2", f"{e_node}, 1, {d[0]:.15g}, {e_node}, 2, {d[1]:.15g}"]
        for k in springing:
            if k in (mid, e_node):
                continue
            xk, yk = nodes[k - 1]
            r = ((xk - x0) * d[0] + (yk - y0) * d[1]) / re
            for dof in (1, 2):
                lines += ["2", f"{k}, {dof}, 1., {e_node}, {dof}, {-r:.15g}"]
    lines += ["*STEP", "*STATIC", "*DLOAD", f"EALL, GRAV, {G_ACC:.15g}, 0., -1., 0."]
    lines += ["*NODE PRINT, NSET=NSPRING, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(lines) + "\n", len(elements)


def springing_free_laterally(nodes, springing):
    """The clamped springing face held along its normal and turning not at all, but free to stretch along
    itself (uniformly, about its axis node, which is held): the lateral (Poisson) strain that a face held
    whole restrains. Each face node k at r_k along the face from the axis node: u_k . n = 0 and
    u_k . d = r_k / r_e u_e . d (linear *EQUATIONs, the dependent term first)."""
    mid, e_node = springing[len(springing) // 2], springing[-1]
    (x0, y0), (xe, ye) = nodes[mid - 1], nodes[e_node - 1]
    re = math.hypot(xe - x0, ye - y0)
    d = ((xe - x0) / re, (ye - y0) / re)
    n = (-d[1], d[0])
    lines = [f"{mid}, 1, 2, 0.", "*EQUATION"]
    for k in springing:
        if k == mid:
            continue
        # u . n = 0: the component along n's larger direction depends on the other.
        big, small = (2, 1) if abs(n[1]) >= abs(n[0]) else (1, 2)
        if abs(n[small - 1]) < 1e-14:
            lines += ["1", f"{k}, {big}, 1."]
        else:
            lines += ["2", f"{k}, {big}, {n[big - 1]:.15g}, {k}, {small}, {n[small - 1]:.15g}"]
        if k == e_node:
            continue
        xk, yk = nodes[k - 1]
        r = ((xk - x0) * d[0] + (yk - y0) * d[1]) / re
        lines += ["4", f"{k}, {small}, {d[small - 1]:.15g}, {k}, {big}, {d[big - 1]:.15g}, "
                  f"{e_node}, 1, {-r * d[0]:.15g}, {e_node}, 2, {-r * d[1]:.15g}"]
    return lines


def section_thickness(arch):
    """The out-of-plane thickness of the elements, t / 1000. CalculiX expands a CPS8 element into a 3D brick
    of this thickness with free faces: the state is plane stress only where the brick is thin against the
    depth (at 1 m on a 0.2 m deep arch, a spread springing's thrust comes out 3.7 % above plane stress'
    at nu 0.2, nearly plane strain's 4.2 %; the error falls as the square of thickness / t, below 1e-5 of
    H/V here). Plane strain does not depend on it; the reactions are divided by it."""
    return 1e-3 * arch.t


def run_ccx(arch, n_across, plane_strain=False, supports="clamped", nu=NU):
    text, n_elements = ccx_input(arch, n_across, plane_strain, supports, nu)
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "arch.inp"), "w") as f:
            f.write(text)
        env = dict(os.environ, OMP_NUM_THREADS="1")
        run = subprocess.run(["ccx", "-i", "arch"], cwd=work, capture_output=True, text=True, env=env)
        dat = open(os.path.join(work, "arch.dat")).read() if os.path.exists(os.path.join(work, "arch.dat")) else ""
    m = re.search(r"total force \(fx,fy,fz\).*?\n\s*\n?\s*([-+0-9.Ee]+)\s+([-+0-9.Ee]+)\s+([-+0-9.Ee]+)", dat, re.S)
    if run.returncode != 0 or not m:
        raise RuntimeError(f"ccx failed ({run.returncode}): {run.stdout[-2000:]}")
    # The support's reaction on the arch: at the left springing H points into the span (+x). CalculiX's RF
    # leaves out the body force's share that the held nodes take straight into the support (1/6 of the
    # springing's row of elements), so V is the half arch's weight itself, rho g times its area.
    fx = float(m.group(1)) / section_thickness(arch)  # per metre of width
    V = RHO * G_ACC * area(arch)
    return fx / V, V, n_elements


def area(arch, n=20000):
    """The half arch's area (m^2 per metre of width) by the shoelace rule over its outline (error ~ 1/n^2)."""
    outline = [arch.face(-1, i / n) for i in range(n + 1)] + [arch.face(+1, 1 - i / n) for i in range(n + 1)]
    return abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(outline, outline[1:] + outline[:1]))) / 2


def continuum(arch, plane_strain=False, supports="clamped", n0=4, nu=NU):
    """H/V extrapolated from n0, 2 n0 and 4 n0 elements through the thickness, its estimated error, the
    three meshes' values and the observed order."""
    values = []
    for n in (n0, 2 * n0, 4 * n0):
        hv, fy, n_el = run_ccx(arch, n, plane_strain, supports, nu)
        values.append(round(hv, 7))  # as reference.csv keeps them: the table is reproducible from its rows
    extrapolated, error, order = extrapolate(values)
    return extrapolated, error, values, order


def extrapolate(values):
    """Richardson's rule on three meshes, each with twice the elements of the one before: the limit, its
    error estimate and the observed order. Where the differences do not fall monotonically (an order
    outside [1, 8]), the finest mesh and the larger difference. CalculiX prints reactions to 7 digits: no
    estimate is below 1e-6 of H/V."""
    d1, d2 = values[1] - values[0], values[2] - values[1]
    order = math.log2(abs(d1 / d2)) if d2 != 0 and d1 / d2 > 0 else float("nan")
    floor = 1e-6 * abs(values[2])
    if math.isfinite(order) and 1 <= order <= 8:
        extrapolated = values[2] + d2 / (2 ** order - 1)
        return extrapolated, max(2 * abs(extrapolated - values[2]), floor), order
    return values[2], max(abs(d1), abs(d2), floor), order


def ogive_hv(ogive, arch, t_over_l, model, plane_strain=False, supports="clamped", nu=NU):
    """ogive's H/V of the scene with one beam model, and its model_error_estimate (NaN where none)."""
    args = [ogive, "thrust", *arch.ogive_args(), "--thickness-ratio", repr(t_over_l), "--supports", supports,
            "--beam-model", model, "--poisson-ratio", repr(nu), "--rtol", "1e-10", "--columns", "H_over_V,model_error_estimate,status"]
    if plane_strain:
        args.append("--plane-strain")
    out = subprocess.run(args, capture_output=True, text=True)
    rows = list(csv.DictReader(out.stdout.splitlines())) if out.returncode in (0, 3) else []
    if not rows or not rows[0]["H_over_V"] or rows[0]["status"] != "success":
        return float("nan"), float("nan")
    return float(rows[0]["H_over_V"]), float(rows[0]["model_error_estimate"] or "nan")


ARCHES = ["semicircular", "equilateral", "segmental", "catenary"]
RATIOS = [0.02, 0.04, 0.06, 0.08, 0.10, 0.12, 0.15, 0.20, 0.25]
MODELS = ["euler-bernoulli", "timoshenko", "curved"]
REFERENCE = os.path.join(HERE, "reference.csv")
TABLE = os.path.join(HERE, "continuum.csv")
POISSON = os.path.join(HERE, "poisson.csv")
ENDS = os.path.join(HERE, "ends.csv")
SPREAD = os.path.join(HERE, "spread.csv")
CROWN = os.path.join(HERE, "crown.csv")
STRIP = os.path.join(HERE, "strip.csv")
JOINT = os.path.join(HERE, "joint.csv")
TRIAL = os.path.join(HERE, "trial.csv")
WEDGE = os.path.join(HERE, "wedge.csv")
WEDGE_ANGLES = (0.5, 5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60, 65, 70, 75)
HELD = os.path.join(HERE, "held.csv")
COMPONENTS = os.path.join(HERE, "components.csv")
RING = os.path.join(HERE, "ring.csv")
HELD_NU = (-0.9, -0.7, -0.5, -0.3, -0.1, 0.0, 0.1, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.97)
SPREAD_CASES = [("semicircular", 0.1), ("semicircular", 0.2), ("segmental", 0.2), ("catenary", 0.2)]
ENDS_CASES = [("semicircular", 0.1), ("semicircular", 0.2), ("equilateral", 0.2), ("catenary", 0.08), ("catenary", 0.2)]
POISSON_CASES = [("semicircular", "pinned", 0.1), ("semicircular", "pinned", 0.2), ("semicircular", "clamped", 0.1),
                 ("semicircular", "clamped", 0.2), ("equilateral", "pinned", 0.2), ("equilateral", "clamped", 0.2)]
REF_FIELDS = ["arch", "supports", "plane", "t_over_L", "H_over_V", "fe_error", "mesh_4", "mesh_8", "mesh_16", "order"]


def reference(cases):
    """CalculiX's H/V for each (arch, supports, plane, t/L) not yet in reference.csv, appended row by row."""
    done = set()
    if os.path.exists(REFERENCE):
        for r in csv.DictReader(open(REFERENCE)):
            done.add((r["arch"], r["supports"], r["plane"], r["t_over_L"]))
    new = not os.path.exists(REFERENCE)
    with open(REFERENCE, "a", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        if new:
            w.writerow(REF_FIELDS)
        for arch, supports, plane, ratio in cases:
            key = (arch, supports, plane, repr(ratio))
            if key in done:
                continue
            hv, err, values, order = continuum(make_arch(arch, ratio * SPAN), plane == "strain", supports)
            w.writerow([arch, supports, plane, repr(ratio), f"{hv:.7f}", f"{err:.1e}",
                        *(f"{v:.7f}" for v in values), f"{order:.2f}"])
            f.flush()
            print(arch, supports, plane, ratio, f"{hv:.6f} +- {err:.1e} (order {order:.2f})", file=sys.stderr)


def table(ogive):
    """continuum.csv: each reference row with every beam model's H/V, its relative error against the
    continuum (relative to max(|H/V|, 0.01), as ogive's estimates are) and ogive's model_error_estimate."""
    rows = list(csv.DictReader(open(REFERENCE)))
    with open(TABLE, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["arch", "supports", "plane", "t_over_L", "continuum", "fe_error"] + MODELS +
                   [f"{m}_error" for m in MODELS] + [f"{m}_estimate" for m in MODELS])
        for r in rows:
            ratio = float(r["t_over_L"])
            arch = make_arch(r["arch"], ratio * SPAN)
            ref = float(r["H_over_V"])
            got = [ogive_hv(ogive, arch, ratio, m, r["plane"] == "strain", r["supports"]) for m in MODELS]
            w.writerow([r["arch"], r["supports"], r["plane"], r["t_over_L"], r["H_over_V"], r["fe_error"]] +
                       [f"{hv:.7f}" for hv, _ in got] +
                       [f"{(hv - ref) / max(abs(ref), 0.01):.3e}" for hv, _ in got] +
                       [f"{est:.3e}" for _, est in got])
    summary()


def summary():
    """The table's summary on stdout: each model's largest error by arch and supports, how often the
    curved bar's error is at most half of Timoshenko's and within 0.5 %, and how often each estimate
    bounds the error."""
    rows = list(csv.DictReader(open(TABLE)))
    print("arch,supports,plane,rows," + ",".join(f"max_{m}_error" for m in MODELS))
    groups = sorted({(r["arch"], r["supports"], r["plane"]) for r in rows}, key=lambda g: (g[2], g[1], ARCHES.index(g[0])))
    for g in groups:
        sel = [r for r in rows if (r["arch"], r["supports"], r["plane"]) == g]
        print(",".join(g) + f",{len(sel)}," + ",".join(f"{max(abs(float(r[f'{m}_error'])) for r in sel):.2e}" for m in MODELS))
    half = [r for r in rows if abs(float(r["curved_error"])) <= 0.5 * abs(float(r["timoshenko_error"]))]
    print(f"curved error <= half of timoshenko's: {len(half)} of {len(rows)} rows")
    for r in rows:
        if r not in half:
            print(f"  not: {r['arch']} {r['supports']} {r['plane']} t/L {r['t_over_L']}: curved {float(r['curved_error']):+.2e}, "
                  f"timoshenko {float(r['timoshenko_error']):+.2e}")
    near = [r for r in rows if float(r["t_over_L"]) <= 0.2]
    ok = [r for r in near if abs(float(r["curved_error"])) <= 0.005]
    print(f"curved error within 0.5 % up to t/L 0.2: {len(ok)} of {len(near)} rows")
    for m in MODELS:
        n = sum(1 for r in rows if float(r[f"{m}_estimate"]) >= abs(float(r[f"{m}_error"])))
        print(f"{m}: model_error_estimate >= error on {n} of {len(rows)} rows")


def poisson(ogive):
    """poisson.csv: the continuum at nu 0 and at the paper's 0.2 beside Timoshenko's beam and the curved bar
    at the same nu (plane stress): how H/V moves with nu alone, the radial stress' Poisson strain that the
    curved bar's section takes and Timoshenko's does not (its nu acts through G only)."""
    with open(POISSON, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["arch", "supports", "t_over_L", "nu", "continuum", "fe_error", "timoshenko", "curved",
                    "timoshenko_error", "curved_error"])
        for arch, supports, ratio in POISSON_CASES:
            for nu in (0.0, NU):
                hv, err, _, _ = continuum(make_arch(arch, ratio * SPAN), False, supports, nu=nu)
                got = [ogive_hv(ogive, make_arch(arch, ratio * SPAN), ratio, m, False, supports, nu)[0]
                       for m in ("timoshenko", "curved")]
                w.writerow([arch, supports, repr(ratio), repr(nu), f"{hv:.7f}", f"{err:.1e}"] +
                           [f"{g:.7f}" for g in got] + [f"{(g - hv) / hv:.3e}" for g in got])
                f.flush()
    print(open(POISSON).read(), end="")


def ends(ogive):
    """ends.csv: the clamped springing face held whole (the table's) against one free to stretch along itself
    (springing_free_laterally), the continuum's H/V beside the curved bar's (plane stress): how much of the
    curved bar's error is the held face's restraint of the lateral strain."""
    with open(ENDS, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["arch", "t_over_L", "held", "free_laterally", "curved", "curved_error_held",
                    "curved_error_free_laterally"])
        for arch, ratio in ENDS_CASES:
            held, _, _, _ = continuum(make_arch(arch, ratio * SPAN), False, "clamped")
            free, _, _, _ = continuum(make_arch(arch, ratio * SPAN), False, "lateral")
            curved = ogive_hv(ogive, make_arch(arch, ratio * SPAN), ratio, "curved")[0]
            w.writerow([arch, repr(ratio), f"{held:.7f}", f"{free:.7f}", f"{curved:.7f}",
                        f"{(curved - held) / held:.3e}", f"{(curved - free) / free:.3e}"])
            f.flush()
    print(open(ENDS).read(), end="")


def spread_thrust(arch, n_across, nu):
    """The clamped continuum's H (N per metre of width) with no weight, each springing face held whole and
    moved outwards by 1e-4 of the span."""
    text, _ = ccx_input(arch, n_across, False, "clamped", nu)
    delta = 1e-4 * SPAN
    text = text.replace("NSPRING, 1, 2, 0.", f"NSPRING, 1, 1, {-delta!r}\nNSPRING, 2, 2, 0.")
    text = re.sub(r"\*DLOAD\n.*\n", "", text)
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "arch.inp"), "w") as f:
            f.write(text)
        run = subprocess.run(["ccx", "-i", "arch"], cwd=work, capture_output=True, text=True,
                             env=dict(os.environ, OMP_NUM_THREADS="1"))
        dat = open(os.path.join(work, "arch.dat")).read() if os.path.exists(os.path.join(work, "arch.dat")) else ""
    m = re.search(r"total force \(fx,fy,fz\).*?\n\s*\n?\s*([-+0-9.Ee]+)", dat, re.S)
    if run.returncode != 0 or not m:
        raise RuntimeError(f"ccx failed ({run.returncode}): {run.stdout[-2000:]}")
    return float(m.group(1)) / section_thickness(arch)


def spread(ogive):
    """spread.csv: the clamped arch without weight, its springings spread apart: the thrust a stiffness alone
    (no body force), the continuum's beside the beams' at nu 0 and 0.2 (plane stress). ogive's thrust of the
    spread is the difference of two runs with the weight (the problem is linear)."""
    def beam(arch, ratio, model, nu):
        def h(ratio_spread):
            args = [ogive, "thrust", *arch.ogive_args(), "--thickness-ratio", repr(ratio), "--supports", "clamped",
                    "--left-spread-ratio", ratio_spread, "--right-spread-ratio", ratio_spread, "--beam-model", model,
                    "--poisson-ratio", repr(nu), "--rtol", "1e-10", "--columns", "H"]
            return float(list(csv.DictReader(subprocess.run(args, capture_output=True, text=True).stdout.splitlines()))[0]["H"])
        return h("1e-4") - h("0")
    with open(SPREAD, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["arch", "t_over_L", "nu", "continuum", "fe_error", "timoshenko", "curved", "timoshenko_error",
                    "curved_error"])
        for name, ratio in SPREAD_CASES:
            for nu in (0.0, NU):
                arch = make_arch(name, ratio * SPAN)
                h, err, _ = extrapolate([round(spread_thrust(arch, n, nu), 3) for n in (4, 8, 16)])
                got = [beam(arch, ratio, m, nu) for m in ("timoshenko", "curved")]
                w.writerow([name, repr(ratio), repr(nu), f"{h:.7g}", f"{err:.1e}"] + [f"{g:.7g}" for g in got] +
                           [f"{(g - h) / h:.3e}" for g in got])
                f.flush()
    print(open(SPREAD).read(), end="")


class RadialCrown(Pointed):
    """The pointed arch's half cut on the radial line through the axis' crown point: the beam's own crown
    section, not the crown's vertical line (where the two legs meet in one wedge of material)."""

    def face(self, side, xi):
        r = self.R + side * self.t / 2
        end = math.acos((SPAN / 2 - self.cx) / self.R)  # the same angle for every radius
        phi = math.pi + xi * (end - math.pi)
        return (self.cx + r * math.cos(phi), r * math.sin(phi))


def crown_input(arch, n_across, supports):
    """The radial crown face held as the beam's crown: every node's ux zero (the crown's set) and its uy
    the axis node's (a face that slides vertically without turning or changing its shape)."""
    text, _ = ccx_input(arch, n_across, False, supports)
    crown = mesh(arch, n_across)[3]
    master = crown[len(crown) // 2]
    lines = ["*EQUATION"]
    for k in crown:
        if k != master:
            lines += ["2", f"{k}, 2, 1., {master}, 2, -1."]
    return text.replace("*STEP", "\n".join(lines) + "\n*STEP", 1)


def run_input(text):
    """Runs ccx on an input deck; the .dat file's text."""
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "arch.inp"), "w") as f:
            f.write(text)
        run = subprocess.run(["ccx", "-i", "arch"], cwd=work, capture_output=True, text=True,
                             env=dict(os.environ, OMP_NUM_THREADS="1"))
        path = os.path.join(work, "arch.dat")
        if run.returncode != 0 or not os.path.exists(path):
            raise RuntimeError(f"ccx failed ({run.returncode}): {run.stdout[-2000:]}")
        return open(path).read()


def crown(ogive):
    """crown.csv: the equilateral arch's continuum with its pointed crown (the table's) beside the same half
    arch ending on the radial line through the axis' crown point, held there as the beam's crown is; the
    curved bar without a crown term (beam.py: the legs meeting at a point, as the radial crown) and ogive's
    (its kink): how much of the bar's error is the pointed crown, and what the kink takes of it."""
    import beam
    with open(CROWN, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["supports", "t_over_L", "pointed", "radial_crown", "fe_error", "bar_without_kink", "curved",
                    "without_kink_error_radial_crown", "without_kink_error_pointed", "curved_error_pointed"])
        ref = {(r["supports"], r["t_over_L"]): float(r["H_over_V"]) for r in csv.DictReader(open(REFERENCE))
               if r["arch"] == "equilateral" and r["plane"] == "stress"}
        for supports in ("clamped", "pinned"):
            for ratio in (0.1, 0.15, 0.2, 0.25):
                arch = RadialCrown(0.5, ratio * SPAN)
                values = []
                for n in (4, 8, 16):
                    dat = run_input(crown_input(arch, n, supports))
                    m = re.search(r"total force \(fx,fy,fz\).*?\n\s*\n?\s*([-+0-9.Ee]+)", dat, re.S)
                    values.append(round(float(m.group(1)) / section_thickness(arch) / (RHO * G_ACC * area(arch)), 7))
                hv, err, _ = extrapolate(values)
                bar = beam.h_over_v("equilateral", ratio, supports)
                curved = ogive_hv(ogive, make_arch("equilateral", ratio * SPAN), ratio, "curved", False, supports)[0]
                pointed = ref[(supports, repr(ratio))]
                w.writerow([supports, repr(ratio), f"{pointed:.7f}", f"{hv:.7f}", f"{err:.1e}", f"{bar:.7f}",
                            f"{curved:.7f}", f"{(bar - hv) / hv:.3e}", f"{(bar - pointed) / pointed:.3e}",
                            f"{(curved - pointed) / pointed:.3e}"])
                f.flush()
    print(open(CROWN).read(), end="")


class Strip:
    """A straight strip of depth t and length ell: x along it, y across."""

    def __init__(self, t, ell):
        self.t, self.ell = t, ell

    def face(self, side, xi):
        return (xi * self.ell, side * self.t / 2)

    def axis_length(self):
        return self.ell


def tip_weights(nodes, tip, t):
    """The consistent nodal forces on a strip's far face (3-node edges, 6-point Gauss) of Saint-Venant's
    tractions per unit resultant: uniform N, parabolic V and linear M; their work with a displacement
    field is the face's displacement conjugate to each."""
    ys = [nodes[n - 1][1] for n in tip]
    tractions = {"N": lambda y: (1 / t, 0.0), "V": lambda y: (0.0, 1.5 / t * (1 - 4 * y * y / (t * t))),
                 "M": lambda y: (-12 * y / t ** 3, 0.0)}
    gauss = [(-0.9324695142, 0.1713244924), (-0.6612093865, 0.3607615730), (-0.2386191861, 0.4679139346),
             (0.2386191861, 0.4679139346), (0.6612093865, 0.3607615730), (0.9324695142, 0.1713244924)]
    forces = {}
    for name, trac in tractions.items():
        f = [[0.0, 0.0] for _ in tip]
        for e in range(0, len(tip) - 1, 2):  # the far face's 3-node edges
            h = ys[e + 2] - ys[e]
            for xi, wt in gauss:
                shape = [xi * (xi - 1) / 2, 1 - xi * xi, xi * (xi + 1) / 2]
                p = trac(ys[e] + (xi + 1) / 2 * h)
                for a in range(3):
                    for d in range(2):
                        f[e + a][d] += p[d] * shape[a] * wt * h / 2
        forces[name] = f
    return forces


def strip_run(ell, nu, n_across):
    """The strip t = 1, E = 1 held whole at x = 0, its far face loaded by Saint-Venant's tractions (the
    consistent nodal forces of a uniform N and of a parabolic shear V): the far face's displacements
    conjugate to N, V and M (the tractions' work per unit load) under each load. nu is the section's
    (plane stress'): from 0.5 (CalculiX's plane stress takes nu < 0.5) the strip is in plane strain (CPE8)
    with nu / (1 + nu) and E = 1 - that^2,
    the same body (its E / (1 - nu^2) is 1, its nu / (1 - nu) the nu asked)."""
    element, modulus = "CPS8", 1.0
    if nu >= 0.5:
        nu = nu / (1 + nu)
        element, modulus = "CPE8", 1 - nu * nu
    t = 1.0
    arch = Strip(t, ell)
    nodes, elements, held, tip = mesh(arch, n_across)
    th = section_thickness(arch)
    lines = ["*HEADING", "held strip", "*NODE"] + [f"{k + 1}, {x:.13f}, {y:.13f}, 0" for k, (x, y) in enumerate(nodes)]
    lines += [f"*ELEMENT, TYPE={element}, ELSET=EALL"] + [f"{k + 1}, " + ", ".join(map(str, e)) for k, e in enumerate(elements)]
    lines += ["*NSET, NSET=NHELD"] + [str(n) for n in held] + ["*NSET, NSET=NTIP"] + [str(n) for n in tip]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", f"{modulus!r}, {nu!r}", "*SOLID SECTION, ELSET=EALL, MATERIAL=M", f"{th!r}",
              "*BOUNDARY", "NHELD, 1, 2, 0."]
    forces = tip_weights(nodes, tip, t)
    for name in ("N", "V"):  # the moment follows from V at two lengths (strip_compliance)
        lines += ["*STEP", "*STATIC", "*CLOAD, OP=NEW"]
        lines += [f"{n}, {d + 1}, {forces[name][k][d] * th:.12g}" for k, n in enumerate(tip) for d in range(2)
                  if abs(forces[name][k][d]) > 1e-14]
        lines += ["*NODE PRINT, NSET=NTIP", "U", "*END STEP"]
    dat = run_input("\n".join(lines) + "\n")
    out = {}
    for name, block in zip(("N", "V"), re.split(r"displacements \(vx,vy,vz\)", dat)[1:]):
        u = {int(m.group(1)): (float(m.group(2)), float(m.group(3)))
             for m in re.finditer(r"^\s*(\d+)\s+([-+0-9.Ee]+)\s+([-+0-9.Ee]+)\s+[-+0-9.Ee]+\s*$", block, re.M)}
        out[name] = {c: sum(forces[c][k][d] * u[n][d] for k, n in enumerate(tip) for d in range(2)) for c in "NVM"}
    return out


def strip_compliance(nu, n_across):
    """The held face's compliance beyond Timoshenko's clamped beam (k = 5/6), per unit width: the far face
    moves by dC (N, V, M) more than the beam's, dC = [[cNN / E, 0, 0], [0, cVV / E, cVM / (E t)],
    [0, cVM / (E t), cMM / (E t^2)]] at the held face's resultants. From two lengths (4 t and 8 t: the
    zone's terms do not depend on the length, the beam's are known)."""
    G, k = 1 / (2 * (1 + nu)), 5 / 6
    r = {ell: strip_run(ell, nu, n_across) for ell in (4.0, 8.0)}
    # Under V the far face turns by ell^2 / 2EI + cVM + ell cMM and moves by ell^3 / 3EI + ell / kGA +
    # cVV + 2 ell cVM + ell^2 cMM (E = t = 1, I = 1/12).
    turn = {ell: r[ell]["V"]["M"] - 6 * ell ** 2 for ell in r}
    cMM = (turn[8.0] - turn[4.0]) / 4
    cVM = turn[4.0] - 4 * cMM
    cVV = r[4.0]["V"]["V"] - 4 * 4.0 ** 3 - 4.0 / (k * G) - 8 * cVM - 16 * cMM
    cNN = r[4.0]["N"]["N"] - 4.0
    return cNN, cVV, cVM, cMM


def strip(ogive):
    """strip.csv: the held face's compliance (strip_compliance) at nu 0 and 0.2, meshes of 8, 16 and 32
    elements through the depth (the held face's corners are singular: it converges slowly); held.csv: at
    32 elements over the section's nu from -0.9 to 0.97 (plane strain's nu / (1 - nu) above 0.5), the table
    that ogive's curved bar interpolates (src/model/curved_section.cpp, kHeldFace)."""
    with open(STRIP, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["nu", "elements_across", "c_NN", "c_VV", "c_VM", "c_MM"])
        for nu in (0.0, NU):
            for n in (8, 16, 32):
                w.writerow([repr(nu), n] + [f"{c:.5f}" for c in strip_compliance(nu, n)])
                f.flush()
    print(open(STRIP).read(), end="")
    with open(HELD, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["nu", "c_NN", "c_VV", "c_VM", "c_MM"])
        for nu in HELD_NU:
            w.writerow([repr(nu)] + [f"{c:.5f}" for c in strip_compliance(nu, 32)])
            f.flush()
    print(open(HELD).read(), end="")


class CrownSegment(Pointed):
    """The pointed arch's crown part, from the axis angle phi0 to the crown: ending on the crown's vertical
    line (the two legs' wedge, `radial` False) or on the radial line through the axis' crown point."""

    def __init__(self, eps, t, phi0, radial):
        super().__init__(eps, t)
        self.phi0, self.radial = phi0, radial

    def face(self, side, xi):
        r = self.R + side * self.t / 2
        end = math.acos((SPAN / 2 - self.cx) / (self.R if self.radial else r))
        phi = self.phi0 + xi * (end - self.phi0)
        return (self.cx + r * math.cos(phi), r * math.sin(phi))

    def axis_length(self):
        return self.R * abs(math.acos((SPAN / 2 - self.cx) / self.R) - self.phi0)


def segment_stiffness(seg, n_across):
    """The crown segment without weight, its crown held as in the table (the vertical line's ux = 0) or as
    the beam's crown (crown_input's radial face), its lower face a rigid line: the 2 x 2 stiffness from the
    lower face's (ux, rotation about its axis node; uy = 0) to the face's force Fx and moment on the
    segment, per metre of width. Translation: every face node moved alike; rotation: the face a rigid line
    about its held axis node (as the pinned springing), turned by a force on its extrados node, Fx from
    the crown's reaction."""
    nodes, elements, low, crown_nodes = mesh(seg, n_across)
    th = section_thickness(seg)
    base = ["*HEADING", "crown segment", "*NODE"] + [f"{k + 1}, {x:.13f}, {y:.13f}, 0" for k, (x, y) in enumerate(nodes)]
    base += ["*ELEMENT, TYPE=CPS8, ELSET=EALL"] + [f"{k + 1}, " + ", ".join(map(str, e)) for k, e in enumerate(elements)]
    base += ["*NSET, NSET=NLOW"] + [str(k) for k in low] + ["*NSET, NSET=NCROWN"] + [str(k) for k in crown_nodes]
    base += ["*MATERIAL, NAME=STONE", "*ELASTIC", f"{E:.15g}, {NU:.15g}", "*SOLID SECTION, ELSET=EALL, MATERIAL=STONE",
             f"{th:.15g}", "*BOUNDARY", "NCROWN, 1, 1, 0."]
    if seg.radial:
        master = crown_nodes[len(crown_nodes) // 2]
        base += ["*EQUATION"] + [x for k in crown_nodes if k != master for x in ("2", f"{k}, 2, 1., {master}, 2, -1.")]
    ref, e_node = low[len(low) // 2], low[-1]
    (x0, y0), (xe, ye) = nodes[ref - 1], nodes[e_node - 1]
    number = r"^\s*(\d+)\s+([-+0-9.Ee]+)\s+([-+0-9.Ee]+)\s+[-+0-9.Ee]+\s*$"
    K = [[0.0, 0.0], [0.0, 0.0]]
    move = 1e-4
    dat = run_input("\n".join(base + ["*BOUNDARY", f"NLOW, 1, 1, {move!r}", "NLOW, 2, 2, 0.", "*STEP", "*STATIC",
                                      "*NODE PRINT, NSET=NLOW", "RF", "*END STEP"]) + "\n")
    rf = {int(m.group(1)): (float(m.group(2)), float(m.group(3))) for m in re.finditer(number, dat, re.M)}
    K[0][0] = sum(rf[k][0] for k in low) / th / move
    K[1][0] = sum((nodes[k - 1][0] - x0) * rf[k][1] - (nodes[k - 1][1] - y0) * rf[k][0] for k in low) / th / move
    re_ = math.hypot(xe - x0, ye - y0)
    d = ((xe - x0) / re_, (ye - y0) / re_)
    normal = (-d[1], d[0])
    lines = base + ["*BOUNDARY", f"{ref}, 1, 2, 0.", "*EQUATION", "2", f"{e_node}, 1, {d[0]:.15g}, {e_node}, 2, {d[1]:.15g}"]
    for k in low:
        if k not in (ref, e_node):
            r = ((nodes[k - 1][0] - x0) * d[0] + (nodes[k - 1][1] - y0) * d[1]) / re_
            lines += [x for dof in (1, 2) for x in ("2", f"{k}, {dof}, 1., {e_node}, {dof}, {-r:.15g}")]
    force = 1e3 * th
    lines += ["*STEP", "*STATIC", "*CLOAD", f"{e_node}, 1, {force * normal[0]:.15g}", f"{e_node}, 2, {force * normal[1]:.15g}",
              "*NODE PRINT, NSET=NLOW", "U", "*NODE PRINT, NSET=NCROWN, TOTALS=ONLY", "RF", "*END STEP"]
    dat = run_input("\n".join(lines) + "\n")
    moved, totals = re.split(r"total force \(fx,fy,fz\)", dat)[:2]
    u = {int(m.group(1)): (float(m.group(2)), float(m.group(3))) for m in re.finditer(number, moved, re.M)}
    turn = (u[e_node][0] * normal[0] + u[e_node][1] * normal[1]) / re_
    crown_fx = float(re.search(r"\n\s*([-+]?[0-9.]+E[-+][0-9]+)\s+", totals).group(1))
    K[0][1] = -crown_fx / th / turn
    K[1][1] = force * re_ / th / turn
    return K


def joint(ogive):
    """joint.csv: the equilateral arch's pointed crown as a joint between the two legs, from the local
    problem alone: the crown's last 4 t of the half arch (CrownSegment) with the pointed crown and with the
    beam's radial one; the difference of their compliances is the joint's (in series), which beam.py turns
    into the crown conditions' (a, b, c): psi + a M + b Fx = 0, Ux + b M + c Fx = 0 (scaled), printed per
    E and t as a t/12, b t^2/12, c t^3/12. Each extrapolated from 4, 8 and 16 elements through the depth."""
    import beam
    with open(JOINT, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["t_over_L", "a", "b", "c", "a_meshes", "b_meshes", "c_meshes"])
        for ratio in RATIOS:
            t = ratio * SPAN
            phi_c = math.acos(-0.5)
            phi0 = phi_c + 4 * t / SPAN  # R = L
            EI = E * t ** 3 / 12
            scale = [[EI / SPAN ** 3, EI / SPAN ** 2], [EI / SPAN ** 2, EI / SPAN]]
            found = []
            for n in (4, 8, 16):
                comp = []
                for radial in (False, True):
                    K = segment_stiffness(CrownSegment(0.5, t, phi0, radial), n)
                    det = K[0][0] * K[1][1] - K[0][1] * K[1][0]
                    comp.append([[K[1][1] / det, -K[0][1] / det], [-K[1][0] / det, K[0][0] / det]])
                dC = [[(comp[0][i][j] - comp[1][i][j]) * scale[i][j] for j in range(2)] for i in range(2)]
                a, b, c = beam.joint_from("equilateral", ratio, 4 * t / SPAN, dC)
                found.append((a * 12 / ratio, b * 12 / ratio ** 2, c * 12 / ratio ** 3))
            best = [extrapolate([round(v[k], 7) for v in found])[0] for k in range(3)]
            w.writerow([repr(ratio)] + [f"{v:.5f}" for v in best] +
                       [" ".join(f"{v[k]:.5f}" for v in found) for k in range(3)])
            f.flush()
    print(open(JOINT).read(), end="")


def crown_rotation(eps, ratio, nu, n_across):
    """The rotation per moment of the crown's last 4 t of the pointed arch eps (no weight, no thrust) with
    its pointed crown less that with the beam's radial crown, per E and t (a of `joint`: the joint's
    rotation compliance is in series with the legs, and with no thrust it is this difference alone)."""
    global NU
    saved, NU = NU, nu
    try:
        t = ratio * SPAN
        R = (0.5 + eps) * SPAN
        phi0 = math.acos(-eps / (0.5 + eps)) + 4 * t / R
        comp = []
        for radial in (False, True):
            K = segment_stiffness(CrownSegment(eps, t, phi0, radial), n_across)
            comp.append(K[0][0] / (K[0][0] * K[1][1] - K[0][1] * K[1][0]))
        return (comp[0] - comp[1]) * E * t * t
    finally:
        NU = saved


def wedge():
    """wedge.csv: a pointed crown's wedge, the joint's rotation compliance a (per E and t^2 of the crown's
    moment) over the crown tangent's angle theta_c, on pointed arches at t/L 0.02, at nu 0 and 0.2, each
    extrapolated from 4, 8 and 16 elements through the depth. The beam's radial crown, a rigid line, stops
    the section's lateral (Poisson) strain that the continuum's crown (a plane of symmetry) lets free: at nu
    0.2 that adds the same 0.030 at every angle (the value as theta_c -> 0, where the two crowns are one);
    the wedge is the nu = 0 column (ogive's crown_wedge), which the nu 0.2 column less that restraint
    repeats within 3e-3."""
    with open(WEDGE, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["theta_c_deg", "eccentricity", "a_nu_0", "a_nu_0.2", "meshes_nu_0", "meshes_nu_0.2"])
        for deg in WEDGE_ANGLES:
            s = math.sin(math.radians(deg))
            eps = 0.5 * s / (1 - s)
            cols, meshes = [], []
            for nu in (0.0, 0.2):
                found = [round(crown_rotation(eps, 0.02, nu, n), 7) for n in (4, 8, 16)]
                cols.append(extrapolate(found)[0])
                meshes.append(" ".join(f"{v:.5f}" for v in found))
            w.writerow([deg, f"{eps:.6f}"] + [f"{v:.5f}" for v in cols] + meshes)
            f.flush()
    print(open(WEDGE).read(), end="")


def trial(ogive):
    """trial.csv: beam.py's curved bar beside the continuum on every plane-stress row of the table, without
    a crown term (none: the section law alone); with the crown joint of joint.csv on the equilateral arch (joint), and with the held
    springing face of strip.csv (the finest mesh, nu 0.2) on the clamped arches and the self-weight's own
    stress across the depth as well (joint_held_weight); the same with the crown joint that the curved
    bar's own coupling gives the kink and the pointed crown's wedge (wedge.csv) instead (kink,
    beam.kink_joint; kink_held, kink_weight and kink_held_weight with one or both of the other terms;
    bare_kink_held_weight the same without the wedge); kink_curved_held and kink_curved_held_weight with the
    held face of a curved bar (ring.csv, beam.held_curved) instead of the straight strip's: the latter is
    ogive's `curved`. The summary as
    the table's, each variant's rows beyond half of Timoshenko's error with the continuum's fe_error."""
    import beam
    joints = {r["t_over_L"]: (float(r["a"]), float(r["b"]), float(r["c"])) for r in csv.DictReader(open(JOINT))}
    held = [r for r in csv.DictReader(open(STRIP)) if r["nu"] == repr(NU)][-1]
    held = tuple(float(held[k]) for k in ("c_NN", "c_VV", "c_VM", "c_MM"))
    rows = [r for r in csv.DictReader(open(TABLE)) if r["plane"] == "stress"]
    out = []
    names = ["none", "joint", "joint_held_weight", "kink", "kink_held", "kink_weight", "kink_held_weight",
             "bare_kink_held_weight", "kink_curved_held", "kink_curved_held_weight"]
    with open(TRIAL, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["arch", "supports", "t_over_L", "continuum", "timoshenko_error", "curved_error"] +
                   [f"{n}_error" for n in names])
        for r in rows:
            ratio, ref = float(r["t_over_L"]), float(r["continuum"])
            pointed = r["arch"] == "equilateral"
            J = joints[r["t_over_L"]] if pointed else (0.0, 0.0, 0.0)
            J = (J[0] * ratio / 12, J[1] * ratio ** 2 / 12, J[2] * ratio ** 3 / 12)
            kink = beam.kink_joint(beam.Arch(r["arch"]), ratio) if pointed else (0.0, 0.0, 0.0)
            bare = beam.kink_joint(beam.Arch(r["arch"]), ratio, wedge=False) if pointed else (0.0, 0.0, 0.0)
            hv = lambda **kw: beam.h_over_v(r["arch"], ratio, r["supports"], **kw)
            got = [hv(), hv(joint=J), hv(joint=J, held=held, weight=True), hv(joint=kink), hv(joint=kink, held=held),
                   hv(joint=kink, weight=True), hv(joint=kink, held=held, weight=True), hv(joint=bare, held=held, weight=True),
                   hv(joint=kink, held="curved"), hv(joint=kink, held="curved", weight=True)]
            errors = [(g - ref) / max(abs(ref), 0.01) for g in got]
            out.append((r, errors))
            w.writerow([r["arch"], r["supports"], r["t_over_L"], r["continuum"], r["timoshenko_error"], r["curved_error"]] +
                       [f"{e:.3e}" for e in errors])
    for k, name in enumerate(names):
        half = sum(1 for r, e in out if abs(e[k]) <= 0.5 * abs(float(r["timoshenko_error"])))
        near = [(r, e) for r, e in out if float(r["t_over_L"]) <= 0.2]
        ok = sum(1 for r, e in near if abs(e[k]) <= 0.005)
        print(f"{name}: error <= half of timoshenko's on {half} of {len(out)} rows, within 0.5 % up to t/L 0.2 on "
              f"{ok} of {len(near)}, largest {max(abs(e[k]) for r, e in out):.2e}")
        for r, e in out:
            if abs(e[k]) > 0.5 * abs(float(r["timoshenko_error"])) and k > 0:
                print(f"  not: {r['arch']} {r['supports']} t/L {r['t_over_L']}: {e[k]:+.2e}, timoshenko "
                      f"{float(r['timoshenko_error']):+.2e}, fe_error {float(r['fe_error']) / float(r['continuum']):.1e}")


def held_body_run(ell, nu, n_across):
    """The strip t = 1, E = 1, held whole at x = 0, under a body force 1 across it (-y) and then along it
    (-x, towards the held face): the far face's displacements conjugate to N, V and M (tip_weights), less
    the beam's: Timoshenko's clamped beam (k = 5/6) with the held face's compliance (held.csv at this nu)
    and the straight bar's own stress under the load across, a curvature -nu/5 b / E (the curved bar's
    weight term's limit). Across, the far face carries the exact solution's self-equilibrated stress
    sigma_x = b (3 y / 5 - 4 y^3 / t^2) (the strip is then the polynomial solution but at the held face)."""
    t, b = 1.0, 1.0
    nodes, elements, held, tip = mesh(Strip(t, ell), n_across)
    th = section_thickness(Strip(t, ell))
    lines = ["*HEADING", "held strip, body force", "*NODE"]
    lines += [f"{k + 1}, {x:.13f}, {y:.13f}, 0" for k, (x, y) in enumerate(nodes)]
    lines += ["*ELEMENT, TYPE=CPS8, ELSET=EALL"] + [f"{k + 1}, " + ", ".join(map(str, e)) for k, e in enumerate(elements)]
    lines += ["*NSET, NSET=NHELD"] + [str(n) for n in held] + ["*NSET, NSET=NTIP"] + [str(n) for n in tip]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", f"1.0, {nu!r}", "*DENSITY", "1.0", "*SOLID SECTION, ELSET=EALL, MATERIAL=M",
              f"{th!r}", "*BOUNDARY", "NHELD, 1, 2, 0."]
    forces = tip_weights(nodes, tip, t)
    # sigma_c = b (3 y / 5 - 4 y^3 / t^2) = b t^2 / 20 (12 y / t^3 - 80 y^3 / t^5): the M pattern's and a cubic's forces
    ys = [nodes[n - 1][1] for n in tip]
    cubic = [0.0 for _ in tip]
    gauss = [(-0.9324695142, 0.1713244924), (-0.6612093865, 0.3607615730), (-0.2386191861, 0.4679139346),
             (0.2386191861, 0.4679139346), (0.6612093865, 0.3607615730), (0.9324695142, 0.1713244924)]
    for e in range(0, len(tip) - 1, 2):
        h = ys[e + 2] - ys[e]
        for xi, wt in gauss:
            y = ys[e] + (xi + 1) / 2 * h
            for a, shape in enumerate((xi * (xi - 1) / 2, 1 - xi * xi, xi * (xi + 1) / 2)):
                cubic[e + a] += b * (0.6 * y - 4 * y ** 3 / t ** 2) * shape * wt * h / 2
    lines += ["*STEP", "*STATIC", "*DLOAD", "EALL, GRAV, 1., 0., -1., 0.", "*CLOAD"]
    lines += [f"{n}, 1, {cubic[k] * th:.12g}" for k, n in enumerate(tip) if abs(cubic[k]) > 1e-14]
    lines += ["*NODE PRINT, NSET=NTIP", "U", "*END STEP"]
    lines += ["*STEP", "*STATIC", "*DLOAD, OP=NEW", "EALL, GRAV, 1., -1., 0., 0.", "*CLOAD, OP=NEW"]
    lines += ["*NODE PRINT, NSET=NTIP", "U", "*END STEP"]
    dat = run_input("\n".join(lines) + "\n")
    got = []
    for block in re.split(r"displacements \(vx,vy,vz\)", dat)[1:]:
        u = {int(m.group(1)): (float(m.group(2)), float(m.group(3)))
             for m in re.finditer(r"^\s*(\d+)\s+([-+0-9.Ee]+)\s+([-+0-9.Ee]+)\s+[-+0-9.Ee]+\s*$", block, re.M)}
        got.append({c: sum(forces[c][k][d] * u[n][d] for k, n in enumerate(tip) for d in range(2)) for c in "NVM"})
    row = [r for r in csv.DictReader(open(HELD)) if float(r["nu"]) == nu][0]
    cNN, cVV, cVM, cMM = (float(row[k]) for k in ("c_NN", "c_VV", "c_VM", "c_MM"))
    kGA, q, kappa = 5 / 6 / (2 * (1 + nu)), b * t, -nu / 5 * b
    # by reciprocity: the work of the load on the beam's displacements under a unit far-face V or M
    # (u_y = Uy0 + psi0 x + 12 (ell x^2 / 2 - x^3 / 6) + x / kGA, Uy0 = cVV + ell cVM, psi0 = cVM + ell cMM;
    # under M: u_y = cVM + cMM x + 6 x^2), and the own-stress curvature's work on their moments (ell - x, 1)
    beam_V = -q * ((cVV + ell * cVM) * ell + (cVM + ell * cMM) * ell ** 2 / 2 + 1.5 * ell ** 4 + ell ** 2 / 2 / kGA)
    beam_V += kappa * ell ** 2 / 2
    beam_M = -q * (cVM * ell + cMM * ell ** 2 / 2 + 2 * ell ** 3) + kappa * ell
    beam_N = -q * (ell ** 2 / 2 + cNN * ell)
    return got[0]["V"] - beam_V, got[0]["M"] - beam_M, got[1]["N"] - beam_N


def held_body(nu=NU, n_across=32):
    """The held face's own displacement under a body force beyond the beam's (held_body_run): (u_N, Uy, psi)
    per b t^2 / E, b t^2 / E and b t / E, the load along the axis for u_N and across for Uy and psi; from
    the strips 4 t and 8 t long (psi the rotation's mean, Uy = dV - psi ell; they must not depend on ell)."""
    runs = {ell: held_body_run(ell, nu, n_across) for ell in (4.0, 8.0)}
    psi = (runs[4.0][1] + runs[8.0][1]) / 2
    return runs[8.0][2], runs[8.0][0] - 8.0 * psi, psi, runs


RING_TK = (0.2, 0.3, 0.4, 0.5, 0.6)


def ring_compliance(nu, t_kappa, n_across=32):
    """A curved bar's held face: the semicircle's half (R = L/2, t/L = t_kappa / 2, no weight), its
    springing face held whole, its crown face loaded by the thick circular bar's own section stresses
    (beam.section_stresses: Golovin's, so that the bar is plane elasticity's exact solution but for the
    held face's zone) of a unit N, V and M in turn. The crown's displacements conjugate to them, less the
    curved bar's (its section law integrated over the quarter turn), are the held face's compliance seen
    through the bar: its (c_NN, c_VV, c_VM, c_MM) as strip_compliance's and c_NM, the turn under N (and the
    stretch under M: Maxwell), per E t (the straight strip's is zero: its symmetry), in the springing's
    frame (the axis leaving it) with N, V and M the bar's forces on the face. nu is the section's (from
    0.5 in plane strain, as strip_run). CalculiX's *CLOAD values are scaled to 1 at their largest (small
    ones came out wrong in 2.21)."""
    import beam
    ratio = t_kappa / 2
    arch = make_arch("semicircular", ratio * SPAN)
    nodes, elements, springing, crown = mesh(arch, n_across)
    t, R = arch.t, SPAN / 2
    E = 12 / t ** 3  # E I = 1 per unit width
    section_nu, element, modulus = nu, "CPS8", E
    if nu >= 0.5:
        nu = nu / (1 + nu)
        element, modulus = "CPE8", E * (1 - nu * nu)
    th = section_thickness(arch)
    sN, sM, tV = beam.section_stresses(t / (2 * R))
    # the crown face x = L/2 from the intrados up, r = y / R; N along +x, V along +y, M anticlockwise
    patterns = [lambda y: (sN(y / R) / R, 0.0), lambda y: (0.0, tV(y / R) / R), lambda y: (-sM(y / R) / R ** 2, 0.0)]
    ys = [nodes[n - 1][1] for n in crown]
    gauss = [(-0.9324695142, 0.1713244924), (-0.6612093865, 0.3607615730), (-0.2386191861, 0.4679139346),
             (0.2386191861, 0.4679139346), (0.6612093865, 0.3607615730), (0.9324695142, 0.1713244924)]
    forces = []
    for trac in patterns:
        f = [[0.0, 0.0] for _ in crown]
        for e in range(0, len(crown) - 1, 2):
            h = ys[e + 2] - ys[e]
            for xi, wt in gauss:
                p = trac(ys[e] + (xi + 1) / 2 * h)
                for a, shape in enumerate((xi * (xi - 1) / 2, 1 - xi * xi, xi * (xi + 1) / 2)):
                    for d in range(2):
                        f[e + a][d] += p[d] * shape * wt * h / 2
        forces.append(f)
    lines = ["*HEADING", "held curved bar", "*NODE"] + [f"{k + 1}, {x:.13f}, {y:.13f}, 0" for k, (x, y) in enumerate(nodes)]
    lines += [f"*ELEMENT, TYPE={element}, ELSET=EALL"] + [f"{k + 1}, " + ", ".join(map(str, e)) for k, e in enumerate(elements)]
    lines += ["*NSET, NSET=NSPRING"] + [str(n) for n in springing] + ["*NSET, NSET=NCROWN"] + [str(n) for n in crown]
    lines += ["*MATERIAL, NAME=M", "*ELASTIC", f"{modulus!r}, {nu!r}", f"*SOLID SECTION, ELSET=EALL, MATERIAL=M", f"{th!r}",
              "*BOUNDARY", "NSPRING, 1, 2, 0."]
    scale = [1 / (th * max(abs(v) for row in f for v in row)) for f in forces]  # per unit width: times th
    for f, sc in zip(forces, scale):
        lines += ["*STEP", "*STATIC", "*CLOAD, OP=NEW"]
        lines += [f"{n}, {d + 1}, {f[k][d] * th * sc:.15g}" for k, n in enumerate(crown) for d in range(2) if f[k][d]]
        lines += ["*NODE PRINT, NSET=NCROWN", "U", "*END STEP"]
    dat = run_input("\n".join(lines) + "\n")
    measured = [[0.0] * 3 for _ in range(3)]
    for j, block in enumerate(re.split(r"displacements \(vx,vy,vz\)", dat)[1:]):
        u = {int(m.group(1)): (float(m.group(2)), float(m.group(3)))
             for m in re.finditer(r"^\s*(\d+)\s+([-+0-9.Ee]+)\s+([-+0-9.Ee]+)\s+[-+0-9.Ee]+\s*$", block, re.M)}
        for i in range(3):
            # per unit load (the loads were scale times) and in the span's units (L = 1, E I = 1)
            work = sum(forces[i][k][d] * u[n][d] for k, n in enumerate(crown) for d in range(2)) / scale[j]
            measured[i][j] = work / SPAN ** (3 - (i == 2) - (j == 2))
    # the curved bar (beam.py's section law, L = 1): the crown's loads (Px, Py, Mc) at (1/2, 1/2) give the
    # section at s, (x, y) on the quarter circle about (1/2, 0), N, V, M = G (Px, Py, Mc)
    axial, coupling, bending, shear = beam.section(ratio, section_nu)
    aN = ratio ** 2 / 12
    aV, coup = aN * 2 * (1 + section_nu) / (5 / 6), -2 * aN * coupling
    S = math.pi / 4
    bar = [[0.0] * 3 for _ in range(3)]
    for x, w in zip(*gauss_legendre(200)):
        s = S / 2 * (1 + x)
        theta = math.pi / 2 - 2 * s
        c, sn = math.cos(theta), math.sin(theta)
        px, py = 0.5 - 0.5 * math.cos(2 * s), 0.5 * math.sin(2 * s)
        G = [[c, sn, 0.0], [-sn, c, 0.0], [-(0.5 - py), 0.5 - px, 1.0]]
        Cs = [[aN * axial, 0.0, coup], [0.0, aV * shear, 0.0], [coup, 0.0, bending]]
        for i in range(3):
            for j in range(3):
                bar[i][j] += S / 2 * w * sum(G[a][i] * Cs[a][b] * G[b][j] for a in range(3) for b in range(3))
    # measured - bar = B' H B, B the crown's loads to the springing's (Fx, Fy, M) = (Px, Py, Mc - Px / 2 + Py / 2),
    # H the springing's compliance in the global frame; its frame (the axis leaving it, straight up) is
    # T H T' with T = [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]
    import numpy as np
    B = np.array([[1.0, 0, 0], [0, 1.0, 0], [-0.5, 0.5, 1.0]])
    Bi = np.linalg.inv(B)
    H = Bi.T @ (np.array(measured) - np.array(bar)) @ Bi
    T = np.array([[0, 1.0, 0], [-1.0, 0, 0], [0, 0, 1.0]])
    local = T @ H @ T.T
    tt = ratio
    return (12 * local[0, 0] / tt ** 3, 12 * local[1, 1] / tt ** 3, 6 * (local[1, 2] + local[2, 1]) / tt ** 2,
            12 * local[2, 2] / tt, 6 * (local[0, 2] + local[2, 0]) / tt ** 2)


def gauss_legendre(n):
    import numpy as np
    return np.polynomial.legendre.leggauss(n)


def ring():
    """ring.csv: the held face of a curved bar (ring_compliance) over the section's nu (HELD_NU) and t kappa
    (t / R at the face: 0.2 to 0.6), 32 elements through the depth; what ogive's curved bar adds to the
    straight strip's (held.csv) at its clamped springings (src/model/curved_section.cpp, kHeldCurved)."""
    with open(RING, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["nu", "t_kappa", "c_NN", "c_VV", "c_VM", "c_MM", "c_NM"])
        for nu in HELD_NU:
            for tk in RING_TK:
                w.writerow([repr(nu), repr(tk)] + [f"{c:.5f}" for c in ring_compliance(nu, tk)])
                f.flush()
    print(open(RING).read(), end="")


COMPONENTS_CASES = [(0.15, 0.2), (0.2, 0.2), (0.15, 0.0), (0.2, 0.0)]
SHAPE_CORNERS, SHAPE_MIDS = [(-1, -1), (1, -1), (1, 1), (-1, 1)], [(0, -1), (1, 0), (0, 1), (-1, 0)]


def weight_part_loads(nodes, elements, part):
    """Consistent nodal forces (per rho g and unit out-of-plane thickness; CPS8's serendipity shape
    functions, 3 x 3 Gauss points) of the weight's part along the section's normal ((g . n) n, n the unit
    d x / d eta at the point: the mesh's lines across are the beam's sections) or the rest (tangential)."""
    forces = [[0.0, 0.0] for _ in nodes]
    g3 = [(-math.sqrt(0.6), 5 / 9), (0.0, 8 / 9), (math.sqrt(0.6), 5 / 9)]
    for e in elements:
        X = [nodes[k - 1] for k in e]
        for x, wx in g3:
            for y, wy in g3:
                N, dx, de = [], [], []
                for a, b in SHAPE_CORNERS:
                    N.append((1 + a * x) * (1 + b * y) * (a * x + b * y - 1) / 4)
                    dx.append(a * (1 + b * y) * (2 * a * x + b * y) / 4)
                    de.append(b * (1 + a * x) * (a * x + 2 * b * y) / 4)
                for a, b in SHAPE_MIDS:
                    if a == 0:
                        N.append((1 - x * x) * (1 + b * y) / 2), dx.append(-x * (1 + b * y)), de.append(b * (1 - x * x) / 2)
                    else:
                        N.append((1 + a * x) * (1 - y * y) / 2), dx.append(a * (1 - y * y) / 2), de.append(-y * (1 + a * x))
                jx = [sum(d * P[i] for d, P in zip(dx, X)) for i in (0, 1)]
                je = [sum(d * P[i] for d, P in zip(de, X)) for i in (0, 1)]
                det = abs(jx[0] * je[1] - jx[1] * je[0])
                h = math.hypot(*je)
                n = (je[0] / h, je[1] / h)
                b = (-n[1] * n[0], -n[1] * n[1])  # (g . n) n with g = (0, -1)
                if part == "tangential":
                    b = (-b[0], -1 - b[1])
                for i, k in enumerate(e):
                    forces[k - 1][0] += wx * wy * det * N[i] * b[0]
                    forces[k - 1][1] += wx * wy * det * N[i] * b[1]
    return forces


def weight_parts(arch, n_across, supports, nu):
    """The springing's H under the weight's normal part (weight_part_loads) and under the rest (the whole
    weight, GRAV, less the normal part's H), each over the whole weight's V. CalculiX's RF at the held
    face leaves out the loads on its own nodes (they go straight into the support): their sum is taken
    off, and the vertical one must then be the part's own (a check: CalculiX 2.21 applied a different load
    than its deck's *CLOAD for the tangential part on the finest mesh at t/L 0.15, which is why that part
    is the difference)."""
    text, _ = ccx_input(arch, n_across, False, supports, nu)
    nodes, elements, springing, _ = mesh(arch, n_across)
    th = section_thickness(arch)
    forces = weight_part_loads(nodes, elements, "normal")
    lines = ["*STEP", "*STATIC", "*CLOAD"]
    lines += [f"{k + 1}, {d + 1}, {f[d] * RHO * G_ACC * th:.15g}" for k, f in enumerate(forces) for d in (0, 1) if f[d]]
    lines += ["*NODE PRINT, NSET=NSPRING, TOTALS=ONLY", "RF", "*END STEP"]
    dat = run_input(text[:text.index("*STEP")] + "\n".join(lines) + "\n")
    m = re.search(r"total force \(fx,fy,fz\).*?\n\s*\n?\s*([-+0-9.Ee]+)\s+([-+0-9.Ee]+)\s+([-+0-9.Ee]+)", dat, re.S)
    V = RHO * G_ACC * area(arch)
    held = [sum(forces[k - 1][d] for k in springing) * RHO * G_ACC / V for d in (0, 1)]
    fy = -sum(f[1] for f in forces) * RHO * G_ACC / V  # the part's weight over the whole weight
    normal = float(m.group(1)) / th / V - held[0]
    if abs(float(m.group(2)) / th / V - held[1] - fy) > 1e-5:
        raise RuntimeError(f"ccx's vertical reaction {float(m.group(2)) / th / V - held[1]:.6f} is not the load's {fy:.6f}")
    whole, _, _ = run_ccx(arch, n_across, False, supports, nu)
    return [normal, whole - normal]


def components():
    """components.csv: the clamped catenary (rise L/2) at t/L 0.15 and 0.2, nu 0.2 and 0, under the
    weight's part along the section's normal and the part along the axis apart (consistent nodal loads),
    the continuum's H (over the whole weight's V, extrapolated from 4, 8 and 16 elements through the depth)
    beside beam.py's curved bar (ogive's: the curved bar's held face, beam.held_curved, and the weight's
    own stress) and the same without the weight's own stress; the whole weight (the parts' sum), also with
    the straight strip's held face (held.csv: all_straight_face) and with the held face's own displacement
    under the body force (held_body, 32 elements through the strip's depth) added at the springing
    (all_held_body)."""
    import beam
    held = {r["nu"]: tuple(float(r[k]) for k in ("c_NN", "c_VV", "c_VM", "c_MM")) for r in csv.DictReader(open(HELD))}
    body = {nu: held_body(nu)[:3] for nu in sorted({nu for _, nu in COMPONENTS_CASES})}
    for nu, (u_n, u_y, psi) in body.items():
        print(f"held face under a body force, nu {nu}: u_N {u_n:+.4f} b t^2 / E (along), Uy {u_y:+.4f} b t^2 / E, "
              f"psi {psi:+.4f} b t / E (across)")
    with open(COMPONENTS, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["arch", "supports", "t_over_L", "nu", "part", "continuum", "fe_error", "curved", "curved_no_weight_stress",
                    "difference", "weight_stress_share"])
        for ratio, nu in COMPONENTS_CASES:
            arch = make_arch("catenary", ratio * SPAN)
            meshes = [weight_parts(arch, n, "clamped", nu) for n in (4, 8, 16)]
            for j, part in enumerate(("normal", "tangential", "all", "all_straight_face", "all_held_body")):
                values = [round(m[0] + m[1] if part.startswith("all") else m[j], 7) for m in meshes]
                hv, err, _ = extrapolate(values)
                face = held[repr(nu)] if part == "all_straight_face" else "curved"
                extra = {"held_load": body[nu], "part": "all"} if part == "all_held_body" else {"part": part[:3] if part.startswith("all") else part}
                curved, bare = (beam.h_over_v("catenary", ratio, "clamped", nu, face, weight=wt, **extra)
                                for wt in (True, False))
                w.writerow(["catenary", "clamped", repr(ratio), repr(nu), part, f"{hv:.7f}", f"{err:.1e}", f"{curved:.7f}",
                            f"{bare:.7f}", f"{curved - hv:+.2e}", f"{curved - bare:+.2e}"])
                f.flush()
    print(open(COMPONENTS).read(), end="")


def figure(out=os.path.join(TOP, "docs", "figures", "continuum.png")):
    """Each beam model's H/V error against the continuum over t/L, one panel per arch (plane stress;
    clamped solid, pinned dashed), drawn by gnuplot."""
    rows = list(csv.DictReader(open(TABLE)))
    with tempfile.TemporaryDirectory() as work:
        script = ["set terminal pngcairo size 1100,820 font 'sans,11' background rgb 'white'", f"set output '{out}'",
                  "set multiplot layout 2,2 title 'Error of H/V against the plane-stress arch (CalculiX CPS8): "
                  "solid clamped, dashed pinned'",
                  "set grid", "set xlabel 't / L'", "set ylabel 'error of H/V, %'", "set key top left font ',9'"]
        for arch in ARCHES:
            lines = []
            for supports, dash in (("clamped", 1), ("pinned", 2)):
                sel = [r for r in rows if r["arch"] == arch and r["supports"] == supports and r["plane"] == "stress"]
                if not sel:
                    continue
                path = os.path.join(work, f"{arch}-{supports}.dat")
                with open(path, "w") as f:
                    for r in sel:
                        f.write(" ".join([r["t_over_L"]] + [str(100 * float(r[f"{m}_error"])) for m in MODELS]) + "\n")
                for j, (m, colour) in enumerate(zip(MODELS, ("#1f77b4", "#d62728", "#2ca02c"))):
                    title = f"title '{m}'" if supports == "clamped" else "notitle"
                    lines.append(f"'{path}' using 1:{j + 2} with linespoints dt {dash} lw 2 pt 7 ps 0.6 "
                                 f"lc rgb '{colour}' {title}")
            script += [f"set title '{arch}'", "plot " + ", ".join(lines) + ", 0 notitle lc rgb 'black'"]
        script.append("unset multiplot")
        subprocess.run(["gnuplot"], input="\n".join(script) + "\n", text=True, check=True)
    print(out)


def check(ogive):
    """The public check: the clamped semicircle at t/L 0.08 in plane stress, CalculiX's H/V on its three
    meshes beside each beam model's. It fails (exit status 1) when the continuum's H/V misses
    reference.csv's, or ogive's curved bar misses continuum.csv's, by more than the reference's fe_error."""
    def row_of(path):
        key = ("semicircular", "clamped", "stress", "0.08")
        return next(r for r in csv.DictReader(open(path)) if (r["arch"], r["supports"], r["plane"], r["t_over_L"]) == key)

    stated, table_row = row_of(REFERENCE), row_of(TABLE)
    # The reference's own error estimate (Richardson's step plus the finest mesh's difference): a continuum
    # that moves by more is another reference, a curved bar that moves by more has changed against it.
    fe_error = float(stated["fe_error"])
    hv, err, values, order = continuum(make_arch("semicircular", 0.08 * SPAN))
    print(f"clamped semicircle, t/L 0.08, plane stress: continuum H/V {hv:.5f} (+- {err:.0e}; meshes "
          f"{', '.join(f'{v:.6f}' for v in values)}, order {order:.2f})")
    bars = {}
    for m in MODELS:
        bars[m], _ = ogive_hv(ogive, make_arch("semicircular", 0.8), 0.08, m)
        print(f"  {m}: {bars[m]:.5f} ({100 * (bars[m] - hv) / hv:+.2f} %)")
    misses = [f"{what} {got:.7f} is not within the reference's fe_error {fe_error:.1e} of {where}'s {want}"
              for what, got, want, where in [("the continuum's H/V", hv, stated["H_over_V"], "reference.csv"),
                                             ("the curved bar's H/V", bars["curved"], table_row["curved"], "continuum.csv")]
              if not abs(got - float(want)) <= fe_error]
    if misses:
        sys.exit("continuum.py check: " + "; ".join(misses))
    print(f"the continuum and the curved bar within the reference's fe_error {fe_error:.1e} of their stated H/V "
          f"({stated['H_over_V']}, {table_row['curved']})")


def reference_all(supports):
    """CalculiX's H/V for every arch and t/L with each of the supports (plane stress), and the clamped
    semicircle in plane strain, into reference.csv (the rows it lacks)."""
    cases = [(a, s, "stress", r) for s in supports.split(",") for a in ARCHES for r in RATIOS]
    cases += [("semicircular", "clamped", "strain", r) for r in RATIOS]
    reference(cases)


def first_sentence(function):
    """A function's docstring up to its first full stop, on one line: its subcommand's help."""
    words = " ".join(function.__doc__.split())
    return words.split(". ")[0].rstrip(".") + "."


def main():
    import textwrap  # here, with the dispatch it serves

    # Each subcommand: its function and what it takes of the options (its help: the docstring's first
    # sentence).
    commands = {
        "check": (check, lambda a: [a.ogive]),
        "reference": (reference_all, lambda a: [a.supports]),
        "table": (table, lambda a: [a.ogive]),
        "summary": (summary, lambda a: []),
        "poisson": (poisson, lambda a: [a.ogive]),
        "ends": (ends, lambda a: [a.ogive]),
        "spread": (spread, lambda a: [a.ogive]),
        "crown": (crown, lambda a: [a.ogive]),
        "strip": (strip, lambda a: [a.ogive]),
        "joint": (joint, lambda a: [a.ogive]),
        "wedge": (wedge, lambda a: []),
        "trial": (trial, lambda a: [a.ogive]),
        "components": (components, lambda a: []),
        "ring": (ring, lambda a: []),
        "figure": (figure, lambda a: []),
    }
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="subcommands:\n" + "\n".join(
            textwrap.fill(first_sentence(f), 100, initial_indent=f"  {name:<10} ", subsequent_indent=" " * 13)
            for name, (f, _) in commands.items()))
    parser.add_argument("what", choices=list(commands), metavar="SUBCOMMAND", help="one of those below")
    parser.add_argument("--ogive", default=os.path.join(TOP, "build", "ogive"), help="the ogive executable")
    parser.add_argument("--supports", default="clamped,pinned", help="reference's supports")
    args = parser.parse_args()
    function, arguments = commands[args.what]
    function(*arguments(args))


if __name__ == "__main__":
    main()
