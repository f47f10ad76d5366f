// The crushing hinges of the spreading path (spreading_crushing.hpp).
#include "limit/spreading_crushing.hpp"

#include <algorithm>
#include <cmath>

#include "limit/limit_internal.hpp"

namespace ogive::spreading_detail {

std::vector<Hinge> turning_points(const Ring& moved, const ThrustState& st, double f_c) {
  std::vector<Hinge> out = st.hinges;
  if (!std::isfinite(f_c)) return out;
  for (Hinge& h : out) {
    if (h.face == Face::axis) continue;
    const std::size_t k = static_cast<std::size_t>(h.joint);
    const Joint& j = moved.joints[k];
    const double depth = limit_detail::joint_normal_force(j, st.force[k]) / f_c;
    const Vec inwards = (j.extrados - j.intrados).normalized();
    h.point = h.face == Face::intrados ? Vec(j.intrados + depth * inwards) : Vec(j.extrados - depth * inwards);
  }
  return out;
}

double crushing_dissipation(const Ring& moved, const Mechanism& mech, const std::vector<Vec>& force, double f_c) {
  if (!std::isfinite(f_c)) return 0;
  double work = 0;
  for (std::size_t i = 0; i < mech.hinges.size(); ++i) {
    if (mech.hinges[i].face == Face::axis) continue;
    const std::size_t j = static_cast<std::size_t>(mech.hinges[i].joint);
    const double N = limit_detail::joint_normal_force(moved.joints[j], force[j]);
    work += N * N / (2 * f_c) * std::abs(mech.rates[i]);
  }
  return work;
}

double farthest_apart(const std::vector<Hinge>& a, const std::vector<Hinge>& b) {
  double most = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) most = std::max(most, (a[i].point - b[i].point).norm());
  return most;
}

bool slid_along(const std::vector<Hinge>& a, const std::vector<Hinge>& b, double reach) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [&](const Hinge& x, const Hinge& y) {
    return x.face == y.face && (x.point - y.point).norm() <= reach;
  });
}

Mechanism grazed_mechanism(const Ring& ring0, const Ring& moved, const std::vector<Hinge>& hinges,
                           const std::vector<Hinge>& contacts, const Twist& vL, const Twist& vR, double reach) {
  if (contacts.size() <= hinges.size()) return {};
  const auto s = [&](const Hinge& h) { return ring0.joints[static_cast<std::size_t>(h.joint)].s; };
  std::vector<Hinge> kept;
  for (const Hinge& c : contacts) {
    const auto at = [&](const Hinge& h) { return h.joint == c.joint && h.face == c.face; };
    const auto beside = [&](const Hinge& h) { return h.face == c.face && std::abs(s(h) - s(c)) <= reach; };
    if (std::any_of(hinges.begin(), hinges.end(), at)) kept.push_back(c);
    else if (std::none_of(hinges.begin(), hinges.end(), beside)) return {};
  }
  if (!same_hinges(kept, hinges)) return {};
  Mechanism mech = choose_mechanism(moved, std::move(kept), vL, vR);
  return same_hinges(mech.hinges, hinges) ? mech : Mechanism{};
}

}  // namespace ogive::spreading_detail
