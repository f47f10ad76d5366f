// The mechanism part of the spreading path (spreading.hpp): increments of the movement; at each, the
// voussoirs placed from the ring at d = 0 by finite rotations at the current hinges alone that close the
// chain exactly (a Newton iteration on three equations), the limit analysis' own program on them, and
// the hinges rolled to the program's contacts until the two agree.
#include "ogive/limit/spreading.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include "limit/limit_internal.hpp"

namespace ogive {
namespace {

using limit_detail::LimitLp;
using Vec = Eigen::Vector2d;

// z x r: the velocity at arm r of a unit rotation rate.
Vec perp(const Vec& r) { return {-r.y(), r.x()}; }

// A rigid motion x -> R(angle) x + shift.
struct Rigid {
  double angle = 0;
  Vec shift = Vec::Zero();
  Vec operator()(const Vec& p) const { return Eigen::Rotation2Dd(angle) * p + shift; }
  // x -> this(first(x)).
  Rigid after(const Rigid& first) const { return {angle + first.angle, Eigen::Rotation2Dd(angle) * first.shift + shift}; }
};
Rigid translation(const Vec& u) { return {0, u}; }
Rigid rotation_about(const Vec& p, double phi) { return {phi, p - Eigen::Rotation2Dd(phi) * p}; }

// Where the pieces are: each voussoir's motion from its place at d = 0, and each springing's.
struct Placement {
  std::vector<Rigid> voussoir;
  Rigid left, right;
};

Vec load_point(const VerticalLoad& l) { return {l.moment / l.force, l.height_moment / l.force}; }
VerticalLoad moved_load(const VerticalLoad& l, const Rigid& m) {
  if (l.force == 0) return l;
  const Vec p = m(load_point(l));
  return {l.force, l.force * p.x(), l.force * p.y()};
}

// ring0 with every voussoir (its centroid and its loads' points) where `at` puts it, and each joint
// midway between its two faces: the left one with the voussoir (or springing) before it, the right one
// with the voussoir after it.
void place_ring(const Ring& ring0, const Placement& at, Ring& ring) {
  ring = ring0;
  const std::size_t n = ring0.voussoirs.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Rigid& m = at.voussoir[k];
    Voussoir& v = ring.voussoirs[k];
    v.centroid = m(ring0.voussoirs[k].centroid);
    v.fill = moved_load(ring0.voussoirs[k].fill, m);
    v.live = moved_load(ring0.voussoirs[k].live, m);
  }
  for (std::size_t j = 0; j <= n; ++j) {
    const Rigid& a = j == 0 ? at.left : at.voussoir[j - 1];
    const Rigid& b = j == n ? at.right : at.voussoir[j];
    const Joint& j0 = ring0.joints[j];
    Joint& jt = ring.joints[j];
    jt.intrados = 0.5 * (a(j0.intrados) + b(j0.intrados));
    jt.extrados = 0.5 * (a(j0.extrados) + b(j0.extrados));
    jt.axis = 0.5 * (a(j0.axis) + b(j0.axis));
  }
}

// Every vertical load of the ring at factor 1 (self-weight, fill, live) by its point of action, with the
// voussoir it bears on.
template <class F>
void for_each_load(const Ring& ring, F&& f) {
  for (std::size_t k = 0; k < ring.voussoirs.size(); ++k) {
    const Voussoir& v = ring.voussoirs[k];
    if (v.weight != 0) f(k, v.weight, v.centroid);
    if (v.fill.force != 0) f(k, v.fill.force, load_point(v.fill));
    if (v.live.force != 0) f(k, v.live.force, load_point(v.live));
  }
}

// Which way a hinge's relative rotation (of the part after it against the part before it, counter-
// clockwise positive) opens its joint: +1 or -1; 0 for a pin, which turns either way. The face opposite
// the contact must move away from the voussoir before the joint.
double opening_sign(const Ring& ring, const Hinge& h) {
  if (h.face == Face::axis) return 0;
  const Joint& jt = ring.joints[static_cast<std::size_t>(h.joint)];
  const Vec q = h.face == Face::intrados ? jt.extrados : jt.intrados;
  const Vec e = jt.extrados - jt.intrados;
  Vec normal(e.y(), -e.x());  // oriented below towards the voussoir after the joint
  const std::size_t n = ring.voussoirs.size();
  const bool last = static_cast<std::size_t>(h.joint) >= n;  // the right springing: none after it
  const Vec c = ring.voussoirs[last ? n - 1 : static_cast<std::size_t>(h.joint)].centroid;
  if (normal.dot(c - jt.axis) < 0) normal = -normal;
  if (last) normal = -normal;
  return perp(q - h.point).dot(normal) >= 0 ? 1.0 : -1.0;
}

// A mechanism: its hinges (ascending) and their relative rotation rates per unit rate of d.
struct Mechanism {
  std::vector<Hinge> hinges;
  std::vector<double> rates;
  bool found() const { return !hinges.empty(); }
};

// The smallest-norm solution x of J x = r for a 3 x m J of rank 3; false when J has a smaller rank (the
// hinges are fewer than three or in a line) or the equations do not hold to round-off.
bool min_norm_solve(const Eigen::MatrixXd& J, const Eigen::Vector3d& r, Eigen::VectorXd& x) {
  if (J.cols() < 3) return false;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const auto& s = svd.singularValues();
  if (!(s(2) > 1e-10 * s(0))) return false;
  x = svd.solve(r);
  return true;
}

// Each hinge's column of the closure equations: the rotation it adds, and the velocity it gives the
// point `at` of the right springing (rotation rate times the arm from the hinge's point `q`).
Eigen::Vector3d closure_column(const Vec& at, const Vec& q) {
  const Vec v = perp(at - q);
  return {1.0, v.x(), v.y()};
}

// The mechanism of `hinges` under the springings' velocities vL, vR: relative rotation rates with sum 0
// (neither springing turns) that carry the right springing at vR - vL relative to the left one, the
// least squared; hinges that this would close are left out one by one (the worst first).
Mechanism choose_mechanism(const Ring& ring, std::vector<Hinge> hinges, const Vec& vL, const Vec& vR) {
  std::vector<double> sign(hinges.size());
  for (std::size_t i = 0; i < hinges.size(); ++i) sign[i] = opening_sign(ring, hinges[i]);
  for (;;) {
    const std::size_t m = hinges.size();
    Eigen::MatrixXd J(3, static_cast<Eigen::Index>(m));
    // The right springing's point taken at the first hinge: the rows are the same equations (the rates
    // sum to 0) with arms of the arch's size.
    const Vec at = m > 0 ? hinges.front().point : Vec::Zero();
    for (std::size_t i = 0; i < m; ++i) J.col(static_cast<Eigen::Index>(i)) = closure_column(at, hinges[i].point);
    Eigen::VectorXd x;
    const Vec dv = vR - vL;
    if (!min_norm_solve(J, Eigen::Vector3d(0, dv.x(), dv.y()), x)) return {};
    const double scale = x.cwiseAbs().maxCoeff();
    std::size_t worst = m;
    double worst_value = -1e-9 * scale;
    for (std::size_t i = 0; i < m; ++i) {
      const double opening = sign[i] * x(static_cast<Eigen::Index>(i));
      if (opening < worst_value) {
        worst_value = opening;
        worst = i;
      }
    }
    if (worst == m) return {std::move(hinges), std::vector<double>(x.data(), x.data() + m)};
    hinges.erase(hinges.begin() + static_cast<std::ptrdiff_t>(worst));
    sign.erase(sign.begin() + static_cast<std::ptrdiff_t>(worst));
  }
}

// The bodies of a chain cut at `hinges` (their points on the ring at d = 0, ascending) and turned there by
// the relative rotations phi (rad, of the part after a hinge against the part before it, counter-
// clockwise positive): the left springing's part moved by uL, each next one turned about its hinge.
void chain_bodies(const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi, const Vec& uL,
                  std::vector<Rigid>& bodies) {
  Rigid chain = translation(uL);
  bodies.assign(hinges.size() + 1, chain);
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    chain = chain.after(rotation_about(hinges[i].point, phi(static_cast<Eigen::Index>(i))));
    bodies[i + 1] = chain;
  }
}

