// The mechanism part of the spreading path (include/ogive/limit/spreading.hpp) on its invariants: the
// program's thrust against the mechanism's virtual work at every step, the loads' potential energy
// along the movement, the start at the limit analysis' H_min, the semicircle's rising thrust
// (Ochsendorf 2006), the capacity against the thickness and its convergence, hinge migration, the pointed
// arch's four hinges, one-sided movement, settling springings (and their mirror symmetry), and misuse.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

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

TEST_CASE("spreading: a settling springing - static work equals the mechanism's, it sheds load, mirrors match") {
  // The right springing spreads and settles (0.5 m down per m out), the left stays: the least-work state
  // of each increment is no longer the least thrust, and the vertical reactions do work on the
  // settlement. The same movement mirrored (the left springing moving) gives the same path.
  SpreadOptions right, left;
  right.left_share = 0;
  right.right_settlement_share = 0.5;
  left.right_share = 0;
  left.left_settlement_share = 0.5;
  const SpreadResult r = spread(0.075, right), m = spread(0.075, left);
  // A finer ring changes the state at d = 0; with joints where its least-work line grazes the faces
  // there the capacity converges.
  REQUIRE(r.status == SpreadStatus::success);
  REQUIRE(m.status == SpreadStatus::success);
  REQUIRE(r.path.size() > 10);
  for (std::size_t i = 0; i < r.path.size(); ++i) {
    const SpreadStep& s = r.path[i];
    CAPTURE(i);
    CHECK(close(s.H, s.H_work, kStaticKinematic));
    if (i > 0) CHECK(s.potential < r.path[i - 1].potential);
  }
  CHECK(close(m.d_max, r.d_max, kSpreadTolerance));
  CHECK(close(m.path.back().H, r.path.back().H, kSameState));
  CHECK(close(m.path.front().V_right, r.path.front().V_left, kSameState));
  // The right springing rising instead (-0.5) is the same mechanics seen in a mirror and moved as a
  // whole (mirrored, the left springing moves out and down while the right stays; lifting the whole by
  // the settlement changes nothing): the same thrust at every d, the vertical reactions swapped.
  SpreadOptions rising = right;
  rising.right_settlement_share = -0.5;
  const SpreadResult u = spread(0.075, rising);
  REQUIRE(u.status == r.status);
  CHECK(close(u.d_max, r.d_max, kSpreadTolerance));
  REQUIRE(u.path.size() == r.path.size());
  for (std::size_t i = 0; i < r.path.size(); ++i) {
    CAPTURE(i);
    CHECK(close(u.path[i].d, r.path[i].d, kExact));
    CHECK(close(u.path[i].H, r.path[i].H, kSameState));
    CHECK(close(u.path[i].V_left, r.path[i].V_right, kSameState));
  }
  // Settling lowers the capacity.
  SpreadOptions level = right;
  level.right_settlement_share = 0;
  const SpreadResult flat = spread(0.075, level);
  REQUIRE(flat.status == SpreadStatus::success);
  CHECK(flat.d_max > r.d_max);
  // Where the settlement dominates, the state at d = 0 is no longer the minimum-thrust one (half the
  // load on each side): a thicker arch has room for a line of thrust that leans to the left springing.
  SpreadOptions steep = right;
  steep.right_settlement_share = 4;
  const SpreadResult sinking = spread(0.1, steep), level_thick = spread(0.1, level);
  // A finer ring changes the sinking arch's state at d = 0; joints where its least-work line grazes the
  // faces there settle it (the same capacity, 0.04893 L, from 201 to 1601 starting joints).
  REQUIRE(sinking.status == SpreadStatus::success);
  REQUIRE(level_thick.status == SpreadStatus::success);
  CHECK(close(level_thick.path.front().V_right, level_thick.path.front().V_left, kSameState));
  CHECK(sinking.path.front().V_right < level_thick.path.front().V_right);
  CHECK(sinking.path.front().H > level_thick.path.front().H);
  for (const SpreadStep& s : sinking.path) CHECK(close(s.H, s.H_work, kStaticKinematic));
  // Misuse: a settlement that is not a number.
  SpreadOptions bad = right;
  bad.right_settlement_share = std::nan("");
  CHECK_THROWS_AS(spread(0.075, bad), std::invalid_argument);
}

