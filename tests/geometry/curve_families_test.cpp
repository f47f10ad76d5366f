// The curve families (include/ogive/geometry/curve_families.hpp): each one's springing and crown, its
// arc-length parametrisation against finite differences, its length and first moment against an
// independent quadrature, its own construction (radius formulas, tangent continuity, the curve's
// equation) and the refusal of invalid parameters.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "ogive/geometry/curve_families.hpp"
#include "support/curves.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

constexpr double kPi = std::numbers::pi;
// Fourth-order central differences with a step d = 1e-3 times the smallest radius of curvature:
// truncation ~(1e-3)^4 / 30, round-off ~1e-16 L / d.
constexpr double kFiniteDifference = 1e-9;
// An independent composite Simpson rule on 20000 panels of a smooth integrand.
constexpr double kQuadrature = 1e-12;

struct Sample {
  std::string label;
  std::shared_ptr<const Curve> curve;
  double span, rise;
  bool smooth;  // not piecewise circular
};

std::vector<Sample> family_samples() {
  const double L = 10.0;
  std::vector<Sample> out;
  auto add = [&](std::string label, std::shared_ptr<const Curve> c, double rr, bool smooth) {
    out.push_back({std::move(label), std::move(c), L, rr * L, smooth});
  };
  for (double rr : {0.1, 0.3, 0.45}) add("segmental " + std::to_string(rr), make_segmental(L, rr), rr, false);
  add("three-centred 0.3", make_three_centred(L, 0.3), 0.3, false);
  add("three-centred 0.2 at 50", make_three_centred(L, 0.2, 50), 0.2, false);
  add("four-centred 0.35", make_four_centred(L, 0.35), 0.35, false);
  add("four-centred 0.3 at 60/10", make_four_centred(L, 0.3, 60, 10), 0.3, false);
  for (double rr : {0.1, 0.3, 0.5, 1.5}) add("elliptical " + std::to_string(rr), make_elliptical(L, rr), rr, true);
  for (double rr : {0.05, 0.5, 2.0}) add("parabolic " + std::to_string(rr), make_parabolic(L, rr), rr, true);
  for (double rr : {0.05, 0.3, 2.0}) add("catenary " + std::to_string(rr), make_catenary(L, rr), rr, true);
  return out;
}

double simpson(const std::function<double(double)>& f, double a, double b, int panels = 20000) {
  const double h = (b - a) / panels;
  double sum = f(a) + f(b);
  for (int i = 1; i < panels; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3;
}

}  // namespace

TEST_CASE("every family starts at the springing and ends at the crown (L/2 - h)") {
  for (const Sample& f : family_samples()) {
    CAPTURE(f.label);
    const Curve& c = *f.curve;
    CHECK(c.span() == f.span);
    CHECK(c.length() > 0);
    const CurvePoint spring = c.at(0.0), crown = c.at(c.length());
    CHECK(std::abs(spring.x) <= kExact * f.span);
    CHECK(std::abs(spring.y) <= kExact * f.span);
    CHECK(close(crown.x, f.span / 2, kExact));
    CHECK(close(crown.y, f.rise, kExact));
    CHECK(close(c.rise(), f.rise, kExact));
    if (c.family() == "four-centred")
      CHECK(crown.theta > 0.01);
    else
      CHECK(std::abs(crown.theta) <= kExact);
    CHECK(f.smooth == c.arcs().empty());
    if (f.smooth) CHECK(c.breakpoints().empty());
  }
}

TEST_CASE("every family is ds-consistent: dx/ds = cos theta - dy/ds = sin theta - dtheta/ds = kappa < 0") {
  for (const Sample& f : family_samples()) {
    CAPTURE(f.label);
    const Curve& c = *f.curve;
    const double S = c.length();
    const auto bps = c.breakpoints();
    double max_kappa = 0;
    for (int i = 0; i <= 200; ++i) max_kappa = std::max(max_kappa, std::abs(c.at(S * i / 200).kappa));
    const double d = std::min(1e-3 * S, 1e-3 / max_kappa);  // a step small against the radius of curvature
    for (int i = 1; i < 60; ++i) {
      const double s = S * i / 60.0;
      CAPTURE(s);
      const CurvePoint p = c.at(s);
      CHECK(p.kappa < 0);
      bool near_break = false;
      for (double b : bps) near_break = near_break || std::abs(s - b) < 3 * d;
      if (near_break) continue;
      CHECK(std::abs(derivative([&](double t) { return c.at(t).x; }, s, d) - std::cos(p.theta)) <= kFiniteDifference);
      CHECK(std::abs(derivative([&](double t) { return c.at(t).y; }, s, d) - std::sin(p.theta)) <= kFiniteDifference);
      CHECK(std::abs(derivative([&](double t) { return c.at(t).theta; }, s, d) - p.kappa) <=
            kFiniteDifference * max_kappa);
    }
  }
}

