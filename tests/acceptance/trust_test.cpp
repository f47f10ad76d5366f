// Every `success` is a guarantee: no option makes a row say success unless its numbers are within rtol of
// the truth (within_tolerance, solve.hpp); below CVODE's floor a row is unverified, never success;
// conditioning is judged on the problem, not on its discretisation.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "methods/bvp.hpp"
#include "cli.hpp"
#include "support/cli_run.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "methods/shooting.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

constexpr int kStations = 41;

Scene scene_of(std::shared_ptr<const Curve> curve, double t_over_L = 0.08) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = t_over_L * s.curve->span();
  return s;
}

// The truth: the closed form (exact to round-off) on circular arcs.
Solution exact(const Scene& scene) {
  Options o;
  o.method = Method::closed_form;
  o.stations = kStations;
  return solve(scene, o);
}

double true_error(const Solution& sol, const Solution& truth, const Scene& scene) {
  return std::max(thrust_error(sol.H_over_V, truth.H_over_V),
                  profile_difference(sol.profile, truth.profile, scene.thickness));
}

}  // namespace

TEST_CASE("trust: no atol - rtol - method or integrator makes a wrong row say success") {
  // atol from far below CVODE's default to absurd (1e300 switches CVODE's error control off), rtol over
  // the whole accepted range, verified and raw. The truth is the closed form.
  const std::vector<Scene> scenes = {paper_scene(0.5), paper_scene(0.0, 0.06, 2e-4)};
  int successes = 0, refused = 0;
  for (const Scene& scene : scenes) {
    const Solution truth = exact(scene);
    REQUIRE(truth.ok());
    for (double atol : {0.0, 1e-14, 1e-8, 1e-2, 1.0, 1e300})
      for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-13, 1e-14})
        for (Method m : {Method::shooting, Method::multiple_shooting, Method::quadrature, Method::automatic})
          for (Integrator integ : {Integrator::adams, Integrator::bdf})
            for (bool verify : {true, false}) {
              Options o;
              o.method = m;
              o.integrator = integ;
              o.rtol = rtol;
              o.atol = atol;
              o.verify = verify;
              o.stations = kStations;
              o.segments = 4;
              const Solution sol = solve(scene, o);
              CAPTURE(atol);
              CAPTURE(rtol);
              CAPTURE(to_string(m));
              CAPTURE(to_string(integ));
              CAPTURE(verify);
              if (sol.ok()) {
                ++successes;
                CHECK(within_tolerance(true_error(sol, truth, scene), rtol));
                CHECK(within_tolerance(sol.diagnostics.error_estimate, rtol));
              } else {
                ++refused;
                CHECK(!sol.message.empty());
              }
              // Raw CVODE is never success; the quadrature's estimate is its own, never switched off.
              if (!verify && (m == Method::shooting || m == Method::multiple_shooting))
                CHECK(sol.status != Status::success);
            }
  }
  CHECK(successes > 300);  // not vacuous: most verified rows succeed
  CHECK(refused > 300);    // raw rows, absurd atol, rtol below CVODE's floor
}

TEST_CASE("trust: a loose atol cannot fool verification - nor change a verified row") {
  // A verified solve runs no looser than CVODE's default atol: a loose atol changes neither the numbers
  // nor the estimate nor the status (it used to turn identical rows into tolerance_not_met).
  for (Integrator integ : {Integrator::adams, Integrator::bdf}) {
    Options o;
    o.method = Method::shooting;
    o.integrator = integ;
    o.rtol = integ == Integrator::bdf ? 1e-10 : 1e-8;
    const Scene scene = paper_scene(0.5);
    const Solution plain = solve(scene, o);
    const Solution truth = exact(scene);
    for (double atol : {1e-8, 1.0, 1e300}) {
      o.atol = atol;
      const Solution sol = solve(scene, o);
      CAPTURE(atol);
      CHECK(sol.status == plain.status);
      CHECK(sol.H_over_V == plain.H_over_V);
      CHECK(sol.diagnostics.error_estimate == plain.diagnostics.error_estimate);
      if (sol.ok()) CHECK(within_tolerance(thrust_error(sol.H_over_V, truth.H_over_V), o.rtol));
    }
  }
  // Raw (--no-verify), the atol is CVODE's as given: with atol 1e300 CVODE's error control is off and
  // the raw row is far off, and says unverified.
  Options raw;
  raw.method = Method::shooting;
  raw.verify = false;
  raw.atol = 1e300;
  const Solution loose = solve(paper_scene(0.5), raw);
  CHECK(loose.status == Status::unverified);
  CHECK(thrust_error(loose.H_over_V, exact(paper_scene(0.5)).H_over_V) > raw.rtol);
}

