#!/usr/bin/python3
"""Peer solver: the pointed-arch scenes of ogive solved by scipy.integrate.solve_bvp.

Solves the six first-order ODEs of docs/model.md along the half arch (springing s=0 to the
crown s=S) in ogive's non-dimensional form:

    s~ = s/L; forces in w L; moments in w L^2; displacements in w L^4/(E I); rotations in w L^3/(E I)

    Ux' = a_N N c - (a_V V + psi) sn      N = c Fx + sn Fy
    Uy' = a_N N sn + (a_V V + psi) c      V = -sn Fx + c Fy
    psi' = M;  Fx' = 0;  Fy' = 1;  M' = sn Fx - c Fy

with a_N = (t/L)^2/12 and a_V = E'/(k G) a_N.  BCs: Ux(0) = -d~, Uy(0) = 0, psi(0) = 0,
Ux(S~) = 0, psi(S~) = 0, Fy(S~) = 0.  H/V = -Fx / S~.

The reference H/V (closed form) comes from `ogive thrust --method closed-form` (--ogive PATH) or from a
CSV (--reference-csv FILE); the reference moment profile from `ogive profile --method closed-form`.

Writes CSV to stdout with the columns of `ogive bench` (plus error_profile), one row per (scene, tol).
Exit status: 0 ok, 1 runtime failure (e.g. the ogive reference could not be run), 2 bad arguments.
"""

import argparse
import csv
import io
import math
import os
import statistics
import subprocess
import sys
import time

try:
    import numpy as np
    from scipy.integrate import solve_bvp
except ImportError:  # e.g. a pyenv python3 first on PATH: retry with Debian's interpreter
    if os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3") and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.stderr.write("scipy_peer.py: needs numpy and scipy (Debian: apt-get install -y python3-scipy python3-numpy)\n")
    sys.exit(1)

COLUMNS = ("curve,eccentricity,span,thickness_ratio,support_displacement_ratio,youngs_modulus,poisson_ratio,"
           "density,gravity,shear_coefficient,plane_strain,method,integrator,rtol,segments,status,H_over_V,"
           "error_H_over_V,error_profile,median_seconds,steps,rhs_evaluations,condition_estimate").split(",")

# Scene parameters: (command-line option, CSV column, default).  Each takes a value, a list a,b,c or a
# linear range start:stop:count, exactly like ogive's options; the scenes are the cartesian product.
SCENE_OPTIONS = [
    ("span", "span", "10"),
    ("youngs-modulus", "youngs_modulus", "14.8e9"),
    ("poisson-ratio", "poisson_ratio", "0.2"),
    ("density", "density", "2348"),
    ("gravity", "gravity", "9.81"),
    ("shear-coefficient", "shear_coefficient", repr(5.0 / 6.0)),
    ("thickness-ratio", "thickness_ratio", "0.08"),
    ("support-displacement-ratio", "support_displacement_ratio", "0"),
    ("eccentricity", "eccentricity", "0"),
]

MAX_VALUES = 100000


class UsageError(Exception):
    pass


def parse_values(text, option):
    """A value, a list a,b,c or a linear range start:stop:count (ogive's syntax)."""
    text = text.strip()
    if not text:
        raise UsageError(f"{option}: needs a value, a list a,b,c or a range start:stop:count")
    if "," in text and ":" in text:
        raise UsageError(f"{option}: '{text}' mixes a list and a range")
    try:
        if ":" in text:
            parts = text.split(":")
            if len(parts) != 3:
                raise UsageError(f"{option}: range '{text}' must be start:stop:count")
            start, stop = float(parts[0]), float(parts[1])
            try:
                count = int(parts[2])
            except ValueError:
                raise UsageError(f"{option}: range count '{parts[2]}' must be a whole number >= 1") from None
            if count < 1 or count > MAX_VALUES:
                raise UsageError(f"{option}: range count must lie in [1, {MAX_VALUES}], got {count}")
            if count == 1:
                if start != stop:
                    raise UsageError(f"{option}: a range of one value needs start == stop, got '{text}'")
                values = [start]
            else:
                values = [start + (stop - start) * i / (count - 1) for i in range(count)]
        else:
            values = [float(p) for p in text.split(",")]
    except ValueError:
        raise UsageError(f"{option}: '{text}' is not a number, a list a,b,c or a range start:stop:count") from None
    if not all(math.isfinite(v) for v in values):
        raise UsageError(f"{option}: values must be finite, got '{text}'")
    return values


