// The limit analysis converged in its joints at the defaults for any load: scenes with point loads at
// awkward positions (not on any joint of the starting ring), live loads and fills, on segmental, pointed
// and parabolic arches, against the same analysis started from 30 times the joints; and an independent
// check that needs no refinement: rings of ever more equally spaced vertical joints (no joint through
// the load) approach the converged load factor from above, as the static theorem says they must.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "limit/limit_internal.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

struct HeldOutScene {
  std::string name;
  Scene scene;
  LimitOptions options;
};

Scene with_point_load(std::shared_ptr<const Curve> curve, double t_over_L, double P, double at) {
  Scene s;
  s.curve = std::move(curve);
  s.thickness = t_over_L * s.span();
  s.loads.points.push_back({P, at});
  return s;
}

std::vector<HeldOutScene> held_out_scenes() {
  std::vector<HeldOutScene> out;
  out.push_back({"segmental rise 0.2131, P at 0.5719", with_point_load(make_segmental(10.0, 0.2131), 0.0675, 26186.2, 0.5719), {}});
  out.push_back({"pointed eps 0.8604, P at 0.3872", with_point_load(make_pointed(10.0, 0.8604), 0.0943, 73588.2, 0.3872), {}});
  HeldOutScene parabolic{"parabolic rise 0.43, P at 0.2937, live load, vertical joints, axis weight",
                         with_point_load(make_parabolic(10.0, 0.43), 0.085, 41017.0, 0.2937), {}};
  parabolic.scene.loads.live.push_back({6300.0, 0.117, 0.683});
  parabolic.options.joints = JointOrientation::vertical;
  parabolic.options.weight = WeightModel::axis;
  out.push_back(parabolic);
  HeldOutScene filled{"pointed eps 0.31, P at 0.6613, fill", with_point_load(make_pointed(10.0, 0.31), 0.11, 52400.0, 0.6613), {}};
  filled.scene.loads.fills.push_back({1800.0, 0.37});
  out.push_back(filled);
  return out;
}

void check_converged(const double value, const double reference, const char* what) {
  CAPTURE(what);
  CAPTURE(value);
  CAPTURE(reference);
  CHECK(std::isnan(value) == std::isnan(reference));
  if (!std::isnan(reference)) CHECK(relative_difference(value, reference) <= kLimitTolerance);
}

}  // namespace

TEST_CASE("limit acceptance: with point loads at the defaults every number is within 1e-4 of 30 times the joints") {
  for (const HeldOutScene& h : held_out_scenes()) {
    CAPTURE(h.name);
    const LimitResult r = analyse_limit(h.scene, h.options);
    LimitOptions fine_options = h.options;
    fine_options.joints_count = 30 * (kDefaultJointsCount - 1) + 1;
    const LimitResult fine = analyse_limit(h.scene, fine_options);
    REQUIRE(r.status == LimitStatus::success);
    REQUIRE(fine.status == LimitStatus::success);
    check_converged(r.H_min(), fine.H_min(), "H_min");
    check_converged(r.H_max(), fine.H_max(), "H_max");
    check_converged(r.thickness_min, fine.thickness_min, "t_min");
    check_converged(r.load_factor(), fine.load_factor(), "load_factor");
    check_converged(r.load_factor_mechanism, fine.load_factor_mechanism, "load_factor_mechanism");
    // A hinge forms under the load: a joint of the ring passes through the load's point.
    const double x = h.scene.loads.points.front().at * h.scene.span();
    bool under = false;
    for (const Hinge& hinge : r.collapse_state.hinges) under |= std::abs(hinge.point.x() - x) <= 1e-9 * h.scene.span();
    CHECK(under);
  }
}

TEST_CASE("limit acceptance: equally spaced vertical joints approach the converged load factor from above") {
  // No joint passes through the load's point 0.5719 L: a hinge under it forms only approximately, so the
  // ring is less constrained than the arch and carries more; as the joints multiply the excess shrinks.
  Scene scene = with_point_load(make_segmental(10.0, 0.2131), 0.0675, 26186.2, 0.5719);
  LimitOptions o;
  o.joints = JointOrientation::vertical;
  const double converged = analyse_limit(scene, o).load_factor();
  double last_excess = INFINITY;
  for (int joints : {101, 401, 1601, 6401}) {
    CAPTURE(joints);
    const Ring ring = limit_detail::make_ring_at(scene, o, limit_detail::uniform_fractions(joints));
    limit_detail::LimitLp lp(ring, 0.0);
    const limit_detail::LimitLp::Answer a = lp.collapse();
    REQUIRE(a.outcome == limit_detail::LimitLp::Outcome::optimal);
    const double excess = a.load_factor / converged - 1;
    CHECK(excess > -kLimitTolerance);  // never below the converged answer, but for its tolerance
    CHECK(excess < last_excess);
    last_excess = excess;
  }
  CHECK(last_excess < 0.01);
}

TEST_CASE("limit acceptance: the mechanism check answers for any load") {
  // A huge point load and a weightless arch under one: thrust lines that touch many joints at once.
  for (const auto& density_and_load : {std::pair{2348.0, 1e17}, std::pair{1e-9, 1e4}}) {
    const auto [density, load] = density_and_load;
    CAPTURE(density_and_load.first);
    Scene scene = paper_scene(0.0, 0.08);
    scene.material.density = density;
    scene.loads.points.push_back({load, 0.5});
    // It returns (four-hinge subsets of a long run of touched joints were tried one by one before), with
    // an answer: the arch cannot carry such a load at factor 1.
    const LimitResult r = analyse_limit(scene, {});
    CHECK(r.status == LimitStatus::inadmissible);
  }
}
