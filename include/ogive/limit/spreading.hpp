// The arch of rigid voussoirs on spreading supports, with large displacements: the mechanism part of the
// path from the limit analysis' minimum-thrust state (d = 0) to collapse.
//
// Kinematics: the three hinges of the mechanism (the minimum-thrust state's hinge nearest the crown and
// the nearest one on each side of it) cut the ring into two rotating blocks; the voussoirs outside the
// outer hinges move with their support (a rigid translation). The springings move apart horizontally,
// the left one by -left_share * d, the right one by +right_share * d. The crown hinge's new position is
// the intersection of the two circles about the moved outer hinges (finite rotations, exact, not
// linearised); every joint point, centroid and load's point of action moves with its block, and every
// load stays vertical.
//
// Statics: at each step the deformed ring, with the three hinges as pins (an opened joint carries its
// force through its hinge point only), goes to the limit analysis' minimum-thrust program.
//
// Collapse, at the first of (bisected to kSpreadTolerance of the span):
//   inadmissible - no thrust line through the hinges fits inside the deformed voussoirs (the program is
//                  infeasible);
//   snap_through - the three hinges are collinear (the circles no longer meet), or a hinge would close
//                  (its relative rotation reverses: the blocks would interpenetrate).
//
// Units: SI (m, N per metre of width). Positions as in limit.hpp.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ogive/limit/limit.hpp"

namespace ogive {

inline constexpr double kSpreadTolerance = 1e-6;  // collapse spread located to this fraction of L

struct SpreadOptions {
  double left_share = 1;   // the left springing moves by -left_share * d (m per m of d), >= 0
  double right_share = 1;  // the right springing moves by +right_share * d, >= 0; one of them > 0
  int steps = 200;         // steps along the path before collapse is bracketed, >= 1
  bool is_valid(std::string* why) const;
};

enum class SpreadCollapse { inadmissible, snap_through };
const char* to_string(SpreadCollapse c);

// One configuration of the mechanism.
struct SpreadStep {
  double d = 0;             // m, the movement parameter: the span grew by (left_share + right_share) d
  double H = std::numeric_limits<double>::quiet_NaN();  // N/m, the program's (static) thrust
  double H_work = std::numeric_limits<double>::quiet_NaN();  // N/m, the mechanism's by virtual work
  double V_left = std::numeric_limits<double>::quiet_NaN(), V_right = std::numeric_limits<double>::quiet_NaN();
  double crown_drop = 0;    // m, the crown hinge's drop
  double potential = 0;     // N m/m, sum of every load times its height
  std::vector<Eigen::Vector2d> hinges;  // m, the three hinge points, left to right
};

enum class SpreadStatus {
  success,        // a path to collapse: every step's H is the program's and agrees with its virtual work
  inadmissible,   // no thrust line fits the arch at d = 0 (t < t_min): no path
  no_mechanism,   // the minimum-thrust state has no hinge on each side of a crown hinge, or its three
                  // hinges do not open under the movement (snap-through at once: a pointed arch's
                  // minimum-thrust state turns about two hinges beside its crown, which three do not
                  // describe); path holds the state at d = 0 in the second case
  lp_failure,     // the LP library stopped without an answer
};
const char* to_string(SpreadStatus s);

struct SpreadResult {
  SpreadStatus status = SpreadStatus::lp_failure;
  std::string message;
  SpreadCollapse collapse = SpreadCollapse::inadmissible;
  double d_max = std::numeric_limits<double>::quiet_NaN();  // m, the movement parameter at collapse
  std::vector<int> hinge_joints;                            // the mechanism's three joints
  std::vector<SpreadStep> path;  // d = 0, the steps, and the last admissible state at d_max
  Ring ring;                     // the ring at d = 0
};

// The mechanism path of `scene` (as analyse_limit takes it) under the movement of `spread`. Throws
// std::invalid_argument for invalid options or scene.
SpreadResult analyse_spreading(const Scene& scene, const LimitOptions& limit, const SpreadOptions& spread);

}  // namespace ogive
