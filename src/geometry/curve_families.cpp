#include "ogive/geometry/curve_families.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "numerics/chebyshev.hpp"
#include "numerics/gauss_legendre.hpp"

namespace ogive {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kHalfPi = std::numbers::pi / 2;
constexpr double kMaxSmoothRiseRatio = 2.0;
// Flatter than this, a smooth family's formulas leave the range of a double (found by fuzzing: the
// catenary's sinh^2 underflows and its parameter a ~ L / (4 rise_ratio) overflows, the parabola's first
// moment is 0/0), and no survey could tell the arch from its springing line anyway.
constexpr double kMinSmoothRiseRatio = 1e-6;

[[noreturn]] void refuse(const std::string& field, const std::string& rule, double value) {
  throw std::invalid_argument(fmt::format("{}: {}, got {}", field, rule, value));
}

void check_span(double span) {
  if (!(span >= kMinSpan && span <= kMaxSpan))
    refuse("span", fmt::format("must lie in [{}, {}] m", kMinSpan, kMaxSpan), span);
}

void check_smooth_rise(double rise_ratio, const char* family) {
  if (!(rise_ratio >= kMinSmoothRiseRatio && rise_ratio <= kMaxSmoothRiseRatio))
    refuse("rise_ratio",
           fmt::format("must lie in [{}, {}] for {} arch", kMinSmoothRiseRatio, kMaxSmoothRiseRatio, family),
           rise_ratio);
}

double radians(double degrees) { return degrees * (kPi / 180.0); }

// The arc length's rule: 16-point Gauss-Legendre per panel.
constexpr int kGaussOrder = 16;

// ---------------------------------------------------------------------------------------------------
// Piecewise-circular constructions.

// The three-/four-centred system: haunch arc r1 turning by `haunch` from vertical, crown arc r2 reaching
// the crown at tangent angle `crown` (0 for three-centred). Returns {r1, r2}.
std::pair<double, double> centred_radii(double half_span, double rise, double haunch, double crown) {
  const double c = std::cos(haunch), s = std::sin(haunch);
  const double a11 = 1 - c, a12 = c - std::sin(crown);
  const double a21 = s, a22 = std::cos(crown) - s;
  const double det = a11 * a22 - a12 * a21;  // < 0 on the open domain of the angles
  return {(half_span * a22 - rise * a12) / det, (a11 * rise - a21 * half_span) / det};
}

void check_haunch_angle(double haunch_angle_deg) {
  if (!std::isfinite(haunch_angle_deg) || !(haunch_angle_deg > 0 && haunch_angle_deg < 90))
    refuse("haunch_angle", "must lie in (0, 90) degrees", haunch_angle_deg);
}

void check_crown_angle(double haunch_angle_deg, double crown_angle_deg) {
  if (!std::isfinite(crown_angle_deg) || !(crown_angle_deg > 0 && crown_angle_deg < 90 - haunch_angle_deg))
    refuse("crown_angle",
           fmt::format("must lie in (0, {}) degrees for haunch_angle {} (0 is the three-centred arch)",
                       90 - haunch_angle_deg, haunch_angle_deg),
           crown_angle_deg);
}

std::pair<double, double> centred_rise_range(double haunch, double crown) {
  const double c = std::cos(haunch), s = std::sin(haunch);
  return {(std::cos(crown) - s) / (2 * (c - std::sin(crown))), std::cos(crown) / (2 * (1 - std::sin(crown)))};
}

std::shared_ptr<const Curve> make_centred(const char* family, double span, double rise_ratio, double haunch,
                                          double crown, const std::string& angles_text) {
  const double half_span = 0.5 * span, rise = rise_ratio * span;
  const auto [r1, r2] = centred_radii(half_span, rise, haunch, crown);
  if (!std::isfinite(rise_ratio) || !(r1 > 0 && r2 > r1 && std::isfinite(r2))) {
    const auto [lo, hi] = centred_rise_range(haunch, crown);
    refuse("rise_ratio",
           fmt::format("must lie in ({:.6g}, {:.6g}) for a {} arch with {}", lo, hi, family, angles_text),
           rise_ratio);
  }
  CircularArc haunch_arc{0.0, r1 * haunch, 0.0, 0.0, kHalfPi, -1.0 / r1};
  const CurvePoint joint = point_on_arc(haunch_arc, haunch_arc.length);
  CircularArc crown_arc{haunch_arc.length, r2 * (kHalfPi - haunch - crown), joint.x, joint.y,
                        kHalfPi - haunch, -1.0 / r2};
  return std::make_shared<PiecewiseCircularCurve>(family, span, std::vector<CircularArc>{haunch_arc, crown_arc});
}

// ---------------------------------------------------------------------------------------------------
// Elliptical: x = a (1 - cos t), y = h sin t.

class EllipticalCurve final : public ParametricCurve {
 public:
  EllipticalCurve(double span, double rise) : span_(span), a_(0.5 * span), h_(rise) {
    // More initial panels when the ellipse is far from a circle; adaptivity does the rest.
    build_arc_length({0.0, kHalfPi}, 4);
  }
  std::string family() const override { return "elliptical"; }
  double span() const override { return span_; }