// The relative rotations phi at `hinges` (points on the ring at d = 0) that close the chain on the right
// springing moved by uR when the left one has moved by uL: Newton's method from the given phi, each step
// the least-squares one (with three hinges the rotations are unique; with more, the closing rotations
// nearest the start). False when the iteration does not close the chain.
bool close_chain(const std::vector<Hinge>& hinges, const Vec& uL, const Vec& uR, double L, Eigen::VectorXd& phi,
                 std::vector<Rigid>& bodies) {
  const std::size_t m = hinges.size();
  for (int iteration = 0; iteration < 30; ++iteration) {
    chain_bodies(hinges, phi, uL, bodies);
    const Rigid& chain = bodies.back();
    const Eigen::Vector3d residual(chain.angle, chain.shift.x() - uR.x(), chain.shift.y() - uR.y());
    if (std::abs(residual(0)) <= 1e-15 && residual.tail<2>().norm() <= 1e-15 * L) {
      bodies.back() = translation(uR);  // equal to round-off: the springing's own motion
      return true;
    }
    Eigen::MatrixXd J(3, static_cast<Eigen::Index>(m));
    for (std::size_t i = 0; i < m; ++i) J.col(static_cast<Eigen::Index>(i)) = closure_column(chain.shift, bodies[i](hinges[i].point));
    Eigen::VectorXd step;
    if (!min_norm_solve(J, -residual, step)) return false;
    phi += step;
  }
  return false;
}

