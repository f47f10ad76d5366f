// The CLI, in-process: CSV on stdout, one line on stderr and exit 2 for bad input, determinism.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "cli_run.hpp"
#include "ogive/solve/solve.hpp"
#include "ogive/output/svg.hpp"
#include "tolerances.hpp"

using ogive::cli::run_cli;
using namespace ogive::test;

TEST_CASE("cli: thrust prints a header and one row per scene of the cartesian product") {
  const Run r = run_command({"thrust", "--eccentricity", "0:1:11", "--thickness-ratio", "0.06,0.08,0.10"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const auto ls = lines(r.out);
  REQUIRE(ls.size() == 1 + 33);
  const auto header = fields(ls[0]);
  for (const char* name : {"H", "V", "H_over_V", "eccentricity", "thickness_ratio", "method", "status"})
    CHECK(std::find(header.begin(), header.end(), std::string(name)) != header.end());
  // The last option in the documented order varies fastest: eccentricity within thickness.
  CHECK(column(r.out, "thickness_ratio", 1) == "0.06");
  CHECK(column(r.out, "eccentricity", 2) == "0.1");
  CHECK(column(r.out, "thickness_ratio", 12) == "0.08");
  for (std::size_t row = 1; row < ls.size(); ++row) {
    CHECK(fields(ls[row]).size() == fields(ls[0]).size());
    CHECK(column(r.out, "status", row) == "success");
    CHECK(column(r.out, "method", row) == "closed-form");
  }
  // H_over_V printed exactly (shortest round-trip) equals the library's value.
  ogive::Scene scene;
  scene.curve = ogive::make_pointed(10.0, 0.5);
  scene.thickness = 0.06 * 10.0;
  CHECK(std::stod(column(r.out, "H_over_V", 6)) == ogive::solve(scene).H_over_V);
}

TEST_CASE("cli: profile prints --stations rows per scene with the internal forces and e") {
  const Run r = run_command({"profile", "--eccentricity", "0,0.5", "--stations", "7"});
  REQUIRE(r.status == 0);
  const auto ls = lines(r.out);
  REQUIRE(ls.size() == 1 + 14);
  const auto header = fields(ls[0]);
  for (const char* name : {"s", "x", "y", "N", "shear_force", "M", "thrust_eccentricity", "thrust_x", "thrust_y"})
    CHECK(std::find(header.begin(), header.end(), std::string(name)) != header.end());
  CHECK(std::stod(column(r.out, "x", 1)) == 0.0);
  CHECK(ogive::close(std::stod(column(r.out, "x", 7)), 10.0, ogive::kExact));
}

TEST_CASE("cli: check reports every method within tolerance - methods and integrators selectable") {
  const Run r = run_command({"check", "--eccentricity", "0,1", "--rtol", "1e-7", "--integrator", "bdf"});
  REQUIRE(r.status == 0);
  const auto ls = lines(r.out);
  REQUIRE(ls.size() == 1 + 2 * 4);  // closed form, quadrature, shooting, multiple shooting
  for (std::size_t row = 1; row < ls.size(); ++row) CHECK(column(r.out, "within_tolerance", row) == "true");
  const Run s = run_command({"thrust", "--method", "multiple-shooting", "--segments", "4", "--rtol", "1e-9", "--all-columns"});
  REQUIRE(s.status == 0);
  CHECK(column(s.out, "method") == "multiple-shooting");
  CHECK(column(s.out, "segments") == "4");
}

TEST_CASE("cli: a solver failure is a status in the row - no number - and exit 3") {
  const Run r = run_command({"thrust", "--method", "shooting", "--rtol", "1e-12", "--max-steps", "3", "--eccentricity", "0,0.5"});
  CHECK(r.status == 3);
  CHECK(r.err.empty());
  REQUIRE(lines(r.out).size() == 3);
  for (std::size_t row : {1, 2}) {
    CHECK(column(r.out, "status", row) == "integrator_failure");
    CHECK(column(r.out, "H_over_V", row) .empty());
  }
}

TEST_CASE("cli: bad input is one line on stderr - exit 2 - nothing on stdout") {
  const std::vector<std::vector<std::string>> cases = {
      {"thrust", "--eccentricity", "-0.5"},
      {"thrust", "--eccentricity", "nan"},
      {"thrust", "--eccentricity", "inf"},
      {"thrust", "--eccentricity", "abc"},
      {"thrust", "--eccentricity", ""},
      {"thrust", "--eccentricity", "0,,1"},
      {"thrust", "--eccentricity", "0:1"},
      {"thrust", "--eccentricity", "0:1:0"},
      {"thrust", "--eccentricity", "0:1:2.5"},
      {"thrust", "--eccentricity", "1:0:1"},
      {"thrust", "--eccentricity", "0:1:1e9"},
      {"thrust", "--eccentricity", "0:1:1000", "--thickness-ratio", "0:0.1:1001", "--span", "1:2:3"},
      {"thrust", "--span", "0"},
      {"thrust", "--span", "-10"},
      {"thrust", "--thickness-ratio", "0"},
      {"thrust", "--thickness-ratio", "1.5"},
      {"thrust", "--support-displacement-ratio", "0.5"},
      {"thrust", "--youngs-modulus", "0"},
      {"thrust", "--poisson-ratio", "0.7"},
      {"thrust", "--poisson-ratio", "-1"},
      {"thrust", "--poisson-ratio", "0.5", "--plane-strain"},
      {"thrust", "--density", "0"},
      {"thrust", "--gravity", "-9.81"},
      {"thrust", "--shear-coefficient", "0"},
      {"thrust", "--curve", "gothic"},
      {"thrust", "--curve", "semicircular", "--eccentricity", "0.5"},
      {"thrust", "--method", "magic"},
      {"thrust", "--method", "3"},
      {"thrust", "--integrator", "0"},
      {"thrust", "--integrator", "rk4"},
      {"thrust", "--rtol", "0"},
      {"thrust", "--rtol", "2"},
      {"thrust", "--atol", "-1"},
      {"thrust", "--segments", "0"},
      {"thrust", "--max-steps", "0"},
      {"profile", "--stations", "0"},
      {"profile", "--stations", "1"},
      {"profile", "--stations", "x"},
      {"bench", "--methods", "closed-form,magic"},
      {"bench", "--repeats", "0"},
      {"thrust", "--curve", "three-centred", "--rise-ratio", "0.14", "--thickness-ratio", "0.2"},  // t > 2 r1
      {"thrust", "--curve", "segmental", "--rise-ratio", "0.7"},
      {"thrust", "--curve", "three-centred", "--rise-ratio", "0.1"},
      {"thrust", "--curve", "four-centred", "--haunch-angle", "45", "--crown-angle", "50"},
      {"thrust", "--curve", "parabolic", "--rise-ratio", "0"},
      {"thrust", "--curve", "pointed", "--rise-ratio", "0.3"},
      {"thrust", "--curve", "parabolic", "--haunch-angle", "30"},
      {"thrust", "--curve", "points"},
      {"thrust", "--curve", "points", "--curve-file", "/nonexistent/arch.csv"},
      {"thrust", "--curve-file", OGIVE_DATA_DIR "/curves/parabola-40.csv"},
      {"thrust", "--curve", "points", "--curve-file", OGIVE_DATA_DIR "/curves/parabola-40.csv", "--span", "12"},
      {"curve", "--stations", "1"},
      {"thrust", "--unknown-option", "1"},
      {"nonsense"},  // bare `ogive` prints the whole help on stderr: "--version ... bare ogive" below
  };
  for (const auto& args : cases) check_refused(args);
  // The message names the option and the rule.
  CHECK(run_command({"thrust", "--poisson-ratio", "0.7"}).err.find("--poisson-ratio") != std::string::npos);
  CHECK(run_command({"thrust", "--poisson-ratio", "0.7"}).err.find("(-1, 0.5]") != std::string::npos);
  CHECK(run_command({"thrust", "--rtol", "0"}).err.find("--rtol") != std::string::npos);
  CHECK(run_command({"profile", "--stations", "1"}).err.find("--stations") != std::string::npos);
  CHECK(run_command({"thrust", "--thickness-ratio", "1.5"}).err.find("--thickness-ratio") != std::string::npos);
}

TEST_CASE("cli: every numeric option refuses nan - infinities - overflow - text - empty - a very long number") {
  const std::string long_number(100000, '1');  // 1e99999: not a finite double
  const std::vector<std::string> bad = {"nan", "inf", "-inf", "1e999", "-1e999", "abc", "", "0x", long_number,
                                        "1,nan", "0:inf:3", "1:2:3:4", "--"};
  // Scene options, on a curve to which each applies.
  const std::vector<std::pair<std::string, std::vector<std::string>>> options = {
      {"--span", {}}, {"--youngs-modulus", {}}, {"--poisson-ratio", {}}, {"--density", {}}, {"--gravity", {}},
      {"--shear-coefficient", {}}, {"--thickness-ratio", {}}, {"--support-displacement-ratio", {}},
      {"--eccentricity", {}}, {"--rise-ratio", {"--curve", "four-centred"}},
      {"--haunch-angle", {"--curve", "four-centred"}}, {"--crown-angle", {"--curve", "four-centred"}},
      {"--rtol", {}}, {"--atol", {}}, {"--segments", {}}, {"--max-steps", {}}};
  for (const auto& [option, context] : options)
    for (const std::string& value : bad) {
      std::vector<std::string> args = {"thrust"};
      args.insert(args.end(), context.begin(), context.end());
      args.push_back(option);
      args.push_back(value);
      check_refused(args);
    }
  // The list options of the other commands.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"profile", "--stations", "1e999"}, {"profile", "--stations", "nan"}, {"curve", "--stations", "-3"},
           {"bench", "--rtols", "nan"}, {"bench", "--rtols", "1e-20"}, {"bench", "--repeats", "nan"},
           {"bench", "--integrators", "rk4"}, {"bench", "--integrators", ""}, {"bench", "--methods", ""},
           {"bench", "--eccentricity", "0:1:1000", "--thickness-ratio", "0.05:0.1:1000", "--rtols", "1e-2:1e-3:2"},
           {"thrust", "--curve", "points", "--curve-file", "/"}, {"thrust", "--plane-strain=maybe"}})
    check_refused(args);
}

