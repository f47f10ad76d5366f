#!/usr/bin/python3
"""An independent re-derivation of ogive's limit analysis with a finite compressive strength.

The semicircle of span L (true voussoir weight: each voussoir an annular sector with its own area and
centroid, radial joints), rho g and f_c as given, solved here from scratch: its own ring geometry, its own
statics and scipy's SLSQP on the convex program (unknowns H, V, M of the left springing and the margin
mu; at each joint the resultant stays N / (2 f_c) inside each face:
    -m_I - N^2 / (2 f_c) >= mu h W   and   m_E - N^2 / (2 f_c) >= mu h W,
m_Q the moment of the joint's force about face point Q, N its normal component, h the joint's length).
It prints H_min, H_max at t/L = 0.08 and t_min (bisection on the sign of the largest margin) beside
ogive's (build/ogive limit) for the same scene: the two agree to the ring's discretisation (n voussoirs
here, ogive's refined ring there).

Run from the repository's top after the build:  /usr/bin/python3 benchmarks/crushing/crushing_check.py
"""
import argparse
import csv
import io
import math
import subprocess

import numpy as np
from scipy.optimize import minimize


def ring(L, t, gamma, n):
    """Joints (intrados, extrados points) and voussoirs (weight, centroid x) of the semicircle."""
    R = L / 2
    Ri, Ro = R - t / 2, R + t / 2
    phi = np.linspace(0.0, math.pi, n + 1)
    u = np.stack([-np.cos(phi), np.sin(phi)], axis=1)  # from the centre (R, 0) towards the joint
    centre = np.array([R, 0.0])
    I = centre + Ri * u
    E = centre + Ro * u
    d = phi[1] - phi[0]
    area = d * (Ro**2 - Ri**2) / 2
    rc = (2 / 3) * (Ro**3 - Ri**3) / (Ro**2 - Ri**2) * math.sin(d / 2) / (d / 2)
    mid = 0.5 * (phi[:-1] + phi[1:])
    x = R - rc * np.cos(mid)
    w = np.full(n, gamma * area)
    return I, E, w, x


class Program:
    """The joints' conditions as functions of z = (H, V, M, mu), forces in W, lengths in L."""

    def __init__(self, L, t, gamma, f_c, n):
        I, E, w, x = ring(L, t, gamma, n)
        self.W = w.sum()
        self.L = L
        self.I, self.E = I / L, E / L
        left_w = np.concatenate([[0.0], np.cumsum(w)]) / self.W  # weight left of each joint
        left_m = np.concatenate([[0.0], np.cumsum(w * x)]) / (self.W * L)  # its moment sum x w
        self.left_w, self.left_m = left_w, left_m
        dvec = self.E - self.I
        self.h = np.linalg.norm(dvec, axis=1)
        dn = dvec / self.h[:, None]
        self.n = np.stack([dn[:, 1], -dn[:, 0]], axis=1)
        self.fc = f_c * L / self.W if math.isfinite(f_c) else math.inf

    def parts(self, z):
        H, V, M = z[0], z[1], z[2]
        Fx = np.full_like(self.left_w, H)
        Fy = V - self.left_w
        m = M - self.left_m  # moment about the origin of the left part's force on the right part
        mI = m - (self.I[:, 0] * Fy - self.I[:, 1] * Fx)
        mE = m - (self.E[:, 0] * Fy - self.E[:, 1] * Fx)
        N = Fx * self.n[:, 0] + Fy * self.n[:, 1]
        return mI, mE, N

    def constraints(self, z):
        mI, mE, N = self.parts(z)
        block = 0.0 if math.isinf(self.fc) else N**2 / (2 * self.fc)
        mu = z[3]
        return np.concatenate([-mI - block - mu * self.h, mE - block - mu * self.h])

    def solve(self, objective, fixed_mu=None, start=None):
        z0 = np.array([0.1, 0.5, 0.0, -0.1]) if start is None else start
        cons = [{"type": "ineq", "fun": self.constraints}]
        if fixed_mu is not None:
            cons.append({"type": "eq", "fun": lambda z: z[3] - fixed_mu})
        bounds = [(0, 10), (-10, 10), (-10, 10), (-1, 1)]
        r = minimize(objective, z0, method="SLSQP", constraints=cons, bounds=bounds,
                     options={"ftol": 1e-14, "maxiter": 1000})
        worst = -min(0.0, self.constraints(r.x).min())
        return r, worst


def margin(L, t, gamma, f_c, n):
    p = Program(L, t, gamma, f_c, n)
    r, worst = p.solve(lambda z: -z[3])
    return r.x[3], worst


def thrust_range(L, t, gamma, f_c, n):
    p = Program(L, t, gamma, f_c, n)
    lo, w1 = p.solve(lambda z: z[0], fixed_mu=0.0)
    hi, w2 = p.solve(lambda z: -z[0], fixed_mu=0.0)
    return lo.x[0] * p.W, hi.x[0] * p.W, max(w1, w2)


def t_min(L, gamma, f_c, n, lo=0.03, hi=0.08):
    a, b = lo * L, hi * L
    assert margin(L, a, gamma, f_c, n)[0] < 0 < margin(L, b, gamma, f_c, n)[0]
    while b - a > 1e-7 * b:
        c = 0.5 * (a + b)
        if margin(L, c, gamma, f_c, n)[0] >= 0:
            b = c
        else:
            a = c
    return b


def ogive(ogive_path, f_c):
    args = [ogive_path, "limit", "--curve", "semicircular", "--span", "10", "--density", "2000",
            "--thickness-ratio", "0.08", "--columns", "H_min,H_max,thickness_min_ratio,status"]
    if math.isfinite(f_c):
        args += ["--compressive-strength", repr(f_c)]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    row = next(csv.DictReader(io.StringIO(out)))
    return float(row["H_min"]), float(row["H_max"]), float(row["thickness_min_ratio"]), row["status"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ogive", default="build/ogive")
    parser.add_argument("--voussoirs", type=int, default=1000)
    a = parser.parse_args()
    L, gamma = 10.0, 2000 * 9.81
    print("| f_c | H_min (scipy) | H_min (ogive) | H_max (scipy) | H_max (ogive) | t_min/L (scipy) | "
          "t_min/L (ogive) |")
    print("|---|---|---|---|---|---|---|")
    for f_c in (math.inf, 20 * 2000 * 9.81 * L, 2e6):
        Hmin, Hmax, worst = thrust_range(L, 0.08 * L, gamma, f_c, a.voussoirs)
        tm = t_min(L, gamma, f_c, a.voussoirs) / L
        o = ogive(a.ogive, f_c)
        name = "infinite" if math.isinf(f_c) else f"{f_c:.4g} Pa"
        print(f"| {name} | {Hmin:.7g} | {o[0]:.7g} | {Hmax:.7g} | {o[1]:.7g} | {tm:.6f} | {o[2]:.6f} |")


if __name__ == "__main__":
    main()
