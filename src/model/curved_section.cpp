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

// A curved bar's held face (curved_section.hpp) at t_kappa 0.2, 0.3, 0.4, 0.5 and 0.6: for each, {nu, NN, VV, VM,
// MM, NM} over the strip's nu, CalculiX's semicircle held at its springing at 32 elements through the depth
// (benchmarks/continuum/ring.csv; from 16 elements to 32 NM moves by 3 %, MM by 4 %).
constexpr std::array<double, 5> kHeldCurvatures = {0.2, 0.3, 0.4, 0.5, 0.6};
constexpr std::array<std::array<std::array<double, 6>, 17>, 5> kHeldCurved = {{
    {{
        {-0.9, -0.24840, -0.05165, 0.21100, -1.55883, -0.04438},
        {-0.7, -0.10999, -0.03427, 0.10680, -0.66037, -0.03144},
        {-0.5, -0.04814, -0.03310, 0.06321, -0.28339, -0.02092},
        {-0.3, -0.01544, -0.03375, 0.03387, -0.09595, -0.01198},
        {-0.1, -0.00140, -0.03589, 0.01094, -0.01787, -0.00381},
        {0.0, 0.00004, -0.03765, 0.00102, -0.00877, 0.00014},
        {0.1, -0.00161, -0.03979, -0.00812, -0.01624, 0.00403},
        {0.2, -0.00594, -0.04118, -0.01676, -0.03853, 0.00781},
        {0.25, -0.00887, -0.04268, -0.02072, -0.05485, 0.00972},
        {0.3, -0.01250, -0.04412, -0.02460, -0.07443, 0.01158},
        {0.4, -0.02039, -0.04498, -0.03231, -0.12301, 0.01507},
        {0.5, -0.03320, -0.04886, -0.03893, -0.18340, 0.01907},
        {0.6, -0.04683, -0.05213, -0.04535, -0.25554, 0.02290},
        {0.7, -0.06223, -0.05517, -0.05157, -0.33936, 0.02667},
        {0.8, -0.07872, -0.05772, -0.05791, -0.43568, 0.03031},
        {0.9, -0.09845, -0.06231, -0.06467, -0.54793, 0.03446},
        {0.97, -0.11501, -0.06747, -0.07112, -0.64451, 0.03799},
    }},
    {{
        {-0.9, -0.24271, -0.05246, 0.21789, -1.58177, -0.06677},
        {-0.7, -0.10848, -0.03607, 0.11107, -0.67825, -0.04676},
        {-0.5, -0.04630, -0.03359, 0.06603, -0.29853, -0.03124},
        {-0.3, -0.01464, -0.03425, 0.03594, -0.10921, -0.01774},
        {-0.1, -0.00139, -0.03655, 0.01251, -0.02965, -0.00536},
        {0.0, -0.00014, -0.03798, 0.00231, -0.01990, 0.00055},
        {0.1, -0.00180, -0.03965, -0.00708, -0.02676, 0.00633},
        {0.2, -0.00629, -0.04166, -0.01576, -0.04851, 0.01207},
        {0.25, -0.00940, -0.04271, -0.01987, -0.06456, 0.01491},
        {0.3, -0.01318, -0.04374, -0.02387, -0.08388, 0.01771},
        {0.4, -0.02266, -0.04642, -0.03138, -0.13203, 0.02337},
        {0.5, -0.03384, -0.04870, -0.03843, -0.19191, 0.02893},
        {0.6, -0.04730, -0.05160, -0.04502, -0.26360, 0.03453},
        {0.7, -0.06273, -0.05483, -0.05128, -0.34701, 0.04021},
        {0.8, -0.08057, -0.05854, -0.05744, -0.44299, 0.04608},
        {0.9, -0.10015, -0.06281, -0.06432, -0.55484, 0.05219},
        {0.97, -0.11607, -0.06690, -0.07095, -0.65117, 0.05721},
    }},
    {{
        {-0.9, -0.23661, -0.05802, 0.22851, -1.61463, -0.08807},
        {-0.7, -0.10545, -0.03888, 0.11723, -0.70376, -0.06162},
        {-0.5, -0.04469, -0.03520, 0.07021, -0.32016, -0.04102},
        {-0.3, -0.01368, -0.03524, 0.03893, -0.12812, -0.02307},
        {-0.1, -0.00110, -0.03699, 0.01463, -0.04641, -0.00661},
        {0.0, -0.00018, -0.03833, 0.00413, -0.03575, 0.00131},
        {0.1, -0.00212, -0.03991, -0.00554, -0.04176, 0.00903},
        {0.2, -0.00675, -0.04172, -0.01449, -0.06272, 0.01665},
        {0.25, -0.01015, -0.04278, -0.01869, -0.07840, 0.02045},
        {0.3, -0.01392, -0.04377, -0.02279, -0.09735, 0.02419},
        {0.4, -0.02334, -0.04610, -0.03053, -0.14481, 0.03170},
        {0.5, -0.03496, -0.04861, -0.03769, -0.20404, 0.03916},
        {0.6, -0.04856, -0.05149, -0.04440, -0.27512, 0.04668},
        {0.7, -0.06423, -0.05457, -0.05081, -0.35793, 0.05425},
        {0.8, -0.08196, -0.05819, -0.05708, -0.45334, 0.06203},
        {0.9, -0.10194, -0.06239, -0.06401, -0.56466, 0.07024},
        {0.97, -0.11790, -0.06643, -0.07067, -0.66067, 0.07691},
    }},
    {{
        {-0.9, -0.22903, -0.06599, 0.24265, -1.65814, -0.10824},
        {-0.7, -0.10160, -0.04272, 0.12536, -0.73745, -0.07575},
        {-0.5, -0.04252, -0.03746, 0.07572, -0.34872, -0.05018},
        {-0.3, -0.01265, -0.03653, 0.04283, -0.15306, -0.02784},
        {-0.1, -0.00090, -0.03768, 0.01744, -0.06853, -0.00729},
        {0.0, -0.00026, -0.03878, 0.00650, -0.05663, 0.00257},
        {0.1, -0.00252, -0.04017, -0.00354, -0.06152, 0.01224},
        {0.2, -0.00750, -0.04185, -0.01280, -0.08145, 0.02177},
        {0.25, -0.01087, -0.04279, -0.01717, -0.09662, 0.02648},
        {0.3, -0.01487, -0.04374, -0.02140, -0.11511, 0.03118},
        {0.4, -0.02453, -0.04597, -0.02939, -0.16166, 0.04056},
        {0.5, -0.03632, -0.04836, -0.03677, -0.22005, 0.04991},
        {0.6, -0.05012, -0.05109, -0.04369, -0.29033, 0.05929},
        {0.7, -0.06604, -0.05417, -0.05024, -0.37241, 0.06879},
        {0.8, -0.08396, -0.05768, -0.05667, -0.46714, 0.07852},
        {0.9, -0.10413, -0.06190, -0.06370, -0.57788, 0.08882},
        {0.97, -0.12032, -0.06589, -0.07041, -0.67371, 0.09721},
    }},
    {{
        {-0.9, -0.21977, -0.07613, 0.26037, -1.71271, -0.12698},
        {-0.7, -0.09693, -0.04757, 0.13554, -0.77984, -0.08893},
        {-0.5, -0.03997, -0.04026, 0.08262, -0.38467, -0.05854},
        {-0.3, -0.01140, -0.03818, 0.04772, -0.18450, -0.03187},
        {-0.1, -0.00069, -0.03857, 0.02095, -0.09641, -0.00727},
        {0.0, -0.00045, -0.03938, 0.00948, -0.08298, 0.00455},
        {0.1, -0.00309, -0.04053, -0.00103, -0.08644, 0.01613},
        {0.2, -0.00838, -0.04198, -0.01070, -0.10504, 0.02756},
        {0.25, -0.01194, -0.04282, -0.01525, -0.11960, 0.03323},
        {0.3, -0.01608, -0.04374, -0.01964, -0.13747, 0.03888},
        {0.4, -0.02601, -0.04576, -0.02795, -0.18284, 0.05012},
        {0.5, -0.03808, -0.04806, -0.03559, -0.24012, 0.06135},
        {0.6, -0.05220, -0.05068, -0.04274, -0.30934, 0.07263},
        {0.7, -0.06831, -0.05366, -0.04948, -0.39040, 0.08403},
        {0.8, -0.08644, -0.05708, -0.05605, -0.48411, 0.09572},
        {0.9, -0.10686, -0.06116, -0.06318, -0.59381, 0.10808},
        {0.97, -0.12317, -0.06510, -0.06988, -0.68885, 0.11814},
    }},
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

HeldFace held_face(double nu, double t_kappa) {
  if (!(nu > -1 && nu < 1)) throw std::invalid_argument("held_face: nu must lie in (-1, 1)");
  if (!std::isfinite(t_kappa)) throw std::invalid_argument("held_face: t_kappa must be finite");
  const auto straight = nearest_quadratic(kHeldFace, nu);
  if (t_kappa == 0) return {straight[0], straight[1], straight[2], straight[3], 0};
  // Over t_kappa: the straight strip's at 0 (no coupling), then the ring's at each measured curvature,
  // each read at nu first.
  std::array<std::array<double, 6>, kHeldCurvatures.size() + 1> over{};
  over[0] = {0, straight[0], straight[1], straight[2], straight[3], 0};
  for (std::size_t k = 0; k < kHeldCurvatures.size(); ++k) {
    const auto c = nearest_quadratic(kHeldCurved[k], nu);
    over[k + 1] = {kHeldCurvatures[k], c[0], c[1], c[2], c[3], c[4]};
  }
  const auto c = nearest_quadratic(over, std::abs(t_kappa));
  return {c[0], c[1], c[2], c[3], std::copysign(c[4], t_kappa)};
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
