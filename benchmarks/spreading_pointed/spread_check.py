#!/usr/bin/env python3
"""An independent check of `ogive spread` on the equilateral arch (pointed, eccentricity 0.5: two arcs of
radius L centred on the opposite springings), the weight on the axis (rho g t per length of axis, at the
centroid of each voussoir's piece of axis: `--weight axis`), both springings moving apart alike. Its own
ring, statics and kinematics (numpy alone; nothing of ogive's).

The model (docs/spreading.md):
- the ring: radial joints equally spaced in angle from the springing bed to the radial joint through the
  intrados' crown point, then the wedge up to the vertical crown joint;
- the symmetric four-hinge mechanism of the state at d = 0 (the line of thrust touching the intrados at
  the haunches and the extrados on both sides of the crown): on the left half, the springing's piece
  below the haunch hinge b (intrados) moves out with its support by u = d / 2, the piece between b and
  the extrados hinge c turns about b, and the crown block between the two extrados hinges drops without
  turning; every other joint is closed, the voussoirs placed from the ring at d = 0 by these rigid
  motions, a hinge's joint midway between its two faces;
- the state: the line of thrust through the two hinges of each half and horizontal at the crown (by
  symmetry); it must lie inside every joint (no tension);
- the path: at d = 0 the hinges are the joints where the least-thrust line of that form fits (a search
  over b and c); they stay while their line fits, and where it no longer does, they roll to the joints
  where the line now leaves the faces (b to the intrados' worst joint, c to the extrados'), until it
  fits; where no hinges near the last ones give a line that fits, the arch collapses (bisected to
  1e-7 L).

Options: --joints N (radial joints over the half, default 4000), --thickness-ratio LIST, --increment
(the span's increase per step over L, default 2.5e-4), --weight axis (the default) or voussoir (each
voussoir's true weight at its centroid, `--weight voussoir`: an annular sector's, and for the crown
wedge the extrados' sector less the triangle of its centre and the crown joint). Prints t/L, the capacity (the span's increase at
collapse over L), H/V at d = 0 and at collapse, and the hinges' x/L (on the ring at d = 0).
"""
import argparse
import math

import numpy as np

L = 1.0
R = 1.0  # eccentricity 0.5: R = (0.5 + 0.5) L
CENTRE = np.array([1.0, 0.0])  # the left arc's centre (the right springing's axis point)
A_CROWN = math.pi / 3


def cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


