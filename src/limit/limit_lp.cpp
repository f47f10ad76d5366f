// The linear programs of limit analysis: built here, solved by the dense simplex method (dense_lp.cpp)
// or by COIN-OR Clp, the independent reference. The only file that includes the LP library.
//
// Why Clp (coinor-libclp-dev) rather than GLPK (libglpk-dev): Clp's licence (EPL-2.0) lets ogive link it
// without becoming GPL, which GLPK (GPL-3) would impose on every binary; Debian ships its pkg-config
// file (clp.pc), so CMake finds it without a module of ours; and it is the faster simplex code of the two
// on repeated small programs.
//
// Each question has at most five unknowns but two inequalities per joint (hundreds). Clp's basis has
// one row per constraint, so the program as written would factorise a basis of hundreds of rows at
// every step. Its dual, min b.y subject to A^T y = c, y >= 0, has one column per joint inequality and a
// row per unknown: a basis of at most 5 x 5. The unknowns are the dual's row prices, from the optimal
// basis. The dense method works on the same dual with its basis as an explicit 5 x 5 matrix, without
// Clp's setup per program (loading the model, its sparse factorisation, its primal cleanup): about ten
// times less time per program on the benchmark's rings, the same optimum to 2e-14.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/LU>

#include <ClpSimplex.hpp>
#include <CoinFinite.hpp>

#include "limit/dense_lp.hpp"
#include "limit/limit_internal.hpp"
#include "limit/limit_lp_impl.hpp"

