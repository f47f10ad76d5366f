// The dense simplex method of dense_lp.hpp.
//
// The program max c.z subject to a_j . z <= b_j (j = 1 .. n, some equalities), z in R^k, and its dual,
// min b.y subject to sum_j y_j a_j = c, y_j >= 0 (free for an equality row). A basis is k rows S; its
// vertex z solves B z = b_S (B: the rows of S), its dual y_S solves B^T y_S = c. The method keeps y_S >= 0
// (dual feasible: the vertex is at least as good as the optimum) and walks towards primal feasibility:
// a row that the vertex violates (slack b_j - a_j . z < 0, its reduced cost in the dual) enters, and the
// ratio test on y_S picks the row that leaves. This is the primal simplex method on the dual program,
// whose basis is only k x k: one step costs the slacks of all rows (n dot products of length k) and a
// k x k factorisation. No slack is violated: optimal. No row can leave: the dual is unbounded, so the
// program is infeasible.
//
// Degeneracy: the start (the caps of the unknowns) has k - 1 zero duals, and a thrust line along a face
// makes many rows tight at once, so steps of length zero are common. The entering row is the most
// violated by distance (slack over |a|), the leaving one the largest pivot among the near-ties of the
// ratio test (Harris), which keeps the bases well conditioned; after a run of steps that do not lower
// the objective the method switches to Bland's rule (the lowest index enters, the lowest index leaves
// among ties), which cannot cycle.
#include "limit/dense_lp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ogive::limit_detail {
namespace {

constexpr int K = kDenseUnknowns;

// A pivot below this (the rows' coefficients are of order one) does not leave the basis.
constexpr double kPivot = 1e-9;
// Harris' relaxation of the ratio test: the duals may go this far below zero.
constexpr double kHarris = 1e-13;
// A basis whose factorisation meets a pivot below this, relative to its largest entry, is singular.
constexpr double kSingular = 1e-12;
// Steps without a decrease of the objective after which Bland's rule takes over.
constexpr int kStallSteps = 20;

// The LU factorisation with partial pivoting of a k x k matrix, P B = L U.
struct SmallLu {
  int k = 0;
  double m[K][K];
  int perm[K];

  // False when B is singular (to kSingular).
  bool factor() {
    double scale = 0;
    for (int i = 0; i < k; ++i)
      for (int c = 0; c < k; ++c) scale = std::max(scale, std::abs(m[i][c]));
    for (int i = 0; i < k; ++i) perm[i] = i;
    for (int c = 0; c < k; ++c) {
      int p = c;
      for (int i = c + 1; i < k; ++i)
        if (std::abs(m[i][c]) > std::abs(m[p][c])) p = i;
      if (!(std::abs(m[p][c]) > kSingular * scale)) return false;
      if (p != c) {
        std::swap(perm[p], perm[c]);
        for (int j = 0; j < k; ++j) std::swap(m[p][j], m[c][j]);
      }
      for (int i = c + 1; i < k; ++i) {
        const double f = m[i][c] / m[c][c];
        m[i][c] = f;
        for (int j = c + 1; j < k; ++j) m[i][j] -= f * m[c][j];
      }
    }
    return true;
  }

  // x <- B^{-1} x.
  void solve(double* x) const {
    double v[K];
    for (int i = 0; i < k; ++i) v[i] = x[perm[i]];
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < i; ++j) v[i] -= m[i][j] * v[j];
    for (int i = k - 1; i >= 0; --i) {
      for (int j = i + 1; j < k; ++j) v[i] -= m[i][j] * v[j];
      v[i] /= m[i][i];
    }
    for (int i = 0; i < k; ++i) x[i] = v[i];
  }

  // x <- B^{-T} x: U^T L^T P x = r.
  void solve_transposed(double* x) const {
    double v[K];
    for (int i = 0; i < k; ++i) {
      v[i] = x[i];
      for (int j = 0; j < i; ++j) v[i] -= m[j][i] * v[j];
      v[i] /= m[i][i];
    }
    for (int i = k - 1; i >= 0; --i)
      for (int j = i + 1; j < k; ++j) v[i] -= m[j][i] * v[j];
    for (int i = 0; i < k; ++i) x[perm[i]] = v[i];
  }
};

struct Basis {
  int rows[K];
  SmallLu lu;
  double z[K];  // the vertex, in the free unknowns' order
  double y[K];  // the duals of the basic rows
};

// Factorises the basis and computes its vertex and duals; false when it is singular.
bool evaluate(const std::vector<DenseRow>& rows, const std::vector<double>& b, const std::vector<int>& free,
              const std::array<double, K>& objective, Basis& basis) {
  const int k = static_cast<int>(free.size());
  basis.lu.k = k;
  for (int i = 0; i < k; ++i)
    for (int c = 0; c < k; ++c) basis.lu.m[i][c] = rows[basis.rows[i]].a[free[c]];
  if (!basis.lu.factor()) return false;
  for (int i = 0; i < k; ++i) basis.z[i] = b[basis.rows[i]];
  basis.lu.solve(basis.z);
  for (int i = 0; i < k; ++i) basis.y[i] = objective[free[i]];
  basis.lu.solve_transposed(basis.y);
  return true;
}

bool dual_feasible(const std::vector<DenseRow>& rows, const Basis& basis, int k, double tolerance) {
  for (int i = 0; i < k; ++i)
    if (!rows[basis.rows[i]].equality && basis.y[i] < -tolerance) return false;
  return true;
}

}  // namespace

