// The ring of voussoirs: joints, and the weight of each voussoir with where it acts.
#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include <fmt/format.h>

#include "geometry/side_view.hpp"
#include "numerics/gauss_legendre.hpp"
#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive {
namespace {

// The integral of f from a to b (either order) by the 8-point rule, piece by piece between the knots
// (ascending) that lie strictly between a and b, where f is smooth.
template <class Result, class F>
Result integral_between_knots(const std::vector<double>& knots, double a, double b, F&& f) {
  Result sum = Result::Zero();
  double from = a;
  auto piece = [&](double to) {
    sum += gauss_legendre_integral<8>(f, from, to);
    from = to;
  };
  if (a < b) {
    for (double k : knots)
      if (k > a && k < b) piece(k);
  } else {
    for (auto k = knots.rbegin(); k != knots.rend(); ++k)
      if (*k < a && *k > b) piece(*k);
  }
  piece(b);
  return sum;
}

// Area, and its first moments (integral of x dA and of y dA), of a region, from its boundary run
// counter-clockwise: Green's theorem with A = int x dy, Sx = int x^2/2 dy, Sy = -int y^2/2 dx.
struct RegionMoments {
  double area = 0, sx = 0, sy = 0;

  void add_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    const double dx = q.x() - p.x(), dy = q.y() - p.y();
    area += 0.5 * (p.x() + q.x()) * dy;
    sx += dy * (p.x() * p.x() + p.x() * q.x() + q.x() * q.x()) / 6.0;
    sy -= dx * (p.y() * p.y() + p.y() * q.y() + q.y() * q.y()) / 6.0;
  }

  // Green's integrands along a face point f.
  static Eigen::Vector3d integrand(const FacePoint& f) {
    const double x = f.p.x(), y = f.p.y();
    return {x * f.dp.y(), 0.5 * x * x * f.dp.y(), -0.5 * y * y * f.dp.x()};
  }

  void add(const Eigen::Vector3d& piece) {
    area += piece[0];
    sx += piece[1];
    sy += piece[2];
  }

  // The faces at each n of `faces`, all from arc length a to b (either order) and each counted with its
  // sign (+1 along a -> b, -1 back); one evaluation of the axis per node serves every face.
  template <std::size_t N>
  void add_faces(const SideView& side, const std::array<std::pair<double, double>, N>& faces, double a, double b) {
    add(integral_between_knots<Eigen::Vector3d>(side.breaks(), a, b, [&](double s) {
      const CurvePoint q = side.at(s);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (const auto& [n, sign] : faces) sum += sign * integrand(offset(q, n));
      return sum;
    }));
  }
};

// One joint of a side with the arc lengths (of the side) at which it meets the intrados, the extrados
// and the axis.
struct SideJoint {
  Joint joint;
  double s_intrados = 0, s_extrados = 0, s_axis = 0;
};

// The integrals over the piece [a, b] of a side's axis that give the weight and centroid of the voussoir
// between the radial joints at a and b, whatever the thickness t: the region P(s) + n N(s), |n| <= t/2
// (N the normal towards the extrados), has the Jacobian 1 - n kappa, so its area is t (b - a) and its
// first moment t int P ds - t^3 / 12 int kappa N ds (the terms odd in n vanish).
struct Band {
  double a = 0, b = 0;
  Eigen::Vector2d P, kN;  // int P ds, int kappa N ds
};

// One side's joints (springing to crown, crown included) and voussoirs in the side's coordinates, and
// its bands: those of the last ring built, which the next one (another thickness, the same joints on a
// smooth crown) reuses.
struct SideRing {
  std::vector<SideJoint> joints;
  std::vector<Voussoir> voussoirs;
  std::vector<Band> bands, previous_bands;
  // The axis point and normal of each radial joint, kept in the same way.
  struct AxisSample {
    double s = 0;
    Eigen::Vector2d point, normal;
  };
  std::vector<AxisSample> samples, previous_samples;
  // The axis' points the fills' integrals asked for, by arc length, when the curve's at() is costly (not
  // piecewise circular: a parabola inverts its arc length by Newton's method): the next ring meets
  // the same nodes wherever its joints are the same.
  bool memoize = false;
  std::unordered_map<double, CurvePoint> memo;
};

