// Arches on walls in the limit analysis (Scene::left_wall, right_wall; src/limit/walls.cpp): the
// buttress problem's public value, the arch's numbers on walls that do not limit it, mirror images,
// the growth of b_min, the virtual work of mechanisms with hinges in the walls, and misuse.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "limit/limit_internal.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The convergence the joints and beds are refined to (kLimitTolerance, limit.hpp).
constexpr double kConverged = kLimitTolerance;
// The static and kinematic multipliers of one mechanism: the same number computed twice.
constexpr double kVirtualWork = 1e-6;
// H_min and H_max just above b_min (the feasible end of a bracket of relative width 1e-10): the range
// has closed to this relative width.
constexpr double kRangeAtMinimum = 1e-5;
// The public value is given to four digits.
constexpr double kFourDigits = 0.5e-4 / 0.1678;

// The semicircle of span 10 m at t/L on walls of height h_w (in spans) and thickness b_w (in spans),
// of the arch's density.
Scene on_walls(double t_over_L, double height, double thickness, double eccentricity = 0.0) {
  Scene s = paper_scene(eccentricity, t_over_L);
  const double L = s.span();
  s.left_wall = s.right_wall = Wall{height * L, thickness * L, s.material.density, 0.0, 0.5};
  return s;
}

bool in_wall(const Ring& ring, int joint) { return joint < ring.left_springing() || joint > ring.right_springing(); }

}  // namespace

TEST_CASE("walls: the semicircle at t/L 0.10 on walls as high as the span needs b_min = 0.1678 L") {
  const Scene s = on_walls(0.10, 1.0, 0.3);
  const double L = s.span();
  const LimitResult r = analyse_limit(s, {});
  REQUIRE(r.status == LimitStatus::success);
  CHECK(close(r.wall_thickness_min / L, 0.1678, kFourDigits));
  // By hand: the arch's minimum-thrust state (H, V) crosses the springing joint at x_s; a wall of
  // thickness b (unit weight gamma, height h) on the point of tipping about its outer toe balances the
  // moments about the toe: H h = V (x_s - x_i + b) + gamma h b^2 / 2, x_i the inner face.
  const LimitResult arch = analyse_limit(paper_scene(0.0, 0.10), {});
  {
    const double H = arch.min_state.H, V = arch.min_state.V_left, x_s = arch.min_state.crossing.front().x();
    const double x_i = arch.ring.joints.front().intrados.x(), h = L, gamma = s.material.density * s.material.gravity;
    const double a = 0.5 * gamma * h, c = V * (x_s - x_i) - H * h;
    const double b = (-V + std::sqrt(V * V - 4 * a * c)) / (2 * a);
    CHECK(close(r.wall_thickness_min, b, kConverged));
  }
  // At that thickness the only state left is the arch's minimum-thrust state, and the walls tip about
  // their outer toes at the base.
  Scene least = s;
  least.left_wall->thickness = least.right_wall->thickness = r.wall_thickness_min * (1 + 1e-9);
  const LimitResult at = analyse_limit(least, {});
  REQUIRE(at.status == LimitStatus::success);
  CHECK(close(at.H_min(), arch.H_min(), kConverged));
  CHECK(close(at.H_max(), at.H_min(), kRangeAtMinimum));
  // The crossing of each base: at its outer toe, to the convergence in the joints (this analysis refines
  // its own ring).
  const std::size_t last = at.ring.joints.size() - 1;
  for (std::size_t base : {std::size_t{0}, last}) {
    const Joint& bed = at.ring.joints[base];
    CHECK(close(bed.extrados.y(), -L, kExact));
    CHECK((at.min_state.crossing[base] - bed.extrados).norm() <= kConverged * (bed.extrados - bed.intrados).norm());
  }
}

TEST_CASE("walls: walls of no height, or very thick ones, give the arch's own numbers") {
  const LimitResult arch = analyse_limit(paper_scene(0.0, 0.10), {});
  SUBCASE("no height: the same ring, the same numbers") {
    const LimitResult r = analyse_limit(on_walls(0.10, 0.0, 0.2), {});
    REQUIRE(r.status == LimitStatus::success);
    CHECK(r.ring.joints.size() == arch.ring.joints.size());
    CHECK(r.H_min() == arch.H_min());
    CHECK(r.H_max() == arch.H_max());
    CHECK(r.thickness_min == arch.thickness_min);
    CHECK(r.V == arch.V);
  }
  SUBCASE("walls five spans thick") {
    const LimitResult r = analyse_limit(on_walls(0.10, 1.0, 5.0), {});
    REQUIRE(r.status == LimitStatus::success);
    CHECK(close(r.H_min(), arch.H_min(), kConverged));
    CHECK(close(r.H_max(), arch.H_max(), kConverged));
    CHECK(close(r.thickness_min, arch.thickness_min, kConverged));
    CHECK(r.V == arch.V);  // the arch's loads: the walls' weight is not V
  }
  SUBCASE("walls five spans thick: the same collapse load factor and acceleration") {
    Scene loaded = paper_scene(0.0, 0.10);
    loaded.loads.points.push_back({50e3, 0.3});
    LimitOptions o;
    o.horizontal_load_factor = true;
    const LimitResult bare = analyse_limit(loaded, o);
    loaded.left_wall = loaded.right_wall = Wall{loaded.span(), 5.0 * loaded.span(), loaded.material.density, 0.0, 0.5};
    const LimitResult r = analyse_limit(loaded, o);
    REQUIRE(r.status == LimitStatus::success);
    CHECK(close(r.load_factor(), bare.load_factor(), kConverged));
    CHECK(close(r.horizontal_load_factor(), bare.horizontal_load_factor(), kConverged));
  }
}