 protected:
  Jet jet(double t, std::size_t) const override {
    // sin t, cos t and 1 - cos t without cancellation, and exact at both ends: t = 0 gives (0, 1, 0),
    // t = pi/2 (the double) gives (1, 0, 1).
    double sn, cs, one_minus_cs;
    if (t <= 0.5 * kHalfPi) {
      sn = std::sin(t);
      cs = std::cos(t);
      const double h = std::sin(0.5 * t);
      one_minus_cs = 2 * h * h;
    } else {
      const double p = kHalfPi - t;
      sn = std::cos(p);
      cs = std::sin(p);
      one_minus_cs = 1 - cs;
    }
    return {a_ * one_minus_cs, h_ * sn, a_ * sn, h_ * cs, a_ * cs, -h_ * sn};
  }

 private:
  double span_, a_, h_;
};

// ---------------------------------------------------------------------------------------------------
// Parabolic: with u = L/2 - x (distance from the crown) and c = 8 h / L^2, y = h - c u^2 / 2,
// tan theta = c u, and the arc length from the crown is sigma(u) = (u sqrt(1 + c^2 u^2) + asinh(c u) / c) / 2.

class ParabolicCurve final : public Curve {
 public:
  ParabolicCurve(double span, double rise)
      : span_(span), half_(0.5 * span), rise_(rise), c_(8 * rise / (span * span)), length_(sigma(half_)) {}
  std::string family() const override { return "parabolic"; }
  double span() const override { return span_; }
  double length() const override { return length_; }

  CurvePoint at(double s) const override {
    const double u = s == 0 ? half_ : s == length_ ? 0.0 : distance_from_crown(length_ - s);
    const double cu = c_ * u;
    const double q = 1 + cu * cu;
    return {half_ - u, 0.5 * c_ * (half_ - u) * (half_ + u), std::atan(cu), -c_ / (q * std::sqrt(q))};
  }

  // |kappa| = c / (1 + c^2 u^2)^{3/2} is largest at the crown.
  double max_curvature() const override { return c_; }

  // The parameter is x (0 at the springing, L/2 at the crown): s = S - sigma(L/2 - x), tan theta = c u.
  std::vector<double> parameter_knots() const override { return {0.0, half_}; }
  ParameterPoint at_parameter(double x) const override {
    const double u = half_ - x;
    const double cu = c_ * u;
    const double speed = std::sqrt(1 + cu * cu);
    return {x == 0 ? 0.0 : length_ - sigma(u), speed, 1 / speed, cu / speed};
  }
  double parameter_at(double s) const override {
    return s == 0 ? 0.0 : s == length_ ? half_ : half_ - distance_from_crown(length_ - s);
  }

  // Integral of x ds = U S - ((1 + c^2 U^2)^{3/2} - 1) / (3 c^2), the bracket by expm1/log1p.
  double first_moment_x() const override {
    const double w = c_ * half_ * c_ * half_;
    const double bracket = std::expm1(1.5 * std::log1p(w));  // (1 + w)^{3/2} - 1
    return half_ * length_ - half_ * half_ * bracket / (3 * w);
  }

