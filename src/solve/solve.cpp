#include "ogive/solve/solve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/LU>
#include <fmt/format.h>

#include "methods/bvp.hpp"
#include "methods/closed_form.hpp"
#include "methods/no_tension.hpp"
#include "methods/quadrature.hpp"
#include "methods/shooting.hpp"
#include "ogive/core/thrust_line.hpp"
#include "ogive/solve/model_error.hpp"

namespace ogive {

namespace {

void add_work(Diagnostics& to, const Diagnostics& from) {
  to.steps += from.steps;
  to.rhs_evaluations += from.rhs_evaluations;
  to.error_test_failures += from.error_test_failures;
  to.jacobian_evaluations += from.jacobian_evaluations;
}

void set_work(Diagnostics& to, const Diagnostics& from) {
  to.steps = from.steps;
  to.rhs_evaluations = from.rhs_evaluations;
  to.error_test_failures = from.error_test_failures;
  to.jacobian_evaluations = from.jacobian_evaluations;
}

Solution solve_once(const std::shared_ptr<const ArchModel>& model, const Options& options, Method method,
                    int segments) {
  if (method == Method::quadrature) {
    // It samples its profile itself (its error estimate compares two degrees' profiles).
    Options verified = options;
    if (options.stations > 0) verified.stations = kVerificationStations;
    return solve_quadrature(model, verified);
  }
  Solution sol = method == Method::closed_form ? solve_closed_form(model, options)
                                               : solve_shooting(model, options, segments);
  if (sol.field && options.stations > 0) {
    if (sol.method == Method::closed_form && options.unprinted_profile) sol.profile = field_scan(sol);
    else sample_profile(sol, kVerificationStations);
  }
  return sol;
}

// The options of the verifying solve: 16 times tighter in rtol and in atol. The user's atol is taken
// only where it is tighter than the default, so that a loose atol cannot make both solves agree on the
// same wrong answer (atol 1e300 turns CVODE's error control off in both).
// `factor` 1: the same rtol, the atol capped at the default (a verified solve's first one).
Options verifying_options(const Options& options, double factor = 16) {
  Options tighter = options;
  tighter.rtol = options.rtol / factor;
  Options plain = options;
  plain.atol = 0;
  const double default_atol = cvode_tolerances(plain).atol;
  tighter.atol = (options.atol > 0 ? std::min(options.atol, default_atol) : default_atol) / factor;
  return tighter;
}

// Whether a 16 times tighter CVODE solve exists above CVODE's tolerance floor.
bool verifiable(const Options& options) {
  return cvode_tolerances(verifying_options(options)).rtol * 16 <= cvode_tolerances(options).rtol * (1 + 1e-9);
}

// How much tighter than `options` a further CVODE solve can run above CVODE's floor, up to 16 times.
double room_below(const Options& options) { return std::min(16.0, cvode_tolerances(options).rtol / kCvodeRtolFloor); }

// CVODE's rtol per unit of --rtol (cvode_tolerances: 1/10 with Adams, 1/1000 with BDF).
double cvode_factor(const Options& options) {
  Options o = options;
  o.rtol = 1;
  return cvode_tolerances(o).rtol;
}

// The smallest rtol at which a verifying CVODE solve 16 times tighter than a solve at rtol runs at
// least 16 times above CVODE's floor (2.56e-12 with Adams, 2.56e-10 with BDF): the no-tension section's.
double full_room_rtol(const Options& options) { return 16 * 16 * kCvodeRtolFloor / cvode_factor(options); }

// solve_verified's ladder: CVODE solves each 16 times tighter than the one before, every one of them a
// full 16 times tighter, down to CVODE's floor at most (kTightestRtol). A solve held less than 16 times
// tighter by the floor runs where round-off sets its error as much as the tolerance, and that error
// changes erratically with the tolerance (calibration.py, seed 2: single shooting with Adams at rtol
// 1e-12 on a thin pointed arch, t/L 0.017: raw solves at CVODE rtol 1e-15 and one ulp above it were off
// by 1.1e-13 and 3.7e-13; its tightest solve there, clamped to the floor 6.25 times tighter than the
// second and returned with their difference, 4.3e-13, as estimate, was off by 1.3e-12). So the ladder
// starts at CVODE rtol f x rtol, or where that would take its third solve below the floor, at
// kLadderTop = 16^2 x the floor (2.56e-13): for --rtol below 2.56e-12 with Adams, 2.56e-10 with BDF,
// the first solve runs looser than f x rtol, and whether the row meets rtol is what its estimate says.
// (The ladder used to start at f x rtol there and squeeze its tightest solve against the floor: below
// 6.4e-13 with Adams, 6.4e-11 with BDF, rows were unverified, and above, up to 2.56e-12 / 2.56e-10,
// tolerance_not_met whatever their differences showed: single shooting with BDF at rtol 1e-10 said so
// on a third of the random scenes whose numbers were within rtol, benchmarks/pessimism/README.md.)
constexpr double kLadderStep = 16;
constexpr double kTightestRtol = kCvodeRtolFloor;
constexpr double kLadderTop = kLadderStep * kLadderStep * kTightestRtol;
constexpr std::size_t kLadderSolves = 5;  // at most: a fourth and fifth where the differences contract
// A solve returned on the contraction of the differences carries this multiple of its difference from
// the solve above it (solve_verified).
constexpr double kContractedFactor = 3;

// The options of solve_verified's first solve: rtol as asked, or looser where the ladder below it would
// pass CVODE's floor (kLadderTop); the atol capped at the default (verifying_options).
Options ladder_start(const Options& options) {
  Options start = options;
  start.rtol = std::max(options.rtol, kLadderTop / cvode_factor(options));
  return verifying_options(start, 1);
}

// A verified solve never runs looser than CVODE's default atol: a loose --atol would only make the first
// solve worse and the difference larger, while the returned (tighter) solution stays the same, so the
// status would change with an option that did not change the numbers.
//
// Three solves x1, x2, x3, each 16 times tighter than the one before (ladder_start: the first at f x
// rtol or looser, the third at CVODE's floor at most); d1 = |x1 - x2|, d2 = |x2 - x3|;
// x2 is returned. The difference of two solves bounds the tighter one's error only if that one is at
// least twice as accurate as the looser: then e2 <= d1 (from x1: e2 <= e1 / 2 and d1 >= e1 - e2);
// from x3, the weaker e3 <= 2 e2 / 3 gives e2 <= d2 + e3, so e2 <= 3 d2. CVODE controls local errors:
// its global error usually falls with the tolerance but need not (Adams changing order can leave a 16
// times tighter solve no better), so neither assumption alone is safe; the estimate is the larger of
// the two, max(d1, 3 d2), which fails only when x2 is not twice as good as x1 and x3 not 1.5 times as
// good as x2. (With 2 d2, from e3 <= e2 / 2, calibration.py, seed 1, found single shooting with Adams
// at rtol 1e-10 on a segmental arch with e1 = 1.60e-12, e2 = 1.73e-12, e3 = 0.89e-12: 2 d2 = 0.97 e2.)
// Where that misses rtol but the differences contract (d2 <= d1 / 2: the errors do fall with the
// tolerance, seen rather than assumed), x3 is returned with 3 d2 (kContractedFactor), which bounds e3
// when e3 <= 3 e2 / 4 (from e2 <= d2 + e3). Single shooting of a thin arch has errors that change
// erratically with the tolerance around their trend, and d2 alone (e3 <= e2 / 2) fell short: a random
// pointed arch (t/L 0.013, benchmarks/pessimism/random_scenes.py, rtol 1e-7) had e3 = 2.67e-8 and e4 =
// 2.70e-8 for d3 = 1.13e-8, where a raw solve at an rtol a millionth from the fourth's was off by 0.82e-8.
// Where that misses rtol too, the ladder goes one rung down while the next solve fits (a full 16
// times tighter, above CVODE's floor) and the differences keep contracting, up to kLadderSolves
// solves: x4 with 3 d3, x5 with 3 d4 (d3 <= d2 / 2 seen, and so on). A thin arch whose single shooting
// solve at f x rtol is off by a hundred times rtol needs them (the same arch at rtol 1e-9: raw errors
// 1.9e-7, 1.2e-8, 3.6e-10, 2.5e-11 down the ladder).
// A difference that is not a number (a station without numbers in either solve) is no agreement: the
// row has no estimate (unverified), never the estimate of what is left.
// The round-off of one CVODE solve's integration, which the differences between the verifying solves
// see only where it differs between them: every step rounds the scaled state (of order one) by a few
// eps, and independent roundings add up as a random walk, sqrt(steps) eps, which the boundary-value
// solve amplifies by its condition. kIntegrationRoundoff (2 for Adams: a corrector's and the history's
// update per step) was checked against the 40-digit reference over 40 random circular arches
// (benchmarks/pessimism/calibration.py, seed 1): it would have turned none of their 940 success rows
// into a miss, and it covers the pessimism table's row at round-off whose differences fell short
// (multiple shooting with BDF at rtol 1e-10: differences 1.5e-13, true error 1.6e-13). BDF's steps
// (a Newton iteration, a linear solve each) round more: over calibration.py's seeds 1 and 2 (80 random
// arches, 320 rows of multiple shooting with BDF at rtol 1e-9 .. 1e-12, thousands of steps) its
// reactions' error reached 6.2 condition eps sqrt(steps) where the differences did not see it (at rtol
// 1e-9: true errors 7.9e-13 and 1.1e-12 for differences of 7.6e-13 and 8.8e-13); 8 keeps a margin of 1.3.
constexpr double kIntegrationRoundoffAdams = 2;
constexpr double kIntegrationRoundoffBdf = 8;
double integration_roundoff(const Diagnostics& own, Integrator integrator) {
  const double per_step = integrator == Integrator::adams ? kIntegrationRoundoffAdams : kIntegrationRoundoffBdf;
  return per_step * own.condition_estimate * std::numeric_limits<double>::epsilon() *
         std::sqrt(static_cast<double>(own.steps));
}

Solution solve_verified(const std::shared_ptr<const ArchModel>& model, const Options& options, Method method,
                        int segments) {
  std::vector<Solution> x;       // the ladder's solves, each 16 times tighter than the one before
  std::vector<double> roundoff;  // each one's integration round-off
  Diagnostics spent;             // the work of every solve, on whichever is returned
  Options next = ladder_start(options);
  auto climb = [&] {
    x.push_back(solve_once(model, next, method, segments));
    if (!x.back().field && x.back().status == Status::integrator_failure) {
      // Once more with a looser atol (retry_atol, shooting.hpp: CVODE stopped on a component held below
      // its own round-off); the ladder's differences judge the answer as any other.
      Options looser = next;
      looser.atol = retry_atol(cvode_tolerances(next).atol);
      Solution again = solve_once(model, looser, method, segments);
      add_work(spent, again.field ? x.back().diagnostics : again.diagnostics);  // the discarded one's work
      if (again.field) x.back() = std::move(again);
    }
    roundoff.push_back(integration_roundoff(x.back().diagnostics, options.integrator));
    add_work(spent, x.back().diagnostics);
    set_work(x.back().diagnostics, spent);
    next = verifying_options(next, kLadderStep);
    return static_cast<bool>(x.back().field);
  };
  // Where the ladder starts looser than f x rtol (ladder_start) and misses rtol, the message says why.
  const double lowest = kLadderTop / cvode_factor(options);
  const std::string held = options.rtol < lowest ? fmt::format("the verifying solves stop at CVODE's floor, so below "
                                                               "rtol {:.3g} ({}) they start looser than rtol / {:.0f}",
                                                               lowest, to_string(options.integrator), 1 / cvode_factor(options))
                                                 : "";
  auto returned = [&](std::size_t k, double estimate, const std::string& why = {}) {
    Solution sol = std::move(x[k]);
    set_work(sol.diagnostics, spent);
    sol.diagnostics.error_estimate = estimate;
    if (!why.empty()) sol.message = why;
    else if (!within_tolerance(estimate, options.rtol) && sol.message.empty()) sol.message = held;
    return sol;
  };
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!climb() || !climb()) return std::move(x.back());
  double above = solution_difference(x[0], x[1]);  // x[k]'s difference from the looser solve
  for (std::size_t k = 1;; ++k) {
    if (!climb()) return returned(k, kNaN, "not verified: the tightest solve failed (" + x[k + 1].message + ")");
    const double below = solution_difference(x[k], x[k + 1]);
    if (std::isnan(above) || std::isnan(below))
      return returned(k, kNaN, "not verified: a verifying solve has a station without numbers");
    const double estimate = std::max({above, 3 * below, roundoff[k]});
    if (within_tolerance(estimate, options.rtol) || !(below <= above / 2)) return returned(k, estimate);
    // The differences contract: x[k + 1] with three times its difference from x[k], or one more rung
    // where it fits.
    const double finer = std::max(kContractedFactor * below, roundoff[k + 1]);
    const bool fits = next.rtol * cvode_factor(next) >= kTightestRtol * (1 - 1e-9);
    if (within_tolerance(finer, options.rtol) || !fits || x.size() >= kLadderSolves) return returned(k + 1, finer);
    above = below;
  }
}

// The message of a raw solve, which verification (Options::verify, the CLI's --no-verify) was asked to skip.
constexpr const char* kNotVerified = "not verified (--no-verify): no error estimate";

// Turns a provisional `success` into what the numbers are worth against rtol: ill_conditioned,
// tolerance_not_met (estimate or residuals above rtol) or unverified (no estimate). The one place that
// applies within_tolerance to a solution.
void judge_solution(Solution& sol, double rtol) {
  if (sol.status != Status::success) return;
  Diagnostics& d = sol.diagnostics;
  const double roundoff = roundoff_bound(sol);
  // Every estimate is at least the round-off bound; the closed form's is that bound alone.
  d.error_estimate = sol.method == Method::closed_form ? roundoff : std::max(d.error_estimate, roundoff);
  if (!within_tolerance(roundoff, rtol)) {
    sol.status = Status::ill_conditioned;
    sol.message = fmt::format("round-off bound {:.3g} (condition estimate {:.3g}) exceeds rtol {:.3g}", roundoff,
                              d.condition_estimate, rtol);
    return;
  }
  if (std::isnan(d.error_estimate)) {
    sol.status = Status::unverified;
    // The estimate is relative to the reactions: where every one is zero (no load reaches the ring and
    // the supports do not move) the solves' difference has no scale.
    const Reactions& r = sol.reactions;
    const bool unloaded = r.H_left == 0 && r.V_left == 0 && r.V_right == 0 && r.H_right == 0 && r.M_left == 0 &&
                          r.M_right == 0;
    // Unloaded is the cause whatever the verification said (its differences are 0 / 0).
    if (unloaded)
      sol.message = "not verified: no load reaches the ring and the supports do not move, so every reaction is 0 "
                    "and a relative error has no scale";
    else if (sol.message.empty())
      sol.message = "not verified: no error estimate (the solves' difference is not a number)";
    return;
  }
  const double residual = std::max(d.boundary_residual, d.equilibrium_residual);
  if (!within_tolerance(d.error_estimate, rtol)) {
    sol.status = Status::tolerance_not_met;
    sol.message = fmt::format("estimated error {:.3g} exceeds rtol {:.3g}", d.error_estimate, rtol) +
                  (sol.message.empty() ? "" : ": " + sol.message);
  } else if (!within_tolerance(residual, rtol)) {
    sol.status = Status::tolerance_not_met;
    sol.message = fmt::format("boundary or equilibrium residual {:.3g} exceeds rtol {:.3g}", residual, rtol);
  }
}

// One method's verified (or raw) solve, judged against `asked`, the rtol the user asked for (auto may
// hand the method a tighter options.rtol).
Solution solve_with(const std::shared_ptr<const ArchModel>& model, const Options& options, Method method,
                    int segments, double asked) {
  // The closed form needs no second solve (its error is round-off), the quadrature has its own estimate.
  const bool own_estimate = method == Method::closed_form || method == Method::quadrature;
  Solution sol = own_estimate || !options.verify ? solve_once(model, options, method, segments)
                                                 : solve_verified(model, options, method, segments);
  if (!own_estimate && !options.verify && sol.message.empty()) sol.message = kNotVerified;
  judge_solution(sol, asked);
  // Stepping across a jump of curvature or of the load (--ignore-breakpoints), CVODE's errors change
  // erratically with its tolerance, so the difference of solves at three tolerances bounds nothing (the
  // stability map: single shooting with Adams on a three-centred arch at rtol 1e-8, an estimate of
  // 2.0e-9 for a profile off by 2.6e-8). Such a row never says success.
  if (!own_estimate && sol.status == Status::success && !options.restart_at_breakpoints &&
      !model->breakpoints().empty()) {
    sol.status = Status::unverified;
    sol.message = "stepped across the breakpoints (--ignore-breakpoints): the error estimate does not hold across "
                  "a jump of curvature or load";
  }
  // The profile was compared at kVerificationStations; the printed one has the stations asked for (an
  // unprinted one is dropped: its work is done).
  if (sol.field && options.stations > 0 && options.unprinted_profile) sol.profile.clear();
  else if (sol.field && options.stations > 0 && options.stations != kVerificationStations)
    sample_profile(sol, options.stations);
  return sol;
}

}  // namespace

