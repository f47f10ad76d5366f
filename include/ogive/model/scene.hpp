// A scene: one unit-width slice of a barrel vault (docs/model.md): its axis, section and material, the
// loads it carries and how its two springings are held and move. SI units throughout: m, Pa, kg/m^3,
// m/s^2, N, N/m and N/m^2 per metre of vault width. Defaults are the paper's travertine arch, clamped,
// under its own weight.
//
// Sign conventions (docs/model.md, "Sign conventions"): x runs from the left springing to the right one, y up;
// loads act downwards; a springing's spread is outward (away from the span), its settlement downward,
// its rotation counter-clockwise positive; reactions are given in Solution::reactions.
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "ogive/geometry/curve.hpp"
#include "ogive/model/section.hpp"

namespace ogive {

struct Material {
  double youngs_modulus = 14.8e9;          // E, Pa; > 0
  double poisson_ratio = 0.20;             // nu, in (-1, 0.5]
  double density = 2348.0;                 // rho, kg/m^3; > 0
  double gravity = 9.81;                   // g, m/s^2; > 0
  double shear_coefficient = 5.0 / 6.0;    // Timoshenko k, > 0 (5/6 for a rectangle)
  bool plane_strain = false;               // true: bending and axial stiffness use E / (1 - nu^2)

