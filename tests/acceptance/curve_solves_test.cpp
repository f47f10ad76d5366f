// Every curve family solved, against physics (the semicircle, the catenary's funicular limit) and against
// the closed form and a finer survey.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>


#include "ogive/geometry/curve_families.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

Solution run(std::shared_ptr<const Curve> curve, double t_over_L, Method m, double rtol = 1e-10, int stations = 0,
             Integrator integ = Integrator::adams) {
  Scene scene;
  scene.curve = std::move(curve);
  scene.thickness = t_over_L * scene.curve->span();
  Options o;
  o.method = m;
  o.rtol = rtol;
  o.stations = stations;
  o.integrator = integ;
  return solve(scene, o);
}

}  // namespace

TEST_CASE("curve solves: the elliptical arch with rise L/2 gives the semicircle's H/V to 1e-9") {
  const double circle = run(make_pointed(10.0, 0.0), 0.08, Method::closed_form).H_over_V;
  for (Integrator integ : {Integrator::adams, Integrator::bdf}) {
    const Solution ellipse = run(make_elliptical(10.0, 0.5), 0.08, Method::multiple_shooting, 1e-10, 0, integ);
    REQUIRE(ellipse.ok());
    CHECK(relative_difference(ellipse.H_over_V, circle) <= 1e-9);
  }
}

TEST_CASE("curve solves: the catenary tends to its funicular H/V = 1/sinh(L/2a) and e falls with t/L") {
  const double L = 10.0, rise = 0.5;
  const double funicular = 1.0 / std::sinh(L / (2.0 * catenary_parameter(L, rise)));
  double previous_gap = 1.0, previous_e = 0.0, previous_t = 0.0;
  for (double t : {0.08, 0.02, 0.005, 0.001}) {
    // rtol 1e-8: the profile's error is measured in kern units (solve.hpp), and on a thin funicular arch
    // the eccentricity amplifies every error of the forces by about L / t, so that CVODE's accuracy
    // (its floor near 1e-13 relative) meets only about 1e-9 of the kern at t/L = 0.001.
    const Solution sol = run(make_catenary(L, rise), t, Method::automatic, 1e-8, 201);
    REQUIRE(sol.ok());
    const double gap = relative_difference(sol.H_over_V, funicular);
    const double e = max_abs_e(sol);
    CAPTURE(t);
    CHECK(gap < previous_gap);
    if (previous_t > 0) {
      // The remainder comes from axial shortening: the largest |e| falls in proportion to t/L.
      const double ratio = (previous_e / e) / (previous_t / t);
      CHECK(ratio > 0.8);
      CHECK(ratio < 1.25);
    }
    previous_gap = gap;
    previous_e = e;
    previous_t = t;
  }
  CHECK(previous_gap < 1e-4);  // at t/L = 0.001
  CHECK(previous_e < 1.0);     // the compression is all but centred: |e| < 1 % of the kern
}

TEST_CASE("curve solves: three- and four-centred arches give the same H/V in closed form and with CVODE") {
  for (auto curve : {make_three_centred(10.0, 1.0 / 3.0), make_three_centred(10.0, 0.25, 50.0),
                     make_four_centred(10.0, 0.42), make_four_centred(10.0, 0.5, 40.0, 10.0)}) {
    REQUIRE(!curve->arcs().empty());
    REQUIRE(!curve->breakpoints().empty());
    const Solution ref = run(curve, 0.08, Method::closed_form);
    REQUIRE(ref.ok());
    for (Integrator integ : {Integrator::adams, Integrator::bdf})
      for (Method m : {Method::shooting, Method::multiple_shooting})
        for (double rtol : {1e-6, 1e-9}) {
          const Solution sol = run(curve, 0.08, m, rtol, 0, integ);
          CAPTURE(curve->family());
          CAPTURE(to_string(m));
          CAPTURE(rtol);
          REQUIRE(sol.ok());
          CHECK(within_tolerance(thrust_error(sol.H_over_V, ref.H_over_V), rtol));
        }
  }
}

