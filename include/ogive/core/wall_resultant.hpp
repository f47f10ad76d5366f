// The resultant down a wall (Scene::left_wall, right_wall) of an elastic or cracking arch: the
// springing's reaction (Reactions, arch_model.hpp) carried down a rigid wall, with the wall's weight and
// its top load added bed by bed. Units: m, N per metre of vault width.
//
// The part of the wall above a horizontal bed at height y carries the arch's force on it (minus the
// springing's reaction, at the springing's axis point, with its couple), its own weight (the blocks and
// the wedge above the bed, at their centroids) and the top load; their resultant crosses the bed at
//   x = (R_y P_x - R_x (P_y - y) + M + W x_W + Q x_Q) / (R_y + W + Q),
// R = (R_x, R_y) the reaction on the arch (left: (H_left, V_left); right: (-H_right, V_right)), M its
// couple (counter-clockwise), P the springing's axis point, W and x_W the wall's weight above the bed
// and its centroid's x, Q and x_Q the top load and where it acts.
#pragma once

#include <limits>
#include <vector>

#include "ogive/model/arch_model.hpp"
#include "ogive/model/scene.hpp"

namespace ogive {

// Where the resultant crosses one bed.
struct WallBedCrossing {
  double y = 0;             // m, the bed's height (the springing line at 0 for the left springing)
  double x = 0;             // m, where the resultant crosses it
  double eccentricity = 0;  // m, from the bed's centre, outwards (away from the span) positive
};

struct WallResultant {
  std::vector<WallBedCrossing> beds;  // from the highest bed (the springing joint's lower end) to the base
  double normal_force = std::numeric_limits<double>::quiet_NaN();  // N/m, on the base, compression positive
  // The base's eccentricity e (m, outwards positive), and the wall's stability: the ratio of the base's
  // half-width to |e| (> 1 while the resultant stays inside the base: the rigid wall stands), and
  // Heyman's geometric factor, b_w over the thickness at which the base's resultant would reach the
  // outer toe (the same wall and reaction, another b_w; NaN when no thickness does).
  double base_eccentricity = std::numeric_limits<double>::quiet_NaN();
  double stability_ratio = std::numeric_limits<double>::quiet_NaN();
  double geometric_factor = std::numeric_limits<double>::quiet_NaN();
};

// The resultant down the scene's left (right = false) or right wall at `beds` + 1 equally spaced beds,
// the highest to the base (beds >= 1). Throws std::invalid_argument for a scene without that wall.
WallResultant wall_resultant(const Scene& scene, const Reactions& reactions, bool right, int beds);

}  // namespace ogive
