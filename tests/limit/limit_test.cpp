// The limit analysis (include/ogive/limit/limit.hpp) on its invariants: the thrust range and t_min
// against the thickness, the static collapse load factor against the kinematic one of its own hinges,
// mirror images, convergence in the joints, friction, misuse, whole curves of their own, live loads,
// fills by hand statics, and pins.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "limit/limit_internal.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The static and kinematic multipliers of one mechanism are the same number computed twice: they agree
// to round-off.
constexpr double kVirtualWork = 1e-6;
// H_min and H_max just above the t_min the root-finder returns (the feasible end of a bracket of
// relative width 1e-10, or a last step below it): the range has closed to this relative width.
constexpr double kRangeAtMinimum = 1e-5;
// The convergence the joints are refined to (kLimitTolerance, limit.hpp).
constexpr double kConverged = kLimitTolerance;

constexpr double kGamma = 2348.0 * 9.81;  // the scenes' unit weight, N/m^3

LimitResult analyse(double eps, double t_over_L, LimitOptions o = {}) { return analyse_limit(paper_scene(eps, t_over_L), o); }

// t_min is the feasible end of a bracket of relative width 1e-10 (analyse_limit): two computations of
// the same root (round-off apart in their margins) agree to a few times that.
constexpr double kRootFinder = 1e-9;
// Two rings that are the same up to round-off (a curve and its mirror image, a half and its whole
// arch): the LPs' answers agree to the LP's feasibility tolerance (1e-11 of the load scale) and a
// little more.
constexpr double kSameRing = 1e-9;

// A whole circular arch with springings at different heights: the arc of radius R from the angle phi0
// (left springing, at the origin) down to phi1 < phi0 (right springing), angles measured at the centre
// from the horizontal. Its crown is the top of the circle (phi = pi/2). A test-only whole curve.
class TiltedArc final : public Curve {
 public:
  TiltedArc(double R, double phi0, double phi1) : R_(R), phi0_(phi0), phi1_(phi1) {
    arc_ = {0.0, length(), 0.0, 0.0, phi0 - std::numbers::pi / 2, -1.0 / R};
  }
  CurveExtent extent() const override { return CurveExtent::whole; }
  std::string family() const override { return "tilted-arc"; }
  double span() const override { return R_ * (std::cos(phi1_) - std::cos(phi0_)); }
  double length() const override { return R_ * (phi0_ - phi1_); }
  CurvePoint at(double s) const override {
    const double phi = phi0_ - s / R_;
    return {R_ * (std::cos(phi) - std::cos(phi0_)), R_ * (std::sin(phi) - std::sin(phi0_)), phi - std::numbers::pi / 2,
            -1.0 / R_};
  }
  std::span<const CircularArc> arcs() const override { return {&arc_, 1}; }
  double crown() const override { return R_ * (phi0_ - std::numbers::pi / 2); }
  double right_springing_height() const override { return R_ * (std::sin(phi1_) - std::sin(phi0_)); }
  double max_curvature() const override { return 1.0 / R_; }
  // The same arch seen from behind: its mirror image, the left springing at the origin again.
  std::shared_ptr<const Curve> mirrored() const {
    return std::make_shared<TiltedArc>(R_, std::numbers::pi - phi1_, std::numbers::pi - phi0_);
  }

 private:
  double R_, phi0_, phi1_;
  CircularArc arc_;
};

Scene scene_of(std::shared_ptr<const Curve> curve, double thickness) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = thickness;
  return s;
}

void check_same_result(const LimitResult& a, const LimitResult& b) {
  REQUIRE(a.status == LimitStatus::success);
  REQUIRE(b.status == LimitStatus::success);
  CHECK(close(a.H_min(), b.H_min(), kSameRing));
  CHECK(close(a.H_max(), b.H_max(), kSameRing));
  CHECK(close(a.V, b.V, kSameRing));
  CHECK(close(a.thickness_min, b.thickness_min, kRootFinder));
  if (!std::isnan(a.load_factor()) || !std::isnan(b.load_factor())) CHECK(close(a.load_factor(), b.load_factor(), kSameRing));
}

// Every state's resultant crosses each joint between its faces, and the reactions balance the loads.
void check_state_inside(const Ring& ring, const ThrustState& st) {
  REQUIRE(st.crossing.size() == ring.joints.size());
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const Eigen::Vector2d d = ring.joints[j].extrados - ring.joints[j].intrados;
    const double u = (st.crossing[j] - ring.joints[j].intrados).dot(d) / d.squaredNorm();
    CHECK(u >= -1e-9);
    CHECK(u <= 1 + 1e-9);
  }
  const double live = std::isnan(st.load_factor) ? 0.0 : st.load_factor * ring.total_live();
  CHECK(close(st.V_left + st.V_right, ring.total_dead() + live, kExact));
}

}  // namespace

