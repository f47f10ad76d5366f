#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <tuple>
#include <memory>
#include <optional>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <Eigen/LU>
#include <fmt/format.h>

#include "methods/bvp.hpp"
#include "numerics/chebyshev.hpp"
#include "methods/damped_newton.hpp"
#include "methods/no_tension.hpp"
#include "ogive/model/section.hpp"

namespace ogive {
namespace {

// Boost's Gauss-Kronrod rule G7-K15 unfolded onto [-1, 1]: the 15 Kronrod nodes ascending, their
// weights, and the 7-point Gauss rule's weights at the same nodes (0 at the Kronrod-only ones). Boost
// tabulates the non-negative half; the Gauss nodes are its even-numbered abscissae (0 among them).
constexpr int kNodes = 15;
struct KronrodRule {
  std::array<double, kNodes> node{}, kronrod{}, gauss{};
};
const KronrodRule& kronrod_rule() {
  static const KronrodRule rule = [] {
    using Kronrod = boost::math::quadrature::gauss_kronrod<double, kNodes>;
    using Gauss = boost::math::quadrature::gauss<double, kNodes / 2>;
    KronrodRule r;
    const auto& x = Kronrod::abscissa();
    const auto& wk = Kronrod::weights();
    const auto& wg = Gauss::weights();
    constexpr int mid = kNodes / 2;
    for (int i = 0; i <= mid; ++i) {
      const auto u = static_cast<std::size_t>(i);
      const double g = i % 2 == 0 ? wg[u / 2] : 0.0;
      r.node[static_cast<std::size_t>(mid + i)] = x[u];
      r.node[static_cast<std::size_t>(mid - i)] = -x[u];
      r.kronrod[static_cast<std::size_t>(mid + i)] = r.kronrod[static_cast<std::size_t>(mid - i)] = wk[u];
      r.gauss[static_cast<std::size_t>(mid + i)] = r.gauss[static_cast<std::size_t>(mid - i)] = g;
    }
    return r;
  }();
  return rule;
}

// The known functions of s the forces are made of (scaled): with the springing's forces (Fx0, Fy0, M0),
//   Fx = Fx0 - H(s),  Fy = Fy0 + B(s),  M = M0 + Fx0 (y - y0) - Fy0 (x - x0) - C(s),
// B the vertical load from 0 to s (point loads included, one at s = 0 too), H the horizontal load from 0
// to s (0 without a horizontal acceleration), C = int_0^s (cos(theta) B + sin(theta) H) ds. On each
// piece between the model's breakpoints (where b, h and theta are smooth, and B jumps at point loads) B,
// H and C are Chebyshev series, built by the Clenshaw-Curtis cumulative integral and doubled in degree until
// their last coefficients fall to round-off: nested integrals of known functions, exact to round-off.
// The axis point and angle come from the curve itself.
struct Point {
  double x = 0, y = 0, c = 1, sn = 0, B = 0, C = 0, H = 0;
};

class Geometry {
 public:
  explicit Geometry(const ArchModel& model) : model_(model) {
    knots_ = {0.0};
    for (double b : model.breakpoints()) knots_.push_back(b);
    knots_.push_back(model.length());
    double B = jumps_at(0.0), C = 0, H = 0;
    for (std::size_t k = 0; k + 1 < knots_.size(); ++k) {
      pieces_.push_back(build_piece(knots_[k], knots_[k + 1], B, C, H));
      const Piece& p = pieces_.back();
      B = chebyshev_series(p.B.data(), p.degree, 1.0) + jumps_at(knots_[k + 1]);
      C = chebyshev_series(p.C.data(), p.degree, 1.0);
      if (horizontal()) H = chebyshev_series(p.H.data(), p.degree, 1.0);
    }
    B_end_ = B;  // after a point load at the end (the end state's Fy, as the shooting's yS)
    start_ = at(0.0, 0);
    end_ = at(model.length(), pieces_.size() - 1);
  }
  const std::vector<double>& knots() const { return knots_; }
  std::size_t pieces() const { return pieces_.size(); }
  // The piece holding s, left-continuous: a knot belongs to the piece that ends there (the state before
  // a point load), s = 0 to the first.
  std::size_t piece_of(double s) const {
    const auto after = std::lower_bound(knots_.begin() + 1, knots_.end() - 1, s);
    return static_cast<std::size_t>(after - (knots_.begin() + 1));
  }
  Point at(double s, std::size_t piece) const {
    const Piece& p = pieces_[piece];
    const double L = model_.scales().length;
    const CurvePoint q = model_.curve().at(s * L);
    const double u = std::clamp((2 * s - p.a - p.b) / (p.b - p.a), -1.0, 1.0);
    const Eigen::Array2d BC = chebyshev_series(p.B.data(), p.C.data(), p.degree, u);
    const double H = horizontal() ? chebyshev_series(p.H.data(), p.degree, u) : 0.0;
    return {q.x / L, q.y / L, std::cos(q.theta), std::sin(q.theta), BC[0], BC[1], H};
  }
  const Point& start() const { return start_; }
  const Point& end() const { return end_; }
  double B_end() const { return B_end_; }
  std::int64_t evaluations() const { return evaluations_; }

