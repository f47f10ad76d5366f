#include "geometry/side_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ogive {

SideView::SideView(const Curve& curve, bool right) : curve_(curve), right_(right) {
  const bool whole = curve.extent() == CurveExtent::whole;
  whole_length_ = curve.whole_length();
  const double C = whole ? curve.crown() : curve.length();
  const double tiny = 1e-12 * whole_length_;
  S_ = right ? whole_length_ - C : C;
  const CurvePoint crown = curve.at(C);  // from the left at a kink (Curve's contract)
  crown_x_ = whole ? crown.x : 0.5 * curve.span();  // a half's crown is at mid-span (to round-off: exactly)
  const auto arcs = curve.arcs();
  if (!right) {
    crown_ = crown;
    for (const CircularArc& a : arcs)
      if (a.s_start < C - tiny) end_arc_ = a;
    for (double b : curve.breakpoints())
      if (b < C - tiny) breaks_.push_back(b);
  } else {
    // The arc holding the crown from the right, reversed and mirrored (as MirroredCurve mirrors arcs).
    for (const CircularArc& a : arcs)
      if (a.s_start + a.length > C + tiny) {
        const CurvePoint end = mirror(point_on_arc(a, a.length), 2.0 * crown_x_);
        end_arc_ = CircularArc{whole_length_ - (a.s_start + a.length), a.length, end.x, end.y, end.theta, a.kappa};
        break;
      }
    if (end_arc_) {
      crown_ = point_on_arc(*end_arc_, S_ - end_arc_->s_start);
    } else {
      // The tangent just past a kink (a curve without arcs gives only the left one at the crown itself).
      const CurvePoint past = curve.at(std::min(C + 1e-10 * whole_length_, whole_length_));
      crown_ = {crown_x_, crown.y, -past.theta, past.kappa};
    }
    crown_.x = crown_x_;
    crown_.y = crown.y;
    const std::vector<double> b = curve.breakpoints();
    for (auto it = b.rbegin(); it != b.rend(); ++it)
      if (*it > C + tiny) breaks_.push_back(whole_length_ - *it);
  }
  breaks_.push_back(S_);
}

double face_at_x(const SideView& side, double n, double x, double lo, double hi, double span, double guess) {
  double s = guess > lo && guess < hi ? guess : 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const FacePoint f = face_at(side, n, s);
    const double r = f.p.x() - x;
    if (r > 0) hi = s; else lo = s;
    if (std::abs(r) <= 1e-15 * span || hi - lo <= 1e-15 * span) break;
    const double newton = f.dp.x() > 0 ? s - r / f.dp.x() : 0.5 * (lo + hi);
    s = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
  }
  return s;
}

SideExtrados::SideExtrados(const SideView& side, double thickness, double span)
    : side_(side), half_t_(0.5 * thickness), span_(span) {
  const double S = side.length(), xc = side.crown_x();
  s_crown_ = S;
  // At a pointed crown the extrados passes the crown's vertical beyond the axis' crown: find where.
  if (side.at(S).theta > 1e-12) {
    double hi = S + thickness;
    while (face_at(side, half_t_, hi).p.x() < xc) hi = S + 2.0 * (hi - S);
    s_crown_ = face_at_x(side, half_t_, xc, S, hi, span);
  }
  x_begin_ = face_at(side, half_t_, 0.0).p.x();
  for (double b : side.breaks())
    if (b < s_crown_) break_x_.push_back(face_at(side, half_t_, b).p.x());
}

double extrados_crown_height(const Curve& curve, double thickness) {
  double height = -std::numeric_limits<double>::infinity();
  for (bool right : {false, true}) {
    if (right && curve.extent() != CurveExtent::whole) break;
    const SideView side(curve, right);
    const SideExtrados extrados(side, thickness, curve.span());
    height = std::max(height, face_at(side, 0.5 * thickness, extrados.s_crown()).p.y());
  }
  return height;
}

IntradosDimensions intrados_dimensions(const Curve& curve, double thickness) {
  if (curve.extent() != CurveExtent::half)
    throw std::invalid_argument("curve: the intrados' clear span and rise are those of a symmetric (half) curve");
  const SideView side(curve, false);
  const double n = -0.5 * thickness, xc = side.crown_x(), S = side.length();
  const FacePoint springing = face_at(side, n, 0.0);
  // The intrados' x grows with s; it reaches the crown's vertical at the crown (smooth) or before it
  // (pointed: the inner face turns past the vertical before the axis does).
  if (!(face_at(side, n, S).p.x() >= xc - 1e-12 * curve.span()) || !(springing.p.x() < xc))
    throw std::invalid_argument("thickness: the intrados of this ring does not reach the crown's vertical");
  const double s = face_at_x(side, n, xc, 0.0, S, curve.span());
  return {2.0 * (xc - springing.p.x()), face_at(side, n, s).p.y() - springing.p.y()};
}

double SideExtrados::s_at(double x, double guess) const {
  if (x <= x_begin_) return 0.0;
  return face_at_x(side_, half_t_, x, 0.0, s_crown_, span_, guess);
}

}  // namespace ogive