TEST_CASE("spreading: the capacity converges with the joints count and the increment") {
  // Three significant digits (a quarter of a percent) between the default ring and one four times
  // finer, and between increments of 1e-3 L and 1e-4 L (the hinges roll at the increments' ends;
  // collapse is bisected to kSpreadTolerance L; each ring is refined next to its hinges at collapse).
  // docs/spreading.md tabulates the measured capacities.
  constexpr double kThreeDigits = 2.5e-3;
  LimitOptions coarse, fine;
  fine.joints_count = 801;
  SpreadOptions large, small;
  large.increment_ratio = 1e-3;
  small.increment_ratio = 1e-4;
  for (const double e : {0.0, 0.5}) {
    CAPTURE(e);
    const Scene scene = paper_scene(e, 0.075);
    const double reference = analyse_spreading(scene, fine, small).d_max;
    CHECK(close(analyse_spreading(scene, coarse, small).d_max, reference, kThreeDigits));
    CHECK(close(analyse_spreading(scene, fine, large).d_max, reference, kThreeDigits));
  }
}

TEST_CASE("spreading: the semicircle's hinges migrate along the path") {
  // With its hinges held where they were at d = 0, the thrust line of the three-hinged semicircle
  // leaves the voussoirs next to its haunch hinges at a span increase of 0.038 L; with them free to
  // move, the arch carries on.
  const SpreadResult r = spread(0.075);
  REQUIRE(r.status == SpreadStatus::success);
  const std::vector<Hinge>& start = r.path.front().hinges;
  const std::vector<Hinge>& end = r.path.back().hinges;
  REQUIRE(start.size() == 3);
  REQUIRE(end.size() == 3);
  CHECK(end.front().joint != start.front().joint);
  CHECK(end.back().joint != start.back().joint);
  CHECK(end[1].joint == start[1].joint);  // the crown's stays
  CHECK(2 * r.d_max / r.ring.span > 0.045);
}

TEST_CASE("spreading: a pointed arch turns about four hinges, symmetrically under a symmetric movement") {
  // Its minimum-thrust state touches the extrados on both sides of the crown and the intrados at both
  // haunches: the crown block drops without turning.
  constexpr double kSymmetric = 1e-9;  // of the span: mirror images to round-off
  const Scene scene = paper_scene(0.5, 0.08);
  const SpreadResult r = analyse_spreading(scene, {}, {});
  // The path runs on a ring with joints where the least-thrust line grazes the faces at d = 0: its
  // least thrust lies above the limit analysis' ring's (whose joints stand for those points) by the
  // square of their distance, 2e-7 of it here.
  constexpr double kGrazingJoints = 1e-6;
  REQUIRE(r.status == SpreadStatus::success);
  const double H_min = analyse_limit(scene, {}).H_min();
  CHECK(r.path.front().H >= H_min * (1 - kSameState));
  CHECK(close(r.path.front().H, H_min, kGrazingJoints));
  const double L = r.ring.span;
  for (std::size_t i = 0; i < r.path.size(); ++i) {
    const SpreadStep& s = r.path[i];
    CAPTURE(i);
    REQUIRE(s.hinges.size() == 4);
    CHECK(close(s.H, s.H_work, kStaticKinematic));
    for (std::size_t k = 0; k < 2; ++k) {
      CHECK(std::abs(s.hinges[k].point.x() + s.hinges[3 - k].point.x() - L) <= kSymmetric * L);
      CHECK(std::abs(s.hinges[k].point.y() - s.hinges[3 - k].point.y()) <= kSymmetric * L);
    }
    if (i > 0) CHECK(s.potential < r.path[i - 1].potential);
  }
  CHECK(r.path.back().H > r.path.front().H);
  CHECK(r.d_max > 0);
}

