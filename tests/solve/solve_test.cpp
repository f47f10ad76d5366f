// The dispatcher (include/ogive/solve/solve.hpp): misuse throws naming the field, and Method::automatic
// chooses the closed form on circular arcs, the quadrature on smooth curves and CVODE where neither
// applies.
#include <doctest/doctest.h>

#include <cmath>
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
