#include "methods/cvode/block_linear_solver.hpp"

#include <Eigen/LU>

#include "methods/cvode/vector_kernels.hpp"

namespace ogive::cvode::block {


namespace {

SUNMatrix_ID get_id(SUNMatrix) { return SUNMATRIX_CUSTOM; }
void destroy(SUNMatrix A) {
  if (!A) return;
  delete static_cast<Block*>(A->content);
  A->content = nullptr;
  SUNMatFreeEmpty(A);
}
SUNMatrix clone(SUNMatrix A) {
  SUNMatrix B = SUNMatNewEmpty(A->sunctx);
  if (!B) return nullptr;
  if (SUNMatCopyOps(A, B) != 0) {
    SUNMatFreeEmpty(B);
    return nullptr;
  }
  B->content = new Block(Block::Zero());
  return B;
}
int zero(SUNMatrix A) {
  of(A).setZero();
  return 0;
}
int copy(SUNMatrix A, SUNMatrix B) {
  of(B) = of(A);
  return 0;
}
int scale_add_identity(sunrealtype c, SUNMatrix A) {  // A = c A + I
  of(A) = c * of(A) + Block::Identity();
  return 0;
}
int scale_add(sunrealtype c, SUNMatrix A, SUNMatrix B) {  // A = c A + B
  of(A) = c * of(A) + of(B);
  return 0;
}

}  // namespace

SUNMatrix make_matrix(SUNContext ctx) {
  SUNMatrix A = SUNMatNewEmpty(ctx);
  if (!A) return nullptr;
  A->ops->getid = get_id;
  A->ops->clone = clone;
  A->ops->destroy = destroy;
  A->ops->zero = zero;
  A->ops->copy = copy;
  A->ops->scaleaddi = scale_add_identity;
  A->ops->scaleadd = scale_add;
  A->content = new Block(Block::Zero());
  return A;
}

namespace {

using Factor = Eigen::PartialPivLU<Block>;
Factor& factor_of(SUNLinearSolver S) { return *static_cast<Factor*>(S->content); }

SUNLinearSolver_Type get_type(SUNLinearSolver) { return SUNLINEARSOLVER_DIRECT; }
SUNLinearSolver_ID get_solver_id(SUNLinearSolver) { return SUNLINEARSOLVER_CUSTOM; }
int initialize(SUNLinearSolver) { return SUNLS_SUCCESS; }
int setup(SUNLinearSolver S, SUNMatrix A) {
  factor_of(S).compute(of(A));
  // Partial pivoting never fails; a zero pivot shows as a non-finite inverse estimate.
  return factor_of(S).rcond() > 0 ? SUNLS_SUCCESS : SUNLS_LUFACT_FAIL;
}
int solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, sunrealtype) {
  const sunindextype columns = vector::size(b) / kStateSize;
  Eigen::Map<const Eigen::Matrix<sunrealtype, kStateSize, Eigen::Dynamic>> B(vector::data(b), kStateSize, columns);
  Eigen::Map<Eigen::Matrix<sunrealtype, kStateSize, Eigen::Dynamic>> X(vector::data(x), kStateSize, columns);
  X = factor_of(S).solve(B);
  return SUNLS_SUCCESS;
}
sunindextype last_flag(SUNLinearSolver) { return 0; }
int free_solver(SUNLinearSolver S) {
  if (!S) return 0;
  delete static_cast<Factor*>(S->content);
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return 0;
}

}  // namespace

SUNLinearSolver make_solver(SUNContext ctx) {
  SUNLinearSolver S = SUNLinSolNewEmpty(ctx);
  if (!S) return nullptr;
  S->ops->gettype = get_type;
  S->ops->getid = get_solver_id;
  S->ops->initialize = initialize;
  S->ops->setup = setup;
  S->ops->solve = solve;
  S->ops->lastflag = last_flag;
  S->ops->free = free_solver;
  S->content = new Factor(kStateSize);
  return S;
}

}  // namespace ogive::cvode::block
