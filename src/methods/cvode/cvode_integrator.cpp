#include "methods/cvode/cvode_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>

#include <cvode/cvode.h>
#include <fmt/format.h>

#include "methods/cvode/block_linear_solver.hpp"
#include "methods/cvode/fixed_point_solver.hpp"
#include "methods/cvode/sundials_support.hpp"
#include "methods/cvode/vector_kernels.hpp"

namespace ogive {

using cvode::check;
using cvode::ContextHandle;
using cvode::CvodeHandle;
using cvode::LinearSolverHandle;
using cvode::MatrixHandle;
using cvode::NonlinearSolverHandle;
using cvode::VectorHandle;
using cvode::flag_name;
namespace vector = cvode::vector;
namespace fixed_point = cvode::fixed_point;
namespace block = cvode::block;

// The SUNDIALS objects of one kind of integration (method and number of columns): a context, the
// template vector, the solvers and the CVODE memory. Creating them costs as much as a short
// integration, so they are kept per thread and reused (CVodeReInit at every span, tolerances and user
// data set anew at every use): across the segments of multiple shooting, the verifying solve, the
// profile's sampling and the scenes of a sweep. One context per thread, as SUNDIALS asks.
struct Workspace {
  Integrator kind;
  std::vector<int> blocks;  // columns of each independent problem (CvodeIntegrator's blocks)
  // Destroyed in reverse order: CVODE's memory before the solvers and vectors it uses, the context last.
  ContextHandle context;
  VectorHandle y;
  MatrixHandle jacobian;
  LinearSolverHandle linear_solver;
  NonlinearSolverHandle nonlinear_solver;
  CvodeHandle cvode;
};

namespace {

// rhs and jac reach the current use's model through CVODE's user data (CvodeIntegrator::Impl).
std::unique_ptr<Workspace> make_workspace(Integrator kind, const std::vector<int>& blocks, CVRhsFn rhs,
                                          CVLsJacFn jac) {
  auto w = std::make_unique<Workspace>();
  w->kind = kind;
  w->blocks = blocks;
  SUNContext ctx = nullptr;
  check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
  w->context.reset(ctx);
  auto block_ends = std::make_shared<std::vector<sunindextype>>();
  sunindextype end = 0;
  for (const int columns : blocks) block_ends->push_back(end += static_cast<sunindextype>(kStateSize) * columns);
  w->y.reset(vector::make(std::move(block_ends), ctx));
  if (!w->y) throw std::runtime_error("N_VNewEmpty failed");
  w->cvode.reset(CVodeCreate(kind == Integrator::adams ? CV_ADAMS : CV_BDF, ctx));
  if (!w->cvode) throw std::runtime_error("CVodeCreate failed");
  void* mem = w->cvode.get();
  check(CVodeInit(mem, rhs, 0.0, w->y.get()), "CVodeInit");
  if (kind == Integrator::adams) {
    w->nonlinear_solver.reset(fixed_point::make(w->y.get(), ctx));
    if (!w->nonlinear_solver) throw std::runtime_error("SUNNonlinSolNewEmpty failed");
    check(CVodeSetNonlinearSolver(mem, w->nonlinear_solver.get()), "CVodeSetNonlinearSolver");
  } else {
    w->jacobian.reset(block::make_matrix(ctx));
    if (!w->jacobian) throw std::runtime_error("SUNMatNewEmpty failed");
    w->linear_solver.reset(block::make_solver(ctx));
    if (!w->linear_solver) throw std::runtime_error("SUNLinSolNewEmpty failed");
    check(CVodeSetLinearSolver(mem, w->linear_solver.get(), w->jacobian.get()), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, jac), "CVodeSetJacFn");
  }
  return w;
}

// The idle workspaces of this thread. At most a few kinds are ever in use at once (multiple shooting's
// 4- and 7-column integrators, the field's 1 column), so the pool stays small.
std::vector<std::unique_ptr<Workspace>>& idle_workspaces() {
  thread_local std::vector<std::unique_ptr<Workspace>> pool;
  return pool;
}

std::unique_ptr<Workspace> take_workspace(Integrator kind, const std::vector<int>& blocks, CVRhsFn rhs,
                                          CVLsJacFn jac) {
  auto& pool = idle_workspaces();
  for (auto it = pool.begin(); it != pool.end(); ++it)
    if ((*it)->kind == kind && (*it)->blocks == blocks) {
      std::unique_ptr<Workspace> w = std::move(*it);
      pool.erase(it);
      return w;
    }
  return make_workspace(kind, blocks, rhs, jac);
}

void return_workspace(std::unique_ptr<Workspace> w) {
  auto& pool = idle_workspaces();
  constexpr std::size_t kMaxIdle = 8;
  if (w && pool.size() < kMaxIdle) pool.push_back(std::move(w));
}

}  // namespace