TEST_CASE("spreading: hinges on the springings' joints open (a tall catenary's), static and kinematic thrust equal") {
  Scene scene = paper_scene(0.0, 0.08);
  scene.curve = make_catenary(10.0, 0.4);
  const SpreadResult r = analyse_spreading(scene, {}, {});
  REQUIRE(r.status == SpreadStatus::success);
  REQUIRE(r.path.front().hinges.size() == 3);
  CHECK(r.path.front().hinges.back().joint == static_cast<int>(r.ring.joints.size()) - 1);  // the right springing's
  CHECK(r.d_max > 0);
  for (const SpreadStep& s : r.path) CHECK(close(s.H, s.H_work, kStaticKinematic));
}

namespace {

// The semicircle at t/L = 0.10 with the true weight of its voussoirs: its haunch hinges stay on their
// joints up to a span increase of about 0.115 L, then roll.
Scene thick_semicircle() { return paper_scene(0.0, 0.10); }
LimitOptions true_weight() {
  LimitOptions o;
  o.weight = WeightModel::voussoir;
  return o;
}

// The angle of a voussoir's joint segment from its intrados corner to its extrados corner.
double joint_angle(const Eigen::Vector2d& intrados, const Eigen::Vector2d& extrados) {
  const Eigen::Vector2d e = extrados - intrados;
  return std::atan2(e.y(), e.x());
}

}  // namespace

TEST_CASE("spreading: hinges roll - every turned joint is a current hinge, and the thrust passes through its contact") {
  // Two voussoirs that meet at a joint place its two faces by their own rigid motions: a relative
  // rotation there (or a gap) is an opened joint, which must be one of the state's hinges, and the
  // thrust line must cross it at the hinge's point, where the faces still touch. Checked before the
  // hinges move (0.10), after they have rolled (0.125, 0.13) and at collapse.
  constexpr double kClosed = 1e-12;   // rad, and of the span: a closed joint's faces coincide to round-off
  constexpr double kContact = 1e-8;   // of the span: the LP's thrust line through the contact point
  const Scene scene = thick_semicircle();
  for (const double stop : {0.10, 0.125, 0.13, std::numeric_limits<double>::infinity()}) {
    CAPTURE(stop);
    SpreadOptions o;
    o.stop_ratio = stop;
    const SpreadResult r = analyse_spreading(scene, true_weight(), o);
    REQUIRE(r.status == SpreadStatus::success);
    const double L = r.ring.span;
    const SpreadStep& last = r.path.back();
    const SpreadShape& shape = r.shape;
    REQUIRE(shape.voussoirs.size() + 1 == r.ring.joints.size());
    REQUIRE(last.hinges.size() >= 3);
    int opened = 0;
    for (std::size_t j = 1; j < shape.voussoirs.size(); ++j) {
      const auto& before = shape.voussoirs[j - 1];  // its right joint: extrados [2], intrados [3]
      const auto& after = shape.voussoirs[j];       // its left joint: intrados [0], extrados [1]
      const double rotation = std::remainder(joint_angle(after[0], after[1]) - joint_angle(before[3], before[2]), 2 * std::numbers::pi);
      const double gap = std::max((after[0] - before[3]).norm(), (after[1] - before[2]).norm());
      const auto hinge = std::find_if(last.hinges.begin(), last.hinges.end(),
                                      [&](const Hinge& h) { return h.joint == static_cast<int>(j); });
      if (std::abs(rotation) <= kClosed && gap <= kClosed * L) continue;
      CAPTURE(j);
      ++opened;
      REQUIRE(hinge != last.hinges.end());
      CHECK((shape.thrust_line[j] - hinge->point).norm() <= kContact * L);
      // The faces still touch at the hinge's point.
      const Eigen::Vector2d& a = hinge->face == Face::intrados ? after[0] : after[1];
      const Eigen::Vector2d& b = hinge->face == Face::intrados ? before[3] : before[2];
      CHECK((a - b).norm() <= kClosed * L);
    }
    CHECK(opened >= 3);
    CHECK(opened <= static_cast<int>(last.hinges.size()));
  }
}

