#include "methods/closed_form.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <unsupported/Eigen/MatrixFunctions>

#include "methods/bvp.hpp"

namespace ogive {
namespace {

constexpr int kCos = 6, kSin = 7;  // the appended trigonometric states

// Local (tangential/radial) components from global ones at a tangent angle of cosine c and sine sn:
// u = R y.
SystemMatrix to_local(double c, double sn) {
  SystemMatrix R = SystemMatrix::Identity();
  R(kUx, kUx) = c;   R(kUx, kUy) = sn;
  R(kUy, kUx) = -sn; R(kUy, kUy) = c;
  R(kFx, kFx) = c;   R(kFx, kFy) = sn;
  R(kFy, kFx) = -sn; R(kFy, kFy) = c;
  return R;
}

// C_j(x) = sum_n (-1)^n x^2n / (2n + j)!, j = 0 .. 7: C_0 = cos x, C_1 = sin x / x and
// C_{j+2} = (1/j! - C_j) / x^2. Entire in x, so the transfer written with them has no negative power of
// the curvature. Below |x| = 3 each is its own alternating series (terms to x^32 / 32!: below 1e-18 of
// the first); above, the recurrence upwards from cos and sin, whose cancellation there loses at most a
// factor of (j+1)(j+2)/x^2 < 5 a step.
std::array<double, 8> trig_phi(double x) {
  constexpr int kTerms = 17;
  constexpr auto inverse_factorials = [] {
    std::array<double, 2 * kTerms + 8> f{};
    double n_factorial = 1.0;
    for (std::size_t n = 0; n < f.size(); ++n) {
      if (n > 0) n_factorial *= static_cast<double>(n);
      f[n] = 1.0 / n_factorial;
    }
    return f;
  }();
  std::array<double, 8> C;
  const double x2 = x * x;
  if (x2 < 9.0) {
    for (int j = 0; j < 8; ++j) {
      double sum = inverse_factorials[2 * (kTerms - 1) + j];
      for (int n = kTerms - 2; n >= 0; --n) sum = inverse_factorials[2 * n + j] - x2 * sum;
      C[j] = sum;
    }
  } else {
    C[0] = std::cos(x);
    C[1] = std::sin(x) / x;
    for (int j = 0; j < 6; ++j) C[j + 2] = (inverse_factorials[j] - C[j]) / x2;
  }
  return C;
}

}  // namespace

// exp(A8 l) for one arc in closed form (derivation: closed_form_derivation.py, which also checks that
// every entry is a polynomial in x = k l, l and the parameters times the C_j above, and picks for each the
// form with the least cancellation over 0 <= |x| <= 2 pi). Local order (u, v, psi, N, V, M, c, sn), with
//   u' = k v + a_N N,  v' = -k u + psi + a_V V,  psi' = M,
//   N' = k V + b sn - h c,  V' = -k N + b c + h sn,  M' = -V,  c' = -k sn,  sn' = k c:
// the constant vertical load b = w_self / w has local components (b sn, b c), and the constant horizontal
// load h = a b of a horizontal acceleration a (Fx' = -h) adds (-h c, h sn).
ArcMatrix arc_exponential(double k, double l, double aN, double aV, double b, double h) {
  const double x = k * l, x2 = x * x;
  const double l2 = l * l, l3 = l2 * l, l4 = l2 * l2;
  const std::array<double, 8> C = trig_phi(x);
  ArcMatrix E = ArcMatrix::Zero();
  // The force block: (c, sn) and (N, V) turn through x; the load's resonance gives the terms in l.
  E(kCos, kCos) = C[0];  E(kCos, kSin) = -C[1] * x;
  E(kSin, kCos) = C[1] * x; E(kSin, kSin) = C[0];
  E(kFx, kFx) = C[0];    E(kFx, kFy) = C[1] * x;
  E(kFy, kFx) = -C[1] * x; E(kFy, kFy) = C[0];
  E(kFx, kCos) = l * (C[1] * x * b - C[0] * h);
  E(kFx, kSin) = l * (C[0] * b + C[1] * x * h);
  E(kFy, kCos) = l * (C[0] * b + C[1] * x * h);
  E(kFy, kSin) = l * (C[0] * h - C[1] * x * b);
  E(kM, kFx) = C[2] * l * x;
  E(kM, kFy) = -C[1] * l;
  E(kM, kM) = 1.0;
  E(kM, kCos) = l2 * (b * (C[2] - C[1]) + h * x * (C[3] - C[2]));
  E(kM, kSin) = l2 * (b * x * (C[2] - C[3]) + h * (C[2] - C[1]));
  // The rotation psi' = M.
  E(kPsi, kFx) = C[3] * l2 * x;
  E(kPsi, kFy) = -C[2] * l2;
  E(kPsi, kPsi) = 1.0;
  E(kPsi, kM) = l;
  E(kPsi, kCos) = l3 * (b * (2 * C[3] - C[2]) + h * x * (2 * C[4] - C[3]));
  E(kPsi, kSin) = l3 * (b * x * (C[3] - 2 * C[4]) + h * (2 * C[3] - C[2]));
  // The displacements (u, v), driven by N, V and psi.
  E(kUx, kUx) = C[0];
  E(kUx, kUy) = C[1] * x;
  E(kUx, kPsi) = C[2] * l * x;
  E(kUx, kFx) = 0.5 * l * (aN * (C[0] + C[1]) + aV * x2 * (C[3] - C[2]) + l2 * x2 * (C[4] - 3 * C[5]));
  E(kUx, kFy) = 0.5 * l * x * (C[1] * (aN + aV) + l2 * (2 * C[4] - C[3]));
  E(kUx, kM) = C[3] * l2 * x;
  E(kUy, kUx) = -C[1] * x;
  E(kUy, kUy) = C[0];
  E(kUy, kPsi) = C[1] * l;
  E(kUy, kFx) = 0.5 * l * x * (l2 * (C[3] - 2 * C[4]) - C[1] * (aN + aV));
  E(kUy, kFy) = 0.5 * l * (aV * (C[0] + C[1]) + aN * x2 * (C[3] - C[2]) + l2 * (C[3] - C[2]));
  E(kUy, kM) = C[2] * l2;
  // The load's columns of (u, v): sums of terms of one sign each but for the few that cross zero.
  const double p = C[1] + C[2] - C[3], m = C[1] - C[2] + C[3], d = x2 * (C[3] - C[2]);
  const double q = C[0] + C[1];
  E(kUx, kCos) = 0.25 * (l2 * (aN * (b * x * p - h * q) + aV * (b * x * m - h * d)) +
                         l4 * (b * x * (5 * C[4] - C[3] - 9 * C[5]) + h * x2 * (C[6] * (x2 - 8) - 5 * C[7] * x2)));
  E(kUx, kSin) = 0.25 * (l2 * (aN * (b * q + h * x * p) + aV * (b * d + h * x * m)) +
                         l4 * (b * x2 * (C[6] * (8 - x2) + 5 * C[7] * x2) + h * x * (5 * C[4] - C[3] - 9 * C[5])));
  E(kUy, kCos) = 0.25 * (l2 * (aN * (b * d + h * x * m) + aV * (b * q + h * x * p)) +
                         l4 * (b * (3 * C[3] - C[2] - 4 * C[4]) + h * x * (3 * C[4] - C[3] - 3 * C[5])));
  E(kUy, kSin) = 0.25 * (l2 * (aN * (-b * x * m + h * d) + aV * (-b * x * p + h * q)) +
                         l4 * (b * x * (C[3] - 3 * C[4] + 3 * C[5]) + h * (3 * C[3] - C[2] - 4 * C[4])));
  return E;
}

namespace {

// One arc's piece [ds0, ds1] (distances from the arc's start, scaled): its exp(A8 l) and the cosines
// and sines of its end tangents.
struct ArcPiece {
  ArcMatrix E;
  double c0, sn0, c1, sn1;
};

// The tangent's angle at distance ds (scaled) from the arc's start.
double tangent_angle(const ArchModel& model, const CircularArc& arc, double ds) {
  return arc.theta_start + arc.kappa * ds * model.scales().length;
}

// The curved bar's exp(A8 l) (ArchModel::curved_bar): the same local system with the section's coupling
// (u' gains coupling M, psi' = bending M + coupling N) and the self-weight's couple (M' gains
// coupling (b sn - h c)). Its coefficients are constant on the arc too, but no closed formula is derived for
// them: Eigen's Pade approximant with scaling and squaring takes the exponential to round-off (the matrix'
// norm is of order |k| l <= 2 pi and a_N <= 1/12: a few squarings).
ArcMatrix curved_arc_exponential(double k, double l, double aN, double aV, const ArchModel::CurvedBar& bar, double b,
                                 double h) {
  ArcMatrix A = ArcMatrix::Zero();
  A(kUx, kUy) = k;
  A(kUx, kFx) = aN * bar.axial;
  A(kUx, kM) = bar.coupling;
  A(kUy, kUx) = -k;
  A(kUy, kPsi) = 1.0;
  A(kUy, kFy) = aV * bar.shear;
  A(kPsi, kM) = bar.bending;
  A(kPsi, kFx) = bar.coupling;
  A(kFx, kFy) = k;
  A(kFx, kSin) = b;
  A(kFx, kCos) = -h;
  A(kFy, kFx) = -k;
  A(kFy, kCos) = b;
  A(kFy, kSin) = h;
  A(kM, kFy) = -1.0;
  A(kM, kSin) = bar.offset * b;
  A(kM, kCos) = -bar.offset * h;
  // The self-weight's own stress across the depth: eps and psi' gain load_strain and load_curvature
  // times its normal part -(b cos + h sin).
  A(kUx, kCos) = -bar.load_strain * b;
  A(kUx, kSin) = -bar.load_strain * h;
  A(kPsi, kCos) = -bar.load_curvature * b;
  A(kPsi, kSin) = -bar.load_curvature * h;
  A(kCos, kSin) = -k;
  A(kSin, kCos) = k;
  return (A * l).exp();
}

// exp(A8 l) of a piece of the arc of length l (scaled), with the model's compliances and loads.
ArcMatrix arc_exponential(const ArchModel& model, const CircularArc& arc, double l) {
  if (model.curved()) {
    const double k = arc.kappa * model.scales().length;
    return curved_arc_exponential(k, l, model.a_N(), model.a_V(), model.curved_bar(k), model.self_weight(),
                                  model.acceleration() * model.self_weight());
  }
  return ogive::arc_exponential(arc.kappa * model.scales().length, l, model.a_N(), model.a_V(), model.self_weight(),
                                model.acceleration() * model.self_weight());
}

ArcPiece arc_piece(const ArchModel& model, const CircularArc& arc, double ds0, double ds1) {
  const double th0 = tangent_angle(model, arc, ds0), th1 = tangent_angle(model, arc, ds1);
  return {arc_exponential(model, arc, ds1 - ds0), std::cos(th0), std::sin(th0), std::cos(th1), std::sin(th1)};
}

// Transfer over [ds0, ds1] of one arc.
Transfer arc_transfer(const ArchModel& model, const CircularArc& arc, double ds0, double ds1) {
  const ArcPiece a = arc_piece(model, arc, ds0, ds1);
  const SystemMatrix back = to_local(a.c1, a.sn1).transpose();
  Transfer t;
  t.Phi = back * a.E.topLeftCorner<6, 6>() * to_local(a.c0, a.sn0);
  t.p = back * (a.E.block<6, 1>(0, kCos) * a.c0 + a.E.block<6, 1>(0, kSin) * a.sn0);
  return t;
}

// The state at s1 from the state y at s0 (scaled, s0 <= s1): the arcs' transfers applied to the vector,
// a matrix-vector product each instead of the 6 x 6 transfer's two matrix products.
StateVector closed_form_state(const ArchModel& model, double s0, StateVector y, double s1) {
  const double L = model.scales().length;
  for (const CircularArc& arc : model.curve().arcs()) {
    const double a0 = arc.s_start / L, a1 = (arc.s_start + arc.length) / L;
    const double lo = std::max(s0, a0), hi = std::min(s1, a1);
    if (hi <= lo) continue;
    const ArcPiece a = arc_piece(model, arc, lo - a0, hi - a0);
    Eigen::Matrix<double, 8, 1> local;
    local << to_local(a.c0, a.sn0) * y, a.c0, a.sn0;
    y = to_local(a.c1, a.sn1).transpose() * (a.E * local).head<6>();
  }
  return y;
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
    // The piece's start in local components once (its sine and cosine among them), then each station a
    // matrix-vector product: the same arithmetic as closed_form_state's on one arc.
    const ArchModel& model = *model_;
    const double L = model.scales().length;
    const auto arcs = model.curve().arcs();
    const auto arc = std::find_if(arcs.begin(), arcs.end(), [&](const CircularArc& a) {
      return a.s_start / L <= s_k && s_k < (a.s_start + a.length) / L;
    });
    std::size_t i = 0;
    if (arc != arcs.end()) {
      const double a0 = arc->s_start / L, a1 = (arc->s_start + arc->length) / L;
      const double th0 = tangent_angle(model, *arc, s_k - a0);
      const double c0 = std::cos(th0), sn0 = std::sin(th0);
      Eigen::Matrix<double, 8, 1> local;
      local << to_local(c0, sn0) * y_k, c0, sn0;
      for (; i < s.size() && s[i] <= a1; ++i) {
        const double th1 = tangent_angle(model, *arc, s[i] - a0);
        const ArcMatrix E = arc_exponential(model, *arc, s[i] - s_k);
        out[i] = s[i] > s_k ? to_local(std::cos(th1), std::sin(th1)).transpose() * (E * local).head<6>() : y_k;
      }
    }
    for (; i < s.size(); ++i) out[i] = closed_form_state(model, s_k, y_k, s[i]);
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
