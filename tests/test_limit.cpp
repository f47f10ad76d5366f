// Limit analysis: published anchors, invariants of the static theorem, the ring's geometry, the CLI.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ogive/limit/limit.hpp"
#include "scenes.hpp"
#include "tolerances.hpp"

using namespace ogive;

namespace {

// A published value given to four decimals holds to half a unit of its last digit.
constexpr double kFourDecimals = 0.5e-4;
// Romano & Ochsendorf's ranges as the seed paper quotes them: two-decimal readings off graphic
// statics, with conventions (joints, weight) the quote does not state (the tolerance).
constexpr double kQuotedReading = 0.02;
// The static and kinematic multipliers of one mechanism are the same number computed twice (the
// issue's tolerance; they agree to round-off).
constexpr double kVirtualWork = 1e-6;
// H_min and H_max just above the t_min the root-finder returns (the feasible end of a bracket of
// relative width 1e-10, or a last step below it): the range has closed to this relative width.
constexpr double kRangeAtMinimum = 1e-5;
// The convergence that the default number of joints is chosen for (README's table).
constexpr double kConverged = 1e-4;

constexpr double kGamma = 2348.0 * 9.81;  // the scenes' unit weight, N/m^3

LimitResult analyse(double eps, double t_over_L, LimitOptions o = {}) { return analyse_limit(paper_scene(eps, t_over_L), o); }

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace

TEST_CASE("limit: semicircle, radial joints, true weight: t_min / R = 0.1075, intrados hinge 54.5 deg from the crown (Milankovitch 1907)") {
  const double R = 5.0;
  const LimitResult r = analyse(0.0, 0.15);
  REQUIRE(r.status == LimitStatus::success);
  CHECK(std::abs(r.thickness_min / R - 0.1075) <= kFourDecimals);
  // At t_min: the five-hinge mechanism; the haunch hinges on the intrados, at the published angle to
  // within one joint spacing.
  Scene at_min = paper_scene(0.0);
  at_min.thickness = r.thickness_min * (1 + 1e-9);  // just above: t_min is known to 1e-10
  const LimitResult m = analyse_limit(at_min, {});
  REQUIRE(m.status == LimitStatus::success);
  const double spacing = 180.0 / (kDefaultJointsCount - 1);
  int haunches = 0;
  for (const Hinge& h : m.min_state.hinges) {
    if (h.face != Face::intrados) continue;
    const double from_crown = degrees(std::atan2(std::abs(h.point.x() - R), h.point.y()));
    CHECK(std::abs(from_crown - 54.5) <= spacing);
    ++haunches;
  }
  CHECK(haunches == 2);
}

TEST_CASE("limit: semicircle, vertical joints: t_min / R = 0.1095 and H / (gamma t R) = 0.6218 at t_min (Makris & Alexakis 2013)") {
  const double R = 5.0;
  LimitOptions o;
  o.joints = JointOrientation::vertical;
  const LimitResult r = analyse(0.0, 0.15, o);
  REQUIRE(r.status == LimitStatus::success);
  CHECK(std::abs(r.thickness_min / R - 0.1095) <= kFourDecimals);
  // The thrust is published at the published t_min, t/R = 0.1095, where our range is still open by
  // 1.6e-4 (ours: t_min / R = 0.10946; at it H / (gamma t R) = 0.62174): 0.6218 must lie in it.
  Scene published = paper_scene(0.0);
  published.thickness = 0.1095 * R;
  const LimitResult m = analyse_limit(published, o);
  REQUIRE(m.status == LimitStatus::success);
  const double unit = kGamma * published.thickness * R;
  CHECK(m.H_min() / unit <= 0.6218 + kFourDecimals);
  CHECK(m.H_max() / unit >= 0.6218 - kFourDecimals);
  CHECK(m.H_max() / unit - m.H_min() / unit <= 2e-4);
}

TEST_CASE("limit: at t/L = 0.15 the thrust range is 0.24 .. 0.58 of the half weight for the semicircle, 0.14 .. 0.30 for the equilateral arch (Romano & Ochsendorf 2010)") {
  const LimitResult semicircle = analyse(0.0, 0.15), equilateral = analyse(0.5, 0.15);
  REQUIRE(semicircle.status == LimitStatus::success);
  REQUIRE(equilateral.status == LimitStatus::success);
  CHECK(std::abs(semicircle.H_min() / semicircle.V - 0.24) <= kQuotedReading);
  CHECK(std::abs(semicircle.H_max() / semicircle.V - 0.58) <= kQuotedReading);
  CHECK(std::abs(equilateral.H_min() / equilateral.V - 0.14) <= kQuotedReading);
  CHECK(std::abs(equilateral.H_max() / equilateral.V - 0.30) <= kQuotedReading);
  // V is half the weight of the true ring: for the semicircle, gamma pi R t / 2.
  CHECK(close(semicircle.V, 0.5 * kGamma * std::numbers::pi * 5.0 * 1.5, kExact));
}

TEST_CASE("limit: H_min <= H_max; H_min falls and H_max rises with thickness; both meet at t_min") {
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
      // t_min does not depend on the thickness it is searched from.
      if (t_min == 0) t_min = r.thickness_min;
      CHECK(close(r.thickness_min, t_min, 1e-9));
    }
    // t_min is known to 1e-10 (the root-finder's bracket) and its margin is zero to round-off there:
    // the range is evaluated just above it.
    Scene at_min = paper_scene(eps);
    at_min.thickness = t_min * (1 + 1e-9);
    const LimitResult m = analyse_limit(at_min, {});
    REQUIRE(m.status == LimitStatus::success);
    CHECK(close(m.H_min(), m.H_max(), kRangeAtMinimum));
    // Just below t_min nothing stands, and the row says so with t_min.
    at_min.thickness = t_min * (1 - 1e-6);
    const LimitResult below = analyse_limit(at_min, {});
    CHECK(below.status == LimitStatus::inadmissible);
    CHECK(std::isnan(below.H_min()));
    CHECK(close(below.thickness_min, t_min, 1e-9));
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
      const Ring ring = make_ring(scene, {});
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
    const int last = kDefaultJointsCount - 1;
    const std::size_t n = l.collapse_state.hinges.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Hinge &h = l.collapse_state.hinges[i], &m = r.collapse_state.hinges[n - 1 - i];
      CHECK(h.joint == last - m.joint);
      CHECK(h.face == m.face);
      CHECK(std::abs(h.point.x() - (10.0 - m.point.x())) <= kExact * 10.0);
    }
  }
}

