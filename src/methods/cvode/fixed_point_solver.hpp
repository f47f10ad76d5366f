// Adams' nonlinear solver for CVODE (private to src/methods/cvode/): the plain fixed-point iteration
// (no Anderson acceleration) of SUNDIALS' SUNNonlinSol_FixedPoint with m = 0, step for step (the same
// calls of CVODE's system function and convergence test, the same numbers, counters and failure
// returns), with its three vector calls an iteration fused into one loop (vector::fixed_point_update_for).
#pragma once

#include <sundials/sundials_nonlinearsolver.h>
#include <sundials/sundials_nvector.h>

namespace ogive::cvode::fixed_point {

// A solver for vectors like y, owned by the caller (SUNNonlinSolFree); nullptr if SUNDIALS cannot
// allocate.
SUNNonlinearSolver make(N_Vector y, SUNContext ctx);

}  // namespace ogive::cvode::fixed_point