// The side's axis at s, through the memo when the side keeps one.
CurvePoint axis_at(const SideView& side, SideRing& cache, double s) {
  if (!cache.memoize) return side.at(s);
  if (cache.memo.size() > 100000) cache.memo.clear();  // bounded: the nodes of thicknesses long past
  const auto [it, inserted] = cache.memo.try_emplace(s);
  if (inserted) it->second = side.at(s);
  return it->second;
}

// The band [a, b] of the side: the previous ring's when it had one (`cursor` walks through them in
// order), else integrated anew; appended to out.bands.
const Band& band_of(const SideView& side, SideRing& out, std::size_t& cursor, double a, double b) {
  const std::vector<Band>& previous = out.previous_bands;
  while (cursor < previous.size() && previous[cursor].a < a) ++cursor;
  if (cursor < previous.size() && previous[cursor].a == a && previous[cursor].b == b) {
    out.bands.push_back(previous[cursor]);
  } else {
    const Eigen::Vector4d g = integral_between_knots<Eigen::Vector4d>(side.breaks(), a, b, [&](double s) {
      const CurvePoint q = side.at(s);
      const double c = std::cos(q.theta), sn = std::sin(q.theta);
      return Eigen::Vector4d(q.x, q.y, -q.kappa * sn, q.kappa * c);
    });
    out.bands.push_back({a, b, g.head<2>(), g.tail<2>()});
  }
  return out.bands.back();
}

// The fill's load on the stretch of a side between arc lengths a < b of the line at offset n (the
// extrados, n = t/2, or the axis, n = 0) that lies over the span (x >= x_min, the side's springing), as
// a force and its moment about the side's origin: int rho_f g max(0, h_f - y_e(x)) dx, y_e(x) the height
// of the true extrados over x. Along the extrados that is its own y; along the axis, the extrados' height
// over the axis point's x, integrated as max(0, h_f - y_e(x)) cos theta per axis length (finite at a
// vertical springing), and only where the extrados lies over the axis point (none over the bed's outer
// end's x at an overhanging springing). The integrand's kink where the fill's level meets y_e is a knot.
VerticalLoad fill_load(const SideView& side, const SideExtrados& extrados, const FillLoad& fill, double gravity,
                       double n, double x_min, double a, double b, double span, SideRing& cache) {
  const double level = fill.height_ratio * span, unit_weight = fill.density * gravity;
  if (!(unit_weight > 0) || !(b > a)) return {};
  if (n == 0.0) x_min = std::max(x_min, extrados.x_begin());
  auto face = [&](double s) { return offset(axis_at(side, cache, s), n); };
  if (face(b).p.x() <= x_min) return {};
  if (face(a).p.x() < x_min) a = face_at_x(side, n, x_min, a, b, span);
  // (h_f - y_e) dx/ds: its sign is that of the fill's depth (dx/ds >= 0), its positive part the load.
  auto excess = [&](double s, Eigen::Vector2d* point) {
    if (n == 0.0) {
      const CurvePoint q = axis_at(side, cache, s);
      if (point) *point = {q.x, q.y};
      return (level - extrados.height(q.x, s)) * std::cos(q.theta);
    }
    const FacePoint f = face(s);
    if (point) *point = f.p;
    return (level - f.p.y()) * f.dp.x();
  };
  std::vector<double> knots;
  double from = a;
  bool submerged = false;  // the excess is positive at the end of some piece
  auto add_root = [&](double to) {
    double lo = from, hi = to, f_lo = excess(lo, nullptr);
    const double f_hi = excess(hi, nullptr);
    submerged = submerged || f_lo > 0 || f_hi > 0;
    if (f_lo * f_hi < 0) {
      for (int it = 0; it < 200 && hi - lo > 1e-15 * span; ++it) {
        const double mid = 0.5 * (lo + hi), f_mid = excess(mid, nullptr);
        if ((f_mid < 0) == (f_lo < 0)) lo = mid, f_lo = f_mid; else hi = mid;
      }
      knots.push_back(0.5 * (lo + hi));
    }
    if (to < b) knots.push_back(to);
    from = to;
  };
  // Where the integrand is not smooth: the side's breaks and, along the axis, the axis points under the
  // extrados' breaks.
  std::vector<double> breaks = side.breaks();
  if (n == 0.0)
    for (double x : extrados.break_x())
      if (x > face_at(side, 0.0, a).p.x() && x < face_at(side, 0.0, b).p.x())
        breaks.push_back(face_at_x(side, 0.0, x, a, b, span));
  std::sort(breaks.begin(), breaks.end());
  for (double k : breaks)
    if (k > a && k < b) add_root(k);
  add_root(b);
  // Each piece between the knots has the sign of its ends (a root inside one is found from them): none
  // positive, the stretch lies above the fill's level and carries nothing.
  if (!submerged) return {};
  const Eigen::Vector3d load = integral_between_knots<Eigen::Vector3d>(knots, a, b, [&](double s) {
    Eigen::Vector2d p;
    const double q = unit_weight * std::max(0.0, excess(s, &p));
    return Eigen::Vector3d(q, q * p.x(), q * p.y());
  });
  return {load.x(), load.y(), load.z()};
}

