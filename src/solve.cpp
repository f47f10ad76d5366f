#include "ogive/solve.hpp"

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

BvpSolution solve_single_segment(const ArchModel& model, const SystemMatrix& Phi, const StateVector& p) {
  const BoundaryConditions bc = model.boundary_conditions();
  const SystemMatrix Q = bc.at_springing + bc.at_crown * Phi;
  const Eigen::PartialPivLU<SystemMatrix> lu(Q);
  BvpSolution out;
  out.rcond = lu.rcond();
  out.y0 = lu.solve(bc.rhs - bc.at_crown * p);
  out.yS = Phi * out.y0 + p;
  return out;
}

void finish_solution(Solution& sol, const BvpSolution& bvp, std::shared_ptr<const StateField> field,
                     double rtol) {
  const ArchModel& model = *sol.model;
  Diagnostics& d = sol.diagnostics;
  d.condition_estimate = bvp.rcond > 0 ? 1.0 / bvp.rcond : std::numeric_limits<double>::infinity();
  constexpr double kRoundoff = std::numeric_limits<double>::epsilon();
  if (!(bvp.rcond > kRoundoff) || !bvp.y0.allFinite()) {
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
  judge_conditioning(sol, rtol);
}

void judge_conditioning(Solution& sol, double rtol) {
  const double condition = sol.diagnostics.condition_estimate;
  if (condition * std::numeric_limits<double>::epsilon() > rtol) {
    sol.status = Status::ill_conditioned;
    sol.message = fmt::format("condition estimate {:.3g} times round-off exceeds rtol {:.3g}", condition, rtol);
  } else {
    sol.status = Status::success;
    sol.message.clear();
  }
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

void sample_profile(Solution& sol, int stations) {
  sol.profile.clear();
  if (stations < 2 || !sol.field) return;
  const double S = sol.model->half_length();
  // Stations over the whole arch; each right-half station is its mirror's state.
  std::vector<double> whole(stations), half;
  for (int i = 0; i < stations; ++i) {
    whole[i] = 2.0 * S * i / (stations - 1);
    half.push_back(whole[i] <= S ? whole[i] : 2.0 * S - whole[i]);
  }
  std::vector<double> sorted = half;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::vector<StateVector> states(sorted.size());
  sol.field->sample(sorted, states);
  sol.profile.reserve(stations);
  for (int i = 0; i < stations; ++i) {
    const std::size_t k = std::lower_bound(sorted.begin(), sorted.end(), half[i]) - sorted.begin();
    sol.profile.push_back(sol.model->to_physical(half[i], states[k], whole[i] > S));
  }
}

namespace {

void add_work(Diagnostics& to, const Diagnostics& from) {
  to.steps += from.steps;
  to.rhs_evaluations += from.rhs_evaluations;
  to.error_test_failures += from.error_test_failures;
  to.jacobian_evaluations += from.jacobian_evaluations;
}

Solution solve_once(const std::shared_ptr<const ArchModel>& model, const Options& options, Method method,
                    int segments) {
  Solution sol = method == Method::closed_form ? solve_closed_form(model, options)
                                               : solve_shooting(model, options, segments);
  if (sol.field && options.stations > 0) sample_profile(sol, options.stations);
  return sol;
}

// CVODE controls each step's local error, not the global error of what is printed; the solve is
// repeated 16 times tighter and the difference, an estimate of the first solve's error, is compared
// with the 10 * rtol the tests accept of every method. The tighter solution is returned (its own error
// is smaller still), its counters include both solves.
Solution solve_verified(const std::shared_ptr<const ArchModel>& model, const Options& options, Method method,
                        int segments) {
  const Solution coarse = solve_once(model, options, method, segments);
  if (!coarse.field) return coarse;
  Options tighter = options;
  tighter.rtol = options.rtol / 16;
  Solution sol = solve_once(model, tighter, method, segments);
  Diagnostics& d = sol.diagnostics;
  add_work(d, coarse.diagnostics);
  if (!sol.field) return sol;
  d.error_estimate = solution_difference(coarse, sol);
  // The tighter solve judged its conditioning against rtol / 16; what was asked is rtol.
  if (sol.status == Status::ill_conditioned) judge_conditioning(sol, options.rtol);
  if (sol.status == Status::success && !(d.error_estimate <= 10 * options.rtol)) {
    sol.status = Status::tolerance_not_met;
    sol.message = fmt::format("estimated error {:.3g} exceeds 10 * rtol = {:.3g}", d.error_estimate,
                              10 * options.rtol);
  }
  return sol;
}

}  // namespace

double solution_difference(const Solution& a, const Solution& b) {
  if (!a.field || !b.field) return std::numeric_limits<double>::quiet_NaN();
  const double H = std::abs(a.H - b.H) / std::abs(b.H);
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
    case Method::closed_form: return solve_once(model, options, Method::closed_form, 0);
    case Method::shooting:
    case Method::multiple_shooting: {
      const int segments = options.method == Method::shooting ? 1 : options.segments;
      if (options.verify) return solve_verified(model, options, options.method, segments);
      return solve_once(model, options, options.method, segments);
    }
    case Method::quadrature: return solve_quadrature(model, options);
    case Method::automatic: break;
  }
  // The smallest model that meets rtol. The closed form is exact to round-off where it applies.
  if (!scene.curve->arcs().empty()) return solve_once(model, options, Method::closed_form, 0);
  // On smooth curves (and between a survey's points) the quadrature method, as fast as the closed form,
  // with its own error estimate; where that does not meet rtol, CVODE shooting below. (Conditioning is
  // the boundary-value system's, the same for every method: CVODE would not cure it.)
  {
    Solution quadrature = solve_quadrature(model, options);
    if (quadrature.status != Status::tolerance_not_met && quadrature.status != Status::not_applicable)
      return quadrature;
  }
  // Otherwise shooting with 1, 2, 4, ... segments (breakpoints add more) until the error estimate meets
  // rtol: more segments shorten the spans over which integration errors grow and cancel. A singular or
  // ill-conditioned system is not cured by more segments (the condition grows with them): stop there.
  Solution sol;
  Diagnostics spent;  // the work of the rejected tries counts too
  for (int segments = 1; segments <= 64; segments *= 2) {
    sol = solve_verified(model, options, segments == 1 ? Method::shooting : Method::multiple_shooting, segments);
    add_work(sol.diagnostics, spent);
    spent = sol.diagnostics;
    if (sol.status == Status::success || sol.status == Status::singular_system ||
        sol.status == Status::ill_conditioned)
      break;
  }
  return sol;
}

}  // namespace ogive
