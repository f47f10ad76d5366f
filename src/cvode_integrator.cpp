#include "cvode_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

namespace ogive {
namespace {

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

std::string flag_name(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // malloc'd by SUNDIALS
  std::string out = name ? name : "CV_UNKNOWN";
  std::free(name);
  return out;
}

// Setup calls cannot fail for valid arguments; if one does, it is a programming error.
void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string(call) + " failed: " + flag_name(flag));
}


// Vector kernels. Debian's libsundials (6.4.1+dfsg1-3) is compiled without optimisation, and for the
// short vectors here (42 entries) CVODE's time went mostly into its serial N_Vector loops (callgrind:
// over half of all instructions). CVODE clones every work vector from the one given to CVodeInit,
// and a clone copies the ops table, so replacing the table's entries on that one vector makes every
// vector CVODE uses run these loops, compiled with the project's flags. Same arithmetic, same order.
namespace kernels {

sunrealtype* data(N_Vector v) { return NV_DATA_S(v); }
sunindextype size(N_Vector v) { return NV_LENGTH_S(v); }

void linear_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
}
void constant(sunrealtype c, N_Vector z) {
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(z); i < n; ++i) zd[i] = c;
}
void prod(N_Vector x, N_Vector y, N_Vector z) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = xd[i] * yd[i];
}
void div(N_Vector x, N_Vector y, N_Vector z) {
  const sunrealtype *xd = data(x), *yd = data(y);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = xd[i] / yd[i];
}
void scale(sunrealtype c, N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = c * xd[i];
}
void abs(N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = std::abs(xd[i]);
}
void inv(N_Vector x, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = 1.0 / xd[i];
}
void add_const(N_Vector x, sunrealtype b, N_Vector z) {
  const sunrealtype* xd = data(x);
  sunrealtype* zd = data(z);
  for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = xd[i] + b;
}
sunrealtype max_norm(N_Vector x) {
  const sunrealtype* xd = data(x);
  sunrealtype m = 0;
  for (sunindextype i = 0, n = size(x); i < n; ++i) m = std::max(m, std::abs(xd[i]));
  return m;
}
sunrealtype wsqr_sum(N_Vector x, N_Vector w) {
  const sunrealtype *xd = data(x), *wd = data(w);
  sunrealtype sum = 0;
  for (sunindextype i = 0, n = size(x); i < n; ++i) sum += (xd[i] * wd[i]) * (xd[i] * wd[i]);
  return sum;
}
sunrealtype wrms_norm(N_Vector x, N_Vector w) { return std::sqrt(wsqr_sum(x, w) / size(x)); }
int linear_combination(int nvec, sunrealtype* c, N_Vector* X, N_Vector z) {
  sunrealtype* zd = data(z);
  const sunindextype n = size(z);
  // z may alias X[0]; scaling it first, then accumulating, handles both cases.
  const sunrealtype* x0 = data(X[0]);
  for (sunindextype i = 0; i < n; ++i) zd[i] = c[0] * x0[i];
  for (int k = 1; k < nvec; ++k) {
    const sunrealtype* xk = data(X[k]);
    for (sunindextype i = 0; i < n; ++i) zd[i] += c[k] * xk[i];
  }
  return 0;
}
int scale_add_multi(int nvec, sunrealtype* a, N_Vector x, N_Vector* Y, N_Vector* Z) {
  const sunrealtype* xd = data(x);
  const sunindextype n = size(x);
  for (int k = 0; k < nvec; ++k) {
    const sunrealtype* yd = data(Y[k]);
    sunrealtype* zd = data(Z[k]);
    for (sunindextype i = 0; i < n; ++i) zd[i] = a[k] * xd[i] + yd[i];
  }
  return 0;
}

