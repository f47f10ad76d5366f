// Closed-form solution for piecewise-circular curves (docs/model.md, the paper's section 2.6).
//
// On an arc of constant curvature the local-component system (u, v, psi, N, V, M) has a constant
// matrix; appending c = cos theta and sn = sin theta (c' = -kappa sn, sn' = kappa c) makes the
// self-weight term part of one constant 8x8 system, so the transfer over an arc of length l is exactly
// exp(A8 l), written out entry by entry (a few sines and cosines and short sums, exact to round-off for
// every curvature, a straight piece included). Arcs are chained in global components, which stay
// continuous across kinks; the six boundary conditions close the system.
#pragma once

#include <memory>

#include "ogive/core/solution.hpp"

namespace ogive {

// Affine transfer y(s1) = Phi y(s0) + p of the scaled global state over [s0, s1] of the half arch.
struct Transfer {
  SystemMatrix Phi = SystemMatrix::Identity();
  StateVector p = StateVector::Zero();
};

// exp(A8 l) of one arc in local components (u, v, psi, N, V, M, cos theta, sin theta), scaled: curvature
// k, length l, compliances a_N and a_V, vertical load b and horizontal load h per length (closed_form.cpp).
using ArcMatrix = Eigen::Matrix<double, 8, 8>;
ArcMatrix arc_exponential(double k, double l, double a_N, double a_V, double b, double h);

// Exact transfer over [s0, s1] (scaled, 0 <= s0 <= s1 <= S~). Requires a piecewise-circular curve.
Transfer closed_form_transfer(const ArchModel& model, double s0, double s1);

// Status not_applicable when the scene's curve is not piecewise circular.
Solution solve_closed_form(std::shared_ptr<const ArchModel> model, const Options& options);

}  // namespace ogive
