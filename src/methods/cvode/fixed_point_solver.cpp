#include "methods/cvode/fixed_point_solver.hpp"

#include "methods/cvode/vector_kernels.hpp"

namespace ogive::cvode::fixed_point {
namespace {

struct Content {
  SUNNonlinSolSysFn system = nullptr;
  SUNNonlinSolConvTestFn test = nullptr;
  void* test_data = nullptr;
  int max_iterations = 3;  // CVODE sets its own (NLS_MAXCOR) when the solver is attached
  int iteration = 0;       // within the current solve
  long iterations = 0, convergence_failures = 0;  // of the last solve (CVODE adds them up)
  N_Vector g = nullptr, delta = nullptr;
  vector::FixedPointUpdate update = nullptr;
};

Content& content(SUNNonlinearSolver s) { return *static_cast<Content*>(s->content); }

SUNNonlinearSolver_Type get_type(SUNNonlinearSolver) { return SUNNONLINEARSOLVER_FIXEDPOINT; }
int initialize(SUNNonlinearSolver s) {
  content(s).iterations = content(s).convergence_failures = 0;
  return content(s).system && content(s).test ? SUN_NLS_SUCCESS : SUN_NLS_MEM_NULL;
}
int solve(SUNNonlinearSolver s, N_Vector, N_Vector y, N_Vector w, sunrealtype tol, sunbooleantype, void* mem) {
  Content& c = content(s);
  c.iterations = c.convergence_failures = 0;
  for (c.iteration = 0; c.iteration < c.max_iterations; ++c.iteration) {
    if (const int flag = c.system(y, c.g, mem); flag != 0) return flag;
    c.update(c.g, y, c.delta);
    ++c.iterations;
    const int flag = c.test(s, y, c.delta, tol, w, c.test_data);
    if (flag == SUN_NLS_SUCCESS) return SUN_NLS_SUCCESS;
    if (flag != SUN_NLS_CONTINUE) {
      ++c.convergence_failures;
      return flag;
    }
  }
  ++c.convergence_failures;
  return SUN_NLS_CONV_RECVR;
}
int free_solver(SUNNonlinearSolver s) {
  if (!s) return SUN_NLS_SUCCESS;
  if (s->content) {
    N_VDestroy(content(s).g);
    N_VDestroy(content(s).delta);
    delete static_cast<Content*>(s->content);
    s->content = nullptr;
  }
  SUNNonlinSolFreeEmpty(s);
  return SUN_NLS_SUCCESS;
}
int set_system(SUNNonlinearSolver s, SUNNonlinSolSysFn f) {
  content(s).system = f;
  return SUN_NLS_SUCCESS;
}
int set_test(SUNNonlinearSolver s, SUNNonlinSolConvTestFn f, void* data) {
  content(s).test = f;
  content(s).test_data = data;
  return SUN_NLS_SUCCESS;
}
int set_max_iterations(SUNNonlinearSolver s, int n) {
  if (n < 1) return SUN_NLS_ILL_INPUT;
  content(s).max_iterations = n;
  return SUN_NLS_SUCCESS;
}
int get_iterations(SUNNonlinearSolver s, long* n) {
  *n = content(s).iterations;
  return SUN_NLS_SUCCESS;
}
int get_iteration(SUNNonlinearSolver s, int* n) {
  *n = content(s).iteration;
  return SUN_NLS_SUCCESS;
}
int get_convergence_failures(SUNNonlinearSolver s, long* n) {
  *n = content(s).convergence_failures;
  return SUN_NLS_SUCCESS;
}

}  // namespace

SUNNonlinearSolver make(N_Vector y, SUNContext ctx) {
  SUNNonlinearSolver s = SUNNonlinSolNewEmpty(ctx);
  if (!s) return nullptr;
  s->ops->gettype = get_type;
  s->ops->initialize = initialize;
  s->ops->solve = solve;
  s->ops->free = free_solver;
  s->ops->setsysfn = set_system;
  s->ops->setctestfn = set_test;
  s->ops->setmaxiters = set_max_iterations;
  s->ops->getnumiters = get_iterations;
  s->ops->getcuriter = get_iteration;
  s->ops->getnumconvfails = get_convergence_failures;
  auto* c = new Content;
  s->content = c;
  c->g = N_VClone(y);
  c->delta = N_VClone(y);
  c->update = vector::fixed_point_update_for(y);
  if (!c->g || !c->delta) {
    free_solver(s);
    return nullptr;
  }
  return s;
}

}  // namespace ogive::cvode::fixed_point
