// The no-tension arch (section.hpp: SectionKind::no_tension): a nonlinear two-point problem solved by
// Newton shooting with CVODE (methods layer).
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

#include <memory>
#include <span>

#include "ogive/solution.hpp"

namespace ogive {

// segments == 1: single shooting; otherwise multiple shooting over shooting_knots(model, segments).
// Status success (provisional, as every method's: solve() judges it against rtol), not_converged (with
// Diagnostics::newton_iterations), inadmissible, integrator_failure (the linear start could not be
// integrated), not_applicable (a hinge inside the domain), singular_system (Newton's matrix).
Solution solve_no_tension(std::shared_ptr<const ArchModel> model, const Options& options, int segments,
                          std::span<const StateVector> guesses = {});

// Single shooting's residual (the end's three conditions, scaled) and its Jacobian with respect to the
// springing's three unknown components, from the springing state y0 (its unknown components are taken,
// the given ones come from the conditions): what Newton solves, exposed for tests (finite differences).
struct ShootingResidual {
  bool ok = false;  // false when the integration left the admissible states
  Eigen::Vector3d residual = Eigen::Vector3d::Zero();
  Eigen::Matrix3d jacobian = Eigen::Matrix3d::Zero();
};
ShootingResidual no_tension_residual(const ArchModel& model, const Options& options, const StateVector& y0);

// The springing forces (Fx, Fy, M, scaled) that maximise the smallest margin t/2 - |M / N| (scaled t~)
// over the domain, with what that margin is (> 0: admissible); for tests and the first guess.
struct AdmissibleStart {
  StateVector y0 = StateVector::Zero();  // the springing state: given components and the found forces
  double margin = 0;                     // the smallest t~/2 - |M~ / N~|, over t~/2 (1: thrust on the axis)
};
AdmissibleStart most_admissible_start(const ArchModel& model);

}  // namespace ogive
