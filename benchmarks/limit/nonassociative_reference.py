#!/usr/bin/env python3
"""An independent check of the non-associative friction collapse factor of `ogive limit` on a segmental
arch with vertical joints (rise L/4, t = 0.18 L, 50 kN/m at 0.3 L, MU 0.6 by default).

    /usr/bin/python3 benchmarks/limit/nonassociative_reference.py [--ogive build/ogive] [--friction 0.6]

It takes from ogive only the ring its answer converged on (the joints' intrados and extrados points, from
`--thrust-line collapse`) and the answer (H and the load factor, and the thrust line's crossing of each
joint). Everything else is its own: each voussoir's weight and centroid from the circles of the
segmental arch (Green's theorem along its arcs and joints), the statics of each joint, and the linear
programs (scipy's HiGHS, not ogive's dense simplex method):

1. ogive's state, by the statics: inside every joint and every Coulomb cone |T| <= MU N.
2. The fixed point: the program with each joint's friction rows held at that state's own normal forces
   (|T_j| <= MU N_j, fixed numbers: Gilbert, Casapulla & Ahmed's non-associative rows) has the same
   largest load factor.
3. The mechanism, by statics alone: the crown block between the joints next to the springings slides
   down at both (vertical joints: N = H across each, and the block's vertical equilibrium gives the
   factor from H, lam = (2 MU H - W_block) / P); bisection on H for the largest (and the least) H
   whose state lies inside every joint and cone. Every factor between the two is a fixed point of the
   iteration (a face of them: the thrust across joints that slide without opening is not determined),
   and a collapse state; ogive's factor must be the least (the safe one: the thrust the arch holds
   decides, and an arch whose springings spread falls to its least), and its message must name the
   largest.

Prints one line per check and exits 1 when one fails (tolerance 1e-8 of the face's largest factor).
"""
import argparse
import csv
import io
import os
import re
import subprocess
import sys

import numpy as np
from scipy.optimize import linprog

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

SPAN, RISE_RATIO, T_RATIO = 10.0, 0.25, 0.18
LOAD, LOAD_AT = 5e4, 0.3
UNIT_WEIGHT = 2348 * 9.81  # ogive's default density (kg/m^3) times g, N/m^3 per metre of width
TOLERANCE = 1e-8           # the factors, relative (the programs' rows hold to ~1e-11 of the loads)
ITERATION_TOLERANCE = 1e-10


def ogive_state(ogive, friction):
    args = [ogive, "limit", "--curve", "segmental", "--rise-ratio", str(RISE_RATIO), "--thickness-ratio",
            str(T_RATIO), "--joints", "vertical", "--point-load", str(LOAD), "--point-load-at", str(LOAD_AT),
            "--friction", str(friction), "--thrust-line", "collapse", "--digits", "17", "--threads", "1"]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    if rows[0]["status"] != "success":
        sys.exit(f"ogive: status {rows[0]['status']}")
    f = lambda r, k: float(r[k])
    I = np.array([[f(r, "intrados_x"), f(r, "intrados_y")] for r in rows])
    E = np.array([[f(r, "extrados_x"), f(r, "extrados_y")] for r in rows])
    Q = np.array([[f(r, "thrust_x"), f(r, "thrust_y")] for r in rows])
    message = subprocess.run(args[:args.index("--thrust-line")] + ["--columns", "message"], check=True,
                             capture_output=True, text=True).stdout
    return I, E, Q, f(rows[0], "H"), f(rows[0], "load_factor"), message


def voussoirs(I, E):
    """Each voussoir's area and centroid: Green's theorem along its intrados arc, its right joint, its
    extrados arc and its left joint (the arcs by 16-point Gauss-Legendre in the angle: exact to round-off)."""
    R = (SPAN ** 2 / 4 + (RISE_RATIO * SPAN) ** 2) / (2 * RISE_RATIO * SPAN)
    C = np.array([SPAN / 2, RISE_RATIO * SPAN - R])
    t = T_RATIO * SPAN
    nodes, weights = np.polynomial.legendre.leggauss(16)

    def arc(r, p, q):  # (A, Sx, Sy) from p to q along the circle of radius r
        a, b = (np.arctan2(*(v - C)[::-1]) for v in (p, q))
        th = 0.5 * (a + b) + 0.5 * (b - a) * nodes
        x, y = C[0] + r * np.cos(th), C[1] + r * np.sin(th)
        dx, dy = -r * np.sin(th), r * np.cos(th)
        w = 0.5 * (b - a) * weights
        return np.array([np.sum(w * x * dy), np.sum(w * 0.5 * x * x * dy), -np.sum(w * 0.5 * y * y * dx)])

    def segment(p, q):
        dx, dy = q - p
        return np.array([0.5 * (p[0] + q[0]) * dy, dy * (p[0] ** 2 + p[0] * q[0] + q[0] ** 2) / 6,
                         -dx * (p[1] ** 2 + p[1] * q[1] + q[1] ** 2) / 6])

    out = []
    for k in range(len(I) - 1):
        m = arc(R - t / 2, I[k], I[k + 1]) + segment(I[k + 1], E[k + 1]) + arc(R + t / 2, E[k + 1], E[k]) \
            + segment(E[k], I[k])
        out.append((abs(m[0]), np.array([m[1] / m[0], m[2] / m[0]])))
    return out


