// CVODE wrapper (private header): the files of src/methods/cvode/ are the only ones that include CVODE;
// this header exposes none of its types. Every SUNDIALS object is owned by RAII handles; every return
// flag is checked, getters included. The wrapper's modules: vector_kernels (ogive's N_Vector),
// fixed_point_solver (Adams' iteration), block_linear_solver (BDF's Newton matrix and its solver) and
// cvode_integrator (the integrator and its per-thread workspaces).
//
// It integrates a system handed to it (Boost.Odeint's way: the integrator owns no model), whose state is
// a 6 x columns matrix Y: for ogive's linear problem Y' = A(s) Y + b(s) e_last^T, the columns of a
// shooting map or transfer (shooting.hpp), or one state (columns = 1); for the no-tension section a
// state and its variations. One CVODE instance is taken per integrator from a per-thread pool and
// re-initialised for every span, never rebuilt.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "ogive/core/solution.hpp"

namespace ogive {

struct IntegratorStats {
  std::int64_t steps = 0, rhs_evaluations = 0, error_test_failures = 0, jacobian_evaluations = 0;
  // Steps whose nonlinear iteration (fixed-point or Newton) failed to converge: CVODE retried them with
  // a smaller step.
  std::int64_t convergence_failures = 0;
};

struct IntegrationError {
  int flag = 0;           // CVODE's return flag
  std::string flag_name;  // e.g. "CV_TOO_MUCH_WORK"
  double s = 0;           // scaled arc length where CVODE stopped
  std::string detail;     // CVODE's own message, if it gave one
};

using OdeMatrix = Eigen::Matrix<double, kStateSize, Eigen::Dynamic>;

// The system: Y' = f(s, Y) and its Jacobian. The columns of Y are alike (a state and its variations, or
// the columns of a fundamental matrix), so the Jacobian is block diagonal with one 6 x 6 block for all
// columns; BDF's linear solver factors that block once. The integrator evaluates the system strictly
// inside the span it integrates (never at a breakpoint itself), so that on either side of a breakpoint
// the system sees the piece being integrated.
class OdeSystem {
 public:
  virtual ~OdeSystem() = default;
  // false: Y lies outside the system's domain (a no-tension section whose resultant left it): CVODE
  // retries a smaller step, and reports CV_REPTD_RHSFUNC_ERR or CV_RHSFUNC_FAIL if it cannot.
  virtual bool rhs(double s, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const = 0;
  virtual SystemMatrix jacobian_block(double s, const Eigen::Ref<const OdeMatrix>& Y) const = 0;
  // Interior points where f is not smooth, ascending: integration restarts there.
  virtual const std::vector<double>& breakpoints() const = 0;
};

// One state's trajectory over a piece as CVODE integrated it (CvodeIntegrator::integrate_dense): for
// every step its end s_n, its size h and order q and its interpolating polynomial (CVODE's Nordsieck
// array, from CVodeGetDky), so that the state anywhere in the piece is CVODE's own interpolant there, as
// an integration to that output would give it (its steps do not depend on the outputs), to round-off,
// with no second integration.
class DenseTrajectory {
 public:
  // The state at s in [start, end] of the piece (clamped to it): s within a few ulps of a span's start
  // (the piece's start or a breakpoint after which CVODE restarted) takes that start's state, as
  // integrate() gives it. Non-finite after a failed integration: never a plausible number.
  StateVector at(double s) const;
  bool failed() const { return failed_; }

 private:
  friend class CvodeIntegrator;
  struct Span {
    double start;
    StateVector y_start;
    std::size_t first_step;  // index of its first step in steps_
  };
  struct Step {
    double s_end, h;
    int order;
    std::size_t first;  // its coefficients z_0 .. z_q (y = sum z_j ((s - s_end) / h)^j) from coefficients_[first]
  };
  std::vector<Span> spans_;
  std::vector<Step> steps_;
  std::vector<StateVector> coefficients_;
  double end_ = 0;
  bool failed_ = false;
};

class CvodeIntegrator {
 public:
  using Matrix = OdeMatrix;
  // Receives output index i and Y at s_out[i].
  using Observer = std::function<void(std::size_t, const Matrix&)>;