namespace {

// Whether two scenes differ at most in their supports' movements and in the sizes of their loads (point
// forces, live intensities, fill densities; the loads' places the same): the continuation's path.
bool on_one_path(const Scene& a, const Scene& b) {
  auto same_support = [](const Support& x, const Support& y) { return x.kind == y.kind; };
  auto same_places = [](const Loads& x, const Loads& y) {
    if (x.points.size() != y.points.size() || x.live.size() != y.live.size() || x.fills.size() != y.fills.size())
      return false;
    for (std::size_t i = 0; i < x.points.size(); ++i)
      if (x.points[i].at != y.points[i].at) return false;
    for (std::size_t i = 0; i < x.live.size(); ++i)
      if (x.live[i].from != y.live[i].from || x.live[i].to != y.live[i].to) return false;
    for (std::size_t i = 0; i < x.fills.size(); ++i)
      if (x.fills[i].height_ratio != y.fills[i].height_ratio) return false;
    return true;
  };
  // Curves are rebuilt for every scene of a sweep: the same curve has the same family and lengths.
  const bool same_curve = a.curve == b.curve ||
                          (a.curve->family() == b.curve->family() && a.curve->extent() == b.curve->extent() &&
                           a.curve->span() == b.curve->span() && a.curve->length() == b.curve->length() &&
                           a.curve->rise() == b.curve->rise() && a.curve->max_curvature() == b.curve->max_curvature());
  const Material &m = a.material, &n = b.material;
  return same_curve && a.thickness == b.thickness && a.section == b.section && a.beam_model == b.beam_model &&
         a.crown_hinge == b.crown_hinge &&
         a.horizontal_acceleration == b.horizontal_acceleration &&
         m.youngs_modulus == n.youngs_modulus && m.poisson_ratio == n.poisson_ratio && m.density == n.density &&
         m.gravity == n.gravity && m.shear_coefficient == n.shear_coefficient && m.plane_strain == n.plane_strain &&
         same_support(a.left, b.left) && same_support(a.right, b.right) && same_places(a.loads, b.loads) &&
         a.symmetric() == b.symmetric();
}

// The scene with movements and load sizes (1 - lambda) of `from`'s plus lambda of `to`'s (on_one_path).
Scene between(const Scene& from, const Scene& to, double lambda) {
  Scene s = to;
  auto mix = [lambda](double a, double b) { return lambda == 1 ? b : (1 - lambda) * a + lambda * b; };
  for (auto [out, a, b] : {std::tuple{&s.left, &from.left, &to.left}, std::tuple{&s.right, &from.right, &to.right}}) {
    out->spread = mix(a->spread, b->spread);
    out->settlement = mix(a->settlement, b->settlement);
    out->rotation = mix(a->rotation, b->rotation);
  }
  for (std::size_t i = 0; i < s.loads.points.size(); ++i)
    s.loads.points[i].force = mix(from.loads.points[i].force, to.loads.points[i].force);
  for (std::size_t i = 0; i < s.loads.live.size(); ++i)
    s.loads.live[i].intensity = mix(from.loads.live[i].intensity, to.loads.live[i].intensity);
  for (std::size_t i = 0; i < s.loads.fills.size(); ++i)
    s.loads.fills[i].density = mix(from.loads.fills[i].density, to.loads.fills[i].density);
  return s;
}

// A solution's springing state in another model's scaled units (the force scale follows the loads).
StateVector springing_state_for(const Solution& from, const ArchModel& to) {
  const Scales &a = from.model->scales(), &b = to.scales();
  StateVector y = from.springing_state;
  y[kUx] *= a.displacement / b.displacement;
  y[kUy] *= a.displacement / b.displacement;
  y[kPsi] *= a.rotation / b.rotation;
  y[kFx] *= a.force / b.force;
  y[kFy] *= a.force / b.force;
  y[kM] *= a.moment / b.moment;
  return y;
}

// The work one scene's no-tension solves may spend, over all its tries, paths and verifying solves (in
// the methods' own counts, Diagnostics::rhs_evaluations): the quadrature form's integrand evaluations,
// and the CVODE right-hand sides of Newton shooting, single and multiple. A cracked arch at the defaults
// takes some 10^4 to 10^5 of each (a verified scene at rtol 1e-11 with four support movements, 1.2 10^6
// right-hand sides by single shooting, 5.3 10^5 by multiple shooting); the budgets are a few seconds'
// work. A solve that finds its budget spent stops with not_converged, and the row's message says which
// budget ran out.
constexpr std::int64_t kQuadratureWork = 10'000'000;
constexpr std::int64_t kCvodeWork = 2'000'000;
struct NoTensionWork {
  std::int64_t quadrature = kQuadratureWork, cvode = kCvodeWork;
  std::string ran_out;  // the message of the first solve that spent its budget
};

// One no-tension solver: Newton shooting (segments 1: single, else multiple) or its quadrature form.
struct NoTensionTry {
  Method method = Method::quadrature;
  int segments = 0;
  double rtol_factor = 1;  // on the rtol handed to the solver
  NoTensionWork* work = nullptr;  // the scene's budget, drawn on by every solve (none: unbounded)
};

// One no-tension solve, raw (no verification), from a neighbouring solution's springing state, else from
// the linear solution (computed only then: along a path every step has a neighbour).
Solution no_tension_once(const Scene& scene, const Options& options, const NoTensionTry& how,
                         const Solution* from = nullptr) {
  auto model = std::make_shared<const ArchModel>(scene, options.whole_arch);
  std::vector<StateVector> guesses;
  if (from) {
    guesses.push_back(springing_state_for(*from, *model));
  } else {
    Scene elastic = scene;
    elastic.section = SectionKind::elastic;
    Options linear = options;
    linear.method = Method::automatic;
    const Solution lin = solve(elastic, linear);
    if (lin.field) guesses.push_back(lin.springing_state);
  }
  if (!how.work)
    return how.method == Method::quadrature ? solve_no_tension_quadrature(model, options, guesses)
                                            : solve_no_tension(model, options, how.segments, guesses);
  std::int64_t& left = how.method == Method::quadrature ? how.work->quadrature : how.work->cvode;
  const std::int64_t budget = std::max<std::int64_t>(left, 0);
  Solution sol = how.method == Method::quadrature ? solve_no_tension_quadrature(model, options, guesses, budget)
                                                  : solve_no_tension(model, options, how.segments, guesses, budget);
  left -= sol.diagnostics.rhs_evaluations;
  if (left <= 0 && sol.status == Status::not_converged) {
    const std::int64_t whole = how.method == Method::quadrature ? kQuadratureWork : kCvodeWork;
    sol.message = work_budget_message(whole, how.method, true);
    if (how.work->ran_out.empty()) how.work->ran_out = fmt::format("{} in {}", sol.message, to_string(how.method));
  }
  return sol;
}

// The no-tension scene `to`, traced from the solved scene of `start` (on_one_path) in steps of the
// movements and load sizes that double after a success and halve after a failure, at most kPathSolves
// solves (near an arch's collapse every step can fail slowly): the raw solve at the target, or the last
// failure.
constexpr int kPathSolves = 40;
Solution trace_path(const Solution& start, const Scene& to, const Options& options, const NoTensionTry& how,
                    int& newton_iterations) {
  const Scene& from = start.model->scene();
  double lambda = 0, step = 1;
  Solution at = start, failure;
  for (int solves = 0; lambda < 1 && solves < kPathSolves; ++solves) {
    const double next = std::min(1.0, lambda + step);
    Solution trial = no_tension_once(between(from, to, next), options, how, &at);
    newton_iterations += trial.diagnostics.newton_iterations;
    if (trial.status == Status::success) {
      lambda = next;
      at = std::move(trial);
      step = std::min(1.0, 2 * step);
    } else {
      failure = std::move(trial);
      step /= 2;
      if (step < 1e-6) break;
    }
  }
  return lambda == 1 ? at : failure;
}

// One solver's raw solve of the scene: from the previous scene's solution (continues) or the linear one;
// where Newton does not converge from them, by continuation (trace_path) from the first start that
// solves: the previous scene, the scene without its supports' movements, the same without its loads
// but the self-weight (continuation in the loads as well as in the movements).
Solution reach(const Scene& scene, const Options& raw, const NoTensionTry& how, const Solution* previous,
               int& iterations) {
  Solution coarse = no_tension_once(scene, raw, how, previous);
  iterations += coarse.diagnostics.newton_iterations;
  if (previous && coarse.status != Status::success) {
    coarse = no_tension_once(scene, raw, how);
    iterations += coarse.diagnostics.newton_iterations;
  }
  if (coarse.status != Status::not_converged && coarse.status != Status::integrator_failure) return coarse;
  std::vector<Scene> starts;
  Scene still = scene;
  still.left.spread = still.left.settlement = still.left.rotation = 0;
  still.right.spread = still.right.settlement = still.right.rotation = 0;
  // Without movements `still` is the scene itself, whose solve has just failed: not solved again.
  auto moves = [](const Support& a) { return a.spread != 0 || a.settlement != 0 || a.rotation != 0; };
  if (moves(scene.left) || moves(scene.right)) starts.push_back(still);
  if (!scene.loads.empty() && scene.material.density > 0) {
    Scene unloaded = still;
    for (PointLoad& p : unloaded.loads.points) p.force = 0;
    for (LiveLoad& q : unloaded.loads.live) q.intensity = 0;
    for (FillLoad& f : unloaded.loads.fills) f.density = 0;
    starts.push_back(unloaded);
  }
  if (previous) coarse = trace_path(*previous, scene, raw, how, iterations);
  for (const Scene& from : starts) {
    if (coarse.status == Status::success) break;
    const Solution start = no_tension_once(from, raw, how);
    iterations += start.diagnostics.newton_iterations;
    if (start.status == Status::success) coarse = trace_path(start, scene, raw, how, iterations);
  }
  return coarse;
}

// The larger of two estimates, a NaN one (not estimated) ignored.
double larger_estimate(double a, double b) { return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b); }

