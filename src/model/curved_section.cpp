#include "ogive/model/curved_section.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

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
  // The free annulus under a radial body force p = 1 (outward): Airy's function A ln r + B r^2 with the
  // body force's potential -p r and the particular (1 - nu) p r^3 / 9 (plane stress: del^4 phi =
  // -(1 - nu) del^2 V), free on both faces; any pure bending added to it is the bending mode's and drops out
  // below. W* are its stresses' integrals against each mode, S* its resultants.
  const Real alpha = (1 - nu) / 9, ga = (3 * alpha - 1) * m.a, gb = (3 * alpha - 1) * m.b;
  const Real LA = (gb - ga) / (1 / (m.a * m.a) - 1 / (m.b * m.b)), LB = (-ga - LA / (m.a * m.a)) / 2;
  Real SN = 0, SM = 0, WFr = 0, WFt = 0, WBr = 0, WBt = 0;
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
    const Real lr = LA / (r * r) + 2 * LB + (3 * alpha - 1) * r, lt = -LA / (r * r) + 2 * LB + (6 * alpha - 1) * r;
    SN += w * lt;
    SM += w * lt * (r - 1);
    WFr += w * r * (s[2] * lr - nu * s[3] * lr);  // the force mode against the load's radial stress
    WFt += w * r * (s[3] * lt - nu * s[2] * lt);
    WBr += w * r * (s[0] * lr - nu * s[1] * lr);
    WBt += w * r * (s[1] * lt - nu * s[0] * lt);
  }
  // (N, M) = T (force mode, bending mode): the energy's matrix in (N, M) is T^-T Q T^-1.
  const Real det = NF * MB - NB * MF;
  const Real i00 = MB / det, i01 = -NB / det, i10 = -MF / det, i11 = NF / det;  // T^-1
  const Real C00 = i00 * (QFF * i00 + QFB * i10) + i10 * (QFB * i00 + QBB * i10);
  const Real C01 = i00 * (QFF * i01 + QFB * i11) + i10 * (QFB * i01 + QBB * i11);
  const Real C11 = i01 * (QFF * i01 + QFB * i11) + i11 * (QFB * i01 + QBB * i11);
  const Real t = 2 * rho;  // A = t, I = t^3 / 12, R = 1
  // The load's own stress: the annulus' field less the modes of its resultants (SN, SM); its energy
  // against the modes of (N, M), derived in N and M, is the section's strain and curvature under the load
  // (q = p t per length of the axis).
  const Real fF = i00 * SN + i01 * SM, fB = i10 * SN + i11 * SM;
  const Real XF = WFr + WFt - fF * QFF - fB * QFB, XB = WBr + WBt - fF * QFB - fB * QBB;
  CurvedSection c;
  c.load_extension = static_cast<double>((i00 * XF + i10 * XB) / t);
  c.load_curvature = static_cast<double>((i01 * XF + i11 * XB));
  c.axial = static_cast<double>(C00 * t);
  c.coupling = static_cast<double>(C01 * t);
  c.bending = static_cast<double>(C11 * t * t * t / 12);
  c.shear = static_cast<double>(QV / (VF * VF) * (Real(5) / 6) * t / (2 * (1 + nu)));
  return c;
}

}  // namespace

