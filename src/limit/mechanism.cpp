// The kinematic check of limit analysis: the multiplier of a mechanism through given hinges by virtual
// work (mechanism_load_factor, mechanism_horizontal_load_factor in limit.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/LU>
#include <fmt/format.h>

#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The multiplier of one mechanism with hinges h (sorted by joint, distinct joints): NaN unless it has
// exactly one degree of freedom, the live load does work in it, and it is kinematically admissible
// (each face hinge opens on the face opposite to its own; a pin turns either way). `live`: what the
// multiplier multiplies (limit_internal.hpp).
double one_mechanism(const Ring& ring, const std::vector<Hinge>& h, limit_detail::LiveKind live) {
  // Bodies b = 0 .. k-2 between consecutive hinges, each with a rigid velocity (u, v, omega): a point p
  // moves with (u - omega p_y, v + omega p_x). The parts outside the first and last hinges stay put.
  const int k = static_cast<int>(h.size()), bodies = k - 1;
  const double L = ring.span;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * k, 3 * bodies);
  for (int i = 0; i < k; ++i) {
    const Eigen::Vector2d p = h[i].point / L;
    // Velocity of the body right of hinge i minus that of the body left of it, at the hinge.
    for (int b : {i - 1, i}) {
      if (b < 0 || b >= bodies) continue;  // the ground
      const double sign = b == i ? 1.0 : -1.0;
      A(2 * i, 3 * b) += sign;
      A(2 * i, 3 * b + 2) -= sign * p.y();
      A(2 * i + 1, 3 * b + 1) += sign;
      A(2 * i + 1, 3 * b + 2) += sign * p.x();
    }
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  lu.setThreshold(1e-10);
  Eigen::VectorXd mode = lu.kernel();
  if (lu.dimensionOfKernel() != 1) return kNaN;
  // The work of downward forces on a voussoir: minus force times the vertical velocity v + omega x of
  // its body, summed over the forces: -(v F + omega sum x F); with `push` = a, plus that of the
  // horizontal forces a F, a F times the horizontal velocity u - omega y: a (u F - omega sum y F).
  // `weight` times the vertical work, plus `push` times the horizontal one.
  auto work = [&](int voussoir, const VerticalLoad& load, double weight, double push) {
    for (int b = 0; b < bodies; ++b)
      if (voussoir >= h[b].joint && voussoir < h[b + 1].joint) {
        const double vertical = -(mode(3 * b + 1) * load.force + mode(3 * b + 2) * load.moment / L);
        if (push == 0) return weight * vertical;
        return weight * vertical + push * (mode(3 * b) * load.force - mode(3 * b + 2) * load.height_moment / L);
      }
    return 0.0;
  };
  const bool horizontal = live == limit_detail::LiveKind::horizontal;
  double live_work = 0, dead_work = 0;
  for (std::size_t v = 0; v < ring.voussoirs.size(); ++v) {
    const int i = static_cast<int>(v);
    const Voussoir& vs = ring.voussoirs[v];
    if (horizontal) {
      live_work += work(i, vs.dead(), 0.0, 1.0);
      dead_work += work(i, vs.dead(), 1.0, 0.0) + work(i, vs.live, 1.0, 0.0);
    } else {
      live_work += work(i, vs.live, 1.0, 0.0);
      dead_work += work(i, vs.dead(), 1.0, ring.acceleration);
    }
  }
  if (!(std::abs(live_work) > 1e-12 * std::abs(dead_work))) return kNaN;
  if (live_work < 0) {  // the sense in which the load does positive work
    mode = -mode;
    live_work = -live_work;
    dead_work = -dead_work;
  }
  // A hinge on the intrados opens the extrados: the right part turns clockwise relative to the left one
  // (omega_right - omega_left < 0); on the extrados, counter-clockwise.
  const double scale = mode.tail(1).cwiseAbs().maxCoeff() + mode.cwiseAbs().maxCoeff();
  for (int i = 0; i < k; ++i) {
    if (h[i].face == Face::axis) continue;
    const double right = i < bodies ? mode(3 * i + 2) : 0.0, left = i > 0 ? mode(3 * (i - 1) + 2) : 0.0;
    const double turn = (right - left) * (h[i].face == Face::intrados ? 1.0 : -1.0);
    if (turn > 1e-9 * scale) return kNaN;
  }
  return -dead_work / live_work;
}

}  // namespace