TEST_CASE("limit: H_min <= H_max, H_min falls and H_max rises with thickness, both meet at t_min") {
  for (double eps : {0.0, 0.25, 0.5, 1.0, 1.5}) {
    CAPTURE(eps);
    double last_min = INFINITY, last_max = 0, t_min = 0;
    for (double t : {0.07, 0.08, 0.10, 0.15, 0.20}) {
      CAPTURE(t);
      const LimitResult r = analyse(eps, t);
      REQUIRE(r.status == LimitStatus::success);
      CHECK(r.H_min() <= r.H_max());
      CHECK(r.H_min() / r.V < last_min);
      CHECK(r.H_max() / r.V > last_max);
      last_min = r.H_min() / r.V;
      last_max = r.H_max() / r.V;
      // t_min does not depend on the thickness it is searched from, beyond the joints' refinement
      // (each thickness refines next to its own hinges).
      if (t_min == 0) t_min = r.thickness_min;
      CHECK(close(r.thickness_min, t_min, kConverged));
    }
    // Just above t_min the range closes: on its own refined ring, H_min = H_max there, or that ring's
    // t_min lies a little higher (within the refinement's tolerance) and the arch is inadmissible.
    Scene at_min = paper_scene(eps);
    at_min.thickness = t_min * (1 + 1e-9);
    const LimitResult m = analyse_limit(at_min, {});
    if (m.status == LimitStatus::success) {
      CHECK(close(m.H_min(), m.H_max(), kRangeAtMinimum));
    } else {
      CHECK(m.status == LimitStatus::inadmissible);
      CHECK(m.thickness_min > at_min.thickness);
      CHECK(close(m.thickness_min, t_min, kConverged));
    }
    // Below t_min by more than the refinement's tolerance nothing stands, and the row says so with t_min.
    at_min.thickness = t_min * (1 - 10 * kConverged);
    const LimitResult below = analyse_limit(at_min, {});
    CHECK(below.status == LimitStatus::inadmissible);
    CHECK(std::isnan(below.H_min()));
    CHECK(close(below.thickness_min, t_min, kConverged));
  }
}

TEST_CASE("limit: the static collapse load factor equals the virtual-work multiplier of its own hinges") {
  for (double eps : {0.0, 0.5, 1.0})
    for (double a : {0.1, 0.25, 0.4}) {
      CAPTURE(eps);
      CAPTURE(a);
      Scene scene = paper_scene(eps, 0.12);
      scene.loads.points.push_back({5e4, a});
      const LimitResult r = analyse_limit(scene, {});
      REQUIRE(r.status == LimitStatus::success);
      // Four hinges, or more at a degenerate optimum (two adjacent joints touched along a face's chord).
      REQUIRE(r.collapse_state.hinges.size() >= 4);
      CHECK(r.load_factor() > 1);  // the arch carries the load itself, so it collapses beyond it
      CHECK(close(r.load_factor(), r.load_factor_mechanism, kVirtualWork));
      // Another mechanism (hinges moved by a joint) is an upper bound: the kinematic theorem.
      std::vector<Hinge> moved = r.collapse_state.hinges;
      const Ring& ring = r.ring;
      const int j = moved[1].joint + 3;
      moved[1] = {j, moved[1].face, moved[1].face == Face::intrados ? ring.joints[j].intrados : ring.joints[j].extrados};
      CHECK(mechanism_load_factor(ring, moved) > r.load_factor());
    }
}

TEST_CASE("limit: a point load at a and one at 1 - a give mirrored hinges and the same load factor") {
  for (double a : {0.1, 0.3, 0.45}) {
    CAPTURE(a);
    Scene left = paper_scene(0.25, 0.12), right = left;
    left.loads.points.push_back({1.5e5, a});
    right.loads.points.push_back({1.5e5, 1.0 - a});
    const LimitResult l = analyse_limit(left, {}), r = analyse_limit(right, {});
    REQUIRE(l.status == LimitStatus::success);
    REQUIRE(r.status == LimitStatus::success);
    CHECK(close(l.load_factor(), r.load_factor(), 1e-9));
    CHECK(close(l.H_min(), r.H_min(), 1e-9));
    CHECK(close(l.H_max(), r.H_max(), 1e-9));
    // The reactions swap sides.
    CHECK(close(l.min_state.V_left, r.min_state.V_right, 1e-9));
    REQUIRE(l.collapse_state.hinges.size() == r.collapse_state.hinges.size());
    REQUIRE(l.ring.joints.size() == r.ring.joints.size());
    const int last = static_cast<int>(l.ring.joints.size()) - 1;
    const std::size_t n = l.collapse_state.hinges.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Hinge &h = l.collapse_state.hinges[i], &m = r.collapse_state.hinges[n - 1 - i];
      CHECK(h.joint == last - m.joint);
      CHECK(h.face == m.face);
      CHECK(std::abs(h.point.x() - (10.0 - m.point.x())) <= kExact * 10.0);
    }
  }
}

