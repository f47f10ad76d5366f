// The library's one Gauss-Legendre rule (private header). Used by Curve::first_moment_x (8 points),
// the parametric curves' arc length (16 points) and the limit analysis' voussoirs (8 points); tests/reference.hpp keeps its own on purpose, so that
// the references stay independent of the code they check.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace ogive {

// N-point rule on [-1, 1]: nodes ascending, symmetric about 0; exact for polynomials of degree 2N - 1.
template <int N>
struct GaussLegendreRule {
  static_assert(N >= 1 && N <= 128, "GaussLegendreRule: 1 to 128 points");
  std::array<double, N> node{}, weight{};
};

// Computed once per N (thread-safe static), by Newton on the Legendre polynomial P_N from Tricomi's
// initial guess, to full double precision (tests/test_gauss_legendre.cpp checks it against published
// nodes and against exact polynomial integrals).
template <int N>
const GaussLegendreRule<N>& gauss_legendre() {
  static const GaussLegendreRule<N> rule = [] {
    GaussLegendreRule<N> r;
    // P_N(x) and P_N'(x) by the three-term recurrence.
    auto legendre = [](double x, double& derivative) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= N; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = N == 1 ? 1.0 : N * (x * p1 - p0) / (x * x - 1);
      return N == 1 ? x : p1;
    };
    for (int i = 0; i < (N + 1) / 2; ++i) {
      double x = std::cos(std::numbers::pi * (i + 0.75) / (N + 0.5));
      double dp = 0;
      for (int it = 0; it < 100; ++it) {
        const double dx = legendre(x, dp) / dp;
        x -= dx;
        if (std::abs(dx) <= 1e-17) break;
      }
      legendre(x, dp);  // P_N' at the converged node, for the weight
      const double w = 2 / ((1 - x * x) * dp * dp);
      r.node[i] = -x;
      r.weight[i] = w;
      r.node[N - 1 - i] = x;
      r.weight[N - 1 - i] = w;
    }
    if (N % 2 == 1) r.node[N / 2] = 0.0;  // the middle node of an odd rule, exactly
    return r;
  }();
  return rule;
}

// Integral of f over [a, b] (either order) by the N-point rule; f may return a number or a vector
// (an Eigen type: the limit analysis integrates centroids).
template <int N, class F>
auto gauss_legendre_integral(F&& f, double a, double b) {
  const GaussLegendreRule<N>& g = gauss_legendre<N>();
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  // The value type, evaluated: an Eigen expression must not outlive the temporaries it refers to.
  using Value = std::decay_t<decltype(f(a))>;
  Value sum = g.weight[0] * f(mid + half * g.node[0]);
  for (int i = 1; i < N; ++i) sum += g.weight[i] * f(mid + half * g.node[i]);
  return Value(half * sum);
}

}  // namespace ogive
