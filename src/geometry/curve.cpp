#include "ogive/geometry/curve.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "numerics/gauss_legendre.hpp"

namespace ogive {
namespace {

// sin(z)/z, accurate near 0 where the quotient would cancel.
double sinc(double z) { return std::abs(z) < 1e-4 ? 1.0 - z * z / 6.0 : std::sin(z) / z; }

}  // namespace

CurvePoint point_on_arc(const CircularArc& arc, double ds) {
  const double half_turn = 0.5 * arc.kappa * ds;
  const double mid = arc.theta_start + half_turn;
  // x1 - x0 = (sin th1 - sin th0)/kappa = ds cos(mid) sinc(half_turn): no cancellation as kappa -> 0.
  const double chord = ds * sinc(half_turn);
  return {arc.x_start + chord * std::cos(mid), arc.y_start + chord * std::sin(mid),
          arc.theta_start + arc.kappa * ds, arc.kappa};
}

CurvePoint mirror(const CurvePoint& p, double span) { return {span - p.x, p.y, -p.theta, p.kappa}; }

PlanePoint along_normal(const CurvePoint& p, double offset) {
  return {p.x - offset * std::sin(p.theta), p.y + offset * std::cos(p.theta)};
}

SectionFaces section_faces(const CurvePoint& p, double thickness) {
  return {along_normal(p, -0.5 * thickness), along_normal(p, 0.5 * thickness)};
}

CurvePoint Curve::at_whole_arch(double s) const {
  const double S = length();
  if (extent() == CurveExtent::whole) return at(s);
  return s <= S ? at(s) : mirror(at(2.0 * S - s), span());
}

namespace {

// A half arch and its mirror image as one whole curve: s in [0, S] is the half's, s in (S, 2S] the mirror
// of the half's point at 2S - s. Its arcs (when the half has some) are the half's followed by their
// mirror images in reverse order; a mirrored arc keeps its curvature and starts at minus the angle its
// original ends with.
class MirroredCurve final : public Curve {
 public:
  explicit MirroredCurve(std::shared_ptr<const Curve> half) : half_(std::move(half)), S_(half_->length()) {
    const auto arcs = half_->arcs();
    arcs_.assign(arcs.begin(), arcs.end());
    for (auto it = arcs.rbegin(); it != arcs.rend(); ++it) {
      const CurvePoint end = mirror(point_on_arc(*it, it->length), half_->span());
      arcs_.push_back({2.0 * S_ - (it->s_start + it->length), it->length, end.x, end.y, end.theta, it->kappa});
    }
  }
  CurveExtent extent() const override { return CurveExtent::whole; }
  std::string family() const override { return half_->family(); }
  double span() const override { return half_->span(); }
  double length() const override { return 2.0 * S_; }
  CurvePoint at(double s) const override { return s <= S_ ? half_->at(s) : mirror(half_->at(2.0 * S_ - s), span()); }
  double angle(double s) const override { return s <= S_ ? half_->angle(s) : -half_->angle(2.0 * S_ - s); }
  // The half's, the crown (its third derivative may jump, its tangent at a pointed crown) and the
  // mirrored ones.
  std::vector<double> breakpoints() const override {
    std::vector<double> out = half_->breakpoints();
    out.push_back(S_);
    const std::vector<double> left = half_->breakpoints();
    for (auto it = left.rbegin(); it != left.rend(); ++it) out.push_back(2.0 * S_ - *it);
    return out;
  }
  std::span<const CircularArc> arcs() const override { return arcs_; }
  double crown() const override { return S_; }
  double first_moment_x() const override {
    // The mirror's x is L - x on the same lengths: integral = S L - M_half, plus the half's M_half.
    return S_ * span();
  }
  double max_curvature() const override { return half_->max_curvature(); }

 private:
  std::shared_ptr<const Curve> half_;
  double S_;
  std::vector<CircularArc> arcs_;
};

}  // namespace

std::shared_ptr<const Curve> whole_arch(std::shared_ptr<const Curve> curve) {
  if (!curve) throw std::invalid_argument("curve: whole_arch needs a curve");
  if (curve->extent() == CurveExtent::whole) return curve;
  return std::make_shared<MirroredCurve>(std::move(curve));
}

double arc_length_at_x(const Curve& whole, double x) {
  // Bisection on x(s), which never decreases: robust where dx/ds vanishes (a vertical springing), and
  // 64 halvings reach round-off of any length.
  const double length = whole.extent() == CurveExtent::whole ? whole.length() : whole.whole_length();
  x = std::clamp(x, 0.0, whole.span());
  double lo = 0, hi = length;
  if (whole.at_whole_arch(lo).x >= x) return lo;
  for (int i = 0; i < 64 && hi - lo > 0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (whole.at_whole_arch(mid).x < x ? lo : hi) = mid;
  }
  return hi;
}

ParameterPoint Curve::at_parameter(double) const {
  throw std::logic_error("Curve::at_parameter: the " + family() + " curve has no parameter of its own");
}

double Curve::parameter_at(double) const {
  throw std::logic_error("Curve::parameter_at: the " + family() + " curve has no parameter of its own");
}

double Curve::max_curvature() const {
  constexpr int kSamples = 512;
  double largest = 0;
  for (int i = 0; i <= kSamples; ++i) largest = std::max(largest, std::abs(at(length() * i / kSamples).kappa));
  return largest;
}

double PiecewiseCircularCurve::max_curvature() const {
  double largest = 0;
  for (const CircularArc& arc : arcs_) largest = std::max(largest, std::abs(arc.kappa));
  return largest;
}

double Curve::first_moment_x() const {
  // Composite 8-point Gauss-Legendre between breakpoints: the integrand is smooth on each piece.
  std::vector<double> knots{0.0};
  for (double b : breakpoints()) knots.push_back(b);
  knots.push_back(length());
  constexpr int kPanelsPerPiece = 32;
  double sum = 0;
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    const double h = (knots[k + 1] - knots[k]) / kPanelsPerPiece;
    for (int p = 0; p < kPanelsPerPiece; ++p) {
      const double mid = knots[k] + (p + 0.5) * h;
      sum += gauss_legendre_integral<8>([&](double s) { return at(s).x; }, mid - 0.5 * h, mid + 0.5 * h);
    }
  }
  return sum;
}

