#!/usr/bin/env python3
"""An independent check of `ogive spread --compressive-strength`: the semicircle of t/L 0.10 (L = 10 m,
rho = 2348 kg/m^3, g = 9.81, the true voussoir weight) on supports spreading symmetrically, as a
three-hinge mechanism of rigid voussoirs whose hinges crush. Its own ring, statics and kinematics (numpy
and scipy only; nothing of ogive's).

The model (the one docs/material-strength.md states):
- no tension, rigid-perfectly-plastic in compression: a joint of length h carrying N bears it on a stress
  block N / f_c deep at the face it turns on; the resultant crosses N / (2 f_c) inside that face, and every
  joint's resultant keeps N / (2 f_c) clear of both faces;
- the blocks turn about the stress block's inner edge, N / f_c inside the face (the neutral axis: the flow
  rule of |M| <= N (h/2 - N / (2 f_c))), at the depth this state's normal force gives (the placement is
  made again until the depths and the state agree);
- the half arch (by symmetry): the springing piece below the haunch hinge moves out with its support,
  the piece above turns about the haunch hinge so that the crown hinge stays on the symmetry axis; a
  hinge's joint is taken midway between its two faces;
- the path: the haunch hinge forms at d = 0 where the three-hinge line of thrust fits (the minimum-thrust
  state) and stays there while that line fits; where it no longer does, it rolls to the nearest joint
  (within 0.05 L along the intrados) where it does; where none does, the arch collapses (bisected).

Options: --joints N (joints over the whole arch, default 4001), --fc LIST (Pa; inf for none),
--turn centre (turn about the stress block's centre instead, to show what the choice moves),
--shift K (start the haunch hinge K joints from where it forms, to show how the capacity follows it),
--roll none (the hinge stays where it formed: the path ends where its line no longer fits).
Prints the capacity (the span's increase at collapse over L), H/V there and the hinge's angle.
"""
import argparse
import math
import sys

import numpy as np
from scipy.optimize import brentq

L, T, RHO, G = 10.0, 1.0, 2348.0, 9.81
R = L / 2
RI, RE = R - T / 2, R + T / 2
MID_PATH = 0.0695  # a span increase along the path (over L) where H / V is printed


def ring(n):
    """Joints at angles a from the left springing (0) to the crown (pi/2), on the left half."""
    m = (n - 1) // 2
    a = np.linspace(0, math.pi / 2, m + 1)
    e = np.stack([-np.cos(a), np.sin(a)], axis=1)  # the joint's direction, intrados to extrados
    I, E = RI * e, RE * e
    da = a[1:] - a[:-1]
    mid = 0.5 * (a[1:] + a[:-1])
    w = RHO * G * 0.5 * (RE**2 - RI**2) * da  # each voussoir's weight, N/m
    rc = (2.0 / 3.0) * (RE**3 - RI**3) / (RE**2 - RI**2) * np.sin(da / 2) / (da / 2)
    g = rc[:, None] * np.stack([-np.cos(mid), np.sin(mid)], axis=1)
    return a, I, E, w, g


def rot(psi):
    c, s = math.cos(psi), math.sin(psi)
    return np.array([[c, -s], [s, c]])


def cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


