// The chain of rigid voussoirs of the spreading path (spreading.hpp), private to the limit module: rigid
// motions, where the pieces are for a set of hinges and their relative rotations, the closure of the
// chain on the moved springings, the mechanism's rates, and the balance of four hinges.
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"

namespace ogive::spreading_detail {

using Vec = Eigen::Vector2d;

// z x r: the velocity at arm r of a unit rotation rate.
inline Vec perp(const Vec& r) { return {-r.y(), r.x()}; }

// A rigid motion x -> R(angle) x + shift.
struct Rigid {
  double angle = 0;
  Vec shift = Vec::Zero();
  Vec operator()(const Vec& p) const { return Eigen::Rotation2Dd(angle) * p + shift; }
  // x -> this(first(x)).
  Rigid after(const Rigid& first) const { return {angle + first.angle, Eigen::Rotation2Dd(angle) * first.shift + shift}; }
};
inline Rigid translation(const Vec& u) { return {0, u}; }
inline Rigid rotation_about(const Vec& p, double phi) { return {phi, p - Eigen::Rotation2Dd(phi) * p}; }

// A rigid body's velocity field per unit rate of the movement: its rotation rate (rad, counter-clockwise)
// and the velocity of the point at the origin. Made from a velocity alone: a translation's.
struct Twist {
  double rate = 0;
  Vec velocity = Vec::Zero();
  Twist() = default;
  Twist(const Vec& v) : velocity(v) {}  // NOLINT: a translation's field, where a velocity was
  Twist(double w, const Vec& v) : rate(w), velocity(v) {}
  // The velocity of the body's point at x (a translation's: its velocity, to the bit).
  Vec at(const Vec& x) const { return rate == 0 ? velocity : Vec(velocity + rate * perp(x)); }
};

// How each springing moves with the movement d: a translation by velocity * d, or (a wall turning about
// its toe) a rotation by rate * d about a fixed pivot, exact for every d; its Twist the same for every d.
struct SpringingMotion {
  Twist twist;
  Vec pivot = Vec::Zero();  // where a rotating springing turns about (m)
  Rigid at(double d) const {
    return twist.rate == 0 ? translation(twist.velocity * d) : rotation_about(pivot, twist.rate * d);
  }
  static SpringingMotion sliding(const Vec& v) { return {Twist(v), Vec::Zero()}; }
  static SpringingMotion turning(const Vec& about, double rate) { return {Twist(rate, -rate * perp(about)), about}; }
};

// Where the pieces are: each voussoir's motion from its place at d = 0, and each springing's.
struct Placement {
  std::vector<Rigid> voussoir;
  Rigid left, right;
};

inline Vec load_point(const VerticalLoad& l) { return {l.moment / l.force, l.height_moment / l.force}; }
VerticalLoad moved_load(const VerticalLoad& l, const Rigid& m);

// ring0 with every voussoir (its centroid and its loads' points) where `at` puts it, and each joint
// midway between its two faces: the left one with the voussoir (or springing) before it, the right one
// with the voussoir after it.
void place_ring(const Ring& ring0, const Placement& at, Ring& ring);

// Every vertical load of the ring at factor 1 (self-weight, fill, live) by its point of action, with the
// voussoir it bears on.
template <class F>
void for_each_load(const Ring& ring, F&& f) {
  for (std::size_t k = 0; k < ring.voussoirs.size(); ++k) {
    const Voussoir& v = ring.voussoirs[k];
    if (v.weight != 0) f(k, v.weight, v.centroid);
    if (v.fill.force != 0) f(k, v.fill.force, load_point(v.fill));
    if (v.live.force != 0) f(k, v.live.force, load_point(v.live));
  }
}

// Which way a hinge's relative rotation (of the part after it against the part before it, counter-
// clockwise positive) opens its joint: +1 or -1; 0 for a pin, which turns either way. The face opposite
// the contact must move away from the voussoir before the joint.
double opening_sign(const Ring& ring, const Hinge& h);

// A mechanism: its hinges (ascending) and their relative rotation rates per unit rate of d.
struct Mechanism {
  std::vector<Hinge> hinges;
  std::vector<double> rates;
  bool found() const { return !hinges.empty(); }
};

// The smallest-norm solution x of J x = r for a 3 x m J of rank 3; false when J has a smaller rank (the
// hinges are fewer than three or in a line) or the equations do not hold to round-off.
bool min_norm_solve(const Eigen::MatrixXd& J, const Eigen::Vector3d& r, Eigen::VectorXd& x);

// Each hinge's column of the closure equations: the rotation it adds, and the velocity it gives the
// point `at` of the right springing (rotation rate times the arm from the hinge's point `q`).
Eigen::Vector3d closure_column(const Vec& at, const Vec& q);

// The mechanism of `hinges` under the springings' velocity fields vL, vR: relative rotation rates whose
// sum is the right springing's rotation rate less the left one's (0 when neither turns) and that carry
// the right springing at vR - vL relative to the left one, the least squared; hinges that this would
// close are left out one by one (the worst first).
Mechanism choose_mechanism(const Ring& ring, std::vector<Hinge> hinges, const Twist& vL, const Twist& vR);

// The bodies of a chain cut at `hinges` (their points on the ring at d = 0, ascending) and turned there by
// the relative rotations phi (rad, of the part after a hinge against the part before it, counter-
// clockwise positive): the left springing's part moved by uL, each next one turned about its hinge.
void chain_bodies(const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi, const Rigid& uL,
                  std::vector<Rigid>& bodies);

// The relative rotations phi at `hinges` (points on the ring at d = 0) that close the chain on the right
// springing moved by uR when the left one has moved by uL (rigid motions: translations, or a wall's
// rotation about its toe): Newton's method from the given phi, each step the least-squares one (with
// three hinges the rotations are unique; with more, the closing rotations nearest the start). False
// when the iteration does not close the chain.
bool close_chain(const std::vector<Hinge>& hinges, const Rigid& uL, const Rigid& uR, double L, Eigen::VectorXd& phi,
                 std::vector<Rigid>& bodies);

// Whether each relative rotation opens its joint (a face hinge turns one way only), to round-off.
bool all_open(const Ring& ring0, const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi);

// The joint whose resultant leans furthest outside Coulomb's cone |F . d| <= friction (F . n) (d along
// the joint, n its normal towards the part after it), by more than round-off of the force; -1 when every
// joint keeps inside (or friction is 0: no sliding check).
int sliding_joint(const Ring& ring, const ThrustState& st, double friction);
// How far the resultant F at `joint` leans outside Coulomb's cone, (|F . d| - friction (F . n)) / |F|
// (as sliding_joint: > kConeRoundOff outside it); 0 for no force.
double cone_excess(const Joint& joint, const Vec& F, double friction);
inline constexpr double kConeRoundOff = 1e-12;

bool same_hinges(const std::vector<Hinge>& a, const std::vector<Hinge>& b);

// `hinges` with each one's point taken from the hinge of `points` at the same joint and face (kept where
// there is none): where a hinge turns now, its stress block's inner edge with a finite compressive strength.
std::vector<Hinge> with_points_of(std::vector<Hinge> hinges, const std::vector<Hinge>& points);

// The relative rotations of `to` taken from those of `from` (phi): a hinge that stays on its joint keeps
// its own; one that has rolled to another joint of the same face takes the rotation of the hinge it
// replaces (the nearest on that face, each given once); a new hinge starts from 0.
Eigen::VectorXd carried_rotations(const std::vector<Hinge>& from, const Eigen::VectorXd& phi,
                                  const std::vector<Hinge>& to);

// The furthest a four-hinge chain's free mode is turned (rad) to find its balance at one movement.
constexpr double kMostBalanceTurn = 0.1;

// The hinge whose rotation has the closing sign the most (all_open is false).
std::size_t most_closed(const Ring& ring0, const std::vector<Hinge>& hinges, const Eigen::VectorXd& phi);

// The hinges of a and b, ascending by joint, each joint and face once.
std::vector<Hinge> union_of(const std::vector<Hinge>& a, const std::vector<Hinge>& b);

// The rotations of `to` (a superset of `from`): each hinge of from keeps its own, a new one starts from 0.
Eigen::VectorXd kept_rotations(const std::vector<Hinge>& from, const Eigen::VectorXd& phi, const std::vector<Hinge>& to);

// Each piece's motion for `voussoirs` voussoirs: those before the first hinge with the left
// springing's body, those between two hinges with their block's, those after the last with the right
// springing's (bodies as chain_bodies gives them).
Placement placement(std::size_t voussoirs, const std::vector<Hinge>& hinges, const std::vector<Rigid>& bodies);

// The loads' work (N m/m) on the chain's free mode at the placement `bodies` of four hinges: the
// closure Jacobian's null vector there (unit, the springings still), turned to agree with `towards`
// when it has four entries. Zero where the thrust line passes through every hinge.
double free_work(const Ring& ring0, const std::vector<Hinge>& hinges, const std::vector<Rigid>& bodies,
                 const Eigen::VectorXd& towards, Eigen::VectorXd& mode);

// Four hinges leave the chain one free mode at a given d: the blocks stand where the loads do no work
// on it (the thrust line through all four hinges), found along the mode by the secant method from the
// closed chain phi. False when that balance is not found within kMostBalanceTurn rad, or is unstable
// (the loads' work on the mode grows as it moves: they drive it on, the blocks snap). A chain already
// in balance to round-off (a symmetric one) is left as it is.
bool balance(const Ring& ring0, const std::vector<Hinge>& hinges, const Rigid& uL, const Rigid& uR,
             Eigen::VectorXd& phi, std::vector<Rigid>& bodies);

// The refinement of the spreading path's ring (analyse_spreading): whether two rings' hinges are at the
// same places (to 1e-9 of the span L; joints of one ring need not have the other's numbers); the hinges
// at collapse that can roll on (on a face, not on a springing's joint); the longest arc length (m) of
// the two voussoirs on each side of each hinge.
bool same_places(const std::vector<Hinge>& a, const std::vector<Hinge>& b, double L);
std::vector<Hinge> rolling_hinges(const Ring& ring, const std::vector<Hinge>& hinges);
double coarsest_next_to(const Ring& ring, const std::vector<Hinge>& hinges);

// The thrust state of the path's state at d = 0 `s` on `ring` (an arch on the ground): its H and V_left,
// through its first hinge's point (the least-work state: limit's minimum-thrust one unless a springing
// settles). No state (not found()) where it has no hinge.
ThrustState start_state(const Ring& ring, const SpreadStep& s);
// Where the line `st` on `ring` (of `scene` with `options`: an arch on the ground, its joints at
// ring.joint_fractions) grazes a face at one of its hinges on the continuous arch: for each
// hinge on a face strictly inside a side, not on a load's edge joint (where the line's curvature jumps),
// whose neighbours' crossings lie inside that face, the vertex of the parabola through the three joints'
// distances from the face against their fractions (Ring::joint_fractions' measure), where none of the
// ring's joints is already (to 1e-12). A joint there lets the line touch the face where it would on the
// continuous arch, whatever joints are added beside it (but within reach: with_grazing).
std::vector<double> grazing_fractions(const Scene& scene, const LimitOptions& options, const Ring& ring,
                                      const ThrustState& st);
// `fractions` (Ring::joint_fractions' measure, with any walls' encoded beds) with joints at `graze`
// (grazing_fractions' on `ring`) instead of those within half kSpreadJointSpacing of the span of them,
// merged (merged_fractions).
std::vector<double> with_grazing(const Ring& ring, std::vector<double> fractions, const std::vector<double>& graze);

}  // namespace ogive::spreading_detail
