// The spreading path on walls (include/ogive/limit/spreading.hpp): the walls turn about their bases'
// outer toes and carry the springings. Checked against the ordinary spread as the walls grow tall,
// against a hand computation of the rigid rotation (the placed voussoirs, the hinges, the wall's balance
// about its toe at collapse), against the independent script benchmarks/spreading_walls/walls_lean.py,
// for convergence in the joints, mirror symmetry, and misuse.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The program's thrust and the mechanism's virtual work: one statically determinate equilibrium
// computed twice, to round-off.
constexpr double kStaticKinematic = 1e-9;
// Positions computed by two exact routes (the chain's composed rigid motions, a rotation by hand), of
// the span.
constexpr double kSamePoint = 1e-12;
// The collapse is located to kSpreadTolerance of the span in the movement: the tipping wall's moment
// about its toe vanishes there to about that much of the moments in it.
constexpr double kLocatedCollapse = 1e-4;
// The path's first state and limit's minimum-thrust state: one LP optimum found twice.
constexpr double kSameState = 1e-9;
// walls_lean.py's numbers, printed to seven significant digits (8000 voussoirs per half, where its
// hinge's joint coincides with ogive's refined one).
constexpr double kReference = 1e-5;

// The semicircle of span 10 m at t/L (the true weight of its voussoirs) on walls of height h_w and
// thickness b_w (in spans), of the arch's density.
Scene on_walls(double t_over_L, double height, double thickness) {
  Scene s = paper_scene(0.0, t_over_L);
  const double L = s.span();
  s.left_wall = s.right_wall = Wall{height * L, thickness * L, s.material.density, 0.0, 0.5};
  return s;
}

SpreadResult spread_on(const Scene& scene, SpreadOptions o = {}, int joints = kDefaultJointsCount) {
  LimitOptions limit;
  limit.joints_count = joints;
  return analyse_spreading(scene, limit, o);
}

