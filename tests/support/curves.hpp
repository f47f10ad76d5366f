// Curve helpers shared by the geometry tests: a derivative by finite differences, a curve that keeps
// Curve's default first moment, and exact samples of a parabola.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ogive/geometry/curve.hpp"

namespace ogive::test {

// Fourth-order central difference of g at s with step d: truncation ~d^4 g^(5) / 30, round-off
// ~1e-16 |g| / d.
inline double derivative(const std::function<double(double)>& g, double s, double d) {
  return (-g(s + 2 * d) + 8 * g(s + d) - 8 * g(s - d) + g(s - 2 * d)) / (12 * d);
}

// The default composite-Gauss first moment of a curve (Curve::first_moment_x, not the override).
struct DefaultMoment final : Curve {
  std::shared_ptr<const Curve> inner;
  std::string family() const override { return "quadrature"; }
  double span() const override { return inner->span(); }
  double length() const override { return inner->length(); }
  CurvePoint at(double s) const override { return inner->at(s); }
  std::vector<double> breakpoints() const override { return inner->breakpoints(); }
};

// The parabola of span L and rise h through both springings: its height and its axis' angle at x.
inline double parabola_y(double L, double h, double x) { return 4 * h * x * (L - x) / (L * L); }
inline double parabola_theta(double L, double h, double x) { return std::atan(4 * h * (L - 2 * x) / (L * L)); }

// n equally spaced exact points of the parabola's left half, springing to crown.
inline std::vector<std::pair<double, double>> parabola_points(double L, double h, int n) {
  std::vector<std::pair<double, double>> xy;
  for (int i = 0; i < n; ++i) {
    const double x = 0.5 * L * i / (n - 1);
    xy.emplace_back(x, parabola_y(L, h, x));
  }
  return xy;
}

}  // namespace ogive::test