namespace {

// load_extension is odd in rho (the faces swap with its sign): rho times an even function, which cancels
// like the modes' constants but sooner (1e-7 of it at rho 1e-3, 1e-10 at 1e-2). Below 0.02 it is that
// function's series in rho^2 through its values at rho 0.01, 0.02 and 0.03 (the next term, rho^6, is below
// 1e-10 of it there).
double small_load_extension(double rho, double nu) {
  constexpr double h = 0.01;
  const double f1 = from_modes(h, nu).load_extension / h;
  const double f2 = from_modes(2 * h, nu).load_extension / (2 * h);
  const double f3 = from_modes(3 * h, nu).load_extension / (3 * h);
  // f = f0 + c2 x + c4 x^2 at x = rho^2 / h^2 = 1, 4, 9.
  const double c4 = ((f3 - f2) / 5 - (f2 - f1) / 3) / 8, c2 = (f2 - f1) / 3 - 5 * c4, f0 = f1 - c2 - c4;
  const double x = rho * rho / (h * h);
  return rho * (f0 + x * (c2 + x * c4));
}

constexpr double kSmallExtension = 0.02;

// The held face's compliance (curved_section.hpp) at the section's nu: {nu, NN, VV, VM, MM}, CalculiX's
// strip at 32 elements through the depth (benchmarks/continuum/held.csv; the held corners are singular,
// and from 16 elements to 32 the coefficients move by 2 to 5 %: 1e-5 of H/V here).
constexpr std::array<std::array<double, 5>, 17> kHeldFace = {{
    {-0.9, -0.24952, -0.04949, 0.20544, -1.54081},
    {-0.7, -0.11207, -0.03720, 0.10446, -0.64655},
    {-0.5, -0.04839, -0.03126, 0.06067, -0.27138},
    {-0.3, -0.01548, -0.03323, 0.03222, -0.08549},
    {-0.1, -0.00157, -0.03756, 0.01021, -0.00870},
    {0.0, 0.00000, -0.03530, -0.00054, 0.00014},
    {0.1, -0.00146, -0.04013, -0.00884, -0.00798},
    {0.2, -0.00564, -0.04260, -0.01713, -0.03075},
    {0.25, -0.00869, -0.04242, -0.02143, -0.04718},
    {0.3, -0.01233, -0.04431, -0.02509, -0.06701},
    {0.4, -0.02134, -0.04696, -0.03237, -0.11604},
    {0.5, -0.03253, -0.04906, -0.03932, -0.17670},
    {0.6, -0.04581, -0.05204, -0.04573, -0.24918},
    {0.7, -0.06112, -0.05612, -0.05163, -0.33339},
    {0.8, -0.07848, -0.05971, -0.05773, -0.43008},
    {0.9, -0.09812, -0.06261, -0.06489, -0.54257},
    {0.97, -0.11380, -0.06631, -0.07166, -0.63935},
}};

// A pointed crown's wedge (curved_section.hpp) over the crown tangent's angle in degrees: {theta_c,
// crown_wedge}, CalculiX's crown segments at t/L 0.02 and nu 0, extrapolated from 4, 8 and 16 elements
// through the depth (benchmarks/continuum/wedge.csv; the intrados' re-entrant corner is singular and the
// extrapolation's step is up to 10 %: 3e-6 of H/V on the equilateral arch at t/L 0.02). At 0 the smooth
// crown's none (the measurement's 5e-4 at 0.5 degrees is of the size of its step).
constexpr std::array<std::array<double, 2>, 17> kCrownWedge = {{
    {0.0, 0.0},
    {0.5, 0.00054},
    {5.0, -0.00477},
    {10.0, -0.02719},
    {15.0, -0.07079},
    {20.0, -0.14315},
    {25.0, -0.25404},
    {30.0, -0.41757},
    {35.0, -0.65365},
    {40.0, -0.99111},
    {45.0, -1.47030},
    {50.0, -2.14845},
    {55.0, -3.11194},
    {60.0, -4.50536},
    {65.0, -6.58554},
    {70.0, -9.86347},
    {75.0, -15.51201},
}};

// The quadratic through the three nodes of a table (x ascending in its first column) nearest x (the first
// or last three beyond its ends), each further column's value at x.
template <std::size_t Rows, std::size_t Columns>
std::array<double, Columns - 1> nearest_quadratic(const std::array<std::array<double, Columns>, Rows>& table, double x) {
  std::size_t i = 0;
  while (i + 3 < Rows && x > 0.5 * (table[i + 1][0] + table[i + 2][0])) ++i;
  std::array<double, Columns - 1> c{};
  for (std::size_t a = i; a < i + 3; ++a) {
    double w = 1;
    for (std::size_t b = i; b < i + 3; ++b)
      if (b != a) w *= (x - table[b][0]) / (table[a][0] - table[b][0]);
    for (std::size_t k = 0; k + 1 < Columns; ++k) c[k] += w * table[a][k + 1];
  }
  return c;
}

}  // namespace

HeldFace held_face(double nu) {
  if (!(nu > -1 && nu < 1)) throw std::invalid_argument("held_face: nu must lie in (-1, 1)");
  const auto c = nearest_quadratic(kHeldFace, nu);
  return {c[0], c[1], c[2], c[3]};
}

double crown_wedge(double theta_c) {
  constexpr double kQuarterTurn = 1.5707963267948966;
  if (!(theta_c >= 0 && theta_c < kQuarterTurn))
    throw std::invalid_argument("crown_wedge: theta_c must lie in [0, pi / 2)");
  constexpr double kDegree = kQuarterTurn / 90;
  return nearest_quadratic(kCrownWedge, theta_c / kDegree)[0];
}

CurvedSection curved_section(double rho, double nu) {
  // Below rho0 the modes' constants cancel to more than the long double's digits (at 1e-4 the coupling
  // keeps six): each factor there is its straight limit plus its rho^2 term, read at rho0 (the next term,
  // rho^4, is below 1e-12 of it).
  constexpr double rho0 = 1e-3;
  CurvedSection c;
  if (rho >= rho0) {
    c = from_modes(rho, nu);
  } else {
    const CurvedSection at = from_modes(rho0, nu);
    const double w = (rho / rho0) * (rho / rho0);
    const double coupling0 = 1 + 1.2 * nu, curvature0 = -0.2 * nu;
    c = {1 + w * (at.axial - 1), coupling0 + w * (at.coupling - coupling0), 1 + w * (at.bending - 1),
         1 + w * (at.shear - 1)};
    c.load_curvature = curvature0 + w * (at.load_curvature - curvature0);
  }
  if (rho < kSmallExtension) c.load_extension = small_load_extension(rho, nu);
  return c;
}

}  // namespace ogive
