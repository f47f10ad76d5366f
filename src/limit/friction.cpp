// Non-associative friction (Gilbert, Casapulla & Ahmed 2006): the iteration on the normal forces that
// the sliding rows hold (limit_internal.hpp, non_associative); and the refinement next to the joints that
// slide (add_sliding_refinement).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
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
// The growth of the change (relative) up to which a step that moves the factor the same way as the last
// one is doubled: the drift of a path whose change stays nearly constant.
constexpr double kSlidingGrowth = 1.05;
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

// An iterate: the state, its normal forces, and how far they are from the held ones (relative to
// `scale`, the loads at its factor).
struct Iterate {
  LimitLp::Answer answer;
  std::vector<double> N;
  double change = 0, scale = 1;
};

// The optimal state nearest the held forces `h` (`a` the program's optimum with them held), its normal
// forces, and how far they are from `h` (relative to the loads at its factor): the iteration's test.
// The program's optimum is a vertex, whose normal forces jump from one to the next (H and the
// reactions are free of the held rows): of the optimal states along the thrust (the least and the
// largest H at the factor found, a hair below it), the one whose normal forces are nearest the held
// ones, so that a state with N = held, where one exists, ends the iteration.
Iterate iterate_at(LimitLp& lp, const Ring& ring, double load_scale, const LimitLp::Answer& a,
                   const std::vector<double>& h) {
  Iterate i{nearest_optimal_state(lp, a, h), {}, 0, 1};
  i.N = lp.normal_forces(i.answer);
  const double scale = std::abs(ring.total_dead()) + std::abs(i.answer.load_factor) * load_scale;
  i.scale = scale > 0 ? scale : 1.0;
  for (std::size_t j = 0; j < i.N.size(); ++j) i.change = std::max(i.change, std::abs(i.N[j] - h[j]));
  i.change /= i.scale;
  return i;
}

// The fixed points that the optimal basis `b` certifies (LimitLp::sliding_fixed_points): the one of
// least factor (`least`) or of largest, held at its own normal forces and confirmed by the same test as
// every iterate's.
std::optional<Iterate> end_of_face(LimitLp& lp, const Ring& ring, double load_scale, const SolveWarm& solve,
                                   const std::vector<int>& b, bool least) {
  const LimitLp::Answer s = lp.sliding_fixed_points(b, least);
  if (s.outcome != LimitLp::Outcome::optimal) return std::nullopt;
  const std::vector<double> fixed = lp.normal_forces(s);
  lp.hold_sliding(fixed);
  const LimitLp::Answer c = solve(&b);
  if (c.outcome != LimitLp::Outcome::optimal) return std::nullopt;
  Iterate f = iterate_at(lp, ring, load_scale, c, fixed);
  if (!(f.change <= kSlidingTolerance)) return std::nullopt;
  return f;
}

// SlidingIteration::note of an answer `factor` at the bottom of the face of basis `face` (rows held).
std::string face_note(LimitLp& lp, const std::vector<int>& face, double factor) {
  const LimitLp::Answer top = lp.sliding_fixed_points(face, false);
  if (top.outcome != LimitLp::Outcome::optimal || !(top.load_factor > (1 + kLimitTolerance) * factor)) return {};
  return fmt::format("non-associative: every factor from the one given up to {:.6g} holds a state with the sliding "
                     "joints on their cones (the thrust across them, which rigid blocks do not determine, decides "
                     "which); the least is given",
                     top.load_factor);
}

}  // namespace

std::optional<LimitLp::Answer> least_thrust_collapse(LimitLp& lp, const Ring& ring, const LimitOptions& options,
                                                     double load_scale, const SolveWarm& solve) {
  if (!(options.friction > 0) || options.friction_model != FrictionModel::non_associative ||
      std::isfinite(options.compressive_strength))
    return std::nullopt;
  lp.hold_sliding({});
  const LimitLp::Answer least = lp.extreme_thrust(0.0, false);
  if (least.outcome != LimitLp::Outcome::optimal) return std::nullopt;
  // Held at the least thrust's own normal forces, the program's optimum is a fixed point of the
  // iteration when its normal forces are those (the same test as every iterate's): the arch at that
  // thrust slides under its weight alone and no live load raises it.
  const std::vector<double> held = lp.normal_forces(least);
  lp.hold_sliding(held);
  const LimitLp::Answer c = solve(nullptr);
  std::optional<LimitLp::Answer> out;
  if (c.outcome == LimitLp::Outcome::optimal) {
    Iterate i = iterate_at(lp, ring, load_scale, c, held);
    if (i.change <= kSlidingTolerance) out = std::move(i.answer);
  }
  lp.hold_sliding({});
  return out;
}

