// Limit analysis: the thrust range, the minimum thickness and the collapse load of a ring of voussoirs.
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive {
namespace {

using limit_detail::LimitLp;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The thinnest arch the search for t_min tries, relative to the span.
constexpr double kThinnestResolved = 1e-6;

// The relative width of the bracket on t at which the root-finder stops.
constexpr double kThicknessTolerance = 1e-10;

// A margin this close below zero (the programs' feasibility tolerance, in the same units) may be the
// round-off of a margin of zero: the thrust programs, which fix it at zero, decide.
constexpr double kMarginTolerance = 1e-11;

// The margin given to a program infeasible for every mu (friction can forbid every thrust line): a
// negative number for the root-finder, which needs only the sign.
constexpr double kNoMargin = -1.0;

// The fraction between a load's joints and their neighbours on either side (beside_loads): far above
// kFractionGap, far below the refinement's voussoirs.
constexpr double kLoadSide = 1e-7;

// The joints of the ring of thickness t: the refined fractions and those at the loads' edges, which
// move with the faces as the thickness changes; with `beside_loads`, also a joint a hair's breadth on
// either side of each load's joint.
//
// Why beside_loads (crushing): a hinge under a load sits N / (2 f_c) inside the face, and the sections on
// the two sides of the load's line differ: the radial joint through the extrados point under the load
// carries it on one side only, and the section just beyond, without it, can be the one that crushes;
// without the neighbours the hinge closes in on the load's joint only linearly with the refinement.
std::vector<double> fractions_at(const Scene& scene, double t, const LimitOptions& options,
                                 const std::vector<double>& refined, bool beside_loads) {
  std::vector<double> f = refined;
  const std::vector<double> at_loads = limit_detail::load_fractions(*scene.curve, t, scene.loads, options);
  f.insert(f.end(), at_loads.begin(), at_loads.end());
  if (beside_loads)
    for (double x : at_loads)
      for (double side : {-kLoadSide, kLoadSide})
        if (x + side > 0 && x + side < 1) f.push_back(x + side);
  return limit_detail::merged_fractions(std::move(f));
}

// Whether a hinge lies inside its face by more than the hinge tolerance (a crushing joint's stress
// block): then the rings that follow have joints beside the loads' (fractions_at).
bool stress_blocks(const Ring& ring, const std::vector<Hinge>& hinges) {
  return std::any_of(hinges.begin(), hinges.end(), [&](const Hinge& h) {
    if (h.face == Face::axis) return false;
    const Joint& j = ring.joints[static_cast<std::size_t>(h.joint)];
    const Eigen::Vector2d& face = h.face == Face::intrados ? j.intrados : j.extrados;
    return (h.point - face).norm() > 1e-9 * (j.extrados - j.intrados).norm();
  });
}

// A joint whose crossing lies this close to a face (relative to the joint) is a hinge of the thinnest
// arch: at t_min the margin is zero to the root-finder's tolerance, not to round-off.
constexpr double kThinnestHingeTolerance = 1e-6;

// What the rounds of one analysis reuse: the LP library's model and the storage of the rings and their
// programs. The search for t_min builds a ring and its programs for every thickness it tries; freeing
// them each time made the heap shrink and grow again (the memory returned to the system and faulted in
// anew), which cost about a third of the time on the project's machine.
struct Work {
  limit_detail::LpWorkspace workspace;
  limit_detail::RingScratch scratch;
  Ring margin_ring;                        // the ring of the thickness the search tries
  std::unique_ptr<LimitLp> lp, margin_lp;  // the round's programs, the search's
  std::unique_ptr<LimitLp> horizontal_lp;  // the round's program of the horizontal acceleration a_c
  // The previous round's optimal bases of the margin, the extreme thrusts and the collapse, by row key:
  // the next, finer ring starts from them (most of its joints are the coarser ring's).
  std::vector<LimitLp::RowKey> margin_basis, min_basis, max_basis, collapse_basis, horizontal_basis;
  // A state had a hinge inside its face (crushing): the rings from then on have joints beside the loads'.
  bool beside_loads = false;

  // Before another scene: nothing of the last one is reused, only the storage.
  void forget() {
    scratch.forget();
    beside_loads = false;
    for (auto* basis : {&margin_basis, &min_basis, &max_basis, &collapse_basis, &horizontal_basis}) basis->clear();
  }
};

// The program solved from the previous round's basis `keys` (when this ring has all its rows), whose
// own optimal basis replaces it.
template <class Solve>
LimitLp::Answer solve_warm(LimitLp& lp, std::vector<LimitLp::RowKey>& keys, Solve&& solve) {
  const std::vector<int> warm = lp.rows(keys);
  LimitLp::Answer a = solve(warm.empty() ? nullptr : &warm);
  keys = lp.keys(a.basis);
  return a;
}

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

// The outcome of the non-associative iteration: the last answer, and why it did not converge (empty:
// it did).
struct SlidingIteration {
  LimitLp::Answer answer;
  std::string failure;
  int iterations = 0;
};

// The program `solve` (lp's collapse, say) with non-associative friction, from `first`, its optimum with
// the Coulomb rows (the associative answer). Each iteration holds every joint's friction rows at the
// normal forces N_prev of the previous state (|T| <= friction N_prev: fixed numbers), re-solves, and moves
// N_prev towards the new normal forces, by a step halved whenever the change fails to shrink by a tenth
// (the iteration can oscillate between two mechanisms). At the fixed point the state lies inside every
// Coulomb cone (N = N_prev) and its mechanism, the normality of fixed-N rows, slides without opening.
// `load_scale`: the live load's magnitude at factor 1 (added to the dead loads times the factor found).
template <class Solve>
SlidingIteration non_associative(LimitLp& lp, const Ring& ring, const LimitOptions& options,
                                 const LimitLp::Answer& first, double load_scale, Solve&& solve) {
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

// The programs of `ring` in work's storage.
LimitLp& programs_of(const Ring& ring, const LimitOptions& options, Work& work, std::unique_ptr<LimitLp>& lp) {
  if (lp) lp->load(ring, options.friction, options.compressive_strength);
  else
    lp = std::make_unique<LimitLp>(ring, options.friction, &work.workspace, limit_detail::LpSolver::dense,
                                   limit_detail::LiveKind::vertical, options.compressive_strength);
  return *lp;
}

// The feasibility margin of the arch of the same axis and loads with thickness t (see analyse_limit).
struct MarginFunction {
  Scene scene;  // a copy whose thickness changes
  const LimitOptions& options;
  const std::vector<double>& refined;
  double load_factor;
  Work& work;
  int solves = 0;
  bool failed = false;
  std::vector<int> basis;  // the last margin's optimal basis: the next thickness starts from it
  double feasible_t = std::numeric_limits<double>::infinity();
  std::vector<double> feasible_refinement;  // around the hinges of the thinnest admissible arch so far
  int basis_joints = 0;                     // the joints of the ring whose margin gave `basis`
  bool feasible_blocks = false;             // the thinnest admissible arch's hinges: stress_blocks

  double operator()(double t) {
    scene.thickness = t;
    Ring& ring = work.margin_ring;
    limit_detail::make_ring_at(scene, options, fractions_at(scene, t, options, refined, work.beside_loads), ring,
                               work.scratch);
    LimitLp& lp = programs_of(ring, options, work, work.margin_lp);
    // A warm start needs the same joints (a load's joints can merge with others at some thickness).
    const bool warm = !basis.empty() && basis_joints == static_cast<int>(ring.joints.size());
    LimitLp::Answer a = lp.margin(load_factor, warm ? &basis : nullptr);
    ++solves;
    basis = std::move(a.basis);
    basis_joints = static_cast<int>(ring.joints.size());
    // No margin at all (friction can forbid every thrust line, whatever mu): as inadmissible as it gets.
    if (a.outcome == LimitLp::Outcome::infeasible) return kNoMargin;
    if (a.outcome != LimitLp::Outcome::optimal) failed = true;
    if (a.outcome == LimitLp::Outcome::optimal && a.margin >= 0 && t < feasible_t) {
      feasible_t = t;
      feasible_refinement.clear();
      const ThrustState st =
          thrust_state(ring, a.H, a.V, a.M, a.load_factor, kThinnestHingeTolerance, options.compressive_strength);
      limit_detail::add_refinement(ring, st.hinges, feasible_refinement);
      feasible_blocks = stress_blocks(ring, st.hinges);
    }
    return a.margin;
  }
};

// The smallest thickness with margin >= 0, from a bracket lo < hi with f(lo) < 0 <= f(hi): Illinois
// (regula falsi that halves the value kept twice at one end, so that both ends move). The margin has a
// kink at its root (different joints become active on either side), so the feasible end often
// converges alone: stop when the bracket or the feasible end's last step is below the tolerance.
// Returns the feasible end.
double thinnest(MarginFunction& f, double lo, double f_lo, double hi, double f_hi) {
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > kThicknessTolerance * hi && !f.failed; ++it) {
    if (f_hi == 0) {
      // A margin of exactly zero (regula falsi stays there, and bisection would creep up to it): the
      // root, unless the margin is zero over an interval; a thickness just below, by the tolerance,
      // that does not stand says which.
      const double below = hi * (1 - kThicknessTolerance);
      if (below <= lo) break;
      const double f_below = f(below);
      if (f_below < 0) break;
      if (f_below == 0) {
        // Zero over an interval: a joint whose force vanishes (voussoirs that carry no load between
        // loaded ones, with H = 0) leaves no margin to give at any thickness that stands. Bisect on
        // whether it stands.
        const double c = 0.5 * (lo + below), f_c = f(c);
        if (f_c >= 0) hi = c, f_hi = f_c;
        else lo = c, f_lo = f_c, hi = below, f_hi = f_below;
        continue;
      }
      hi = below;
      f_hi = f_below;
      continue;
    }
    double c = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(c > lo && c < hi)) c = 0.5 * (lo + hi);
    const double f_c = f(c);
    if (f_c >= 0) {
      const double step = hi - c;
      hi = c;
      f_hi = f_c;
      if (side == 1) f_lo *= 0.5;
      side = 1;
      if (step <= kThicknessTolerance * hi) break;
    } else {
      lo = c;
      f_lo = f_c;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    }
  }
  return hi;
}

}  // namespace