class Half:
    """The left half: joints 0 (springing bed) .. n (radial, through the intrados' crown point) and n + 1
    (the vertical crown joint); voussoirs 0 .. n (the last one the crown wedge)."""

    def __init__(self, n, t, extra=(), weight='axis'):
        ri, re = R - t / 2, R + t / 2
        a_i = math.acos((CENTRE[0] - L / 2) / ri)
        a_e = math.acos((CENTRE[0] - L / 2) / re)
        a = np.linspace(0.0, a_i, n + 1) if n > 0 else np.array([0.0, a_i])
        a = np.unique(np.concatenate([a, [x for x in extra if 0 < x < a_i]]))
        n = len(a) - 1
        d = np.stack([-np.cos(a), np.sin(a)], axis=1)
        I = CENTRE + ri * d
        E = CENTRE + re * d
        I = np.vstack([I, [L / 2, ri * math.sin(a_i)]])
        E = np.vstack([E, [L / 2, re * math.sin(a_e)]])
        lo = a.copy()  # voussoir k from angle lo[k] to hi[k]
        hi = np.append(a[1:], A_CROWN)
        da = hi - lo
        mid = 0.5 * (lo + hi)
        w = t * R * da  # unit weight: rho g = 1
        if weight == 'axis':
            rc = R * np.sin(da / 2) / (da / 2)
        else:  # the annular sector's centroid (its area is t R da too)
            rc = 2.0 / 3.0 * (re**3 - ri**3) / (re**2 - ri**2) * np.sin(da / 2) / (da / 2)
        g = CENTRE + rc[:, None] * np.stack([-np.cos(mid), np.sin(mid)], axis=1)
        if weight == 'voussoir':
            # The crown wedge, from the radial joint through the intrados' crown point to the vertical
            # crown joint under the extrados: the extrados' sector from a_i to a_e less the triangle of
            # the centre and the crown joint's two ends.
            th = a_e - a_i
            sector_area = 0.5 * re**2 * th
            sector_c = CENTRE + (4 * re * math.sin(th / 2) / (3 * th)) * np.array([-math.cos(a_i + th / 2),
                                                                                   math.sin(a_i + th / 2)])
            tri = [CENTRE, I[-1], E[-1]]
            tri_area = 0.5 * abs(cross(tri[1] - tri[0], tri[2] - tri[0]))
            tri_c = (tri[0] + tri[1] + tri[2]) / 3
            w[-1] = sector_area - tri_area
            g[-1] = (sector_area * sector_c - tri_area * tri_c) / w[-1]
        self.n, self.t, self.I, self.E, self.w, self.g, self.a = n, t, I, E, w, g, a
        self.V = w.sum()

    def state(self, b, c, u):
        """Hinges b (intrados) and c (extrados, b < c <= n) when each springing has moved out by u: H, the
        least margin (m) of the line of thrust inside the half's joints other than the hinges (< 0: it
        leaves the arch), the joint of the least margin on each face, or None where the chain cannot close."""
        I0, E0, w, g, n = self.I, self.E, self.w, self.g, self.n
        v = E0[c] - I0[b]
        r = math.hypot(v[0], v[1])
        if (v[0] + u) / r > 1:
            return None
        psi = math.acos((v[0] + u) / r) - math.atan2(v[1], v[0])  # the middle piece's rotation (< 0)
        Q = np.array([[math.cos(psi), -math.sin(psi)], [math.sin(psi), math.cos(psi)]])
        pb = I0[b] + np.array([-u, 0.0])
        mid = lambda x: pb + (x - I0[b]) @ Q.T
        drop = E0[c][1] - mid(E0[c])[1]
        low, top = np.array([-u, 0.0]), np.array([0.0, -drop])
        # Each voussoir's and joint's motion: springing piece (< b), middle piece, crown block (>= c).
        gm = g + low
        gm[b:c] = mid(g[b:c])
        gm[c:] = g[c:] + top
        Im, Em = I0 + low, E0 + low
        Im[b + 1:c], Em[b + 1:c] = mid(I0[b + 1:c]), mid(E0[b + 1:c])
        Im[c + 1:], Em[c + 1:] = I0[c + 1:] + top, E0[c + 1:] + top
        Im[b], Em[b] = 0.5 * (I0[b] + low + mid(I0[b])), 0.5 * (E0[b] + low + mid(E0[b]))
        Im[c], Em[c] = 0.5 * (mid(I0[c]) + I0[c] + top), 0.5 * (mid(E0[c]) + E0[c] + top)
        if b == 0:
            Im[0], Em[0] = I0[0] + low, E0[0] + low
        # The line through Im[b] and Em[c], horizontal at the crown: H (y0 - p_y) = sum w (g_x - p_x)
        # about each hinge's point p of the parts above it.
        mb = float(np.sum(w[b:] * (gm[b:, 0] - Im[b][0])))
        mc = float(np.sum(w[c:] * (gm[c:, 0] - Em[c][0])))
        H = (mb - mc) / (Em[c][1] - Im[b][1])
        y0 = Em[c][1] + mc / H
        # Every joint j: the part from it to the crown holds (-H, 0) at (L/2, y0) and its weights; the
        # rest pushes it with F = (H, W_j) through the joint's point at s (0 intrados, 1 extrados).
        W = np.concatenate([np.cumsum(w[::-1])[::-1], [0.0]])
        Mw = np.concatenate([np.cumsum((w * gm[:, 0])[::-1])[::-1], [0.0]])
        F = np.stack([np.full(n + 2, H), W], axis=1)
        M = Mw - H * y0
        dj = Em - Im
        with np.errstate(invalid='ignore', divide='ignore'):  # a degenerate joint (none on a path)
            s = (M - cross(Im, F)) / cross(dj, F)
        h = np.linalg.norm(dj, axis=1)
        # the crown joint carries (H, 0): its point is y0 on the vertical joint
        s[n + 1] = (y0 - Im[n + 1][1]) / (Em[n + 1][1] - Im[n + 1][1])
        lo_m, hi_m = np.nan_to_num(s * h, nan=-np.inf), np.nan_to_num((1 - s) * h, nan=-np.inf)
        lo_m[b] = np.inf
        hi_m[c] = np.inf
        ji, je = int(np.argmin(lo_m)), int(np.argmin(hi_m))
        return H, float(lo_m[ji]), ji, float(hi_m[je]), je, drop

    def fits(self, b, c, u, tol):
        st = self.state(b, c, u)
        return st is not None and min(st[1], st[3]) >= -tol


def settle(half, b, c, u, tol, most=400):
    """The hinges at u from (b, c): each that its line leaves a face rolls to that face's worst joint,
    until the line fits (None: it finds none, or the hinges would leave the half)."""
    seen = set()
    for _ in range(most):
        st = half.state(b, c, u)
        if st is None:
            return None
        _, lo, ji, hi, je, _ = st
        if min(lo, hi) >= -tol:
            return b, c
        if (b, c) in seen:
            return None
        seen.add((b, c))
        if lo < -tol and (lo <= hi or hi >= -tol):
            b = ji
        else:
            c = je
        if not (0 <= b < c <= half.n):
            return None
    return None