 private:
  double sigma(double u) const {
    const double cu = c_ * u;
    return 0.5 * (u * std::sqrt(1 + cu * cu) + std::asinh(cu) / c_);
  }
  // Solves sigma(u) = target (sigma is odd, increasing and convex for u >= 0): Newton from the right of
  // the root converges monotonically; a bisection safeguard keeps it inside the bracket anyway.
  double distance_from_crown(double target) const {
    const double sign = target < 0 ? -1.0 : 1.0;
    target = std::abs(target);
    // Bracket: sigma(u) >= u, so u* <= target; sigma(u) >= c u^2 / 2, so u* <= sqrt(2 target / c).
    double lo = 0, hi = std::min(target, std::sqrt(2 * target / c_));
    double u = hi;
    for (int it = 0; it < 200; ++it) {
      const double f = sigma(u) - target;
      if (f > 0) hi = u; else lo = u;
      if (f == 0) break;
      const double cu = c_ * u;
      double next = u - f / std::sqrt(1 + cu * cu);
      if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
      const bool done = std::abs(next - u) <= 1e-15 * half_;
      u = next;
      if (done) break;
    }
    return sign * u;
  }

  double span_, half_, rise_, c_, length_;
};

// ---------------------------------------------------------------------------------------------------
// Catenary: sigma = arc length from the crown = a sinh(u / a), u = L/2 - x.

// Solves g(z) = (cosh z - 1) / z = q for z = L / (2 a) > 0. g is increasing and convex, g(z) >= z / 2,
// so the root lies in (0, 2 q]; Newton from the right of the root converges monotonically.
double catenary_z(double q) {
  auto g = [](double z) {
    const double sh = std::sinh(0.5 * z);
    return 2 * sh * sh / z;
  };
  auto dg = [](double z) {
    if (z < 1e-4) return 0.5 + z * z / 8;  // the series: no 0/0 for tiny z
    const double sh = std::sinh(0.5 * z);
    return (z * std::sinh(z) - 2 * sh * sh) / (z * z);
  };
  double lo = 0, hi = 2 * q;
  double z = hi;
  for (int it = 0; it < 300; ++it) {
    const double f = g(z) - q;
    if (f > 0) hi = z; else lo = z;
    if (f == 0) break;
    double next = z - f / dg(z);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - z) <= 4 * std::numeric_limits<double>::epsilon() * z;
    z = next;
    if (done) break;
  }
  return z;
}

class CatenaryCurve final : public Curve {
 public:
  CatenaryCurve(double span, double rise, double a)
      : span_(span), half_(0.5 * span), rise_(rise), a_(a), length_(a * std::sinh(half_ / a)) {}
  std::string family() const override { return "catenary"; }
  double span() const override { return span_; }
  double length() const override { return length_; }

  CurvePoint at(double s) const override {
    const double sigma = length_ - s;
    const double u = s == 0 ? half_ : a_ * std::asinh(sigma / a_);
    // y = a (cosh(U/a) - cosh(u/a)) = 2 a sinh((U + u) / 2a) sinh((U - u) / 2a): exactly 0 at the springing.
    const double y = 2 * a_ * std::sinh((half_ + u) / (2 * a_)) * std::sinh((half_ - u) / (2 * a_));
    const double r = sigma / a_;
    return {half_ - u, s == length_ ? rise_ : y, std::atan(r), -1.0 / (a_ * (1 + r * r))};
  }

  // tan theta = sigma / a: no hyperbolic function needed.
  double angle(double s) const override { return std::atan((length_ - s) / a_); }

  // Integral of x ds = int_0^U (U - u) cosh(u / a) du = a^2 (cosh(U / a) - 1) = a h.
  double first_moment_x() const override { return a_ * rise_; }
  // |kappa| = 1 / (a (1 + (sigma / a)^2)) is largest at the crown.
  double max_curvature() const override { return 1.0 / a_; }

 private:
  double span_, half_, rise_, a_, length_;
};

}  // namespace

// ---------------------------------------------------------------------------------------------------
// ParametricCurve

