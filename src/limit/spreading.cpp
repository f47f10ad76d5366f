// The mechanism part of the spreading path (spreading.hpp): increments of the movement; at each, the
// voussoirs placed from the ring at d = 0 by finite rotations at the current hinges alone that close the
// chain exactly (a Newton iteration on three equations), the limit analysis' own program on them, and
// the hinges rolled to the program's contacts until the two agree.
#include "ogive/limit/spreading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>
#include <stdexcept>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "limit/limit_internal.hpp"
#include "limit/spreading_chain.hpp"
#include "limit/spreading_crushing.hpp"
#include "limit/spreading_walls.hpp"

namespace ogive {
namespace {

using limit_detail::LimitLp;
using namespace spreading_detail;

// One admissible state of the path: its hinges where the ring at d = 0 has them with their relative
// rotations, where that puts the pieces, the program's answer and the mechanism that moves them on.
struct State {
  std::vector<Hinge> hinges;  // joint, face and the point on the ring at d = 0, ascending
  Eigen::VectorXd phi;        // rad, each hinge's relative rotation from d = 0
  Placement at;
  LimitLp::Answer answer;
  Mechanism mechanism;
  SpreadStep step;
  int sliding = -1;  // the joint whose resultant leaves the friction cone (sliding_joint), or -1
  Tipping tipping;   // on walls: the bed whose resultant leaves its wall (none: the walls carry the state)
  std::vector<Hinge> contacts, resultants;  // where the thrust line touches: turning points; resultants' points
  std::vector<Vec> force;                   // N/m, each joint's (ThrustState::force)
  Vec crossing_left = Vec::Zero(), crossing_right = Vec::Zero();  // m, where the springings' reactions cross
  // Each hinge's relative rotation rate per unit rate of d, to start the next increment from: the
  // mechanism's (none where it left a hinge out: the next placement is found from phi alone).
  Eigen::VectorXd rates;
};

enum class Outcome { admissible, inadmissible, snap_through, lp_failure, unsettled, sliding, wall_tips };

// A contact further than this along its face (arc length over the span) from every hinge on that face
// has not rolled there: the thrust line has come to touch the face at a second place, a new hinge.
constexpr double kNewHingeReach = 0.05;
// A hinge with a contact this many joints from it, or fewer, on its face has rolled there.
constexpr int kRollJoints = 2;

// Hinges that roll more often than this at one movement have found no state whose contacts are its
// hinges (a ring whose joints alternate at the same d; not seen on the tested arches).
constexpr int kMostRolls = 20;

// With a finite strength a state is placed again about its own turning points until they agree to this (of L).
constexpr double kPointsAgree = 1e-12;
constexpr int kMostReplacements = 30;  // at most (they agree after two to four)

class Path {
 public:
  // `walls`: the walls that move the springings, ring0 their arch (nullptr: as `spread` says).
  Path(const Ring& ring0, const LimitOptions& limit, const SpreadOptions& spread, SpreadWalls* walls = nullptr)
      : ring0_(ring0),
        friction_(limit.friction),
        compressive_strength_(limit.compressive_strength),
        lp_(ring0, 0.0, nullptr, limit_detail::LpSolver::dense, limit_detail::LiveKind::vertical,
            limit.compressive_strength),
        vL_(walls ? walls->left() : SpringingMotion::sliding(Vec(-spread.left_share, -spread.left_settlement_share))),
        vR_(walls ? walls->right() : SpringingMotion::sliding(Vec(spread.right_share, -spread.right_settlement_share))),
        live_factor_(ring0.has_live_load() ? 1.0 : 0.0),
        walls_(walls) {}

  // The state at d = 0: the unmoved ring, its hinges those of the program's minimum-thrust (least-work)
  // state, none turned yet.
  Outcome start(State& s) {
    Placement at;
    at.voussoir.assign(ring0_.voussoirs.size(), Rigid{});
    const Outcome o = evaluate(std::move(at), 0, nullptr, s);
    if (o != Outcome::admissible) return o;
    if (s.sliding >= 0) return Outcome::sliding;
    if (s.tipping.tips()) return tips(s.tipping);
    s.hinges = on_ring0(s.mechanism.hinges);
    s.phi = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(s.hinges.size()));
    s.rates = Eigen::Map<const Eigen::VectorXd>(s.mechanism.rates.data(), static_cast<Eigen::Index>(s.mechanism.rates.size()));
    return o;
  }