TEST_CASE("spreading: the semicircle's capacity with rolling hinges against an independent rigid-block reference") {
  // The semicircle at t/L = 0.10, true weight, both springings: a three-hinge mechanism (crown extrados,
  // the haunch hinges on the intrados) whose haunch hinge is, at each d, the joint at which the
  // three-hinge thrust line fits the voussoirs, computed by a separate program of rigid blocks on
  // uniform rings: capacity 0.131546 L from 201 to 1601 joints, 0.131656 from 3201, 0.131688 from 6401
  // (the hinge at collapse near 30.57 degrees from the springing); H/V at collapse 0.57531, 0.57509,
  // 0.57553; H/V at a span increase of 0.130 L 0.5678 from 3201 and 6401 joints.
  constexpr double kReferenceCapacity = 0.131688;
  constexpr double kFourDigits = 1e-4 / 0.13165;  // the bar: 1e-4 of the span
  constexpr double kHOverVDigits = 2e-4;          // H/V to its fourth significant digit
  const SpreadResult r = analyse_spreading(thick_semicircle(), true_weight(), {});
  REQUIRE(r.status == SpreadStatus::success);
  const double L = r.ring.span;
  CHECK(close(2 * r.d_max / L, kReferenceCapacity, kFourDigits));
  CHECK(close(r.path.back().H / r.path.back().V_left, 0.5755, kHOverVDigits));
  SpreadOptions o;
  o.stop_ratio = 0.130;
  const SpreadResult at = analyse_spreading(thick_semicircle(), true_weight(), o);
  REQUIRE(at.status == SpreadStatus::success);
  CHECK(close(at.path.back().H / at.path.back().V_left, 0.56777, kHOverVDigits));
  CHECK(at.rolls > 0);
}

TEST_CASE("spreading: without the whole path, the same answer from the first and last states only") {
  SpreadOptions whole, two;
  two.whole_path = false;
  const SpreadResult a = spread(0.075, whole), b = spread(0.075, two);
  REQUIRE(a.status == SpreadStatus::success);
  REQUIRE(b.status == SpreadStatus::success);
  REQUIRE(b.path.size() == 2);
  CHECK(a.d_max == b.d_max);
  CHECK(a.path.back().H == b.path.back().H);
  CHECK(a.path.front().H == b.path.front().H);
}

namespace {

LimitOptions with_friction(double mu) {
  LimitOptions o;
  o.friction = mu;
  return o;
}

// The angle (rad) of joint j's resultant to the joint's normal, from the state's H and V_left, the loads
// of the voussoirs before the joint (vertical: the same wherever the voussoirs are) and the joint's line
// where the moved voussoirs have it (the face of the voussoir after it; the last voussoir's right face
// at the right springing): computed apart from the program's rows and from sliding_joint.
double resultant_angle(const SpreadResult& r, std::size_t j) {
  const SpreadStep& s = r.path.back();
  double left = 0;
  for (std::size_t k = 0; k < j; ++k) {
    const Voussoir& v = r.ring.voussoirs[k];
    left += v.weight + v.fill.force + v.live.force;
  }
  const Eigen::Vector2d F(s.H, s.V_left - left);
  const std::size_t n = r.shape.voussoirs.size();
  const auto& face = r.shape.voussoirs[j < n ? j : n - 1];
  const Eigen::Vector2d along = (j < n ? face[1] - face[0] : face[2] - face[3]).normalized();
  return std::atan2(std::abs(F.dot(along)), std::abs(F.x() * along.y() - F.y() * along.x()));
}

}  // namespace

