#include "ogive/model/curved_section.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "numerics/gauss_legendre.hpp"

namespace ogive {

namespace {

using Real = long double;  // the modes' constants are differences that cancel like rho^2

// Golovin's pure bending and Michell's end force of the annulus a < r < b (R = 1, E = 1), free on both
// faces: each mode's radial and hoop stress at r (the force mode's shear stress is minus its radial
// stress, times cos of the angle where the hoop stress goes with its sine).
struct Modes {
  Real a, b, lg, n0, n1, A, B, D;
  explicit Modes(Real rho) : a(1 - rho), b(1 + rho) {
    lg = std::log1p(rho) - std::log1p(-rho);  // ln(b / a)
    n0 = 16 * rho * rho - 4 * (a * b) * (a * b) * lg * lg;  // (b^2 - a^2)^2 - 4 a^2 b^2 ln(b/a)^2
    n1 = -4 * rho + (a * a + b * b) * lg;                    // a^2 - b^2 + (a^2 + b^2) ln(b/a)
    A = 1 / (2 * n1);
    B = -(a * a) * (b * b) / (2 * n1);
    D = -(a * a + b * b) / n1;
  }
  // {radial, hoop} of the bending mode and of the force mode at r.
  std::array<Real, 4> at(Real r) const {
    const Real logs = b * b * std::log(r / b) + a * a * std::log(a / r);
    const Real inner = (a * a) * (b * b) * lg / (r * r);
    const Real k = -4 / n0;
    return {k * (inner + logs), k * (-inner + logs + b * b - a * a), 2 * A * r - 2 * B / (r * r * r) + D / r,
            6 * A * r + 2 * B / (r * r * r) + D / r};
  }
};

}  // namespace

namespace {

CurvedSection from_modes(double rho_in, double nu_in) {
  const Real rho = rho_in, nu = nu_in;
  const Modes m(rho);
  // Integrals over the depth in u = ln r (r dr = r^2 du): the integrands are entire in u, and 48 points
  // take them to round-off for every rho < 1 that a scene admits (rho <= 0.99: ln(b/a) <= 5.3).
  Real NF = 0, MF = 0, NB = 0, MB = 0, VF = 0, QFF = 0, QFB = 0, QBB = 0, QV = 0;
  const GaussLegendreRule<48>& g = gauss_legendre<48>();
  const Real u0 = std::log(m.a), u1 = std::log(m.b), mid = (u0 + u1) / 2, half = (u1 - u0) / 2;
  for (int i = 0; i < 48; ++i) {
    const Real r = std::exp(mid + half * g.node[i]);
    const Real w = half * g.weight[i] * r;  // dr = r du
    const std::array<Real, 4> s = m.at(r);  // Br, Bt, Fr, Ft
    NB += w * s[1];
    MB += w * s[1] * (r - 1);
    NF += w * s[3];
    MF += w * s[3] * (r - 1);
    VF += w * s[2];
    QBB += w * r * (s[0] * s[0] + s[1] * s[1] - 2 * nu * s[0] * s[1]);
    QFF += w * r * (s[2] * s[2] + s[3] * s[3] - 2 * nu * s[2] * s[3]);
    QFB += w * r * (s[2] * s[0] + s[3] * s[1] - nu * (s[2] * s[1] + s[3] * s[0]));
    QV += w * r * s[2] * s[2] * 2 * (1 + nu);  // tau^2 / G
  }
  // (N, M) = T (force mode, bending mode): the energy's matrix in (N, M) is T^-T Q T^-1.
  const Real det = NF * MB - NB * MF;
  const Real i00 = MB / det, i01 = -NB / det, i10 = -MF / det, i11 = NF / det;  // T^-1
  const Real C00 = i00 * (QFF * i00 + QFB * i10) + i10 * (QFB * i00 + QBB * i10);
  const Real C01 = i00 * (QFF * i01 + QFB * i11) + i10 * (QFB * i01 + QBB * i11);
  const Real C11 = i01 * (QFF * i01 + QFB * i11) + i11 * (QFB * i01 + QBB * i11);
  const Real t = 2 * rho;  // A = t, I = t^3 / 12, R = 1
  CurvedSection c;
  c.axial = static_cast<double>(C00 * t);
  c.coupling = static_cast<double>(C01 * t);
  c.bending = static_cast<double>(C11 * t * t * t / 12);
  c.shear = static_cast<double>(QV / (VF * VF) * (Real(5) / 6) * t / (2 * (1 + nu)));
  return c;
}

}  // namespace

CurvedSection curved_section(double rho, double nu) {
  // Below rho0 the modes' constants cancel to more than the long double's digits (at 1e-4 the coupling
  // keeps six): each factor there is its straight limit plus its rho^2 term, read at rho0 (the next term,
  // rho^4, is below 1e-12 of it).
  constexpr double rho0 = 1e-3;
  if (rho >= rho0) return from_modes(rho, nu);
  const CurvedSection at = from_modes(rho0, nu);
  const double w = (rho / rho0) * (rho / rho0);
  const double coupling0 = 1 + 1.2 * nu;
  return {1 + w * (at.axial - 1), coupling0 + w * (at.coupling - coupling0), 1 + w * (at.bending - 1),
          1 + w * (at.shear - 1)};
}

}  // namespace ogive