const char* to_string(FrictionModel f) {
  switch (f) {
    case FrictionModel::associative: return "associative";
    case FrictionModel::non_associative: return "non_associative";
  }
  return "unknown";
}

const char* to_string(LimitStatus s) {
  switch (s) {
    case LimitStatus::success: return "success";
    case LimitStatus::inadmissible: return "inadmissible";
    case LimitStatus::lp_failure: return "lp_failure";
    case LimitStatus::not_converged: return "not_converged";
  }
  return "unknown";
}

namespace {

// A bracket of t_min: f(lo) < 0 <= f(hi) when found.
struct Bracket {
  double lo, f_lo, hi, f_hi;
  bool found = false;
};

// From an admissible thickness down, halving, to the first that does not stand; not below `floor`
// (below kThinnestResolved L the margin is at the LP's tolerance: an arch that stands that thin, a
// funicular one, gets no t_min and says so rather than a number of round-off).
Bracket bracket_down(MarginFunction& f, Bracket b, double floor) {
  for (int i = 0; i < 60 && !f.failed && 0.5 * b.hi >= floor; ++i) {
    b.lo = 0.5 * b.hi;
    b.f_lo = f(b.lo);
    if (b.f_lo < 0) {
      b.found = true;
      break;
    }
    b.hi = b.lo;
    b.f_hi = b.f_lo;
  }
  return b;
}

// From an inadmissible thickness up, doubling, to the first that stands; not beyond `cap`.
Bracket bracket_up(MarginFunction& f, Bracket b, double cap) {
  for (int i = 0; i < 60 && !f.failed && b.hi < cap; ++i) {
    b.hi = std::min(2.0 * b.lo, cap);
    b.f_hi = f(b.hi);
    if (b.f_hi >= 0) {
      b.found = true;
      break;
    }
    b.lo = b.hi;
    b.f_lo = b.f_hi;
  }
  return b;
}

// The first relative step from the previous ring's t_min when bracketing the next one: a refinement of
// the joints moves t_min by less than this, mostly (the steps grow fourfold when it moves more).
constexpr double kNearStep = 1e-3;
// The first step from t0, relative, in multiples of the margin there (see bracket_near).
constexpr double kNearMarginSteps = 10.0;

// A bracket around t0, the t_min of the previous (coarser) ring, within (floor, ceiling): from t0 down
// while it stands, or up while it does not, by relative steps that grow fourfold; a step up that reaches
// the ceiling ends there, where f(ceiling) = f_ceiling (NaN: unknown).
Bracket bracket_near(MarginFunction& f, double t0, double floor, double ceiling, double f_ceiling) {
  Bracket b{t0, f(t0), t0, 0.0};
  // The margin is a relative distance of the thrust line from the faces, of the order of the relative
  // change of thickness: a margin near zero at t0 puts the root that close, so try a step of a few
  // times it first (the tolerance for a margin of exactly zero).
  double step = std::clamp(kNearMarginSteps * std::abs(b.f_lo), kThicknessTolerance, kNearStep);
  if (b.f_lo >= 0) {
    b.f_hi = b.f_lo;
    for (int i = 0; i < 60 && !f.failed && b.hi * (1 - step) >= floor; ++i) {
      b.lo = b.hi * (1 - step);
      b.f_lo = f(b.lo);
      if (b.f_lo < 0) return {b.lo, b.f_lo, b.hi, b.f_hi, true};
      b.hi = b.lo;
      b.f_hi = b.f_lo;
      step = std::min(std::max(4 * step, kNearStep), 0.5);
    }
    return b;
  }
  for (int i = 0; i < 60 && !f.failed && b.lo < ceiling; ++i, step = std::min(4 * step, 1.0)) {
    b.hi = std::min(b.lo * (1 + step), ceiling);
    b.f_hi = b.hi == ceiling && !std::isnan(f_ceiling) ? f_ceiling : f(b.hi);
    if (b.f_hi >= 0) return {b.lo, b.f_lo, b.hi, b.f_hi, true};
    b.lo = b.hi;
    b.f_lo = b.f_hi;
  }
  return b;
}

// Where the search for t_min ended: t_min, or NaN when the bracket was not found (then below `hi`
// when the arch stands at every thickness tried).
struct Thinnest {
  double t_min = kNaN;
  bool bracketed = false;
  double hi = 0;
};

// t_min of the arch of thickness t whose margin there is `margin` (admissible: its thrust programs
// feasible too), starting from `near` (the previous ring's t_min; NaN: none) when it lies below the
// thickness that stands (or above t when the arch does not).
Thinnest search_thinnest(MarginFunction& f, double t, double margin, bool admissible, double floor, double cap,
                         double near) {
  Thinnest out;
  // A zero margin whose thrust programs are infeasible, or a margin below zero by round-off whose thrust
  // programs are feasible: t is t_min to round-off.
  if ((!admissible && margin >= 0) || (admissible && margin < 0)) {
    out.t_min = t;
    return out;
  }
  Bracket bracket{t, margin, t, margin};
  bool warm = false;
  if (!std::isnan(near) && (admissible ? near > floor && near < t : near > t && near < cap)) {
    bracket = bracket_near(f, near, admissible ? floor : t, admissible ? t : cap, admissible ? margin : kNaN);
    warm = bracket.found;
  }
  if (!warm) {
    bracket = Bracket{t, margin, t, margin};
    bracket = admissible ? bracket_down(f, bracket, floor) : bracket_up(f, bracket, cap);
  }
  out.bracketed = bracket.found;
  out.hi = bracket.hi;
  if (bracket.found && !f.failed) out.t_min = thinnest(f, bracket.lo, bracket.f_lo, bracket.hi, bracket.f_hi);
  return out;
}

// The horizontal acceleration a_c of collapse into r (horizontal_state, horizontal_load_factor_mechanism):
// the largest lambda of the program whose lambda pushes the dead loads horizontally, every vertical load
// at factor 1. False when the program stops without an answer.
struct HorizontalCollapse {
  ThrustState state;
  double mechanism = kNaN;
  std::vector<Hinge> mechanism_hinges;  // the mechanism's (limit_detail::least_mechanism); empty: none
  std::string sliding_failure;  // why the non-associative iteration did not converge (then no state)
};

bool horizontal_collapse(const Ring& ring, const LimitOptions& options, Work& work, HorizontalCollapse& r,
                         int& lp_solves) {
  if (!(ring.total_dead() != 0.0)) return true;
  if (work.horizontal_lp) work.horizontal_lp->load(ring, options.friction, options.compressive_strength);
  else
    work.horizontal_lp = std::make_unique<LimitLp>(ring, options.friction, &work.workspace,
                                                   limit_detail::LpSolver::dense, limit_detail::LiveKind::horizontal,
                                                   options.compressive_strength);
  LimitLp& lp = *work.horizontal_lp;
  const int solves_before = lp.solves();
  LimitLp::Answer c = solve_warm(lp, work.horizontal_basis, [&](const std::vector<int>* w) { return lp.collapse(w); });
  // The horizontal load of the dead loads at a_c (what the iteration's tolerance is relative to).
  const SlidingIteration sliding =
      non_associative(lp, ring, options, c, std::abs(ring.total_dead()), [&](const std::vector<int>* w) { return lp.collapse(w); });
  lp_solves += lp.solves() - solves_before;
  if (!sliding.failure.empty()) {
    r.sliding_failure = sliding.failure;
    return true;
  }
  c = sliding.answer;
  if (c.outcome == LimitLp::Outcome::failure) return false;
  if (c.outcome != LimitLp::Outcome::optimal) return true;  // cannot stand, or no finite a_c
  // The state: the ring pushed by a_c with its live load at factor 1.
  Ring shaken = ring;
  shaken.acceleration = c.load_factor;
  r.state = thrust_state(shaken, c.H, c.V, c.M, 1.0, 1e-9, options.compressive_strength);
  r.state.load_factor = c.load_factor;
  limit_detail::LeastMechanism m = limit_detail::least_mechanism(ring, r.state.hinges, limit_detail::LiveKind::horizontal);
  r.mechanism = m.factor;
  r.mechanism_hinges = std::move(m.hinges);
  return true;
}

// Throws std::invalid_argument when nothing loads the ring. Scene::validate lets density 0 pass with a
// fill; a fill whose level lies below the extrados over the whole span (it meets the extrados beyond the
// springing's vertical) loads nothing, and a ring that carries nothing has no thrust, no thinnest
// thickness and no mechanism to find. A fill that reaches the extrados over any part of the span is a
// scene: the unloaded voussoirs carry its thrust.
//
// Loads so small that the squares of the forces underflow (below about 1e-154 N/m; kSmallestLoads leaves
// room for the moments and sums) would make every joint look forceless and every thrust line admissible
// or none: refused too. The analysis is homogeneous in the loads, so such a scene is the same arch as
// one with its loads in ordinary units.
constexpr double kSmallestLoads = 1e-100;  // N/m, the ring's total load

void require_loaded(const Scene& scene, const Ring& ring) {
  const double total = std::abs(ring.total_dead()) + std::abs(ring.total_live());
  if (total != 0.0 && total < kSmallestLoads)
    throw std::invalid_argument(fmt::format(
        "density, fill_density: the ring's loads total {:.3g} N/m, below {:g} N/m, too small for the arithmetic of "
        "rigid voussoirs (their squares underflow); the analysis is the same at any scale: give the loads in N",
        total, kSmallestLoads));
  if (ring.total_dead() != 0.0 || ring.has_live_load()) return;
  double level = 0;
  for (const FillLoad& fill : scene.loads.fills)
    if (fill.density > 0) level = std::max(level, fill.height_ratio);
  if (!(level > 0))
    throw std::invalid_argument("density, fill_density: with no self-weight and no fill's weight (both 0) and no "
                                "point or live load the ring carries nothing: nothing to analyse");
  throw std::invalid_argument(fmt::format(
      "fill_height_ratio: the fill's level ({} of the span) lies below the arch's extrados over the whole span, "
      "so the fill loads nothing, and with density 0 the ring has no weight: nothing to analyse",
      level));
}

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

// Why no thrust line stands: where it would have to fit, and whether a thicker arch would stand (t_min
// below `t_cap`).
std::string inadmissible_message(const LimitOptions& options, double t_min, double t_cap) {
  std::string where = options.friction > 0 ? "inside the arch and its joints' friction cones" : "inside the arch";
  if (std::isfinite(options.compressive_strength))
    where += fmt::format(" clear of the stress blocks that crush its joints (compressive strength {:g} Pa)",
                         options.compressive_strength);
  return std::isnan(t_min) ? fmt::format("no thrust line fits {} at any thickness up to {} m", where, t_cap)
                           : fmt::format("no thrust line fits {}: t < t_min", where);
}

// One analysis on the ring whose joints are `refined` and the loads' (fractions_at), and where the next
// ring should be finer: next to every hinge of its states and of the thinnest arch.
struct Round {
  LimitResult result;
  std::vector<double> refinement;
};

Round analyse_round(const Scene& scene, const LimitOptions& options, const std::vector<double>& refined,
                    double previous_t_min, Work& work) {
  const Curve& curve = *scene.curve;
  Round round;
  LimitResult& r = round.result;
  limit_detail::make_ring_at(scene, options, fractions_at(scene, scene.thickness, options, refined, work.beside_loads),
                             r.ring, work.scratch);
  const Ring& ring = r.ring;
  require_loaded(scene, ring);
  const bool live = ring.has_live_load();
  const double load_factor = live ? 1.0 : 0.0;  // the H range and t_min: under the loads as given

  r.V = 0.5 * (ring.total_dead() + ring.total_live());
  LimitLp& lp = programs_of(ring, options, work, work.lp);
  const int solves_before = lp.solves();
  auto fail = [&](const char* problem, const char* failure) {  // failure: LimitLp::Answer::failure
    r.status = LimitStatus::lp_failure;
    r.message = fmt::format("the LP of {} stopped without an answer{}{}", problem, failure ? ": " : "", failure ? failure : "");
    r.lp_solves += lp.solves() - solves_before;
    return round;
  };
  const double f_c = options.compressive_strength;
  auto state = [&](const LimitLp::Answer& a) { return thrust_state(ring, a.H, a.V, a.M, a.load_factor, 1e-9, f_c); };

  using Warm = const std::vector<int>*;
  LimitLp::Answer margin = solve_warm(lp, work.margin_basis, [&](Warm w) { return lp.margin(load_factor, w); });
  if (margin.outcome == LimitLp::Outcome::infeasible) margin.margin = kNoMargin;
  else if (margin.outcome != LimitLp::Outcome::optimal) return fail("the feasibility margin", margin.failure);
  // A margin within the programs' tolerance of zero (the thrust vanishing at some joint leaves none to
  // give) is decided by the thrust programs' feasibility below.
  bool admissible = margin.margin >= -kMarginTolerance;
  bool unbounded_thrust = false;
  if (admissible) {
    const LimitLp::Answer lo =
        solve_warm(lp, work.min_basis, [&](Warm w) { return lp.extreme_thrust(load_factor, false, w); });
    const LimitLp::Answer hi =
        solve_warm(lp, work.max_basis, [&](Warm w) { return lp.extreme_thrust(load_factor, true, w); });
    if (lo.outcome == LimitLp::Outcome::failure || lo.outcome == LimitLp::Outcome::unbounded)
      return fail("the minimum thrust", lo.failure);
    if (hi.outcome == LimitLp::Outcome::failure) return fail("the maximum thrust", hi.failure);
    // A margin of zero to round-off can still leave the thrust programs infeasible: not admissible.
    admissible = lo.outcome == LimitLp::Outcome::optimal && hi.outcome != LimitLp::Outcome::infeasible;
    if (admissible) {
      r.min_state = state(lo);
      if (hi.outcome == LimitLp::Outcome::optimal) r.max_state = state(hi);
      else unbounded_thrust = true;
    }
  }
  limit_detail::LeastMechanism mechanism;
  std::string sliding_failure;  // the non-associative iteration's of the collapse load factor
  if (live) {
    LimitLp::Answer c = solve_warm(lp, work.collapse_basis, [&](Warm w) { return lp.collapse(w); });
    const SlidingIteration sliding =
        non_associative(lp, ring, options, c, std::abs(ring.total_live()), [&](Warm w) { return lp.collapse(w); });
    sliding_failure = sliding.failure;
    if (sliding_failure.empty()) c = sliding.answer;
    if (!sliding_failure.empty()) {
      // No load factor: the collapse state stays absent.
    } else if (c.outcome == LimitLp::Outcome::optimal) {
      r.collapse_state = state(c);
      mechanism = limit_detail::least_mechanism(ring, r.collapse_state.hinges, limit_detail::LiveKind::vertical);
      r.load_factor_mechanism = mechanism.factor;
    } else if (c.outcome == LimitLp::Outcome::failure) {
      return fail("the collapse load", c.failure);
    }
    // infeasible: the dead loads alone cannot stand; unbounded: the live load cannot make a mechanism.
  }
  r.lp_solves += lp.solves() - solves_before;

  // t_min: bracket the root of the margin, then Illinois.
  MarginFunction f{scene,        options, refined, load_factor, work, 0, false, margin.basis,
                   std::numeric_limits<double>::infinity(), {}, static_cast<int>(ring.joints.size())};
  const double t = scene.thickness;
  const double t_cap = 0.99 * max_thickness(curve);
  // Where the thrust vanishes at some joint the margin is zero at every thickness that stands (no
  // distance from the faces to give): its sign is the round-off's, and t_min is not searched.
  const bool forceless = r.min_state.forceless || r.max_state.forceless;
  const Thinnest thinnest_arch =
      forceless ? Thinnest{}
                : search_thinnest(f, t, margin.margin, admissible, kThinnestResolved * curve.span(), t_cap,
                                  previous_t_min);
  r.thickness_min = thinnest_arch.t_min;
  const bool bracketed = forceless || thinnest_arch.bracketed || !std::isnan(thinnest_arch.t_min);
  const double hi = thinnest_arch.hi;
  r.lp_solves += f.solves;
  if (f.failed) {
    r.status = LimitStatus::lp_failure;
    r.message = "the LP of the feasibility margin stopped without an answer while searching t_min";
    return round;
  }
  for (const ThrustState* st : {&r.min_state, &r.max_state, &r.collapse_state}) {
    limit_detail::add_refinement(ring, st->hinges, round.refinement);
    if (stress_blocks(ring, st->hinges)) work.beside_loads = true;
  }
  if (!std::isnan(r.thickness_min)) {
    round.refinement.insert(round.refinement.end(), f.feasible_refinement.begin(), f.feasible_refinement.end());
    if (f.feasible_blocks) work.beside_loads = true;
  }
  // The next ring is refined next to every joint the collapse state touches; the result lists the
  // mechanism's hinges (a thrust line along a face touches a run of joints, of which the mechanism needs
  // one).
  if (!mechanism.hinges.empty()) r.collapse_state.hinges = std::move(mechanism.hinges);
  if (fails_virtual_work(r, "collapse load factor", r.load_factor(), r.load_factor_mechanism)) return round;
  if (!admissible) {
    r.status = LimitStatus::inadmissible;
    r.message = inadmissible_message(options, r.thickness_min, t_cap);
    return round;
  }
  r.status = LimitStatus::success;
  if (!bracketed) r.message = fmt::format("t_min below {} m: not searched further", hi);
  auto note = [&](const std::string& text) { r.message += (r.message.empty() ? "" : "; ") + text; };
  if (forceless)
    note("the thrust vanishes at some joints (voussoirs without weight or load between loaded ones): no margin "
         "there to search t_min by, and no hinge");
  if (!sliding_failure.empty()) {
    r.status = LimitStatus::not_converged;
    note("the non-associative friction iteration of the collapse load factor did not converge: " + sliding_failure);
  }
  if (unbounded_thrust) note("no largest thrust: a thrust line of any H fits inside the arch (H_max absent)");
  if (live && std::isnan(r.load_factor()) && sliding_failure.empty())
    note("the live load cannot turn the arch into a mechanism (no finite load factor)");
  if (!std::isnan(r.load_factor()) && std::isnan(r.load_factor_mechanism)) {
    if (r.collapse_state.hinges.size() > kMaxMechanismHinges)
      note(fmt::format("the collapse state touches {} joints: the mechanism check takes at most {} hinges "
                       "(a run of consecutive ones counting as three)",
                       r.collapse_state.hinges.size(), kMaxMechanismHinges));
    else
      note(options.friction > 0 ? "no rotational mechanism through the collapse hinges: joints slide at collapse"
                                : "no one-degree rotational mechanism through the collapse hinges");
  }
  return round;
}

// The largest relative change of a number between two results (NaN in one only: infinite).
double largest_change(const LimitResult& a, const LimitResult& b) {
  double worst = 0;
  auto compare = [&](double x, double y) {
    if (std::isnan(x) && std::isnan(y)) return;
    if (std::isnan(x) != std::isnan(y)) {
      worst = std::numeric_limits<double>::infinity();
      return;
    }
    const double scale = std::max(std::abs(x), std::abs(y));
    if (scale > 0) worst = std::max(worst, std::abs(x - y) / scale);
  };
  compare(a.H_min(), b.H_min());
  compare(a.H_max(), b.H_max());
  compare(a.thickness_min, b.thickness_min);
  compare(a.load_factor(), b.load_factor());
  compare(a.load_factor_mechanism, b.load_factor_mechanism);
  return worst;
}

// The largest change of a_c and its kinematic value between two rings. a_c vanishes at t_min: its
// changes count relative to 1 % of g at least, as H/V's do to 0.01.
double largest_change(const HorizontalCollapse& a, const HorizontalCollapse& b) {
  double worst = 0;
  for (auto [x, y] : {std::pair{a.state.load_factor, b.state.load_factor}, std::pair{a.mechanism, b.mechanism}}) {
    if (std::isnan(x) && std::isnan(y)) continue;
    if (std::isnan(x) != std::isnan(y)) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(x - y) / std::max({std::abs(x), std::abs(y), 0.01}));
  }
  return worst;
}

