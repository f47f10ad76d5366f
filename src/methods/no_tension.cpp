#include "methods/no_tension.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

#include <Eigen/LU>
#include <fmt/format.h>

#include "methods/bvp.hpp"
#include "methods/cvode/cvode_integrator.hpp"
#include "methods/damped_newton.hpp"
#include "ogive/model/section.hpp"
#include "methods/shooting.hpp"

namespace ogive {
namespace {

constexpr int kStations = 513;  // the admissibility check's and the first guess' stations

// The system's Jacobian at state y (the linear A(theta) where the section is elastic).
SystemMatrix jacobian(const ArchModel& model, double c, double sn, const SectionStrain& ss) {
  const double aV = model.a_V();
  SystemMatrix J = SystemMatrix::Zero();
  J(kUx, kPsi) = -sn;
  J(kUx, kFx) = ss.eps_N * c * c + aV * sn * sn;
  J(kUx, kFy) = (ss.eps_N - aV) * c * sn;
  J(kUx, kM) = ss.eps_M * c;
  J(kUy, kPsi) = c;
  J(kUy, kFx) = (ss.eps_N - aV) * c * sn;
  J(kUy, kFy) = ss.eps_N * sn * sn + aV * c * c;
  J(kUy, kM) = ss.eps_M * sn;
  J(kPsi, kFx) = ss.kappa_N * c;
  J(kPsi, kFy) = ss.kappa_N * sn;
  J(kPsi, kM) = ss.kappa_M;
  J(kM, kFx) = sn;
  J(kM, kFy) = -c;
  return J;
}

// Column 0: the state, y' = f(s, y); columns 1..: its variations, dY' = J(s, y) dY. It counts its
// evaluations and refuses any beyond allow()'s limit (CVODE then gives up the integration within a few
// calls, as for an inadmissible state): what bounds a Newton trial's work and a solve's.
class NoTensionSystem final : public OdeSystem {
 public:
  explicit NoTensionSystem(const ArchModel& model)
      : model_(model), t_(model.scene().thickness / model.scales().length) {}
  std::int64_t calls() const { return calls_; }
  void allow(std::int64_t calls) { limit_ = calls; }
  bool rhs(double s, const Eigen::Ref<const OdeMatrix>& Y, Eigen::Ref<OdeMatrix> dY) const override {
    if (++calls_ > limit_) return false;
    const double th = model_.theta(s), c = std::cos(th), sn = std::sin(th);
    const auto y = Y.col(0);
    const double N = c * y[kFx] + sn * y[kFy], V = -sn * y[kFx] + c * y[kFy];
    const SectionStrain ss = section_strain(SectionKind::no_tension, N, y[kM], t_);
    if (!ss.admissible) return false;
    const double rot = model_.a_V() * V + y[kPsi];
    auto dy = dY.col(0);
    dy[kUx] = ss.eps * c - rot * sn;
    dy[kUy] = ss.eps * sn + rot * c;
    dy[kPsi] = ss.kappa;
    dy[kFx] = 0.0 - model_.horizontal_load(s);  // +0 without a horizontal load
    dy[kFy] = model_.load(s);
    dy[kM] = sn * y[kFx] - c * y[kFy];
    if (Y.cols() > 1) dY.rightCols(Y.cols() - 1).noalias() = jacobian(model_, c, sn, ss) * Y.rightCols(Y.cols() - 1);
    return true;
  }
  SystemMatrix jacobian_block(double s, const Eigen::Ref<const OdeMatrix>& Y) const override {
    const double th = model_.theta(s), c = std::cos(th), sn = std::sin(th);
    const double N = c * Y(kFx, 0) + sn * Y(kFy, 0);
    const SectionStrain ss = section_strain(SectionKind::no_tension, N, Y(kM, 0), t_);
    return ss.admissible ? jacobian(model_, c, sn, ss) : model_.system_matrix(th);
  }
  const std::vector<double>& breakpoints() const override { return model_.breakpoints(); }

