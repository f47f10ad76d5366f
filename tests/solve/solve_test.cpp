// The dispatcher (include/ogive/solve/solve.hpp): misuse throws naming the field, and Method::automatic
// chooses the closed form on circular arcs, the quadrature on smooth curves and CVODE where neither
// applies.
#include <doctest/doctest.h>

#include <cmath>
#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

Scene scene_of(std::shared_ptr<const Curve> curve, double t_over_L = 0.08) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = t_over_L * s.curve->span();
  return s;
}

}  // namespace

TEST_CASE("closed form: misuse throws naming the field") {
  Scene bad = paper_scene(0.0);
  bad.material.poisson_ratio = 0.7;
  CHECK_THROWS_WITH_AS(solve(bad), doctest::Contains("poisson_ratio"), std::invalid_argument);
  bad = paper_scene(0.0);
  bad.thickness = 0;
  CHECK_THROWS_WITH_AS(solve(bad), doctest::Contains("thickness"), std::invalid_argument);
  bad = paper_scene(0.0);
  bad.thickness = 10.0;  // deeper than twice the radius (5 m)
  CHECK_THROWS_WITH_AS(solve(bad), doctest::Contains("thickness"), std::invalid_argument);
  Options o;
  o.rtol = 0;
  CHECK_THROWS_WITH_AS(solve(paper_scene(0.0), o), doctest::Contains("rtol"), std::invalid_argument);
  o = {};
  o.stations = 1;
  CHECK_THROWS_WITH_AS(solve(paper_scene(0.0), o), doctest::Contains("stations"), std::invalid_argument);
}

TEST_CASE("auto: the closed form on circular arcs - the quadrature on smooth curves - CVODE where it does not apply") {
  Options o;  // Method::automatic by default
  CHECK(solve(paper_scene(0.5), o).method == Method::closed_form);
  CHECK(solve(scene_of(make_four_centred(10.0, 0.5)), o).method == Method::closed_form);
  const Scene catenary = scene_of(make_catenary(10.0, 0.5));
  const Solution thrust_only = solve(catenary, o);
  REQUIRE(thrust_only.ok());
  CHECK(thrust_only.method == Method::quadrature);
  CHECK(thrust_only.diagnostics.segments == 1);  // one panel: the catenary has no breakpoints
  CHECK(thrust_only.profile.empty());  // stations only when asked for
  CHECK(std::isfinite(thrust_only.diagnostics.error_estimate));
  // A parabola sampled at 40 points, without its breakpoints: the quadrature does not apply; shooting
  // steps across the jumps of curvature, where no estimate holds: its answer is unverified, never a
  // success.
  Options no_breakpoints = o;
  no_breakpoints.restart_at_breakpoints = false;
  const Scene survey = scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/parabola-40.csv"));
  Options quadrature = no_breakpoints;
  quadrature.method = Method::quadrature;
  CHECK(solve(survey, quadrature).status == Status::not_applicable);
  const Solution fallback = solve(survey, no_breakpoints);
  CHECK(fallback.status == Status::unverified);
  CHECK(fallback.message.find("--ignore-breakpoints") != std::string::npos);
  CHECK(fallback.method != Method::quadrature);
  REQUIRE(fallback.field);
  // The same survey with its breakpoints: verified shooting or the quadrature meets rtol.
  CHECK(solve(survey, o).ok());
}

TEST_CASE("auto with BDF where a ladder from rtol / 1000 would pass CVODE's floor: an estimate, never unverified") {
  // A semicircle under a partial live load: neither the closed form nor the quadrature applies, so auto
  // runs verified shooting. Below rtol 2.56e-10 its verifying solves start looser than rtol / 1000 (they
  // used to be squeezed against CVODE's floor, and every such row said unverified): each row has an
  // estimate, and says success only where the reference (multiple shooting with Adams, 64 segments,
  // rtol 1e-11: at 1e-12 its round-off bound, 1.6e-12, is above rtol) finds it within rtol.
  Scene scene = paper_scene(0.0);
  scene.loads.live.push_back(LiveLoad{5e3, 0.2, 0.7});
  Options exact;
  exact.method = Method::multiple_shooting;
  exact.segments = 64;
  exact.rtol = 1e-11;
  exact.stations = 41;
  const Solution reference = solve(scene, exact);
  REQUIRE(reference.ok());
  const double noise = reference.diagnostics.error_estimate;
  int successes = 0;
  for (double rtol : {1e-10, 1e-11, 1e-12}) {
    Options o;
    o.integrator = Integrator::bdf;
    o.rtol = rtol;
    o.stations = 41;
    const Solution sol = solve(scene, o);
    CAPTURE(rtol);
    CAPTURE(to_string(sol.status));
    REQUIRE(sol.field);
    CHECK((sol.method == Method::shooting || sol.method == Method::multiple_shooting));
    CHECK(sol.status != Status::unverified);
    CHECK(std::isfinite(sol.diagnostics.error_estimate));
    const double error = std::max(thrust_error(sol.H_over_V, reference.H_over_V),
                                  profile_difference(sol.profile, reference.profile, scene.thickness));
    CAPTURE(error);
    CHECK(error <= sol.diagnostics.error_estimate + noise);
    if (sol.ok()) {
      ++successes;
      CHECK(error <= rtol + noise);
    }
  }
  CHECK(successes >= 2);  // not vacuous: at 1e-10 and 1e-11 it verifies (at 1e-12 ill_conditioned)
}

TEST_CASE("solution_difference: a profile difference that is not a number is kept, not dropped") {
  // std::max(reactions, NaN) returns the reactions: a station without numbers would have vanished from
  // every CVODE estimate.
  Options o;
  o.method = Method::closed_form;
  o.stations = 5;
  const Solution exact = solve(paper_scene(0.5), o);
  REQUIRE(exact.ok());
  Solution holed = exact;
  holed.profile[3].psi = std::numeric_limits<double>::quiet_NaN();
  CHECK(solution_difference(exact, exact) == 0);
  CHECK(std::isnan(solution_difference(holed, exact)));
  CHECK(std::isnan(solution_difference(exact, holed)));
}

namespace ogive {

TEST_CASE("unverified rows say why in the user's words") {
  // A fill whose level lies below the extrados everywhere and no self-weight: nothing loads the ring,
  // every reaction is 0, and the relative difference of the verifying solves has no scale.
  Scene s = paper_scene(0.0);
  s.material.density = 0;
  s.loads.fills.push_back({1800, 0.01});
  const Solution unloaded = solve(s, Options{});
  CAPTURE(unloaded.message);
  CHECK(unloaded.status == Status::unverified);
  CHECK(unloaded.H == 0);
  CHECK(unloaded.message.find("no load reaches the ring") != std::string::npos);
  // A raw CVODE solve: verification was turned off, which the message names as the command line does.
  Options raw;
  raw.method = Method::shooting;
  raw.verify = false;
  const Solution sol = solve(paper_scene(0.0), raw);
  CHECK(sol.status == Status::unverified);
  CHECK(sol.message == "not verified (--no-verify): no error estimate");
}

}  // namespace ogive
