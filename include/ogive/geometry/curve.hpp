// Generator curves, described by arc length.
//
// A Curve is the axis of an arch from its left springing (s = 0, at x = 0, y = 0), and its extent() says
// how much of the arch it describes:
//   half:  the LEFT HALF of a symmetric arch, to the crown at s = S = length(), x = span/2; the right
//          half is its mirror image about x = span/2 (every classic family, and half-arch surveys);
//   whole: the whole arch, springing to springing: s = length() is the right springing, at x = span(),
//          y = right_springing_height() (either sign: a rampant arch). The span L is the horizontal
//          distance between the springings, and heights are measured up from the left springing.
// whole_arch(curve) turns a half into the whole arch it stands for (mirrored); the model solves a
// symmetric scene over the half and every other scene over the whole.
// Units: metres and radians.
//   theta(s): angle of the tangent (direction of increasing s) to the horizontal; pi/2 at a vertical
//             left springing, 0 at a smooth crown, > 0 at a pointed crown's kink on the left half (and
//             < 0 beyond the crown of a whole arch).
//   kappa(s): d theta / ds (1/m); negative for an arch that curves downwards (kappa = -1/R on a circle).
// Invariants every Curve keeps: span() > 0; length() > 0; at(0) is (0, 0); a half's at(S).x == span()/2,
// a whole's at(length()).x == span(); x(s) never decreases; breakpoints() are strictly increasing and
// strictly inside (0, length()). At a breakpoint where the tangent jumps (a pointed crown of a whole
// arch), angle() and at() give the value before it (from the left).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

namespace ogive {

// The spans every generator curve accepts, m (from a model's millimetre to a kilometre-scale arch).
// Bounded so that lengths, curvatures and the first moment (~ span^2) of any curve stay far inside the
// range of a double: fuzzing found spans near 1e308 or 1e-320 giving nan and inf geometry.
inline constexpr double kMinSpan = 1e-3;
inline constexpr double kMaxSpan = 1e6;

// One point of the axis with its tangent angle and curvature.
struct CurvePoint {
  double x = 0;      // m, horizontal, from the left springing towards the crown
  double y = 0;      // m, vertical, up from the springing line
  double theta = 0;  // rad
  double kappa = 0;  // 1/m
};

// A point of the half arch given by a curve's own parameter t (see Curve::parameter_knots).
struct ParameterPoint {
  double s = 0;                  // m, arc length at t
  double speed = 0;              // ds/dt (> 0)
  double cos = 1, sin = 0;       // the unit tangent: cos theta, sin theta (no trigonometric call needed)
};

// A circular arc (or a straight piece when kappa == 0) of a piecewise-circular curve.
struct CircularArc {
  double s_start = 0;  // m, arc length at the arc's start
  double length = 0;   // m
  double x_start = 0, y_start = 0, theta_start = 0;
  double kappa = 0;  // 1/m, constant on the arc
};

// The arc of `arcs` (ascending, not empty) that holds arc length s (m): the last one whose start is <= s,
// the first for s before it (s outside the curve extrapolates its end arcs).
const CircularArc& arc_at(std::span<const CircularArc> arcs, double s);

enum class CurveExtent { half, whole };

class Curve {
 public:
  virtual ~Curve() = default;
  virtual CurveExtent extent() const { return CurveExtent::half; }
  virtual std::string family() const = 0;
  virtual double span() const = 0;         // L, m
  virtual double length() const = 0;  // m: S for a half, the whole arch's length for a whole
  virtual CurvePoint at(double s) const = 0;
  // at(s).theta alone: what the integrators and the quadrature ask for at every node or right-hand
  // side. Families override it where the angle is cheaper than the point (same value to round-off).
  virtual double angle(double s) const { return at(s).theta; }
  // Interior arc lengths where the curvature or its derivative jumps: integrators restart there.
  virtual std::vector<double> breakpoints() const { return {}; }
  // Non-empty exactly when the curve is piecewise circular; then the closed form applies arc by arc.
  virtual std::span<const CircularArc> arcs() const { return {}; }
  // The crown's arc length (m): S for a half and a mirrored half; a whole curve's highest point.
  virtual double crown() const { return length(); }
  // The highest point's height above the left springing (m): the crown's y.
  double rise() const { return at(crown()).y; }
  // The right springing's height above the left one (m): 0 for a half (its mirror) and a symmetric arch.
  virtual double right_springing_height() const { return 0.0; }
  // The length of the whole arch (m): 2 S for a half, length() for a whole.
  double whole_length() const { return extent() == CurveExtent::half ? 2.0 * length() : length(); }
  // The point at arc length s of the whole arch, 0 <= s <= whole_length(): for a half, on the right half
  // the mirror image of the left half's point at 2S - s; for a whole, at(s).
  CurvePoint at_whole_arch(double s) const;
  // Integral of x(s) ds over the curve's extent (m^2): the weight's moment about the springing per unit w.
  virtual double first_moment_x() const;
  // A parameter of the curve's own, t, increasing from the springing to the crown, in which arc length and
  // tangent are explicit (no inversion of s(t)): the quadrature method places its nodes in t then. The
  // knots are t at the springing, at every breakpoint (in order) and at the crown; empty (the default)
  // when the curve has no such parameter. at_parameter(t) for t within the knots; parameter_at(s) is its
  // inverse. Both throw std::logic_error on a curve without a parameter.
  virtual std::vector<double> parameter_knots() const { return {}; }
  virtual ParameterPoint at_parameter(double t) const;
  virtual double parameter_at(double s) const;
  // The largest |kappa| over the half arch (1/m). The families know it exactly or cached it at
  // construction; this default samples 513 points of at(s) on every call.
  virtual double max_curvature() const;
};

// A half arch made of circular arcs that join with a continuous position (tangent jumps are allowed only
// at the crown). Positions, angles and the first moment are exact.
class PiecewiseCircularCurve final : public Curve {
 public:
  PiecewiseCircularCurve(std::string family, double span, std::vector<CircularArc> arcs);
  std::string family() const override { return family_; }
  double span() const override { return span_; }
  double length() const override { return length_; }
  CurvePoint at(double s) const override;
  double angle(double s) const override;
  std::vector<double> breakpoints() const override;
  std::span<const CircularArc> arcs() const override { return arcs_; }
  double first_moment_x() const override;
  double max_curvature() const override;

