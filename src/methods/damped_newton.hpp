// The no-tension methods' one Newton (private header, methods layer): damped by halving until the trial
// is admissible and the residual falls, shared by Newton shooting (no_tension.cpp) and the quadrature
// form (no_tension_quadrature.cpp), which differ only in how they evaluate the residual and its Jacobian.
#pragma once

#include <algorithm>
#include <utility>

#include <functional>
#include <span>

#include <Eigen/LU>
#include <fmt/format.h>

#include "methods/no_tension.hpp"

namespace ogive {

// The first guess of both (no_tension.hpp): start(y0) tries a springing state (true when Newton can start
// from it): each finite one of `guesses` in turn, then most_admissible_start's. False when none
// starts, with sol's status and message set: inadmissible (no state keeps the resultant inside every
// section) or not_converged (the most admissible state could not be evaluated).
bool first_guess(const ArchModel& model, std::span<const StateVector> guesses,
                 const std::function<bool(const StateVector&)>& start, Solution& sol);

inline constexpr int kMaxNewtonIterations = 30;  // beyond, a path of smaller movements is cheaper (solve.cpp)
inline constexpr int kMaxNewtonHalvings = 40;

// Newton from the unknowns x with their evaluation e (e.ok: the residual and Jacobian exist) to the root
// of e.residual. evaluate(x) returns an Evaluation with ok, residual (Eigen::VectorXd) and jacobian
// (Eigen::MatrixXd); ok false means the trial left the admissible states (N < 0 and |M / N| < t / 2
// everywhere) or could not be evaluated, and the step is halved. A step is taken when its residual's max
// norm falls by Armijo's 1e-4 lambda. Converged when Newton's full step changes no unknown by more than
// step_tol times max(|x|, 1) (the forces are of order one in scaled units): Newton's own error is then
// negligible beside the evaluation's, which the residual cannot fall below; such a small step is taken
// as soon as it can be evaluated. When no step lowers the residual, converged if at_noise(e) says the
// residual is at the evaluation's own noise (a nearly singular direction, H insensitive once hinges
// have formed, keeps Newton's step from looking small there). x and e end at the last accepted point.
// True when converged; else sol's status is singular_system (Newton's matrix) or not_converged, with a
// message. sol's newton_iterations is set either way.
template <class Evaluation, class Evaluate, class AtNoise>
bool damped_newton(Evaluate&& evaluate, AtNoise&& at_noise, double step_tol, Eigen::VectorXd& x, Evaluation& e,
                   Solution& sol) {
  int& iterations = sol.diagnostics.newton_iterations;
  iterations = 0;
  bool converged = false;
  for (; iterations < kMaxNewtonIterations && !converged; ++iterations) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(e.jacobian);
    const Eigen::VectorXd step = -lu.solve(e.residual);
    if (!step.allFinite()) {
      sol.status = Status::singular_system;
      sol.message = "Newton's matrix is singular";
      return false;
    }
    const bool small = step.cwiseAbs().maxCoeff() <= step_tol * std::max(1.0, x.cwiseAbs().maxCoeff());
    const double norm = e.residual.template lpNorm<Eigen::Infinity>();
    double lambda = 1;
    bool accepted = false;
    for (int h = 0; h < kMaxNewtonHalvings && !accepted; ++h, lambda *= 0.5) {
      const Eigen::VectorXd trial = x + lambda * step;
      Evaluation et = evaluate(trial);
      if (et.ok && (small || et.residual.template lpNorm<Eigen::Infinity>() <= (1 - 1e-4 * lambda) * norm)) {
        x = trial;
        e = std::move(et);
        accepted = true;
        converged = small;
      }
    }
    if (!accepted) {
      converged = at_noise(e);
      break;
    }
  }
  if (!converged) {
    sol.status = Status::not_converged;
    sol.message = fmt::format("Newton did not converge in {} iterations (residual {:.3g})", iterations,
                              e.residual.template lpNorm<Eigen::Infinity>());
  }
  return converged;
}

}  // namespace ogive