void install(N_Vector v) {
  N_Vector_Ops ops = v->ops;
  ops->nvlinearsum = linear_sum;
  ops->nvconst = constant;
  ops->nvprod = prod;
  ops->nvdiv = div;
  ops->nvscale = scale;
  ops->nvabs = abs;
  ops->nvinv = inv;
  ops->nvaddconst = add_const;
  ops->nvmaxnorm = max_norm;
  ops->nvwrmsnorm = wrms_norm;
  ops->nvwsqrsumlocal = wsqr_sum;
  ops->nvlinearcombination = linear_combination;
  ops->nvscaleaddmulti = scale_add_multi;
}

}  // namespace kernels

}  // namespace

struct CvodeIntegrator::Impl {
  const ArchModel& model;
  int columns;
  std::int64_t max_steps;
  std::vector<double> breakpoints;
  std::string last_message;  // CVODE's error text, captured instead of printed
  ContextHandle context;
  VectorHandle y;
  MatrixHandle jacobian;
  LinearSolverHandle linear_solver;
  NonlinearSolverHandle nonlinear_solver;
  CvodeHandle cvode;
  bool initialised = false;

  Impl(const ArchModel& m, int cols, std::int64_t steps, bool restart)
      : model(m), columns(cols), max_steps(steps), breakpoints(restart ? m.breakpoints() : std::vector<double>{}) {}

  static int rhs(sunrealtype s, N_Vector y, N_Vector ydot, void* user_data) {
    const auto* self = static_cast<const Impl*>(user_data);
    const SystemMatrix A = self->model.system_matrix(self->model.theta(s));
    const int n = self->columns;
    Eigen::Map<const Matrix> Y(N_VGetArrayPointer(y), kStateSize, n);
    Eigen::Map<Matrix> dY(N_VGetArrayPointer(ydot), kStateSize, n);
    dY.noalias() = A * Y;
    dY(kFy, n - 1) += 1.0;  // the self-weight load rides on the last column
    return 0;
  }

  static int jac(sunrealtype s, N_Vector, N_Vector, SUNMatrix J, void* user_data, N_Vector, N_Vector,
                 N_Vector) {
    const auto* self = static_cast<const Impl*>(user_data);
    const SystemMatrix A = self->model.system_matrix(self->model.theta(s));
    SUNMatZero(J);
    for (int c = 0; c < self->columns; ++c)
      for (int j = 0; j < kStateSize; ++j)
        for (int i = 0; i < kStateSize; ++i)
          if (A(i, j) != 0.0) SM_ELEMENT_D(J, c * kStateSize + i, c * kStateSize + j) = A(i, j);
    return 0;
  }

  static void error_handler(int, const char*, const char* function, char* msg, void* data) {
    static_cast<Impl*>(data)->last_message = std::string(function) + ": " + msg;
  }
};

CvodeIntegrator::CvodeIntegrator(const ArchModel& model, Integrator kind, double rtol, double atol,
                                 std::int64_t max_steps, int columns, bool restart_at_breakpoints)
    : impl_(std::make_unique<Impl>(model, columns, max_steps, restart_at_breakpoints)) {
  Impl& m = *impl_;
  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
  m.context.reset(ctx);
  const sunindextype n = static_cast<sunindextype>(kStateSize) * columns;
  m.y.reset(N_VNew_Serial(n, ctx));
  if (!m.y) throw std::runtime_error("N_VNew_Serial failed");
  kernels::install(m.y.get());
  N_VConst(0.0, m.y.get());
  m.cvode.reset(CVodeCreate(kind == Integrator::adams ? CV_ADAMS : CV_BDF, ctx));
  if (!m.cvode) throw std::runtime_error("CVodeCreate failed");
  void* mem = m.cvode.get();
  check(CVodeSetErrHandlerFn(mem, &Impl::error_handler, impl_.get()), "CVodeSetErrHandlerFn");
  check(CVodeInit(mem, &Impl::rhs, 0.0, m.y.get()), "CVodeInit");
  check(CVodeSStolerances(mem, rtol, atol), "CVodeSStolerances");
  check(CVodeSetUserData(mem, impl_.get()), "CVodeSetUserData");
  check(CVodeSetMaxNumSteps(mem, static_cast<long>(max_steps)), "CVodeSetMaxNumSteps");
  if (kind == Integrator::adams) {
    m.nonlinear_solver.reset(SUNNonlinSol_FixedPoint(m.y.get(), 0, ctx));
    if (!m.nonlinear_solver) throw std::runtime_error("SUNNonlinSol_FixedPoint failed");
    check(CVodeSetNonlinearSolver(mem, m.nonlinear_solver.get()), "CVodeSetNonlinearSolver");
  } else {
    m.jacobian.reset(SUNDenseMatrix(n, n, ctx));
    if (!m.jacobian) throw std::runtime_error("SUNDenseMatrix failed");
    m.linear_solver.reset(SUNLinSol_Dense(m.y.get(), m.jacobian.get(), ctx));
    if (!m.linear_solver) throw std::runtime_error("SUNLinSol_Dense failed");
    check(CVodeSetLinearSolver(mem, m.linear_solver.get(), m.jacobian.get()), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, &Impl::jac), "CVodeSetJacFn");
  }
}