double ParametricCurve::speed(double t, std::size_t piece) const {
  const Jet j = jet(t, piece);
  return std::sqrt(j.dx * j.dx + j.dy * j.dy);
}

double ParametricCurve::integral_of_speed(double t0, double t1, std::size_t piece) const {
  return gauss_legendre_integral<kGaussOrder>([&](double t) { return speed(t, piece); }, t0, t1);
}

void ParametricCurve::build_arc_length(const std::vector<double>& knots, int initial_panels) {
  if (knots.size() < 2) throw std::invalid_argument("curve: a parametric curve needs two knots");
  constexpr double kPanelTolerance = 4e-15;  // relative, per panel
  constexpr int kMaxDepth = 60;
  const double range = knots.back() - knots.front();
  knots_ = knots;
  t_.assign(1, knots.front());
  s_.assign(1, 0.0);
  piece_.clear();
  first_moment_ = 0;
  max_curvature_ = 0;
  const auto curvature = [](const Jet& j) {
    const double v2 = j.dx * j.dx + j.dy * j.dy;
    return std::abs(j.dx * j.ddy - j.dy * j.ddx) / (v2 * std::sqrt(v2));
  };
  struct Panel {
    double a, b, integral;
    int depth;
  };
  std::vector<Panel> stack;
  // Panels examined (accepted or split), over all pieces.
  std::size_t panels = 0;
  const std::size_t budget =
      kPanelBudgetBase + kPanelBudgetPerPanel * (knots.size() - 1) * static_cast<std::size_t>(initial_panels);
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    // Panels of this piece, left to right: a stack popped from the left end.
    for (int p = initial_panels - 1; p >= 0; --p) {
      const double w = (knots[k + 1] - knots[k]) / initial_panels;
      const double a = p == 0 ? knots[k] : knots[k] + p * w;
      const double b = p == initial_panels - 1 ? knots[k + 1] : knots[k] + (p + 1) * w;
      stack.push_back({a, b, integral_of_speed(a, b, k), 0});
    }
    while (!stack.empty()) {
      // Found by fuzzing: a points fit that nearly stops at its crown made this loop split panels down
      // to 1e-13 of the range -- billions of them (minutes) -- because round-off in the speed kept the
      // halves from agreeing. Smooth pieces need few panels (a points fit's pieces one, an ellipse about
      // 40, a sharp but sound turn a few hundred), so past a budget the curve is refused instead.
      if (++panels > budget)
        throw ArcLengthError(k, fmt::format("curve: the arc length between t = {} and {} does not converge: the "
                                            "speed nearly vanishes there (a cusp)",
                                            knots[k], knots[k + 1]));
      const Panel panel = stack.back();
      stack.pop_back();
      const double mid = 0.5 * (panel.a + panel.b);
      const double left = integral_of_speed(panel.a, mid, k), right = integral_of_speed(mid, panel.b, k);
      const bool converged = std::abs(panel.integral - (left + right)) <= kPanelTolerance * (left + right);
      if (converged || panel.depth >= kMaxDepth || (panel.b - panel.a) <= 1e-13 * range) {
        // Keep the one-panel value: the Newton inversion integrates from the panel's start with the same
        // rule, so s(t) is continuous at the panel ends.
        t_.push_back(panel.b);
        s_.push_back(s_.back() + panel.integral);
        piece_.push_back(k);
        first_moment_ += gauss_legendre_integral<kGaussOrder>(
            [&](double t) {
              const Jet j = jet(t, k);
              max_curvature_ = std::max(max_curvature_, curvature(j));
              return j.x * std::sqrt(j.dx * j.dx + j.dy * j.dy);
            },
            panel.a, panel.b);
        max_curvature_ = std::max({max_curvature_, curvature(jet(panel.a, k)), curvature(jet(panel.b, k))});
      } else {
        stack.push_back({mid, panel.b, right, panel.depth + 1});
        stack.push_back({panel.a, mid, left, panel.depth + 1});
      }
    }
  }
  build_arc_table();
}