namespace ogive::limit_detail {
namespace {

// The objective that maximises (or minimises) one unknown.
Objective pushing(Column c, bool maximise) {
  Objective o{};
  o[c] = maximise ? 1.0 : -1.0;
  return o;
}

// Into `h`, whose storage is reused; from row `from` on (the rows before it held already, as they are).
void hold(const std::vector<Inequality>& rows, const std::array<double, kUnknowns>& fixed, Held& h,
          std::size_t from = 0) {
  if (from == 0) {
    h.free.clear();
    h.infeasible = false;
    for (int c = 0; c < kUnknowns; ++c)
      if (std::isnan(fixed[c])) h.free.push_back(c);
  }
  h.b.resize(rows.size());
  for (std::size_t r = from; r < rows.size(); ++r) {
    const Inequality& row = rows[r];
    double b = row.b;
    bool any = false;
    for (int c = 0; c < kUnknowns; ++c)
      if (!std::isnan(fixed[c])) b -= row.a[c] * fixed[c];
      else any = any || row.a[c] != 0.0;
    h.b[r] = b;
    // A row of held unknowns only: it holds or the program is infeasible.
    if (!any && (b < -1e-12 || (row.equality && b > 1e-12))) h.infeasible = true;
  }
}

}  // namespace

struct LpWorkspace::Impl {
  // Made on the first program Clp solves (the dense method solves the others).
  std::unique_ptr<ClpSimplex> model;
  ClpSimplex& clp() {
    if (!model) {
      model = std::make_unique<ClpSimplex>();
      model->setLogLevel(0);
      // The program is scaled already (forces in W, lengths in L: coefficients of order one); Clp's own
      // scaling made it report "optimal" answers that were infeasible once unscaled (secondary status 3).
      model->scaling(0);
      // Clp's dual feasibility tolerance is how far the thrust line may stray outside a joint (in units
      // of W L): its default 1e-7 let the collapse multiplier exceed the kinematic one by 1e-6.
      model->setDualTolerance(kFeasibility);
      model->setPrimalTolerance(kFeasibility);
    }
    return *model;
  }
};

LpWorkspace::LpWorkspace() : impl_(std::make_unique<Impl>()) {}
LpWorkspace::~LpWorkspace() = default;

LimitLp::LimitLp(const Ring& ring, double friction, LpWorkspace* workspace, LpSolver solver, LiveKind live,
                 double compressive_strength)
    : impl_(std::make_unique<Impl>()) {
  impl_->live = live;
  if (!workspace) {
    own_workspace_ = std::make_unique<LpWorkspace>();
    workspace = own_workspace_.get();
  }
  impl_->workspace = workspace->impl_.get();
  impl_->solver = solver;
  load(ring, friction, compressive_strength);
}

void LimitLp::load(const Ring& ring, double friction, double compressive_strength) {
  // The force scale: every load in magnitude (1 for a ring loaded with nothing, where any scale will do).
  double W = 0, dead = 0, live = 0;
  for (const Voussoir& v : ring.voussoirs) {
    W += std::abs(v.dead().force) + std::abs(v.live.force);
    dead += std::abs(v.dead().force);
    live += std::abs(v.live.force);
  }
  impl_->dead_weight = dead;
  impl_->live_weight = live;
  if (!(W > 0)) W = 1;
  const double L = ring.span;
  impl_->weight = W;
  impl_->span = L;
  std::vector<Inequality>& rows = impl_->rows;
  rows.clear();
  Impl& p = *impl_;
  const bool crushing = std::isfinite(compressive_strength);
  p.strength = crushing ? compressive_strength * L / W : std::numeric_limits<double>::infinity();
  p.previous_cuts.swap(p.cuts);
  p.previous_joints = p.normals.size();
  p.cuts.clear();
  p.normals.clear();
  p.row_face.clear();
  p.sliding.clear();
  p.coulomb.clear();
  p.friction = friction;
  LoadsLeftOfJoints& left = impl_->left;
  loads_left_of_joints(ring, left);
  std::size_t pin = 0;
  const bool horizontal = impl_->live == LiveKind::horizontal;
  const double a = horizontal ? 0.0 : ring.acceleration;
  std::vector<RowKey>& keys = impl_->keys;
  keys.clear();
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const std::size_t first = rows.size();
    const Eigen::Vector2d I = ring.joints[j].intrados / L, E = ring.joints[j].extrados / L;
    double D = left.dead[j].force / W, MD = left.dead[j].moment / (W * L);
    const double P = left.live[j].force / W, MP = left.live[j].moment / (W * L);
    // The horizontal dead load a G to the left of the joint and its moment a MG (clockwise).
    const double G = D, MG = left.dead[j].height_moment / (W * L);
    const double aG = a * G, aMG = a * MG;
    // lambda's coefficient in the moment about Q: the live load's Qx P - MP, or the horizontal one's
    // Qy G - MG (then the live load is dead, at factor 1).
    auto factor = [&](const Eigen::Vector2d& Q) { return horizontal ? Q.y() * G - MG : Q.x() * P - MP; };
    if (horizontal) D += P, MD += MP;
    const double h = (E - I).norm();
    // Moment of the joint's force about Q: H Qy - V Qx + M + lambda (Qx P - MP) + (Qx D - MD)
    // + (Qy aG - aMG); <= -mu h about the intrados point, >= mu h about the extrados point, 0 about a
    // pin's axis point.
    auto dead = [&](const Eigen::Vector2d& Q) { return a == 0 ? Q.x() * D - MD : Q.x() * D - MD + (Q.y() * aG - aMG); };
    rows.push_back({{I.y(), -I.x(), 1.0, factor(I), h}, -dead(I)});
    rows.push_back({{-E.y(), E.x(), -1.0, -factor(E), h}, dead(E)});
    if (crushing) {
      // N = n . F, n the normal towards the right-hand part, F = (H + aG, V - D - lambda P).
      const Eigen::Vector2d d = (E - I) / h, n(d.y(), -d.x());
      Impl::Normal& normal = p.normals.emplace_back();  // in place: a copy of it stalled on its stores
      normal.a = {n.x(), n.y(), 0.0, horizontal ? n.x() * G : -n.y() * P, 0.0};
      normal.c = a == 0 ? -n.y() * D : -n.y() * D + n.x() * aG;
      normal.face_row = static_cast<int>(first);
    }
    if (pin < ring.pins.size() && ring.pins[pin] == static_cast<int>(j)) {
      const Eigen::Vector2d A = ring.joints[j].axis / L;
      rows.push_back({{A.y(), -A.x(), 1.0, factor(A), 0.0}, -dead(A), true});
      ++pin;
    }
    if (friction > 0) {
      // Normal n (towards the right-hand part) and direction d of the joint; F = (H + aG, V - D - lambda P).
      const Eigen::Vector2d d = (E - I) / h, n(d.y(), -d.x());
      // v . F as a . z + c (the rows below are such functions of sign d - friction n, <= 0).
      auto linear = [&](const Eigen::Vector2d& v) {
        Impl::Normal f;
        f.a = {v.x(), v.y(), 0.0, horizontal ? v.x() * G : -v.y() * P, 0.0};
        f.c = a == 0 ? -v.y() * D : -v.y() * D + v.x() * aG;
        return f;
      };
      p.sliding.push_back({static_cast<int>(rows.size()), linear(d), linear(n)});
      for (double sign : {1.0, -1.0}) {  // sign * (F . d) - friction * (F . n) <= 0
        const Eigen::Vector2d c = sign * d - friction * n;
        rows.push_back({{c.x(), c.y(), 0.0, horizontal ? c.x() * G : -c.y() * P, 0.0},
                        a == 0 ? c.y() * D : c.y() * D - c.x() * aG});
      }
    }
    for (std::size_t r = first; r < rows.size(); ++r) keys.push_back({ring.joints[j].s, static_cast<int>(r - first)});
    if (crushing)
      for (std::size_t r = first; r < rows.size(); ++r)
        p.row_face.push_back(r - first < 2 ? static_cast<int>(2 * j + (r - first)) : -1);
  }
  const std::size_t tail = rows.size();
  impl_->joint_rows = static_cast<int>(tail);
  // The sign of H and lambda, and the caps. Under a horizontal acceleration the left springing may pull
  // (H < 0: the leeward side holds the arch), so H's row bounds it only beyond the caps.
  rows.push_back({{-1, 0, 0, 0, 0}, a == 0 && !horizontal ? 0.0 : 2 * kCap});
  rows.push_back({{0, 0, 0, -1, 0}, 0.0});
  for (int c = 0; c < kUnknowns; ++c)
    for (double sign : {1.0, -1.0}) {
      Inequality cap{{0, 0, 0, 0, 0}, c == kMu && sign > 0 ? kMaxMargin : kCap};
      cap.a[c] = sign;
      rows.push_back(cap);
    }
  for (std::size_t r = tail; r < rows.size(); ++r)
    keys.push_back({std::numeric_limits<double>::infinity(), static_cast<int>(r - tail)});
  for (Inequality& row : rows) {
    double sum = 0;
    for (double a : row.a) sum += a * a;
    row.norm = std::sqrt(sum);
  }
  p.cuts_begin = static_cast<int>(rows.size());
}

