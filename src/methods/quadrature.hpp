// The quadrature method (the classical force method) for smooth curves and every curve in general.
//
// On the half arch Fx is constant and Fy' = 1 (scaled), so M, psi and the displacements follow from the
// springing state by nested integrals of known functions of the angle theta(s) (arch_model.hpp): no
// differential equation is left to step through. A horizontal acceleration a adds Fx' = -a (also a
// constant) and makes the load antisymmetric in part: that arch is solved over its whole length, springing
// to springing, by the same integrals. The domain is cut into panels at the curve's breakpoints (the
// crown, pointed or not, is a panel's end); on each panel theta is sampled at
// Chebyshev-Lobatto nodes and every integral is a Clenshaw-Curtis cumulative integral, exact for
// polynomials of the panel's degree and spectrally accurate for the analytic pieces a curve is made of.
// The six boundary conditions then close the same 6x6 system as the other methods.
//
// Error estimate of its own (no second solve): the nodes of degree N are half of those of degree 2N, so
// the method solves at N = 4, 8, 16, ... 256 per panel, reusing every angle, until the difference between
// two successive degrees (as solution_difference measures it: the reactions and, with stations,
// profile_difference) meets rtol, and returns the finer one (never the first pair's). The estimate is of
// the returned degree's own error: with the last two differences d0, d1 shrinking by q = d1 / d0 <= 1/2,
// the tail d1 q / (1 - q) (spectral convergence shrinks them faster still, so it errs on the safe side),
// else d1 (finer_error_bound). solve() floors it at the solution's round-off bound (roundoff_bound: for
// this method its own, kRoundoffQuadrature x eps x (condition + A), in core/solution.hpp).
// With Options::unprinted_profile (a summary reads the field; no profile is printed) the fields of two
// degrees are compared at the finer one's nodes (its own states there, the coarser one's interpolant at
// the nodes between its own), with the reactions and H/V, as profile_difference measures them; no
// station of either field is sampled. The same degree is returned as with the 129 stations.
// The field (Solution::at, profiles) interpolates the nodes' states per panel (barycentric formula),
// accurate to the method's tolerance at any station.
#pragma once

#include <memory>

#include "ogive/core/solution.hpp"

namespace ogive {

// Of the Options it reads rtol, stations and restart_at_breakpoints; integrator, atol, segments and
// max_steps are CVODE's, and verify does not apply (the estimate is the method's own, never skipped).
// Status: solve() judges the estimate as every method's (within_tolerance: success when it is at most
// rtol; tolerance_not_met when even degree 256 does not meet it, a curve that is not smooth between its
// breakpoints; ill_conditioned when the condition times round-off exceeds rtol); singular_system from
// finish_solution; not_applicable beyond the symmetric arch with clamped springings under its own weight
// (with or without a horizontal acceleration; a crown hinge only without one), and when
// Options::restart_at_breakpoints is off on a curve that has breakpoints (a panel across a jump converges
// too slowly for the estimate to hold). Diagnostics: segments = panels,
// rhs_evaluations = angle evaluations theta(s), steps = 0.
Solution solve_quadrature(std::shared_ptr<const ArchModel> model, const Options& options);

}  // namespace ogive
