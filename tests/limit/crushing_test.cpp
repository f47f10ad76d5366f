// The limit analysis with a finite compressive strength (LimitOptions::compressive_strength): Heyman's
// numbers at a very large strength, the stress blocks at the optimum's hinges, the static against the
// kinematic multiplier through them, the fall of every capacity with f_c, the thrust range closing to a
// point where the arch just stands, the public check on the semicircle, and misuse.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/LU>

#include "limit/limit_internal.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"
#include "ogive/solve/assessment.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The crushing programs hold their conditions to the LP's own row tolerance (1e-11 of W L): a stress
// block's position agrees with N / (2 f_c) to far better than the hinge tolerance of thrust_state.
constexpr double kHingeOffset = 1e-9;
// The static and kinematic multipliers of one mechanism are one number computed twice.
constexpr double kVirtualWork = kStaticKinematicTolerance;
// A strength so large that the stress blocks (N / f_c ~ 1e-25 m) are far below round-off of the joints.
constexpr double kHugeStrength = 1e30;
// The published t_min / L of the semicircle at f_c = 20 rho g L, to its four printed digits.
constexpr double kPublishedDigits = 0.5e-5;

constexpr double kRho = 2000.0, kG = 9.81, kSpan = 10.0;

Scene semicircle(double t_over_L) {
  Scene s;
  s.curve = make_pointed(kSpan, 0.0);
  s.thickness = t_over_L * kSpan;
  s.material.density = kRho;
  s.material.gravity = kG;
  return s;
}

// A semicircle with a point load of a third of its weight at x = 0.3 L.
Scene loaded_semicircle() {
  Scene s = semicircle(0.1);
  s.loads.points.push_back({20e3, 0.3});
  return s;
}

// A flat segmental arch (rise L / 5) with a point load at a quarter of the span.
Scene loaded_segmental() {
  Scene s;
  s.curve = make_segmental(kSpan, 0.2);
  s.thickness = 0.06 * kSpan;
  s.material.density = kRho;
  s.material.gravity = kG;
  s.loads.points.push_back({100e3, 0.25});
  return s;
}

// With `acceleration`, a_c too.
LimitResult analyse(const Scene& scene, double f_c, bool acceleration = false) {
  LimitOptions o;
  o.compressive_strength = f_c;
  o.horizontal_load_factor = acceleration;
  return analyse_limit(scene, o);
}

// Every joint of `st`: its crossing's distance from each face (m, along the joint) against the stress
// block's half depth N / (2 f_c), N from the joint's equilibrium (the loads to its left).
struct Offsets {
  double worst_hinge = 0;    // the largest |distance - N/(2 f_c)| / h over the face hinges
  double worst_inside = 0;   // the largest (N/(2 f_c) - distance) / h over all joints (> 0: a crushed joint)
  int face_hinges = 0;
};

Offsets offsets(const Ring& ring, const ThrustState& st, double f_c) {
  const limit_detail::LoadsLeftOfJoints left = limit_detail::loads_left_of_joints(ring);
  const double lambda = ring.has_live_load() ? st.load_factor : 0.0;
  Offsets out;
  for (std::size_t j = 0; j < ring.joints.size(); ++j) {
    const Joint& joint = ring.joints[j];
    const Eigen::Vector2d F(st.H, st.V_left - left.dead[j].force - lambda * left.live[j].force);
    const Eigen::Vector2d d = joint.extrados - joint.intrados;
    const double h = d.norm();
    const Eigen::Vector2d n(d.y() / h, -d.x() / h);
    const double N = F.dot(n), block = N / (2 * f_c);
    const double from_intrados = (st.crossing[j] - joint.intrados).norm();
    const double from_extrados = (st.crossing[j] - joint.extrados).norm();
    out.worst_inside = std::max(out.worst_inside, (block - std::min(from_intrados, from_extrados)) / h);
    for (const Hinge& hinge : st.hinges) {
      if (hinge.joint != static_cast<int>(j) || hinge.face == Face::axis) continue;
      const double distance = hinge.face == Face::intrados ? from_intrados : from_extrados;
      out.worst_hinge = std::max(out.worst_hinge, std::abs(distance - block) / h);
      CHECK((hinge.point - st.crossing[j]).norm() == 0.0);
      ++out.face_hinges;
    }
  }
  return out;
}