LimitLp::~LimitLp() = default;

std::vector<double> LimitLp::normal_forces(const Answer& a) const {
  const Impl& p = *impl_;
  // The unknowns as the program's (lambda unscaled: the rows' lambda coefficients are for it).
  const std::array<double, kUnknowns> z{a.H / p.weight, a.V / p.weight, a.M / (p.weight * p.span), a.load_factor,
                                        a.margin};
  std::vector<double> out;
  out.reserve(p.sliding.size());
  for (const Impl::Sliding& sl : p.sliding) {
    double N = sl.normal.c;
    for (int c = 0; c < kUnknowns; ++c) N += sl.normal.a[c] * z[c];
    out.push_back(N * p.weight);
  }
  return out;
}

int LimitLp::clp_fallbacks() const { return impl_->fallbacks; }

LimitLp::Answer LimitLp::Impl::unscaled(std::array<double, kUnknowns> z, const Objective& objective) const {
  Answer a;
  a.H = z[kH] * weight;
  a.V = z[kV] * weight;
  a.M = z[kM] * weight * span;
  a.load_factor = z[kLambda] * lambda_scale;
  a.margin = z[kMu];
  a.outcome = Outcome::optimal;
  for (int c = 0; c < kUnknowns; ++c)
    if (objective[c] != 0 && std::abs(z[c]) >= 0.5 * kCap) a.outcome = Outcome::unbounded;
  return a;
}

LimitLp::Answer LimitLp::Impl::optimise(const Objective& objective, const std::array<double, kUnknowns>& fixed,
                                        const std::vector<int>* warm) {
  if (std::isfinite(strength)) return crushed(objective, fixed, warm);
  Held& h = held;
  hold(rows, fixed, h);
  if (h.infeasible) return finish(Solved{Outcome::infeasible, {}, {}}, objective);
  return finish(solve(h, fixed, objective, warm), objective);
}

Inequality LimitLp::Impl::cut_row(int joint, int face, double N0) const {
  // The face's row a . z <= b plus (2 N0 N - N0^2) / (2 f_c), N = n . z + c: linear in z.
  const Normal& n = normals[static_cast<std::size_t>(joint)];
  Inequality row = rows[static_cast<std::size_t>(n.face_row + face)];
  const double k = N0 / strength;
  double sum = 0;
  for (int c = 0; c < kUnknowns; ++c) {
    row.a[c] += k * n.a[c];
    sum += row.a[c] * row.a[c];
  }
  row.b += N0 * N0 / (2 * strength) - k * n.c;
  row.norm = std::sqrt(sum);
  return row;
}

