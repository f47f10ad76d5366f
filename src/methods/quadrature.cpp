#include "methods/quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "methods/bvp.hpp"
#include "numerics/chebyshev.hpp"

namespace ogive {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The force method's unknowns are the springing's forces: the state is y(s) = Y(s) [Fx0, Fy0, M0, 1], the
// last column carrying the load (Fy' = b) and the springing's given movements (Ux0, Uy0, psi0).
constexpr int kColumns = 4;
constexpr int kLoad = 3;
constexpr std::array<int, 3> kUnknowns = {kFx, kFy, kM};
using Columns = Eigen::Matrix<double, kStateSize, kColumns>;

// A panel of the half arch and its nodes x_i in [-1, 1]. The nodes are Chebyshev points either in the
// arc length s or, where the curve has a parameter t of its own in which s is explicit (the parabola, the
// ellipse, the surveys' splines: Curve::parameter_knots), in t: no inversion of s(t) at any node.
// Integrals in s become integrals in x with the Jacobian ds/dx.
struct Panel {
  double a = 0, b = 0;    // scaled arc lengths at the ends
  double pa = 0, pb = 0;  // the nodes' variable at the ends: scaled s, or t
  bool in_parameter = false;
  // At the current degree's nodes (rows): cos theta, sin theta, s - a (scaled) and ds/dx (scaled).
  Eigen::Matrix<double, Eigen::Dynamic, 4> nodes;
};
enum NodeColumn : int { kCos = 0, kSin = 1, kDs = 2, kJacobian = 3 };

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
          e.in_parameter ? model_->curve().parameter_at(std::clamp(s[i], e.a, e.b) * L) : s[i];
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

// The cumulative integral in s of every column of X from the panel's start, at every node, into out:
// Q (ds/dx X), column by column: for these sizes (9 to 257 nodes, 1 to 3 columns) a matrix-vector product
// per column, vectorised along Q's columns, beats both a blocked GEMM (packing) and a lazy product
// (strided). `scaled` is the caller's work space (the same shape as X).
template <class In, class Work, class Out>
void cumulative(const Eigen::MatrixXd& Q, const Eigen::Ref<const Eigen::VectorXd>& jacobian, const In& X,
                Work& scaled, Out&& out) {
  scaled.noalias() = jacobian.asDiagonal() * X;
  for (Eigen::Index j = 0; j < X.cols(); ++j) out.col(j).noalias() = Q * scaled.col(j);
}

// The columns on one panel: Fx, Fy, M and psi at every node; for Ux and Uy only their integrands at the
// nodes (the values at the nodes are needed only for the solved state: two integrals, not eight).
struct PanelColumns {
  // Component k of the columns at every node is node.middleCols<kColumns>(k * kColumns); for kUx and kUy
  // it is their derivative d/ds. One allocation per panel.
  Eigen::Matrix<double, Eigen::Dynamic, kStateSize * kColumns> node;
  Columns end;  // the columns at the panel's end
  auto component(int k) { return node.middleCols<kColumns>(k * kColumns); }
  auto component(int k) const { return node.middleCols<kColumns>(k * kColumns); }
};

// The curved bar (ArchModel::curved_bar) on one panel, from the straight beam's columns: M gains the
// self-weight's couple on the load column, psi' = bending M + coupling N replaces psi' = M, and the
// displacements' integrands take the coupled axis strain. Unlike the straight beam's nested integrals of
// known functions, these read the curvature at every node, and psi takes one cumulative integral a column.
void curve_panel(const ArchModel& model, const Panel& panel, const ChebyshevRule& rule, const Columns& Y,
                 PanelColumns& out) {
  const int n = rule.degree + 1;
  const Eigen::MatrixXd& Q = rule.integration;
  const auto c = panel.nodes.col(kCos), sn = panel.nodes.col(kSin), ds = panel.nodes.col(kDs);
  const auto J = panel.nodes.col(kJacobian);
  std::vector<ArchModel::CurvedBar> bars(n);
  for (int i = 0; i < n; ++i) bars[i] = model.curved_bar(model.kappa(panel.a + ds[i]));
  Eigen::VectorXd f(n), scaled(n), integral(n);
  const double b = model.self_weight(), a = model.acceleration();
  for (int i = 0; i < n; ++i) f[i] = bars[i].offset * b * (sn[i] - a * c[i]);
  cumulative(Q, J, f, scaled, integral);
  out.component(kM).col(kLoad) += integral;
  for (int j = 0; j < kColumns; ++j) {
    const auto Fx = out.component(kFx).col(j), Fy = out.component(kFy).col(j), M = out.component(kM).col(j);
    const bool weight = j == kLoad;  // the self-weight's own stress across the depth strains the load column
    for (int i = 0; i < n; ++i) {
      f[i] = bars[i].bending * M[i] + bars[i].coupling * (c[i] * Fx[i] + sn[i] * Fy[i]);
      if (weight) f[i] += bars[i].load_curvature * model.weight_normal_load(c[i], sn[i]);
    }
    cumulative(Q, J, f, scaled, integral);
    out.component(kPsi).col(j) = Y(kPsi, j) + integral.array();
    for (int i = 0; i < n; ++i) {
      StateVector y, dy;
      y << 0.0, 0.0, out.component(kPsi)(i, j), Fx[i], Fy[i], M[i];
      model.curved_derivative(c[i], sn[i], bars[i], y.data(), dy.data(), 0.0, 0.0, false);
      if (weight) {
        const double eps = bars[i].load_strain * model.weight_normal_load(c[i], sn[i]);
        dy[kUx] += eps * c[i];
        dy[kUy] += eps * sn[i];
      }
      out.component(kUx)(i, j) = dy[kUx];
      out.component(kUy)(i, j) = dy[kUy];
    }
  }
  for (int k : {kFx, kFy, kM, kPsi}) out.end.row(k) = out.component(k).row(n - 1);
  for (int k : {kUx, kUy}) out.end.row(k) = Y.row(k) + Q.row(n - 1) * (J.asDiagonal() * out.component(k));
}

// The force method's nested integrals from the columns Y at the panel's start, in the order each needs
// the one before: Fx, Fy, then M, psi, then Ux, Uy. Every column's M' = sn Fx - c Fy is a combination of
// the same three functions sn, c and c (s - a) (Fx constant, Fy = Fy(a) + load (s - a)), so M and psi
// take three cumulative integrals each, whatever the number of columns.
PanelColumns integrate_panel(const ArchModel& model, const Panel& panel, const ChebyshevRule& rule,
                             const Columns& Y) {
  const int n = rule.degree + 1;
  const Eigen::MatrixXd& Q = rule.integration;
  const auto c = panel.nodes.col(kCos), sn = panel.nodes.col(kSin), ds = panel.nodes.col(kDs);
  const auto J = panel.nodes.col(kJacobian);
  // basis | once | twice: the three functions, their integrals and their integrals' integrals.
  Eigen::Matrix<double, Eigen::Dynamic, 9> work(n, 9);
  work.col(0) = sn;
  work.col(1) = c;
  work.col(2) = c.cwiseProduct(ds);
  Eigen::Matrix<double, Eigen::Dynamic, 3> scaled(n, 3);
  cumulative(Q, J, work.leftCols<3>(), scaled, work.middleCols<3>(3));
  cumulative(Q, J, work.middleCols<3>(3), scaled, work.rightCols<3>());
  // M' = basis * weights, column by column (the load column's Fy grows with s - a).
  Eigen::Matrix<double, 3, kColumns> weights;
  const double b = model.self_weight();  // Fy' on the load column (quadrature needs it constant)
  weights << Y.row(kFx), -Y.row(kFy), Eigen::Matrix<double, 1, kColumns>::Unit(kLoad) * -b;
  // A horizontal acceleration over the whole arch: the load column's Fx falls by h per length
  // (Fx = Fx(a) - h (s - a)), adding -h sn (s - a) to its M': a fourth function and its two integrals.
  const double h = model.horizontal_load(panel.a);  // constant: the self-weight's mass alone
  Eigen::Matrix<double, Eigen::Dynamic, 3> shaken;
  if (h != 0) {
    shaken.resize(n, 3);
    shaken.col(0) = sn.cwiseProduct(ds);
    Eigen::VectorXd column_scaled(n);
    cumulative(Q, J, shaken.col(0), column_scaled, shaken.col(1));
    cumulative(Q, J, shaken.col(1), column_scaled, shaken.col(2));
  }
  PanelColumns out;
  out.node.resize(n, kStateSize * kColumns);
  // Node by node, column by column: no temporaries; the displacements' derivatives from the model.
  for (int j = 0; j < kColumns; ++j) {
    const double Fx = Y(kFx, j), Fy0 = Y(kFy, j), M0 = Y(kM, j), psi0 = Y(kPsi, j);
    const double load = j == kLoad ? b : 0.0;
    const double horizontal = j == kLoad ? h : 0.0;
    const double w0 = weights(0, j), w1 = weights(1, j), w2 = weights(2, j);
    for (int i = 0; i < n; ++i) {
      StateVector y, dy;
      y[kUx] = y[kUy] = 0;  // nothing depends on the displacements
      y[kFx] = Fx;
      y[kFy] = Fy0 + load * ds[i];
      y[kM] = M0 + work(i, 3) * w0 + work(i, 4) * w1 + work(i, 5) * w2;
      y[kPsi] = psi0 + ds[i] * M0 + work(i, 6) * w0 + work(i, 7) * w1 + work(i, 8) * w2;
      if (horizontal != 0) {
        y[kFx] -= horizontal * ds[i];
        y[kM] -= horizontal * shaken(i, 1);
        y[kPsi] -= horizontal * shaken(i, 2);
      }
      model.derivative(c[i], sn[i], y.data(), dy.data(), load, horizontal);
      for (int k : {kFx, kFy, kM, kPsi}) out.node(i, k * kColumns + j) = y[k];
      for (int k : {kUx, kUy}) out.node(i, k * kColumns + j) = dy[k];
    }
  }
  for (int k : {kFx, kFy, kM, kPsi}) out.end.row(k) = out.component(k).row(n - 1);
  // The last row of the integration matrix is the Clenshaw-Curtis rule over the whole panel.
  for (int k : {kUx, kUy})
    out.end.row(k) = Y.row(k) + Q.row(n - 1) * (J.asDiagonal() * out.component(k));
  if (model.curved()) curve_panel(model, panel, rule, Y, out);
  return out;
}

// The columns across the curved bar's kink (ArchModel::kink) where the panel ends on it: the whole turn
// at once (the quadrature takes no point loads).
void cross_kink(const ArchModel& model, const Panel& panel, Columns& Y) {
  if (!model.kink() || panel.b != model.kink()->s) return;
  const Columns before = Y;
  Y += model.kink_jump(model.kink()->theta_before, model.kink()->theta_after) * before;
}

// One degree's transfer over the half arch and its boundary-value solve; the field is built only for
// the degree that is returned (make_solution). The panels' columns are not kept (a survey of 10^5
// points has 10^5 panels, and they would take kilobytes each): node_states integrates them again from
// the springing, the same arithmetic in the same order, so the same numbers.
struct Level {
  int degree = 0;
  Columns springing;                    // the columns at s = 0
  BvpSolution bvp;
  Eigen::Matrix<double, kColumns, 1> y0;  // the solved springing forces and 1: y(s) = Y(s) y0
};

Level solve_level(const ArchModel& model, const std::vector<Panel>& panels, int degree) {
  const ChebyshevRule& rule = chebyshev_rule(degree);
  Level level;
  level.degree = degree;
  Columns Y = Columns::Zero();
  // Each force's column starts from a unit force and the movements it gives the springing (the curved
  // bar's held face; none otherwise), the load column from the springing's given movements.
  const SpringingSplit split = springing_split(model);
  for (int j = 0; j < 3; ++j)
    for (int k : {int{kUx}, int{kUy}, int{kPsi}, kUnknowns[j]}) Y(k, j) = split.U(k, j);
  for (int k : {kUx, kUy, kPsi}) Y(k, kLoad) = split.start[k];
  level.springing = Y;
  for (const Panel& panel : panels) {
    Y = integrate_panel(model, panel, rule, Y).end;
    cross_kink(model, panel, Y);
  }
  // The whole transfer y(S) = Phi y(0) + p for the boundary-value solve the methods share. The given
  // springing components' columns are exact: a unit Ux0 or Uy0 is a rigid translation, a unit psi0 a
  // rigid rotation about the springing (Ux = -y, Uy = x at the domain's end: the crown, or the right
  // springing).
  SystemMatrix Phi = SystemMatrix::Identity();
  const double L = model.scales().length;
  const CurvePoint end = model.curve().at(model.curve().length());
  Phi(kUx, kPsi) = -end.y / L;
  Phi(kUy, kPsi) = end.x / L;
  // A force's column is its transfer plus the rigid motion of the movements it started with.
  for (int j = 0; j < 3; ++j) {
    Phi.col(kUnknowns[j]) = Y.col(j);
    if (level.springing.col(j).head<3>().any())
      Phi.col(kUnknowns[j]) -= Phi.leftCols<3>() * level.springing.col(j).head<3>();
  }
  // The load column started from the given movements: p is the transfer of a zero start.
  const StateVector p = Y.col(kLoad) - Phi * level.springing.col(kLoad);
  level.bvp = solve_single_segment(model, Phi, p);
  level.y0 << level.bvp.y0[kFx], level.bvp.y0[kFy], level.bvp.y0[kM], 1.0;
  return level;
}

// The solved state of one degree at every node of every panel: Fx, Fy, M and psi from the columns, Ux
// and Uy by integrating the solved integrands.
NodeStates node_states(const ArchModel& model, const std::vector<Panel>& panels, const Level& level) {
  const ChebyshevRule& rule = chebyshev_rule(level.degree);
  const int n = level.degree + 1;
  NodeStates states;
  states.reserve(panels.size());
  StateVector y_start = level.springing * level.y0;
  Columns Y = level.springing;
  Eigen::Matrix<double, Eigen::Dynamic, 2> integrand(n, 2), scaled(n, 2), integral(n, 2);
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const PanelColumns columns = integrate_panel(model, panels[k], rule, Y);
    Y = columns.end;
    cross_kink(model, panels[k], Y);
    Eigen::MatrixXd panel_states(kStateSize, n);
    for (int i : {kFx, kFy, kM, kPsi}) panel_states.row(i) = (columns.component(i) * level.y0).transpose();
    integrand.col(0) = columns.component(kUx) * level.y0;
    integrand.col(1) = columns.component(kUy) * level.y0;
    cumulative(rule.integration, panels[k].nodes.col(kJacobian), integrand, scaled, integral);
    panel_states.row(kUx) = (y_start[kUx] + integral.col(0).array()).transpose();
    panel_states.row(kUy) = (y_start[kUy] + integral.col(1).array()).transpose();
    y_start = Y * level.y0;
    states.push_back(std::move(panel_states));
  }
  return states;
}