// a_c converged in the joints on rings of its own, refined next to its hinges only: the thrust range,
// t_min and the load factor keep the rings they converged on, whether or not a_c is asked for.
// Rounds as analyse_limit's: converged after two quiet refinements in a row.
struct HorizontalOutcome {
  HorizontalCollapse collapse;
  Ring ring;
  bool failed = false;     // the program stopped without an answer
  bool converged = false;
  double change = 0;       // the last refinement's largest_change
  int lp_solves = 0;
};

HorizontalOutcome converge_horizontal(const Scene& scene, const LimitOptions& options, Work& work) {
  HorizontalOutcome out;
  std::vector<double> refined = limit_detail::uniform_fractions(options.joints_count);
  auto round = [&](HorizontalCollapse& c) {
    limit_detail::make_ring_at(scene, options,
                               fractions_at(scene, scene.thickness, options, refined, work.beside_loads), out.ring,
                               work.scratch);
    if (!horizontal_collapse(out.ring, options, work, c, out.lp_solves)) out.failed = true;
  };
  round(out.collapse);
  out.change = std::numeric_limits<double>::infinity();
  int quiet = 0;
  for (int k = 0; k < kMaxLimitRefinements && !out.failed; ++k) {
    std::vector<double> refinement;
    limit_detail::add_refinement(out.ring, out.collapse.state.hinges, refinement);
    if (stress_blocks(out.ring, out.collapse.state.hinges)) work.beside_loads = true;
    if (refinement.empty()) {
      out.change = 0;
      break;
    }
    refined.insert(refined.end(), refinement.begin(), refinement.end());
    refined = limit_detail::merged_fractions(std::move(refined));
    HorizontalCollapse next;
    round(next);
    if (out.failed) break;
    out.change = largest_change(out.collapse, next);
    out.collapse = std::move(next);
    quiet = out.change <= kLimitTolerance ? quiet + 1 : 0;
    if (quiet == 2) break;
  }
  out.converged = out.change <= kLimitTolerance && (quiet == 2 || out.change == 0);
  return out;
}

}  // namespace