// The upper-bound (kinematic) multiplier of the collapse state's four hinges with the flow rule of the
// crushing condition: each joint turns about the edge of its stress block (the neutral axis, N / f_c
// inside the face, where the block's strain rate vanishes), not about the block's centre, and the block
// dissipates N^2 / (2 f_c) per unit of relative rotation. Its own kinematics and work sums, independent
// of mechanism_load_factor; N from the joints' equilibrium at the static state.
double dissipation_multiplier(const Ring& ring, const ThrustState& st, double f_c) {
  const limit_detail::LoadsLeftOfJoints left = limit_detail::loads_left_of_joints(ring);
  const std::vector<Hinge>& h = st.hinges;
  REQUIRE(h.size() == 4);
  std::vector<Eigen::Vector2d> centre;
  std::vector<double> N;
  for (const Hinge& hinge : h) {
    const std::size_t j = static_cast<std::size_t>(hinge.joint);
    const Joint& joint = ring.joints[j];
    const Eigen::Vector2d F(st.H, st.V_left - left.dead[j].force - st.load_factor * left.live[j].force);
    const Eigen::Vector2d d = (joint.extrados - joint.intrados).normalized();
    N.push_back(F.dot(Eigen::Vector2d(d.y(), -d.x())));
    const double depth = N.back() / f_c;
    centre.push_back(hinge.face == Face::intrados ? Eigen::Vector2d(joint.intrados + depth * d)
                                                  : Eigen::Vector2d(joint.extrados - depth * d));
  }
  // Three bodies between the hinges, each (u, v, omega); at each hinge the bodies on either side (the
  // ground beyond the first and last) move alike at the turning point.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(8, 9);
  for (int i = 0; i < 4; ++i)
    for (int b : {i - 1, i}) {
      if (b < 0 || b > 2) continue;
      const double sign = b == i ? 1.0 : -1.0;
      A(2 * i, 3 * b) += sign;
      A(2 * i, 3 * b + 2) -= sign * centre[static_cast<std::size_t>(i)].y();
      A(2 * i + 1, 3 * b + 1) += sign;
      A(2 * i + 1, 3 * b + 2) += sign * centre[static_cast<std::size_t>(i)].x();
    }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  REQUIRE(lu.dimensionOfKernel() == 1);
  const Eigen::VectorXd mode = lu.kernel().col(0);
  double dead = 0, live = 0;  // the loads' work rates: a downward force F at x does -F (v + omega x)
  for (int b = 0; b < 3; ++b)
    for (int k = h[static_cast<std::size_t>(b)].joint; k < h[static_cast<std::size_t>(b) + 1].joint; ++k) {
      const Voussoir& v = ring.voussoirs[static_cast<std::size_t>(k)];
      dead -= mode(3 * b + 1) * v.dead().force + mode(3 * b + 2) * v.dead().moment;
      live -= mode(3 * b + 1) * v.live.force + mode(3 * b + 2) * v.live.moment;
    }
  double dissipated = 0;
  for (int i = 0; i < 4; ++i) {
    const double right = i < 3 ? mode(3 * i + 2) : 0.0, left_turn = i > 0 ? mode(3 * (i - 1) + 2) : 0.0;
    dissipated += N[static_cast<std::size_t>(i)] * N[static_cast<std::size_t>(i)] / (2 * f_c) *
                  std::abs(right - left_turn);
  }
  if (live < 0) dead = -dead, live = -live;  // the sense in which the live load does positive work
  return (dissipated - dead) / live;
}