TEST_CASE("walls: a symmetric system has mirrored hinges") {
  const Scene s = on_walls(0.10, 1.0, 0.1678 * 1.0001);
  const LimitResult r = analyse_limit(s, {});
  REQUIRE(r.status == LimitStatus::success);
  const int n = static_cast<int>(r.ring.joints.size());
  for (const ThrustState* st : {&r.min_state, &r.max_state}) {
    REQUIRE(!st->hinges.empty());
    for (const Hinge& h : st->hinges) {
      const bool mirrored = std::any_of(st->hinges.begin(), st->hinges.end(),
                                        [&](const Hinge& g) { return g.joint == n - 1 - h.joint && g.face == h.face; });
      CHECK(mirrored);
      CHECK(close(r.ring.joints[h.joint].intrados.y(), r.ring.joints[n - 1 - h.joint].intrados.y(), kExact));
    }
  }
}

TEST_CASE("walls: b_min grows with the wall's height and with a load on the arch") {
  double previous = 0;
  for (double height : {0.25, 0.5, 1.0, 2.0}) {
    const LimitResult r = analyse_limit(on_walls(0.10, height, 0.5), {});
    REQUIRE(r.status == LimitStatus::success);
    CHECK(r.wall_thickness_min > previous);
    previous = r.wall_thickness_min;
  }
  Scene loaded = on_walls(0.10, 1.0, 0.5);
  const double unloaded = analyse_limit(loaded, {}).wall_thickness_min;
  loaded.loads.points.push_back({50e3, 0.5});
  const LimitResult r = analyse_limit(loaded, {});
  REQUIRE(r.status == LimitStatus::success);
  CHECK(r.wall_thickness_min > unloaded);
}

TEST_CASE("walls: the collapse load factor and a_c equal the virtual work of their mechanisms, hinges in walls") {
  Scene s = on_walls(0.10, 1.0, 0.19);
  s.loads.points.push_back({20e3, 0.3});
  LimitOptions o;
  o.horizontal_load_factor = true;
  const LimitResult r = analyse_limit(s, o);
  REQUIRE(r.status == LimitStatus::success);
  REQUIRE(std::isfinite(r.load_factor()));
  CHECK(close(r.load_factor(), r.load_factor_mechanism, kVirtualWork));
  CHECK(close(mechanism_load_factor(r.ring, r.collapse_state.hinges), r.load_factor(), kVirtualWork));
  REQUIRE(std::isfinite(r.horizontal_load_factor()));
  CHECK(close(r.horizontal_load_factor(), r.horizontal_load_factor_mechanism, kVirtualWork));
  // Walls just above b_min: the mechanisms turn a wall.
  const auto walls_turn = [](const Ring& ring, const std::vector<Hinge>& hinges) {
    return std::any_of(hinges.begin(), hinges.end(), [&](const Hinge& h) { return in_wall(ring, h.joint); });
  };
  CHECK(walls_turn(r.ring, r.collapse_state.hinges));
  CHECK(walls_turn(r.horizontal_ring, r.horizontal_state.hinges));
  // The walls' mass is shaken too: the same walls without weight would let the arch take more.
  Scene light = s;
  light.left_wall->density = light.right_wall->density = 1.0;
  const LimitResult q = analyse_limit(light, o);
  CHECK(q.horizontal_load_factor() != r.horizontal_load_factor());
}

TEST_CASE("walls: converged in the joints and the beds") {
  const LimitResult coarse = analyse_limit(on_walls(0.10, 1.0, 0.3), {});
  LimitOptions fine;
  fine.joints_count = 801;
  const LimitResult r = analyse_limit(on_walls(0.10, 1.0, 0.3), fine);
  REQUIRE(coarse.status == LimitStatus::success);
  REQUIRE(r.status == LimitStatus::success);
  CHECK(close(coarse.wall_thickness_min, r.wall_thickness_min, 2 * kConverged));
  CHECK(close(coarse.thickness_min, r.thickness_min, 2 * kConverged));
}

