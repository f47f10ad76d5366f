// The analysis's checks: a scene that loads nothing is refused, and what an inadmissible arch's message
// says.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "limit/limit_internal.hpp"
#include "ogive/limit/limit.hpp"

namespace ogive::limit_detail {

// Throws std::invalid_argument when nothing loads the ring. Scene::validate lets density 0 pass with a
// fill; a fill whose level lies below the extrados over the whole span (it meets the extrados beyond the
// springing's vertical) loads nothing, and a ring that carries nothing has no thrust, no thinnest
// thickness and no mechanism to find. A fill that reaches the extrados over any part of the span is a
// scene: the unloaded voussoirs carry its thrust.
//
// Loads so small that the squares of the forces underflow (below about 1e-154 N/m; kSmallestLoads leaves
// room for the moments and sums) would make every joint look forceless and every thrust line admissible
// or none: refused too. The analysis is homogeneous in the loads, so such a scene is the same arch as
// one with its loads in ordinary units.
constexpr double kSmallestLoads = 1e-100;  // N/m, the ring's total load

void require_loaded(const Scene& scene, const Ring& ring) {
  const double total = std::abs(ring.total_dead()) + std::abs(ring.total_live());
  if (total != 0.0 && total < kSmallestLoads)
    throw std::invalid_argument(fmt::format(
        "density, fill_density: the ring's loads total {:.3g} N/m, below {:g} N/m, too small for the arithmetic of "
        "rigid voussoirs (their squares underflow); the analysis is the same at any scale: give the loads in N",
        total, kSmallestLoads));
  if (ring.total_dead() != 0.0 || ring.has_live_load()) return;
  double level = 0;
  for (const FillLoad& fill : scene.loads.fills)
    if (fill.density > 0) level = std::max(level, fill.height_ratio);
  if (!(level > 0))
    throw std::invalid_argument("density, fill_density: with no self-weight and no fill's weight (both 0) and no "
                                "point or live load the ring carries nothing: nothing to analyse");
  throw std::invalid_argument(fmt::format(
      "fill_height_ratio: the fill's level ({} of the span) lies below the arch's extrados over the whole span, "
      "so the fill loads nothing, and with density 0 the ring has no weight: nothing to analyse",
      level));
}

// Why no thrust line stands: where it would have to fit, and whether a thicker arch would stand (t_min
// below `t_cap`).
std::string inadmissible_message(const LimitOptions& options, double t_min, double t_cap, const std::string& on,
                                 const std::string& thinner) {
  std::string where = "inside the arch" + on + (options.friction > 0 ? " and its joints' friction cones" : "");
  if (std::isfinite(options.compressive_strength))
    where += fmt::format(" clear of the stress blocks that crush its joints (compressive strength {:g} Pa)",
                         options.compressive_strength);
  return std::isnan(t_min) ? fmt::format("no thrust line fits {} at any thickness up to {} m{}", where, t_cap, thinner)
                           : fmt::format("no thrust line fits {}: t < t_min{}", where, thinner);
}

}  // namespace ogive::limit_detail
