// Whole-arch points curves (springing to springing, springings at any heights): the fit against exact
// curves, against the half fit it must equal on symmetric points, the rules and the invariants.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "fuzz/fuzz_checks.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/model/scene.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

using Points = std::vector<std::pair<double, double>>;

// The whole fit of symmetric points and the half fit mirrored are one spline (the header's claim for the
// half fit): they differ by round-off only, in the chord lengths of the mirrored points (measured 7e-16 L in
// position and angle, 3e-14 of the largest curvature).
constexpr double kSameSpline = 1e-13;

std::string data_file(const char* name) {
  return std::string(OGIVE_DATA_DIR) + "/curves/" + name;
}

std::shared_ptr<const Curve> parse_whole(const std::string& text) {
  std::istringstream in(text);
  return parse_whole_points_curve(in, "w.csv");
}

// The symmetric parabola y = 4 h x (L - x) / L^2 at n equally spaced x over [0, x_end].
Points parabola_points(double L, double h, int n, double x_end) {
  Points xy;
  for (int i = 0; i < n; ++i) {
    const double x = x_end * i / (n - 1);
    xy.emplace_back(x, 4 * h * x * (L - x) / (L * L));
  }
  return xy;
}

// An asymmetric exact curve: the parabola y = c - k (x - a)^2 through (0, 0) and (L, h_right) with its
// apex at x = a, so k = h_right / (L (2a - L)) and c = k a^2. Arc length in closed form.
struct TiltedParabola {
  double L, h_right, a;
  double k() const { return h_right / (L * (2 * a - L)); }
  double c() const { return k() * a * a; }
  double y(double x) const { return c() - k() * (x - a) * (x - a); }
  double theta(double x) const { return std::atan(-2 * k() * (x - a)); }
  // The arc length from x = 0: with u = 2k(x - a), ds = sqrt(1 + u^2) dx = sqrt(1 + u^2) du / (2k).
  double arc_length(double x) const {
    const auto primitive = [&](double u) { return 0.5 * (u * std::sqrt(1 + u * u) + std::asinh(u)) / (2 * k()); };
    return primitive(2 * k() * (x - a)) - primitive(-2 * k() * a);
  }
  Points points(int n) const {
    Points xy;
    for (int i = 0; i < n; ++i) {
      const double x = L * i / (n - 1);
      xy.emplace_back(x, i == 0 ? 0.0 : i == n - 1 ? h_right : y(x));  // the ends exact
    }
    return xy;
  }
};

// The invariants a whole points curve keeps exactly or to round-off, whatever its points.
void check_whole_invariants(const Curve& c, std::size_t points) {
  CHECK(c.extent() == CurveExtent::whole);
  CHECK(c.family() == "whole-points");
  CHECK(c.arcs().empty());
  const double S = c.length();
  CHECK(c.whole_length() == S);
  CHECK(c.at(0).x == 0);
  CHECK(c.at(0).y == 0);
  CHECK(c.at(S).x == c.span());
  CHECK(c.at(S).y == c.right_springing_height());
  // One restart per interior point, strictly increasing inside (0, S); the knots are the points' tau.
  const std::vector<double> bp = c.breakpoints();
  CHECK(bp.size() == points - 2);
  CHECK(std::adjacent_find(bp.begin(), bp.end(), std::greater_equal<>()) == bp.end());
  CHECK(bp.front() > 0);
  CHECK(bp.back() < S);
  const std::vector<double> knots = c.parameter_knots();
  REQUIRE(knots.size() == points);
  CHECK(c.at_parameter(knots.front()).s == 0);
  CHECK(c.at_parameter(knots.back()).s == S);
  for (std::size_t i = 0; i < bp.size(); ++i) CHECK(c.at_parameter(knots[i + 1]).s == bp[i]);
  // x never decreases, no point is above the crown, whose tangent is horizontal (a root of dy/dtau).
  const double crown = c.crown(), rise = c.rise();
  CHECK(crown > 0);
  CHECK(crown < S);
  CHECK(std::abs(c.at(crown).theta) <= kExact);
  double previous_x = 0;
  for (int i = 0; i <= 4000; ++i) {
    const CurvePoint p = c.at(S * i / 4000);
    CHECK(p.x >= previous_x);
    CHECK(p.y <= rise);
    previous_x = p.x;
  }
  CHECK_NOTHROW(fuzz::check_curve(c));
}

