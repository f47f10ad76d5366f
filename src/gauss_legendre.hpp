// The 8-point Gauss-Legendre rule on [-1, 1] (private header): nodes +-kGaussNodes[i], weights
// kGaussWeights[i]. Exact for polynomials of degree 15; used for integrals along the axis.
#pragma once

#include <array>
#include <type_traits>

namespace ogive {

inline constexpr std::array<double, 4> kGaussNodes = {0.1834346424956498, 0.5255324099163290,
                                                      0.7966664774136267, 0.9602898564975363};
inline constexpr std::array<double, 4> kGaussWeights = {0.3626837833783620, 0.3137066458778873,
                                                        0.2223810344533745, 0.1012285362903763};

// Integral of f over [a, b] (either order) by the 8-point rule.
template <class F>
auto gauss_legendre_8(F&& f, double a, double b) {
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  // The value type, evaluated: an Eigen expression must not outlive the temporaries it refers to.
  using Value = std::decay_t<decltype(f(a))>;
  Value sum = kGaussWeights[0] * (f(mid - half * kGaussNodes[0]) + f(mid + half * kGaussNodes[0]));
  for (std::size_t i = 1; i < kGaussNodes.size(); ++i)
    sum += kGaussWeights[i] * (f(mid - half * kGaussNodes[i]) + f(mid + half * kGaussNodes[i]));
  return Value(half * sum);
}

}  // namespace ogive
