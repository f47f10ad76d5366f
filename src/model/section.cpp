#include "ogive/model/section.hpp"

#include <cmath>
#include <limits>

namespace ogive {

SectionStrain section_strain(SectionKind kind, double N, double M, double t) {
  SectionStrain s;
  const double a_N = t * t / 12;
  const double P = -N;
  const double e = P > 0 ? std::abs(M) / P : 0.0;
  if (kind == SectionKind::elastic || (P > 0 && e <= t / 6)) {
    s.eps = a_N * N;
    s.kappa = M;
    s.eps_N = a_N;
    s.kappa_M = 1;
    return s;
  }
  if (!(P > 0) || !(e < t / 2)) {
    s.admissible = false;
    s.cracked = true;
    s.compressed_depth = 0;
    return s;
  }
  // The cracked law (section.hpp) and its derivatives: u = t/2 - sigma M / P, du/dM = -sigma / P,
  // du/dN = -e / P; with g(u) = 1/u - t / (6 u^2) for eps = -(t^3 / 18) P g(u).
  const double sigma = M > 0 ? 1.0 : -1.0;
  const double u = t / 2 - e;
  const double t3 = t * t * t;
  s.cracked = true;
  s.compressed_depth = 3 * u / t;
  s.kappa = sigma * P * t3 / (54 * u * u);
  s.kappa_M = t3 / (27 * u * u * u);
  s.kappa_N = sigma * t3 / 54 * (-1 / (u * u) + 2 * e / (u * u * u));
  const double g = 1 / u - t / (6 * u * u);
  const double dg = -1 / (u * u) + t / (3 * u * u * u);
  s.eps = -(t3 / 18) * P * g;
  s.eps_M = sigma * (t3 / 18) * dg;
  s.eps_N = (t3 / 18) * (g + e * dg);
  return s;
}

CompressiveStress compressive_stress(SectionKind kind, double N, double M, double t) {
  CompressiveStress out;
  const double P = -N, m = std::abs(M), sign = M > 0 ? 1.0 : M < 0 ? -1.0 : 0.0;
  if (!(P > 0)) {
    out.sigma = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  if (kind == SectionKind::elastic || m <= P * t / 6) {
    out.sigma = P / t + 6 * m / (t * t);
    out.d_N = -1 / t;
    out.d_M = sign * 6 / (t * t);
    return out;
  }
  const double u = t / 2 - m / P;
  if (!(u > 0)) {
    out.sigma = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  // sigma = 2 P / (3 u) with du/dP = m / P^2 and du/dm = -1 / P.
  out.sigma = 2 * P / (3 * u);
  out.d_N = -(2 / (3 * u) - 2 * m / (3 * u * u * P));
  out.d_M = sign * 2 / (3 * u * u);
  return out;
}

}  // namespace ogive