  // The state at a further movement `dd` from `from`: the pieces placed from the ring at d = 0 with the
  // current hinges only (every other joint closed), the program solved on them; while its contacts are
  // not those hinges, the hinges roll to the contacts (a hinge's rotation going with it to its new
  // joint) and the placement and the program are made again.
  Outcome advance(const State& from, double dd, State& to) {
    const double d = from.step.d + dd;
    snap_point_ = Vec::Constant(std::numeric_limits<double>::quiet_NaN());
    std::vector<Hinge> hinges = from.hinges;
    Eigen::VectorXd phi = from.phi + from.rates * dd;
    const std::vector<int>* warm = &from.answer.basis;
    std::vector<std::vector<Hinge>> seen;
    int replacements = 0;
    for (int roll = 0; roll <= kMostRolls; ++roll) {
      std::vector<Rigid> bodies;
      if (!close_chain(hinges, vL_.at(d), vR_.at(d), ring0_.span, phi, bodies)) return Outcome::snap_through;
      if (hinges.size() == 4) {
        const Eigen::VectorXd unbalanced = phi;
        if (!balance(ring0_, hinges, vL_.at(d), vR_.at(d), phi, bodies)) {
          // The loads drive the free mode on: where would the blocks come to rest? The program on the
          // chain closed without balance says which joints the thrust line would touch.
          if (!close_chain(hinges, vL_.at(d), vR_.at(d), ring0_.span, phi = unbalanced, bodies)) return Outcome::snap_through;
          if (evaluate(placement(hinges, bodies), d, warm, to) != Outcome::admissible) return Outcome::snap_through;
          return snapped(hinges, phi, on_ring0(to.mechanism.hinges), d, warm);
        }
      }
      if (!all_open(ring0_, hinges, phi)) {
        // Of four hinges, one whose joint has closed again (its rotation back through zero) is none.
        if (hinges.size() != 4) return Outcome::snap_through;
        const std::size_t shut = most_closed(ring0_, hinges, phi);
        hinges.erase(hinges.begin() + static_cast<std::ptrdiff_t>(shut));
        Eigen::VectorXd rest(3);
        for (Eigen::Index i = 0, k = 0; i < 4; ++i)
          if (static_cast<std::size_t>(i) != shut) rest(k++) = phi(i);
        phi = rest;
        ++rolls_;
        continue;
      }
      const Outcome o = evaluate(placement(hinges, bodies), d, warm, to);
      if (o != Outcome::admissible) return o;
      const std::vector<Hinge> contacts = on_ring0(hinges.size() == 4 ? to.contacts : to.mechanism.hinges);
      const bool own = same_hinges(on_ring0(to.mechanism.hinges), hinges) || grazed_beside(hinges, to);
      // Four hinges in balance: the thrust line passes through each (the mechanism may leave one out
      // whose rate would close it: it turns with the others, its joint still open).
      if (own || (hinges.size() == 4 && same_hinges(on_ring0(to.contacts), hinges))) {
        // A settled state (not a placement on the way to it) that a joint would slide out of.
        if (to.sliding >= 0) return Outcome::sliding;
        if (to.tipping.tips()) return tips(to.tipping);  // a state of the arch that a wall does not carry
        if (own)
          to.rates = Eigen::Map<const Eigen::VectorXd>(to.mechanism.rates.data(), static_cast<Eigen::Index>(hinges.size()));
        else
          to.rates = Eigen::VectorXd::Zero(4);
        if (!own) to.step.hinges = to.resultants;  // all four, where they are now
        std::vector<Hinge> own_points = with_points_of(hinges, own ? on_ring0(to.mechanism.hinges) : on_ring0(to.contacts));
        if (std::isfinite(compressive_strength_) && farthest_apart(own_points, hinges) > kPointsAgree * ring0_.span) {
          if (++replacements > kMostReplacements) break;
          hinges = std::move(own_points);
          warm = &to.answer.basis;
          --roll;
          continue;
        }
        to.hinges = std::move(own_points);
        to.phi = std::move(phi);
        return o;
      }
      if (std::any_of(seen.begin(), seen.end(), [&](const auto& h) { return same_hinges(h, contacts); })) {
        // The hinge goes back and forth between two joints (the thrust line grazes the face between
        // them): both open, the voussoirs between them turning so that the thrust line passes through
        // both (the four hinges' balance), tried once.
        std::vector<Hinge> both = union_of(hinges, contacts);
        if (both.size() != 4 || std::any_of(seen.begin(), seen.end(), [&](const auto& h) { return same_hinges(h, both); }))
          break;
        seen.push_back(hinges);
        phi = kept_rotations(hinges, phi, both);
        hinges = std::move(both);
        warm = &to.answer.basis;
        ++rolls_;
        continue;
      }
      seen.push_back(hinges);
      std::vector<Hinge> next;
      bool snaps = false;
      if (!rolled_or_new(hinges, phi, contacts, next, phi, snaps)) {
        if (snaps) return snapped(hinges, phi, contacts, d, warm);
        break;
      }
      hinges = std::move(next);
      warm = &to.answer.basis;
      ++rolls_;
    }
    return Outcome::unsettled;
  }