 private:
  std::string family_;
  double span_;
  double length_;
  std::vector<CircularArc> arcs_;
};

// The whole arch a curve stands for: a whole curve itself, a half joined to its mirror image (extent
// whole, the crown at s = S a breakpoint; piecewise circular when the half is). Throws
// std::invalid_argument for a null curve.
std::shared_ptr<const Curve> whole_arch(std::shared_ptr<const Curve> curve);

// The arc length (m) at which the axis reaches the horizontal position x (m, clamped to [0, span]) on the
// whole arch of the curve (x(s) never decreases): the first such s, to round-off of the span.
double arc_length_at_x(const Curve& whole, double x);

// The mirror image about x = span/2 of a left-half point, its tangent pointing on towards the right
// springing (theta < 0); the curvature keeps its sign: the mirrored arch still turns downwards.
CurvePoint mirror(const CurvePoint& p, double span);

// A point of the plane of the arch, m.
struct PlanePoint {
  double x = 0, y = 0;
};

// The point at signed distance `offset` (m) from the axis point p along the section's normal
// n = (-sin theta, cos theta), which points to the extrados on both halves of the arch (theta < 0 on
// the right half). The thrust line's point (offset -M/N) and the section's faces (offset +-t/2) are
// both this one formula.
PlanePoint along_normal(const CurvePoint& p, double offset);

// The two ends of the cross-section at axis point p of an arch of thickness t (m): the intrados at
// offset -t/2 and the extrados at +t/2 along the normal (along_normal).
struct SectionFaces {
  PlanePoint intrados, extrados;
};
SectionFaces section_faces(const CurvePoint& p, double thickness);

// The height (m) above the springing line of the extrados (the axis offset by t/2 along the normal) of
// a ring of thickness t over the crown's vertical: above a pointed crown, where the two sides' extrados
// meet (higher than the crown + t/2). The level of a fill "to the crown's extrados". A whole curve:
// the higher of its two sides' there.
double extrados_crown_height(const Curve& curve, double thickness);

// The intrados (the axis offset by t/2 along the normal, inwards) of a ring of thickness t on a half
// curve, as engineers measure it: the clear span between its two springing points, and its rise from
// them to where it crosses the crown's vertical (below a pointed crown, where the two sides' intrados
// meet, lower than the crown - t/2). Throws std::invalid_argument for a whole curve (its two springings
// need not be level) or a thickness whose intrados does not reach the crown's vertical.
struct IntradosDimensions {
  double clear_span = 0;  // m
  double rise = 0;        // m
};
IntradosDimensions intrados_dimensions(const Curve& curve, double thickness);

// Position, angle and curvature on one arc, at distance ds (0 <= ds <= arc.length) from its start.
CurvePoint point_on_arc(const CircularArc& arc, double ds);

// The pointed (two-centred) arch of docs/model.md: radius R = (0.5 + eccentricity) * span, centre on the
// springing line at eccentricity * span beyond mid-span; eccentricity 0 is the semicircle.
// Throws std::invalid_argument naming `span` (in [kMinSpan, kMaxSpan]) or `eccentricity` for a value outside
// its domain.
std::shared_ptr<const Curve> make_pointed(double span, double eccentricity);

// The pointed arch's radius, R = (0.5 + eccentricity) span (m), and the eccentricity that gives a rise
// ratio h / span (the crown over the centre at eccentricity * span beyond mid-span: h^2 = R^2 -
// (eccentricity span)^2, so eccentricity = (h / span)^2 - 1/4) or a radius ratio R / span (R / span -
// 1/2). Below the semicircle's (h / span or R / span under 1/2) the eccentricity is negative: no pointed
// arch (make_pointed refuses it).
double pointed_radius(double span, double eccentricity);
double pointed_eccentricity_for_rise(double rise_ratio);
double pointed_eccentricity_for_radius(double radius_ratio);

}  // namespace ogive