// The Solution of one degree from its states at the nodes: the field, reactions, residuals and status;
// the profile when stations are asked for.
Solution make_solution(const std::shared_ptr<const ArchModel>& model, const std::vector<Panel>& panels,
                       const Level& level, NodeStates states, int stations) {
  Solution sol;
  sol.method = Method::quadrature;
  sol.model = model;
  sol.diagnostics.segments = static_cast<int>(panels.size());
  finish_solution(sol, level.bvp, std::make_shared<QuadratureField>(model, panels, level.degree, std::move(states)));
  if (sol.field && stations > 0) sample_profile(sol, stations);
  return sol;
}

// A degree's states at the nodes of twice its degree: its own nodes are the even-numbered ones there,
// the odd-numbered ones (half-way between, in angle) take its interpolant, the field it would return.
NodeStates at_doubled_nodes(const NodeStates& states, int degree) {
  const ChebyshevRule& rule = chebyshev_rule(degree);
  const ChebyshevRule& doubled = chebyshev_rule(2 * degree);
  NodeStates out;
  out.reserve(states.size());
  for (const Eigen::MatrixXd& panel : states) {
    Eigen::MatrixXd fine(kStateSize, 2 * degree + 1);
    for (int i = 0; i <= 2 * degree; ++i)
      fine.col(i) = i % 2 == 0 ? Eigen::VectorXd(panel.col(i / 2)) : chebyshev_interpolate(rule, panel, doubled.node[i]);
    out.push_back(std::move(fine));
  }
  return out;
}