  int rolls() const { return rolls_; }
  // On walls, where the last state a wall does not carry gives way (after the bisection: the collapse's).
  const Tipping& tipping() const { return tipping_; }

  // Whether `to` is settled on `hinges` alone, its other contacts grazing beside them (grazed_mechanism):
  // with a finite strength within kNewHingeReach; without, on the short joints of a refined ring only
  // (within 2 kSpreadJointSpacing), where a line nearly parallel to a face touches two joints at once.
  bool grazed_beside(const std::vector<Hinge>& hinges, State& to) const {
    const double reach = (std::isfinite(compressive_strength_) ? kNewHingeReach : 2 * kSpreadJointSpacing) * ring0_.span;
    Mechanism mech = grazed_mechanism(ring0_, moved_, hinges, to.contacts, vL_.twist, vR_.twist, reach);
    if (!mech.found()) return false;
    to.mechanism = std::move(mech);
    to.step.H_work = thrust_by_work(to, to.step.V_left, to.step.V_right);
    to.step.hinges = with_points_of(to.mechanism.hinges, to.resultants);
    return true;
  }

  // New hinges that no balance holds: the loads move the blocks on at fixed springings. If the chain
  // with `contacts` as its hinges (where the blocks would come to rest) has no thrust line inside it
  // either, the arch falls (Outcome::inadmissible: thrust_leaves_arch); else the blocks snap to another
  // state, which the path does not follow (Outcome::snap_through).
  Outcome snapped(const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi, const std::vector<Hinge>& contacts,
                  double d, const std::vector<int>* warm) {
    Eigen::VectorXd rest = carried_rotations(hinges, phi, contacts);
    std::vector<Rigid> bodies;
    State there;
    if (close_chain(contacts, vL_.at(d), vR_.at(d), ring0_.span, rest, bodies) && all_open(ring0_, contacts, rest) &&
        evaluate(placement(contacts, bodies), d, warm, there) == Outcome::inadmissible)
      return Outcome::inadmissible;
    for (const Hinge& c : contacts)
      if (std::none_of(hinges.begin(), hinges.end(), [&](const Hinge& h) { return h.joint == c.joint && h.face == c.face; }))
        snap_point_ = c.point;
    return Outcome::snap_through;
  }
  // Where the last movement's new hinge is on the ring at d = 0 (NaN: none; after a snap_through, none
  // means the hinges came into a line).
  const Vec& snap_point() const { return snap_point_; }