TEST_CASE("limit: the numbers are converged in the joints to 1e-4 from any starting count") {
  for (double eps : {0.0, 0.5, 1.5}) {
    CAPTURE(eps);
    std::vector<LimitResult> runs;
    for (int n : {51, 201, kDefaultJointsCount, 30 * (kDefaultJointsCount - 1) + 1}) {
      LimitOptions o;
      o.joints_count = n;
      runs.push_back(analyse(eps, 0.10, o));
      REQUIRE(runs.back().status == LimitStatus::success);
    }
    const LimitResult& fine = runs.back();  // 30 times the default's joints, refined in turn
    for (std::size_t k = 0; k + 1 < runs.size(); ++k) {
      CAPTURE(k);
      CHECK(relative_difference(runs[k].H_min(), fine.H_min()) <= kConverged);
      CHECK(relative_difference(runs[k].H_max(), fine.H_max()) <= kConverged);
      CHECK(relative_difference(runs[k].thickness_min, fine.thickness_min) <= kConverged);
    }
  }
}

TEST_CASE("limit: friction: a generous coefficient changes nothing, a small one forbids the arch") {
  LimitOptions o;
  const LimitResult free = analyse(0.0, 0.15, o);
  o.friction = 10.0;
  const LimitResult rough = analyse(0.0, 0.15, o);
  REQUIRE(rough.status == LimitStatus::success);
  CHECK(close(rough.H_min(), free.H_min(), kExact));
  CHECK(close(rough.H_max(), free.H_max(), kExact));
  // The springing bed is horizontal: the support's H/V cannot exceed the friction coefficient, and the
  // semicircle needs H/V >= 0.235 at t = 0.15 L.
  o.friction = 0.2;
  const LimitResult smooth = analyse(0.0, 0.15, o);
  CHECK(smooth.status == LimitStatus::inadmissible);
  o.friction = 0.5;
  const LimitResult between = analyse(0.0, 0.15, o);
  REQUIRE(between.status == LimitStatus::success);
  CHECK(close(between.H_min(), free.H_min(), kExact));
  CHECK(between.H_max() / between.V <= 0.5 * (1 + kExact));
}

TEST_CASE("limit: misuse throws naming the field") {
  LimitOptions o;
  o.joints_count = 4;
  CHECK_THROWS_WITH_AS(analyse(0.0, 0.1, o), doctest::Contains("joints_count"), std::invalid_argument);
  Scene outside = paper_scene(0.0, 0.1);
  outside.loads.points.push_back({1e5, 1.2});
  CHECK_THROWS_WITH_AS(analyse_limit(outside, {}), doctest::Contains("point_load_at"), std::invalid_argument);
  // Density 0 and a fill that lies below the extrados everywhere: nothing loads the ring.
  Scene empty = paper_scene(0.0, 0.1);
  empty.material.density = 0;
  empty.loads.fills.push_back({1800.0, 0.01});
  CHECK_THROWS_WITH_AS(analyse_limit(empty, {}), doctest::Contains("fill_height_ratio"), std::invalid_argument);
  // Just below the extrados' height over the springings (sqrt(0.55^2 - 0.5^2) L = 0.229 L at t = 0.1 L):
  // the same; just above, the fill loads the springers alone, and the ring is solved (the weightless
  // voussoirs between carry no force: they stand with H = 0).
  empty.loads.fills.front().height_ratio = 0.228;
  CHECK_THROWS_WITH_AS(analyse_limit(empty, {}), doctest::Contains("fill_height_ratio"), std::invalid_argument);
  empty.loads.fills.front().height_ratio = 0.24;
  const LimitResult springers = analyse_limit(empty, {});
  CHECK(springers.status == LimitStatus::success);
  CHECK(springers.H_min() == 0.0);
  CHECK(std::abs(springers.H_max()) <= 1e-12 * springers.V);
  // Where the thrust vanishes its crossing is undefined: no hinge there, and no margin to search t_min
  // by (the margin is zero at every thickness that stands, its sign the round-off's).
  CHECK(springers.min_state.forceless);
  CHECK(springers.min_state.hinges.empty());
  CHECK(std::isnan(springers.thickness_min));
  CHECK(springers.message.find("vanishes") != std::string::npos);
  o = {};
  o.friction = -0.1;
  CHECK_THROWS_WITH_AS(analyse(0.0, 0.1, o), doctest::Contains("friction"), std::invalid_argument);
}

TEST_CASE("limit: a symmetric scene given as a whole curve (whole_arch of the half) gives the half's numbers") {
  for (double eps : {0.0, 0.5})
    for (JointOrientation j : {JointOrientation::radial, JointOrientation::vertical})
      for (double a : {-1.0, 0.3}) {  // no point load, then one off the centre
        CAPTURE(eps);
        CAPTURE(a);
        CAPTURE(to_string(j));
        LimitOptions o;
        o.joints = j;
        Scene half = paper_scene(eps, 0.12);
        if (a > 0) half.loads.points.push_back({1e5, a});
        Scene whole = half;
        whole.curve = whole_arch(half.curve);
        check_same_result(analyse_limit(half, o), analyse_limit(whole, o));
      }
}