TEST_CASE("walls: with friction b_min is converged in the joints where joints on their cones bound it") {
  // The segmental arch of rise L/4, t = 0.15 L, vertical joints, on walls 5 m high, friction 0.8: at
  // b_min the joints next to the springings are on their cones (they lie nearly along the thrust), and
  // friction rather than a margin ends the walls' search. The rings are refined next to them as next to
  // the hinges: b_min at the defaults is that of 6001 joints to the convergence in the joints.
  Scene s = paper_scene(0.0, 0.15);
  s.curve = make_segmental(10.0, 0.25);
  s.left_wall = s.right_wall = Wall{5.0, 5.0, s.material.density, 0.0, 0.5};
  LimitOptions o;
  o.friction = 0.8;
  o.joints = JointOrientation::vertical;
  const LimitResult r = analyse_limit(s, o);
  o.joints_count = 6001;
  const LimitResult fine = analyse_limit(s, o);
  REQUIRE(r.status == LimitStatus::success);
  REQUIRE(fine.status == LimitStatus::success);
  CHECK(close(r.wall_thickness_min, fine.wall_thickness_min, kConverged));
  // Friction bounds it: without friction the walls may be thinner.
  LimitOptions frictionless;
  frictionless.joints = JointOrientation::vertical;
  CHECK(analyse_limit(s, frictionless).wall_thickness_min < (1 - 10 * kConverged) * r.wall_thickness_min);
}

TEST_CASE("walls: a wall thinner than its springing joint, or below it, is refused naming the field") {
  auto refused = [](Scene s, const char* field) {
    try {
      s.validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).rfind(field, 0) == 0;
    }
    return false;
  };
  CHECK(refused(on_walls(0.10, 1.0, 0.05), "left_wall_thickness"));
  Scene s = on_walls(0.10, 1.0, 0.3);
  s.right_wall->height = -1.0;
  CHECK(refused(s, "right_wall_height"));
  s = on_walls(0.10, 1.0, 0.3);
  s.left_wall->top_load_at = 1.5;
  CHECK(refused(s, "left_wall_top_load_at"));
  s = on_walls(0.10, 1.0, 0.3);
  s.left_wall->density = -1;
  CHECK(refused(s, "left_wall_density"));
  // A segmental arch's springing joint is inclined: its lower end lies below the springing line, and
  // a wall must reach it.
  Scene seg = paper_scene(0.0, 0.10);
  seg.curve = make_segmental(10.0, 0.25);
  seg.left_wall = Wall{0.0, 3.0, 2000.0, 0.0, 0.5};
  CHECK(refused(seg, "left_wall_height"));
  seg.left_wall->height = 2.0;
  CHECK_NOTHROW(seg.validate());
  CHECK(analyse_limit(seg, {}).status == LimitStatus::success);
}

TEST_CASE("walls: a rampant arch on walls of different heights, each from its own springing") {
  std::vector<std::pair<double, double>> xy;
  for (int k = 0; k <= 80; ++k) {
    const double x = 10.0 * k / 80;
    xy.emplace_back(x, 0.2 * x + 20.0 * (x / 10) * (1 - x / 10));  // the right springing 2 m higher
  }
  Scene s = paper_scene(0.0, 0.06);
  s.curve = make_whole_points_curve(xy);
  s.left_wall = Wall{6.0, 2.0, s.material.density, 0.0, 0.5};
  s.right_wall = Wall{4.0, 2.0, s.material.density, 0.0, 0.5};
  const LimitResult r = analyse_limit(s, {});
  REQUIRE(r.status == LimitStatus::success);
  // The bases: 6 m below the left springing, 4 m below the right one (at y = 2 m).
  CHECK(close(r.ring.joints.front().intrados.y(), -6.0, kExact));
  CHECK(close(r.ring.joints.back().intrados.y(), -2.0, kExact));
  // Walls that do not limit the arch: its own thrust range; b_min below the walls given.
  Scene bare = s;
  bare.left_wall.reset();
  bare.right_wall.reset();
  const LimitResult arch = analyse_limit(bare, {});
  CHECK(close(r.H_min(), arch.H_min(), kConverged));
  CHECK(close(r.H_max(), arch.H_max(), kConverged));
  CHECK(r.wall_thickness_min < 2.0);
}

TEST_CASE("walls: on walls thinner than b_min the system does not stand, and t_min is searched only on arches the walls carry") {
  const Scene s = on_walls(0.08, 1.0, 0.12);  // t = 0.8 m on walls 1.2 m thick, b_min = 1.66 m
  const LimitResult r = analyse_limit(s, {});
  CHECK(r.status == LimitStatus::inadmissible);
  CHECK(r.wall_thickness_min > 0.12 * s.span());
  CHECK(r.message.find("thinner than b_min") != std::string::npos);
  // No arch up to 1.2 m thick (a springing joint as wide as the walls) stands on them.
  CHECK(std::isnan(r.thickness_min));
  CHECK(r.message.find("up to 1.2 m") != std::string::npos);
}
