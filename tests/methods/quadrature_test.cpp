// The quadrature (force) method (src/methods/quadrature.hpp) and its own error estimate: against the
// closed form on every circular family, against verified CVODE multiple shooting on the smooth curves
// and the surveys, against the catenary's funicular limit, and where it does not apply.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "methods/quadrature.hpp"
#include "ogive/core/thrust_line.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

constexpr int kStations = 41;  // as ogive bench measures profiles

Scene scene_of(std::shared_ptr<const Curve> curve, double t_over_L = 0.08, double d_over_L = 0.0) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = t_over_L * s.curve->span();
  s.set_support_displacement(d_over_L * s.curve->span());
  return s;
}

Solution solve_with(const Scene& scene, Method m, double rtol, int stations = kStations) {
  Options o;
  o.method = m;
  o.rtol = rtol;
  o.stations = stations;
  return solve(scene, o);
}

// The error of everything a solution prints: H/V and the profile.
double true_error(const Solution& sol, const Solution& ref, const Scene& scene) {
  return std::max(relative_difference(sol.H_over_V, ref.H_over_V),
                  profile_difference(sol.profile, ref.profile, scene.thickness));
}

}  // namespace

TEST_CASE("quadrature: the closed form's H/V and profile on every circular family, rtol 1e-4 .. 1e-12") {
  std::vector<Scene> scenes;
  for (double eps : {0.0, 0.25, 0.5, 1.0, 2.0}) scenes.push_back(scene_of(make_pointed(10.0, eps)));
  scenes.push_back(scene_of(make_pointed(10.0, 0.5), 0.2, 3e-4));  // thick, supports spread
  scenes.push_back(scene_of(make_segmental(10.0, 0.1)));
  scenes.push_back(scene_of(make_segmental(10.0, 0.3)));
  scenes.push_back(scene_of(make_three_centred(10.0, 0.25, 50.0)));
  scenes.push_back(scene_of(make_four_centred(10.0, 0.42)));
  scenes.push_back(scene_of(make_four_centred(10.0, 0.5, 40.0, 10.0)));
  for (const Scene& scene : scenes) {
    const Solution ref = solve_with(scene, Method::closed_form, 1e-12);
    // The closed form's profile at rtol 1e-12 may lie below its round-off bound (ill_conditioned): solved.
    REQUIRE(ref.field);
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
      const Solution sol = solve_with(scene, Method::quadrature, rtol);
      CAPTURE(scene.curve->family());
      CAPTURE(rtol);
      if (sol.status == Status::ill_conditioned) {  // the round-off bound (kern-amplified) exceeds rtol
        CHECK(roundoff_bound(sol) > rtol);
        continue;
      }
      REQUIRE(sol.ok());
      CHECK(sol.method == Method::quadrature);
      const double error = true_error(sol, ref, scene);
      CHECK(error <= 10 * rtol);
      // Its own estimate bounds its true error, up to the closed form's own round-off.
      CHECK(error <= sol.diagnostics.error_estimate + roundoff_bound(ref));
      CHECK(sol.diagnostics.error_estimate <= 10 * rtol);
    }
  }
}

TEST_CASE("quadrature: verified CVODE multiple shooting's H/V and profile on smooth curves and surveys") {
  const std::vector<Scene> scenes = {
      scene_of(make_catenary(10.0, 0.5)),        scene_of(make_catenary(10.0, 0.2), 0.02),
      scene_of(make_parabolic(10.0, 0.5)),       scene_of(make_parabolic(10.0, 0.3)),
      scene_of(make_elliptical(10.0, 0.3)),      scene_of(make_elliptical(10.0, 0.7), 0.1, 2e-4),
      scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/catenary-survey.csv")),
      scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/parabola-40.csv")),
      scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/semicircle-24.csv")),
  };
  for (const Scene& scene : scenes) {
    Options o;
    o.method = Method::multiple_shooting;
    o.rtol = 1e-12;
    o.segments = 32;
    o.stations = kStations;
    const Solution ref = solve(scene, o);
    REQUIRE(ref.field);  // success, or ill_conditioned on the survey (condition 1e4): solved
    // The reference's own error: its verification estimate, or its conditioning, whichever is larger.
    // (Its estimate is at least its round-off bound, condition x eps amplified by L / t for the couples.)
    const double ref_error = std::max(ref.diagnostics.error_estimate, roundoff_bound(ref));
    REQUIRE(ref_error <= 1e-10);
    for (double rtol : {1e-6, 1e-8, 1e-10}) {
      const Solution sol = solve_with(scene, Method::quadrature, rtol);
      CAPTURE(scene.curve->family());
      CAPTURE(rtol);
      REQUIRE(sol.ok());
      const double error = true_error(sol, ref, scene);
      CHECK(error <= 10 * rtol);
      CHECK(error <= sol.diagnostics.error_estimate + ref_error);
    }
  }
}

