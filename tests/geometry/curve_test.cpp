// The Curve interface (include/ogive/geometry/curve.hpp) and the pointed arch: its construction, the
// exact first moment against the default quadrature, the section's faces, a curve's own parameter and
// its largest curvature.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "ogive/geometry/curve.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "support/tolerances.hpp"

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

TEST_CASE("geometry: the faces are t/2 either side of the axis, across the tangent, extrados outside") {
  const double t = 0.8;
  for (const auto& curve : {make_pointed(10, 0.5), make_catenary(10, 0.4), make_four_centred(10, 0.42, 45, 15)}) {
    CAPTURE(curve->family());
    const double S = curve->length();
    for (int k = 0; k <= 20; ++k) {
      const CurvePoint p = curve->at_whole_arch(2 * S * k / 20);
      const SectionFaces f = section_faces(p, t);
      CHECK(std::abs(std::hypot(f.extrados.x - f.intrados.x, f.extrados.y - f.intrados.y) - t) <= kExact * t);
      CHECK(std::abs((f.extrados.x + f.intrados.x) / 2 - p.x) <= kExact * 10);
      CHECK(std::abs((f.extrados.y + f.intrados.y) / 2 - p.y) <= kExact * 10);
      // Perpendicular to the tangent (cos theta, sin theta).
      const double dot = (f.extrados.x - f.intrados.x) * std::cos(p.theta) + (f.extrados.y - f.intrados.y) * std::sin(p.theta);
      CHECK(std::abs(dot) <= kExact * t);
      // The extrados is the face farther from the arch's inside: from a point below the crown on the
      // mid-span line, every extrados point is farther than its intrados point.
      const double below_crown = 0.5 * curve->rise();
      CHECK(std::hypot(f.extrados.x - 5, f.extrados.y - below_crown) > std::hypot(f.intrados.x - 5, f.intrados.y - below_crown));
    }
  }
  // On the semicircle: the faces are the circles of radii R -+ t/2 about the centre (L/2, 0).
  const auto circle = make_pointed(10, 0);
  for (int k = 0; k <= 10; ++k) {
    const SectionFaces f = section_faces(circle->at(circle->length() * k / 10), t);
    CHECK(std::abs(std::hypot(f.intrados.x - 5, f.intrados.y) - (5 - t / 2)) <= kExact * 10);
    CHECK(std::abs(std::hypot(f.extrados.x - 5, f.extrados.y) - (5 + t / 2)) <= kExact * 10);
  }
}

TEST_CASE("curves: a parameter of their own agrees with the arc length (parabola, ellipse, surveys)") {
  const std::vector<std::shared_ptr<const Curve>> curves = {
      make_parabolic(10.0, 0.5), make_parabolic(10.0, 1.5), make_elliptical(10.0, 0.3), make_elliptical(10.0, 1.2),
      read_points_curve(OGIVE_DATA_DIR "/curves/catenary-survey.csv")};
  for (const auto& curve : curves) {
    const std::vector<double> knots = curve->parameter_knots();
    REQUIRE(knots.size() == curve->breakpoints().size() + 2);
    CAPTURE(curve->family());
    // The knots are the springing, the breakpoints and the crown.
    CHECK(curve->at_parameter(knots.front()).s == 0.0);
    CHECK(close(curve->at_parameter(knots.back()).s, curve->length(), kExact));
    for (std::size_t k = 1; k + 1 < knots.size(); ++k)
      CHECK(close(curve->at_parameter(knots[k]).s, curve->breakpoints()[k - 1], kExact));
    for (std::size_t k = 0; k + 1 < knots.size(); ++k)
      for (double f : {0.1, 0.37, 0.5, 0.93}) {
        const double t = knots[k] + f * (knots[k + 1] - knots[k]);
        const ParameterPoint p = curve->at_parameter(t);
        // The same point as at(s): the unit tangent, and t back from s.
        CHECK(std::abs(p.cos * p.cos + p.sin * p.sin - 1) <= kExact);
        CHECK(std::abs(std::atan2(p.sin, p.cos) - curve->at(p.s).theta) <= kExact);
        CHECK(std::abs(curve->parameter_at(p.s) - t) <= kExact * (knots.back() - knots.front()));
        // ds/dt against a central difference of s(t) (step 1e-5 of the piece: error ~ 1e-10 of s'').
        const double h = 1e-5 * (knots[k + 1] - knots[k]);
        const double difference = (curve->at_parameter(t + h).s - curve->at_parameter(t - h).s) / (2 * h);
        CHECK(close(p.speed, difference, 1e-8));
      }
  }
  // Curves whose arc length is their parameter have none of their own.
  for (const auto& curve : {make_catenary(10.0, 0.5), make_pointed(10.0, 0.5)}) {
    CHECK(curve->parameter_knots().empty());
    CHECK_THROWS_AS(curve->at_parameter(0.0), std::logic_error);
    CHECK_THROWS_AS(curve->parameter_at(0.0), std::logic_error);
  }
}

