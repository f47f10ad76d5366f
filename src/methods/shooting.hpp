// Single and multiple shooting for the linear boundary-value problem of ArchModel, with CVODE.
//
// Single shooting integrates the state's affine map [T | c] from the springing (its m unknown
// directions and the particular solution: 4 columns, 5 with a crown hinge) to the domain's end, across
// point loads and the hinge (bvp.hpp's march adds them between pieces), and solves the m x m condensed
// end conditions. Multiple shooting integrates that map over its first segment only; every later
// segment k gives its transfer y(s_k+1) = Phi_k y(s_k) + p_k from 5 integrated columns (unit psi, Fx,
// Fy, M and the load's; a unit Ux or Uy stays one exactly), applied to the map in turn, so that no
// integration error grows over more than one segment. With Adams all segments are integrated in one
// CVODE run, side by side in a normalised parameter, each held to the tolerance by a block error norm
// (one start-up of Adams instead of one per segment); with BDF one after the other. The condition
// estimate is the boundary-value problem's (Skeel's, on the condensed system): the same for every
// segment count.
#pragma once

#include <memory>
#include <vector>

#include "ogive/core/solution.hpp"

namespace ogive {

// The tolerances CVODE is given for Options o, with every multiplier between --rtol/--atol and CVODE
// in this one place: rtol = max(o.rtol * f, kCvodeRtolFloor) with f = 1/10 (Adams) or 1/1000 (BDF);
// atol = o.atol if > 0, else 1e-6 of that rtol. Why: CVODE controls each step's local error; the
// global error of a shooting solve is their accumulation amplified by the boundary-value system's
// condition (about 10^2), and BDF (order <= 5) takes ~4x more steps than Adams (order <= 12): at
// 1/100 its verified profiles missed rtol by 1.2-3.6x on the pointed arches. A verified solve also runs
// 16 and 256 times tighter (solve.cpp), never below kCvodeRtolFloor: below rtol 256 f^-1 kCvodeRtolFloor
// (2.56e-12 with Adams, 2.56e-10 with BDF) its first solve runs looser than f x rtol.
struct CvodeTolerances {
  double rtol = 0, atol = 0;
};
// Below about 1e-15 CVODE cannot hold a relative tolerance in double precision (it stops with
// CV_TOO_MUCH_ACC): its tolerance is clamped here, and a verifying solve below it is no tighter.
inline constexpr double kCvodeRtolFloor = 1e-15;
CvodeTolerances cvode_tolerances(const Options& o);
// A solve, or a piece of its profile, that CVODE could not finish at the default atol runs once more
// with the larger of 16 times that atol and kRetryAtol: an atol of 1e-6 of a tight rtol can hold a
// component that starts at zero (multiple shooting's unit columns, M at a crown hinge) below its own
// round-off, and CVODE stops (CV_TOO_MUCH_WORK). Not the default: thin arches need the small atol
// (single shooting with Adams at CVODE rtol 1.6e-14 on a pointed arch of t/L 0.017: profile errors
// 2.4e-13 with atol 1.6e-20, 1.3e-12 with 1e-17, 6.1e-12 with 1e-16). (Multiple shooting with BDF at
// CVODE rtol 3.9e-12 on a thin pointed arch under a live load: 200,000 steps in one segment with atol
// 3.9e-18 and 1e-18, 2,149 steps over the whole arch with 1e-17.)
inline constexpr double kRetryAtol = 1e-17;
double retry_atol(double atol);

// Segment boundaries over [0, S~]: `segments` equal pieces, plus every curve breakpoint when
// segments > 1 and at_breakpoints (single shooting lets the integrator restart at breakpoints
// instead). Scaled.
std::vector<double> shooting_knots(const ArchModel& model, int segments, bool at_breakpoints = true);

// segments == 1 is single shooting. Status integrator_failure when CVODE fails (the message names the
// flag and the arc length in m); singular_system / ill_conditioned from the condition estimate.
Solution solve_shooting(std::shared_ptr<const ArchModel> model, const Options& options, int segments);

}  // namespace ogive