  // Adams uses the fixed-point (functional) iteration, SUNDIALS' plain one re-implemented with fused
  // vector loops (the same numbers): the system is not stiff. BDF uses Newton with the analytic
  // Jacobian, block diagonal with A(theta) in every column's block, and a linear solver that factors
  // that one 6x6 block. Vectors are ogive's own N_Vector type, with kernels compiled for the lengths of
  // 1 to 5 columns. rtol and atol must be > 0 (std::invalid_argument); CVODE's error weights are its
  // scalar-tolerance ones, 1 / (rtol |y_i| + atol): atol applies to every scaled component. restart_at_breakpoints = false lets steps straddle the
  // curve's jumps of curvature (for studies only). Throws std::runtime_error if SUNDIALS cannot allocate.
  // The system must outlive the integrator.
  CvodeIntegrator(const OdeSystem& system, Integrator kind, double rtol, double atol, std::int64_t max_steps,
                  int columns, bool restart_at_breakpoints = true);
  // A state of several independent problems side by side, blocks[k] columns each (multiple shooting's
  // segments integrated together): CVODE's weighted RMS norm, in its error test and its iteration's
  // convergence test, is the largest of the blocks' own, so each problem is held to rtol and atol as if
  // integrated alone. The columns are sum(blocks).
  CvodeIntegrator(const OdeSystem& system, Integrator kind, double rtol, double atol, std::int64_t max_steps,
                  const std::vector<int>& blocks, bool restart_at_breakpoints = true);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // From Y0 at s0 through the ascending outputs s_out (each >= s0), restarting at the system's
  // breakpoints that lie in between (unless told not to) so that no step straddles a jump of curvature.
  std::optional<IntegrationError> integrate(double s0, const Matrix& Y0, std::span<const double> s_out,
                                            const Observer& observer);

  // One state (an integrator of 1 column) from y0 at s0 to end, restarting at the breakpoints as
  // integrate() does and with the same steps (the first sized toward each span's end), every step's
  // interpolating polynomial kept in `out`.
  std::optional<IntegrationError> integrate_dense(double s0, const StateVector& y0, double end, DenseTrajectory& out);

  // Accumulated over every integrate() and integrate_dense() call.
  const IntegratorStats& stats() const { return stats_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  IntegratorStats stats_;
};

// A field's pieces integrated by CVODE, each from its start state to its end (CVODE sizes its steps
// toward the end of the span it is given, so every state is the same whichever others are asked: a
// printed profile is the one whose error was estimated at other stations). Without `keep`, every request
// integrates the piece through the states asked (a profile's stations: nothing kept); with it, each
// piece is integrated once, on first use, and kept as CVODE's dense output (DenseTrajectory), for a
// field searched point by point (a thrust-line summary's refinement), which would otherwise integrate
// the piece again for every point. Both take the same steps: their states agree to round-off (an ulp),
// and a field uses one or the other for all its states. Non-finite states, never plausible ones, where
// the integration fails. Thread-safe.
class FieldPieces {
 public:
  using MakeIntegrator = std::function<std::unique_ptr<CvodeIntegrator>()>;
  explicit FieldPieces(bool keep) : keep_(keep) {}
  // The states at the ascending s (inside the piece that starts at s_k with y_k and ends at end), by an
  // integrator of one column that `make` builds when the piece must be integrated.
  void sample(double s_k, const StateVector& y_k, double end, std::span<const double> s, std::span<StateVector> out,
              const MakeIntegrator& make) const;

 private:
  bool keep_;
  mutable std::mutex mutex_;
  mutable std::map<double, std::shared_ptr<const DenseTrajectory>> pieces_;
};


}  // namespace ogive
