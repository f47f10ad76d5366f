// Gauss-Legendre rules (src/numerics/gauss_legendre.hpp): the published nodes and weights, symmetry, and
// exactness for polynomials up to degree 2N - 1.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "numerics/gauss_legendre.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// Published to 16 significant digits (Abramowitz & Stegun, table 25.4): agreement to their last digit.
constexpr double kPublishedDigits = 2e-16;

// Integral of x^k over [a, b].
double monomial_integral(int k, double a, double b) { return (std::pow(b, k + 1) - std::pow(a, k + 1)) / (k + 1); }

template <int N>
void check_gauss_exact() {
  const GaussLegendreRule<N>& g = gauss_legendre<N>();
  double sum = 0;
  for (int i = 0; i < N; ++i) {
    sum += g.weight[i];
    CHECK(g.weight[i] > 0);
    CHECK(g.node[i] == -g.node[N - 1 - i]);  // symmetric to the last bit
    if (i > 0) CHECK(g.node[i] > g.node[i - 1]);
  }
  CHECK(close(sum, 2.0, kExact));
  for (int k = 0; k <= 2 * N - 1; ++k) {
    const double exact = monomial_integral(k, -0.3, 1.0);
    const double rule = gauss_legendre_integral<N>([k](double x) { return std::pow(x, k); }, -0.3, 1.0);
    CAPTURE(N);
    CAPTURE(k);
    CHECK(std::abs(rule - exact) <= kExact * std::max(1.0, std::abs(exact)));
  }
}

}  // namespace

TEST_CASE("Gauss-Legendre: the published 8-point rule, and exact for polynomials of degree 2N - 1") {
  const GaussLegendreRule<8>& g = gauss_legendre<8>();
  const double nodes[] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  const double weights[] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  for (int i = 0; i < 4; ++i) {
    CHECK(std::abs(g.node[4 + i] - nodes[i]) <= kPublishedDigits * 4);
    CHECK(std::abs(g.weight[4 + i] - weights[i]) <= kPublishedDigits * 4);
  }
  CHECK(gauss_legendre<1>().node[0] == 0.0);
  CHECK(gauss_legendre<5>().node[2] == 0.0);
  check_gauss_exact<1>();
  check_gauss_exact<2>();
  check_gauss_exact<5>();
  check_gauss_exact<8>();
  check_gauss_exact<16>();
}