 private:
  struct Piece {
    double a = 0, b = 0;
    int degree = 0;
    Eigen::VectorXd B, C, H;  // Chebyshev coefficients on [a, b] (H only with a horizontal load)
  };
  bool horizontal() const { return model_.acceleration() != 0; }
  double jumps_at(double s) const {
    double f = 0;
    for (const PointJump& j : model_.jumps())
      if (j.s == s) f += j.force;
    return f;
  }
  Piece build_piece(double a, double b, double B_a, double C_a, double H_a) {
    Piece p;
    p.a = a;
    p.b = b;
    const double h = 0.5 * (b - a);
    for (int degree = 16;; degree *= 2) {
      const ChebyshevRule& rule = chebyshev_rule(degree);
      Eigen::VectorXd load(degree + 1), cosine(degree + 1), push(degree + 1), sine(degree + 1);
      // The ends' values are the one-sided limits from inside the piece (a live load starts or stops at
      // a knot, a pointed crown turns there, and angle() gives the value from the left): extrapolated
      // linearly from 1e-9 and 2e-9 of the piece inside, where b and theta are smooth (error of order
      // 1e-18 of the piece's second derivatives).
      const double inward = 1e-9 * (b - a);
      auto sample = [&](double s, int i) {
        const double theta = model_.theta(s);
        load[i] = model_.load(s);
        cosine[i] = std::cos(theta);
        if (!horizontal()) return;
        push[i] = model_.horizontal_load(s);
        sine[i] = std::sin(theta);
      };
      for (int i = 1; i < degree; ++i) sample(0.5 * (a + b) + h * rule.node[i], i);
      for (auto [i, end, step] : {std::tuple{0, a, inward}, std::tuple{degree, b, -inward}}) {
        sample(end + 2 * step, i);
        const double load2 = load[i], cosine2 = cosine[i], push2 = push[i], sine2 = sine[i];
        sample(end + step, i);
        load[i] = 2 * load[i] - load2;
        cosine[i] = 2 * cosine[i] - cosine2;
        push[i] = 2 * push[i] - push2;
        sine[i] = 2 * sine[i] - sine2;
      }
      evaluations_ += degree + 3;
      const Eigen::VectorXd Bv = (B_a + (h * (rule.integration * load)).array()).matrix();
      Eigen::VectorXd moment = cosine.cwiseProduct(Bv), Hv;
      if (horizontal()) {
        Hv = (H_a + (h * (rule.integration * push)).array()).matrix();
        moment += sine.cwiseProduct(Hv);
      }
      const Eigen::VectorXd Cv = (C_a + (h * (rule.integration * moment)).array()).matrix();
      p.degree = degree;
      p.B = rule.to_coefficients * Bv;
      p.C = rule.to_coefficients * Cv;
      if (horizontal()) p.H = rule.to_coefficients * Hv;
      // Converged when the last two coefficients of both are at round-off of the largest.
      auto resolved = [](const Eigen::VectorXd& a) {
        const Eigen::Index n = a.size();
        return std::max(std::abs(a[n - 1]), std::abs(a[n - 2])) <= 4e-16 * a.cwiseAbs().maxCoeff() * std::sqrt(double(n));
      };
      if ((resolved(p.B) && resolved(p.C) && (!horizontal() || resolved(p.H))) || degree == kMaxChebyshevDegree)
        return p;
    }
  }