TEST_CASE("quadrature: a summary's estimate from the nodes bounds the field's, H/V's and the largest e's true errors") {
  // Asked for an unprinted profile (thrust's summary columns), the quadrature compares two degrees at the
  // finer one's nodes instead of at 129 stations. Its estimate must still bound what the summary reads:
  // the whole field (sampled afterwards at 41 stations), H/V and the largest eccentricity, here against
  // the closed form (circular curves) and verified multiple shooting (the others), from rtol 1e-4 on.
  struct Case {
    Scene scene;
    bool circular;
  };
  const std::vector<Case> cases = {
      {scene_of(make_pointed(10.0, 0.0)), true},           {scene_of(make_pointed(10.0, 1.0), 0.03), true},
      {scene_of(make_segmental(10.0, 0.3)), true},         {scene_of(make_four_centred(10.0, 0.42)), true},
      {scene_of(make_catenary(10.0, 0.5)), false},         {scene_of(make_catenary(10.0, 0.2), 0.02), false},
      {scene_of(make_parabolic(10.0, 0.3)), false},        {scene_of(make_elliptical(10.0, 0.7), 0.1, 2e-4), false},
      {scene_of(read_points_curve(OGIVE_DATA_DIR "/curves/parabola-40.csv")), false},
  };
  int compared = 0;
  for (const Case& c : cases) {
    Options r;
    r.method = c.circular ? Method::closed_form : Method::multiple_shooting;
    r.rtol = 1e-12;
    r.segments = 32;
    r.stations = kStations;
    const Solution ref = solve(c.scene, r);
    REQUIRE(ref.field);
    const double ref_error = std::max(c.circular ? 0.0 : ref.diagnostics.error_estimate, roundoff_bound(ref));
    REQUIRE(ref_error <= 1e-10);
    const ThrustLineSummary ref_line = summarize_thrust_line(ref);
    REQUIRE(ref_line.ok);
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
      Options o;
      o.method = Method::quadrature;
      o.rtol = rtol;
      o.stations = 65;  // any count: the estimate is at the nodes
      o.unprinted_profile = true;
      Solution sol = solve(c.scene, o);
      CAPTURE(c.scene.curve->family());
      CAPTURE(rtol);
      REQUIRE(sol.ok());
      CHECK(sol.profile.empty());
      const double estimate = sol.diagnostics.error_estimate;
      CHECK(estimate <= rtol);
      // The same degree's sampled estimate: the same status.
      o.unprinted_profile = false;
      CHECK(solve(c.scene, o).status == sol.status);
      const ThrustLineSummary line = summarize_thrust_line(sol);
      REQUIRE(line.ok);
      sample_profile(sol, kStations);
      CHECK(true_error(sol, ref, c.scene) <= estimate + ref_error);
      // e = 600 M / (N t): its error in units of max(|e|, 100 %) combines M's (in kern units) and N's.
      CHECK(std::abs(line.max_abs_e - ref_line.max_abs_e) / std::max(ref_line.max_abs_e, 100.0) <=
            2 * (estimate + ref_error));
      ++compared;
    }
  }
  CHECK(compared == 36);
}

