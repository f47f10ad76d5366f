#include "ogive/model/arch_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ogive/model/curved_section.hpp"
#include "geometry/side_view.hpp"
#include "numerics/chebyshev.hpp"
#include "numerics/gauss_legendre.hpp"

namespace ogive {
namespace {

// Where f changes sign along [0, S] (scaled s): sampled, then bisected to round-off. f is continuous.
template <class F>
std::vector<double> sign_changes(F&& f, double S) {
  constexpr int kSamples = 256;
  std::vector<double> roots;
  double a = 0, fa = f(0.0);
  for (int i = 1; i <= kSamples; ++i) {
    const double b = S * i / kSamples, fb = f(b);
    if ((fa < 0) != (fb < 0)) {
      double lo = a, hi = b;
      const bool rising = fa < 0;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        ((f(mid) < 0) == rising ? lo : hi) = mid;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    a = b;
    fa = fb;
  }
  return roots;
}

}  // namespace

// The true extrados over the domain's axis points: the left side's up to the crown's vertical and, over a
// whole domain, the right side's beyond it (both sides meet there, above a pointed crown).
struct ArchModel::Extrados {
  struct Side {
    Side(const Curve& curve, bool right, double thickness) : view(curve, right), face(view, thickness, curve.span()) {}
    SideView view;
    SideExtrados face;
  };
  // The height over an axis point and whether the extrados lies over it at all (not over the x below
  // the bed's outer end of an overhanging springing: there the height is the extrados' first point's).
  struct Height {
    double y = 0;
    bool over = true;
  };

  Extrados(const Curve& domain, double thickness)
      : whole(domain.extent() == CurveExtent::whole), span(domain.span()) {
    sides.push_back(std::make_unique<Side>(domain, false, thickness));
    if (whole) sides.push_back(std::make_unique<Side>(domain, true, thickness));
    whole_length = domain.whole_length();
  }

  // The extrados' height over the axis point p at arc length s (m) of the domain.
  Height over(const CurvePoint& p, double s) const {
    const bool right = whole && p.x > sides[0]->view.crown_x();
    const Side& side = *sides[right ? 1 : 0];
    const double x = side.view.curve_x(p.x);
    const double guess = right ? whole_length - s : s;
    return {side.face.height(x, guess), x >= side.face.x_begin()};
  }

  // The domain's arc lengths (m) where the fill's load is not smooth whatever its level: the axis points
  // under the extrados' breaks, and where the extrados starts to lie over the axis.
  std::vector<double> breaks() const {
    std::vector<double> out;
    for (std::size_t k = 0; k < sides.size(); ++k) {
      const SideView& view = sides[k]->view;
      std::vector<double> xs = sides[k]->face.break_x();
      if (sides[k]->face.x_begin() > view.at(0.0).x) xs.push_back(sides[k]->face.x_begin());
      for (double x : xs)
        if (x > view.at(0.0).x && x < view.crown_x())
          out.push_back(view.whole_s(face_at_x(view, 0.0, x, 0.0, view.length(), span)));
    }
    return out;
  }

