// Limit analysis of the no-tension masonry arch (Heyman): which thrusts an arch of rigid voussoirs can
// carry, how thin it could be, and which load makes it collapse, through which hinges.
//
// The model: rigid voussoirs, joints that resist no tension, infinite compressive strength unless one is
// given (LimitOptions::compressive_strength: the joints then crush), no sliding unless a friction
// coefficient is given. The whole arch, springing to springing, is cut into voussoirs
// by joints; each joint is a straight segment from the intrados to the extrados. An arch is admissible
// (can stand) when some thrust line in equilibrium with the loads crosses every joint between its
// intrados and extrados points (the static or safe theorem). With vertical loads only, the thrust line
// is fixed by three unknowns (the horizontal thrust H, the left support's vertical reaction and its
// moment) and, under a live load, its multiplier; every joint condition is linear in them, so every
// question below is a linear program (src/limit/limit_lp.cpp, the only file with the LP library). With
// a finite compressive strength each joint's condition is convex instead, and each question is solved
// exactly by tangent cuts added to the same linear program.
//
// The scene's loads (Scene::loads), in two groups:
//   dead (factor 1): the self-weight (density; 0 allowed with another load) and the fills, q(x) =
//        rho_f g max(0, h_f - y_e(x)) per horizontal length over the span 0 <= x <= L;
//   live (the collapse load factor multiplies all of them together): the point loads and the live loads.
// Each voussoir carries the loads over its own stretch of the span, lumped as one force and its moment
// (so at their horizontal centroid): with WeightModel::voussoir the stretch between its joints' extrados
// points and y_e the true extrados, with WeightModel::axis the stretch between its joints' axis points
// and y_e = y + t / (2 cos theta) above the axis point (the elastic model's convention). A point load at
// x = a L acts at x on the voussoir whose stretch holds x (the first of two at a shared end).
//
// Supports and hinges: rigid voussoirs ignore the supports' movements and the material's stiffness (a
// spreading support brings the arch to H_min). A pinned springing and the scene's crown hinge are pins:
// the thrust line passes through the axis point of that joint (an equality constraint in the LP: the
// resultant's moment about the point vanishes), and the pin turns either way in a mechanism. A clamped
// springing is the bed of the arch, where the thrust line may cross anywhere between the faces.
//
// Units: SI (m, N per metre of vault width, N m per metre). Positions are global: x from the left
// springing towards the right, y up from the springing line.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ogive/model/scene.hpp"

