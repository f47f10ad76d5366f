// The reference a scene's H/V is checked (check) or measured (bench) against: the closed form where it
// applies (a piecewise-circular curve, the elastic section, no live load or fill); otherwise verified
// multiple shooting far tighter than anything compared with it (rtol 1e-12, or 100 times tighter than
// asked down to 2e-13, what Adams can still verify; 32 segments), its own error stated.
#pragma once

#include "ogive/core/solution.hpp"
#include "ogive/model/scene.hpp"
#include "ogive/solve/solve.hpp"

namespace ogive::cli {

double reference_rtol(const Options& o);

Solution reference_solution(const Scene& scene, Options o);

// The reference's own error: its error estimate (which includes its condition times round-off), NaN
// when it has no numbers.
double reference_error(const Solution& ref);

// The error of H/V by the measure of the status (Diagnostics::error_estimate): relative to
// max(|H/V|, 1/100).
double thrust_difference(double H_over_V, double reference);

}  // namespace ogive::cli
