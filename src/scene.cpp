#include "ogive/scene.hpp"

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

void Scene::validate() const {
  if (!curve) throw std::invalid_argument("curve: a scene needs a generator curve");
  require_positive("thickness", thickness);
  require_positive("youngs_modulus", material.youngs_modulus);
  require_positive("density", material.density);
  require_positive("gravity", material.gravity);
  require_positive("shear_coefficient", material.shear_coefficient);
  const double nu = material.poisson_ratio;
  if (!std::isfinite(nu) || !(nu > -1.0 && nu <= 0.5)) refuse("poisson_ratio", "must lie in (-1, 0.5]", nu);
  if (material.plane_strain && nu == 0.5)
    refuse("poisson_ratio", "must be < 0.5 in plane strain (E / (1 - nu^2) stays finite)", nu);
  if (!std::isfinite(support_displacement))
    refuse("support_displacement", "must be finite", support_displacement);
  // The model works in units of w L, w L^2, w L^4 / EI and w L^3 / EI (arch_model.cpp). Each field can
  // be finite while a product is not: found by fuzzing, density 1e308 gave w = inf, then H = V = inf
  // and H/V = nan with status success. So every scale must be a finite positive double too.
  {
    const double L = span(), w = weight_per_length(), EI = material.effective_modulus() * inertia();
    const double displacement = w * L * L * L * L / EI;
    const double scales[] = {w, EI, w * L, w * L * L, displacement, w * L * L * L / EI, inertia() / (area() * L * L)};
    for (double scale : scales)
      if (!std::isfinite(scale) || !(scale > 0))
        throw std::invalid_argument(fmt::format(
            "density, gravity, thickness and youngs_modulus: the weight per length w = {} N/m and the bending "
            "stiffness EI = {} N m^2 with span {} m give force, moment or displacement scales (w L, w L^2, "
            "w L^4 / EI) beyond the range of a double",
            w, EI, L));
    if (!std::isfinite(support_displacement / displacement))
      refuse("support_displacement", "must be finite in units of w L^4 / EI", support_displacement);
  }
  // A section deeper than twice the radius of curvature would overlap itself on the intrados.
  const double limit = max_thickness(*curve);
  if (thickness >= limit)
    throw std::invalid_argument(fmt::format(
        "thickness: must be less than twice the smallest radius of curvature ({} m), got {} m", limit, thickness));
}

}  // namespace ogive
