#include "ogive/solve.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/LU>
#include <fmt/format.h>

#include "bvp.hpp"
#include "ogive/closed_form.hpp"
#include "ogive/quadrature.hpp"
#include "ogive/shooting.hpp"

namespace ogive {

namespace {

void add_work(Diagnostics& to, const Diagnostics& from) {
  to.steps += from.steps;
  to.rhs_evaluations += from.rhs_evaluations;
  to.error_test_failures += from.error_test_failures;
  to.jacobian_evaluations += from.jacobian_evaluations;
}

Solution solve_once(const std::shared_ptr<const ArchModel>& model, const Options& options, Method method,
                    int segments) {
  if (method == Method::quadrature) {
    // It samples its profile itself (its error estimate compares two degrees' profiles).
    Options capped = options;
    capped.stations = std::min(options.stations, kVerificationStations);
    return solve_quadrature(model, capped);
  }
  Solution sol = method == Method::closed_form ? solve_closed_form(model, options)
                                               : solve_shooting(model, options, segments);
  if (sol.field && options.stations > 0) sample_profile(sol, std::min(options.stations, kVerificationStations));
  return sol;
}

// The options of the verifying solve: 16 times tighter in rtol and in atol. The user's atol is taken
// only where it is tighter than the default, so that a loose atol cannot make both solves agree on the
// same wrong answer (atol 1e300 turns CVODE's error control off in both).
Options verifying_options(const Options& options) {
  Options tighter = options;
  tighter.rtol = options.rtol / 16;
  Options plain = options;
  plain.atol = 0;
  const double default_atol = cvode_tolerances(plain).atol;
  tighter.atol = (options.atol > 0 ? std::min(options.atol, default_atol) : default_atol) / 16;
  return tighter;
}

// CVODE controls each step's local error, not the global error of what is printed; the solve is
// repeated 16 times tighter and the difference estimates the first solve's error. The tighter solution
// is returned: whenever it is at least twice as accurate as the first, the estimate bounds its error
// too. Its counters include both solves. Where CVODE's tolerance floor leaves no room for a tighter
// solve, the first is returned without an estimate (judged `unverified`).
// Whether a 16 times tighter CVODE solve exists above CVODE's tolerance floor.
bool verifiable(const Options& options) {
  return cvode_tolerances(verifying_options(options)).rtol * 16 <= cvode_tolerances(options).rtol * (1 + 1e-9);
}

Solution solve_verified(const std::shared_ptr<const ArchModel>& model, const Options& options, Method method,
                        int segments) {
  const Solution coarse = solve_once(model, options, method, segments);
  if (!coarse.field) return coarse;
  if (!verifiable(options)) {
    Solution sol = coarse;
    sol.message = fmt::format("rtol {:.3g} is below what a 16 times tighter CVODE solve can verify (CVODE's "
                              "tolerance floor {:.0e})", options.rtol, kCvodeRtolFloor);
    return sol;
  }
  Solution sol = solve_once(model, verifying_options(options), method, segments);
  Diagnostics& d = sol.diagnostics;
  add_work(d, coarse.diagnostics);
  if (sol.field) d.error_estimate = solution_difference(coarse, sol);
  return sol;
}

// Turns a provisional `success` into what the numbers are worth against rtol: ill_conditioned,
// tolerance_not_met (estimate or residuals above rtol) or unverified (no estimate). The one place that
// applies within_tolerance to a solution.
void judge_solution(Solution& sol, double rtol) {
  if (sol.status != Status::success) return;
  Diagnostics& d = sol.diagnostics;
  const double roundoff = d.condition_estimate * std::numeric_limits<double>::epsilon();
  if (!within_tolerance(roundoff, rtol)) {
    sol.status = Status::ill_conditioned;
    sol.message = fmt::format("condition estimate {:.3g} times round-off exceeds rtol {:.3g}", d.condition_estimate, rtol);
    return;
  }
  if (sol.method == Method::closed_form) d.error_estimate = roundoff;  // exact but for round-off
  if (std::isnan(d.error_estimate)) {
    sol.status = Status::unverified;
    if (sol.message.empty()) sol.message = "not verified (Options::verify off): no error estimate";
    return;
  }
  d.error_estimate = std::max(d.error_estimate, roundoff);
  const double residual = std::max(d.boundary_residual, d.equilibrium_residual);
  if (!within_tolerance(d.error_estimate, rtol)) {
    sol.status = Status::tolerance_not_met;
    sol.message = fmt::format("estimated error {:.3g} exceeds rtol {:.3g}", d.error_estimate, rtol);
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
  judge_solution(sol, asked);
  // The profile was compared at kVerificationStations at most; the printed one has every station.
  if (sol.field && options.stations > kVerificationStations) sample_profile(sol, options.stations);
  return sol;
}

}  // namespace

Solution solve(const Scene& scene, const Options& options) {
  scene.validate();
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
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
  // Otherwise verified shooting with 1, 2, 4, ... 64 segments (breakpoints add more) while each doubling
  // at least halves the error estimate: more segments shorten the spans over which integration errors
  // grow and cancel. Where segments stop helping (a thin near-funicular arch, whose eccentricity in kern
  // units amplifies every error of the forces by about L/t), CVODE is run tighter instead, by what the
  // estimate says is missing. Conditioning is the problem's own (it does not change with segments), so
  // a singular or ill-conditioned system, or rtol below what can be verified, ends the search.
  Options solver = options;
  solver.verify = true;
  Solution sol;
  Diagnostics spent;  // the work of the rejected tries counts too
  int segments = 1;
  double previous = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < 16; ++attempt) {
    sol = solve_with(model, solver, segments == 1 ? Method::shooting : Method::multiple_shooting, segments,
                     options.rtol);
    add_work(sol.diagnostics, spent);
    spent = sol.diagnostics;
    if (sol.status != Status::tolerance_not_met && sol.status != Status::integrator_failure) break;
    const double estimate = sol.diagnostics.error_estimate;
    const bool improving = !(estimate > previous / 2);  // also true after an integrator failure (NaN)
    previous = estimate;
    if (segments < 64 && improving) {
      segments *= 2;
      continue;
    }
    if (solver.rtol < options.rtol && !improving) break;  // tightening no longer helps: round-off's floor
    Options tighter = solver;
    tighter.rtol = std::max(solver.rtol * std::clamp(options.rtol / estimate / 4, 1e-3, 0.25), 1e-14);
    // Keep the last judged solve rather than one that cannot be verified at CVODE's floor.
    if (!verifiable(tighter)) break;
    solver = tighter;
  }
  return sol;
}

}  // namespace ogive