CvodeIntegrator::~CvodeIntegrator() = default;

std::optional<IntegrationError> CvodeIntegrator::integrate(double s0, const Matrix& Y0,
                                                           std::span<const double> s_out,
                                                           const Observer& observer) {
  Impl& m = *impl_;
  void* mem = m.cvode.get();
  const int n = m.columns;
  Eigen::Map<Matrix> Y(N_VGetArrayPointer(m.y.get()), kStateSize, n);
  Y = Y0;
  Matrix current = Y0;
  if (s_out.empty()) return std::nullopt;
  const double s_end = s_out.back();
  // Knots: s0, the breakpoints strictly inside (s0, s_end), s_end. Each span is integrated afresh.
  std::vector<double> knots{s0};
  for (double b : m.breakpoints)
    if (b > s0 && b < s_end) knots.push_back(b);
  knots.push_back(s_end);

  std::size_t next = 0;
  while (next < s_out.size() && s_out[next] <= s0) observer(next++, current);
  for (std::size_t k = 0; k + 1 < knots.size() && next < s_out.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    if (b <= a) continue;
    Y = current;
    check(CVodeReInit(mem, a, m.y.get()), "CVodeReInit");
    check(CVodeSetStopTime(mem, b), "CVodeSetStopTime");
    std::optional<IntegrationError> failure;
    double reached = a;
    // One CVode call to tout; a failure is recorded with the arc length CVODE had reached.
    auto advance = [&](double tout) {
      sunrealtype t = a;
      const int flag = CVode(mem, tout, m.y.get(), &t, CV_NORMAL);
      if (flag < 0) {
        sunrealtype t_now = a;
        CVodeGetCurrentTime(mem, &t_now);
        failure = IntegrationError{flag, flag_name(flag), t_now, m.last_message};
        return false;
      }
      reached = t;
      current = Y;
      return true;
    };
    while (next < s_out.size() && s_out[next] <= b) {
      if (!advance(s_out[next])) break;
      observer(next++, current);
    }
    // No output left in this span: run to the breakpoint so that the next span starts there.
    if (!failure && reached < b) advance(b);
    // Counters restart with every CVodeReInit: collect them span by span.
    long steps = 0, rhs = 0, etf = 0, jacs = 0;
    CVodeGetNumSteps(mem, &steps);
    CVodeGetNumRhsEvals(mem, &rhs);
    CVodeGetNumErrTestFails(mem, &etf);
    if (m.jacobian) CVodeGetNumJacEvals(mem, &jacs);
    stats_.steps += steps;
    stats_.rhs_evaluations += rhs;
    stats_.error_test_failures += etf;
    stats_.jacobian_evaluations += jacs;
    if (failure) return failure;
  }
  return std::nullopt;
}

}  // namespace ogive
