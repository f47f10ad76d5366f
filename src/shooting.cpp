#include "ogive/shooting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
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

// The shooting solution's field: integrates the solved state from the nearest segment start.
class ShootingField final : public StateField {
 public:
  ShootingField(std::shared_ptr<const ArchModel> model, const Options& options, std::vector<double> knots,
                std::vector<StateVector> starts)
      : model_(std::move(model)), options_(options), knots_(std::move(knots)), starts_(std::move(starts)) {}

  void sample(std::span<const double> s, std::span<StateVector> out) const override {
    const CvodeTolerances tol = cvode_tolerances(options_);
    CvodeIntegrator integrator(*model_, options_.integrator, tol.rtol, tol.atol, options_.max_steps, 1,
                               options_.restart_at_breakpoints);
    std::size_t i = 0;
    for (std::size_t k = 0; k < starts_.size() && i < s.size(); ++k) {
      const bool last = k + 1 == starts_.size();
      std::size_t j = i;
      while (j < s.size() && (last || s[j] < knots_[k + 1])) ++j;
      if (j == i) continue;
      const auto failure = integrator.integrate(
          knots_[k], starts_[k], s.subspan(i, j - i),
          [&](std::size_t n, const CvodeIntegrator::Matrix& Y) { out[i + n] = Y.col(0); });
      if (failure)  // Marked, never plausible: the caller sees non-finite states.
        for (std::size_t n = i; n < j; ++n) out[n].setConstant(std::numeric_limits<double>::quiet_NaN());
      i = j;
    }
  }

 private:
  std::shared_ptr<const ArchModel> model_;
  Options options_;
  std::vector<double> knots_;
  std::vector<StateVector> starts_;
};

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
  const double S = model.half_length();
  std::vector<double> knots;
  for (int k = 0; k <= segments; ++k) knots.push_back(S * k / segments);
  knots.back() = S;
  if (segments > 1 && at_breakpoints)
    for (double b : model.breakpoints()) knots.push_back(b);
  std::sort(knots.begin(), knots.end());
  // Merge knots closer than a part in 1e9 of the half arch: a breakpoint on a uniform knot.
  knots.erase(std::unique(knots.begin(), knots.end(), [S](double a, double b) { return b - a < 1e-9 * S; }),
              knots.end());
  knots.back() = S;
  return knots;
}

