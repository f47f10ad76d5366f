// The seed paper's Figures 7 to 12, by the closed form: H/V against E and Poisson's ratio, against the
// eccentricity, the thickness and the support displacement, and the eccentricity of the thrust along
// the arch (docs/model.md explains each reading).
#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>

#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// Tolerances for readings off the paper's figures and text.
constexpr double kFigureReading = 0.05;  // a value read off a plotted curve, relative

}  // namespace

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
