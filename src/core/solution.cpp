#include "ogive/core/solution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

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
    case Status::not_converged: return "not_converged";
    case Status::inadmissible: return "inadmissible";
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

double reaction_difference(const Reactions& a, const Reactions& r, double thickness) {
  const double F = std::max({std::abs(r.H_left), std::abs(r.V_left), std::abs(r.V_right)});
  auto force = [&](double x, double ref) { return std::abs(x - ref) / std::max(std::abs(ref), F / 100); };
  const double couple_scale = std::max({std::abs(r.M_left), std::abs(r.M_right), F * thickness / 6});
  const double worst = std::max({force(a.H_left, r.H_left), force(a.H_right, r.H_right), force(a.V_left, r.V_left),
                                 force(a.V_right, r.V_right), std::abs(a.M_left - r.M_left) / couple_scale,
                                 std::abs(a.M_right - r.M_right) / couple_scale});
  return std::isfinite(worst) ? worst : std::numeric_limits<double>::quiet_NaN();
}

double roundoff_bound(const Solution& sol) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double condition = sol.diagnostics.condition_estimate;
  const double base = condition * eps;
  if (!sol.model) return kRoundoffProfile * base;
  const double L = sol.model->scene().span(), t = sol.model->scene().thickness;
  // The couples' scales are reaction_difference's and profile_difference's.
  const Reactions& r = sol.reactions;
  const double F = std::max({std::abs(r.H_left), std::abs(r.V_left), std::abs(r.V_right)});
  const double reactions = F * L / std::max({std::abs(r.M_left), std::abs(r.M_right), F * t / 6});
  double profile = 0;  // the profile's A, where there is a profile
  if (!sol.profile.empty()) {
    double Fp = 0, N = 0, M = 0;
    for (const ArchState& a : sol.profile) {
      Fp = std::max(Fp, std::hypot(a.N, a.V));
      N = std::max(N, std::abs(a.N));
      M = std::max(M, std::abs(a.M));
    }
    profile = std::max(1.0, Fp * L / std::max(M, N * t / 6));
  }
  double bound = 0;
  if (sol.method == Method::quadrature && sol.model->scene().section == SectionKind::elastic) {
    // Its own arithmetic's (kRoundoffQuadrature): the no-tension quadrature's Newton and section law
    // near the hinges keep the general bound below.
    bound = kRoundoffQuadrature * eps * (condition + std::max(reactions, profile));
  } else {
    const bool integrated = sol.method == Method::shooting || sol.method == Method::multiple_shooting;
    bound = base * (kRoundoffFloor + kRoundoffReactions * reactions);
    if (profile > 0)
      bound = std::max(bound, (integrated ? kRoundoffProfileIntegrated : kRoundoffProfile) * base * profile);
  }
  return std::isfinite(bound) ? bound : kRoundoffProfile * base;
}

namespace {

// H/V is printed beside the reactions and the profile: its error combines H's and V's (up to twice
// either one's measure), so it is measured itself, relative to max(|H/V|, 1/100) as H is to F / 100.
// Where V_left is below F / 100 (a load at the right springing, carried by it alone) H/V is the ratio
// of two numbers of the order of round-off, and the reactions' measure is the only one.
double thrust_difference(const Reactions& a, const Reactions& r) {
  const double F = std::max({std::abs(r.H_left), std::abs(r.V_left), std::abs(r.V_right)});
  if (!(std::abs(r.V_left) >= F / 100)) return 0;
  const double HV = r.H_left / r.V_left;  // Solution::H_over_V
  const double d = std::abs(a.H_left / a.V_left - HV) / std::max(std::abs(HV), 0.01);
  return std::isfinite(d) ? d : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

double reaction_and_thrust_difference(const Reactions& a, const Reactions& reference, double thickness) {
  const double thrust = thrust_difference(a, reference);
  if (std::isnan(thrust)) return thrust;
  return std::max(reaction_difference(a, reference, thickness), thrust);
}

double solution_difference(const Solution& a, const Solution& b) {
  if (!a.field || !b.field) return std::numeric_limits<double>::quiet_NaN();
  return sampled_solution_difference(a, b);
}

double sampled_solution_difference(const Solution& a, const Solution& b) {
  const double thickness = b.model->scene().thickness;
  const double reactions = reaction_and_thrust_difference(a.reactions, b.reactions, thickness);
  if (std::isnan(reactions) || b.profile.empty()) return reactions;
  // A profile difference that is not a number (a station without numbers) is kept: std::max would drop it.
  const double profiles = profile_difference(a.profile, b.profile, thickness);
  return std::isnan(profiles) ? profiles : std::max(reactions, profiles);
}

double profile_difference(const std::vector<ArchState>& profile, const std::vector<ArchState>& reference,
                          double thickness) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (profile.size() != reference.size() || reference.empty()) return kNaN;
  double dU = 0, dpsi = 0, dF = 0, dM = 0, U = 0, psi = 0, F = 0, N = 0, M = 0;
  for (std::size_t k = 0; k < reference.size(); ++k) {
    const ArchState& a = profile[k];
    const ArchState& r = reference[k];
    // A station without a number (a non-finite state) is no agreement: std::max would drop its NaN.
    for (const ArchState* x : {&a, &r})
      if (!std::isfinite(x->Ux) || !std::isfinite(x->Uy) || !std::isfinite(x->psi) || !std::isfinite(x->N) ||
          !std::isfinite(x->V) || !std::isfinite(x->M))
        return kNaN;
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

}  // namespace ogive