TEST_CASE("limit: a whole curve of its own: the tilted semicircle (phi 180 -> 0 degrees) is the semicircle") {
  const auto own = std::make_shared<TiltedArc>(5.0, std::numbers::pi, 0.0);
  for (double a : {-1.0, 0.3}) {
    CAPTURE(a);
    Scene semicircle = paper_scene(0.0, 0.12), whole = scene_of(own, 1.2);
    if (a > 0) {
      semicircle.loads.points.push_back({1e5, a});
      whole.loads.points.push_back({1e5, a});
    }
    check_same_result(analyse_limit(semicircle, {}), analyse_limit(whole, {}));
  }
}

TEST_CASE("limit: an asymmetric whole arch (springings at different heights) and its mirror image give the same numbers and mirrored hinges") {
  // A circle of radius 5 m from its left end (180 degrees, a vertical springing) to 30 degrees above the
  // horizontal through the centre on the right: the right springing 2.5 m higher.
  const auto tilted = std::make_shared<TiltedArc>(5.0, std::numbers::pi, std::numbers::pi / 6);
  const auto behind = tilted->mirrored();
  const double L = tilted->span(), rise_right = tilted->right_springing_height();
  CHECK(close(behind->span(), L, kExact));
  CHECK(close(rise_right, 2.5, kExact));
  const double a = 0.3, fill_level = 6.0;  // m above the original left springing
  Scene front = scene_of(tilted, 0.15 * L), back = scene_of(behind, 0.15 * L);
  front.loads.points.push_back({1e5, a});
  back.loads.points.push_back({1e5, 1.0 - a});
  // The fill's level above each one's left springing: the mirrored arch's left springing is the higher one.
  front.loads.fills.push_back({1800.0, fill_level / L});
  back.loads.fills.push_back({1800.0, (fill_level - rise_right) / L});
  const LimitResult f = analyse_limit(front, {}), b = analyse_limit(back, {});
  check_same_result(f, b);
  const Ring ring_f = make_ring(front, {}), ring_b = make_ring(back, {});
  CHECK(close(ring_f.total_fill(), ring_b.total_fill(), kExact));
  CHECK(ring_f.total_fill() > 0);
  // The crown joint is vertical through the top of the circle.
  const Joint& crown = ring_f.joints[ring_f.crown_joint()];
  CHECK(std::abs(crown.axis.x() - tilted->at(tilted->crown()).x) <= kExact * L);
  CHECK(std::abs(crown.intrados.x() - crown.extrados.x()) <= kExact * L);
  for (const ThrustState* st : {&f.min_state, &f.max_state, &f.collapse_state}) check_state_inside(f.ring, *st);
  CHECK(close(f.load_factor(), f.load_factor_mechanism, kVirtualWork));
  CHECK(close(f.min_state.V_left, b.min_state.V_right, kSameRing));
  REQUIRE(f.ring.joints.size() == b.ring.joints.size());
  const int last = static_cast<int>(f.ring.joints.size()) - 1;
  const std::size_t n = f.collapse_state.hinges.size();
  REQUIRE(n == b.collapse_state.hinges.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Hinge &h = f.collapse_state.hinges[i], &m = b.collapse_state.hinges[n - 1 - i];
    CHECK(h.joint == last - m.joint);
    CHECK(h.face == m.face);
  }
}

TEST_CASE("limit: a live load over half the span: the static load factor equals the mechanism's by virtual work") {
  for (double eps : {0.0, 0.5})
    for (WeightModel w : {WeightModel::voussoir, WeightModel::axis}) {
      CAPTURE(eps);
      CAPTURE(to_string(w));
      LimitOptions o;
      o.weight = w;
      Scene scene = paper_scene(eps, 0.12);
      scene.loads.live.push_back({2e4, 0.0, 0.5});
      const LimitResult r = analyse_limit(scene, o);
      REQUIRE(r.status == LimitStatus::success);
      REQUIRE(r.collapse_state.hinges.size() >= 4);
      CHECK(r.load_factor() > 1);
      CHECK(close(r.load_factor(), r.load_factor_mechanism, kVirtualWork));
      // The ring carries the whole live load q L / 2, on the loaded half.
      const Ring ring = make_ring(scene, o);
      CHECK(close(ring.total_live(), 2e4 * 5.0, kExact));
      for (std::size_t k = ring.voussoirs.size() / 2; k < ring.voussoirs.size(); ++k)
        CHECK(ring.voussoirs[k].live.force == 0.0);
      CHECK(close(r.V, 0.5 * (ring.total_weight() + 2e4 * 5.0), kExact));
    }
}