TEST_CASE("smooth family half_length and first_moment_x agree with an independent quadrature") {
  const double L = 10.0, U = 5.0;
  for (double rr : {0.05, 0.3, 0.5, 2.0}) {
    CAPTURE(rr);
    const double h = rr * L;
    {  // Parabola: ds = sqrt(1 + y'^2) dx.
      const auto c = make_parabolic(L, rr);
      auto ds = [&](double x) { return std::hypot(1.0, 4 * h * (L - 2 * x) / (L * L)); };
      CHECK(close(c->length(), simpson(ds, 0, U), kQuadrature));
      CHECK(close(c->first_moment_x(), simpson([&](double x) { return x * ds(x); }, 0, U), kQuadrature));
    }
    {  // Catenary.
      const double a = catenary_parameter(L, rr);
      const auto c = make_catenary(L, rr);
      auto ds = [&](double x) { return std::cosh((x - U) / a); };
      CHECK(close(c->length(), simpson(ds, 0, U), kQuadrature));
      CHECK(close(c->first_moment_x(), simpson([&](double x) { return x * ds(x); }, 0, U), kQuadrature));
    }
    if (rr <= 1.5) {  // Ellipse: the quarter perimeter by the trapezoid rule over the whole period.
      const auto c = make_elliptical(L, rr);
      auto speed = [&](double t) { return std::hypot(U * std::sin(t), h * std::cos(t)); };
      const int n = 4000;
      double perimeter = 0;
      for (int i = 0; i < n; ++i) perimeter += speed(2 * kPi * i / n) * (2 * kPi / n);
      CHECK(close(c->length(), perimeter / 4, kQuadrature));
      CHECK(close(c->first_moment_x(),
                  simpson([&](double t) { return U * (1 - std::cos(t)) * speed(t); }, 0, kPi / 2), kQuadrature));
    }
  }
  // Every family's first moment agrees with the default composite-Gauss rule on its own at(s).
  for (const Sample& f : family_samples()) {
    CAPTURE(f.label);
    DefaultMoment q;
    q.inner = f.curve;
    CHECK(close(q.first_moment_x(), f.curve->first_moment_x(), kExact));
  }
}

TEST_CASE("smooth family at(s) continues smoothly just beyond both ends") {
  std::vector<std::shared_ptr<const Curve>> curves = {make_elliptical(10, 0.2), make_parabolic(10, 0.5),
                                                      make_catenary(10, 0.3),
                                                      make_points_curve(parabola_points(10, 5, 20))};
  for (const auto& c : curves) {
    CAPTURE(c->family());
    const double S = c->length(), d = 1e-7 * S;
    for (double s0 : {0.0, S}) {
      const CurvePoint p = c->at(s0);
      for (double ds : {-d, d}) {
        const CurvePoint q = c->at(s0 + ds);
        CHECK(std::isfinite(q.x + q.y + q.theta + q.kappa));
        // Second order in ds: |kappa| ds^2 / 2 at most, plus round-off.
        CHECK(std::abs(q.x - (p.x + ds * std::cos(p.theta))) <= std::abs(p.kappa) * d * d + kExact * 10);
        CHECK(std::abs(q.y - (p.y + ds * std::sin(p.theta))) <= std::abs(p.kappa) * d * d + kExact * 10);
      }
    }
  }
}

TEST_CASE("elliptical family at rise L/2 is the semicircle") {
  const double L = 10.0;
  const auto e = make_elliptical(L, 0.5);
  const auto c = make_pointed(L, 0.0);
  CHECK(close(e->length(), c->length(), kExact));
  for (int i = 0; i <= 100; ++i) {
    const double s = c->length() * i / 100;
    CAPTURE(s);
    const CurvePoint p = e->at(s), q = c->at(s);
    CHECK(std::abs(p.x - q.x) <= kExact * L);
    CHECK(std::abs(p.y - q.y) <= kExact * L);
    CHECK(std::abs(p.theta - q.theta) <= kExact);
    CHECK(close(p.kappa, q.kappa, kExact));
  }
}

TEST_CASE("elliptical family lies on its ellipse with the ellipse's curvature") {
  const double L = 10.0, a = 5.0;
  for (double rr : {0.1, 0.3, 1.5}) {
    const double h = rr * L;
    const auto c = make_elliptical(L, rr);
    for (int i = 0; i <= 50; ++i) {
      const CurvePoint p = c->at(c->length() * i / 50);
      const double u = (p.x - a) / a, v = p.y / h;
      CHECK(std::abs(u * u + v * v - 1) <= kExact);
      // kappa = -a h / (a^2 sin^2 t + h^2 cos^2 t)^{3/2} with cos t = -u, sin t = v.
      const double q = a * a * v * v + h * h * u * u;
      CHECK(close(p.kappa, -a * h / (q * std::sqrt(q)), 1e-10));
    }
  }
}

