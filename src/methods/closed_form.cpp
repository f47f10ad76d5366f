#include "methods/closed_form.hpp"

#include <algorithm>
#include <cmath>

#include <unsupported/Eigen/MatrixFunctions>

#include "methods/bvp.hpp"

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

// exp(A8 l) for one arc (scaled curvature k), local order (u, v, psi, N, V, M, c, sn); the constant
// vertical load b = w_self / w has local components (b sn, b c), and the constant horizontal load a b of a
// horizontal acceleration a (Fx' = -a b) adds (-a b c, a b sn): both are linear in (c, sn).
Matrix8 arc_exponential(const ArchModel& model, double k, double l) {
  const double b = model.self_weight();
  const double h = model.acceleration() * b;
  Matrix8 A = Matrix8::Zero();
  A(kUx, kUy) = k;   A(kUx, kFx) = model.a_N();                      // u'   = k v + a_N N
  A(kUy, kUx) = -k;  A(kUy, kPsi) = 1.0; A(kUy, kFy) = model.a_V();  // v'   = -k u + psi + a_V V
  A(kPsi, kM) = 1.0;                                                 // psi' = M
  A(kFx, kFy) = k;   A(kFx, kSin) = b;  A(kFx, kCos) = -h;           // N'   = k V + b sn - h c
  A(kFy, kFx) = -k;  A(kFy, kCos) = b;  A(kFy, kSin) = h;            // V'   = -k N + b c + h sn
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

// The closed form's field: exact state anywhere. Each station is reached from the start of its own piece
// (an arc, or part of one between point loads; its state solved once, piece by piece, from the
// springing), so a station's state does not depend on how many other stations are asked for: chaining
// station to station would accumulate round-off (the crown moment moved by 1.6e-10 between 3 and 999 999
// stations).
class ClosedFormField final : public PiecewiseField {
 public:
  ClosedFormField(std::shared_ptr<const ArchModel> model, std::vector<double> knots, std::vector<StateVector> starts)
      : PiecewiseField(std::move(knots), std::move(starts)), model_(std::move(model)) {}

 protected:
  void propagate(double s_k, const StateVector& y_k, std::span<const double> s,
                 std::span<StateVector> out) const override {
    for (std::size_t i = 0; i < s.size(); ++i) {
      const Transfer t = closed_form_transfer(*model_, s_k, s[i]);
      out[i] = t.Phi * y_k + t.p;
    }
  }

 private:
  std::shared_ptr<const ArchModel> model_;
};

}  // namespace

Transfer closed_form_transfer(const ArchModel& model, double s0, double s1) {
  const double L = model.scales().length;
  Transfer total;
  for (const CircularArc& arc : model.curve().arcs()) {
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
  const auto arcs = model->curve().arcs();
  if (arcs.empty() || !model->self_weight_only_distributed()) {
    sol.status = Status::not_applicable;
    sol.message = arcs.empty() ? "closed form needs a piecewise-circular curve; " + model->curve().family() + " is not"
                               : "closed form treats the self-weight (with its horizontal acceleration) and point "
                                 "loads exactly, not a live load or fill (their load per axis length is not constant "
                                 "on an arc)";
    return sol;
  }
  // Pieces: the arcs, cut at the point loads and the hinge; one exponential each.
  const double L = model->scales().length;
  std::vector<double> arc_starts;
  arc_starts.reserve(arcs.size());
  for (const CircularArc& arc : arcs) arc_starts.push_back(arc.s_start / L);
  const std::vector<double> knots = merge_knots(*model, arc_starts);
  March m;
  march(*model, knots,
        [&](std::size_t k, AffineState& Y) {
          const Transfer t = closed_form_transfer(*model, knots[k], knots[k + 1]);
          const AffineState next = t.Phi.lazyProduct(Y);
          Y = next;
          Y.col(Y.cols() - 1) += t.p;
          return true;
        },
        m);
  BvpSolution bvp = solve_march(*model, std::move(m));
  sol.diagnostics.segments = static_cast<int>(knots.size() - 1);
  auto field = std::make_shared<ClosedFormField>(model, std::move(bvp.knots), std::move(bvp.starts));
  finish_solution(sol, bvp, std::move(field));
  return sol;
}

}  // namespace ogive