  bool whole = false;
  double span = 0, whole_length = 0;
  std::vector<std::unique_ptr<Side>> sides;
};

ArchModel::ArchModel(Scene scene, bool whole_arch_domain) : scene_(std::move(scene)) {
  if (scene_.beam_model == BeamModel::automatic)
    throw std::invalid_argument("beam_model: automatic is solve()'s choice; a model needs euler_bernoulli, "
                                "timoshenko or curved");
  const Material& m = scene_.material;
  const double L = scene_.span();
  const double w = scene_.reference_load_per_length();
  const double EI = m.effective_modulus() * scene_.inertia();
  scales_.length = L;
  scales_.force = w * L;
  scales_.moment = w * L * L;
  scales_.displacement = w * L * L * L * L / EI;
  scales_.rotation = w * L * L * L / EI;
  half_ = scene_.symmetric() && !whole_arch_domain;
  curve_ = half_ ? scene_.curve : whole_arch(scene_.curve);
  length_ = curve_->length() / L;
  // a_N = I / (A L^2) exactly: the same modulus stiffens bending and stretching.
  a_N_ = scene_.inertia() / (scene_.area() * L * L);
  // Euler-Bernoulli: no shear strain, the limit k G A -> infinity.
  a_V_ = scene_.beam_model == BeamModel::euler_bernoulli
             ? 0.0
             : m.effective_modulus() / (m.shear_coefficient * m.shear_modulus()) * a_N_;
  self_weight_ = scene_.weight_per_length() / w;
  uniform_ = scene_.loads.empty();
  find_kink();
  place_loads();
  set_boundary_conditions();
  sum_loads();
  if (curved()) {
    sum_centroid_offset();
    tabulate_section();
  }
}

void ArchModel::find_kink() {
  // Only a half curve has a kink (the pointed crown, where it meets its mirror); a whole curve is smooth.
  // A smooth crown's tangent is 0 to round-off: a kink turns by a finite angle.
  constexpr double kSmoothCrown = 1e-9;
  if (!curved() || scene_.curve->extent() != CurveExtent::half) return;
  const double theta_c = scene_.curve->angle(scene_.curve->length());
  if (std::abs(theta_c) <= kSmoothCrown) return;
  crown_kink_angle_ = theta_c;
  if (!half_) kink_ = Kink{scene_.curve->length() / scene_.span(), theta_c, -theta_c};
}

SystemMatrix ArchModel::kink_jump(double theta1, double theta2) const {
  SystemMatrix K = SystemMatrix::Zero();
  const double f = a_N_ * (1 + 1.2 * section_poisson_ratio());
  const double dsin = std::sin(theta2) - std::sin(theta1), dcos = std::cos(theta1) - std::cos(theta2);
  K(kUx, kM) = f * dsin;
  K(kUy, kM) = f * dcos;
  K(kPsi, kFx) = f * dsin;
  K(kPsi, kFy) = f * dcos;
  // The crown's wedge turns each leg's crown section against the symmetry line by crown_wedge M / (E t^2),
  // M~ t~ / 12 scaled (E = 12 / t~^3 with E I = 1 and the span 1): over the half turn theta_c to 0 that,
  // over the whole turn twice that.
  const double t = std::sqrt(12.0 * a_N_), theta_c = std::abs(crown_kink_angle_);
  if (theta_c > 0) K(kPsi, kM) = crown_wedge(theta_c) * t / 12.0 * std::abs(theta2 - theta1) / theta_c;
  return K;
}

void ArchModel::sum_centroid_offset() {
  // The self-weight acts t^2 |kappa| / 12 beyond the axis point along the extrados normal (-sn, c): its
  // moment about the left springing (clockwise positive) changes by int b_self (-delta sn) + h_self delta c
  // with delta = -a_N k (scaled), between the breakpoints where the curvature is smooth.
  const double L = scales_.length, a = acceleration();
  std::vector<double> knots{0.0};
  knots.insert(knots.end(), breakpoints_.begin(), breakpoints_.end());
  knots.push_back(length_);
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    constexpr int kPanels = 8;
    for (int i = 0; i < kPanels; ++i) {
      const double lo = knots[k] + (knots[k + 1] - knots[k]) * i / kPanels;
      const double hi = knots[k] + (knots[k + 1] - knots[k]) * (i + 1) / kPanels;
      load_moment_ += gauss_legendre_integral<16>(
          [&](double s) {
            const CurvePoint p = curve_->at(s * L);
            const double delta = -a_N_ * p.kappa * L;
            return self_weight_ * delta * (-std::sin(p.theta) + a * std::cos(p.theta));
          },
          lo, hi);
    }
  }
}

double ArchModel::kappa(double s) const { return curve_->at(s * scales_.length).kappa * scales_.length; }

double ArchModel::section_poisson_ratio() const {
  // Plane strain: the stresses of the free annulus are the same; its strains take E / (1 - nu^2), which
  // a_N already has, and nu / (1 - nu).
  const Material& m = scene_.material;
  return m.plane_strain ? m.poisson_ratio / (1 - m.poisson_ratio) : m.poisson_ratio;
}

void ArchModel::tabulate_section() {
  // In rho^2 the factors are analytic up to rho^2 = 1, far from [0, 1/4]: degree 16 is at round-off.
  const ChebyshevRule& rule = chebyshev_rule(kSectionDegree);
  const double nu = section_poisson_ratio(), top = kTabulatedRho * kTabulatedRho;
  // load_extension is odd in rho: its series is of load_extension / rho.
  Eigen::Matrix<double, kSectionDegree + 1, 6> values;
  for (int i = 0; i <= kSectionDegree; ++i) {
    const double rho = std::sqrt(0.5 * (rule.node[i] + 1) * top);
    const CurvedSection c = curved_section(rho, nu);
    const double extension = rho > 0 ? c.load_extension / rho : curved_section(1e-6, nu).load_extension / 1e-6;
    values.row(i) << c.axial, c.coupling, c.bending, c.shear, extension, c.load_curvature;
  }
  const Eigen::Matrix<double, kSectionDegree + 1, 6> series = rule.to_coefficients * values;
  for (int f = 0; f < 6; ++f)
    for (int i = 0; i <= kSectionDegree; ++i) section_series_[f][i] = series(i, f);
}

ArchModel::CurvedBar ArchModel::curved_bar(double k) const {
  CurvedBar bar;
  if (!curved()) return bar;
  bar.offset = a_N_ * k;
  bar.coupling = a_N_ * k;
  // rho = |kappa| t / 2 = |k| t~ / 2, t~ = sqrt(12 a_N).
  const double rho = 0.5 * std::abs(k) * std::sqrt(12.0 * a_N_);
  if (rho == 0) return bar;
  CurvedSection section;
  if (rho <= kTabulatedRho) {
    const double x = 2 * (rho * rho) / (kTabulatedRho * kTabulatedRho) - 1;
    section.axial = chebyshev_series(section_series_[0].data(), kSectionDegree, x);
    section.coupling = chebyshev_series(section_series_[1].data(), kSectionDegree, x);
    section.bending = chebyshev_series(section_series_[2].data(), kSectionDegree, x);
    section.shear = chebyshev_series(section_series_[3].data(), kSectionDegree, x);
    section.load_extension = rho * chebyshev_series(section_series_[4].data(), kSectionDegree, x);
    section.load_curvature = chebyshev_series(section_series_[5].data(), kSectionDegree, x);
  } else {
    section = curved_section(rho, section_poisson_ratio());
  }
  bar.axial = section.axial;
  bar.coupling *= section.coupling;
  bar.bending = section.bending;
  bar.shear = section.shear;
  bar.load_strain = -(k > 0 ? 1 : -1) * a_N_ * std::sqrt(12.0 * a_N_) * section.load_extension;
  bar.load_curvature = -a_N_ * section.load_curvature;
  return bar;
}

void ArchModel::curved_derivative(double c, double sn, const CurvedBar& bar, const double* y, double* dy,
                                  double load, double horizontal, bool self_weight) const {
  const double N = c * y[kFx] + sn * y[kFy];
  const double V = -sn * y[kFx] + c * y[kFy];
  const double q = self_weight ? weight_normal_load(c, sn) : 0.0;
  const double eps = a_N_ * bar.axial * N + bar.coupling * y[kM] + bar.load_strain * q;
  const double rot = a_V_ * bar.shear * V + y[kPsi];
  dy[kUx] = eps * c - rot * sn;
  dy[kUy] = eps * sn + rot * c;
  dy[kPsi] = bar.bending * y[kM] + bar.coupling * N + bar.load_curvature * q;
  dy[kFx] = -horizontal;
  dy[kFy] = load;
  dy[kM] = sn * y[kFx] - c * y[kFy];
  if (self_weight) dy[kM] += bar.offset * self_weight_ * (sn - acceleration() * c);
}

SystemMatrix ArchModel::curved_system_matrix(double theta, const CurvedBar& bar) const {
  SystemMatrix A = system_matrix(theta);
  const double c = std::cos(theta), sn = std::sin(theta);
  const double aN = a_N_ * bar.axial, aV = a_V_ * bar.shear;
  A(kUx, kFx) = aN * c * c + aV * sn * sn;
  A(kUx, kFy) = (aN - aV) * c * sn;
  A(kUy, kFx) = (aN - aV) * c * sn;
  A(kUy, kFy) = aN * sn * sn + aV * c * c;
  A(kUx, kM) = bar.coupling * c;
  A(kUy, kM) = bar.coupling * sn;
  A(kPsi, kFx) = bar.coupling * c;
  A(kPsi, kFy) = bar.coupling * sn;
  A(kPsi, kM) = bar.bending;
  return A;
}

void ArchModel::place_loads() {
  const double L = scales_.length;
  const Loads& loads = scene_.loads;
  std::vector<double> curve_breaks;
  for (double b : curve_->breakpoints()) curve_breaks.push_back(b / L);
  // A load within a part in 1e12 of a curve breakpoint acts there (a load at the crown of a pointed arch:
  // on the kink, not one round-off away from it).
  auto snapped = [&](double s) {
    for (double b : curve_breaks)
      if (std::abs(s - b) <= 1e-12 * length_) return b;
    if (s <= 1e-12 * length_) return 0.0;
    if (s >= length_ * (1 - 1e-12)) return length_;
    return s;
  };
  // x = 0 and x = L are the springings themselves: near a vertical springing x(s) is flat, and inverting it
  // would place the load a distance of order sqrt(round-off) inside the arch.
  auto s_at = [&](double ratio) {
    if (ratio <= 0) return 0.0;
    if (ratio >= 1) return half_ ? 2.0 * length_ : length_;
    return snapped(arc_length_at_x(*scene_.curve, ratio * L) / L);
  };

  for (const PointLoad& p : loads.points) {
    const double force = p.force / scales_.force;
    if (half_ && std::abs(p.at - 0.5) <= 1e-14) crown_load_ += 0.5 * force;  // half of it on each half
    else if (!half_ || p.at < 0.5) jumps_.push_back({s_at(p.at), force});
    // Over the half, a load beyond the crown is the mirror of one before it (Scene::symmetric).
  }
  std::sort(jumps_.begin(), jumps_.end(), [](const PointJump& a, const PointJump& b) { return a.s < b.s; });
  if (scene_.crown_hinge && !half_) hinge_ = snapped(curve_->crown() / L);

  breakpoints_ = curve_breaks;
  auto add_break = [&](double s) {
    if (s > 0 && s < length_) breakpoints_.push_back(s);
  };
  for (const PointJump& j : jumps_) add_break(j.s);
  if (hinge_) add_break(*hinge_);
  for (const LiveLoad& q : loads.live) {
    live_spans_.push_back({s_at(q.from), s_at(q.to), q.intensity});
    add_break(live_spans_.back().from);
    add_break(live_spans_.back().to);
  }
  if (!loads.fills.empty()) {
    extrados_ = std::make_shared<const Extrados>(*curve_, scene_.thickness);
    for (double s : extrados_->breaks()) add_break(snapped(s / L));
  }
  for (const FillLoad& f : loads.fills) {
    const double level = f.height_ratio * L;
    // Where the fill's level meets the extrados (a continuous function of s: beyond where the extrados
    // lies over the axis, the extrados' first height).
    for (double s : sign_changes(
             [&](double s) { return level - extrados_->over(curve_->at(s * L), s * L).y; }, length_))
      add_break(snapped(s));
  }
  std::sort(breakpoints_.begin(), breakpoints_.end());
  breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end()), breakpoints_.end());
}

