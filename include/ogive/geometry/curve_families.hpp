// The classic arch families of docs/model.md ("Generator curves") and the user's surveyed points, as Curves.
//
// Every factory takes the span L (m, in [kMinSpan, kMaxSpan] of curve.hpp) and the rise as a ratio
// rise_ratio = h / L, and returns the LEFT half of a symmetric arch (see curve.hpp; the whole points curve
// below is the one whole arch). Invalid parameters
// throw std::invalid_argument whose message is "<name>: <rule>, got <value>", <name> being the parameter
// as the CLI spells it without dashes (span, rise_ratio, haunch_angle, crown_angle), e.g.
//   "rise_ratio: must lie in (0, 0.5) for a segmental arch, got 0.7".
//
// Piecewise-circular families (segmental, three-centred, four-centred) are PiecewiseCircularCurves, so
// arcs() is non-empty and the closed form applies. The others (elliptical, parabolic, catenary, points)
// are smooth: their at(s) is accurate to about 1e-15 relative (position, angle, curvature), curvature is
// continuous, and breakpoints() is empty. For s slightly outside [0, S] they extrapolate the curve's
// natural continuation.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ogive/geometry/curve.hpp"

namespace ogive {

// ---------------------------------------------------------------------------------------------------
// Piecewise-circular families.

// Segmental: one circular arc through both springings and the crown, 0 < rise_ratio < 0.5.
// Radius R = (L^2/4 + h^2) / (2 h); the springing tangent makes 2 atan(2 h / L) with the horizontal.
std::shared_ptr<const Curve> make_segmental(double span, double rise_ratio);

// Three-centred (basket-handle) arch: a haunch arc of radius r1 centred on the springing line at (r1, 0)
// (vertical tangent at the springing) turns through haunch_angle; a crown arc of radius r2 > r1 centred
// on the mid-span line continues it tangentially to a horizontal crown tangent. r1 and r2 follow from
// span and rise:
//   r1 (1 - cos a) + r2 cos a = L/2,   r1 sin a + r2 (1 - sin a) = h     (a = haunch_angle).
// haunch_angle in (0, 90) degrees; the default 60 is the classic equal-angle construction (each of the
// three arcs subtends 60 degrees). Possible rises: rise_ratio in three_centred_rise_range(haunch_angle),
// i.e. ((1 - sin a) / (2 cos a), 0.5) -- (0.1340, 0.5) for 60 degrees. At the lower end r1 -> 0, at the
// upper end r1 = r2 (the semicircle).
std::shared_ptr<const Curve> make_three_centred(double span, double rise_ratio, double haunch_angle_deg = 60);

// Four-centred (Tudor) pointed arch: the three-centred construction with a pointed crown. A haunch arc of
// radius r1, centred on the springing line at (r1, 0), leaves the springing vertically and turns through
// haunch_angle; a crown arc of radius r2 > r1 (centre below the springing line, on the far side of
// mid-span) continues it tangentially and meets its mirror image at the crown with the tangent at
// crown_angle above the horizontal (a kink of 2 crown_angle). r1 and r2 follow linearly from span and rise:
//   r1 (1 - cos a) + r2 (cos a - sin c) = L/2,   r1 sin a + r2 (cos c - sin a) = h   (a, c as named).
// haunch_angle in (0, 90) degrees, crown_angle in (0, 90 - haunch_angle) degrees (crown_angle 0 is the
// three-centred arch). Possible rises: rise_ratio in four_centred_rise_range(haunch_angle, crown_angle) =
//   ((cos c - sin a) / (2 (cos a - sin c)), cos c / (2 (1 - sin c)))
// -- (0.2887, 0.6516) for the defaults 45 and 15. At the lower end r1 -> 0 (a two-centred arch with a
// corner at the springing); at the upper end r1 = r2 (the pointed arch of that crown angle).
// The defaults are close to the textbook quarter-point construction (haunch centres at the quarter points
// of the span, crown centres at the lower corners of the square standing below them: haunch_angle 45,
// r1 = L/4, r2 = (1/4 + 1/sqrt 2) L, crown_angle = asin(r1 / r2) = 15.14 degrees, rise_ratio 0.4239).
std::shared_ptr<const Curve> make_four_centred(double span, double rise_ratio, double haunch_angle_deg = 45,
                                               double crown_angle_deg = 15);

// The open interval of rise ratios each construction can make, for the given angles (degrees); throws like
// the factories for angles outside their domain.
std::pair<double, double> three_centred_rise_range(double haunch_angle_deg);
std::pair<double, double> four_centred_rise_range(double haunch_angle_deg, double crown_angle_deg);

// ---------------------------------------------------------------------------------------------------
// Smooth families: rise_ratio in [1e-6, 2] for each (limits of practice; below 1e-6 the formulas would
// also leave the range of a double).

// Half-ellipse with semi-axes L/2 (horizontal) and h: x = L/2 (1 - cos t), y = h sin t, t in [0, pi/2].
// rise_ratio 0.5 is the semicircle, computed by the same general path (not special-cased to a circular
// arc, so the closed form does not apply to it). Arc length: adaptive Gauss-Legendre, inverted by Newton.
std::shared_ptr<const Curve> make_elliptical(double span, double rise_ratio);

// Parabola y = 4 h x (L - x) / L^2. Closed-form arc length (asinh), inverted by Newton. The springing
// tangent is atan(4 h / L), not vertical.
std::shared_ptr<const Curve> make_parabolic(double span, double rise_ratio);

// Catenary y = h - a (cosh((x - L/2) / a) - 1), a from a (cosh(L / (2 a)) - 1) = h. Arc length from the
// crown is a sinh(u / a) (u = L/2 - x), so at(s) is explicit. Funicular of its own weight: H / V at the
// springing = 1 / sinh(L / (2 a)).
std::shared_ptr<const Curve> make_catenary(double span, double rise_ratio);

// The catenary's parameter a (m) for that span and rise ratio (same domain checks as make_catenary).
double catenary_parameter(double span, double rise_ratio);

// ---------------------------------------------------------------------------------------------------
// Smooth curves given by a parameter t, re-parameterised by arc length: the base of the elliptical and
// points curves. A derived class supplies the position and its first two t-derivatives on each piece
// (pieces are the intervals between the knots given to build_arc_length; the curve must be analytic
// inside each piece and have a non-vanishing speed), then calls build_arc_length from its constructor.
// The arc length is tabulated on panels (adaptive 16-point Gauss-Legendre, never crossing a knot, each
// panel's integral agreeing with its two halves' sum to 4e-15 relative); at(s) finds t by safeguarded
// Newton on s(t), which is accurate to round-off: s(t) is a Chebyshev table per panel (checked against
// the Gauss integral to 2e-15 of the panel at construction), or the Gauss integral itself where the
// table disagrees.
class ParametricCurve : public Curve {
 public:
  struct Jet {
    double x, y;    // position, m
    double dx, dy;  // d/dt
    double ddx, ddy;  // d^2/dt^2
  };
  double length() const override { return s_.back(); }
  CurvePoint at(double s) const override;
  double first_moment_x() const override { return first_moment_; }
  // The largest |kappa| at the arc-length panels' ends and Gauss nodes, found while tabulating.
  double max_curvature() const override { return max_curvature_; }
  // The parameter t at arc length s (exact table values at the panel ends, so at(0) and at(S) are the
  // curve's end points exactly).
  double parameter_at(double s) const override;
  // The knots given to build_arc_length, and the arc length, angle and speed at t without inversion.
  std::vector<double> parameter_knots() const override { return knots_; }
  ParameterPoint at_parameter(double t) const override;