class Ring:
    """The statics of each joint: the part left of joint j (voussoirs 0 .. j-1, the left springing's
    reaction (H, V) and moment M about the origin) passes F_j = (H, V - D_j - lam P_j) with moment
    m_j = M - MD_j - lam MP_j; compression N_j = F_j . n_j, shear T_j = F_j . d_j (d_j intrados to
    extrados, n_j = (d_y, -d_x), towards the right-hand part)."""

    def __init__(self, I, E):
        self.I, self.E = I, E
        vs = voussoirs(I, E)
        W = np.array([UNIT_WEIGHT * a for a, _ in vs])
        x = np.array([c[0] for _, c in vs])
        P = np.zeros(len(vs))
        # The load on the vertical joint through its point belongs to the part left of it (ogive's rule:
        # the part that holds the vertical below the point; a vertical joint leans neither way).
        at = LOAD_AT * SPAN
        j = int(np.argmin(np.abs(I[:, 0] - at)))
        if abs(I[j, 0] - at) > 1e-9 * SPAN:
            sys.exit("no joint through the point load")
        P[j - 1] = LOAD
        self.D = np.concatenate([[0], np.cumsum(W)])
        self.MD = np.concatenate([[0], np.cumsum(W * x)])
        self.P = np.concatenate([[0], np.cumsum(P)])
        self.MP = np.concatenate([[0], np.cumsum(P * at)])
        self.W = self.D[-1]
        d = E - I
        self.h = np.linalg.norm(d, axis=1)
        self.d = d / self.h[:, None]
        self.n = np.column_stack([self.d[:, 1], -self.d[:, 0]])

    def linear(self, v):
        """v_j . F_j as a z + c over z = (H, V, M, lam), per joint (rows)."""
        a = np.column_stack([v[:, 0], v[:, 1], np.zeros(len(v)), -v[:, 1] * self.P])
        return a, -v[:, 1] * self.D

    def rows(self, friction, held=None):
        """A z <= b: each joint's two face rows, and its friction rows (Coulomb's, or held at `held`)."""
        I, E = self.I, self.E
        ones = np.ones(len(I))
        # m - I x F <= 0 and m - E x F >= 0.
        face_i = np.column_stack([I[:, 1], -I[:, 0], ones, I[:, 0] * self.P - self.MP]), self.MD - I[:, 0] * self.D
        face_e = -np.column_stack([E[:, 1], -E[:, 0], ones, E[:, 0] * self.P - self.MP]), -(self.MD - E[:, 0] * self.D)
        aT, cT = self.linear(self.d)
        aN, cN = self.linear(self.n)
        blocks = [face_i, face_e]
        for s in (1.0, -1.0):
            if held is None:
                blocks.append((s * aT - friction * aN, -(s * cT - friction * cN)))
            else:
                blocks.append((s * aT, friction * np.maximum(held, 0) - s * cT))
        A = np.vstack([b[0] for b in blocks])
        b = np.concatenate([b[1] for b in blocks])
        return A, b

    def normal(self, z):
        a, c = self.linear(self.n)
        return a @ z + c

    def shear(self, z):
        a, c = self.linear(self.d)
        return a @ z + c


def scaled(ring, A, b):
    """The rows in units of the load W and the span (H, V in W; M in W L; lam as it is)."""
    S = np.diag([ring.W, ring.W, ring.W * SPAN, 1.0])
    return A @ S / ring.W, b / ring.W, S


def collapse(ring, friction, held=None):
    A, b, S = scaled(ring, *ring.rows(friction, held))
    bounds = [(0, None), (None, None), (None, None), (0, None)]
    r = linprog([0, 0, 0, -1], A_ub=A, b_ub=b, bounds=bounds, method="highs",
                options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10})
    if r.status != 0:
        return None
    return S @ r.x