 private:
  const ArchModel& model_;
  double t_;
  mutable std::int64_t calls_ = 0;
  std::int64_t limit_ = std::numeric_limits<std::int64_t>::max();
};

// The statics on a grid: with the springing forces (Fx0, Fy0, M0), Fx = Fx0 - H(s), Fy = Fy0 + B(s),
// M = M0 + Fx0 y(s) - Fy0 x(s) - C(s), B the vertical load up to s (point loads included), H the
// horizontal one (0 without a horizontal acceleration), C = int (c B + sn H) ds.
struct Statics {
  std::vector<double> c, sn, x, y, B, C, H;
  double t = 0;
  Statics(const ArchModel& model) : t(model.scene().thickness / model.scales().length) {
    const double S = model.length(), L = model.scales().length;
    const auto& jumps = model.jumps();
    std::size_t next_jump = 0;
    double B_prev = 0, C_prev = 0, s_prev = 0, c_prev = 0, H_prev = 0, sn_prev = 0;
    const bool horizontal = model.acceleration() != 0;
    for (int i = 0; i < kStations; ++i) {
      const double s = S * i / (kStations - 1);
      const CurvePoint p = model.curve().at(s * L);
      // Trapezoid in s for the distributed load, then the point loads passed.
      double Bi = i == 0 ? 0.0 : B_prev + 0.5 * (model.load(s_prev) + model.load(s)) * (s - s_prev);
      while (next_jump < jumps.size() && jumps[next_jump].s <= s) Bi += jumps[next_jump++].force;
      const double ci = std::cos(p.theta), sni = std::sin(p.theta);
      double Ci = i == 0 ? 0.0 : C_prev + 0.5 * (c_prev * B_prev + ci * Bi) * (s - s_prev);
      double Hi = 0;
      if (horizontal && i > 0) {
        Hi = H_prev + 0.5 * (model.horizontal_load(s_prev) + model.horizontal_load(s)) * (s - s_prev);
        Ci += 0.5 * (sn_prev * H_prev + sni * Hi) * (s - s_prev);
      }
      c.push_back(ci);
      sn.push_back(sni);
      H.push_back(Hi);
      x.push_back(p.x / L);
      y.push_back(p.y / L);
      B.push_back(Bi);
      C.push_back(Ci);
      B_prev = Bi, C_prev = Ci, s_prev = s, c_prev = ci, H_prev = Hi, sn_prev = sni;
    }
  }
  // The margin as a function of M0 alone at fixed (Fx, Fy0), the same number as margin(Fx, Fy0, M0):
  // the stations' P and their moments but M0 formed once, so that a search over M0 costs one
  // multiplication per station (the first guess' nested searches spend their time here).
  struct MomentMargin {
    bool tension = false;
    double tension_margin = 0;
    Eigen::ArrayXd moment, inverse;  // M - M0 and 1 / (P t / 2) at every station
    double operator()(double M0) const {
      if (tension) return tension_margin;
      return (1 - (moment + M0).abs() * inverse).minCoeff();  // (Eigen vectorises the minimum)
    }
  };
  MomentMargin moment_margin(double Fx, double Fy0) const {
    MomentMargin out;
    out.moment.resize(static_cast<Eigen::Index>(c.size()));
    out.inverse.resize(static_cast<Eigen::Index>(c.size()));
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double P = -(c[i] * (Fx - H[i]) + sn[i] * (Fy0 + B[i]));
      if (!(P > 0)) {  // under tension the margin does not depend on M0
        out.tension = true;
        out.tension_margin = margin(Fx, Fy0, 0.0);
        return out;
      }
      out.moment[static_cast<Eigen::Index>(i)] = Fx * y[i] - Fy0 * x[i] - C[i];
      out.inverse[static_cast<Eigen::Index>(i)] = 1 / (P * (t / 2));
    }
    return out;
  }
  // The smallest (t/2 - |M/N|) / (t/2) over the stations; where N >= 0, -10 + min(-N) / scale instead
  // (below every admissible value and increasing as the compression grows: a direction for the search).
  double margin(double Fx, double Fy0, double M0) const {
    double worst = std::numeric_limits<double>::infinity(), least_P = std::numeric_limits<double>::infinity();
    bool tension = false;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double Fy = Fy0 + B[i];
      const double P = -(c[i] * (Fx - H[i]) + sn[i] * Fy);
      least_P = std::min(least_P, P);
      if (!(P > 0)) {
        tension = true;
        continue;
      }
      const double M = M0 + Fx * y[i] - Fy0 * x[i] - C[i];
      worst = std::min(worst, 1 - std::abs(M) / P / (t / 2));
    }
    if (tension) return -10 + least_P / (1 + std::abs(B.back()));
    return worst;
  }
};