// Whether fill_load along the extrados between joints a and b is zero for a fill up to `level`, known
// from the joints' extrados points alone: both at or above the level, no break of the side between them
// and a not before the span's start (then fill_load evaluates its excess at these two points only, and
// neither is positive).
bool above_fill(const SideView& side, const SideJoint& a, const SideJoint& b, double level, double x_min) {
  if (!(a.joint.extrados.y() >= level && b.joint.extrados.y() >= level && a.joint.extrados.x() >= x_min)) return false;
  for (double k : side.breaks())
    if (k > a.s_extrados && k < b.s_extrados) return false;
  return true;
}

// Where the joints of a side end at the crown: the crown joint is vertical through the crown. At a
// pointed crown the intrados reaches the crown's vertical before the axis does and the extrados after
// it. Joints are placed by their intrados' arc length in [0, intrados].
struct CrownEnds {
  double intrados = 0, extrados = 0;
};

// Whether the side ends at a pointed crown (a kink of the axis): its tangent there is not horizontal.
bool pointed_crown(const SideView& side) { return side.at(side.length()).theta > 1e-12; }

CrownEnds crown_ends(const SideView& side, double thickness, double span) {
  const double S = side.length(), half_t = 0.5 * thickness, xc = side.crown_x();
  return {pointed_crown(side) ? face_at_x(side, -half_t, xc, 0.0, S, span) : S,
          SideExtrados(side, thickness, span).s_crown()};
}

