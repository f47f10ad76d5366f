// The no-tension section's solvers (src/methods/no_tension.hpp): Newton's Jacobians against finite
// differences, single against multiple shooting, the quadrature form against multiple shooting on
// cracked scenes of every kind it treats, the linear model where nothing cracks, and the statuses of an
// arch that cannot stand and of an rtol below what double precision supports.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "methods/damped_newton.hpp"
#include "methods/no_tension.hpp"
#include "ogive/model/section.hpp"
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

// Newton's Jacobian of a residual function against finite differences, at a point 2 % off the solution
// in H and M0 (where the residual is not small). The unknowns are the springing's free components in
// their order: Fx, Fy, M when clamped, psi, Fx, Fy when pinned.
template <class Residual>
void check_jacobian(const StateVector& solution, Residual&& residual, std::array<int, 3> unknowns = {kFx, kFy, kM}) {
  StateVector y0 = solution;
  y0[kFx] *= 1.02;
  y0[kM] *= 0.98;
  const ShootingResidual r = residual(y0);
  REQUIRE(r.ok);
  for (int j = 0; j < 3; ++j) {
    const int component = unknowns[static_cast<std::size_t>(j)];
    const double h = 1e-5 * std::max(1.0, std::abs(y0[component]));
    StateVector a = y0, b = y0;
    a[component] += h;
    b[component] -= h;
    const ShootingResidual ra = residual(a), rb = residual(b);
    StateVector a2 = y0, b2 = y0;
    a2[component] += h / 2;
    b2[component] -= h / 2;
    const ShootingResidual ra2 = residual(a2), rb2 = residual(b2);
    REQUIRE(ra.ok);
    REQUIRE(rb.ok);
    REQUIRE(ra2.ok);
    REQUIRE(rb2.ok);
    // Richardson's extrapolation of two central differences: error O(h^4), so that the curvature's
    // steep peaks near the hinges do not swamp the comparison.
    const Eigen::Vector3d fd1 = (ra.residual - rb.residual) / (2 * h), fd2 = (ra2.residual - rb2.residual) / h;
    const Eigen::Vector3d fd = (4 * fd2 - fd1) / 3;
    CAPTURE(j);
    CHECK((fd - r.jacobian.col(j)).lpNorm<Eigen::Infinity>() <= 1e-6 * r.jacobian.lpNorm<Eigen::Infinity>());
  }
}

// A scene by the quadrature form (verified at kRtol, with a profile) and its reference, multiple
// shooting at kRtol / 10, whose own estimate the comparisons add.
struct AgainstShooting {
  Solution quadrature, reference;
};
AgainstShooting quadrature_against_shooting(const Scene& s) {
  Options o = shooting(Method::quadrature);
  o.stations = 65;
  AgainstShooting r;
  r.quadrature = solve(s, o);
  o.method = Method::multiple_shooting;
  o.rtol = kRtol / 10;
  r.reference = solve(s, o);
  return r;
}

}  // namespace

TEST_CASE("no-tension: where no section leaves the kern it is the linear model") {
  // The equilateral arch at t/L = 0.2, fixed supports: the linear |e| stays below 99 % everywhere.
  Options o = shooting(Method::shooting, 1e-11);
  o.stations = 65;
  const Solution nt = solve(no_tension(0.5, 0.2), o);
  Options exact;
  exact.method = Method::closed_form;
  exact.stations = 65;
  const Solution linear = solve(paper_scene(0.5, 0.2), exact);
  REQUIRE(nt.ok());
  REQUIRE(linear.ok());
  CHECK(max_abs_e(linear) < 100);
  CHECK(relative_difference(nt.H_over_V, linear.H_over_V) <= 1e-10);
  for (const ArchState& st : nt.profile) CHECK_FALSE(st.cracked);
}

TEST_CASE("no-tension: the shooting Jacobian is the residual's derivative (finite differences)") {
  const auto model = std::make_shared<const ArchModel>(no_tension(0.0, 0.08, 1e-4));
  const Solution sol = solve(model->scene(), shooting());
  REQUIRE(sol.ok());
  const Options tight = shooting(Method::shooting, 1e-12);
  check_jacobian(sol.springing_state,
                 [&](const StateVector& y0) { return no_tension_residual(*model, tight, y0); });
}

TEST_CASE("no-tension quadrature: its Jacobian is its residual's derivative (finite differences)") {
  // The half arch and an asymmetric whole one with a pinned springing (unknowns Fx0, Fy0, psi0 there:
  // the derivative by M0 is then by a given component, which the residual ignores).
  for (bool whole : {false, true}) {
    Scene s = no_tension(0.25, 0.08, 1e-4);
    if (whole) {
      s.loads.points.push_back({0.05 * s.reference_load_per_length() * 10.0, 0.3});
      s.left.kind = SupportKind::pinned;
    }
    const auto model = std::make_shared<const ArchModel>(s);
    CAPTURE(whole);
    REQUIRE(model->half() == !whole);
    const Solution sol = solve(s, shooting(Method::quadrature));
    REQUIRE(sol.ok());
    const Options tight = shooting(Method::quadrature, 1e-12);
    check_jacobian(
        sol.springing_state, [&](const StateVector& y0) { return no_tension_quadrature_residual(*model, tight, y0); },
        whole ? std::array<int, 3>{kPsi, kFx, kFy} : std::array<int, 3>{kFx, kFy, kM});
  }
}