  const ArchModel& model_;
  std::vector<double> knots_;
  std::vector<Piece> pieces_;
  Point start_, end_;
  double B_end_ = 0;
  std::int64_t evaluations_ = 0;
};

// The integrands: five values (kappa, kappa y, kappa x, and the axis' own stretching and shear in x and
// y: gx = eps c - a_V V sn, gy = eps sn + a_V V c) and their derivatives with respect to the springing's
// forces (Fx0, Fy0, M0): value v at f[v], its derivative by force j at f[kValues + 3 v + j].
constexpr int kValues = 5;
constexpr int kIntegrands = kValues * 4;
enum Value : int { kKappa = 0, kKappaY = 1, kKappaX = 2, kGx = 3, kGy = 4 };
using Integrands = Eigen::Matrix<double, kIntegrands, 1>;

struct Forces {
  double Fx, Fy, M, N, V;
};
Forces forces_at(const Point& g, const Point& origin, const StateVector& y0) {
  Forces f;
  f.Fx = y0[kFx] - g.H;
  f.Fy = y0[kFy] + g.B;
  f.M = y0[kM] + y0[kFx] * (g.y - origin.y) - y0[kFy] * (g.x - origin.x) - g.C;
  f.N = g.c * f.Fx + g.sn * f.Fy;
  f.V = -g.sn * f.Fx + g.c * f.Fy;
  return f;
}
// N < 0 and |M / N| < t / 2: the section's domain (section.hpp), checked before anything is integrated.
bool admissible(const Forces& f, double t) { return f.N < 0 && std::abs(f.M) < -f.N * 0.5 * t; }

// The round-off in the values at one node: N and M are sums of terms (forces_at) each rounded to a few
// units of round-off of its size (the geometry's x, y, B and C, exact to round-off, included), and the
// section's law turns an error dN, dM into |kappa_N| dN + |kappa_M| dM, which near a hinge (u -> 0) grows
// as 1 / u^3: there round-off, not the rule, bounds what any quadrature of these integrands can reach.
void node_noise(const Point& g, const Point& origin, const StateVector& y0, const Forces& F, const SectionStrain& ss,
                double* noise) {
  constexpr double kUnits = 4 * std::numeric_limits<double>::epsilon();
  const double dN =
      kUnits * (std::abs(g.c * F.Fx) + std::abs(g.c * g.H) + std::abs(g.sn * F.Fy) + std::abs(g.sn * g.B));
  const double dM = kUnits * (std::abs(y0[kM]) + std::abs(y0[kFx] * (g.y - origin.y)) +
                              std::abs(y0[kFy] * (g.x - origin.x)) + std::abs(g.C));
  const double dk = std::abs(ss.kappa_N) * dN + std::abs(ss.kappa_M) * dM;
  const double de = std::abs(ss.eps_N) * dN + std::abs(ss.eps_M) * dM;
  noise[kKappa] = dk;
  noise[kKappaY] = dk * std::abs(g.y);
  noise[kKappaX] = dk * std::abs(g.x);
  noise[kGx] = de * std::abs(g.c);
  noise[kGy] = de * std::abs(g.sn);
}

// The integrands at node g (false where the section is inadmissible); with noise, each value's round-off
// (node_noise) too.
bool integrands(const Point& g, const Point& origin, const StateVector& y0, double t, double aV, double* f,
                double* noise = nullptr) {
  const Forces F = forces_at(g, origin, y0);
  const SectionStrain ss = section_strain(SectionKind::no_tension, F.N, F.M, t);
  if (!ss.admissible) return false;
  if (noise) node_noise(g, origin, y0, F, ss, noise);
  f[kKappa] = ss.kappa;
  f[kKappaY] = ss.kappa * g.y;
  f[kKappaX] = ss.kappa * g.x;
  f[kGx] = ss.eps * g.c - aV * F.V * g.sn;
  f[kGy] = ss.eps * g.sn + aV * F.V * g.c;
  const double dN[3] = {g.c, g.sn, 0}, dM[3] = {g.y - origin.y, origin.x - g.x, 1}, dV[3] = {-g.sn, g.c, 0};
  for (int j = 0; j < 3; ++j) {
    const double dk = ss.kappa_N * dN[j] + ss.kappa_M * dM[j], de = ss.eps_N * dN[j] + ss.eps_M * dM[j];
    f[kValues + 3 * kKappa + j] = dk;
    f[kValues + 3 * kKappaY + j] = dk * g.y;
    f[kValues + 3 * kKappaX + j] = dk * g.x;
    f[kValues + 3 * kGx + j] = de * g.c - aV * dV[j] * g.sn;
    f[kValues + 3 * kGy + j] = de * g.sn + aV * dV[j] * g.c;
  }
  return true;
}

// The state at a point g from the integrals I from 0 to it (the values' part is enough):
//   psi = psi0 + K,   Ux = Ux0 + Gx - psi0 (y - y0) - (K y - KY),   Uy = Uy0 + Gy + psi0 (x - x0) + (K x - KX)
// (int_0^s psi sn ds = int psi dy, by parts), the forces explicit. B is given: the end's is after a
// point load there.
StateVector state_at(const Point& g, double B, const Point& origin, const StateVector& y0, const Integrands& I) {
  StateVector y;
  const double dx = g.x - origin.x, dy = g.y - origin.y;
  y[kPsi] = y0[kPsi] + I[kKappa];
  y[kUx] = y0[kUx] + I[kGx] - y0[kPsi] * dy - (I[kKappa] * g.y - I[kKappaY]);
  y[kUy] = y0[kUy] + I[kGy] + y0[kPsi] * dx + (I[kKappa] * g.x - I[kKappaX]);
  y[kFx] = y0[kFx] - g.H;
  y[kFy] = y0[kFy] + B;
  y[kM] = y0[kM] + y0[kFx] * dy - y0[kFy] * dx - g.C;
  return y;
}

// A panel of the adaptive quadrature with its nodes' known functions (kept while Newton iterates: only
// the integrands change with the unknowns) and, for the current unknowns, its Kronrod integrals, its
// error (|K15 - G7| of the values), the values' L1 norms and their round-off (the rule's weights times
// node_noise: what |K15 - G7| cannot fall below however small the panel).
struct Panel {
  double a = 0, b = 0;
  std::size_t piece = 0;
  std::array<Point, kNodes> nodes;
  Integrands kronrod = Integrands::Zero();
  std::array<double, kValues> error{}, l1{}, noise{};
  // At its round-off: each value's |K15 - G7| within kNoiseFactor of the noise both rules carry (the
  // difference of two sums each off by up to the noise), so that halving it cannot lower its error.
  static constexpr double kNoiseFactor = 2;
  bool at_noise() const {
    for (std::size_t v = 0; v < kValues; ++v)
      if (error[v] > kNoiseFactor * noise[v]) return false;
    return true;
  }
};

// The adaptive G7-K15 quadrature of the integrands over [0, S~], panels between the model's knots.
// Global: the panels whose share of the error is largest are halved until the sum over the panels of
// the largest value error (each value's |K15 - G7| over its L1 norm over the domain) is at most tol, or
// until every panel above its share is at its round-off (Panel::at_noise: near a hinge whose compressed
// depth is a tiny fraction of t, the section law amplifies round-off in M beyond tol) or too narrow:
// that sum is then the accuracy the integrals have, above tol (accuracy()). The panels are kept from one
// call to the next (the peaks move little between Newton's iterates).
class AdaptiveQuadrature {
 public:
  AdaptiveQuadrature(const ArchModel& model, const Geometry& geometry, double tol)
      : geometry_(geometry), tol_(tol), t_(model.scene().thickness / model.scales().length), aV_(model.a_V()) {
    // At least 32 panels over the domain: a curvature peak narrower than the panels' nodes could
    // otherwise hide between them in a first evaluation.
    const double S = model.length();
    const auto& knots = geometry.knots();
    for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
      const int n = std::max(1, static_cast<int>(std::ceil(kInitialPanels * (knots[k + 1] - knots[k]) / S)));
      for (int i = 0; i < n; ++i)
        panels_.push_back(make_panel(knots[k] + (knots[k + 1] - knots[k]) * i / n,
                                     i + 1 == n ? knots[k + 1] : knots[k] + (knots[k + 1] - knots[k]) * (i + 1) / n, k));
    }
    min_width_ = 1e-13 * S;
  }

