#include "ogive/model/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace ogive {
namespace {

[[noreturn]] void refuse(const char* field, const char* rule, double value) {
  throw std::invalid_argument(fmt::format("{}: {}, got {}", field, rule, value));
}

void require_positive(const char* field, double value) {
  if (!std::isfinite(value) || !(value > 0)) refuse(field, "must be finite and > 0", value);
}

}  // namespace

// The curve knows its largest curvature (exactly or cached at construction): validating a scene does
// not evaluate the curve again (it used to sample 513 points, 20-67 % of a raw CVODE solve).
double max_thickness(const Curve& curve) { return 2.0 / curve.max_curvature(); }

// The self-weight per axis length plus every other load spread evenly over the whole arch's length (a
// fill counted at its level's full depth over the span): the force scale of the model, never 0 for a
// valid scene. With self-weight alone it is w, as before loads existed.
double Scene::reference_load_per_length() const {
  double other = 0;
  const double L = span();
  for (const PointLoad& p : loads.points) other += std::abs(p.force);
  for (const LiveLoad& q : loads.live) other += std::abs(q.intensity) * (q.to - q.from) * L;
  for (const FillLoad& f : loads.fills) other += f.density * material.gravity * f.height_ratio * L * L;
  const double reference = weight_per_length() + other / curve->whole_length();
  if (horizontal_acceleration == 0) return reference;
  // The horizontal load of the masses too: a large acceleration keeps the scaled loads of order one.
  double fill = 0;
  for (const FillLoad& f : loads.fills) fill += f.density * material.gravity * f.height_ratio * L * L;
  return reference + std::abs(horizontal_acceleration) * (weight_per_length() + fill / curve->whole_length());
}