bool dense_vertex(const std::vector<DenseRow>& rows, const std::vector<double>& b, const std::vector<int>& free,
                  const std::vector<int>& basis, std::array<double, K>& z) {
  const int k = static_cast<int>(free.size()), n = static_cast<int>(rows.size());
  if (static_cast<int>(basis.size()) != k || k == 0) return false;
  Basis vertex;
  for (int i = 0; i < k; ++i) {
    if (basis[i] < 0 || basis[i] >= n) return false;
    vertex.rows[i] = basis[i];
  }
  if (!evaluate(rows, b, free, std::array<double, K>{}, vertex)) return false;
  for (int c = 0; c < k; ++c) z[free[c]] = vertex.z[c];
  return true;
}

DenseLpAnswer solve_dense_lp(const std::vector<DenseRow>& rows, const std::vector<double>& b,
                             const std::vector<int>& free, const std::array<double, K>& objective,
                             const std::vector<int>& start, const std::vector<int>* warm, double tolerance) {
  DenseLpAnswer answer;
  const int k = static_cast<int>(free.size()), n = static_cast<int>(rows.size());
  Basis basis;
  bool started = false;
  if (warm && static_cast<int>(warm->size()) == k) {
    bool valid = true;
    for (int i = 0; i < k; ++i) {
      const int r = (*warm)[i];
      valid = valid && r >= 0 && r < n && std::find(warm->begin(), warm->begin() + i, r) == warm->begin() + i;
      basis.rows[i] = valid ? r : 0;
    }
    started = valid && evaluate(rows, b, free, objective, basis) &&
              dual_feasible(rows, basis, k, tolerance);
  }
  if (!started) {
    std::copy(start.begin(), start.end(), basis.rows);
    if (!evaluate(rows, b, free, objective, basis)) return answer;  // failure
  }

  double best_value = std::numeric_limits<double>::infinity();
  int stalled = 0;
  const int max_steps = 1000 + 10 * n;
  for (int step = 0; step < max_steps; ++step) {
    answer.iterations = step;
    const bool bland = stalled > kStallSteps;
    // The free unknowns at their columns, the fixed ones at 0 (folded into b): every row's slack is one
    // dot product of length five.
    std::array<double, K> z{};
    for (int c = 0; c < k; ++c) z[free[c]] = basis.z[c];
    // Pricing: the row the vertex violates most, by distance (Bland: the first violated row).
    int q = -1;
    double best = 0, q_slack = 0;
    for (int j = 0; j < n; ++j) {
      const DenseRow& row = rows[j];
      const double s = b[j] - (row.a[0] * z[0] + row.a[1] * z[1] + row.a[2] * z[2] + row.a[3] * z[3] +
                               row.a[4] * z[4]);
      const double violation = row.equality ? -std::abs(s) : s;
      if (!(violation < -tolerance)) continue;
      if (std::find(basis.rows, basis.rows + k, j) != basis.rows + k) continue;  // round-off of a basic row
      const double score = violation / row.norm;
      if (score < best) {
        best = score;
        q = j;
        q_slack = s;
      }
      if (bland) break;
    }
    if (q < 0) {  // no row violated: optimal
      answer.outcome = DenseLpAnswer::Outcome::optimal;
      for (int c = 0; c < k; ++c) answer.z[free[c]] = basis.z[c];
      answer.basis.assign(basis.rows, basis.rows + k);
      return answer;
    }
    // Row q enters with dual sigma * theta (an equality row's dual may be negative); the basic duals
    // move by -theta * w, w = sigma B^{-T} a_q, to keep sum y a = c.
    const double sigma = rows[q].equality && q_slack > 0 ? -1.0 : 1.0;
    double w[K];
    for (int c = 0; c < k; ++c) w[c] = sigma * rows[q].a[free[c]];
    basis.lu.solve_transposed(w);
    int p = -1;
    if (!bland) {
      // Harris: the largest step any dual allows when relaxed by kHarris, then the largest pivot among
      // the rows whose own ratio lies within it.
      double bound = std::numeric_limits<double>::infinity();
      for (int i = 0; i < k; ++i)
        if (!rows[basis.rows[i]].equality && w[i] > kPivot)
          bound = std::min(bound, (std::max(basis.y[i], 0.0) + kHarris) / w[i]);
      for (int i = 0; i < k; ++i)
        if (!rows[basis.rows[i]].equality && w[i] > kPivot && std::max(basis.y[i], 0.0) / w[i] <= bound &&
            (p < 0 || w[i] > w[p]))
          p = i;
    } else {
      double least = std::numeric_limits<double>::infinity();
      for (int i = 0; i < k; ++i) {
        if (rows[basis.rows[i]].equality || !(w[i] > kPivot)) continue;
        const double ratio = std::max(basis.y[i], 0.0) / w[i];
        if (ratio < least || (ratio == least && basis.rows[i] < basis.rows[p])) {
          least = ratio;
          p = i;
        }
      }
    }
    if (p < 0) {  // nothing leaves: the dual is unbounded below, the program infeasible
      answer.outcome = DenseLpAnswer::Outcome::infeasible;
      return answer;
    }
    basis.rows[p] = q;
    if (!evaluate(rows, b, free, objective, basis)) return answer;  // failure
    double value = 0;
    for (int c = 0; c < k; ++c) value += objective[free[c]] * basis.z[c];
    if (value < best_value - 1e-15 * std::max(1.0, std::abs(best_value))) {
      best_value = value;
      stalled = 0;
    } else {
      ++stalled;
    }
  }
  return answer;  // failure: no optimum within the steps allowed
}

}  // namespace ogive::limit_detail
