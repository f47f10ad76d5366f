// The walls under the springings in the limit analysis: their blocks and beds on the ring's chain, their
// beds' refinement, and the least wall thickness b_min on which the arch stands.
//
// Why the walls are voussoirs of the ring rather than a program of their own: every row of LimitLp is
// the equilibrium of what lies before a joint along the chain from the left support, so a horizontal bed
// of a wall is a joint like the arch's (its intrados point on the inner face, its extrados point on the
// outer one: the normal (d.y, -d.x) points up the left wall and down the right one, towards the next part
// of the chain, and N > 0 is compression), and the wall's blocks are voussoirs with their weight. The
// thrust programs, t_min's search, the collapse load factor, a_c and the mechanism check (whose hinges
// may then lie at a bed's edge or at a base's toe) need nothing else.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive::limit_detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Where the encoded wall fractions lie (limit_internal.hpp): a left wall's bed at depth fraction f as
// kLeftWallCode + f, a right wall's as kRightWallCode + f.
constexpr double kLeftWallCode = 2.0, kRightWallCode = 4.0;

// A degenerate block (the wedge under a horizontal springing joint; a wall of no height), relative to
// the span.
constexpr double kDegenerate = 1e-12;

// One wall's beds (in chain order) and blocks between them, from its outline and its depth fractions
// (ascending in [0, 1]: 0 the highest bed, 1 the base).
struct WallChain {
  std::vector<Joint> beds;          // base first for the left wall, last for the right one
  std::vector<Voussoir> blocks;     // between consecutive beds, and the wedge up to the springing joint
};

WallChain wall_chain(const WallOutline& o, const Wall& wall, double gravity, double span, double whole_length,
                     std::vector<double> depths) {
  const bool right = o.outward > 0;
  const double unit_weight = wall.density * gravity;
  const Eigen::Vector2d I = o.joint.intrados, E = o.joint.extrados;
  const bool has_wedge = o.wedge_area > kDegenerate * span * span;
  const double depth = o.top_y - o.base_y;
  const bool has_body = depth > kDegenerate * span;
  WallChain out;
  if (!has_body && !has_wedge) return out;
  if (!has_body) depths = {0.0};
  // The beds from the top down, then the blocks between them; without a wedge the springing joint sits
  // on the level of the highest bed (depth 0), which is then no joint of its own.
  std::vector<Joint> beds;
  for (double f : depths) {
    const double y = has_body ? o.top_y - f * depth : o.top_y;
    Joint j;
    j.intrados = {o.inner_x, y};
    j.extrados = {o.outer_x, y};
    j.axis = 0.5 * (j.intrados + j.extrados);
    j.s = right ? whole_length + span * (1.0 + f) : -span * (1.0 + f);
    beds.push_back(j);
  }
  std::vector<Voussoir> blocks;  // from the top down; blocks[0] the wedge when there is one
  if (has_wedge) {
    Voussoir v;
    v.weight = unit_weight * o.wedge_area;
    v.centroid = o.wedge_centroid;
    blocks.push_back(v);
  }
  for (std::size_t k = 0; k + 1 < beds.size(); ++k) {
    Voussoir v;
    const double h = beds[k].intrados.y() - beds[k + 1].intrados.y();
    v.weight = unit_weight * wall.thickness * h;
    v.centroid = 0.5 * (beds[k].axis + beds[k + 1].axis);
    blocks.push_back(v);
  }
  if (!has_wedge) beds.erase(beds.begin());
  if (!blocks.empty() && wall.top_load > 0) {
    // The top load on the wall's top at its point: over the wedge's top where it is, else the top bed's level.
    const double x = o.inner_x + o.outward * wall.top_load_at * wall.thickness;
    const double y = std::max({o.top_y, I.y(), E.y()});
    blocks.front().fill += VerticalLoad{wall.top_load, wall.top_load * x, wall.top_load * y};
  }
  if (right) {
    out.beds = std::move(beds);
    out.blocks = std::move(blocks);
  } else {
    out.beds.assign(beds.rbegin(), beds.rend());
    out.blocks.assign(blocks.rbegin(), blocks.rend());
  }
  return out;
}