def slide_statics(ring, friction, a, b, H):
    """The crown block between joints a and b (vertical joints: N = H across each, T vertical) sliding down
    at both, T_a = friction H and T_b = -friction H: its vertical equilibrium fixes lam, the left part's
    V follows, and M must lie within every joint's face bounds. (lam, V, M) of such a state inside
    every joint and cone, or None."""
    W_block, P_block = ring.D[b] - ring.D[a], ring.P[b] - ring.P[a]
    lam = (2 * friction * H - W_block) / P_block
    if lam < 0:
        return None
    V = friction * H + ring.D[a] + lam * ring.P[a]
    Fy = V - ring.D - lam * ring.P
    T, N = ring.shear(np.array([H, V, 0, lam])), ring.normal(np.array([H, V, 0, lam]))
    if np.any(np.abs(T) - friction * N > 1e-12 * ring.W):
        return None
    cross = lambda Q: Q[:, 0] * Fy - Q[:, 1] * H
    base = ring.MD + lam * ring.MP
    upper, lower = base + cross(ring.I), base + cross(ring.E)  # m - I x F <= 0, m - E x F >= 0
    if np.max(lower) > np.min(upper) + 1e-12 * ring.W * SPAN:
        return None
    return lam, V, 0.5 * (np.max(lower) + np.min(upper))


def face_by_statics(ring, friction, H0):
    """The range of factors of the crown block's slide at the joints next to the springings, by bisection
    on H from a state that stands (H0): the states of one slide form an interval of H."""
    a, b = 1, len(ring.I) - 2
    # Inside the face, a hair from the end where ogive's state lies (to the rows' tolerance).
    H0 = next((h for h in (H0 * (1 + 1e-6), H0 * (1 - 1e-6)) if slide_statics(ring, friction, a, b, h) is not None),
              None)
    if H0 is None:
        return None
    ends = []
    for direction in (-1, 1):
        lo, hi = H0, H0
        while slide_statics(ring, friction, a, b, hi) is not None and abs(hi) < 1e3 * H0:
            hi = H0 + 2 * (hi - H0) + direction * 1e-3 * H0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if slide_statics(ring, friction, a, b, mid) is not None:
                lo = mid
            else:
                hi = mid
        ends.append(slide_statics(ring, friction, a, b, lo)[0])
    return ends


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ogive", default=os.path.join(ROOT, "build", "ogive"))
    ap.add_argument("--friction", type=float, default=0.6)
    args = ap.parse_args()
    mu = args.friction
    I, E, Q, H, lam, message = ogive_state(args.ogive, mu)
    ring = Ring(I, E)
    # V and M of ogive's state from its thrust line's crossings: Q_j x F_j = m_j, linear in (V, M).
    lhs = np.column_stack([Q[:, 0], -np.ones(len(Q))])
    rhs = Q[:, 1] * H + Q[:, 0] * (ring.D + lam * ring.P) - ring.MD - lam * ring.MP
    (V, M), *_ = np.linalg.lstsq(lhs, rhs, rcond=None)
    z = np.array([H, V, M, lam])
    scale = ring.W + lam * ring.P[-1]
    N, T = ring.normal(z), ring.shear(z)
    A, b = ring.rows(mu, N)
    failures = 0

    def check(what, ok, text):
        nonlocal failures
        failures += 0 if ok else 1
        print(f"{'ok  ' if ok else 'FAIL'} {what}: {text}")

    print(f"ogive: {len(I)} joints, H = {H:.10g} N/m, load factor {lam:.12g}")
    outside = max(np.max(np.abs(T) - mu * N), 0) / scale
    rows = np.max(A[:2 * len(I)] @ z - b[:2 * len(I)]) / (scale * SPAN)
    check("inside the cones", outside <= 1e-9, f"max(|T| - MU N) = {outside:.2e} of the loads")
    check("inside the joints", rows <= 1e-9, f"largest face row {rows:.2e} of W L")
    face = face_by_statics(ring, mu, H)
    if face is None:
        check("the crown block's slide", False, "ogive's state is not the slide at the joints next to the springings")
        sys.exit(1)
    low, top = face
    fixed = collapse(ring, mu, N)
    check("fixed point", fixed is not None and abs(fixed[3] - lam) <= TOLERANCE * top,
          f"held at its own N: {fixed[3]:.12g} ({abs(fixed[3] - lam) / top:.1e} of the face's largest)"
          if fixed is not None else "no optimum")
    assoc = collapse(ring, mu)
    print(f"associative on the same ring: {assoc[3]:.12g}")
    check("least factor of the slide", abs(low - lam) <= TOLERANCE * top,
          f"by statics {low:.12g} ({abs(low - lam) / top:.1e} of the face's largest)")
    named = re.search(r"every factor from the one given up to ([0-9.eE+-]+)", message)
    check("the message names the largest", named is not None and abs(float(named.group(1)) - top) <= 5e-6 * top,
          f"by statics {top:.12g}, the message {named.group(1) if named else 'nothing'} (6 digits); every factor "
          "between is a fixed point too (the thrust across the sliding joints is not determined)")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
