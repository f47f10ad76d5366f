// The walls' lean (--wall-lean, --left-wall-lean, --right-wall-lean): the springing's movement of a wall's
// rigid rotation about its base's outer toe, checked by hand and against a rigid motion of the whole arch;
// the lean is the same scene as the explicit movement options it stands for; no lean changes nothing; the
// cracking arch on leaning walls; bad input refused.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "ogive/solve/solve.hpp"
#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

// Two routes to one scene whose springing movements differ in their last bits (a lean's movement in
// metres against a ratio printed and read back, times the span): the reactions agree to round-off times
// the system's condition.
constexpr double kSameMovement = 1e-12;
// The forces of a rigid motion of the whole arch, against those of the arch held still: none but
// round-off, which the motion's own forces would dwarf (a movement of 1e-3 L in one springing alone
// changes H by a multiple of itself).
constexpr double kRigidMotion = 1e-9;

// The semicircle of span 10 m, t = 1 m, on walls 10 m high and 2.5 m thick: its springing joints are
// horizontal, from x = 0.5 m to -0.5 m on the left (x = 9.5 m to 10.5 m on the right).
Scene semicircle_on_walls() {
  Scene s;
  s.curve = make_pointed(10.0, 0.0);
  s.thickness = 1.0;
  s.left_wall = s.right_wall = Wall{10.0, 2.5, s.material.density, 0.0, 0.5};
  return s;
}

const std::vector<std::string> kWalls = {"--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                                         "--wall-thickness", "2.5"};
const char* const kReactions[] = {"H_left", "V_left", "M_left", "H_right", "V_right", "M_right"};

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

double number(const std::string& csv, const char* name, std::size_t row = 1) {
  return std::stod(column(csv, name, row));
}

}  // namespace

TEST_CASE("wall lean: the springing moves by the wall's rigid rotation about its outer toe, by hand") {
  const Scene s = semicircle_on_walls();
  const double lean = 0.002;
  // The left wall: its inner face at x = 0.5 m, its outer toe at T = (0.5 - 2.5, -10) = (-2, -10). An
  // outward lean turns it counter-clockwise by `lean`: the springing's axis point p = (0, 0) moves by
  // lean (-(p_y - T_y), p_x - T_x) = lean (-10, 2) m: out by 0.02 m, up by 0.004 m.
  const Support left = wall_lean_movement(wall_outline(*s.curve, s.thickness, *s.left_wall, false), lean,
                                          SupportKind::clamped);
  CHECK(close(left.spread, lean * 10.0, kExact));
  CHECK(close(left.settlement, -lean * 2.0, kExact));
  CHECK(left.rotation == lean);
  // The right wall: its toe at T = (9.5 + 2.5, -10) = (12, -10), p = (10, 0); an outward lean turns it
  // clockwise: p moves by -lean (-(p_y - T_y), p_x - T_x) = lean (10, 2) m, out (+x) and up.
  const Support right = wall_lean_movement(wall_outline(*s.curve, s.thickness, *s.right_wall, true), lean,
                                           SupportKind::clamped);
  CHECK(close(right.spread, lean * 10.0, kExact));
  CHECK(close(right.settlement, -lean * 2.0, kExact));
  CHECK(right.rotation == -lean);
  // A pinned springing translates alike and turns freely: no rotation given. An inward lean reverses it all.
  const Support pinned = wall_lean_movement(wall_outline(*s.curve, s.thickness, *s.left_wall, false), -lean,
                                            SupportKind::pinned);
  CHECK(pinned.kind == SupportKind::pinned);
  CHECK(close(pinned.spread, -lean * 10.0, kExact));
  CHECK(close(pinned.settlement, lean * 2.0, kExact));
  CHECK(pinned.rotation == 0);
  CHECK_THROWS_AS(wall_lean_movement(wall_outline(*s.curve, s.thickness, *s.left_wall, false), std::nan(""),
                                     SupportKind::clamped),
                  std::invalid_argument);
  // A segmental arch's inclined springing joint: the motion is still a rotation about the toe, of length
  // |lean| |p - T| and square to p - T.
  Scene seg = s;
  seg.curve = make_segmental(10.0, 0.25);
  const WallOutline o = wall_outline(*seg.curve, seg.thickness, *seg.right_wall, true);
  const Support m = wall_lean_movement(o, lean, SupportKind::clamped);
  const Eigen::Vector2d arm = o.joint.axis - Eigen::Vector2d(o.outer_x, o.base_y);
  const Eigen::Vector2d u(m.spread, -m.settlement);  // +x is outwards on the right
  CHECK(close(u.norm(), lean * arm.norm(), kExact));
  CHECK(std::abs(u.dot(arm)) <= kExact * u.norm() * arm.norm());
  CHECK(close(m.spread, lean * seg.right_wall->height, kExact));
}

