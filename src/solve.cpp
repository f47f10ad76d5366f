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

const char* to_string(Method m) {
  switch (m) {
    case Method::closed_form: return "closed-form";
    case Method::shooting: return "shooting";
    case Method::multiple_shooting: return "multiple-shooting";
    case Method::automatic: return "auto";
    case Method::quadrature: return "quadrature";
  }
  return "?";
}

const char* to_string(Integrator i) { return i == Integrator::adams ? "adams" : "bdf"; }

const char* to_string(Status s) {
  switch (s) {
    case Status::success: return "success";
    case Status::not_applicable: return "not_applicable";
    case Status::integrator_failure: return "integrator_failure";
    case Status::singular_system: return "singular_system";
    case Status::ill_conditioned: return "ill_conditioned";
    case Status::tolerance_not_met: return "tolerance_not_met";
    case Status::unverified: return "unverified";
  }
  return "?";
}

bool Options::is_valid(std::string* why) const {
  auto fail = [&](std::string text) {
    if (why) *why = std::move(text);
    return false;
  };
  if (!(rtol >= 1e-14 && rtol <= 1e-1)) return fail(fmt::format("rtol: must lie in [1e-14, 0.1], got {}", rtol));
  if (!(atol >= 0) || !std::isfinite(atol)) return fail(fmt::format("atol: must be finite and >= 0, got {}", atol));
  if (segments < 1 || segments > 10000) return fail(fmt::format("segments: must lie in [1, 10000], got {}", segments));
  if (max_steps < 1) return fail(fmt::format("max_steps: must be >= 1, got {}", max_steps));
  if (stations == 1 || stations < 0 || stations > 1000000)
    return fail(fmt::format("stations: must be 0 or lie in [2, 1000000], got {}", stations));
  return true;
}

ArchState Solution::at(double s) const {
  if (!field || !model) throw std::logic_error("Solution::at: no solved field (status " +
                                               std::string(to_string(status)) + ")");
  const double L = model->scales().length;
  const double S = model->length();
  double s_scaled = s / L;
  const bool mirrored = model->half() && s_scaled > S;
  if (mirrored) s_scaled = 2.0 * S - s_scaled;
  s_scaled = std::clamp(s_scaled, 0.0, S);
  StateVector y;
  field->sample(std::span<const double>(&s_scaled, 1), std::span<StateVector>(&y, 1));
  return model->to_physical(s_scaled, y, mirrored);
}

std::vector<ArchState> sample_stations(const Solution& sol, int stations, int first, int count) {
  std::vector<ArchState> out;
  if (stations < 2 || !sol.field || first < 0 || count <= 0 || first + count > stations) return out;
  const double S = sol.model->length();
  const bool half = sol.model->half();
  const double whole_length = half ? 2.0 * S : S;
  // Stations over the whole arch; over a half model, a right-half station is its mirror's state.
  std::vector<double> whole(count), domain(count);
  for (int i = 0; i < count; ++i) {
    whole[i] = i + first == stations - 1 ? whole_length : whole_length * (first + i) / (stations - 1);
    domain[i] = half && whole[i] > S ? 2.0 * S - whole[i] : whole[i];
  }
  std::vector<double> sorted = domain;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::vector<StateVector> states(sorted.size());
  sol.field->sample(sorted, states);
  out.reserve(count);
  for (int i = 0; i < count; ++i) {
    const std::size_t k = std::lower_bound(sorted.begin(), sorted.end(), domain[i]) - sorted.begin();
    out.push_back(sol.model->to_physical(domain[i], states[k], half && whole[i] > S));
  }
  return out;
}

void sample_profile(Solution& sol, int stations) { sol.profile = sample_stations(sol, stations, 0, stations); }

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

double reaction_difference(const Reactions& a, const Reactions& r, double thickness) {
  const double F = std::max({std::abs(r.H_left), std::abs(r.V_left), std::abs(r.V_right)});
  auto force = [&](double x, double ref) { return std::abs(x - ref) / std::max(std::abs(ref), F / 100); };
  const double couple_scale = std::max({std::abs(r.M_left), std::abs(r.M_right), F * thickness / 6});
  const double worst = std::max({force(a.H_left, r.H_left), force(a.H_right, r.H_right), force(a.V_left, r.V_left),
                                 force(a.V_right, r.V_right), std::abs(a.M_left - r.M_left) / couple_scale,
                                 std::abs(a.M_right - r.M_right) / couple_scale});
  return std::isfinite(worst) ? worst : std::numeric_limits<double>::quiet_NaN();
}

double solution_difference(const Solution& a, const Solution& b) {
  if (!a.field || !b.field) return std::numeric_limits<double>::quiet_NaN();
  const double thickness = b.model->scene().thickness;
  const double reactions = reaction_difference(a.reactions, b.reactions, thickness);
  if (b.profile.empty()) return reactions;
  return std::max(reactions, profile_difference(a.profile, b.profile, thickness));
}

double profile_difference(const std::vector<ArchState>& profile, const std::vector<ArchState>& reference,
                          double thickness) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (profile.size() != reference.size() || reference.empty()) return kNaN;
  double dU = 0, dpsi = 0, dF = 0, dM = 0, U = 0, psi = 0, F = 0, N = 0, M = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const ArchState& a = profile[k];
    const ArchState& r = reference[k];
    dU = std::max(dU, std::hypot(a.Ux - r.Ux, a.Uy - r.Uy));
    dpsi = std::max(dpsi, std::abs(a.psi - r.psi));
    dF = std::max(dF, std::hypot(a.N - r.N, a.V - r.V));
    dM = std::max(dM, std::abs(a.M - r.M));
    U = std::max(U, std::hypot(r.Ux, r.Uy));
    psi = std::max(psi, std::abs(r.psi));
    F = std::max(F, std::hypot(r.N, r.V));
    N = std::max(N, std::abs(r.N));
    M = std::max(M, std::abs(r.M));
  }
  // A component that vanishes all along the reference (not seen in practice: self-weight deflects every
  // arch) must vanish in the profile too.
  auto ratio = [](double diff, double scale) {
    return scale > 0 ? diff / scale : (diff == 0 ? 0.0 : std::numeric_limits<double>::infinity());
  };
  const double worst = std::max({ratio(dU, U), ratio(dpsi, psi), ratio(dF, F), ratio(dM, std::max(M, N * thickness / 6))});
  return std::isfinite(worst) ? worst : kNaN;
}

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