// The maximum of f over [a, b]: the best of `samples` equally spaced points, refined by golden section
// between its neighbours (the margin is not unimodal in general: a pointed crown makes it kink).
template <class F>
double scan_max(F&& f, double a, double b, int samples, int iterations = 40);

// Golden-section maximum of f over [a, b] (f quasi-concave): its argument.
template <class F>
double golden_max(F&& f, double a, double b, int iterations = 48) {
  const double r = 0.5 * (std::sqrt(5.0) - 1);
  double x1 = b - r * (b - a), x2 = a + r * (b - a), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < iterations; ++i) {
    if (f1 < f2) {
      a = x1, x1 = x2, f1 = f2, x2 = a + r * (b - a), f2 = f(x2);
    } else {
      b = x2, x2 = x1, f2 = f1, x1 = b - r * (b - a), f1 = f(x1);
    }
  }
  return f1 < f2 ? x2 : x1;
}

template <class F>
double scan_max(F&& f, double a, double b, int samples, int iterations) {
  double best = a, best_value = -std::numeric_limits<double>::infinity();
  const double h = (b - a) / (samples - 1);
  for (int i = 0; i < samples; ++i) {
    const double x = a + h * i, v = f(x);
    if (v > best_value) best = x, best_value = v;
  }
  return golden_max(f, std::max(a, best - h), std::min(b, best + h), iterations);
}

// One evaluation of the shooting residual and its Jacobian at the unknowns x.
struct Evaluation {
  bool ok = false;
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;
  std::vector<StateVector> starts;  // the state at each piece's start (after its point loads)
  StateVector y0, yS;
  std::optional<IntegrationError> failure;
  std::size_t failed_piece = 0;
};

// A Newton trial whose integration takes more than kTrialFactor times the right-hand sides of the
// costliest evaluation that succeeded (and more than kTrialFloor) is given up, as an inadmissible one
// is (Newton halves its step): such a trial creeps toward a section whose resultant reaches its face,
// where the curvature grows as 1 / u^2 and CVODE's steps shrink without end (measured: 200 000 steps,
// CVODE's limit, for trials beside accepted states that took 60 to 2 000). Near the solution the trials
// cost what the accepted states cost.
constexpr std::int64_t kTrialFactor = 4;
constexpr std::int64_t kTrialFloor = 5000;

class Shooter {
 public:
  Shooter(const ArchModel& model, const Options& options, int segments, std::int64_t budget)
      : model_(model), system_(model), split_(springing_split(model)), options_(options), budget_(budget) {
    knots_ = segments == 1 ? required_knots(model) : shooting_knots(model, segments, true);
    K_ = knots_.size() - 1;
    multiple_ = segments > 1 && K_ > 1;
    size_ = 3 + (multiple_ ? kStateSize * static_cast<int>(K_ - 1) : 0);
    const CvodeTolerances tol = cvode_tolerances(options);
    carried_.emplace(system_, options.integrator, tol.rtol, tol.atol, options.max_steps, 4, true);
    if (multiple_) fresh_.emplace(system_, options.integrator, tol.rtol, tol.atol, options.max_steps, kStateSize + 1, true);
  }
  int size() const { return size_; }
  const std::vector<double>& knots() const { return knots_; }
  IntegratorStats stats() const {
    IntegratorStats s = carried_->stats();
    if (fresh_) {
      s.steps += fresh_->stats().steps;
      s.rhs_evaluations += fresh_->stats().rhs_evaluations;
      s.error_test_failures += fresh_->stats().error_test_failures;
      s.jacobian_evaluations += fresh_->stats().jacobian_evaluations;
    }
    return s;
  }

  double jump_at(double s) const {
    double f = 0;
    for (const PointJump& j : model_.jumps())
      if (j.s == s) f += j.force;
    return f;
  }

  // The unknowns of a first guess: z from the springing state y0; with multiple shooting, every later
  // segment's start by integrating from it (false if that fails).
  bool unknowns_from(const StateVector& y0, Eigen::VectorXd& x) {
    x.resize(size_);
    x.head<3>() = split_.U.transpose() * y0;
    if (!multiple_) return true;
    Evaluation e = evaluate_single(x.head<3>());
    if (!e.ok) return false;
    for (std::size_t k = 1; k < K_; ++k) x.segment<kStateSize>(3 + kStateSize * static_cast<Eigen::Index>(k - 1)) = e.starts[k];
    return true;
  }