SlidingIteration non_associative(LimitLp& lp, const Ring& ring, const LimitOptions& options,
                                 const LimitLp::Answer& first, double load_scale, const SolveWarm& solve) {
  SlidingIteration out;
  out.answer = first;
  if (!(options.friction > 0) || options.friction_model != FrictionModel::non_associative ||
      first.outcome != LimitLp::Outcome::optimal || !lp.slides(first.basis))
    return out;  // no joint on its cone in the optimum's basis: its mechanism only hinges (no dilatancy)
  std::vector<double> held = lp.normal_forces(first);
  // The last held forces with a state (the first: the associative optimum is one), and the state's own.
  std::vector<double> good = held, good_N = held;
  double step = 1.0, previous = std::numeric_limits<double>::infinity();
  std::vector<int> basis = first.basis;
  auto iterate = [&](const LimitLp::Answer& a, const std::vector<double>& h) {
    return iterate_at(lp, ring, load_scale, a, h);
  };
  // The answer, and (from a face's bottom, `face` its basis) the face's largest factor where it is higher.
  auto converged = [&](Iterate&& i, const std::vector<int>* face) {
    if (face) out.note = face_note(lp, *face, i.answer.load_factor);
    lp.hold_sliding({});
    out.answer = std::move(i.answer);
    return out;
  };
  std::vector<std::vector<int>> tried;  // the bases whose face has been tried, each sorted
  const bool faces = !std::isfinite(options.compressive_strength);  // LimitLp::sliding_fixed_points
  double last_factor = first.load_factor, last_move = 0;
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
      out.failure =
          a.outcome == LimitLp::Outcome::infeasible
              ? fmt::format("no state with the joints' normal forces held at iteration {}: the last state's normal "
                            "forces (factor {:.6g}) differed from the held ones by {:.3g} of the loads, and steps "
                            "towards them down to {:.0e} of the way left no state{}; a non-associative collapse state "
                            "need not exist (a search of every one finds none on some arches: docs/limit-analysis.md)",
                            it, last_factor, previous, kSlidingRetryFloor,
                            faces ? " (nor did the faces of fixed points its bases certify)" : "")
              : fmt::format("no state with the joints' normal forces held at iteration {} ({})", it,
                            a.outcome == LimitLp::Outcome::unbounded ? "unbounded"
                                                                      : (a.failure ? a.failure : "LP failure"));
      return out;
    }
    Iterate i = iterate(a, held);
    basis = i.answer.basis;
    // The basis' rows with a positive multiplier certify the optimum whatever numbers the held rows
    // hold, so every state inside the cones with those rows tight is a fixed point: a face of them,
    // along which the factor varies (the thrust across sliding joints is not determined where they
    // slide without opening). The relaxed steps below creep towards that face for thousands of
    // programs, and stop wherever they enter it. Every state of the face is a collapse state of the
    // non-associative arch, the thrust it holds deciding which (an arch whose springings spread falls to
    // its least thrust): its state of least factor, the safe one, ends the iteration as soon as the test
    // confirms it (each basis tried once; a face with no state leaves the iteration where it was), and
    // is the answer also where the steps entered the face above it.
    std::vector<int> key = basis;
    std::sort(key.begin(), key.end());
    const bool untried = std::find(tried.begin(), tried.end(), key) == tried.end();
    if (untried) tried.push_back(std::move(key));
    if (i.change <= kSlidingTolerance) {
      std::optional<Iterate> low = end_of_face(lp, ring, load_scale, solve, basis, true);
      if (low && low->answer.load_factor <= i.answer.load_factor) return converged(std::move(*low), &basis);
      return converged(std::move(i), nullptr);
    }
    if (untried)
      if (std::optional<Iterate> low = end_of_face(lp, ring, load_scale, solve, basis, true))
        return converged(std::move(*low), &basis);
    const double change = i.change;
    const std::vector<double>& N = i.N;
    out.answer = std::move(i.answer);
    // The step: halved while the change fails to shrink by a tenth (the iteration can oscillate between
    // two mechanisms), doubled (up to a whole one) while the factor keeps moving one way with the
    // change not growing by more than kSlidingGrowth (a drift along a path, not an oscillation). Longer
    // steps take another path, which may end elsewhere: only where the faces end the iteration (not
    // with crushing, whose cuts stand for curved rows), at their least factor.
    const double move = out.answer.load_factor - last_factor;
    if (!(change < 0.9 * previous)) step = std::max(0.5 * step, kSlidingRelaxationFloor);
    if (faces && it > 2 && change <= kSlidingGrowth * previous && move * last_move > 0) step = std::min(1.0, 2 * step);
    last_move = move;
    last_factor = out.answer.load_factor;
    previous = change;
    // The same state as the last iteration's (its vertex settled): the relaxed steps would only creep
    // towards its normal forces; hold them at once.
    double moved = 0;
    for (std::size_t j = 0; j < N.size() && !good_N.empty(); ++j) moved = std::max(moved, std::abs(N[j] - good_N[j]));
    const bool settled = it > 1 && moved <= kSlidingTolerance * i.scale;
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
