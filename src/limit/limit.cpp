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

using limit_detail::fails_virtual_work;
using limit_detail::inadmissible_message;
using limit_detail::kNoMargin;
using limit_detail::LimitLp;
using limit_detail::require_loaded;
using limit_detail::stress_blocks;
using limit_detail::ThicknessMargin;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The thinnest arch the search for t_min tries, relative to the span.
constexpr double kThinnestResolved = 1e-6;

// The relative width of the bracket on t at which the root-finder stops.
constexpr double kThicknessTolerance = 1e-10;

// A margin this close below zero (the programs' feasibility tolerance, in the same units) may be the
// round-off of a margin of zero: the thrust programs, which fix it at zero, decide.
constexpr double kMarginTolerance = 1e-11;

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

// The smallest thickness with margin >= 0, from a bracket lo < hi with f(lo) < 0 <= f(hi): Illinois
// (regula falsi that halves the value kept twice at one end, so that both ends move). The margin has a
// kink at its root (different joints become active on either side), so the feasible end often
// converges alone: stop when the bracket or the feasible end's last step is below the tolerance.
// Returns the feasible end.
double thinnest(ThicknessMargin& f, double lo, double f_lo, double hi, double f_hi) {
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
Bracket bracket_down(ThicknessMargin& f, Bracket b, double floor) {
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
Bracket bracket_up(ThicknessMargin& f, Bracket b, double cap) {
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
Bracket bracket_near(ThicknessMargin& f, double t0, double floor, double ceiling, double f_ceiling) {
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
Thinnest search_thinnest(ThicknessMargin& f, double t, double margin, bool admissible, double floor, double cap,
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
  std::string sliding_note;     // the iteration's note (SlidingIteration::note)
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
  const limit_detail::SlidingIteration sliding =
      limit_detail::non_associative(lp, ring, options, c, std::abs(ring.total_dead()), [&](const std::vector<int>* w) { return lp.collapse(w); });
  lp_solves += lp.solves() - solves_before;
  if (!sliding.failure.empty()) {
    r.sliding_failure = sliding.failure;
    return true;
  }
  r.sliding_note = sliding.note;
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

// A load factor of 0 (an arch that a sliding state holds at its weight alone) is round-off's from one
// ring or program to the next: its changes count relative to the programs' own accuracy at least.
constexpr double kZeroFactor = 1e-9;

// The least of the non-associative collapse states the iteration reaches is one, but another (other
// joints sliding) can have a lower factor: benchmarks/limit/nonassociative_enumeration.py finds one at
// factor 0 where the associative optimum is itself a fixed point (docs/limit-analysis.md). The least of
// all is a program with complementarity conditions, which ogive does not solve: every answer says so.
constexpr const char* kNotLeast = "non-associative: a collapse state of a lower factor with other joints sliding is "
                                  "not excluded (the least of all is not proven)";
bool non_associative(const LimitOptions& o) {
  return o.friction > 0 && o.friction_model == FrictionModel::non_associative;
}

// Why a collapse load factor has no kinematic one to check it against.
std::string no_mechanism_note(const LimitResult& r, const LimitOptions& options) {
  if (r.collapse_state.hinges.size() > kMaxMechanismHinges)
    return fmt::format("the collapse state touches {} joints: the mechanism check takes at most {} hinges "
                       "(a run of consecutive ones counting as three)",
                       r.collapse_state.hinges.size(), kMaxMechanismHinges);
  return options.friction > 0 ? "no rotational mechanism through the collapse hinges: joints slide at collapse"
                              : "no one-degree rotational mechanism through the collapse hinges";
}

// The notes of a successful result after the first (how t_min's search ended): what is absent, and why;
// a non-associative iteration that did not converge (sliding_failure) makes it not_converged.
void add_notes(LimitResult& r, const LimitOptions& options, const std::string& walls_note, bool forceless,
               bool unbounded_thrust, bool live, const std::string& sliding_failure) {
  auto note = [&](const std::string& text) { r.message += (r.message.empty() ? "" : "; ") + text; };
  if (!walls_note.empty()) note(walls_note);
  if (forceless)
    note("the thrust vanishes at some joints (voussoirs without weight or load between loaded ones): no margin "
         "there to search t_min by, and no hinge");
  if (!sliding_failure.empty()) r.status = LimitStatus::not_converged;
  if (unbounded_thrust) note("no largest thrust: a thrust line of any H fits inside the arch (H_max absent)");
  if (live && std::isnan(r.load_factor()))
    note(sliding_failure.empty() ? "the live load cannot turn the arch into a mechanism (no finite load factor)"
                                 : "the non-associative friction iteration of the collapse load factor did not "
                                   "converge: " + sliding_failure);
  if (!std::isnan(r.load_factor()) && std::isnan(r.load_factor_mechanism)) note(no_mechanism_note(r, options));
}

// The collapse load factor's program, by the friction model: with `failure` (then no answer: the
// outcome infeasible) when the non-associative iteration did not converge, and its note.
LimitLp::Answer collapse_answer(LimitLp& lp, const Ring& ring, const LimitOptions& options, Work& work,
                                std::string& failure, std::string& note) {
  auto collapse = [&](const std::vector<int>* w) { return lp.collapse(w); };
  const LimitLp::Answer c = solve_warm(lp, work.collapse_basis, collapse);
  limit_detail::SlidingIteration sliding =
      limit_detail::non_associative(lp, ring, options, c, std::abs(ring.total_live()), collapse);
  failure = sliding.failure;
  note = sliding.note;
  if (!failure.empty()) sliding.answer.outcome = LimitLp::Outcome::infeasible;
  else if (std::optional<LimitLp::Answer> low =
               limit_detail::least_thrust_collapse(lp, ring, options, std::abs(ring.total_live()), collapse);
           low && sliding.answer.outcome == LimitLp::Outcome::optimal &&
           low->load_factor <
               sliding.answer.load_factor - kLimitTolerance * std::max(std::abs(sliding.answer.load_factor), kZeroFactor)) {
    note = fmt::format("non-associative: the arch at its least thrust under its own weight slides at factor {:.6g}, "
                       "below the {:.6g} the iteration from the associative optimum reached",
                       low->load_factor, sliding.answer.load_factor);
    return *low;
  }
  return sliding.answer;
}

// One analysis on the ring whose joints are `refined` and the loads' (fractions_at), and where the next
// ring should be finer: next to every hinge of its states and of the thinnest arch.
struct Round {
  LimitResult result;
  std::vector<double> refinement;
};

Round analyse_round(const Scene& scene, const LimitOptions& options, const std::vector<double>& refined,
                    double previous_t_min, double previous_b_min, Work& work) {
  const Curve& curve = *scene.curve;
  Round round;
  LimitResult& r = round.result;
  limit_detail::make_ring_at(scene, options, fractions_at(scene, scene.thickness, options, refined, work.beside_loads),
                             r.ring, work.scratch);
  const Ring& ring = r.ring;
  require_loaded(scene, ring);
  const bool live = ring.has_live_load();
  const double load_factor = live ? 1.0 : 0.0;  // the H range and t_min: under the loads as given

  r.V = limit_detail::arch_half_load(ring);
  LimitLp& lp = limit_detail::programs_of(ring, options, work.workspace, work.lp);
  const int solves_before = lp.solves();
  auto fail = [&](const char* problem, const char* failure) {  // failure: LimitLp::Answer::failure
    r.status = LimitStatus::lp_failure;
    r.message = fmt::format("the LP of {} stopped without an answer{}{}", problem, failure ? ": " : "", failure ? failure : "");
    r.lp_solves += lp.solves() - solves_before;
    return round;
  };
  auto state = [&](const LimitLp::Answer& a) {
    return thrust_state(ring, a.H, a.V, a.M, a.load_factor, 1e-9, options.compressive_strength);
  };

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
  std::string sliding_failure, sliding_note;  // the non-associative iteration's of the collapse load factor
  if (live) {
    const LimitLp::Answer c = collapse_answer(lp, ring, options, work, sliding_failure, sliding_note);
    if (c.outcome == LimitLp::Outcome::optimal) {
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
  ThicknessMargin f(
      ThicknessMargin::Of::arch, scene, options,
      [&](double thickness) { return fractions_at(scene, thickness, options, refined, work.beside_loads); }, load_factor,
      work.margin_ring, work.scratch, work.workspace, work.margin_lp);
  f.basis = lp.faces(margin.basis);
  f.basis_joints = static_cast<int>(ring.joints.size());
  const double t = scene.thickness;
  const double t_cap = std::min(0.99 * max_thickness(curve), limit_detail::thickest_on_walls(scene));
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
    limit_detail::add_sliding_refinement(ring, *st, options, round.refinement);
    if (stress_blocks(ring, st->hinges)) work.beside_loads = true;
  }
  if (!std::isnan(r.thickness_min)) {
    round.refinement.insert(round.refinement.end(), f.refinement.begin(), f.refinement.end());
    if (f.feasible_blocks) work.beside_loads = true;
  }
  const limit_detail::WallSearch walls =
      limit_detail::least_wall_thickness(scene, options, fractions_at(scene, t, options, refined, work.beside_loads), load_factor,
                                         previous_b_min, r, round.refinement);
  if (walls.failed) return fail("the feasibility margin while searching the least wall thickness", nullptr);
  // The next ring is refined next to every joint the collapse state touches; the result lists the
  // mechanism's hinges (a thrust line along a face touches a run of joints, of which the mechanism needs
  // one).
  if (!mechanism.hinges.empty()) r.collapse_state.hinges = std::move(mechanism.hinges);
  if (fails_virtual_work(r, "collapse load factor", r.load_factor(), r.load_factor_mechanism)) return round;
  if (!admissible) {
    r.status = LimitStatus::inadmissible;
    r.message = inadmissible_message(options, r.thickness_min, t_cap, walls.on, walls.thinner);
    return round;
  }
  r.status = LimitStatus::success;
  if (!bracketed) r.message = fmt::format("t_min below {} m: not searched further", hi);
  add_notes(r, options, walls.note, forceless, unbounded_thrust, live, sliding_failure);
  if (!sliding_note.empty()) r.message += (r.message.empty() ? "" : "; ") + sliding_note;
  if (non_associative(options) && !std::isnan(r.load_factor()))
    r.message += std::string(r.message.empty() ? "" : "; ") + kNotLeast;
  return round;
}

// The largest relative change of a number between two results (NaN in one only: infinite).
double largest_change(const LimitResult& a, const LimitResult& b) {
  double worst = 0;
  auto compare = [&](double x, double y, double floor = 0) {
    if (std::isnan(x) && std::isnan(y)) return;
    if (std::isnan(x) != std::isnan(y)) {
      worst = std::numeric_limits<double>::infinity();
      return;
    }
    const double scale = std::max({std::abs(x), std::abs(y), floor});
    if (scale > 0) worst = std::max(worst, std::abs(x - y) / scale);
  };
  compare(a.H_min(), b.H_min());
  compare(a.H_max(), b.H_max());
  compare(a.thickness_min, b.thickness_min);
  compare(a.wall_thickness_min, b.wall_thickness_min);
  compare(a.load_factor(), b.load_factor(), kZeroFactor);
  compare(a.load_factor_mechanism, b.load_factor_mechanism, kZeroFactor);
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
    limit_detail::add_sliding_refinement(out.ring, out.collapse.state, options, refinement);
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
  Round round = analyse_round(scene, options, refined, kNaN, kNaN, work);
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
    Round next =
        analyse_round(scene, options, refined, round.result.thickness_min, round.result.wall_thickness_min, work);
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
    if (!h.collapse.sliding_note.empty())
      r.message += std::string(r.message.empty() ? "" : "; ") + "a_c " + h.collapse.sliding_note;
    if (non_associative(options) && std::isnan(r.load_factor()) && !std::isnan(r.horizontal_load_factor()))
      r.message += std::string(r.message.empty() ? "" : "; ") + "a_c " + kNotLeast;
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
