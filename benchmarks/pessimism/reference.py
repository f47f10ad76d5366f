"""An independent reference in 40-digit decimal arithmetic: the symmetric circular arch (semicircular,
pointed, segmental) with clamped springings under its own weight, each springing moved outwards by d.

It shares no code with ogive: the local equations of docs/model.md (constant matrix on an arc, the
self-weight carried by two appended states cos theta and sin theta), the exponential by scaling and
squaring of its Taylor series, the half arch's three unknowns (Fx, Fy, M at the springing) from the
crown's three conditions (Ux = 0, psi = 0, Fy = 0). Round-off in 40 digits is some 1e-35: its numbers
are exact for the purpose of measuring errors of 1e-16 and above.

Standard library only (decimal).
"""
from decimal import Decimal as D, getcontext

getcontext().prec = 40


def _pi():
    # The decimal module's recipe (Python documentation).
    getcontext().prec += 2
    three = D(3)
    lasts, t, s, n, na, d, da = 0, three, 3, 1, 0, 0, 24
    while s != lasts:
        lasts = s
        n, na = n + na, na + 8
        d, da = d + da, da + 32
        t = (t * n) / d
        s += t
    getcontext().prec -= 2
    return +s


PI = _pi()


def _cos(x):
    getcontext().prec += 2
    i, lasts, s, fact, num, sign = 0, 0, D(1), 1, D(1), 1
    while s != lasts:
        lasts = s
        i += 2
        fact *= i * (i - 1)
        num *= x * x
        sign *= -1
        s += num / fact * sign
    getcontext().prec -= 2
    return +s


def _sin(x):
    return _cos(PI / 2 - x)


def _acos(c):
    # Newton on cos(phi) = c from a float start.
    import math
    phi = D(repr(math.acos(float(c))))
    for _ in range(6):
        phi -= (_cos(phi) - c) / (-_sin(phi))
    return phi


def _asin(x):
    return PI / 2 - _acos(x)


def _matmul(a, b):
    n, m, p = len(a), len(b), len(b[0])
    return [[sum((a[i][k] * b[k][j] for k in range(m)), D(0)) for j in range(p)] for i in range(n)]


def _expm(a):
    n = len(a)
    norm = max(sum(abs(x) for x in row) for row in a)
    k = 0
    while norm > D("0.01"):
        norm /= 2
        k += 1
    scaled = [[x / (D(2) ** k) for x in row] for row in a]
    result = [[D(int(i == j)) for j in range(n)] for i in range(n)]
    term = [row[:] for row in result]
    for m in range(1, 40):
        term = _matmul(term, scaled)
        term = [[x / m for x in row] for row in term]
        result = [[result[i][j] + term[i][j] for j in range(n)] for i in range(n)]
    for _ in range(k):
        result = _matmul(result, result)
    return result


def _solve3(a, b):
    a = [row[:] + [bb] for row, bb in zip(a, b)]
    for c in range(3):
        p = max(range(c, 3), key=lambda r: abs(a[r][c]))
        a[c], a[p] = a[p], a[c]
        for r in range(3):
            if r != c:
                f = a[r][c] / a[c][c]
                a[r] = [x - f * y for x, y in zip(a[r], a[c])]
    return [a[i][3] / a[i][i] for i in range(3)]


def half_arch(curve, span, thickness, eccentricity=0.0, rise=None, d_ratio=0.0, E=14.8e9, nu=0.2,
              rho=2348.0, g=9.81, k_shear=5 / 6):
    """Radius R, springing tangent angle theta0 and half length S of a circular half arch."""
    L = D(repr(span))
    if curve == "semicircular":
        R = L / 2
        return R, PI / 2, R * PI / 2
    if curve == "pointed":
        eps = D(repr(eccentricity))
        R = (D("0.5") + eps) * L
        alpha = _acos(eps / (D("0.5") + eps))
        return R, PI / 2, R * alpha
    if curve == "segmental":
        h = D(repr(rise)) * L
        R = (L * L / 4 + h * h) / (2 * h)
        beta = _asin(L / (2 * R))
        return R, beta, R * beta
    raise ValueError(curve)