// The joints and voussoirs of one side, with their self-weight and fill: the springing bed, a joint at
// each of `fractions` (ascending in (0, 1): its intrados at that fraction of the intrados' arc length to
// the crown's vertical) and the crown joint.
void make_side(const SideView& side, double thickness, double unit_weight, const std::vector<FillLoad>& fills,
               double gravity, const LimitOptions& options, const std::vector<double>& fractions, double span,
               SideRing& out) {
  const double S = side.length(), half_t = 0.5 * thickness, xc = side.crown_x();
  const int m = static_cast<int>(fractions.size()) + 1;  // voussoirs per side
  const SideExtrados extrados(side, thickness, span);
  const double s_extrados_crown = extrados.s_crown();
  const double s_intrados_crown = pointed_crown(side) ? face_at_x(side, -half_t, xc, 0.0, S, span) : S;

  std::swap(out.samples, out.previous_samples);
  out.samples.clear();
  std::size_t sample_cursor = 0;
  auto make_joint = [&](double s_in, double s_ex, double s_axis) {
    SideJoint h;
    if (s_in == s_ex && s_ex == s_axis) {  // a radial joint: one point of the axis serves its three
      const std::vector<SideRing::AxisSample>& previous = out.previous_samples;
      while (sample_cursor < previous.size() && previous[sample_cursor].s < s_axis) ++sample_cursor;
      if (sample_cursor < previous.size() && previous[sample_cursor].s == s_axis) {
        out.samples.push_back(previous[sample_cursor]);
      } else {
        const CurvePoint q = side.at(s_axis);
        const Eigen::Vector2d normal(-std::sin(q.theta), std::cos(q.theta));
        out.samples.push_back({s_axis, Eigen::Vector2d(q.x, q.y), normal});
      }
      // As offset() computes the face points, from the same numbers.
      const SideRing::AxisSample& q = out.samples.back();
      h.joint.intrados = q.point + -half_t * q.normal;
      h.joint.extrados = q.point + half_t * q.normal;
      h.joint.axis = q.point + 0.0 * q.normal;
    } else {
      h.joint.intrados = face_at(side, -half_t, s_in).p;
      h.joint.extrados = face_at(side, half_t, s_ex).p;
      h.joint.axis = face_at(side, 0.0, s_axis).p;
    }
    h.joint.s = side.whole_s(s_axis);
    h.s_intrados = s_in;
    h.s_extrados = s_ex;
    h.s_axis = s_axis;
    return h;
  };
  std::vector<SideJoint>& joints = out.joints;
  joints.clear();
  joints.push_back(make_joint(0.0, 0.0, 0.0));  // the springing bed, normal to the axis
  for (int j = 1; j < m; ++j) {
    // Both orientations space the joints over the part of the arch whose joints cut it in two: radial
    // joints over the axis up to where the intrados reaches the crown's vertical, vertical ones over
    // the intrados.
    const double s = s_intrados_crown * fractions[j - 1];
    if (options.joints == JointOrientation::radial) {
      joints.push_back(make_joint(s, s, s));
    } else {
      const double x = face_at(side, -half_t, s).p.x();
      joints.push_back(make_joint(s, face_at_x(side, half_t, x, 0.0, s_extrados_crown, span),
                                  face_at_x(side, 0.0, x, 0.0, S, span)));
    }
  }
  SideJoint crown = make_joint(s_intrados_crown, s_extrados_crown, S);
  crown.joint.intrados.x() = crown.joint.extrados.x() = crown.joint.axis.x() = xc;  // exactly vertical
  joints.push_back(crown);

  const double x_min = side.at(0.0).x;  // the springing's axis point: the span starts there
  out.voussoirs.assign(m, Voussoir{});
  std::swap(out.bands, out.previous_bands);
  out.bands.clear();
  std::size_t cursor = 0;
  for (int k = 0; k < m; ++k) {
    const SideJoint &a = joints[k], &b = joints[k + 1];
    Voussoir& v = out.voussoirs[k];
    const bool radial = a.s_intrados == a.s_extrados && a.s_intrados == a.s_axis && b.s_intrados == b.s_extrados &&
                        b.s_intrados == b.s_axis;
    if (options.weight == WeightModel::voussoir && radial) {  // one band between radial joints
      const Band& band = band_of(side, out, cursor, a.s_axis, b.s_axis);
      const double length = b.s_axis - a.s_axis;
      v.weight = unit_weight * thickness * length;
      v.centroid = (band.P - (thickness * thickness / 12.0) * band.kN) / length;
    } else if (options.weight == WeightModel::voussoir) {
      RegionMoments r;  // Green's theorem along its faces and joints
      r.add_faces<1>(side, {{{-half_t, 1.0}}}, a.s_intrados, b.s_intrados);
      r.add_faces<1>(side, {{{half_t, 1.0}}}, b.s_extrados, a.s_extrados);
      r.add_segment(b.joint.intrados, b.joint.extrados);
      r.add_segment(a.joint.extrados, a.joint.intrados);
      v.weight = unit_weight * r.area;
      v.centroid = Eigen::Vector2d(r.sx / r.area, r.sy / r.area);
    } else {
      // rho g t per length of axis, at the centroid of the voussoir's piece of axis.
      const Eigen::Vector2d first = gauss_legendre_integral<8>(
          [&](double s) -> Eigen::Vector2d { return face_at(side, 0.0, s).p; }, a.s_axis, b.s_axis);
      const double length = b.s_axis - a.s_axis;
      v.weight = unit_weight * thickness * length;
      v.centroid = first / length;
    }
    // The fills over the voussoir's stretch: of the extrados with the true ring, of the axis with the
    // axis model (the elastic model's convention).
    for (const FillLoad& f : fills) {
      if (options.weight == WeightModel::voussoir && above_fill(side, a, b, f.height_ratio * span, x_min)) continue;
      if (options.weight == WeightModel::voussoir)
        v.fill += fill_load(side, extrados, f, gravity, half_t, x_min, a.s_extrados, b.s_extrados, span, out);
      else
        v.fill += fill_load(side, extrados, f, gravity, 0.0, x_min, a.s_axis, b.s_axis, span, out);
    }
  }
}