TEST_CASE("limit: the fill's weight is the integral of rho_f g (h_f - y_extrados) over the span, fill raises H_min of the semicircle and lowers its t_min") {
  const double L = 10.0, R = 5.0, t = 1.5, r = R + 0.5 * t, rho_f = 1800.0, g = 9.81;
  // Closed form of int_0^L max(0, h - y_e(x)) dx with y_e = sqrt(r^2 - u^2), u = x - L/2: the
  // extrados of the true ring over the whole span (r > L/2).
  auto F = [&](double u) { return 0.5 * (u * std::sqrt(r * r - u * u) + r * r * std::asin(u / r)); };
  auto exact = [&](double h) {
    if (h >= r) return rho_f * g * (h * L - (F(L / 2) - F(-L / 2)));
    const double u_star = std::sqrt(r * r - h * h);  // y_e = h there; the fill lies beyond |u| > u_star
    return rho_f * g * 2.0 * (h * (L / 2 - u_star) - (F(L / 2) - F(u_star)));
  };
  for (double h : {0.7 * L, 0.4 * L}) {
    CAPTURE(h);
    // Both weight models carry the fill of the true extrados: over its stretches, or over the axis'.
    for (auto [j, w] : {std::pair{JointOrientation::radial, WeightModel::voussoir},
                        std::pair{JointOrientation::vertical, WeightModel::voussoir},
                        std::pair{JointOrientation::radial, WeightModel::axis}}) {
      LimitOptions o;
      o.joints = j;
      o.weight = w;
      Scene scene = paper_scene(0.0, t / L);
      scene.loads.fills.push_back({rho_f, h / L});
      const Ring ring = make_ring(scene, o);
      CHECK(close(ring.total_fill(), exact(h), kExact));
      // Symmetric: its resultant acts at mid-span.
      double moment = 0;
      for (const Voussoir& v : ring.voussoirs) moment += v.fill.moment;
      CHECK(close(moment, 0.5 * L * ring.total_fill(), kExact));
    }
  }
  // H_min by hand: the symmetric state through the crown's extrados and an intrados haunch hinge; the
  // part between joint j and the crown turns about the intrados point I_j, so H (E_c,y - I_j,y) >= the
  // moment of its loads about I_j, and H_min is the largest such bound (an independent statics of the
  // ring's loads, without the LP).
  auto by_hand = [](const Ring& ring) {
    const int c = ring.crown_joint();
    double H = 0;
    for (int j = 0; j < c; ++j) {
      double moment = 0;
      for (int k = j; k < c; ++k) {
        const VerticalLoad d = ring.voussoirs[k].dead();
        moment += d.moment - d.force * ring.joints[j].intrados.x();
      }
      H = std::max(H, moment / (ring.joints[c].extrados.y() - ring.joints[j].intrados.y()));
    }
    return H;
  };
  // The fill stabilises the haunches: a thinner arch stands under any level of it. Over the crown
  // (h_f = 0.6 L, 0.7 L) it loads the central part and raises H_min; a fill of the haunches alone
  // (h_f = 0.5 L < the crown's extrados, 0.575 L) lies on the central part's extrados only outboard of
  // its intrados hinges (radial joints: the extrados end of the hinge joint is 1.3 m outboard of its
  // intrados end) and, resisting the mechanism, lowers H_min slightly: both by the hand statics too.
  const Scene bare = paper_scene(0.0, 0.15);
  const LimitResult b = analyse_limit(bare, {});
  REQUIRE(b.status == LimitStatus::success);
  CHECK(close(b.H_min(), by_hand(b.ring), kExact));
  for (double h : {0.3, 0.5, 0.6, 0.7}) {
    CAPTURE(h);
    Scene filled = bare;
    filled.loads.fills.push_back({rho_f, h});
    const LimitResult f = analyse_limit(filled, {});
    REQUIRE(f.status == LimitStatus::success);
    CHECK(close(f.H_min(), by_hand(f.ring), kExact));
    CHECK(f.thickness_min < b.thickness_min);
    if (h >= 0.6) CHECK(f.H_min() > b.H_min());
    if (h == 0.5) CHECK(f.H_min() < b.H_min());
    CHECK(std::isnan(f.load_factor()));  // the fill is dead: no load factor
  }
}

TEST_CASE("limit: the crown hinge is a pin: every state's thrust line passes through the crown's axis point") {
  for (double eps : {0.0, 0.5}) {
    CAPTURE(eps);
    Scene scene = paper_scene(eps, 0.12);
    scene.crown_hinge = true;
    scene.loads.points.push_back({1e5, 0.3});
    const LimitResult r = analyse_limit(scene, {});
    REQUIRE(r.status == LimitStatus::success);
    const Ring& ring = r.ring;
    const int c = ring.crown_joint();
    const Eigen::Vector2d pin = ring.joints[c].axis;
    CHECK(std::abs(pin.x() - 5.0) <= kExact * 10.0);
    for (const ThrustState* st : {&r.min_state, &r.max_state, &r.collapse_state}) {
      REQUIRE(st->found());
      CHECK((st->crossing[c] - pin).norm() <= 1e-9 * 10.0);
      check_state_inside(ring, *st);
      const auto it = std::find_if(st->hinges.begin(), st->hinges.end(), [&](const Hinge& h) { return h.joint == c; });
      REQUIRE(it != st->hinges.end());
      CHECK(it->face == Face::axis);
    }
    // The pin narrows the range: the thrust range of the hingeless arch contains the pinned one's (each
    // on its own refined ring: to the refinement's tolerance).
    Scene free = scene;
    free.crown_hinge = false;
    const LimitResult u = analyse_limit(free, {});
    CHECK(r.H_min() >= u.H_min() * (1 - kConverged));
    CHECK(r.H_max() <= u.H_max() * (1 + kConverged));
    CHECK(r.load_factor() <= u.load_factor() * (1 + kConverged));
    // The mechanism through the pin (which turns either way) gives the same factor by virtual work.
    CHECK(close(r.load_factor(), r.load_factor_mechanism, kVirtualWork));
  }
}