  // The integrals over the domain at the springing state y0 and the values' L1 norms; false when a node
  // is inadmissible. Their accuracy (the sum of the panels' relative errors) is accuracy().
  bool integrate(const StateVector& y0, Integrands& total, std::array<double, kValues>& l1) {
    at_.reset();
    accuracy_ = std::numeric_limits<double>::infinity();
    if (spent()) return false;
    // Admissibility first, on every node, before any integrand is formed.
    for (const Panel& p : panels_)
      for (const Point& g : p.nodes)
        if (!admissible(forces_at(g, geometry_.start(), y0), t_)) return false;
    for (Panel& p : panels_)
      if (!evaluate(p, y0)) return false;
    for (int round = 0;; ++round) {
      l1.fill(0);
      for (const Panel& p : panels_)
        for (int v = 0; v < kValues; ++v) l1[static_cast<std::size_t>(v)] += p.l1[static_cast<std::size_t>(v)];
      std::vector<double> share(panels_.size());
      double sum = 0;
      for (std::size_t i = 0; i < panels_.size(); ++i) {
        double e = 0;
        for (std::size_t v = 0; v < kValues; ++v) e = std::max(e, panels_[i].error[v] / std::max(l1[v], 1e-300));
        share[i] = e;
        sum += e;
      }
      accuracy_ = sum;
      // Below the tolerance round-off allows, halving would go on until memory ran out (found: rtol 1e-14
      // was killed at several GB): a bounded number of panels, at most, and the accuracy reached.
      if (sum <= tol_ || round == kMaxRounds || panels_.size() > kMaxPanels) break;
      // Halve every panel above the mean share that is still wide enough and above its round-off.
      const double threshold = tol_ / static_cast<double>(panels_.size());
      std::vector<Panel> next;
      next.reserve(panels_.size() + 16);
      bool split = false;
      for (std::size_t i = 0; i < panels_.size(); ++i) {
        const Panel& p = panels_[i];
        if (share[i] > threshold && p.b - p.a > min_width_ && !p.at_noise()) {
          const double mid = 0.5 * (p.a + p.b);
          if (spent()) return false;
          for (auto [a, b] : {std::pair{p.a, mid}, std::pair{mid, p.b}}) {
            Panel half = make_panel(a, b, p.piece);
            for (const Point& g : half.nodes)
              if (!admissible(forces_at(g, geometry_.start(), y0), t_)) return false;
            if (!evaluate(half, y0)) return false;
            next.push_back(std::move(half));
          }
          split = true;
        } else {
          next.push_back(p);
        }
      }
      panels_ = std::move(next);
      if (!split) break;
    }
    total.setZero();
    for (const Panel& p : panels_) total += p.kronrod;
    at_ = y0;
    return true;
  }
  // Whether the panels hold the integrals at y0 (the last successful integrate was there).
  bool holds(const StateVector& y0) const { return at_ && *at_ == y0; }
  // The last integration's relative accuracy: the sum of the panels' value errors over their L1 norms
  // (at most tol unless round-off or the bounds on the panels stopped it above).
  double accuracy() const { return accuracy_; }

