// Named tolerances for the tests: what each comparison means, never doctest's default Approx.
#pragma once

#include <algorithm>
#include <cmath>

namespace ogive {

inline constexpr double kExact = 1e-12;  // algebra and exact formulas, after round-off
// Two exact methods in floating point agree to round-off times the system's condition (~10^2..10^3).
inline constexpr double kTwoExactMethods = 1e-11;

// |a - b| <= tol * max(|a|, |b|): a relative comparison.
inline bool close(double a, double b, double tol) {
  return std::abs(a - b) <= tol * std::max(std::abs(a), std::abs(b));
}

inline double relative_difference(double a, double b) { return std::abs(a - b) / std::abs(b); }

// The error of H/V as ogive's status measures it (solve.hpp, Diagnostics::error_estimate): relative to
// max(|H/V|, 1/100), because H passes through zero under support spreading.
inline double thrust_error(double H_over_V, double reference) {
  return std::abs(H_over_V - reference) / std::max(std::abs(reference), 0.01);
}

}  // namespace ogive