namespace {

void require_finite(const char* field, double value) {
  if (!std::isfinite(value)) refuse(field, "must be finite", value);
}

void validate_support(const Support& s, const char* spread, const char* settlement, const char* rotation) {
  require_finite(spread, s.spread);
  require_finite(settlement, s.settlement);
  require_finite(rotation, s.rotation);
  if (s.kind == SupportKind::pinned && s.rotation != 0)
    refuse(rotation, "must be 0 on a pinned springing (its section turns freely; the rotation is a result)",
           s.rotation);
}

// A's load is B's mirror image (x -> L - x), positions to round-off (0.8 mirrors to 0.19999999999999996).
bool same_position(double a, double b) { return std::abs(a - b) <= 1e-14; }
bool mirrored(const PointLoad& a, const PointLoad& b) { return a.force == b.force && same_position(a.at, 1.0 - b.at); }
bool mirrored(const LiveLoad& a, const LiveLoad& b) {
  return a.intensity == b.intensity && same_position(a.from, 1.0 - b.to) && same_position(a.to, 1.0 - b.from);
}

// Every load has a mirror image among the loads (itself for a centred one), counted with multiplicity.
template <class Load>
bool mirror_invariant(const std::vector<Load>& loads) {
  std::vector<bool> used(loads.size(), false);
  for (std::size_t i = 0; i < loads.size(); ++i) {
    if (used[i]) continue;
    bool found = false;
    for (std::size_t j = i; j < loads.size() && !found; ++j)
      if (!used[j] && mirrored(loads[i], loads[j])) {
        used[i] = used[j] = found = true;
      }
    if (!found) return false;
  }
  return true;
}

bool same_wall(const std::optional<Wall>& a, const std::optional<Wall>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a || (a->height == b->height && a->thickness == b->thickness && a->density == b->density &&
                a->top_load == b->top_load && a->top_load_at == b->top_load_at);
}

// A wall's height and thickness at the most, in spans: beyond, it is no wall of a vault (and its
// weight's products leave the range of a double).
constexpr double kLargestWall = 100.0;
// The walls' weight and top load at the most, relative to the arch's loads: beyond, the arch's forces are
// round-off in the system's equilibrium (the limit analysis works in units of the whole load).
constexpr double kHeaviestWalls = 1e4;

// One wall's fields and fit to its springing (Scene::validate); arch_load: the arch's loads (N/m).
void validate_wall(const Wall& w, const Curve& curve, double thickness, double gravity, double arch_load, bool right) {
  const char* side = right ? "right_wall" : "left_wall";
  auto field = [&](const char* name) { return fmt::format("{}_{}", side, name); };
  if (!std::isfinite(w.height) || !(w.height >= 0)) refuse(field("height").c_str(), "must be finite and >= 0", w.height);
  if (!std::isfinite(w.thickness) || !(w.thickness > 0))
    refuse(field("thickness").c_str(), "must be finite and > 0", w.thickness);
  if (!std::isfinite(w.density) || !(w.density >= 0))
    refuse(field("density").c_str(), "must be finite and >= 0", w.density);
  if (!std::isfinite(w.top_load) || !(w.top_load >= 0))
    refuse(field("top_load").c_str(), "must be finite and >= 0 (downwards)", w.top_load);
  if (!(w.top_load_at >= 0 && w.top_load_at <= 1))
    refuse(field("top_load_at").c_str(), "must lie in [0, 1] (a fraction of the wall's thickness from its inner face)",
           w.top_load_at);
  const double L = curve.span();
  if (w.height > kLargestWall * L)
    throw std::invalid_argument(fmt::format("{}: must be at most {} spans ({} m), got {} m", field("height"),
                                            kLargestWall, kLargestWall * L, w.height));
  if (w.thickness > kLargestWall * L)
    throw std::invalid_argument(fmt::format("{}: must be at most {} spans ({} m), got {} m", field("thickness"),
                                            kLargestWall, kLargestWall * L, w.thickness));
  const double load = w.density * gravity * w.thickness * (w.height + thickness) + w.top_load;
  if (!std::isfinite(load) || load > kHeaviestWalls * arch_load)
    throw std::invalid_argument(fmt::format(
        "{}, {}: the wall's weight and top load ({} N/m) must be at most {:g} times the arch's loads ({} N/m)",
        field("density"), field("top_load"), load, kHeaviestWalls, arch_load));
  const WallOutline o = wall_outline(curve, thickness, w, right);
  // The springing joint from its intrados point outwards: its horizontal width, on the wall's side.
  const double width = o.outward * (o.joint.extrados.x() - o.joint.intrados.x());
  if (width < -1e-12 * curve.span())
    throw std::invalid_argument(fmt::format(
        "{}: the springing joint leans inwards (its extrados point lies {} m inside the span beyond its intrados "
        "point): it does not rest on the wall's top",
        field("thickness"), -width));
  if (w.thickness < width * (1 - 1e-12))
    throw std::invalid_argument(fmt::format(
        "{}: must be at least the springing joint's horizontal width ({} m), the wall carrying the whole joint, got {} m",
        field("thickness"), width, w.thickness));
  if (o.base_y > o.top_y + 1e-12 * curve.span())
    throw std::invalid_argument(fmt::format(
        "{}: must reach the springing joint's lower end ({} m below the springing's axis point), got {} m",
        field("height"), o.joint.axis.y() - o.top_y, w.height));
}

}  // namespace

SpringingJoint springing_joint(const Curve& curve, double thickness, bool right) {
  const CurvePoint q = right ? curve.at_whole_arch(curve.whole_length()) : curve.at(0.0);
  // The normal towards the extrados (the left of the direction of travel, left to right), as the ring's
  // joints are made (src/limit/voussoirs.cpp).
  const Eigen::Vector2d p(q.x, q.y), normal(-std::sin(q.theta), std::cos(q.theta));
  const double half_t = 0.5 * thickness;
  return {p - half_t * normal, p + half_t * normal, p};
}

WallOutline wall_outline(const Curve& curve, double thickness, const Wall& wall, bool right) {
  return wall_outline(springing_joint(curve, thickness, right), wall, right);
}