struct CvodeIntegrator::Impl {
  const OdeSystem& system;
  int columns;
  bool restart;
  std::string last_message;  // CVODE's error text, captured instead of printed
  std::unique_ptr<Workspace> workspace;
  double span_start = 0, span_end = 0;  // the span being integrated
  double first_inside = 0, last_inside = 0;  // the numbers next to its ends, inside it
  double rtol = 0, atol = 0;  // CVODE's, as given (atol > 0)
  std::int64_t max_steps = 0;  // CVODE's step limit between outputs; integrate_dense's per span
  vector::ErrorWeights error_weights = nullptr;  // the kernel for the workspace's vector, chosen once

  Impl(const OdeSystem& s, int cols, bool restart_at_breakpoints)
      : system(s), columns(cols), restart(restart_at_breakpoints) {}

  // s moved strictly inside the current span: at a breakpoint the system must see the piece being
  // integrated (a pointed crown's angle, a live load's edge), and CVODE evaluates at the span's ends.
  double inside(double s) const {
    if (!restart || !(span_end > span_start)) return s;
    return std::clamp(s, first_inside, last_inside);
  }

  // CVODE's error weights (CVodeWFtolerances: SUNDIALS' hook for a weight function), the same numbers
  // as its own for scalar tolerances, at a fraction of the cost (vector::error_weights).
  static int weights(N_Vector y, N_Vector w, void* user_data) {
    const auto* self = static_cast<const Impl*>(user_data);
    return self->error_weights(self->rtol, self->atol, y, w) ? 0 : -1;
  }

  static int rhs(sunrealtype s, N_Vector y, N_Vector ydot, void* user_data) {
    const auto* self = static_cast<const Impl*>(user_data);
    const int n = self->columns;
    Eigen::Map<const Matrix> Y(N_VGetArrayPointer(y), kStateSize, n);
    Eigen::Map<Matrix> dY(N_VGetArrayPointer(ydot), kStateSize, n);
    return self->system.rhs(self->inside(s), Y, dY) ? 0 : 1;  // 1: recoverable, CVODE tries a smaller step
  }

  // The Jacobian's one block (the block matrix type above stores only that).
  static int jac(sunrealtype s, N_Vector y, N_Vector, SUNMatrix J, void* user_data, N_Vector, N_Vector,
                 N_Vector) {
    const auto* self = static_cast<const Impl*>(user_data);
    Eigen::Map<const Matrix> Y(N_VGetArrayPointer(y), kStateSize, self->columns);
    block::of(J) = self->system.jacobian_block(self->inside(s), Y);
    return 0;
  }

  // CVODE restarted at a, to stop at b, from the state in the workspace's vector.
  void start_span(double a, double b) {
    span_start = a;
    span_end = b;
    first_inside = std::nextafter(a, b);
    last_inside = std::nextafter(b, a);
    void* mem = workspace->cvode.get();
    check(CVodeReInit(mem, a, workspace->y.get()), "CVodeReInit");
    check(CVodeSetStopTime(mem, b), "CVodeSetStopTime");
  }

  // The spans of an integration from s0 to end: s0, the breakpoints strictly inside (s0, end) unless
  // steps may straddle them, end. Each span is integrated afresh.
  std::vector<double> span_knots(double s0, double end) const {
    std::vector<double> knots{s0};
    if (restart)
      for (double b : system.breakpoints())
        if (b > s0 && b < end) knots.push_back(b);
    knots.push_back(end);
    return knots;
  }

