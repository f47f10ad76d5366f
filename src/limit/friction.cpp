// Non-associative friction (Gilbert, Casapulla & Ahmed 2006): the iteration on the normal forces that
// the sliding rows hold (limit_internal.hpp, non_associative); and the refinement next to the joints that
// slide (add_sliding_refinement).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive {

const char* to_string(FrictionModel f) {
  switch (f) {
    case FrictionModel::associative: return "associative";
    case FrictionModel::non_associative: return "non_associative";
  }
  return "unknown";
}

namespace limit_detail {

// A joint whose force is this close to Coulomb's cone (relative to the force) slides in the state: far
// above the programs' row tolerance (1e-11 of the load), far below any margin a state keeps.
constexpr double kOnCone = 1e-9;

void add_sliding_refinement(const Ring& ring, const ThrustState& st, const LimitOptions& options,
                            std::vector<double>& out) {
  if (!(options.friction > 0) || st.force.size() != ring.joints.size())
    return;
  std::vector<Hinge> sliding;
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const Joint& joint = ring.joints[j];
    const Eigen::Vector2d along = (joint.extrados - joint.intrados).normalized();
    const Eigen::Vector2d& F = st.force[j];
    const double N = cross(F, along), T = F.dot(along);  // compression positive, as thrust_state's
    if (std::abs(T) >= options.friction * N - kOnCone * F.norm())
      sliding.push_back({static_cast<int>(j), Face::intrados, joint.intrados});
  }
  add_refinement(ring, sliding, out);
}

namespace {

// Non-associative friction (Gilbert, Casapulla & Ahmed 2006): the iterations at the most, the change of
// the normal forces (relative to the ring's loads, dead plus live at the factor found) at which they have
// converged, and the under-relaxation's floor.
constexpr int kMaxSlidingIterations = 4000;
constexpr double kSlidingTolerance = 1e-10;
constexpr double kSlidingRelaxationFloor = 1.0 / 64;
// The shortest step tried towards held forces with no state before giving up.
constexpr double kSlidingRetryFloor = 1e-6;

// The factor a hair below the optimum at which the iteration looks for the optimal state nearest the
// held normal forces (at the optimum itself the set can be empty by round-off).
constexpr double kBelowOptimum = 1e-10;

// Of the states at `a`'s factor (times 1 - kBelowOptimum) between the least and the largest thrust, the
// one whose normal forces are nearest `held` (least squares); `a` itself when those programs fail.
LimitLp::Answer nearest_optimal_state(LimitLp& lp, const LimitLp::Answer& a, const std::vector<double>& held) {
  const double factor = a.load_factor * (1 - kBelowOptimum);
  const LimitLp::Answer lo = lp.extreme_thrust(factor, false), hi = lp.extreme_thrust(factor, true);
  if (lo.outcome != LimitLp::Outcome::optimal || hi.outcome != LimitLp::Outcome::optimal) return a;
  const std::vector<double> N_lo = lp.normal_forces(lo), N_hi = lp.normal_forces(hi);
  double num = 0, den = 0;
  for (std::size_t j = 0; j < held.size(); ++j) {
    const double d = N_hi[j] - N_lo[j];
    num += d * (held[j] - N_lo[j]);
    den += d * d;
  }
  const double theta = den > 0 ? std::clamp(num / den, 0.0, 1.0) : 0.0;
  LimitLp::Answer out = lo;
  out.H = lo.H + theta * (hi.H - lo.H);
  out.V = lo.V + theta * (hi.V - lo.V);
  out.M = lo.M + theta * (hi.M - lo.M);
  out.load_factor = factor;
  out.basis = a.basis;
  return out;
}


}  // namespace

SlidingIteration non_associative(LimitLp& lp, const Ring& ring, const LimitOptions& options,
                                 const LimitLp::Answer& first, double load_scale, const SolveWarm& solve) {
  SlidingIteration out{first, {}, 0};
  if (!(options.friction > 0) || options.friction_model != FrictionModel::non_associative ||
      first.outcome != LimitLp::Outcome::optimal || !lp.slides(first.basis))
    return out;  // no joint on its cone in the optimum's basis: its mechanism only hinges (no dilatancy)
  std::vector<double> held = lp.normal_forces(first);
  // The last held forces with a state (the first: the associative optimum is one), and the state's own.
  std::vector<double> good = held, good_N = held;
  double step = 1.0, previous = std::numeric_limits<double>::infinity();
  std::vector<int> basis = first.basis;
  for (int it = 1; it <= kMaxSlidingIterations; ++it) {
    out.iterations = it;
    lp.hold_sliding(held);
    LimitLp::Answer a = solve(basis.empty() ? nullptr : &basis);
    if (a.outcome == LimitLp::Outcome::infeasible && step > kSlidingRetryFloor) {
      // Held forces with no state: a shorter step from the last ones that had one. (The held forces
      // with a state are a convex set: the average of two states is one of the average forces.)
      step *= 0.5;
      for (std::size_t j = 0; j < held.size(); ++j) held[j] = good[j] + step * (good_N[j] - good[j]);
      continue;
    }
    if (a.outcome != LimitLp::Outcome::optimal) {
      lp.hold_sliding({});
      out.answer = LimitLp::Answer{};
      out.failure = fmt::format("no state with the joints' normal forces held at iteration {} ({})", it,
                                a.outcome == LimitLp::Outcome::infeasible ? "infeasible"
                                : a.outcome == LimitLp::Outcome::unbounded ? "unbounded"
                                                                           : (a.failure ? a.failure : "LP failure"));
      return out;
    }
    // The program's optimum is a vertex, whose normal forces jump from one to the next (H and the
    // reactions are free of the held rows): of the optimal states along the thrust (the least and the
    // largest H at the factor found, a hair below it), take the one whose normal forces are nearest the
    // held ones, so that a state with N = held, where one exists, ends the iteration.
    a = nearest_optimal_state(lp, a, held);
    const std::vector<double> N = lp.normal_forces(a);
    const double scale = std::abs(ring.total_dead()) + std::abs(a.load_factor) * load_scale;
    double change = 0;
    for (std::size_t j = 0; j < N.size(); ++j) change = std::max(change, std::abs(N[j] - held[j]));
    change /= scale > 0 ? scale : 1.0;
    basis = a.basis;
    out.answer = std::move(a);
    if (change <= kSlidingTolerance) {
      lp.hold_sliding({});
      return out;
    }
    if (!(change < 0.9 * previous)) step = std::max(0.5 * step, kSlidingRelaxationFloor);
    previous = change;
    // The same state as the last iteration's (its vertex settled): the relaxed steps would only creep
    // towards its normal forces; hold them at once.
    double moved = 0;
    for (std::size_t j = 0; j < N.size() && !good_N.empty(); ++j) moved = std::max(moved, std::abs(N[j] - good_N[j]));
    const bool settled = it > 1 && moved <= kSlidingTolerance * (scale > 0 ? scale : 1.0);
    good = held;
    good_N = N;
    for (std::size_t j = 0; j < N.size(); ++j) held[j] = settled ? N[j] : held[j] + step * (N[j] - held[j]);
  }
  lp.hold_sliding({});
  out.answer = LimitLp::Answer{};
  out.failure = fmt::format("the normal forces still moved by {:.3g} of the loads after {} iterations", previous,
                            kMaxSlidingIterations);
  return out;
}

}  // namespace limit_detail
}  // namespace ogive
