// ogive spread on walls: the walls' lean at collapse, the path's rotation, the ground's rows unchanged by
// the walls' columns, and the refusal of what has no meaning on walls.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/spreading.hpp"
#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

TEST_CASE("cli: spread on walls gives each wall's lean at collapse, the library's") {
  const Run r = run_command({"spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--weight", "voussoir",
                             "--wall-height", "10", "--wall-thickness", "2.5"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(column(r.out, "collapse") == "wall_tips");
  CHECK(column(r.out, "message").find("left wall tips at its bed at y = -1 L") != std::string::npos);
  Scene s;
  s.curve = make_pointed(10.0, 0.0);
  s.thickness = 1.0;
  s.left_wall = s.right_wall = Wall{10.0, 2.5, s.material.density, 0.0, 0.5};
  const SpreadResult lib = analyse_spreading(s, {}, {});
  REQUIRE(lib.status == SpreadStatus::success);
  CHECK(close(std::stod(column(r.out, "left_wall_rotation_collapse")), lib.left_wall_rotation, kExact));
  CHECK(close(std::stod(column(r.out, "right_wall_top_displacement_collapse")), lib.right_wall_top_displacement, kExact));
  CHECK(close(std::stod(column(r.out, "spread_capacity_ratio")), lib.path.back().span_increase / 10.0, kExact));
  // The left wall alone leans: the right one's rotation 0.
  const Run left = run_command({"spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                                "--wall-thickness", "2.5", "--moving", "left", "--columns", "right_wall_rotation_collapse"});
  REQUIRE(left.status == 0);
  CHECK(column(left.out, "right_wall_rotation_collapse") == "0");
  // --path: the mechanism rows carry the rotation, the last one the collapse's.
  const Run path = run_command({"spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--weight", "voussoir",
                                "--wall-height", "10", "--wall-thickness", "2.5", "--path", "--steps", "4", "--columns",
                                "part,wall_rotation,collapse"});
  REQUIRE(path.status == 0);
  const std::size_t rows = 1 + 10 + 5;  // elastic, the cracking rows, the mechanism's
  CHECK(column(path.out, "part", rows) == "mechanism");
  CHECK(column(path.out, "collapse", rows) == "wall_tips");
  CHECK(close(std::stod(column(path.out, "wall_rotation", rows)), lib.left_wall_rotation, kExact));
  // The cracking rows: small rotations, no springing moving more than 1e-2 of the span.
  for (std::size_t row = 2; row <= 11; ++row) {
    CHECK(column(path.out, "part", row) == "cracking");
    const double theta = std::stod(column(path.out, "wall_rotation", row));
    CHECK(theta >= 0);
    CHECK(theta * 10.0 <= 1e-2 * 10.0 + 1e-12);  // h_w = L: the springing's outward movement
  }
}

TEST_CASE("cli: spread without walls prints no wall column unless asked") {
  const Run r = run_command({"spread", "--thickness-ratio", "0.08"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find("wall") == std::string::npos);
}

TEST_CASE("cli: spread on walls refuses what has no meaning there, one line and exit 2") {
  const std::vector<std::string> walls = {"spread", "--wall-height", "10", "--wall-thickness", "2.5"};
  for (const std::vector<std::string> extra :
       {std::vector<std::string>{"--left-settlement-share", "0.5"}, {"--right-settlement-share", "-1"}}) {
    std::vector<std::string> args = walls;
    args.insert(args.end(), extra.begin(), extra.end());
    check_refused(args);
  }
  // A finite strength is taken: the walls' beds are checked with their stress blocks.
  const Run crushing = run_command({"spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--weight", "voussoir",
                                    "--wall-height", "10", "--wall-thickness", "2.5", "--compressive-strength", "2MPa",
                                    "--columns", "status,collapse,message"});
  CHECK(crushing.status == 0);
  CHECK(column(crushing.out, "status") == "success");
  CHECK(column(crushing.out, "collapse") == "wall_tips");
  CHECK(column(crushing.out, "message").find("N / (2 f_c)") != std::string::npos);
  // A wall of no height under a horizontal springing joint has nothing to turn: that scene's row says so.
  const Run flat = run_command({"spread", "--wall-height", "0,10", "--wall-thickness", "2", "--columns", "status,message"});
  CHECK(flat.status == 3);
  CHECK(column(flat.out, "status", 1) == "invalid_scene");
  CHECK(column(flat.out, "message", 1).find("--wall-height") == 0);
  CHECK(column(flat.out, "status", 2) != "invalid_scene");
  // A moving springing without a wall under it.
  check_refused({"spread", "--left-wall-height", "10", "--left-wall-thickness", "2.5"});
  check_refused({"spread", "--left-wall-height", "10", "--left-wall-thickness", "2.5", "--moving", "right"});
}

TEST_CASE("cli: spread on walls with friction: the walls' beds slide as well as tip") {
  // The segmental arch's sloping springing joint puts a wedge of wall over the highest bed, whose
  // horizontal face carries the thrust as shear: with friction 0.6 the walls slide there first.
  const std::vector<std::string> scene = {"spread", "--curve", "segmental", "--thickness-ratio", "0.1", "--wall-height",
                                          "5", "--wall-thickness", "3"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = scene;
    args.insert(args.end(), extra.begin(), extra.end());
    return run_command(args);
  };
  const std::string columns = "status,collapse,spread_capacity_ratio,sliding_joint,left_wall_rotation_collapse,message";
  const Run sliding = with({"--friction", "0.6", "--columns", columns});
  const Run frictionless = with({"--columns", columns});
  REQUIRE(sliding.status == 0);
  REQUIRE(frictionless.status == 0);
  CHECK(column(sliding.out, "collapse") == "sliding");
  CHECK(column(sliding.out, "message").find("the left wall slides at its bed") == 0);
  CHECK(std::stod(column(sliding.out, "sliding_joint")) < 0);  // the left wall's bed, outside the span
  CHECK(column(frictionless.out, "collapse") == "wall_tips");
  CHECK(std::stod(column(sliding.out, "spread_capacity_ratio")) < std::stod(column(frictionless.out, "spread_capacity_ratio")));
  // A friction never reached: the frictionless path's rows, to the byte (but the friction column).
  const Run generous = with({"--friction", "5", "--path", "--steps", "5", "--columns", "part,spread_ratio,wall_rotation,H_over_V,hinges,collapse"});
  const Run plain = with({"--path", "--steps", "5", "--columns", "part,spread_ratio,wall_rotation,H_over_V,hinges,collapse"});
  REQUIRE(generous.status == 0);
  CHECK(generous.out == plain.out);
}

