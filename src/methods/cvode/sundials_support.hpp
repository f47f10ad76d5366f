// The CVODE wrapper's shared pieces (private to src/methods/cvode/): RAII handles for the SUNDIALS
// objects, and the check of a setup call's return flag.
#pragma once

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <cvode/cvode.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nonlinearsolver.h>
#include <sundials/sundials_nvector.h>

namespace ogive::cvode {

// RAII handles for the SUNDIALS objects.
struct ContextDeleter { void operator()(SUNContext c) const { SUNContext_Free(&c); } };
struct VectorDeleter { void operator()(_generic_N_Vector* v) const { N_VDestroy(v); } };
struct MatrixDeleter { void operator()(_generic_SUNMatrix* m) const { SUNMatDestroy(m); } };
struct LinearSolverDeleter { void operator()(_generic_SUNLinearSolver* s) const { SUNLinSolFree(s); } };
struct NonlinearSolverDeleter { void operator()(_generic_SUNNonlinearSolver* s) const { SUNNonlinSolFree(s); } };
struct CvodeDeleter { void operator()(void* mem) const { CVodeFree(&mem); } };

using ContextHandle = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using VectorHandle = std::unique_ptr<_generic_N_Vector, VectorDeleter>;
using MatrixHandle = std::unique_ptr<_generic_SUNMatrix, MatrixDeleter>;
using LinearSolverHandle = std::unique_ptr<_generic_SUNLinearSolver, LinearSolverDeleter>;
using NonlinearSolverHandle = std::unique_ptr<_generic_SUNNonlinearSolver, NonlinearSolverDeleter>;
using CvodeHandle = std::unique_ptr<void, CvodeDeleter>;

inline std::string flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // malloc'd by SUNDIALS
  std::string out = name ? name : "CV_UNKNOWN";
  std::free(name);
  return out;
}

// Setup calls cannot fail for valid arguments; if one does, it is a programming error.
inline void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string(call) + " failed: " + flag_name(flag));
}

}  // namespace ogive::cvode
