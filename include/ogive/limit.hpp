// Limit analysis of the no-tension masonry arch (Heyman): which thrusts an arch of rigid voussoirs can
// carry, how thin it could be, and which load makes it collapse, through which hinges.
//
// The model: rigid voussoirs, joints that resist no tension, infinite compressive strength, no sliding
// unless a friction coefficient is given. The whole arch, springing to springing, is cut into voussoirs
// by joints; each joint is a straight segment from the intrados to the extrados. An arch is admissible
// (can stand) when some thrust line in equilibrium with the loads crosses every joint between its
// intrados and extrados points (the static or safe theorem). With vertical loads only, the thrust line
// is fixed by three unknowns (the horizontal thrust H, the left support's vertical reaction and its
// moment) and, under a live load, its multiplier; every joint condition is linear in them, so every
// question below is a linear program (src/limit/limit_lp.cpp, the only file with the LP library).
//
// Units: SI (m, N per metre of vault width, N m per metre). Positions are global: x from the left
// springing towards the right, y up from the springing line.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ogive/scene.hpp"

namespace ogive {

// Joint orientation. The springing joints (the beds on the supports) are always normal to the axis;
// this chooses the interior joints. At a pointed crown (a kink of the axis) the joints normal to the two
// halves' axes meet inside the section, and a line that does not cut the arch in two is not a joint:
// the crown joint is always vertical (for a smooth crown that is also the normal one), and the radial
// joints are spaced over the axis only up to the point whose normal meets the intrados at mid-span.
enum class JointOrientation {
  radial,    // normal to the axis (default)
  vertical,  // vertical lines through equally spaced points of the intrados
};

// Where each voussoir's weight acts.
enum class WeightModel {
  voussoir,  // the true ring: the area between intrados, extrados and the two joints, at its centroid
  axis,      // Heyman's approximation, the elastic model's convention: rho g t per length of axis,
             // at the centroid of the voussoir's piece of axis
};

const char* to_string(JointOrientation j);
const char* to_string(WeightModel w);

// The collapse load: one vertical point load on the extrados, whose multiplier at collapse is the load
// factor. A small struct on purpose: issue 11's general loads (several point loads, distributed
// loads, fill) will replace it without changing the rest of the module.
struct CollapseLoad {
  double force = 0;       // P, N per metre of vault width, downward; 0: no live load
  double position = 0.5;  // a: the load acts at x = a L, in [0, 1], on the voussoir whose extrados holds x
  bool present() const { return force > 0; }
};

// The default number of joints: enough that every printed number of the semicircle and the pointed
// family (eps 0 .. 1.5, t/L 0.06 .. 0.2) is converged to 1e-4 (the convergence table of the README).
inline constexpr int kDefaultJointsCount = 401;
inline constexpr int kMinJointsCount = 5;
inline constexpr int kMaxJointsCount = 20001;

struct LimitOptions {
  JointOrientation joints = JointOrientation::radial;
  WeightModel weight = WeightModel::voussoir;
  // Joints springing to springing, both springings included; odd, so that one joint is at the crown
  // (4 voussoirs at least, the fewest that can form a mechanism with a crown joint).
  int joints_count = kDefaultJointsCount;
  // Coulomb friction coefficient of the joints; 0: no sliding check (sliding is excluded). When > 0,
  // every joint must also satisfy |shear| <= friction * normal force.
  double friction = 0;
  CollapseLoad point_load;
  // Ceres-style check: false with the reason in *why (naming the field) when an option is unusable.
  bool is_valid(std::string* why) const;
};

// ---------------------------------------------------------------------------------------------
// The ring of voussoirs.

struct Joint {
  Eigen::Vector2d intrados;  // m
  Eigen::Vector2d extrados;  // m
  double s = 0;              // m, arc length of the point where the joint crosses the axis (whole arch)
};

struct Voussoir {
  double weight = 0;         // N per metre of width, downward
  Eigen::Vector2d centroid;  // m, where the weight acts
};

// joints.size() == voussoirs.size() + 1; voussoir k lies between joints k and k + 1. The ring is
// symmetric about mid-span (the curve is), and joints[joints.size() / 2] is the vertical crown joint.
struct Ring {
  std::vector<Joint> joints;
  std::vector<Voussoir> voussoirs;
  double span = 0;  // L, m
  double total_weight() const;
};

// The voussoirs of `curve` (the left half of a symmetric arch) with thickness t (m) and unit weight
// gamma = rho g (N/m^3). Throws std::invalid_argument naming the field for a thickness that does not fit
// the curve or invalid options. joints.size() == options.joints_count.
Ring make_ring(const Curve& curve, double thickness, double unit_weight, const LimitOptions& options);

// ---------------------------------------------------------------------------------------------
// Results.

enum class Face { intrados, extrados };

struct Hinge {
  int joint = 0;  // index into Ring::joints
  Face face = Face::intrados;
  Eigen::Vector2d point;  // m, the hinge: the joint's intrados or extrados point
};

// One thrust line in equilibrium: the reactions and, for each joint, where the resultant crosses it.
struct ThrustState {
  double H = std::numeric_limits<double>::quiet_NaN();            // N/m, inward push of each support
  double V_left = std::numeric_limits<double>::quiet_NaN();       // N/m, upward reaction, left support
  double V_right = std::numeric_limits<double>::quiet_NaN();      // N/m, upward reaction, right support
  double load_factor = std::numeric_limits<double>::quiet_NaN();  // multiplier on the point load
  std::vector<Eigen::Vector2d> crossing;  // m, one per joint: the resultant's point on the joint
  std::vector<Hinge> hinges;              // joints where the crossing is at a face (to 1e-9 of the joint)
  bool found() const { return !crossing.empty(); }
};

enum class LimitStatus {
  success,       // every number of the result was found
  inadmissible,  // no thrust line fits inside the arch under the given loads (t < t_min): H_min, H_max
                 // and their states are absent; t_min (the thickness at which it would stand) is given
                 // when one exists below the curve's largest thickness
  lp_failure,    // the LP library stopped without an answer (the message says which problem)
};
const char* to_string(LimitStatus s);

struct LimitResult {
  LimitStatus status = LimitStatus::lp_failure;
  std::string message;  // empty on success
  // V: half the total vertical load (self-weight plus the point load): the springings' share when
  // the scene is symmetric.
  double V = std::numeric_limits<double>::quiet_NaN();
  ThrustState min_state;  // the smallest H (the arch pushes least: the state a spreading support reaches)
  ThrustState max_state;  // the largest H; absent (with a message) when H is unbounded: a flat, thick
                          // arch holds a straight thrust line of any H (infinite compressive strength)
  double thickness_min = std::numeric_limits<double>::quiet_NaN();  // t_min, m, same axis and loads
  // With a point load: the largest multiplier of the point load that the arch carries (self-weight
  // times 1), its state with the collapse mechanism's hinges, and the kinematic multiplier of the same
  // hinges by virtual work (mechanism_load_factor); absent without a point load, or when the arch cannot
  // carry its self-weight alone.
  ThrustState collapse_state;
  double load_factor_mechanism = std::numeric_limits<double>::quiet_NaN();
  int lp_solves = 0;  // linear programs solved for this result

