#!/usr/bin/python3
"""Derives exp(A8 l) of a circular arc in closed form, the entries that closed_form.cpp's
arc_exponential writes out, and prints them (about 2 minutes; needs python3-sympy and mpmath).

    /usr/bin/python3 src/methods/closed_form_derivation.py

States (local, scaled): u, v, psi, N, V, M, c = cos theta, sn = sin theta. With Z = u + i v,
W = N + i V and q = c + i sn the arc's equations read
    q' = i k q,   W' = -i k W + (i b - h) conj(q),   M' = -Im W,   psi' = M,
    Z' = -i k Z + a_N Re W + i (psi + a_V Im W),
so every state is a quasi-polynomial, a sum of c_{m,p} s^p e^{i m k s}, whose integrals are exact.
Each entry at s = l is then rewritten with x = k l as a polynomial in x, l and the parameters times
    C_j(x) = sum_n (-1)^n x^2n / (2n + j)!   (C_0 = cos x, C_1 = sin x / x, C_{j+2} = (1/j! - C_j) / x^2),
entire functions: the script checks that no negative power of x is left, so nothing cancels as k -> 0.
Of the forms that C_j = 1/j! - x^2 C_{j+2} gives, each parameter group keeps the one whose terms'
magnitudes sum to the least multiple of its value over 0 < x <= 2 pi (a measure of cancellation).
"""
import sys

import mpmath
import sympy as sp

k, l, x = sp.symbols("k l x", positive=True)
aN, aV, b, h = sp.symbols("a_N a_V b h", real=True)
init = sp.symbols("u0 v0 psi0 N0 V0 M0 c0 sn0", real=True)
u0, v0, psi0, N0, V0, M0, c0, sn0 = init
I = sp.I
J = 12
C = sp.symbols(f"C0:{J}")
mpmath.mp.dps = 40


class QP:
    """A quasi-polynomial: coefficient of s^p e^{i m k s} by (m, p)."""

    def __init__(self, terms=None):
        self.t = {key: c for key, c in (terms or {}).items() if c != 0}

    def __add__(self, o):
        r = dict(self.t)
        for key, c in o.t.items():
            r[key] = sp.expand(r.get(key, 0) + c)
        return QP(r)

    def scale(self, a):
        return QP({key: sp.expand(a * c) for key, c in self.t.items()})

    def shift(self, m):
        return QP({(mm + m, p): c for (mm, p), c in self.t.items()})

    def conj(self):
        return QP({(-m, p): sp.expand(sp.conjugate(c)) for (m, p), c in self.t.items()})

    def integral(self):
        """The antiderivative that vanishes at s = 0."""
        r = QP()
        for (m, p), c in self.t.items():
            if m == 0:
                r = r + QP({(0, p + 1): c / (p + 1)})
                continue
            a = I * m * k
            terms = {}
            for q in range(p + 1):
                coef = (-1) ** q * sp.factorial(p) / sp.factorial(p - q) / a ** (q + 1)
                terms[(m, p - q)] = terms.get((m, p - q), 0) + c * coef
            terms[(0, 0)] = terms.get((0, 0), 0) - c * (-1) ** p * sp.factorial(p) / a ** (p + 1)
            r = r + QP(terms)
        return r

    def value(self):
        """At s = l."""
        return sp.expand(sum(c * l ** p * sp.exp(I * m * k * l) for (m, p), c in self.t.items()))


def conv(m, g):
    """The solution of y' = i m k y + g with y(0) = 0."""
    return g.shift(-m).integral().shift(m)


def real(z):
    return (z + z.conj()).scale(sp.Rational(1, 2))


def imag(z):
    return (z + z.conj().scale(-1)).scale(1 / (2 * I))


def states():
    q = QP({(1, 0): c0 + I * sn0})
    W = QP({(-1, 0): N0 + I * V0}) + conv(-1, q.conj().scale(I * b - h))
    N, V = real(W), imag(W)
    M = QP({(0, 0): M0}) + V.integral().scale(-1)
    psi = QP({(0, 0): psi0}) + M.integral()
    Z = QP({(-1, 0): u0 + I * v0}) + conv(-1, N.scale(aN) + psi.scale(I) + V.scale(I * aV))
    return [real(Z), imag(Z), psi, N, V, M, real(q), imag(q)]


