// The no-tension arch (section.hpp: SectionKind::no_tension): a nonlinear two-point problem solved by
// Newton, either shooting with CVODE (solve_no_tension) or in the quadrature form of the force method
// (solve_no_tension_quadrature, below), the independent checks of each other (methods layer).
//
// The state and the six equations are the linear model's (arch_model.hpp), but for the section's law:
// eps and kappa follow from N and M by section_strain, so that Ux', Uy' and psi' are nonlinear in the
// forces (the forces' equations stay linear: they are statics). CVODE integrates the state together with
// its variations dy/dz with respect to the springing's three unknown components z (the variational
// equations dY' = J(s, y) dY, J the system's Jacobian, which section_strain's derivatives give), so that
// one integration gives the boundary residual and its exact Jacobian.
//
// Single shooting: Newton on z (3 unknowns), the residual being the end's three conditions. Multiple
// shooting (segments > 1): Newton on z and every later segment's start state (6 each), the residual being
// the continuity of the state at every knot and the end's conditions. Both damp Newton's step by halving
// it until the trial state is admissible (N < 0 and |M / N| < t / 2 everywhere: CVODE's right-hand side
// refuses any other state) and the residual's max norm falls (Armijo with 1e-4). Converged when a full
// step changes no unknown by more than 1e-4 rtol relative to max(|unknown|, 1) (scaled units: the forces
// are of order one). Point loads jump as in the linear model; a hinge inside the domain is not treated
// (not_applicable).
//
// The first guess: the first of `guesses` (springing states, scaled: a neighbouring solution's for
// continuation along a support movement, the linear model's) that is admissible, else the most
// admissible statically possible state: the springing forces that maximise the smallest margin t/2 - |M/N| over 513 stations
// (nested golden-section searches; the forces are explicit in the springing's unknowns). When that
// margin is not positive, the status is inadmissible.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>

#include "ogive/core/solution.hpp"

namespace ogive {

// The work a solve may spend, in the units of its Diagnostics::rhs_evaluations: CVODE's right-hand-side
// evaluations for Newton shooting, integrand and geometry evaluations for the quadrature form. A solve
// that spends its budget stops with status not_converged and the message work_budget_message(budget,
// method) ("the work budget of N ... ran out"; with `scene`, "the scene's work budget ...", for the
// budget of all a scene's solves). Counts, not times: the same scene stops at the same point on any
// machine and for any number of threads.
inline constexpr std::int64_t kUnlimitedWork = std::numeric_limits<std::int64_t>::max();
std::string work_budget_message(std::int64_t budget, Method method, bool scene = false);

// segments == 1: single shooting; otherwise multiple shooting over shooting_knots(model, segments).
// Status success (provisional, as every method's: solve() judges it against rtol), not_converged (with
// Diagnostics::newton_iterations: Newton's kMaxNewtonIterations, or the work budget, ran out),
// inadmissible, integrator_failure (the linear start could not be integrated), not_applicable (a hinge
// inside the domain), singular_system (Newton's matrix). A Newton trial whose integration takes more than
// 8 times the right-hand sides of the costliest evaluation that succeeded (and more than 20 000) is given
// up as an inadmissible one is: Newton halves its step.
Solution solve_no_tension(std::shared_ptr<const ArchModel> model, const Options& options, int segments,
                          std::span<const StateVector> guesses = {}, std::int64_t budget = kUnlimitedWork);

// Single shooting's residual (the end's three conditions, scaled) and its Jacobian with respect to the
// springing's three unknown components, from the springing state y0 (its unknown components are taken,
// the given ones come from the conditions): what Newton solves, exposed for tests (finite differences).
struct ShootingResidual {
  bool ok = false;  // false when the integration left the admissible states
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
};
ShootingResidual no_tension_residual(const ArchModel& model, const Options& options, const StateVector& y0);

// The quadrature (force-method) form of the same Newton (Method::quadrature; src/methods/no_tension_quadrature.cpp):
// the forces are explicit in the springing's unknowns z (Fx = Fx0, Fy = Fy0 + B(s), M = M0 + Fx0 (y - y0)
// - Fy0 (x - x0) - C(s), B the load up to s with the point loads, C = int_0^s cos(theta) B ds, both
// Chebyshev series per piece between the model's breakpoints, converged to round-off), so the end's
// kinematic conditions are single integrals of known functions of s:
//   psi(S) = psi0 + int kappa ds
//   Ux(S)  = Ux0 + int (eps c - a_V V sn) ds - psi0 (y_S - y0) - int kappa (y_S - y) ds
//   Uy(S)  = Uy0 + int (eps sn + a_V V c) ds + psi0 (x_S - x0) + int kappa (x_S - x) ds
// with eps, kappa from section_strain; their derivatives with respect to z (section_strain's eps_N, eps_M,
// kappa_N, kappa_M) integrate to Newton's exact Jacobian. The integrals are Boost's Gauss-Kronrod G7-K15
// rule, adaptive and global over panels between the breakpoints and point loads (at least 32 over the
// domain; those with the largest share of |K15 - G7| halved until its sum, each value's over its L1
// norm, is at most max(rtol / 100, 1e-14)); a trial z is first checked for admissibility on every node.
// Newton, its damping and convergence rules and the first guesses are solve_no_tension's (the caller's
// guesses, the first admissible at every node, then most_admissible_start); at the quadrature's noise
// when the residual is within 10 times its tolerance, or the accuracy the panels reach above it, of the
// integrals' L1 norms. The field: the same
// integrals from 0 to any s (the panels' cumulative sums, the last panel's part by the same rule).
// Its error_estimate: what the panels' errors (the larger of |K15 - G7| and their round-off, which near
// a hinge whose compressed depth is a tiny part of t holds the integrals above their tolerance: such a
// panel is not halved) and Newton's last residual leave in the reactions, to first order through
// Newton's matrix; solve() adds a second solve at rtol / 16 and takes the larger estimate.
// Status as solve_no_tension's (success provisional; not_applicable for a crown hinge over the whole
// arch, as there). Diagnostics: rhs_evaluations = integrand and geometry evaluations, segments = the
// final panels, steps = 0.
Solution solve_no_tension_quadrature(std::shared_ptr<const ArchModel> model, const Options& options,
                                     std::span<const StateVector> guesses = {}, std::int64_t budget = kUnlimitedWork);
// Its residual and Jacobian at the springing state y0, as no_tension_residual (ok false when a node is
// inadmissible or the quadrature cannot meet its tolerance).
ShootingResidual no_tension_quadrature_residual(const ArchModel& model, const Options& options, const StateVector& y0);

// The springing forces (Fx, Fy, M, scaled) that maximise the smallest margin t/2 - |M / N| (scaled t~)
// over the domain, with what that margin is (> 0: admissible); for tests and the first guess.
struct AdmissibleStart {
  StateVector y0 = StateVector::Zero();  // the springing state: given components and the found forces
  double margin = 0;                     // the smallest t~/2 - |M~ / N~|, over t~/2 (1: thrust on the axis)
};
AdmissibleStart most_admissible_start(const ArchModel& model);

}  // namespace ogive