int LimitLp::Impl::add_cut(int joint, int face, double N0) {
  const double force = N0 * weight;
  for (std::size_t i = 0; i < cuts.size(); ++i)
    if (cuts[i].joint == joint && cuts[i].face == face && cuts[i].force == force) return cuts_begin + static_cast<int>(i);
  rows.push_back(cut_row(joint, face, N0));
  cuts.push_back({joint, face, force});
  return static_cast<int>(rows.size()) - 1;
}

std::vector<int> LimitLp::Impl::carried(const std::vector<int>& warm) {
  std::vector<int> out = warm;
  for (int& r : out) {
    const int i = r - cuts_begin;
    if (i < 0 || i < static_cast<int>(cuts.size())) continue;  // this ring's row
    if (i >= static_cast<int>(previous_cuts.size()) || previous_joints != normals.size()) return warm;
    const Cut& c = previous_cuts[static_cast<std::size_t>(i)];
    r = add_cut(c.joint, c.face, c.force / weight);
  }
  return out;
}

std::vector<int> LimitLp::Impl::newton(const std::vector<int>& basis, std::array<double, kUnknowns>& z,
                                       const std::vector<int>& free) {
  const int k = static_cast<int>(free.size());
  if (static_cast<int>(basis.size()) != k || k == 0) return {};
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kUnknowns, kUnknowns>;
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kUnknowns, 1>;
  Matrix J(k, k);
  Vector g(k);
  double residual = std::numeric_limits<double>::infinity();
  for (int step = 0; step <= kMaxNewtonSteps; ++step) {
    for (int i = 0; i < k; ++i) {
      const int r = basis[static_cast<std::size_t>(i)], f = face_of(r);
      if (f < 0) {  // a row of no face: linear, tight
        const Inequality& row = rows[static_cast<std::size_t>(r)];
        double v = -row.b;
        for (int c = 0; c < kUnknowns; ++c) v += row.a[c] * z[c];
        g(i) = v;
        for (int c = 0; c < k; ++c) J(i, c) = row.a[free[static_cast<std::size_t>(c)]];
        continue;
      }
      const int joint = f / 2, face = f % 2;
      const Normal& n = normals[static_cast<std::size_t>(joint)];
      const Inequality& row = rows[static_cast<std::size_t>(n.face_row + face)];
      g(i) = crushing(joint, face, z);
      const double slope = normal_force(joint, z) / strength;
      for (int c = 0; c < k; ++c) {
        const int u = free[static_cast<std::size_t>(c)];
        J(i, c) = row.a[u] + slope * n.a[u];
      }
    }
    residual = g.cwiseAbs().maxCoeff();
    if (!std::isfinite(residual)) return {};
    if (residual <= kNewtonResidual && step == 0) return basis;  // its rows hold their conditions already
    if (residual <= kNewtonResidual || step == kMaxNewtonSteps) break;
    Eigen::FullPivLU<Matrix> lu(J);
    lu.setThreshold(1e-12);
    if (!lu.isInvertible()) return {};  // two rows of one face, say
    const Vector dz = lu.solve(-g);
    for (int c = 0; c < k; ++c) z[free[static_cast<std::size_t>(c)]] += dz(c);
  }
  if (!(residual <= kNewtonResidual)) return {};
  // The basis with each face's row replaced by its cut at the solution (the face's own row at N = 0).
  std::vector<int> out = basis;
  for (int i = 0; i < k; ++i) {
    const int f = face_of(basis[static_cast<std::size_t>(i)]);
    if (f < 0) continue;
    const double N = normal_force(f / 2, z);
    out[static_cast<std::size_t>(i)] =
        N != 0 ? add_cut(f / 2, f % 2, N) : normals[static_cast<std::size_t>(f / 2)].face_row + f % 2;
  }
  return out;
}

LimitLp::Impl::Solved LimitLp::Impl::refined(const std::vector<int>& basis, const std::array<double, kUnknowns>& z,
                                             const std::array<double, kUnknowns>& fixed) {
  Solved out{Outcome::optimal, z, {}};
  out.basis = newton(basis, out.z, held.free);
  if (out.basis.empty()) return out;
  // Its vertex as the dense method computes it (the answer one more program would return on it).
  hold(rows, fixed, held, held.b.size());  // the cuts just added
  out.z = fixed;
  if (!dense_vertex(rows, held.b, held.free, out.basis, out.z)) out.basis.clear();
  return out;
}

