#include "ogive/quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "bvp.hpp"
#include "chebyshev.hpp"

namespace ogive {
namespace {

// The force method's unknowns are the springing's forces: the state is y(s) = Y(s) [Fx0, Fy0, M0, 1], the
// last column carrying the load (Fy' = 1) and the given springing displacement Ux0 = -d (Uy0 = psi0 = 0).
constexpr int kColumns = 4;
constexpr int kLoad = 3;
constexpr std::array<int, 3> kUnknowns = {kFx, kFy, kM};
using Columns = Eigen::Matrix<double, kStateSize, kColumns>;
using NodeColumns = Eigen::Matrix<double, Eigen::Dynamic, kColumns>;  // one component at every node

// A panel of the half arch and its nodes x_i in [-1, 1]. The nodes are Chebyshev points either in the
// arc length s or, where the curve has a parameter t of its own in which s is explicit (the parabola, the
// ellipse, the surveys' splines: Curve::parameter_knots), in t: no inversion of s(t) at any node.
// Integrals in s become integrals in x with the Jacobian ds/dx.
struct Panel {
  double a = 0, b = 0;    // scaled arc lengths at the ends
  double pa = 0, pb = 0;  // the nodes' variable at the ends: scaled s, or t
  bool in_parameter = false;
  // At the current degree's nodes: cos theta, sin theta, s - a (scaled) and ds/dx (scaled).
  std::vector<double> cos, sin, ds, jacobian;
};

// The states at every node of every panel (kStateSize x (degree + 1) per panel).
using NodeStates = std::vector<Eigen::MatrixXd>;

class QuadratureField final : public StateField {
 public:
  QuadratureField(std::shared_ptr<const ArchModel> model, const std::vector<Panel>& panels, int degree,
                  NodeStates states)
      : model_(std::move(model)), rule_(chebyshev_rule(degree)), states_(std::move(states)) {
    for (const Panel& p : panels) ends_.push_back({p.a, p.b, p.pa, p.pb, p.in_parameter});
  }
  void sample(std::span<const double> s, std::span<StateVector> out) const override {
    const double L = model_->scales().length;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const auto after =
          std::upper_bound(ends_.begin(), ends_.end(), s[i], [](double v, const Ends& e) { return v < e.a; });
      const std::size_t k = after == ends_.begin() ? 0 : static_cast<std::size_t>(after - ends_.begin()) - 1;
      const Ends& e = ends_[k];
      const double p =
          e.in_parameter ? model_->scene().curve->parameter_at(std::clamp(s[i], e.a, e.b) * L) : s[i];
      const double x = std::clamp((2 * p - e.pa - e.pb) / (e.pb - e.pa), -1.0, 1.0);
      out[i] = chebyshev_interpolate(rule_, states_[k], x);
    }
  }

