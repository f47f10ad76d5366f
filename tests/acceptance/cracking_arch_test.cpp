// The cracking arch as a whole: where the no-tension arch cracks against where the linear model leaves
// the kern, its thrust against the linear one at fixed supports (the paper's agreement with its cracked
// DEM arches), and along a spreading support the limit analysis' minimum thrust as the floor it
// approaches, on a path without hysteresis; scenes whose hinges open to a tiny part of t answer at the
// defaults, against Newton shooting.
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

namespace ogive {
namespace {

constexpr double kRtol = 1e-8;  // asked of the no-tension solves below; success guarantees it

Scene no_tension(double eps, double t_over_L, double d_over_L = 0) {
  Scene s = paper_scene(eps, t_over_L, d_over_L);
  s.section = SectionKind::no_tension;
  return s;
}

Options shooting(Method m = Method::shooting, double rtol = kRtol) {
  Options o;
  o.method = m;
  o.rtol = rtol;
  return o;
}

// Two scenes whose hinges open until the compressed depth is a few millionths of t or less, so that
// round-off in the section law holds the quadrature's integrals near 1e-9 (above the rtol / 100 they
// are asked for at the defaults), each with its reference: Newton shooting over 8 segments (CVODE
// through the same hinges, an independent method) at rtol 1e-6, its H/V and its own error estimate.
// That solve takes 30 to 60 s, so it is run once (the commands in benchmarks/cracking/README.md).
struct OpenHinges {
  const char* name;
  Scene scene;
  double H_over_V, estimate;  // the reference's
};
std::vector<OpenHinges> open_hinges() {
  Scene loaded = no_tension(0.5, 0.1, 1e-2);  // ogive thrust --eccentricity 0.5 --span 8 --thickness-ratio 0.1 ...
  loaded.curve = make_pointed(8.0, 0.5);
  loaded.thickness = 0.8;
  loaded.material.density = 2000;
  loaded.loads.points.push_back({5e4, 0.25});
  loaded.set_support_displacement(1e-2 * 8.0);
  return {{"equilateral, a point load at L/4, spread 1e-2 L", loaded, 0.19823050327943686, 1.014047093728099e-09},
          {"eps 1.5, t/L 0.08, spread 1e-3 L", no_tension(1.5, 0.08, 1e-3), 0.12095719714885166, 6.465566710630795e-08}};
}

}  // namespace

TEST_CASE("no-tension: cracks where the linear model leaves the kern, and H/V stays close to it at fixed supports") {
  Options o = shooting(Method::automatic);
  o.stations = 129;
  for (double eps : {0.0, 0.5}) {
    const Solution nt = solve(no_tension(eps, 0.08), o);
    Options exact;
    exact.method = Method::closed_form;
    exact.stations = 129;
    const Solution linear = solve(paper_scene(eps, 0.08), exact);
    REQUIRE(nt.ok());
    REQUIRE(linear.ok());
    // Cracks start where the linear model leaves the kern: every cracked zone of the no-tension arch
    // holds stations where the linear |e| exceeds 100 %, and every such zone of the linear model is
    // cracked at its peak (the redistribution widens the zones; it makes no new one).
    const std::size_t n = nt.profile.size();
    for (std::size_t i = 0; i < n;) {
      if (nt.profile[i].cracked) {
        std::size_t j = i;
        bool overlaps = false;
        for (; j < n && nt.profile[j].cracked; ++j) overlaps = overlaps || std::abs(linear.profile[j].e) > 100;
        CAPTURE(eps);
        CAPTURE(nt.profile[i].s);
        CHECK(overlaps);
        i = j;
      } else {
        ++i;
      }
    }
    for (std::size_t i = 0; i < n;) {
      if (std::abs(linear.profile[i].e) > 100) {
        std::size_t peak = i, j = i;
        for (; j < n && std::abs(linear.profile[j].e) > 100; ++j)
          if (std::abs(linear.profile[j].e) > std::abs(linear.profile[peak].e)) peak = j;
        CAPTURE(eps);
        CAPTURE(linear.profile[peak].s);
        CHECK(nt.profile[peak].cracked);
        i = j;
      } else {
        ++i;
      }
    }
    // ... and H/V stays within 1.5 % of the linear value (the paper's agreement of its cracked DEM
    // arches with the continuous model at fixed supports).
    CAPTURE(eps);
    CHECK(relative_difference(nt.H_over_V, linear.H_over_V) <= 0.015);
  }
}

TEST_CASE("no-tension: along spreading H/V falls towards the minimum thrust, and the path has no hysteresis") {
  const double t = 0.08;
  Scene s = no_tension(0.0, t);
  LimitOptions lo;
  lo.weight = WeightModel::axis;  // this model's convention: the weight on the axis
  Scene rigid = paper_scene(0.0, t);
  const LimitResult limit = analyse_limit(rigid, lo);
  REQUIRE(limit.status == LimitStatus::success);
  const double floor = limit.H_min() / limit.V;
  std::vector<double> ds{0};
  for (int i = 0; i <= 16; ++i) ds.push_back(std::pow(10.0, -6 + 4.0 * i / 16));
  std::vector<Solution> path;
  const Options o = shooting(Method::automatic);
  for (double d : ds) {
    s.set_support_displacement(d * 10.0);
    path.push_back(solve(s, o, path.empty() ? nullptr : &path.back()));
    REQUIRE(path.back().ok());
  }
  for (std::size_t k = 1; k < path.size(); ++k) {
    CAPTURE(ds[k]);
    CHECK(path[k].H_over_V <= path[k - 1].H_over_V * (1 + kRtol));  // never rises
    CHECK(path[k].H_over_V >= floor);                               // never below the minimum thrust
  }
  CHECK(path.back().H_over_V <= floor * 1.02);  // within 2 % of it at d = 1 % of the span
  // Back down to d = 0 along the same values: the model is elastic, the states return.
  Solution back = path.back();
  for (std::size_t k = ds.size() - 1; k-- > 0;) {
    s.set_support_displacement(ds[k] * 10.0);
    back = solve(s, o, &back);
    REQUIRE(back.ok());
    CAPTURE(ds[k]);
    CHECK(relative_difference(back.H_over_V, path[k].H_over_V) <= 4 * kRtol);
  }
}

}  // namespace ogive

