// The feasibility margin as a function of one thickness (limit_internal.hpp, ThicknessMargin): t_min's
// search and b_min's call the same function, only the thickness it sets differs.
#include <algorithm>
#include <memory>
#include <utility>
#include <vector>

#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive::limit_detail {

bool stress_blocks(const Ring& ring, const std::vector<Hinge>& hinges) {
  return std::any_of(hinges.begin(), hinges.end(), [&](const Hinge& h) {
    if (h.face == Face::axis) return false;
    const Joint& j = ring.joints[static_cast<std::size_t>(h.joint)];
    const Eigen::Vector2d& face = h.face == Face::intrados ? j.intrados : j.extrados;
    return (h.point - face).norm() > 1e-9 * (j.extrados - j.intrados).norm();
  });
}

ThicknessMargin::ThicknessMargin(Of of, const Scene& scene, const LimitOptions& options, Fractions fractions,
                                 double load_factor, Ring& ring, RingScratch& scratch, LpWorkspace& workspace,
                                 std::unique_ptr<LimitLp>& lp)
    : of_(of), scene_(scene), options_(options), fractions_(std::move(fractions)), load_factor_(load_factor),
      ring_(ring), scratch_(scratch), workspace_(workspace), lp_(lp) {}

double ThicknessMargin::operator()(double thickness) {
  if (of_ == Of::arch) scene_.thickness = thickness;
  else
    for (std::optional<Wall>* wall : {&scene_.left_wall, &scene_.right_wall})
      if (*wall) (*wall)->thickness = thickness;
  make_ring_at(scene_, options_, fractions_(thickness), ring_, scratch_);
  LimitLp& lp = programs_of(ring_, options_, workspace_, lp_);
  // A warm start needs the same joints (a load's joints can merge with others at some thickness).
  const bool warm = !basis.empty() && basis_joints == static_cast<int>(ring_.joints.size());
  LimitLp::Answer a = lp.margin(load_factor_, warm ? &basis : nullptr);
  ++solves;
  basis = std::move(a.basis);
  basis_joints = static_cast<int>(ring_.joints.size());
  // No margin at all (friction can forbid every thrust line, whatever mu): as inadmissible as it gets.
  if (a.outcome == LimitLp::Outcome::infeasible) return kNoMargin;
  if (a.outcome != LimitLp::Outcome::optimal) {
    failed = true;
    return a.margin;
  }
  if (a.margin >= 0 && thickness < feasible) {
    feasible = thickness;
    refinement.clear();
    const ThrustState st =
        thrust_state(ring_, a.H, a.V, a.M, a.load_factor, kThinnestHingeTolerance, options_.compressive_strength);
    add_refinement(ring_, st.hinges, refinement);
    add_sliding_refinement(ring_, st, options_, refinement);  // a joint on its cone bounds it too
    if (of_ == Of::arch) feasible_blocks = stress_blocks(ring_, st.hinges);
  }
  return a.margin;
}

}  // namespace ogive::limit_detail
