// The ring of voussoirs: joints, and the weight of each voussoir with where it acts.
#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "gauss_legendre.hpp"
#include "limit/limit_internal.hpp"
#include "ogive/limit.hpp"

namespace ogive {
namespace {

// A point of the line at signed distance n from the axis of the left half (n > 0 towards the extrados),
// at axis arc length s, and its derivative d/ds. Beyond the crown (s > S; only the extrados of a pointed
// crown goes there, up to mid-span) the face is continued: along the last arc for a piecewise-circular
// curve (Curve::at extrapolates its end arcs), otherwise along the crown's tangent.
struct FacePoint {
  Eigen::Vector2d p, dp;
};

CurvePoint axis_at(const Curve& curve, double s) {
  const double S = curve.length();
  if (s <= S || !curve.arcs().empty()) return curve.at(s);
  const CurvePoint c = curve.at(S);
  return {c.x + (s - S) * std::cos(c.theta), c.y + (s - S) * std::sin(c.theta), c.theta, 0.0};
}

FacePoint offset(const CurvePoint& q, double n) {
  const Eigen::Vector2d tangent(std::cos(q.theta), std::sin(q.theta));
  const Eigen::Vector2d normal(-tangent.y(), tangent.x());  // towards the extrados
  // d(P + n normal)/ds = tangent (1 - n kappa): d normal/ds = -kappa tangent.
  return {Eigen::Vector2d(q.x, q.y) + n * normal, (1.0 - n * q.kappa) * tangent};
}

FacePoint face_at(const Curve& curve, double n, double s) { return offset(axis_at(curve, s), n); }

// The arc length s in [lo, hi] where the face at n reaches abscissa x. x grows with s on every face of
// a valid ring (dx/ds = cos theta (1 - n kappa) >= 0), so a safeguarded Newton iteration converges.
double face_at_x(const Curve& curve, double n, double x, double lo, double hi) {
  double s = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const FacePoint f = face_at(curve, n, s);
    const double r = f.p.x() - x;
    if (r > 0) hi = s; else lo = s;
    if (std::abs(r) <= 1e-15 * curve.span() || hi - lo <= 1e-15 * curve.span()) break;
    const double newton = f.dp.x() > 0 ? s - r / f.dp.x() : 0.5 * (lo + hi);
    s = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
  }
  return s;
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
  // sign (+1 along a -> b, -1 back), piece by piece between the knots (the curve's breakpoints and the
  // crown), where the integrand is smooth; one evaluation of the axis per node serves every face.
  template <std::size_t N>
  void add_faces(const Curve& curve, const std::vector<double>& breaks, const std::array<std::pair<double, double>, N>& faces,
                 double a, double b) {
    double from = a;
    auto piece = [&](double to) {
      add(gauss_legendre_integral<8>(
          [&](double s) -> Eigen::Vector3d {
            const CurvePoint q = axis_at(curve, s);
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (const auto& [n, sign] : faces) sum += sign * integrand(offset(q, n));
            return sum;
          },
          from, to));
      from = to;
    };
    if (a < b) {
      for (double k : breaks)
        if (k > a && k < b) piece(k);
    } else {
      for (auto k = breaks.rbegin(); k != breaks.rend(); ++k)
        if (*k < a && *k > b) piece(*k);
    }
    piece(b);
  }
};

// One joint of the left half with the arc lengths at which it meets the intrados and extrados faces.
struct HalfJoint {
  Joint joint;
  double s_intrados = 0, s_extrados = 0;
};

}  // namespace

const char* to_string(JointOrientation j) { return j == JointOrientation::radial ? "radial" : "vertical"; }
const char* to_string(WeightModel w) { return w == WeightModel::voussoir ? "voussoir" : "axis"; }

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
  if (!std::isfinite(point_load.force) || point_load.force < 0)
    return fail(fmt::format("point_load: must be finite and >= 0 (N/m, downward), got {}", point_load.force));
  if (!std::isfinite(point_load.position) || point_load.position < 0 || point_load.position > 1)
    return fail(fmt::format("point_load_at: must lie in [0, 1] (x/L: within the span), got {}", point_load.position));
  return true;
}

double Ring::total_weight() const {
  double w = 0;
  for (const Voussoir& v : voussoirs) w += v.weight;
  return w;
}

