// Non-associative friction's rows (LimitLp::hold_sliding, normal_forces, slides): the friction rows of
// each joint held at given normal forces and back, and the joints' normal forces of a state.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "limit/limit_internal.hpp"
#include "limit/limit_lp_impl.hpp"

namespace ogive::limit_detail {

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

bool LimitLp::slides(const std::vector<int>& basis) const {
  for (const Impl::Sliding& sl : impl_->sliding)
    for (int r : basis)
      if (r == sl.row || r == sl.row + 1) return true;
  return false;
}

}  // namespace ogive::limit_detail