// The states at the panels' current nodes as profile_difference reads them (displacements, rotation,
// N, V and M in SI units), each section's tangent from the nodes' own cos and sin: no point of the
// curve is evaluated.
std::vector<ArchState> node_profile(const ArchModel& model, const std::vector<Panel>& panels, const NodeStates& states) {
  std::vector<ArchState> out;
  for (std::size_t k = 0; k < panels.size(); ++k) {
    const auto& nodes = panels[k].nodes;
    for (Eigen::Index i = 0; i < states[k].cols(); ++i) {
      const StateVector y = states[k].col(i);
      out.push_back(model.section_state(nodes(i, kCos), nodes(i, kSin), y));
    }
  }
  return out;
}

// The panels' nodes (sample_nodes' rows) depend on the domain's curve alone: its shape, its span (the
// length scale) and whether the domain is its half. A thread keeps them for the last curve it solved on,
// so that a sweep over one curve or survey (thickness, material, loads, supports) evaluates the curve
// at each panel's nodes once per degree, not once per scene: the same rows, computed in the same order.
// Only for at most kKeptPanels panels (a survey of a few thousand points): a larger survey's rows would
// take a kilobyte a panel, for a saving that its own solve dwarfs.
constexpr std::size_t kKeptPanels = 8192;
struct NodeGeometry {
  bool keeps = true;  // whether rows are kept (at most kKeptPanels panels)
  std::weak_ptr<const Curve> curve;
  bool half = true;
  double length_scale = 0;
  std::vector<std::array<double, 4>> panels;  // each panel's a, b, pa, pb
  std::map<std::pair<std::size_t, int>, Eigen::Matrix<double, Eigen::Dynamic, 4>> rows;  // (panel, degree)
};