// Whether each relative rotation opens its joint (a face hinge turns one way only), to round-off.
bool all_open(const Ring& ring0, const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi) {
  const double scale = phi.size() > 0 ? phi.cwiseAbs().maxCoeff() : 0.0;
  for (std::size_t i = 0; i < hinges.size(); ++i)
    if (opening_sign(ring0, hinges[i]) * phi(static_cast<Eigen::Index>(i)) < -1e-9 * scale) return false;
  return true;
}

bool same_hinges(const std::vector<Hinge>& a, const std::vector<Hinge>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const Hinge& x, const Hinge& y) { return x.joint == y.joint && x.face == y.face; });
}

// The relative rotations of `to` taken from those of `from` (phi): a hinge that stays on its joint keeps
// its own; one that has rolled to another joint of the same face takes the rotation of the hinge it
// replaces (the nearest on that face, each given once); a new hinge starts from 0.
Eigen::VectorXd carried_rotations(const std::vector<Hinge>& from, const Eigen::VectorXd& phi,
                                  const std::vector<Hinge>& to) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(to.size()));
  std::vector<bool> taken(from.size(), false), given(to.size(), false);
  // The pairs of one face by their distance in joints, the nearest first (the same joint: 0).
  for (int distance = 0;;) {
    int next = std::numeric_limits<int>::max();
    for (std::size_t i = 0; i < to.size(); ++i) {
      for (std::size_t k = 0; k < from.size() && !given[i]; ++k) {
        if (taken[k] || from[k].face != to[i].face) continue;
        const int gap = std::abs(from[k].joint - to[i].joint);
        if (gap == distance) {
          out(static_cast<Eigen::Index>(i)) = phi(static_cast<Eigen::Index>(k));
          taken[k] = given[i] = true;
        } else if (gap > distance) {
          next = std::min(next, gap);
        }
      }
    }
    if (next == std::numeric_limits<int>::max()) break;
    distance = next;
  }
  return out;
}

// One admissible state of the path: its hinges where the ring at d = 0 has them with their relative
// rotations, where that puts the pieces, the program's answer and the mechanism that moves them on.
struct State {
  std::vector<Hinge> hinges;  // joint, face and the point on the ring at d = 0, ascending
  Eigen::VectorXd phi;        // rad, each hinge's relative rotation from d = 0
  Placement at;
  LimitLp::Answer answer;
  Mechanism mechanism;
  SpreadStep step;
};

