// Independent references for the tests: nothing here calls the solvers under test.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "ogive/model/scene.hpp"

namespace ogive::reference {

// Gauss-Legendre nodes and weights on [a, b] (Newton on the Legendre polynomial).
inline void gauss_legendre(int n, double a, double b, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = 0.5 * (a + b) + 0.5 * (b - a) * z;
    w[i] = (b - a) / ((1 - z * z) * dp * dp);
  }
}

// Horizontal reaction H (N/m) of the clamped symmetric pointed arch by Castigliano's theorem (the
// force method): the crown's horizontal force H and couple Mc are the redundants; the complementary
// energy of bending, stretching and shear is stationary in Mc (no crown rotation) and its derivative
// in H equals -d (the springing moved outwards by d). Geometry in closed form: on the left arc,
// centre (R, 0), x = R (1 - cos(s/R)), y = R sin(s/R), theta = pi/2 - s/R.
inline double castigliano_pointed_H(double span, double eccentricity, double thickness, const Material& m,
                                    double d) {
  const double R = (0.5 + eccentricity) * span;
  const double S = R * std::acos(eccentricity / (0.5 + eccentricity));
  const double E = m.effective_modulus();
  const double EI = E * thickness * thickness * thickness / 12.0;
  const double EA = E * thickness;
  const double kGA = m.shear_coefficient * m.shear_modulus() * thickness;
  const double w = m.density * m.gravity * thickness;
  auto x_of = [&](double s) { return R * (1 - std::cos(s / R)); };
  auto G_of = [&](double s) { return R * s - R * R * std::sin(s / R); };  // integral of x from 0 to s
  const double yc = R * std::sin(S / R);
  std::vector<double> xs, ws;
  gauss_legendre(96, 0.0, S, xs, ws);
  double I1 = 0, Ia = 0, Ia2 = 0, Im = 0, Ima = 0, Icc = 0, Iss = 0, Ilc = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double s = xs[i], q = ws[i];
    const double c = std::sin(s / R), sn = std::cos(s / R);  // cos, sin of theta
    const double a = yc - R * std::sin(s / R);
    const double mw = w * (G_of(S) - G_of(s) - x_of(s) * (S - s));
    I1 += q;
    Ia += q * a;
    Ia2 += q * a * a;
    Im += q * mw;
    Ima += q * mw * a;
    Icc += q * c * c;
    Iss += q * sn * sn;
    Ilc += q * w * (S - s) * sn * c;
  }
  // [I1/EI, Ia/EI; Ia/EI, Ia2/EI + Icc/EA + Iss/kGA] [Mc; H] = [Im/EI; -d + Ima/EI - Ilc/EA + Ilc/kGA]
  const double a11 = I1 / EI, a12 = Ia / EI, a22 = Ia2 / EI + Icc / EA + Iss / kGA;
  const double b1 = Im / EI, b2 = -d + Ima / EI - Ilc / EA + Ilc / kGA;
  return (a11 * b2 - a12 * b1) / (a11 * a22 - a12 * a12);
}

// Left horizontal reaction H_left (N/m, pointing into the span) of the two-hinged semicircle (pinned
// springings that do not move) under its self-weight w per axis length and the horizontal load a w per
// axis length towards +x, by Castigliano's theorem with H_left the redundant. With phi the angle from
// the left springing (x = R (1 - cos phi), y = R sin phi, s = R phi, cos theta = sin phi, sin theta =
// cos phi), statics of the part before s gives Fx = -H_left - a w R phi, Fy = -V_left + w R phi and
//   M = x V_left - y H_left - w R^2 (sin phi - phi cos phi) - a w R^2 (phi sin phi - 1 + cos phi),
// V_left = w R (pi/2 - a) from the moments about the right pin. The complementary energy of bending,
// stretching and shear is stationary in H_left (the springings do not move): M = M0 - y H_left,
// N = N0 - cos(theta) H_left, V = V0 + sin(theta) H_left.
inline double castigliano_two_hinged_semicircle_H(double span, double thickness, const Material& m, double a) {
  const double R = 0.5 * span, pi = std::numbers::pi;
  const double E = m.effective_modulus();
  const double EI = E * thickness * thickness * thickness / 12.0, EA = E * thickness;
  const double kGA = m.shear_coefficient * m.shear_modulus() * thickness;
  const double w = m.density * m.gravity * thickness;
  const double V_left = w * R * (pi / 2 - a);
  std::vector<double> phis, ws;
  gauss_legendre(128, 0.0, pi, phis, ws);
  double numerator = 0, denominator = 0;
  for (std::size_t i = 0; i < phis.size(); ++i) {
    const double phi = phis[i], q = ws[i] * R;  // ds = R dphi
    const double x = R * (1 - std::cos(phi)), y = R * std::sin(phi);
    const double c = std::sin(phi), sn = std::cos(phi);
    const double Fx0 = -a * w * R * phi, Fy = -V_left + w * R * phi;
    const double M0 = x * V_left - w * R * R * (std::sin(phi) - phi * std::cos(phi)) -
                      a * w * R * R * (phi * std::sin(phi) - 1 + std::cos(phi));
    const double N0 = c * Fx0 + sn * Fy, V0 = -sn * Fx0 + c * Fy;
    numerator += q * (M0 * y / EI + N0 * c / EA - V0 * sn / kGA);
    denominator += q * (y * y / EI + c * c / EA + sn * sn / kGA);
  }
  return numerator / denominator;
}

}  // namespace ogive::reference
