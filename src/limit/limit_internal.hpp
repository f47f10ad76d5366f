// Shared inside the limit-analysis module (private header): the loads as seen from each joint, and the
// linear programs (src/limit/limit_lp.cpp, the only file that includes the LP library).
#pragma once

#include <algorithm>
#include <compare>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ogive/limit/limit.hpp"

namespace ogive::limit_detail {

// The plane cross product a x b (its z component): the moment of force b at arm a.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// What lies to the left of each joint j (voussoirs 0 .. j-1), for the equilibrium of that part: the
// dead and the live loads (at factor 1), each with its moment about the origin. One entry per joint.
struct LoadsLeftOfJoints {
  std::vector<VerticalLoad> dead, live;
};
LoadsLeftOfJoints loads_left_of_joints(const Ring& ring);
// The same into `out`, whose storage is reused.
void loads_left_of_joints(const Ring& ring, LoadsLeftOfJoints& out);

// Joint fractions (Ring::joint_fractions): closer than this are one joint.
inline constexpr double kFractionGap = 1e-9;
// The fractions of a ring of joints_count equally spaced joints.
std::vector<double> uniform_fractions(int joints_count);
// The fractions of the joints at the loads' edges on both sides (make_ring(scene, ...) describes them)
// of a ring of `curve` with thickness t; none for a thickness that does not fit the curve.
std::vector<double> load_fractions(const Curve& curve, double thickness, const Loads& loads,
                                   const LimitOptions& options);
// uniform_fractions(options.joints_count) with the scene's load_fractions.
std::vector<double> starting_fractions(const Scene& scene, const LimitOptions& options);
// Sorted, strictly inside (0, 1) or encoding a wall's bed (kept_wall_fraction), none within
// kFractionGap of the one before.
std::vector<double> merged_fractions(std::vector<double> fractions);
// Appends the fractions that halve the two voussoirs on each side of each hinge's joint (on both sides
// of the arch: the fractions are shared), and for a hinge at a wall's bed the encoded depth fractions
// that halve the two blocks on each side of it (that wall's only).
void add_refinement(const Ring& ring, const std::vector<Hinge>& hinges, std::vector<double>& out);

// Walls (src/limit/walls.cpp). A wall's beds lie at depth fractions f in [0, 1] of the wall from its
// highest bed (0) to its base (1): kWallBlocks equal blocks, and the beds that the refinement adds,
// carried among the arch's fractions encoded as 2 + f (left wall) or 4 + f (right wall), which
// merged_fractions keeps and the arch's joints ignore.
inline constexpr int kWallBlocks = 16;
bool is_wall_fraction(double f);    // an encoded wall bed, not an arch joint
bool kept_wall_fraction(double f);  // an encoded wall bed strictly inside its wall (0 < f < 1, by kFractionGap)
// Puts the scene's walls on the ring (built without them): the left wall's beds and blocks before the
// arch, the right wall's after it (Ring::left_wall_joints), at the fractions' encoded wall beds.
void attach_walls(const Scene& scene, const std::vector<double>& fractions, Ring& ring);
// The thickest arch whose springing joints the scene's walls carry whole (as wide as the thinnest
// wall): where t_min's search stops; infinity without walls.
double thickest_on_walls(const Scene& scene);
// The normal force (N/m, compression positive, 0 for tension) of the force F across `joint` (F of the
// part left of it on the part right of it; the joint's intrados to extrados d, its normal (d.y, -d.x)).
inline double joint_normal_force(const Joint& joint, const Eigen::Vector2d& F) {
  const Eigen::Vector2d d = joint.extrados - joint.intrados;
  return std::max(0.0, (F.x() * d.y() - F.y() * d.x()) / d.norm());
}
// Half the arch's loads (dead plus live at factor 1; the walls' not counted): LimitResult::V.
double arch_half_load(const Ring& ring);
// The least wall thickness of the scene on the joints `fractions`, under dead + load_factor * live,
// starting near `near` (the previous ring's; NaN: none): into r (wall_thickness_min, lp_solves), with
// the refinement next to its hinges and its joints on their cones appended to `refinement`. Nothing
// without walls.
struct WallSearch {
  double b_min = std::numeric_limits<double>::quiet_NaN();
  std::string note;                // why there is no root, or why it is the least thickness allowed
  // For the message of a system that does not stand: " on its walls" (empty without walls), and
  // " (or the walls are thinner than b_min)" when some is.
  std::string on, thinner;
  std::vector<double> refinement;  // next to the hinges of the thinnest wall that stands
  int solves = 0;
  bool failed = false;  // a program stopped without an answer
};
WallSearch least_wall_thickness(const Scene& scene, const LimitOptions& options, const std::vector<double>& fractions,
                                double load_factor, double near, LimitResult& r, std::vector<double>& refinement);
// The ring of the scene (as make_ring) with its joints at `fractions` (as merged_fractions returns them).
Ring make_ring_at(const Scene& scene, const LimitOptions& options, const std::vector<double>& fractions);

// Work areas for building ring after ring (the search for t_min builds one per thickness): their storage
// is kept, so that the heap does not grow and shrink at every ring.
class RingScratch {
 public:
  RingScratch();
  ~RingScratch();
  RingScratch(const RingScratch&) = delete;
  RingScratch& operator=(const RingScratch&) = delete;
  // Forgets the last rings (what the next ring of the same joints would reuse), keeping the storage:
  // before the rings of another scene.
  void forget();