 private:
  struct Ends {
    double a, b, pa, pb;
    bool in_parameter;
  };
  std::shared_ptr<const ArchModel> model_;
  std::vector<Ends> ends_;
  const ChebyshevRule& rule_;
  NodeStates states_;
};

// The cumulative integral in s of every column of X from the panel's start, at every node: Q (ds/dx X),
// column by column: for these sizes (9 to 257 nodes, 3 columns) a matrix-vector product per column,
// vectorised along Q's columns, beats both a blocked GEMM (packing) and a lazy product (strided).
template <class Matrix>
Matrix cumulative(const Eigen::MatrixXd& Q, const Eigen::Ref<const Eigen::VectorXd>& jacobian, const Matrix& X) {
  const Matrix scaled = jacobian.asDiagonal() * X;
  Matrix out(X.rows(), X.cols());
  for (Eigen::Index j = 0; j < X.cols(); ++j) out.col(j).noalias() = Q * scaled.col(j);
  return out;
}

// The columns on one panel: Fx, Fy, M and psi at every node; for Ux and Uy only their integrands at the
// nodes (the values at the nodes are needed only for the solved state: two integrals, not eight).
struct PanelColumns {
  std::array<NodeColumns, kStateSize> node;  // node[kUx], node[kUy]: d/ds of Ux, Uy
  Columns end;                               // the columns at the panel's end
};

// The force method's nested integrals from the columns Y at the panel's start, in the order each needs
// the one before: Fx, Fy, then M, psi, then Ux, Uy. Every column's M' = sn Fx - c Fy is a combination of
// the same three functions sn, c and c (s - a) (Fx constant, Fy = Fy(a) + load (s - a)), so M and psi
// take three cumulative integrals each, whatever the number of columns.
PanelColumns integrate_panel(const ArchModel& model, const Panel& panel, const ChebyshevRule& rule,
                             const Columns& Y) {
  const int n = rule.degree + 1;
  const Eigen::MatrixXd& Q = rule.integration;
  const double* c = panel.cos.data();
  const double* sn = panel.sin.data();
  const double* ds = panel.ds.data();
  const Eigen::Map<const Eigen::VectorXd> J(panel.jacobian.data(), n);
  Eigen::Matrix<double, Eigen::Dynamic, 3> basis(n, 3);
  for (int i = 0; i < n; ++i) basis.row(i) << sn[i], c[i], c[i] * ds[i];
  const Eigen::Matrix<double, Eigen::Dynamic, 3> once = cumulative(Q, J, basis);
  const Eigen::Matrix<double, Eigen::Dynamic, 3> twice = cumulative(Q, J, once);
  // M' = basis * weights, column by column (the load column's Fy grows with s - a).
  Eigen::Matrix<double, 3, kColumns> weights;
  weights << Y.row(kFx), -Y.row(kFy), Eigen::Matrix<double, 1, kColumns>::Unit(kLoad) * -1.0;
  PanelColumns out;
  auto& node = out.node;
  for (auto& m : node) m.resize(n, kColumns);
  const double a_N = model.a_N(), a_V = model.a_V();
  // Node by node, column by column: no temporaries.
  for (int j = 0; j < kColumns; ++j) {
    const double Fx = Y(kFx, j), Fy0 = Y(kFy, j), M0 = Y(kM, j), psi0 = Y(kPsi, j);
    const double load = j == kLoad ? 1.0 : 0.0;
    const double w0 = weights(0, j), w1 = weights(1, j), w2 = weights(2, j);
    for (int i = 0; i < n; ++i) {
      const double Fy = Fy0 + load * ds[i];
      const double M = M0 + once(i, 0) * w0 + once(i, 1) * w1 + once(i, 2) * w2;
      const double psi = psi0 + ds[i] * M0 + twice(i, 0) * w0 + twice(i, 1) * w1 + twice(i, 2) * w2;
      const double N = c[i] * Fx + sn[i] * Fy;
      const double rotation = a_V * (c[i] * Fy - sn[i] * Fx) + psi;
      node[kFx](i, j) = Fx;
      node[kFy](i, j) = Fy;
      node[kM](i, j) = M;
      node[kPsi](i, j) = psi;
      node[kUx](i, j) = a_N * N * c[i] - rotation * sn[i];
      node[kUy](i, j) = a_N * N * sn[i] + rotation * c[i];
    }
  }
  for (int k : {kFx, kFy, kM, kPsi}) out.end.row(k) = node[k].row(n - 1);
  // The last row of the integration matrix is the Clenshaw-Curtis rule over the whole panel.
  for (int k : {kUx, kUy}) out.end.row(k) = Y.row(k) + Q.row(n - 1) * (J.asDiagonal() * node[k]);
  return out;
}

// One degree's transfer over the half arch and its boundary-value solve; the field is built only for
// the degree that is returned (make_solution).
struct Level {
  int degree = 0;
  std::vector<PanelColumns> columns;
  Columns springing;                    // the columns at s = 0
  BvpSolution bvp;
  Eigen::Matrix<double, kColumns, 1> y0;  // the solved springing forces and 1: y(s) = Y(s) y0
};

Level solve_level(const ArchModel& model, const std::vector<Panel>& panels, int degree) {
  const ChebyshevRule& rule = chebyshev_rule(degree);
  Level level;
  level.degree = degree;
  Columns Y = Columns::Zero();
  for (int j = 0; j < 3; ++j) Y(kUnknowns[j], j) = 1.0;
  Y(kUx, kLoad) = -model.support_displacement();
  level.springing = Y;
  level.columns.reserve(panels.size());
  for (const Panel& panel : panels) {
    level.columns.push_back(integrate_panel(model, panel, rule, Y));
    Y = level.columns.back().end;
  }
  // The whole transfer y(S) = Phi y(0) + p for the boundary-value solve the methods share. The given
  // springing components' columns are exact: a unit Ux0 or Uy0 is a rigid translation, a unit psi0 a
  // rigid rotation about the springing (Ux = -y, Uy = x at the crown).
  SystemMatrix Phi = SystemMatrix::Identity();
  for (int j = 0; j < 3; ++j) Phi.col(kUnknowns[j]) = Y.col(j);
  const double L = model.scales().length;
  const CurvePoint crown = model.scene().curve->at(model.scene().curve->half_length());
  Phi(kUx, kPsi) = -crown.y / L;
  Phi(kUy, kPsi) = crown.x / L;
  // The load column started from Ux0 = -d: p is the transfer of a zero start.
  const StateVector p = Y.col(kLoad) + model.support_displacement() * Phi.col(kUx);
  level.bvp = solve_single_segment(model, Phi, p);
  level.y0 << level.bvp.y0[kFx], level.bvp.y0[kFy], level.bvp.y0[kM], 1.0;
  return level;
}

// The Solution of one degree: the solved state at the nodes (Ux and Uy by integrating the solved
// integrands), the field, reactions, residuals and status; the profile when stations are asked for.
Solution make_solution(const std::shared_ptr<const ArchModel>& model, const std::vector<Panel>& panels,
                       const Level& level, const Options& options) {
  const ChebyshevRule& rule = chebyshev_rule(level.degree);
  NodeStates states;
  StateVector y_start = level.springing * level.y0;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const auto& node = level.columns[k].node;
    Eigen::MatrixXd panel_states(kStateSize, level.degree + 1);
    for (int i : {kFx, kFy, kM, kPsi}) panel_states.row(i) = (node[i] * level.y0).transpose();
    const Eigen::Map<const Eigen::VectorXd> J(panels[k].jacobian.data(), level.degree + 1);
    for (int i : {kUx, kUy}) {
      const Eigen::VectorXd integrand = node[i] * level.y0;
      panel_states.row(i) = (y_start[i] + cumulative(rule.integration, J, integrand).array()).transpose();
    }
    y_start = level.columns[k].end * level.y0;
    states.push_back(std::move(panel_states));
  }
  Solution sol;
  sol.method = Method::quadrature;
  sol.model = model;
  sol.diagnostics.segments = static_cast<int>(panels.size());
  finish_solution(sol, level.bvp,
                  std::make_shared<QuadratureField>(model, panels, level.degree, std::move(states)),
                  options.rtol);
  if (sol.field && options.stations > 0) sample_profile(sol, options.stations);
  return sol;
}

