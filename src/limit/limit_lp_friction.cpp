// Non-associative friction's rows (LimitLp::hold_sliding, normal_forces, slides, sliding_fixed_points):
// the friction rows of each joint held at given normal forces and back, the joints' normal forces of a
// state, and the face of fixed points that an optimal basis with the rows held certifies.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "limit/limit_internal.hpp"
#include "limit/limit_lp_impl.hpp"

namespace ogive::limit_detail {

// A multiplier of the basis counts (its row carries the optimum's certificate) above this fraction of
// the largest: far above the round-off of a 4 x 4 solve, far below any multiplier a tight row has.
constexpr double kCertificate = 1e-9;

void LimitLp::hold_sliding(const std::vector<double>& normal_forces) {
  Impl& p = *impl_;
  if (p.sliding.empty()) return;
  if (normal_forces.empty()) {  // the Coulomb rows as load() made them
    for (std::size_t i = 0; i < p.coulomb.size(); ++i)
      p.rows[static_cast<std::size_t>(p.sliding[i / 2].row) + i % 2] = p.coulomb[i];
    p.coulomb.clear();
    return;
  }
  if (normal_forces.size() != p.sliding.size())
    throw std::logic_error("LimitLp::hold_sliding: one normal force per joint of the ring");
  const bool saved = !p.coulomb.empty();
  for (std::size_t j = 0; j < p.sliding.size(); ++j) {
    const Impl::Sliding& sl = p.sliding[j];
    const double N = std::max(0.0, normal_forces[j]) / p.weight;
    for (int k = 0; k < 2; ++k) {
      const double sign = k == 0 ? 1.0 : -1.0;
      Inequality& row = p.rows[static_cast<std::size_t>(sl.row + k)];
      if (!saved) p.coulomb.push_back(row);
      // sign T <= friction N_j, T = along . z + c.
      double sum = 0;
      for (int c = 0; c < kUnknowns; ++c) {
        row.a[c] = sign * sl.along.a[c];
        sum += row.a[c] * row.a[c];
      }
      row.b = p.friction * N - sign * sl.along.c;
      row.norm = std::sqrt(sum);
    }
  }
}

LimitLp::Answer LimitLp::sliding_fixed_points(const std::vector<int>& basis, bool least) {
  Impl& p = *impl_;
  constexpr int kFree = 4;  // H, V, M and lambda; the margin held at 0
  if (p.coulomb.empty() || std::isfinite(p.strength) || static_cast<int>(basis.size()) != kFree) return Answer{};
  // The basis' multipliers y (B^T y = the objective's gradient, lambda's), with the rows as held.
  Eigen::Matrix4d Bt;
  for (int i = 0; i < kFree; ++i) {
    const int r = basis[static_cast<std::size_t>(i)];
    if (r < 0 || r >= static_cast<int>(p.rows.size())) return Answer{};
    for (int c = 0; c < kFree; ++c) Bt(c, i) = p.rows[static_cast<std::size_t>(r)].a[c];
  }
  const Eigen::FullPivLU<Eigen::Matrix4d> lu(Bt);
  if (!lu.isInvertible()) return Answer{};
  const Eigen::Vector4d y = lu.solve(Eigen::Vector4d(0, 0, 0, 1));
  // The rows that carry the certificate (a positive multiplier): tight, with their Coulomb rows for the
  // held ones, as equalities; every other row as the associative program has it.
  hold_sliding({});
  std::vector<std::pair<int, bool>> tight;
  for (int i = 0; i < kFree; ++i) {
    if (!(y(i) > kCertificate * y.cwiseAbs().maxCoeff())) continue;
    Inequality& row = p.rows[static_cast<std::size_t>(basis[static_cast<std::size_t>(i)])];
    tight.emplace_back(basis[static_cast<std::size_t>(i)], row.equality);
    row.equality = true;
  }
  Answer a = collapse(&basis, least);
  for (const auto& [r, was] : tight) p.rows[static_cast<std::size_t>(r)].equality = was;
  return a;
}

bool LimitLp::slides(const std::vector<int>& basis) const {
  for (const Impl::Sliding& sl : impl_->sliding)
    for (int r : basis)
      if (r == sl.row || r == sl.row + 1) return true;
  return false;
}

}  // namespace ogive::limit_detail