WallOutline wall_outline(const SpringingJoint& joint, const Wall& wall, bool right) {
  WallOutline o;
  o.joint = joint;
  o.outward = right ? 1.0 : -1.0;
  o.inner_x = o.joint.intrados.x();
  o.outer_x = o.inner_x + o.outward * wall.thickness;
  o.top_y = std::min(o.joint.intrados.y(), o.joint.extrados.y());
  o.base_y = o.joint.axis.y() - wall.height;
  // The wedge's outline (either orientation) by the shoelace formula.
  const Eigen::Vector2d I = o.joint.intrados, E = o.joint.extrados;
  const Eigen::Vector2d p[] = {{o.outer_x, o.top_y}, {o.inner_x, o.top_y}, I, E, {o.outer_x, E.y()}};
  double a = 0;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < 5; ++i) {
    const Eigen::Vector2d &u = p[i], &v = p[(i + 1) % 5];
    const double w = u.x() * v.y() - v.x() * u.y();
    a += w;
    c += w * (u + v);
  }
  o.wedge_area = 0.5 * std::abs(a);
  if (a != 0) o.wedge_centroid = c / (3.0 * a);
  return o;
}

Support wall_lean_movement(const WallOutline& wall, double lean, SupportKind kind) {
  if (!std::isfinite(lean)) refuse("wall_lean", "must be finite (rad, outwards positive)", lean);
  // Outwards is -x for the left wall: its outward lean turns it counter-clockwise.
  const double phi = -wall.outward * lean;
  const Eigen::Vector2d arm = wall.joint.axis - Eigen::Vector2d(wall.outer_x, wall.base_y);
  const Eigen::Vector2d u(-phi * arm.y(), phi * arm.x());  // phi k x arm
  Support m;
  m.kind = kind;
  m.spread = wall.outward * u.x();
  m.settlement = -u.y();
  m.rotation = kind == SupportKind::clamped ? phi : 0.0;
  return m;
}

bool Scene::symmetric() const {
  if (!curve || curve->extent() != CurveExtent::half || horizontal_acceleration != 0) return false;
  if (!same_wall(left_wall, right_wall)) return false;
  if (left.kind != right.kind || left.spread != right.spread || left.settlement != right.settlement ||
      left.rotation != -right.rotation)
    return false;
  return mirror_invariant(loads.points) && mirror_invariant(loads.live);
}

