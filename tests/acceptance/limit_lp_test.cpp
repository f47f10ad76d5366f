// The limit analysis' dense simplex method (src/limit/dense_lp.cpp) against COIN-OR Clp, the
// independent reference: the same programs on many rings (curves, thicknesses on both sides of t_min,
// joint counts, both stereotomies, point loads, fills, pins, friction) give the same outcome and the
// same optimum, and the dense method's state is admissible. Degenerate optima (a thrust line along a
// face touches many joints at once) are among them: the thick arches' extreme thrusts and the collapse
// states under a point load.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "limit/limit_internal.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "support/scenes.hpp"

using namespace ogive;
using limit_detail::LimitLp;
using limit_detail::LpSolver;

namespace {

// Both methods stop at a vertex whose rows hold to 1e-11 of the load scale (their feasibility
// tolerance) and are mostly the same vertex: the optima agree to round-off. Measured: at most 2e-14 (of
// the total load W for H, of 1 for the margin and of the load factor).
constexpr double kSameOptimum = 1e-12;

struct Case {
  std::string name;
  Scene scene;
  LimitOptions options;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (double eps : {0.0, 0.5, 1.5})
    for (double t : {0.03, 0.06, 0.1, 0.2})
      for (int loads = 0; loads < 3; ++loads) {
        Case c{"eps " + std::to_string(eps) + ", t/L " + std::to_string(t) + ", loads " + std::to_string(loads),
               paper_scene(eps, t), {}};
        if (loads >= 1) c.scene.loads.points.push_back({2e4, 0.3});
        if (loads == 2) c.scene.loads.fills.push_back({1800.0, 0.35});
        out.push_back(c);
      }
  Case segmental{"segmental, vertical joints, axis weight, live load", {}, {}};
  segmental.scene.curve = make_segmental(10.0, 0.2);
  segmental.scene.thickness = 0.7;
  segmental.scene.loads.live.push_back({5e3, 0.1, 0.6});
  segmental.options.joints = JointOrientation::vertical;
  segmental.options.weight = WeightModel::axis;
  out.push_back(segmental);
  Case parabolic{"parabolic, point load", {}, {}};
  parabolic.scene.curve = make_parabolic(10.0, 0.4);
  parabolic.scene.thickness = 0.9;
  parabolic.scene.loads.points.push_back({4e4, 0.62});
  out.push_back(parabolic);
  Case pinned{"pinned springings and crown hinge", paper_scene(0.5, 0.12), {}};
  pinned.scene.crown_hinge = true;
  pinned.scene.left.kind = pinned.scene.right.kind = SupportKind::pinned;
  out.push_back(pinned);
  Case hinge{"crown hinge, point load", paper_scene(0.0, 0.12), {}};
  hinge.scene.crown_hinge = true;
  hinge.scene.loads.points.push_back({3e4, 0.25});
  out.push_back(hinge);
  for (double mu : {0.1, 0.45, 0.8}) {
    Case friction{"friction " + std::to_string(mu), paper_scene(0.0, 0.1), {}};
    friction.options.friction = mu;
    friction.scene.loads.points.push_back({5e4, 0.25});
    out.push_back(friction);
  }
  return out;
}

// The same outcome, and for an optimum the same objective (scaled by `scale`).
void compare(const char* what, const LimitLp::Answer& dense, const LimitLp::Answer& clp,
             double target_dense, double target_clp, double scale, double& worst) {
  CAPTURE(what);
  REQUIRE(clp.outcome != LimitLp::Outcome::failure);
  CHECK(dense.outcome == clp.outcome);
  if (dense.outcome != LimitLp::Outcome::optimal || clp.outcome != LimitLp::Outcome::optimal) return;
  const double d = std::abs(target_dense - target_clp) / scale;
  worst = std::max(worst, d);
  CHECK(d <= kSameOptimum);
}

}  // namespace

TEST_CASE("limit acceptance: the dense simplex method gives Clp's optimum on every program") {
  double worst = 0;
  int programs = 0;
  for (const Case& c : cases())
    for (int joints : {21, 201, 801}) {
      CAPTURE(c.name);
      CAPTURE(joints);
      LimitOptions o = c.options;
      o.joints_count = joints;
      const Ring ring = limit_detail::make_ring_at(c.scene, o, limit_detail::starting_fractions(c.scene, o));
      double W = 0;
      for (const Voussoir& v : ring.voussoirs) W += std::abs(v.dead().force) + std::abs(v.live.force);
      LimitLp dense(ring, o.friction, nullptr, LpSolver::dense), clp(ring, o.friction, nullptr, LpSolver::clp);
      const double lambda = ring.has_live_load() ? 1.0 : 0.0;
      const LimitLp::Answer md = dense.margin(lambda), mc = clp.margin(lambda);
      compare("margin", md, mc, md.margin, mc.margin, 1.0, worst);
      for (bool largest : {false, true}) {
        const LimitLp::Answer hd = dense.extreme_thrust(lambda, largest), hc = clp.extreme_thrust(lambda, largest);
        compare(largest ? "H_max" : "H_min", hd, hc, hd.H, hc.H, W, worst);
        if (hd.outcome == LimitLp::Outcome::optimal) {
          const ThrustState st = thrust_state(ring, hd.H, hd.V, hd.M, lambda);
          for (std::size_t j = 0; j < ring.joints.size(); ++j) {
            // The crossing lies on the joint, between its faces, to the programs' tolerance.
            const Joint& joint = ring.joints[j];
            const double u = (st.crossing[j] - joint.intrados).dot(joint.extrados - joint.intrados) /
                             (joint.extrados - joint.intrados).squaredNorm();
            CHECK(u >= -1e-8);
            CHECK(u <= 1 + 1e-8);
          }
        }
      }
      if (ring.has_live_load()) {
        const LimitLp::Answer cd = dense.collapse(), cc = clp.collapse();
        compare("collapse", cd, cc, cd.load_factor, cc.load_factor, std::max(1.0, std::abs(cc.load_factor)),
                worst);
        programs += 1;
      }
      // A warm start from another thickness's optimal basis (as the search for t_min makes).
      Scene thinner = c.scene;
      thinner.thickness *= 0.9;
      const Ring other = limit_detail::make_ring_at(thinner, o, ring.joint_fractions);
      if (other.joints.size() == ring.joints.size()) {
        LimitLp dense_other(other, o.friction, nullptr, LpSolver::dense);
        LimitLp clp_other(other, o.friction, nullptr, LpSolver::clp);
        const LimitLp::Answer wd = dense_other.margin(lambda, &md.basis), wc = clp_other.margin(lambda, &mc.basis);
        compare("warm margin", wd, wc, wd.margin, wc.margin, 1.0, worst);
        CHECK(dense_other.clp_fallbacks() == 0);
        programs += 1;
      }
      CHECK(dense.clp_fallbacks() == 0);
      programs += 3;
    }
  MESSAGE("programs compared: " << programs << ", largest difference of the optima: " << worst);
}