enum class Outcome { admissible, inadmissible, snap_through, lp_failure, unsettled };

// Hinges that roll more often than this at one movement have found no state whose contacts are its
// hinges (a ring whose joints alternate at the same d; not seen on the tested arches).
constexpr int kMostRolls = 20;

class Path {
 public:
  Path(const Ring& ring0, const LimitOptions& limit, const SpreadOptions& spread)
      : ring0_(ring0),
        friction_(limit.friction),
        lp_(ring0, limit.friction),
        vL_(-spread.left_share, -spread.left_settlement_share),
        vR_(spread.right_share, -spread.right_settlement_share),
        live_factor_(ring0.has_live_load() ? 1.0 : 0.0) {}

  // The state at d = 0: the unmoved ring, its hinges those of the program's minimum-thrust (least-work)
  // state, none turned yet.
  Outcome start(State& s) {
    Placement at;
    at.voussoir.assign(ring0_.voussoirs.size(), Rigid{});
    const Outcome o = evaluate(std::move(at), 0, nullptr, s);
    if (o != Outcome::admissible) return o;
    s.hinges = on_ring0(s.mechanism.hinges);
    s.phi = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(s.hinges.size()));
    return o;
  }

  // The state at a further movement `dd` from `from`: the pieces placed from the ring at d = 0 with the
  // current hinges only (every other joint closed), the program solved on them; while its contacts are
  // not those hinges, the hinges roll to the contacts (a hinge's rotation going with it to its new
  // joint) and the placement and the program are made again.
  Outcome advance(const State& from, double dd, State& to) {
    const double d = from.step.d + dd;
    std::vector<Hinge> hinges = from.hinges;
    Eigen::VectorXd phi = from.phi;
    for (std::size_t i = 0; i < hinges.size(); ++i) phi(static_cast<Eigen::Index>(i)) += from.mechanism.rates[i] * dd;
    const std::vector<int>* warm = &from.answer.basis;
    std::vector<std::vector<Hinge>> seen;
    for (int roll = 0; roll <= kMostRolls; ++roll) {
      std::vector<Rigid> bodies;
      if (!close_chain(hinges, vL_ * d, vR_ * d, ring0_.span, phi, bodies)) return Outcome::snap_through;
      if (!all_open(ring0_, hinges, phi)) return Outcome::snap_through;
      const Outcome o = evaluate(placement(hinges, bodies), d, warm, to);
      if (o != Outcome::admissible) return o;
      const std::vector<Hinge> contacts = on_ring0(to.mechanism.hinges);
      if (same_hinges(contacts, hinges)) {
        to.hinges = std::move(hinges);
        to.phi = std::move(phi);
        return o;
      }
      if (std::any_of(seen.begin(), seen.end(), [&](const auto& h) { return same_hinges(h, contacts); })) break;
      seen.push_back(hinges);
      phi = carried_rotations(hinges, phi, contacts);
      hinges = contacts;
      warm = &to.answer.basis;
      ++rolls_;
    }
    return Outcome::unsettled;
  }

  int rolls() const { return rolls_; }

  // The state of the pieces `at`, movement d: the program's answer, its contacts' mechanism.
  Outcome evaluate(Placement at, double d, const std::vector<int>* warm, State& s) {
    place_ring(ring0_, at, moved_);
    lp_.load(moved_, friction_);
    // The least work on the movement: H (vR - vL).x - V_left vL.y - V_right vR.y, V_right = total - V_left.
    const LimitLp::Answer a = lp_.least_work(live_factor_, vR_.x() - vL_.x(), vR_.y() - vL_.y(), warm);
    if (a.outcome == LimitLp::Outcome::infeasible) return Outcome::inadmissible;
    if (a.outcome != LimitLp::Outcome::optimal) return Outcome::lp_failure;
    const ThrustState st = thrust_state(moved_, a.H, a.V, a.M, live_factor_);
    Mechanism mech = choose_mechanism(moved_, st.hinges, vL_, vR_);
    if (!mech.found()) return Outcome::snap_through;
    s.at = std::move(at);
    s.answer = a;
    s.mechanism = std::move(mech);
    SpreadStep& step = s.step;
    step.d = d;
    step.H = a.H;
    step.V_left = st.V_left;
    step.V_right = st.V_right;
    step.H_work = thrust_by_work(s.mechanism, st.V_left, st.V_right);
    const std::size_t cj = static_cast<std::size_t>(ring0_.crown_joint());
    step.crown_drop = ring0_.joints[cj].extrados.y() - moved_.joints[cj].extrados.y();
    step.potential = 0;
    for_each_load(moved_, [&](std::size_t, double f, const Vec& p) { step.potential += f * p.y(); });
    step.hinges = s.mechanism.hinges;
    return Outcome::admissible;
  }

  const Ring& moved() const { return moved_; }
  const Ring& ring() const { return ring0_; }

 private:
  // The hinges with their points on the ring at d = 0.
  std::vector<Hinge> on_ring0(std::vector<Hinge> hinges) const {
    for (Hinge& h : hinges) {
      const Joint& j = ring0_.joints[static_cast<std::size_t>(h.joint)];
      h.point = h.face == Face::intrados ? j.intrados : h.face == Face::extrados ? j.extrados : j.axis;
    }
    return hinges;
  }

  // Each piece's motion: the voussoirs before the first hinge with the left springing's body, those
  // between two hinges with their block's, those after the last with the right springing's.
  Placement placement(const std::vector<Hinge>& hinges, const std::vector<Rigid>& bodies) const {
    Placement at;
    at.voussoir.resize(ring0_.voussoirs.size());
    std::size_t body = 0;
    for (std::size_t k = 0; k < at.voussoir.size(); ++k) {
      while (body < hinges.size() && static_cast<std::size_t>(hinges[body].joint) <= k) ++body;
      at.voussoir[k] = bodies[body];
    }
    at.left = bodies.front();
    at.right = bodies.back();
    return at;
  }

  // The thrust by virtual work of the mechanism at the moved ring: each body's velocity per unit rate
  // of d, the loads' work -sum F v_y and the vertical reactions' V_left vL.y + V_right vR.y balanced by
  // the supports' H (vR - vL).x.
  double thrust_by_work(const Mechanism& mech, double V_left, double V_right) const {
    const std::vector<Hinge>& h = mech.hinges;
    double work = 0;
    std::size_t body = 0;
    for_each_load(moved_, [&](std::size_t k, double f, const Vec& p) {
      while (body < h.size() && static_cast<std::size_t>(h[body].joint) <= k) ++body;
      Vec v = vL_;
      for (std::size_t i = 0; i < body; ++i) v += mech.rates[i] * perp(p - h[i].point);
      work -= f * v.y();
    });
    return (work + V_left * vL_.y() + V_right * vR_.y()) / (vR_.x() - vL_.x());
  }

  const Ring& ring0_;
  const double friction_;
  LimitLp lp_;
  Ring moved_;
  const Vec vL_, vR_;
  const double live_factor_;
  int rolls_ = 0;
};

}  // namespace