// Where a side's joints must lie for a hinge to form where a load's line of action meets the faces
// (x_view in the side's coordinates): the joint whose intrados is at x_view and, for radial joints,
// those whose extrados and axis points are at x_view (a vertical joint there is all three). A hinge
// under a point load, or at a live load's or a fill's end, then forms where it would in the continuum.
void add_fractions_at_x(const SideView& side, double thickness, double x_view, const LimitOptions& options,
                        double span, std::vector<double>& out) {
  const double half_t = 0.5 * thickness;
  const CrownEnds ends = crown_ends(side, thickness, span);
  const double S_in = ends.intrados;
  auto add_face = [&](double n) {
    // Radial joints are placed by the arc length they share with every face; only up to S_in.
    if (!(face_at(side, n, 0.0).p.x() < x_view && face_at(side, n, S_in).p.x() > x_view)) return;
    out.push_back(face_at_x(side, n, x_view, 0.0, S_in, span) / S_in);
  };
  add_face(-half_t);
  if (options.joints == JointOrientation::radial) {
    add_face(half_t);
    add_face(0.0);
  }
}

// The arc length of a side in [0, hi] where its extrados' height reaches `level` (NaN if it does not).
double extrados_at_height(const SideView& side, double thickness, double level, double hi, double span) {
  const double half_t = 0.5 * thickness;
  auto f = [&](double s) { return face_at(side, half_t, s).p.y() - level; };
  double lo = 0.0, f_lo = f(lo);
  if (!((f_lo < 0) != (f(hi) < 0))) return std::numeric_limits<double>::quiet_NaN();
  for (int it = 0; it < 200 && hi - lo > 1e-15 * span; ++it) {
    const double mid = 0.5 * (lo + hi), f_mid = f(mid);
    if ((f_mid < 0) == (f_lo < 0)) lo = mid, f_lo = f_mid; else hi = mid;
  }
  return 0.5 * (lo + hi);
}

// The fractions (as make_side takes them) of the joints at every load's edges on one side: point loads,
// the ends of live loads, and where each fill's level meets the extrados.
void add_load_fractions(const SideView& side, double thickness, const Loads& loads, const LimitOptions& options,
                        double span, std::vector<double>& out) {
  auto at_curve_x = [&](double x) { add_fractions_at_x(side, thickness, side.curve_x(x), options, span, out); };
  for (const PointLoad& p : loads.points) at_curve_x(p.at * span);
  for (const LiveLoad& q : loads.live) {
    at_curve_x(q.from * span);
    at_curve_x(q.to * span);
  }
  const CrownEnds ends = crown_ends(side, thickness, span);
  for (const FillLoad& f : loads.fills) {
    const double s = extrados_at_height(side, thickness, f.height_ratio * span, ends.extrados, span);
    if (!std::isnan(s)) at_curve_x(side.curve_x(face_at(side, 0.5 * thickness, s).p.x()));
  }
}

// A joint or a voussoir of one side in the curve's coordinates.
Joint to_curve(const SideView& side, const Joint& j) {
  auto flip = [&](const Eigen::Vector2d& p) { return Eigen::Vector2d(side.curve_x(p.x()), p.y()); };
  return {flip(j.intrados), flip(j.extrados), flip(j.axis), j.s};
}

Voussoir to_curve(const SideView& side, const Voussoir& v) {
  Voussoir out = v;
  out.centroid.x() = side.curve_x(v.centroid.x());
  out.fill.moment = side.curve_moment(v.fill.force, v.fill.moment);
  return out;
}

// The boundaries over the span of each voussoir's stretch (see limit.hpp): its joints' extrados or
// axis abscissae.
double stretch_end(const Joint& j, WeightModel w) { return w == WeightModel::voussoir ? j.extrados.x() : j.axis.x(); }