TEST_CASE("wall lean: the arch turned rigidly with the left wall carries the forces of the arch held still") {
  // The left wall leans; the right springing is moved as the same rigid rotation about the left toe
  // moves it: the whole arch turns as a rigid body, which strains nothing, so every reaction is the
  // unmoved arch's. This checks the lean's movement against the beam model's own conventions (spread
  // outwards, settlement downwards, rotation counter-clockwise), elastic and no-tension, clamped.
  for (const SectionKind section : {SectionKind::elastic, SectionKind::no_tension}) {
    CAPTURE(static_cast<int>(section));
    Scene still = semicircle_on_walls();
    still.section = section;
    const double lean = 1e-3;
    Scene turned = still;
    const WallOutline left = wall_outline(*still.curve, still.thickness, *still.left_wall, false);
    turned.left = wall_lean_movement(left, lean, SupportKind::clamped);
    const Eigen::Vector2d toe(left.outer_x, left.base_y), p_right(10.0, 0.0);
    const Eigen::Vector2d u = lean * Eigen::Vector2d(-(p_right - toe).y(), (p_right - toe).x());
    turned.right = {SupportKind::clamped, u.x(), -u.y(), lean};
    // The same movement of the right springing alone: large forces (what the rigid motion cancels).
    Scene strained = still;
    strained.right = turned.right;
    Options o;
    o.rtol = 1e-10;
    const Solution a = solve(still, o), b = solve(turned, o), c = solve(strained, o);
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    const double scale = std::abs(a.reactions.V_left);
    CHECK(std::abs(b.reactions.H_left - a.reactions.H_left) <= kRigidMotion * scale);
    CHECK(std::abs(b.reactions.V_left - a.reactions.V_left) <= kRigidMotion * scale);
    CHECK(std::abs(b.reactions.M_left - a.reactions.M_left) <= kRigidMotion * scale * 10.0);
    CHECK(std::abs(b.reactions.H_right - a.reactions.H_right) <= kRigidMotion * scale);
    CHECK(std::abs(b.reactions.M_right - a.reactions.M_right) <= kRigidMotion * scale * 10.0);
    if (section == SectionKind::elastic) {
      REQUIRE(c.ok());
      CHECK(std::abs(c.reactions.H_left - a.reactions.H_left) > 0.1 * std::abs(a.reactions.H_left));
    }
  }
}