// This thread's node geometry, emptied first unless it is for the model's curve and these panels.
NodeGeometry& node_geometry(const ArchModel& model, const std::vector<Panel>& panels) {
  thread_local NodeGeometry geometry;
  std::vector<std::array<double, 4>> ends;
  for (const Panel& p : panels) ends.push_back({p.a, p.b, p.pa, p.pb});
  if (geometry.curve.lock() != model.scene().curve || geometry.half != model.half() ||
      geometry.length_scale != model.scales().length || geometry.panels != ends) {
    geometry.curve = model.scene().curve;
    geometry.half = model.half();
    geometry.length_scale = model.scales().length;
    geometry.keeps = ends.size() <= kKeptPanels;
    geometry.panels = geometry.keeps ? std::move(ends) : std::vector<std::array<double, 4>>{};
    geometry.rows.clear();
  }
  return geometry;
}

// cos theta, sin theta, s - a and ds/dx at the nodes of degree `degree` of panel k, keeping those of
// degree / 2 (the even-numbered nodes); from `geometry` where this curve's were computed before. The
// count of the curve's evaluations that the rows take (whether or not they were kept).
std::int64_t sample_nodes(const ArchModel& model, Panel& panel, int degree, NodeGeometry& geometry, std::size_t k) {
  Eigen::Matrix<double, Eigen::Dynamic, 4> unkept;
  auto& kept = geometry.keeps ? geometry.rows[{k, degree}] : unkept;
  const bool refining = panel.nodes.rows() == degree / 2 + 1;
  if (kept.rows() == degree + 1) {
    panel.nodes = kept;
    return refining ? degree / 2 : degree + 1;
  }
  const ChebyshevRule& rule = chebyshev_rule(degree);
  Eigen::Matrix<double, Eigen::Dynamic, 4> coarse(degree + 1, 4);
  coarse.swap(panel.nodes);  // panel.nodes: degree + 1 rows now; coarse: the previous degree's, if any
  const double L = model.scales().length;
  const double mid = 0.5 * (panel.pa + panel.pb), h = 0.5 * (panel.pb - panel.pa);
  std::int64_t evaluations = 0;
  for (int i = 0; i <= degree; ++i) {
    if (refining && i % 2 == 0) {
      panel.nodes.row(i) = coarse.row(i / 2);
      continue;
    }
    // The ends exactly, so that neighbouring panels meet at the same point.
    const double p = i == 0 ? panel.pa : i == degree ? panel.pb : mid + h * rule.node[i];
    if (panel.in_parameter) {
      const ParameterPoint q = model.curve().at_parameter(p);
      panel.nodes.row(i) << q.cos, q.sin, i == 0 ? 0.0 : i == degree ? panel.b - panel.a : q.s / L - panel.a,
          h * q.speed / L;
    } else {
      // Over the whole arch the crown may be a kink (the pointed arch): an end node inside the domain
      // takes the angle of its own panel's side, a few ulps inside it (the curve's angle at the kink is
      // one side's).
      double inside = p;
      if (!model.half() && i == 0 && panel.a > 0) inside = p + 4 * kEps * std::abs(p);
      if (!model.half() && i == degree && panel.b < model.length()) inside = p - 4 * kEps * std::abs(p);
      const double theta = model.theta(inside);
      panel.nodes.row(i) << std::cos(theta), std::sin(theta), p - panel.a, h;
    }
    ++evaluations;
  }
  if (geometry.keeps) kept = panel.nodes;
  return evaluations;
}