  double shear_modulus() const { return youngs_modulus / (2.0 * (1.0 + poisson_ratio)); }
  // The modulus that the section's axial and bending stiffness use (plane stress or plane strain).
  double effective_modulus() const {
    return plane_strain ? youngs_modulus / (1.0 - poisson_ratio * poisson_ratio) : youngs_modulus;
  }
};

// A vertical point load on the axis at x = at * L from the left springing (at in [0, 1]; a load at a
// springing goes straight into its support).
struct PointLoad {
  double force = 0;  // P, N per metre of vault width, downwards (may be negative: upwards)
  double at = 0.5;   // x / L
};

// A uniform load per horizontal length over from * L <= x <= to * L (0 <= from < to <= 1): a live load
// on the deck, acting on the axis points beneath it.
struct LiveLoad {
  double intensity = 0;  // q, N/m^2 (N per metre of horizontal length per metre of width), downwards
  double from = 0, to = 1;
};

// Fill: the weight of the material between the extrados and the level h_f above the left springing,
// q(x) = density g max(0, h_f - y_e(x)) per horizontal length, y_e(x) = y(x) + t / (2 cos theta(x)) being
// the extrados above the axis point at x (its height along the vertical through that point, the section
// assumed thin). Per axis length that is density g max(0, (h_f - y) cos theta - t / 2): finite even at a
// vertical springing.
struct FillLoad {
  double density = 0;       // rho_f, kg/m^3, >= 0
  double height_ratio = 0;  // h_f / L, above the left springing; > 0
};

// Every load but the self-weight (which is Material::density, 0 allowed when another load is present).
struct Loads {
  std::vector<PointLoad> points;
  std::vector<LiveLoad> live;
  std::vector<FillLoad> fills;
  bool empty() const { return points.empty() && live.empty() && fills.empty(); }
};

// The beam theory that models the slice (docs/model.md, "Beam models"), from the least to the richest.
enum class BeamModel {
  euler_bernoulli,  // no shear strain (an infinite shear stiffness); the axis stretches by N / (E A)
  timoshenko,       // the paper's: the section turns against the axis by the shear strain V / (k G A)
  curved,           // a thick curved bar: Timoshenko's shear with Winkler-Bach's section (the neutral axis
                    // off the centroid; the axis' strain and curvature coupled through the curvature) and
                    // each slice's weight at its centroid, t^2 / (12 R) beyond the axis (arch_model.hpp)
  automatic,        // solve() picks the least of the three whose model error estimate is within
                    // Scene::model_tolerance (ogive/solve/model_error.hpp); an ArchModel needs one of them
};

// "euler-bernoulli", "timoshenko", "curved", "auto".
const char* to_string(BeamModel m);

enum class SupportKind {
  clamped,  // displacements and rotation given
  pinned,   // displacements given, the section turns freely (M = 0)
};

// One springing: how it is held and how it moves (given movements, not reactions).
struct Support {
  SupportKind kind = SupportKind::clamped;
  double spread = 0;      // m, horizontal, outward (away from the span) positive
  double settlement = 0;  // m, vertical, downward positive
  double rotation = 0;    // rad, counter-clockwise positive; a pinned springing's must be 0 (it is free)
};

// A wall under a springing (docs/model.md, "Walls"): a rectangular block of masonry whose inner face is
// the vertical through the springing joint's intrados point and which extends outwards (away from the
// span) by its thickness b_w, from its base h_w below the springing's axis point up to the springing
// joint, which rests on its top. Its beds are horizontal; like the arch's joints they resist no tension
// and (unless the limit analysis is given a friction coefficient) do not slide.
struct Wall {
  double height = 0;     // h_w, m, from the base to the springing line (the springing's axis point); >= 0
  double thickness = 0;  // b_w, m, > 0, at least the springing joint's horizontal width
  double density = 0;    // rho_w, kg/m^3, >= 0 (g is the scene's)
  double top_load = 0;   // N per metre of vault width, >= 0, downwards, on the wall's top (a wall above, a roof)
  double top_load_at = 0.5;  // where it acts: the fraction of b_w from the inner face, in [0, 1]
};

// A springing joint, normal to the axis at the springing (the bed of the arch on its support or wall).
struct SpringingJoint {
  Eigen::Vector2d intrados, extrados, axis;  // m
};
// The springing joint of the arch of `curve` with thickness t (m): the left one or the right one.
SpringingJoint springing_joint(const Curve& curve, double thickness, bool right);

// A wall's outline (m), from its springing joint and the Wall: `outward` is -1 for the left wall, +1 for
// the right one; the inner face at x = inner_x, the outer one at outer_x = inner_x + outward b_w; the
// highest horizontal bed at top_y (the lower end of the springing joint: the springing joint rests on it
// when it is horizontal, else a wedge of wall fills the space between the two), the base at base_y =
// the springing's axis height - h_w.
struct WallOutline {
  SpringingJoint joint;
  double outward = -1, inner_x = 0, outer_x = 0, top_y = 0, base_y = 0;
  // The wedge between the highest bed and the springing joint (with the wall's top beyond the joint's
  // extrados at its height): area (m^2, 0 under a horizontal joint) and centroid (m).
  double wedge_area = 0;
  Eigen::Vector2d wedge_centroid = Eigen::Vector2d::Zero();
};
WallOutline wall_outline(const SpringingJoint& joint, const Wall& wall, bool right);
WallOutline wall_outline(const Curve& curve, double thickness, const Wall& wall, bool right);

// The springing's movement when its wall leans: the wall's rigid rotation by `lean` rad about its base's
// outer toe T = (outer_x, base_y), outwards positive (the left wall turning counter-clockwise, the right
// one clockwise). For small rotations the lean is the wall's out-of-plumb, its top's outward displacement
// over its height. The rotation phi (counter-clockwise: lean on the left, -lean on the right) moves the
// springing's axis point p (joint.axis, where the arch's boundary conditions hold) by
// phi k x (p - T) = phi (-(p_y - T_y), p_x - T_x): outwards by lean h_w and upwards by lean times p's
// horizontal distance from the toe. A clamped springing also turns with the wall by phi; a pinned one
// only translates (its section turns freely). Returned as a Support of `kind` (spread outwards and
// settlement downwards, m; rotation counter-clockwise, rad): the movement alone, which adds to the
// springing's given movement (small displacements superpose). Throws std::invalid_argument for a lean
// that is not finite.
Support wall_lean_movement(const WallOutline& wall, double lean, SupportKind kind);

struct Scene {
  // The axis: a half arch (symmetric) or a whole one, springing to springing (curve.hpp); required.
  std::shared_ptr<const Curve> curve;
  double thickness = 0.8;              // t, m; rectangular section t x 1 m: A = t, I = t^3 / 12
  Material material;
  Loads loads;
  Support left, right;
  // The section's law (section.hpp): elastic (linear, the paper's) or no_tension (cracks where the
  // resultant leaves the kern; solved by Newton, no_tension.hpp).
  SectionKind section = SectionKind::elastic;
  // The beam theory (arch_model.hpp): Timoshenko's, the paper's, unless asked otherwise.
  BeamModel beam_model = BeamModel::timoshenko;
  // The relative error of H/V that the beam model may make against the two-dimensional arch, in [0, 1)
  // (0: nothing asked). Above 0, solve() estimates the model's error (Diagnostics::model_error_estimate,
  // ogive/solve/model_error.hpp) and a solution whose estimate exceeds it is tolerance_not_met;
  // beam_model automatic needs it. The elastic section only.
  double model_tolerance = 0;
  bool crown_hinge = false;  // a hinge (M = 0, the rotation free to jump) at the crown (Curve::crown)
  // Pseudo-static earthquake: every mass of the scene (the arch's self-weight and the fill, not point or
  // live loads) also carries a horizontal force a times its weight, to +x (left to right) for a > 0; a
  // fraction of g, finite. A scene with a != 0 is not symmetric: it is solved over the whole arch.
  double horizontal_acceleration = 0;
  // The walls under the springings (none: the springing rests on the ground). A wall's base is the
  // support then; only the limit analysis takes walls (analyse_limit), the elastic analyses do not (a
  // wall's lean reaches them as its springing's movement: wall_lean_movement).
  std::optional<Wall> left_wall, right_wall;
  bool has_walls() const { return left_wall.has_value() || right_wall.has_value(); }
  // b_w of the thinner wall, m; infinity without walls.
  double thinnest_wall() const {
    const double none = std::numeric_limits<double>::infinity();
    return std::min(left_wall ? left_wall->thickness : none, right_wall ? right_wall->thickness : none);
  }

