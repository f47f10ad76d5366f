// Points curves (a half arch through surveyed points, include/ogive/geometry/curve_families.hpp): the
// spline fit against exact samples and its convergence, the shipped files, the file format's variants
// and every rule of the reader, located at its line.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ogive/geometry/curve_families.hpp"
#include "support/curves.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

constexpr double kPi = std::numbers::pi;
// Fourth-order central differences: truncation ~d^4 f^(5) / 30, round-off ~1e-16 L / d.
constexpr double kFiniteDifference = 1e-9;

std::string data_file(const char* name) { return std::string(OGIVE_DATA_DIR) + "/curves/" + name; }

std::shared_ptr<const Curve> parse_text(const std::string& text) {
  std::istringstream in(text);
  return parse_points_curve(in, "t.csv");
}

}  // namespace

TEST_CASE("points fitted to exact parabola samples reproduce it and converge as points are added") {
  const double L = 10.0, h = 5.0;
  const auto exact = make_parabolic(L, 0.5);
  double previous_y = 0, previous_theta = 0, previous_length = 0;
  for (int n : {40, 80, 160}) {
    CAPTURE(n);
    const auto c = make_points_curve(parabola_points(L, h, n));
    CHECK(c->family() == "points");
    CHECK(c->span() == L);
    // One restart per interior point, strictly increasing inside (0, S).
    const std::vector<double> bp = c->breakpoints();
    CHECK(bp.size() == static_cast<std::size_t>(n) - 2);
    CHECK(std::is_sorted(bp.begin(), bp.end()));
    CHECK(bp.front() > 0);
    CHECK(bp.back() < c->length());
    CHECK(c->arcs().empty());
    CHECK(c->at(0).x == 0);
    CHECK(c->at(0).y == 0);
    CHECK(c->at(c->length()).x == L / 2);
    CHECK(c->at(c->length()).y == h);
    CHECK(std::abs(c->at(c->length()).theta) <= kExact);
    double err_y = 0, err_theta = 0;
    for (int i = 0; i <= 2000; ++i) {
      const CurvePoint p = c->at(c->length() * i / 2000);
      err_y = std::max(err_y, std::abs(p.y - parabola_y(L, h, p.x)));
      err_theta = std::max(err_theta, std::abs(p.theta - parabola_theta(L, h, p.x)));
    }
    const double err_length = std::abs(c->length() - exact->length());
    MESSAGE("n ", n, ": max |dy| ", err_y, " m, max |dtheta| ", err_theta, " rad, |dS| ", err_length, " m");
    CHECK(err_y <= 1e-5 * L);
    CHECK(err_theta <= 1e-3);
    CHECK(err_length <= 1e-5 * L);
    if (n > 40) {
      CHECK(err_y < previous_y / 8);  // fourth order: 16 per halving
      CHECK(err_theta < previous_theta / 4);
      CHECK(err_length < previous_length / 8);
    }
    previous_y = err_y;
    previous_theta = err_theta;
    previous_length = err_length;
  }
}

TEST_CASE("points curve is ds-consistent and its first moment matches quadrature") {
  const auto c = make_points_curve(parabola_points(10, 5, 40));
  // The spline's third derivative jumps at the points: a small step keeps the truncation error small.
  const double S = c->length(), d = 1e-4 * S;
  for (int i = 1; i < 60; ++i) {
    const double s = S * i / 60.0;
    const CurvePoint p = c->at(s);
    CHECK(std::abs(derivative([&](double t) { return c->at(t).x; }, s, d) - std::cos(p.theta)) <= kFiniteDifference);
    CHECK(std::abs(derivative([&](double t) { return c->at(t).y; }, s, d) - std::sin(p.theta)) <= kFiniteDifference);
    // The spline's curvature is continuous but its derivative jumps at the points: second-order only.
    CHECK(std::abs(derivative([&](double t) { return c->at(t).theta; }, s, d) - p.kappa) <= 1e-5);
  }
  // The override integrates knot by knot; the default composite rule does not see the knots: 1e-9 only.
  DefaultMoment q;
  q.inner = c;
  CHECK(close(q.first_moment_x(), c->first_moment_x(), 1e-9));
  CHECK(close(c->first_moment_x(), make_parabolic(10, 0.5)->first_moment_x(), 1e-5));
}