// A coarser degree's solution as the comparison with the next reads it (sampled_solution_difference:
// its reactions and profile), its field dropped: a survey's fields take most of the memory, and two
// degrees' at once would double it. No profile where it was not solved (make_solution samples one
// only then), which the comparison reads as not a number, as solution_difference does.
Solution without_field(Solution sol) {
  sol.field.reset();
  return sol;
}

// The error of the finer of two degrees N and 2N, from the differences d1 = |x_N - x_2N| and
// d0 = |x_N/2 - x_N|. Where the differences shrink by a ratio q = d1 / d0 <= 1/2 per doubling (converging),
// the finer degree's error is the tail of the differences still to come, at most d1 q / (1 - q) if they
// keep shrinking at least geometrically: spectral convergence makes them shrink faster, so the bound
// errs on the safe side by about d0 / C. Otherwise (no previous difference, or not yet converging) d1
// itself, which bounds the coarser degree's error.
double finer_error_bound(double d1, double d0) {
  if (!(d0 > 0) || !(d1 >= 0)) return d1;
  const double q = d1 / d0;
  return q <= 0.5 ? d1 * q / (1 - q) : d1;
}

// The panels between the knots (scaled arc lengths, the domain's ends and the curve's breakpoints), in the
// curve's own parameter where it has one that matches its breakpoints.
std::vector<Panel> make_panels(const ArchModel& model, const std::vector<double>& knots) {
  const std::vector<double> parameter = model.curve().parameter_knots();
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
  return panels;
}

}  // namespace