  // Whether the solve's budget of right-hand sides is spent.
  bool spent() const { return system_.calls() >= budget_; }

  Evaluation evaluate(const Eigen::VectorXd& x) {
    const std::int64_t before = system_.calls();
    const std::int64_t trial = succeeded_ > 0 ? std::max(kTrialFloor, kTrialFactor * succeeded_)
                                              : std::numeric_limits<std::int64_t>::max() - before;
    system_.allow(before + std::min(trial, std::max<std::int64_t>(budget_ - before, 0)));
    Evaluation e = multiple_ ? evaluate_multiple(x) : evaluate_single(x.head<3>());
    if (e.ok) succeeded_ = std::max(succeeded_, system_.calls() - before);
    return e; }

 private:
  // Integrates [y | dY] over piece k; false on failure (recorded in e).
  bool integrate(CvodeIntegrator& integrator, std::size_t k, OdeMatrix& Y, Evaluation& e) {
    const double end = knots_[k + 1];
    OdeMatrix out;
    e.failure = integrator.integrate(knots_[k], Y, std::span<const double>(&end, 1),
                                     [&](std::size_t, const CvodeIntegrator::Matrix& M) { out = M; });
    if (e.failure) {
      e.failed_piece = k;
      return false;
    }
    Y = out;
    Y(kFy, 0) += jump_at(end);
    return true;
  }

  Evaluation evaluate_single(const Eigen::Vector3d& z) {
    Evaluation e;
    OdeMatrix Y(kStateSize, 4);
    e.y0 = split_.start + split_.U * z;
    Y << e.y0, split_.U;
    Y(kFy, 0) += jump_at(0.0);
    for (std::size_t k = 0; k < K_; ++k) {
      e.starts.push_back(Y.col(0));
      if (!integrate(*carried_, k, Y, e)) return e;
    }
    finish(e, Y.col(0), Y.rightCols<3>(), 0);
    return e;
  }

  Evaluation evaluate_multiple(const Eigen::VectorXd& x) {
    Evaluation e;
    e.residual = Eigen::VectorXd::Zero(size_);
    e.jacobian = Eigen::MatrixXd::Zero(size_, size_);
    e.y0 = split_.start + split_.U * x.head<3>();
    OdeMatrix first(kStateSize, 4);
    first << e.y0, split_.U;
    first(kFy, 0) += jump_at(0.0);
    e.starts.push_back(first.col(0));
    if (!integrate(*carried_, 0, first, e)) return e;
    OdeMatrix end = first;
    auto column_of = [](std::size_t k) { return k == 0 ? Eigen::Index{0} : 3 + kStateSize * static_cast<Eigen::Index>(k - 1); };
    for (std::size_t k = 1; k < K_; ++k) {
      // Continuity at knot k: y_k - (end of piece k - 1) = 0.
      const Eigen::Index row = kStateSize * static_cast<Eigen::Index>(k - 1);
      const StateVector yk = x.segment<kStateSize>(column_of(k));
      e.residual.segment<kStateSize>(row) = yk - end.col(0);
      e.jacobian.block(row, column_of(k - 1), kStateSize, end.cols() - 1) = -end.rightCols(end.cols() - 1);
      e.jacobian.block<kStateSize, kStateSize>(row, column_of(k)).setIdentity();
      OdeMatrix Y(kStateSize, kStateSize + 1);
      Y << yk, SystemMatrix::Identity();
      e.starts.push_back(yk);
      if (!integrate(*fresh_, k, Y, e)) return e;
      end = Y;
    }
    finish(e, end.col(0), end.rightCols(end.cols() - 1), column_of(K_ - 1));
    return e;
  }

  // The end's three conditions and their derivatives (the last rows).
  void finish(Evaluation& e, const StateVector& yS, const Eigen::Ref<const OdeMatrix>& dY, Eigen::Index column) {
    const BoundaryConditions& bc = model_.boundary_conditions();
    const Eigen::Matrix<double, 3, kStateSize> B = bc.at_end.bottomRows<3>();
    if (e.residual.size() == 0) {
      e.residual = Eigen::VectorXd::Zero(size_);
      e.jacobian = Eigen::MatrixXd::Zero(size_, size_);
    }
    e.residual.tail<3>() = B * yS - bc.rhs.tail<3>();
    e.jacobian.block(size_ - 3, column, 3, dY.cols()) = B * dY;
    e.yS = yS;
    e.ok = true;
  }

