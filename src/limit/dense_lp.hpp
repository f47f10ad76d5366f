// A dense simplex method for linear programs of at most five unknowns and many inequalities: the shape
// of every program of the limit analysis (src/limit/limit_lp.cpp), private to the module.
//
// Why a method of our own beside Clp: each program has at most five unknowns (H, V, M, lambda, mu) and
// two rows per joint. A general sparse code pays for its generality at every call (loading the model,
// sparse factorisations, its primal cleanup), which for such a shape costs far more than the
// arithmetic. Here a basis is an explicit k x k matrix (k <= 5) factorised afresh at every step, so
// every step costs one pass over the rows (O(N k)) and never accumulates round-off. Clp stays the
// independent reference (tests/acceptance/limit_lp_test.cpp compares both on many rings).
#pragma once

#include <array>
#include <vector>

namespace ogive::limit_detail {

inline constexpr int kDenseUnknowns = 5;

// One row a . z <= b (or = b for an equality) over all five unknowns; a program uses the coefficients
// of its free unknowns only (the fixed ones are folded into b by the caller).
struct DenseRow {
  std::array<double, kDenseUnknowns> a{};
  double b = 0;
  bool equality = false;
  double norm = 1;  // |a|, to rank violated rows by their distance from the vertex
};

struct DenseLpAnswer {
  enum class Outcome { optimal, infeasible, failure } outcome = Outcome::failure;
  std::array<double, kDenseUnknowns> z{};  // the free unknowns at the optimum (the fixed ones 0)
  std::vector<int> basis;                  // the k rows tight at the optimal vertex
  int iterations = 0;
};

// Maximises objective . z over z (the unknowns `free`, k = free.size() <= 5; the objective's other
// entries are ignored) subject to the rows, whose right-hand sides are `b` (one per row). `start`: k
// rows whose vertex is dual feasible for this objective (the caps of the unknowns, say); `warm`: a better start to try first
// (the previous program's optimal basis), used when it is a nonsingular, dual-feasible basis.
// `tolerance`: how far a row may be violated at the optimum (absolute, in the rows' units).
DenseLpAnswer solve_dense_lp(const std::vector<DenseRow>& rows, const std::vector<double>& b,
                             const std::vector<int>& free, const std::array<double, kDenseUnknowns>& objective,
                             const std::vector<int>& start, const std::vector<int>* warm, double tolerance);

// The vertex of the k rows `basis` (right-hand sides `b`) into z's free unknowns (the others left as
// they are), by the same arithmetic as solve_dense_lp's: the optimum it returns on that basis. False when
// the rows are singular or an index is out of range.
bool dense_vertex(const std::vector<DenseRow>& rows, const std::vector<double>& b, const std::vector<int>& free,
                  const std::vector<int>& basis, std::array<double, kDenseUnknowns>& z);

}  // namespace ogive::limit_detail