Eigen::Vector2d turned(const Eigen::Vector2d& p, const Eigen::Vector2d& about, double theta) {
  return about + Eigen::Rotation2Dd(theta) * (p - about);
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

TEST_CASE("spreading walls: as the walls grow tall the path tends to the ordinary spread's, as 1 / h_w") {
  // A wall's rotation theta moves its springing out by h_w theta, up by b_w theta and turns it by theta:
  // at a given span increase the last two fall as 1 / h_w. Walls 5 m thick stand whatever their height.
  const SpreadResult ground = analyse_spreading(paper_scene(0.0, 0.1), {}, {});
  REQUIRE(ground.status == SpreadStatus::success);
  const double capacity = 2 * ground.d_max / ground.ring.span;
  double c[2];
  const double heights[2] = {30.0, 100.0};
  for (int k = 0; k < 2; ++k) {
    const SpreadResult r = spread_on(on_walls(0.1, heights[k], 0.5));
    REQUIRE(r.status == SpreadStatus::success);
    CHECK(r.collapse == ground.collapse);
    c[k] = r.path.back().span_increase / r.ring.span;
    CHECK(c[k] < capacity);  // the turning springings take some of it
  }
  // The two heights' capacities extrapolated to h_w -> infinity (c = c_inf - k / h_w).
  const double extrapolated = (heights[1] * c[1] - heights[0] * c[0]) / (heights[1] - heights[0]);
  CHECK(close(extrapolated, capacity, kSpreadCapacityTolerance));
  CHECK(!close(c[1], capacity, 1e-4));  // not the ordinary path itself: the walls do turn it
}

TEST_CASE("spreading walls: the semicircle on walls h_w = L, b_w = 0.25 L against an independent script") {
  // benchmarks/spreading_walls/walls_lean.csv: the symmetric three-hinge mechanism in closed form, the
  // wall tipping where the moment about its toe turns outwards.
  const Scene scene = on_walls(0.1, 1.0, 0.25);
  const SpreadResult r = spread_on(scene);
  REQUIRE(r.status == SpreadStatus::success);
  CHECK(r.collapse == SpreadCollapse::wall_tips);
  CHECK(r.tipping_wall == 0);
  // At rest: the system's minimum-thrust state (limit on the walls), the least moment about the toes.
  CHECK(close(r.path.front().H, analyse_limit(scene, {}).H_min(), kSameState));
  const double L = r.ring.span;
  CHECK(close(r.tipping_bed_y, r.ring.joints.front().axis.y() - L, kExact));  // at the base
  CHECK(close(r.left_wall_rotation, 0.03874469, kReference));
  CHECK(close(r.right_wall_rotation, r.left_wall_rotation, kExact));
  CHECK(close(r.left_wall_top_displacement, 0.3873499, kReference));
  CHECK(close(r.path.back().span_increase / L, 0.07784523, kReference));
  CHECK(close(r.path.front().H / r.path.front().V_left, 0.3080841, kReference));
  CHECK(close(r.path.back().H / r.path.back().V_left, 0.4615859, kReference));
}

TEST_CASE("spreading walls: the springing turns with its wall about the toe, the thrust through the hinges") {
  const Scene scene = on_walls(0.1, 1.0, 0.25);
  const SpreadResult r = spread_on(scene);
  REQUIRE(r.status == SpreadStatus::success);
  const Ring& ring = r.ring;
  const double L = ring.span, theta = r.left_wall_rotation;
  REQUIRE(theta > 0);
  // By hand: the toe below the outer face, h_w under the springing's axis point.
  const Joint& springing = ring.joints.front();
  const Eigen::Vector2d toe(springing.intrados.x() - scene.left_wall->thickness,
                            springing.axis.y() - scene.left_wall->height);
  // The voussoirs before the first hinge move with the wall: every corner turned by theta about the toe.
  const SpreadStep& last = r.path.back();
  REQUIRE(last.hinges.size() == 3);
  const int first_hinge = last.hinges.front().joint;
  REQUIRE(first_hinge > 0);
  for (int k = 0; k < first_hinge; ++k) {
    const Joint &a = ring.joints[static_cast<std::size_t>(k)], &b = ring.joints[static_cast<std::size_t>(k + 1)];
    const Eigen::Vector2d corners[4] = {a.intrados, a.extrados, b.extrados, b.intrados};
    for (int c = 0; c < 4; ++c)
      CHECK((r.shape.voussoirs[static_cast<std::size_t>(k)][static_cast<std::size_t>(c)] - turned(corners[c], toe, theta))
                .norm() <= kSamePoint * L);
  }
  // The span's increase: the springings' intrados points turned about their toes (mirror images).
  const Eigen::Vector2d moved = turned(springing.intrados, toe, theta);
  CHECK(close(last.span_increase, 2 * (springing.intrados.x() - moved.x()), kTwoExactMethods));
  // The wall top's outer corner, straight above the toe at the springing line: out by h_w sin(theta).
  CHECK(close(r.left_wall_top_displacement, scene.left_wall->height * std::sin(theta), kExact));
  // The thrust line passes through each hinge of the collapse state where the hinge has moved: the
  // first one turned with the wall.
  for (const Hinge& h : last.hinges)
    CHECK((r.shape.thrust_line[static_cast<std::size_t>(h.joint)] - h.point).norm() <= 1e-9 * L);
  CHECK((last.hinges.front().point - turned(ring.joints[static_cast<std::size_t>(first_hinge)].intrados, toe, theta))
            .norm() <= kSamePoint * L);
  // The wall tips at collapse: the arch's reaction on it (-H, -V_left through the thrust line's point on
  // the springing joint) and the wall's weight (at its turned centroid) balance about the toe.
  const Wall& w = *scene.left_wall;
  const double weight = w.density * scene.material.gravity * w.thickness * w.height;
  const Eigen::Vector2d centroid = turned(toe + Eigen::Vector2d(0.5 * w.thickness, 0.5 * w.height), toe, theta);
  const Eigen::Vector2d p = r.shape.thrust_line.front();
  const double overturning = cross(p - toe, Eigen::Vector2d(-last.H, -last.V_left));
  const double restoring = cross(centroid - toe, Eigen::Vector2d(0, -weight));
  CHECK(std::abs(overturning + restoring) <= kLocatedCollapse * std::abs(restoring));
}

TEST_CASE("spreading walls: the program's thrust equals the mechanism's virtual work on the turning springings") {
  // Both walls, and the left one alone (an unsymmetric movement whose hinges are not mirrored).
  for (const double right_share : {1.0, 0.0}) {
    SpreadOptions o;
    o.right_share = right_share;
    const SpreadResult r = spread_on(on_walls(0.1, 1.0, 0.25), o);
    CAPTURE(right_share);
    REQUIRE(r.status == SpreadStatus::success);
    REQUIRE(r.path.size() > 10);
    for (const SpreadStep& s : r.path) CHECK(close(s.H, s.H_work, kStaticKinematic));
    if (right_share == 0) CHECK(r.right_wall_rotation == 0);
  }
}

TEST_CASE("spreading walls: the lean at collapse converges in the joints") {
  const Scene scene = on_walls(0.1, 1.0, 0.25);
  const SpreadResult coarse = spread_on(scene, {}, 201), fine = spread_on(scene, {}, 801);
  REQUIRE(coarse.status == SpreadStatus::success);
  REQUIRE(fine.status == SpreadStatus::success);
  CHECK(close(coarse.left_wall_rotation, fine.left_wall_rotation, kSpreadCapacityTolerance));
  CHECK(close(coarse.left_wall_top_displacement, fine.left_wall_top_displacement, kSpreadCapacityTolerance));
}

TEST_CASE("spreading walls: a symmetric system gives mirrored hinges along the path") {
  const SpreadResult r = spread_on(on_walls(0.1, 1.0, 0.25));
  REQUIRE(r.status == SpreadStatus::success);
  const double L = r.ring.span;
  // The mirror: the vertical through the crown joint's axis point.
  const double mid = r.ring.joints[static_cast<std::size_t>(r.ring.crown_joint())].axis.x();
  for (const SpreadStep* s : {&r.path.front(), &r.path.back()}) {
    REQUIRE(s->hinges.size() == 3);
    const Hinge &a = s->hinges.front(), &b = s->hinges.back();
    CHECK(a.face == b.face);
    CHECK(std::abs((a.point.x() - mid) + (b.point.x() - mid)) <= 1e-9 * L);
    CHECK(std::abs(a.point.y() - b.point.y()) <= 1e-9 * L);
    CHECK(std::abs(s->hinges[1].point.x() - mid) <= 1e-9 * L);
  }
}

TEST_CASE("spreading walls: one wall leaning, then the other: mirror images") {
  const Scene scene = on_walls(0.1, 1.0, 0.25);
  SpreadOptions left, right;
  left.right_share = 0;
  right.left_share = 0;
  const SpreadResult a = spread_on(scene, left), b = spread_on(scene, right);
  REQUIRE(a.status == SpreadStatus::success);
  REQUIRE(b.status == SpreadStatus::success);
  CHECK(a.tipping_wall == 0);
  CHECK(b.tipping_wall == 1);
  CHECK(close(a.left_wall_rotation, b.right_wall_rotation, kSpreadTolerance));
  CHECK(close(a.path.back().span_increase, b.path.back().span_increase, kSpreadTolerance));
  const double L = a.ring.span;
  const double mid = a.ring.joints[static_cast<std::size_t>(a.ring.crown_joint())].axis.x();
  const std::vector<Hinge>&ha = a.path.back().hinges, &hb = b.path.back().hinges;
  REQUIRE(ha.size() == hb.size());
  for (std::size_t i = 0; i < ha.size(); ++i) {
    const Hinge &x = ha[i], &y = hb[hb.size() - 1 - i];
    CHECK(x.face == y.face);
    CHECK(std::abs((x.point.x() - mid) + (y.point.x() - mid)) <= kSpreadTolerance * L);  // each collapse located to that
    CHECK(std::abs(x.point.y() - y.point.y()) <= kSpreadTolerance * L);  // each collapse located to that
  }
}

TEST_CASE("spreading walls: walls thinner than b_min leave no path, and misuse throws") {
  const Scene thin = on_walls(0.1, 1.0, 0.15);  // b_min = 0.1678 L (limit)
  CHECK(spread_on(thin).status == SpreadStatus::inadmissible);
  const Scene scene = on_walls(0.1, 1.0, 0.25);
  SpreadOptions settling;
  settling.left_settlement_share = 0.5;
  CHECK_THROWS_AS(analyse_spreading(scene, {}, settling), std::invalid_argument);
  LimitOptions crushing;
  crushing.compressive_strength = 0.3e6;  // the base's N (about 757 kN/m) above f_c b_w = 750 kN/m: it crushes
  CHECK(analyse_spreading(scene, crushing, {}).status == SpreadStatus::inadmissible);
  Scene one = scene;
  one.left_wall.reset();
  CHECK_THROWS_AS(analyse_spreading(one, {}, {}), std::invalid_argument);  // the left springing has no wall to turn
  SpreadOptions right_only;
  right_only.left_share = 0;
  CHECK(analyse_spreading(one, {}, right_only).status == SpreadStatus::success);
}

TEST_CASE("spreading walls: a strength nothing crushes at gives the uncrushable path") {
  const Scene scene = on_walls(0.1, 1.0, 0.25);
  LimitOptions strong;
  strong.compressive_strength = 1e12;  // stress blocks of a micrometre
  const SpreadResult rigid = spread_on(scene), r = analyse_spreading(scene, strong, {});
  REQUIRE(rigid.status == SpreadStatus::success);
  REQUIRE(r.status == SpreadStatus::success);
  CHECK(r.collapse == rigid.collapse);
  CHECK(r.tipping_wall == rigid.tipping_wall);
  CHECK(close(spread_capacity_ratio(r, {}), spread_capacity_ratio(rigid, {}), kSpreadCapacityTolerance));
  CHECK(close(r.left_wall_rotation, rigid.left_wall_rotation, kSpreadCapacityTolerance));
}

TEST_CASE("spreading walls: with a finite strength the wall tips where its base's stress block reaches the toe") {
  // The semicircle of span 10 m on walls 10 m high and 2.5 m thick at f_c = 2 MPa: the walls govern.
  const Scene scene = on_walls(0.1, 1.0, 0.25);
  LimitOptions crushing;
  crushing.compressive_strength = 2e6;
  const SpreadResult rigid = spread_on(scene), r = analyse_spreading(scene, crushing, {});
  REQUIRE(rigid.status == SpreadStatus::success);
  REQUIRE(r.status == SpreadStatus::success);
  REQUIRE(r.collapse == SpreadCollapse::wall_tips);
  CHECK(r.tipping_wall == 0);
  CHECK(r.message.find("N / (2 f_c)") != std::string::npos);
  CHECK(r.left_wall_rotation < rigid.left_wall_rotation);  // it tips earlier
  CHECK(spread_capacity_ratio(r, {}) < spread_capacity_ratio(rigid, {}));
  for (const SpreadStep& s : r.path) CHECK(close(s.H, s.H_work, kStaticKinematic));
  // By hand: the wall (turned by theta about its toe) balances about the centre of its base's stress
  // block, N / (2 f_c) inside the toe along the turned base, N the resultant's component normal to it.
  const Ring& ring = r.ring;
  const double L = ring.span, theta = r.left_wall_rotation;
  CHECK(close(r.tipping_bed_y, ring.joints.front().axis.y() - L, kExact));  // at the base
  const Joint& springing = ring.joints.front();
  const Wall& w = *scene.left_wall;
  const Eigen::Vector2d toe(springing.intrados.x() - w.thickness, springing.axis.y() - w.height);
  const SpreadStep& last = r.path.back();
  const double weight = w.density * scene.material.gravity * w.thickness * w.height;
  const double N = (last.V_left + weight) * std::cos(theta) - last.H * std::sin(theta);
  const Eigen::Vector2d centre = turned(toe + Eigen::Vector2d(N / (2 * crushing.compressive_strength), 0), toe, theta);
  const Eigen::Vector2d centroid = turned(toe + Eigen::Vector2d(0.5 * w.thickness, 0.5 * w.height), toe, theta);
  const Eigen::Vector2d p = r.shape.thrust_line.front();
  const double overturning = cross(p - centre, Eigen::Vector2d(-last.H, -last.V_left));
  const double restoring = cross(centroid - centre, Eigen::Vector2d(0, -weight));
  CHECK(std::abs(overturning + restoring) <= kLocatedCollapse * std::abs(restoring));
}

namespace {

// The segmental arch (rise L/4) of span 10 m at t/L = 0.1 on walls h_w = L/2, b_w = 0.3 L: its springing
// joint is radial, sloping, so each wall's highest bed lies under a wedge and carries the arch's thrust
// H as shear on its horizontal face, with the arch's V and the wedge's weight as normal force.
Scene segmental_on_walls() {
  Scene s;
  s.curve = make_segmental(10.0, 0.25);
  s.thickness = 1.0;
  s.left_wall = s.right_wall = Wall{5.0, 3.0, s.material.density, 0.0, 0.5};
  return s;
}

LimitOptions with_friction(double mu) {
  LimitOptions o;
  o.friction = mu;
  return o;
}

}  // namespace

TEST_CASE("spreading walls: with friction a wall slides at its highest bed, where H / N reaches the friction") {
  const Scene scene = segmental_on_walls();
  const double mu = 0.6;
  const SpreadResult r = analyse_spreading(scene, with_friction(mu), {});
  const SpreadResult frictionless = analyse_spreading(scene, {}, {});
  REQUIRE(r.status == SpreadStatus::success);
  REQUIRE(frictionless.status == SpreadStatus::success);
  CHECK(r.collapse == SpreadCollapse::sliding);
  CHECK(r.sliding_joint == -1);  // no joint of the arch: a wall's bed
  CHECK(r.tipping_wall == 0);    // the symmetric system: the left wall, checked first
  CHECK(r.message.find("the left wall slides at its bed") == 0);
  // The frictionless walls tip later: the slip comes first.
  CHECK(frictionless.collapse == SpreadCollapse::wall_tips);
  CHECK(r.d_max < frictionless.d_max);
  // The bed is the wall's highest, at the lower end of the springing joint, and it turned with the wall
  // about the toe: its axis point where the wall's rigid rotation by theta puts it.
  const WallOutline o = wall_outline(*scene.curve, scene.thickness, *scene.left_wall, false);
  CHECK(close(r.tipping_bed_y, o.top_y, kSamePoint));
  const Eigen::Vector2d toe(o.outer_x, o.base_y), bed(0.5 * (o.inner_x + o.outer_x), o.top_y);
  const Eigen::Vector2d moved = turned(bed, toe, r.left_wall_rotation);
  const double L = scene.span();
  CHECK(std::abs(r.sliding_point.x() - moved.x()) <= kSamePoint * L);
  CHECK(std::abs(r.sliding_point.y() - moved.y()) <= kSamePoint * L);
  // By hand, at collapse: on the turned horizontal bed the resultant's shear and normal force are the
  // arch's reaction (H, V_left) with the wedge's weight, resolved along the bed turned by theta. The
  // last state inside the cone has |shear| / normal at the friction, to the collapse's location.
  const SpreadStep& last = r.path.back();
  const double theta = r.left_wall_rotation;
  const double wedge = scene.left_wall->density * scene.material.gravity * o.wedge_area;
  const Eigen::Vector2d F(-last.H, -(last.V_left + wedge));  // on the wall below the bed, from above
  const Eigen::Vector2d along(std::cos(theta), std::sin(theta)), normal(-std::sin(theta), std::cos(theta));
  const double ratio = std::abs(F.dot(along)) / -F.dot(normal);
  CHECK(ratio <= mu * (1 + kExact));
  CHECK(ratio >= mu * (1 - kLocatedCollapse));
}

TEST_CASE("spreading walls: a friction the walls and the arch never use gives the frictionless path, to the byte") {
  for (const Scene& scene : {segmental_on_walls(), on_walls(0.1, 1.0, 0.25)}) {
    SpreadOptions o;
    o.steps = 20;
    const SpreadResult a = analyse_spreading(scene, {}, o);
    const SpreadResult b = analyse_spreading(scene, with_friction(5.0), o);
    REQUIRE(a.status == SpreadStatus::success);
    REQUIRE(b.status == SpreadStatus::success);
    CHECK(b.collapse == a.collapse);
    CHECK(b.d_max == a.d_max);
    CHECK(b.left_wall_rotation == a.left_wall_rotation);
    CHECK(b.left_wall_top_displacement == a.left_wall_top_displacement);
    CHECK(b.message == a.message);
    REQUIRE(b.path.size() == a.path.size());
    for (std::size_t k = 0; k < a.path.size(); ++k) {
      CHECK(b.path[k].d == a.path[k].d);
      CHECK(b.path[k].H == a.path[k].H);
      CHECK(b.path[k].span_increase == a.path[k].span_increase);
    }
  }
}


TEST_CASE("spreading walls: the equilateral arch on walls converges in the joints") {
  // Its haunch hinges at d = 0 sit where the least-thrust line grazes the intrados; refined next to no
  // finer than kSpreadJointSpacing (a joint nearer that point touches the line as well), the path settles.
  for (const double t : {0.06, 0.1, 0.14}) {
    CAPTURE(t);
    Scene scene = paper_scene(0.5, t);
    const double L = scene.span();
    scene.left_wall = scene.right_wall = Wall{L, 0.25 * L, scene.material.density, 0.0, 0.5};
    LimitOptions coarse, fine;
    coarse.weight = fine.weight = WeightModel::axis;
    fine.joints_count = 401;
    const SpreadOptions o;
    const SpreadResult a = analyse_spreading(scene, coarse, o), b = analyse_spreading(scene, fine, o);
    CAPTURE(a.message);
    CAPTURE(b.message);
    REQUIRE(a.status == SpreadStatus::success);
    REQUIRE(b.status == SpreadStatus::success);
    CHECK(close(spread_capacity_ratio(a, o), spread_capacity_ratio(b, o), kSpreadCapacityTolerance));
  }
}