def fmt(x):
    """Numbers as ogive writes them: shortest round-trip text; integers without a decimal point."""
    if isinstance(x, str):
        return x
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    x = float(x)
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


# ---------------------------------------------------------------------------------------------------------
# The model


class Scene:
    def __init__(self, p, plane_strain):
        self.p = p  # dict keyed by CSV column
        self.plane_strain = plane_strain
        L, eps, tr = p["span"], p["eccentricity"], p["thickness_ratio"]
        E, nu, k = p["youngs_modulus"], p["poisson_ratio"], p["shear_coefficient"]
        rho, g = p["density"], p["gravity"]
        t = tr * L
        E_eff = E / (1.0 - nu * nu) if plane_strain else E
        G = E / (2.0 * (1.0 + nu))
        self.R = 0.5 + eps  # R / L
        self.alpha_c = math.acos(eps / (0.5 + eps))
        self.S = self.R * self.alpha_c  # S / L
        self.a_N = tr * tr / 12.0
        self.a_V = E_eff / (k * G) * self.a_N
        w = rho * g * t
        I = t ** 3 / 12.0
        self.w, self.L = w, L
        self.disp_scale = w * L ** 4 / (E_eff * I)
        self.d = p["support_displacement_ratio"] * L / self.disp_scale  # d~
        self.moment_scale = w * L * L

    # State y = (Ux, Uy, psi, Fx, Fy, M); vectorised: s shape (m,), y shape (6, m).
    def fun(self, s, y):
        th = 0.5 * math.pi - s / self.R
        c, sn = np.cos(th), np.sin(th)
        Fx, Fy, psi = y[3], y[4], y[2]
        N = c * Fx + sn * Fy
        V = -sn * Fx + c * Fy
        shear = self.a_V * V + psi
        return np.vstack((self.a_N * N * c - shear * sn,
                          self.a_N * N * sn + shear * c,
                          y[5],
                          np.zeros_like(s),
                          np.ones_like(s),
                          sn * Fx - c * Fy))

    def fun_jac(self, s, y):
        th = 0.5 * math.pi - s / self.R
        c, sn = np.cos(th), np.sin(th)
        aN, aV = self.a_N, self.a_V
        J = np.zeros((6, 6, s.size))
        J[0, 2] = -sn
        J[0, 3] = aN * c * c + aV * sn * sn
        J[0, 4] = (aN - aV) * c * sn
        J[1, 2] = c
        J[1, 3] = (aN - aV) * c * sn
        J[1, 4] = aN * sn * sn + aV * c * c
        J[2, 5] = 1.0
        J[5, 3] = sn
        J[5, 4] = -c
        return J

    def bc(self, ya, yb):
        return np.array([ya[0] + self.d, ya[1], ya[2], yb[0], yb[2], yb[4]])

    @staticmethod
    def bc_jac(ya, yb):
        Ja = np.zeros((6, 6))
        Jb = np.zeros((6, 6))
        Ja[0, 0] = Ja[1, 1] = Ja[2, 2] = 1.0
        Jb[3, 0] = Jb[4, 2] = Jb[5, 4] = 1.0
        return Ja, Jb


def solve(scene, tol, nodes, max_nodes, analytic_jacobian, counter):
    s0 = np.linspace(0.0, scene.S, nodes)
    y0 = np.zeros((6, nodes))
    y0[4] = s0 - scene.S  # Fy is known exactly; everything else starts at zero (the problem is linear)

    def fun(s, y):
        counter["calls"] += 1
        counter["points"] += s.size
        return scene.fun(s, y)

    kwargs = dict(tol=tol, max_nodes=max_nodes)
    if analytic_jacobian:
        kwargs.update(fun_jac=scene.fun_jac, bc_jac=scene.bc_jac)
    return solve_bvp(fun, scene.bc, s0, y0, **kwargs)


# ---------------------------------------------------------------------------------------------------------
# References