TEST_CASE("spreading with friction: a generous coefficient changes nothing, to the byte") {
  const Scene scene = paper_scene(0.0, 0.075);
  const SpreadResult free = analyse_spreading(scene, {}, {});
  const SpreadResult rough = analyse_spreading(scene, with_friction(0.6), {});
  REQUIRE(free.status == SpreadStatus::success);
  REQUIRE(rough.status == SpreadStatus::success);
  CHECK(rough.collapse == free.collapse);
  CHECK(rough.d_max == free.d_max);
  CHECK(rough.sliding_joint == -1);
  REQUIRE(rough.path.size() == free.path.size());
  for (std::size_t i = 0; i < free.path.size(); ++i) {
    CAPTURE(i);
    CHECK(rough.path[i].H == free.path[i].H);
    CHECK(rough.path[i].V_left == free.path[i].V_left);
  }
}

TEST_CASE("spreading with friction: the semicircle slides on a springing's bed, its resultant at atan mu there") {
  // The semicircle's thrust rises as it spreads (H/V from 0.35 at d = 0 to 0.47 at collapse at
  // t = 0.075 L): with 0.35 < mu < 0.47 the resultant on a springing's bed (horizontal, its normal
  // vertical) reaches the friction cone on the way, and a slip there is the wall's movement carried on.
  // Bisected to kSpreadTolerance L, along which H/V moves by about 2 kSpreadTolerance.
  constexpr double kBisected = 1e-5;     // rad
  constexpr double kInsideCone = 1e-9;   // rad: the other joints keep within the cone to round-off
  int tested = 0;
  for (const double t : {0.075, 0.1}) {
    const Scene scene = paper_scene(0.0, t);
    const SpreadStep end = analyse_spreading(scene, {}, {}).path.back();
    const ThrustState start = analyse_limit(scene, {}).min_state;
    for (const double mu : {0.4, 0.45}) {
      CAPTURE(t);
      CAPTURE(mu);
      if (!(mu > start.H / start.V_left && mu < end.H / end.V_left)) continue;
      ++tested;
      const SpreadResult r = analyse_spreading(scene, with_friction(mu), {});
      REQUIRE(r.status == SpreadStatus::success);
      REQUIRE(r.collapse == SpreadCollapse::sliding);
      const std::size_t last = r.ring.joints.size() - 1;
      CHECK((r.sliding_joint == 0 || r.sliding_joint == static_cast<int>(last)));
      const std::size_t j = static_cast<std::size_t>(r.sliding_joint);
      CHECK(std::abs(resultant_angle(r, j) - std::atan(mu)) <= kBisected);
      // The springings' beds carry the same H and V (a symmetric arch): both at the cone, neither beyond.
      CHECK(resultant_angle(r, 0) <= std::atan(mu) + kInsideCone);
      CHECK(resultant_angle(r, last) <= std::atan(mu) + kInsideCone);
      for (std::size_t k = 1; k < last; ++k) {
        const bool hinge = std::any_of(r.path.back().hinges.begin(), r.path.back().hinges.end(),
                                       [&](const Hinge& h) { return h.joint == static_cast<int>(k); });
        if (!hinge) CHECK(resultant_angle(r, k) <= std::atan(mu) + kInsideCone);
      }
      CHECK(r.d_max > 0);
    }
  }
  CHECK(tested == 4);
}

TEST_CASE("spreading with friction: the capacity grows with the coefficient up to the frictionless one") {
  const Scene scene = paper_scene(0.0, 0.075);
  const double free = analyse_spreading(scene, {}, {}).d_max;
  double previous = 0;
  int slid = 0;
  for (const double mu : {0.36, 0.38, 0.4, 0.42, 0.44, 0.46, 0.48, 0.5}) {
    CAPTURE(mu);
    const SpreadResult r = analyse_spreading(scene, with_friction(mu), {});
    REQUIRE(r.status == SpreadStatus::success);
    CHECK(r.d_max >= previous);
    CHECK(r.d_max <= free);
    if (r.collapse == SpreadCollapse::sliding) ++slid;
    else CHECK(r.d_max == free);
    previous = r.d_max;
  }
  CHECK(slid >= 4);
}

