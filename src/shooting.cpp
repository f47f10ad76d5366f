#include "ogive/shooting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "bvp.hpp"
#include "cvode_integrator.hpp"

namespace ogive {
namespace {

std::string failure_message(const IntegrationError& e, const ArchModel& model, std::size_t segment,
                            std::size_t segments) {
  std::string text = fmt::format("CVODE {} at s = {:.6g} m (shooting segment {} of {})", e.flag_name,
                                 e.s * model.scales().length, segment + 1, segments);
  if (!e.detail.empty()) text += ": " + e.detail;
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

// ArchModel's problem as the integrator's system: Y' = A(theta(s)) Y + b(s) e_Fy e_last^T (the load
// rides on the last column: the particular solution, or the one state of a field's integration).
class ArchSystem final : public OdeSystem {
 public:
  explicit ArchSystem(const ArchModel& model) : model_(model) {}
  bool rhs(double s, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const override {
    const SystemMatrix A = model_.system_matrix(model_.theta(s));
    dY.noalias() = A * Y;
    dY(kFy, Y.cols() - 1) += model_.load(s);
    return true;
  }
  SystemMatrix jacobian_block(double s, const Eigen::Ref<const OdeMatrix>&) const override {
    return model_.system_matrix(model_.theta(s));
  }
  const std::vector<double>& breakpoints() const override { return model_.breakpoints(); }

 private:
  const ArchModel& model_;
};

// The shooting solution's field: integrates the solved state from the start of its piece.
class ShootingField final : public PiecewiseField {
 public:
  ShootingField(std::shared_ptr<const ArchModel> model, const Options& options, std::vector<double> knots,
                std::vector<StateVector> starts)
      : PiecewiseField(std::move(knots), std::move(starts)), model_(std::move(model)), system_(*model_),
        options_(options) {}

 protected:
  void propagate(double s_k, const StateVector& y_k, std::span<const double> s,
                 std::span<StateVector> out) const override {
    const CvodeTolerances tol = cvode_tolerances(options_);
    CvodeIntegrator integrator(system_, options_.integrator, tol.rtol, tol.atol, options_.max_steps, 1,
                               options_.restart_at_breakpoints);
    const auto failure = integrator.integrate(s_k, y_k, s, [&](std::size_t n, const CvodeIntegrator::Matrix& Y) {
      out[n] = Y.col(0);
    });
    if (failure)  // Marked, never plausible: the caller sees non-finite states.
      for (StateVector& y : out) y.setConstant(std::numeric_limits<double>::quiet_NaN());
  }

 private:
  std::shared_ptr<const ArchModel> model_;
  ArchSystem system_;
  Options options_;
};

// A later segment of multiple shooting integrates the columns of unit psi, Fx, Fy, M and the load's.
constexpr int kIntegratedColumns = 5;
constexpr std::array<int, 4> kIntegratedStarts = {kPsi, kFx, kFy, kM};

}  // namespace

CvodeTolerances cvode_tolerances(const Options& o) {
  const double factor = o.integrator == Integrator::adams ? 0.1 : 0.001;
  CvodeTolerances t;
  t.rtol = std::max(o.rtol * factor, kCvodeRtolFloor);
  // The scaled state is of order one; components that pass through zero would otherwise be held to an
  // absolute error of order rtol, which the measured errors showed to dominate. Hence a low floor.
  t.atol = o.atol > 0 ? o.atol : t.rtol * 1e-6;
  return t;
}

std::vector<double> shooting_knots(const ArchModel& model, int segments, bool at_breakpoints) {
  const double S = model.length();
  std::vector<double> extra;
  if (segments > 1) {
    for (int k = 1; k < segments; ++k) extra.push_back(S * k / segments);
    if (at_breakpoints) extra.insert(extra.end(), model.breakpoints().begin(), model.breakpoints().end());
  }
  return merge_knots(model, extra);
}

Solution solve_shooting(std::shared_ptr<const ArchModel> model, const Options& options, int segments) {
  Solution sol;
  sol.method = segments == 1 ? Method::shooting : Method::multiple_shooting;
  sol.model = model;
  const std::vector<double> knots = shooting_knots(*model, segments, options.restart_at_breakpoints);
  const std::size_t K = knots.size() - 1;
  sol.diagnostics.segments = static_cast<int>(K);

  const CvodeTolerances tol = cvode_tolerances(options);
  const ArchSystem system(*model);
  // Single shooting carries the state's affine map [T | c] from the springing to the end: its m unknown
  // directions and the particular solution (4 columns; 5 with a hinge, whose column is 0 before it),
  // across point loads and the hinge (march adds them between pieces). Multiple shooting integrates that
  // only over its first segment; every later one starts afresh, so that no integration error grows over
  // more than one segment, and its transfer y(b) = Phi y(a) + p is applied to the map. Of Phi's six
  // columns those of unit psi, Fx, Fy and M are integrated, with p (5 columns, not 7): a unit Ux or Uy
  // at the segment's start stays a unit Ux or Uy exactly (nothing depends on the displacements). (The
  // rigid rotation's column from the curve's positions, 4 columns, was 6 % faster still but left the
  // slender parabola's verified error estimate 2x higher: 1.9e-9 against 2.4e-10 at rtol 1e-9.)
  const int m = unknown_count(*model);
  CvodeIntegrator carried(system, options.integrator, tol.rtol, tol.atol, options.max_steps, m + 1,
                          options.restart_at_breakpoints);
  std::optional<CvodeIntegrator> fresh;
  if (segments > 1 && K > 1)
    fresh.emplace(system, options.integrator, tol.rtol, tol.atol, options.max_steps, kIntegratedColumns,
                  options.restart_at_breakpoints);
  std::optional<IntegrationError> failure;
  std::size_t failed_piece = 0;
  auto integrate = [&](CvodeIntegrator& integrator, std::size_t k, const OdeMatrix& Y0, OdeMatrix& Y1) {
    const double end = knots[k + 1];
    failure = integrator.integrate(knots[k], Y0, std::span<const double>(&end, 1),
                                   [&](std::size_t, const CvodeIntegrator::Matrix& Y) { Y1 = Y; });
    failed_piece = k;
    return !failure;
  };
  March marched;
  const bool ok = march(*model, knots,
                        [&](std::size_t k, AffineState& Y) {
                          if (!fresh || k == 0) {
                            OdeMatrix end;
                            if (!integrate(carried, k, OdeMatrix(Y), end)) return false;
                            Y = end;
                            return true;
                          }
                          OdeMatrix start = OdeMatrix::Zero(kStateSize, kIntegratedColumns);
                          for (int j = 0; j < 4; ++j) start(kIntegratedStarts[j], j) = 1.0;
                          OdeMatrix G;
                          if (!integrate(*fresh, k, start, G)) return false;
                          SystemMatrix Phi = SystemMatrix::Identity();
                          for (int j = 0; j < 4; ++j) Phi.col(kIntegratedStarts[j]) = G.col(j);
                          const AffineState next = Phi.lazyProduct(Y);
                          Y = next;
                          Y.col(Y.cols() - 1) += G.col(4);
                          return true;
                        },
                        marched);
  for (const CvodeIntegrator* integrator : {&carried, fresh ? &*fresh : nullptr}) {
    if (!integrator) continue;
    const IntegratorStats& st = integrator->stats();
    sol.diagnostics.steps += st.steps;
    sol.diagnostics.rhs_evaluations += st.rhs_evaluations;
    sol.diagnostics.error_test_failures += st.error_test_failures;
    sol.diagnostics.jacobian_evaluations += st.jacobian_evaluations;
  }
  if (!ok) {
    sol.status = Status::integrator_failure;
    sol.message = failure ? failure_message(*failure, *model, failed_piece, K) : "integration failed";
    return sol;
  }
  // The condition of the boundary-value problem, not of a discretisation of it: the equations in the
  // unknowns are condensed through every segment's transfer, and judged by the same function as the
  // closed form's.
  BvpSolution bvp = solve_march(*model, std::move(marched));
  auto field = std::make_shared<ShootingField>(model, options, std::move(bvp.knots), std::move(bvp.starts));
  finish_solution(sol, bvp, std::move(field));
  return sol;
}

}  // namespace ogive