TEST_CASE("limit: the three-hinged semicircle (pinned springings, crown hinge) is statically determinate: H = W/2 (1 - d/R)") {
  const double R = 5.0, t = 1.5, r_in = R - t / 2, r_out = R + t / 2;
  Scene scene = paper_scene(0.0, t / 10.0);
  scene.crown_hinge = true;
  scene.left.kind = scene.right.kind = SupportKind::pinned;
  const LimitResult r = analyse_limit(scene, {});
  REQUIRE(r.status == LimitStatus::success);
  // The half ring weighs W/2 = gamma t pi R / 2 at d = 4 (r_out^3 - r_in^3) / (3 pi (r_out^2 - r_in^2))
  // from the centre line; moments of the left half about the crown pin (R, R): H R = V R - (W/2) d.
  const double half_weight = 0.5 * kGamma * t * std::numbers::pi * R;
  const double d = 4.0 * (std::pow(r_out, 3) - std::pow(r_in, 3)) / (3.0 * std::numbers::pi * (r_out * r_out - r_in * r_in));
  const double H = half_weight * (1.0 - d / R);
  CHECK(close(r.H_min(), H, kSameRing));
  CHECK(close(r.H_max(), H, kSameRing));
  REQUIRE(r.min_state.hinges.size() == 3);
  for (const Hinge& h : r.min_state.hinges) CHECK(h.face == Face::axis);
}

TEST_CASE("limit: an analysis does not depend on the analyses its thread made before") {
  // Each thread keeps its work areas (rings, programs, the bands and bases a finer ring reuses) from
  // one analysis to the next: what it keeps of another scene must not reach this one.
  Scene a = paper_scene(0.5, 0.1);
  a.loads.points.push_back({2e4, 0.3});
  Scene b = scene_of(make_parabolic(10.0, 0.4), 0.9);
  b.loads.fills.push_back({1800.0, 0.3});
  LimitResult fresh, after;
  std::thread([&] { fresh = analyse_limit(a, {}); }).join();
  std::thread([&] {
    (void)analyse_limit(b, {});
    (void)analyse_limit(paper_scene(0.5, 0.12), {});
    after = analyse_limit(a, {});
  }).join();
  CHECK(after.status == fresh.status);
  CHECK(after.H_min() == fresh.H_min());
  CHECK(after.H_max() == fresh.H_max());
  CHECK(after.thickness_min == fresh.thickness_min);
  CHECK(after.load_factor() == fresh.load_factor());
  CHECK(after.lp_solves == fresh.lp_solves);
  CHECK(after.ring.joints.size() == fresh.ring.joints.size());
}

TEST_CASE("limit: under a horizontal acceleration a the three-hinged semicircle is statics: H_left = W/2 (1 - d/R - a)") {
  // As above, each half ring's weight W/2 acts at its centroid (R -+ d, d) from the left springing's
  // pin, and a W/2 horizontally at the same points. Moments about the right pin: V_left = W/2 - a W d /
  // (2R); of the left half about the crown pin (R, R): R H_left = R V_left - (W/2) d - a (W/2) (R - d),
  // so H_left = (W/2) (1 - d/R - a), whatever the joints.
  const double R = 5.0, t = 1.5, r_in = R - t / 2, r_out = R + t / 2;
  const double d = 4.0 * (std::pow(r_out, 3) - std::pow(r_in, 3)) / (3.0 * std::numbers::pi * (r_out * r_out - r_in * r_in));
  const double half_weight = 0.5 * kGamma * t * std::numbers::pi * R;
  // (Beyond |a| = 0.1 or so the statically determined thrust line leaves this ring: inadmissible.)
  for (double a : {-0.1, 0.05, 0.1}) {
    Scene scene = paper_scene(0.0, t / 10.0);
    scene.crown_hinge = true;
    scene.left.kind = scene.right.kind = SupportKind::pinned;
    scene.horizontal_acceleration = a;
    const LimitResult r = analyse_limit(scene, {});
    CAPTURE(a);
    REQUIRE(r.status == LimitStatus::success);
    const double H = half_weight * (1.0 - d / R - a);
    CHECK(std::abs(r.H_min() - H) <= kSameRing * half_weight);
    CHECK(std::abs(r.H_max() - H) <= kSameRing * half_weight);
    CHECK(std::abs(r.min_state.V_left - (half_weight - a * 2 * half_weight * d / (2 * R))) <= kSameRing * half_weight);
  }
}