// Adds the point and live loads of `loads` to the ring's voussoirs (at load factor 1).
void add_live_loads(Ring& ring, const Loads& loads, WeightModel w) {
  const double L = ring.span;
  const std::size_t n = ring.voussoirs.size();
  const double tie = 1e-12 * L;
  for (const PointLoad& p : loads.points) {
    const double x = p.at * L;
    std::size_t k = 0;
    while (k + 1 < n && x > stretch_end(ring.joints[k + 1], w) + tie) ++k;
    // A joint through the load's point (make_ring places one there): the load belongs to the part that
    // holds the vertical just below that point, where the thrust line bends. The joint leans one way or
    // the other, and the part on the other side touches the load only at the joint's end.
    if (k + 1 < n && std::abs(x - stretch_end(ring.joints[k + 1], w)) <= tie && ring.joints[k + 1].intrados.x() < x)
      ++k;
    ring.voussoirs[k].live += {p.force, p.force * x};
  }
  for (const LiveLoad& q : loads.live)
    for (std::size_t k = 0; k < n; ++k) {
      const double lo = std::max({stretch_end(ring.joints[k], w), q.from * L, 0.0});
      const double hi = std::min({stretch_end(ring.joints[k + 1], w), q.to * L, L});
      if (hi > lo) ring.voussoirs[k].live += {q.intensity * (hi - lo), q.intensity * (hi - lo) * 0.5 * (lo + hi)};
    }
}

// The ring of any curve with the self-weight and fills (make_ring's two forms), written over `ring`
// (its vectors' storage reused) with the sides built in `scratch`.
void build_ring(const Curve& curve, double thickness, double unit_weight, const std::vector<FillLoad>& fills,
                double gravity, const LimitOptions& options, const std::vector<double>& fractions, Ring& ring,
                std::array<SideRing, 2>& scratch) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  if (!std::isfinite(unit_weight) || !(unit_weight >= 0))
    throw std::invalid_argument(fmt::format("unit_weight: must be finite and >= 0 (N/m^3), got {}", unit_weight));
  if (!std::isfinite(thickness) || !(thickness > 0) || thickness >= max_thickness(curve))
    throw std::invalid_argument(fmt::format(
        "thickness: must be > 0 and less than twice the smallest radius of curvature ({} m), got {} m",
        max_thickness(curve), thickness));
  const double L = curve.span();
  const SideView left_view(curve, false);
  for (SideRing& side : scratch) side.memoize = curve.arcs().empty();
  SideRing& left = scratch[0];
  ring.joint_fractions = fractions;
  // At a pointed crown the radial joint through the intrados' crown point (fraction 1) is a joint of
  // the continuum: a hinge at that point may open there rather than on the vertical crown joint, the
  // wedge between the two joints then turning with the other half (the collapse acceleration of a
  // pointed arch, whose hinge sits at the crown, is 2-5e-3 lower than on the vertical joint alone). Equally
  // spaced or halved fractions only approach it; it is always a joint. (Elsewhere fraction 1 is the
  // crown joint itself.)
  // (A ring's own fractions, given again, have it already.)
  if (options.joints == JointOrientation::radial && pointed_crown(left_view) &&
      (ring.joint_fractions.empty() || ring.joint_fractions.back() < 1.0))
    ring.joint_fractions.push_back(1.0);
  make_side(left_view, thickness, unit_weight, fills, gravity, options, ring.joint_fractions, L, left);
  ring.span = L;
  ring.pins.clear();
  const int m = static_cast<int>(left.voussoirs.size());
  ring.joints.clear();
  for (const SideJoint& h : left.joints) ring.joints.push_back(h.joint);
  ring.voussoirs = left.voussoirs;
  if (curve.extent() == CurveExtent::half) {
    // The right half: the mirror image of the left one about mid-span.
    const double S = curve.length();
    for (int j = m - 1; j >= 0; --j) {
      const Joint& h = left.joints[j].joint;
      auto flip = [&](const Eigen::Vector2d& p) { return Eigen::Vector2d(L - p.x(), p.y()); };
      ring.joints.push_back({flip(h.intrados), flip(h.extrados), flip(h.axis), 2.0 * S - h.s});
    }
    for (int k = m - 1; k >= 0; --k) {
      Voussoir v = left.voussoirs[k];
      v.centroid.x() = L - v.centroid.x();
      v.fill.moment = v.fill.force * L - v.fill.moment;
      ring.voussoirs.push_back(v);
    }
    return;
  }
  const SideView right_view(curve, true);
  SideRing& right = scratch[1];
  make_side(right_view, thickness, unit_weight, fills, gravity, options, ring.joint_fractions, L, right);
  // Both sides end on the crown's vertical; at a kink the two sides' faces meet there only when the
  // kink is symmetric (else the vertical joint would not cut the arch in two).
  const Joint a = left.joints.back().joint, b = to_curve(right_view, right.joints.back().joint);
  const double mismatch = std::max((a.intrados - b.intrados).norm(), (a.extrados - b.extrados).norm());
  if (mismatch > 1e-7 * L)
    throw std::invalid_argument(fmt::format(
        "curve: the crown (s = {} m) is a kink whose two sides are not mirror images: the faces of the two sides "
        "meet the crown's vertical {} m apart, so no vertical crown joint cuts the arch in two",
        curve.crown(), mismatch));
  for (int j = m - 1; j >= 0; --j) ring.joints.push_back(to_curve(right_view, right.joints[j].joint));
  for (int k = m - 1; k >= 0; --k) ring.voussoirs.push_back(to_curve(right_view, right.voussoirs[k]));
}