def ogive_args(scene):
    p = scene.p
    args = ["--curve", "pointed"]
    for opt, col, _ in SCENE_OPTIONS:
        args += [f"--{opt}", repr(float(p[col]))]
    if scene.plane_strain:
        args.append("--plane-strain")
    return args


def run_ogive(path, sub, args):
    cmd = [path, sub, "--method", "closed-form", "--all-columns"] + args
    try:
        res = subprocess.run(cmd, capture_output=True, text=True, check=False)
    except OSError as e:
        raise RuntimeError(f"cannot run {path}: {e}") from None
    if res.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({res.returncode}): {res.stderr.strip()}")
    return list(csv.DictReader(io.StringIO(res.stdout)))


def ogive_reference_hv(path, scene):
    rows = run_ogive(path, "thrust", ogive_args(scene))
    if len(rows) != 1 or "H_over_V" not in rows[0]:
        raise RuntimeError("ogive thrust: expected one row with an H_over_V column")
    if rows[0].get("status", "success") != "success":
        sys.stderr.write(f"scipy_peer.py: warning: closed-form reference status {rows[0]['status']}\n")
    return float(rows[0]["H_over_V"])


PROFILE_COLUMNS = ("s", "theta", "Ux", "Uy", "psi", "N", "shear_force", "M")


def ogive_reference_profile(path, scene, stations):
    """The closed form's profile: a dict of arrays keyed by PROFILE_COLUMNS (SI units)."""
    rows = run_ogive(path, "profile", ogive_args(scene) + ["--stations", str(stations)])
    for col in PROFILE_COLUMNS:
        if not rows or col not in rows[0]:
            raise RuntimeError(f"ogive profile: no '{col}' column")
    return {col: np.array([float(r[col]) for r in rows]) for col in PROFILE_COLUMNS}


def scene_matches(row, scene):
    for _, col, _ in SCENE_OPTIONS:
        if col in row and row[col] not in ("", None):
            try:
                v = float(row[col])
            except ValueError:
                return False
            if not math.isclose(v, scene.p[col], rel_tol=1e-9, abs_tol=1e-12):
                return False
    if "plane_strain" in row and row["plane_strain"] not in ("", None):
        if (row["plane_strain"].strip() not in ("0", "false", "False")) != scene.plane_strain:
            return False
    if "curve" in row and row["curve"] not in ("pointed", "semicircular"):
        return False
    return True


def csv_reference_hv(rows, scene):
    """H/V of the first matching row, preferring method closed-form when a method column exists."""
    matches = [r for r in rows if scene_matches(r, scene) and r.get("H_over_V") not in (None, "")]
    closed = [r for r in matches if r.get("method") == "closed-form"]
    pick = closed or ([] if any("method" in r for r in matches) else matches)
    if not pick:
        return math.nan
    return float(pick[0]["H_over_V"])


def read_csv_rows(path):
    """Rows of a CSV that may be several CSVs concatenated (a header line starts each block)."""
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    rows, header = [], None
    for line in lines:
        if not line.strip():
            continue
        fields = next(csv.reader([line]))
        if fields and fields[0] == "curve":
            header = fields
            continue
        if header is None:
            raise UsageError(f"--reference-csv: {path} has no header line starting with 'curve'")
        rows.append(dict(zip(header, fields)))
    return rows


def profile_error(sol, scene, ref):
    """ogive's profile_difference (include/ogive/solve.hpp) over the half-arch stations: the error of
    (Ux, Uy) relative to max |U|, of psi relative to max |psi|, of (N, V) relative to the largest
    resultant, and of M relative to max(max |M|, max |N| t / 6)."""
    S = scene.S * scene.L
    keep = ref["s"] <= S * (1.0 + 1e-12) + 1e-12
    r = {col: ref[col][keep] for col in PROFILE_COLUMNS}
    if r["s"].size == 0:
        return math.nan
    y = sol.sol(np.clip(r["s"] / scene.L, 0.0, scene.S))
    force, rotation = scene.w * scene.L, scene.disp_scale / scene.L
    Ux, Uy, psi = y[0] * scene.disp_scale, y[1] * scene.disp_scale, y[2] * rotation
    Fx, Fy, M = y[3] * force, y[4] * force, y[5] * scene.moment_scale
    c, sn = np.cos(r["theta"]), np.sin(r["theta"])
    N, V = c * Fx + sn * Fy, -sn * Fx + c * Fy
    t = scene.p["thickness_ratio"] * scene.L

    def ratio(diff, scale):
        return diff / scale if scale > 0 else (0.0 if diff == 0 else math.inf)

    errors = [ratio(np.max(np.hypot(Ux - r["Ux"], Uy - r["Uy"])), np.max(np.hypot(r["Ux"], r["Uy"]))),
              ratio(np.max(np.abs(psi - r["psi"])), np.max(np.abs(r["psi"]))),
              ratio(np.max(np.hypot(N - r["N"], V - r["shear_force"])), np.max(np.hypot(r["N"], r["shear_force"]))),
              ratio(np.max(np.abs(M - r["M"])), max(np.max(np.abs(r["M"])), np.max(np.abs(r["N"])) * t / 6))]
    worst = max(errors)
    return float(worst) if math.isfinite(worst) else math.nan