const char* to_string(SpreadCollapse c) {
  return c == SpreadCollapse::thrust_leaves_arch ? "thrust_leaves_arch" : "snap_through";
}

const char* to_string(SpreadStatus s) {
  switch (s) {
    case SpreadStatus::success: return "success";
    case SpreadStatus::inadmissible: return "inadmissible";
    case SpreadStatus::no_mechanism: return "no_mechanism";
    case SpreadStatus::lp_failure: return "lp_failure";
    case SpreadStatus::not_collapsed: return "not_collapsed";
    case SpreadStatus::unsettled: return "unsettled";
    case SpreadStatus::not_converged: return "not_converged";
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
  if (!std::isfinite(left_settlement_share)) return bad("left_settlement_share must be finite");
  if (!std::isfinite(right_settlement_share)) return bad("right_settlement_share must be finite");
  if (!(increment_ratio >= kLeastIncrementRatio && increment_ratio <= 0.1))
    return bad("increment_ratio must lie in [1e-4, 0.1] (finer increments take longer without moving the capacity)");
  if (steps < 1 || steps > 100000) return bad("steps must be in [1, 100000]");
  if (!(stop_ratio >= 0)) return bad("stop_ratio must be >= 0 (infinity: to collapse)");
  return true;
}

// The shape of a state on the path, for drawing: its program solved again to have the moved ring and
// its thrust line.
SpreadShape shape_of(Path& path, const State& current) {
  const Ring& ring0 = path.ring();
  State last;
  path.evaluate(current.at, current.step.d, &current.answer.basis, last);
  SpreadShape shape;
  shape.thrust_line = thrust_state(path.moved(), last.answer.H, last.answer.V, last.answer.M,
                                   ring0.has_live_load() ? 1.0 : 0.0).crossing;
  shape.voussoirs.resize(ring0.voussoirs.size());
  for (std::size_t k = 0; k < ring0.voussoirs.size(); ++k) {
    const Rigid& m = current.at.voussoir[k];
    const Joint &a = ring0.joints[k], &b = ring0.joints[k + 1];
    shape.voussoirs[k] = {m(a.intrados), m(a.extrados), m(b.extrados), m(b.intrados)};
  }
  return shape;
}

// The path's printed rows: d = 0, the state reached at or before each d_end i / steps, and the last.
std::vector<SpreadStep> printed_rows(const std::vector<SpreadStep>& all, int steps) {
  std::vector<SpreadStep> rows{all.front()};
  std::size_t k = 0;
  const double end = all.back().d;
  for (int i = 1; i < steps; ++i) {
    const double target = end * i / steps;
    while (k + 1 < all.size() && all[k + 1].d <= target) ++k;
    if (all[k].d > rows.back().d) rows.push_back(all[k]);
  }
  if (all.back().d > rows.back().d || rows.size() == 1) rows.push_back(all.back());
  return rows;
}

// Every state of the path, or (SpreadOptions::whole_path false) the first and the last only.
class Recorder {
 public:
  explicit Recorder(bool whole) : whole_(whole) {}
  void add(const SpreadStep& s) {
    if (whole_ || all_.size() < 2) all_.push_back(s);
    else all_.back() = s;
  }
  const SpreadStep& front() const { return all_.front(); }
  const SpreadStep& back() const { return all_.back(); }
  std::vector<SpreadStep> rows(int steps) const { return whole_ ? printed_rows(all_, steps) : all_; }

 private:
  bool whole_;
  std::vector<SpreadStep> all_;
};

// The path on the ring `ring` (the limit analysis' `base` gives the state at d = 0 where it has none).
SpreadResult follow(const Ring& ring, const LimitResult& base, const LimitOptions& limit, const SpreadOptions& spread) {
  SpreadResult r;
  r.ring = ring;
  const Ring& ring0 = r.ring;
  const double L = ring0.span;
  const double sides = spread.left_share + spread.right_share;
  Path path(ring0, limit, spread);

  State current;
  const Outcome first = path.start(current);
  if (first != Outcome::admissible) {
    if (first == Outcome::snap_through) {  // admissible, but nothing moves the springings apart
      r.status = SpreadStatus::no_mechanism;
      r.message = "the hinges of the state at d = 0 make no mechanism that moves the springings apart";
      SpreadStep s;
      s.H = base.min_state.H;
      s.V_left = base.min_state.V_left;
      s.V_right = base.min_state.V_right;
      s.hinges = base.min_state.hinges;
      r.path.push_back(s);
      return r;
    }
    r.status = first == Outcome::lp_failure ? SpreadStatus::lp_failure : SpreadStatus::inadmissible;
    r.message = first == Outcome::lp_failure ? "the LP of the minimum thrust stopped without an answer"
                                             : "no thrust line fits inside the arch at d = 0";
    return r;
  }

  Recorder all(spread.whole_path);
  all.add(current.step);
  const double increment = spread.increment_ratio * L / sides;
  const double tolerance = kSpreadTolerance * L / sides;
  const double stop = spread.stop_ratio * L / sides;  // infinity without a stop
  // A span that grew by more than 2.5 L has outgrown any arch: both halves lie flat before that.
  const long most = static_cast<long>(std::ceil(2.5 / spread.increment_ratio));
  auto failed = [&](Outcome o) {
    r.status = o == Outcome::lp_failure ? SpreadStatus::lp_failure : SpreadStatus::unsettled;
    r.message = o == Outcome::lp_failure
                    ? "the LP of the minimum thrust stopped without an answer"
                    : "the hinges found no state whose contacts are its hinges beyond a span increase of " +
                          std::to_string(sides * current.step.d / L) + " L";
    r.path = {all.front(), all.back()};
    return r;
  };
  State next;
  for (long i = 0;; ++i) {
    if (i == most) {
      r.status = SpreadStatus::not_collapsed;
      r.message = "no collapse before the span grew by 2.5 L (both halves would lie flat before that)";
      r.path = {all.front(), all.back()};
      return r;
    }
    // The last increment ends at the stop, if there is one before collapse.
    const double to_stop = stop - current.step.d;
    const bool stops = to_stop <= increment;
    Outcome o = path.advance(current, stops ? to_stop : increment, next);
    ++r.increments;
    if (o == Outcome::admissible) {
      std::swap(current, next);
      all.add(current.step);
      if (stops) {
        r.stopped = true;
        break;
      }
      continue;
    }
    if (o == Outcome::lp_failure || o == Outcome::unsettled) return failed(o);
    // Collapse within this increment: bisect it from the current state.
    double lo = 0, hi = stops ? to_stop : increment;
    Outcome last_bad = o;
    bool moved_on = false;
    State best;
    while (hi - lo > tolerance) {
      const double mid = 0.5 * (lo + hi);
      const Outcome om = path.advance(current, mid, next);
      ++r.increments;
      if (om == Outcome::lp_failure || om == Outcome::unsettled) return failed(om);
      if (om == Outcome::admissible) {
        lo = mid;
        std::swap(best, next);
        moved_on = true;
      } else {
        hi = mid;
        last_bad = om;
      }
    }
    if (moved_on) {
      current = std::move(best);
      all.add(current.step);
    }
    r.collapse = last_bad == Outcome::inadmissible ? SpreadCollapse::thrust_leaves_arch : SpreadCollapse::snap_through;
    break;
  }
  if (!r.stopped) r.d_max = current.step.d;
  r.rolls = path.rolls();
  r.shape = shape_of(path, current);
  r.path = all.rows(spread.steps);
  r.status = SpreadStatus::success;
  return r;
}

// Whether two rings' hinges are at the same places (joints of one ring need not have the other's numbers).
bool same_places(const std::vector<Hinge>& a, const std::vector<Hinge>& b, double L) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [&](const Hinge& x, const Hinge& y) {
    return x.face == y.face && (x.point - y.point).norm() <= 1e-9 * L;
  });
}

