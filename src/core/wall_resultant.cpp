#include "ogive/core/wall_resultant.hpp"

#include <cmath>
#include <stdexcept>

namespace ogive {
namespace {

// The reaction on the arch at one springing, in global components, and its axis point.
struct Springing {
  double Rx = 0, Ry = 0, M = 0;
  Eigen::Vector2d P;
};

// The crossing of the bed at height y by the resultant above it (wall_resultant.hpp gives the formula),
// and the normal force there.
WallBedCrossing crossing(const WallOutline& o, const Wall& w, double gravity, const Springing& s, double y,
                         double* normal) {
  const double unit = w.density * gravity, b = w.thickness;
  const double body = unit * b * (o.top_y - y), wedge = unit * o.wedge_area;
  const double W = body + wedge;
  const double xW = body * 0.5 * (o.inner_x + o.outer_x) + wedge * o.wedge_centroid.x();  // W times x_W
  const double xQ = o.inner_x + o.outward * w.top_load_at * b;
  const double N = s.Ry + W + w.top_load;
  const double x = (s.Ry * s.P.x() - s.Rx * (s.P.y() - y) + s.M + xW + w.top_load * xQ) / N;
  if (normal) *normal = N;
  return {y, x, o.outward * (x - 0.5 * (o.inner_x + o.outer_x))};
}

}  // namespace

WallResultant wall_resultant(const Scene& scene, const Reactions& r, bool right, int beds) {
  const std::optional<Wall>& wall = right ? scene.right_wall : scene.left_wall;
  if (!wall) throw std::invalid_argument(right ? "right_wall: the scene has none" : "left_wall: the scene has none");
  if (beds < 1) throw std::invalid_argument("beds: must be >= 1");
  const Curve& curve = *scene.curve;
  const CurvePoint q = right ? curve.at_whole_arch(curve.whole_length()) : curve.at(0.0);
  Springing s{right ? -r.H_right : r.H_left, right ? r.V_right : r.V_left, right ? r.M_right : r.M_left,
              Eigen::Vector2d(q.x, q.y)};
  const double g = scene.material.gravity;
  const WallOutline o = wall_outline(curve, scene.thickness, *wall, right);
  WallResultant out;
  for (int k = 0; k <= beds; ++k) {
    const double y = o.top_y + (o.base_y - o.top_y) * k / beds;
    out.beds.push_back(crossing(o, *wall, g, s, y, k == beds ? &out.normal_force : nullptr));
  }
  const double e = out.beds.back().eccentricity, half = 0.5 * wall->thickness;
  out.base_eccentricity = e;
  out.stability_ratio = half / std::abs(e);
  // The thickness at which the base's resultant reaches the outer toe: the root of its distance beyond
  // the toe, d(b) = e + b/2 - b, positive for a wall too thin (the thrust pushes the resultant out) and
  // negative for a very thick one (its weight at its middle holds it); bisection to round-off.
  auto beyond = [&](double b) {
    Wall w = *wall;
    w.thickness = b;
    const WallOutline ob = wall_outline(curve, scene.thickness, w, right);
    return crossing(ob, w, g, s, ob.base_y, nullptr).eccentricity - 0.5 * b;
  };
  double lo = 1e-9 * curve.span(), hi = 1e3 * curve.span();
  if (beyond(lo) > 0 && beyond(hi) < 0) {
    for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      (beyond(mid) > 0 ? lo : hi) = mid;
    }
    out.geometric_factor = wall->thickness / hi;
  }
  return out;
}

}  // namespace ogive
