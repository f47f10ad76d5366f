// BDF's linear algebra for CVODE (private to src/methods/cvode/): the Newton matrix I - gamma J and its
// solver. Every column of the state obeys the same ODE, so J is block diagonal with identical 6 x 6
// blocks A(theta): the matrix type stores that one block, and the linear solver factors it once (Eigen,
// partial pivoting) and solves every column with it, instead of a dense LU of the whole matrix.
#pragma once

#include <Eigen/Dense>

#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "ogive/model/arch_model.hpp"

namespace ogive::cvode::block {

using Block = Eigen::Matrix<sunrealtype, kStateSize, kStateSize>;

// The one block a matrix made by make_matrix stores.
inline Block& of(SUNMatrix A) { return *static_cast<Block*>(A->content); }

// A block matrix (zero) and a linear solver for it, owned by the caller (SUNMatDestroy, SUNLinSolFree);
// nullptr if SUNDIALS cannot allocate.
SUNMatrix make_matrix(SUNContext ctx);
SUNLinearSolver make_solver(SUNContext ctx);

}  // namespace ogive::cvode::block