// The largest |dy| and |dtheta| against an exact curve over 2000 stations of s.
struct Deviation {
  double y = 0, theta = 0;
};
Deviation deviation(const Curve& c, const std::function<double(double)>& y, const std::function<double(double)>& theta) {
  Deviation d;
  for (int i = 0; i <= 2000; ++i) {
    const CurvePoint p = c.at(c.length() * i / 2000);
    d.y = std::max(d.y, std::abs(p.y - y(p.x)));
    d.theta = std::max(d.theta, std::abs(p.theta - theta(p.x)));
  }
  return d;
}

}  // namespace

TEST_CASE("whole points from a symmetric parabola reproduce it and equal the mirrored half fit") {
  const double L = 10.0, h = 5.0;
  const double exact_length = 2 * make_parabolic(L, 0.5)->length();
  const auto y = [&](double x) { return 4 * h * x * (L - x) / (L * L); };
  const auto theta = [&](double x) { return std::atan(4 * h * (L - 2 * x) / (L * L)); };
  Deviation previous;
  double previous_length = 0;
  for (int half_points : {21, 41, 81}) {
    const int n = 2 * half_points - 1;
    CAPTURE(n);
    const auto c = make_whole_points_curve(parabola_points(L, h, n, L));
    check_whole_invariants(*c, n);
    CHECK(c->span() == L);
    CHECK(c->right_springing_height() == 0);
    const Deviation d = deviation(*c, y, theta);
    const double err_length = std::abs(c->length() - exact_length);
    const double err_crown = std::abs(c->crown() - 0.5 * exact_length);
    MESSAGE("n ", n, ": max |dy| ", d.y, " m, max |dtheta| ", d.theta, " rad, |dS| ", err_length, " m, |d crown| ",
            err_crown, " m");
    CHECK(d.y <= 1e-5 * L);
    CHECK(d.theta <= 1e-3);
    CHECK(err_length <= 1e-5 * L);
    CHECK(std::abs(c->at(c->crown()).x - 0.5 * L) <= 1e-12 * L);  // the fit is symmetric
    CHECK(close(c->rise(), h, kExact));  // the middle point is the apex, and the fit's too
    if (half_points > 21) {
      CHECK(d.y < previous.y / 8);  // fourth order: 16 per halving
      CHECK(d.theta < previous.theta / 4);
      CHECK(err_length < previous_length / 8);
    }
    previous = d;
    previous_length = err_length;
    // The half file of the left half, mirrored: the same spline.
    const auto mirrored = whole_arch(make_points_curve(parabola_points(L, h, half_points, 0.5 * L)));
    CHECK(close(c->length(), mirrored->length(), kSameSpline));
    CHECK(close(c->crown(), mirrored->crown(), kSameSpline));
    CHECK(close(c->first_moment_x(), mirrored->first_moment_x(), kSameSpline));
    for (int i = 0; i <= 400; ++i) {
      const double s = c->length() * i / 400;
      const CurvePoint p = c->at(s), q = mirrored->at(s);
      CHECK(std::abs(p.x - q.x) <= kSameSpline * L);
      CHECK(std::abs(p.y - q.y) <= kSameSpline * L);
      CHECK(std::abs(p.theta - q.theta) <= kSameSpline);
      CHECK(std::abs(p.kappa - q.kappa) <= kSameSpline * c->max_curvature());  // measured 1.2e-14 of 0.4 /m
    }
  }
}

