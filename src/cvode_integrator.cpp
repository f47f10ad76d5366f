#include "cvode_integrator.hpp"

#include <algorithm>
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

  Impl(const ArchModel& m, int cols, std::int64_t steps)
      : model(m), columns(cols), max_steps(steps), breakpoints(m.breakpoints()) {}

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
                                 std::int64_t max_steps, int columns)
    : impl_(std::make_unique<Impl>(model, columns, max_steps)) {
  Impl& m = *impl_;
  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
  m.context.reset(ctx);
  const sunindextype n = static_cast<sunindextype>(kStateSize) * columns;
  m.y.reset(N_VNew_Serial(n, ctx));
  if (!m.y) throw std::runtime_error("N_VNew_Serial failed");
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
    while (next < s_out.size() && s_out[next] <= b) {
      sunrealtype t = a;
      const int flag = CVode(mem, s_out[next], m.y.get(), &t, CV_NORMAL);
      if (flag < 0) {
        sunrealtype t_now = a;
        CVodeGetCurrentTime(mem, &t_now);
        failure = IntegrationError{flag, flag_name(flag), t_now, m.last_message};
        break;
      }
      reached = t;
      current = Y;
      observer(next++, current);
    }
    if (!failure && reached < b) {
      // No output left in this span: run to the breakpoint so that the next span starts there.
      sunrealtype t = a;
      const int flag = CVode(mem, b, m.y.get(), &t, CV_NORMAL);
      if (flag < 0) {
        sunrealtype t_now = a;
        CVodeGetCurrentTime(mem, &t_now);
        failure = IntegrationError{flag, flag_name(flag), t_now, m.last_message};
      }
      current = Y;
    }
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
