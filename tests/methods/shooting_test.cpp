// CVODE single and multiple shooting (src/methods/shooting.hpp) against the closed form: accuracy,
// convergence, slender arches, profiles, breakpoints and failure reporting.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "methods/closed_form.hpp"
#include "methods/shooting.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The raw methods (Options::verify off): these tests measure CVODE's own accuracy, which the
// tolerance factors of shooting.cpp rest on. Verification is tested in acceptance/failure_modes_test.cpp.
Solution run(const Scene& scene, Method m, Integrator i = Integrator::adams, double rtol = 1e-8, int stations = 0,
             int segments = 8) {
  Options o;
  o.method = m;
  o.integrator = i;
  o.rtol = rtol;
  o.stations = stations;
  o.segments = segments;
  o.verify = false;
  return solve(scene, o);
}

// A raw solve's status: the closed form's is a guarantee (success), CVODE's without verification is
// `unverified`, never success; either way the numbers are there.
bool solved_raw(const Solution& sol) {
  return sol.field && sol.status == (sol.method == Method::closed_form ? Status::success : Status::unverified);
}

// The error of H/V scaled by V's own scale: H/V itself crosses zero as d grows.
double hv_error(const Solution& a, const Solution& ref) {
  return std::abs(a.H_over_V - ref.H_over_V) / std::max(std::abs(ref.H_over_V), 0.1);
}

const std::vector<double> kRtols = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11};

}  // namespace

// What the raw methods achieve with the tolerances cvode_tolerances gives CVODE: within 10 rtol. This is
// the margin verification starts from, not the guarantee of `success` (which is rtol).
TEST_CASE("shooting: raw single and multiple shooting agree with the closed form to 10 rtol - both integrators") {
  for (double eps : {0.0, 0.5, 1.0, 2.0})
    for (double t : {0.06, 0.2})
      for (double d : {0.0, 3e-4}) {
        const Scene scene = paper_scene(eps, t, d);
        const Solution ref = run(scene, Method::closed_form);
        for (Integrator integ : {Integrator::adams, Integrator::bdf})
          for (Method m : {Method::shooting, Method::multiple_shooting})
            for (double rtol : kRtols) {
              const Solution sol = run(scene, m, integ, rtol);
              CAPTURE(eps);
              CAPTURE(t);
              CAPTURE(d);
              CAPTURE(to_string(integ));
              CAPTURE(to_string(m));
              CAPTURE(rtol);
              REQUIRE(solved_raw(sol));
              CHECK(sol.message.find("not verified") != std::string::npos);
              CHECK(hv_error(sol, ref) <= 10 * rtol);
              CHECK(sol.diagnostics.steps > 0);
              CHECK(sol.diagnostics.rhs_evaluations >= sol.diagnostics.steps);
              CHECK(sol.diagnostics.boundary_residual <= 10 * rtol);
              CHECK(sol.diagnostics.equilibrium_residual <= 10 * rtol);
            }
      }
}

TEST_CASE("shooting: tightening rtol 100-fold cuts the error roughly 100-fold") {
  // Least-squares slope of log(error) against log(rtol) over 1e-4 .. 1e-10: about 1 (tolerance
  // proportionality). Single errors scatter, so the slope, not each ratio, is the claim.
  for (Integrator integ : {Integrator::adams, Integrator::bdf})
    for (Method m : {Method::shooting, Method::multiple_shooting}) {
      const Scene scene = paper_scene(0.5);
      const Solution ref = run(scene, Method::closed_form);
      std::vector<double> lx, ly;
      for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
        const double err = hv_error(run(scene, m, integ, rtol), ref);
        REQUIRE(err > 0);
        lx.push_back(std::log10(rtol));
        ly.push_back(std::log10(err));
      }
      const double mx = (lx[0] + lx[1] + lx[2] + lx[3]) / 4, my = (ly[0] + ly[1] + ly[2] + ly[3]) / 4;
      double sxy = 0, sxx = 0;
      for (int k = 0; k < 4; ++k) {
        sxy += (lx[k] - mx) * (ly[k] - my);
        sxx += (lx[k] - mx) * (lx[k] - mx);
      }
      const double slope = sxy / sxx;
      CAPTURE(to_string(integ));
      CAPTURE(to_string(m));
      CHECK(slope > 0.7);
      CHECK(slope < 1.4);
      // Over the whole range the error falls by at least 10^4 (ideal: 10^6).
      CHECK(ly.front() - ly.back() > 4.0);
    }
}