 protected:
  // piece: the index of the knot interval that contains t (t may lie slightly outside it when
  // extrapolating beyond the ends).
  virtual Jet jet(double t, std::size_t piece) const = 0;
  // knots: strictly increasing, first = the springing's t, last = the crown's t; at least two.
  // initial_panels: panels per piece before adaptive refinement. Throws ArcLengthError (naming the
  // piece reached) when the panels examined exceed kPanelBudgetBase + kPanelBudgetPerPanel x the initial
  // panels: the speed nearly vanishes somewhere (a cusp), where round-off in the speed keeps a panel and
  // its halves from agreeing at any size. The work stays linear in the number of knots.
  void build_arc_length(const std::vector<double>& knots, int initial_panels = 1);
  static constexpr std::size_t kPanelBudgetBase = 4096;
  static constexpr std::size_t kPanelBudgetPerPanel = 64;
  struct ArcLengthError : std::invalid_argument {
    ArcLengthError(std::size_t piece, const std::string& what) : std::invalid_argument(what), piece(piece) {}
    std::size_t piece;  // the knot interval
  };
  // The arc length at a parameter value that is a knot given to build_arc_length (exact table entry).
  double arc_length_at_knot(double t) const;

 private:
  std::pair<double, std::size_t> locate(double s) const;  // t and its piece
  double speed(double t, std::size_t piece) const;
  double integral_of_speed(double t0, double t1, std::size_t piece) const;
  std::vector<double> knots_;       // as given to build_arc_length
  std::vector<double> t_;           // panel ends, size P + 1
  std::vector<double> s_;           // arc length at the panel ends
  std::vector<std::size_t> piece_;  // the knot interval of each panel, size P
  // Per panel, the Chebyshev coefficients (degree kArcTableDegree, in t mapped to [-1, 1]) of
  // s(t) - s(panel start), so that at(s) inverts a polynomial (one jet per Newton step) instead of a
  // 16-point Gauss integral per step; not ok for a panel where the table disagrees with the Gauss
  // integral by more than kArcTableTolerance (that panel keeps the Gauss inversion).
  static constexpr int kArcTableDegree = 16;
  static constexpr double kArcTableTolerance = 2e-15;  // relative to the panel's length
  std::vector<double> arc_table_;
  std::vector<bool> arc_table_ok_;
  void build_arc_table();
  double first_moment_ = 0;
  double max_curvature_ = 0;
};

// ---------------------------------------------------------------------------------------------------
// Points: a user's list of axis points, fitted by a C2 curve and re-parameterised by arc length. Two
// kinds of file, one syntax (read by one reader): a HALF file (family "points", extent half) runs from
// the springing to the crown of a symmetric arch; a WHOLE file (family "whole-points", extent whole)
// from the left springing to the right one, the springings at any heights. The file format, every rule
// the points must keep and the fit are specified in docs/file-formats.md; the functions below keep it.
//
// What a returned curve guarantees, beyond curve.hpp's invariants: it passes through every point (in
// file coordinates shifted so that the first point is (0, 0); a half file's springing y is set to
// exactly 0); arcs() is empty (the closed form does not apply) and the curvature is continuous, while
// its derivative jumps at the points, so breakpoints() returns the interior points' arc lengths (an
// integrator of high order must restart there); at(s) is accurate to round-off. A half curve's crown
// tangent is horizontal (the fit is that of the points and their mirror image); a whole curve's crown()
// is the arc length of the fit's highest point, and right_springing_height() is the last point's y
// minus the first's. Symmetric whole points give whole_arch() of their left half's curve to round-off.

// A problem with a points file, located: what() is one line "FILE:LINE: rule broken", or "FILE: rule
// broken" when the problem is the file as a whole (cannot be opened or read; line() is then 0).
class CurveFileError : public std::invalid_argument {
 public:
  CurveFileError(const std::string& file, std::size_t line, const std::string& rule);
  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string file_;
  std::size_t line_;
  std::string rule_;
};

inline constexpr std::size_t kPointsMinCount = 4;
inline constexpr std::size_t kPointsMaxCount = 100000;
inline constexpr std::size_t kPointsMaxLineLength = 4096;

// Reads and fits a points file; throws CurveFileError.
std::shared_ptr<const Curve> read_points_curve(const std::string& path);
// The same from a stream; name_for_messages stands for FILE in the errors.
std::shared_ptr<const Curve> parse_points_curve(std::istream& in, const std::string& name_for_messages);
// The same rules for points given directly (file coordinates); throws std::invalid_argument
// "points: point K (of N): rule broken", K counted from 1.
std::shared_ptr<const Curve> make_points_curve(std::vector<std::pair<double, double>> xy);

// The whole-arch counterparts (family "whole-points", extent whole), with the same error conventions:
// CurveFileError "FILE:LINE: rule" from the file forms, std::invalid_argument "points: point K (of N):
// rule broken" from make_whole_points_curve. At least kPointsMinCount points (4: not-a-knot at both ends
// needs one cubic's worth), at most kPointsMaxCount.
std::shared_ptr<const Curve> read_whole_points_curve(const std::string& path);
std::shared_ptr<const Curve> parse_whole_points_curve(std::istream& in, const std::string& name_for_messages);
std::shared_ptr<const Curve> make_whole_points_curve(std::vector<std::pair<double, double>> xy);

}  // namespace ogive
