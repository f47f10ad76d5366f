#!/usr/bin/python3
"""The curved bar of docs/model.md ("Beam models") in Python, for trying end terms against the continuum
before they go into ogive: the half arch of the benchmark's four scenes under its own weight, solved by
shooting (scipy's DOP853), with two optional terms that ogive does not have:

- a held springing face's compliance (continuum.py strip): the clamped springing's (Ux, Uy, psi) start at
  dC (N, V, M) instead of zero, in the section's frame;
- a crown joint (continuum.py joint): the crown's conditions Ux = 0 and psi = 0 become
  Ux + b M + c Fx = 0 and psi + a M + b Fx = 0 (the half of a joint between the two legs).

With the held face (strip.csv's finest mesh at nu 0.2, held.csv's row), the self-weight's own stress
(weight=True) and on the equilateral arch kink_joint (the joint that the bar's own coupling gives a kinked
axis, and the pointed crown's wedge, wedge.csv) it is ogive's `--beam-model curved` (H/V within 3e-7 of ogive's); without them, ogive's curved bar's
section law alone.
Units: the span L = 1 and E I = 1 (the compliances below are scaled accordingly); nu the section's.
"""
import functools
import math

import numpy as np
from scipy.integrate import solve_ivp

LD = np.longdouble


def modes(rho):
    """The thick circular bar's stress modes at rho = t / (2R) (R = 1, long double): ln(b / a), Golovin's
    pure bending's denominator n0 and the end force's constants A, B, D. The bending mode's hoop stress
    is -4 / n0 (-a^2 b^2 ln(b/a) / r^2 + b^2 ln(r/b) + a^2 ln(a/r) + b^2 - a^2), the end force's radial and
    hoop ones 2 A r - 2 B / r^3 + D / r and 6 A r + 2 B / r^3 + D / r (times the sine of the angle)."""
    a, b = 1 - rho, 1 + rho
    lg = np.log1p(rho) - np.log1p(-rho)
    n0 = 16 * rho * rho - 4 * (a * b) ** 2 * lg * lg
    n1 = -4 * rho + (a * a + b * b) * lg
    return lg, n0, 1 / (2 * n1), -(a * a) * (b * b) / (2 * n1), -(a * a + b * b) / n1


def section_stresses(rho):
    """The section's stresses (R = 1) of a unit N and M about the axis r = 1 (hoop: M's with int sigma
    (r - 1) dr = 1, tension at the extrados) and of a unit V (shear), each a function of r: the bending
    and end-force modes (modes) combined to those resultants."""
    rho = LD(rho)
    a, b = 1 - rho, 1 + rho
    lg, n0, A, B, D = modes(rho)
    Bt = lambda r: -4 / n0 * (-a * a * b * b * lg / (r * r) + b * b * np.log(r / b) + a * a * np.log(a / r) + b * b - a * a)
    Ft = lambda r: 6 * A * r + 2 * B / r ** 3 + D / r
    Fr = lambda r: 2 * A * r - 2 * B / r ** 3 + D / r
    nodes, weights = np.polynomial.legendre.leggauss(64)
    NF = MF = NB = MB = VF = LD(0)
    for x, w in zip(nodes, weights):
        r, w = 1 + rho * LD(x), rho * LD(w)
        NF, MF, NB, MB, VF = NF + w * Ft(r), MF + w * Ft(r) * (r - 1), NB + w * Bt(r), MB + w * Bt(r) * (r - 1), VF + w * Fr(r)
    det = NF * MB - NB * MF
    return (lambda r: float((MB * Ft(LD(r)) - MF * Bt(LD(r))) / det), lambda r: float((NF * Bt(LD(r)) - NB * Ft(LD(r))) / det),
            lambda r: float(Fr(LD(r)) / VF))