def start(half, tol):
    """The hinges at d = 0: the least thrust over (b, c) whose line fits (a coarse scan, then rolled to
    the contacts; then the neighbours of that pair searched for a lower thrust)."""
    n = half.n
    step = max(1, n // 100)
    best = None
    for b in range(0, n, step):
        for c in range(b + step, n + 1, step):
            st = half.state(b, c, 0.0)
            if st is None or min(st[1], st[3]) < -1e-3 * half.t:
                continue
            if best is None or st[0] < best[0]:
                best = (st[0], b, c)
    b, c = settle(half, best[1], best[2], 0.0, tol)
    # the least H among fitting pairs near it
    H = half.state(b, c, 0.0)[0]
    improved = True
    while improved:
        improved = False
        for db in (-1, 0, 1):
            for dc in (-1, 0, 1):
                nb, nc = b + db, c + dc
                if (db or dc) and 0 <= nb < nc <= n and half.fits(nb, nc, 0.0, tol):
                    Hn = half.state(nb, nc, 0.0)[0]
                    if Hn < H - 1e-15 * H:
                        b, c, H, improved = nb, nc, Hn, True
    return b, c


def tangent_angles(t, weight):
    """The hinges of the continuous arch at d = 0: the angles (from the springing) of the intrados and
    extrados points where the least-thrust line touches the faces. Any line inside the arch passes
    above the intrados at b and below the extrados at c, so its thrust is at least that of the line
    through both (horizontal at the crown): the least thrust is the largest of those, found over the
    two angles on a ring with joints there alone (the loads' moments do not depend on the joints)."""
    def H(x):
        half = Half(0, t, x, weight)
        ib, ic = int(np.searchsorted(half.a, x[0])), int(np.searchsorted(half.a, x[1]))
        st = half.state(ib, ic, 0.0)
        return st[0]
    a_i = math.acos((CENTRE[0] - L / 2) / (R - t / 2))
    best = None
    for xb in np.linspace(0.02, 0.6, 30) * a_i:  # a coarse scan, then golden sections on each angle
        for xc in np.linspace(0.5, 0.98, 25) * a_i:
            if xc > xb and (best is None or H((xb, xc)) > best[0]):
                best = (H((xb, xc)), xb, xc)
    xb, xc = best[1], best[2]
    step = 0.05 * a_i
    for _ in range(4):
        xb = golden(lambda v: -H((v, xc)), max(1e-9, xb - step), min(xc - 1e-9, xb + step))
        xc = golden(lambda v: -H((xb, v)), max(xb + 1e-9, xc - step), min(a_i - 1e-12, xc + step))
        step *= 0.1
    return xb, xc


def golden(f, lo, hi, tol=1e-13):
    g = (math.sqrt(5) - 1) / 2
    x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
    f1, f2 = f(x1), f(x2)
    while hi - lo > tol:
        if f1 < f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - g * (hi - lo)
            f1 = f(x1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + g * (hi - lo)
            f2 = f(x2)
    return 0.5 * (lo + hi)


def capacity(n, t, increment, tol_ratio=1e-12, exact=True, weight='axis'):
    half = Half(n, t, tangent_angles(t, weight) if exact else (), weight)
    tol = tol_ratio * L
    b, c = start(half, tol)
    H0 = half.state(b, c, 0.0)[0]
    hinges0 = (half.I[b][0], half.E[c][0])
    u, du = 0.0, increment * L / 2
    while True:
        nxt = settle(half, b, c, u + du, tol)
        if nxt is None:
            lo_u, hi_u = u, u + du
            while hi_u - lo_u > 0.5e-7 * L:
                m = 0.5 * (lo_u + hi_u)
                r = settle(half, b, c, m, tol)
                if r is None:
                    hi_u = m
                else:
                    lo_u, (b, c) = m, r
            u = lo_u
            break
        (b, c), u = nxt, u + du
    H = half.state(b, c, u)[0]
    return 2 * u / L, H0 / half.V, H / half.V, hinges0, (half.I[b][0], half.E[c][0]), (b, c)


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--joints', type=int, default=4000)
    p.add_argument('--thickness-ratio', default='0.06,0.1,0.14')
    p.add_argument('--increment', type=float, default=2.5e-4)
    p.add_argument('--weight', choices=('axis', 'voussoir'), default='axis')
    o = p.parse_args()
    print('joints,thickness_ratio,capacity,H_over_V_d0,H_over_V_collapse,hinges_d0,hinges_collapse')
    for t in o.thickness_ratio.split(','):
        cap, hv0, hv, h0, h1, _ = capacity(o.joints, float(t), o.increment, weight=o.weight)
        print(f'{o.joints},{t},{cap:.6f},{hv0:.6f},{hv:.6f},{h0[0]:.6f}:intrados;{h0[1]:.6f}:extrados,'
              f'{h1[0]:.6f}:intrados;{h1[1]:.6f}:extrados', flush=True)


if __name__ == '__main__':
    main()