// The hinges at collapse that can roll on: those on a face, but not on a springing's joint.
std::vector<Hinge> rolling_hinges(const Ring& ring, const std::vector<Hinge>& hinges) {
  std::vector<Hinge> out;
  const int last = static_cast<int>(ring.joints.size()) - 1;
  for (const Hinge& h : hinges)
    if (h.face != Face::axis && h.joint > 0 && h.joint < last) out.push_back(h);
  return out;
}

// The longest arc length (m) of the two voussoirs on each side of each hinge.
double coarsest_next_to(const Ring& ring, const std::vector<Hinge>& hinges) {
  double most = 0;
  const int n = static_cast<int>(ring.voussoirs.size());
  for (const Hinge& h : hinges)
    for (int k = std::max(h.joint - 2, 0); k < std::min(h.joint + 2, n); ++k)
      most = std::max(most, ring.joints[static_cast<std::size_t>(k + 1)].s - ring.joints[static_cast<std::size_t>(k)].s);
  return most;
}

// The capacity depends on where the ring has joints for the hinges to roll to (the hinges at collapse
// sit where the thrust line grazes a face; a joint nearer that point lets the path go on): the path is
// followed again on a ring whose voussoirs next to the hinges at collapse are halved, until they are
// no longer than kSpreadJointSpacing L and the capacity moved by at most kSpreadCapacityTolerance of itself at
// the last refinement.
SpreadResult analyse_spreading(const Scene& scene, const LimitOptions& limit, const SpreadOptions& spread) {
  std::string why;
  if (!spread.is_valid(&why)) throw std::invalid_argument("SpreadOptions: " + why);
  if (scene.has_walls()) throw std::invalid_argument("left_wall, right_wall: the spreading analysis takes no walls");
  const LimitResult base = analyse_limit(scene, limit);
  if (base.status == LimitStatus::inadmissible || !base.min_state.found()) {
    SpreadResult r;
    r.ring = base.ring;
    r.status = base.status == LimitStatus::lp_failure ? SpreadStatus::lp_failure : SpreadStatus::inadmissible;
    r.message = base.message.empty() ? "no thrust line fits inside the arch at d = 0" : base.message;
    return r;
  }
  const double sides = spread.left_share + spread.right_share;
  SpreadOptions round = spread;  // the rounds to collapse, keeping the first and last states only
  round.whole_path = false;
  round.stop_ratio = std::numeric_limits<double>::infinity();
  SpreadResult r = follow(base.ring, base, limit, round);
  std::vector<double> fractions = r.ring.joint_fractions;
  int increments = r.increments, rolls = r.rolls;
  double change = 0;  // no refinement: nothing moved
  bool stayed = false;  // a finer ring changed the state at d = 0: the last ring's path stands
  for (int refinement = 0; r.status == SpreadStatus::success && refinement < kMostSpreadRefinements; ++refinement) {
    const std::vector<Hinge> rolling = rolling_hinges(r.ring, r.path.back().hinges);
    if (rolling.empty() || (refinement > 0 && coarsest_next_to(r.ring, rolling) <= kSpreadJointSpacing * r.ring.span &&
                            change <= kSpreadCapacityTolerance))
      break;
    limit_detail::add_refinement(r.ring, rolling, fractions);
    fractions = limit_detail::merged_fractions(std::move(fractions));
    SpreadResult finer = follow(limit_detail::make_ring_at(scene, limit, fractions), base, limit, round);
    increments += finer.increments;
    rolls += finer.rolls;
    if (finer.status != SpreadStatus::success) return finer;
    // A finer ring that resolves the state at d = 0 into other contacts (a pointed arch's thrust line
    // grazing its extrados over several of the new joints) starts another path: the last ring's stands
    // (docs/spreading.md measures how far it has converged).
    if (!same_places(finer.path.front().hinges, r.path.front().hinges, r.ring.span)) {
      stayed = true;
      break;
    }
    // Relative to the capacity, but not below kSpreadCapacityFloor of the span (an arch near t_min,
    // whose capacity is next to nothing).
    change = std::abs(finer.d_max - r.d_max) / std::max(finer.d_max, kSpreadCapacityFloor * r.ring.span / sides);
    r = std::move(finer);
  }
  const bool converged = r.status != SpreadStatus::success || stayed || change <= kSpreadCapacityTolerance;
  SpreadResult out = r;
  if (spread.whole_path || spread.stop_ratio < std::numeric_limits<double>::infinity()) {
    out = follow(r.ring, base, limit, spread);
    out.increments += increments;
    out.rolls += rolls;
  } else {
    out.increments = increments;
    out.rolls = rolls;
  }
  if (out.status == SpreadStatus::success && !converged) {
    out.status = SpreadStatus::not_converged;
    out.message = "the capacity still moved by " + std::to_string(change) + " of itself at the last refinement of the joints";
  }
  return out;
}

}  // namespace ogive