TEST_CASE("cli: a wall's lean is the springing movement it stands for") {
  // The left wall of kWalls leans by 0.002: by hand (the first case), its springing moves out by
  // 0.002 x 10 m, up by 0.002 x 2 m and turns by 0.002; over the 10 m span the explicit options are
  // --left-spread-ratio 0.002 --left-settlement-ratio -0.0004 (--left-rotation 0.002 when clamped).
  const std::vector<std::string> columns = {"--columns", "H_left,V_left,M_left,H_right,V_right,M_right"};
  for (const char* supports : {"clamped", "pinned"})
    for (const char* section : {"elastic", "no-tension"}) {
      CAPTURE(supports);
      CAPTURE(section);
      const std::vector<std::string> base = with(with({"thrust"}, kWalls), {"--supports", supports, "--section", section});
      const Run lean = run_command(with(with(base, {"--left-wall-lean", "0.002"}), columns));
      std::vector<std::string> given = {"--left-spread-ratio", "0.002", "--left-settlement-ratio", "-0.0004"};
      if (std::string(supports) == "clamped") given.insert(given.end(), {"--left-rotation", "0.002"});
      const Run explicit_ = run_command(with(with(base, given), columns));
      REQUIRE(lean.status == 0);
      REQUIRE(explicit_.status == 0);
      for (const char* c : kReactions) {
        CAPTURE(c);
        CHECK(close(number(lean.out, c), number(explicit_.out, c), kSameMovement));
      }
      // The lean moves the reactions (a spread lowers H).
      const Run plumb = run_command(with(base, columns));
      CHECK(number(lean.out, "H_left") < number(plumb.out, "H_left"));
      // The columns the lean adds by default: the movement it causes, as given above.
      const Run shown = run_command(with(base, {"--left-wall-lean", "2mm/m"}));
      REQUIRE(shown.status == 0);
      CHECK(close(number(shown.out, "left_lean_spread_ratio"), 0.002, kExact));
      CHECK(close(number(shown.out, "left_lean_settlement_ratio"), -0.0004, kExact));
      CHECK(number(shown.out, "left_lean_rotation") == (std::string(supports) == "clamped" ? 0.002 : 0.0));
      CHECK(number(shown.out, "right_lean_spread_ratio") == 0);
    }
  // Both walls leaning, over an explicit spread: the movements add (a symmetric scene, solved on its half).
  const std::vector<std::string> base = with({"thrust"}, kWalls);
  const Run both = run_command(with(base, {"--wall-lean", "0.001", "--support-displacement-ratio", "0.0005",
                                           "--columns", "domain,H_left,V_left,M_left,H_right,V_right,M_right"}));
  const Run sides = run_command(with(base, {"--left-spread-ratio", "0.0015", "--right-spread-ratio", "0.0015",
                                            "--left-settlement-ratio", "-0.0002", "--right-settlement-ratio", "-0.0002",
                                            "--left-rotation", "0.001", "--right-rotation", "-0.001", "--columns",
                                            "domain,H_left,V_left,M_left,H_right,V_right,M_right"}));
  REQUIRE(both.status == 0);
  REQUIRE(sides.status == 0);
  CHECK(column(both.out, "domain") == "half");
  for (const char* c : kReactions) {
    CAPTURE(c);
    CHECK(close(number(both.out, c), number(sides.out, c), kSameMovement));
  }
}

TEST_CASE("cli: no lean, or a lean of 0, changes no output") {
  const std::string columns = "H,V,H_over_V,H_left,M_left,H_right,M_right,left_wall_base_eccentricity,"
                              "right_wall_stability_ratio,status,error_estimate";
  for (const char* section : {"elastic", "no-tension"})
    for (const char* supports : {"clamped", "pinned"}) {
      const std::vector<std::string> base =
          with(with({"thrust"}, kWalls), {"--section", section, "--supports", supports, "--support-displacement-ratio",
                                          "0.001", "--columns", columns});
      const Run none = run_command(base);
      const Run zero = run_command(with(base, {"--wall-lean", "0", "--right-wall-lean", "0"}));
      REQUIRE(none.status == 0);
      CHECK(zero.out == none.out);
    }
}

