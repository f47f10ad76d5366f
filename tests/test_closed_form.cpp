// The closed form against physics, an independent force-method reference and the paper's figures.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "methods/closed_form.hpp"
#include "ogive/solve/solve.hpp"
#include "reference.hpp"
#include "scenes.hpp"
#include "tolerances.hpp"

using namespace ogive;

namespace {


Solution closed_form(const Scene& scene, int stations = 0) {
  Options o;
  o.method = Method::closed_form;
  o.stations = stations;
  return solve(scene, o);
}

// Two exact methods in floating point agree to round-off times the system's condition (~10^2..10^3).
constexpr double kTwoExactMethods = 1e-11;
// Tolerances for readings off the paper's figures and text.
constexpr double kFigureReading = 0.05;  // a value read off a plotted curve, relative

}  // namespace

TEST_CASE("closed form: the solution meets all six boundary conditions and global equilibrium") {
  for (double eps : {0.0, 0.3, 0.5, 1.0, 3.0})
    for (double t : {0.06, 0.2})
      for (double d : {0.0, 2e-4}) {
        CAPTURE(eps);
        CAPTURE(t);
        CAPTURE(d);
        const Scene scene = paper_scene(eps, t, d);
        const Solution sol = closed_form(scene, 3);  // springing, crown, springing
        REQUIRE(sol.status == Status::success);
        CHECK(sol.diagnostics.boundary_residual <= kExact);
        CHECK(sol.diagnostics.equilibrium_residual <= kExact);
        // In SI, from the profile: the springing and crown states themselves.
        const ArchState& spring = sol.profile.front();
        const ArchState& crown = sol.profile[1];
        const double disp = sol.model->scales().displacement, rot = sol.model->scales().rotation;
        const double force = sol.model->scales().force;
        CHECK(std::abs(spring.Ux + scene.left.spread) <= kExact * disp);
        CHECK(std::abs(spring.Uy) <= kExact * disp);
        CHECK(std::abs(spring.psi) <= kExact * rot);
        CHECK(std::abs(crown.Ux) <= kExact * disp);
        CHECK(std::abs(crown.psi) <= kExact * rot);
        CHECK(std::abs(crown.Fy) <= kExact * force);
        // The vertical reaction is half the weight, w S, and H = -Fx everywhere.
        CHECK(close(sol.V, scene.weight_per_length() * scene.curve->length(), kExact));
        CHECK(close(-spring.Fy, sol.V, kExact));
        CHECK(close(-crown.Fx, sol.H, kExact));
      }
}

TEST_CASE("closed form: H/V does not change when E is scaled (Figure 7)") {
  for (double eps : {0.0, 0.5, 1.0}) {
    const double reference = closed_form(paper_scene(eps)).H_over_V;
    for (double factor : {1e-3, 0.1, 7.0, 1e3}) {
      Scene scene = paper_scene(eps);
      scene.material.youngs_modulus *= factor;
      CHECK(close(closed_form(scene).H_over_V, reference, kExact));
    }
  }
}

TEST_CASE("closed form: H/V is practically independent of Poisson's ratio (Figure 7)") {
  // The figure's colour scale shows no visible change for nu in [0, 0.5]: less than 1 %.
  const double base = closed_form(paper_scene(0.0)).H_over_V;
  for (double nu : {0.0, 0.1, 0.3, 0.4, 0.5}) {
    Scene scene = paper_scene(0.0);
    scene.material.poisson_ratio = nu;
    CHECK(relative_difference(closed_form(scene).H_over_V, base) < 0.01);
  }
}

TEST_CASE("closed form: agrees with the force method (Castigliano) for any eccentricity - thickness - d") {
  for (double eps : {0.0, 0.25, 0.5, 1.0, 2.0, 5.0})
    for (double t : {0.01, 0.08, 0.2})
      for (double d : {0.0, 1e-4, -5e-5}) {
        CAPTURE(eps);
        CAPTURE(t);
        CAPTURE(d);
        const Scene scene = paper_scene(eps, t, d);
        const double H = reference::castigliano_pointed_H(10.0, eps, scene.thickness, scene.material,
                                                          scene.left.spread);
        const Solution sol = closed_form(scene);
        REQUIRE(sol.ok());
        // Scale by the weight: H may cross zero as d grows.
        CHECK(std::abs(sol.H - H) <= kTwoExactMethods * sol.V);
      }
  Scene strain = paper_scene(0.5);
  strain.material.plane_strain = true;
  CHECK(close(closed_form(strain).H, reference::castigliano_pointed_H(10.0, 0.5, 0.8, strain.material, 0.0),
              kTwoExactMethods));
}