  const ArchModel& model_;
  NoTensionSystem system_;
  SpringingSplit split_;
  Options options_;
  std::vector<double> knots_;
  std::size_t K_ = 1;
  bool multiple_ = false;
  int size_ = 3;
  std::optional<CvodeIntegrator> carried_, fresh_;
  std::int64_t budget_;
  std::int64_t succeeded_ = 0;  // the most right-hand sides an evaluation that succeeded took
};

// The field: integrates the solved state from the start of its piece (column 0 only); kept as CVODE's
// dense output when a summary will search it (Options::unprinted_profile).
class NoTensionField final : public PiecewiseField {
 public:
  NoTensionField(std::shared_ptr<const ArchModel> model, const Options& options, std::vector<double> knots,
                 std::vector<StateVector> starts)
      : PiecewiseField(std::move(knots), std::move(starts)), model_(std::move(model)), system_(*model_), options_(options), pieces_(options.unprinted_profile) {}

 protected:
  void propagate(double s_k, const StateVector& y_k, std::span<const double> s,
                 std::span<StateVector> out) const override {
    pieces_.sample(s_k, y_k, piece_end(s_k), s, out, [&] {
      const CvodeTolerances tol = cvode_tolerances(options_);
      return std::make_unique<CvodeIntegrator>(system_, options_.integrator, tol.rtol, tol.atol, options_.max_steps, 1,
                                               true);
    });
  }

 private:
  std::shared_ptr<const ArchModel> model_;
  NoTensionSystem system_;
  Options options_;
  FieldPieces pieces_;
};

}  // namespace

ShootingResidual no_tension_residual(const ArchModel& model, const Options& options, const StateVector& y0) {
  Shooter shooter(model, options, 1, kUnlimitedWork);
  Eigen::VectorXd x;
  ShootingResidual out;
  if (!shooter.unknowns_from(y0, x)) return out;
  const Evaluation e = shooter.evaluate(x);
  if (!e.ok) return out;
  out.ok = true;
  out.residual = e.residual;
  out.jacobian = e.jacobian;
  return out;
}

AdmissibleStart most_admissible_start(const ArchModel& model) {
  const Statics st(model);
  const SpringingSplit split = springing_split(model);
  const BoundaryConditions& bc = model.boundary_conditions();
  const bool M0_free = split.U.row(kM).any();
  // Over the half, Fy(S) = rhs fixes Fy0 = rhs - B(S); over the whole arch V_left is free.
  const bool Fy_fixed = model.half();
  const double Fy_half = bc.rhs(5) - st.B.back();
  const double W = std::max(std::abs(st.B.back()), 1e-300);
  const double t = st.t;
  auto best_M0 = [&](double Fx, double Fy0) {
    if (!M0_free) return 0.0;
    const double P0 = std::max(-(st.c[0] * Fx + st.sn[0] * Fy0), 0.0);
    const Statics::MomentMargin margin = st.moment_margin(Fx, Fy0);
    return scan_max(margin, -0.5 * t * P0, 0.5 * t * P0, 21);
  };
  auto best_Fy = [&](double Fx) {
    if (Fy_fixed) return Fy_half;
    return scan_max([&](double Fy0) { return st.margin(Fx, Fy0, best_M0(Fx, Fy0)); }, -W, 0.0, 11, 30);
  };
  // H over [0, 50 W] in a logarithmic scan (flat arches push hard, pointed ones little), then refined.
  auto margin_at_H = [&](double H) {
    const double Fy0 = best_Fy(-H);
    return st.margin(-H, Fy0, best_M0(-H, Fy0));
  };
  const double logH = scan_max([&](double q) { return margin_at_H(W * std::exp(q)); }, std::log(1e-3), std::log(50.0),
                               Fy_fixed ? 121 : 41);
  const double H = W * std::exp(logH);
  AdmissibleStart out;
  const double Fy0 = best_Fy(-H), M0 = best_M0(-H, Fy0);
  out.y0 = split.start;
  out.y0[kFx] = -H;
  out.y0[kFy] = Fy0;
  if (M0_free) out.y0[kM] = M0;
  out.margin = st.margin(-H, Fy0, M0);
  return out;
}

