// The walls' options (--wall-..., --left-wall-..., --right-wall-...): limit's wall_thickness_min and
// hinges in walls, the two forms of each option, sweeps, units, and the refusal of bad input.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ogive/geometry/curve_families.hpp"
#include "ogive/limit/limit.hpp"
#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {
// The static and kinematic multipliers of one mechanism: the same number computed twice.
constexpr double kVirtualWork = 1e-6;
}  // namespace

TEST_CASE("cli: limit on walls prints wall_thickness_min and the hinges at the walls' beds") {
  const Run r = run_command({"limit", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                             "--wall-thickness", "1.6780,1.6", "--columns", "status,wall_thickness_min,hinges_min"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  CHECK(column(r.out, "status", 1) == "success");
  CHECK(column(r.out, "status", 2) == "inadmissible");
  // The library's b_min, whatever the walls given.
  Scene s;
  s.curve = make_pointed(10.0, 0.0);
  s.thickness = 1.0;
  s.left_wall = s.right_wall = Wall{10.0, 3.0, s.material.density, 0.0, 0.5};
  const double b_min = analyse_limit(s, {}).wall_thickness_min;
  for (std::size_t row : {1u, 2u}) CHECK(close(std::stod(column(r.out, "wall_thickness_min", row)), b_min, kLimitTolerance));
  // A load on the arch: the collapse mechanism tips the far wall about its outer toe at the base (y = -h_w).
  const Run c = run_command({"limit", "--wall-height", "10", "--wall-thickness", "2", "--point-load", "50kN",
                             "--point-load-at", "0.3", "--columns", "load_factor,load_factor_mechanism,hinges_collapse"});
  REQUIRE(c.status == 0);
  CHECK(close(std::stod(column(c.out, "load_factor")), std::stod(column(c.out, "load_factor_mechanism")), kVirtualWork));
  CHECK(column(c.out, "hinges_collapse").find("wall-outer@-1") != std::string::npos);
}

TEST_CASE("cli: one wall's option over both walls', kN and metres") {
  const Run both = run_command({"limit", "--wall-height", "8", "--wall-thickness", "2", "--wall-top-load", "20kN",
                                "--all-columns"});
  const Run sides = run_command({"limit", "--left-wall-height", "800cm", "--right-wall-height", "8",
                                 "--left-wall-thickness", "2", "--right-wall-thickness", "2", "--left-wall-top-load",
                                 "20000", "--right-wall-top-load", "20000", "--all-columns"});
  REQUIRE(both.status == 0);
  REQUIRE(sides.status == 0);
  for (const char* c : {"H_min", "H_max", "thickness_min_ratio", "wall_thickness_min", "left_wall_density",
                        "right_wall_top_load", "left_wall_top_load_at"})
    CHECK(column(both.out, c) == column(sides.out, c));
  CHECK(column(both.out, "left_wall_density") == "2348");
  // The right wall's own option wins over both walls'.
  const Run lopsided = run_command({"limit", "--wall-height", "8", "--wall-thickness", "2", "--right-wall-thickness",
                                    "5", "--columns", "left_wall_thickness,right_wall_thickness"});
  REQUIRE(lopsided.status == 0);
  CHECK(column(lopsided.out, "left_wall_thickness") == "2");
  CHECK(column(lopsided.out, "right_wall_thickness") == "5");
  // Walls of no height: the arch's own numbers.
  const Run none = run_command({"limit", "--columns", "H_min,H_max,thickness_min_ratio"});
  const Run flat = run_command({"limit", "--wall-height", "0", "--wall-thickness", "2", "--columns",
                                "H_min,H_max,thickness_min_ratio"});
  CHECK(none.out == flat.out);
}

TEST_CASE("cli: a sweep of wall heights gives b_min growing with the height") {
  const Run r = run_command({"limit", "--wall-height", "2:20:4", "--wall-thickness", "3", "--columns",
                             "wall_height,wall_thickness_min"});
  REQUIRE(r.status == 0);
  double previous = 0;
  for (std::size_t row = 1; row <= 4; ++row) {
    const double b = std::stod(column(r.out, "wall_thickness_min", row));
    CHECK(b > previous);
    previous = b;
  }
}

TEST_CASE("cli: bad wall input gets one line and exit 2") {
  check_refused({"limit", "--wall-height", "-1", "--wall-thickness", "2"});
  check_refused({"limit", "--wall-height", "5"});                       // no thickness
  check_refused({"limit", "--wall-thickness", "2"});                    // no height
  check_refused({"limit", "--left-wall-density", "2000"});              // no left height
  check_refused({"limit", "--right-wall-height", "5", "--left-wall-thickness", "2", "--right-wall-thickness", "2"});
  check_refused({"limit", "--wall-height", "5", "--wall-thickness", "0.5"});  // thinner than the springing joint
  check_refused({"limit", "--wall-height", "5", "--wall-thickness", "2", "--wall-top-load-at", "1.5"});
  check_refused({"limit", "--wall-height", "5", "--wall-thickness", "2", "--wall-top-load", "-3"});
  check_refused({"limit", "--wall-height", "5kg", "--wall-thickness", "2"});
  check_refused({"limit", "--wall-height", "1e308", "--wall-thickness", "2"});  // beyond 100 spans
  check_refused({"thrust", "--wall-height", "5", "--wall-thickness", "1e300"});
  check_refused({"limit", "--wall-height", "5", "--wall-thickness", "2", "--wall-density", "1e12"});  // too heavy
  check_refused({"limit", "--curve", "segmental", "--wall-height", "0", "--wall-thickness", "3"});  // below the joint
  for (const char* command : {"profile", "check", "curve", "bench"})
    check_refused({command, "--wall-height", "5", "--wall-thickness", "2"});
}

TEST_CASE("cli: assess and report on walls") {
  // Walls thinner than b_min: no arch thickness stands on them, a geometric factor of 0 that fails.
  const Run thin = run_command({"assess", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                                "--wall-thickness", "1.5", "--columns", "verdict,governing,geometric_safety_factor,message"});
  CHECK(thin.status == 0);
  CHECK(column(thin.out, "verdict") == "fail");
  CHECK(column(thin.out, "geometric_safety_factor") == "0");
  CHECK(column(thin.out, "message").find("thinner than b_min") != std::string::npos);
  // Walls that stand: the arch's t / t_min on them, as limit gives it; the spreading capacity is the
  // walls' lean to collapse, spread's span increase (not d times the shares: the walls turn).
  const Run thick = run_command({"assess", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                                 "--wall-thickness", "2", "--require-spread", "0.01", "--columns",
                                 "geometric_safety_factor,thickness_min_ratio,spread_capacity_ratio,"
                                 "spread_capacity_ratio_outcome,message"});
  CHECK(thick.status == 0);  // a verdict: t / t_min = 1.86 fails the default 2, whatever the spreading
  const Run lim = run_command({"limit", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                               "--wall-thickness", "2", "--columns", "thickness_min_ratio"});
  CHECK(column(thick.out, "thickness_min_ratio") == column(lim.out, "thickness_min_ratio"));
  const Run spread = run_command({"spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--weight", "voussoir",
                                  "--wall-height", "10", "--wall-thickness", "2", "--columns",
                                  "spread_capacity_ratio,left_wall_rotation_collapse,left_wall_top_displacement_collapse"});
  REQUIRE(spread.status == 0);
  CHECK(column(thick.out, "spread_capacity_ratio") == column(spread.out, "spread_capacity_ratio"));
  CHECK(column(thick.out, "spread_capacity_ratio_outcome") == "pass");  // 0.033 >= 0.01
  CHECK(column(thick.out, "message").find("spread") == std::string::npos);
  // Asked for more than the walls give: the spreading criterion fails, with its margin.
  const Run more = run_command({"assess", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                                "--wall-thickness", "2", "--require-geometric-factor", "1.5", "--require-spread", "0.05",
                                "--columns", "verdict,governing,margin"});
  CHECK(column(more.out, "verdict") == "fail");
  CHECK(column(more.out, "governing") == "spread_capacity_ratio");
  CHECK(close(std::stod(column(more.out, "margin")), std::stod(column(spread.out, "spread_capacity_ratio")) / 0.05, kExact));
  // A wall on one side only: that wall leans, the other springing stands on the ground.
  const Run one = run_command({"assess", "--curve", "semicircular", "--thickness-ratio", "0.1", "--left-wall-height",
                               "10", "--left-wall-thickness", "2.5", "--require-spread", "0.01", "--columns",
                               "spread_capacity_ratio,spread_capacity_ratio_outcome"});
  const Run one_spread = run_command({"spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--weight",
                                      "voussoir", "--left-wall-height", "10", "--left-wall-thickness", "2.5", "--moving",
                                      "left", "--columns", "spread_capacity_ratio"});
  CHECK(column(one.out, "spread_capacity_ratio_outcome") == "pass");
  CHECK(column(one.out, "spread_capacity_ratio") == column(one_spread.out, "spread_capacity_ratio"));
  // With a finite compressive strength: spread's path on walls with it (the beds' stress blocks checked).
  const Run crushing = run_command({"assess", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height",
                                    "10", "--wall-thickness", "2", "--require-spread", "0.01", "--compressive-strength",
                                    "20MPa", "--columns", "spread_capacity_ratio,spread_capacity_ratio_outcome"});
  const Run crushing_spread = run_command({"spread", "--curve", "semicircular", "--thickness-ratio", "0.1", "--weight",
                                           "voussoir", "--wall-height", "10", "--wall-thickness", "2",
                                           "--compressive-strength", "20MPa", "--columns", "spread_capacity_ratio"});
  CHECK(column(crushing.out, "spread_capacity_ratio_outcome") == "pass");
  CHECK(column(crushing.out, "spread_capacity_ratio") == column(crushing_spread.out, "spread_capacity_ratio"));
  CHECK(column(crushing.out, "spread_capacity_ratio") != column(spread.out, "spread_capacity_ratio"));
  // The report draws the walls, the elastic resultant down them, and gives b_min beside each wall.
  const Run page = run_command({"report", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                                "--wall-thickness", "2", "--output", "-"});
  CHECK(page.status == 0);
  for (const char* part : {"id=\"wall-left\"", "id=\"wall-right\"", "wall-resultant-left", "wall-resultant-right",
                           "least wall thickness b<sub>min</sub>"})
    CHECK(page.out.find(part) != std::string::npos);
  // Where the report gives the spreading capacity on walls, it gives the walls' lean at collapse too.
  CHECK(page.out.find("id=\"walls-lean\"") == std::string::npos);  // not required: no capacity, no lean
  const Run spreading = run_command({"report", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height",
                                     "10", "--wall-thickness", "2", "--require-spread", "0.01", "--output", "-"});
  REQUIRE(spreading.status == 0);
  const std::size_t lean = spreading.out.find("id=\"walls-lean\"");
  REQUIRE(lean != std::string::npos);
  const std::string rotation = column(spread.out, "left_wall_rotation_collapse");
  const std::string top = column(spread.out, "left_wall_top_displacement_collapse");
  CHECK(spreading.out.find("data-value=\"" + rotation + "\"", lean) != std::string::npos);
  CHECK(spreading.out.find("data-value=\"" + top + "\"", lean) != std::string::npos);
}

TEST_CASE("cli: a wall's refusal names the option the value came by") {
  // Both walls from --wall-thickness: the message names it, not a side's option the user did not give.
  const Run shared = run_command({"limit", "--wall-height", "5", "--wall-thickness", "0.5"});
  CHECK(shared.status == 2);
  CHECK(shared.out.empty());
  CHECK(shared.err.starts_with("ogive: --wall-thickness: must be at least"));
  // A side's own option is named when it is the one given.
  const Run side = run_command({"limit", "--wall-height", "5", "--wall-thickness", "2", "--left-wall-thickness", "0.5"});
  CHECK(side.status == 2);
  CHECK(side.err.starts_with("ogive: --left-wall-thickness: must be at least"));
  const Run at = run_command({"limit", "--wall-height", "5", "--wall-thickness", "2", "--wall-top-load-at", "1.5"});
  CHECK(at.err.starts_with("ogive: --wall-top-load-at: must lie in [0, 1]"));
}

TEST_CASE("cli: thrust on walls prints each wall's resultant, elastic and cracked alike") {
  for (const char* section : {"elastic", "no-tension"}) {
    CAPTURE(section);
    const Run r = run_command({"thrust", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                               "--wall-thickness", "2", "--section", section});
    REQUIRE(r.status == 0);
    // Five crossings from the springing line down to the base, at y/L = -1.
    const std::string crossings = column(r.out, "left_wall_crossings");
    CHECK(std::count(crossings.begin(), crossings.end(), ';') == 4);
    CHECK(crossings.find(";-1:") != std::string::npos);
    // A symmetric scene: the walls' numbers are each other's.
    CHECK(close(std::stod(column(r.out, "left_wall_stability_ratio")),
                std::stod(column(r.out, "right_wall_stability_ratio")), kExact));
    CHECK(std::stod(column(r.out, "left_wall_geometric_factor")) > 0);
  }
  // Without walls the columns are not printed by default.
  const Run plain = run_command({"thrust"});
  CHECK(plain.out.find("wall") == std::string::npos);
}

TEST_CASE("cli: draw on walls shows the walls, the limit lines and the elastic resultant down to the bases") {
  const Run r = run_command({"draw", "--curve", "semicircular", "--thickness-ratio", "0.1", "--wall-height", "10",
                             "--wall-thickness", "2", "--limit", "--output", "-"});
  REQUIRE(r.status == 0);
  for (const char* id : {"wall-left", "wall-right", "ground-left", "thrust-line-min", "wall-resultant-left",
                         "wall-resultant-right"})
    CHECK(r.out.find(std::string("id=\"") + id + "\"") != std::string::npos);
}
