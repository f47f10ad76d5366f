// The mechanism part of the spreading path (spreading.hpp). The crown hinge's position is found in
// closed form (two circles), so the finite rotations are exact; the program is the limit analysis' own.
#include "ogive/limit/spreading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <Eigen/Geometry>

#include "limit/limit_internal.hpp"

namespace ogive {
namespace {

using limit_detail::LimitLp;
using Vec = Eigen::Vector2d;

using limit_detail::cross;

// A rigid motion p -> centre' + R(angle) (p - centre).
struct Motion {
  Vec centre = Vec::Zero(), moved = Vec::Zero();
  double angle = 0;
  Vec operator()(const Vec& p) const { return moved + Eigen::Rotation2Dd(angle) * (p - centre); }
};

// The four bodies: left support part, left block, right block, right support part.
struct Configuration {
  Motion body[4];
  Vec crown;  // the crown hinge, moved
};

struct Mechanism {
  int joint[3];  // left, crown, right hinge joints
  Vec point[3];  // their points at d = 0
  double left_share, right_share;
};

// The configuration at movement d; false when the two circles do not meet (the hinges are collinear).
bool configure(const Mechanism& m, double d, Configuration& c) {
  const Vec uL(-m.left_share * d, 0), uR(m.right_share * d, 0);
  const Vec p1 = m.point[0] + uL, p3 = m.point[2] + uR;
  const double a = (m.point[1] - m.point[0]).norm(), b = (m.point[1] - m.point[2]).norm();
  const Vec chord = p3 - p1;
  const double c_len = chord.norm();
  if (c_len >= a + b || c_len <= std::abs(a - b)) return false;
  // The crown hinge on the same side of the chord as at d = 0 (the branch the motion follows).
  const double along = (a * a - b * b + c_len * c_len) / (2 * c_len);
  const double off = std::sqrt(std::max(0.0, a * a - along * along));
  const Vec e = chord / c_len, n(-e.y(), e.x());
  const double side = cross(m.point[2] - m.point[0], m.point[1] - m.point[0]) >= 0 ? 1.0 : -1.0;
  c.crown = p1 + along * e + side * off * n;
  auto angle_of = [](const Vec& v) { return std::atan2(v.y(), v.x()); };
  c.body[0] = {Vec::Zero(), uL, 0};
  c.body[1] = {m.point[0], p1, angle_of(c.crown - p1) - angle_of(m.point[1] - m.point[0])};
  c.body[2] = {m.point[2], p3, angle_of(c.crown - p3) - angle_of(m.point[1] - m.point[2])};
  c.body[3] = {Vec::Zero(), uR, 0};
  return true;
}

// The body of voussoir k, and of joint j's left side.
int body_of_voussoir(const Mechanism& m, int k) {
  return k < m.joint[0] ? 0 : k < m.joint[1] ? 1 : k < m.joint[2] ? 2 : 3;
}

Vec load_point(const VerticalLoad& l) { return {l.moment / l.force, l.height_moment / l.force}; }
VerticalLoad moved_load(const VerticalLoad& l, const Motion& mo) {
  if (l.force == 0) return l;
  const Vec p = mo(load_point(l));
  return {l.force, l.force * p.x(), l.force * p.y()};
}

// The ring moved into configuration c: every point with its body, the hinge joints as pins through
// their hinge points.
void move_ring(const Ring& ring0, const Mechanism& m, const Configuration& c, Ring& ring) {
  ring = ring0;
  for (std::size_t k = 0; k < ring.voussoirs.size(); ++k) {
    const Motion& mo = c.body[body_of_voussoir(m, static_cast<int>(k))];
    Voussoir& v = ring.voussoirs[k];
    v.centroid = mo(ring0.voussoirs[k].centroid);
    v.fill = moved_load(ring0.voussoirs[k].fill, mo);
    v.live = moved_load(ring0.voussoirs[k].live, mo);
  }
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const int k = std::max(0, static_cast<int>(j) - 1);  // the voussoir on its left (the first: its right)
    const Motion& mo = c.body[j == 0 ? 0 : body_of_voussoir(m, k)];
    Joint& jt = ring.joints[j];
    jt.intrados = mo(ring0.joints[j].intrados);
    jt.extrados = mo(ring0.joints[j].extrados);
    jt.axis = mo(ring0.joints[j].axis);
  }
  for (int h = 0; h < 3; ++h) {
    const Motion& mo = c.body[h == 0 ? 0 : h];  // the left side's body of each hinge joint
    ring.joints[m.joint[h]].axis = mo(m.point[h]);
    ring.pins.push_back(m.joint[h]);
  }
  std::sort(ring.pins.begin(), ring.pins.end());
  ring.pins.erase(std::unique(ring.pins.begin(), ring.pins.end()), ring.pins.end());
}

// Whether every hinge opens (the face opposite its contact separates into the arch's direction) by more
// than -gap_floor; at d = 0 nothing has opened.
bool hinges_open(const Ring& ring0, const Mechanism& m, const Configuration& c, double gap_floor) {
  for (int h = 0; h < 3; ++h) {
    const Joint& j = ring0.joints[m.joint[h]];
    const bool contact_intrados = (m.point[h] - j.intrados).norm() < (m.point[h] - j.extrados).norm();
    const Vec q = contact_intrados ? j.extrados : j.intrados;
    const Vec gap = c.body[h + 1](q) - c.body[h](q);
    const Vec e = j.extrados - j.intrados;
    const Vec towards_right(e.y(), -e.x());  // the joint's normal pointing to the next voussoir
    // Which way the joint's normal points: towards the voussoir on its right, or (the right springing's
    // joint, with none there) away from the one on its left.
    const int voussoirs = static_cast<int>(ring0.voussoirs.size());
    const bool right_springing = m.joint[h] >= voussoirs;
    const Vec centroid = ring0.voussoirs[right_springing ? voussoirs - 1 : m.joint[h]].centroid;
    const double side = towards_right.dot(centroid - j.axis) >= 0 ? 1.0 : -1.0;
    const double sign = right_springing ? -side : side;
    if (sign * towards_right.normalized().dot(gap) < -gap_floor) return false;
  }
  return true;
}

// Every vertical load of the ring at factor 1 (self-weight, fill, live) by its point of action.
template <class F>
void for_each_load(const Ring& ring, F&& f) {
  for (const Voussoir& v : ring.voussoirs) {
    if (v.weight != 0) f(v.weight, v.centroid);
    if (v.fill.force != 0) f(v.fill.force, load_point(v.fill));
    if (v.live.force != 0) f(v.live.force, load_point(v.live));
  }
}

// The mechanism's thrust by virtual work at configuration c of the moved ring: the velocities per unit
// rate of d (the closure's derivative at c), then the supports' work -H (left_share + right_share)
// balances the loads' -sum F v_y.
double thrust_by_work(const Ring& moved, const Mechanism& m, const Configuration& c) {
  const Vec vL(-m.left_share, 0), vR(m.right_share, 0);
  const Vec a = c.crown - c.body[1].moved, b = c.crown - c.body[2].moved;
  // vL + w1 z x a = vR + w3 z x b, z x r = (-r_y, r_x).
  Eigen::Matrix2d A;
  A << -a.y(), b.y(), a.x(), -b.x();
  const Eigen::Vector2d w = A.fullPivLu().solve(Eigen::Vector2d(vR.x() - vL.x(), vR.y() - vL.y()));
  const double omega[4] = {0, w(0), w(1), 0};
  const Vec base[4] = {Vec::Zero(), c.body[1].moved, c.body[2].moved, Vec::Zero()};
  const Vec vel[4] = {vL, vL, vR, vR};
  double work = 0;
  for (std::size_t k = 0; k < moved.voussoirs.size(); ++k) {
    const int body = body_of_voussoir(m, static_cast<int>(k));
    const Voussoir& v = moved.voussoirs[k];
    auto vy = [&](const Vec& p) { return vel[body].y() + omega[body] * (p - base[body]).x(); };
    if (v.weight != 0) work -= v.weight * vy(v.centroid);
    if (v.fill.force != 0) work -= v.fill.force * vy(load_point(v.fill));
    if (v.live.force != 0) work -= v.live.force * vy(load_point(v.live));
  }
  return work / (m.left_share + m.right_share);
}

// The mechanism's hinges among `hinges` (indices; -1 when missing): the one nearest the crown joint cj
// and the nearest one on each side of it.
struct MechanismHinges {
  int left = -1, crown = -1, right = -1;
};
MechanismHinges mechanism_hinges(const std::vector<Hinge>& hinges, int cj) {
  MechanismHinges m;
  for (std::size_t i = 0; i < hinges.size(); ++i)
    if (m.crown < 0 || std::abs(hinges[i].joint - cj) < std::abs(hinges[m.crown].joint - cj)) m.crown = static_cast<int>(i);
  for (std::size_t i = 0; m.crown >= 0 && i < hinges.size(); ++i) {
    const int j = hinges[i].joint, c = hinges[m.crown].joint;
    if (j < c && (m.left < 0 || j > hinges[m.left].joint)) m.left = static_cast<int>(i);
    if (j > c && (m.right < 0 || j < hinges[m.right].joint)) m.right = static_cast<int>(i);
  }
  return m;
}

struct Evaluation {
  bool admissible = false;
  bool snap = false;
  bool lp_failed = false;
  SpreadStep step;
};

}  // namespace