TEST_CASE("limit: a horizontal acceleration thickens the thinnest arch, the same either way, and a = 0 is the vertical analysis") {
  // The semicircle (radial joints): t_min rises with |a| (Alexakis & Makris' tables), -a is the mirror
  // image of a, and a = 0 gives the analysis without the option, number for number.
  const LimitResult still = analyse(0.0, 0.15);
  Scene zero = paper_scene(0.0, 0.15);
  zero.horizontal_acceleration = 0.0;
  const LimitResult same = analyse_limit(zero, {});
  CHECK(same.thickness_min == still.thickness_min);
  CHECK(same.H_min() == still.H_min());
  double previous = still.thickness_min;
  for (double a : {0.05, 0.1, 0.2}) {
    Scene plus = paper_scene(0.0, 0.15), minus = plus;
    plus.horizontal_acceleration = a;
    minus.horizontal_acceleration = -a;
    const LimitResult p = analyse_limit(plus, {}), m = analyse_limit(minus, {});
    CAPTURE(a);
    REQUIRE(p.status == LimitStatus::success);
    REQUIRE(m.status == LimitStatus::success);
    CHECK(p.thickness_min > previous);
    // Each converged in the joints to kConverged, on rings refined next to mirrored hinges.
    CHECK(close(p.thickness_min, m.thickness_min, kConverged));
    // The mirror image: a state under -a is the mirror of one under a, whose left thrust is the other's
    // right thrust, H_left + a W (W the weight): so H_min(-a) = H_min(a) + a W, and the same for H_max.
    const double W = 2 * p.V;
    CHECK(std::abs(m.H_min() - (p.H_min() + a * W)) <= kConverged * W);
    CHECK(std::abs(m.H_max() - (p.H_max() + a * W)) <= kConverged * W);
    previous = p.thickness_min;
  }
}

TEST_CASE("limit: under a horizontal acceleration the collapse load factor is its mechanism's (static = kinematic)") {
  // The virtual work of the collapse mechanism counts the horizontal dead loads too: without them the
  // kinematic multiplier would differ from the LP's.
  for (double a : {-0.05, 0.05}) {
    Scene scene = paper_scene(0.5, 0.15);
    scene.loads.points.push_back({2e5, 0.25});
    scene.horizontal_acceleration = a;
    const LimitResult r = analyse_limit(scene, {});
    CAPTURE(a);
    REQUIRE(r.status == LimitStatus::success);
    REQUIRE(r.collapse_state.hinges.size() == 4);
    CHECK(close(r.load_factor(), r.load_factor_mechanism, kVirtualWork));
  }
}

namespace {

LimitResult shaken_analysis(double eps, double t_over_L, JointOrientation joints = JointOrientation::radial,
                            int joints_count = kDefaultJointsCount) {
  LimitOptions o;
  o.joints = joints;
  o.joints_count = joints_count;
  o.horizontal_load_factor = true;
  return analyse_limit(paper_scene(eps, t_over_L), o);
}

// Relative difference of accelerations, against 1 % of g at least (a_c vanishes at t_min).
double acceleration_gap(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 0.01}); }

}  // namespace

TEST_CASE("limit: the collapse acceleration a_c is 0 at t_min, rises about linearly above, and static = kinematic") {
  // Semicircle, radial joints: t_min / R = 0.1075 (Milankovitch), t/L = t/(2R).
  const LimitResult at_min = shaken_analysis(0.0, 0.15);
  REQUIRE(at_min.status == LimitStatus::success);
  const double t_min = at_min.thickness_min / 10.0;  // t/L
  CHECK(std::abs(2 * t_min - 0.1075) <= 5e-4);
  const LimitResult just_above = shaken_analysis(0.0, t_min * (1 + 1e-6));
  REQUIRE(just_above.status == LimitStatus::success);
  CHECK(just_above.horizontal_load_factor() >= 0.0);
  CHECK(just_above.horizontal_load_factor() <= 1e-4);
  // Above it: increments of a_c over equal steps of t differ by a fifth at most.
  std::vector<double> a_c;
  for (double f : {1.2, 1.4, 1.6}) {
    const LimitResult r = shaken_analysis(0.0, t_min * f);
    REQUIRE(r.status == LimitStatus::success);
    a_c.push_back(r.horizontal_load_factor());
    // The virtual work of the mechanism through the static solution's hinges gives the same a_c.
    CHECK(close(r.horizontal_load_factor(), r.horizontal_load_factor_mechanism, 1e-9));
    CHECK(r.horizontal_state.hinges.size() == 4);
  }
  CHECK(a_c[0] > 0);
  CHECK(a_c[1] > a_c[0]);
  CHECK(std::abs((a_c[2] - a_c[1]) - (a_c[1] - a_c[0])) <= 0.2 * (a_c[1] - a_c[0]));
  // Below t_min the arch cannot stand its own weight: no a_c.
  CHECK(std::isnan(shaken_analysis(0.0, t_min * 0.95).horizontal_load_factor()));
}

TEST_CASE("limit: vertical joints give a lower a_c than radial ones for the semicircle (Alexakis & Makris)") {
  for (double t_over_L : {0.08, 0.15}) {
    const LimitResult radial = shaken_analysis(0.0, t_over_L);
    const LimitResult vertical = shaken_analysis(0.0, t_over_L, JointOrientation::vertical);
    CAPTURE(t_over_L);
    REQUIRE(radial.status == LimitStatus::success);
    REQUIRE(vertical.status == LimitStatus::success);
    CHECK(vertical.horizontal_load_factor() < radial.horizontal_load_factor());
  }
  // The thinnest semicircle with vertical joints: t_min / R = 0.1095 (Makris & Alexakis).
  CHECK(std::abs(2 * shaken_analysis(0.0, 0.15, JointOrientation::vertical).thickness_min / 10.0 - 0.1095) <= 5e-4);
}