  const std::vector<Panel>& panels() const { return panels_; }
  std::int64_t evaluations() const { return evaluations_; }
  // At most `evaluations` integrand evaluations: beyond, integrate() fails (as for an inadmissible node).
  void allow(std::int64_t evaluations) { budget_ = evaluations; }
  bool spent() const { return evaluations_ >= budget_; }

 private:
  static constexpr int kInitialPanels = 32;
  static constexpr int kMaxRounds = 60;
  static constexpr std::size_t kMaxPanels = 8192;  // about 120 times what a cracked arch needs at rtol 1e-12

  Panel make_panel(double a, double b, std::size_t piece) const {
    Panel p;
    p.a = a;
    p.b = b;
    p.piece = piece;
    const KronrodRule& r = kronrod_rule();
    const double mid = 0.5 * (a + b), h = 0.5 * (b - a);
    for (std::size_t i = 0; i < kNodes; ++i) p.nodes[i] = geometry_.at(mid + h * r.node[i], piece);
    return p;
  }
  bool evaluate(Panel& p, const StateVector& y0) {
    const KronrodRule& r = kronrod_rule();
    const double h = 0.5 * (p.b - p.a);
    Integrands f, gauss = Integrands::Zero();
    std::array<double, kValues> noise{};
    p.kronrod.setZero();
    p.l1.fill(0);
    p.noise.fill(0);
    for (std::size_t i = 0; i < kNodes; ++i) {
      if (!integrands(p.nodes[i], geometry_.start(), y0, t_, aV_, f.data(), noise.data())) return false;
      p.kronrod += r.kronrod[i] * f;
      if (r.gauss[i] != 0) gauss += r.gauss[i] * f;
      for (std::size_t v = 0; v < kValues; ++v) {
        p.l1[v] += r.kronrod[i] * std::abs(f[static_cast<Eigen::Index>(v)]);
        p.noise[v] += r.kronrod[i] * noise[v];
      }
    }
    evaluations_ += kNodes;
    p.kronrod *= h;
    for (std::size_t v = 0; v < kValues; ++v) {
      p.error[v] = h * std::abs(p.kronrod[static_cast<Eigen::Index>(v)] / h - gauss[static_cast<Eigen::Index>(v)]);
      p.l1[v] *= h;
      p.noise[v] *= h;
    }
    return true;
  }