@functools.lru_cache(None)
def section(rho, nu, weight=False):
    """The thick circular bar's four factors (axial, coupling, bending, shear) at rho = t / (2R): Golovin's
    and Michell's stresses' complementary energy (include/ogive/model/curved_section.hpp), by 48-point
    Gauss-Legendre in ln r in long double; below rho = 1e-3 the straight limit plus its rho^2 term."""
    if rho < 1e-3:
        at, w, c0 = section(1e-3, nu), (rho / 1e-3) ** 2, 1 + 1.2 * nu
        return (1 + w * (at[0] - 1), c0 + w * (at[1] - c0), 1 + w * (at[2] - 1), 1 + w * (at[3] - 1))
    rho, nu = LD(rho), LD(nu)
    a, b = 1 - rho, 1 + rho
    # the free annulus under a radial body force 1 (the self-weight's own stress; see weight_terms)
    alpha = (1 - nu) / 9
    ga, gb = (3 * alpha - 1) * a, (3 * alpha - 1) * b
    LA = (gb - ga) / (1 / (a * a) - 1 / (b * b))
    LB = (-ga - LA / (a * a)) / 2
    SN = SM = WFr = WFt = WBr = WBt = LD(0)
    lg, n0, A, B, D = modes(rho)
    nodes, weights = np.polynomial.legendre.leggauss(48)
    u0, u1 = np.log(a), np.log(b)
    NF = MF = NB = MB = VF = QFF = QFB = QBB = QV = LD(0)
    for x, wx in zip(nodes, weights):
        r = np.exp((u0 + u1) / 2 + (u1 - u0) / 2 * LD(x))
        w = (u1 - u0) / 2 * LD(wx) * r
        logs, inner, k = b * b * np.log(r / b) + a * a * np.log(a / r), a * a * b * b * lg / (r * r), -4 / n0
        Br, Bt = k * (inner + logs), k * (-inner + logs + b * b - a * a)
        Fr, Ft = 2 * A * r - 2 * B / r ** 3 + D / r, 6 * A * r + 2 * B / r ** 3 + D / r
        NB, MB, NF, MF, VF = NB + w * Bt, MB + w * Bt * (r - 1), NF + w * Ft, MF + w * Ft * (r - 1), VF + w * Fr
        QBB += w * r * (Br * Br + Bt * Bt - 2 * nu * Br * Bt)
        QFF += w * r * (Fr * Fr + Ft * Ft - 2 * nu * Fr * Ft)
        QFB += w * r * (Fr * Br + Ft * Bt - nu * (Fr * Bt + Ft * Br))
        QV += w * r * Fr * Fr * 2 * (1 + nu)
        lr, lt = LA / (r * r) + 2 * LB + (3 * alpha - 1) * r, -LA / (r * r) + 2 * LB + (6 * alpha - 1) * r
        SN, SM = SN + w * lt, SM + w * lt * (r - 1)
        WFr, WFt = WFr + w * r * (Fr * lr - nu * Ft * lr), WFt + w * r * (Ft * lt - nu * Fr * lt)
        WBr, WBt = WBr + w * r * (Br * lr - nu * Bt * lr), WBt + w * r * (Bt * lt - nu * Br * lt)
    det = NF * MB - NB * MF
    i00, i01, i10, i11 = MB / det, -NB / det, -MF / det, NF / det
    C00 = i00 * (QFF * i00 + QFB * i10) + i10 * (QFB * i00 + QBB * i10)
    C01 = i00 * (QFF * i01 + QFB * i11) + i10 * (QFB * i01 + QBB * i11)
    C11 = i01 * (QFF * i01 + QFB * i11) + i11 * (QFB * i01 + QBB * i11)
    t = 2 * rho
    if weight:
        fF, fB = i00 * SN + i01 * SM, i10 * SN + i11 * SM
        XF, XB = WFr + WFt - fF * QFF - fB * QFB, WBr + WBt - fF * QFB - fB * QBB
        return (float((i00 * XF + i10 * XB) / t), float(i01 * XF + i11 * XB))
    return (float(C00 * t), float(C01 * t), float(C11 * t ** 3 / 12), float(QV / (VF * VF) * LD(5) / 6 * t / (2 * (1 + nu))))