TEST_CASE("limit: every admissible four-hinge mechanism on a coarse grid gives at least a_c (kinematic theorem)") {
  for (double eps : {0.0, 0.5}) {
    const LimitResult r = shaken_analysis(eps, 0.12);
    REQUIRE(r.status == LimitStatus::success);
    const double a_c = r.horizontal_load_factor();
    const Ring& ring = r.ring;
    // Every 16th joint, and each hinge on either face: the mechanisms a coarse search would try.
    std::vector<int> grid;
    for (int j = 0; j < static_cast<int>(ring.joints.size()); j += 16) grid.push_back(j);
    grid.push_back(static_cast<int>(ring.joints.size()) - 1);
    auto hinge = [&](int j, int face) {
      const Joint& joint = ring.joints[static_cast<std::size_t>(j)];
      return face == 0 ? Hinge{j, Face::intrados, joint.intrados} : Hinge{j, Face::extrados, joint.extrados};
    };
    int admissible = 0;
    for (std::size_t a = 0; a < grid.size(); ++a)
      for (std::size_t b = a + 1; b < grid.size(); ++b)
        for (std::size_t c = b + 1; c < grid.size(); ++c)
          for (std::size_t d = c + 1; d < grid.size(); ++d)
            for (int faces = 0; faces < 16; ++faces) {
              const std::vector<Hinge> h = {hinge(grid[a], faces & 1), hinge(grid[b], (faces >> 1) & 1),
                                            hinge(grid[c], (faces >> 2) & 1), hinge(grid[d], (faces >> 3) & 1)};
              const double m = mechanism_horizontal_load_factor(ring, h);
              if (std::isnan(m) || m < 0) continue;  // not admissible, or the acceleration the other way
              ++admissible;
              CHECK(m >= a_c * (1 - 1e-9));
            }
    CAPTURE(eps);
    CHECK(admissible > 10);
  }
}

TEST_CASE("limit: a_c converges with the starting joints") {
  // The analysis refines next to the hinges until a_c moves by less than kLimitTolerance: from 41, 101
  // or 201 starting joints the same a_c to that.
  const LimitResult fine = shaken_analysis(0.5, 0.1);
  for (int count : {41, 101}) {
    const LimitResult coarse = shaken_analysis(0.5, 0.1, JointOrientation::radial, count);
    CAPTURE(count);
    REQUIRE(coarse.status == LimitStatus::success);
    CHECK(acceleration_gap(coarse.horizontal_load_factor(), fine.horizontal_load_factor()) <= 2 * kConverged);
  }
}

TEST_CASE("limit: a ring over a pointed crown with radial joints has the joint through the intrados' crown point") {
  // Beside the vertical crown joint, on each side: the radial joint that meets the intrados at the crown
  // (fraction 1). A smooth crown, or vertical joints, have no other joint through that point.
  LimitOptions o;
  o.joints_count = 21;
  const Ring pointed = make_ring(paper_scene(0.5, 0.15), o);
  const int c = pointed.crown_joint();
  CHECK(pointed.joints.size() == 23);
  CHECK(pointed.joint_fractions.back() == 1.0);
  for (int side : {-1, 1}) {
    const Joint& beside = pointed.joints[static_cast<std::size_t>(c + side)];
    CHECK((beside.intrados - pointed.joints[static_cast<std::size_t>(c)].intrados).norm() <= 1e-12 * pointed.span);
    CHECK(side * (beside.extrados.x() - pointed.joints[static_cast<std::size_t>(c)].extrados.x()) > 0);
    // The wedge between the two joints: its triangle and the sliver of ring between the triangle's
    // extrados side and the extrados arc (a few per cent of it at most here).
    const Voussoir& wedge = pointed.voussoirs[static_cast<std::size_t>(side < 0 ? c - 1 : c)];
    const Eigen::Vector2d a = beside.extrados - beside.intrados,
                          b = pointed.joints[static_cast<std::size_t>(c)].extrados - beside.intrados;
    const double triangle = 0.5 * std::abs(a.x() * b.y() - a.y() * b.x()) * 2348.0 * 9.81;
    CHECK(wedge.weight > triangle);
    CHECK(wedge.weight < 1.05 * triangle);
  }
  // Its own fractions given again build the same ring.
  const Ring again = limit_detail::make_ring_at(paper_scene(0.5, 0.15), o, pointed.joint_fractions);
  CHECK(again.joints.size() == pointed.joints.size());
  CHECK(make_ring(paper_scene(0.0, 0.15), o).joints.size() == 21);
  o.joints = JointOrientation::vertical;
  CHECK(make_ring(paper_scene(0.5, 0.15), o).joints.size() == 21);
}