  const Geometry& geometry_;
  std::vector<Panel> panels_;
  std::optional<StateVector> at_;
  double tol_, t_, aV_, min_width_ = 0;
  double accuracy_ = std::numeric_limits<double>::infinity();
  std::int64_t evaluations_ = 0;
  std::int64_t budget_ = kUnlimitedWork;
};

// One evaluation of the end's three conditions and their Jacobian in the springing's unknowns z.
struct Evaluation {
  bool ok = false;
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;
  StateVector y0, yS;
  Eigen::Matrix<double, kStateSize, 3> dyS_dz = Eigen::Matrix<double, kStateSize, 3>::Zero();
  double kinematic_scale = 1;  // the size the end's displacements and rotation are integrated against
  double accuracy = 0;         // the integrals' relative accuracy (AdaptiveQuadrature::accuracy)
};

class QuadratureShooter {
 public:
  QuadratureShooter(const ArchModel& model, double tol)
      : model_(model), geometry_(std::make_shared<const Geometry>(model)), quadrature_(model, *geometry_, tol),
        split_(springing_split(model)) {}

  Evaluation evaluate(const Eigen::Vector3d& z) {
    Evaluation e;
    e.y0 = split_.start + split_.U * z;
    Integrands I;
    std::array<double, kValues> l1{};
    if (!quadrature_.integrate(e.y0, I, l1)) return e;
    e.accuracy = quadrature_.accuracy();
    const Point& o = geometry_->start();
    const Point& g = geometry_->end();
    e.yS = state_at(g, geometry_->B_end(), o, e.y0, I);
    // d yS / d y0, column by springing component (the rigid motions' columns exact).
    SystemMatrix D = SystemMatrix::Identity();
    D(kUx, kPsi) = -(g.y - o.y);
    D(kUy, kPsi) = g.x - o.x;
    D(kM, kFx) = g.y - o.y;
    D(kM, kFy) = -(g.x - o.x);
    const int force[3] = {kFx, kFy, kM};
    auto d = [&](int value, int j) { return I[kValues + 3 * value + j]; };
    for (int j = 0; j < 3; ++j) {
      D(kPsi, force[j]) = d(kKappa, j);
      D(kUx, force[j]) = d(kGx, j) - (d(kKappa, j) * g.y - d(kKappaY, j));
      D(kUy, force[j]) = d(kGy, j) + (d(kKappa, j) * g.x - d(kKappaX, j));
    }
    const BoundaryConditions& bc = model_.boundary_conditions();
    const Eigen::Matrix<double, 3, kStateSize> B = bc.at_end.bottomRows<3>();
    e.residual = B * e.yS - bc.rhs.tail<3>();
    e.dyS_dz = D * split_.U;
    e.jacobian = B * e.dyS_dz;
    e.kinematic_scale = std::max(1.0, l1[kKappa] * (1 + std::abs(g.x) + std::abs(g.y)) + l1[kKappaY] + l1[kKappaX] +
                                          l1[kGx] + l1[kGy]);
    e.ok = true;
    return e;
  }
  const std::shared_ptr<const Geometry>& geometry() const { return geometry_; }
  const AdaptiveQuadrature& quadrature() const { return quadrature_; }
  AdaptiveQuadrature& quadrature() { return quadrature_; }
  const SpringingSplit& split() const { return split_; }