Ring make_ring(const Curve& curve, double thickness, double unit_weight, const LimitOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  if (!std::isfinite(unit_weight) || !(unit_weight > 0))
    throw std::invalid_argument(fmt::format("unit_weight: must be finite and > 0 (N/m^3), got {}", unit_weight));
  if (!std::isfinite(thickness) || !(thickness > 0) || thickness >= max_thickness(curve))
    throw std::invalid_argument(fmt::format(
        "thickness: must be > 0 and less than twice the smallest radius of curvature ({} m), got {} m",
        max_thickness(curve), thickness));
  const double L = curve.span(), S = curve.length(), half_t = 0.5 * thickness;
  const int m = (options.joints_count - 1) / 2;  // voussoirs per half

  // The crown joint is vertical at mid-span. At a pointed crown the intrados reaches mid-span before the
  // axis does and the extrados after it: find where.
  const bool pointed = curve.at(S).theta > 1e-12;
  double s_intrados_crown = S, s_extrados_crown = S;
  if (pointed) {
    s_intrados_crown = face_at_x(curve, -half_t, 0.5 * L, 0.0, S);
    double hi = S + thickness;
    while (face_at(curve, half_t, hi).p.x() < 0.5 * L) hi = S + 2.0 * (hi - S);
    s_extrados_crown = face_at_x(curve, half_t, 0.5 * L, S, hi);
  }

  auto make_joint = [&](double s_in, double s_ex, double s_axis) {
    HalfJoint h;
    h.joint.intrados = face_at(curve, -half_t, s_in).p;
    h.joint.extrados = face_at(curve, half_t, s_ex).p;
    h.joint.s = s_axis;
    h.s_intrados = s_in;
    h.s_extrados = s_ex;
    return h;
  };
  std::vector<HalfJoint> half;
  half.reserve(m + 1);
  half.push_back(make_joint(0.0, 0.0, 0.0));  // the springing bed, normal to the axis
  for (int j = 1; j < m; ++j) {
    // Both orientations space the joints over the part of the arch whose joints cut it in two: radial
    // joints over the axis up to where the intrados reaches mid-span, vertical ones over the intrados.
    const double s = s_intrados_crown * j / m;
    if (options.joints == JointOrientation::radial) {
      half.push_back(make_joint(s, s, s));
    } else {
      const double x = face_at(curve, -half_t, s).p.x();
      half.push_back(make_joint(s, face_at_x(curve, half_t, x, 0.0, s_extrados_crown), face_at_x(curve, 0.0, x, 0.0, S)));
    }
  }
  HalfJoint crown = make_joint(s_intrados_crown, s_extrados_crown, S);
  crown.joint.intrados.x() = crown.joint.extrados.x() = 0.5 * L;  // exactly vertical
  half.push_back(crown);

  // Where the faces' integrands are not smooth: the curve's breakpoints and the crown (sorted).
  std::vector<double> breaks = curve.breakpoints();
  breaks.push_back(S);
  std::vector<Voussoir> left(m);
  for (int k = 0; k < m; ++k) {
    const HalfJoint &a = half[k], &b = half[k + 1];
    if (options.weight == WeightModel::voussoir) {
      RegionMoments r;
      if (a.s_intrados == a.s_extrados && b.s_intrados == b.s_extrados) {  // radial joints: one band
        r.add_faces<2>(curve, breaks, {{{-half_t, 1.0}, {half_t, -1.0}}}, a.s_intrados, b.s_intrados);
      } else {
        r.add_faces<1>(curve, breaks, {{{-half_t, 1.0}}}, a.s_intrados, b.s_intrados);
        r.add_faces<1>(curve, breaks, {{{half_t, 1.0}}}, b.s_extrados, a.s_extrados);
      }
      r.add_segment(b.joint.intrados, b.joint.extrados);
      r.add_segment(a.joint.extrados, a.joint.intrados);
      left[k] = {unit_weight * r.area, Eigen::Vector2d(r.sx / r.area, r.sy / r.area)};
    } else {
      // rho g t per length of axis, at the centroid of the voussoir's piece of axis.
      const Eigen::Vector2d first = gauss_legendre_integral<8>(
          [&](double s) -> Eigen::Vector2d { return face_at(curve, 0.0, s).p; }, a.joint.s, b.joint.s);
      const double length = b.joint.s - a.joint.s;
      left[k] = {unit_weight * thickness * length, first / length};
    }
  }

  Ring ring;
  ring.span = L;
  ring.joints.reserve(2 * m + 1);
  for (const HalfJoint& h : half) ring.joints.push_back(h.joint);
  for (int j = m - 1; j >= 0; --j) {
    const Joint& h = half[j].joint;
    ring.joints.push_back({Eigen::Vector2d(L - h.intrados.x(), h.intrados.y()),
                           Eigen::Vector2d(L - h.extrados.x(), h.extrados.y()), 2.0 * S - h.s});
  }
  ring.voussoirs = left;
  for (int k = m - 1; k >= 0; --k)
    ring.voussoirs.push_back({left[k].weight, Eigen::Vector2d(L - left[k].centroid.x(), left[k].centroid.y())});
  return ring;
}

namespace limit_detail {

int loaded_voussoir(const Ring& ring, const CollapseLoad& load) {
  if (!load.present()) return -1;
  const double x = load.position * ring.span;
  for (std::size_t k = 0; k + 1 < ring.joints.size(); ++k)
    if (x <= ring.joints[k + 1].extrados.x()) return static_cast<int>(k);
  return static_cast<int>(ring.voussoirs.size()) - 1;
}

LoadsLeftOfJoints loads_left_of_joints(const Ring& ring, const CollapseLoad& load) {
  const std::size_t n = ring.joints.size();
  LoadsLeftOfJoints out{std::vector<double>(n, 0.0), std::vector<double>(n, 0.0), std::vector<double>(n, 0.0),
                        std::vector<double>(n, 0.0)};
  const int loaded = loaded_voussoir(ring, load);
  for (std::size_t j = 1; j < n; ++j) {
    const Voussoir& v = ring.voussoirs[j - 1];
    out.dead[j] = out.dead[j - 1] + v.weight;
    out.dead_moment[j] = out.dead_moment[j - 1] + v.weight * v.centroid.x();
    if (loaded >= 0 && static_cast<int>(j) > loaded) {
      out.live[j] = load.force;
      out.live_moment[j] = load.force * load.position * ring.span;
    }
  }
  return out;
}

}  // namespace limit_detail
}  // namespace ogive