  // CVODE's failure `flag`, with the arc length it had reached and its own message.
  IntegrationError failure(int flag) const {
    sunrealtype reached = span_start;
    check(CVodeGetCurrentTime(workspace->cvode.get(), &reached), "CVodeGetCurrentTime");
    return IntegrationError{flag, flag_name(flag), reached, last_message};
  }

  // The span's counters into `stats` (they restart with every CVodeReInit: collected span by span).
  void count_span(IntegratorStats& stats) const {
    void* mem = workspace->cvode.get();
    long steps = 0, rhs = 0, etf = 0, jacs = 0, ncf = 0;
    check(CVodeGetNumSteps(mem, &steps), "CVodeGetNumSteps");
    check(CVodeGetNumRhsEvals(mem, &rhs), "CVodeGetNumRhsEvals");
    check(CVodeGetNumErrTestFails(mem, &etf), "CVodeGetNumErrTestFails");
    check(CVodeGetNumNonlinSolvConvFails(mem, &ncf), "CVodeGetNumNonlinSolvConvFails");
    if (workspace->jacobian) check(CVodeGetNumJacEvals(mem, &jacs), "CVodeGetNumJacEvals");
    stats.steps += steps;
    stats.rhs_evaluations += rhs;
    stats.error_test_failures += etf;
    stats.jacobian_evaluations += jacs;
    stats.convergence_failures += ncf;
  }

  static void error_handler(int, const char*, const char* function, char* msg, void* data) {
    static_cast<Impl*>(data)->last_message = std::string(function) + ": " + msg;
  }
};

CvodeIntegrator::CvodeIntegrator(const OdeSystem& system, Integrator kind, double rtol, double atol,
                                 std::int64_t max_steps, int columns, bool restart_at_breakpoints)
    : CvodeIntegrator(system, kind, rtol, atol, max_steps, std::vector<int>{columns}, restart_at_breakpoints) {}

CvodeIntegrator::CvodeIntegrator(const OdeSystem& system, Integrator kind, double rtol, double atol,
                                 std::int64_t max_steps, const std::vector<int>& blocks,
                                 bool restart_at_breakpoints)
    : impl_(std::make_unique<Impl>(system, std::accumulate(blocks.begin(), blocks.end(), 0),
                                   restart_at_breakpoints)) {
  if (!(rtol > 0) || !(atol > 0))
    throw std::invalid_argument("CvodeIntegrator: rtol and atol must be > 0");
  Impl& m = *impl_;
  m.workspace = take_workspace(kind, blocks, &Impl::rhs, &Impl::jac);
  void* mem = m.workspace->cvode.get();
  // Everything a previous use set is set anew: the error handler's and the functions' data, the
  // tolerances, the step limit (the stop time and the history are set by every span's CVodeReInit).
  check(CVodeSetErrHandlerFn(mem, &Impl::error_handler, impl_.get()), "CVodeSetErrHandlerFn");
  check(CVodeSetUserData(mem, impl_.get()), "CVodeSetUserData");
  m.rtol = rtol;
  m.atol = atol;
  m.error_weights = vector::error_weights_for(m.workspace->y.get());
  check(CVodeWFtolerances(mem, &Impl::weights), "CVodeWFtolerances");
  m.max_steps = max_steps;
  check(CVodeSetMaxNumSteps(mem, static_cast<long>(max_steps)), "CVodeSetMaxNumSteps");
}

CvodeIntegrator::~CvodeIntegrator() {
  if (impl_ && impl_->workspace) return_workspace(std::move(impl_->workspace));
}

namespace {

// Whether t lies too close to t0 for CVODE to take a step to it: CVODE returns CV_TOO_CLOSE when
// |t - t0| < 2 uround max(|t0|, |t|); a margin of 2 on that.
bool too_close_to_step(double t0, double t) {
  return std::abs(t - t0) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t0), std::abs(t));
}

}  // namespace

