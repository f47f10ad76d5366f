// The cracking arch (issue 13): the no-tension section's law against its own derivation, the shooting
// Jacobian against finite differences, single against multiple shooting, the path of a support movement
// traced there and back, and the limit analysis' minimum thrust as the floor it approaches.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>

#include "ogive/limit/limit.hpp"
#include "methods/no_tension.hpp"
#include "ogive/model/section.hpp"
#include "ogive/solve/solve.hpp"
#include "scenes.hpp"
#include "tolerances.hpp"

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

}  // namespace

TEST_CASE("no-tension: the section's law is the linear stress block it was derived from") {
  // Forward: a compressed depth c and a face strain eps_f give, by integrating the linear stress
  // E eps_f (1 - z / c) over 0 <= z <= c (Simpson, 2000 intervals), the resultant and its moment about
  // the axis; the law must return eps_f / c as the curvature and the plane section's strain at the axis.
  const double t = 0.08;  // scaled depth t/L; E = 1 in these units: eps = P t^3 / 12 ... (section.hpp)
  // In the scaled law E I = 1 for the unit section, so E = 12 / t^3 and the scaled N, M are forces.
  const double E = 12 / (t * t * t);
  for (double c_over_t : {0.95, 0.7, 0.4, 0.1, 0.02}) {
    for (double sign : {1.0, -1.0}) {
      const double c = c_over_t * t, eps_f = 1e-3;
      constexpr int n = 2000;
      double P = 0, moment = 0;
      for (int i = 0; i <= n; ++i) {
        const double z = c * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        const double stress = E * eps_f * (1 - z / c);  // compression, from the compressed face
        P += w * stress;
        moment += w * stress * (t / 2 - z);  // about the axis, towards the compressed face
      }
      P *= c / n / 3;
      moment *= c / n / 3;
      // The compressed face is the intrados for M > 0 (sign +1): M = sign * moment, N = -P.
      const SectionStrain s = section_strain(SectionKind::no_tension, -P, sign * moment, t);
      CAPTURE(c_over_t);
      CAPTURE(sign);
      REQUIRE(s.admissible);
      CHECK(s.cracked);
      CHECK(close(s.compressed_depth, c_over_t, 1e-9));
      CHECK(close(s.kappa, sign * eps_f / c, 1e-9));
      CHECK(close(s.eps, -eps_f * (1 - t / (2 * c)), 1e-9));
    }
  }
  // In the kern it is the linear law; at the kern's edge the two meet with continuous derivatives.
  const double P = 2.0, edge = P * t / 6;
  const SectionStrain in = section_strain(SectionKind::no_tension, -P, 0.5 * edge, t);
  CHECK_FALSE(in.cracked);
  CHECK(close(in.kappa, 0.5 * edge, kExact));
  CHECK(close(in.eps, -P * t * t / 12, kExact));
  const SectionStrain below = section_strain(SectionKind::no_tension, -P, edge * (1 - 1e-9), t);
  const SectionStrain above = section_strain(SectionKind::no_tension, -P, edge * (1 + 1e-9), t);
  CHECK(above.cracked);
  for (auto [a, b] : {std::pair{below.kappa, above.kappa}, {below.eps, above.eps}, {below.kappa_M, above.kappa_M},
                      {below.kappa_N, above.kappa_N}, {below.eps_N, above.eps_N}, {below.eps_M, above.eps_M}})
    CHECK(std::abs(a - b) <= 1e-7 * std::max({std::abs(a), std::abs(b), 1.0}));
  // The derivatives against central differences, in the cracked range.
  for (double e_over_t : {0.2, 0.3, 0.45}) {
    const double N = -1.3, M = 1.3 * e_over_t * t, h = 1e-7;
    const SectionStrain s = section_strain(SectionKind::no_tension, N, M, t);
    const SectionStrain n1 = section_strain(SectionKind::no_tension, N + h, M, t);
    const SectionStrain n0 = section_strain(SectionKind::no_tension, N - h, M, t);
    const SectionStrain m1 = section_strain(SectionKind::no_tension, N, M + h, t);
    const SectionStrain m0 = section_strain(SectionKind::no_tension, N, M - h, t);
    CAPTURE(e_over_t);
    CHECK(close(s.kappa_N, (n1.kappa - n0.kappa) / (2 * h), 1e-6));
    CHECK(close(s.kappa_M, (m1.kappa - m0.kappa) / (2 * h), 1e-6));
    CHECK(close(s.eps_N, (n1.eps - n0.eps) / (2 * h), 1e-6));
    CHECK(close(s.eps_M, (m1.eps - m0.eps) / (2 * h), 1e-6));
  }
  // Outside the section, or under tension: not admissible.
  CHECK_FALSE(section_strain(SectionKind::no_tension, -1, 0.51 * t, t).admissible);
  CHECK_FALSE(section_strain(SectionKind::no_tension, 0.1, 0, t).admissible);
}

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
  for (const auto& [name, s] : scenes) {
    CAPTURE(name);
    const auto [quadrature, reference] = quadrature_against_shooting(s);
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

}  // namespace ogive

namespace ogive {

TEST_CASE("no-tension: an rtol below what the quadrature can meet is a status, in bounded memory") {
  // Found by trying extreme options: at rtol 1e-14 the adaptive quadrature halved its panels until the
  // process was killed. Now it stops at a bounded number of panels and says why.
  Scene s = paper_scene(0.0, 0.08, 1e-3);
  s.section = SectionKind::no_tension;
  Options o;
  o.method = Method::quadrature;
  o.rtol = 1e-14;
  const Solution sol = solve(s, o);
  CHECK(sol.status == Status::not_converged);
  CHECK(sol.message.find("cannot meet its tolerance") != std::string::npos);
  CHECK(std::isnan(sol.H));
}

}  // namespace ogive
