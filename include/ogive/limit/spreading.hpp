// The arch of rigid voussoirs on spreading supports, with large displacements: the mechanism part of the
// path from the limit analysis' minimum-thrust state at d = 0 (the least-work state, below, with
// settling springings) to collapse.
//
// The movement: the left springing moves by (-left_share, -left_settlement_share) d, the right one by
// (+right_share, -right_settlement_share) d (x right, y up: the settlements downwards positive), d
// growing from 0 in increments of increment_ratio * L. The span grows: left_share + right_share > 0.
//
// The state at each d: the voussoirs where the current hinges put them, the limit analysis' program on
// the voussoirs there, every joint free (no hinge is imposed), for the state that does the least work
// on the movement: the smallest H (left_share + right_share) + V_left (left_settlement_share -
// right_settlement_share) (V_left the left springing's vertical reaction; the smallest H when neither
// settles; where the arch leaves room, a settling springing sheds load to the other). The joints where
// its thrust line touches a face (or crosses a pin) are its contacts; a state is settled when its
// contacts are its hinges.
//
// Rolling hinges: a joint that is not a current hinge is closed (its faces together, as at d = 0); an
// opened no-tension joint touches only at its hinge's edge, so a thrust line must cross it there. The
// pieces are placed from the ring at d = 0 with the current hinges only: the hinges, ascending along
// the arch, cut it into blocks; the voussoirs before the first hinge move with the left springing,
// those after the last with the right one; the blocks turn about the hinges by finite relative
// rotations (exact rigid motions, not linearised) that close the chain on the moved right springing.
// Three hinges fix the rotations; with more (a pointed arch's minimum-thrust state has two beside its
// crown, a symmetric pair) they are the closing ones nearest the last state's carried on by its
// mechanism's rates, the least squared rates (for a symmetric arch under a symmetric movement, the
// symmetric motion). From one d to the next the hinges are carried on; where the program's contacts on
// that placement are other joints, the hinges roll to them - a hinge that moves to another joint of
// its face takes its relative rotation along, and its old joint closes; a new hinge starts from no
// rotation - and the placement and the program are made again, until the contacts are the hinges.
// A hinge turns one way only (its joint opens on the face opposite its contact; a pin either way): a
// contact whose mechanism's rate would close it is no hinge, and a state whose rotations would close a
// hinge is no state of the path.
//
// New hinges: a contact further than 0.05 L along its face from every hinge on it has not rolled there
// (the thrust line touches the face at a second place, the pointed crown's intrados, say): it is a new
// hinge, from no rotation, and a hinge left with no contact within two joints of it stays open, its
// joint still turned. So does a hinge the program's contacts go back and forth from (the thrust line
// grazing the face between two joints, or either edge of a load). Four hinges leave the chain one free
// mode at each d: the blocks stand where the loads do no work on it, the thrust line through all four
// (found along the mode by the secant method), a balance that must be stable (the loads' work turning
// against the mode beyond it); a hinge whose rotation goes back through zero closes, and three remain.
// A new hinge that no stable balance of four holds (or that would make five) is a snap: the loads move
// the blocks on at fixed springings, and the path ends there (snap_through), unless where the blocks
// would come to rest no thrust line fits either (thrust_leaves_arch).
//
// A joint is taken midway between its two faces: exact at a closed joint (the faces coincide) and at
// a settled hinge, whose contact point both faces share and through which the thrust line passes.
//
// The joints: the limit analysis' ring at d = 0 (refined next to its hinges), then refined again next to
// the hinges at collapse, halving the two voussoirs on each side of each, and the path followed again,
// until those voussoirs are no longer than kSpreadJointSpacing L and the capacity moved by at most
// kSpreadCapacityTolerance of itself at the last refinement: the hinges at collapse sit where the
// thrust line grazes a face, and a joint nearer that point lets the path go on. The hinges refined
// next to: those at collapse on a face, not on a springing's joint. A refinement that changes the
// state at d = 0 (a pointed arch's thrust line grazing its extrados over several new joints) is not
// taken: the last ring's path stands (the limit analysis' ring when it is the first).
//
// Crushing (LimitOptions::compressive_strength f_c finite): the program at each movement is the crushing
// one (each joint's resultant N / (2 f_c) clear of its faces). Where a hinge's resultant crosses and
// where its blocks turn are two points. For the joint's condition Phi = |M| - N h/2 + N^2 / (2 f_c) <= 0
// the associated flow turns the blocks relatively about the point N / f_c inside the face (the stress
// block's inner edge, the neutral axis: the block's material crushes, the faces interpenetrating by the
// rotation times the block's depth, and the rest of the joint opens), while the resultant crosses at the
// block's centre, N / (2 f_c) inside. Turned about the centre, half the block would open and carry no
// stress. So the blocks turn about the inner edges: the placement (the chain's closure too) turns each
// hinge's blocks about its inner edge, taken to the ring at d = 0 at the same fraction of its joint, and
// the virtual work of the mechanism on those points balances the loads, the supports' H and the blocks'
// dissipation, N^2 / (2 f_c) per unit of relative rotation (SpreadStep::H_work; equal to the program's H,
// as the work of the joint's stress block on a rotation about its inner edge is that dissipation). The
// edge moves with N: each state is placed about its own edges (again until they agree to 1e-12 L), so
// the state at d is one, whatever the increments (a finite rotation about the current edge: the crushing
// depth at the face is the rotation times the current N / f_c, not its history). The program's thrust
// line touches the stress blocks' offset curve, which it grazes over a stretch of the face: its contacts
// can jump further along a face than two refined joints at once, so a contact within 0.05 L of a hinge
// on its face is that hinge rolled, whatever the joints between, and a state whose thrust line passes
// through its hinges and touches the face beside one as well (the moment the contact moves on) is settled
// on its hinges. Near collapse the contact jumps along the graze to a joint where no hinge holds a line,
// and the path ends there (thrust_leaves_arch); a hinge rolled instead to the nearest joint whose
// three-hinge line still fits would go 0.5 % to 1.8 % further on the semicircle at 2 to 0.5 MPa
// (benchmarks/crushing/spread_check.py), through states whose least-thrust line touches elsewhere: the
// capacity given is the lower. A hinge stays where it formed at d = 0, held by the corner its opened
// joint makes, until the contact moves past it: the capacity follows where it formed, so the refinement
// halves the voussoirs next to the hinges at d = 0 as well as those at collapse, and a finer ring whose
// hinges at d = 0 only slid along their faces (by at most 0.05 L) goes on refining from there (that is
// the limit analysis' minimum-thrust state resolved further). On walls the refinement does the same,
// with or without crushing: the state at d = 0 overturns the walls least, and its hinges slide along
// their faces as the ring is refined (the semicircle of t/L 0.1 on walls 10 m high with its weight on
// the axis, on walls 2 to 5 m thick: without it, capacities 1.1e-3 to 2.2e-3 apart, not_converged).
//
// Friction (LimitOptions::friction > 0): the program is the one without friction, and every state's
// resultant at every joint is checked against Coulomb's cone, |shear| <= friction * normal force. The
// state of a mechanism is its hinges' own (three fix it), and a Coulomb joint inside its cone does not
// slip (friction without dilatancy: the non-associative law), so while every joint keeps inside the
// cone the blocks can only turn about their hinges, as without friction: the path is the frictionless
// one, to the byte, and exact. The first state whose resultant leaves the cone at a joint ends the path:
// that joint slides. ogive follows no sliding mechanism: the capacity is the movement to the first slip,
// never more than the arch's (a slip at a springing's bed is the wall's movement carried on by the
// loads, which the friction no longer balances where the thrust rises with the movement). At d = 0 the friction-admissible state of least thrust is limit's (LimitResult::min_state
// with the friction); when the frictionless minimum-thrust state already leaves the cone, the path is
// that one state, collapse `sliding` at d = 0.
//
// Walls (Scene::left_wall, right_wall): the springings stand on walls that lean outwards, each turning
// as a rigid body about its base's outer toe T (the left wall counter-clockwise, the right one
// clockwise), by left_share d and right_share d: d is then the walls' rotation (rad), and no springing
// settles. A wall's rotation carries the springing joint on its top by an exact rigid motion x -> T +
// R(theta) (x - T) (large displacements: a point h above the toe and b inside it moves out by
// h sin theta + b (1 - cos theta) and up by b sin theta - h (1 - cos theta), and the joint turns by
// theta); the voussoirs before the first hinge turn with the left wall, those after the last with the
// right one, and the chain closes on the two springings' rigid motions. The least-work state: the
// arch's reactions do work on the springings' rigid motions, the left one's (H, V_left, through the
// point p where the thrust line crosses the springing joint) at the rate (H, V_left) . w(p) with
// w(x) = omega perp(x - T) the wall's velocity field, omega its rotation rate (counter-clockwise). That
// rate is -omega times the moment of the arch's thrust on the wall about the toe, M_T = (p - T) x
// (-H, -V_left) (for the left wall the moment that overturns it), so the work the arch does on the
// walls is left_share M_T,left + right_share M_T,right per unit of d, each moment taken outwards
// positive: linear in the program's unknowns H, V_left and M_left (the reaction's moment about the
// origin; M_T,left = -M_left + T x (H, V_left)). Its least is the state
// that overturns the walls least (LimitLp::least_work with per_M); with translations alone it is the
// work above, to the bit. The virtual-work check (SpreadStep::H_work) balances the loads' work on the
// mechanism's velocities against the springing reactions' on the walls' velocities at p:
// H (w_R(p_R) - w_L(p_L)).x = loads' work + V_left w_L(p_L).y + V_right w_R(p_R).y.
// The walls carry each state or tip: the resultant down each wall (the arch's reaction with the weights
// of the wall's blocks and the top load above each bed, where the wall has carried them) must cross
// every bed between its faces in compression (to 1e-9 of the bed); the first state where it leaves one
// is the wall's collapse about that bed's edge (wall_tips, the lowest such bed). The path is the arch's
// (SpreadResult::ring is the arch's ring, without the walls): a program on the walls too would move the
// arch's thrust line to keep a wall's resultant inside, a state the arch's hinges do not make. At d = 0
// the walls must stand (walls thinner than b_min: inadmissible, as analyse_limit says); for two walls
// leaning alike under a symmetric arch the least-work state there is the system's minimum-thrust one
// (the least H through the crown's highest point makes the least moment about each toe). With friction
// the walls' beds are checked as the arch's joints are: the resultant down a wall must keep inside each
// bed's cone, |shear| <= friction * normal force; the first state where it leaves one ends the path,
// collapse sliding (sliding_joint -1: no joint of the arch; tipping_wall and tipping_bed_y say which wall
// and bed, sliding_point where the bed's axis point is then). The path up to it is the frictionless
// one, to the byte. With a finite compressive strength f_c the arch's path is the crushing one (above)
// and the walls' beds are checked with their stress blocks, as limit crushes them: the resultant down a
// wall must cross each bed at least N / (2 f_c) inside its faces (N the bed's normal force; so N <= f_c
// b_w); the first state where it comes nearer a face is the wall's collapse about that bed (wall_tips,
// the message saying whether it tips or crushes). A wall still turns as a rigid body about its base's
// outer toe: the crushing of the base under the toe (the wall would turn about the toe's stress block's
// inner edge, N / f_c inside) is not followed, only checked at the beds.
// The span's increase (SpreadStep::span_increase) is the springings' intrados points' horizontal
// distance less L; increment_ratio, stop_ratio and the bisection of the collapse (kSpreadTolerance)
// measure it by its rate at d = 0.
//
// Collapse, at the first of (the last increment bisected to kSpreadTolerance of the span):
//   thrust_leaves_arch - no thrust line fits inside the moved voussoirs (the program is infeasible): the
//                  line of thrust would have to leave the arch;
//   snap_through - no mechanism of the current hinges moves the springings apart: the hinges are in a
//                  line, or fewer than three remain that open, or their rotations would close one; or a
//                  new hinge snaps (above; SpreadResult::message says where);
//   sliding      - (with friction) a joint's resultant leaves the friction cone
//                  (SpreadResult::sliding_joint), or on walls a wall's resultant leaves a bed's;
//   wall_tips    - (on walls) the resultant down a wall leaves one of its beds: the wall tips about that
//                  bed's edge (SpreadResult::tipping_wall, tipping_bed_y).
//
// Units: SI (m, N per metre of width). Positions as in limit.hpp: x from the left springing's intrados
// at d = 0, y up.
#pragma once

