#!/usr/bin/env python3
"""Every non-associative friction collapse state of ogive's ring, by a complementarity search, against
the factor `ogive limit` gives on it (the collapse load factor, or with --acceleration the collapse
acceleration a_c).

    /usr/bin/python3 benchmarks/limit/nonassociative_enumeration.py [--ogive build/ogive] [--scene thick]
        [--joints-count 11] [--friction 0.7] [--acceleration] [--seconds 300]

The scene: the segmental arch of rise L/4 and t = 0.15 L with vertical joints and 50 kN/m at 0.15 L
(`--scene thick`, docs/limit-analysis.md's table; the statics are those of vertical joints, the point
load on the part left of its joint, as nonassociative_reference.py's). It takes from ogive only the
ring (the joints' intrados and extrados points of its `--thrust-line` rows: ogive refines the ring next
to its hinges and sliding joints, so the ring is its own final one; where a_c has no state, the load
factor's) and ogive's answer. Everything else is its own (nonassociative_reference.py's voussoirs:
Green's theorem on the circles; its own statics and scipy's HiGHS programs).

A state z = (H, V, M, lam) is a non-associative collapse state (a fixed point of Gilbert, Casapulla &
Ahmed's iteration) when it lies inside every joint and Coulomb cone and, with each joint's friction rows
held at its own normal forces (|T_j| <= MU N_j, fixed numbers), it is an optimum of the program that
maximises lam: there are multipliers y >= 0 on rows tight at z with sum y_i g_i = e_lam (the gradients
g_i of the face rows as they are and of the held rows +-T_j: a mechanism that hinges and slides without
opening, the live load's work positive). So the collapse states are the union, over every set S of
rows with such multipliers, of the states inside the cones with the rows of S tight (a held row tight
as its Coulomb row). ogive's rings have hundreds of joints, too many to try every set, so the search
is one mixed-integer program (scipy's HiGHS): a binary per row (in S, so tight, or not, so its
multiplier 0, by big-M rows with the multipliers and slacks bounded by Y_MAX and SLACK_MAX, far above
any the rings need), minimising (maximising) lam over every S at once. The state found is checked
again by the program held at its own normal forces. `--seconds` bounds each search; one that does not
end proves nothing and says so.

Prints the least and largest factor of all, ogive's, and whether ogive's is above the least (the unsafe
side) by more than 1e-6 of the associative factor; exits 1 then, or where ogive gives a number and no
collapse state exists, or gives none where one does.
"""
import argparse
import csv
import io
import os
import subprocess
import sys

import numpy as np
from scipy.optimize import Bounds, LinearConstraint, linprog, milp
from scipy.sparse import csr_matrix, hstack, identity

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import nonassociative_reference as ref  # noqa: E402  (its voussoirs: the circles' Green's theorem)

SCENES = {
    # rise ratio, thickness ratio, joints, point load at
    "thick": (0.25, 0.15, "vertical", 0.15),
}
LOAD = 5e4
TOLERANCE = 1e-6


