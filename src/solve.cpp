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

SpringingSplit springing_split(const ArchModel& model) {
  const BoundaryConditions bc = model.boundary_conditions();
  SpringingSplit split;
  std::array<bool, kStateSize> known{};
  for (int r = 0; r < 3; ++r) {
    Eigen::Index j = 0;
    bc.at_springing.row(r).cwiseAbs().maxCoeff(&j);
    // Each springing condition fixes one component: a unit row (ArchModel's conditions are).
    if (bc.at_springing(r, j) != 1.0 || bc.at_springing.row(r).cwiseAbs().sum() != 1.0)
      throw std::logic_error("springing_split: a springing condition is not of the form y_j = value");
    known[static_cast<std::size_t>(j)] = true;
    split.start[j] = bc.rhs(r);
  }
  int column = 0;
  for (int j = 0; j < kStateSize; ++j)
    if (!known[static_cast<std::size_t>(j)]) split.U(j, column++) = 1.0;
  return split;
}

double boundary_value_condition(const ArchModel& model, const ReducedTransfer& PhiU) {
  const BoundaryConditions bc = model.boundary_conditions();
  const Eigen::Matrix3d Q = bc.at_crown.bottomRows<3>() * PhiU;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(Q);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  // Skeel's measure, not ||Q|| ||Q^-1||: the rows mix displacement and force conditions whose sizes
  // differ by orders of magnitude, and a norm-wise estimate would report that scaling, not a loss of
  // digits. |Q^-1| |Q| is what partial pivoting's backward error is amplified by, row scaling aside.
  const Eigen::Matrix3d amplification = lu.inverse().cwiseAbs() * Q.cwiseAbs();
  const double condition = amplification.rowwise().sum().maxCoeff();
  return std::isfinite(condition) ? condition : std::numeric_limits<double>::infinity();
}

double boundary_value_condition(const ArchModel& model, const SystemMatrix& Phi) {
  return boundary_value_condition(model, ReducedTransfer(Phi * springing_split(model).U));
}

BvpSolution solve_reduced(const ArchModel& model, const ReducedTransfer& PhiU, const StateVector& q) {
  const BoundaryConditions bc = model.boundary_conditions();
  const SpringingSplit split = springing_split(model);
  const Eigen::Matrix3d Q = bc.at_crown.bottomRows<3>() * PhiU;
  const Eigen::Vector3d u = Q.partialPivLu().solve(bc.rhs.tail<3>() - bc.at_crown.bottomRows<3>() * q);
  BvpSolution out;
  out.condition = boundary_value_condition(model, PhiU);
  out.y0 = split.start + split.U * u;
  out.yS = PhiU * u + q;
  return out;
}

BvpSolution solve_single_segment(const ArchModel& model, const SystemMatrix& Phi, const StateVector& p) {
  const SpringingSplit split = springing_split(model);
  return solve_reduced(model, Phi * split.U, Phi * split.start + p);
}

void finish_solution(Solution& sol, const BvpSolution& bvp, std::shared_ptr<const StateField> field) {
  const ArchModel& model = *sol.model;
  Diagnostics& d = sol.diagnostics;
  d.condition_estimate = bvp.condition;
  constexpr double kRoundoff = std::numeric_limits<double>::epsilon();
  if (!(bvp.condition * kRoundoff < 1) || !bvp.y0.allFinite() || !bvp.yS.allFinite()) {
    sol.status = Status::singular_system;
    sol.message = fmt::format("boundary-value system singular to working precision (condition {:.3g})",
                              d.condition_estimate);
    return;
  }
  sol.field = std::move(field);
  d.boundary_residual = model.boundary_residual(bvp.y0, bvp.yS);
  d.equilibrium_residual = model.equilibrium_residual(bvp.y0, bvp.yS);
  sol.H = model.horizontal_reaction(bvp.y0);
  sol.V = model.vertical_reaction();
  sol.H_over_V = sol.H / sol.V;
  sol.status = Status::success;  // provisional: judge_solution decides against rtol
  sol.message.clear();
}

ArchState Solution::at(double s) const {
  if (!field || !model) throw std::logic_error("Solution::at: no solved field (status " +
                                               std::string(to_string(status)) + ")");
  const double L = model->scales().length;
  const double S = model->half_length();
  double s_scaled = s / L;
  const bool mirrored = s_scaled > S;
  if (mirrored) s_scaled = 2.0 * S - s_scaled;
  s_scaled = std::clamp(s_scaled, 0.0, S);
  StateVector y;
  field->sample(std::span<const double>(&s_scaled, 1), std::span<StateVector>(&y, 1));
  return model->to_physical(s_scaled, y, mirrored);
}

std::vector<ArchState> sample_stations(const Solution& sol, int stations, int first, int count) {
  std::vector<ArchState> out;
  if (stations < 2 || !sol.field || first < 0 || count <= 0 || first + count > stations) return out;
  const double S = sol.model->half_length();
  // Stations over the whole arch; a right-half station is its mirror's state on the half arch.
  std::vector<double> whole(count), half(count);
  for (int i = 0; i < count; ++i) {
    whole[i] = 2.0 * S * (first + i) / (stations - 1);
    half[i] = whole[i] <= S ? whole[i] : 2.0 * S - whole[i];
  }
  std::vector<double> sorted = half;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::vector<StateVector> states(sorted.size());
  sol.field->sample(sorted, states);
  out.reserve(count);
  for (int i = 0; i < count; ++i) {
    const std::size_t k = std::lower_bound(sorted.begin(), sorted.end(), half[i]) - sorted.begin();
    out.push_back(sol.model->to_physical(half[i], states[k], whole[i] > S));
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

// H is measured against max(|H|, V / 100): under support spreading H passes through zero, where no
// relative error of H means anything, and its absolute error is then held to rtol V / 100.
double solution_difference(const Solution& a, const Solution& b) {
  if (!a.field || !b.field) return std::numeric_limits<double>::quiet_NaN();
  const double H = std::abs(a.H - b.H) / std::max(std::abs(b.H), std::abs(b.V) / 100);
  if (b.profile.empty()) return H;
  return std::max(H, profile_difference(a.profile, b.profile, b.model->scene().thickness));
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
  auto model = std::make_shared<const ArchModel>(scene);
  switch (options.method) {
    case Method::closed_form: return solve_with(model, options, Method::closed_form, 0, options.rtol);
    case Method::shooting: return solve_with(model, options, Method::shooting, 1, options.rtol);
    case Method::multiple_shooting:
      return solve_with(model, options, Method::multiple_shooting, options.segments, options.rtol);
    case Method::quadrature: return solve_with(model, options, Method::quadrature, 0, options.rtol);
    case Method::automatic: break;
  }
  // The smallest model that meets rtol. The closed form is exact to round-off where it applies.
  if (!scene.curve->arcs().empty()) return solve_with(model, options, Method::closed_form, 0, options.rtol);
  // On smooth curves (and between a survey's points) the quadrature method, as fast as the closed form,
  // with its own error estimate; where that does not meet rtol, CVODE shooting below. (Conditioning is
  // the boundary-value problem's, the same for every method: CVODE would not cure it.)
  {
    Solution quadrature = solve_with(model, options, Method::quadrature, 0, options.rtol);
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
