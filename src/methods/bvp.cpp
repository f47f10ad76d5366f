#include "methods/bvp.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>
#include <fmt/format.h>

namespace ogive {

SpringingSplit springing_split(const ArchModel& model) {
  const BoundaryConditions& bc = model.boundary_conditions();
  SpringingSplit split;
  // Each springing condition fixes one component y_j (its coefficient 1, the row's only one of 1) given
  // the unknown ones (the held face's compliance: its other coefficients, on components no row fixes).
  std::array<int, 3> fixed{};
  std::array<bool, kStateSize> known{};
  for (int r = 0; r < 3; ++r) {
    int ones = 0;
    for (int j = 0; j < kStateSize; ++j)
      if (bc.at_start(r, j) == 1.0) {
        fixed[static_cast<std::size_t>(r)] = j;
        ++ones;
      }
    if (ones != 1) throw std::logic_error("springing_split: a springing condition fixes no single component");
    known[static_cast<std::size_t>(fixed[static_cast<std::size_t>(r)])] = true;
    split.start[fixed[static_cast<std::size_t>(r)]] = bc.rhs(r);
  }
  int column = 0;
  for (int k = 0; k < kStateSize; ++k) {
    if (known[static_cast<std::size_t>(k)]) continue;
    split.U(k, column) = 1.0;
    for (int r = 0; r < 3; ++r)
      if (bc.at_start(r, k) != 0) split.U(fixed[static_cast<std::size_t>(r)], column) = -bc.at_start(r, k);
    ++column;
  }
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < kStateSize; ++k)
      if (known[static_cast<std::size_t>(k)] && k != fixed[static_cast<std::size_t>(r)] && bc.at_start(r, k) != 0)
        throw std::logic_error("springing_split: a springing condition couples two fixed components");
  return split;
}

int unknown_count(const ArchModel& model) { return model.hinge() ? 4 : 3; }