void ArchModel::set_boundary_conditions() {
  // The conditions, each fixing one component (springing_split relies on it). A springing fixes its
  // displacements (its spread outwards: -x at the left, +x at the right) and its rotation if clamped,
  // else its moment; the half's crown its symmetry (Ux, psi or the hinge's M, and Fy). The curved bar's
  // clamped springing is a face held whole: its displacements and rotation are the support's plus the
  // held face's compliance times the forces there (held_face_compliance).
  auto springing = [&](const Support& support, double outward, Eigen::Index first, SystemMatrix& at) {
    at(first, kUx) = 1.0;
    bc_.rhs(first) = outward * support.spread / scales_.displacement;
    at(first + 1, kUy) = 1.0;
    bc_.rhs(first + 1) = -support.settlement / scales_.displacement;
    if (support.kind == SupportKind::clamped) {
      at(first + 2, kPsi) = 1.0;
      bc_.rhs(first + 2) = support.rotation / scales_.rotation;
      if (curved()) at.block<3, 3>(first, kFx) = -held_face_compliance(first == 0);
    } else {
      at(first + 2, kM) = 1.0;
    }
  };
  springing(scene_.left, -1.0, 0, bc_.at_start);
  if (half_) {
    bc_.at_end(3, kUx) = 1.0;
    bc_.at_end(4, scene_.crown_hinge ? kM : kPsi) = 1.0;
    bc_.at_end(5, kFy) = 1.0;
    bc_.rhs(5) = -crown_load_;
    if (crown_kink_angle_ != 0) {
      // The crown's conditions hold beyond the half of the kink's turn, on the symmetry line.
      const SystemMatrix K = kink_jump(crown_kink_angle_, 0.0);
      bc_.at_end.row(3) += K.row(kUx);
      if (!scene_.crown_hinge) bc_.at_end.row(4) += K.row(kPsi);
    }
  } else {
    springing(scene_.right, 1.0, 3, bc_.at_end);
  }
}