namespace ogive {

// Joint orientation. The springing joints (the beds on the supports) are always normal to the axis;
// this chooses the interior joints. At a pointed crown (a kink of the axis) the joints normal to the two
// halves' axes meet inside the section, and a line that does not cut the arch in two is not a joint:
// the crown joint is always vertical through the crown (Curve::crown; for a smooth crown that is also
// the normal one), and on each side the radial joints are spaced over the axis only up to the point
// whose normal meets the intrados below the crown, that point's joint (through the intrados' crown point)
// included.
enum class JointOrientation {
  radial,    // normal to the axis (default)
  vertical,  // vertical lines through equally spaced points of the intrados
};

// Where each voussoir's weight acts, and where the other loads meet the ring (see the top of the file).
enum class WeightModel {
  voussoir,  // the true ring: the area between intrados, extrados and the two joints, at its centroid;
             // the other loads on the extrados
  axis,      // Heyman's approximation, the elastic model's convention: rho g t per length of axis,
             // at the centroid of the voussoir's piece of axis; the other loads on the axis
};

// How the joints slide (LimitOptions::friction > 0). Coulomb's cone |T| <= friction N bounds the joint
// forces of every admissible state either way; the models differ in the sliding mechanism's flow rule.
enum class FrictionModel {
  // Associative (normality): a sliding joint also opens (dilatancy tan phi = friction). Every number is
  // the largest over the states inside the cones: the collapse load factor and a_c are upper bounds of
  // the non-associative ones (every real collapse state is inside the cones), exact where the collapse
  // mechanism only hinges.
  associative,
  // Non-associative (masonry: sliding without dilatancy), the iterative method of Gilbert, Casapulla &
  // Ahmed (2006): the load factor and a_c are those of a state whose sliding rows |T_j| <= friction N_j
  // hold each N_j fixed at the previous iterate's normal force, re-solved until the normal forces
  // converge; the converged state is inside every cone and has a mechanism that slides without opening.
  // No theorem makes it a bound; it is at most the associative factor. A run that does not converge
  // gives no load factor and says so (LimitStatus::not_converged).
  non_associative,
};

const char* to_string(JointOrientation j);
const char* to_string(WeightModel w);
const char* to_string(FrictionModel f);

// The default number of joints of the starting ring (analyse_limit then refines it; see there).
inline constexpr int kDefaultJointsCount = 201;
inline constexpr int kMinJointsCount = 5;
inline constexpr int kMaxJointsCount = 20001;

struct LimitOptions {
  JointOrientation joints = JointOrientation::radial;
  WeightModel weight = WeightModel::voussoir;
  // Joints springing to springing of the starting ring, both springings included, equally spaced;
  // odd, so that one joint is at the crown (4 voussoirs at least, the fewest that can form a mechanism
  // with a crown joint). make_ring(scene, ...) and analyse_limit add joints to these (see there).
  int joints_count = kDefaultJointsCount;
  // Coulomb friction coefficient of the joints; 0: no sliding check (sliding is excluded). When > 0,
  // every joint must also satisfy |shear| <= friction * normal force.
  double friction = 0;
  // The sliding's flow rule (with friction > 0): the collapse load factor and a_c by it. The thrust range
  // and t_min are those of the states inside the cones whichever it is (FrictionModel, analyse_limit).
  FrictionModel friction_model = FrictionModel::non_associative;
  // The masonry's compressive strength f_c (Pa, > 0; infinity: Heyman's infinite strength). Finite, the
  // joints crush: rigid-perfectly-plastic in compression, no tension, a joint of length h with normal
  // force N (N/m, compression positive) bears it on a stress block N / f_c deep at the face, so its
  // resultant stays at least N / (2 f_c) inside each face: |M| <= N (h/2 - N/(2 f_c)) about the joint's
  // middle, and N <= f_c h. Every number of the result honours it (the thrust range, t_min, the collapse
  // load factor and a_c); a hinge then sits N / (2 f_c) inside its face (thrust_state).
  double compressive_strength = std::numeric_limits<double>::infinity();
  // Also the horizontal acceleration of collapse a_c (LimitResult::horizontal_state): one program per
  // round on rings of its own (LimitResult::horizontal_ring), refined next to its hinges alone.
  bool horizontal_load_factor = false;
  // Ceres-style check: false with the reason in *why (naming the field) when an option is unusable.
  bool is_valid(std::string* why) const;
};

// ---------------------------------------------------------------------------------------------
// The ring of voussoirs.

struct Joint {
  Eigen::Vector2d intrados;  // m
  Eigen::Vector2d extrados;  // m
  Eigen::Vector2d axis;      // m, where the joint crosses the axis (a pin's point)
  double s = 0;              // m, arc length of that point along the whole arch
};

// Vertical forces on one voussoir by their resultant: the total, downward, and its moment about the
// origin (sum of x F; the resultant acts at x = moment / force), and the sum of y F over the same forces
// (the moment, clockwise, of the horizontal forces a F that a horizontal acceleration a adds at the same
// points: Ring::acceleration).
struct VerticalLoad {
  double force = 0;          // N per metre of width, downward
  double moment = 0;         // N m per metre of width
  double height_moment = 0;  // N m per metre of width: sum of y F
  VerticalLoad& operator+=(const VerticalLoad& o) {
    force += o.force;
    moment += o.moment;
    height_moment += o.height_moment;
    return *this;
  }
};

struct Voussoir {
  double weight = 0;         // N per metre of width, downward: the self-weight
  Eigen::Vector2d centroid;  // m, where the self-weight acts
  VerticalLoad fill;         // the fills' share (dead)
  VerticalLoad live;         // the point and live loads' share at load factor 1
  // Every dead load: the self-weight at its centroid and the fill (the masses a horizontal acceleration
  // pushes).
  VerticalLoad dead() const {
    return {weight + fill.force, weight * centroid.x() + fill.moment, weight * centroid.y() + fill.height_moment};
  }
};

// joints.size() == voussoirs.size() + 1; voussoir k lies between joints k and k + 1; as many voussoirs
// of the arch on each side of the crown, and joints[crown_joint()] is the vertical crown joint, at
// Curve::crown.
// A ring of a half curve (or of a symmetric whole one) is symmetric about mid-span.
struct Ring {
  std::vector<Joint> joints;
  std::vector<Voussoir> voussoirs;
  std::vector<int> pins;  // joints whose thrust passes through their axis point, ascending
  double span = 0;        // L, m
  // a (Scene::horizontal_acceleration): each voussoir's dead load also pushes a times itself towards +x,
  // at the same points (the self-weight at the centroid of its weight model, the fill where it bears).
  double acceleration = 0;
  // Where each side's interior joints lie, ascending in (0, 1]: joint i of a side (1 .. m-1, from its
  // springing; the same on both sides) has its intrados at fraction joint_fractions[i - 1] of the
  // intrados' arc length from the springing to the crown's vertical. Fraction 1, at a pointed crown with
  // radial joints only: the radial joint through the intrados' crown point, beside the vertical crown
  // joint (the two meet there, and the wedge between them is a voussoir).
  std::vector<double> joint_fractions;
  // Walls (Scene::left_wall, right_wall): the ring is then the chain from the left wall's base up the
  // wall, over the arch and down the right wall to its base. Its first left_wall_joints joints are the
  // left wall's horizontal beds (base first), its last right_wall_joints the right wall's (base last);
  // each bed's intrados point is on the wall's inner face, its extrados point on the outer one, and its
  // s lies outside the arch's [0, whole length] (below 0 on the left wall, beyond it on the right one),
  // ascending along the chain. The voussoirs between them are the wall's blocks. 0 and 0 without walls.
  int left_wall_joints = 0, right_wall_joints = 0;
  int left_springing() const { return left_wall_joints; }
  int right_springing() const { return static_cast<int>(joints.size()) - 1 - right_wall_joints; }
  int crown_joint() const { return (left_springing() + right_springing()) / 2; }
  double total_weight() const;  // N/m, the self-weight
  double total_fill() const;    // N/m
  double total_dead() const;    // N/m, self-weight plus fill
  double total_live() const;    // N/m, at load factor 1
  // Whether a load factor means anything: some voussoir carries a live load.
  bool has_live_load() const;
};

// The ring of `curve` (a half, mirrored, or a whole curve springing to springing) with thickness t (m)
// and unit weight gamma = rho g (N/m^3, >= 0) under its self-weight alone (no pins). Throws
// std::invalid_argument naming the field for a thickness that does not fit the curve, invalid options,
// or a whole curve whose crown is a kink that is not symmetric (the vertical crown joint would not
// cut the arch in two). joints.size() == options.joints_count, plus two at a pointed crown with radial
// joints (the radial joints through the intrados' crown point: Ring::joint_fractions).
Ring make_ring(const Curve& curve, double thickness, double unit_weight, const LimitOptions& options);

// The ring of the scene (its curve, thickness, density and gravity) with every load of Scene::loads
// and the pins of its pinned springings and crown hinge. Its joints: options.joints_count equally
// spaced, and on both sides those through each point load's line of action, each live load's ends and
// where each fill's level meets the extrados (for radial joints one each through the intrados, the
// axis and the extrados point there; for vertical joints the vertical line), so that a hinge can form
// under a load as it would in the continuum. joints.size() >= options.joints_count.
Ring make_ring(const Scene& scene, const LimitOptions& options);

// ---------------------------------------------------------------------------------------------
// Results.

// Where a hinge turns: a face (the joint opens on the other one; it turns one way only), or the axis
// point of a pinned joint (it turns either way).
enum class Face { intrados, extrados, axis };
const char* to_string(Face f);

struct Hinge {
  int joint = 0;  // index into Ring::joints
  Face face = Face::intrados;
  // m, the hinge: the joint's intrados, extrados or axis point; with a finite compressive strength a
  // face hinge's is the stress block's centre, N / (2 f_c) inside the face (thrust_state).
  Eigen::Vector2d point;
};

// One thrust line in equilibrium: the reactions and, for each joint, where the resultant crosses it.
struct ThrustState {
  double H = std::numeric_limits<double>::quiet_NaN();            // N/m, inward push of each support
  double V_left = std::numeric_limits<double>::quiet_NaN();       // N/m, upward reaction, left support (wall's base)
  double V_right = std::numeric_limits<double>::quiet_NaN();      // N/m, upward reaction, right support (wall's base)
  double load_factor = std::numeric_limits<double>::quiet_NaN();  // multiplier on the live load
  std::vector<Eigen::Vector2d> crossing;  // m, one per joint: the resultant's point on the joint
  std::vector<Eigen::Vector2d> force;     // N/m, one per joint: the part left of it on the part right of it
  std::vector<Hinge> hinges;              // by joint: the pins, and the joints where the crossing is at a
                                          // face (to 1e-9 of the joint); of a collapse state in
                                          // LimitResult, its mechanism's (see there). A joint that
                                          // carries no force is none (forceless).
  // Some joint carries no force (|F| below 1e-9 of the load): voussoirs without weight or load between
  // loaded ones, with H = 0. Its crossing is undefined (where the round-off puts it).
  bool forceless = false;
  bool found() const { return !crossing.empty(); }
};

enum class LimitStatus {
  success,       // every number of the result was found
  inadmissible,  // no thrust line fits inside the arch under the given loads (t < t_min): H_min, H_max
                 // and their states are absent; t_min (the thickness at which it would stand) is given
                 // when one exists below the curve's largest thickness
  lp_failure,    // the LP library stopped without an answer (the message says which problem), or the
                 // static multiplier of a collapse (load factor, a_c) and the virtual work of its
                 // mechanism differ by more than kStaticKinematicTolerance (the answer is not trusted)
  not_converged, // the numbers still moved by more than kLimitTolerance at the last refinement of the
                 // joints: the result of the finest ring is given, with the last change in the message
};

// The relative change between two refinements of the joints below which every number of a result
// (H_min, H_max, t_min, the load factors) is taken as converged.
inline constexpr double kLimitTolerance = 1e-4;
// The refinements of the joints analyse_limit makes at the most.
inline constexpr int kMaxLimitRefinements = 10;
// The relative difference between the static multiplier of a collapse (load factor, a_c) and the
// kinematic one of its hinges beyond which the result is an lp_failure: the two are one number computed
// twice, equal to round-off when the program's answer is right.
inline constexpr double kStaticKinematicTolerance = 1e-6;
// The most hinges the mechanism check takes: beyond, the four-hinge subsets are too many to try.
inline constexpr std::size_t kMaxMechanismHinges = 12;
const char* to_string(LimitStatus s);

struct LimitResult {
  LimitStatus status = LimitStatus::lp_failure;
  std::string message;  // empty on success
  // V: half the total vertical load (dead plus live at factor 1): each springing's share when the
  // scene is symmetric, the scale of H_min / V and H_max / V otherwise (each state has V_left, V_right).
  double V = std::numeric_limits<double>::quiet_NaN();  // the arch's loads only (the walls' not counted)
  ThrustState min_state;  // the smallest H (the arch pushes least: the state a spreading support reaches)
  ThrustState max_state;  // the largest H; absent (with a message) when H is unbounded: a flat, thick
                          // arch holds a straight thrust line of any H (infinite compressive strength)
  double thickness_min = std::numeric_limits<double>::quiet_NaN();  // t_min, m, same axis and loads; NaN
                                                                   // (with a message) below 1e-6 of the span;
                                                                   // on the scene's walls when it has any (up
                                                                   // to the thickness whose springing joint
                                                                   // is as wide as the thinnest wall)
  // With walls: the least wall thickness b_min (m) on which the arch as it is stands, every wall of the
  // scene given that thickness (their heights, densities and top loads kept): the root of the
  // feasibility margin in b_w, as t_min's. When the walls stand at the least thickness that carries the
  // springing joints (their horizontal width) that width, with a message; NaN without walls, when the
  // arch itself cannot stand, or when no wall up to 1000 spans thick holds it (with a message).
  double wall_thickness_min = std::numeric_limits<double>::quiet_NaN();
  // With a live load: the largest multiplier of the live load that the arch carries (dead loads
  // times 1), its state with the collapse mechanism's hinges, and the kinematic multiplier of the same
  // hinges by virtual work (mechanism_load_factor); absent without a live load, or when the arch cannot
  // carry its dead loads alone. The hinges (here and in horizontal_state) are the mechanism's: of the
  // joints the thrust line touches (a run of them where it runs along a face), the four (pins included)
  // of the least admissible one-degree mechanism; every touched joint when none is one (a joint slides,
  // with friction) and the message says so.
  ThrustState collapse_state;
  double load_factor_mechanism = std::numeric_limits<double>::quiet_NaN();
  // The horizontal acceleration a_c (towards +x, a fraction of g) that turns the arch into a mechanism,
  // with every vertical load at factor 1 and the scene's own acceleration ignored: its state (load_factor
  // = a_c; H the left springing's), and the kinematic a_c of the same hinges
  // (mechanism_horizontal_load_factor). Absent when the arch cannot carry its vertical loads, or no
  // finite acceleration makes a mechanism. Its joints are horizontal_ring's.
  ThrustState horizontal_state;
  double horizontal_load_factor_mechanism = std::numeric_limits<double>::quiet_NaN();
  int lp_solves = 0;  // linear programs solved for this result
  // The ring of the states above but horizontal_state (their joint indices and crossings):
  // make_ring(scene, options)'s, refined next to the hinges. t_min's rings (other thicknesses) are not
  // kept.
  Ring ring;
  // horizontal_state's ring (LimitOptions::horizontal_load_factor): make_ring(scene, options)'s refined
  // next to a_c's hinges alone, so that asking for a_c changes no other number. Empty otherwise.
  Ring horizontal_ring;

