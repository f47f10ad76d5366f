// The beam model's own error: how far the beam's H/V may lie from the two-dimensional arch's, and the
// choice of the least beam model that a scene needs (docs/model.md, "The beam's validity").
//
// Every method solves a beam; the beam models a plane arch (plane stress or strain). Against that
// continuum (benchmarks/continuum: CalculiX, quadratic elements, converged meshes, the springing faces
// held, the self-weight a body force) the curved bar is the closest model, and its own error in H/V is
// bounded, on every scene of the benchmark's table, by curved_bar_bound. The estimate of a model's
// relative error in H/V is its distance from the curved bar plus that bound:
//   model_error_estimate = |H/V - H/V_curved| / max(|H/V_curved|, 0.01) + curved_bar_bound(scene)
// (relative to max(|H/V|, 1/100) as the solver's error estimate is: H passes through zero under support
// spreading). The bound is calibrated on symmetric arches under their own weight, clamped and pinned;
// under other loads the distance to the curved bar still measures what the richer model changes.
#pragma once

#include "ogive/core/solution.hpp"
#include "ogive/model/scene.hpp"

namespace ogive {

// The curved bar's error bound in H/V, relative: c1 (t/L) + c2 (t/L)^2 (model_error.cpp gives the
// constants and the table's largest ratio of error to bound).
double curved_bar_bound(const Scene& scene);

// The estimate above, from a model's H/V and the curved bar's for the same scene.
double model_error_estimate(const Scene& scene, double H_over_V, double curved_H_over_V);

// Whether solve() must estimate the model's error: Scene::beam_model automatic, Scene::model_tolerance
// > 0, or Options::estimate_model_error.
inline bool asks_model_error(const Scene& scene, const Options& options) {
  return scene.beam_model == BeamModel::automatic || scene.model_tolerance > 0 || options.estimate_model_error;
}

// solve() for such a scene: the curved bar's solve, then the scene's model (beam_model automatic: the
// least of euler-bernoulli, timoshenko and curved whose estimate is within model_tolerance; the curved
// bar when none is), with Diagnostics::model_error_estimate set. A solution whose estimate exceeds a
// model_tolerance > 0 that the numbers' own error met is tolerance_not_met, its message saying so.
// The section must be elastic (Scene::validate); `previous` goes to each solve.
Solution solve_with_model_error(const Scene& scene, const Options& options, const Solution* previous = nullptr);

}  // namespace ogive
