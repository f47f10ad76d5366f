#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "ogive/geometry/curve.hpp"
#include "tolerances.hpp"

using namespace ogive;

TEST_CASE("pointed curve: springing - crown and radius follow the construction") {
  const double L = 10.0;
  for (double eps : {0.0, 0.25, 0.5, 1.0, 3.0}) {
    CAPTURE(eps);
    const auto curve = make_pointed(L, eps);
    const double R = (0.5 + eps) * L;
    const double alpha_c = std::acos(eps / (0.5 + eps));
    CHECK(close(curve->length(), R * alpha_c, kExact));
    const CurvePoint spring = curve->at(0.0);
    CHECK(std::abs(spring.x) <= kExact * L);
    CHECK(std::abs(spring.y) <= kExact * L);
    CHECK(close(spring.theta, std::numbers::pi / 2, kExact));
    const CurvePoint crown = curve->at(curve->length());
    CHECK(close(crown.x, L / 2, kExact));
    CHECK(close(crown.y, R * std::sin(alpha_c), kExact));
    // Every point lies on the circle about (L/2 + eps L, 0).
    for (int i = 0; i <= 20; ++i) {
      const CurvePoint p = curve->at(curve->length() * i / 20.0);
      CHECK(close(std::hypot(p.x - (0.5 + eps) * L, p.y), R, kExact));
      CHECK(close(p.kappa, -1.0 / R, kExact));
    }
  }
}

TEST_CASE("pointed curve: the exact first moment agrees with quadrature") {
  // Curve::first_moment_x is composite Gauss-Legendre; the arc override is exact.
  struct Quadrature final : Curve {
    std::shared_ptr<const Curve> inner;
    std::string family() const override { return "quadrature"; }
    double span() const override { return inner->span(); }
    double length() const override { return inner->length(); }
    CurvePoint at(double s) const override { return inner->at(s); }
  };
  for (double eps : {0.0, 0.5, 2.0}) {
    Quadrature q;
    q.inner = make_pointed(10.0, eps);
    CHECK(close(q.first_moment_x(), q.inner->first_moment_x(), kExact));
  }
}

TEST_CASE("pointed curve: invalid construction throws naming the field") {
  CHECK_THROWS_WITH_AS(make_pointed(-1.0, 0.0), doctest::Contains("span"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_pointed(10.0, -0.1), doctest::Contains("eccentricity"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_pointed(10.0, std::nan("")), doctest::Contains("eccentricity"), std::invalid_argument);
}