TEST_CASE("cli: a bad curve file is one line naming the file and the line - exit 2 - nothing on stdout") {
  const std::string dir = std::filesystem::temp_directory_path() / "ogive_test_cli_curves";
  std::filesystem::create_directories(dir);
  // Each body breaks one rule; the expected line is where the rule breaks.
  const std::vector<std::pair<std::string, std::string>> files = {
      {"", ":1"},                                                   // empty file
      {"a,b\n0,0\n1,2\n2,3\n3,4\n", ":1"},                         // bad header
      {"x,y\n0,0\n1,2\n2,abc\n3,4\n", ":4"},                       // not a number
      {"x,y\n0,0\n1,2\n2,inf\n3,4\n", ":4"},                       // not finite
      {"x,y\n0,0\n1,2\n2,3\n", ":4"},                               // fewer than 4 points
      {"x,y\n0,0\n1,2\n1,2\n2,3\n3,4\n", ":4"},                   // repeated point
      {"x,y\n0,0\n2,2\n1,3\n3,4\n", ":4"},                         // x not increasing
      {"x,y\n0,0.5\n1,2\n2,3\n3,4\n", ":2"},                       // not on the springing line
      {"x,y\n0,0\n1,2\n2,1\n3,4\n", ":4"},                         // y falls: doubles back
      {"x,y\n0,0\n1,2,7\n2,3\n3,4\n", ":3"},                       // wrong number of fields
      {std::string("x,y\n0,0\n\x01\xff\xfe,2\n2,3\n3,4\n"), ":3"},  // binary bytes
  };
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string path = dir + "/bad" + std::to_string(k) + ".csv";
    std::ofstream(path, std::ios::binary) << files[k].first;
    CAPTURE(k);
    const Run r = run_command({"thrust", "--curve", "points", "--curve-file", path});
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(lines(r.err).size() == 1);
    CHECK(r.err.find(path + files[k].second + ":") != std::string::npos);
  }
  // CRLF, a byte-order mark and trailing blank lines are ordinary input: the same output as the plain file.
  std::ifstream plain_in(OGIVE_DATA_DIR "/curves/parabola-40.csv");
  const std::string plain((std::istreambuf_iterator<char>(plain_in)), std::istreambuf_iterator<char>());
  std::string crlf;
  for (char c : plain) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  std::ofstream(dir + "/variant.csv", std::ios::binary) << "\xEF\xBB\xBF" << crlf << "\r\n\r\n";
  const Run a = run_command({"thrust", "--curve", "points", "--curve-file", OGIVE_DATA_DIR "/curves/parabola-40.csv"});
  const Run b = run_command({"thrust", "--curve", "points", "--curve-file", dir + "/variant.csv"});
  CHECK(a.status == 0);
  CHECK(b.status == 0);
  CHECK(a.out == b.out);
  std::filesystem::remove_all(dir);
}