TEST_CASE("no-tension: single and multiple shooting agree on cracked scenes") {
  // The reactions of both, verified at rtol; the profiles (through the hinges' curvature peaks) of
  // multiple shooting and of auto, which tightens CVODE where the profile needs it.
  for (double d : {0.0, 1e-4}) {
    for (double eps : {0.0, 0.5}) {
      const Scene s = no_tension(eps, 0.08, d);
      const Solution single = solve(s, shooting(Method::shooting));
      const Solution multiple = solve(s, shooting(Method::multiple_shooting));
      CAPTURE(d);
      CAPTURE(eps);
      REQUIRE(single.ok());
      REQUIRE(multiple.ok());
      CHECK(reaction_difference(single.reactions, multiple.reactions, s.thickness) <= 2 * kRtol);
      Options o = shooting(Method::automatic);
      o.stations = 65;
      const Solution automatic = solve(s, o);
      o.rtol = kRtol / 10;
      const Solution tight = solve(s, o);
      REQUIRE(automatic.ok());
      REQUIRE(tight.field);  // the reference, whatever its status: its own estimate is added below
      bool cracked = false;
      for (const ArchState& st : automatic.profile) cracked = cracked || st.cracked;
      CHECK(cracked);
      CHECK(solution_difference(automatic, tight) <= kRtol + tight.diagnostics.error_estimate);
    }
  }
}

TEST_CASE("no-tension quadrature: agrees with multiple shooting on cracked scenes (reactions and profiles)") {
  // Two independent methods (explicit forces and adaptive Gauss-Kronrod against CVODE through the same
  // hinges): the quadrature's reactions and profile, verified at rtol, within rtol of multiple
  // shooting's at rtol / 10 (plus that reference's own estimate).
  for (double d : {0.0, 1e-4}) {
    for (double eps : {0.0, 0.5}) {
      const Scene s = no_tension(eps, 0.08, d);
      const auto [quadrature, reference] = quadrature_against_shooting(s);
      CAPTURE(d);
      CAPTURE(eps);
      REQUIRE(quadrature.ok());
      CHECK(quadrature.method == Method::quadrature);
      REQUIRE(reference.field);  // whatever its status: its own estimate is added below
      CHECK(reaction_difference(quadrature.reactions, reference.reactions, s.thickness) <=
            kRtol + reference.diagnostics.error_estimate);
      bool cracked = false;
      for (const ArchState& st : quadrature.profile) cracked = cracked || st.cracked;
      CHECK(cracked);
      CHECK(solution_difference(quadrature, reference) <= kRtol + reference.diagnostics.error_estimate);
    }
  }
}

TEST_CASE("no-tension quadrature: whole arches, pinned springings, point, live and fill loads, a crown hinge") {
  // What the method treats besides the symmetric clamped arch, each against multiple shooting: the
  // quadrature's reactions and profile within rtol of multiple shooting's at rtol / 10.
  const double w = paper_scene(0.25, 0.1).reference_load_per_length() * 10.0;  // N/m: the weight of 10 m of axis
  std::vector<std::pair<const char*, Scene>> scenes;
  {
    Scene s = no_tension(0.25, 0.1, 1e-4);
    s.loads.points.push_back({0.2 * w, 0.3});
    s.left.kind = s.right.kind = SupportKind::pinned;
    scenes.push_back({"point load at 0.3 L, pinned", s});
  }
  {
    Scene s = no_tension(0.25, 0.1, 1e-4);
    s.loads.live.push_back({0.1 * w / 10.0, 0.2, 0.7});
    s.left.kind = SupportKind::pinned;
    scenes.push_back({"live load over 0.2 .. 0.7 L, left pinned", s});
  }
  {
    Scene s = no_tension(0.25, 0.1, 1e-4);
    s.loads.fills.push_back({1800, 0.3});
    scenes.push_back({"fill to 0.3 L, symmetric", s});
  }
  {
    Scene s = no_tension(0.25, 0.1, 1e-4);
    s.crown_hinge = true;
    s.left.kind = s.right.kind = SupportKind::pinned;
    scenes.push_back({"three-hinged (the crown hinge ends the half)", s});
  }
  for (const auto& scene : scenes) {
    CAPTURE(scene.first);
    const auto [quadrature, reference] = quadrature_against_shooting(scene.second);
    REQUIRE(quadrature.ok());
    REQUIRE(reference.field);
    CHECK(solution_difference(quadrature, reference) <= kRtol + reference.diagnostics.error_estimate);
  }
  // A crown hinge inside the whole arch is not treated (as by the shooting).
  Scene hinged = no_tension(0.25, 0.1, 1e-4);
  hinged.crown_hinge = true;
  hinged.left.kind = hinged.right.kind = SupportKind::pinned;
  Options o = shooting(Method::quadrature);
  o.whole_arch = true;
  CHECK(solve(hinged, o).status == Status::not_applicable);
}