TEST_CASE("points files shipped in data/curves fit their curves") {
  {
    const auto file = read_points_curve(data_file("parabola-40.csv"));
    const auto direct = make_points_curve(parabola_points(10, 5, 40));
    CHECK(file->span() == 10);
    CHECK(close(file->length(), direct->length(), 1e-14));
    for (int i = 0; i <= 50; ++i) {
      const double s = file->length() * i / 50;
      CHECK(std::abs(file->at(s).y - direct->at(s).y) <= 1e-14 * 10);
    }
  }
  {
    const auto c = read_points_curve(data_file("semicircle-24.csv"));
    const auto exact = make_pointed(10, 0);
    CHECK(c->span() == 10);
    CHECK(close(c->length(), exact->length(), 1e-5));
    for (int i = 0; i <= 200; ++i) {
      const CurvePoint p = c->at(c->length() * i / 200);
      CHECK(std::abs(std::hypot(p.x - 5, p.y) - 5) <= 1e-5);
      CHECK(std::abs(p.kappa + 0.2) <= 2e-3);
    }
    CHECK(std::abs(c->at(0).theta - kPi / 2) <= 1e-3);
  }
  {
    const auto c = read_points_curve(data_file("catenary-survey.csv"));
    CHECK(c->span() == 12);
    CHECK(c->rise() == 4);
    const auto model = make_catenary(12, 4.0 / 12);
    CHECK(close(c->length(), model->length(), 1e-3));
    for (int i = 0; i <= 100; ++i) {
      const CurvePoint p = c->at(c->length() * i / 100);
      const double a = catenary_parameter(12, 4.0 / 12);
      CHECK(std::abs(p.y - (4 - a * (std::cosh((p.x - 6) / a) - 1))) <= 5e-3);  // survey noise: +-2 mm
      CHECK(p.kappa < 0);
    }
  }
}

TEST_CASE("points file variants (CRLF - BOM - spaces - trailing blank lines) give identical curves") {
  std::string plain = "x,y\n";
  for (const auto& [x, y] : parabola_points(10, 5, 12)) plain += fmt::format("{},{}", x, y) + "\n";
  const auto reference = parse_text(plain);
  auto replace_all = [](std::string s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
      s.replace(at, from.size(), to);
    return s;
  };
  const std::vector<std::string> variants = {
      replace_all(plain, "\n", "\r\n"),
      "\xEF\xBB\xBF" + plain,
      plain + "\n\n  \n\t\n",
      replace_all(replace_all(plain, ",", " ,\t "), "x ,\t y", " X , Y "),
      plain.substr(0, plain.size() - 1),  // no final line end
      "\xEF\xBB\xBF" + replace_all(plain, "\n", "\r\n") + "\r\n\r\n",
  };
  for (std::size_t v = 0; v < variants.size(); ++v) {
    CAPTURE(v);
    const auto c = parse_text(variants[v]);
    CHECK(c->length() == reference->length());
    CHECK(c->first_moment_x() == reference->first_moment_x());
    for (int i = 0; i <= 40; ++i) {
      const double s = reference->length() * i / 40;
      const CurvePoint p = c->at(s), q = reference->at(s);
      CHECK(p.x == q.x);
      CHECK(p.y == q.y);
      CHECK(p.theta == q.theta);
      CHECK(p.kappa == q.kappa);
    }
  }
}

