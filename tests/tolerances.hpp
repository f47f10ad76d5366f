// Named tolerances for the tests: what each comparison means, never doctest's default Approx.
#pragma once

#include <algorithm>
#include <cmath>

namespace ogive {

inline constexpr double kExact = 1e-12;  // algebra and exact formulas, after round-off

// |a - b| <= tol * max(|a|, |b|): a relative comparison.
inline bool close(double a, double b, double tol) {
  return std::abs(a - b) <= tol * std::max(std::abs(a), std::abs(b));
}

inline double relative_difference(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace ogive