class Arch:
    """The half arch (L = 1), s from the springing to the crown: its tangent's angle and curvature."""

    def __init__(self, kind):
        self.kind = kind
        if kind == "semicircular":
            self.R, self.th0, self.th1 = 0.5, math.pi / 2, 0.0
        elif kind == "equilateral":  # eccentricity 0.5: R = L, the crown's tangent at 30 degrees
            self.R, self.th0, self.th1 = 1.0, math.pi / 2, math.pi / 6
        elif kind == "segmental":  # rise L/4
            self.R = (0.25 + 1 / 16) / 0.5
            self.th0, self.th1 = math.asin(0.5 / self.R), 0.0
        elif kind == "catenary":  # rise L/2
            lo, hi = 1e-3, 1e3
            for _ in range(200):
                mid = math.sqrt(lo * hi)
                lo, hi = (mid, hi) if mid * (math.cosh(0.5 / mid) - 1) > 0.5 else (lo, mid)
            self.a = math.sqrt(lo * hi)
            self.S = self.a * math.sinh(0.5 / self.a)
        else:
            raise ValueError(kind)
        if kind != "catenary":
            self.S = self.R * (self.th0 - self.th1)

    def theta(self, s):
        return math.atan((self.S - s) / self.a) if self.kind == "catenary" else self.th0 - s / self.R

    def kappa(self, s):
        return -1 / (self.a * (1 + ((self.S - s) / self.a) ** 2)) if self.kind == "catenary" else -1 / self.R


def weight_terms(rho, nu):
    """The self-weight's own stress across the depth (tried, not in ogive; git show 124e398): the section's
    (load_extension, load_curvature) per q, q the weight's part along the extrados normal. Below rho 0.005
    their straight limits (0, -nu / 5)."""
    if rho < 5e-3:
        return (0.0, -0.2 * nu)
    return section(rho, nu, True)


def rates(arch, t, nu, s, Y, load, weight=False, part="all"):
    """dY/ds of the curved bar (ArchModel::curved_derivative) for the columns of Y; `load` the weight's
    column (the others homogeneous). part: the whole weight (all), or its part along the section's normal
    (normal: (g.n) n) or along the axis (tangential), each per unit length at the slice's centroid."""
    th, k = arch.theta(s), arch.kappa(s)
    c, sn = math.cos(th), math.sin(th)
    axial, coupling, bending, shear = section(abs(k) * t / 2, nu)
    aN = t * t / 12
    aV = aN * 2 * (1 + nu) / (5 / 6)
    coup = aN * k * coupling
    extension, curvature = weight_terms(abs(k) * t / 2, nu) if weight else (0.0, 0.0)
    load_strain, load_curvature = -math.copysign(1, k) * aN * t * extension, -aN * curvature
    px, py = {"all": (0.0, -1.0), "normal": (c * sn, -c * c), "tangential": (-sn * c, -sn * sn)}[part]
    q = px * (-sn) + py * c  # the load's part along the extrados normal
    dY = np.zeros_like(Y)
    for j in range(Y.shape[1]):
        ux, uy, psi, fx, fy, M = Y[:, j]
        N, V = c * fx + sn * fy, -sn * fx + c * fy
        eps, rot = aN * axial * N + coup * M, aV * shear * V + psi
        b = 1.0 if j == load else 0.0
        eps += load_strain * (b * q)
        dY[:, j] = [eps * c - rot * sn, eps * sn + rot * c, bending * M + coup * N + load_curvature * (b * q), -b * px,
                    -b * py, sn * fx - c * fy + aN * k * b * (-sn * py - c * px)]
    return dY


def nearest_quadratic(table, x):
    """The quadratic through the three rows of table (x ascending in its first column) nearest x (the end
    ones beyond), each further column at x: ogive's interpolation of its tables."""
    i = 0
    while i + 3 < len(table) and x > 0.5 * (table[i + 1][0] + table[i + 2][0]):
        i += 1
    out = [0.0] * (len(table[0]) - 1)
    for a in range(i, i + 3):
        w = 1.0
        for b in range(i, i + 3):
            if b != a:
                w *= (x - table[b][0]) / (table[a][0] - table[b][0])
        for k in range(len(out)):
            out[k] += w * table[a][k + 1]
    return out