// The depth fractions of one wall: kWallBlocks equal blocks and the refined ones (decoded).
std::vector<double> wall_depths(const std::vector<double>& encoded, double code) {
  std::vector<double> f;
  for (int k = 0; k <= kWallBlocks; ++k) f.push_back(static_cast<double>(k) / kWallBlocks);
  for (double e : encoded)
    if (e > code && e < code + 1.0) f.push_back(e - code);
  std::sort(f.begin(), f.end());
  std::vector<double> out;
  for (double x : f)
    if (out.empty() || x - out.back() > kFractionGap) out.push_back(x);
  return out;
}

}  // namespace

bool is_wall_fraction(double f) { return f > 1.5; }

bool kept_wall_fraction(double f) {
  for (double code : {kLeftWallCode, kRightWallCode})
    if (f > code + kFractionGap && f < code + 1.0 - kFractionGap) return true;
  return false;
}

void attach_walls(const Scene& scene, const std::vector<double>& fractions, Ring& ring) {
  ring.left_wall_joints = ring.right_wall_joints = 0;
  if (!scene.has_walls()) return;
  const double L = ring.span, W = scene.curve->whole_length(), g = scene.material.gravity;
  auto joint_of = [](const Joint& j) { return SpringingJoint{j.intrados, j.extrados, j.axis}; };
  if (scene.right_wall) {
    const WallOutline o = wall_outline(joint_of(ring.joints.back()), *scene.right_wall, true);
    WallChain c = wall_chain(o, *scene.right_wall, g, L, W, wall_depths(fractions, kRightWallCode));
    ring.joints.insert(ring.joints.end(), c.beds.begin(), c.beds.end());
    ring.voussoirs.insert(ring.voussoirs.end(), c.blocks.begin(), c.blocks.end());
    ring.right_wall_joints = static_cast<int>(c.beds.size());
  }
  if (scene.left_wall) {
    const WallOutline o = wall_outline(joint_of(ring.joints.front()), *scene.left_wall, false);
    WallChain c = wall_chain(o, *scene.left_wall, g, L, W, wall_depths(fractions, kLeftWallCode));
    ring.joints.insert(ring.joints.begin(), c.beds.begin(), c.beds.end());
    ring.voussoirs.insert(ring.voussoirs.begin(), c.blocks.begin(), c.blocks.end());
    ring.left_wall_joints = static_cast<int>(c.beds.size());
  }
}

void add_refinement(const Ring& ring, const std::vector<Hinge>& hinges, std::vector<double>& out) {
  const int first = ring.left_springing(), last = ring.right_springing();
  const int m = ring.crown_joint() - first;  // the arch's voussoirs per side
  const std::vector<double>& f = ring.joint_fractions;
  // Side joint i's fraction: 0 at the springing, 1 at the crown.
  auto at = [&](int i) { return i <= 0 ? 0.0 : i >= m ? 1.0 : f[static_cast<std::size_t>(i - 1)]; };
  // A wall bed's depth fraction from its height (the beds' own: the highest bed 0, the base 1).
  auto depth = [&](int j, int top, int base) {
    const Joint& springing = ring.joints[static_cast<std::size_t>(top == first - 1 ? first : last)];
    const double y0 = std::min(springing.intrados.y(), springing.extrados.y());
    const double y1 = ring.joints[static_cast<std::size_t>(base)].intrados.y();
    return y0 == y1 ? 0.0 : (y0 - ring.joints[static_cast<std::size_t>(j)].intrados.y()) / (y0 - y1);
  };
  // Two voussoirs (blocks) on each side of the hinge: the true hinge may lie beyond the next joint.
  for (const Hinge& h : hinges) {
    if (h.joint < first || h.joint > last) {
      const bool left = h.joint < first;
      const int top = left ? first - 1 : last + 1, base = left ? 0 : static_cast<int>(ring.joints.size()) - 1;
      const int step = left ? -1 : 1;  // from the top down
      const double code = left ? kLeftWallCode : kRightWallCode;
      for (int k = -2; k < 2; ++k) {
        const int a = h.joint + step * k, b = a + step;
        if ((a - top) * step < 0 || (b - base) * step > 0) continue;
        out.push_back(code + 0.5 * (depth(a, top, base) + depth(b, top, base)));
      }
      continue;
    }
    const int j = h.joint - first;
    const int i = j <= m ? j : 2 * m - j;
    for (int k = std::max(i - 2, 0); k < std::min(i + 2, m); ++k) out.push_back(0.5 * (at(k) + at(k + 1)));
  }
}

