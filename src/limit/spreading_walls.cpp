// The walls under a spreading arch (spreading_walls.hpp).
//
// Why the path is followed on the arch's ring and the walls checked beside it: a wall that turns as a
// rigid body about its toe is the springing's rigid motion, imposed like a spreading support's; the
// arch's state is its mechanism's (three hinges fix it), and the walls either carry that state or tip.
// A program on the ring with the walls would instead move the arch's thrust line to keep a wall's
// resultant inside it, a state the arch's hinges do not make.
#include "limit/spreading_walls.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "limit/limit_internal.hpp"

namespace ogive::spreading_detail {
namespace {

// The ring `system` without its walls: the joints from the left springing to the right one, the
// voussoirs between them, the pins among those joints (renumbered).
Ring without_walls(const Ring& system) {
  Ring arch = system;
  const int first = system.left_springing(), last = system.right_springing();
  arch.joints.assign(system.joints.begin() + first, system.joints.begin() + last + 1);
  arch.voussoirs.assign(system.voussoirs.begin() + first, system.voussoirs.begin() + last);
  arch.pins.clear();
  for (int p : system.pins)
    if (p >= first && p <= last) arch.pins.push_back(p - first);
  arch.left_wall_joints = arch.right_wall_joints = 0;
  return arch;
}

// The outer corner of a wall's top: above its toe, at the highest point of the springing joint it
// carries (a wall's top reaches the joint's higher end: model.md, Walls).
Vec top_corner(const Vec& toe, const Joint& springing) {
  return {toe.x(), std::max(springing.intrados.y(), springing.extrados.y())};
}

// Why a wall gives way at a bed where it does not slide (SpreadResult::message).
const char* tipping_reason(const Tipping& t) {
  if (t.crushes) return "the normal force down it exceeds f_c b_w";
  return t.stress_block ? "the resultant down it comes within N / (2 f_c) of the bed's edge (its stress block leaves the bed)"
                        : "the resultant down it leaves the bed";
}

}  // namespace

SpreadWalls::SpreadWalls(const Ring& system, const SpreadOptions& spread) : system_(system), arch_(without_walls(system)) {
  const bool has_left = system.left_wall_joints > 0, has_right = system.right_wall_joints > 0;
  // A wall of no height under a horizontal springing joint has no blocks: nothing turns.
  if (spread.left_share > 0 && !has_left)
    throw std::invalid_argument("left_wall_height: a leaning wall of no height (under a horizontal springing joint) "
                                "has nothing to turn about its toe");
  if (spread.right_share > 0 && !has_right)
    throw std::invalid_argument("right_wall_height: a leaning wall of no height (under a horizontal springing joint) "
                                "has nothing to turn about its toe");
  const Vec left_toe = system.joints.front().extrados, right_toe = system.joints.back().extrados;
  // Outwards: the left wall counter-clockwise, the right one clockwise.
  left_ = has_left ? SpringingMotion::turning(left_toe, spread.left_share) : SpringingMotion::sliding(Vec::Zero());
  right_ = has_right ? SpringingMotion::turning(right_toe, -spread.right_share) : SpringingMotion::sliding(Vec::Zero());
  left_top_ = top_corner(left_toe, arch_.joints.front());
  right_top_ = top_corner(right_toe, arch_.joints.back());
}

double SpreadWalls::span_rate() const {
  return right_.twist.at(arch_.joints.back().intrados).x() - left_.twist.at(arch_.joints.front().intrados).x();
}

Tipping SpreadWalls::tipping(const Placement& at, double H, double V, double M, double live_factor, double friction,
                             double compressive_strength) {
  const int first = system_.left_springing(), last = system_.right_springing();
  Placement whole;
  whole.left = at.left;
  whole.right = at.right;
  whole.voussoir.assign(static_cast<std::size_t>(first), at.left);
  whole.voussoir.insert(whole.voussoir.end(), at.voussoir.begin(), at.voussoir.end());
  whole.voussoir.resize(system_.voussoirs.size(), at.right);
  place_ring(system_, whole, moved_);
  // The reactions at the left wall's base: the arch's at its springing with the left wall's loads.
  double V_base = V, M_base = M;
  for (int k = 0; k < first; ++k) {
    const VerticalLoad l = moved_.voussoirs[static_cast<std::size_t>(k)].dead();
    V_base += l.force;
    M_base += l.moment;
  }
  const ThrustState st = thrust_state(moved_, H, V_base, M_base, live_factor);
  // Whether bed j gives way: tips (the resultant leaves it, or with a finite strength its stress block)
  // or crushes, else slides (it leaves the friction cone).
  const auto gives_way = [&](int j, bool right) -> std::optional<Tipping> {
    const std::size_t k = static_cast<std::size_t>(j);
    const Joint& b = moved_.joints[k];
    const Vec e = b.extrados - b.intrados;
    const double u = (st.crossing[k] - b.intrados).dot(e) / e.squaredNorm();
    // The normal force, N > 0 in compression (the bed's normal towards the next part of the chain).
    const double N = limit_detail::cross(st.force[k], e);
    const double y = system_.joints[k].intrados.y();
    // The stress block's half depth as a fraction of the bed: N / (2 f_c b_w) (0 without a strength).
    const double inside = N > 0 ? N / (2 * compressive_strength * e.squaredNorm()) : 0.0;
    const bool block = std::isfinite(compressive_strength);
    if (inside > 0.5) return Tipping{j, right, false, true, block, y};
    if (!(u >= inside - 1e-9 && u <= 1 - inside + 1e-9 && N > 0)) return Tipping{j, right, false, false, block, y};
    if (friction > 0 && cone_excess(b, st.force[k], friction) > kConeRoundOff) return Tipping{j, right, true, false, block, y};
    return std::nullopt;
  };
  const int count = static_cast<int>(system_.joints.size());
  for (int j = 0; j < first; ++j)
    if (const auto t = gives_way(j, false)) return *t;
  for (int j = count - 1; j > last; --j)
    if (const auto t = gives_way(j, true)) return *t;
  return {};
}

double SpreadWalls::rotation(bool right, double d) const {
  const bool has = right ? system_.right_wall_joints > 0 : system_.left_wall_joints > 0;
  if (!has) return std::numeric_limits<double>::quiet_NaN();
  return right ? -right_.twist.rate * d : left_.twist.rate * d;
}

double SpreadWalls::top_displacement(bool right, double d) const {
  const double theta = rotation(right, d);
  const Vec& toe = right ? right_.pivot : left_.pivot;
  const Vec& top = right ? right_top_ : left_top_;
  return (top.y() - toe.y()) * std::sin(theta);  // the corner above the toe, turned outwards by theta
}

void check_spread_on_walls(const Scene& scene, const SpreadOptions& spread) {
  if (spread.left_settlement_share != 0 || spread.right_settlement_share != 0)
    throw std::invalid_argument(
        "left_settlement_share, right_settlement_share: on walls the springings move by the walls' rotation alone");
  if ((spread.left_share > 0 && !scene.left_wall) || (spread.right_share > 0 && !scene.right_wall))
    throw std::invalid_argument("left_share, right_share: on walls only a springing on a wall moves (its wall turns)");
}

std::optional<SpreadWalls> SpreadWalls::of(const Ring& ring, const SpreadOptions& spread) {
  if (ring.left_wall_joints == 0 && ring.right_wall_joints == 0) return std::nullopt;
  return SpreadWalls(ring, spread);
}

std::vector<Hinge> SpreadWalls::arch_hinges(std::vector<Hinge> hinges) const {
  const int first = system_.left_springing(), last = system_.right_springing();
  std::erase_if(hinges, [&](const Hinge& h) { return h.joint < first || h.joint > last; });
  for (Hinge& h : hinges) h.joint -= first;
  return hinges;
}

void SpreadWalls::at_collapse(SpreadResult& r, const Tipping& t) const {
  const bool slides = r.collapse == SpreadCollapse::sliding && r.sliding_joint < 0;
  if (r.collapse == SpreadCollapse::wall_tips || slides) {
    r.tipping_wall = t.right ? 1 : 0;
    r.tipping_bed_y = t.y;
    r.message = slides ? fmt::format("the {} wall slides at its bed at y = {:.6g} L: the resultant down it leaves the "
                                     "bed's friction cone",
                                     t.right ? "right" : "left", t.y / arch_.span)
                       : fmt::format("the {} wall {} at its bed at y = {:.6g} L: {}", t.right ? "right" : "left",
                                     t.crushes ? "crushes" : "tips", t.y / arch_.span, tipping_reason(t));
    // The bed turns with its wall, a rigid body about the toe.
    if (slides) r.sliding_point = (t.right ? right_ : left_).at(r.d_max)(system_.joints[static_cast<std::size_t>(t.bed)].axis);
  }
  r.left_wall_rotation = rotation(false, r.d_max);
  r.right_wall_rotation = rotation(true, r.d_max);
  r.left_wall_top_displacement = top_displacement(false, r.d_max);
  r.right_wall_top_displacement = top_displacement(true, r.d_max);
}

SpreadResult SpreadWalls::tips_at_once(SpreadResult r, const SpreadStep& step, const Tipping& t) const {
  r.path.push_back(step);
  r.status = SpreadStatus::success;
  r.collapse = t.slides ? SpreadCollapse::sliding : SpreadCollapse::wall_tips;
  r.d_max = 0;
  at_collapse(r, t);
  return r;
}

}  // namespace ogive::spreading_detail

namespace ogive {

SpreadOptions leaning_walls(const Scene& scene, SpreadOptions spread) {
  if (!scene.has_walls()) return spread;
  const double L = scene.span();
  for (const bool right : {false, true}) {
    const std::optional<Wall>& wall = right ? scene.right_wall : scene.left_wall;
    bool leans = false;
    if (wall) {
      const WallOutline o = wall_outline(*scene.curve, scene.thickness, *wall, right);
      leans = o.top_y - o.base_y > 1e-9 * L || o.wedge_area > 1e-9 * L * L;  // well above the ring's least block
    }
    if (!leans) (right ? spread.right_share : spread.left_share) = 0;
  }
  return spread;
}

double spread_capacity_ratio(const SpreadResult& r, const SpreadOptions& spread) {
  if (!std::isfinite(r.d_max) || r.path.empty()) return std::numeric_limits<double>::quiet_NaN();
  const bool walls = std::isfinite(r.left_wall_rotation) || std::isfinite(r.right_wall_rotation);
  return walls ? r.path.back().span_increase / r.ring.span : (spread.left_share + spread.right_share) * r.d_max / r.ring.span;
}

}  // namespace ogive