const char* to_string(SpreadCollapse c) { return c == SpreadCollapse::inadmissible ? "inadmissible" : "snap_through"; }

const char* to_string(SpreadStatus s) {
  switch (s) {
    case SpreadStatus::success: return "success";
    case SpreadStatus::inadmissible: return "inadmissible";
    case SpreadStatus::no_mechanism: return "no_mechanism";
    case SpreadStatus::lp_failure: return "lp_failure";
  }
  return "?";
}

bool SpreadOptions::is_valid(std::string* why) const {
  auto bad = [&](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(left_share >= 0) || !std::isfinite(left_share)) return bad("left_share must be finite and >= 0");
  if (!(right_share >= 0) || !std::isfinite(right_share)) return bad("right_share must be finite and >= 0");
  if (!(left_share + right_share > 0)) return bad("left_share + right_share must be > 0 (the span must grow)");
  if (steps < 1 || steps > 100000) return bad("steps must be in [1, 100000]");
  return true;
}

SpreadResult analyse_spreading(const Scene& scene, const LimitOptions& limit, const SpreadOptions& spread) {
  std::string why;
  if (!spread.is_valid(&why)) throw std::invalid_argument("SpreadOptions: " + why);
  SpreadResult r;
  const LimitResult base = analyse_limit(scene, limit);
  r.ring = base.ring;
  if (base.status == LimitStatus::inadmissible || !base.min_state.found()) {
    r.status = base.status == LimitStatus::lp_failure ? SpreadStatus::lp_failure : SpreadStatus::inadmissible;
    r.message = base.message.empty() ? "no thrust line fits inside the arch at d = 0" : base.message;
    return r;
  }
  const Ring& ring0 = base.ring;
  const std::vector<Hinge>& hinges = base.min_state.hinges;
  const auto [left, crown, right] = mechanism_hinges(hinges, ring0.crown_joint());
  if (left < 0 || right < 0) {
    r.status = SpreadStatus::no_mechanism;
    r.message = "the minimum-thrust state has no hinge on each side of its crown hinge";
    return r;
  }
  Mechanism m{{hinges[left].joint, hinges[crown].joint, hinges[right].joint},
              {hinges[left].point, hinges[crown].point, hinges[right].point},
              spread.left_share,
              spread.right_share};
  r.hinge_joints = {m.joint[0], m.joint[1], m.joint[2]};
  const double L = ring0.span;
  const double lf = ring0.has_live_load() ? 1.0 : 0.0;

  Ring moved;
  LimitLp lp(ring0, limit.friction);
  auto evaluate = [&](double d) {
    Evaluation ev;
    Configuration c;
    if (!configure(m, d, c) || (d > 0 && !hinges_open(ring0, m, c, 1e-12 * L))) {
      ev.snap = true;
      return ev;
    }
    move_ring(ring0, m, c, moved);
    lp.load(moved, limit.friction);
    const LimitLp::Answer a = lp.extreme_thrust(lf, false);
    if (a.outcome == LimitLp::Outcome::infeasible) return ev;
    if (a.outcome != LimitLp::Outcome::optimal) {
      ev.lp_failed = true;
      return ev;
    }
    const ThrustState st = thrust_state(moved, a.H, a.V, a.M, lf);
    ev.admissible = true;
    ev.step.d = d;
    ev.step.H = a.H;
    ev.step.V_left = st.V_left;
    ev.step.V_right = st.V_right;
    ev.step.H_work = thrust_by_work(moved, m, c);
    ev.step.crown_drop = m.point[1].y() - c.crown.y();
    double potential = 0;
    for_each_load(moved, [&](double f, const Vec& p) { potential += f * p.y(); });
    ev.step.potential = potential;
    ev.step.hinges = {c.body[1].moved, c.crown, c.body[2].moved};
    return ev;
  };

  Evaluation first = evaluate(0);
  if (!first.admissible) {
    r.status = first.lp_failed ? SpreadStatus::lp_failure : SpreadStatus::inadmissible;
    r.message = "no thrust line through the minimum-thrust state's hinges fits the arch at d = 0";
    return r;
  }
  // Bracket the collapse by doubling, then bisect.
  double lo = 0, hi = 1e-5 * L;
  Evaluation last_bad;
  for (;;) {
    Evaluation ev = evaluate(hi);
    if (ev.lp_failed) {
      r.status = SpreadStatus::lp_failure;
      r.message = "the LP of the minimum thrust stopped without an answer";
      return r;
    }
    if (!ev.admissible) {
      last_bad = ev;
      break;
    }
    lo = hi;
    hi *= 2;
  }
  while (hi - lo > kSpreadTolerance * L) {
    const double mid = 0.5 * (lo + hi);
    Evaluation ev = evaluate(mid);
    if (ev.admissible) lo = mid;
    else {
      last_bad = ev;
      hi = mid;
    }
  }
  r.collapse = last_bad.snap ? SpreadCollapse::snap_through : SpreadCollapse::inadmissible;
  r.d_max = lo;
  if (lo == 0 && last_bad.snap) {  // the hinges do not move this way at all: no mechanism, not a capacity of 0
    r.status = SpreadStatus::no_mechanism;
    r.message = "the minimum-thrust state's three hinges nearest the crown do not open under this movement (a "
                "pointed arch turns about two hinges beside its crown: four hinges)";
    r.path.push_back(first.step);
    return r;
  }
  r.path.reserve(spread.steps + 1);
  r.path.push_back(first.step);
  for (int i = 1; i <= spread.steps; ++i) {
    Evaluation ev = evaluate(lo * i / spread.steps);
    if (!ev.admissible) {  // a window of inadmissibility inside the bracket: collapse is there
      r.d_max = r.path.back().d;
      break;
    }
    r.path.push_back(ev.step);
  }
  r.status = SpreadStatus::success;
  return r;
}

}  // namespace ogive