TEST_CASE("quadrature: a scene's numbers do not depend on what its thread solved before") {
  // A thread keeps the panels' node geometry of the last curve it solved on (a sweep over one survey
  // evaluates the curve once). The same scene solved on a fresh thread, after another thickness of the
  // same survey, after other curves, over the whole arch and again: the same bits.
  const auto survey = read_points_curve(OGIVE_DATA_DIR "/curves/parabola-40.csv");
  const Scene scene = scene_of(survey, 0.08);
  auto run = [&](const Scene& s) {
    Options o;
    o.method = Method::quadrature;
    o.stations = kStations;
    return solve(s, o);
  };
  Scene shaken = scene;  // solved over the whole arch
  shaken.horizontal_acceleration = 0.1;
  Solution fresh;
  std::thread([&] { fresh = run(scene); }).join();
  REQUIRE(fresh.ok());
  std::vector<Solution> again;
  again.push_back(run(scene_of(survey, 0.05)));  // the same curve: its geometry kept
  again.push_back(run(scene));
  again.push_back(run(scene_of(make_catenary(10.0, 0.5))));  // another curve: the geometry replaced
  again.push_back(run(scene));
  again.push_back(run(shaken));  // the same curve over the whole arch: other panels
  again.push_back(run(scene));
  CHECK(again[4].ok());
  CHECK_FALSE(again[4].model->half());
  for (std::size_t i : {1, 3, 5}) {
    CAPTURE(i);
    const Solution& sol = again[i];
    REQUIRE(sol.ok());
    CHECK(sol.H == fresh.H);
    CHECK(sol.V == fresh.V);
    CHECK(sol.diagnostics.error_estimate == fresh.diagnostics.error_estimate);
    CHECK(sol.diagnostics.rhs_evaluations == fresh.diagnostics.rhs_evaluations);
    REQUIRE(sol.profile.size() == fresh.profile.size());
    for (std::size_t k = 0; k < sol.profile.size(); ++k) {
      CHECK(sol.profile[k].M == fresh.profile[k].M);
      CHECK(sol.profile[k].Uy == fresh.profile[k].Uy);
    }
  }
}

TEST_CASE("quadrature: the catenary tends to its funicular H/V = 1/sinh(L/2a) as t/L falls") {
  const double L = 10.0, rise = 0.5;
  const double funicular = 1.0 / std::sinh(L / (2.0 * catenary_parameter(L, rise)));
  // (That the eccentricity falls with t/L is checked in acceptance/curve_solves_test.cpp, where auto runs
  // this method.)
  double previous_gap = 0, previous_t = 0;
  for (double t : {0.08, 0.02, 0.005, 0.001, 1e-4}) {
    const Solution sol = solve_with(scene_of(make_catenary(L, rise), t), Method::quadrature, 1e-12, 0);
    // Thin arches' couples amplify round-off by L / t: ill_conditioned at rtol 1e-12, H/V still exact.
    REQUIRE((sol.ok() || sol.status == Status::ill_conditioned));
    const double gap = relative_difference(sol.H_over_V, funicular);
    CAPTURE(t);
    if (previous_t > 0) {
      // The remainder comes from axial shortening and shear, both of order (t/L)^2.
      const double order = std::log(previous_gap / gap) / std::log(previous_t / t);
      CHECK(order > 1.9);
      CHECK(order < 2.1);
    }
    previous_gap = gap;
    previous_t = t;
  }
  CHECK(previous_gap < 1e-7);  // t/L = 1e-4: 3.5e-8
}

TEST_CASE("quadrature: misuse and what does not apply") {
  // Ignoring the breakpoints would put a jump of curvature inside a panel: refused as not applicable.
  Options o;
  o.method = Method::quadrature;
  o.restart_at_breakpoints = false;
  const Solution sol = solve(scene_of(make_four_centred(10.0, 0.42)), o);
  CHECK(sol.status == Status::not_applicable);
  CHECK(!sol.message.empty());
  CHECK(!sol.field);
  // A curve without breakpoints has none to ignore.
  CHECK(solve(scene_of(make_catenary(10.0, 0.5)), o).ok());
  CHECK(std::string(to_string(Method::quadrature)) == "quadrature");
}