Eigen::Matrix3d ArchModel::held_face_compliance(bool left) const {
  // The face's compliance (curved_section.hpp's held_face) scaled: with E I = 1 and the span 1, E = 12 /
  // t~^3, so V / E is V~ t~^3 / 12, M / (E t) is M~ t~^2 / 12 and M / (E t^2) is M~ t~ / 12.
  // The face's t / R: an arch's kappa is negative, its centre of curvature on the intrados' side, opposite
  // the face's V (the held face's t_kappa > 0), at both springings.
  const double t = std::sqrt(12.0 * a_N_);
  const double s_face = left ? 0.0 : curve_->length();
  const HeldFace c = held_face(section_poisson_ratio(), -t * curve_->at(s_face).kappa * scales_.length);
  Eigen::Matrix3d local;
  local << c.NN * t * t * t, 0, c.NM * t * t, 0, c.VV * t * t * t, c.VM * t * t, c.NM * t * t, c.VM * t * t, c.MM * t;
  local /= 12.0;
  // The left springing's frame is the axis leaving it (theta at s = 0), and its forces on the face are
  // y(0)'s Fx, Fy, M (the part beyond on the part before): y(0) = T' C T y(0)'s forces, T from global
  // to the frame. At the right springing the axis arrives: its frame is turned by pi (the same T up to
  // the sign of N and V), the forces on the face are minus y(S~)'s, and the frame's rotation is the
  // global one. The face is the mirror image of the left one, whose V and M the mirror reverses: C in the
  // face's own frame (N leaving it, V and M anticlockwise) is diag(1, -1, -1) C diag(1, -1, -1), and in T's
  // (N and V reversed) y(S~) = -T' D C D T y(S~)'s forces with D = diag(1, -1, 1) (the signs of VM and NV
  // change, NM's does not).
  const double theta = curve_->at(s_face).theta;
  const double c0 = std::cos(theta), s0 = std::sin(theta);
  Eigen::Matrix3d T;
  T << c0, s0, 0, -s0, c0, 0, 0, 0, 1;
  if (left) return T.transpose() * local * T;
  const Eigen::Vector3d d(1, -1, 1);
  return -T.transpose() * d.asDiagonal() * local * d.asDiagonal() * T;
}