double thickest_on_walls(const Scene& scene) {
  double thickest = std::numeric_limits<double>::infinity();
  for (bool right : {false, true}) {
    const std::optional<Wall>& w = right ? scene.right_wall : scene.left_wall;
    if (!w) continue;
    // The springing joint's horizontal width is linear in t: its width at t = 1 m scales it.
    const WallOutline o = wall_outline(*scene.curve, 1.0, *w, right);
    const double width = o.outward * (o.joint.extrados.x() - o.joint.intrados.x());
    if (width > 0) thickest = std::min(thickest, w->thickness / width);
  }
  return thickest;
}

double arch_half_load(const Ring& ring) {
  // Without walls, the ring's totals summed as they always were (the same V to the bit).
  if (ring.left_wall_joints == 0 && ring.right_wall_joints == 0) return 0.5 * (ring.total_dead() + ring.total_live());
  double total = 0;
  for (int k = ring.left_springing(); k < ring.right_springing(); ++k) {
    const Voussoir& v = ring.voussoirs[static_cast<std::size_t>(k)];
    total += v.dead().force + v.live.force;
  }
  return 0.5 * total;
}

// ---------------------------------------------------------------------------------------------
// b_min: the least wall thickness.

namespace {

// The relative width of the bracket on b_w at which the root-finder stops (as t_min's).
constexpr double kWallTolerance = 1e-10;
// The thickest wall tried, in spans.
constexpr double kThickestWall = 1000.0;
// A bed whose crossing lies this close to an edge (relative to the bed) is a hinge of the least wall.
constexpr double kLeastWallHingeTolerance = 1e-6;

// What the search keeps from one thickness to the next (per thread: one analysis at a time).
struct WallWork {
  LpWorkspace workspace;
  RingScratch scratch;
  Ring ring;
  std::unique_ptr<LimitLp> lp;
  std::vector<int> basis;
  std::size_t basis_joints = 0;
};

// The margin (LimitLp::margin) of the scene with every wall b thick, on the joints `fractions`.
struct WallMargin {
  Scene scene;
  const LimitOptions& options;
  const std::vector<double>& fractions;
  double load_factor;
  WallWork& work;
  int solves = 0;
  bool failed = false;
  double feasible_b = std::numeric_limits<double>::infinity();
  // Next to the hinges, and to the joints on their friction cones, of the thinnest wall that stands so far.
  std::vector<double> refinement;

  double operator()(double b) {
    if (scene.left_wall) scene.left_wall->thickness = b;
    if (scene.right_wall) scene.right_wall->thickness = b;
    make_ring_at(scene, options, fractions, work.ring, work.scratch);
    LimitLp& lp = programs_of(work.ring, options, work.workspace, work.lp);
    const bool warm = !work.basis.empty() && work.basis_joints == work.ring.joints.size();
    LimitLp::Answer a = lp.margin(load_factor, warm ? &work.basis : nullptr);
    ++solves;
    work.basis = a.basis;
    work.basis_joints = work.ring.joints.size();
    if (a.outcome == LimitLp::Outcome::infeasible) return -1.0;
    if (a.outcome != LimitLp::Outcome::optimal) {
      failed = true;
      return -1.0;
    }
    if (a.margin >= 0 && b < feasible_b) {
      feasible_b = b;
      refinement.clear();
      const ThrustState st = thrust_state(work.ring, a.H, a.V, a.M, a.load_factor, kLeastWallHingeTolerance,
                                          options.compressive_strength);
      add_refinement(work.ring, st.hinges, refinement);
      add_sliding_refinement(work.ring, st, options, refinement);  // a joint on its cone bounds it too
    }
    return a.margin;
  }
};

}  // namespace

