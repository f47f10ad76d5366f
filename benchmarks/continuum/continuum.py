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


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("what", choices=["check", "reference", "table", "summary", "poisson", "ends", "spread", "figure"])
    parser.add_argument("--ogive", default=os.path.join(TOP, "build", "ogive"))
    parser.add_argument("--supports", default="clamped,pinned")
    args = parser.parse_args()
    if args.what == "check":
        hv, err, values, order = continuum(make_arch("semicircular", 0.08 * SPAN))
        print(f"clamped semicircle, t/L 0.08, plane stress: continuum H/V {hv:.5f} (+- {err:.0e}; meshes "
              f"{', '.join(f'{v:.6f}' for v in values)}, order {order:.2f})")
        for m in MODELS:
            b, _ = ogive_hv(args.ogive, make_arch("semicircular", 0.8), 0.08, m)
            print(f"  {m}: {b:.5f} ({100 * (b - hv) / hv:+.2f} %)")
    elif args.what == "reference":
        cases = [(a, s, "stress", r) for s in args.supports.split(",") for a in ARCHES for r in RATIOS]
        cases += [("semicircular", "clamped", "strain", r) for r in RATIOS]
        reference(cases)
    elif args.what == "table":
        table(args.ogive)
    elif args.what == "summary":
        summary()
    elif args.what == "poisson":
        poisson(args.ogive)
    elif args.what == "spread":
        spread(args.ogive)
    elif args.what == "ends":
        ends(args.ogive)
    else:
        figure()


if __name__ == "__main__":
    main()