def solve(curve, span=10.0, thickness_ratio=0.08, eccentricity=0.0, rise=None, d_ratio=0.0, stations=41,
          E=14.8e9, nu=0.2, rho=2348.0, g=9.81, k_shear=5 / 6):
    """Reactions (dict as ogive's H_left .. M_right) and the profile at `stations` equally spaced
    stations springing to springing (dicts of Ux, Uy, psi, N, shear_force, M), as floats."""
    L = D(repr(span))
    t = D(repr(thickness_ratio)) * L
    Ed, G = D(repr(E)), D(repr(E)) / (2 * (1 + D(repr(nu))))
    EA, kGA, EI = Ed * t, D(repr(k_shear)) * G * t, Ed * t ** 3 / 12
    w = D(repr(rho)) * D(repr(g)) * t
    R, th0, S = half_arch(curve, span, thickness_ratio, eccentricity, rise)
    kap = -1 / R
    d = D(repr(d_ratio)) * L

    def A(l):
        a = [[D(0)] * 8 for _ in range(8)]
        a[0][1], a[0][3] = kap, 1 / EA
        a[1][0], a[1][2], a[1][4] = -kap, D(1), 1 / kGA
        a[2][5] = 1 / EI
        a[3][4], a[3][7] = kap, w
        a[4][3], a[4][6] = -kap, w
        a[5][4] = D(-1)
        a[6][7] = -kap
        a[7][6] = kap
        return [[x * l for x in row] for row in a]

    c0, s0 = _cos(th0), _sin(th0)

    def to_local(y, c, s):
        ux, uy, psi, fx, fy, m = y
        return [ux * c + uy * s, -ux * s + uy * c, psi, fx * c + fy * s, -fx * s + fy * c, m]

    def to_global(y, c, s):
        u, v, psi, n, sh, m = y
        return [u * c - v * s, u * s + v * c, psi, n * c - sh * s, n * s + sh * c, m]

    def state_at(y0, l, E8=None):
        E8 = E8 or _expm(A(l))
        z = to_local(y0, c0, s0) + [c0, s0]
        zl = [sum(E8[i][j] * z[j] for j in range(8)) for i in range(8)]
        th = th0 + kap * l
        return to_global(zl[:6], _cos(th), _sin(th)), th

    ES = _expm(A(S))

    def crown(y0):
        y, _ = state_at(y0, S, ES)
        return [y[0], y[2], y[4]]  # Ux, psi, Fy

    base = [-d, D(0), D(0), D(0), D(0), D(0)]
    r0 = crown(base)
    cols = []
    for k in range(3):
        y = base[:]
        y[3 + k] = D(1)
        rk = crown(y)
        cols.append([rk[i] - r0[i] for i in range(3)])
    mat = [[cols[j][i] for j in range(3)] for i in range(3)]
    fx, fy, m = _solve3(mat, [-x for x in r0])
    y0 = [-d, D(0), D(0), fx, fy, m]
    reactions = {"H_left": float(-fx), "V_left": float(-fy), "M_left": float(-m),
                 "H_right": float(-fx), "V_right": float(-fy), "M_right": float(m)}
    profile = []
    for i in range(stations):
        # A station at the crown is its left side's state (a pointed crown's shear force jumps there).
        mirrored = 2 * i > stations - 1
        j = stations - 1 - i if mirrored else i
        l = 2 * S * j / (stations - 1)
        y, th = state_at(y0, l)
        c, s = _cos(th), _sin(th)
        n = y[3] * c + y[4] * s
        sh = -y[3] * s + y[4] * c
        sign = -1 if mirrored else 1
        profile.append({"Ux": float(sign * y[0]), "Uy": float(y[1]), "psi": float(sign * y[2]), "N": float(n),
                        "shear_force": float(sign * sh), "M": float(y[5])})
    return reactions, profile
