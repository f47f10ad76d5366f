// Single and multiple shooting for the linear boundary-value problem of ArchModel, with CVODE.
//
// Each shooting segment [s_k, s_k+1] yields its fundamental matrix Phi_k and the load's particular
// solution p_k from one CVODE integration of 7 columns. Multiple shooting keeps every segment's start
// state y_k as an unknown: springing conditions, continuity y_k+1 = Phi_k y_k + p_k and crown
// conditions form one block-bidiagonal sparse system solved by Eigen's SparseLU. Nothing is condensed,
// so the growth of Phi over one segment, not over the whole arch, sets the conditioning.
#pragma once

#include <memory>
#include <vector>

#include "ogive/solve.hpp"

namespace ogive {

// Segment boundaries over [0, S~]: `segments` equal pieces, plus every curve breakpoint when
// segments > 1 and at_breakpoints (single shooting lets the integrator restart at breakpoints
// instead). Scaled.
std::vector<double> shooting_knots(const ArchModel& model, int segments, bool at_breakpoints = true);

// segments == 1 is single shooting. Status integrator_failure when CVODE fails (the message names the
// flag and the arc length in m); singular_system / ill_conditioned from the condition estimate.
Solution solve_shooting(std::shared_ptr<const ArchModel> model, const Options& options, int segments);

}  // namespace ogive
