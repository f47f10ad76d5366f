// `ogive draw`: the SVG is well-formed (xmllint) and to scale: its thrust line is the profile's point by
// point, --limit's lines are ogive limit's joint by joint with the hinges circled, the faces lie at t/2
// from the axis; one file per scene with --output-dir; bad targets refused; an unsolved scene drawn
// without a thrust line; a thrust line that runs off split where it leaves the drawing.
#include <doctest/doctest.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ogive/output/svg.hpp"
#include "support/cli_run.hpp"
#include "support/files.hpp"
#include "support/tolerances.hpp"

using namespace ogive::test;

namespace {

// The points of the SVG path with the given id, in the arch's metres: SVG (x, -y) times the drawing's
// unit (data-metres-per-unit) back to (x, y). Each subpath ("M") is one run; the drawing writes
// "M x,y L x,y ..." (include/ogive/output/svg.hpp).
std::vector<std::vector<std::pair<double, double>>> svg_path_points(const std::string& svg, const std::string& id) {
  const std::size_t unit_at = svg.find("data-metres-per-unit=\"");
  REQUIRE(unit_at != std::string::npos);
  const double unit = std::stod(svg.substr(unit_at + 22));
  const std::size_t at = svg.find("id=\"" + id + "\"");
  REQUIRE_MESSAGE(at != std::string::npos, "no element " << id);
  const std::size_t d = svg.find(" d=\"", at) + 4;
  std::istringstream in(svg.substr(d, svg.find('"', d) - d));
  std::vector<std::vector<std::pair<double, double>>> runs;
  for (std::string command, xy; in >> command >> xy;) {
    REQUIRE((command == "M" || command == "L"));
    if (command == "M") runs.emplace_back();
    const std::size_t comma = xy.find(',');
    runs.back().emplace_back(unit * std::stod(xy.substr(0, comma)), -unit * std::stod(xy.substr(comma + 1)));
  }
  return runs;
}

bool xmllint_accepts(const std::string& path) {
  return std::system(("xmllint --noout '" + path + "' 2>/dev/null").c_str()) == 0;
}

}  // namespace

TEST_CASE("draw: the SVG is well-formed and its thrust line is the profile's, point by point") {
  TempDir dir("ogive_test_draw");
  // Closed form, CVODE shooting on a smooth curve, spreading supports, a pointed crown, a model arch
  // of 5 mm drawn in units of 1 mm.
  const std::vector<std::vector<std::string>> scenes = {
      {"--eccentricity", "0.5"},
      {"--span", "0.005"},
      {"--curve", "catenary", "--rise-ratio", "0.4"},
      {"--curve", "semicircular", "--support-displacement-ratio", "0.0001"},
      {"--eccentricity", "1", "--thickness-ratio", "0.2"}};
  for (const auto& scene : scenes) {
    std::vector<std::string> draw = {"draw", "--stations", "41", "--output", dir / "arch.svg"};
    std::vector<std::string> profile = {"profile", "--stations", "41", "--all-columns"};
    draw.insert(draw.end(), scene.begin(), scene.end());
    profile.insert(profile.end(), scene.begin(), scene.end());
    CAPTURE(scene.back());
    const Run drawn = run_command(draw), profiled = run_command(profile);
    REQUIRE(drawn.status == 0);
    REQUIRE(profiled.status == 0);
    CHECK(drawn.err.empty());
    CHECK(column(drawn.out, "file") == dir / "arch.svg");
    CHECK(column(drawn.out, "H_over_V") == column(profiled.out, "H_over_V"));
    CHECK(xmllint_accepts(dir / "arch.svg"));
    const auto runs = svg_path_points(read_text(dir / "arch.svg"), "thrust-line");
    REQUIRE(runs.size() == 1);  // every station has a thrust point in these scenes
    REQUIRE(runs[0].size() == 41);
    const double span = std::stod(column(profiled.out, "span"));
    for (std::size_t k = 0; k < 41; ++k) {
      // Both print the shortest decimal that reads back to the same double: they agree to round-off (of
      // the division by the drawing's unit, exact when the unit is 1 m).
      CHECK(std::abs(runs[0][k].first - std::stod(column(profiled.out, "thrust_x", k + 1))) <= ogive::kExact * span);
      CHECK(std::abs(runs[0][k].second - std::stod(column(profiled.out, "thrust_y", k + 1))) <= ogive::kExact * span);
    }
  }
}