  double H_min() const { return min_state.H; }
  double H_max() const { return max_state.H; }
  double load_factor() const { return collapse_state.load_factor; }
};

// The admissible thrust range, the minimum thickness and, with a point load, the collapse load factor
// of `scene` (its curve, thickness, density and gravity; the elastic fields and the support displacement
// do not enter: rigid voussoirs). Throws std::invalid_argument for an invalid scene or options.
//
// t_min is found by a bracketing root-finder (Illinois) on the LP's feasibility margin: the largest mu
// such that each joint's resultant stays at least mu |joint| W away (in moment, W the self-weight) from
// both faces; mu >= 0 exactly when the arch is admissible. Relative tolerance 1e-10 on t.
LimitResult analyse_limit(const Scene& scene, const LimitOptions& options);

// The state of a thrust line with reactions (H, V_left) and left-support moment M_left about the origin
// (N m/m), under the ring's self-weight and `load_factor` times the point load: where it crosses each
// joint. The hinges are joints crossed at a face to `hinge_tolerance` of the joint's length.
ThrustState thrust_state(const Ring& ring, const CollapseLoad& load, double H, double V_left, double M_left,
                         double load_factor, double hinge_tolerance = 1e-9);

// The kinematic (upper-bound) multiplier of the point load for the mechanism whose hinges are given:
// the voussoirs between consecutive hinges rotate as rigid bodies, those before the first and after the
// last stay on their supports; virtual work of self-weight plus lambda P vanishes. NaN unless the hinges
// make a mechanism of one degree of freedom in which the point load does work and every hinge opens on
// the face opposite to its own (kinematically admissible). Given more than four hinges (a degenerate
// static optimum), the least multiplier of the admissible mechanisms of four of them.
double mechanism_load_factor(const Ring& ring, const CollapseLoad& load, const std::vector<Hinge>& hinges);

}  // namespace ogive