TEST_CASE("limit: the numbers converge as the joints are refined; the default is converged to 1e-4") {
  for (double eps : {0.0, 0.5, 1.5}) {
    CAPTURE(eps);
    std::vector<LimitResult> runs;
    for (int n : {51, 201, kDefaultJointsCount, 4 * (kDefaultJointsCount - 1) + 1}) {
      LimitOptions o;
      o.joints_count = n;
      runs.push_back(analyse(eps, 0.10, o));
      REQUIRE(runs.back().status == LimitStatus::success);
    }
    const LimitResult& fine = runs.back();
    auto error = [&](const LimitResult& r) {
      return std::max({relative_difference(r.H_min(), fine.H_min()), relative_difference(r.H_max(), fine.H_max()),
                       relative_difference(r.thickness_min, fine.thickness_min)});
    };
    CHECK(error(runs[1]) <= error(runs[0]));
    CHECK(error(runs[2]) <= error(runs[1]));
    CHECK(error(runs[2]) <= kConverged);
  }
}

TEST_CASE("limit: the ring's weight and centroids are those of the annulus; the axis weight is rho g t per axis length") {
  const auto curve = make_pointed(10.0, 0.0);
  const double R = 5.0, t = 0.8, r_in = R - t / 2, r_out = R + t / 2;
  LimitOptions o;
  o.joints_count = 9;  // 45-degree voussoirs: the quadrature must be exact on large pieces too
  const Ring ring = make_ring(*curve, t, kGamma, o);
  REQUIRE(ring.voussoirs.size() == 8);
  CHECK(close(ring.total_weight(), kGamma * std::numbers::pi * R * t, kExact));
  // An annulus sector of angle 2b has its centroid at 2/3 (r_out^3 - r_in^3) / (r_out^2 - r_in^2) sin(b) / b.
  const double b = std::numbers::pi / 16;
  const double radius = 2.0 / 3.0 * (std::pow(r_out, 3) - std::pow(r_in, 3)) / (r_out * r_out - r_in * r_in) * std::sin(b) / b;
  for (std::size_t k = 0; k < ring.voussoirs.size(); ++k) {
    const double angle = std::numbers::pi - (2 * k + 1) * b;  // from the centre (L/2, 0), springing at pi
    CHECK(std::abs(ring.voussoirs[k].centroid.x() - (R + radius * std::cos(angle))) <= kExact * R);
    CHECK(std::abs(ring.voussoirs[k].centroid.y() - radius * std::sin(angle)) <= kExact * R);
  }
  o.weight = WeightModel::axis;
  const Ring axis = make_ring(*curve, t, kGamma, o);
  CHECK(close(axis.total_weight(), kGamma * t * 2.0 * curve->length(), kExact));
}