std::optional<IntegrationError> CvodeIntegrator::integrate(double s0, const Matrix& Y0,
                                                           std::span<const double> s_out,
                                                           const Observer& observer) {
  Impl& m = *impl_;
  Workspace& w = *m.workspace;
  void* mem = w.cvode.get();
  const int n = m.columns;
  Eigen::Map<Matrix> Y(N_VGetArrayPointer(w.y.get()), kStateSize, n);
  Y = Y0;
  Matrix current = Y0;
  if (s_out.empty()) return std::nullopt;
  const double s_end = s_out.back();
  const std::vector<double> knots = m.span_knots(s0, s_end);

  std::size_t next = 0;
  while (next < s_out.size() && s_out[next] <= s0) observer(next++, current);
  for (std::size_t k = 0; k + 1 < knots.size() && next < s_out.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    if (b <= a) continue;
    Y = current;
    m.start_span(a, b);
    std::optional<IntegrationError> failure;
    double reached = a;
    // One CVode call to tout (task CV_NORMAL or CV_ONE_STEP); a failure is recorded with the arc length
    // CVODE had reached.
    auto call = [&](double tout, int task, sunrealtype& t) {
      const int flag = CVode(mem, tout, w.y.get(), &t, task);
      if (flag < 0) {
        failure = m.failure(flag);
        return false;
      }
      return true;
    };
    auto advance = [&](double tout) {
      sunrealtype t = a;
      if (!call(tout, CV_NORMAL, t)) return false;
      reached = t;
      current = Y;
      return true;
    };
    // An output within a few ulps of the span's start (a station that rounds just past a segment's knot
    // or a breakpoint) is the start's state: CVODE refuses a tout that close (CV_TOO_CLOSE, within 2
    // round-offs of t0), and the state cannot change by more than round-off over that distance.
    while (next < s_out.size() && s_out[next] <= b && too_close_to_step(a, s_out[next])) observer(next++, current);
    // The first step toward the span's end, whatever the outputs: CVODE sizes its first step from the
    // distance to the first tout, so a first output nearer the start would change every later step, and a
    // profile's numbers with the number of stations asked (the printed profile would not be the one its
    // error was estimated on). The outputs behind that step are interpolated, as all others.
    if (next < s_out.size() && !too_close_to_step(a, b)) {
      sunrealtype t = a;
      call(b, CV_ONE_STEP, t);
    }
    while (!failure && next < s_out.size() && s_out[next] <= b) {
      if (!advance(s_out[next])) break;
      observer(next++, current);
    }
    // No output left in this span: run to the breakpoint so that the next span starts there (a span too
    // short to step, an output just past a breakpoint, carries its start's state).
    if (!failure && reached < b && !too_close_to_step(reached, b)) advance(b);
    m.count_span(stats_);
    if (failure) return failure;
  }
  return std::nullopt;
}

std::optional<IntegrationError> CvodeIntegrator::integrate_dense(double s0, const StateVector& y0, double end,
                                                                 DenseTrajectory& out) {
  Impl& m = *impl_;
  if (m.columns != 1) throw std::logic_error("CvodeIntegrator::integrate_dense integrates one state");
  Workspace& w = *m.workspace;
  void* mem = w.cvode.get();
  Eigen::Map<Matrix> Y(N_VGetArrayPointer(w.y.get()), kStateSize, 1);
  out = DenseTrajectory{};
  out.end_ = end;
  // The spans and the first step of each as integrate() takes them, so that every step, and with it the
  // polynomial an output there would be interpolated from, is the same.
  const std::vector<double> knots = m.span_knots(s0, end);
  StateVector current = y0;
  VectorHandle dky(N_VClone(w.y.get()));
  if (!dky) throw std::runtime_error("N_VClone failed");
  Eigen::Map<const Matrix> D(N_VGetArrayPointer(dky.get()), kStateSize, 1);
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    const double a = knots[k], b = knots[k + 1];
    out.spans_.push_back({a, current, out.steps_.size()});
    if (!(b > a) || too_close_to_step(a, b)) continue;  // no step: the span's end keeps its start's state
    Y = current;
    m.start_span(a, b);
    std::optional<IntegrationError> failure;
    sunrealtype t = a;
    for (std::int64_t taken = 0;; ++taken) {
      // CVODE counts its step limit per call, and here every call is one step: the limit is the span's.
      if (taken == m.max_steps) {
        failure = IntegrationError{CV_TOO_MUCH_WORK, flag_name(CV_TOO_MUCH_WORK), t,
                                   fmt::format("{} steps taken before reaching the span's end", m.max_steps)};
        break;
      }
      const int flag = CVode(mem, b, w.y.get(), &t, CV_ONE_STEP);
      if (flag < 0) {
        failure = m.failure(flag);
        break;
      }
      // The step just taken: its polynomial y(s) = sum_j z_j ((s - s_n) / h)^j, z_j = h^j y^(j)(s_n) / j!
      // (CVODE's Nordsieck array), valid over [s_n - h, s_n].
      DenseTrajectory::Step step;
      int order = 0;
      check(CVodeGetCurrentTime(mem, &step.s_end), "CVodeGetCurrentTime");
      check(CVodeGetLastStep(mem, &step.h), "CVodeGetLastStep");
      check(CVodeGetLastOrder(mem, &order), "CVodeGetLastOrder");
      step.order = order;
      step.first = out.coefficients_.size();
      double scale = 1;  // h^j / j!
      for (int j = 0; j <= order; ++j) {
        if (j > 0) scale *= step.h / j;
        check(CVodeGetDky(mem, step.s_end, j, dky.get()), "CVodeGetDky");
        out.coefficients_.push_back(j == 0 ? StateVector(D.col(0)) : StateVector(scale * D.col(0)));
      }
      out.steps_.push_back(step);
      if (flag == CV_TSTOP_RETURN || !(t < b) || too_close_to_step(t, b)) break;
    }
    m.count_span(stats_);
    if (failure) {
      out.failed_ = true;
      return failure;
    }
    current = Y.col(0);  // at b: CVODE's state at its stop time
  }
  return std::nullopt;
}