void ArchModel::sum_loads() {
  const double L = scales_.length;
  const Loads& loads = scene_.loads;
  // The domain's load and its moment about the left springing, for the equilibrium residual: the
  // self-weight exactly (the curve's first moment), point loads at their x, other loads by Gauss-Legendre
  // between the breakpoints, where they are smooth.
  total_load_ = self_weight_ * length_;
  load_moment_ = self_weight_ * curve_->first_moment_x() / (L * L);
  for (const PointJump& j : jumps_) {
    total_load_ += j.force;
    load_moment_ += j.force * curve_->at(j.s * L).x / L;
  }
  // The horizontal load: the self-weight's total exactly, the fill's and every moment h y by Gauss-Legendre.
  const double a = acceleration();
  total_horizontal_load_ = a * self_weight_ * length_;
  if (!loads.live.empty() || !loads.fills.empty() || a != 0) {
    std::vector<double> knots{0.0};
    knots.insert(knots.end(), breakpoints_.begin(), breakpoints_.end());
    knots.push_back(length_);
    constexpr int kPanels = 8;
    for (std::size_t k = 0; k + 1 < knots.size(); ++k)
      for (int i = 0; i < kPanels; ++i) {
        const double lo = knots[k] + (knots[k + 1] - knots[k]) * i / kPanels;
        const double hi = knots[k] + (knots[k + 1] - knots[k]) * (i + 1) / kPanels;
        const Eigen::Vector3d part = gauss_legendre_integral<16>(
            [&](double s) {
              const CurvePoint p = curve_->at(s * L);
              const double q = distributed_load(s, p);
              const double fill = a != 0 ? a * fill_load(s, p) : 0.0;
              const double moment = q * p.x / L + (a != 0 ? (a * self_weight_ + fill) * p.y / L : 0.0);
              return Eigen::Vector3d(q, moment, fill);
            },
            lo, hi);
        total_load_ += part(0);
        load_moment_ += part(1);
        total_horizontal_load_ += part(2);
      }
  }
}