TEST_CASE("Figure 8: H/V about 0.40 for the semicircle - about 41 % lower at eps 0.5 and 55 % at eps 1") {
  const double semicircle = closed_form(paper_scene(0.0)).H_over_V;
  CHECK(close(semicircle, 0.40, kFigureReading));
  const double drop_half = 1.0 - closed_form(paper_scene(0.5)).H_over_V / semicircle;
  const double drop_one = 1.0 - closed_form(paper_scene(1.0)).H_over_V / semicircle;
  // docs/model.md: a careful implementation gives ~41 % and ~55 % (the paper's text rounds to 45 %, 55 %).
  CHECK(std::abs(drop_half - 0.41) < 0.03);
  CHECK(std::abs(drop_one - 0.55) < 0.03);
  // And H/V falls monotonically with pointedness.
  double previous = semicircle;
  for (int i = 1; i <= 20; ++i) {
    const double now = closed_form(paper_scene(0.1 * i)).H_over_V;
    CHECK(now < previous);
    previous = now;
  }
}

TEST_CASE("Figure 9: thicker arches have a smaller H/V at every eccentricity") {
  for (int i = 0; i <= 10; ++i) {
    const double eps = 0.1 * i;
    double previous = closed_form(paper_scene(eps, 0.04)).H_over_V;
    for (double t : {0.06, 0.08, 0.10, 0.15, 0.20}) {
      const double now = closed_form(paper_scene(eps, t)).H_over_V;
      CAPTURE(eps);
      CAPTURE(t);
      CHECK(now < previous);
      previous = now;
    }
  }
}

TEST_CASE("Figure 10: H/V falls linearly with d - zero near d/L = 0.017 % for the semicircle") {
  // Linearity is exact in a linear model: second differences vanish to round-off.
  for (double eps : {0.0, 0.5, 1.0}) {
    const double h0 = closed_form(paper_scene(eps, 0.08, 0.0)).H_over_V;
    const double h1 = closed_form(paper_scene(eps, 0.08, 1e-4)).H_over_V;
    const double h2 = closed_form(paper_scene(eps, 0.08, 2e-4)).H_over_V;
    CHECK(std::abs(h2 - 2 * h1 + h0) <= kTwoExactMethods * std::abs(h0));
    CHECK(h1 < h0);
  }
  const double h0 = closed_form(paper_scene(0.0)).H_over_V;
  const double slope = (closed_form(paper_scene(0.0, 0.08, 1e-4)).H_over_V - h0) / 1e-4;
  const double zero = -h0 / slope;  // d/L where the thrust turns outwards
  CHECK(zero > 0.015e-2);
  CHECK(zero < 0.019e-2);
  // The more pointed, the slower the fall.
  double previous_rate = -slope;
  for (double eps : {0.25, 0.5, 1.0, 2.0}) {
    const double rate = (closed_form(paper_scene(eps)).H_over_V - closed_form(paper_scene(eps, 0.08, 1e-4)).H_over_V) / 1e-4;
    CHECK(rate > 0);
    CHECK(rate < previous_rate);
    previous_rate = rate;
  }
}


TEST_CASE("Figure 11: large bending at the crown - eps 0.5 is the most favourable - thick arches stay in the kern at the springing") {
  constexpr int kStations = 401;
  for (double t : {0.08, 0.20}) {
    const Solution circle = closed_form(paper_scene(0.0, t), kStations);
    const Solution equilateral = closed_form(paper_scene(0.5, t), kStations);
    const Solution pointed = closed_form(paper_scene(1.0, t), kStations);
    CAPTURE(t);
    CHECK(max_abs_e(equilateral) < max_abs_e(circle));
    CHECK(max_abs_e(equilateral) < max_abs_e(pointed));
    const std::size_t crown = kStations / 2;
    if (t == 0.08) {
      // The neighbourhood of the crown carries large bending in all three shapes: |e| > 100 %.
      for (const Solution* s : {&circle, &equilateral, &pointed}) CHECK(std::abs(s->profile[crown].e) > 100.0);
    } else {
      // Thick vaults: the reactions act inside the kern for the circle and the equilateral arch.
      CHECK(std::abs(circle.profile.front().e) < 100.0);
      CHECK(std::abs(equilateral.profile.front().e) < 100.0);
    }
    // Thicker is more favourable at most sections: here, at the springing.
  }
  CHECK(std::abs(closed_form(paper_scene(0.0, 0.20), 3).profile.front().e) <
        std::abs(closed_form(paper_scene(0.0, 0.08), 3).profile.front().e));
}