StateVector DenseTrajectory::at(double s) const {
  if (failed_ || spans_.empty()) return StateVector::Constant(std::numeric_limits<double>::quiet_NaN());
  s = std::min(s, end_);
  // The span that holds s: the last one starting before it (a station at a breakpoint belongs to the
  // span that ends there).
  auto span = std::lower_bound(spans_.begin(), spans_.end(), s, [](const Span& x, double v) { return x.start < v; });
  if (span == spans_.begin()) return spans_.front().y_start;  // at or before the piece's start
  --span;
  const std::size_t first = span->first_step;
  const std::size_t last = span + 1 == spans_.end() ? steps_.size() : (span + 1)->first_step;
  if (too_close_to_step(span->start, s) || first == last) return span->y_start;
  // The first step of the span that ends at or after s (the last one for s just past the span's end).
  auto step = std::lower_bound(steps_.begin() + static_cast<std::ptrdiff_t>(first),
                               steps_.begin() + static_cast<std::ptrdiff_t>(last), s,
                               [](const Step& x, double v) { return x.s_end < v; });
  if (step == steps_.begin() + static_cast<std::ptrdiff_t>(last)) --step;
  // CVodeGetDky's sum: the highest power first, each power by repeated products.
  const double x = (s - step->s_end) / step->h;
  StateVector y = StateVector::Zero();
  for (int j = step->order; j >= 0; --j) {
    double c = 1;
    for (int i = 0; i < j; ++i) c *= x;
    y += c * coefficients_[step->first + static_cast<std::size_t>(j)];
  }
  return y;
}

void FieldPieces::sample(double s_k, const StateVector& y_k, double end, std::span<const double> s,
                         std::span<StateVector> out, const MakeIntegrator& make) const {
  if (!keep_) {
    const std::unique_ptr<CvodeIntegrator> integrator = make();
    std::vector<double> outputs(s.begin(), s.end());
    if (outputs.empty() || end > outputs.back()) outputs.push_back(end);
    const auto failure = integrator->integrate(s_k, y_k, outputs, [&](std::size_t n, const CvodeIntegrator::Matrix& Y) {
      if (n < out.size()) out[n] = Y.col(0);
    });
    if (failure)
      for (StateVector& y : out) y.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  std::shared_ptr<const DenseTrajectory> piece;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    auto& slot = pieces_[s_k];
    if (!slot) {
      auto made = std::make_shared<DenseTrajectory>();
      make()->integrate_dense(s_k, y_k, end, *made);
      slot = std::move(made);
    }
    piece = slot;
  }
  for (std::size_t i = 0; i < s.size() && i < out.size(); ++i) out[i] = piece->at(s[i]);
}

}  // namespace ogive
