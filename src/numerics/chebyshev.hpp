// Chebyshev-Lobatto (Clenshaw-Curtis) panels (private header): nodes, cumulative integration and
// interpolation of a smooth function from its values at the nodes. The quadrature method's one rule.
#pragma once

#include <span>
#include <vector>

#include <Eigen/Dense>

namespace ogive {

// The rule of degree N on [-1, 1]: N + 1 nodes x_i = -cos(i pi / N), ascending, x_0 = -1, x_N = 1.
// Nested: the nodes of degree N are the even-numbered nodes of degree 2N.
struct ChebyshevRule {
  int degree = 0;
  Eigen::VectorXd node;
  // (integration * f)_i = integral from -1 to x_i of the polynomial interpolating f at the nodes: exact
  // for polynomials of degree N, spectrally accurate for analytic f.
  Eigen::MatrixXd integration;
  Eigen::VectorXd barycentric_weight;  // (-1)^i, halved at both ends
  // (to_coefficients * f)_k = a_k: the interpolant is sum_k a_k T_k(x) (discrete cosine transform).
  Eigen::MatrixXd to_coefficients;
};

// The degrees the quadrature method uses: 4, 8, 16, ..., kMaxChebyshevDegree.
inline constexpr int kMinChebyshevDegree = 4;
inline constexpr int kMaxChebyshevDegree = 256;

// The rule of that degree (a power of two in [kMinChebyshevDegree, kMaxChebyshevDegree]), built once
// (in long double) and cached; thread-safe. Throws std::invalid_argument for any other degree.
const ChebyshevRule& chebyshev_rule(int degree);

// Values at x in [-1, 1] of the polynomials taking the rows of `values` (rows x (degree + 1)) at the
// rule's nodes: the barycentric formula (stable; exact at the nodes).
// sum_k a[k] T_k(x), k = 0 .. degree, by Clenshaw's recurrence (no division: the fast way to evaluate one
// tabulated function many times).
double chebyshev_series(const double* a, int degree, double x);
// Two series of the same degree at the same x in one recurrence (the no-tension quadrature's B and C).
Eigen::Array2d chebyshev_series(const double* a, const double* b, int degree, double x);
Eigen::VectorXd chebyshev_interpolate(const ChebyshevRule& rule, const Eigen::Ref<const Eigen::MatrixXd>& values,
                                      double x);

}  // namespace ogive
