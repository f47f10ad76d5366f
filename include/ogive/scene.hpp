// A scene: one unit-width slice of a symmetric barrel vault under its own weight (docs/model.md).
// SI units throughout: m, Pa, kg/m^3, m/s^2, N. Defaults are the paper's travertine.
#pragma once

#include <memory>

#include "ogive/curve.hpp"

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

struct Scene {
  std::shared_ptr<const Curve> curve;  // the half arch, springing to crown; required
  double thickness = 0.8;              // t, m; rectangular section t x 1 m: A = t, I = t^3 / 12
  Material material;
  double support_displacement = 0.0;   // d, m: each springing moves outwards by d (may be negative)

  double span() const { return curve->span(); }
  double area() const { return thickness; }
  double inertia() const { return thickness * thickness * thickness / 12.0; }
  // Self-weight per unit axis length, N/m (the mass centre's offset from the axis is neglected).
  double weight_per_length() const { return material.density * material.gravity * area(); }

  // Throws std::invalid_argument whose message names the field and the rule it breaks, e.g.
  // "poisson_ratio: must lie in (-1, 0.5], got 0.7". A valid scene has every field finite, positive
  // stiffness and weight, and a thickness that fits the curve (t < 2 * smallest radius of curvature,
  // so that the intrados does not fold over).
  void validate() const;
};

// Twice the smallest radius of curvature of the curve (m; inf for a straight curve): a section this deep
// or deeper folds over on the intrados. Scene::validate refuses thickness >= max_thickness(*curve).
double max_thickness(const Curve& curve);

}  // namespace ogive
