#!/usr/bin/python3
"""An independent reference for `ogive spread` on walls: the semicircular arch (t/L = 0.1, the true weight
of its voussoirs) on two walls of the arch's density, h_w = L and b_w = 0.25 L, both leaning outwards by
the same rotation theta about their bases' outer toes.

No linear program and none of ogive's code: the symmetric three-hinge mechanism in closed form.
- The arch: radial joints, n per half, each voussoir an annular sector (its area and centroid exact).
- The left wall and the voussoirs from the springing up to the haunch hinge (intrados, joint k) turn as
  one rigid body by theta about the toe; the voussoirs from the hinge to the crown turn about the moved
  hinge by the angle that brings the crown's extrados point back onto the symmetry line (the right half
  mirrors the left one).
- The thrust: with the crown's force horizontal (symmetry) through the crown's extrados, the least H
  whose line passes above the intrados at every joint j of the half in the moved configuration,
  H_j = sum over the voussoirs from j to the crown of W (x - x_j) / (y_C - y_j): H = max_j H_j. The hinge
  is where the max is (it rolls down as the walls lean: the configuration is rebuilt with the hinge at
  the new joint until it stays put).
- The wall tips when the moment about its toe of the crown's thrust and of every weight of the half
  (wall and arch, where they have moved) turns outwards: M = H (y_C - y_T) - sum W (x - x_T) >= 0.
  theta at collapse: the root of M (bisection).
Prints the rotation at collapse, the wall top's horizontal displacement, the span's increase, H/V at
d = 0 and at collapse, and the hinge. With --compare OGIVE (run from the repository's top): also
ogive spread's numbers for the same system and their relative differences.
"""
import math
import sys

L = 10.0
t = 0.1 * L
R = L / 2  # the axis' radius
ri, re = R - t / 2, R + t / 2
hw, bw = L, 0.25 * L
args = [a for k, a in enumerate(sys.argv[1:]) if not a.startswith("--") and sys.argv[k] != "--compare"]
n = int(args[0]) if args else 8000  # voussoirs per half

# The left half: joints at angles from pi (springing) to pi/2 (crown); centre at the origin.
phis = [math.pi - (math.pi / 2) * k / n for k in range(n + 1)]
blocks = []  # (weight, centroid) with unit weight 1
for k in range(n):
    a, b = phis[k], phis[k + 1]
    dphi = a - b
    area = 0.5 * (re * re - ri * ri) * dphi
    rc = (2.0 / 3.0) * (re ** 3 - ri ** 3) / (re * re - ri * ri) * math.sin(dphi / 2) / (dphi / 2)
    m = 0.5 * (a + b)
    blocks.append((area, (rc * math.cos(m), rc * math.sin(m))))
V = sum(w for w, _ in blocks)  # the half arch's weight: V of each springing

# The wall: inner face under the springing's intrados point, outer face b_w further out, base h_w below
# the springing line; the toe its outer bottom corner.
x_in = -ri
toe = (x_in - bw, -hw)
wall_weight = bw * hw
wall_centroid = (x_in - bw / 2, -hw / 2)
crown = (0.0, re)  # the crown joint's extrados point


def rot(p, about, ang):
    c, s = math.cos(ang), math.sin(ang)
    dx, dy = p[0] - about[0], p[1] - about[1]
    return (about[0] + c * dx - s * dy, about[1] + s * dx + c * dy)


def intrados(k):
    return (ri * math.cos(phis[k]), ri * math.sin(phis[k]))


def configuration(theta, hinge):
    """The motions of the lower body (wall and voussoirs below the hinge) and of the upper one."""
    P = intrados(hinge)
    Pm = rot(P, toe, theta)
    # The upper body: x -> Pm + R(w) (x - P); the crown's extrados on x = 0. Newton from w = theta.
    cx, cy = crown[0] - P[0], crown[1] - P[1]
    w = theta
    for _ in range(60):
        f = Pm[0] + math.cos(w) * cx - math.sin(w) * cy
        df = -math.sin(w) * cx - math.cos(w) * cy
        step = f / df
        w -= step
        if abs(step) < 1e-16:
            break
    lower = lambda p: rot(p, toe, theta)
    upper = lambda p: (Pm[0] + math.cos(w) * (p[0] - P[0]) - math.sin(w) * (p[1] - P[1]),
                       Pm[1] + math.sin(w) * (p[0] - P[0]) + math.cos(w) * (p[1] - P[1]))
    return lower, upper


