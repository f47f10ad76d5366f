// The state of a thrust line: where it crosses each joint, and its hinges (thrust_state in limit.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive {
namespace {

using limit_detail::cross;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A joint whose force is below this fraction of the ring's load carries none (ThrustState::forceless).
constexpr double kForceless = 1e-9;

}  // namespace

ThrustState thrust_state(const Ring& ring, double H, double V_left, double M_left, double load_factor,
                         double hinge_tolerance, double compressive_strength) {
  const limit_detail::LoadsLeftOfJoints left = limit_detail::loads_left_of_joints(ring);
  const bool live = ring.has_live_load();
  const double lambda = live ? load_factor : 0.0;
  ThrustState st;
  st.H = H;
  st.V_left = V_left;
  st.load_factor = live ? load_factor : kNaN;
  st.V_right = ring.total_dead() + lambda * ring.total_live() - V_left;
  st.crossing.reserve(ring.joints.size());
  // The scale below which a joint's force is none: the loads' (vanishing at no joint of a ring with
  // weight, where the thrust is at least the weight's share).
  const std::size_t last = ring.joints.size() - 1;
  const double forceless = kForceless * (std::abs(left.dead[last].force) + std::abs(lambda * left.live[last].force) +
                                         std::abs(ring.acceleration * left.dead[last].force));
  std::size_t pin = 0;
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const Joint& joint = ring.joints[j];
    // The force of the part left of the joint on the part right of it, and its moment about the origin.
    // (A horizontal acceleration a adds a times the dead load left of it, and that load's moment.)
    const double a = ring.acceleration;
    const Eigen::Vector2d F(a == 0 ? H : H + a * left.dead[j].force,
                            V_left - left.dead[j].force - lambda * left.live[j].force);
    const double moment = a == 0 ? M_left - left.dead[j].moment - lambda * left.live[j].moment
                                 : M_left - left.dead[j].moment - lambda * left.live[j].moment -
                                       a * left.dead[j].height_moment;
    // Its line meets the joint I + u (E - I) where (I + u d) x F = moment.
    const Eigen::Vector2d d = joint.extrados - joint.intrados;
    const double u = (moment - cross(joint.intrados, F)) / cross(d, F);
    st.crossing.push_back(joint.intrados + u * d);
    st.force.push_back(F);
    if (F.norm() <= forceless && !(pin < ring.pins.size() && ring.pins[pin] == static_cast<int>(j))) {
      st.forceless = true;
      continue;
    }
    if (pin < ring.pins.size() && ring.pins[pin] == static_cast<int>(j)) {
      st.hinges.push_back({static_cast<int>(j), Face::axis, joint.axis});
      ++pin;
      continue;
    }
    if (std::isfinite(compressive_strength)) {
      // The stress block N / f_c deep: its centre, N / (2 f_c) inside the face, is where the joint turns.
      const double h = d.norm(), N = limit_detail::joint_normal_force(joint, F);
      const double inside = N / (2 * compressive_strength * h);
      const Eigen::Vector2d& at = st.crossing.back();
      if (u - inside <= hinge_tolerance) st.hinges.push_back({static_cast<int>(j), Face::intrados, at});
      if (u + inside >= 1.0 - hinge_tolerance) st.hinges.push_back({static_cast<int>(j), Face::extrados, at});
      continue;
    }
    if (u <= hinge_tolerance) st.hinges.push_back({static_cast<int>(j), Face::intrados, joint.intrados});
    if (u >= 1.0 - hinge_tolerance) st.hinges.push_back({static_cast<int>(j), Face::extrados, joint.extrados});
  }
  return st;
}

}  // namespace ogive
