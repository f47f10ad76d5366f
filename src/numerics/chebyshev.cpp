#include "numerics/chebyshev.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ogive {
namespace {

using LongMatrix = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

ChebyshevRule build_rule(int N) {
  const long double pi = std::numbers::pi_v<long double>;
  const int n = N + 1;
  ChebyshevRule r;
  r.degree = N;
  r.node.resize(n);
  r.barycentric_weight.resize(n);
  std::vector<long double> x(n);
  for (int i = 0; i < n; ++i) {
    // -cos(i pi / N) written as sin((2i - N) pi / 2N): symmetric about 0 to the last bit.
    x[i] = std::sin(static_cast<long double>(2 * i - N) * pi / (2 * N));
    r.node[i] = static_cast<double>(x[i]);
    r.barycentric_weight[i] = (i % 2 == 0 ? 1.0 : -1.0) * (i == 0 || i == N ? 0.5 : 1.0);
  }
  // T(i, k) = T_k(x_i) for k = 0 .. N + 1 (the integral has degree N + 1).
  LongMatrix T(n, N + 2);
  for (int i = 0; i < n; ++i) {
    T(i, 0) = 1;
    T(i, 1) = x[i];
    for (int k = 2; k <= N + 1; ++k) T(i, k) = 2 * x[i] * T(i, k - 1) - T(i, k - 2);
  }
  // Coefficients from values (discrete cosine transform at the Lobatto nodes): a = C f.
  LongMatrix C(n, n);
  for (int k = 0; k <= N; ++k)
    for (int i = 0; i < n; ++i) {
      const long double end = (i == 0 || i == N) ? 0.5L : 1.0L;
      const long double edge = (k == 0 || k == N) ? 0.5L : 1.0L;
      C(k, i) = 2.0L / N * end * edge * T(i, k);
    }
  // Integral of sum a_k T_k from -1: b_k = (c_{k-1} a_{k-1} - a_{k+1}) / 2k (c_0 = 2), b_0 makes it vanish
  // at -1, where T_k = (-1)^k.
  LongMatrix B = LongMatrix::Zero(N + 2, n);
  for (int k = 1; k <= N + 1; ++k) {
    B(k, k - 1) += (k == 1 ? 2.0L : 1.0L) / (2 * k);
    if (k + 1 <= N) B(k, k + 1) -= 1.0L / (2 * k);
  }
  for (int k = 1; k <= N + 1; ++k) B.row(0) -= (k % 2 == 0 ? 1.0L : -1.0L) * B.row(k);
  r.integration = (T * B * C).cast<double>();
  r.to_coefficients = C.cast<double>();
  return r;
}

}  // namespace

const ChebyshevRule& chebyshev_rule(int degree) {
  constexpr int kLevels = 7;  // 4, 8, 16, 32, 64, 128, 256
  static_assert(kMinChebyshevDegree << (kLevels - 1) == kMaxChebyshevDegree);
  int level = 0;
  while (level < kLevels && (kMinChebyshevDegree << level) != degree) ++level;
  if (level == kLevels)
    throw std::invalid_argument("chebyshev_rule: degree must be a power of two in [4, 256], got " +
                                std::to_string(degree));
  static std::once_flag once[kLevels];
  static std::unique_ptr<const ChebyshevRule> rules[kLevels];
  std::call_once(once[level], [&] { rules[level] = std::make_unique<const ChebyshevRule>(build_rule(degree)); });
  return *rules[level];
}

namespace {

// Clenshaw's recurrence for M series of the same degree at once (independent chains: the processor
// overlaps them).
template <int M>
Eigen::Array<double, M, 1> clenshaw(const std::array<const double*, M>& a, int degree, double x) {
  using Value = Eigen::Array<double, M, 1>;
  Value b1 = Value::Zero(), b2 = Value::Zero(), ak;
  for (int k = degree; k >= 1; --k) {
    for (int m = 0; m < M; ++m) ak[m] = a[static_cast<std::size_t>(m)][k];
    const Value b0 = ak + 2 * x * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  for (int m = 0; m < M; ++m) ak[m] = a[static_cast<std::size_t>(m)][0];
  return ak + x * b1 - b2;
}

}  // namespace

double chebyshev_series(const double* a, int degree, double x) { return clenshaw<1>({a}, degree, x)[0]; }

Eigen::Array2d chebyshev_series(const double* a, const double* b, int degree, double x) {
  return clenshaw<2>({a, b}, degree, x);
}

Eigen::VectorXd chebyshev_interpolate(const ChebyshevRule& rule, const Eigen::Ref<const Eigen::MatrixXd>& values,
                                      double x) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(values.rows());
  double denominator = 0;
  for (int i = 0; i <= rule.degree; ++i) {
    const double dx = x - rule.node[i];
    if (dx == 0) return values.col(i);
    const double q = rule.barycentric_weight[i] / dx;
    sum += q * values.col(i);
    denominator += q;
  }
  return sum / denominator;
}

}  // namespace ogive