TEST_CASE("trust: near CVODE's floor the verifying solves start looser - an estimate, never a false success") {
  // The ladder's tightest solve stays 16 times above CVODE's floor (1e-15), so at rtol 1e-13 and 1e-14
  // it starts at CVODE rtol 4.1e-12, far looser than rtol / 10: the row has an estimate, and it says
  // tolerance_not_met (or ill_conditioned, below the round-off bound) with that estimate above rtol.
  const Scene scene = paper_scene(5.0);
  for (Integrator integ : {Integrator::adams, Integrator::bdf})
    for (double rtol : {1e-14, 1e-13}) {
      Options o;
      o.method = Method::shooting;
      o.integrator = integ;
      o.rtol = rtol;
      const Solution sol = solve(scene, o);
      CAPTURE(to_string(integ));
      CAPTURE(rtol);
      CHECK((sol.status == Status::tolerance_not_met || sol.status == Status::ill_conditioned));
      CHECK(std::isfinite(sol.diagnostics.error_estimate));
      CHECK(!within_tolerance(sol.diagnostics.error_estimate, rtol));
      if (sol.status == Status::tolerance_not_met) CHECK(sol.message.find("floor") != std::string::npos);
      CHECK(sol.field);  // the numbers are there, without a promise
    }
  // Where the ladder below f x rtol fits (Adams at rtol 4.1e-11 and above), it starts there, and the
  // row says success; with BDF the same rtol starts looser and says success where its estimate meets it.
  Options o;
  o.method = Method::shooting;
  o.rtol = 1e-10;
  const Solution truth = exact(scene);
  REQUIRE(truth.ok());
  for (Integrator integ : {Integrator::adams, Integrator::bdf}) {
    o.integrator = integ;
    o.stations = kStations;
    const Solution sol = solve(scene, o);
    CAPTURE(to_string(integ));
    CHECK(sol.status == Status::success);
    CHECK(within_tolerance(true_error(sol, truth, scene), o.rtol));
  }
}

TEST_CASE("trust: --no-verify rows say unverified - auto always verifies") {
  const Run raw = run_command({"thrust", "--curve", "three-centred", "--method", "shooting", "--ignore-breakpoints", "--no-verify"});
  CHECK(raw.status == 3);
  CHECK(column(raw.out, "status") == "unverified");
  CHECK(column(raw.out, "error_estimate").empty());
  CHECK(column(raw.out, "message").find("not verified") != std::string::npos);
  const Run autop = run_command({"thrust", "--curve", "catenary", "--no-verify"});
  CHECK(autop.status == 0);
  CHECK(column(autop.out, "status") == "success");
  CHECK(!column(autop.out, "error_estimate").empty());
}

TEST_CASE("trust: the condition estimate is the problem's - multiple shooting with 1 .. 64 segments succeeds at rtol 1e-12") {
  const Scene scene = scene_of(make_segmental(10.0, 0.2));
  const Solution truth = exact(scene);
  REQUIRE(truth.ok());
  Options o;
  o.method = Method::shooting;
  o.rtol = 1e-12;
  const Solution single = solve(scene, o);
  REQUIRE(single.ok());
  for (int segments : {1, 2, 4, 8, 16, 32, 64}) {
    o.method = Method::multiple_shooting;
    o.segments = segments;
    const Solution sol = solve(scene, o);
    CAPTURE(segments);
    REQUIRE(sol.ok());
    CHECK(within_tolerance(thrust_error(sol.H_over_V, truth.H_over_V), o.rtol));
    // The same boundary-value problem has the same condition, whatever its discretisation (the
    // transfers differ by CVODE's error only).
    CHECK(close(sol.diagnostics.condition_estimate, single.diagnostics.condition_estimate, 1e-6));
    CHECK(close(sol.diagnostics.condition_estimate, truth.diagnostics.condition_estimate, 1e-6));
  }
  // --segments 1 under multiple shooting is single shooting (and says so): the same numbers.
  o.segments = 1;
  const Solution one = solve(scene, o);
  CHECK(one.method == Method::shooting);
  CHECK(one.diagnostics.segments == 1);
  CHECK(within_tolerance(thrust_error(one.H_over_V, single.H_over_V), o.rtol));
}