void ParametricCurve::build_arc_table() {
  const ChebyshevRule& rule = chebyshev_rule(kArcTableDegree);
  const std::size_t panels = piece_.size(), n = kArcTableDegree + 1;
  arc_table_.assign(panels * n, 0.0);
  arc_table_ok_.assign(panels, false);
  Eigen::VectorXd speeds(n);
  for (std::size_t k = 0; k < panels; ++k) {
    const double mid = 0.5 * (t_[k] + t_[k + 1]), h = 0.5 * (t_[k + 1] - t_[k]);
    for (std::size_t i = 0; i < n; ++i) speeds[i] = speed(mid + h * rule.node[i], piece_[k]);
    const Eigen::VectorXd s = h * (rule.integration * speeds);
    const Eigen::VectorXd a = rule.to_coefficients * s;
    std::copy(a.data(), a.data() + n, arc_table_.begin() + k * n);
    // The table must reproduce the Gauss integral (what the tabulation accepted) to round-off, at the
    // panel's end and between the nodes (a quarter of the way).
    const double length = s_[k + 1] - s_[k];
    const double quarter = integral_of_speed(t_[k], t_[k] + 0.5 * h, piece_[k]);
    arc_table_ok_[k] = std::abs(s[n - 1] - length) <= kArcTableTolerance * length &&
                       std::abs(chebyshev_series(a.data(), kArcTableDegree, -0.5) - quarter) <= kArcTableTolerance * length;
  }
}

std::pair<double, std::size_t> ParametricCurve::locate(double s) const {
  const std::size_t panels = piece_.size();
  if (s == s_.back()) return {t_.back(), piece_.back()};
  // The panel k with s_[k] <= s < s_[k + 1]; the end panels take s outside [0, S].
  std::size_t k = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin());
  k = k == 0 ? 0 : std::min(k - 1, panels - 1);
  const std::size_t piece = piece_[k];
  if (s == s_[k]) return {t_[k], piece};
  const bool bracketed = s >= s_[k] && s <= s_[k + 1];
  double lo = t_[k], hi = t_[k + 1];
  double t = lo + (hi - lo) * ((s - s_[k]) / (s_[k + 1] - s_[k]));
  const double tolerance = 1e-15 * (t_.back() - t_.front());
  const bool tabulated = bracketed && arc_table_ok_[k];
  const double* table = arc_table_.data() + k * (kArcTableDegree + 1);
  const double mid = 0.5 * (t_[k] + t_[k + 1]), inverse_h = 2 / (t_[k + 1] - t_[k]);
  for (int it = 0; it < 100; ++it) {
    const double f = s_[k] - s + (tabulated ? chebyshev_series(table, kArcTableDegree, (t - mid) * inverse_h)
                                            : integral_of_speed(t_[k], t, piece));
    if (f == 0) break;
    if (bracketed) (f > 0 ? hi : lo) = t;
    double next = t - f / speed(t, piece);
    if (bracketed && !(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
    const bool done = std::abs(next - t) <= tolerance;
    t = next;
    if (done) break;
  }
  return {t, piece};
}

double ParametricCurve::parameter_at(double s) const { return locate(s).first; }

ParameterPoint ParametricCurve::at_parameter(double t) const {
  // The arc-length panel holding t (the end panels take t outside the knots), then its table or its
  // Gauss integral from the panel's start: the same s(t) that at(s) inverts.
  const std::size_t panels = piece_.size();
  std::size_t k = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin());
  k = k == 0 ? 0 : std::min(k - 1, panels - 1);
  const std::size_t piece = piece_[k];
  double s = s_[k];
  if (t == t_[k + 1]) {
    s = s_[k + 1];
  } else if (t != t_[k]) {
    const double mid = 0.5 * (t_[k] + t_[k + 1]), inverse_h = 2 / (t_[k + 1] - t_[k]);
    s += arc_table_ok_[k] ? chebyshev_series(arc_table_.data() + k * (kArcTableDegree + 1), kArcTableDegree,
                                             (t - mid) * inverse_h)
                          : integral_of_speed(t_[k], t, piece);
  }
  const Jet j = jet(t, piece);
  const double speed = std::sqrt(j.dx * j.dx + j.dy * j.dy);
  return {s, speed, j.dx / speed, j.dy / speed};
}