  // Where the hinges go when the program's contacts are others. A contact within kNewHingeReach L of a
  // hinge on its face is that hinge rolled there, its rotation going with it (a hinge whose neighbour
  // within kRollJoints joints is a contact has rolled into it); a contact further from every hinge on
  // its face is a new hinge, from no rotation, and an opened hinge with no contact next to it stays open
  // (the thrust line must still cross its joint there): four hinges, in balance. False when nothing
  // changes, or (`snaps`) when more than four would be open: new hinges that no balance of four holds.
  bool rolled_or_new(const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi, const std::vector<Hinge>& contacts,
                     std::vector<Hinge>& next, Eigen::VectorXd& next_phi, bool& snaps) {
    const auto s = [&](const Hinge& h) { return ring0_.joints[static_cast<std::size_t>(h.joint)].s; };
    const auto is_new = [&](const Hinge& c) {
      return std::none_of(hinges.begin(), hinges.end(), [&](const Hinge& h) {
        return h.face == c.face && std::abs(s(h) - s(c)) <= kNewHingeReach * ring0_.span;
      });
    };
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < hinges.size(); ++k) {
      // With a finite strength: within kNewHingeReach along the grazed offset curve (spreading.hpp).
      const bool rolled = std::any_of(contacts.begin(), contacts.end(), [&](const Hinge& c) {
        if (std::isfinite(compressive_strength_))
          return c.face == hinges[k].face && std::abs(s(c) - s(hinges[k])) <= kNewHingeReach * ring0_.span;
        return c.face == hinges[k].face && std::abs(c.joint - hinges[k].joint) <= kRollJoints;
      });
      if (!rolled && phi(static_cast<Eigen::Index>(k)) != 0) kept.push_back(k);
    }
    const Eigen::VectorXd carried = carried_rotations(hinges, phi, contacts);
    if (kept.empty() && std::none_of(contacts.begin(), contacts.end(), is_new)) {  // rolls alone, as ever
      next_phi = carried;
      next = contacts;
      return !same_hinges(next, hinges);
    }
    std::vector<std::pair<Hinge, double>> out;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      if (is_new(contacts[i])) snap_point_ = contacts[i].point;  // where a snap would start
      out.emplace_back(contacts[i], is_new(contacts[i]) ? 0.0 : carried(static_cast<Eigen::Index>(i)));
    }
    for (const std::size_t k : kept) out.emplace_back(hinges[k], phi(static_cast<Eigen::Index>(k)));
    if (out.size() > 4) {
      snaps = true;
      return false;
    }
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first.joint < b.first.joint; });
    next.clear();
    next_phi.resize(static_cast<Eigen::Index>(out.size()));
    for (std::size_t i = 0; i < out.size(); ++i) {
      next.push_back(out[i].first);
      next_phi(static_cast<Eigen::Index>(i)) = out[i].second;
    }
    return !same_hinges(next, hinges);
  }

  // The state of the pieces `at`, movement d: the program's answer, its contacts' mechanism.
  Outcome evaluate(Placement at, double d, const std::vector<int>* warm, State& s) {
    place_ring(ring0_, at, moved_);
    lp_.load(moved_, 0.0, compressive_strength_);  // the program without friction: the cone is checked on its state
    // The least work on the movement: H (vR - vL).x - V_left vL.y - V_right vR.y, V_right = total - V_left.
    // On walls, per_M the rotation rates' difference: the reactions' moments about the toes (spreading.hpp).
    const Vec dv = vR_.twist.velocity - vL_.twist.velocity;
    const LimitLp::Answer a = lp_.least_work(live_factor_, dv.x(), dv.y(), vR_.twist.rate - vL_.twist.rate, warm);
    if (a.outcome == LimitLp::Outcome::infeasible) return Outcome::inadmissible;
    if (a.outcome != LimitLp::Outcome::optimal) return Outcome::lp_failure;
    const ThrustState st = thrust_state(moved_, a.H, a.V, a.M, live_factor_, 1e-9, compressive_strength_);
    std::vector<Hinge> turning = turning_points(moved_, st, compressive_strength_);
    Mechanism mech = choose_mechanism(moved_, turning, vL_.twist, vR_.twist);
    if (!mech.found()) return Outcome::snap_through;
    s.sliding = sliding_joint(moved_, st, friction_);
    s.tipping = walls_ ? walls_->tipping(at, a.H, a.V, a.M, live_factor_, friction_, compressive_strength_) : Tipping{};
    s.contacts = std::move(turning);
    s.resultants = st.hinges;
    s.force = st.force;
    s.crossing_left = st.crossing.front();
    s.crossing_right = st.crossing.back();
    s.at = std::move(at);
    s.answer = a;
    s.mechanism = std::move(mech);
    SpreadStep& step = s.step;
    step.d = d;
    step.H = a.H;
    step.V_left = st.V_left;
    step.V_right = st.V_right;
    step.H_work = thrust_by_work(s, st.V_left, st.V_right);
    step.span_increase = (moved_.joints.back().intrados.x() - moved_.joints.front().intrados.x()) -
                         (ring0_.joints.back().intrados.x() - ring0_.joints.front().intrados.x());
    const std::size_t cj = static_cast<std::size_t>(ring0_.crown_joint());
    step.crown_drop = ring0_.joints[cj].extrados.y() - moved_.joints[cj].extrados.y();
    step.potential = 0;
    for_each_load(moved_, [&](std::size_t, double f, const Vec& p) { step.potential += f * p.y(); });
    step.hinges = with_points_of(s.mechanism.hinges, st.hinges);  // where the resultants cross
    return Outcome::admissible;
  }

  const Ring& moved() const { return moved_; }
  double compressive_strength() const { return compressive_strength_; }
  const Ring& ring() const { return ring0_; }

 private:
  // The hinges of the moved ring with their points on the ring at d = 0: a face's point, or with a
  // finite compressive strength the point as far inside the face (along the joint, in its fraction of
  // the joint's length) as the hinge's point on the moved ring (where its blocks turn: turning_points).
  std::vector<Hinge> on_ring0(std::vector<Hinge> hinges) const {
    for (Hinge& h : hinges) {
      const std::size_t k = static_cast<std::size_t>(h.joint);
      const Joint& j = ring0_.joints[k];
      if (h.face == Face::axis) {
        h.point = j.axis;
        continue;
      }
      const Vec& face = h.face == Face::intrados ? j.intrados : j.extrados;
      if (!std::isfinite(compressive_strength_)) {
        h.point = face;
        continue;
      }
      const Joint& moved = moved_.joints[k];
      const Vec& moved_face = h.face == Face::intrados ? moved.intrados : moved.extrados;
      const double inside = (h.point - moved_face).norm() / (moved.extrados - moved.intrados).norm();
      const Vec& other = h.face == Face::intrados ? j.extrados : j.intrados;
      h.point = face + inside * (other - face);
    }
    return hinges;
  }

  Placement placement(const std::vector<Hinge>& hinges, const std::vector<Rigid>& bodies) const {
    return spreading_detail::placement(ring0_.voussoirs.size(), hinges, bodies);
  }

  // The thrust by virtual work of the mechanism at the moved ring: each body's velocity per unit rate
  // of d, the loads' work -sum F v_y and the vertical reactions' V_left vL.y + V_right vR.y balanced by
  // the supports' H (vR - vL).x, each springing's velocity at the point its reaction crosses the
  // springing joint (the state's crossings: the program's; the same everywhere on a translating
  // springing), and (with a finite strength) the crushing blocks' dissipation.
  double thrust_by_work(const State& s, double V_left, double V_right) const {
    const Mechanism& mech = s.mechanism;
    const std::vector<Hinge>& h = mech.hinges;
    double work = 0;
    std::size_t body = 0;
    for_each_load(moved_, [&](std::size_t k, double f, const Vec& p) {
      while (body < h.size() && static_cast<std::size_t>(h[body].joint) <= k) ++body;
      Vec v = vL_.twist.at(p);
      for (std::size_t i = 0; i < body; ++i) v += mech.rates[i] * perp(p - h[i].point);
      work -= f * v.y();
    });
    if (std::isfinite(compressive_strength_)) work -= crushing_dissipation(moved_, mech, s.force, compressive_strength_);
    const Vec vl = vL_.twist.at(s.crossing_left), vr = vR_.twist.at(s.crossing_right);
    return (work + V_left * vl.y() + V_right * vr.y()) / (vr.x() - vl.x());
  }

  const Ring& ring0_;
  const double friction_;
  const double compressive_strength_;  // f_c, Pa (infinity: none)
  LimitLp lp_;
  Ring moved_;
  const SpringingMotion vL_, vR_;
  const double live_factor_;
  SpreadWalls* walls_;
  Tipping tipping_;

  Outcome tips(const Tipping& t) {
    tipping_ = t;
    return t.slides ? Outcome::sliding : Outcome::wall_tips;
  }
  int rolls_ = 0;
  Vec snap_point_ = Vec::Constant(std::numeric_limits<double>::quiet_NaN());
};

}  // namespace

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

