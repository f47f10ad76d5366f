// The section's law (include/ogive/model/section.hpp): the no-tension section against the linear stress
// block it was derived from, its continuity at the kern's edge and its derivatives.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "ogive/model/section.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

TEST_CASE("no-tension: the section's law is the linear stress block it was derived from") {
  // Forward: a compressed depth c and a face strain eps_f give, by integrating the linear stress
  // E eps_f (1 - z / c) over 0 <= z <= c (Simpson, 2000 intervals), the resultant and its moment about
  // the axis; the law must return eps_f / c as the curvature and the plane section's strain at the axis.
  const double t = 0.08;  // scaled depth t/L; E = 1 in these units: eps = P t^3 / 12 ... (section.hpp)
  // In the scaled law E I = 1 for the unit section, so E = 12 / t^3 and the scaled N, M are forces.
  const double E = 12 / (t * t * t);
  for (double c_over_t : {0.95, 0.7, 0.4, 0.1, 0.02}) {
    for (double sign : {1.0, -1.0}) {
      const double c = c_over_t * t, eps_f = 1e-3;
      constexpr int n = 2000;
      double P = 0, moment = 0;
      for (int i = 0; i <= n; ++i) {
        const double z = c * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        const double stress = E * eps_f * (1 - z / c);  // compression, from the compressed face
        P += w * stress;
        moment += w * stress * (t / 2 - z);  // about the axis, towards the compressed face
      }
      P *= c / n / 3;
      moment *= c / n / 3;
      // The compressed face is the intrados for M > 0 (sign +1): M = sign * moment, N = -P.
      const SectionStrain s = section_strain(SectionKind::no_tension, -P, sign * moment, t);
      CAPTURE(c_over_t);
      CAPTURE(sign);
      REQUIRE(s.admissible);
      CHECK(s.cracked);
      CHECK(close(s.compressed_depth, c_over_t, 1e-9));
      CHECK(close(s.kappa, sign * eps_f / c, 1e-9));
      CHECK(close(s.eps, -eps_f * (1 - t / (2 * c)), 1e-9));
    }
  }
  // In the kern it is the linear law; at the kern's edge the two meet with continuous derivatives.
  const double P = 2.0, edge = P * t / 6;
  const SectionStrain in = section_strain(SectionKind::no_tension, -P, 0.5 * edge, t);
  CHECK_FALSE(in.cracked);
  CHECK(close(in.kappa, 0.5 * edge, kExact));
  CHECK(close(in.eps, -P * t * t / 12, kExact));
  const SectionStrain below = section_strain(SectionKind::no_tension, -P, edge * (1 - 1e-9), t);
  const SectionStrain above = section_strain(SectionKind::no_tension, -P, edge * (1 + 1e-9), t);
  CHECK(above.cracked);
  for (auto [a, b] : {std::pair{below.kappa, above.kappa}, {below.eps, above.eps}, {below.kappa_M, above.kappa_M},
                      {below.kappa_N, above.kappa_N}, {below.eps_N, above.eps_N}, {below.eps_M, above.eps_M}})
    CHECK(std::abs(a - b) <= 1e-7 * std::max({std::abs(a), std::abs(b), 1.0}));
  // The derivatives against central differences, in the cracked range.
  for (double e_over_t : {0.2, 0.3, 0.45}) {
    const double N = -1.3, M = 1.3 * e_over_t * t, h = 1e-7;
    const SectionStrain s = section_strain(SectionKind::no_tension, N, M, t);
    const SectionStrain n1 = section_strain(SectionKind::no_tension, N + h, M, t);
    const SectionStrain n0 = section_strain(SectionKind::no_tension, N - h, M, t);
    const SectionStrain m1 = section_strain(SectionKind::no_tension, N, M + h, t);
    const SectionStrain m0 = section_strain(SectionKind::no_tension, N, M - h, t);
    CAPTURE(e_over_t);
    CHECK(close(s.kappa_N, (n1.kappa - n0.kappa) / (2 * h), 1e-6));
    CHECK(close(s.kappa_M, (m1.kappa - m0.kappa) / (2 * h), 1e-6));
    CHECK(close(s.eps_N, (n1.eps - n0.eps) / (2 * h), 1e-6));
    CHECK(close(s.eps_M, (m1.eps - m0.eps) / (2 * h), 1e-6));
  }
  // Outside the section, or under tension: not admissible.
  CHECK_FALSE(section_strain(SectionKind::no_tension, -1, 0.51 * t, t).admissible);
  CHECK_FALSE(section_strain(SectionKind::no_tension, 0.1, 0, t).admissible);
}

TEST_CASE("compressive stress: the linear and the triangular block's peak, their resultants, continuity, slopes") {
  const double t = 0.6, P = 2.0e5;  // m, N/m
  // The elastic linear stress P/t + 6 m/t^2 is the face value of sigma(z) = P/t + 12 m z / t^3.
  for (double m : {0.0, 0.02 * P * t, P * t / 6, 0.3 * P * t}) {
    CAPTURE(m);
    const CompressiveStress s = compressive_stress(SectionKind::elastic, -P, -m, t);
    CHECK(close(s.sigma, P / t + 12 * m * (t / 2) / (t * t * t), kExact));
  }
  // Beyond the kern, the triangular block of depth c and peak sigma: its resultant 0.5 sigma c is P and
  // acts c/3 from the face, at m / P from the axis.
  for (double ratio : {0.2, 0.3, 0.45, 0.499}) {
    CAPTURE(ratio);
    const double m = ratio * P * t;
    const CompressiveStress s = compressive_stress(SectionKind::no_tension, -P, m, t);
    const double c = 2 * P / s.sigma;  // from the resultant
    CHECK(close(P * (t / 2 - c / 3), m, kExact));
  }
  // The two laws meet at the kern's edge with the same value and slopes.
  const double edge = P * t / 6;
  const CompressiveStress in = compressive_stress(SectionKind::no_tension, -P, edge, t);
  const CompressiveStress out = compressive_stress(SectionKind::no_tension, -P, edge * (1 + 1e-12), t);
  CHECK(close(in.sigma, out.sigma, 1e-11));
  CHECK(close(in.d_N, out.d_N, 1e-9));
  CHECK(close(in.d_M, out.d_M, 1e-9));
  // The slopes against central differences (step 1e-6 relative: the difference's error ~1e-10).
  for (SectionKind kind : {SectionKind::elastic, SectionKind::no_tension})
    for (double ratio : {0.1, -0.3, 0.4}) {
      CAPTURE(ratio);
      const double N = -P, M = ratio * P * t, hN = 1e-6 * P, hM = 1e-6 * P * t;
      const CompressiveStress s = compressive_stress(kind, N, M, t);
      const double dN = (compressive_stress(kind, N + hN, M, t).sigma - compressive_stress(kind, N - hN, M, t).sigma) / (2 * hN);
      const double dM = (compressive_stress(kind, N, M + hM, t).sigma - compressive_stress(kind, N, M - hM, t).sigma) / (2 * hM);
      CHECK(close(s.d_N, dN, 1e-7));
      CHECK(close(s.d_M, dM, 1e-7));
    }
  // No compression, or the no-tension resultant on or beyond a face: no stress.
  CHECK(std::isnan(compressive_stress(SectionKind::elastic, 0.0, 1.0, t).sigma));
  CHECK(std::isnan(compressive_stress(SectionKind::elastic, P, 0.0, t).sigma));
  CHECK(std::isnan(compressive_stress(SectionKind::no_tension, -P, P * t / 2, t).sigma));
  CHECK(std::isfinite(compressive_stress(SectionKind::elastic, -P, P * t, t).sigma));
}
