// The fuzz targets' checks (tests/fuzz/fuzz_checks.hpp) in the ordinary suite: every seed of the corpora
// in tests/fuzz/corpus/ (the found-* files are inputs the fuzzers broke), and each bug the fuzzers found,
// with its input as a literal and the answer it must get.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/fuzz_checks.hpp"
#include "ogive/model/scene.hpp"
#include "support/tolerances.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus(const char* name) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(fs::path(OGIVE_FUZZ_CORPUS_DIR) / name))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Run {
  int status;
  std::string out, err;
};

Run cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int status = ogive::cli::run_cli(args, out, err);
  return {status, out.str(), err.str()};
}

// Exit 2 with one line on stderr that contains `what`, nothing on stdout.
void check_refused(const std::vector<std::string>& args, const std::string& what) {
  CAPTURE(args.back());
  const Run r = cli(args);
  CHECK(r.status == ogive::cli::kExitUsage);
  CHECK(r.out.empty());
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_MESSAGE(r.err.find(what) != std::string::npos, r.err);
}

// The CurveFileError that a points file gives.
ogive::CurveFileError file_error(const std::string& text) {
  std::istringstream in(text);
  try {
    ogive::parse_points_curve(in, "f.csv");
  } catch (const ogive::CurveFileError& e) {
    return e;
  }
  FAIL("the file was accepted");
  return {"", 0, ""};
}

}  // namespace

TEST_CASE("fuzz corpus: every parse_values seed passes the fuzz target's checks") {
  const auto files = corpus("parse_values");
  CHECK(files.size() >= 10);
  for (const fs::path& file : files) {
    INFO(file.filename().string());
    CHECK_NOTHROW(ogive::fuzz::check_values(slurp(file), true));  // the CLI part for every seed
  }
}

TEST_CASE("fuzz corpus: every points_file seed passes the fuzz target's checks") {
  const auto files = corpus("points_file");
  CHECK(files.size() >= 10);
  for (const fs::path& file : files) {
    INFO(file.filename().string());
    CHECK_NOTHROW(ogive::fuzz::check_points_file(slurp(file)));
  }
}

TEST_CASE("fuzz checks: a broken invariant is reported") {
  CHECK_NOTHROW(ogive::fuzz::check_points_file("x,y\n0,0\n1,1\n2,1.5\n3,1.7\n"));
  CHECK_NOTHROW(ogive::fuzz::check_values("0:1:11", true));
  CHECK_THROWS_AS(ogive::fuzz::require(false, "broken"), ogive::fuzz::InvariantBroken);
}

TEST_CASE("fuzz found: a range near the ends of the double range gave inf and nan") {
  using ogive::cli::parse_values;
  constexpr double kMax = std::numeric_limits<double>::max();
  // (stop - start) * i overflowed: inf; stop - start itself overflowed: nan.
  const auto up = parse_values("11:01.7976931348623157e308:5", "--x");
  REQUIRE(up.size() == 5);
  CHECK(up.front() == 11);
  CHECK(up.back() == kMax);
  for (std::size_t i = 1; i < up.size(); ++i) {
    CHECK(std::isfinite(up[i]));
    CHECK(up[i] > up[i - 1]);
  }
  CHECK(parse_values("-1e308:1e308:3", "--x") == std::vector<double>{-1e308, 0, 1e308});
  const auto down = parse_values(".51e308:.1:6", "--x");
  REQUIRE(down.size() == 6);
  for (std::size_t i = 1; i < down.size(); ++i) CHECK(down[i] < down[i - 1]);
  CHECK(down.back() == 0.1);
  // Ordinary ranges keep their values bit for bit.
  CHECK(parse_values("0:1:11", "--x")[3] == 0.3);
  CHECK_NOTHROW(ogive::fuzz::check_values("-1e308:1e308:3", true));
}

TEST_CASE("fuzz found: density 1e308 gave H = V = inf and H/V = nan with status success") {
  ogive::Scene scene;
  scene.curve = ogive::make_pointed(10, 0);
  scene.material.density = 1e308;  // w = rho g t overflows
  CHECK_THROWS_WITH_AS(scene.validate(), doctest::Contains("beyond the range of a double"), std::invalid_argument);
  scene.material.density = 1e-300;
  scene.material.gravity = 1e-300;  // w underflows to 0
  CHECK_THROWS_AS(scene.validate(), std::invalid_argument);
  check_refused({"thrust", "--method", "closed-form", "--density", "\t1e308\t\t"}, "beyond the range of a double");
  // The defaults and the paper's extremes still pass.
  scene.material = {};
  CHECK_NOTHROW(scene.validate());
  scene.material.youngs_modulus = 1e12;
  scene.thickness = 0.2 * 10;
  CHECK_NOTHROW(scene.validate());
}