TEST_CASE("points file errors are CurveFileErrors located at the right line") {
  const std::string good = "0,0\n1,1.5\n2,2.5\n3,3\n";
  struct Case {
    std::string text;
    std::size_t line;
    std::string rule;
  };
  const std::string long_line = "1," + std::string(4095, '1');  // 4097 characters
  std::string too_many = "x,y\n";
  for (int i = 0; i <= 100000; ++i) too_many += std::to_string(i) + "," + std::to_string(i == 0 ? 0 : 1) + "\n";
  const std::vector<Case> cases = {
      {"", 1, "empty file"},
      {"\n\n", 1, "empty file"},
      {"\nx,y\n" + good, 1, "expected the header x,y, got a blank line"},
      {"a,b\n" + good, 1, "the header must be x,y, got \"a,b\""},
      {"x;y\n" + good, 1, "the header must be x,y"},
      {"x,y,z\n" + good, 1, "the header must be x,y"},
      {"x,y\n0,0\n1,2,3\n", 3, "expected 2 fields x,y, got 3"},
      {"x,y\n0,0\n1\n", 3, "expected 2 fields x,y, got 1"},
      {"x,y\n0,0\n1,2,\n", 3, "expected 2 fields x,y, got 3"},
      {"x,y\n0,0\nabc,1\n", 3, "x is not a number: \"abc\""},
      {"x,y\n0,0\n1,\n", 3, "y is not a number: \"\""},
      {"x,y\n0,0\n1,2m\n", 3, "y is not a number: \"2m\""},
      {"x,y\n0,0\n1,+-2\n", 3, "y is not a number"},
      {"x,y\n0,0\n1\r2,3\n", 3, "x is not a number: \"1\\x0d2\""},
      {"x,y\n0,0\n1,nan\n", 3, "y must be a finite number, got \"nan\""},
      {"x,y\n0,0\n1,-inf\n", 3, "y must be a finite number"},
      {"x,y\n0,0\n1,1e999\n", 3, "y is out of the range of a double"},
      {"x,y\n", 1, "0 points, a points curve needs at least 4"},
      {"x,y\n0,0\n1,1\n2,2\n", 4, "3 points, a points curve needs at least 4"},
      {"x,y\n0,0\n1,1\n\n2,2\n3,3\n", 4, "blank line inside the data"},
      {"x,y\n0,0\n" + long_line + "\n2,2\n", 3, "line longer than 4096 characters"},
      {too_many, 100002, "more than 100000 points"},
      {"x,y\n0,0.5\n1,1\n2,2\n3,3\n", 2, "the first point is the springing and must lie on the springing line"},
      {"x,y\n0,0\n1,1\n1,1\n2,2\n3,3\n", 4, "repeated point (1, 1)"},
      {"x,y\n0,0\n1,1\n2,2\n1.5,2.5\n3,3\n", 5, "x must increase from springing to crown (1.5 after 2)"},
      {"x,y\n0,0\n1,1\n1,2\n3,3\n", 4, "x must increase from springing to crown (1 after 1)"},
      {"x,y\n0,0\n1,-0.1\n2,2\n3,3\n", 3, "must lie above the springing line y = 0, got y = -0.1"},
      {"x,y\n0,0\n1,0\n2,2\n3,3\n", 3, "must lie above the springing line"},
      {"x,y\n0,0\n1,1\n2,2\n3,1.5\n4,2.5\n", 5, "y must not fall from springing to crown (1.5 after 2)"},
      {"x,y\n0,0\n1,2\n2,3\n3,2.5\n", 5, "y must not fall"},
  };
  for (const Case& k : cases) {
    CAPTURE(k.text.substr(0, 60));
    try {
      parse_text(k.text);
      FAIL("no error");
    } catch (const CurveFileError& e) {
      const std::string what = e.what();
      CHECK(e.line() == k.line);
      CHECK(e.file() == "t.csv");
      CHECK(what.rfind("t.csv:" + std::to_string(k.line) + ": ", 0) == 0);
      CHECK(what.find(k.rule) != std::string::npos);
      CHECK(what.find('\n') == std::string::npos);
      CHECK(what.find('\r') == std::string::npos);
      CAPTURE(what);
      CHECK(what.size() < 300);
    }
  }
  // Number forms: an optional sign (also '+'), leading or trailing point, exponent in either case.
  const auto forms = parse_text("x,y\n+0,-0\n.5,1E-0\n1.,+1.5\n2e0,2.5e+00\n");
  CHECK(forms->span() == 4);
  CHECK(forms->rise() == 2.5);
  // A line of exactly 4096 characters is fine.
  const std::string longest = "0.5," + std::string(4096 - 5, ' ') + "1";
  CHECK(longest.size() == 4096);
  CHECK_NOTHROW(parse_text("x,y\n0,0\n" + longest + "\n2,2\n3,3\n"));
  CHECK_NOTHROW(parse_text("x,y\r\n0,0\r\n" + longest + "\r\n2,2\r\n3,3\r\n"));
  // Whole-file problems carry line 0 and no line in the message.
  const std::string missing = "/nonexistent-ogive-dir/none.csv";
  try {
    read_points_curve(missing);
    FAIL("no error");
  } catch (const CurveFileError& e) {
    CHECK(e.line() == 0);
    CHECK(std::string(e.what()).rfind(missing + ": cannot be opened (No such file or directory)", 0) == 0);
  }
  const std::string dir = std::filesystem::temp_directory_path().string();
  const std::string dir_rule = dir + ": cannot be read";
  CHECK_THROWS_WITH_AS(read_points_curve(dir), doctest::Contains(dir_rule.c_str()), CurveFileError);
  // CurveFileError is an invalid_argument.
  CHECK_THROWS_AS(parse_text("x,y\n"), std::invalid_argument);
}

TEST_CASE("make_points_curve applies the same rules to points given directly") {
  CHECK_THROWS_WITH_AS(make_points_curve({{0, 0}, {1, 1}, {2, 2}}),
                       "points: 3 points given, a points curve needs 4 to 100000", std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_points_curve({{0, 0}, {1, 1}, {0.5, 2}, {3, 3}, {4, 4}}),
                       "points: point 3 (of 5): x must increase from springing to crown (0.5 after 1)",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(make_points_curve({{0, 0}, {1, NAN}, {2, 2}, {3, 3}}),
                       doctest::Contains("points: point 2 (of 4): x and y must be finite"), std::invalid_argument);
  // Springing translated to x = 0; a springing within 1e-9 span of the line is put on it.
  const auto c = make_points_curve({{100, 1e-10}, {101, 1.5}, {102, 2.5}, {103, 3}});
  CHECK(c->span() == 6);
  CHECK(c->at(0).x == 0);
  CHECK(c->at(0).y == 0);
  CHECK(c->at(c->length()).x == 3);
  CHECK(c->rise() == 3);
}