TEST_CASE("trust: BDF with its analytic Jacobian meets rtol - and uses the Jacobian") {
  const Scene scene = paper_scene(1.0);
  const Solution truth = exact(scene);
  for (double rtol : {1e-6, 1e-9}) {
    Options o;
    o.method = Method::shooting;
    o.integrator = Integrator::bdf;
    o.rtol = rtol;
    o.stations = kStations;
    const Solution sol = solve(scene, o);
    CAPTURE(rtol);
    REQUIRE(sol.ok());
    CHECK(sol.diagnostics.jacobian_evaluations > 0);
    CHECK(within_tolerance(true_error(sol, truth, scene), rtol));
  }
}

TEST_CASE("trust: the residuals take part in the status") {
  Options o;
  o.method = Method::shooting;
  const Solution sol = solve(scene_of(make_catenary(10.0, 0.5)), o);
  REQUIRE(sol.ok());
  CHECK(within_tolerance(sol.diagnostics.boundary_residual, o.rtol));
  CHECK(within_tolerance(sol.diagnostics.equilibrium_residual, o.rtol));
}

TEST_CASE("trust: check on a survey - the reference's status and error printed - exit 0") {
  const Run r = run_command({"check", "--curve", "points", "--curve-file", OGIVE_DATA_DIR "/curves/catenary-survey.csv"});
  CHECK(r.status == 0);
  REQUIRE(lines(r.out).size() == 4);  // quadrature, shooting, multiple shooting
  for (std::size_t row : {1, 2, 3}) {
    CHECK(column(r.out, "within_tolerance", row) == "true");
    CHECK(column(r.out, "reference_status", row) == "success");
    CHECK(std::stod(column(r.out, "reference_error", row)) <= 1e-12);
  }
  const Run c = run_command({"check", "--curve", "catenary", "--rise-ratio", "0.3,0.6", "--rtol", "1e-9"});
  CHECK(c.status == 0);
  CHECK(lines(c.out).size() == 1 + 2 * 3);
}

TEST_CASE("trust: an impossible combination inside a sweep is a row - exit 3 - none possible is exit 2") {
  const Run r = run_command({"thrust", "--curve", "catenary", "--rise-ratio", "1e-6,0.5,2", "--thickness-ratio", "0.5"});
  CHECK(r.status == 3);
  CHECK(r.err.empty());
  REQUIRE(lines(r.out).size() == 4);
  CHECK(column(r.out, "status", 2) == "success");
  CHECK(column(r.out, "status", 3) == "invalid_scene");
  CHECK(column(r.out, "message", 3).find("--thickness-ratio") != std::string::npos);
  CHECK(column(r.out, "H_over_V", 3).empty());
  for (const auto& line : lines(r.out)) CHECK(fields(line).size() == fields(lines(r.out)[0]).size());
  // Each command writes such a row.
  for (const char* command : {"profile", "check", "curve"}) {
    const Run p = run_command({command, "--curve", "catenary", "--rise-ratio", "0.5,2", "--thickness-ratio", "0.5"});
    CAPTURE(command);
    CHECK(p.status == 3);
    CHECK(p.out.find("invalid_scene") != std::string::npos);
  }
  check_refused({"thrust", "--curve", "catenary", "--rise-ratio", "2", "--thickness-ratio", "0.5"});
  check_refused({"thrust", "--curve", "catenary", "--rise-ratio", "1.5,2", "--thickness-ratio", "0.5"});
}