 private:
  friend void make_ring_at(const Scene&, const LimitOptions&, const std::vector<double>&, Ring&, RingScratch&);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
// make_ring_at written over `ring`, whose storage is reused with the scratch's.
void make_ring_at(const Scene& scene, const LimitOptions& options, const std::vector<double>& fractions, Ring& ring,
                  RingScratch& scratch);

// What the programs of one round share: Clp's model, made on the first program Clp solves and reused by
// the next ones instead of making work areas of its own; one per round of an analysis, so never shared
// between threads (the library's objects are not thread-safe).
class LpWorkspace {
 public:
  LpWorkspace();
  ~LpWorkspace();
  LpWorkspace(const LpWorkspace&) = delete;
  LpWorkspace& operator=(const LpWorkspace&) = delete;

 private:
  friend class LimitLp;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Which method solves the programs: the dense simplex method (dense_lp.hpp), or COIN-OR Clp (the
// independent reference the tests compare it with).
enum class LpSolver { dense, clp };

// What the load factor lambda multiplies: the live load (point and live loads; the dead loads at factor
// 1, pushed by Ring::acceleration), or the horizontal acceleration of the dead loads (the acceleration
// a_c of collapse; every vertical load at factor 1, Ring::acceleration ignored).
enum class LiveKind { vertical, horizontal };

// The mechanism_load_factor (live == vertical) or mechanism_horizontal_load_factor (horizontal) of
// the hinges, and the hinges of the mechanism that gives it: the given ones (sorted by joint) when they
// are four or fewer, else the four of the least admissible mechanism; empty (and NaN) when none is one.
struct LeastMechanism {
  double factor = std::numeric_limits<double>::quiet_NaN();
  std::vector<Hinge> hinges;
};
LeastMechanism least_mechanism(const Ring& ring, const std::vector<Hinge>& hinges, LiveKind live);
// Makes r an lp_failure, and says why, when the static multiplier of a collapse (`what`) and the
// kinematic one of its hinges disagree by more than kStaticKinematicTolerance (neither absent); true then.
bool fails_virtual_work(LimitResult& r, const char* what, double static_factor, double kinematic_factor);

// The linear programs of one ring and its loads. Unknowns: the thrust H, the left support's vertical
// reaction V and moment M about the origin, the load factor lambda and the margin mu. Joint j carries
// F_j = (H, V - D_j - lambda P_j) with moment m_j = M - MD_j - lambda MP_j about the origin; the
// resultant crosses the joint between its intrados point I and extrados point E (in compression) iff
// m_j - I x F_j <= -mu h_j and m_j - E x F_j >= mu h_j, h_j = |E - I| W (W the total load, dead plus
// live, in magnitude). At a pin (Ring::pins) also m_j - A x F_j = 0, A the joint's axis point.
//
// With a finite compressive strength f_c (Pa) the masonry crushes: the joint's normal force N_j = F_j . n_j
// (n_j its normal towards the right-hand part; N > 0 in compression) bears on a stress block N_j / f_c
// deep at the face, so the resultant stays N_j / (2 f_c) inside each face: both face rows gain
// N_j^2 / (2 f_c) on their left (m_j - I x F_j + N_j^2 / (2 f_c) <= -mu h_j, and likewise at E), which
// also bounds N_j <= f_c |E - I|. The set stays convex; every program is solved exactly on it by tangent
// cuts (limit_lp.cpp), to the programs' feasibility tolerance. Infinite f_c: the rows above alone.
class LimitLp {
 public:
  // `workspace`: the model to solve in (nullptr: one of its own); it must outlive this.
  // `compressive_strength`: f_c, Pa, > 0 (infinity: Heyman's infinite strength).
  LimitLp(const Ring& ring, double friction, LpWorkspace* workspace = nullptr, LpSolver solver = LpSolver::dense,
          LiveKind live = LiveKind::vertical,
          double compressive_strength = std::numeric_limits<double>::infinity());
  ~LimitLp();
  LimitLp(const LimitLp&) = delete;
  LimitLp& operator=(const LimitLp&) = delete;
  // The programs of another ring (another thickness, say), in the storage of this one's.
  void load(const Ring& ring, double friction, double compressive_strength = std::numeric_limits<double>::infinity());

  enum class Outcome { optimal, infeasible, unbounded, failure };
  struct Answer {
    Outcome outcome = Outcome::failure;
    double H = 0, V = 0, M = 0, load_factor = 0, margin = 0;  // SI units; margin dimensionless
    std::vector<int> basis;  // the optimal basis (which joint inequalities are tight), to warm-start
    // Why a failure (outcome failure) failed when the LP itself did not (the crushing cuts); else null.
    const char* failure = nullptr;
  };
  // The smallest or largest H of an admissible state under dead + load_factor * live (mu = 0).
  // `warm` (here and below): an optimal basis of the same question to start from (the previous ring's,
  // translated by rows(keys(...))); ignored unless it is a nonsingular, dual-feasible basis here.
  Answer extreme_thrust(double load_factor, bool largest, const std::vector<int>* warm = nullptr);
  // The smallest per_H H + per_V V of an admissible state under dead + load_factor * live (mu = 0; H
  // and V the left springing's, as in Answer): the state that does the least work on a movement of the
  // springings (per_H the span's increase, per_V the right springing's rise over the left's, per unit
  // movement). With per_V = 0 and per_H > 0, extreme_thrust's smallest H.
  Answer least_work(double load_factor, double per_H, double per_V, const std::vector<int>* warm = nullptr);
  // The smallest per_H H + per_V V + per_M M (M the left support's moment about the origin, as in
  // Answer): the work on rigid motions of the springings (walls turning about their toes), per_M the
  // right springing's rotation rate less the left one's (counter-clockwise, rad per unit movement), per_H
  // and per_V the difference of the two springings' velocities at the origin. per_M = 0: least_work's.
  Answer least_work(double load_factor, double per_H, double per_V, double per_M, const std::vector<int>* warm = nullptr);
  // The largest margin mu under dead + load_factor * live: >= 0 iff the arch is admissible.
  // `warm`: the basis of the margin of a ring with the same joints count (another thickness), to start
  // from.
  Answer margin(double load_factor, const std::vector<int>* warm = nullptr);
  // The largest load factor lambda >= 0 with an admissible state (mu = 0); `least`: the smallest (the
  // bottom of a face of states, LimitLp::sliding_fixed_points).
  Answer collapse(const std::vector<int>* warm = nullptr, bool least = false);
  // A row by what it says rather than by its index, which a finer ring changes: the arc length of its
  // joint (Joint::s) and its place among the joint's rows, or infinity and its place among the sign and
  // cap rows after the joints; a crushing cut (finite f_c) has its face row's key with `cut` the normal
  // force (N/m, nonzero) it touches the crushing condition at (0 for every other row).
  struct RowKey {
    double s = 0;
    int place = 0;
    double cut = 0;
    auto operator<=>(const RowKey&) const = default;
  };
  std::vector<RowKey> keys(const std::vector<int>& basis) const;
  // The rows with those keys here (a cut's made anew when this ring has its joint); empty when one of
  // them has none (its joint is not in this ring).
  std::vector<int> rows(const std::vector<RowKey>& keys);
  // The basis with each crushing cut replaced by its face's own row: indices that name the same rows in
  // any program of a ring with as many joints (another LimitLp's, which makes the cuts anew from the
  // faces when warm-started with them). Without crushing the basis itself.
  std::vector<int> faces(const std::vector<int>& basis) const;
  // Non-associative friction (Gilbert, Casapulla & Ahmed 2006): with `normal_forces` (N/m, one per
  // joint, clamped at 0) each joint's two friction rows become |T_j| <= friction N_j with N_j those fixed
  // numbers (a Tresca-like row: its normality has no dilatancy), linear in the unknowns like every row;
  // empty: the Coulomb rows |T_j| <= friction n . F_j again, to the bit. Nothing without friction. The rows keep
  // their keys (warm starts carry over).
  void hold_sliding(const std::vector<double>& normal_forces);
  // The normal force N_j = n_j . F_j (N/m, compression positive) of each joint in the state of an
  // optimal answer of this ring's programs.
  std::vector<double> normal_forces(const Answer& a) const;
  // While hold_sliding holds normal forces, `basis` an optimal basis of the collapse program (H, V, M and
  // lambda free, the margin at 0) with them held: its rows whose multiplier is positive certify the
  // optimum whatever numbers the held rows hold, so every state inside every Coulomb cone (and every
  // joint) with those rows tight (a held row's as its Coulomb row, |T_j| = friction N_j) is a fixed point
  // of the non-associative iteration: held at its own normal forces, the program has it for an optimum.
  // The largest factor among those states (the collapse program with those rows as equalities, on the
  // Coulomb rows; the held rows are released: hold them again to go on). Not optimal when there is no
  // such state, the basis is singular, nothing is held, or the masonry crushes (finite f_c: its cuts'
  // rows stand for curved conditions). `least`: the least factor among them instead.
  Answer sliding_fixed_points(const std::vector<int>& basis, bool least = false);
  // Whether a friction row is among the rows of an optimal basis (a joint may slide in its mechanism).
  bool slides(const std::vector<int>& basis) const;
  int solves() const { return solves_; }
  // The linear programs solved for the crushing cuts beyond the first of each program (0 with infinite f_c).
  int cut_rounds() const;
  // The linear programs solved in all (with crushing: none for a question whose warm start certified
  // itself, several for one that took rounds of cuts).
  int programs() const;
  // Programs the dense method handed to Clp (a basis it found singular, or its step limit).
  int clp_fallbacks() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::unique_ptr<LpWorkspace> own_workspace_;
  int solves_ = 0;
};

// The programs of `ring` under the options' friction and compressive strength (the vertical live load's),
// in `lp`'s storage when it has some, else made anew in `workspace`: every analysis of rings one after
// another (the rounds, t_min's and b_min's searches) reuses its programs through this.
LimitLp& programs_of(const Ring& ring, const LimitOptions& options, LpWorkspace& workspace,
                     std::unique_ptr<LimitLp>& lp);

// The outcome of the non-associative iteration: the last answer, and why it did not converge (empty:
// it did).
struct SlidingIteration {
  LimitLp::Answer answer;
  std::string failure;
  // Where the answer is the least factor of a face of fixed points whose largest factor is above it by
  // more than the limit tolerance: says so (every factor between holds a state with the sliding joints
  // on their cones); else empty.
  std::string note;
  int iterations = 0;
};
// A program of lp solved from an optimal basis to start from (nullptr: none).
using SolveWarm = std::function<LimitLp::Answer(const std::vector<int>*)>;
// The program `solve` (lp's collapse, say) with non-associative friction, from `first`, its optimum with
// the Coulomb rows (the associative answer). Each iteration holds every joint's friction rows at the
// normal forces N_prev of the previous state (|T| <= friction N_prev: fixed numbers), re-solves, and moves
// N_prev towards the new normal forces, by a step halved whenever the change fails to shrink by a tenth
// (the iteration can oscillate between two mechanisms) and doubled while the factor drifts one way. At
// a fixed point the state lies inside every Coulomb cone (N = N_prev) and its mechanism, the normality
// of fixed-N rows, slides without opening. The fixed points come in faces (LimitLp::sliding_fixed_points:
// the states inside the cones with the rows that certify an optimal basis tight), along which the factor
// varies: every state of a face is a collapse state, the thrust across the sliding joints (which rigid
// blocks do not determine) deciding which, so at each new basis, and where the steps converge, the
// iteration ends at the state of least factor of the basis' face (the safe one) when held at its own
// normal forces it passes the same test (1e-10 of the loads). With crushing the faces are not used and the steps not doubled.
// `load_scale`: the live load's magnitude at factor 1 (added to the dead loads times the factor found).
SlidingIteration non_associative(LimitLp& lp, const Ring& ring, const LimitOptions& options,
                                 const LimitLp::Answer& first, double load_scale, const SolveWarm& solve);
// A second start of the non-associative search: the state of least thrust under the dead loads alone
// (the thrust a spreading arch falls to), its friction rows held at its own normal forces. Where the
// program's optimum then passes the iteration's test, it is a collapse state (inside every cone, a
// fixed point), often at a factor of 0: the arch at its least thrust slides under its weight, a
// mechanism the iteration from the associative optimum need not reach (it can be a fixed point
// itself). None without non-associative friction, with crushing, or where the test fails.
std::optional<LimitLp::Answer> least_thrust_collapse(LimitLp& lp, const Ring& ring, const LimitOptions& options,
                                                     double load_scale, const SolveWarm& solve);
// With friction: appends the refinement (add_refinement's) next to the joints of `st` whose force lies
// on Coulomb's cone. A sliding joint bounds a state as a hinge does, and a finer ring moves it (with
// vertical joints the one next to a springing, nearly along the thrust, slides first, and lies closer to
// the springing on a finer ring): refined next to the hinges alone, the rings saw no change where sliding
// governs and said converged with t_min 1 % off. Nothing without friction.
void add_sliding_refinement(const Ring& ring, const ThrustState& st, const LimitOptions& options,
                            std::vector<double>& out);

// The analysis's checks (limit_checks.cpp). Throws std::invalid_argument naming the field when nothing
// (or next to nothing) loads the ring.
void require_loaded(const Scene& scene, const Ring& ring);
// Why no thrust line stands, and whether a thicker arch would (t_min below t_cap): `on` " on its walls"
// (empty without), `thinner` whether a wall is thinner than b_min (LeastWallSearch's words).
std::string inadmissible_message(const LimitOptions& options, double t_min, double t_cap, const std::string& on,
                                 const std::string& thinner);

// The margin given to a program infeasible for every mu (friction can forbid every thrust line): a
// negative number for the root-finders, which need only the sign.
inline constexpr double kNoMargin = -1.0;
// A joint whose crossing lies this close to a face (relative to the joint) is a hinge of the thinnest
// arch, or of the thinnest walls: at the root the margin is zero to the root-finder's tolerance, not to
// round-off.
inline constexpr double kThinnestHingeTolerance = 1e-6;
// Whether a hinge lies inside its face by more than the hinge tolerance (a crushing joint's stress
// block): then the rings that follow have joints beside the loads' (limit.cpp, fractions_at).
bool stress_blocks(const Ring& ring, const std::vector<Hinge>& hinges);

// The feasibility margin (LimitLp::margin under dead + load_factor * live) of the scene as a function of
// one thickness: the arch's t (t_min's search, limit.cpp) or every wall's b_w (b_min's, walls.cpp), the
// one root-finders' function of both. Each call builds the ring of that thickness on `fractions` of it
// and solves its margin from the previous call's optimal basis when the ring has as many joints. A
// program infeasible for every mu gives kNoMargin; one that stopped without an answer sets `failed`
// (the search must stop: the value is no answer). It keeps the thinnest thickness that stood so far and
// the refinement next to its state's hinges and sliding joints (add_sliding_refinement), for the next
// round's ring, and (the arch's) whether its hinges are stress blocks.
class ThicknessMargin {
 public:
  enum class Of { arch, walls };
  // The ring's joints at a thickness (the arch's loads' joints move with its faces).
  using Fractions = std::function<std::vector<double>(double thickness)>;
  // The ring and the programs are built in the storage given (reused from one call to the next).
  ThicknessMargin(Of of, const Scene& scene, const LimitOptions& options, Fractions fractions, double load_factor,
                  Ring& ring, RingScratch& scratch, LpWorkspace& workspace, std::unique_ptr<LimitLp>& lp);
  double operator()(double thickness);

  int solves = 0;
  bool failed = false;
  std::vector<int> basis;  // the last margin's optimal basis: the next thickness starts from it
  int basis_joints = 0;    // the joints of the ring whose margin gave `basis`
  double feasible = std::numeric_limits<double>::infinity();  // the thinnest thickness that stood so far
  std::vector<double> refinement;  // next to the hinges and sliding joints of that state
  bool feasible_blocks = false;    // the arch's: that state's hinges are stress blocks

 private:
  Of of_;
  Scene scene_;  // a copy whose thickness changes
  const LimitOptions& options_;
  Fractions fractions_;
  double load_factor_;
  Ring& ring_;
  RingScratch& scratch_;
  LpWorkspace& workspace_;
  std::unique_ptr<LimitLp>& lp_;
};

}  // namespace ogive::limit_detail