// The strength at which `scene` just stands (bisection on its status, to 1e-6 relative): the lowest
// f_c with an admissible state.
double just_standing(const Scene& scene, double lo, double hi) {
  REQUIRE(analyse(scene, lo).status == LimitStatus::inadmissible);
  REQUIRE(analyse(scene, hi).status == LimitStatus::success);
  while (hi - lo > 1e-6 * hi) {
    const double mid = std::sqrt(lo * hi);
    (analyse(scene, mid).status == LimitStatus::success ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

TEST_CASE("crushing: a very large strength gives Heyman's numbers") {
  for (const Scene& scene : {semicircle(0.08), loaded_semicircle(), loaded_segmental()}) {
    LimitOptions heyman, strong;
    heyman.horizontal_load_factor = strong.horizontal_load_factor = true;
    strong.compressive_strength = kHugeStrength;
    const LimitResult a = analyse_limit(scene, heyman), b = analyse_limit(scene, strong);
    REQUIRE(a.status == LimitStatus::success);
    CHECK(b.status == a.status);
    // The programs' optima are the same vertices: the same doubles.
    CHECK(b.H_min() == a.H_min());
    CHECK(b.H_max() == a.H_max());
    CHECK(b.thickness_min == a.thickness_min);
    CHECK(b.lp_solves == a.lp_solves);
    if (!std::isnan(a.load_factor())) CHECK(b.load_factor() == a.load_factor());
    CHECK(b.horizontal_load_factor() == a.horizontal_load_factor());
    // The kinematic multipliers turn about the crossings (1e-25 m from the faces) rather than the faces.
    if (!std::isnan(a.load_factor_mechanism))
      CHECK(close(b.load_factor_mechanism, a.load_factor_mechanism, kExact));
    CHECK(close(b.horizontal_load_factor_mechanism, a.horizontal_load_factor_mechanism, kExact));
  }
}

TEST_CASE("crushing: the optimum's hinges sit N / (2 f_c) inside their faces, and virtual work agrees") {
  for (const Scene& scene : {loaded_semicircle(), loaded_segmental()}) {
    for (double f_c : {2e7, 5e6, 3e6}) {
      const LimitResult r = analyse(scene, f_c, true);
      INFO("f_c = " << f_c << ": " << r.message);
      REQUIRE(r.status == LimitStatus::success);
      for (const ThrustState* st : {&r.min_state, &r.max_state, &r.collapse_state}) {
        const Offsets at = offsets(r.ring, *st, f_c);
        CHECK(at.face_hinges >= 1);
        CHECK(at.worst_hinge <= kHingeOffset);
        CHECK(at.worst_inside <= kHingeOffset);
      }
      const Offsets shaken = offsets(r.horizontal_ring, r.horizontal_state, f_c);
      CHECK(shaken.face_hinges >= 1);
      // The collapse: four hinges, the mechanism through the stress blocks' centres does no work at the
      // static multiplier.
      CHECK(r.collapse_state.hinges.size() == 4);
      CHECK(close(mechanism_load_factor(r.ring, r.collapse_state.hinges), r.load_factor(), kVirtualWork));
      // The same multiplier by the kinematic theorem of the crushing model: the blocks turning about the
      // stress blocks' edges, the work of the loads balanced by what the blocks dissipate.
      CHECK(close(dissipation_multiplier(r.ring, r.collapse_state, f_c), r.load_factor(), kVirtualWork));
      CHECK(close(mechanism_horizontal_load_factor(r.horizontal_ring, r.horizontal_state.hinges),
                  r.horizontal_load_factor(), kVirtualWork));
    }
  }
}

TEST_CASE("crushing: the capacities fall monotonically with the strength") {
  for (const Scene& scene : {loaded_semicircle(), loaded_segmental()}) {
    double load_factor = std::numeric_limits<double>::infinity(), range = load_factor, safety = load_factor;
    double acceleration = load_factor;
    for (double f_c : {std::numeric_limits<double>::infinity(), 1e8, 2e7, 1e7, 5e6, 3e6}) {
      const LimitResult r = analyse(scene, f_c, true);
      INFO("f_c = " << f_c << ": " << r.message);
      REQUIRE(r.status == LimitStatus::success);
      CHECK(r.load_factor() < load_factor);
      CHECK(r.H_max() - r.H_min() < range);
      CHECK(scene.thickness / r.thickness_min < safety);
      CHECK(r.horizontal_load_factor() < acceleration);
      load_factor = r.load_factor();
      range = r.H_max() - r.H_min();
      safety = scene.thickness / r.thickness_min;
      acceleration = r.horizontal_load_factor();
    }
  }
}

TEST_CASE("crushing: the thrust range closes to one point at the strength where the arch just stands") {
  Scene plain = semicircle(0.1);
  for (const Scene& scene : {plain, loaded_segmental()}) {
    const double f_star = just_standing(scene, 1e4, 1e8);
    INFO("f_c* = " << f_star);
    // Just above it the range is a sliver; it widens as f_c moves away.
    double previous = 0;
    for (double above : {1e-5, 1e-3, 1e-1}) {
      const LimitResult r = analyse(scene, f_star * (1 + above));
      REQUIRE(r.status == LimitStatus::success);
      const double width = (r.H_max() - r.H_min()) / r.V;
      CHECK(width > previous);
      if (above == 1e-5) CHECK(width < 1e-2);
      previous = width;
    }
    // Just below it no thrust line stands, and the message says that the joints crush.
    const LimitResult below = analyse(scene, f_star * (1 - 1e-5));
    CHECK(below.status == LimitStatus::inadmissible);
    CHECK(below.message.find("crush") != std::string::npos);
    CHECK(std::isnan(below.H_min()));
  }
}

TEST_CASE("crushing: the semicircle at f_c = 20 rho g L has t_min = 0.05542 L (0.05374 L without crushing)") {
  const Scene scene = semicircle(0.08);
  const LimitResult heyman = analyse(scene, std::numeric_limits<double>::infinity());
  const LimitResult crushed = analyse(scene, 20 * kRho * kG * kSpan);
  REQUIRE(heyman.status == LimitStatus::success);
  REQUIRE(crushed.status == LimitStatus::success);
  CHECK(std::abs(heyman.thickness_min / kSpan - 0.05374) <= kPublishedDigits);
  CHECK(std::abs(crushed.thickness_min / kSpan - 0.05542) <= kPublishedDigits);
}

TEST_CASE("crushing: misuse and an arch crushed under its own weight") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double bad : {0.0, -1.0, nan, -std::numeric_limits<double>::infinity()}) {
    LimitOptions o;
    o.compressive_strength = bad;
    std::string why;
    CHECK_FALSE(o.is_valid(&why));
    CHECK(why.find("compressive_strength") != std::string::npos);
    CHECK_THROWS_AS(analyse_limit(semicircle(0.08), o), std::invalid_argument);
  }
  // Far too weak for the arch's own weight at any thickness: inadmissible, no thrust, a message.
  const LimitResult r = analyse(semicircle(0.08), 1e3);
  CHECK(r.status == LimitStatus::inadmissible);
  CHECK(std::isnan(r.H_min()));
  CHECK(std::isnan(r.H_max()));
  CHECK(r.message.find("crush") != std::string::npos);
}

TEST_CASE("crushing: the assessment's factors and spreading capacity honour the strength") {
  AssessmentOptions o;
  o.require.spread_capacity_ratio = 0.01;
  o.limit.compressive_strength = 3e6;
  const Scene scene = loaded_semicircle();
  const Assessment a = assess(scene, o);
  const LimitResult direct = analyse(scene, 3e6);
  CHECK(a.limit.thickness_min == direct.thickness_min);
  CHECK(a.limit.load_factor() == direct.load_factor());
  // The spreading path with the same strength, and less than the uncrushable voussoirs' capacity.
  const SpreadResult crushing = analyse_spreading(scene, o.limit, o.spread);
  LimitOptions heyman = o.limit;
  heyman.compressive_strength = std::numeric_limits<double>::infinity();
  const SpreadResult uncrushable = analyse_spreading(scene, heyman, o.spread);
  // With the strength the capacity converges and the assessment judges it; the uncrushable voussoirs'
  // converges too (joints where the least-thrust line grazes the faces at d = 0).
  REQUIRE(crushing.status == SpreadStatus::success);
  REQUIRE(uncrushable.status == SpreadStatus::success);
  const CriterionResult& spread = a.criteria[static_cast<int>(Criterion::spread_capacity_ratio)];
  CHECK(spread.outcome == Outcome::pass);
  CHECK(crushing.d_max < uncrushable.d_max);
}

TEST_CASE("crushing: the cuts' programs solved by Clp give the dense method's optima") {
  // The same convex programs through the independent LP library: the cut loop converges to the same
  // optimum whichever simplex code solves its linear programs.
  constexpr double kTwoSolvers = 1e-9;  // both hold the crushing rows to 1e-11 of W L
  for (const Scene& scene : {loaded_semicircle(), loaded_segmental()}) {
    LimitOptions o;
    o.compressive_strength = 3e6;
    const Ring ring = make_ring(scene, o);
    using limit_detail::LimitLp;
    using limit_detail::LpSolver;
    LimitLp dense(ring, 0.0, nullptr, LpSolver::dense, limit_detail::LiveKind::vertical, 3e6);
    LimitLp clp(ring, 0.0, nullptr, LpSolver::clp, limit_detail::LiveKind::vertical, 3e6);
    for (bool largest : {false, true}) {
      const LimitLp::Answer a = dense.extreme_thrust(1.0, largest), b = clp.extreme_thrust(1.0, largest);
      REQUIRE(a.outcome == LimitLp::Outcome::optimal);
      REQUIRE(b.outcome == LimitLp::Outcome::optimal);
      CHECK(close(a.H, b.H, kTwoSolvers));
    }
    const LimitLp::Answer a = dense.collapse(), b = clp.collapse();
    REQUIRE(a.outcome == LimitLp::Outcome::optimal);
    REQUIRE(b.outcome == LimitLp::Outcome::optimal);
    CHECK(close(a.load_factor, b.load_factor, kTwoSolvers));
    const LimitLp::Answer m = dense.margin(1.0), n = clp.margin(1.0);
    CHECK(std::abs(m.margin - n.margin) <= kTwoSolvers);
    CHECK(dense.cut_rounds() > 0);
  }
}

TEST_CASE("crushing: a program warm-started from another thickness's optimum has the cold program's optimum") {
  // The search for t_min solves the margin of thickness after thickness, each from the previous optimal
  // basis: Newton's method on its faces' exact conditions, which certifies itself as the optimum (the
  // KKT conditions) without a linear program when the active faces stay, and the rounds of cuts from
  // there when they do not. Either way the optimum must be the one the program finds from nothing.
  constexpr double kWarmCold = 1e-9;  // both hold the crushing rows to 1e-11 of W L
  constexpr double kFc = 3e6;
  using limit_detail::LimitLp;
  using Question = LimitLp::Answer (*)(LimitLp&, const std::vector<int>*);
  const Question questions[] = {
      [](LimitLp& lp, const std::vector<int>* w) { return lp.margin(1.0, w); },
      [](LimitLp& lp, const std::vector<int>* w) { return lp.extreme_thrust(1.0, false, w); },
      [](LimitLp& lp, const std::vector<int>* w) { return lp.extreme_thrust(1.0, true, w); },
      [](LimitLp& lp, const std::vector<int>* w) { return lp.collapse(w); },
  };
  int certified = 0, with_rounds = 0;
  for (const Scene& scene : {loaded_semicircle(), loaded_segmental()}) {
    LimitOptions o;
    o.compressive_strength = kFc;
    const Ring first = make_ring(scene, o);
    for (double factor : {1.0001, 1.01, 1.1, 0.9}) {
      Scene other = scene;
      other.thickness *= factor;
      const Ring ring = make_ring(other, o);
      REQUIRE(ring.joints.size() == first.joints.size());  // the warm start needs as many joints
      for (const Question& ask : questions) {
        LimitLp warm(first, 0.0, nullptr, limit_detail::LpSolver::dense, limit_detail::LiveKind::vertical, kFc);
        const LimitLp::Answer from = ask(warm, nullptr);
        REQUIRE(from.outcome == LimitLp::Outcome::optimal);
        warm.load(ring, 0.0, kFc);
        const int programs = warm.programs();
        const LimitLp::Answer a = ask(warm, &from.basis);
        LimitLp cold(ring, 0.0, nullptr, limit_detail::LpSolver::dense, limit_detail::LiveKind::vertical, kFc);
        const LimitLp::Answer b = ask(cold, nullptr);
        INFO("thickness x " << factor);
        REQUIRE(a.outcome == b.outcome);
        if (b.outcome != LimitLp::Outcome::optimal) continue;
        (warm.programs() == programs ? certified : with_rounds) += 1;
        CHECK(std::abs(a.margin - b.margin) <= kWarmCold);
        CHECK(close(a.H, b.H, kWarmCold));
        CHECK(close(a.load_factor, b.load_factor, kWarmCold));
        // The warm optimum keeps every joint's thrust N / (2 f_c) clear of the faces (its own statics).
        if (a.margin >= 0.0) {
          const ThrustState st = thrust_state(ring, a.H, a.V, a.M, a.load_factor, 1e-9, kFc);
          CHECK(offsets(ring, st, kFc).worst_inside <= kHingeOffset);
        }
      }
    }
  }
  // Both paths were taken: a warm start that certified itself, and one that needed its programs.
  CHECK(certified > 0);
  CHECK(with_rounds > 0);
  // A basis feasible but not optimal for the question (the least thrust's, for the greatest): the
  // certificate's multipliers refuse it, and the programs go on to the greatest thrust.
  for (const Scene& scene : {loaded_semicircle(), loaded_segmental()}) {
    LimitOptions o;
    o.compressive_strength = kFc;
    const Ring ring = make_ring(scene, o);
    LimitLp lp(ring, 0.0, nullptr, limit_detail::LpSolver::dense, limit_detail::LiveKind::vertical, kFc);
    const LimitLp::Answer lo = lp.extreme_thrust(1.0, false);
    const LimitLp::Answer hi = lp.extreme_thrust(1.0, true, &lo.basis);
    LimitLp cold(ring, 0.0, nullptr, limit_detail::LpSolver::dense, limit_detail::LiveKind::vertical, kFc);
    const LimitLp::Answer b = cold.extreme_thrust(1.0, true);
    REQUIRE(hi.outcome == LimitLp::Outcome::optimal);
    REQUIRE(b.outcome == LimitLp::Outcome::optimal);
    CHECK(close(hi.H, b.H, kWarmCold));
    CHECK(hi.H > lo.H);
  }
}