std::string snap_message(const Vec& point, double span) {
  char x[32];
  std::snprintf(x, sizeof x, "%.6g", point.x() / span);
  return std::string("a hinge forms at x = ") + x +
         " L (where the arch stood at d = 0) that no balance of the hinges holds: the blocks move on at fixed "
         "springings";
}

std::string sliding_message(const Vec& point, double span) {
  char x[32];
  std::snprintf(x, sizeof x, "%.6g", point.x() / span);
  return std::string("the joint at x = ") + x + " L slides: its resultant leaves the friction cone";
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

// The frictionless minimum-thrust state leaves the friction cone at `joint`: the path is the state at
// d = 0 with friction (limit's, `base`), and it slides at once.
SpreadResult slides_at_once(SpreadResult r, const LimitResult& base, int joint) {
  SpreadStep s;
  s.H = s.H_work = base.min_state.H;
  s.V_left = base.min_state.V_left;
  s.V_right = base.min_state.V_right;
  s.hinges = base.min_state.hinges;
  r.path.push_back(s);
  r.status = SpreadStatus::success;
  r.collapse = SpreadCollapse::sliding;
  r.d_max = 0;
  r.sliding_joint = joint;
  r.sliding_point = r.ring.joints[static_cast<std::size_t>(joint)].axis;
  r.message = sliding_message(r.sliding_point, r.ring.span);
  return r;
}

// The path on the ring `ring` (the limit analysis' `base` gives the state at d = 0 where it has none).
SpreadResult follow(const Ring& ring, const LimitResult& base, const LimitOptions& limit, const SpreadOptions& spread) {
  SpreadResult r;
  std::optional<SpreadWalls> walls = SpreadWalls::of(ring, spread);  // on walls the path is the arch's
  r.ring = walls ? walls->arch() : ring;
  const Ring& ring0 = r.ring;
  const double L = ring0.span;
  const double sides = walls ? walls->span_rate() : spread.left_share + spread.right_share;
  Path path(ring0, limit, spread, walls ? &*walls : nullptr);
  r.span_rate = sides;

  State current;
  const Outcome first = path.start(current);
  if (first == Outcome::sliding && current.sliding >= 0) return slides_at_once(std::move(r), base, current.sliding);
  if (first == Outcome::wall_tips || first == Outcome::sliding) return walls->tips_at_once(std::move(r), current.step, path.tipping());
  if (first != Outcome::admissible) {
    if (first == Outcome::snap_through) {  // admissible, but nothing moves the springings apart
      r.status = SpreadStatus::no_mechanism;
      r.message = "the hinges of the state at d = 0 make no mechanism that moves the springings apart";
      SpreadStep s;
      s.H = base.min_state.H;
      s.V_left = base.min_state.V_left;
      s.V_right = base.min_state.V_right;
      s.hinges = base.min_state.hinges;
      if (walls) s.hinges = walls->arch_hinges(s.hinges);
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
    int sliding = next.sliding;
    Vec snap = path.snap_point();
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
        sliding = next.sliding;
        snap = path.snap_point();
      }
    }
    if (moved_on) {
      current = std::move(best);
      all.add(current.step);
    }
    r.collapse = last_bad == Outcome::inadmissible ? SpreadCollapse::thrust_leaves_arch
                 : last_bad == Outcome::sliding    ? SpreadCollapse::sliding
                 : last_bad == Outcome::wall_tips  ? SpreadCollapse::wall_tips
                                                   : SpreadCollapse::snap_through;
    if (r.collapse == SpreadCollapse::sliding) r.sliding_joint = sliding;
    if (r.collapse == SpreadCollapse::snap_through && std::isfinite(snap.x())) r.message = snap_message(snap, L);
    break;
  }
  if (!r.stopped) r.d_max = current.step.d;
  r.rolls = path.rolls();
  r.shape = shape_of(path, current);  // leaves path.moved() the last state's ring
  if (r.sliding_joint >= 0) {
    r.sliding_point = path.moved().joints[static_cast<std::size_t>(r.sliding_joint)].axis;
    r.message = sliding_message(r.sliding_point, L);
  }
  r.path = all.rows(spread.steps);
  r.status = SpreadStatus::success;
  if (walls) walls->at_collapse(r, path.tipping());
  return r;
}