LimitResult analyse_limit(const Scene& scene, const LimitOptions& options) {
  scene.validate();
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  std::vector<double> refined = limit_detail::uniform_fractions(options.joints_count);
  // Each thread keeps its work areas from one analysis to the next (a few hundred kB): freed after every
  // scene, the memory went back to the system and was faulted in again by the next one, which on the
  // project's machine took longer than the analysis itself.
  thread_local Work work;
  work.forget();
  Round round = analyse_round(scene, options, refined, kNaN, work);
  int solves = round.result.lp_solves;
  double change = std::numeric_limits<double>::infinity();
  // Converged after two refinements in a row that moved no number by more than the tolerance: one alone
  // can miss a hinge that lies beyond the joints it added (and then moves nothing).
  int quiet = 0;
  for (int k = 0; k < kMaxLimitRefinements && round.result.status != LimitStatus::lp_failure; ++k) {
    // Nothing to refine around (no hinge anywhere): a finer ring gives the same numbers.
    if (round.refinement.empty()) {
      change = 0;
      break;
    }
    refined.insert(refined.end(), round.refinement.begin(), round.refinement.end());
    refined = limit_detail::merged_fractions(std::move(refined));
    Round next = analyse_round(scene, options, refined, round.result.thickness_min, work);
    solves += next.result.lp_solves;
    change = next.result.status == LimitStatus::lp_failure ? change : largest_change(round.result, next.result);
    round = std::move(next);
    quiet = change <= kLimitTolerance ? quiet + 1 : 0;
    if (quiet == 2) break;
  }
  LimitResult r = std::move(round.result);
  r.lp_solves = solves;
  if (r.status != LimitStatus::lp_failure && !(change <= kLimitTolerance && (quiet == 2 || change == 0))) {
    r.status = LimitStatus::not_converged;
    const std::string text = fmt::format("the numbers still moved by {:.3g} (relative) at the last of {} refinements "
                                         "of the joints",
                                         change, kMaxLimitRefinements);
    r.message = r.message.empty() ? text : text + "; " + r.message;
  }
  if (options.horizontal_load_factor && r.status != LimitStatus::lp_failure) {
    HorizontalOutcome h = converge_horizontal(scene, options, work);
    r.lp_solves += h.lp_solves;
    if (h.failed) {
      r.status = LimitStatus::lp_failure;
      r.message = "the LP of the collapse acceleration stopped without an answer";
      return r;
    }
    if (!h.collapse.sliding_failure.empty()) {
      r.status = LimitStatus::not_converged;
      const std::string text = "the non-associative friction iteration of the collapse acceleration did not "
                               "converge: " + h.collapse.sliding_failure;
      r.message = r.message.empty() ? text : text + "; " + r.message;
      return r;
    }
    r.horizontal_state = std::move(h.collapse.state);
    r.horizontal_load_factor_mechanism = h.collapse.mechanism;
    r.horizontal_ring = std::move(h.ring);
    if (!h.collapse.mechanism_hinges.empty()) r.horizontal_state.hinges = std::move(h.collapse.mechanism_hinges);
    if (fails_virtual_work(r, "collapse acceleration", r.horizontal_load_factor(), r.horizontal_load_factor_mechanism))
      return r;
    if (!h.converged) {
      if (r.status == LimitStatus::success) r.status = LimitStatus::not_converged;
      const std::string text = fmt::format("the collapse acceleration still moved by {:.3g} (relative) at the last "
                                           "of {} refinements of its joints",
                                           h.change, kMaxLimitRefinements);
      r.message = r.message.empty() ? text : text + "; " + r.message;
    }
  }
  return r;
}

}  // namespace ogive
