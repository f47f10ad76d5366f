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

// Skeel's condition number || |Q^-1| |Q| ||_inf of Q = B_springing + B_crown Phi, Phi the transfer of
// the homogeneous system over the half arch: the relative error that round-off in the six conditions
// can cause in the solution, whatever the units of the rows. Infinite when Q is singular.
double boundary_value_condition(const ArchModel& model, const SystemMatrix& Phi);

// Solves at_springing y0 + at_crown (Phi y0 + p) = rhs for y0, where y(S) = Phi y(0) + p.
BvpSolution solve_single_segment(const ArchModel& model, const SystemMatrix& Phi, const StateVector& p);

// Fills reactions, residuals and the condition estimate. Status success (provisional: solve() judges
// it against rtol with judge_solution), or singular_system when the condition exceeds 1 / round-off.
void finish_solution(Solution& sol, const BvpSolution& bvp, std::shared_ptr<const StateField> field);

}  // namespace ogive