double ArchModel::theta(double s) const { return curve_->angle(s * scales_.length); }

double ArchModel::distributed_load(double s, const CurvePoint& p) const {
  const double L = scales_.length, w = scales_.force / L;
  const double c = std::cos(p.theta);
  double q = 0;
  for (const LiveSpan& live : live_spans_)
    if (s >= live.from && s <= live.to) q += live.intensity * c;
  if (extrados_) {
    const Extrados::Height e = extrados_->over(p, s * L);
    if (e.over)
      for (const FillLoad& f : scene_.loads.fills) q += fill_weight(f, e.y, c);
  }
  return q / w;
}

double ArchModel::fill_weight(const FillLoad& f, double extrados_y, double c) const {
  return f.density * scene_.material.gravity * std::max(0.0, f.height_ratio * scales_.length - extrados_y) * c;
}

double ArchModel::fill_load(double s, const CurvePoint& p) const {
  if (!extrados_) return 0.0;
  const Extrados::Height e = extrados_->over(p, s * scales_.length);
  if (!e.over) return 0.0;
  const double c = std::cos(p.theta);
  double q = 0;
  for (const FillLoad& f : scene_.loads.fills) q += fill_weight(f, e.y, c);
  return q / (scales_.force / scales_.length);
}

double ArchModel::load(double s) const {
  if (uniform_) return self_weight_;
  return self_weight_ + distributed_load(s, curve_->at(s * scales_.length));
}

double ArchModel::horizontal_load(double s) const {
  const double a = acceleration();
  if (a == 0) return 0.0;
  if (!extrados_) return a * self_weight_;
  return a * (self_weight_ + fill_load(s, curve_->at(s * scales_.length)));
}

ArchModel::SystemEntries ArchModel::system_entries(double theta) const {
  const double c = std::cos(theta), sn = std::sin(theta);
  SystemEntries e;
  e.ux_psi = -sn;
  e.ux_fx = a_N_ * c * c + a_V_ * sn * sn;
  e.ux_fy = (a_N_ - a_V_) * c * sn;
  e.uy_psi = c;
  e.uy_fx = (a_N_ - a_V_) * c * sn;
  e.uy_fy = a_N_ * sn * sn + a_V_ * c * c;
  e.m_fx = sn;
  e.m_fy = -c;
  return e;
}

SystemMatrix ArchModel::system_matrix(double theta) const {
  const SystemEntries e = system_entries(theta);
  SystemMatrix A = SystemMatrix::Zero();
  A(kUx, kPsi) = e.ux_psi;
  A(kUx, kFx) = e.ux_fx;
  A(kUx, kFy) = e.ux_fy;
  A(kUy, kPsi) = e.uy_psi;
  A(kUy, kFx) = e.uy_fx;
  A(kUy, kFy) = e.uy_fy;
  A(kPsi, kM) = 1.0;
  A(kM, kFx) = e.m_fx;
  A(kM, kFy) = e.m_fy;
  return A;
}

Reactions ArchModel::reactions(const StateVector& y0, const StateVector& yS) const {
  Reactions r;
  r.H_left = -y0[kFx] * scales_.force;
  r.V_left = -y0[kFy] * scales_.force;
  r.M_left = -y0[kM] * scales_.moment;
  if (half_) {
    r.H_right = r.H_left;
    r.V_right = r.V_left;
    r.M_right = -r.M_left;
  } else {
    r.H_right = -yS[kFx] * scales_.force;
    r.V_right = yS[kFy] * scales_.force;
    r.M_right = yS[kM] * scales_.moment;
  }
  return r;
}