def lifted(expr_cos, p, j0):
    """x^p times cos x (j0 = 0) or sin x / x (j0 = 1), with C_j for the first j >= -p of j0's parity."""
    if p >= 0:
        return x ** p * C[j0]
    j = j0 + (-p) + ((-p) % 2)
    half = (j - j0) // 2
    head = sum((-1) ** n * x ** (2 * n) / sp.factorial(2 * n + j0) for n in range(half))
    return x ** p * head + (-1) ** half * x ** (p + j - j0) * C[j]


def rewrite(expr):
    """expr (in k, l, exp(i k l)) as a polynomial in x, l, the parameters and the C_j; exact."""
    e = sp.expand(sp.expand_trig(sp.expand(sp.expand(expr.subs(k, x / l)).rewrite(sp.cos))))
    out = 0
    for (pc, ps), coef in sp.Poly(e, sp.cos(x), sp.sin(x)).terms():
        assert pc + ps <= 1, (pc, ps)
        for term in sp.Add.make_args(sp.expand(coef)):
            num, den = sp.fraction(sp.together(term))
            p = (sp.degree(num, x) if num.has(x) else 0) - (sp.degree(den, x) if den.has(x) else 0)
            rest = sp.simplify(term / x ** p)
            assert not rest.has(x)
            if pc:
                out += rest * lifted(sp.cos(x), p, 0)
            elif ps:  # x^p sin x = x^(p+1) (sin x / x)
                out += rest * lifted(sp.sin(x), p + 1, 1)
            else:
                out += rest * x ** p
    out = sp.expand(out)
    for term in sp.Add.make_args(out):
        assert not sp.fraction(sp.together(term))[1].has(x), f"a negative power of x is left: {term}"
    return out


def c_value(j, xv):
    xv = mpmath.mpf(xv)
    return mpmath.nsum(lambda n: (-1) ** int(n) * xv ** (2 * n) / mpmath.factorial(2 * n + j), [0, mpmath.inf])


def cancellation(G):
    """The largest ratio of the terms' summed magnitudes to the value, over 0 < x <= 2 pi."""
    worst = 1
    terms = sp.Add.make_args(sp.expand(G))
    for xv in [1e-3, 0.3, 1.0, 2.0, 4.0, 6.3]:
        sub = {x: xv, **{C[j]: c_value(j, xv) for j in range(J)}}
        vals = [mpmath.mpf(sp.N(t.subs(sub), 30)) for t in terms]
        if sum(vals) != 0:
            worst = max(worst, sum(abs(v) for v in vals) / abs(sum(vals)))
    return worst


def lift(G, T):
    """Every C_j with j < T rewritten through C_j = 1/j! - x^2 C_{j+2} until j >= T."""
    for _ in range(J):
        low = [j for j in range(T) if G.has(C[j])]
        if not low:
            break
        for j in low:
            G = sp.expand(G.subs(C[j], 1 / sp.factorial(j) - x ** 2 * C[j + 2]))
    return G


def least_cancelling(G):
    best, best_form = cancellation(G), G
    for T in range(1, 8):
        form = lift(G, T)
        c = cancellation(form)
        if c < 0.7 * best:
            best, best_form = c, form
    return best_form


def main():
    gens = [l, aN, aV, b, h]
    for i, row in enumerate(states()):
        value = row.value()
        for j, s0 in enumerate(init):
            coef = value.coeff(s0)
            if coef == 0:
                continue
            entry = 0
            for mon, G in sp.Poly(rewrite(coef), *gens).terms():
                entry += sp.Mul(*[g ** e for g, e in zip(gens, mon)]) * sp.collect(least_cancelling(G), list(C))
            print(f"E({i}, {j}) = {entry}")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
