#include "ogive/solve/model_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "ogive/solve/solve.hpp"

namespace ogive {

namespace {

// The bound's constants, from benchmarks/continuum/continuum.csv (its README gives the curved bar's
// errors row by row). The linear term covers the ends (what remains of a pointed crown's joint beyond its
// kink and wedge, of a clamped springing's zone beyond its held face), whose zones are about t long; the
// quadratic one how they grow as the arch deepens (the largest ratio of error to bound, 0.08, is the
// clamped equilateral arch's at t/L 0.25: a margin for the scenes beyond the table).
constexpr double kLinear = 0.012, kQuadratic = 0.35;

Scene with_model(const Scene& scene, BeamModel model) {
  Scene s = scene;
  s.beam_model = model;
  s.model_tolerance = 0;
  return s;
}

}  // namespace

double curved_bar_bound(const Scene& scene) {
  const double r = scene.thickness / scene.span();
  return kLinear * r + kQuadratic * r * r;
}

double model_error_estimate(const Scene& scene, double H_over_V, double curved_H_over_V) {
  if (!std::isfinite(H_over_V) || !std::isfinite(curved_H_over_V)) return std::numeric_limits<double>::quiet_NaN();
  return std::abs(H_over_V - curved_H_over_V) / std::max(std::abs(curved_H_over_V), 0.01) + curved_bar_bound(scene);
}

Solution solve_with_model_error(const Scene& scene, const Options& options, const Solution* previous) {
  Options plain = options;
  plain.estimate_model_error = false;
  if (scene.section != SectionKind::elastic) {
    // Only an estimate without a tolerance gets here (Scene::validate): none for this section.
    return solve(with_model(scene, scene.beam_model), plain, previous);
  }
  const Solution curved = solve(with_model(scene, BeamModel::curved), plain, previous);
  const double curved_H_over_V = curved.field ? curved.H_over_V : std::numeric_limits<double>::quiet_NaN();
  std::vector<BeamModel> candidates{scene.beam_model};
  if (scene.beam_model == BeamModel::automatic)
    candidates = {BeamModel::euler_bernoulli, BeamModel::timoshenko, BeamModel::curved};
  const double tolerance = scene.model_tolerance;
  Solution sol;
  for (BeamModel model : candidates) {
    sol = model == BeamModel::curved ? curved : solve(with_model(scene, model), plain, previous);
    sol.diagnostics.model_error_estimate =
        sol.field ? model_error_estimate(scene, sol.H_over_V, curved_H_over_V) : std::numeric_limits<double>::quiet_NaN();
    if (tolerance > 0 && sol.diagnostics.model_error_estimate <= tolerance) break;
  }
  const double estimate = sol.diagnostics.model_error_estimate;
  if (tolerance > 0 && sol.status == Status::success && !(estimate <= tolerance)) {
    sol.status = Status::tolerance_not_met;
    sol.message = std::isnan(estimate)
                      ? fmt::format("the model's error could not be estimated (the curved bar's solve: {}), model "
                                    "tolerance {:.3g}",
                                    to_string(curved.status), tolerance)
                      : fmt::format("the {} beam's model error estimate {:.3g} exceeds the model tolerance {:.3g}",
                                    to_string(sol.model->beam_model()), estimate, tolerance);
  }
  return sol;
}

}  // namespace ogive