TEST_CASE("cli: the cracking arch on leaning walls: H falls as they lean outwards, and its hinges form") {
  const Run r = run_command(with(with({"thrust"}, kWalls), {"--section", "no-tension", "--wall-lean",
                                                            "0,1e-4,3e-4,1e-3,3e-3", "--columns",
                                                            "wall_lean,status,H_over_V,max_thrust_eccentricity"}));
  REQUIRE(r.status == 0);
  // The floor: the least thrust of the arch of rigid voussoirs with the cracking arch's weight (on the axis).
  Scene rigid = semicircle_on_walls();
  rigid.left_wall.reset();
  rigid.right_wall.reset();
  LimitOptions lo;
  lo.weight = WeightModel::axis;
  const LimitResult limit = analyse_limit(rigid, lo);
  REQUIRE(limit.status == LimitStatus::success);
  const double floor = limit.H_min() / limit.V;
  double previous = INFINITY;
  for (std::size_t row = 1; row <= 5; ++row) {
    CAPTURE(row);
    CHECK(column(r.out, "status", row) == "success");
    const double h = number(r.out, "H_over_V", row);
    CHECK(h < previous);
    CHECK(h >= floor * (1 - 1e-6));
    previous = h;
  }
  // At a lean of 3e-3 (the springings out by 0.3 % of the span): within 3 % of the floor, the resultant
  // at the section's face somewhere (|e| near 300 %: a hinge).
  CHECK(previous <= floor * 1.03);
  CHECK(number(r.out, "max_thrust_eccentricity", 5) > 290);
  CHECK(number(r.out, "max_thrust_eccentricity", 1) < number(r.out, "max_thrust_eccentricity", 5));
  // The hinges, from the profile of the library's scene (the lean's movement at both springings): the
  // compressed depth falls to a small part of t at the crown and at both haunches, the spreading arch's
  // three hinges.
  Scene s = semicircle_on_walls();
  s.section = SectionKind::no_tension;
  s.left = wall_lean_movement(wall_outline(*s.curve, s.thickness, *s.left_wall, false), 3e-3, SupportKind::clamped);
  s.right = wall_lean_movement(wall_outline(*s.curve, s.thickness, *s.right_wall, true), 3e-3, SupportKind::clamped);
  Options o;
  o.stations = 201;
  const Solution sol = solve(s, o);
  REQUIRE(sol.ok());
  CHECK(close(sol.H_over_V, previous, 1e-6));
  // The least compressed depth in the crown's third and in each outer third.
  double crown = 1, left = 1, right = 1;
  for (const ArchState& st : sol.profile) {
    const double x = st.x / 10.0;
    double& zone = x < 1.0 / 3 ? left : x > 2.0 / 3 ? right : crown;
    zone = std::min(zone, st.compressed_depth);
  }
  CHECK(crown < 0.1);
  CHECK(left < 0.1);
  CHECK(right < 0.1);
}

TEST_CASE("cli: a bad lean gets one line and exit 2") {
  const std::vector<std::string> base = with({"thrust"}, kWalls);
  check_refused({"thrust", "--wall-lean", "0.001"});  // no wall
  check_refused({"thrust", "--right-wall-height", "10", "--wall-thickness", "2.5", "--left-wall-lean", "0.001"});
  check_refused(with(base, {"--wall-lean", "nan"}));
  check_refused(with(base, {"--wall-lean", "inf"}));
  check_refused(with(base, {"--wall-lean", "0.02"}));  // beyond the small-displacement rule
  check_refused(with(base, {"--wall-lean", "2kg"}));
  // The sum of the lean's movement and the options' keeps their rule: 0.008 + 0.004 of the span.
  const Run sum = run_command(with(base, {"--left-wall-lean", "0.008", "--left-spread-ratio", "0.004"}));
  CHECK(sum.status == 2);
  CHECK(sum.out.empty());
  CHECK(lines(sum.err).size() == 1);
  CHECK(sum.err.find("--left-wall-lean") != std::string::npos);
  CHECK(sum.err.find("--left-spread-ratio") != std::string::npos);
  // A lean of 0.005 on walls three spans high moves the springings by 0.015 of the span: named by the
  // option that gave it.
  const Run tall = run_command({"thrust", "--wall-height", "30", "--wall-thickness", "5", "--wall-lean", "0.005"});
  CHECK(tall.status == 2);
  CHECK(tall.out.empty());
  CHECK(tall.err.starts_with("ogive: --wall-lean: the left springing's spread"));
  // The rotation's sum too (clamped).
  check_refused(with(base, {"--right-wall-lean", "-0.006", "--right-rotation", "0.006"}));
  // The analyses that take the walls as built, or move the springings themselves.
  for (const char* command : {"limit", "assess", "spread"}) check_refused(with({command}, with(kWalls, {"--wall-lean", "0.001"})));
  check_refused(with({"draw"}, with(kWalls, {"--wall-lean", "0.001", "--spread-stage", "0.5", "--output", "x.svg"})));
  check_refused({"profile", "--wall-height", "10", "--wall-thickness", "2.5", "--wall-lean", "0.001"});
}