std::vector<double> required_knots(const ArchModel& model) {
  std::vector<double> knots;
  knots.reserve(model.jumps().size() + 4);
  knots.push_back(0.0);
  for (const PointJump& j : model.jumps())
    if (j.s > 0 && j.s < model.length()) knots.push_back(j.s);
  if (model.hinge()) knots.push_back(*model.hinge());
  if (model.kink()) knots.push_back(model.kink()->s);
  knots.push_back(model.length());
  std::sort(knots.begin(), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
  return knots;
}

std::vector<double> merge_knots(const ArchModel& model, std::vector<double> extra) {
  std::vector<double> required = required_knots(model);
  const double S = model.length(), close = 1e-9 * S;
  // Only the extra knots inside (0, S~) count; without any, and with the required ones farther apart than
  // `close` (the merging below would change nothing), those are the answer: one allocation, not four, for
  // a circular arc's single arc or single shooting.
  std::erase_if(extra, [&](double e) { return !(e > close && e < S - close); });
  const bool apart = std::adjacent_find(required.begin(), required.end(),
                                        [&](double a, double b) { return b - a < close; }) == required.end();
  if (extra.empty() && apart) return required;
  std::vector<double> out = required;
  out.reserve(required.size() + extra.size());
  for (double e : extra) {
    const bool near = std::any_of(required.begin(), required.end(), [&](double r) { return std::abs(r - e) < close; });
    if (!near) out.push_back(e);
  }
  std::sort(out.begin(), out.end());
  // Extra knots closer than `close` to each other: keep the first.
  std::vector<double> merged;
  for (double k : out) {
    const bool is_required = std::binary_search(required.begin(), required.end(), k);
    if (!merged.empty() && k - merged.back() < close) {
      if (is_required) merged.back() = k;
      continue;
    }
    merged.push_back(k);
  }
  return merged;
}

bool march(const ArchModel& model, const std::vector<double>& knots, const Advance& advance, March& out) {
  const int m = unknown_count(model);
  out.split = springing_split(model);
  AffineState Y = AffineState::Zero(kStateSize, m + 1);
  Y.leftCols<3>() = out.split.U;
  Y.col(m) = out.split.start;
  const auto& jumps = model.jumps();
  // The point loads at s (a knot): Fy jumps by their force.
  auto apply_jumps = [&](double s) {
    for (const PointJump& j : jumps)
      if (j.s == s) Y(kFy, m) += j.force;
  };
  out.knots = knots;
  out.starts.clear();
  out.hinge_row.resize(0);
  apply_jumps(0.0);
  const std::size_t K = knots.size() - 1;
  out.starts.reserve(K);
  for (std::size_t k = 0; k < K; ++k) {
    out.starts.push_back(Y);
    if (!advance(k, Y)) return false;
    const double s = knots[k + 1];
    if (model.hinge() && s == *model.hinge()) {
      out.hinge_row = Y.row(kM);
      Y.col(3).setZero();
      Y(kPsi, 3) = 1.0;  // psi jumps by the fourth unknown
    }
    const bool kink = model.kink() && s == model.kink()->s;
    // A kink's turn in two halves, a load at the crown between them (each half turns with its side's Fy).
    auto turn = [&](double theta1, double theta2) {
      const AffineState jump = model.kink_jump(theta1, theta2).lazyProduct(Y);
      Y += jump;
    };
    if (kink) turn(model.kink()->theta_before, 0.0);
    apply_jumps(s);
    if (kink) turn(0.0, model.kink()->theta_after);
  }
  out.end = Y;
  return true;
}

namespace {

// The reduced problem is 3 x 3 or 4 x 4, so it is solved with fixed sizes: Eigen's dynamic-size LU and
// products take their blocked paths (and allocate) on such tiny matrices. The sums are written out in a
// fixed order (sequential, column by column), so that every result is reproducible to the last bit.
template <int M>
using Square = Eigen::Matrix<double, M, M>;
template <int M>
using Column = Eigen::Matrix<double, M, 1>;

template <int M>
double skeel_condition(const Square<M>& Q) {
  const Eigen::FullPivLU<Square<M>> lu(Q);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  // Skeel's measure, not ||Q|| ||Q^-1||: the rows mix displacement and force conditions whose sizes
  // differ by orders of magnitude, and a norm-wise estimate would report that scaling, not a loss of
  // digits. |Q^-1| |Q| is what partial pivoting's backward error is amplified by, row scaling aside.
  const Square<M> inverse = lu.inverse();
  double condition = 0;
  for (int i = 0; i < M; ++i) {
    double row = 0;  // row i of |Q^-1| |Q|, summed
    for (int j = 0; j < M; ++j) {
      double a = std::abs(inverse(i, 0)) * std::abs(Q(0, j));
      for (int k = 1; k < M; ++k) a += std::abs(inverse(i, k)) * std::abs(Q(k, j));
      row = j == 0 ? a : row + a;
    }
    condition = i == 0 ? row : std::max(condition, row);
  }
  return std::isfinite(condition) ? condition : std::numeric_limits<double>::infinity();
}

// z from Q z = rhs: LU with partial pivoting, then the unit-lower and the upper solve column by column.
template <int M>
Column<M> solve_reduced(const Square<M>& Q, const Column<M>& rhs) {
  const Eigen::PartialPivLU<Square<M>> lu(Q);
  const Square<M>& LU = lu.matrixLU();
  Column<M> z = lu.permutationP() * rhs;
  for (int i = 0; i < M; ++i)
    if (z[i] != 0)
      for (int j = i + 1; j < M; ++j) z[j] -= z[i] * LU(j, i);
  for (int i = M - 1; i >= 0; --i)
    if (z[i] != 0) {
      z[i] /= LU(i, i);
      for (int j = 0; j < i; ++j) z[j] -= z[i] * LU(j, i);
    }
  return z;
}

// The reduced problem's solution z and its condition, for M unknowns.
template <int M>
Column<M> solve_with_condition(const ReducedMatrix& Q, const ReducedVector& rhs, double& condition) {
  const Square<M> QM = Q;
  condition = skeel_condition<M>(QM);
  return solve_reduced<M>(QM, rhs);
}

}  // namespace

double boundary_value_condition(const ReducedMatrix& Q) {
  if (Q.rows() == 3 && Q.cols() == 3) return skeel_condition<3>(Q);
  if (Q.rows() == 4 && Q.cols() == 4) return skeel_condition<4>(Q);
  throw std::logic_error("boundary_value_condition: the reduced matrix is 3 x 3 or 4 x 4");
}

BvpSolution solve_march(const ArchModel& model, March&& march) {
  const int m = unknown_count(model);
  const BoundaryConditions& bc = model.boundary_conditions();
  ReducedMatrix Q(m, m);
  ReducedVector rhs(m);
  const Eigen::Matrix<double, 3, kStateSize> B = bc.at_end.bottomRows<3>();
  // Coefficient-based products throughout: for these tiny matrices Eigen's GEMM/GEMV kernels (chosen for
  // dynamic sizes) cost more than the arithmetic.
  Q.topRows(3) = B.lazyProduct(march.end.leftCols(m));
  rhs.head(3) = bc.rhs.tail<3>() - B.lazyProduct(march.end.col(m));
  if (m == 4) {
    Q.row(3) = march.hinge_row.leftCols(m);
    rhs(3) = -march.hinge_row(m);
  }
  BvpSolution out;
  Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxUnknowns + 1, 1> z1(m + 1);
  if (m == 4) z1.head<4>() = solve_with_condition<4>(Q, rhs, out.condition);
  else z1.head<3>() = solve_with_condition<3>(Q, rhs, out.condition);
  z1(m) = 1.0;
  out.y0 = march.split.start + march.split.U * z1.head<3>();
  out.yS = march.end.lazyProduct(z1);
  out.knots = std::move(march.knots);
  out.starts.reserve(march.starts.size());
  for (const AffineState& Y : march.starts) out.starts.push_back(Y.lazyProduct(z1));
  if (m == 4) out.hinge_moment = march.hinge_row.dot(z1);
  return out;
}

BvpSolution solve_single_segment(const ArchModel& model, const SystemMatrix& Phi, const StateVector& p) {
  March m;
  const std::vector<double> knots{0.0, model.length()};
  march(model, knots,
        [&](std::size_t, AffineState& Y) {
          const AffineState next = Phi.lazyProduct(Y);
          Y = next;
          Y.col(Y.cols() - 1) += p;
          return true;
        },
        m);
  return solve_march(model, std::move(m));
}

void finish_solution(Solution& sol, const BvpSolution& bvp, std::shared_ptr<const StateField> field) {
  const ArchModel& model = *sol.model;
  Diagnostics& d = sol.diagnostics;
  d.condition_estimate = bvp.condition;
  constexpr double kRoundoff = std::numeric_limits<double>::epsilon();
  if (!(bvp.condition * kRoundoff < 1) || !bvp.y0.allFinite() || !bvp.yS.allFinite()) {
    sol.status = Status::singular_system;
    sol.message = fmt::format("boundary-value system singular to working precision (condition {:.3g})",
                              d.condition_estimate);
    return;
  }
  sol.field = std::move(field);
  d.boundary_residual = model.boundary_residual(bvp.y0, bvp.yS, bvp.hinge_moment);
  d.equilibrium_residual = model.equilibrium_residual(bvp.y0, bvp.yS);
  sol.reactions = model.reactions(bvp.y0, bvp.yS);
  sol.springing_state = bvp.y0;
  sol.H = sol.reactions.H_left;
  sol.V = sol.reactions.V_left;
  sol.H_over_V = sol.H / sol.V;
  sol.status = Status::success;  // provisional: judge_solution decides against rtol
  sol.message.clear();
}

double PiecewiseField::piece_end(double s_k) const {
  const auto next = std::upper_bound(knots_.begin(), knots_.end(), s_k);
  return next == knots_.end() ? knots_.back() : *next;
}

void PiecewiseField::sample(std::span<const double> s, std::span<StateVector> out) const {
  std::size_t i = 0;
  const std::size_t K = starts_.size();
  for (std::size_t k = 0; k < K && i < s.size(); ++k) {
    const bool last = k + 1 == K;
    std::size_t j = i;
    // Left-continuous: a station at a knot belongs to the piece that ends there (the state before a point
    // load or a hinge), as over the half the crown's state is the left half's.
    while (j < s.size() && (last || s[j] <= knots_[k + 1])) ++j;
    if (j == i) continue;
    propagate(knots_[k], starts_[k], s.subspan(i, j - i), out.subspan(i, j - i));
    i = j;
  }
}

}  // namespace ogive
