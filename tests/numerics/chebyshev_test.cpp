// Chebyshev-Lobatto rules (src/numerics/chebyshev.hpp): nested nodes, the cumulative integration matrix
// and the barycentric interpolant, exact on polynomials up to the rule's degree.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "numerics/chebyshev.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// Integral of x^k over [a, b].
double monomial_integral(int k, double a, double b) { return (std::pow(b, k + 1) - std::pow(a, k + 1)) / (k + 1); }

}  // namespace

TEST_CASE("Chebyshev-Lobatto rules: nested nodes, cumulative integrals and interpolation exact for degree N") {
  CHECK_THROWS_AS(chebyshev_rule(12), std::invalid_argument);
  CHECK_THROWS_AS(chebyshev_rule(512), std::invalid_argument);
  for (int N = kMinChebyshevDegree; N <= kMaxChebyshevDegree; N *= 2) {
    const ChebyshevRule& r = chebyshev_rule(N);
    REQUIRE(r.node.size() == N + 1);
    CHECK(r.node[0] == -1.0);
    CHECK(r.node[N] == 1.0);
    if (N < kMaxChebyshevDegree) {
      const ChebyshevRule& fine = chebyshev_rule(2 * N);
      for (int i = 0; i <= N; ++i) CHECK(fine.node[2 * i] == r.node[i]);
    }
    // Monomials up to degree N: the cumulative integral from -1 at every node, and the interpolant
    // between the nodes.
    for (int k : {0, 1, 2, N / 2, N - 1, N}) {
      Eigen::VectorXd f(N + 1);
      for (int i = 0; i <= N; ++i) f[i] = std::pow(r.node[i], k);
      const Eigen::VectorXd F = r.integration * f;
      double worst = 0;
      for (int i = 0; i <= N; ++i) worst = std::max(worst, std::abs(F[i] - monomial_integral(k, -1.0, r.node[i])));
      CAPTURE(N);
      CAPTURE(k);
      CHECK(worst <= kExact);
      for (double x : {-0.999, -0.31, 0.0123, 0.77}) {
        const double p = chebyshev_interpolate(r, f.transpose(), x)[0];
        CHECK(std::abs(p - std::pow(x, k)) <= kExact);
      }
    }
  }
}