TEST_CASE("draw --limit: the minimum and maximum thrust lines are ogive limit's, joint by joint - hinges circled") {
  TempDir dir("ogive_test_draw_limit");
  const std::vector<std::string> scene = {"--eccentricity", "0.5", "--thickness-ratio", "0.1"};
  std::vector<std::string> draw = {"draw", "--limit", "--output", dir / "limit.svg"};
  draw.insert(draw.end(), scene.begin(), scene.end());
  const Run drawn = run_command(draw);
  REQUIRE(drawn.status == 0);
  CHECK(xmllint_accepts(dir / "limit.svg"));
  const std::string svg = read_text(dir / "limit.svg");
  for (const char* state : {"min", "max"}) {
    std::vector<std::string> limit = {"limit", "--thrust-line", state};
    limit.insert(limit.end(), scene.begin(), scene.end());
    const Run joints = run_command(limit);
    REQUIRE(joints.status == 0);
    const auto runs = svg_path_points(svg, std::string("thrust-line-") + state);
    REQUIRE(runs.size() == 1);
    REQUIRE(runs[0].size() + 1 == lines(joints.out).size());
    std::size_t hinges = 0;
    for (std::size_t k = 0; k < runs[0].size(); ++k) {
      CHECK(std::abs(runs[0][k].first - std::stod(column(joints.out, "thrust_x", k + 1))) <= ogive::kExact * 10);
      CHECK(std::abs(runs[0][k].second - std::stod(column(joints.out, "thrust_y", k + 1))) <= ogive::kExact * 10);
      hinges += column(joints.out, "hinge", k + 1).empty() ? 0 : 1;
    }
    const std::size_t group = svg.find(std::string("id=\"thrust-line-") + state + "-hinges\"");
    REQUIRE(group != std::string::npos);
    std::size_t circles = 0;
    for (std::size_t at = svg.find("<circle", group); at < svg.find("</g>", group); at = svg.find("<circle", at + 1))
      ++circles;
    CHECK(circles == hinges);
    CHECK(hinges >= 3);  // a mechanism's worth
  }
}

TEST_CASE("draw: the faces lie at t/2 from the axis - the semicircle's on circles of radius (L +- t)/2") {
  TempDir dir("ogive_test_draw_faces");
  REQUIRE(run_command({"draw", "--curve", "semicircular", "--thickness-ratio", "0.1", "--output", dir / "s.svg"}).status == 0);
  const std::string svg = read_text(dir / "s.svg");
  const double L = 10, t = 1;
  for (const auto& face : {std::pair{"intrados", (L - t) / 2}, std::pair{"extrados", (L + t) / 2},
                            std::pair{"axis", L / 2}}) {
    const auto& [id, radius] = face;
    CAPTURE(face.first);
    const auto runs = svg_path_points(svg, id);
    REQUIRE(runs.size() == 1);
    CHECK(runs[0].size() == 2 * 101 - 1);  // the left half's samples and their mirror images
    for (const auto& [x, y] : runs[0]) CHECK(std::abs(std::hypot(x - L / 2, y) - radius) <= ogive::kExact * L);
    CHECK(std::abs(runs[0].front().first - (L - 2 * radius) / 2) <= ogive::kExact * L);  // springings on y = 0
    CHECK(std::abs(runs[0].back().first - (L + 2 * radius) / 2) <= ogive::kExact * L);
  }
  CHECK(svg.find("id=\"support-left\"") != std::string::npos);
  CHECK(svg.find("id=\"support-right\"") != std::string::npos);
  CHECK(svg.find("id=\"scale-bar\"") != std::string::npos);
  CHECK(svg.find("id=\"support-movement\"") == std::string::npos);  // d = 0: nothing moves
  CHECK(svg.find("H/V = 0.3") != std::string::npos);
}

TEST_CASE("draw: --output-dir writes one file per scene, named after what varies - one CSV row each") {
  TempDir dir("ogive_test_draw_dir");
  const Run r = run_command({"draw", "--eccentricity", "0,0.5", "--support-displacement-ratio", "0,0.0002", "--output-dir",
                     dir.path.string()});
  REQUIRE(r.status == 0);
  REQUIRE(lines(r.out).size() == 1 + 4);
  const std::string expected = dir / "pointed_support-displacement-ratio-0.0002_eccentricity-0.5.svg";
  CHECK(column(r.out, "file", 4) == expected);
  for (std::size_t row = 1; row <= 4; ++row) CHECK(xmllint_accepts(column(r.out, "file", row)));
  const std::string moved = read_text(expected);
  CHECK(moved.find("id=\"support-movement\"") != std::string::npos);
  CHECK(moved.find("d = 2 mm outwards") != std::string::npos);  // 0.0002 of 10 m
}