// The coarse solve verified as every CVODE solve: again 16 times tighter, from the coarse solution (the
// quadrature down to the options' floor of 1e-14, CVODE down to its own); the estimate is the larger
// of the two solves' difference and the tighter solve's own (the quadrature's: what the accuracy its
// integrals reach leaves in the reactions, which round-off near a hinge can hold above rtol). CVODE's
// tighter solve must itself run at least 16 times above CVODE's floor: nearer it round-off, not the
// tolerance, sets its error, and the two solves can share it (the pessimism table: Newton shooting
// with BDF at rtol 1e-10, CVODE at 6.25e-15, estimated 3.1e-11 for a profile off by 5.3e-11). Without a
// tighter solve, only an own estimate above rtol is kept (it says tolerance_not_met); else unverified.
Solution verify_no_tension(const Scene& scene, const Options& options, const Options& raw, const NoTensionTry& how,
                           const Solution& coarse, int& iterations, Diagnostics& spent) {
  double floor = coarse.diagnostics.error_estimate;
  Solution sol = coarse;
  sol.diagnostics.error_estimate = std::numeric_limits<double>::quiet_NaN();
  if (!options.verify) {
    sol.message = kNotVerified;
    return sol;
  }
  const bool quadrature = how.method == Method::quadrature;
  if (!(quadrature ? raw.rtol / 16 >= 1e-14 : verifiable(raw) && room_below(verifying_options(raw)) >= 16)) {
    if (floor > options.rtol) sol.diagnostics.error_estimate = floor;
    else sol.message = "rtol below what a 16 times tighter solve can verify (above CVODE's floor: rtol " +
                       fmt::format("{:.3g}", full_room_rtol(raw) * options.rtol / raw.rtol) + ")";
    return sol;
  }
  Options fine = verifying_options(raw);
  fine.verify = false;
  sol = no_tension_once(scene, fine, how, &coarse);
  iterations += sol.diagnostics.newton_iterations;
  add_work(spent, sol.diagnostics);
  if (sol.status != Status::success) {
    // The answer at rtol stands, without an estimate (unverified): the tighter Newton stopping short
    // (a residual at CVODE's error through the hinges) says nothing against it.
    const std::string why = sol.message;
    sol = coarse;
    sol.diagnostics.error_estimate = std::numeric_limits<double>::quiet_NaN();
    sol.message = fmt::format("not verified: the 16 times tighter solve did not converge ({})", why);
    return sol;
  }
  Solution first = coarse;
  if (options.stations > 0) {
    sample_profile(first, kVerificationStations);
    sample_profile(sol, kVerificationStations);
  }
  floor = larger_estimate(floor, sol.diagnostics.error_estimate);
  // A difference that is not a number (a station without numbers) is no agreement: no estimate.
  const double difference = solution_difference(first, sol);
  sol.diagnostics.error_estimate = std::isnan(difference) ? difference : larger_estimate(difference, floor);
  if (std::isnan(difference)) sol.message = "not verified: a verifying solve has a station without numbers";
  return sol;
}