def held_curved(nu, t_kappa):
    """ogive's held face at the section's nu and t kappa (curved_section.cpp's held_face): the straight
    strip's (held.csv) at t_kappa 0, the ring's (ring.csv, continuum.py ring) at 0.2 to 0.5, each read at
    nu by quadratics, then over t_kappa: (c_NN, c_VV, c_VM, c_MM, c_NM)."""
    import csv
    import os
    here = os.path.dirname(os.path.abspath(__file__))
    keys = ("c_NN", "c_VV", "c_VM", "c_MM")
    straight = nearest_quadratic([[float(r["nu"])] + [float(r[k]) for k in keys] for r in csv.DictReader(open(os.path.join(here, "held.csv")))], nu)
    rows = list(csv.DictReader(open(os.path.join(here, "ring.csv"))))
    over = [[0.0] + straight + [0.0]]
    for tk in sorted({float(r["t_kappa"]) for r in rows}):
        at = [[float(r["nu"])] + [float(r[k]) for k in keys + ("c_NM",)] for r in rows if float(r["t_kappa"]) == tk]
        over.append([tk] + nearest_quadratic(at, nu))
    c = nearest_quadratic(over, abs(t_kappa))
    return tuple(c[:4]) + (math.copysign(c[4], t_kappa),)


def held_face(arch, t, c_held):
    """The held springing face's compliance (c_NN, c_VV, c_VM, c_MM of continuum.py strip, per E and t, and
    a curved bar's c_NM of continuum.py ring) as the 3 x 3 matrix from (Fx, Fy, M) to (Ux, Uy, psi) at the
    springing, scaled (E = 12 / t^3)."""
    cNN, cVV, cVM, cMM = c_held[:4]
    cNM = c_held[4] if len(c_held) > 4 else 0.0
    local = np.array([[cNN * t ** 3, 0, cNM * t ** 2], [0, cVV * t ** 3, cVM * t ** 2], [cNM * t ** 2, cVM * t ** 2, cMM * t]]) / 12
    th = arch.theta(0.0)
    T = np.array([[math.cos(th), math.sin(th), 0], [-math.sin(th), math.cos(th), 0], [0, 0, 1]])
    return T.T @ local @ T


def h_over_v(kind, t, supports="clamped", nu=0.2, held=None, joint=None, weight=False, part="all", held_load=None):
    """H/V of the half arch (t = t/L). held: the clamped springing face's (c_NN, c_VV, c_VM, c_MM[, c_NM]),
    or "curved" for ogive's (held_curved at the springing's t kappa);
    joint: the crown joint's scaled (a, b, c); weight: the self-weight's own stress across the depth;
    part: the weight's part that loads the arch (rates), its H over the whole weight's V; held_load: the
    held face's own displacement under a body force b (continuum.py held_body: a straight strip), its
    (u_N, Uy, psi) per b t^2 / E, b t^2 / E and b t / E (u_N under b along the axis, Uy and psi under b
    across it), added at the springing."""
    arch = Arch(kind)
    free = [3, 4, 5] if supports == "clamped" else [2, 3, 4]
    Y0 = np.zeros((6, 4))
    for j, i in enumerate(free):
        Y0[i, j] = 1.0
    if held == "curved":  # ogive's: the face's own curvature (held_curved)
        held = held_curved(nu, -t * arch.kappa(0.0))
    if held is not None and supports == "clamped":
        Y0[0:3, :] = held_face(arch, t, held) @ Y0[3:6, :]
    if held_load is not None and supports == "clamped":
        th = arch.theta(0.0)
        c, sn = math.cos(th), math.sin(th)
        # the weight per unit length is 1: b = 1 / t, E = 12 / t^3; along the axis -sin, across -cos
        local = np.array([held_load[0] * sn * t ** 4 / 12, held_load[1] * c * t ** 4 / 12, held_load[2] * c * t ** 3 / 12])
        Y0[0:3, 3] += np.array([[c, -sn, 0], [sn, c, 0], [0, 0, 1]]) @ local
    sol = solve_ivp(lambda s, y: rates(arch, t, nu, s, y.reshape(6, 4), 3, weight, part).ravel(), (0.0, arch.S), Y0.ravel(),
                    method="DOP853", rtol=1e-11, atol=1e-14)
    YS = sol.y[:, -1].reshape(6, 4)
    a, b, c = joint if joint is not None else (0.0, 0.0, 0.0)
    rows = np.array([YS[0] + b * YS[5] + c * YS[3], YS[2] + a * YS[5] + b * YS[3], YS[4]])
    z = np.linalg.solve(rows[:, :3], -rows[:, 3])
    y0 = Y0[:, :3] @ z + Y0[:, 3]
    return y0[3] / y0[4] if part == "all" else -y0[3] / arch.S