 private:
  const ArchModel& model_;
  std::shared_ptr<const Geometry> geometry_;
  AdaptiveQuadrature quadrature_;
  SpringingSplit split_;
};

// The field: the same integrals from 0 to any s, the last panel's part by the Kronrod rule over [a, s]
// (a part of a panel that met the tolerance is resolved at least as well).
class QuadratureField final : public StateField {
 public:
  QuadratureField(std::shared_ptr<const ArchModel> model, const QuadratureShooter& shooter, const StateVector& y0)
      : model_(std::move(model)), geometry_(shooter.geometry()), y0_(y0),
        t_(model_->scene().thickness / model_->scales().length) {
    // The cumulative integrals at every panel's start (the panels of the last evaluation, at y0).
    Integrands sum = Integrands::Zero();
    for (const Panel& p : shooter.quadrature().panels()) {
      a_.push_back(p.a);
      piece_.push_back(p.piece);
      cumulative_.push_back(sum);
      sum += p.kronrod;
    }
  }
  void sample(std::span<const double> s, std::span<StateVector> out) const override {
    const KronrodRule& r = kronrod_rule();
    const double aV = model_->a_V();
    for (std::size_t n = 0; n < s.size(); ++n) {
      // The panel holding s, left-continuous at the knots as the geometry's pieces.
      const Geometry& geometry = *geometry_;
      const std::size_t piece = geometry.piece_of(s[n]);
      auto after = std::upper_bound(a_.begin(), a_.end(), s[n]);
      std::size_t k = after == a_.begin() ? 0 : static_cast<std::size_t>(after - a_.begin()) - 1;
      while (k > 0 && piece_[k] > piece) --k;  // s at a knot: the panel before it
      Integrands I = cumulative_[k], f;
      const double mid = 0.5 * (a_[k] + s[n]), h = 0.5 * (s[n] - a_[k]);
      bool ok = true;
      for (std::size_t i = 0; i < kNodes && h > 0; ++i) {
        ok = ok && integrands(geometry.at(mid + h * r.node[i], piece), geometry.start(), y0_, t_, aV, f.data());
        I += h * r.kronrod[i] * f;
      }
      const Point g = geometry.at(s[n], piece);
      out[n] = ok ? state_at(g, g.B, geometry.start(), y0_, I)
                  : StateVector::Constant(std::numeric_limits<double>::quiet_NaN());
    }
  }

 private:
  std::shared_ptr<const ArchModel> model_;  // (the geometry refers to it)
  std::shared_ptr<const Geometry> geometry_;
  StateVector y0_;
  double t_;
  std::vector<double> a_;
  std::vector<std::size_t> piece_;
  std::vector<Integrands> cumulative_;
};

// What the integrals' errors and Newton's last residual leave in the reactions, to first order through
// Newton's matrix J. A panel's error in the values (the larger of |K15 - G7| and its round-off) moves
// the end's state along known directions: dK turns the end by dK about the panel's middle (psi by dK, Ux
// by -dK (y_S - y_m), Uy by dK (x_S - x_m)), dGx and dGy move it along x and y; each direction is carried
// through J^-1 B (B the end's conditions) and the panels' parts added in absolute value, with Newton's
// remaining step J^-1 r. The errors of one panel thus keep their correlation: near a hinge they turn the
// end about it, which J resists most (the soft direction of a mechanism is another). Each unknown's
// error is then carried through the reactions (the end's forces are explicit in z) and the parts'
// reaction_difference (the verification's measure) added. Infinite when J is singular.
double reaction_floor(const ArchModel& model, const SpringingSplit& split, const Evaluation& e,
                      const std::vector<Panel>& panels, const Point& end) {
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(e.jacobian);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  const Eigen::Matrix<double, 3, kStateSize> JB = lu.inverse() * model.boundary_conditions().at_end.bottomRows<3>();
  Eigen::Vector3d dz = (lu.inverse() * e.residual).cwiseAbs();
  for (const Panel& p : panels) {
    const Point& m = p.nodes[kNodes / 2];
    auto bound = [&](Value v) { return std::max(p.error[static_cast<std::size_t>(v)], p.noise[static_cast<std::size_t>(v)]); };
    const Eigen::Vector3d turn = JB.col(kPsi) - (end.y - m.y) * JB.col(kUx) + (end.x - m.x) * JB.col(kUy);
    dz += turn.cwiseAbs() * bound(kKappa) + JB.col(kUx).cwiseAbs() * bound(kGx) + JB.col(kUy).cwiseAbs() * bound(kGy);
  }
  const Reactions at = model.reactions(e.y0, e.yS);
  double floor = 0;
  for (int j = 0; j < 3; ++j) {
    const StateVector y0 = e.y0 + split.U.col(j) * dz[j], yS = e.yS + e.dyS_dz.col(j) * dz[j];
    floor += reaction_difference(model.reactions(y0, yS), at, model.scene().thickness);
  }
  return floor;
}

// The quadrature's tolerance: well below rtol (its |K15 - G7| overstates the Kronrod rule's error by
// orders of magnitude on resolved panels), above round-off.
double quadrature_tolerance(double rtol) { return std::max(1e-2 * rtol, 1e-14); }

}  // namespace