// Whether a is a better answer than b: success first, then one with numbers, then the smaller estimate.
bool better(const Solution& a, const Solution& b) {
  if (a.ok() != b.ok()) return a.ok();
  if (static_cast<bool>(a.field) != static_cast<bool>(b.field)) return static_cast<bool>(a.field);
  if (!a.field) return false;
  return a.diagnostics.error_estimate < b.diagnostics.error_estimate ||
         (std::isnan(b.diagnostics.error_estimate) && !std::isnan(a.diagnostics.error_estimate));
}

// Whether a quadrature answer misses rtol for a reason of the scene in double precision, which no
// other method cures, and then says in its message the rtol the scene supports: the largest of its
// error estimate, residuals and condition times round-off (what judge_solution holds against rtol),
// rounded up to one significant digit. The quadrature resolves its integrals to rtol / 100 unless
// round-off near a hinge stops it above (its own estimate carries that), and CVODE integrates the
// same section law with its own error on top.
bool name_the_floor(Solution& sol, double rtol) {
  const bool missed = sol.status == Status::tolerance_not_met || sol.status == Status::ill_conditioned;
  if (sol.method != Method::quadrature || !sol.field || !missed) return false;
  const Diagnostics& d = sol.diagnostics;
  const double limit = std::max({d.error_estimate, d.boundary_residual, d.equilibrium_residual,
                                 d.condition_estimate * std::numeric_limits<double>::epsilon()});
  if (!(limit > rtol)) return false;
  const double unit = std::pow(10.0, std::floor(std::log10(limit)));
  const double supported = std::ceil(limit / unit * (1 - 1e-12)) * unit;
  sol.message += fmt::format(": in double precision this scene's answer is good to about {:.1e} (its error estimate, "
                             "residuals and condition; round-off in the section law near the hinges bounds the "
                             "quadrature's integrals): ask for rtol {:.1e} or larger",
                             supported, supported);
  return true;
}

