// Shared by the methods (private header): the two-point boundary-value solve over one segment and the
// bookkeeping that turns a solved springing state into a Solution.
#pragma once

#include <memory>

#include "ogive/solve.hpp"

namespace ogive {

struct BvpSolution {
  StateVector y0 = StateVector::Zero();  // scaled state at the springing
  StateVector yS = StateVector::Zero();  // scaled state at the crown
  double rcond = 0;                      // reciprocal 1-norm condition estimate of the BVP matrix
};

// Solves at_springing y0 + at_crown (Phi y0 + p) = rhs for y0, where y(S) = Phi y(0) + p.
BvpSolution solve_single_segment(const ArchModel& model, const SystemMatrix& Phi, const StateVector& p);

// Status success, or ill_conditioned (with its message) when the condition estimate times round-off
// exceeds rtol: the one place that judges whether conditioning lets a solution meet rtol.
void judge_conditioning(Solution& sol, double rtol);

// Fills reactions, residuals, condition estimate and status (success, or singular_system /
// ill_conditioned when the condition estimate says the asked rtol cannot be trusted).
void finish_solution(Solution& sol, const BvpSolution& bvp, std::shared_ptr<const StateField> field,
                     double rtol);

// The larger of the relative differences of H and of the profiles (when both carry one): the error
// estimate of a solution a against a tighter one b. NaN when either has no field.
double solution_difference(const Solution& a, const Solution& b);

}  // namespace ogive
