// The mechanism part of the spreading path (include/ogive/limit/spreading.hpp) on its invariants: the
// program's thrust against the mechanism's virtual work at every step, the loads' potential energy
// along the movement, the start at the limit analysis' H_min, the semicircle's rising thrust
// (Ochsendorf 2006), the capacity against the thickness, one-sided movement, and misuse.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The program's thrust through three pins and the virtual work of the same three-hinge mechanism are
// one statically determinate equilibrium computed twice: they agree to round-off.
constexpr double kStaticKinematic = 1e-9;
// The path's first state is the limit analysis' minimum-thrust state, solved again with its hinges as
// pins: the same thrust to the LP's round-off.
constexpr double kSameState = 1e-9;

SpreadResult spread(double t_over_L, SpreadOptions o = {}) { return analyse_spreading(paper_scene(0.0, t_over_L), {}, o); }

}  // namespace

TEST_CASE("spreading: the static thrust equals the mechanism's virtual work at every step, and the loads descend") {
  const SpreadResult r = spread(0.075);
  REQUIRE(r.status == SpreadStatus::success);
  REQUIRE(r.path.size() > 10);
  for (std::size_t i = 0; i < r.path.size(); ++i) {
    const SpreadStep& s = r.path[i];
    CAPTURE(i);
    CHECK(close(s.H, s.H_work, kStaticKinematic));
    if (i > 0) {
      CHECK(s.potential < r.path[i - 1].potential);  // the weights go down
      CHECK(s.crown_drop > r.path[i - 1].crown_drop);
    }
  }
}

TEST_CASE("spreading: the path starts at H_min and the semicircle's thrust rises to collapse (Ochsendorf)") {
  const Scene scene = paper_scene(0.0, 0.075);
  const LimitResult lim = analyse_limit(scene, {});
  const SpreadResult r = analyse_spreading(scene, {}, {});
  REQUIRE(r.status == SpreadStatus::success);
  CHECK(close(r.path.front().H, lim.H_min(), kSameState));
  CHECK(r.path.back().H > r.path.front().H);
  CHECK(r.d_max > 0);
}

TEST_CASE("spreading: the capacity grows with the thickness from zero at t_min") {
  const double t_min_over_L = 0.1075 / 2;  // Milankovitch's t/R = 0.1075; t/L = t/(2R)
  double previous = 0;
  for (double t : {1.02 * t_min_over_L, 0.065, 0.075, 0.09}) {
    const SpreadResult r = spread(t);
    CAPTURE(t);
    REQUIRE(r.status == SpreadStatus::success);
    const double capacity = 2 * r.d_max / r.ring.span;
    CHECK(capacity > previous);
    previous = capacity;
  }
  const SpreadResult near = spread(1.0005 * t_min_over_L);
  REQUIRE(near.status == SpreadStatus::success);
  const SpreadResult thicker = spread(0.075);
  CHECK(near.d_max < 0.05 * thicker.d_max);
}

TEST_CASE("spreading: below t_min there is no path, and bad options throw") {
  const SpreadResult r = spread(0.05);
  CHECK(r.status == SpreadStatus::inadmissible);
  CHECK(r.path.empty());
  SpreadOptions o;
  o.left_share = o.right_share = 0;
  CHECK_THROWS_AS(spread(0.075, o), std::invalid_argument);
  o.left_share = -1;
  o.right_share = 1;
  CHECK_THROWS_AS(spread(0.075, o), std::invalid_argument);
}

TEST_CASE("spreading: one-sided movement keeps static and kinematic thrust equal") {
  SpreadOptions o;
  o.left_share = 0;
  const SpreadResult r = spread(0.075, o);
  REQUIRE(r.status == SpreadStatus::success);
  for (const SpreadStep& s : r.path) CHECK(close(s.H, s.H_work, kStaticKinematic));
  CHECK(r.d_max > 0);
}

TEST_CASE("spreading: the capacity converges with the joints count and the steps") {
  // Three significant digits: the capacity is bisected to kSpreadTolerance L whatever the steps, and the
  // limit analysis refines its ring next to the hinges whatever the starting joints count.
  constexpr double kThreeDigits = 5e-4;
  LimitOptions coarse, fine;
  coarse.joints_count = 101;
  fine.joints_count = 401;
  SpreadOptions few, many;
  few.steps = 20;
  many.steps = 400;
  const Scene scene = paper_scene(0.0, 0.075);
  const double a = analyse_spreading(scene, coarse, few).d_max;
  const double b = analyse_spreading(scene, fine, many).d_max;
  CHECK(close(a, b, kThreeDigits));
}

TEST_CASE("spreading: a pointed arch's two hinges beside the crown are no three-hinge mechanism, not a capacity of 0") {
  const Scene scene = paper_scene(0.5, 0.08);
  const SpreadResult r = analyse_spreading(scene, {}, {});
  CHECK(r.status == SpreadStatus::no_mechanism);
  REQUIRE(r.path.size() == 1);
  CHECK(close(r.path.front().H, analyse_limit(scene, {}).H_min(), kSameState));
}

TEST_CASE("spreading: hinges on the springings' joints open (a tall catenary's), static and kinematic thrust equal") {
  Scene scene = paper_scene(0.0, 0.08);
  scene.curve = make_catenary(10.0, 0.4);
  const SpreadResult r = analyse_spreading(scene, {}, {});
  REQUIRE(r.status == SpreadStatus::success);
  REQUIRE(r.hinge_joints.size() == 3);
  CHECK(r.hinge_joints.back() == static_cast<int>(r.ring.joints.size()) - 1);  // the right springing's joint
  CHECK(r.d_max > 0);
  for (const SpreadStep& s : r.path) CHECK(close(s.H, s.H_work, kStaticKinematic));
}