Solution solve_no_tension_scene(const Scene& scene, const Options& options, const Solution* previous) {
  if (options.method == Method::closed_form) {
    Solution sol;
    sol.method = options.method;
    sol.model = std::make_shared<const ArchModel>(scene, options.whole_arch);
    sol.status = Status::not_applicable;
    sol.message = "the no-tension section is solved by Newton (quadrature, shooting, multiple-shooting or auto)";
    return sol;
  }
  const bool continues = previous && previous->field && previous->model && on_one_path(previous->model->scene(), scene) &&
                         previous->model->half() == ArchModel(scene, options.whole_arch).half();
  // auto tries the quadrature form (no integration of an ODE: milliseconds), then single shooting, then
  // 8 segments, then 8 segments with CVODE 10 times tighter (a profile through hinges needs it); judged
  // against the rtol asked, always. The best answer is kept; a quadrature answer that double precision
  // holds above rtol ends the search (name_the_floor), as does an arch that cannot stand.
  std::vector<NoTensionTry> tries;
  if (options.method == Method::quadrature) tries = {{Method::quadrature, 0, 1.0}};
  else if (options.method == Method::shooting) tries = {{Method::shooting, 1, 1.0}};
  else if (options.method == Method::multiple_shooting) tries = {{Method::multiple_shooting, options.segments, 1.0}};
  else
    tries = {{Method::quadrature, 0, 1.0},
             {Method::shooting, 1, 1.0},
             {Method::multiple_shooting, 8, 1.0},
             {Method::multiple_shooting, 8, 0.1}};
  Solution best;
  int iterations = 0;
  Diagnostics spent;
  // auto always verifies (Options::verify): with it off, every try's answer would be unverified and the
  // search would run through every method.
  Options asked = options;
  if (options.method == Method::automatic) asked.verify = true;
  NoTensionWork work;
  for (NoTensionTry how : tries) {
    how.work = &work;
    Options raw = options;
    raw.verify = false;
    raw.rtol = std::max(options.rtol * how.rtol_factor, 1e-14);
    Solution coarse = reach(scene, raw, how, continues ? previous : nullptr, iterations);
    add_work(spent, coarse.diagnostics);
    Solution sol = coarse.status == Status::success
                       ? verify_no_tension(scene, asked, raw, how, coarse, iterations, spent)
                       : coarse;
    set_work(sol.diagnostics, spent);
    judge_solution(sol, options.rtol);
    const bool at_floor = name_the_floor(sol, options.rtol);
    if (sol.field && options.stations > 0 && options.unprinted_profile) sol.profile.clear();
    else if (sol.field && options.stations > 0 && static_cast<int>(sol.profile.size()) != options.stations)
      sample_profile(sol, options.stations);
    if (best.status == Status::not_applicable || better(sol, best)) best = std::move(sol);
    if (best.ok() || at_floor || best.status == Status::inadmissible) break;
  }
  best.diagnostics.newton_iterations = iterations;
  // A search cut short by a budget says so, whichever try's answer is kept.
  if (!best.ok() && !work.ran_out.empty() && best.message.find("work budget") == std::string::npos)
    best.message += (best.message.empty() ? "" : "; then ") + work.ran_out;
  return best;
}

}  // namespace