class Half:
    def __init__(self, n, fc, turn):
        self.a, self.I, self.E, self.w, self.g = ring(n)
        self.m = len(self.a) - 1
        self.fc, self.turn = fc, turn
        self.V = self.w.sum()

    def state(self, b, u):
        """The state with the haunch hinge at joint b when each support has moved out by u: H, the
        least margin of the resultant to the stress blocks' limits over the half's joints (m, < 0: the
        line does not fit), and the hinge's rotation; None where the chain does not close."""
        I, E, w, g, m, fc = self.I, self.E, self.w, self.g, self.m, self.fc
        finite = math.isfinite(fc)
        depth = 1.0 if self.turn == 'edge' else 0.5  # the turning point's depth, in units of N / f_c
        a_h = a_c = 0.0
        for _ in range(100):
            eb = (E[b] - I[b]) / T
            ph0 = I[b] + depth * a_h * eb            # the haunch turning point on the unmoved ring
            ph = ph0 + np.array([-u, 0.0])
            q0 = np.array([0.0, RE - depth * a_c])   # the crown turning point
            v = q0 - ph0
            f = lambda psi: ph[0] + v[0] * math.cos(psi) - v[1] * math.sin(psi)
            try:
                psi = brentq(f, -0.6, 0.3, xtol=1e-15)
            except ValueError:
                return None
            Q = rot(psi)
            B = lambda x: ph + (x - ph0) @ Q.T
            shift = np.array([-u, 0.0])
            Im, Em = I + shift, E + shift
            Im[b + 1:], Em[b + 1:] = B(I[b + 1:]), B(E[b + 1:])
            Im[b], Em[b] = 0.5 * (I[b] + shift + B(I[b])), 0.5 * (E[b] + shift + B(E[b]))
            Im[m], Em[m] = np.array([0.0, B(I[m])[1]]), np.array([0.0, B(E[m])[1]])  # midway: its mirror
            gm = g + shift
            gm[b:] = B(g[b:])
            # The resultants' points: the haunch's N_h / (2 f_c) above the intrados, the crown's H / (2 f_c)
            # below the extrados, on the joints midway between their faces.
            eh = (Em[b] - Im[b]) / np.linalg.norm(Em[b] - Im[b])
            rh = Im[b] + 0.5 * a_h * eh
            c = Em[m] - np.array([0.0, 0.5 * a_c])
            H = float(np.sum(w[b:] * (gm[b:, 0] - rh[0])) / (c[1] - rh[1]))
            Wb = w[b:].sum()
            Nh = H * eh[1] - Wb * eh[0]  # the normal force across the haunch joint
            new_h, new_c = (Nh / fc, H / fc) if finite else (0.0, 0.0)
            if abs(new_h - a_h) + abs(new_c - a_c) <= 1e-14:
                break
            a_h, a_c = new_h, new_c
        # Every joint of the half: the part from it to the crown holds the crown's (-H, 0) at c and its
        # weights; the lower part pushes it with (H, W_j) through x_j = I_j + s (E_j - I_j).
        W = np.concatenate([np.cumsum(w[::-1])[::-1], [0.0]])
        Mw = np.concatenate([np.cumsum((w * gm[:, 0])[::-1])[::-1], [0.0]])
        F = np.stack([np.full(m + 1, H), W], axis=1)
        M = Mw - H * c[1]
        d = Em - Im
        s = (M - cross(Im, F)) / cross(d, F)
        h = np.linalg.norm(d, axis=1)
        n = np.stack([d[:, 1], -d[:, 0]], axis=1) / h[:, None]
        N = np.sum(F * n, axis=1)
        half_block = N / (2 * fc) if finite else 0.0 * N
        margin = np.minimum(s * h - half_block, (1 - s) * h - half_block)
        margin[b] = margin[m] = 0.0  # the hinges, there by construction
        return H, float(margin[:m].min()), psi

    def fits(self, b, u):
        st = self.state(b, u)
        return st is not None and st[1] >= -1e-9, st


def capacity(n, fc, turn, shift, roll, step=2.5e-4):
    half = Half(n, fc, turn)
    # d = 0: the joint where the three-hinge line fits (the minimum-thrust state's haunch hinge).
    lo, hi = int(0.1 * half.m), int(0.9 * half.m)
    ok = [b for b in range(lo, hi) if half.fits(b, 0.0)[0]]
    if not ok:
        sys.exit('no three-hinge line fits at d = 0')
    b = ok[len(ok) // 2] + shift
    reach = int(0.05 * L / (RI * (half.a[1] - half.a[0])))
    u = 0.0
    du = step * L / 2

    def settle(b, u):
        if half.fits(b, u)[0]:
            return b
        if roll == 'none':
            return None
        for k in range(1, reach + 1):
            for c in (b - k, b + k):
                if 0 < c < half.m and half.fits(c, u)[0]:
                    return c
        return None

    mid_path = None  # H / V at a span increase of MID_PATH L
    while True:
        if mid_path is None and 2 * u / L >= MID_PATH - 1e-12:
            mid_path = half.state(b, MID_PATH * L / 2)[0] / half.V
        nb = settle(b, u + du)
        if nb is None:
            lo_u, hi_u = u, u + du
            while hi_u - lo_u > 0.5e-6 * L:
                mid = 0.5 * (lo_u + hi_u)
                mb = settle(b, mid)
                if mb is None:
                    hi_u = mid
                else:
                    lo_u, b = mid, mb
            u = lo_u
            break
        b, u = nb, u + du
    H = half.state(b, u)[0]
    return 2 * u / L, H / half.V, math.degrees(half.a[b]), len(ok), mid_path


def main():
    p = argparse.ArgumentParser()
    p.add_argument('--joints', type=int, default=4001)
    p.add_argument('--fc', default='inf,2e6,1e6')
    p.add_argument('--turn', default='edge', choices=['edge', 'centre'])
    p.add_argument('--shift', type=int, default=0)
    p.add_argument('--roll', default='nearest', choices=['nearest', 'none'])
    o = p.parse_args()
    print('joints,f_c,turn,shift,roll,capacity,H_over_V_collapse,hinge_angle_deg,joints_fitting_at_d0,H_over_V_mid_path')
    for fc in o.fc.split(','):
        cap, hv, ang, nfit, mid = capacity(o.joints, float(fc), o.turn, o.shift, o.roll)
        mid = '' if mid is None else f'{mid:.6f}'  # collapse before MID_PATH
        print(f'{o.joints},{fc},{o.turn},{o.shift},{o.roll},{cap:.6f},{hv:.5f},{ang:.4f},{nfit},{mid}', flush=True)


if __name__ == '__main__':
    main()