ShootingResidual no_tension_quadrature_residual(const ArchModel& model, const Options& options, const StateVector& y0) {
  QuadratureShooter shooter(model, quadrature_tolerance(options.rtol));
  const Evaluation e = shooter.evaluate(shooter.split().U.transpose() * y0);
  ShootingResidual out;
  if (!e.ok) return out;
  out.ok = true;
  out.residual = e.residual;
  out.jacobian = e.jacobian;
  return out;
}

Solution solve_no_tension_quadrature(std::shared_ptr<const ArchModel> model, const Options& options,
                                     std::span<const StateVector> guesses, std::int64_t budget) {
  Solution sol;
  sol.method = Method::quadrature;
  sol.model = model;
  if (model->hinge()) {
    sol.status = Status::not_applicable;
    sol.message = "the no-tension section does not take a crown hinge over the whole arch";
    return sol;
  }
  const double tol = quadrature_tolerance(options.rtol);
  QuadratureShooter shooter(*model, tol);
  const std::int64_t geometry_work = shooter.geometry()->evaluations();
  shooter.quadrature().allow(budget > geometry_work ? budget - geometry_work : 0);
  auto count_work = [&] {
    sol.diagnostics.rhs_evaluations = shooter.quadrature().evaluations() + shooter.geometry()->evaluations();
    sol.diagnostics.segments = static_cast<int>(shooter.quadrature().panels().size());
  };
  // The first guess: the first given one that is admissible at every node, else the most admissible.
  Eigen::VectorXd x(3);
  Evaluation e;
  const bool started = first_guess(*model, guesses, [&](const StateVector& y0) {
    x = shooter.split().U.transpose() * y0;
    e = shooter.evaluate(x);
    return e.ok;
  }, sol);
  if (!started) {
    count_work();
    if (sol.status == Status::not_converged && shooter.quadrature().spent())
      sol.message = work_budget_message(budget, sol.method);
    return sol;
  }
  // At the noise: the residual within 10 times what the integrals' tolerance, or the accuracy they
  // reached above it (round-off near a hinge), leaves in the end's conditions.
  const bool converged = damped_newton(
      [&](const Eigen::VectorXd& trial) { return shooter.evaluate(trial); },
      [&](const Evaluation& at) {
        return at.residual.lpNorm<Eigen::Infinity>() <= 10 * std::max(tol, at.accuracy) * at.kinematic_scale;
      },
      1e-2 * options.rtol, x, e, sol);
  count_work();
  if (!converged) {
    if (shooter.quadrature().spent()) sol.message = work_budget_message(budget, sol.method);
    return sol;
  }
  // The last accepted evaluation is at x, but the panels may since have been refined by rejected trials:
  // evaluate once more, so that the field's panels hold the integrals at the solution.
  // (one evaluation more, whatever the budget: its work is bounded by the panels' limits)
  shooter.quadrature().allow(kUnlimitedWork);
  if (!shooter.quadrature().holds(e.y0)) e = shooter.evaluate(x);
  if (!e.ok) {
    sol.status = Status::not_converged;
    sol.message = "the converged state could not be integrated again";
    count_work();
    return sol;
  }
  count_work();
  BvpSolution bvp;
  bvp.y0 = e.y0;
  bvp.yS = e.yS;
  bvp.knots = shooter.geometry()->knots();
  // The condition of Newton's last matrix (the linearised problem's), Skeel's measure as every method's.
  bvp.condition = boundary_value_condition(e.jacobian);
  finish_solution(sol, bvp, std::make_shared<QuadratureField>(model, shooter, e.y0));
  if (!sol.field) return sol;
  sol.diagnostics.error_estimate =
      reaction_floor(*model, shooter.split(), e, shooter.quadrature().panels(), shooter.geometry()->end());
  // The end's conditions are differences of integrals that a hinge's rotations make much larger than
  // the scaled units' one: their residual is measured against the integrals' size, as Newton's is.
  sol.diagnostics.boundary_residual /= e.kinematic_scale;
  return sol;
}

}  // namespace ogive