TEST_CASE("spreading with friction: no state at d = 0 inside the cones, or one that slides at once") {
  // Below the minimum-thrust state's H/V no state keeps the springings' beds inside the cone: limit
  // with the friction says inadmissible, and so does spread.
  const Scene scene = paper_scene(0.0, 0.075);
  CHECK(analyse_limit(scene, with_friction(0.3)).status == LimitStatus::inadmissible);
  CHECK(analyse_spreading(scene, with_friction(0.3), {}).status == SpreadStatus::inadmissible);
  // A thick semicircle's minimum-thrust line leans on a haunch joint beyond atan 0.35: the state it
  // starts from is limit's, of higher thrust, and the first movement slides.
  const Scene thick = paper_scene(0.0, 0.12);
  const LimitResult lim = analyse_limit(thick, with_friction(0.35));
  REQUIRE(lim.status == LimitStatus::success);
  const SpreadResult r = analyse_spreading(thick, with_friction(0.35), {});
  REQUIRE(r.status == SpreadStatus::success);
  CHECK(r.collapse == SpreadCollapse::sliding);
  CHECK(r.d_max == 0);
  REQUIRE(r.path.size() == 1);
  CHECK(r.path.front().H == lim.min_state.H);
  CHECK(r.path.front().H > analyse_limit(thick, {}).min_state.H);
}

namespace {

// The engineer's vault (docs/assessing-an-arch.md): an equilateral arch of 8 m, t = 0.8 m, fill of the
// same density to the crown, 50 kN/m at a quarter of the span.
Scene engineers_arch() {
  Scene s;
  s.curve = make_pointed(8.0, 0.5);
  s.thickness = 0.8;
  s.material.density = 2000;
  s.loads.fills.push_back(FillLoad{2000.0, 0.924});
  s.loads.points.push_back({5e4, 0.25});
  return s;
}

}  // namespace

TEST_CASE("spreading: the loaded pointed arch snaps where a hinge forms at its crown, every state in balance") {
  // Its three hinges (left haunch, extrados next to the load, right haunch) turn until the thrust line
  // reaches the intrados at the pointed crown, far from the right haunch's hinge: a fourth hinge that
  // no balance holds (the loads do work on the chain's free mode as it opens, at fixed springings), and
  // the blocks move on. Before it, with the true weight, the load's two edge joints both open (four
  // hinges in balance: the thrust line through each).
  constexpr double kClosed = 1e-12;   // rad, and of the span
  constexpr double kContact = 1e-8;   // of the span
  constexpr double kAtCrown = 1e-4;   // of the span: the thrust line at the crown's intrados at collapse
  for (const WeightModel weight : {WeightModel::voussoir, WeightModel::axis}) {
    CAPTURE(to_string(weight));
    LimitOptions o;
    o.weight = weight;
    const SpreadResult r = analyse_spreading(engineers_arch(), o, {});
    // A finer ring changes the state at d = 0. With the weight on the axis, joints where the
    // least-thrust line grazes the faces there settle it (the same capacity from 201 to 1601 starting
    // joints); with the true weight the capacity still moves by 3.2e-3 of itself on the rings with them.
    REQUIRE(r.status == (weight == WeightModel::axis ? SpreadStatus::success : SpreadStatus::not_converged));
    CHECK(r.collapse == SpreadCollapse::snap_through);
    CHECK(r.message.find("x = 0.5 L") != std::string::npos);
    const double L = r.ring.span;
    CHECK(2 * r.d_max / L > 0.005);
    bool four = false;
    for (std::size_t i = 0; i < r.path.size(); ++i) {
      CAPTURE(i);
      CHECK(close(r.path[i].H, r.path[i].H_work, kStaticKinematic));
      if (i > 0) CHECK(r.path[i].potential < r.path[i - 1].potential);
      four = four || r.path[i].hinges.size() == 4;
    }
    if (weight == WeightModel::voussoir) CHECK(four);
    // Every opened joint at collapse is a hinge, the thrust line through its point.
    const SpreadShape& shape = r.shape;
    const SpreadStep& last = r.path.back();
    int opened = 0;
    for (std::size_t j = 1; j < shape.voussoirs.size(); ++j) {
      const auto& before = shape.voussoirs[j - 1];
      const auto& after = shape.voussoirs[j];
      const double rotation = std::remainder(joint_angle(after[0], after[1]) - joint_angle(before[3], before[2]), 2 * std::numbers::pi);
      const double gap = std::max((after[0] - before[3]).norm(), (after[1] - before[2]).norm());
      if (std::abs(rotation) <= kClosed && gap <= kClosed * L) continue;
      CAPTURE(j);
      ++opened;
      const auto hinge = std::find_if(last.hinges.begin(), last.hinges.end(),
                                      [&](const Hinge& h) { return h.joint == static_cast<int>(j); });
      REQUIRE(hinge != last.hinges.end());
      CHECK((shape.thrust_line[j] - hinge->point).norm() <= kContact * L);
    }
    CHECK(opened >= 3);
    // The new contact: the thrust line reaches the intrados at the pointed crown (the joints through the
    // intrados' crown point, where the arch stood at d = 0), which is no hinge.
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t j = 1; j < shape.voussoirs.size(); ++j)
      if (std::abs(r.ring.joints[j].intrados.x() - L / 2) <= 1e-9 * L)
        nearest = std::min(nearest, (shape.thrust_line[j] - shape.voussoirs[j][0]).norm());
    CHECK(nearest <= kAtCrown * L);
  }
}