// The capacity depends on where the ring has joints for the hinges to roll to (the hinges at collapse
// sit where the thrust line grazes a face; a joint nearer that point lets the path go on): the path is
// followed again on a ring whose voussoirs next to the hinges at collapse are halved, until they are
// no longer than kSpreadJointSpacing L and the capacity moved by at most kSpreadCapacityTolerance of itself at
// the last refinement.
SpreadResult analyse_spreading(const Scene& scene, const LimitOptions& limit, const SpreadOptions& spread) {
  std::string why;
  if (!spread.is_valid(&why)) throw std::invalid_argument("SpreadOptions: " + why);
  if (scene.has_walls()) check_spread_on_walls(scene, spread);
  // The ring and the path are those without friction (the cone is checked on each state); the state at
  // d = 0 with friction, and whether there is one, is limit's with it.
  LimitOptions frictionless = limit;
  frictionless.friction = 0;
  const LimitResult base = analyse_limit(scene, frictionless);
  const LimitResult with_friction = limit.friction > 0 ? analyse_limit(scene, limit) : LimitResult{};
  const LimitResult& start = limit.friction > 0 ? with_friction : base;
  for (const LimitResult* each : {&base, &start}) {
    if (each->status == LimitStatus::inadmissible || !each->min_state.found()) {
      SpreadResult r;
      r.ring = base.ring;
      r.status = each->status == LimitStatus::lp_failure ? SpreadStatus::lp_failure : SpreadStatus::inadmissible;
      r.message = each == &base || each->status == LimitStatus::lp_failure
                      ? (each->message.empty() ? "no thrust line fits inside the arch at d = 0" : each->message)
                      : "no state of the arch at d = 0 keeps every joint's resultant inside the friction cone";
      return r;
    }
  }
  const double sides = scene.has_walls() ? SpreadWalls(base.ring, spread).span_rate() : spread.left_share + spread.right_share;
  SpreadOptions round = spread;  // the rounds to collapse, keeping the first and last states only
  round.whole_path = false;
  round.stop_ratio = std::numeric_limits<double>::infinity();
  SpreadResult r = follow(base.ring, start, limit, round);
  Ring system;  // on walls, the ring with the walls of r (r.ring is the arch's alone)
  if (scene.has_walls()) system = base.ring;
  std::vector<double> fractions = r.ring.joint_fractions;
  int increments = r.increments, rolls = r.rolls;
  double change = 0;  // no refinement: nothing moved
  bool other_start = false;  // the last refinement changed the state at d = 0
  bool grazed = false;       // joints were put where the line grazes the faces at d = 0
  std::optional<std::pair<SpreadResult, double>> before;  // the path and change before that
  // With a finite strength, and on walls, the capacity follows the hinges at d = 0 (spreading.hpp): they are refined
  // next to as well (to kSpreadJointSpacing), and a finer ring that only slides them along their faces resolves them.
  const bool follows_start = std::isfinite(limit.compressive_strength) || scene.has_walls();
  for (int refinement = 0; r.status == SpreadStatus::success && refinement < kMostSpreadRefinements; ++refinement) {
    std::vector<Hinge> rolling = rolling_hinges(r.ring, r.path.back().hinges);
    for (const Hinge& h : follows_start ? rolling_hinges(r.ring, r.path.front().hinges) : std::vector<Hinge>{})
      if (coarsest_next_to(r.ring, {h}) > kSpreadJointSpacing * r.ring.span) rolling.push_back(h);
    if (rolling.empty() || r.d_max == 0 || (refinement > 0 && coarsest_next_to(r.ring, rolling) <= kSpreadJointSpacing * r.ring.span &&
                            change <= kSpreadCapacityTolerance))
      break;
    limit_detail::add_refinement(r.ring, rolling, fractions);
    fractions = limit_detail::merged_fractions(std::move(fractions));
    Ring finer_ring = limit_detail::make_ring_at(scene, frictionless, fractions);
    SpreadResult finer = follow(finer_ring, start, limit, round);
    increments += finer.increments, rolls += finer.rolls;
    if (finer.status != SpreadStatus::success && !before) return finer;
    if (finer.status != SpreadStatus::success && (change = std::numeric_limits<double>::infinity())) break;
    // Relative to the capacity, but not below kSpreadCapacityFloor of the span (an arch near t_min,
    // whose capacity is next to nothing).
    change = std::abs(finer.d_max - r.d_max) / std::max(finer.d_max, kSpreadCapacityFloor * r.ring.span / sides);
    // A finer ring that resolves the state at d = 0 into other contacts (a pointed arch's thrust line
    // grazing its extrados over several of the new joints, and a path from there no nearer the arch's)
    // starts another path: the last ring's stands, its capacity checked against the finer one's (with a
    // finite strength hinges at d = 0 that only slid along their faces are that state resolved further).
    if (!same_places(finer.path.front().hinges, r.path.front().hinges, r.ring.span) &&
        !(follows_start && slid_along(finer.path.front().hinges, r.path.front().hinges, kNewHingeReach * r.ring.span))) {
      // A hinge at d = 0 that stays to collapse (a pointed arch's haunch) carries the capacity with its
      // joint: once, joints where the path's line at d = 0 grazes the continuous arch's faces, which the
      // finer rings keep (on walls and with crushing the refinement next to those hinges resolves them).
      const bool graze_now = !follows_start && !grazed && change > kSpreadCapacityTolerance;
      const std::vector<double> graze =
          graze_now ? grazing_fractions(scene, frictionless, r.ring, start_state(r.ring, r.path.front()))
                    : std::vector<double>{};
      grazed = true;
      if ((other_start = graze.empty())) break;
      before.emplace(r, change);  // what stands where the ring with them does not converge
      fractions = with_grazing(r.ring, std::move(fractions), graze);
      r = follow(limit_detail::make_ring_at(scene, frictionless, fractions), start, limit, round);
      increments += r.increments, rolls += r.rolls;
      change = std::numeric_limits<double>::infinity(), refinement = -1;  // starts over from that ring
      continue;
    }
    r = std::move(finer);
    if (scene.has_walls()) system = std::move(finer_ring);
  }
  if (before && !(r.status == SpreadStatus::success && change <= kSpreadCapacityTolerance)) {
    std::tie(r, change) = *before;  // the ring with grazing joints did not settle it: as without them
    other_start = true;
  }
  const bool converged = r.status != SpreadStatus::success || change <= kSpreadCapacityTolerance;  // to 1e-3
  SpreadResult out = r;
  if (spread.whole_path || spread.stop_ratio < std::numeric_limits<double>::infinity()) {
    out = follow(scene.has_walls() ? system : r.ring, start, limit, spread);
    out.increments += increments, out.rolls += rolls;
  } else {
    out.increments = increments;
    out.rolls = rolls;
  }
  if (out.status == SpreadStatus::success && !converged) {
    // Most often a state at d = 0 that each finer ring resolves into other contacts (a point load's, a
    // springing's that settles), the path from each another.
    out.status = SpreadStatus::not_converged;
    out.message = fmt::format("the capacity moved by {:.2g} of itself at the last refinement of the joints{}{}", change,
                              other_start ? " (whose ring changed the state at d = 0: the coarser ring's path is given)" : "",
                              out.message.empty() ? "" : "; " + out.message);
  }
  return out;
}

}  // namespace ogive