// cos theta, sin theta, s - a and ds/dx at the nodes of degree `degree`, keeping those of degree / 2
// (the even-numbered nodes).
std::int64_t sample_nodes(const ArchModel& model, Panel& panel, int degree) {
  const ChebyshevRule& rule = chebyshev_rule(degree);
  Panel coarse;
  std::swap(coarse.cos, panel.cos);
  std::swap(coarse.sin, panel.sin);
  std::swap(coarse.ds, panel.ds);
  std::swap(coarse.jacobian, panel.jacobian);
  for (auto* v : {&panel.cos, &panel.sin, &panel.ds, &panel.jacobian}) v->assign(degree + 1, 0.0);
  const double L = model.scales().length;
  const double mid = 0.5 * (panel.pa + panel.pb), h = 0.5 * (panel.pb - panel.pa);
  std::int64_t evaluations = 0;
  for (int i = 0; i <= degree; ++i) {
    if (!coarse.cos.empty() && i % 2 == 0) {
      panel.cos[i] = coarse.cos[i / 2];
      panel.sin[i] = coarse.sin[i / 2];
      panel.ds[i] = coarse.ds[i / 2];
      panel.jacobian[i] = coarse.jacobian[i / 2];
      continue;
    }
    // The ends exactly, so that neighbouring panels meet at the same point.
    const double p = i == 0 ? panel.pa : i == degree ? panel.pb : mid + h * rule.node[i];
    if (panel.in_parameter) {
      const ParameterPoint q = model.scene().curve->at_parameter(p);
      panel.cos[i] = q.cos;
      panel.sin[i] = q.sin;
      panel.ds[i] = i == 0 ? 0.0 : i == degree ? panel.b - panel.a : q.s / L - panel.a;
      panel.jacobian[i] = h * q.speed / L;
    } else {
      const double theta = model.theta(p);
      panel.cos[i] = std::cos(theta);
      panel.sin[i] = std::sin(theta);
      panel.ds[i] = p - panel.a;
      panel.jacobian[i] = h;
    }
    ++evaluations;
  }
  return evaluations;
}

}  // namespace