TEST_CASE("curve solves: points sampled from the parabola reproduce its H/V and converge as points are added") {
  const double L = 10.0, h = 5.0;
  const double parabola = run(make_parabolic(L, h / L), 0.08, Method::multiple_shooting, 1e-11).H_over_V;
  auto sampled = [&](int n) {
    std::vector<std::pair<double, double>> xy;
    for (int i = 0; i < n; ++i) {
      const double x = 0.5 * L * i / (n - 1);
      xy.emplace_back(x, 4.0 * h * x * (L - x) / (L * L));
    }
    return make_points_curve(xy);
  };
  const double e40 = relative_difference(run(sampled(40), 0.08, Method::multiple_shooting, 1e-11).H_over_V, parabola);
  const double e80 = relative_difference(run(sampled(80), 0.08, Method::multiple_shooting, 1e-11).H_over_V, parabola);
  const double e160 = relative_difference(run(sampled(160), 0.08, Method::multiple_shooting, 1e-11).H_over_V, parabola);
  CHECK(e40 <= 1e-4);
  CHECK(e80 < e40);
  CHECK(e160 < e80);
  // The shipped file holds the same 40 points.
  const double file = run(read_points_curve(OGIVE_DATA_DIR "/curves/parabola-40.csv"), 0.08,
                          Method::multiple_shooting, 1e-11).H_over_V;
  CHECK(relative_difference(file, parabola) <= 1e-4);
}

namespace {

// Under AddressSanitizer the resident memory holds its shadow and its quarantine of freed blocks: no
// measure of what a solve keeps. The memory bounds are asserted in the ordinary build only.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kMemoryMeasurable = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kMemoryMeasurable = false;
#else
constexpr bool kMemoryMeasurable = true;
#endif
#else
constexpr bool kMemoryMeasurable = true;
#endif

// The process's peak resident memory (VmHWM, MB) since reset_peak() (Linux: writing 5 to
// /proc/self/clear_refs resets it to the resident memory of the moment).
void reset_peak() { std::ofstream("/proc/self/clear_refs") << "5"; }
double peak_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1e3;  // kB
  return 0;
}
double resident_mb() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6)) / 1e3;  // kB
  return 0;
}

}  // namespace

// Half an elliptical arch sampled at n points (100 000 is the most a points file may hold).
Scene survey(int n) {
  std::vector<std::pair<double, double>> xy;
  for (int i = 0; i < n; ++i) {
    const double t = std::numbers::pi / 2 * i / (n - 1);
    xy.emplace_back(5 * (1 - std::cos(t)), 4 * std::sin(t));
  }
  Scene s;
  s.curve = make_points_curve(xy);
  s.thickness = 0.8;
  return s;
}

// The growth of the process's peak resident memory over one solve (MB), what the survey costs: the
// solve's numbers are kept, not its field (the command line writes a row and drops it).
double solve_growth(const Scene& s, const Options& o, Solution& kept) {
  reset_peak();
  const double before = resident_mb();
  {
    const Solution sol = solve(s, o);
    kept.status = sol.status;
    kept.H_over_V = sol.H_over_V;
    kept.diagnostics.error_estimate = sol.diagnostics.error_estimate;
  }
  return peak_mb() - before;
}

TEST_CASE("a survey of 100 000 points is solved with its profile within 200 MB (it took 0.9 GB)") {
  Options profile;
  profile.stations = 129;
  Solution sol;
  const double growth = solve_growth(survey(100000), profile, sol);
  if (kMemoryMeasurable) CHECK(growth <= 200);
  CHECK(sol.status == Status::success);
}

TEST_CASE("a survey of 20 000 points over the whole arch is solved within 100 MB (it took 275 MB, 1.3 GB at 100 000)") {
  // Multiple shooting over 40 000 segments, the whole arch cut at every point: in runs of 4096, whose
  // CVODE vectors are a fixed part of it (100 000 points: 183 MB).
  Options whole;
  whole.whole_arch = true;
  Solution over_whole, over_half;
  const Scene s = survey(20000);
  const double growth = solve_growth(s, whole, over_whole);
  if (kMemoryMeasurable) CHECK(growth <= 100);
  CHECK(over_whole.status == Status::success);
  solve_growth(s, Options{}, over_half);
  CHECK(thrust_error(over_whole.H_over_V, over_half.H_over_V) <=
        over_whole.diagnostics.error_estimate + over_half.diagnostics.error_estimate);
}