bool LimitLp::Impl::optimal(const Solved& s, const Objective& objective, const std::vector<int>& free) const {
  // The Karush-Kuhn-Tucker conditions of the convex program: s.z satisfies every row and every face's
  // exact condition to the LP's own tolerances, and the objective is a combination of the gradients of
  // its basis' conditions (tight there) with multipliers >= 0 (an equality's of either sign). Then no
  // feasible point is better: the optimum, as the program on the cuts at s.z would find it.
  const int k = static_cast<int>(free.size());
  if (static_cast<int>(s.basis.size()) != k || k == 0) return false;
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kUnknowns, kUnknowns>;
  using Vector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kUnknowns, 1>;
  Matrix Jt(k, k);
  Vector pushed(k);
  for (int i = 0; i < k; ++i) {
    // Row i's gradient: a cut's row at s.z is the tangent of its face's condition there.
    const Inequality& row = rows[static_cast<std::size_t>(s.basis[static_cast<std::size_t>(i)])];
    for (int u = 0; u < k; ++u) Jt(u, i) = row.a[free[static_cast<std::size_t>(u)]];
  }
  for (int u = 0; u < k; ++u) pushed(u) = objective[free[static_cast<std::size_t>(u)]];
  Eigen::FullPivLU<Matrix> lu(Jt);
  lu.setThreshold(1e-12);
  if (!lu.isInvertible()) return false;
  const Vector y = lu.solve(pushed);
  for (int i = 0; i < k; ++i)
    if (!(y(i) >= -kFeasibility) && !rows[static_cast<std::size_t>(s.basis[static_cast<std::size_t>(i)])].equality)
      return false;
  for (int r = 0; r < cuts_begin; ++r) {
    if (face_of(r) >= 0) continue;  // a face: its exact condition below
    const Inequality& row = rows[static_cast<std::size_t>(r)];
    double g = -row.b;
    for (int c = 0; c < kUnknowns; ++c) g += row.a[c] * s.z[c];
    if (g > kFeasibility || (row.equality && g < -kFeasibility)) return false;
  }
  for (std::size_t j = 0; j < normals.size(); ++j) {
    const double N = normal_force(static_cast<int>(j), s.z);
    for (int face = 0; face < 2; ++face)
      if (crushing(static_cast<int>(j), face, s.z, N) > kCrushingTolerance) return false;
  }
  return true;
}

LimitLp::Answer LimitLp::Impl::crushed(const Objective& objective, const std::array<double, kUnknowns>& fixed,
                                       const std::vector<int>* warm) {
  // Outer approximation: the face rows are the tangent cuts at N = 0 of the convex crushing conditions;
  // each round solves the program on the cuts so far and adds, at every face whose condition the optimum
  // breaks, the cut at its normal force there (Kelley: each round about quarters the violation), and at
  // the faces of the optimal basis the cuts at the solution of their exact conditions (Newton), which
  // are tight at the true optimum when the basis names its active faces: then the next program's vertex
  // is that optimum. An infeasible program on the cuts is infeasible on the conditions too.
  std::vector<int> basis;
  if (warm) basis = carried(*warm);
  const std::vector<int>* start = warm ? &basis : nullptr;
  Held& h = held;
  hold(rows, fixed, h);
  if (h.infeasible) return finish(Solved{Outcome::infeasible, {}, {}}, objective);
  std::array<double, kUnknowns> vertex = fixed;
  if (warm && dense_vertex(rows, h.b, h.free, basis, vertex)) {
    // The warm basis names the faces the previous program's optimum had active; when this optimum has
    // the same, Newton's solution of their exact conditions from the basis' vertex is it and certifies
    // itself (no program at all). Otherwise the first program starts from its cuts.
    Solved guess = refined(basis, vertex, fixed);
    if (!guess.basis.empty()) {
      if (optimal(guess, objective, h.free)) return finish(guess, objective);
      basis = std::move(guess.basis);
    }
  }
  for (int round = 0; round < kMaxCutRounds; ++round) {
    if (round > 0) ++cut_rounds;
    hold(rows, fixed, h, h.b.size());  // the cuts added since
    if (h.infeasible) return finish(Solved{Outcome::infeasible, {}, {}}, objective);
    const Solved s = solve(h, fixed, objective, start);
    if (s.outcome != Outcome::optimal) return finish(s, objective);
    const std::size_t before = cuts.size();
    bool broken = false;
    for (std::size_t j = 0; j < normals.size(); ++j) {
      const double N = normal_force(static_cast<int>(j), s.z);
      for (int face = 0; face < 2; ++face)
        if (crushing(static_cast<int>(j), face, s.z, N) > kCrushingTolerance) {
          broken = true;
          if (N != 0) add_cut(static_cast<int>(j), face, N);
        }
    }
    // A face broken by no more than the LP leaves a row (its cut at this very N is there already): done.
    if (!broken || cuts.size() == before) return finish(s, objective);
    // Newton's solution on the optimal basis' faces: the optimum when it certifies itself (a round
    // without a program); else the next program starts from the basis with its faces' cuts there.
    Solved next = refined(s.basis, s.z, fixed);
    if (!next.basis.empty() && optimal(next, objective, h.free)) {
      ++cut_rounds;
      return finish(next, objective);
    }
    basis = next.basis.empty() ? s.basis : std::move(next.basis);
    start = &basis;
  }
  Answer a;
  a.failure = "the crushing conditions were still broken after the most rounds of tangent cuts";
  return a;
}