#include <array>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ogive/limit/limit.hpp"

namespace ogive {

inline constexpr double kSpreadTolerance = 1e-6;  // collapse movement located to this fraction of L
// The finest increment (SpreadOptions::increment_ratio): from 1e-4 to 1e-5 no measured capacity moved by
// as much as 1e-6 of the span (docs/spreading.md), and a path to collapse takes at most 25,000 of them.
inline constexpr double kLeastIncrementRatio = 1e-4;
// The refinements of the joints next to the hinges at collapse, at most (analyse_spreading), and the
// longest voussoir there after them (of the span, in arc length along the axis).
inline constexpr int kMostSpreadRefinements = 12;
inline constexpr double kSpreadJointSpacing = 2.5e-4;
// The capacity (the span's increase at collapse over L) is refined until it moves by at most this much
// of itself (three significant digits), or of kSpreadCapacityFloor when it is smaller.
inline constexpr double kSpreadCapacityTolerance = 1e-3;
inline constexpr double kSpreadCapacityFloor = 1e-2;

struct SpreadOptions {
  double left_share = 1;   // the left springing moves by -left_share * d (m per m of d), >= 0
  double right_share = 1;  // the right springing moves by +right_share * d, >= 0; one of them > 0
  // On walls each share is its wall's rotation outwards per unit of d (rad per rad), and a moving side
  // needs its wall.
  // Each springing's settlement per unit of d (m per m, downwards positive; finite, either sign): with
  // a horizontal share, a springing moving along a sloping line; without one, a pure settlement. 0 on
  // walls.
  double left_settlement_share = 0, right_settlement_share = 0;
  // The increment of the span's increase (left_share + right_share) * d over L between two
  // re-solutions of the minimum-thrust state (where the hinges may move), in [kLeastIncrementRatio, 0.1].
  double increment_ratio = 2.5e-4;
  int steps = 200;  // the path's rows: states at about d_max i / steps, i = 0 .. steps; >= 1
  // false: SpreadResult::path keeps the state at d = 0 and the last one only, and the memory taken does
  // not grow with the increments.
  bool whole_path = true;
  // Stop where the span's increase over L reaches this, before collapse (SpreadResult::stopped): the
  // path's last state is there. >= 0 (0: the state at d = 0); infinity: to collapse.
  double stop_ratio = std::numeric_limits<double>::infinity();
  bool is_valid(std::string* why) const;
};

enum class SpreadCollapse { thrust_leaves_arch, snap_through, sliding, wall_tips };
const char* to_string(SpreadCollapse c);

// One state of the mechanism.
struct SpreadStep {
  double d = 0;  // m, the movement parameter: the span grew by (left_share + right_share) d; on walls rad
  // m, the span's increase: the springings' intrados points' horizontal distance less L ((left_share +
  // right_share) d without walls)
  double span_increase = 0;
  double H = std::numeric_limits<double>::quiet_NaN();       // N/m, the program's (static) thrust
  // N/m, the mechanism's thrust by virtual work: the loads' work on its velocities, with the vertical
  // reactions' own work on the settlements (V_left and V_right the program's), over the span's growth
  double H_work = std::numeric_limits<double>::quiet_NaN();
  double V_left = std::numeric_limits<double>::quiet_NaN(), V_right = std::numeric_limits<double>::quiet_NaN();
  double crown_drop = 0;     // m, the drop of the crown joint's extrados point
  double potential = 0;      // N m/m, sum of every load times its height
  std::vector<Hinge> hinges;  // the mechanism's hinges, ascending: joint, face and where the point is now
};

enum class SpreadStatus {
  success,       // a path to collapse: every state's H is the program's and equals its virtual work
                 // (H_work), and the capacity moved by at most kSpreadCapacityTolerance of itself at the
                 // last refinement of the joints
  inadmissible,  // no thrust line fits the arch at d = 0 (t < t_min): no path
  no_mechanism,  // the state at d = 0 has no mechanism that moves the springings apart;
                 // path holds that state
  lp_failure,    // the LP library stopped without an answer
  not_collapsed, // no collapse before the span grew by 2.5 L, which no arch survives: path holds d = 0
                 // and the last state
  unsettled,     // at some movement the hinges found no placement whose program's contacts are its
                 // hinges (they rolled back and forth): path holds d = 0 and the last settled state
  not_converged, // the capacity moved by more than kSpreadCapacityTolerance of itself at the last refinement
                 // of the joints (after kMostSpreadRefinements, or where the finer ring changed the state at
                 // d = 0 and the coarser ring's path is given): the path and its numbers are given, the
                 // message says by how much the capacity moved
};
const char* to_string(SpreadStatus s);

// The voussoirs of a state where they have moved, and its line of thrust.
struct SpreadShape {
  // m: each voussoir's corners, its intrados and extrados points on its left joint, then its extrados
  // and intrados points on its right joint (an opened joint shows as the gap between neighbours).
  std::vector<std::array<Eigen::Vector2d, 4>> voussoirs;
  std::vector<Eigen::Vector2d> thrust_line;  // m: where the resultant crosses each joint (midway between its faces)
};

struct SpreadResult {
  SpreadStatus status = SpreadStatus::lp_failure;
  std::string message;
  SpreadCollapse collapse = SpreadCollapse::thrust_leaves_arch;
  double d_max = std::numeric_limits<double>::quiet_NaN();  // m (rad on walls), the movement parameter at collapse
  bool stopped = false;  // the path stopped at SpreadOptions::stop_ratio before collapse (d_max is NaN)
  // collapse == sliding: the joint of `ring` that slides (-1 for a wall's bed), and where its axis point
  // (or the bed's) is at collapse (m); -1 and NaN otherwise.
  int sliding_joint = -1;
  Eigen::Vector2d sliding_point = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  // collapse == wall_tips (or sliding at a wall's bed): the wall (0 left, 1 right) whose resultant leaves
  // a bed (or its friction cone), and the bed's height (m, y as the ring's at d = 0; the base at the
  // springing's axis height less h_w); -1 and NaN otherwise.
  int tipping_wall = -1;
  double tipping_bed_y = std::numeric_limits<double>::quiet_NaN();
  // On walls, each wall's lean at collapse (at d_max): its rotation outwards (rad; the left wall's
  // counter-clockwise, the right one's clockwise) and the outward horizontal displacement of its top's
  // outer corner (m); NaN for a side without a wall, and without walls.
  double left_wall_rotation = std::numeric_limits<double>::quiet_NaN();
  double right_wall_rotation = std::numeric_limits<double>::quiet_NaN();
  double left_wall_top_displacement = std::numeric_limits<double>::quiet_NaN();
  double right_wall_top_displacement = std::numeric_limits<double>::quiet_NaN();
  // m per unit of d: the span's rate of increase at d = 0 (left_share + right_share without walls), by
  // which increment_ratio and stop_ratio measure the movement; NaN where there is no path.
  double span_rate = std::numeric_limits<double>::quiet_NaN();
  int increments = 0;             // increments taken (each one or more programs, plus the bisection's)
  int rolls = 0;                  // times the hinges rolled to other joints (each one program more)
  // d = 0, about `steps` states between, and the last admissible one (SpreadOptions::whole_path false:
  // d = 0 and the last)
  std::vector<SpreadStep> path;
  Ring ring;                      // the ring at d = 0
  SpreadShape shape;              // path.back()'s voussoirs and thrust line (a success's)
};

// The spreading capacity of a path that collapsed (`r` of analyse_spreading under `spread`): the span's
// increase at collapse over L, (left_share + right_share) d_max / L; on walls (whose rotation moves the
// springings not in proportion to d) the springings' intrados points' own distance at collapse less L
// (the path's last SpreadStep::span_increase), over L. NaN without a collapse (d_max NaN).
double spread_capacity_ratio(const SpreadResult& r, const SpreadOptions& spread);

// The movement `spread` on the walls of `scene` (unchanged without walls): each side whose wall has
// something to turn (some height below its springing joint, or a wedge under a sloping one: at least
// 1e-9 of L, of L^2) leans by its share, the other side stands (share 0). The shares may then both be 0
// (no wall to lean): not a valid movement.
SpreadOptions leaning_walls(const Scene& scene, SpreadOptions spread);

// The mechanism path of `scene` (as analyse_limit takes it) under the movement of `spread`. Throws
// std::invalid_argument for invalid options or scene, and on walls for settlement shares or a moving
// springing without a wall of some height.
SpreadResult analyse_spreading(const Scene& scene, const LimitOptions& limit, const SpreadOptions& spread);

}  // namespace ogive