Solution solve(const Scene& scene, const Options& options, const Solution* previous) {
  scene.validate();
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  if (asks_model_error(scene, options)) return solve_with_model_error(scene, options, previous);
  if (scene.section == SectionKind::no_tension) return solve_no_tension_scene(scene, options, previous);
  auto model = std::make_shared<const ArchModel>(scene, options.whole_arch);
  switch (options.method) {
    case Method::closed_form: return solve_with(model, options, Method::closed_form, 0, options.rtol);
    case Method::shooting: return solve_with(model, options, Method::shooting, 1, options.rtol);
    case Method::multiple_shooting:
      return solve_with(model, options, Method::multiple_shooting, options.segments, options.rtol);
    case Method::quadrature: return solve_with(model, options, Method::quadrature, 0, options.rtol);
    case Method::automatic: break;
  }
  // The smallest model that meets rtol. The closed form is exact to round-off where it applies.
  {
    // Where the closed form treats the scene (a piecewise-circular curve, no distributed load but the
    // self-weight), it is exact to round-off: nothing smaller or faster.
    Solution exact = solve_with(model, options, Method::closed_form, 0, options.rtol);
    if (exact.status != Status::not_applicable) return exact;
  }
  // On smooth curves (and between a survey's points) the quadrature method, as fast as the closed form,
  // with its own error estimate; where that does not meet rtol, CVODE shooting below. (Conditioning is
  // the boundary-value problem's, the same for every method: CVODE would not cure it.)
  {
    Solution quadrature = solve_with(model, options, Method::quadrature, 0, options.rtol);
    // (not_applicable beyond the symmetric clamped arch under its own weight: quadrature.hpp)
    if (quadrature.status != Status::tolerance_not_met && quadrature.status != Status::not_applicable)
      return quadrature;
  }
  // Otherwise verified shooting with 1, 2, 4, ... 64 segments (breakpoints add more) until two doublings
  // in a row fail to halve the error estimate: more segments shorten the spans over which integration
  // errors grow and cancel (one doubling may not show it: on a thin parabola 2 segments gain little over
  // 1, 4 a factor 25). Where segments stop helping (a thin near-funicular arch, whose eccentricity in kern
  // units amplifies every error of the forces by about L/t), CVODE is run tighter instead, by what the
  // estimate says is missing. Conditioning is the problem's own (it does not change with segments), so
  // a singular or ill-conditioned system ends the search.
  Options solver = options;
  solver.verify = true;
  Solution sol;
  Diagnostics spent;  // the work of the rejected tries counts too
  int segments = 1, stalls = 0;  // stalls: the last doublings in a row that did not halve the estimate
  double previous_estimate = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < 16; ++attempt) {
    sol = solve_with(model, solver, segments == 1 ? Method::shooting : Method::multiple_shooting, segments,
                     options.rtol);
    add_work(sol.diagnostics, spent);
    spent = sol.diagnostics;
    // A failed or unverified try (a verifying solve without numbers somewhere) goes on like one that
    // missed rtol: more segments may verify where one did not.
    const bool unverified = sol.status == Status::unverified && solver.restart_at_breakpoints;
    if (sol.status != Status::tolerance_not_met && sol.status != Status::integrator_failure && !unverified) break;
    const double estimate = sol.diagnostics.error_estimate;
    const bool improving = !(estimate > previous_estimate / 2);  // also true after an integrator failure (NaN)
    previous_estimate = estimate;
    stalls = improving ? 0 : stalls + 1;
    if (segments < 64 && stalls < 2) {
      segments *= 2;
      continue;
    }
    if (solver.rtol < options.rtol && !improving) break;  // tightening no longer helps: round-off's floor
    Options tighter = solver;
    tighter.rtol = std::max(solver.rtol * std::clamp(options.rtol / estimate / 4, 1e-3, 0.25), 1e-14);
    // Tighter only while the verifying ladder's first solve runs tighter: below that its tightest solve
    // would reach CVODE's floor, and the ladder starts no lower (ladder_start).
    if (!(cvode_tolerances(ladder_start(tighter)).rtol < cvode_tolerances(ladder_start(solver)).rtol)) break;
    solver = tighter;
  }
  return sol;
}

}  // namespace ogive
