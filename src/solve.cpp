#include "ogive/solve.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/LU>
#include <fmt/format.h>

#include "bvp.hpp"
#include "ogive/closed_form.hpp"
#include "ogive/shooting.hpp"

namespace ogive {

const char* to_string(Method m) {
  switch (m) {
    case Method::closed_form: return "closed-form";
    case Method::shooting: return "shooting";
    case Method::multiple_shooting: return "multiple-shooting";
    case Method::automatic: return "auto";
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
  if (d.condition_estimate * kRoundoff > rtol) {
    sol.status = Status::ill_conditioned;
    sol.message = fmt::format("condition estimate {:.3g} times round-off exceeds rtol {:.3g}",
                              d.condition_estimate, rtol);
  } else {
    sol.status = Status::success;
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

Solution solve(const Scene& scene, const Options& options) {
  scene.validate();
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  auto model = std::make_shared<const ArchModel>(scene);
  Method method = options.method;
  if (method == Method::automatic)
    method = scene.curve->arcs().empty() ? Method::multiple_shooting : Method::closed_form;
  Solution sol;
  switch (method) {
    case Method::closed_form: sol = solve_closed_form(model, options); break;
    case Method::shooting: sol = solve_shooting(model, options, 1); break;
    default: sol = solve_shooting(model, options, options.segments); break;
  }
  if (sol.field && options.stations > 0) sample_profile(sol, options.stations);
  return sol;
}

}  // namespace ogive