TEST_CASE("draw: bad targets are one line naming the option - exit 2 - nothing on stdout") {
  TempDir dir("ogive_test_draw_bad");
  std::filesystem::create_directories(dir.path / "sub.svg");
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"draw"},                                                            // no target
           {"draw", "--output", dir / "a.svg", "--output-dir", dir.path.string()},  // two targets
           {"draw", "--output", dir / "sub.svg"},                               // a directory
           {"draw", "--output", dir / "missing/a.svg"},                         // cannot be created
           {"draw", "--output", dir / "a,b.svg"},                               // would break the CSV
           {"draw", "--output", dir / "a.svg", "--eccentricity", "0,1"},         // a sweep into one file
           {"draw", "--output-dir", dir / "missing", "--eccentricity", "0,1"},   // no such directory
           {"draw", "--output-dir", dir / "a.svg"},                              // not a directory
           {"draw", "--output-dir", dir.path.string(), "--eccentricity", "0.5,0.5"},  // two scenes, one name
           {"draw", "--output-dir", dir.path.string(), "--eccentricity", "0:1:1001"},  // too many pictures
           {"draw", "--output", dir / "a.svg", "--stations", "1"},
           {"draw", "--output", dir / "a.svg", "--rise-ratio", "0.3"},
           {"draw", "--output", ""},      // an empty name is not "no target"
           {"draw", "--output-dir", ""}}) {
    check_refused(args);
    const Run r = run_command(args);
    CHECK((r.err.find("--output") != std::string::npos || r.err.find("--stations") != std::string::npos ||
           r.err.find("--rise-ratio") != std::string::npos));
  }
  CHECK(run_command({"draw"}).err.find("--output FILE.svg") != std::string::npos);
  CHECK(run_command({"draw", "--output-dir", ""}).err.find("--output-dir: the name must not be empty") !=
        std::string::npos);
  // Nothing was left behind by the refusals.
  CHECK(std::distance(std::filesystem::directory_iterator(dir.path), std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("draw: no empty or partial file is left - an invalid scene is not drawn - a failed write removes its file") {
  TempDir dir("ogive_test_draw_whole");
  const auto files_in = [&] {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  };
  // Rise 2 with t/L 0.5 makes no catenary: its row says invalid_scene and no file of its name appears.
  const Run r = run_command({"draw", "--curve", "catenary", "--rise-ratio", "0.5,2", "--thickness-ratio", "0.5",
                             "--output-dir", dir.path.string()});
  CHECK(r.status == 3);
  CHECK(column(r.out, "status", 2) == "invalid_scene");
  CHECK(files_in() == std::vector<std::string>{"catenary_rise-ratio-0.5.svg"});
  CHECK(xmllint_accepts(dir / "catenary_rise-ratio-0.5.svg"));
  // A write that fails (here a file size limit, as a full disk would): exit 4, one line naming the
  // file, and neither the picture nor a partial one is left; an existing picture stays as it was.
  std::filesystem::remove(dir / "catenary_rise-ratio-0.5.svg");
  { std::ofstream(dir / "old.svg") << "kept"; }
  struct rlimit saved{};
  REQUIRE(getrlimit(RLIMIT_FSIZE, &saved) == 0);
  const auto saved_handler = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = saved;
  small.rlim_cur = 1000;  // bytes: less than any drawing
  REQUIRE(setrlimit(RLIMIT_FSIZE, &small) == 0);
  const Run full = run_command({"draw", "--eccentricity", "0,0.5", "--output-dir", dir.path.string()});
  const Run replaced = run_command({"draw", "--output", dir / "old.svg"});
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, saved_handler);
  for (const Run& failed : {full, replaced}) {
    CHECK(failed.status == 4);
    CHECK(lines(failed.err).size() == 1);
    CHECK(failed.err.find("cannot write " + dir.path.string()) != std::string::npos);
  }
  CHECK(files_in() == std::vector<std::string>{"old.svg"});
  CHECK(read_text(dir / "old.svg") == "kept");
  // Written whole, it replaces the old file.
  REQUIRE(run_command({"draw", "--output", dir / "old.svg"}).status == 0);
  CHECK(xmllint_accepts(dir / "old.svg"));
  CHECK(files_in() == std::vector<std::string>{"old.svg"});
  // A symlink (as /dev/stdout is) is written through, not replaced by a file.
  std::filesystem::create_symlink(dir / "old.svg", dir / "link.svg");
  REQUIRE(run_command({"draw", "--eccentricity", "1", "--output", dir / "link.svg"}).status == 0);
  CHECK(std::filesystem::is_symlink(dir / "link.svg"));
  CHECK(read_text(dir / "old.svg").find("eccentricity 1,") != std::string::npos);
  CHECK(files_in() == std::vector<std::string>{"link.svg", "old.svg"});
}

TEST_CASE("draw: an unsolved scene is drawn without a thrust line - its row says why - exit 3") {
  TempDir dir("ogive_test_draw_unsolved");
  const Run r = run_command({"draw", "--curve", "catenary", "--method", "closed-form", "--output", dir / "c.svg"});
  CHECK(r.status == 3);
  CHECK(column(r.out, "status") == "not_applicable");
  CHECK(column(r.out, "H_over_V").empty());
  const std::string svg = read_text(dir / "c.svg");
  CHECK(xmllint_accepts(dir / "c.svg"));
  CHECK(svg.find("id=\"thrust-line\"") == std::string::npos);
  CHECK(svg.find("no solution: not_applicable") != std::string::npos);
  CHECK(svg_path_points(svg, "extrados").size() == 1);
}

TEST_CASE("draw: a thrust line that runs off keeps the profile's points in order - drops only the far ones") {
  // Where N changes sign the thrust point runs to infinity: the semicircle at d/L = 0.02 % has such a
  // station; the drawing leaves out points farther than kFarFromArch spans from the arch.
  TempDir dir("ogive_test_draw_far");
  const std::vector<std::string> scene = {"--curve", "semicircular", "--support-displacement-ratio", "0.0002",
                                          "--stations", "101"};
  std::vector<std::string> draw = {"draw", "--output", dir / "far.svg"}, profile = {"profile"};
  draw.insert(draw.end(), scene.begin(), scene.end());
  profile.insert(profile.end(), scene.begin(), scene.end());
  const Run drawn = run_command(draw), profiled = run_command(profile);
  REQUIRE(drawn.status == 0);
  REQUIRE(profiled.status == 0);
  const auto runs = svg_path_points(read_text(dir / "far.svg"), "thrust-line");
  std::vector<std::pair<double, double>> points;
  for (const auto& run : runs) points.insert(points.end(), run.begin(), run.end());
  const double L = 10, t = 0.8;
  std::size_t next = 0, far = 0;
  for (std::size_t k = 1; k <= 101; ++k) {
    const std::string tx = column(profiled.out, "thrust_x", k), ty = column(profiled.out, "thrust_y", k);
    const double x = std::stod(tx), y = std::stod(ty);
    // The arch's box: x in [-t/2, L + t/2], y in [0, L/2 + t/2].
    const bool near = x >= -t / 2 - ogive::kFarFromArch * L && x <= L + t / 2 + ogive::kFarFromArch * L &&
                      y >= -ogive::kFarFromArch * L && y <= L / 2 + t / 2 + ogive::kFarFromArch * L;
    if (!near) {
      ++far;
      continue;
    }
    REQUIRE(next < points.size());
    CHECK(std::abs(points[next].first - x) <= ogive::kExact * L);
    CHECK(std::abs(points[next].second - y) <= ogive::kExact * L);
    ++next;
  }
  CHECK(next == points.size());
  CHECK(far >= 1);           // the scene does run off ...
  CHECK(runs.size() == far + 1);  // ... and each dropped station splits the line (none at the ends here)
}

TEST_CASE("draw --limit: under a horizontal acceleration the collapse line of a_c is ogive limit's, joint by joint") {
  TempDir dir("ogive_test_draw_horizontal");
  const std::vector<std::string> scene = {"--eccentricity", "0", "--thickness-ratio", "0.1",
                                          "--horizontal-acceleration", "0.1"};
  std::vector<std::string> draw = {"draw", "--limit", "--output", dir / "shaken.svg"};
  draw.insert(draw.end(), scene.begin(), scene.end());
  REQUIRE(run_command(draw).status == 0);
  CHECK(xmllint_accepts(dir / "shaken.svg"));
  const std::string svg = read_text(dir / "shaken.svg");
  std::vector<std::string> limit = {"limit", "--thrust-line", "horizontal"};
  limit.insert(limit.end(), scene.begin(), scene.end());
  const Run joints = run_command(limit);
  REQUIRE(joints.status == 0);
  const auto runs = svg_path_points(svg, "thrust-line-horizontal");
  REQUIRE(runs.size() == 1);
  REQUIRE(runs[0].size() + 1 == lines(joints.out).size());
  for (std::size_t k = 0; k < runs[0].size(); ++k)
    CHECK(std::abs(runs[0][k].first - std::stod(column(joints.out, "thrust_x", k + 1))) <= ogive::kExact * 10);
  CHECK(svg.find("collapse at a_c = ") != std::string::npos);
  // Without an acceleration the drawing has the minimum and maximum lines alone.
  std::vector<std::string> still = {"draw", "--limit", "--output", dir / "still.svg", "--eccentricity", "0",
                                    "--thickness-ratio", "0.1"};
  REQUIRE(run_command(still).status == 0);
  CHECK(read_text(dir / "still.svg").find("thrust-line-horizontal") == std::string::npos);
}

TEST_CASE("draw --spread-stage on walls: the arch on its walls, each turned about its toe as spread turns it") {
  TempDir dir("ogive_test_draw_spread_stage_walls");
  const std::vector<std::string> walls = {"--wall-height", "10", "--wall-thickness", "3"};
  std::vector<std::string> spread = {"spread", "--columns",
                                     "status,spread_capacity_ratio,left_wall_rotation_collapse,right_wall_rotation_collapse"};
  spread.insert(spread.end(), walls.begin(), walls.end());
  const Run collapse = run_command(spread);
  REQUIRE(collapse.status == 0);
  REQUIRE(column(collapse.out, "status") == "success");
  const double capacity = std::stod(column(collapse.out, "spread_capacity_ratio"));
  const std::string file = dir / "stage.svg";
  std::vector<std::string> draw = {"draw", "--spread-stage", "1", "--output", file};
  draw.insert(draw.end(), walls.begin(), walls.end());
  REQUIRE(run_command(draw).status == 0);
  CHECK(xmllint_accepts(file));
  const std::string svg = read_text(file);
  const double L = 10, t = 0.8;  // the default span and thickness
  const auto ring = svg_path_points(svg, "spread-stage");
  REQUIRE(ring.size() == 1);
  const auto& left_springing = ring[0].front();
  const auto& right_springing = ring[0][ring[0].size() / 2 - 1];
  // The springings' intrados corners, L - t apart at d = 0, as far apart as spread's capacity says.
  CHECK(std::abs((right_springing.first - left_springing.first - (L - t)) / L - capacity) <= 1e-9);
  for (const bool right : {false, true}) {
    CAPTURE(right);
    const char* side = right ? "right" : "left";
    const auto plumb = svg_path_points(svg, std::string("wall-") + side);
    const auto turned = svg_path_points(svg, std::string("spread-stage-wall-") + side);
    REQUIRE(plumb.size() == 1);
    REQUIRE(turned.size() == 1);
    REQUIRE(turned[0].size() == plumb[0].size());
    // The toe (the base's outer corner, second) stays; every corner keeps its distance from it.
    const auto& toe = plumb[0][1];
    CHECK(std::abs(turned[0][1].first - toe.first) <= 1e-9 * L);
    CHECK(std::abs(turned[0][1].second - toe.second) <= 1e-9 * L);
    const auto from_toe = [&](const std::pair<double, double>& p) { return std::hypot(p.first - toe.first, p.second - toe.second); };
    for (std::size_t k = 0; k < plumb[0].size(); ++k) CHECK(std::abs(from_toe(turned[0][k]) - from_toe(plumb[0][k])) <= 1e-9 * L);
    // The base turned outwards by spread's rotation at collapse.
    const double theta = std::stod(column(collapse.out, std::string(side) + "_wall_rotation_collapse"));
    const auto& inner = turned[0][0];
    const double angle = std::atan2(inner.second - toe.second, std::abs(inner.first - toe.first));
    CHECK(std::abs(angle - theta) <= 1e-9);
    // The arch stands on it: the springing joint's intrados point on the wall's top (fifth corner) is
    // the ring's springing corner.
    const auto& springing = right ? right_springing : left_springing;
    CHECK(std::abs(turned[0][4].first - springing.first) <= 1e-9 * L);
    CHECK(std::abs(turned[0][4].second - springing.second) <= 1e-9 * L);
  }
  // A wall on one side only: that wall leans, the other springing stays on the ground.
  std::vector<std::string> one = {"draw", "--spread-stage", "0.5", "--left-wall-height", "10", "--left-wall-thickness",
                                  "3", "--output", "-"};
  const Run lopsided = run_command(one);
  REQUIRE(lopsided.status == 0);
  CHECK(lopsided.out.find("id=\"spread-stage-wall-left\"") != std::string::npos);
  CHECK(lopsided.out.find("id=\"spread-stage-wall-right\"") == std::string::npos);
}

TEST_CASE("draw --spread-stage: the spread mechanism's ring where it has moved, its thrust line and hinges") {
  TempDir dir("ogive_test_draw_spread_stage");
  // The semicircle, t/L = 0.1: ogive spread's capacity and hinges at collapse are the stage's at 1.
  const std::vector<std::string> scene = {"--eccentricity", "0", "--thickness-ratio", "0.1"};
  std::vector<std::string> spread = {"spread", "--columns", "spread_capacity_ratio,hinges_at_collapse"};
  spread.insert(spread.end(), scene.begin(), scene.end());
  const Run collapse = run_command(spread);
  REQUIRE(collapse.status == 0);
  const double capacity = std::stod(column(collapse.out, "spread_capacity_ratio", 1));
  const std::string hinges = column(collapse.out, "hinges_at_collapse", 1);
  const std::size_t hinges_at_collapse = static_cast<std::size_t>(std::count(hinges.begin(), hinges.end(), ';') + 1);
  const double L = 10, t = 1;  // the default span, and t/L 0.1
  for (const double fraction : {0.0, 0.5, 1.0}) {
    CAPTURE(fraction);
    const std::string file = dir / "stage.svg";
    std::vector<std::string> draw = {"draw", "--spread-stage", fmt::format("{}", fraction), "--output", file};
    draw.insert(draw.end(), scene.begin(), scene.end());
    const Run drawn = run_command(draw);
    REQUIRE(drawn.status == 0);
    CHECK(xmllint_accepts(file));
    const std::string svg = read_text(file);
    // The ring's outline: the intrados corners springing to springing, then the extrados' back. The
    // springings' intrados corners lie L - t apart at d = 0 and move apart by the span's increase.
    const auto ring = svg_path_points(svg, "spread-stage");
    REQUIRE(ring.size() == 1);
    REQUIRE(ring[0].size() % 4 == 0);
    const auto& left = ring[0].front();
    const auto& right = ring[0][ring[0].size() / 2 - 1];
    CHECK(std::abs(left.second) <= 1e-9 * L);
    CHECK(std::abs(right.second) <= 1e-9 * L);
    const double increase = (right.first - left.first - (L - t)) / L;
    // The stage stops at fraction x capacity to the path's bisection tolerance; the drawing's digits are
    // a few more than that.
    CHECK(std::abs(increase - fraction * capacity) <= 1e-5);
    CHECK(!svg_path_points(svg, "spread-stage-thrust-line").empty());
    const std::size_t group = svg.find("id=\"spread-stage-hinges\"");
    REQUIRE(group != std::string::npos);
    std::size_t circles = 0;
    for (std::size_t at = svg.find("<circle", group); at < svg.find("</g>", group); at = svg.find("<circle", at + 1))
      ++circles;
    if (fraction == 1.0) CHECK(circles == hinges_at_collapse);
    CHECK(circles >= 3);
  }
  // Bad stages and the movements the stage sets itself: one line naming the option, exit 2, no output.
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"--spread-stage", "1.5"}, {"--spread-stage", "-0.1"}, {"--spread-stage", "nan"},
        {"--spread-stage", "0.5", "--left-spread-ratio", "0.01"},
        {"--spread-stage", "0.5", "--horizontal-acceleration", "0.1"}}) {
    std::vector<std::string> draw = {"draw", "--output", dir / "bad.svg"};
    draw.insert(draw.end(), bad.begin(), bad.end());
    const Run r = run_command(draw);
    CAPTURE(bad.back());
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(lines(r.err).size() == 1);
    CHECK(r.err.find(bad.size() == 2 ? "--spread-stage" : bad[2]) != std::string::npos);
    CHECK(!std::filesystem::exists(dir / "bad.svg"));
  }
}
