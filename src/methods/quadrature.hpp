// The quadrature method (the classical force method) for smooth curves and every curve in general.
//
// On the half arch Fx is constant and Fy' = 1 (scaled), so M, psi and the displacements follow from the
// springing state by nested integrals of known functions of the angle theta(s) (arch_model.hpp): no
// differential equation is left to step through. The half arch is cut into panels at the curve's
// breakpoints (the crown, pointed or not, is the last panel's end); on each panel theta is sampled at
// Chebyshev-Lobatto nodes and every integral is a Clenshaw-Curtis cumulative integral, exact for
// polynomials of the panel's degree and spectrally accurate for the analytic pieces a curve is made of.
// The six boundary conditions then close the same 6x6 system as the other methods.
//
// Error estimate of its own (no second solve): the nodes of degree N are half of those of degree 2N, so
// the method solves at N = 8, 16, 32, ... 256 per panel (from 4 when breakpoints cut the arch into
// several panels), reusing every angle, until the difference between two successive degrees (of H
// relative to max(|H|, V / 100), as solution_difference measures it, and, with stations,
// profile_difference) meets rtol, and returns the finer one. Diagnostics::error_estimate is that difference, which bounds the
// coarser solution's error and overstates the finer one's, floored at round-off: 10 x eps x the
// condition estimate (at least 100).
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
// finish_solution; not_applicable when
// Options::restart_at_breakpoints is off on a curve that has breakpoints (a panel across a jump converges
// too slowly for the estimate to hold). Diagnostics: segments = panels,
// rhs_evaluations = angle evaluations theta(s), steps = 0.
Solution solve_quadrature(std::shared_ptr<const ArchModel> model, const Options& options);

}  // namespace ogive