TEST_CASE("cli: help goes to stdout with exit 0 - output is deterministic") {
  const Run h = run_command({"--help"});
  CHECK(h.status == 0);
  CHECK(h.out.find("thrust") != std::string::npos);
  const std::vector<std::string> args = {"profile", "--eccentricity", "0,0.7", "--method", "multiple-shooting",
                                         "--stations", "9", "--support-displacement-ratio", "1e-4"};
  const Run a = run_command(args), b = run_command(args);
  CHECK(a.status == 0);
  CHECK(a.out == b.out);
}

// ---------------------------------------------------------------------------------------------
// draw, --version, bare ogive, the help's examples.

namespace {

// A fresh directory under the system's temporary directory, removed at the end of the scope.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name) : path(std::filesystem::temp_directory_path() / name) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string operator/(const std::string& file) const { return (path / file).string(); }
};

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

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
  for (const auto& [id, radius] : {std::pair{"intrados", (L - t) / 2}, std::pair{"extrados", (L + t) / 2},
                                   std::pair{"axis", L / 2}}) {
    CAPTURE(id);
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
           {"draw", "--output", dir / "a.svg", "--rise-ratio", "0.3"}}) {
    check_refused(args);
    const Run r = run_command(args);
    CHECK((r.err.find("--output") != std::string::npos || r.err.find("--stations") != std::string::npos ||
           r.err.find("--rise-ratio") != std::string::npos));
  }
  CHECK(run_command({"draw"}).err.find("--output FILE.svg") != std::string::npos);
}