LimitLp::Impl::Solved LimitLp::Impl::dense(const Held& h, const std::array<double, kUnknowns>& fixed,
                                     const Objective& objective, const std::vector<int>* warm) const {
  // The start: the caps of the free unknowns, each on the side the objective pushes it (its dual the
  // objective's coefficient): a vertex no worse than the optimum, whatever the rows.
  const int caps = joint_rows + kSignRows;
  std::vector<int> start;
  for (int c : h.free) start.push_back(caps + 2 * c + (objective[c] < 0 ? 1 : 0));
  const DenseLpAnswer d = solve_dense_lp(rows, h.b, h.free, objective, start, warm, kFeasibility);
  // The dense method fails only on a basis it finds singular or a step limit (neither met in the test
  // suite): Clp then decides.
  if (d.outcome == DenseLpAnswer::Outcome::failure) {
    ++fallbacks;
    return clp(h, fixed, objective, warm);
  }
  Solved a;
  if (d.outcome == DenseLpAnswer::Outcome::infeasible) return Solved{Outcome::infeasible, {}, {}};
  a.outcome = Outcome::optimal;
  a.z = fixed;
  for (int c : h.free) a.z[c] = d.z[c];
  a.basis = d.basis;
  return a;
}

LimitLp::Impl::Solved LimitLp::Impl::clp(const Held& h, const std::array<double, kUnknowns>& fixed,
                                   const Objective& objective, const std::vector<int>* warm) const {
  // The free unknowns become the dual's rows; every inequality with a free coefficient a column.
  const std::vector<int>& free = h.free;
  const int m = static_cast<int>(free.size());
  std::vector<CoinBigIndex> start{0};
  std::vector<int> index;
  std::vector<double> value, cost, column_lower;
  std::vector<int> kept;  // the inequality of each column
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Inequality& row = rows[r];
    bool any = false;
    for (int k = 0; k < m; ++k)
      if (row.a[free[k]] != 0.0) {
        index.push_back(k);
        value.push_back(row.a[free[k]]);
        any = true;
      }
    if (!any) continue;  // held unknowns only: it holds (hold() checked)
    cost.push_back(h.b[r]);
    // An equality of the program is a free variable of its dual.
    column_lower.push_back(row.equality ? -COIN_DBL_MAX : 0.0);
    kept.push_back(static_cast<int>(r));
    start.push_back(static_cast<CoinBigIndex>(index.size()));
  }
  const int columns = static_cast<int>(cost.size());
  const std::vector<double> column_upper(columns, COIN_DBL_MAX);
  std::vector<double> rhs(m, 0.0);  // A^T y = c, the objective
  for (int k = 0; k < m; ++k) rhs[k] = objective[free[k]];
  ClpSimplex& model = workspace->clp();
  model.loadProblem(columns, m, start.data(), index.data(), value.data(), column_lower.data(), column_upper.data(),
                    cost.data(), rhs.data(), rhs.data());
  model.setOptimizationDirection(1.0);
  if (warm && static_cast<int>(warm->size()) == m) {
    // Start from the given basic columns (the same inequalities tight as in the previous program),
    // every other column at its bound of 0 (a free one at 0), every row out of the basis.
    model.createStatus();
    for (int c = 0; c < columns; ++c)
      model.setColumnStatus(c, column_lower[c] == 0.0 ? ClpSimplex::atLowerBound : ClpSimplex::isFree);
    for (int k = 0; k < m; ++k) model.setRowStatus(k, ClpSimplex::isFixed);
    std::vector<int> sorted = *warm;
    std::sort(sorted.begin(), sorted.end());
    int c = 0;
    for (int r : sorted) {
      while (c < columns && kept[c] < r) ++c;
      if (c < columns && kept[c] == r) model.setColumnStatus(c, ClpSimplex::basic);
    }
  } else {
    model.createStatus();  // the slack basis, whatever the workspace's previous program left
  }
  model.dual();
  Solved a;
  // The dual infeasible (no y) <=> the primal unbounded, prevented by the caps; the dual unbounded <=>
  // the primal infeasible.
  if (model.isProvenDualInfeasible()) {
    a.outcome = Outcome::infeasible;
    return a;
  }
  if (!model.isProvenOptimal() || model.secondaryStatus() != 0) return a;  // failure
  a.outcome = Outcome::optimal;
  a.z = fixed;
  const double* price = model.getRowPrice();
  for (int k = 0; k < m; ++k) a.z[free[k]] = price[k];
  for (int c = 0; c < columns; ++c)
    if (model.getColumnStatus(c) == ClpSimplex::basic) a.basis.push_back(kept[c]);
  return a;
}