Ring build_ring(const Curve& curve, double thickness, double unit_weight, const std::vector<FillLoad>& fills,
                double gravity, const LimitOptions& options, const std::vector<double>& fractions) {
  Ring ring;
  std::array<SideRing, 2> scratch;
  build_ring(curve, thickness, unit_weight, fills, gravity, options, fractions, ring, scratch);
  return ring;
}

}  // namespace

const char* to_string(JointOrientation j) { return j == JointOrientation::radial ? "radial" : "vertical"; }
const char* to_string(WeightModel w) { return w == WeightModel::voussoir ? "voussoir" : "axis"; }
const char* to_string(Face f) {
  switch (f) {
    case Face::intrados: return "intrados";
    case Face::extrados: return "extrados";
    case Face::axis: return "axis";
  }
  return "unknown";
}

bool LimitOptions::is_valid(std::string* why) const {
  auto fail = [&](std::string reason) {
    if (why) *why = std::move(reason);
    return false;
  };
  if (joints_count < kMinJointsCount || joints_count > kMaxJointsCount || joints_count % 2 == 0)
    return fail(fmt::format("joints_count: must be odd and lie in [{}, {}] (a joint at the crown), got {}",
                            kMinJointsCount, kMaxJointsCount, joints_count));
  if (!std::isfinite(friction) || friction < 0)
    return fail(fmt::format("friction: must be finite and >= 0 (0: no sliding check), got {}", friction));
  if (!(compressive_strength > 0))
    return fail(fmt::format("compressive_strength: must be > 0 (Pa; infinity: no crushing), got {}",
                            compressive_strength));
  return true;
}

namespace {
template <class F>
double sum_over(const std::vector<Voussoir>& voussoirs, F f) {
  double total = 0;
  for (const Voussoir& v : voussoirs) total += f(v);
  return total;
}
}  // namespace

double Ring::total_weight() const { return sum_over(voussoirs, [](const Voussoir& v) { return v.weight; }); }
double Ring::total_fill() const { return sum_over(voussoirs, [](const Voussoir& v) { return v.fill.force; }); }
double Ring::total_dead() const { return total_weight() + total_fill(); }
double Ring::total_live() const { return sum_over(voussoirs, [](const Voussoir& v) { return v.live.force; }); }
bool Ring::has_live_load() const {
  for (const Voussoir& v : voussoirs)
    if (v.live.force != 0.0 || v.live.moment != 0.0) return true;
  return false;
}

Ring make_ring(const Curve& curve, double thickness, double unit_weight, const LimitOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  return build_ring(curve, thickness, unit_weight, {}, 0.0, options,
                    limit_detail::uniform_fractions(options.joints_count));
}

Ring make_ring(const Scene& scene, const LimitOptions& options) {
  return limit_detail::make_ring_at(scene, options, limit_detail::starting_fractions(scene, options));
}

