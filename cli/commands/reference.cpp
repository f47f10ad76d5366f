#include "reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ogive::cli {

double reference_rtol(const Options& o) { return std::max(std::min(1e-12, o.rtol / 100), 2e-13); }

Solution reference_solution(const Scene& scene, Options o) {
  if (!scene.curve->arcs().empty()) {
    Options exact = o;
    exact.method = Method::closed_form;
    Solution sol = solve(scene, exact);
    if (sol.status != Status::not_applicable) return sol;  // a live load, a fill, the no-tension section: not its
  }
  o.method = Method::multiple_shooting;
  o.integrator = Integrator::adams;
  o.rtol = reference_rtol(o);
  // Newton shooting of the no-tension section converges to 1e-11, not to 1e-12 (its residual's noise).
  if (scene.section == SectionKind::no_tension) o.rtol = std::max(o.rtol, 1e-11);
  o.atol = 0;
  o.segments = 32;
  o.verify = true;
  o.restart_at_breakpoints = true;
  return solve(scene, o);
}

double reference_error(const Solution& ref) {
  return ref.field ? ref.diagnostics.error_estimate : std::numeric_limits<double>::quiet_NaN();
}

double thrust_difference(double H_over_V, double reference) {
  return std::abs(H_over_V - reference) / std::max(std::abs(reference), 0.01);
}

}  // namespace ogive::cli