def crown_wedge(theta_c):
    """A pointed crown's wedge (ogive's crown_wedge), per E and t^2: wedge.csv's nu = 0 column at the
    crown tangent's angle (radians), which must be one of its nodes here (the equilateral arch's 30 deg)."""
    import csv
    import os
    rows = csv.DictReader(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "wedge.csv")))
    found = [float(r["a_nu_0"]) for r in rows if abs(float(r["theta_c_deg"]) - math.degrees(theta_c)) < 1e-6]
    return found[0]


def kink_joint(arch, t, nu=0.2, wedge=True):
    """The crown joint that the curved bar's own coupling gives a kinked axis: the bar's eps and psi' gain
    coupling kappa M and coupling kappa N (coupling = a_N (1 + 6 nu / 5) as t/R -> 0), and over the crown's
    turn, where kappa is a Dirac delta, their integrals are the half joint (0, -a_N (1 + 6 nu / 5) sin
    theta_c, 0): psi jumps by a_N coupling' int N dtheta = a_N coupling' Fx sin theta_c (Fy = 0 at the
    crown), Ux by a_N coupling' M int cos theta dtheta, the same. With `wedge` the pointed crown's wedge
    too, a = crown_wedge t / 12 (scaled: per E and t^2, E = 12 / t^3)."""
    theta_c = arch.theta(arch.S)
    a = crown_wedge(abs(theta_c)) * t / 12 if wedge else 0.0
    return (a, -t * t / 12 * (1 + 1.2 * nu) * math.sin(theta_c), 0.0)


def segment_compliance(kind, t, length, joint, nu=0.2):
    """The crown's last `length` of the half arch without weight, its lower section moved (Ux, psi) with Uy
    = 0 and the crown's conditions (with the joint): the 2 x 2 compliance from the section's (Fx, M) on the
    segment to (Ux, psi), scaled."""
    arch = Arch(kind)
    Y0 = np.zeros((6, 5))
    Y0[3, 0] = Y0[4, 1] = Y0[5, 2] = Y0[0, 3] = Y0[2, 4] = 1.0
    sol = solve_ivp(lambda s, y: rates(arch, t, nu, s, y.reshape(6, 5), -1).ravel(), (arch.S - length, arch.S),
                    Y0.ravel(), method="DOP853", rtol=1e-12, atol=1e-16)
    YS = sol.y[:, -1].reshape(6, 5)
    a, b, c = joint
    rows = np.array([YS[0] + b * YS[5] + c * YS[3], YS[2] + a * YS[5] + b * YS[3], YS[4]])
    K = np.zeros((2, 2))
    for j, col in enumerate((3, 4)):
        F = np.linalg.solve(rows[:, :3], -rows[:, col])  # Fx, Fy, M of the segment on the moved section
        K[:, j] = [-F[0], -F[2]]
    return np.linalg.inv(K)


def joint_from(kind, t, length, dC, nu=0.2):
    """The crown joint (a, b, c), scaled, whose segment compliance exceeds the jointless one by dC (the
    continuum's pointed crown less its radial one, the same segment): the joint is in series, so this is
    linear in (a, b, c)."""
    base = segment_compliance(kind, t, length, (0.0, 0.0, 0.0), nu)
    cols = [(segment_compliance(kind, t, length, J, nu) - base)[[0, 0, 1], [0, 1, 1]]
            for J in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))]
    return np.linalg.solve(np.array(cols).T, np.asarray(dC)[[0, 0, 1], [0, 1, 1]])