TEST_CASE("curves: the largest curvature they know agrees with sampling the curve (Scene::validate's rule)") {
  const std::vector<std::shared_ptr<const Curve>> curves = {
      make_pointed(10.0, 0.5),     make_four_centred(10.0, 0.42), make_catenary(10.0, 0.5),
      make_parabolic(10.0, 1.5),   make_elliptical(10.0, 0.3),    make_elliptical(10.0, 1.2),
      read_points_curve(OGIVE_DATA_DIR "/curves/catenary-survey.csv")};
  for (const auto& curve : curves) {
    double sampled = 0;
    constexpr int kSamples = 4096;
    for (int i = 0; i <= kSamples; ++i)
      sampled = std::max(sampled, std::abs(curve->at(curve->length() * i / kSamples).kappa));
    CAPTURE(curve->family());
    // Never smaller than what any sample shows (to round-off), and no more than sampling between the
    // samples can miss (the curvature varies smoothly between breakpoints).
    CHECK(curve->max_curvature() >= sampled * (1 - kExact));
    CHECK(curve->max_curvature() <= sampled * (1 + 1e-3));
  }
}

TEST_CASE("extrados over the crown: the semicircle's R + t/2, a pointed arch's where both sides' offset arcs meet") {
  // The semicircle of span L: the crown's extrados at L/2 + t/2 above the springing line, its half and
  // its whole arch alike.
  const double L = 10, t = 0.8;
  const auto semicircle = ogive::make_pointed(L, 0.0);
  CHECK(ogive::close(ogive::extrados_crown_height(*semicircle, t), L / 2 + t / 2, ogive::kExact));
  CHECK(ogive::close(ogive::extrados_crown_height(*ogive::whole_arch(semicircle), t), L / 2 + t / 2, ogive::kExact));
  // The pointed arch: the left arc's centre at R from the left springing on the springing line, its
  // extrados the circle of radius R + t/2, over x = L/2 at sqrt((R + t/2)^2 - (R - L/2)^2).
  for (double rise_ratio : {0.6, std::sqrt(0.75), 1.2}) {
    const double e = ogive::pointed_eccentricity_for_rise(rise_ratio), R = ogive::pointed_radius(L, e);
    const auto pointed = ogive::make_pointed(L, e);
    CAPTURE(rise_ratio);
    CHECK(ogive::close(pointed->rise() / L, rise_ratio, ogive::kExact));
    const double expected = std::sqrt((R + t / 2) * (R + t / 2) - (R - L / 2) * (R - L / 2));
    CHECK(ogive::close(ogive::extrados_crown_height(*pointed, t), expected, ogive::kExact));
    CHECK(ogive::extrados_crown_height(*pointed, t) > pointed->rise() + t / 2);  // above a kink: higher
    CHECK(ogive::close(ogive::pointed_eccentricity_for_radius(R / L), e, ogive::kExact));
  }
}