TEST_CASE("fuzz found: a catenary of rise ratio 1e-320 had nan geometry") {
  // sinh^2 underflowed in the parameter's equation and a ~ L / (4 rise_ratio) overflows.
  CHECK_THROWS_WITH_AS(ogive::make_catenary(10, 31.90041e-320),
                       doctest::Contains("rise_ratio: must lie in [1e-06, 2] for a catenary arch, got 3.19"),
                       std::invalid_argument);
  CHECK_THROWS_AS(ogive::make_parabolic(10, 1e-300), std::invalid_argument);  // its first moment would be 0/0
  check_refused({"curve", "--curve", "catenary", "--rise-ratio", "31.90041e-320"}, "--rise-ratio: must lie in [1e-06, 2]");
  // The smallest allowed rise gives finite geometry.
  for (auto make : {ogive::make_catenary, ogive::make_parabolic, ogive::make_elliptical})
    CHECK_NOTHROW(ogive::fuzz::check_curve(*make(10, 1e-6)));
}

TEST_CASE("fuzz found: spans near the ends of the double range gave inf and nan geometry") {
  CHECK_THROWS_WITH_AS(ogive::make_pointed(1.7e308, 0), "span: must lie in [0.001, 1000000] m, got 1.7e+308",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(ogive::make_catenary(5e-324, 0.5), doctest::Contains("span: must lie in"), std::invalid_argument);
  check_refused({"curve", "--curve", "catenary", "--span", "1.7e308"}, "--span: must lie in [0.001, 1000000] m");
  for (double span : {ogive::kMinSpan, ogive::kMaxSpan}) {
    CHECK_NOTHROW(ogive::fuzz::check_curve(*ogive::make_pointed(span, 100)));
    CHECK_NOTHROW(ogive::fuzz::check_curve(*ogive::make_catenary(span, 2)));
    CHECK_NOTHROW(ogive::fuzz::check_curve(*ogive::make_elliptical(span, 1e-6)));
  }
}

TEST_CASE("fuzz found: points files with coordinates near 1e300 gave a nan curve") {
  // The spline's h^2 overflowed.
  const auto rise = file_error("x,y\n0,0\n1,2\n2,3\n4,3.5\n5,1e300 \n");
  CHECK(rise.line() == 6);
  CHECK(rise.rule() == "the rise (the crown's y) must be at most 100 spans, got 1e+300 for a span of 10");
  const auto span = file_error("X,y\n-1e308,0\n0.1282018218,0.253102\n2.4,4.3122\n2.43575,5\n");
  CHECK(span.line() == 5);
  CHECK(span.rule() == "the span 2 (x_crown - x_springing) must lie in [0.001, 1000000] m, got inf");
  // Points 1e-300 apart made zero-length pieces.
  const auto close = file_error("x,y\n0,0\n1,1\n1.0000000000000002,1\n2,1.5\n3,1.7\n");
  CHECK(close.line() == 4);
  CHECK(close.rule().find("less than 1e-9 of the span") != std::string::npos);
}

TEST_CASE("fuzz found: a points fit that stops at its crown took minutes to tabulate") {
  // 4 points, a steep last step before the crown whose tangent the fit makes horizontal: the spline
  // turned back (dx/dtau < 0) or nearly stopped at the crown, and the adaptive arc-length table split
  // panels down to 1e-13 of the range. Each must be refused at once, naming the crown's line.
  const auto back = file_error("x, y\n0.05, 0.000\n0.200,1\n1.75, 1.105\n2.02, 2.309\n");
  CHECK(back.line() == 5);
  CHECK(back.rule().find("stops or turns back at the crown") != std::string::npos);
  const auto cusp = file_error("X,y\n0,0\n0.12820512820518219,0.532212\n2.4,4.3122\n2.43575,5\n");
  CHECK(cusp.line() == 5);
  CHECK(cusp.rule().find("nearly stops (a cusp)") != std::string::npos);
  // A sound sharp turn still fits: a pointed arch of eccentricity 10 (rise 3.2 L) sampled at 100 points,
  // whose kink at the crown the fit rounds off within the last piece (a few hundred panels).
  const auto pointed = ogive::make_pointed(10, 10);
  std::vector<std::pair<double, double>> xy;
  for (int i = 0; i < 100; ++i) {
    const ogive::CurvePoint p = pointed->at(pointed->length() * i / 99);
    xy.emplace_back(p.x, i == 0 ? 0.0 : p.y);
  }
  const auto fitted = ogive::make_points_curve(xy);
  CHECK_NOTHROW(ogive::fuzz::check_curve(*fitted));
  CHECK(ogive::close(fitted->rise(), pointed->rise(), 1e-12));
}
