// The resultant down a wall (ogive/core/wall_resultant.hpp) against a hand calculation: the elastic
// arch's thrust line at the springing carried down a rectangular wall bed by bed.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "ogive/core/wall_resultant.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

TEST_CASE("wall resultant: three beds against a hand calculation from the springing's thrust point") {
  Scene s = paper_scene(0.0, 0.10);  // semicircle, span 10 m, t = 1 m: a horizontal springing joint
  const double h = 8.0, b = 2.5, rho = 2000.0, Q = 30e3, g = s.material.gravity;
  s.left_wall = Wall{h, b, rho, Q, 0.25};
  Options o;
  o.stations = 11;
  const Solution sol = solve(s, o);
  REQUIRE(sol.ok());
  // By hand: the arch's resultant crosses the springing joint at (x_s, 0) with the reaction's V and H
  // (the thrust point of the profile's first station); below the springing, at depth z, the part of the
  // wall above carries it, its own weight gamma b z at the wall's middle x_m and the top load Q at x_Q:
  //   x(z) = (V x_s + gamma b z x_m + Q x_Q - H z) / (V + gamma b z + Q).
  const ArchState& first = sol.profile.front();
  REQUIRE(std::abs(first.thrust_y) <= kExact * s.span());
  const double H = sol.reactions.H_left, V = sol.reactions.V_left, x_s = first.thrust_x;
  const double inner = 0.5 * s.thickness, x_m = inner - 0.5 * b, x_Q = inner - 0.25 * b;
  const WallResultant w = wall_resultant(s, sol.reactions, false, 4);
  REQUIRE(w.beds.size() == 5);
  for (int k : {0, 2, 4}) {  // the top, the middle and the base
    const double z = h * k / 4.0, weight = rho * g * b * z;
    const double x = (V * x_s + weight * x_m + Q * x_Q - H * z) / (V + weight + Q);
    CAPTURE(k);
    CHECK(std::abs(w.beds[k].y + z) <= kExact * h);
    // The profile's thrust point and the reactions are one solution's: round-off apart.
    CHECK(close(w.beds[k].x, x, kTwoExactMethods));
    CHECK(close(w.beds[k].eccentricity, x_m - x, kTwoExactMethods));
  }
  CHECK(close(w.normal_force, V + rho * g * b * h + Q, kExact));
  CHECK(close(w.stability_ratio, 0.5 * b / std::abs(w.base_eccentricity), kExact));
  // The geometric factor: with b / factor the base's resultant sits on the outer toe.
  Scene at_toe = s;
  at_toe.left_wall->thickness = b / w.geometric_factor;
  const WallResultant t = wall_resultant(at_toe, sol.reactions, false, 4);
  CHECK(close(t.base_eccentricity, 0.5 * at_toe.left_wall->thickness, kTwoExactMethods));
  CHECK_THROWS_AS(wall_resultant(s, sol.reactions, true, 4), std::invalid_argument);
}