namespace {

WallSearch search_wall_thickness(const Scene& scene, const LimitOptions& options, const std::vector<double>& fractions,
                                 double load_factor, double near) {
  thread_local WallWork work;
  work.scratch.forget();
  work.basis.clear();
  WallSearch out;
  WallMargin f{scene, options, fractions, load_factor, work, 0, false, std::numeric_limits<double>::infinity(), {}};
  // The least thickness that carries the springing joints: their horizontal widths.
  double least = 0;
  for (bool right : {false, true}) {
    const std::optional<Wall>& w = right ? scene.right_wall : scene.left_wall;
    if (!w) continue;
    const WallOutline o = wall_outline(*scene.curve, scene.thickness, *w, right);
    least = std::max(least, o.outward * (o.joint.extrados.x() - o.joint.intrados.x()));
  }
  least = std::max(least, kDegenerate * scene.span());
  const double cap = kThickestWall * scene.span();
  auto finish = [&]() {
    out.solves = f.solves;
    out.failed = f.failed;
    out.refinement = f.refinement;
    return out;
  };
  // A bracket lo < hi, f(lo) < 0 <= f(hi): near the previous ring's b_min when given, else from the least.
  double lo = least, f_lo = f(lo), hi = lo, f_hi = f_lo;
  if (f.failed) return finish();
  if (f_lo >= 0) {
    out.b_min = least;
    out.note = fmt::format("the walls stand at the least thickness that carries the springing joints ({:.6g} m)", least);
    return finish();
  }
  bool found = false;
  if (std::isfinite(near) && near > least) {
    double step = 1e-3;
    double a = near, f_a = f(a);
    if (f_a >= 0) {  // down until it fails
      hi = a, f_hi = f_a;
      for (int i = 0; i < 60 && !f.failed; ++i, step = std::min(4 * step, 0.5)) {
        const double b = std::max(hi * (1 - step), least);
        if (b <= least) break;  // lo = least fails already
        const double f_b = f(b);
        if (f_b < 0) {
          lo = b, f_lo = f_b;
          break;
        }
        hi = b, f_hi = f_b;
      }
      found = true;
    } else {  // up until it stands
      lo = a, f_lo = f_a;
      for (int i = 0; i < 60 && !f.failed && lo < cap; ++i, step = std::min(4 * step, 1.0)) {
        hi = std::min(lo * (1 + step), cap);
        f_hi = f(hi);
        if (f_hi >= 0) {
          found = true;
          break;
        }
        lo = hi, f_lo = f_hi;
      }
    }
  }
  if (!found) {  // doubling from the least thickness
    lo = least, f_lo = -1.0;
    for (int i = 0; i < 60 && !f.failed && lo < cap; ++i) {
      hi = std::min(2 * lo, cap);
      f_hi = f(hi);
      if (f_hi >= 0) {
        found = true;
        break;
      }
      lo = hi, f_lo = f_hi;
    }
  }
  if (f.failed) return finish();
  if (!found) {
    out.note = fmt::format("no wall up to {:.6g} m thick holds the arch", cap);
    return finish();
  }
  // Illinois, as t_min's: regula falsi halving the value kept twice at one end.
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > kWallTolerance * hi && !f.failed; ++it) {
    double c = f_hi == 0 ? 0.5 * (lo + hi) : (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(c > lo && c < hi)) c = 0.5 * (lo + hi);
    const double f_c = f(c);
    if (f_c >= 0) {
      const double step = hi - c;
      hi = c, f_hi = f_c;
      if (side == 1) f_lo *= 0.5;
      side = 1;
      if (step <= kWallTolerance * hi) break;
    } else {
      lo = c, f_lo = f_c;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    }
  }
  out.b_min = f.failed ? kNaN : hi;
  return finish();
}

}  // namespace

WallSearch least_wall_thickness(const Scene& scene, const LimitOptions& options, const std::vector<double>& fractions,
                                double load_factor, double near, LimitResult& r, std::vector<double>& refinement) {
  if (!scene.has_walls()) return {};
  WallSearch w = search_wall_thickness(scene, options, fractions, load_factor, near);
  w.on = " on its walls";
  for (const std::optional<Wall>& wall : {scene.left_wall, scene.right_wall})
    if (wall && wall->thickness < w.b_min) w.thinner = fmt::format(" (a wall is thinner than b_min = {:.6g} m)", w.b_min);
  r.wall_thickness_min = w.b_min;
  r.lp_solves += w.solves;
  refinement.insert(refinement.end(), w.refinement.begin(), w.refinement.end());
  return w;
}

}  // namespace ogive::limit_detail