double ParametricCurve::arc_length_at_knot(double t) const {
  const auto it = std::lower_bound(t_.begin(), t_.end(), t);
  if (it == t_.end() || *it != t) throw std::logic_error("arc_length_at_knot: not a knot");
  return s_[static_cast<std::size_t>(it - t_.begin())];
}

CurvePoint ParametricCurve::at(double s) const {
  const auto [t, piece] = locate(s);
  const Jet j = jet(t, piece);
  const double v2 = j.dx * j.dx + j.dy * j.dy;
  const double v = std::sqrt(v2);
  return {j.x, j.y, std::atan2(j.dy, j.dx), (j.dx * j.ddy - j.dy * j.ddx) / (v2 * v)};
}

// ---------------------------------------------------------------------------------------------------
// Factories

std::shared_ptr<const Curve> make_segmental(double span, double rise_ratio) {
  check_span(span);
  if (!std::isfinite(rise_ratio) || !(rise_ratio > 0 && rise_ratio < 0.5))
    refuse("rise_ratio", "must lie in (0, 0.5) for a segmental arch", rise_ratio);
  const double half_span = 0.5 * span, rise = rise_ratio * span;
  const double radius = (half_span * half_span + rise * rise) / (2 * rise);
  // The springing angle is twice the chord's angle from springing to crown (inscribed-angle theorem).
  const double alpha = 2 * std::atan(rise / half_span);
  return std::make_shared<PiecewiseCircularCurve>(
      "segmental", span, std::vector<CircularArc>{{0.0, radius * alpha, 0.0, 0.0, alpha, -1.0 / radius}});
}

std::pair<double, double> three_centred_rise_range(double haunch_angle_deg) {
  check_haunch_angle(haunch_angle_deg);
  return centred_rise_range(radians(haunch_angle_deg), 0.0);
}

std::pair<double, double> four_centred_rise_range(double haunch_angle_deg, double crown_angle_deg) {
  check_haunch_angle(haunch_angle_deg);
  check_crown_angle(haunch_angle_deg, crown_angle_deg);
  return centred_rise_range(radians(haunch_angle_deg), radians(crown_angle_deg));
}

std::shared_ptr<const Curve> make_three_centred(double span, double rise_ratio, double haunch_angle_deg) {
  check_span(span);
  check_haunch_angle(haunch_angle_deg);
  return make_centred("three-centred", span, rise_ratio, radians(haunch_angle_deg), 0.0,
                      fmt::format("haunch_angle {}", haunch_angle_deg));
}

std::shared_ptr<const Curve> make_four_centred(double span, double rise_ratio, double haunch_angle_deg,
                                               double crown_angle_deg) {
  check_span(span);
  check_haunch_angle(haunch_angle_deg);
  check_crown_angle(haunch_angle_deg, crown_angle_deg);
  return make_centred("four-centred", span, rise_ratio, radians(haunch_angle_deg), radians(crown_angle_deg),
                      fmt::format("haunch_angle {} and crown_angle {}", haunch_angle_deg, crown_angle_deg));
}

std::shared_ptr<const Curve> make_elliptical(double span, double rise_ratio) {
  check_span(span);
  check_smooth_rise(rise_ratio, "an elliptical");
  return std::make_shared<EllipticalCurve>(span, rise_ratio * span);
}

std::shared_ptr<const Curve> make_parabolic(double span, double rise_ratio) {
  check_span(span);
  check_smooth_rise(rise_ratio, "a parabolic");
  return std::make_shared<ParabolicCurve>(span, rise_ratio * span);
}

double catenary_parameter(double span, double rise_ratio) {
  check_span(span);
  check_smooth_rise(rise_ratio, "a catenary");
  // With z = L / (2a): a (cosh(L / 2a) - 1) = h  <=>  (cosh z - 1) / z = h / (L / 2) = 2 rise_ratio.
  return 0.5 * span / catenary_z(2 * rise_ratio);
}

std::shared_ptr<const Curve> make_catenary(double span, double rise_ratio) {
  const double a = catenary_parameter(span, rise_ratio);
  return std::make_shared<CatenaryCurve>(span, rise_ratio * span, a);
}

}  // namespace ogive