  // Sets both springings' outward spread to d (m): today's "support displacement" of the paper.
  void set_support_displacement(double d) { left.spread = right.spread = d; }

  double span() const { return curve->span(); }
  // Whether the scene is its own mirror image about x = L/2: a half curve, equal supports and movements
  // (a rotation mirrors to minus itself), loads that map onto themselves and no horizontal acceleration.
  // Such a scene is solved over the half arch.
  bool symmetric() const;
  double area() const { return thickness; }
  double inertia() const { return thickness * thickness * thickness / 12.0; }
  // Self-weight per unit axis length, N/m (the mass centre's offset from the axis is neglected); 0 with
  // density 0.
  double weight_per_length() const { return material.density * material.gravity * area(); }
  // The model's force scale w_ref (N/m, > 0 for a valid scene): the self-weight per axis length plus
  // every other load's total spread over the whole arch's length, plus |a| times the masses' (self-weight
  // and fill) under a horizontal acceleration a (scene.cpp says how each counts).
  double reference_load_per_length() const;

  // Throws std::invalid_argument whose message names the field and the rule it breaks, e.g.
  // "poisson_ratio: must lie in (-1, 0.5], got 0.7". A valid scene has every field finite, positive
  // stiffness, density >= 0, some load (self-weight or another), loads inside the span, a fill level
  // above the springing, no rotation given to a pinned springing, a thickness that fits the curve
  // (t < 2 * smallest radius of curvature, so that the intrados does not fold over), and the elastic
  // section for the curved beam model, and walls with finite fields, h_w >= 0 (deep enough to hold an
  // inclined springing joint), b_w at least the springing joint's horizontal width, h_w and b_w at most
  // 100 spans, a weight and top load at most 1e4 times the arch's loads, and a springing joint that rests
  // on its wall (its extrados point over the wall, not inside the span).
  void validate() const;
};

// Twice the smallest radius of curvature of the curve (m; inf for a straight curve): a section this deep
// or deeper folds over on the intrados. Scene::validate refuses thickness >= max_thickness(*curve).
double max_thickness(const Curve& curve);

}  // namespace ogive