std::vector<LimitLp::RowKey> LimitLp::keys(const std::vector<int>& basis) const {
  const Impl& p = *impl_;
  std::vector<RowKey> out;
  for (int r : basis) {
    if (r < p.cuts_begin) {
      out.push_back(p.keys[static_cast<std::size_t>(r)]);
      continue;
    }
    const Impl::Cut& c = p.cuts[static_cast<std::size_t>(r - p.cuts_begin)];
    RowKey key = p.keys[static_cast<std::size_t>(p.normals[static_cast<std::size_t>(c.joint)].face_row + c.face)];
    key.cut = c.force;
    out.push_back(key);
  }
  return out;
}

std::vector<int> LimitLp::rows(const std::vector<RowKey>& keys) {
  Impl& p = *impl_;
  std::vector<int> out;
  const std::vector<RowKey>& all = p.keys;
  for (const RowKey& k : keys) {
    const auto it = std::lower_bound(all.begin(), all.end(), RowKey{k.s, k.place, 0.0});
    if (it == all.end() || it->s != k.s || it->place != k.place) return {};
    const int r = static_cast<int>(it - all.begin());
    if (k.cut == 0) {
      out.push_back(r);
      continue;
    }
    // A cut: made anew at its force on this ring's face (none without crushing).
    const int f = std::isfinite(p.strength) && r < p.joint_rows ? p.row_face[static_cast<std::size_t>(r)] : -1;
    if (f < 0) return {};
    out.push_back(p.add_cut(f / 2, f % 2, k.cut / p.weight));
  }
  return out;
}

std::vector<int> LimitLp::faces(const std::vector<int>& basis) const {
  const Impl& p = *impl_;
  std::vector<int> out = basis;
  for (int& r : out)
    if (r >= p.cuts_begin) {
      const Impl::Cut& c = p.cuts[static_cast<std::size_t>(r - p.cuts_begin)];
      r = p.normals[static_cast<std::size_t>(c.joint)].face_row + c.face;
    }
  return out;
}

int LimitLp::cut_rounds() const { return impl_->cut_rounds; }

int LimitLp::programs() const { return impl_->programs; }

LimitLp::Answer LimitLp::extreme_thrust(double load_factor, bool largest, const std::vector<int>* warm) {
  ++solves_;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return impl_->optimise(pushing(kH, largest), {nan, nan, nan, load_factor, 0.0}, warm);
}

LimitLp::Answer LimitLp::margin(double load_factor, const std::vector<int>* warm) {
  ++solves_;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return impl_->optimise(pushing(kMu, true), {nan, nan, nan, load_factor, nan}, warm);
}