TEST_CASE("whole points of an asymmetric parabola converge to it, with the crown at its apex") {
  // Springings at different heights (the right one 2 m up), the apex 1 m right of mid-span.
  for (const TiltedParabola exact : {TiltedParabola{10, 2, 6}, TiltedParabola{10, -1.5, 4.5}}) {
    CAPTURE(exact.h_right);
    const double apex_s = exact.arc_length(exact.a), total = exact.arc_length(exact.L);
    Deviation previous;
    double previous_length = 0, previous_crown = 0;
    for (int n : {40, 80, 160}) {
      CAPTURE(n);
      const auto c = make_whole_points_curve(exact.points(n));
      check_whole_invariants(*c, n);
      CHECK(c->span() == exact.L);
      CHECK(c->right_springing_height() == exact.h_right);
      const Deviation d = deviation(
          *c, [&](double x) { return exact.y(x); }, [&](double x) { return exact.theta(x); });
      const double err_length = std::abs(c->length() - total);
      const double err_crown = std::abs(c->crown() - apex_s);
      const CurvePoint top = c->at(c->crown());
      MESSAGE("n ", n, ": max |dy| ", d.y, " m, max |dtheta| ", d.theta, " rad, |dS| ", err_length,
              " m, |d crown s| ", err_crown, " m, crown x ", top.x, ", y ", top.y);
      CHECK(d.y <= 1e-5 * exact.L);
      CHECK(d.theta <= 1e-3);
      CHECK(err_length <= 1e-5 * exact.L);
      CHECK(err_crown <= 1e-4 * exact.L);
      CHECK(std::abs(top.x - exact.a) <= 1e-4 * exact.L);
      CHECK(std::abs(top.y - exact.c()) <= 1e-6 * exact.L);
      CHECK(c->rise() == top.y);
      if (n > 40) {
        CHECK(d.y < previous.y / 8);  // fourth order
        CHECK(d.theta < previous.theta / 4);  // third order
        CHECK(err_length < previous_length / 8);
        CHECK(err_crown < previous_crown / 4);  // where theta = 0: as accurate as theta
      }
      previous = d;
      previous_length = err_length;
      previous_crown = err_crown;
    }
  }
}

TEST_CASE("whole points files shipped in data/curves fit their curves") {
  {
    // 41 points of the parabola of span 10 and rise 5: its left 21 are parabola-40's curve's kind.
    const auto c = read_whole_points_curve(data_file("parabola-whole-41.csv"));
    check_whole_invariants(*c, 41);
    CHECK(c->span() == 10);
    CHECK(c->rise() == 5);
    const auto mirrored = whole_arch(make_points_curve(parabola_points(10, 5, 21, 5)));
    CHECK(close(c->length(), mirrored->length(), kSameSpline));
    for (int i = 0; i <= 100; ++i) {
      const double s = c->length() * i / 100;
      CHECK(std::abs(c->at(s).y - mirrored->at(s).y) <= kSameSpline * 10);
    }
  }
  {
    // A rampant arch: a circular arc of centre (3.3, -0.8) from the left springing, through the right
    // springing 6 m away and 1.259 m higher; 25 points surveyed with +-3 mm noise (the left springing
    // is the survey's datum, at (100, 50)), given to the millimetre.
    const auto c = read_whole_points_curve(data_file("rampant-survey.csv"));
    check_whole_invariants(*c, 25);
    const double cx = 3.3, cy = -0.8, R = std::hypot(cx, cy);
    CHECK(close(c->span(), 6.002, kExact));
    CHECK(close(c->right_springing_height(), 1.260, kExact));
    CHECK(std::abs(c->right_springing_height() - (cy + std::sqrt(R * R - (6 - cx) * (6 - cx)))) <= 3e-3);
    double worst = 0;
    for (int i = 0; i <= 400; ++i) {
      const CurvePoint p = c->at(c->length() * i / 400);
      worst = std::max(worst, std::abs(std::hypot(p.x - cx, p.y - cy) - R));
    }
    MESSAGE("rampant survey: max distance from the circle ", worst, " m; crown at x ", c->at(c->crown()).x, ", rise ",
            c->rise());
    CHECK(worst <= 5e-3);  // the survey's noise, 3 mm, and the fit between the points
    CHECK(std::abs(c->rise() - (R + cy)) <= 5e-3);
    // Near the flat crown 3 mm of noise in y over 0.3 m moves the apex by noise/spacing x R ~ 0.1 m.
    CHECK(std::abs(c->at(c->crown()).x - cx) <= 0.1);
    // The arc's length to round-off of the noise: R times its angle.
    const double angle = std::atan2(-cy, -cx) - std::atan2(1.260 - cy, 6.002 - cx);
    CHECK(std::abs(c->length() - R * angle) <= 1e-2);
  }
}