# ---------------------------------------------------------------------------------------------------------


def build_parser():
    ap = argparse.ArgumentParser(
        description="Solve ogive's pointed-arch scenes with scipy.integrate.solve_bvp; CSV (ogive bench columns) on stdout.",
        epilog="Values: a value, a list a,b,c or a linear range start:stop:count. Example: "
               "scipy_peer.py --eccentricity 0,0.5,1 --tols 1e-2,1e-4,1e-6,1e-8 --ogive build/ogive --repeats 5")
    for opt, _, default in SCENE_OPTIONS:
        ap.add_argument(f"--{opt}", default=default, metavar="VALUES", help=f"(default {default})")
    ap.add_argument("--plane-strain", action="store_true", help="E / (1 - nu^2) for axial and bending stiffness")
    ap.add_argument("--tols", default="1e-3,1e-6,1e-9", metavar="VALUES",
                    help="solve_bvp tol values, list or linear range (default 1e-3,1e-6,1e-9)")
    ap.add_argument("--repeats", type=int, default=5, help="solves per row; the median time is printed (default 5)")
    ap.add_argument("--initial-nodes", type=int, default=11, help="initial uniform mesh nodes (default 11)")
    ap.add_argument("--max-nodes", type=int, default=100000, help="solve_bvp max_nodes (default 100000)")
    ap.add_argument("--fd-jacobian", action="store_true",
                    help="let solve_bvp estimate the Jacobians by finite differences (integrator column "
                         "'collocation-fd'); default: analytic fun_jac and bc_jac")
    ref = ap.add_mutually_exclusive_group()
    ref.add_argument("--ogive", metavar="PATH", help="ogive executable for the closed-form H/V and M profile")
    ref.add_argument("--reference-csv", metavar="FILE",
                     help="CSV with scene columns and H_over_V (rows with method closed-form preferred)")
    ap.add_argument("--reference-profile-csv", metavar="FILE",
                    help="with --reference-csv: an `ogive profile` CSV (columns s, M and scene columns) "
                         "for error_profile")
    ap.add_argument("--stations", type=int, default=41,
                    help="stations of the reference profile, springing to springing (default 41)")
    return ap