namespace ogive {

TEST_CASE("no-tension: scenes with nearly open hinges answer at the defaults, quickly, within rtol of Newton shooting") {
  for (const OpenHinges& c : open_hinges()) {
    CAPTURE(c.name);
    const Solution sol = solve(c.scene, Options{});
    CAPTURE(sol.message);
    REQUIRE(sol.ok());
    // Fast: by the quadrature form alone, in a few tens of Newton iterations and at most a few hundred
    // thousand integrand evaluations (measured 14 and 19 iterations, 24 000 and 79 000 evaluations,
    // 0.1 and 0.2 s; they took 157 iterations through every method and minutes, and failed, before).
    CHECK(sol.method == Method::quadrature);
    CHECK(sol.diagnostics.newton_iterations <= 40);
    CHECK(sol.diagnostics.rhs_evaluations <= 400000);
    // Within the defaults' rtol of the reference, plus the reference's own estimate.
    CHECK(thrust_error(sol.H_over_V, c.H_over_V) <= Options{}.rtol + c.estimate);
  }
}

TEST_CASE("no-tension: a sweep of loads continues from the previous load's solution") {
  // Continuation in the loads as well as in the movements: each scene of a sweep over a point load's
  // size starts from the previous one's springing state (carried into the new scene's force scale); every
  // answer equals a fresh solve of the same scene.
  Scene s = no_tension(0.5, 0.1, 1e-3);
  s.loads.points.push_back({0.0, 0.25});
  const double w = s.reference_load_per_length() * 10.0;
  Solution previous;
  for (double P : {0.05, 0.1, 0.2, 0.3}) {
    s.loads.points[0].force = P * w;
    const Solution along = solve(s, Options{}, previous.field ? &previous : nullptr);
    const Solution fresh = solve(s, Options{});
    CAPTURE(P);
    REQUIRE(along.ok());
    REQUIRE(fresh.ok());
    CHECK(reaction_difference(along.reactions, fresh.reactions, s.thickness) <=
          along.diagnostics.error_estimate + fresh.diagnostics.error_estimate);
    previous = along;
  }
}

}  // namespace ogive

namespace ogive {

// Scenes that Newton cannot solve at the defaults, each of which took minutes or never ended: a row
// each, within the work budgets (solve.hpp), whose message names what ran out; no success that a second
// method does not confirm.
void check_budget_row(const Scene& s) {
  const Solution sol = solve(s, Options{});
  CAPTURE(sol.message);
  CHECK(sol.status == Status::not_converged);
  CHECK(sol.message.find("work budget") != std::string::npos);
}

TEST_CASE("no-tension: scenes Newton cannot solve end in a not_converged row that names the budget: a filled elliptical arch") {
  Scene fill = no_tension(0.0, 0.07448);  // ogive thrust --curve elliptical --rise-ratio 0.4865 ...
  fill.curve = make_elliptical(10.0, 0.4865);
  fill.loads.points.push_back({7820, 0.02659});
  fill.loads.fills.push_back({1423, 0.4091});
  fill.left.kind = fill.right.kind = SupportKind::pinned;
  check_budget_row(fill);
}

TEST_CASE("no-tension: scenes Newton cannot solve end in a not_converged row that names the budget: thick semicircles spread") {
  check_budget_row(no_tension(0.0, 0.6, 1e-4));
  check_budget_row(no_tension(0.0, 0.999, 1e-4));
}

TEST_CASE("no-tension: Newton shooting at rtol 1.04e-11 with four support movements answers, and never says success unconfirmed") {
  Scene s = no_tension(0.0, 0.08);
  s.left.spread = 3e-3 * 10.0;
  s.right.spread = 1e-3 * 10.0;
  s.left.settlement = 2e-3 * 10.0;
  s.right.rotation = 2e-3;
  const Solution sol = solve(s, shooting(Method::shooting, 1.04e-11));
  CAPTURE(sol.message);
  CHECK(sol.status != Status::not_applicable);
  if (sol.ok()) {
    // Confirmed by the quadrature form, an independent method, within both estimates.
    const Solution other = solve(s, shooting(Method::quadrature, 1e-9));
    REQUIRE(other.ok());
    CHECK(reaction_difference(sol.reactions, other.reactions, s.thickness) <=
          sol.diagnostics.error_estimate + other.diagnostics.error_estimate);
  }
}

TEST_CASE("no-tension: auto verifies with verification off, as it does on, and stops at the first method that succeeds") {
  Options raw;
  raw.verify = false;
  const Scene s = no_tension(0.0, 0.08, 1e-4);
  const Solution off = solve(s, raw), on = solve(s, Options{});
  CAPTURE(off.message);
  REQUIRE(off.ok());
  CHECK(off.method == Method::quadrature);
  CHECK(off.H_over_V == on.H_over_V);
  CHECK(off.diagnostics.newton_iterations == on.diagnostics.newton_iterations);
}

}  // namespace ogive