TEST_CASE("segmental family follows the known radius formula") {
  const double L = 10.0;
  for (double rr : {0.05, 0.25, 0.49}) {
    CAPTURE(rr);
    const double h = rr * L;
    const double R = (L * L / 4 + h * h) / (2 * h);
    const auto c = make_segmental(L, rr);
    REQUIRE(c->arcs().size() == 1);
    CHECK(close(c->arcs()[0].kappa, -1 / R, kExact));
    CHECK(close(c->at(0).theta, std::asin(L / (2 * R)), kExact));
    CHECK(close(c->length(), R * std::asin(L / (2 * R)), kExact));
    for (int i = 0; i <= 20; ++i) {
      const CurvePoint p = c->at(c->length() * i / 20);
      CHECK(close(std::hypot(p.x - L / 2, p.y - (h - R)), R, kExact));
    }
  }
}

TEST_CASE("three-centred family: tangent-continuous - curvature jumps from -1/r1 to -1/r2 at the breakpoint") {
  const double L = 10.0;
  for (double phi_deg : {30.0, 60.0, 75.0}) {
    const auto [lo, hi] = three_centred_rise_range(phi_deg);
    CHECK(close(lo, (1 - std::sin(phi_deg * kPi / 180)) / (2 * std::cos(phi_deg * kPi / 180)), kExact));
    CHECK(hi == 0.5);
    for (double t : {0.02, 0.5, 0.98}) {
      const double rr = lo + t * (hi - lo), h = rr * L, phi = phi_deg * kPi / 180;
      CAPTURE(phi_deg);
      CAPTURE(rr);
      const auto c = make_three_centred(L, rr, phi_deg);
      const auto bps = c->breakpoints();
      REQUIRE(bps.size() == 1);
      const double b = bps[0], eps = 1e-9 * c->length();
      const CurvePoint before = c->at(b - eps), after = c->at(b + eps), at = c->at(b);
      // Tangent-continuous: the jump across 2 eps is the turning of the arcs over that length.
      CHECK(std::abs(after.theta - before.theta) <= eps * (std::abs(before.kappa) + std::abs(after.kappa)) + kExact);
      const CurvePoint haunch_end = point_on_arc(c->arcs()[0], c->arcs()[0].length);
      CHECK(std::abs(haunch_end.theta - c->arcs()[1].theta_start) <= kExact);
      CHECK(close(at.theta, kPi / 2 - phi, kExact));
      const double r1 = -1 / before.kappa, r2 = -1 / after.kappa;
      CHECK(r1 > 0);
      CHECK(r2 > r1);
      // Independent geometry: haunch centre (r1, 0); crown centre (L/2, h - r2); the joint is on both
      // circles and on the line through both centres.
      CHECK(close(std::hypot(at.x - r1, at.y), r1, kExact));
      CHECK(close(std::hypot(at.x - L / 2, at.y - (h - r2)), r2, kExact));
      CHECK(close(std::hypot(L / 2 - r1, h - r2), r2 - r1, kExact));
    }
  }
  // Classic equal-angle construction: each of the three arcs subtends 60 degrees.
  const auto c = make_three_centred(L, 0.3);
  REQUIRE(c->arcs().size() == 2);
  CHECK(close(c->arcs()[0].length * -c->arcs()[0].kappa, kPi / 3, kExact));
  CHECK(close(c->arcs()[1].length * -c->arcs()[1].kappa, kPi / 6, kExact));  // half of the crown arc
  // Outside the interval: refused, naming rise_ratio and the interval.
  CHECK_THROWS_WITH_AS(make_three_centred(L, 0.1), doctest::Contains("rise_ratio: must lie in (0.133975, 0.5)"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_three_centred(L, 0.5), doctest::Contains("rise_ratio"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_three_centred(L, 0.3, 90), doctest::Contains("haunch_angle"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_three_centred(L, 0.3, 0), doctest::Contains("haunch_angle"), std::invalid_argument);
}

TEST_CASE("four-centred family reproduces the quarter-point construction and joins tangentially") {
  // Haunch centres at the quarter points (r1 = L/4), crown centres at the lower corners of the square
  // standing below them: the left crown arc is centred at (3L/4, -L/2) with r2 = L/4 + L/sqrt(2).
  const double L = 8.0;
  const double r1 = L / 4, r2 = L / 4 + L / std::sqrt(2.0);
  const double crown_deg = std::asin(r1 / r2) * 180 / kPi;
  const double rise = -L / 2 + std::sqrt(r2 * r2 - r1 * r1);
  const auto c = make_four_centred(L, rise / L, 45, crown_deg);
  REQUIRE(c->arcs().size() == 2);
  CHECK(close(-1 / c->arcs()[0].kappa, r1, kExact));
  CHECK(close(-1 / c->arcs()[1].kappa, r2, kExact));
  CHECK(close(c->at(c->length()).theta, crown_deg * kPi / 180, kExact));
  for (int i = 0; i <= 10; ++i) {
    const double s = c->arcs()[1].s_start + c->arcs()[1].length * i / 10;
    const CurvePoint p = c->at(s);
    CHECK(close(std::hypot(p.x - 3 * L / 4, p.y + L / 2), r2, kExact));
  }
  const double b = c->breakpoints().at(0), eps = 1e-9;
  CHECK(std::abs(c->at(b + eps).theta - c->at(b - eps).theta) <= 2 * eps / r1);
  CHECK(std::abs(point_on_arc(c->arcs()[0], c->arcs()[0].length).theta - c->arcs()[1].theta_start) <= kExact);
  CHECK(close(c->at(b).theta, kPi / 4, kExact));
  // The defaults' interval, and refusals.
  const auto [lo, hi] = four_centred_rise_range(45, 15);
  CHECK(std::abs(lo - 0.288675) < 1e-6);
  CHECK(std::abs(hi - 0.651613) < 1e-6);
  CHECK_NOTHROW(make_four_centred(L, lo + 1e-9));
  CHECK_NOTHROW(make_four_centred(L, hi - 1e-9));
  CHECK_THROWS_WITH_AS(make_four_centred(L, 0.25), doctest::Contains("rise_ratio: must lie in (0.288675, 0.651613)"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_four_centred(L, 0.7), doctest::Contains("rise_ratio"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_four_centred(L, 0.4, 45, 0), doctest::Contains("crown_angle"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_four_centred(L, 0.4, 45, 45), doctest::Contains("crown_angle"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_four_centred(L, 0.4, 95, 5), doctest::Contains("haunch_angle"), std::invalid_argument);
}

TEST_CASE("catenary family: the parameter solves a (cosh(L/2a) - 1) = h and the curve is the catenary") {
  const double L = 10.0;
  for (double rr : {1e-4, 0.05, 0.3, 0.5, 2.0}) {
    CAPTURE(rr);
    const double h = rr * L, a = catenary_parameter(L, rr);
    // a (cosh z - 1) = 2 a sinh^2(z / 2), the form without cancellation for small rises.
    CHECK(close(2 * a * std::pow(std::sinh(L / (4 * a)), 2), h, kExact));
    if (rr >= 0.05) CHECK(close(a * (std::cosh(L / (2 * a)) - 1), h, kExact));
    const auto c = make_catenary(L, rr);
    // Funicular: H / V at the springing = cot theta(0) = 1 / sinh(L / 2a).
    CHECK(close(1 / std::tan(c->at(0).theta), 1 / std::sinh(L / (2 * a)), kExact));
    for (int i = 0; i <= 20; ++i) {
      const CurvePoint p = c->at(c->length() * i / 20);
      CHECK(std::abs(p.y - (h - a * (std::cosh((p.x - L / 2) / a) - 1))) <= kExact * L);
    }
  }
}

TEST_CASE("parabolic family: y(x) - the springing angle atan(4h/L) and the curvature") {
  const double L = 10.0;
  for (double rr : {0.05, 0.5, 2.0}) {
    const double h = rr * L;
    const auto c = make_parabolic(L, rr);
    CHECK(close(c->at(0).theta, std::atan(4 * h / L), kExact));
    for (int i = 0; i <= 20; ++i) {
      const CurvePoint p = c->at(c->length() * i / 20);
      CHECK(std::abs(p.y - parabola_y(L, h, p.x)) <= kExact * L);
      CHECK(std::abs(p.theta - parabola_theta(L, h, p.x)) <= kExact);
      const double slope = std::tan(p.theta);
      CHECK(close(p.kappa, -8 * h / (L * L) / std::pow(1 + slope * slope, 1.5), kExact));
    }
  }
}

TEST_CASE("family factories refuse invalid parameters - naming the field") {
  CHECK_THROWS_WITH_AS(make_segmental(10, 0.7), "rise_ratio: must lie in (0, 0.5) for a segmental arch, got 0.7",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_segmental(-1, 0.2), doctest::Contains("span: "), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_segmental(10, 0), doctest::Contains("rise_ratio: "), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_elliptical(10, 2.5), "rise_ratio: must lie in [1e-06, 2] for an elliptical arch, got 2.5",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_parabolic(10, std::nan("")), doctest::Contains("rise_ratio: "), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_catenary(10, -0.1), doctest::Contains("rise_ratio: "), std::invalid_argument);
  CHECK_THROWS_WITH_AS(catenary_parameter(0, 0.1), doctest::Contains("span: "), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_three_centred(INFINITY, 0.3), doctest::Contains("span: "), std::invalid_argument);
}
