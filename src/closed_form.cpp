#include "ogive/closed_form.hpp"

#include <algorithm>
#include <cmath>

#include <unsupported/Eigen/MatrixFunctions>

#include "bvp.hpp"

namespace ogive {
namespace {

using Matrix8 = Eigen::Matrix<double, 8, 8>;
constexpr int kCos = 6, kSin = 7;  // the appended trigonometric states

// Local (tangential/radial) components from global ones at tangent angle theta: u = R y.
SystemMatrix to_local(double theta) {
  const double c = std::cos(theta), sn = std::sin(theta);
  SystemMatrix R = SystemMatrix::Identity();
  R(kUx, kUx) = c;   R(kUx, kUy) = sn;
  R(kUy, kUx) = -sn; R(kUy, kUy) = c;
  R(kFx, kFx) = c;   R(kFx, kFy) = sn;
  R(kFy, kFx) = -sn; R(kFy, kFy) = c;
  return R;
}

// exp(A8 l) for one arc (scaled curvature k), local order (u, v, psi, N, V, M, c, sn).
Matrix8 arc_exponential(const ArchModel& model, double k, double l) {
  Matrix8 A = Matrix8::Zero();
  A(kUx, kUy) = k;   A(kUx, kFx) = model.a_N();                      // u'   = k v + a_N N
  A(kUy, kUx) = -k;  A(kUy, kPsi) = 1.0; A(kUy, kFy) = model.a_V();  // v'   = -k u + psi + a_V V
  A(kPsi, kM) = 1.0;                                                 // psi' = M
  A(kFx, kFy) = k;   A(kFx, kSin) = 1.0;                             // N'   = k V + sn
  A(kFy, kFx) = -k;  A(kFy, kCos) = 1.0;                             // V'   = -k N + c
  A(kM, kFy) = -1.0;                                                 // M'   = -V
  A(kCos, kSin) = -k;                                                // c'   = -k sn
  A(kSin, kCos) = k;                                                 // sn'  = k c
  return (A * l).exp();
}

// Transfer over [ds0, ds1] of one arc (distances from the arc's start, scaled).
Transfer arc_transfer(const ArchModel& model, const CircularArc& arc, double ds0, double ds1) {
  const double L = model.scales().length;
  const double k = arc.kappa * L;
  const double th0 = arc.theta_start + arc.kappa * ds0 * L;
  const double th1 = arc.theta_start + arc.kappa * ds1 * L;
  const Matrix8 E = arc_exponential(model, k, ds1 - ds0);
  const SystemMatrix back = to_local(th1).transpose();
  Transfer t;
  t.Phi = back * E.topLeftCorner<6, 6>() * to_local(th0);
  t.p = back * (E.block<6, 1>(0, kCos) * std::cos(th0) + E.block<6, 1>(0, kSin) * std::sin(th0));
  return t;
}

// The closed form's field: exact state anywhere. Each station is reached from the start of its own arc
// (whose state is chained once, arc by arc, from the springing), so a station's state does not depend
// on how many other stations are asked for: chaining station to station would accumulate round-off
// (the crown moment moved by 1.6e-10 between 3 and 999 999 stations).
class ClosedFormField final : public StateField {
 public:
  // arc_transfers: each arc's whole transfer, already computed for the boundary-value problem.
  ClosedFormField(std::shared_ptr<const ArchModel> model, const StateVector& y0,
                  const std::vector<Transfer>& arc_transfers)
      : model_(std::move(model)) {
    const double L = model_->scales().length;
    StateVector y = y0;
    const auto arcs = model_->scene().curve->arcs();
    for (std::size_t k = 0; k < arcs.size(); ++k) {
      arc_starts_.push_back(arcs[k].s_start / L);
      start_states_.push_back(y);
      y = arc_transfers[k].Phi * y + arc_transfers[k].p;
    }
  }
  void sample(std::span<const double> s, std::span<StateVector> out) const override {
    for (std::size_t i = 0; i < s.size(); ++i) {
      // The arc that holds s: the last one starting at or before it.
      const auto it = std::upper_bound(arc_starts_.begin() + 1, arc_starts_.end(), s[i]);
      const std::size_t k = static_cast<std::size_t>(it - arc_starts_.begin()) - 1;
      const Transfer t = closed_form_transfer(*model_, arc_starts_[k], s[i]);
      out[i] = t.Phi * start_states_[k] + t.p;
    }
  }

 private:
  std::shared_ptr<const ArchModel> model_;
  std::vector<double> arc_starts_;         // scaled arc length where each arc starts
  std::vector<StateVector> start_states_;  // the state there
};

}  // namespace

Transfer closed_form_transfer(const ArchModel& model, double s0, double s1) {
  const double L = model.scales().length;
  Transfer total;
  for (const CircularArc& arc : model.scene().curve->arcs()) {
    const double a0 = arc.s_start / L, a1 = (arc.s_start + arc.length) / L;
    const double lo = std::max(s0, a0), hi = std::min(s1, a1);
    if (hi <= lo) continue;
    const Transfer t = arc_transfer(model, arc, lo - a0, hi - a0);
    total.Phi = t.Phi * total.Phi;
    total.p = t.Phi * total.p + t.p;
  }
  return total;
}

Solution solve_closed_form(std::shared_ptr<const ArchModel> model, const Options& /*options: nothing to set*/) {
  Solution sol;
  sol.method = Method::closed_form;
  sol.model = model;
  if (model->scene().curve->arcs().empty()) {
    sol.status = Status::not_applicable;
    sol.message = "closed form needs a piecewise-circular curve; " + model->scene().curve->family() +
                  " is not";
    return sol;
  }
  // One exponential per arc: chained for the boundary-value problem, kept for the field's arc starts.
  const double L = model->scales().length;
  std::vector<Transfer> arcs;
  Transfer t;
  for (const CircularArc& arc : model->scene().curve->arcs()) {
    arcs.push_back(arc_transfer(*model, arc, 0.0, arc.length / L));
    t.Phi = arcs.back().Phi * t.Phi;
    t.p = arcs.back().Phi * t.p + arcs.back().p;
  }
  const BvpSolution bvp = solve_single_segment(*model, t.Phi, t.p);
  sol.diagnostics.segments = static_cast<int>(arcs.size());
  finish_solution(sol, bvp, std::make_shared<ClosedFormField>(model, bvp.y0, arcs));
  return sol;
}

}  // namespace ogive