TEST_CASE("cli: --version names the project version; bare ogive prints the help on stderr with exit 2") {
  const Run v = run_command({"--version"});
  CHECK(v.status == 0);
  CHECK(v.out == std::string("ogive ") + OGIVE_VERSION + "\n");
  const Run bare = run_command({});
  CHECK(bare.status == 2);
  CHECK(bare.out.empty());
  for (const char* sub : {"thrust", "profile", "check", "curve", "bench", "draw", "docs/model.md"})
    CHECK(bare.err.find(sub) != std::string::npos);
}

TEST_CASE("cli: every subcommand's help has two examples, and they run") {
  TempDir dir("ogive_test_examples");
  for (const char* sub : {"thrust", "profile", "check", "curve", "bench", "draw"}) {
    CAPTURE(sub);
    const Run help = run_command({sub, "--help"});
    REQUIRE(help.status == 0);
    std::vector<std::vector<std::string>> examples;
    for (const std::string& line : lines(help.out)) {
      if (line.rfind(std::string("  ogive ") + sub + " ", 0) != 0) continue;
      std::istringstream words(line.substr(line.find(sub)));
      std::vector<std::string> args;
      for (std::string w; words >> w && w != "#";) {
        if (w.rfind("data/", 0) == 0) w = OGIVE_DATA_DIR + w.substr(4);        // the repository's data
        if (w.ends_with(".svg") || w == "pictures") w = dir / w;                // files into the temp dir
        args.push_back(w);
      }
      examples.push_back(args);
    }
    CHECK(examples.size() == 2);
    std::filesystem::create_directories(dir.path / "pictures");
    for (auto args : examples) {
      if (std::string(sub) == "bench") {  // one solve per row is enough to show that the example works
        const auto repeats = std::find(args.begin(), args.end(), "--repeats");
        if (repeats != args.end()) args.erase(repeats, repeats + 2);
        args.insert(args.end(), {"--repeats", "1"});
      }
      const Run r = run_command(args);
      CAPTURE(r.err);
      CHECK(r.status == 0);
    }
  }
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