TEST_CASE("shooting: slender arches - t/L = 1e-3 and 1e-4 - multiple shooting agrees with the closed form to 1e-7") {
  for (double t : {1e-3, 1e-4})
    for (double eps : {0.0, 0.5, 1.0}) {
      const Scene scene = paper_scene(eps, t);
      const Solution ref = run(scene, Method::closed_form);
      REQUIRE(ref.ok());
      for (Integrator integ : {Integrator::adams, Integrator::bdf}) {
        const Solution sol = run(scene, Method::multiple_shooting, integ, 1e-9);
        CAPTURE(t);
        CAPTURE(eps);
        CAPTURE(to_string(integ));
        REQUIRE(solved_raw(sol));
        CHECK(hv_error(sol, ref) <= 1e-7);
      }
    }
}

TEST_CASE("shooting: the profile matches the closed form's at every station") {
  constexpr int kStations = 61;
  for (double eps : {0.0, 1.0}) {
    const Scene scene = paper_scene(eps, 0.1, 1e-4);
    const Solution ref = run(scene, Method::closed_form, Integrator::adams, 1e-8, kStations);
    for (Method m : {Method::shooting, Method::multiple_shooting}) {
      const double rtol = 1e-8;
      const Solution sol = run(scene, m, Integrator::adams, rtol, kStations);
      REQUIRE(sol.profile.size() == ref.profile.size());
      // Each quantity against its own scale along the arch (max |.|), since each crosses zero.
      auto scale_of = [&](auto get) {
        double s = 0;
        for (const ArchState& st : ref.profile) s = std::max(s, std::abs(get(st)));
        return s;
      };
      const double sN = scale_of([](const ArchState& s) { return s.N; });
      const double sV = scale_of([](const ArchState& s) { return s.V; });
      const double sM = scale_of([](const ArchState& s) { return s.M; });
      const double sUx = scale_of([](const ArchState& s) { return s.Ux; });
      const double sUy = scale_of([](const ArchState& s) { return s.Uy; });
      const double sPsi = scale_of([](const ArchState& s) { return s.psi; });
      for (std::size_t k = 0; k < ref.profile.size(); ++k) {
        const ArchState &a = sol.profile[k], &b = ref.profile[k];
        CAPTURE(k);
        CHECK(close(a.s, b.s, kExact));
        CHECK(std::abs(a.N - b.N) <= 10 * rtol * sN);
        CHECK(std::abs(a.V - b.V) <= 10 * rtol * sV);
        CHECK(std::abs(a.M - b.M) <= 10 * rtol * sM);
        CHECK(std::abs(a.Ux - b.Ux) <= 10 * rtol * sUx);
        CHECK(std::abs(a.Uy - b.Uy) <= 10 * rtol * sUy);
        CHECK(std::abs(a.psi - b.psi) <= 10 * rtol * sPsi);
        // e = 600 M / (N t): relative to the kern, its error follows from M's and N's.
        CHECK(std::abs(a.e - b.e) <= 600.0 * 10 * rtol * (sM / std::abs(b.N) + std::abs(b.M) * sN / (b.N * b.N)) / 1.0);
      }
      // The state view at any s, right half included, agrees as well.
      const double s = 1.2345 * scene.curve->length();
      CHECK(std::abs(sol.at(s).M - ref.at(s).M) <= 10 * rtol * sM);
    }
  }
}