def state(theta, hinge):
    lower, upper = configuration(theta, hinge)
    C = upper(crown)
    moved = [(w, lower(c) if k < hinge else upper(c)) for k, (w, c) in enumerate(blocks)]
    best, arg = -1.0, None
    # H_j for every intrados joint of the half but the crown's (a suffix sum of the loads' moments).
    sw, swx = 0.0, 0.0
    for j in range(n - 1, -1, -1):
        w, c = moved[j]
        sw += w
        swx += w * c[0]
        I = lower(intrados(j)) if j <= hinge else upper(intrados(j))
        Hj = (swx - sw * I[0]) / (C[1] - I[1])
        if Hj > best:
            best, arg = Hj, j
    return best, arg, C, moved, lower


def settled(theta, hinge):
    for _ in range(200):
        H, arg, C, moved, lower = state(theta, hinge)
        if arg == hinge:
            return H, hinge, C, moved, lower
        hinge = arg
    raise RuntimeError("the hinge does not settle")


def tipping_moment(theta, hinge):
    H, hinge, C, moved, lower = settled(theta, hinge)
    M = H * (C[1] - toe[1])
    for w, c in moved:
        M -= w * (c[0] - toe[0])
    wc = lower(wall_centroid)
    M -= wall_weight * (wc[0] - toe[0])
    return M, H, hinge


H0, hinge0, _, _, _ = settled(0.0, n // 2)
M0, _, _ = tipping_moment(0.0, hinge0)
assert M0 < 0, "the wall tips at d = 0"
# March theta up (the hinge rolls), then bisect the first sign change of M.
theta, step, hinge = 0.0, 1e-3, hinge0
while True:
    M, H, hinge = tipping_moment(theta + step, hinge)
    if M >= 0:
        break
    theta += step
lo, hi = theta, theta + step
for _ in range(60):
    mid = 0.5 * (lo + hi)
    M, H, h = tipping_moment(mid, hinge)
    if M >= 0:
        hi = mid
    else:
        lo, hinge = mid, h
theta_c = lo
M, Hc, hinge = tipping_moment(theta_c, hinge)
top = (toe[0], 0.0)  # the wall top's outer corner
top_moved = rot(top, toe, theta_c)
I0 = (x_in, 0.0)  # the springing's intrados point on the wall's top
span_increase = 2 * (I0[0] - rot(I0, toe, theta_c)[0])
x_hinge = intrados(hinge)[0] + R  # from the left springing's axis point
print("voussoirs_per_half,theta_collapse,top_displacement,spread_capacity_ratio,H_over_V_d0,H_over_V_collapse,"
      "hinge0_x_over_L,hinge_collapse_x_over_L")
print(f"{n},{theta_c:.7g},{top[0] - top_moved[0]:.7g},{span_increase / L:.7g},{H0 / V:.7g},{Hc / V:.7g},"
      f"{(intrados(hinge0)[0] + R) / L:.6g},{x_hinge / L:.6g}")

if "--compare" in sys.argv:
    import subprocess
    ogive = sys.argv[sys.argv.index("--compare") + 1]
    out = subprocess.run([ogive, "spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--weight", "voussoir",
                          "--wall-height", str(hw), "--wall-thickness", str(bw), "--columns",
                          "left_wall_rotation_collapse,left_wall_top_displacement_collapse,spread_capacity_ratio,"
                          "H_over_V_plateau,H_over_V_collapse,collapse"], capture_output=True, text=True, check=True).stdout
    names, values = [line.split(",") for line in out.strip().splitlines()]
    row = dict(zip(names, values))
    print("quantity,script,ogive,relative_difference")
    for name, mine in [("left_wall_rotation_collapse", theta_c), ("left_wall_top_displacement_collapse", top[0] - top_moved[0]),
                       ("spread_capacity_ratio", span_increase / L), ("H_over_V_plateau", H0 / V),
                       ("H_over_V_collapse", Hc / V)]:
        theirs = float(row[name])
        print(f"{name},{mine:.7g},{theirs:.7g},{abs(theirs - mine) / abs(mine):.1e}")
    print(f"collapse,wall_tips,{row['collapse']},")