TEST_CASE("whole points invariants hold for springings at either height and the file equals the direct points") {
  // The rampant survey mirrored: the right springing lower than the left.
  const auto survey = read_whole_points_curve(data_file("rampant-survey.csv"));
  Points mirrored;
  const std::vector<double> knots = survey->parameter_knots();
  for (auto it = knots.rbegin(); it != knots.rend(); ++it) {
    const CurvePoint p = survey->at(survey->at_parameter(*it).s);
    mirrored.emplace_back(survey->span() - p.x, p.y);
  }
  const auto c = make_whole_points_curve(mirrored);
  check_whole_invariants(*c, mirrored.size());
  CHECK(close(c->right_springing_height(), -survey->right_springing_height(), kExact));
  CHECK(close(c->length(), survey->length(), 1e-12));  // the not-a-knot fit is symmetric under reversal
  CHECK(close(c->length() - c->crown(), survey->crown(), 1e-12));
  CHECK(close(c->rise(), survey->rise() - survey->right_springing_height(), 1e-12));  // from the other springing
  // The 4-point minimum: one cubic.
  const auto minimal = parse_whole("x,y\n0,0\n1,1\n2,1\n3,0\n");
  check_whole_invariants(*minimal, 4);
  CHECK(close(minimal->at(minimal->crown()).x, 1.5, kExact));
  // A file translates to the same curve as its points given directly.
  std::string text = "x,y\n";
  const TiltedParabola tilted{8, 1, 4.5};
  Points shifted = tilted.points(17);
  for (auto& [x, y] : shifted) {
    x += 250;
    y -= 30;
    text += fmt::format("{},{}\n", x, y);
  }
  const auto from_file = parse_whole(text), direct = make_whole_points_curve(shifted);
  CHECK(from_file->length() == direct->length());
  CHECK(from_file->crown() == direct->crown());
  CHECK(close(from_file->span(), 8, kExact));
  CHECK(close(from_file->right_springing_height(), 1, kExact));
}