ArchState ArchModel::section_state(double c, double sn, const StateVector& y) const {
  ArchState st;
  st.Ux = y[kUx] * scales_.displacement;
  st.Uy = y[kUy] * scales_.displacement;
  st.psi = y[kPsi] * scales_.rotation;
  st.Fx = y[kFx] * scales_.force;
  st.Fy = y[kFy] * scales_.force;
  st.M = y[kM] * scales_.moment;
  st.N = c * st.Fx + sn * st.Fy;
  st.V = -sn * st.Fx + c * st.Fy;
  return st;
}

ArchState ArchModel::to_physical(double s, const StateVector& y, bool mirrored) const {
  const double L = scales_.length;
  const CurvePoint on_domain = curve_->at(s * L);
  mirrored = mirrored && half_;
  const CurvePoint p = mirrored ? mirror(on_domain, L) : on_domain;
  StateVector z = y;
  if (mirrored) {
    // Reflection about x = L/2, with "beyond" and "before" swapped on the right half.
    z[kUx] = -z[kUx];
    z[kPsi] = -z[kPsi];
    z[kFy] = -z[kFy];
  }
  ArchState st = section_state(std::cos(p.theta), std::sin(p.theta), z);
  st.s = mirrored ? 2.0 * curve_->length() - s * L : s * L;
  st.x = p.x;
  st.y = p.y;
  st.theta = p.theta;
  const double t = scene_.thickness;
  // Where the normal force vanishes there is no eccentricity: NaN, never an unbounded number that reads
  // as a result. (Under tension, N > 0, e is the tensile force's eccentricity; the CLI flags it.)
  if (st.N == 0) {
    st.e = st.thrust_x = st.thrust_y = std::numeric_limits<double>::quiet_NaN();
    return st;
  }
  st.e = 600.0 * st.M / (st.N * t);
  st.compressive_stress = compressive_stress(scene_.section, st.N, st.M, t).sigma;
  if (scene_.section == SectionKind::no_tension) {
    const SectionStrain ss = section_strain(SectionKind::no_tension, st.N / scales_.force, st.M / scales_.moment, t / L);
    st.compressed_depth = ss.compressed_depth;
    st.cracked = ss.cracked;
  }
  // F acting at offset a along the extrados normal n = (-sn, c) has moment -a N about the axis point,
  // so the resultant crosses the section at a = -M / N.
  const PlanePoint thrust = along_normal(p, -st.M / st.N);
  st.thrust_x = thrust.x;
  st.thrust_y = thrust.y;
  return st;
}

double ArchModel::boundary_residual(const StateVector& y0, const StateVector& yS, double hinge_moment) const {
  const double conditions = (bc_.at_start * y0 + bc_.at_end * yS - bc_.rhs).lpNorm<Eigen::Infinity>();
  return std::max(conditions, std::abs(hinge_moment));
}

double ArchModel::equilibrium_residual(const StateVector& y0, const StateVector& yS) const {
  const double L = scales_.length;
  const CurvePoint end = curve_->at(curve_->length());
  const double xS = end.x / L, yS_pos = end.y / L;
  // Over the half, the crown's half load is the end condition Fy(S) = -P/2, not a load of the domain.
  const double vertical = yS[kFy] - y0[kFy] - total_load_;
  // Moments about the left springing: the end's force and couple, the springing's couple, the loads.
  const double moment = xS * yS[kFy] - yS_pos * yS[kFx] + yS[kM] - y0[kM] - load_moment_;
  const double horizontal = yS[kFx] - y0[kFx] + total_horizontal_load_;
  const double scale = std::max({std::abs(total_load_) + std::abs(crown_load_) + std::abs(total_horizontal_load_),
                                 std::abs(y0[kFy]), std::abs(yS[kFy]),
                                 std::abs(y0[kFx]), std::numeric_limits<double>::min()});
  return std::max({std::abs(vertical), std::abs(horizontal), std::abs(moment) / std::max(xS, 1e-300)}) / scale;
}

}  // namespace ogive