TEST_CASE("Figure 12: for the semicircle - e near the crown grows huge at d/L = 0.03 %") {
  const double e0 = std::abs(closed_form(paper_scene(0.0, 0.08, 0.0), 3).profile[1].e);
  const double e3 = std::abs(closed_form(paper_scene(0.0, 0.08, 3e-4), 3).profile[1].e);
  CHECK(e0 > 100.0);
  CHECK(e3 > 10.0 * e0);
}

TEST_CASE("closed form: every station - right half included - balances the free body from the left springing") {
  // The right half is not solved but mapped from the left (symmetry, with "beyond" and "before"
  // swapped): this checks that map against statics and the right springing's own conditions, which a
  // wrong sign of Ux, psi or Fy there would break. Free body [0, s]: the support pushes -F(0) and the
  // couple -M(0), the part beyond pushes F(s) with M(s), the weight w per length acts at the axis.
  const double d = 1e-4 * 10.0;
  const Scene scene = paper_scene(0.5, 0.08, 1e-4);
  Options o;
  o.method = Method::closed_form;
  o.stations = 41;
  const Solution sol = solve(scene, o);
  REQUIRE(sol.ok());
  const double w = scene.weight_per_length(), L = 10.0;
  const ArchState& a = sol.profile.front();
  // The integral of x over [0, s] of the whole arch by composite Simpson on each half (smooth there).
  auto first_moment = [&](double s_end) {
    const double S = scene.curve->length();
    auto simpson = [&](double lo, double hi) {
      const int n = 4000;
      const double h = (hi - lo) / n;
      double sum = 0;
      for (int k = 0; k <= n; ++k) {
        const double x = scene.curve->at_whole_arch(lo + k * h).x;
        sum += x * ((k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2));
      }
      return sum * h / 3;
    };
    return s_end <= S ? simpson(0, s_end) : simpson(0, S) + simpson(S, s_end);
  };
  for (const ArchState& st : sol.profile) {
    CAPTURE(st.s);
    CHECK(std::abs(st.Fx - a.Fx) <= kExact * w * L);
    CHECK(std::abs(st.Fy - (a.Fy + w * st.s)) <= kExact * w * L);
    const double moment = a.M + (a.x * a.Fy - a.y * a.Fx) - (st.x * st.Fy - st.y * st.Fx) + w * first_moment(st.s);
    CHECK(std::abs(st.M - moment) <= 1e-10 * w * L * L);
    // The resultant F acting at the thrust point has the moment M about the axis point.
    const double arm_x = st.thrust_x - st.x, arm_y = st.thrust_y - st.y;
    CHECK(std::abs(arm_x * st.Fy - arm_y * st.Fx - st.M) <= 1e-9 * std::abs(st.N) * 0.8);
    // e is the offset in per cent of the kern half-width t/6.
    CHECK(close(std::abs(st.e) / 100.0 * 0.8 / 6.0, std::hypot(arm_x, arm_y), 1e-9));
  }
  // Both springings: the left moves out by d (to -x), the right by d (to +x); neither settles nor turns.
  const ArchState& z = sol.profile.back();
  CHECK(close(a.Ux, -d, 1e-12));
  CHECK(close(z.Ux, d, 1e-12));
  const double U = std::abs(d);
  CHECK(std::abs(a.Uy) <= kExact * U);
  CHECK(std::abs(z.Uy) <= kExact * U);
  CHECK(std::abs(a.psi) <= kExact * U / L);
  CHECK(std::abs(z.psi) <= kExact * U / L);
  CHECK(close(z.x, L, kExact));
}

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