TEST_CASE("whole points file errors name the line and the rule") {
  struct Case {
    std::string text;
    std::size_t line;
    std::string rule;
  };
  std::string semicircle = "x,y\n";  // vertical springing tangents, sampled exactly
  for (int i = 0; i < 13; ++i) {
    const double a = std::numbers::pi * (1 - i / 12.0);
    semicircle += fmt::format("{},{}\n", 5 + 5 * std::cos(a), i == 0 || i == 12 ? 0.0 : 5 * std::sin(a));
  }
  const std::vector<Case> cases = {
      // The one reader: the syntax rules and their lines as for the half files.
      {"", 1, "empty file"},
      {"a,b\n0,0\n1,1\n2,1\n3,0\n", 1, "the header must be x,y"},
      {"x,y\n0,0\n1,1\n2,x\n3,0\n", 4, "y is not a number: \"x\""},
      {"x,y\n", 1, "0 points, a whole-points curve needs at least 4"},
      {"x,y\n0,0\n1,1\n2,0\n", 4, "3 points, a whole-points curve needs at least 4"},
      // The whole rules.
      {"x,y\n0,0\n0.0001,0.001\n0.0002,0.001\n0.0005,0\n", 5,
       "the span x_last - x_first (springing to springing) must lie in [0.001, 1000000] m, got 0.0005"},
      {"x,y\n0,0\n1,1\n2,1.5\n1.5,1.6\n3,1\n4,0\n", 5,
       "x must increase from springing to springing (1.5 after 2): the arch folds back here"},
      {"x,y\n0,0\n1,1\n1,2\n3,1\n4,0\n", 4, "x must increase from springing to springing (1 after 1)"},
      {"x,y\n0,0\n4,1\n3,2\n2,1\n0,0\n", 4, "x must increase from springing to springing (3 after 4)"},
      {"x,y\n0,0\n1,1\n1,1\n3,1\n4,0\n", 4, "repeated point (1, 1), the same as the previous one"},
      {"x,y\n0,0\n1,1\n1.0000000001,1\n3,1\n4,0\n", 4, "less than 1e-9 of the span"},
      {"x,y\n0,0\n0.5,200\n0.8,300\n1,150\n", 5, "the right springing must lie within 100 spans"},
      {"x,y\n0,-1e308\n1,1e308\n2,1\n3,0\n", 5, "the right springing must lie within 100 spans"},
      {"x,y\n0,0\n0.5,200\n0.8,10\n1,0\n", 3, "the rise (the highest point's height above the left springing) must be "
                                             "at most 100 spans, got 200 for a span of 1"},
      {"x,y\n0,0\n1,-0.5\n2,-0.6\n3,0\n", 3, "every point between the springings must lie above the chord joining them"},
      {"x,y\n0,0\n1,1\n2,1\n3,1.5\n4,1.5\n6,3\n", 4, "must lie above the chord joining them: y = 1 here, the chord's "
                                                    "height 1"},
      {"x,y\n10,5\n11,7\n12,7.5\n13,6.4\n14,7.1\n", 5, "above the chord"},  // 6.4 below the chord's 6.575
      // Points that only fall from the left springing (all above the chord), and their mirror image, have
      // no crown between the springings (inputs from the fuzzer).
      {"x,y\n100,52.594\n103.554,52.583\n103.868,52.546\n104.183,52.477\n104.482,52.382\n106.002,51.260\n", 2,
       "the highest point is the left springing: a whole arch rises from both springings to a crown between them"},
      {"x,y\n0,0\n1,0.9\n2,1.6\n3,2\n", 5, "the highest point is the right springing"},
      // The fit.
      {"x,y\n0,0\n0.01,1\n0.02,2\n2,2.1\n4,0\n", 3, "the spline folds back between this point and the previous one"},
      {"x,y\n0,0\n1,1\n1.01,3\n3,3.1\n4,0\n", 4, "the spline folds back"},
      {semicircle, 3, "the spline folds back between this point and the previous one (dx/dtau = -0.00312"},
  };
  for (const Case& k : cases) {
    CAPTURE(k.text.substr(0, 60));
    try {
      parse_whole(k.text);
      FAIL("no error");
    } catch (const CurveFileError& e) {
      const std::string what = e.what();
      CAPTURE(what);
      CHECK(e.line() == k.line);
      CHECK(e.file() == "w.csv");
      CHECK(what.rfind("w.csv:" + std::to_string(k.line) + ": ", 0) == 0);
      CHECK(what.find(k.rule) != std::string::npos);
      CHECK(what.find('\n') == std::string::npos);
      CHECK(what.size() < 300);
    }
  }
  // Whole-file problems, as for the half.
  const std::string missing = "/nonexistent-ogive-dir/none.csv";
  CHECK_THROWS_WITH_AS(read_whole_points_curve(missing), doctest::Contains("none.csv: cannot be opened"),
                       CurveFileError);
  // Direct points: the same rules, "points: point K (of N): rule".
  CHECK_THROWS_WITH_AS(make_whole_points_curve({{0, 0}, {1, 1}, {2, 0}}),
                       "points: 3 points given, a whole-points curve needs 4 to 100000", std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_whole_points_curve({{0, 0}, {1, 1}, {2, INFINITY}, {3, 0}}),
                       doctest::Contains("points: point 3 (of 4): x and y must be finite"), std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_whole_points_curve({{0, 0}, {1, 1}, {2, 0.4}, {3, 1}}),
                       "points: point 3 (of 4): every point between the springings must lie above the chord joining "
                       "them: y = 0.4 here, the chord's height 0.6666666666666666 (heights above the left springing)",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_whole_points_curve({{0, 0}, {0.01, 1}, {0.02, 2}, {2, 2.1}, {4, 0}}),
                       doctest::Contains("points: point 2 (of 5): the spline folds back"), std::invalid_argument);
  // The half reader still refuses what only a whole file may be (its y falls after the crown).
  std::istringstream rampant_as_half("x,y\n0,0\n1,1\n2,1.5\n3,1\n");
  CHECK_THROWS_WITH_AS(parse_points_curve(rampant_as_half, "h.csv"), doctest::Contains("h.csv:5: y must not fall"),
                       CurveFileError);
}