  double H_min() const { return min_state.H; }
  double H_max() const { return max_state.H; }
  double load_factor() const { return collapse_state.load_factor; }
  double horizontal_load_factor() const { return horizontal_state.load_factor; }
};

// The admissible thrust range, the minimum thickness and, with a live load, the collapse load factor
// of `scene` (its curve of either extent, thickness, density, gravity, loads, pinned springings and
// crown hinge; the elastic constants and the supports' movements do not enter: rigid voussoirs).
// Throws std::invalid_argument for an invalid scene or options, or a scene that loads the ring with
// nothing (every load zero over the ring).
//
// Converged in the joints: the analysis runs on make_ring's ring, then again with the voussoirs next to
// every hinge (of the minimum, maximum and collapse states, and of the thinnest arch) halved, two on
// each side, until in two refinements in a row no number of the result (H_min, H_max, t_min,
// load_factor, load_factor_mechanism) moved by more than kLimitTolerance relative (status
// not_converged after kMaxLimitRefinements). a_c and its kinematic value converge in the same way on
// rings of their own, refined next to a_c's hinges (a change relative to 0.01 g at least, since a_c
// vanishes at t_min).
// The result is that of the last, finest ring; lp_solves counts every round's programs.
//
// t_min (same axis, stereotomy and loads; the fill follows the extrados) is found by a bracketing
// root-finder (Illinois) on the LP's feasibility margin: the largest mu such that each joint's
// resultant stays at least mu |joint| W away (in moment, W the total load) from both faces (with a finite
// compressive strength, from the stress blocks N / (2 f_c) inside them); mu >= 0 exactly when the arch
// is admissible. Relative tolerance 1e-10 on t.
LimitResult analyse_limit(const Scene& scene, const LimitOptions& options);

// The state of a thrust line with reactions (H, V_left) and left-support moment M_left about the origin
// (N m/m), under the ring's dead loads and `load_factor` times its live load (ignored without one):
// where it crosses each joint. The hinges are the ring's pins and the joints crossed at a face to
// `hinge_tolerance` of the joint's length, the hinge at the face's point. With a finite
// `compressive_strength` f_c (Pa; LimitOptions::compressive_strength) a hinge is where the crossing lies
// N / (2 f_c) inside a face (N the joint's normal force; to the same tolerance), at the crossing: the
// centre of the stress block the joint turns on.
ThrustState thrust_state(const Ring& ring, double H, double V_left, double M_left, double load_factor,
                         double hinge_tolerance = 1e-9,
                         double compressive_strength = std::numeric_limits<double>::infinity());

// The kinematic (upper-bound) multiplier of the ring's live load for the mechanism whose hinges are
// given: the voussoirs between consecutive hinges rotate as rigid bodies, those before the first and
// after the last stay on their supports; the virtual work of the dead loads plus lambda times the live
// load vanishes (each voussoir's loads by their resultant). NaN unless the hinges make a mechanism of one
// degree of freedom in which the live load does work and every face hinge opens on the face opposite to
// its own (kinematically admissible; a pin turns either way). Given more than four hinges (a degenerate
// static optimum), the least multiplier of the admissible mechanisms of four of them, a run of hinges
// at consecutive joints on one face represented by its first, middle and last; NaN when more than
// kMaxMechanismHinges remain.
double mechanism_load_factor(const Ring& ring, const std::vector<Hinge>& hinges);
// The same for the horizontal acceleration of the dead loads (towards +x, its work the horizontal force
// a F times the horizontal velocity at each voussoir's load), every vertical load at factor 1 and
// Ring::acceleration ignored: the kinematic a_c of the mechanism. NaN as above, or without dead loads.
double mechanism_horizontal_load_factor(const Ring& ring, const std::vector<Hinge>& hinges);

}  // namespace ogive