namespace limit_detail {

LeastMechanism least_mechanism(const Ring& ring, const std::vector<Hinge>& hinges, LiveKind live) {
  LeastMechanism out;
  if (hinges.size() < 3) return out;
  std::vector<Hinge> sorted = hinges;
  std::sort(sorted.begin(), sorted.end(), [](const Hinge& a, const Hinge& b) { return a.joint < b.joint; });
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].joint == sorted[i - 1].joint) return out;
  if (sorted.size() <= 4) {
    out.factor = one_mechanism(ring, sorted, live);
    if (!std::isnan(out.factor)) out.hinges = std::move(sorted);
    return out;
  }
  // A thrust line tangent to a face touches a run of consecutive joints on it (the finer the joints,
  // the longer the run): the first, middle and last of each run stand for it.
  std::vector<Hinge> h;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i + 1;
    while (j < sorted.size() && sorted[j].joint == sorted[j - 1].joint + 1 && sorted[j].face == sorted[i].face) ++j;
    h.push_back(sorted[i]);
    if (j - i > 2) h.push_back(sorted[i + (j - i) / 2]);
    if (j - i > 1) h.push_back(sorted[j - 1]);
    i = j;
  }
  if (h.size() > kMaxMechanismHinges) return out;
  // More hinges than a one-degree mechanism has (a degenerate optimum: e.g. the thrust line along an
  // intrados chord touches two adjacent joints): every admissible mechanism of four of them is an upper
  // bound (the kinematic theorem); the least is the multiplier of these hinges.
  const std::size_t n = h.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d) {
          std::vector<Hinge> four{h[a], h[b], h[c], h[d]};
          const double m = one_mechanism(ring, four, live);
          if (!std::isnan(m) && !(m >= out.factor)) {
            out.factor = m;
            out.hinges = std::move(four);
          }
        }
  return out;
}

}  // namespace limit_detail

double mechanism_load_factor(const Ring& ring, const std::vector<Hinge>& hinges) {
  if (!ring.has_live_load()) return kNaN;
  return limit_detail::least_mechanism(ring, hinges, limit_detail::LiveKind::vertical).factor;
}

double mechanism_horizontal_load_factor(const Ring& ring, const std::vector<Hinge>& hinges) {
  if (!(ring.total_dead() != 0.0)) return kNaN;
  return limit_detail::least_mechanism(ring, hinges, limit_detail::LiveKind::horizontal).factor;
}

namespace limit_detail {

// Makes r an lp_failure, and says why, when the static multiplier of a collapse and the kinematic one of
// its hinges disagree (neither absent); true then. The two are the same number computed twice (the
// thrust line passes through the mechanism's hinges, so the virtual work of its loads vanishes at the
// static multiplier): a difference says that the program's answer is off by as much.
bool fails_virtual_work(LimitResult& r, const char* what, double static_factor, double kinematic_factor) {
  if (std::isnan(static_factor) || std::isnan(kinematic_factor)) return false;
  const double scale = std::max(std::abs(static_factor), std::abs(kinematic_factor));
  if (std::abs(static_factor - kinematic_factor) <= kStaticKinematicTolerance * scale) return false;
  const std::string why = fmt::format("the {} of the linear program ({:.6g}) and the virtual work of its mechanism "
                                      "({:.6g}) disagree: the program's answer is not to be trusted",
                                      what, static_factor, kinematic_factor);
  r.status = LimitStatus::lp_failure;
  r.message = r.message.empty() ? why : why + "; " + r.message;
  return true;
}

}  // namespace limit_detail
}  // namespace ogive