void Scene::validate() const {
  if (!curve) throw std::invalid_argument("curve: a scene needs a generator curve");
  require_positive("thickness", thickness);
  require_positive("youngs_modulus", material.youngs_modulus);
  if (!std::isfinite(material.density) || !(material.density >= 0))
    refuse("density", "must be finite and >= 0", material.density);
  if (material.density == 0 && loads.empty())
    refuse("density", "must be > 0 when the arch carries no other load", material.density);
  require_positive("gravity", material.gravity);
  require_positive("shear_coefficient", material.shear_coefficient);
  const double nu = material.poisson_ratio;
  if (!std::isfinite(nu) || !(nu > -1.0 && nu <= 0.5)) refuse("poisson_ratio", "must lie in (-1, 0.5]", nu);
  if (material.plane_strain && nu == 0.5)
    refuse("poisson_ratio", "must be < 0.5 in plane strain (E / (1 - nu^2) stays finite)", nu);
  require_finite("horizontal_acceleration", horizontal_acceleration);
  validate_support(left, "left_spread", "left_settlement", "left_rotation");
  validate_support(right, "right_spread", "right_settlement", "right_rotation");
  for (const PointLoad& p : loads.points) {
    require_finite("point_load", p.force);
    if (!(p.at >= 0 && p.at <= 1)) refuse("point_load_at", "must lie in [0, 1] (x / L within the span)", p.at);
  }
  for (const LiveLoad& q : loads.live) {
    require_finite("live_load", q.intensity);
    if (!(q.from >= 0 && q.from <= 1)) refuse("live_load_from", "must lie in [0, 1] (x / L within the span)", q.from);
    if (!(q.to >= 0 && q.to <= 1)) refuse("live_load_to", "must lie in [0, 1] (x / L within the span)", q.to);
    if (!(q.to > q.from)) refuse("live_load_to", fmt::format("must exceed live_load_from ({})", q.from).c_str(), q.to);
  }
  for (const FillLoad& f : loads.fills) {
    if (!std::isfinite(f.density) || !(f.density >= 0)) refuse("fill_density", "must be finite and >= 0", f.density);
    if (!std::isfinite(f.height_ratio) || !(f.height_ratio > 0))
      refuse("fill_height_ratio", "must be finite and > 0 (the fill's level lies above the springing line)",
             f.height_ratio);
  }
  // The model works in units of w L, w L^2, w L^4 / EI and w L^3 / EI (arch_model.cpp), w being the
  // reference load per axis length (reference_load_per_length). Each field can be finite while a product
  // is not: found by fuzzing, density 1e308 gave w = inf, then H = V = inf and H/V = nan with status
  // success. So every scale must be a finite positive double too.
  {
    const double L = span(), w = reference_load_per_length(), EI = material.effective_modulus() * inertia();
    const double displacement = w * L * L * L * L / EI;
    const double scales[] = {w, EI, w * L, w * L * L, displacement, w * L * L * L / EI, inertia() / (area() * L * L)};
    for (double scale : scales)
      if (!std::isfinite(scale) || !(scale > 0))
        throw std::invalid_argument(fmt::format(
            "density, gravity, thickness{}: the weight per length w = {} N/m{} and the bending "
            "stiffness EI = {} N m^2 with span {} m give force, moment or displacement scales (w L, w L^2, "
            "w L^4 / EI) beyond the range of a double",
            horizontal_acceleration != 0 ? ", youngs_modulus and horizontal_acceleration" : " and youngs_modulus", w,
            horizontal_acceleration != 0 ? " (with a times the masses)" : "", EI, L));
    for (const auto& [field, value] : {std::pair{"left_spread", left.spread}, {"left_settlement", left.settlement},
                                        {"right_spread", right.spread}, {"right_settlement", right.settlement}})
      if (!std::isfinite(value / displacement)) refuse(field, "must be finite in units of w L^4 / EI", value);
  }
  if (!std::isfinite(model_tolerance) || !(model_tolerance >= 0 && model_tolerance < 1))
    refuse("model_tolerance", "must lie in [0, 1) (a relative error of H/V; 0: none asked)", model_tolerance);
  if (beam_model == BeamModel::automatic && !(model_tolerance > 0))
    throw std::invalid_argument("beam_model: automatic needs a model_tolerance > 0 (the error the model may make)");
  if ((beam_model == BeamModel::automatic || model_tolerance > 0) && section != SectionKind::elastic)
    throw std::invalid_argument(
        "model_tolerance: the model's error is estimated for the elastic section only (against the curved bar)");
  if (beam_model == BeamModel::curved && section != SectionKind::elastic)
    throw std::invalid_argument(
        "beam_model: curved takes the elastic section only (the no-tension section's law is a straight beam's)");
  // A section deeper than twice the radius of curvature would overlap itself on the intrados.
  const double limit = max_thickness(*curve);
  if (thickness >= limit)
    throw std::invalid_argument(fmt::format(
        "thickness: must be less than twice the smallest radius of curvature ({} m), got {} m", limit, thickness));
  const double arch_load = reference_load_per_length() * curve->whole_length();
  if (left_wall) validate_wall(*left_wall, *curve, thickness, material.gravity, arch_load, false);
  if (right_wall) validate_wall(*right_wall, *curve, thickness, material.gravity, arch_load, true);
}

const char* to_string(BeamModel m) {
  switch (m) {
    case BeamModel::euler_bernoulli: return "euler-bernoulli";
    case BeamModel::timoshenko: return "timoshenko";
    case BeamModel::curved: return "curved";
    case BeamModel::automatic: return "auto";
  }
  return "";
}

}  // namespace ogive