TEST_CASE("no-tension: an arch too thin to stand without tension is inadmissible, not a number") {
  const Solution sol = solve(no_tension(0.0, 0.04), shooting(Method::automatic));
  CHECK(sol.status == Status::inadmissible);
  CHECK(std::isnan(sol.H));
  CHECK_FALSE(sol.message.empty());
  // The quadrature form says so too; the closed form does not apply.
  CHECK(solve(no_tension(0.0, 0.04), shooting(Method::quadrature)).status == Status::inadmissible);
  Options o;
  o.method = Method::closed_form;
  CHECK(solve(no_tension(0.0, 0.08), o).status == Status::not_applicable);
}

TEST_CASE("no-tension: an rtol below what double precision supports is the best answer, with the rtol it supports") {
  // At rtol 1e-14 the adaptive quadrature cannot resolve its integrals to rtol / 100 (round-off in the
  // section law near the hinges): it stops at a bounded number of panels, gives its best answer as
  // tolerance_not_met (or ill_conditioned, where the round-off bound exceeds rtol), and its message names
  // the rtol the scene supports, which is then met.
  Scene s = paper_scene(0.0, 0.08, 1e-3);
  s.section = SectionKind::no_tension;
  Options o;
  o.rtol = 1e-14;
  const Solution sol = solve(s, o);
  REQUIRE(sol.field);
  CHECK(sol.method == Method::quadrature);
  // Either the estimate exceeds rtol, or the round-off bound does (core/solution.hpp: roundoff_bound).
  CHECK((sol.status == Status::tolerance_not_met || sol.status == Status::ill_conditioned));
  CHECK(sol.diagnostics.error_estimate > o.rtol);
  CHECK(sol.diagnostics.segments <= 10000);  // panels: bounded (AdaptiveQuadrature's kMaxPanels and rounds)
  const std::string ask = "ask for rtol ";
  const std::size_t at = sol.message.find(ask);
  REQUIRE(at != std::string::npos);
  const double supported = std::stod(sol.message.substr(at + ask.size()));
  CAPTURE(sol.message);
  CHECK(supported >= sol.diagnostics.error_estimate);
  CHECK(supported < 1e-10);  // the quadrature's floor, not a failure
  // No contradiction: at the rtol it names, the scene succeeds, and both answers agree within it.
  o.rtol = supported;
  const Solution met = solve(s, o);
  CHECK(met.ok());
  CHECK(reaction_difference(sol.reactions, met.reactions, s.thickness) <= supported);
}

}  // namespace ogive

namespace ogive {

TEST_CASE("no-tension: a solve stops at its work budget, with not_converged naming it, after the same work every time") {
  // The thick semicircle spread by 1e-4 L: Newton does not converge from its first guess (its hinges
  // open to a sliver of t), so a small budget runs out. It runs out at a count, not a time: the same
  // work and iterations on every run.
  const auto model = std::make_shared<const ArchModel>(no_tension(0.0, 0.6, 1e-4), false);
  const Options o = shooting();
  for (const Method m : {Method::shooting, Method::quadrature}) {
    CAPTURE(std::string(to_string(m)));
    constexpr std::int64_t kBudget = 30000;
    auto run = [&] {
      return m == Method::shooting ? solve_no_tension(model, o, 1, {}, kBudget)
                                   : solve_no_tension_quadrature(model, o, {}, kBudget);
    };
    const Solution a = run(), b = run();
    CHECK(a.status == Status::not_converged);
    CHECK(a.message == work_budget_message(kBudget, m));
    CHECK_FALSE(a.field);
    // Beyond the budget only the evaluation under way: CVODE's few retries of a refused right-hand
    // side, or the quadrature's nodes at the trial (15 a panel) and the two halves it was splitting.
    const std::int64_t under_way = m == Method::shooting ? 100 : 15 * (a.diagnostics.segments + 2);
    CHECK(a.diagnostics.rhs_evaluations <= kBudget + under_way);
    CHECK(a.diagnostics.rhs_evaluations == b.diagnostics.rhs_evaluations);
    CHECK(a.diagnostics.newton_iterations == b.diagnostics.newton_iterations);
  }
}

TEST_CASE("no-tension: Newton shooting gives up a trial that creeps toward a face instead of integrating it to CVODE's step limit") {
  // The same scene's single-shooting Newton, unbounded: its trials beyond the admissible states used to
  // run to CVODE's 200 000 steps each (some 400 000 right-hand sides, seconds), while the accepted
  // evaluations take a few hundred; 30 iterations spent some 10^7. Now such a trial stops at 4 times the
  // costliest accepted evaluation (at least 5 000 right-hand sides).
  const auto model = std::make_shared<const ArchModel>(no_tension(0.0, 0.6, 1e-4), false);
  const Solution sol = solve_no_tension(model, shooting(), 1);
  CAPTURE(sol.message);
  CHECK(sol.diagnostics.newton_iterations <= kMaxNewtonIterations);
  CHECK(sol.diagnostics.rhs_evaluations <= 1'000'000);
}

}  // namespace ogive