Solution solve_quadrature(std::shared_ptr<const ArchModel> model, const Options& options) {
  std::vector<double> knots{0.0};
  for (double b : model->breakpoints()) knots.push_back(b);
  if (!options.restart_at_breakpoints && knots.size() > 1) {
    // Across a jump of curvature (or of its derivative) the nodes' polynomials converge only slowly, and
    // the difference of two degrees no longer bounds the error (measured on the survey: estimate 6e-8,
    // true error 2e-7). Studies of what a jump costs are for the integrators.
    Solution sol;
    sol.method = Method::quadrature;
    sol.model = model;
    sol.status = Status::not_applicable;
    sol.message = "the quadrature method integrates between the curve's breakpoints: it does not ignore them";
    return sol;
  }
  knots.push_back(model->half_length());
  // The curve's own parameter where it has one that matches its breakpoints.
  const std::vector<double> parameter = model->scene().curve->parameter_knots();
  const bool in_parameter = parameter.size() == knots.size();
  std::vector<Panel> panels;
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    Panel p;
    p.a = knots[k];
    p.b = knots[k + 1];
    p.in_parameter = in_parameter;
    p.pa = in_parameter ? parameter[k] : p.a;
    p.pb = in_parameter ? parameter[k + 1] : p.b;
    panels.push_back(std::move(p));
  }

  std::int64_t evaluations = 0;
  int degree = kMinChebyshevDegree;
  for (Panel& p : panels) evaluations += sample_nodes(*model, p, degree);
  // Without stations, a degree that is not returned needs no field: only its H (its Fx at the springing).
  const bool profiles = options.stations > 0;
  Level coarse = solve_level(*model, panels, degree);
  Solution coarse_solution = profiles ? make_solution(model, panels, coarse, options) : Solution{};
  Solution sol;
  double estimate = std::numeric_limits<double>::quiet_NaN();
  while (true) {
    degree *= 2;
    for (Panel& p : panels) evaluations += sample_nodes(*model, p, degree);
    Level fine = solve_level(*model, panels, degree);
    const double condition = 1.0 / fine.bvp.rcond;
    // H = -Fx at the springing times the force scale: its relative difference is that of y0[Fx].
    double difference = std::abs(coarse.y0[0] - fine.y0[0]) / std::abs(fine.y0[0]);
    if (profiles) {
      sol = make_solution(model, panels, fine, options);
      difference = solution_difference(coarse_solution, sol);
    }
    // Round-off bounds what any degree can show: the estimate never claims less than 10 x eps x the
    // condition estimate, or x 100 for well-conditioned scenes (the springing state's round-off is
    // condition x eps; the nested sums over O(1) terms and the profile's measure of M against the kern
    // lose more: measured 7e-14 = 15 x condition x eps against the closed form on the pointed arch
    // eps = 2, condition 21). Once two degrees agree to that, more nodes cannot help.
    const double roundoff = 10 * std::max(condition, 100.0) * std::numeric_limits<double>::epsilon();
    estimate = std::max(difference, roundoff);
    const bool done = !(difference > std::max(options.rtol, roundoff)) || degree == kMaxChebyshevDegree;
    if (done) {
      if (!profiles) sol = make_solution(model, panels, fine, options);
      break;
    }
    coarse = std::move(fine);
    if (profiles) coarse_solution = std::move(sol);
  }
  if (!sol.field) return sol;  // singular: finish_solution said so
  Diagnostics& d = sol.diagnostics;
  d.rhs_evaluations = evaluations;
  d.error_estimate = estimate;
  if (sol.status == Status::success && !(estimate <= 10 * options.rtol)) {
    sol.status = Status::tolerance_not_met;
    sol.message = fmt::format("estimated error {:.3g} exceeds 10 * rtol = {:.3g} at degree {} per panel", estimate,
                              10 * options.rtol, degree);
  }
  return sol;
}

}  // namespace ogive