def main(argv):
    ap = build_parser()
    a = ap.parse_args(argv)  # argparse exits with status 2 on a malformed command line
    try:
        values = {col: parse_values(getattr(a, opt.replace("-", "_")), f"--{opt}") for opt, col, _ in SCENE_OPTIONS}
        tols = parse_values(a.tols, "--tols")
        for t in tols:
            if not (0.0 < t <= 0.1):
                raise UsageError(f"--tols: must lie in (0, 0.1], got {t!r}")
        if a.repeats < 1 or a.repeats > 100000:
            raise UsageError(f"--repeats: must lie in [1, 100000], got {a.repeats}")
        if a.initial_nodes < 2:
            raise UsageError(f"--initial-nodes: must be >= 2, got {a.initial_nodes}")
        if a.max_nodes < a.initial_nodes:
            raise UsageError("--max-nodes: must be >= --initial-nodes")
        if a.stations < 2:
            raise UsageError(f"--stations: must be >= 2, got {a.stations}")
        positive = ("span", "youngs_modulus", "density", "gravity", "shear_coefficient", "thickness_ratio")
        for col in positive:
            if any(not v > 0 for v in values[col]):
                raise UsageError(f"--{col.replace('_', '-')}: must be > 0")
        if any(v < 0 for v in values["eccentricity"]):
            raise UsageError("--eccentricity: must be >= 0")
        if any(not (-1.0 < v < 0.5) for v in values["poisson_ratio"]):
            raise UsageError("--poisson-ratio: must lie in (-1, 0.5)")
        if a.reference_profile_csv and not a.reference_csv:
            raise UsageError("--reference-profile-csv needs --reference-csv")
        if a.ogive and not (os.path.isfile(a.ogive) and os.access(a.ogive, os.X_OK)):
            raise UsageError(f"--ogive: '{a.ogive}' is not an executable file")
        ref_rows = read_csv_rows(a.reference_csv) if a.reference_csv else None
        prof_rows = read_csv_rows(a.reference_profile_csv) if a.reference_profile_csv else None
    except UsageError as e:
        sys.stderr.write(f"scipy_peer.py: {e}\n")
        return 2
    except OSError as e:
        sys.stderr.write(f"scipy_peer.py: {e}\n")
        return 2
    if not a.ogive and not a.reference_csv:
        sys.stderr.write("scipy_peer.py: warning: no --ogive or --reference-csv: error columns will be nan\n")

    # Scene grid in ogive's option order (the last option varies fastest).
    grid = [{}]
    for _, col, _ in SCENE_OPTIONS:
        grid = [dict(g, **{col: v}) for g in grid for v in values[col]]

    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(COLUMNS)
    integrator = "collocation-fd" if a.fd_jacobian else "collocation"
    try:
        for p in grid:
            scene = Scene(p, a.plane_strain)
            hv_ref, prof_ref = math.nan, None
            if a.ogive:
                hv_ref = ogive_reference_hv(a.ogive, scene)
                prof_ref = ogive_reference_profile(a.ogive, scene, a.stations)
            elif ref_rows is not None:
                hv_ref = csv_reference_hv(ref_rows, scene)
                if math.isnan(hv_ref):
                    sys.stderr.write(f"scipy_peer.py: warning: no reference H/V in {a.reference_csv} for {p}\n")
                if prof_rows is not None:
                    pr = [r for r in prof_rows if scene_matches(r, scene) and all(c in r for c in PROFILE_COLUMNS)]
                    if pr:
                        prof_ref = {c: np.array([float(r[c]) for r in pr]) for c in PROFILE_COLUMNS}
            for tol in tols:
                seconds, sol, counter = [], None, None
                for _ in range(a.repeats):
                    c = {"calls": 0, "points": 0}
                    t0 = time.perf_counter()
                    sol = solve(scene, tol, a.initial_nodes, a.max_nodes, not a.fd_jacobian, c)
                    seconds.append(time.perf_counter() - t0)
                    counter = counter or c
                Fx = float(sol.sol(0.0)[3])
                hv = -Fx / scene.S
                err = abs(hv - hv_ref) / abs(hv_ref) if math.isfinite(hv_ref) and hv_ref != 0 else math.nan
                eprof = profile_error(sol, scene, prof_ref) if prof_ref is not None else math.nan
                status = "success" if sol.status == 0 else "not_converged"
                if sol.status != 0:
                    sys.stderr.write(f"scipy_peer.py: eps={p['eccentricity']} tol={tol!r}: solve_bvp status "
                                     f"{sol.status}: {sol.message}\n")
                row = {col: p[col] for _, col, _ in SCENE_OPTIONS}
                row.update(curve="pointed", plane_strain="true" if a.plane_strain else "false", method="scipy-solve_bvp",
                           integrator=integrator, rtol=tol, segments=sol.x.size - 1, status=status,
                           H_over_V=hv, error_H_over_V=err, error_profile=eprof,
                           median_seconds=statistics.median(seconds), steps=int(sol.niter),
                           rhs_evaluations=counter["calls"], condition_estimate=math.nan)
                out.writerow([fmt(row[c]) for c in COLUMNS])
                sys.stdout.flush()
    except RuntimeError as e:
        sys.stderr.write(f"scipy_peer.py: {e}\n")
        return 1
    except BrokenPipeError:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
