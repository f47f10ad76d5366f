// Shared by the methods (private header): the two-point boundary-value solve over one segment and the
// bookkeeping that turns a solved springing state into a Solution.
#pragma once

#include <limits>
#include <memory>

#include "ogive/solve.hpp"

namespace ogive {

struct BvpSolution {
  StateVector y0 = StateVector::Zero();  // scaled state at the springing
  StateVector yS = StateVector::Zero();  // scaled state at the crown
  double condition = std::numeric_limits<double>::infinity();  // boundary_value_condition
};

// The springing's three conditions fix three components of y(0) (Ux, Uy, psi for a clamped springing),
// so y(0) = start + U u with u the three unknown components: a shooting method integrates the three
// columns of U and the particular solution from `start` (4 columns, not 7), and the boundary-value
// problem is the crown's three conditions in u.
struct SpringingSplit {
  Eigen::Matrix<double, kStateSize, 3> U = Eigen::Matrix<double, kStateSize, 3>::Zero();
  StateVector start = StateVector::Zero();
};
SpringingSplit springing_split(const ArchModel& model);

// The transfer of the reduced problem over the half arch: y(S) = PhiU u + q.
using ReducedTransfer = Eigen::Matrix<double, kStateSize, 3>;

// Skeel's condition number || |Q^-1| |Q| ||_inf of the reduced boundary-value matrix Q = B_crown PhiU
// (3 x 3): the relative error that round-off in the conditions can cause in the solution, whatever the
// units of the rows. Infinite when Q is singular. Every method reports this one number for a scene.
double boundary_value_condition(const ArchModel& model, const ReducedTransfer& PhiU);
// The same for the full transfer Phi of the homogeneous system (PhiU = Phi U).
double boundary_value_condition(const ArchModel& model, const SystemMatrix& Phi);

// Solves the crown's conditions B_crown (PhiU u + q) = rhs for u; y0 = start + U u, yS = PhiU u + q.
BvpSolution solve_reduced(const ArchModel& model, const ReducedTransfer& PhiU, const StateVector& q);
// The same from the full transfer y(S) = Phi y(0) + p.
BvpSolution solve_single_segment(const ArchModel& model, const SystemMatrix& Phi, const StateVector& p);

// Fills reactions, residuals and the condition estimate. Status success (provisional: solve() judges
// it against rtol with judge_solution), or singular_system when the condition exceeds 1 / round-off.
void finish_solution(Solution& sol, const BvpSolution& bvp, std::shared_ptr<const StateField> field);

// The larger of the relative differences of H and of the profiles (when both carry one): the error
// estimate of a solution a against a tighter one b. NaN when either has no field.
double solution_difference(const Solution& a, const Solution& b);

}  // namespace ogive