TEST_CASE("shooting: a field kept as CVODE's dense output gives the states integrated to each station") {
  // A field that a summary will search (Options::unprinted_profile) keeps each piece's steps instead of
  // integrating it again for every state asked. The same steps, interpolated by the same polynomials:
  // every state agrees with the field integrated through the stations, to a few round-offs of each
  // quantity's largest size (kDenseAgreement), over a hinge, a point load and a breakpoint.
  constexpr double kDenseAgreement = 16 * std::numeric_limits<double>::epsilon();
  constexpr int kStations = 97;
  Scene pointed = paper_scene(1.0, 0.1, 1e-4);
  pointed.loads.points = {{2e4, 0.3}};
  Scene hinged = paper_scene(0.5);
  hinged.left.kind = hinged.right.kind = SupportKind::pinned;
  hinged.crown_hinge = true;
  for (const Scene& scene : {pointed, hinged})
    for (Method m : {Method::shooting, Method::multiple_shooting})
      for (Integrator i : {Integrator::adams, Integrator::bdf}) {
        Options o;
        o.method = m;
        o.integrator = i;
        o.verify = false;
        o.stations = kStations;
        const Solution stepped = solve(scene, o);
        o.unprinted_profile = true;
        Solution kept = solve(scene, o);
        CAPTURE(std::string(to_string(m)));
        CAPTURE(std::string(to_string(i)));
        REQUIRE(stepped.field);
        REQUIRE(kept.field);
        CHECK(kept.profile.empty());
        // The stations one at a time, in reverse: a search's order, not a profile's.
        std::vector<ArchState> one_by_one;
        for (int k = kStations; k-- > 0;) one_by_one.push_back(sample_stations(kept, kStations, k, 1).at(0));
        std::reverse(one_by_one.begin(), one_by_one.end());
        CHECK(profile_difference(one_by_one, stepped.profile, scene.thickness) <= kDenseAgreement);
        sample_profile(kept, kStations);
        CHECK(profile_difference(kept.profile, stepped.profile, scene.thickness) <= kDenseAgreement);
      }
}

TEST_CASE("shooting: segment boundaries include the curve's breakpoints") {
  // A three-centred half arch built by hand: haunch arc r1 = 2 m over 60 deg, crown arc r2 = 8 m.
  const double r1 = 2.0, r2 = 8.0, a1 = std::numbers::pi / 3, a2 = std::numbers::pi / 6;
  CircularArc haunch{0.0, r1 * a1, 0.0, 0.0, std::numbers::pi / 2, -1.0 / r1};
  const CurvePoint join = point_on_arc(haunch, haunch.length);
  CircularArc crown{haunch.length, r2 * a2, join.x, join.y, join.theta, -1.0 / r2};
  const double span = 2.0 * point_on_arc(crown, crown.length).x;
  Scene scene;
  scene.curve = std::make_shared<PiecewiseCircularCurve>("three-centred", span, std::vector{haunch, crown});
  scene.thickness = 0.08 * span;
  const ArchModel model(scene);
  const std::vector<double> knots = shooting_knots(model, 3);
  const double b = haunch.length / span;
  CHECK(std::any_of(knots.begin(), knots.end(), [&](double k) { return std::abs(k - b) < kExact; }));
  CHECK(shooting_knots(model, 1).size() == 2);  // single shooting: one segment; the integrator restarts
  const Solution ref = run(scene, Method::closed_form);
  for (Method m : {Method::shooting, Method::multiple_shooting})
    for (Integrator integ : {Integrator::adams, Integrator::bdf}) {
      const Solution sol = run(scene, m, integ, 1e-9, 0, 3);
      REQUIRE(solved_raw(sol));
      CHECK(hv_error(sol, ref) <= 1e-8);
    }
}

TEST_CASE("shooting: a CVODE failure is a status naming the flag and where - never a number") {
  Options o;
  o.method = Method::multiple_shooting;
  o.rtol = 1e-12;
  o.max_steps = 5;
  const Solution sol = solve(paper_scene(0.5), o);
  CHECK(sol.status == Status::integrator_failure);
  CHECK(sol.message.find("CV_TOO_MUCH_WORK") != std::string::npos);
  CHECK(sol.message.find("s = ") != std::string::npos);
  CHECK(std::isnan(sol.H_over_V));
  CHECK(sol.profile.empty());
  CHECK_THROWS_AS(sol.at(1.0), std::logic_error);
}

TEST_CASE("shooting: more segments than one Adams run holds are integrated in runs, verified as one run is") {
  // 10 000 segments: three runs of at most 4096 segments each (a survey of 10^5 points would otherwise
  // hold every segment in each of CVODE's vectors). The verified answer meets rtol against the closed form.
  const Scene s = paper_scene(0.5, 0.08, 1e-4);
  Options o;
  o.method = Method::multiple_shooting;
  o.segments = 10000;
  const Solution sol = solve(s, o), exact = closed_form(s);
  REQUIRE(sol.ok());
  CHECK(sol.diagnostics.segments >= 10000);
  CHECK(reaction_difference(sol.reactions, exact.reactions, s.thickness) <= o.rtol);
  CHECK(thrust_error(sol.H_over_V, exact.H_over_V) <= o.rtol);
}