PiecewiseCircularCurve::PiecewiseCircularCurve(std::string family, double span,
                                               std::vector<CircularArc> arcs)
    : family_(std::move(family)), span_(span), length_(0), arcs_(std::move(arcs)) {
  if (!(span_ > 0) || !std::isfinite(span_))
    throw std::invalid_argument("span: must be a finite positive length");
  if (arcs_.empty()) throw std::invalid_argument("curve: a piecewise-circular curve needs an arc");
  for (const CircularArc& arc : arcs_) {
    if (!(arc.length > 0) || !std::isfinite(arc.length) || !std::isfinite(arc.kappa))
      throw std::invalid_argument("curve: every arc needs a finite positive length and curvature");
    if (std::abs(arc.s_start - length_) > 1e-12 * span_)
      throw std::invalid_argument("curve: arcs must follow each other without gaps");
    length_ += arc.length;
  }
}

const CircularArc& arc_at(std::span<const CircularArc> arcs, double s) {
  auto it = std::upper_bound(arcs.begin(), arcs.end(), s, [](double v, const CircularArc& a) { return v < a.s_start; });
  return it == arcs.begin() ? arcs.front() : *std::prev(it);
}

CurvePoint PiecewiseCircularCurve::at(double s) const {
  const CircularArc& arc = arc_at(arcs_, s);
  return point_on_arc(arc, s - arc.s_start);
}

double PiecewiseCircularCurve::angle(double s) const {
  const CircularArc& arc = arc_at(arcs_, s);
  return arc.theta_start + arc.kappa * (s - arc.s_start);  // as point_on_arc
}

std::vector<double> PiecewiseCircularCurve::breakpoints() const {
  std::vector<double> out;
  for (std::size_t i = 1; i < arcs_.size(); ++i)
    if (arcs_[i].kappa != arcs_[i - 1].kappa) out.push_back(arcs_[i].s_start);
  return out;
}

double PiecewiseCircularCurve::first_moment_x() const {
  // On an arc, x(s0 + u) = x0 + int_0^u cos(theta0 + k v) dv, so int x ds = x0 l + l^2 Re[e^{i theta0} g(i k l)]
  // with g(z) = (e^z - 1 - z) / z^2; near z = 0 g comes from its series, which avoids the cancellation.
  double sum = 0;
  for (const CircularArc& arc : arcs_) {
    const std::complex<double> z(0.0, arc.kappa * arc.length);
    std::complex<double> g;
    if (std::abs(z) < 0.5) {
      std::complex<double> term = 0.5;  // z^n / (n + 2)!
      g = term;
      for (int n = 1; n < 16; ++n) {
        term *= z / double(n + 2);
        g += term;
      }
    } else {
      g = (std::exp(z) - 1.0 - z) / (z * z);
    }
    sum += arc.x_start * arc.length +
           arc.length * arc.length * (std::polar(1.0, arc.theta_start) * g).real();
  }
  return sum;
}

std::shared_ptr<const Curve> make_pointed(double span, double eccentricity) {
  if (!(span >= kMinSpan && span <= kMaxSpan))
    throw std::invalid_argument(fmt::format("span: must lie in [{}, {}] m, got {}", kMinSpan, kMaxSpan, span));
  if (!(eccentricity >= 0) || !std::isfinite(eccentricity))
    throw std::invalid_argument("eccentricity: must be finite and >= 0");
  const double radius = pointed_radius(span, eccentricity);
  // Half-arch angle: cos(alpha_c) = eccentricity / (0.5 + eccentricity).
  const double alpha_c = std::acos(eccentricity / (0.5 + eccentricity));
  const std::string family = eccentricity == 0 ? "semicircular" : "pointed";
  return std::make_shared<PiecewiseCircularCurve>(
      family, span,
      std::vector<CircularArc>{{0.0, radius * alpha_c, 0.0, 0.0, std::numbers::pi / 2, -1.0 / radius}});
}

double pointed_radius(double span, double eccentricity) { return (0.5 + eccentricity) * span; }
double pointed_eccentricity_for_rise(double rise_ratio) { return rise_ratio * rise_ratio - 0.25; }
double pointed_eccentricity_for_radius(double radius_ratio) { return radius_ratio - 0.5; }

}  // namespace ogive