TEST_CASE("limit: the pointed ring weighs what the two annulus segments left of mid-span weigh, whatever the joints") {
  // Each half is the part of an annulus (centre eps L beyond mid-span, radii R -+ t/2) above the
  // springing line and before mid-span: half a circular segment of each disc, cut at d = eps L from the
  // centre, of area r^2 acos(d/r) - d sqrt(r^2 - d^2).
  const double eps = 0.5, L = 10.0, t = 1.5, R = (0.5 + eps) * L, d = eps * L;
  auto segment = [&](double r) { return r * r * std::acos(d / r) - d * std::sqrt(r * r - d * d); };
  const double area = segment(R + t / 2) - segment(R - t / 2);  // both halves
  for (JointOrientation j : {JointOrientation::radial, JointOrientation::vertical})
    for (int n : {9, kDefaultJointsCount}) {
      LimitOptions o;
      o.joints = j;
      o.joints_count = n;
      CHECK(close(make_ring(*make_pointed(L, eps), t, kGamma, o).total_weight(), kGamma * area, kExact));
    }
}

TEST_CASE("limit: at a pointed crown the crown joint is vertical and every joint cuts the arch in two") {
  for (JointOrientation j : {JointOrientation::radial, JointOrientation::vertical}) {
    LimitOptions o;
    o.joints = j;
    const Ring ring = make_ring(*make_pointed(10.0, 0.5), 1.5, kGamma, o);
    const Joint& crown = ring.joints[ring.joints.size() / 2];
    CHECK(crown.intrados.x() == 5.0);
    CHECK(crown.extrados.x() == 5.0);
    CHECK(crown.extrados.y() > crown.intrados.y());
    // The left half's joints lie left of mid-span, in order, both ends on the faces' correct sides.
    for (std::size_t k = 0; k + 1 < ring.joints.size() / 2; ++k) {
      CHECK(ring.joints[k].intrados.x() < 5.0);
      CHECK(ring.joints[k].extrados.x() < 5.0);
      CHECK(ring.joints[k + 1].intrados.x() > ring.joints[k].intrados.x());
      CHECK(ring.voussoirs[k].weight > 0);
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
  CHECK_THROWS_WITH_AS(analyse_limit(empty, {}), doctest::Contains("loads"), std::invalid_argument);
  o = {};
  o.friction = -0.1;
  CHECK_THROWS_WITH_AS(analyse(0.0, 0.1, o), doctest::Contains("friction"), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Whole curves, the scene's loads, pins.

namespace {

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
  for (const ThrustState* st : {&f.min_state, &f.max_state, &f.collapse_state}) check_state_inside(ring_f, *st);
  CHECK(close(f.load_factor(), f.load_factor_mechanism, kVirtualWork));
  CHECK(close(f.min_state.V_left, b.min_state.V_right, kSameRing));
  const int last = kDefaultJointsCount - 1;
  const std::size_t n = f.collapse_state.hinges.size();
  REQUIRE(n == b.collapse_state.hinges.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Hinge &h = f.collapse_state.hinges[i], &m = b.collapse_state.hinges[n - 1 - i];
    CHECK(h.joint == last - m.joint);
    CHECK(h.face == m.face);
  }
}

TEST_CASE("limit: a whole curve whose crown is an asymmetric kink is refused, naming the curve") {
  // The left half of the equilateral arch (eps 0.5) joined at its crown to the mirror image of the left
  // half of a sharper pointed arch (eps 1.0), raised so that the crowns meet: the two sides' faces cut
  // the crown's vertical at different heights.
  class Kinked final : public Curve {
   public:
    Kinked() : left_(make_pointed(10.0, 0.5)), right_(make_pointed(10.0, 1.0)) {}
    CurveExtent extent() const override { return CurveExtent::whole; }
    std::string family() const override { return "kinked"; }
    double span() const override { return 10.0; }
    double length() const override { return left_->length() + right_->length(); }
    double crown() const override { return left_->length(); }
    CurvePoint at(double s) const override {
      const double S = left_->length();
      if (s <= S) return left_->at(s);
      CurvePoint p = mirror(right_->at(length() - s), 10.0);
      p.y += left_->at(S).y - right_->at(right_->length()).y;  // the crowns meet
      return p;
    }
    std::vector<double> breakpoints() const override { return {left_->length()}; }
    double max_curvature() const override { return std::max(left_->max_curvature(), right_->max_curvature()); }

   private:
    std::shared_ptr<const Curve> left_, right_;
  };
  CHECK_THROWS_WITH_AS(make_ring(*std::make_shared<Kinked>(), 0.8, kGamma, {}), doctest::Contains("kink"),
                       std::invalid_argument);
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

TEST_CASE("limit: the fill's weight is the integral of rho_f g (h_f - y_extrados) over the span; fill raises H_min of the semicircle and lowers its t_min") {
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
    for (JointOrientation j : {JointOrientation::radial, JointOrientation::vertical}) {
      LimitOptions o;
      o.joints = j;
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
  CHECK(close(b.H_min(), by_hand(make_ring(bare, {})), kExact));
  for (double h : {0.3, 0.5, 0.6, 0.7}) {
    CAPTURE(h);
    Scene filled = bare;
    filled.loads.fills.push_back({rho_f, h});
    const LimitResult f = analyse_limit(filled, {});
    REQUIRE(f.status == LimitStatus::success);
    CHECK(close(f.H_min(), by_hand(make_ring(filled, {})), kExact));
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
    const Ring ring = make_ring(scene, {});
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
    // The pin narrows the range: the thrust range of the hingeless arch contains the pinned one's.
    Scene free = scene;
    free.crown_hinge = false;
    const LimitResult u = analyse_limit(free, {});
    CHECK(r.H_min() >= u.H_min() * (1 - kSameRing));
    CHECK(r.H_max() <= u.H_max() * (1 + kSameRing));
    CHECK(r.load_factor() <= u.load_factor() * (1 + kSameRing));
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

// ---------------------------------------------------------------------------------------------
// The command line.

namespace {

struct Run {
  int status;
  std::string out, err;
};

Run limit_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "limit");
  std::ostringstream out, err;
  const int status = ogive::cli::run_cli(args, out, err);
  return {status, out.str(), err.str()};
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!text.empty() && text.back() == sep && sep != '\n') out.push_back("");
  return out;
}

std::string field(const std::string& csv, const std::string& name, std::size_t row = 1) {
  const auto lines = split(csv, '\n');
  const auto header = split(lines.at(0), ',');
  const auto it = std::find(header.begin(), header.end(), name);
  REQUIRE_MESSAGE(it != header.end(), "no column " << name);
  return split(lines.at(row), ',').at(static_cast<std::size_t>(it - header.begin()));
}

}  // namespace

TEST_CASE("limit: the three-hinged arch with the axis weight carries the elastic model's thrust (statically determinate: stiffness does not enter)") {
  for (double eps : {0.0, 0.5, 1.0}) {
    CAPTURE(eps);
    Scene scene = paper_scene(eps, 0.15);
    scene.crown_hinge = true;
    scene.left.kind = scene.right.kind = SupportKind::pinned;
    LimitOptions o;
    o.weight = WeightModel::axis;  // the elastic model's rho g t per axis length
    const LimitResult r = analyse_limit(scene, o);
    REQUIRE(r.status == LimitStatus::success);
    // The elastic solve's success promises its numbers to its rtol; the LP's are exact to 1e-9 or better.
    const Solution elastic = solve(scene);
    REQUIRE(elastic.status == Status::success);
    const double tolerance = Options{}.rtol + kSameRing;
    CHECK(close(r.H_min(), elastic.H, tolerance));
    CHECK(close(r.H_max(), elastic.H, tolerance));
    CHECK(close(r.V, elastic.V, tolerance));
  }
}

TEST_CASE("cli: limit prints one row per scene, inadmissible arches as rows, hinges as x/L:face") {
  const Run r = limit_cli({"--eccentricity", "0,0.5", "--thickness-ratio", "0.03,0.15"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const auto lines = split(r.out, '\n');
  REQUIRE(lines.size() == 1 + 4);
  CHECK(field(r.out, "status", 1) == "inadmissible");
  CHECK(field(r.out, "H_min", 1).empty());
  CHECK(!field(r.out, "thickness_min_ratio", 1).empty());
  CHECK(field(r.out, "status", 3) == "success");
  // The semicircle's minimum-thrust hinges: haunch intrados, crown extrados, haunch intrados.
  const auto hinges = split(field(r.out, "hinges_min", 3), ';');
  REQUIRE(hinges.size() == 3);
  CHECK(hinges[1] == "0.5:extrados");
  CHECK(hinges[0].find(":intrados") != std::string::npos);
  CHECK(close(std::stod(field(r.out, "geometric_safety_factor", 3)),
              0.15 / std::stod(field(r.out, "thickness_min_ratio", 3)), kExact));
  CHECK(r.out.find("nan") == std::string::npos);
  CHECK(r.out.find("inf") == std::string::npos);
}

TEST_CASE("cli: limit with a point load prints the load factor and its mechanism's; --thrust-line one row per joint") {
  const Run r = limit_cli({"--point-load", "2e5", "--point-load-at", "0.25", "--thickness-ratio", "0.12"});
  REQUIRE(r.status == 0);
  const double lf = std::stod(field(r.out, "load_factor")), mech = std::stod(field(r.out, "load_factor_mechanism"));
  CHECK(close(lf, mech, kVirtualWork));
  CHECK(split(field(r.out, "hinges_collapse"), ';').size() == 4);

  const Run lines = limit_cli({"--thrust-line", "collapse", "--point-load", "2e5", "--point-load-at", "0.25",
                               "--thickness-ratio", "0.12", "--joints-count", "41"});
  REQUIRE(lines.status == 0);
  REQUIRE(split(lines.out, '\n').size() == 1 + 41);
  int hinges = 0;
  for (std::size_t j = 1; j <= 41; ++j) {
    // Every crossing lies on its joint, between intrados and extrados.
    const double ix = std::stod(field(lines.out, "intrados_x", j)), iy = std::stod(field(lines.out, "intrados_y", j));
    const double ex = std::stod(field(lines.out, "extrados_x", j)), ey = std::stod(field(lines.out, "extrados_y", j));
    const double tx = std::stod(field(lines.out, "thrust_x", j)), ty = std::stod(field(lines.out, "thrust_y", j));
    const double length = std::hypot(ex - ix, ey - iy);
    const double u = ((tx - ix) * (ex - ix) + (ty - iy) * (ey - iy)) / (length * length);
    CHECK(std::abs((tx - ix) * (ey - iy) - (ty - iy) * (ex - ix)) <= 1e-9 * length * 10.0);
    CHECK(u >= -1e-9);
    CHECK(u <= 1 + 1e-9);
    hinges += !field(lines.out, "hinge", j).empty();
  }
  CHECK(hinges == 4);

  // A state that does not exist (the arch cannot stand): one row that says so, without numbers.
  const Run none = limit_cli({"--thrust-line", "max", "--thickness-ratio", "0.03", "--joints-count", "41"});
  REQUIRE(none.status == 0);
  REQUIRE(split(none.out, '\n').size() == 2);
  CHECK(field(none.out, "status") == "inadmissible");
  CHECK(field(none.out, "thrust_x").empty());
}

TEST_CASE("cli: limit takes the scene's loads and pins: a live load's factor, the three-hinged arch's single thrust") {
  const Run live = limit_cli({"--live-load", "2e4", "--live-load-to", "0.5", "--fill-density", "1800",
                              "--fill-height-ratio", "0.5", "--thickness-ratio", "0.12"});
  REQUIRE(live.status == 0);
  CHECK(field(live.out, "status") == "success");
  CHECK(close(std::stod(field(live.out, "load_factor")), std::stod(field(live.out, "load_factor_mechanism")), kVirtualWork));
  // The fill is dead: without a live load no load factor.
  const Run dead = limit_cli({"--fill-density", "1800", "--fill-height-ratio", "0.5", "--thickness-ratio", "0.12"});
  REQUIRE(dead.status == 0);
  CHECK(field(dead.out, "load_factor").empty());

  const Run pinned = limit_cli({"--supports", "pinned", "--crown-hinge", "--eccentricity", "0", "--thickness-ratio", "0.15"});
  REQUIRE(pinned.status == 0);
  CHECK(field(pinned.out, "hinges_min") == "0:axis;0.5:axis;1:axis");
  CHECK(close(std::stod(field(pinned.out, "H_min")), std::stod(field(pinned.out, "H_max")), kSameRing));
}

TEST_CASE("cli: limit refuses bad input with one line and exit 2") {
  const std::vector<std::vector<std::string>> cases = {
      {"--friction", "0"},
      {"--friction", "-0.3"},
      {"--joints-count", "3"},
      {"--joints-count", "200"},
      {"--joints-count", "x"},
      {"--joints", "diagonal"},
      {"--weight", "lumped"},
      {"--point-load", "1e5", "--point-load-at", "1.5"},
      {"--point-load", "1e5", "--point-load-at", "-0.1"},
      {"--point-load-at", "0.3"},
      {"--thrust-line", "collapse"},
      {"--thrust-line", "middle"},
      {"--support-displacement-ratio", "0.0001"},
      {"--left-spread-ratio", "0.0001"},
      {"--thrust-line", "collapse", "--fill-density", "1800", "--fill-height-ratio", "0.5"},
      {"--thickness-ratio", "1.2"},
      {"--repeats", "-1"},
  };
  for (const auto& args : cases) {
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    CAPTURE(joined);
    const Run r = limit_cli(args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(split(r.err, '\n').size() == 1);
    CHECK(r.err.rfind("ogive: ", 0) == 0);
  }
}
