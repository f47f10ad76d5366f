// One side of an arch, springing to crown, seen as the left half of a symmetric arch, and the faces of
// its ring: the lines at a signed distance from the axis along the normal, the extrados (t/2) above all.
// Both the elastic model and limit analysis load the arch with the fill above this extrados, so they
// share this one construction of it (private header of the geometry layer).
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "ogive/geometry/curve.hpp"

namespace ogive {

// The left side as it is; the right side run from its springing towards the crown and mirrored about the
// vertical through the crown (x -> 2 x_c - x), so that one construction serves both sides of a whole
// curve; a half curve has only its left side (the right is its mirror image about mid-span). Beyond the
// crown (s > S; only the extrados of a pointed crown goes there, up to the crown's vertical) the side's
// axis is continued: along its last arc for a piecewise-circular curve, otherwise along its tangent at
// the crown. Keeps a reference to the curve.
class SideView {
 public:
  SideView(const Curve& curve, bool right);

  double length() const { return S_; }         // m, springing to crown
  double crown_x() const { return crown_x_; }  // m, in the view's (and the curve's) coordinates
  // The axis' point at arc length s from this side's springing (continued beyond the crown). Inline:
  // the faces' integrals call it at every node.
  CurvePoint at(double s) const {
    if (right_ ? s < S_ : s <= S_) return right_ ? mirror(curve_.at(whole_length_ - s), 2.0 * crown_x_) : curve_.at(s);
    if (end_arc_) return point_on_arc(*end_arc_, s - end_arc_->s_start);
    return {crown_.x + (s - S_) * std::cos(crown_.theta), crown_.y + (s - S_) * std::sin(crown_.theta), crown_.theta, 0.0};
  }
  // Interior breakpoints of the side and the crown, ascending: where the faces' integrands are not smooth.
  const std::vector<double>& breaks() const { return breaks_; }
  // The curve's coordinates of a view's abscissa, and the whole arch's arc length of a view's.
  double curve_x(double x) const { return right_ ? 2.0 * crown_x_ - x : x; }
  // The moment about the curve's origin (sum of F curve_x(x)) of forces with total `force` and moment
  // `moment` about the view's origin.
  double curve_moment(double force, double moment) const { return right_ ? 2.0 * crown_x_ * force - moment : moment; }
  double whole_s(double s) const { return right_ ? whole_length_ - s : s; }

 private:
  const Curve& curve_;
  bool right_;
  double whole_length_ = 0, S_ = 0, crown_x_ = 0;
  CurvePoint crown_;  // the crown with this side's tangent
  std::optional<CircularArc> end_arc_;
  std::vector<double> breaks_;
};

// A point of the line at signed distance n from the axis (n > 0 towards the extrados), at arc length s
// of a side, and its derivative d/ds.
struct FacePoint {
  Eigen::Vector2d p, dp;
};

// The face point at offset n from the axis point q.
inline FacePoint offset(const CurvePoint& q, double n) {
  const Eigen::Vector2d tangent(std::cos(q.theta), std::sin(q.theta));
  const Eigen::Vector2d normal(-tangent.y(), tangent.x());  // towards the extrados
  // d(P + n normal)/ds = tangent (1 - n kappa): d normal/ds = -kappa tangent.
  return {Eigen::Vector2d(q.x, q.y) + n * normal, (1.0 - n * q.kappa) * tangent};
}
inline FacePoint face_at(const SideView& side, double n, double s) { return offset(side.at(s), n); }

// The arc length s in [lo, hi] where the face at n reaches abscissa x, starting from `guess` (the middle
// of [lo, hi] when outside it). x grows with s on every face of a valid ring (dx/ds = cos theta
// (1 - n kappa) >= 0), so a safeguarded Newton iteration converges; to 1e-15 of the span.
double face_at_x(const SideView& side, double n, double x, double lo, double hi, double span,
                 double guess = -1.0);

// The extrados of one side (the face at t/2) as a height over the horizontal position: from the bed's
// outer end over the springing to the crown's vertical, where the extrados of a pointed crown meets the
// other side's (beyond the axis' crown). Keeps a reference to the side.
class SideExtrados {
 public:
  SideExtrados(const SideView& side, double thickness, double span);
  // The side's arc length where the extrados reaches the crown's vertical (beyond S at a pointed crown).
  double s_crown() const { return s_crown_; }
  // The extrados' abscissa over the springing (the outer end of the bed, normal to the axis): no extrados
  // lies over x below it.
  double x_begin() const { return x_begin_; }
  // The side's arc length where the extrados reaches x (x_begin <= x <= the crown's x; clamped to the
  // ends outside), searched from `guess`.
  double s_at(double x, double guess = -1.0) const;
  // The extrados' height over x (x_begin <= x <= the crown's x).
  double height(double x, double guess = -1.0) const { return face_at(side_, half_t_, s_at(x, guess)).p.y(); }
  // The abscissae, ascending, of the extrados over the side's breaks (before the crown's vertical): where
  // the height's curvature (or slope, past a kinked crown's continuation) may jump.
  const std::vector<double>& break_x() const { return break_x_; }

 private:
  const SideView& side_;
  double half_t_ = 0, span_ = 0, s_crown_ = 0, x_begin_ = 0;
  std::vector<double> break_x_;
};

}  // namespace ogive