Solution solve_shooting(std::shared_ptr<const ArchModel> model, const Options& options, int segments) {
  Solution sol;
  sol.method = segments == 1 ? Method::shooting : Method::multiple_shooting;
  sol.model = model;
  const std::vector<double> knots = shooting_knots(*model, segments, options.restart_at_breakpoints);
  const std::size_t K = knots.size() - 1;
  sol.diagnostics.segments = static_cast<int>(K);

  const CvodeTolerances tol = cvode_tolerances(options);
  // The first segment starts at the springing, where three components are given: it integrates the
  // three unknown directions and the particular solution (4 columns). Later segments start from a full
  // unknown state (the fundamental matrix and the particular solution: 7 columns).
  const SpringingSplit split = springing_split(*model);
  CvodeIntegrator first(*model, options.integrator, tol.rtol, tol.atol, options.max_steps, 4,
                        options.restart_at_breakpoints);
  std::optional<CvodeIntegrator> rest;
  if (K > 1)
    rest.emplace(*model, options.integrator, tol.rtol, tol.atol, options.max_steps, kStateSize + 1,
                 options.restart_at_breakpoints);
  // Segment k maps its unknown start x_k (u for k = 0, y_k after) to its end: G[k] x_k + g[k].
  std::vector<Eigen::Matrix<double, kStateSize, Eigen::Dynamic>> G(K);
  std::vector<StateVector> g(K);
  for (std::size_t k = 0; k < K; ++k) {
    CvodeIntegrator::Matrix Y0(kStateSize, k == 0 ? 4 : kStateSize + 1);
    if (k == 0) Y0 << split.U, split.start;
    else Y0 << SystemMatrix::Identity(), StateVector::Zero();
    const double end = knots[k + 1];
    CvodeIntegrator& integrator = k == 0 ? first : *rest;
    const auto failure = integrator.integrate(knots[k], Y0, std::span<const double>(&end, 1),
                                              [&](std::size_t, const CvodeIntegrator::Matrix& Y) {
                                                G[k] = Y.leftCols(Y.cols() - 1);
                                                g[k] = Y.col(Y.cols() - 1);
                                              });
    if (failure) {
      sol.status = Status::integrator_failure;
      sol.message = failure_message(*failure, *model, k, K);
      break;
    }
  }
  for (const CvodeIntegrator* integrator : {&first, rest ? &*rest : nullptr}) {
    if (!integrator) continue;
    const IntegratorStats& st = integrator->stats();
    sol.diagnostics.steps += st.steps;
    sol.diagnostics.rhs_evaluations += st.rhs_evaluations;
    sol.diagnostics.error_test_failures += st.error_test_failures;
    sol.diagnostics.jacobian_evaluations += st.jacobian_evaluations;
  }
  if (sol.status == Status::integrator_failure) return sol;

  if (K == 1) {
    const BvpSolution bvp = solve_reduced(*model, G[0], g[0]);
    finish_solution(sol, bvp, std::make_shared<ShootingField>(model, options, knots, std::vector{bvp.y0}));
    return sol;
  }

  // Unknowns: u (3), then the start state of every later segment (6 each). Rows: 6 continuity rows per
  // interior knot, 3 crown conditions; block-bidiagonal, so the LU has little fill.
  const BoundaryConditions bc = model->boundary_conditions();
  auto column_of = [](std::size_t k) { return k == 0 ? Eigen::Index{0} : 3 + kStateSize * static_cast<Eigen::Index>(k - 1); };
  const Eigen::Index n = 3 + kStateSize * static_cast<Eigen::Index>(K - 1);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k + 1 < K; ++k) {
    const Eigen::Index row = kStateSize * static_cast<Eigen::Index>(k);
    for (int i = 0; i < kStateSize; ++i) {
      for (Eigen::Index j = 0; j < G[k].cols(); ++j)
        if (G[k](i, j) != 0) entries.emplace_back(row + i, column_of(k) + j, G[k](i, j));
      entries.emplace_back(row + i, column_of(k + 1) + i, -1.0);
      rhs(row + i) = -g[k](i);
    }
  }
  const Eigen::Matrix<double, 3, kStateSize> crown = bc.at_crown.bottomRows<3>() * G[K - 1];
  const Eigen::Vector3d crown_rhs = bc.rhs.tail<3>() - bc.at_crown.bottomRows<3>() * g[K - 1];
  for (int r = 0; r < 3; ++r) {
    for (int j = 0; j < kStateSize; ++j)
      if (crown(r, j) != 0) entries.emplace_back(n - 3 + r, column_of(K - 1) + j, crown(r, j));
    rhs(n - 3 + r) = crown_rhs(r);
  }
  Eigen::SparseMatrix<double> Q(n, n);
  Q.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(Q);
  BvpSolution bvp;
  std::vector<StateVector> starts(K);
  if (lu.info() == Eigen::Success) {
    const Eigen::VectorXd z = lu.solve(rhs);
    starts[0] = split.start + split.U * z.head<3>();
    for (std::size_t k = 1; k < K; ++k) starts[k] = z.segment<kStateSize>(column_of(k));
    bvp.y0 = starts.front();
    bvp.yS = G[K - 1] * starts.back() + g[K - 1];
    // The condition of the boundary-value problem, not of this discretisation of it: the sparse
    // system's own condition grows with the number of segments (its identity blocks), while its
    // solution's accuracy does not. So the segments' transfers are condensed into Phi(S) U and judged
    // by the same function as single shooting and the closed form.
    ReducedTransfer whole = G[0];
    for (std::size_t k = 1; k < K; ++k) whole = G[k] * whole;
    bvp.condition = boundary_value_condition(*model, whole);
  }
  finish_solution(sol, bvp, std::make_shared<ShootingField>(model, options, knots, std::move(starts)));
  return sol;
}

}  // namespace ogive