LimitLp::Answer LimitLp::collapse(const std::vector<int>* warm, bool least) {
  ++solves_;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Impl& p = *impl_;
  const double dead = p.dead_weight, live = p.live_weight;
  // At collapse the live load is lambda_c times its value at factor 1, of the order of the dead load
  // (the mechanism's work balances): when the two differ by orders of magnitude, the program in units of
  // their sum sees the loads at collapse at the scale of its tolerances (a point load 1e10 times the
  // self-weight gave a thrust line touching every joint and twice the true multiplier), or lambda_c
  // beyond its cap. The collapse is then solved in units of the dead load, lambda in units of the dead
  // over the live load: every joint row times W / dead (its right-hand side and lambda's coefficient;
  // the geometric coefficients of H, V and M keep their value with H, V, M in the new unit), lambda's
  // coefficient also times dead / live.
  if (p.live == LiveKind::vertical && dead > 0 && live > 0 &&
      (live > kCollapseScaleRatio * dead || dead > kCollapseScaleRatio * live)) {
    // (With crushing the cuts, the normal forces and f_c too: N^2 / (2 f_c) scales as the rows.)
    const std::vector<Inequality> given = p.rows;
    const std::vector<Impl::Normal> given_normals = p.normals;
    const std::size_t given_cuts = p.cuts.size();
    const double to_dead = p.weight / dead, per_lambda = dead / live;
    for (int r = 0; r < static_cast<int>(p.rows.size()); ++r) {
      if (r >= p.joint_rows && r < p.cuts_begin) continue;  // the sign and cap rows
      Inequality& row = p.rows[static_cast<std::size_t>(r)];
      row.b *= to_dead;
      row.a[kLambda] *= to_dead * per_lambda;
      double sum = 0;
      for (double x : row.a) sum += x * x;
      row.norm = std::sqrt(sum);
    }
    for (Impl::Normal& n : p.normals) {
      n.c *= to_dead;
      n.a[kLambda] *= to_dead * per_lambda;
    }
    const double weight = p.weight, strength = p.strength;
    p.weight = dead;
    p.strength *= to_dead;
    p.lambda_scale = per_lambda;
    Answer a = p.optimise(pushing(kLambda, !least), {nan, nan, nan, nan, 0.0}, warm);
    p.rows = given;
    p.normals = given_normals;
    p.weight = weight;
    p.strength = strength;
    p.lambda_scale = 1;
    // The cuts made meanwhile, in the program's own units again (at the same force: the same rows).
    for (std::size_t i = given_cuts; i < p.cuts.size(); ++i) {
      const Impl::Cut& c = p.cuts[i];
      p.rows.push_back(p.cut_row(c.joint, c.face, c.force / p.weight));
    }
    return a;
  }
  return p.optimise(pushing(kLambda, !least), {nan, nan, nan, nan, 0.0}, warm);
}

LimitLp::Answer LimitLp::least_work(double load_factor, double per_H, double per_V, const std::vector<int>* warm) {
  ++solves_;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // H and V share their scale (W), so the scaled objective has the same direction; normalised, so that
  // per_V = 0 is extreme_thrust's program to the bit.
  const double norm = std::max(std::abs(per_H), std::abs(per_V));
  if (!(norm > 0) || !std::isfinite(norm)) return Answer{};  // no objective: a failure, not an answer
  Objective objective{};
  objective[kH] = -per_H / norm;
  objective[kV] = -per_V / norm;
  return impl_->optimise(objective, {nan, nan, nan, load_factor, 0.0}, warm);
}

LimitLp::Answer LimitLp::least_work(double load_factor, double per_H, double per_V, double per_M,
                                    const std::vector<int>* warm) {
  if (per_M == 0) return least_work(load_factor, per_H, per_V, warm);
  ++solves_;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // M's scale is W L (H's and V's W): its coefficient in the scaled program is per_M L.
  const double per_m = per_M * impl_->span;
  const double norm = std::max({std::abs(per_H), std::abs(per_V), std::abs(per_m)});
  if (!(norm > 0) || !std::isfinite(norm)) return Answer{};
  Objective objective{};
  objective[kH] = -per_H / norm;
  objective[kV] = -per_V / norm;
  objective[kM] = -per_m / norm;
  return impl_->optimise(objective, {nan, nan, nan, load_factor, 0.0}, warm);
}

LimitLp& programs_of(const Ring& ring, const LimitOptions& options, LpWorkspace& workspace,
                     std::unique_ptr<LimitLp>& lp) {
  if (lp) lp->load(ring, options.friction, options.compressive_strength);
  else
    lp = std::make_unique<LimitLp>(ring, options.friction, &workspace, LpSolver::dense, LiveKind::vertical,
                                   options.compressive_strength);
  return *lp;
}

}  // namespace ogive::limit_detail
