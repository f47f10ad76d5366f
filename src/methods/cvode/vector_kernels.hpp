// ogive's own N_Vector for CVODE (private to src/methods/cvode/): N_VNewEmpty with an operation table of
// loops compiled with the project's flags. Debian's libsundials is built without optimisation, and for
// the short vectors of shooting (6 to a few hundred numbers) CVODE's time went mostly into its serial
// vector loops; these are the same loops, the same arithmetic in the same order, so the same bits.
// CVODE clones every work vector from the one given to CVodeInit, and a clone copies the table, so
// every vector CVODE uses is one of these.
#pragma once

#include <memory>
#include <vector>

#include <sundials/sundials_nvector.h>

namespace ogive::cvode::vector {


struct Content {
  sunindextype length = 0;
  sunrealtype* data = nullptr;
  bool owns_data = false;
  // The ends of the independent problems the state holds, ascending, the last = length (one block: the
  // whole state). The weighted RMS norm is the largest of the blocks' own norms.
  std::shared_ptr<const std::vector<sunindextype>> block_ends;
};

inline Content& content(N_Vector v) { return *static_cast<Content*>(v->content); }
inline sunrealtype* data(N_Vector v) { return content(v).data; }
inline sunindextype size(N_Vector v) { return content(v).length; }

// A vector of zeros, block_ends->back() numbers long, with every operation CVODE, its Newton and
// fixed-point solvers and the block linear solver use (nullptr if SUNDIALS cannot allocate). With one
// block the loops are compiled for its length where it is 1 to 5 columns of 6 numbers.
N_Vector make(std::shared_ptr<const std::vector<sunindextype>> block_ends, SUNContext ctx);

// CVODE's error weights w_i = 1 / (rtol |y_i| + atol) for vectors like y, as CVODE computes them for
// scalar tolerances (the same operations in the same order), in one loop. False if a weight would not
// be positive.
using ErrorWeights = bool (*)(sunrealtype rtol, sunrealtype atol, N_Vector y, N_Vector w);
ErrorWeights error_weights_for(N_Vector y);

// The fixed-point iteration's update for vectors like y: delta = g - y, then y = g.
using FixedPointUpdate = void (*)(N_Vector g, N_Vector y, N_Vector delta);
FixedPointUpdate fixed_point_update_for(N_Vector y);

}  // namespace ogive::cvode::vector