bool first_guess(const ArchModel& model, std::span<const StateVector> guesses,
                 const std::function<bool(const StateVector&)>& start, Solution& sol) {
  for (const StateVector& g : guesses)
    if (g.allFinite() && start(g)) return true;
  const AdmissibleStart a = most_admissible_start(model);
  if (!(a.margin > 0)) {
    sol.status = Status::inadmissible;
    sol.message = fmt::format("no state keeps the resultant inside every section (best margin {:.3g} of t/2): the "
                              "arch cannot stand without tension",
                              a.margin);
    return false;
  }
  if (start(a.y0)) return true;
  sol.status = Status::not_converged;
  sol.message = "the most admissible first guess could not be integrated";
  return false;
}

std::string work_budget_message(std::int64_t budget, Method method, bool scene) {
  return fmt::format("the {} budget of {} {} ran out", scene ? "scene's work" : "work", budget,
                     method == Method::quadrature ? "integrand evaluations" : "CVODE right-hand-side evaluations");
}

Solution solve_no_tension(std::shared_ptr<const ArchModel> model, const Options& options, int segments,
                          std::span<const StateVector> guesses, std::int64_t budget) {
  Solution sol;
  sol.method = segments == 1 ? Method::shooting : Method::multiple_shooting;
  sol.model = model;
  if (model->hinge()) {
    sol.status = Status::not_applicable;
    sol.message = "the no-tension section does not take a crown hinge over the whole arch";
    return sol;
  }
  Shooter shooter(*model, options, segments, budget);
  sol.diagnostics.segments = static_cast<int>(shooter.knots().size() - 1);
  auto count_work = [&] {
    const IntegratorStats s = shooter.stats();
    sol.diagnostics.steps = s.steps;
    sol.diagnostics.rhs_evaluations = s.rhs_evaluations;
    sol.diagnostics.error_test_failures = s.error_test_failures;
    sol.diagnostics.jacobian_evaluations = s.jacobian_evaluations;
  };
  // The first guess: the first admissible one given, or the most admissible state.
  const Statics statics(*model);
  Eigen::VectorXd x;
  Evaluation e;
  const bool started = first_guess(*model, guesses, [&](const StateVector& y0) {
    if (statics.margin(y0[kFx], y0[kFy], y0[kM]) <= 0 || !shooter.unknowns_from(y0, x)) return false;
    e = shooter.evaluate(x);
    return e.ok;
  }, sol);
  if (!started) {
    count_work();
    if (sol.status == Status::not_converged && shooter.spent()) sol.message = work_budget_message(budget, sol.method);
    return sol;
  }
  // Converged when Newton's full step changes no unknown by more than rtol / 100 of its size: beside
  // the integration's own error, which the residual cannot fall below, Newton's is then negligible. At
  // the integration's noise: CVODE's tolerance on the end's displacements and rotation.
  const double noise = 10 * cvode_tolerances(options).rtol;
  const bool converged = damped_newton(
      [&](const Eigen::VectorXd& trial) { return shooter.evaluate(trial); },
      [&](const Evaluation& at) {
        const double kinematics = std::max({1.0, std::abs(at.yS[kUx]), std::abs(at.yS[kUy]), std::abs(at.yS[kPsi])});
        return at.residual.lpNorm<Eigen::Infinity>() <= noise * kinematics;
      },
      1e-2 * options.rtol, x, e, sol);
  count_work();
  if (!converged) {
    if (shooter.spent()) sol.message = work_budget_message(budget, sol.method);
    return sol;
  }
  BvpSolution bvp;
  bvp.y0 = e.y0;
  bvp.yS = e.yS;
  bvp.knots = shooter.knots();
  bvp.starts = e.starts;
  // The condition of Newton's last matrix (the linearised problem's), Skeel's measure as the linear
  // model's: for single shooting it is the same 3 x 3 matrix in the springing's unknowns.
  {
    const Eigen::MatrixXd& J = e.jacobian;
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(J);
    bvp.condition = lu.isInvertible() ? (lu.inverse().cwiseAbs() * J.cwiseAbs()).rowwise().sum().maxCoeff()
                                      : std::numeric_limits<double>::infinity();
  }
  finish_solution(sol, bvp, std::make_shared<NoTensionField>(model, options, bvp.knots, bvp.starts));
  return sol;
}

}  // namespace ogive