namespace limit_detail {

std::vector<double> uniform_fractions(int joints_count) {
  const int m = (joints_count - 1) / 2;  // voussoirs per side
  std::vector<double> f;
  f.reserve(m - 1);
  for (int j = 1; j < m; ++j) f.push_back(static_cast<double>(j) / m);
  return f;
}

std::vector<double> starting_fractions(const Scene& scene, const LimitOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  if (!scene.curve) throw std::invalid_argument("curve: a scene needs a generator curve");
  std::vector<double> f = uniform_fractions(options.joints_count);
  const std::vector<double> at_loads = load_fractions(*scene.curve, scene.thickness, scene.loads, options);
  f.insert(f.end(), at_loads.begin(), at_loads.end());
  return merged_fractions(std::move(f));
}

std::vector<double> merged_fractions(std::vector<double> f) {
  std::sort(f.begin(), f.end());
  std::vector<double> out;
  out.reserve(f.size());
  for (double x : f) {
    if (!(x > kFractionGap && x < 1.0 - kFractionGap) && !kept_wall_fraction(x)) continue;
    if (!out.empty() && x - out.back() <= kFractionGap) continue;
    out.push_back(x);
  }
  return out;
}

std::vector<double> load_fractions(const Curve& curve, double thickness, const Loads& loads,
                                   const LimitOptions& options) {
  std::vector<double> out;
  const double L = curve.span();
  if (!std::isfinite(thickness) || !(thickness > 0) || thickness >= max_thickness(curve)) return out;  // refused later
  add_load_fractions(SideView(curve, false), thickness, loads, options, L, out);
  if (curve.extent() == CurveExtent::whole) {
    add_load_fractions(SideView(curve, true), thickness, loads, options, L, out);
  } else {
    // A half curve's right side is the mirror of its left one: the loads beyond mid-span, mirrored.
    Loads mirrored;
    for (const PointLoad& q : loads.points) mirrored.points.push_back({q.force, 1.0 - q.at});
    for (const LiveLoad& q : loads.live) mirrored.live.push_back({q.intensity, 1.0 - q.to, 1.0 - q.from});
    add_load_fractions(SideView(curve, false), thickness, mirrored, options, L, out);
  }
  return out;
}

struct RingScratch::Impl {
  std::array<SideRing, 2> sides;
  std::vector<double> arch;  // the arch's fractions of a ring with walls
};

RingScratch::RingScratch() : impl_(std::make_unique<Impl>()) {}
RingScratch::~RingScratch() = default;

void RingScratch::forget() {
  for (SideRing& side : impl_->sides) {
    side.bands.clear();
    side.previous_bands.clear();
    side.samples.clear();
    side.previous_samples.clear();
    side.memo.clear();
  }
}

void make_ring_at(const Scene& scene, const LimitOptions& options, const std::vector<double>& fractions, Ring& ring,
                  RingScratch& scratch) {
  if (!scene.curve) throw std::invalid_argument("curve: a scene needs a generator curve");
  const Material& m = scene.material;
  // The arch's fractions come first (merged_fractions sorts them); the walls' beds after them.
  const auto walls = std::find_if(fractions.begin(), fractions.end(), is_wall_fraction);
  const std::vector<double>& arch = walls == fractions.end() ? fractions : scratch.impl_->arch;
  if (walls != fractions.end()) scratch.impl_->arch.assign(fractions.begin(), walls);
  build_ring(*scene.curve, scene.thickness, m.density * m.gravity, scene.loads.fills, m.gravity, options, arch, ring,
             scratch.impl_->sides);
  add_live_loads(ring, scene.loads, options.weight);
  attach_walls(scene, fractions, ring);
  ring.acceleration = scene.horizontal_acceleration;
  if (scene.left.kind == SupportKind::pinned) ring.pins.push_back(ring.left_springing());
  if (scene.crown_hinge) ring.pins.push_back(ring.crown_joint());
  if (scene.right.kind == SupportKind::pinned) ring.pins.push_back(ring.right_springing());
}

Ring make_ring_at(const Scene& scene, const LimitOptions& options, const std::vector<double>& fractions) {
  Ring ring;
  RingScratch scratch;
  make_ring_at(scene, options, fractions, ring, scratch);
  return ring;
}

void loads_left_of_joints(const Ring& ring, LoadsLeftOfJoints& out) {
  const std::size_t n = ring.joints.size();
  out.dead.assign(n, VerticalLoad{});
  out.live.assign(n, VerticalLoad{});
  for (std::size_t j = 1; j < n; ++j) {
    const Voussoir& v = ring.voussoirs[j - 1];
    out.dead[j] = out.dead[j - 1];
    out.dead[j] += v.dead();
    out.live[j] = out.live[j - 1];
    out.live[j] += v.live;
  }
}

LoadsLeftOfJoints loads_left_of_joints(const Ring& ring) {
  LoadsLeftOfJoints out;
  loads_left_of_joints(ring, out);
  return out;
}

}  // namespace limit_detail
}  // namespace ogive