def ogive_ring(ogive, scene, count, friction, acceleration):
    rise, t, joints, at = SCENES[scene]
    curve = ["--curve", "segmental", "--rise-ratio", str(rise)]
    args = [ogive, "limit", *curve, "--thickness-ratio", str(t), "--joints", joints, "--point-load", str(LOAD),
            "--point-load-at", str(at), "--friction", str(friction), "--joints-count", str(count), "--digits", "17",
            "--threads", "1"]
    out = subprocess.run(args + ["--thrust-line", "horizontal" if acceleration else "collapse"], check=False,
                         capture_output=True, text=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    if not rows[0]["intrados_x"]:  # no state (not converged): the ring of the load factor's state
        out = subprocess.run(args + ["--thrust-line", "collapse"], check=False, capture_output=True, text=True).stdout
        rows = list(csv.DictReader(io.StringIO(out)))
    f = lambda r, k: float(r[k])
    I = np.array([[f(r, "intrados_x"), f(r, "intrados_y")] for r in rows])
    E = np.array([[f(r, "extrados_x"), f(r, "extrados_y")] for r in rows])
    column = "horizontal_load_factor" if acceleration else "load_factor"
    summary = list(csv.DictReader(io.StringIO(subprocess.run(
        args + ["--columns", f"status,{column},message"], check=False, capture_output=True, text=True).stdout)))[0]
    value = float(summary[column]) if summary[column] else float("nan")
    return I, E, value, summary["status"], summary["message"]


class Ring:
    """The part left of joint j (the left springing's reaction (H, V), its moment M about the origin, the
    loads of voussoirs 0 .. j-1) passes F_j = (H + lam Ax_j + cx_j, V + lam Ay_j + cy_j) with moment
    m_j = M + lam Am_j + cm_j; N_j = F_j . n_j, T_j = F_j . d_j (ref.Ring's conventions). lam multiplies
    the point load (vertical) or the voussoirs' weights pushed horizontally, the point load at 1."""

    def __init__(self, scene, I, E, acceleration):
        rise, t, _, at = SCENES[scene]
        ref.RISE_RATIO, ref.T_RATIO = rise, t
        vs = ref.voussoirs(I, E)
        W = np.array([ref.UNIT_WEIGHT * a for a, _ in vs])
        x = np.array([c[0] for _, c in vs])
        y = np.array([c[1] for _, c in vs])
        P = np.zeros(len(vs))
        at *= ref.SPAN
        j = int(np.argmin(np.abs(I[:, 0] - at)))  # the vertical joint through the load
        if abs(I[j, 0] - at) > 1e-9 * ref.SPAN:
            sys.exit("no joint through the point load")
        P[j - 1] = LOAD
        cum = lambda v: np.concatenate([[0], np.cumsum(v)])
        D, MD, Pc, MP, YD = cum(W), cum(W * x), cum(P), cum(P * at), cum(W * y)
        zero = np.zeros(len(I))
        if acceleration:
            self.A = (D, zero, -YD)
            self.c = (zero, -D - Pc, -MD - MP)
        else:
            self.A = (zero, -Pc, -MP)
            self.c = (zero, -D, -MD)
        self.W = D[-1] + Pc[-1]
        d = E - I
        self.d = d / np.linalg.norm(d, axis=1)[:, None]
        self.n = np.column_stack([self.d[:, 1], -self.d[:, 0]])
        self.I, self.E = I, E

    def linear(self, v):
        a = np.column_stack([v[:, 0], v[:, 1], np.zeros(len(v)), v[:, 0] * self.A[0] + v[:, 1] * self.A[1]])
        return a, v[:, 0] * self.c[0] + v[:, 1] * self.c[1]

    def face(self, Q):
        """m_j - Q_j x F_j as a z + c."""
        Ax, Ay, Am = self.A
        cx, cy, cm = self.c
        a = np.column_stack([Q[:, 1], -Q[:, 0], np.ones(len(Q)), Am - Q[:, 0] * Ay + Q[:, 1] * Ax])
        return a, cm - Q[:, 0] * cy + Q[:, 1] * cx

    def rows(self, mu):
        """(A, c, G): the rows A z + c <= 0 (per joint: intrados face, extrados face, +T, -T Coulomb) and each
        row's gradient in the held program G (the face rows' own; the friction rows' +-grad T), in units of
        the loads and the span."""
        ai, ci = self.face(self.I)
        ae, ce = self.face(self.E)
        aT, cT = self.linear(self.d)
        aN, cN = self.linear(self.n)
        A = np.stack([ai, -ae, aT - mu * aN, -aT - mu * aN], axis=1).reshape(-1, 4)
        c = np.stack([ci, -ce, cT - mu * cN, -cT - mu * cN], axis=1).reshape(-1)
        G = np.stack([ai, -ae, aT, -aT], axis=1).reshape(-1, 4)
        S = np.diag([self.W, self.W, self.W * ref.SPAN, 1.0])  # z = S u, u in units of the loads
        norm = np.where(np.arange(len(c)) % 4 < 2, self.W * ref.SPAN, self.W)
        return (A @ S) / norm[:, None], c / norm, (G @ S) / norm[:, None], S


# The mixed-integer search's bounds, in units of the loads and the span: a certificate's multipliers (the
# mechanism's displacements per unit work of the live load) and a row's slack; the answer is checked
# against both (a bound reached would cut states off) and re-checked by the held program.
Y_MAX, SLACK_MAX = 1e6, 1e3


def least_by_milp(A, c, G, lam_max, least=True, seconds=300):
    """The least (largest) lam of all collapse states: one binary per row (in the certificate: tight, or
    not: multiplier 0), the complementarity y_i (slack_i) = 0 by big-M rows. (u, y, rows in S) or None."""
    R = len(c)
    n = 4 + 2 * R
    Au = csr_matrix(A)
    I = identity(R, format="csr")
    Z = csr_matrix((R, R))
    rows = [
        LinearConstraint(hstack([Au, Z, Z]), -np.inf, -c),                                   # inside every row
        LinearConstraint(hstack([csr_matrix((4, 4)), csr_matrix(G.T), csr_matrix((4, R))]),  # sum y G = e_lam
                         [0, 0, 0, 1], [0, 0, 0, 1]),
        LinearConstraint(hstack([csr_matrix((R, 4)), I, -Y_MAX * I]), -np.inf, 0),           # y_i <= Y b_i
        LinearConstraint(hstack([-Au, Z, SLACK_MAX * I]), -np.inf, SLACK_MAX + c),          # slack <= S (1 - b)
    ]
    lo = np.concatenate([[0, -SLACK_MAX, -SLACK_MAX, 0], np.zeros(2 * R)])
    hi = np.concatenate([[SLACK_MAX, SLACK_MAX, SLACK_MAX, lam_max], np.full(R, Y_MAX), np.ones(R)])
    cost = np.zeros(n)
    cost[3] = 1.0 if least else -1.0
    integrality = np.concatenate([np.zeros(4 + R), np.ones(R)])
    r = milp(cost, constraints=rows, bounds=Bounds(lo, hi), integrality=integrality,
             options={"time_limit": seconds, "mip_rel_gap": 1e-9})
    if r.x is None:
        return None, r
    u, y, b = r.x[:4], r.x[4:4 + R], r.x[4 + R:]
    # The mechanism's rows: in S with a multiplier (a row in S with y = 0 is merely tight).
    return (u, y, np.flatnonzero((b > 0.5) & (y > 1e-9 * np.max(y)))), r


def fixed_point(A, c, G, u, mu):
    """Held at its own normal forces, the program's largest lam, and the state's worst row."""
    friction = np.arange(len(c)) % 4 >= 2
    b = -c.copy()
    # A held row: sign T <= MU N(u): G u + (c_T) <= MU N(u), i.e. G u <= b_held.
    b[friction] = (G[friction] @ u - A[friction] @ u) - c[friction]
    A_h = np.where(friction[:, None], G, A)
    r = linprog([0, 0, 0, -1.0], A_ub=A_h, b_ub=b, bounds=[(0, None), (None, None), (None, None), (0, None)],
                method="highs", options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10})
    return (r.x[3] if r.status == 0 else float("inf")), float(np.max(A @ u + c))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ogive", default=os.path.join(ref.ROOT, "build", "ogive"))
    ap.add_argument("--scene", choices=sorted(SCENES), default="thick")
    ap.add_argument("--joints-count", type=int, default=11)
    ap.add_argument("--friction", type=float, default=0.7)
    ap.add_argument("--acceleration", action="store_true", help="a_c (else the load factor)")
    ap.add_argument("--seconds", type=float, default=300, help="the mixed-integer search's time limit")
    args = ap.parse_args()
    I, E, given, status, message = ogive_ring(args.ogive, args.scene, args.joints_count, args.friction,
                                              args.acceleration)
    ring = Ring(args.scene, I, E, args.acceleration)
    A, c, G, S = ring.rows(args.friction)
    what = "a_c" if args.acceleration else "load factor"
    print(f"{args.scene}, ogive's ring of {len(I)} joints, MU {args.friction}, {what}; ogive: {status}, {given!r}")
    # The associative factor bounds every collapse state (each lies inside the cones).
    assoc = linprog([0, 0, 0, -1.0], A_ub=A, b_ub=-c, bounds=[(0, None), (None, None), (None, None), (0, None)],
                    method="highs")
    lam_max = assoc.x[3] if assoc.status == 0 else 1e3
    print(f"associative on the ring: {lam_max:.12g}")
    name = lambda r: f"{r // 4}{'ieTt'[r % 4]}"  # joint, row: i/e faces, T/t friction +/-
    found = {}
    for least in (False, True):
        sol, r = least_by_milp(A, c, G, lam_max * (1 + 1e-9), least, args.seconds)
        label = "least" if least else "largest"
        if sol is None:
            print(f"{label}: {'none' if r.status == 2 else 'not found'} ({r.message})")
            if r.status != 2:
                sys.exit(f"the search did not end within {args.seconds} s: nothing proven")
            continue
        u, y, rows = sol
        held, worst = fixed_point(A, c, G, u, args.friction)
        bound = max(np.max(y) / Y_MAX, np.max(np.abs(u[:3])) / SLACK_MAX)
        print(f"{label}: {u[3]:.12g} (proven to gap {r.mip_gap:.1e}; rows {' '.join(name(k) for k in rows)}; held "
              f"at its own N the program's largest {held:.12g}; worst row {worst:.1e}; nearest bound {bound:.1e})")
        found[label] = (u[3], held)
    if "least" not in found:
        print("no non-associative collapse state on this ring" + ("" if np.isnan(given) else ": ogive gives one"))
        sys.exit(0 if np.isnan(given) else 1)
    least, held = found["least"]
    if abs(held - least) > 1e-9 * max(lam_max, 1):
        print("FAIL the least is not a fixed point")
        sys.exit(1)
    if np.isnan(given):
        print("FAIL ogive gives no number")
        sys.exit(1)
    gap = given - least
    above = gap > TOLERANCE * max(lam_max, 1.0)
    print(f"{'ABOVE' if above else 'ok   '} ogive {given:.12g} - global least = {gap:.3g}")
    sys.exit(1 if above else 0)


if __name__ == "__main__":
    main()