TEST_CASE("spreading: loaded arches whose contacts went back and forth now reach a collapse, in balance") {
  // A point load near the crown with fill: the thrust line grazes the extrados at both edges of the
  // load's joints, or touches a face far from its hinges. Each path ends at a collapse, its thrust the
  // mechanism's virtual work at every state and the loads going down.
  for (const auto& scene_at : {std::pair{0.0, 0.1}, std::pair{0.2, 0.08}, std::pair{0.5, 0.1}, std::pair{1.0, 0.15}}) {
    // Named copies: clang cannot capture a structured binding in CAPTURE's lambda.
    const double eccentricity = scene_at.first, thickness = scene_at.second;
    CAPTURE(eccentricity);
    CAPTURE(thickness);
    Scene s = paper_scene(eccentricity, thickness);
    s.material.density = 2000;
    s.loads.fills.push_back(FillLoad{2000.0, 0.9});
    s.loads.points.push_back({5e4, 0.4});
    LimitOptions o;
    o.weight = WeightModel::axis;
    const SpreadResult r = analyse_spreading(s, o, {});
    // At eccentricity 0.5 a finer ring changes the state at d = 0 and the capacity moves by more than
    // 1e-3 of itself there, joints where the least-thrust line grazes the faces or not; the others converge.
    REQUIRE(r.status == (eccentricity == 0.5 ? SpreadStatus::not_converged : SpreadStatus::success));
    CHECK(r.d_max > 0);
    for (std::size_t i = 0; i < r.path.size(); ++i) {
      CAPTURE(i);
      CHECK(close(r.path[i].H, r.path[i].H_work, kStaticKinematic));
      if (i > 0) CHECK(r.path[i].potential < r.path[i - 1].potential);
    }
  }
}