Solution solve_quadrature(std::shared_ptr<const ArchModel> model, const Options& options) {
  // Fx constant and Fy' constant make M, psi and the displacements nested integrals of known functions;
  // with other loads, a pinned springing or a hinge inside, the method would need more columns than it
  // carries: the integrators and the closed form treat those scenes.
  // A horizontal acceleration makes the symmetric arch's load antisymmetric in part: the same columns
  // carry it over the whole arch (Fx' = -h, a constant too), without a hinge inside.
  const bool shaken_symmetric = model->acceleration() != 0 && !model->hinge() && [&] {
    Scene still = model->scene();
    still.horizontal_acceleration = 0;
    return still.symmetric();
  }();
  if (!(model->half() || shaken_symmetric) || !model->uniform_load() ||
      model->scene().left.kind != SupportKind::clamped) {
    Solution sol;
    sol.method = Method::quadrature;
    sol.model = model;
    sol.status = Status::not_applicable;
    sol.message = "the quadrature method treats the symmetric arch with clamped springings under its own weight "
                  "alone (solved over the half; over the whole arch when a horizontal acceleration shakes it and no "
                  "crown hinge divides it)";
    return sol;
  }
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
  knots.push_back(model->length());
  std::vector<Panel> panels = make_panels(*model, knots);

  std::int64_t evaluations = 0;
  NodeGeometry& geometry = node_geometry(*model, panels);
  // Short panels (a survey's, cut at every point) converge sooner: start lower there; a single long
  // panel starts higher, where it would otherwise spend one more level.
  int degree = kMinChebyshevDegree;
  for (std::size_t k = 0; k < panels.size(); ++k) evaluations += sample_nodes(*model, panels[k], degree, geometry, k);
  // Without stations, a degree that is not returned needs no field: only its H (its Fx at the springing).
  const bool profiles = options.stations > 0;
  // A profile asked for only so that the estimate covers the field a summary reads (nothing printed):
  // the two degrees are compared at the finer one's nodes, from the states there and the coarser one's
  // interpolant between its own nodes, instead of at kVerificationStations stations of both fields. Their
  // difference is a polynomial of the finer degree on each panel: its largest value over the panel is at
  // most the Lebesgue constant of those nodes (below 4.6 up to degree 256) times its largest value at them.
  const bool node_estimate = profiles && options.unprinted_profile;
  const bool sampled = profiles && !node_estimate;
  Level coarse = solve_level(*model, panels, degree);
  NodeStates coarse_states = node_estimate ? node_states(*model, panels, coarse) : NodeStates{};
  Solution coarse_solution =
      sampled ? without_field(make_solution(model, panels, coarse, node_states(*model, panels, coarse), options.stations))
              : Solution{};
  Solution sol;
  NodeStates fine_states;
  double estimate = std::numeric_limits<double>::quiet_NaN();
  double previous_difference = std::numeric_limits<double>::quiet_NaN();
  while (true) {
    degree *= 2;
    for (std::size_t k = 0; k < panels.size(); ++k) evaluations += sample_nodes(*model, panels[k], degree, geometry, k);
    Level fine = solve_level(*model, panels, degree);
    const double condition = fine.bvp.condition;
    if (node_estimate) fine_states = node_states(*model, panels, fine);
    const Reactions fine_reactions = model->reactions(fine.bvp.y0, fine.bvp.yS);
    const Reactions coarse_reactions = model->reactions(coarse.bvp.y0, coarse.bvp.yS);
    const double thickness = model->scene().thickness;
    // The reactions' difference, as solution_difference measures it.
    double difference = reaction_difference(coarse_reactions, fine_reactions, thickness);
    if (sampled) {
      sol = make_solution(model, panels, fine, node_states(*model, panels, fine), options.stations);
      difference = coarse_solution.profile.empty() || !sol.field ? std::numeric_limits<double>::quiet_NaN()
                                                                  : sampled_solution_difference(coarse_solution, sol);
    } else if (node_estimate) {
      const double fields = profile_difference(node_profile(*model, panels, at_doubled_nodes(coarse_states, degree / 2)),
                                               node_profile(*model, panels, fine_states), thickness);
      const double reactions = reaction_and_thrust_difference(coarse_reactions, fine_reactions, thickness);
      difference = std::isnan(fields) || std::isnan(reactions) ? std::numeric_limits<double>::quiet_NaN()
                                                                : std::max(fields, reactions);
    }
    // Round-off bounds what any degree can show: once two degrees agree to 10 x eps x the condition
    // estimate (x 100 for well-conditioned scenes), more nodes cannot help. solve() floors the estimate
    // at the solution's round-off bound (roundoff_bound).
    const double roundoff = 10 * std::max(condition, 100.0) * std::numeric_limits<double>::epsilon();
    estimate = finer_error_bound(difference, previous_difference);
    // The first degree is never returned: the estimate needs two differences.
    const bool done = (!(difference > std::max(options.rtol, roundoff)) && !std::isnan(previous_difference)) ||
                      degree == kMaxChebyshevDegree;
    if (done) {
      if (node_estimate) {
        // The node states stand for the unprinted profile: roundoff_bound reads its largest forces and
        // couple, and solve() drops it.
        std::vector<ArchState> nodes = node_profile(*model, panels, fine_states);
        sol = make_solution(model, panels, fine, std::move(fine_states), 0);
        if (sol.field) sol.profile = std::move(nodes);
      } else if (!sampled) {
        sol = make_solution(model, panels, fine, node_states(*model, panels, fine), 0);
      }
      break;
    }
    previous_difference = difference;
    coarse = std::move(fine);
    coarse_states = std::move(fine_states);
    if (sampled) coarse_solution = without_field(std::move(sol));
  }
  if (!sol.field) return sol;  // singular: finish_solution said so
  Diagnostics& d = sol.diagnostics;
  d.rhs_evaluations = evaluations;
  d.error_estimate = estimate;  // judged against rtol by solve(), as every method's (within_tolerance)
  return sol;
}

}  // namespace ogive