TEST_CASE("spreading: the equilateral arch converges on an independent reference's capacity") {
  // benchmarks/spreading_pointed/spread_check.py: its own ring (2000 equal voussoirs per half and a
  // joint where the least-thrust line grazes each face at d = 0, the haunch hinge's joint to collapse),
  // statics and kinematics of the symmetric four-hinge mechanism, the weight on the axis. Its capacity
  // (the span's increase at collapse over L) and H/V at collapse; 4000 and 8000 voussoirs per half
  // move the capacity by at most 1.1e-4 of itself (benchmarks/spreading_pointed/README.md).
  struct Reference {
    double t_over_L, capacity, H_over_V_collapse;
  };
  // H/V at collapse follows where the haunch hinge's joint is: 6e-5 at t = 0.09 L, whose ring has it
  // 1e-5 L from the grazing point (its finer rings change the capacity by less than 1e-3: success);
  // to the reference's six printed digits elsewhere.
  constexpr double kHaunchJoint = 1e-4;
  for (const Reference ref : {Reference{0.06, 0.142070, 0.294260}, Reference{0.08, 0.269991, 0.360135},
                              Reference{0.09, 0.331889, 0.395599},
                              Reference{0.10, 0.391232, 0.432441}, Reference{0.12, 0.499831, 0.509434},
                              Reference{0.14, 0.594840, 0.589554}}) {
    CAPTURE(ref.t_over_L);
    LimitOptions o;
    o.weight = WeightModel::axis;
    const SpreadOptions spread_options;
    const SpreadResult r = analyse_spreading(paper_scene(0.5, ref.t_over_L), o, spread_options);
    CAPTURE(r.message);
    REQUIRE(r.status == SpreadStatus::success);
    CHECK(close(spread_capacity_ratio(r, spread_options), ref.capacity, kSpreadCapacityTolerance));
    CHECK(close(r.path.back().H / r.path.back().V_left, ref.H_over_V_collapse, kHaunchJoint));
  }
}

TEST_CASE("spreading: the equilateral arch with the true voussoir weight converges on the independent reference") {
  // benchmarks/spreading_pointed/spread_check.py --weight voussoir at t = 0.075 L: each voussoir's true
  // weight at its centroid (annular sectors, and the crown wedge under the extrados), 2000 equal
  // voussoirs per half and a joint at each grazing point: capacity 0.237987, H/V 0.188556 at d = 0 and
  // 0.342476 at collapse (4000 and 8000 voussoirs: 0.238054 and 0.238020). On 801 starting joints a
  // joint the refinement had put 8e-6 L from the intrados' grazing point stood beside the one put
  // there, the least-thrust line touching both: the state at d = 0 changed on every finer ring.
  constexpr double kHaunchJoint = 1e-4;  // H/V follows where the haunch hinge's joint is (as above)
  for (const int joints : {201, 801}) {
    CAPTURE(joints);
    LimitOptions o;
    o.weight = WeightModel::voussoir;
    o.joints_count = joints;
    const SpreadOptions spread_options;
    const SpreadResult r = analyse_spreading(paper_scene(0.5, 0.075), o, spread_options);
    CAPTURE(r.message);
    REQUIRE(r.status == SpreadStatus::success);
    CHECK(close(spread_capacity_ratio(r, spread_options), 0.237987, kSpreadCapacityTolerance));
    CHECK(close(r.path.front().H / r.path.front().V_left, 0.188556, kHaunchJoint));
    CHECK(close(r.path.back().H / r.path.back().V_left, 0.342476, kHaunchJoint));
    CHECK(r.path.front().hinges.size() == 4);
  }
}

TEST_CASE("spreading: the semicircle whose springing settles by three times its spread converges whatever the joints") {
  // The state at d = 0 is the least-work one, not limit's least-thrust one (the line leans towards the
  // left springing, a hinge at the settling springing's extrados): the joints put where that line grazes
  // the intrados give the same capacity from 201 and 1601 starting joints (docs/spreading.md).
  std::vector<double> capacities;
  for (const int joints : {201, 1601}) {
    CAPTURE(joints);
    LimitOptions o;
    o.weight = WeightModel::axis;
    o.joints_count = joints;
    SpreadOptions s;
    s.left_share = 0;
    s.right_settlement_share = 3;
    const SpreadResult r = analyse_spreading(paper_scene(0.0, 0.075), o, s);
    CAPTURE(r.message);
    REQUIRE(r.status == SpreadStatus::success);
    CHECK(r.path.front().V_right < r.path.front().V_left);  // the settling springing sheds load
    for (const SpreadStep& step : r.path) CHECK(close(step.H, step.H_work, kStaticKinematic));
    capacities.push_back(spread_capacity_ratio(r, s));
  }
  CHECK(close(capacities[0], capacities[1], kSpreadCapacityTolerance));
}
