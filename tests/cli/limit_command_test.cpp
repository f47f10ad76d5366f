// `ogive limit` (the CLI's limit subcommand): one row per scene with inadmissible arches as rows and
// hinges as x/L:face, the load factor and its mechanism's, one row per joint with --thrust-line, the
// scene's loads and pins, and the refusal of bad input.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// The static and kinematic multipliers of one mechanism are the same number computed twice: they agree
// to round-off.
constexpr double kVirtualWork = 1e-6;
// The thrusts of a statically determinate arch found twice by the LP agree to its feasibility
// tolerance (1e-11 of the load scale) and a little more.
constexpr double kSameRing = 1e-9;

struct Run {
  int status;
  std::string out, err;
};

Run limit_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "limit");
  std::ostringstream out, err;
  const int status = ogive::cli::run_cli(args, out, err);
  return {status, out.str(), err.str()};
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!text.empty() && text.back() == sep && sep != '\n') out.push_back("");
  return out;
}

std::string field(const std::string& csv, const std::string& name, std::size_t row = 1) {
  const auto lines = split(csv, '\n');
  const auto header = split(lines.at(0), ',');
  const auto it = std::find(header.begin(), header.end(), name);
  REQUIRE_MESSAGE(it != header.end(), "no column " << name);
  return split(lines.at(row), ',').at(static_cast<std::size_t>(it - header.begin()));
}

}  // namespace

TEST_CASE("cli: limit prints one row per scene, inadmissible arches as rows, hinges as x/L:face") {
  const Run r = limit_cli({"--eccentricity", "0,0.5", "--thickness-ratio", "0.03,0.15"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const auto lines = split(r.out, '\n');
  REQUIRE(lines.size() == 1 + 4);
  CHECK(field(r.out, "status", 1) == "inadmissible");
  CHECK(field(r.out, "H_min", 1).empty());
  CHECK(!field(r.out, "thickness_min_ratio", 1).empty());
  CHECK(field(r.out, "status", 3) == "success");
  // The semicircle's minimum-thrust hinges: haunch intrados, crown extrados, haunch intrados.
  const auto hinges = split(field(r.out, "hinges_min", 3), ';');
  REQUIRE(hinges.size() == 3);
  CHECK(hinges[1] == "0.5:extrados");
  CHECK(hinges[0].find(":intrados") != std::string::npos);
  CHECK(close(std::stod(field(r.out, "geometric_safety_factor", 3)),
              0.15 / std::stod(field(r.out, "thickness_min_ratio", 3)), kExact));
  CHECK(r.out.find("nan") == std::string::npos);
  CHECK(r.out.find("inf") == std::string::npos);
}

TEST_CASE("cli: limit with a point load prints the load factor and its mechanism's, --thrust-line one row per joint") {
  const Run r = limit_cli({"--point-load", "2e5", "--point-load-at", "0.25", "--thickness-ratio", "0.12"});
  REQUIRE(r.status == 0);
  const double lf = std::stod(field(r.out, "load_factor")), mech = std::stod(field(r.out, "load_factor_mechanism"));
  CHECK(close(lf, mech, kVirtualWork));
  CHECK(split(field(r.out, "hinges_collapse"), ';').size() == 4);

  const Run lines = limit_cli({"--thrust-line", "collapse", "--point-load", "2e5", "--point-load-at", "0.25",
                               "--thickness-ratio", "0.12", "--joints-count", "41"});
  REQUIRE(lines.status == 0);
  // One row per joint of the result's ring: the 41 asked for, those under the load and those the
  // refinement added next to the hinges; an odd count (one at the crown).
  const std::size_t joints = split(lines.out, '\n').size() - 1;
  CHECK(joints > 41);
  CHECK(joints % 2 == 1);
  int hinges = 0;
  for (std::size_t j = 1; j <= joints; ++j) {
    // Every crossing lies on its joint, between intrados and extrados.
    const double ix = std::stod(field(lines.out, "intrados_x", j)), iy = std::stod(field(lines.out, "intrados_y", j));
    const double ex = std::stod(field(lines.out, "extrados_x", j)), ey = std::stod(field(lines.out, "extrados_y", j));
    const double tx = std::stod(field(lines.out, "thrust_x", j)), ty = std::stod(field(lines.out, "thrust_y", j));
    const double length = std::hypot(ex - ix, ey - iy);
    const double u = ((tx - ix) * (ex - ix) + (ty - iy) * (ey - iy)) / (length * length);
    CHECK(std::abs((tx - ix) * (ey - iy) - (ty - iy) * (ex - ix)) <= 1e-9 * length * 10.0);
    CHECK(u >= -1e-9);
    CHECK(u <= 1 + 1e-9);
    hinges += !field(lines.out, "hinge", j).empty();
  }
  CHECK(hinges == 4);

  // A state that does not exist (the arch cannot stand): one row that says so, without numbers.
  const Run none = limit_cli({"--thrust-line", "max", "--thickness-ratio", "0.03", "--joints-count", "41"});
  REQUIRE(none.status == 0);
  REQUIRE(split(none.out, '\n').size() == 2);
  CHECK(field(none.out, "status") == "inadmissible");
  CHECK(field(none.out, "thrust_x").empty());
}

TEST_CASE("cli: limit takes the scene's loads and pins: a live load's factor, the three-hinged arch's single thrust") {
  const Run live = limit_cli({"--live-load", "2e4", "--live-load-to", "0.5", "--fill-density", "1800",
                              "--fill-height-ratio", "0.5", "--thickness-ratio", "0.12"});
  REQUIRE(live.status == 0);
  CHECK(field(live.out, "status") == "success");
  CHECK(close(std::stod(field(live.out, "load_factor")), std::stod(field(live.out, "load_factor_mechanism")), kVirtualWork));
  // The fill is dead: without a live load no load factor.
  const Run dead = limit_cli({"--fill-density", "1800", "--fill-height-ratio", "0.5", "--thickness-ratio", "0.12"});
  REQUIRE(dead.status == 0);
  CHECK(field(dead.out, "load_factor").empty());

  const Run pinned = limit_cli({"--supports", "pinned", "--crown-hinge", "--eccentricity", "0", "--thickness-ratio", "0.15"});
  REQUIRE(pinned.status == 0);
  CHECK(field(pinned.out, "hinges_min") == "0:axis;0.5:axis;1:axis");
  CHECK(close(std::stod(field(pinned.out, "H_min")), std::stod(field(pinned.out, "H_max")), kSameRing));
}

TEST_CASE("cli: limit's friction model: non-associative by default with --friction, its column empty without") {
  const std::vector<std::string> scene = {"--curve", "segmental", "--rise-ratio", "0.25", "--thickness-ratio", "0.15",
                                          "--joints", "vertical", "--point-load", "5e4", "--point-load-at", "0.15",
                                          "--columns", "friction_model,status,load_factor"};
  std::vector<std::string> args = scene;
  args.insert(args.end(), {"--friction", "0.7"});
  const Run fallback = limit_cli(args);
  args.insert(args.end(), {"--friction-model", "associative"});
  const Run associative = limit_cli(args);
  REQUIRE(fallback.status == 0);
  REQUIRE(associative.status == 0);
  CHECK(field(fallback.out, "friction_model") == "non-associative");
  CHECK(field(associative.out, "friction_model") == "associative");
  // The associative factor bounds the non-associative one from above (docs/limit-analysis.md: 9.90, 2.42).
  CHECK(std::stod(field(fallback.out, "load_factor")) < 0.5 * std::stod(field(associative.out, "load_factor")));
  const Run none = limit_cli(scene);
  REQUIRE(none.status == 0);
  CHECK(field(none.out, "friction_model").empty());
}

TEST_CASE("cli: limit refuses bad input with one line and exit 2") {
  const std::vector<std::vector<std::string>> cases = {
      {"--friction", "0"},
      {"--friction", "-0.3"},
      {"--friction", "0.5", "--friction-model", "dilatant"},
      {"--friction-model", "associative"},
      {"--joints-count", "3"},
      {"--joints-count", "200"},
      {"--joints-count", "x"},
      {"--joints", "diagonal"},
      {"--weight", "lumped"},
      {"--point-load", "1e5", "--point-load-at", "1.5"},
      {"--point-load", "1e5", "--point-load-at", "-0.1"},
      {"--point-load-at", "0.3"},
      {"--thrust-line", "collapse"},
      {"--thrust-line", "middle"},
      {"--support-displacement-ratio", "0.0001"},
      {"--left-spread-ratio", "0.0001"},
      {"--thrust-line", "collapse", "--fill-density", "1800", "--fill-height-ratio", "0.5"},
      {"--thickness-ratio", "1.2"},
      {"--repeats", "-1"},
      {"--threads", "0"},
      {"--threads", "257"},
      {"--threads", "two"},
      {"--youngs-modulus", "1"},
      {"--poisson-ratio", "0.3"},
      {"--shear-coefficient", "1"},
      {"--plane-strain"},
      {"--section", "no-tension"},
  };
  for (const auto& args : cases) {
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    CAPTURE(joined);
    const Run r = limit_cli(args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(split(r.err, '\n').size() == 1);
    CHECK(r.err.rfind("ogive: ", 0) == 0);
  }
}

TEST_CASE("cli: limit --threads 2 prints the same bytes as --threads 1, in the scenes' order") {
  // Scenes of every kind in one sweep: inadmissible ones (t < t_min), point loads with a collapse load
  // factor, and the largest thrust's joint rows.
  const std::vector<std::string> sweep = {"--thickness-ratio", "0.04:0.14:12", "--point-load", "0,2e4",
                                          "--point-load-at", "0.3", "--eccentricity", "0,0.5"};
  auto with_threads = [&](std::vector<std::string> args, const char* threads) {
    args.insert(args.end(), {"--threads", threads});
    return limit_cli(args);
  };
  const Run one = with_threads(sweep, "1"), two = with_threads(sweep, "2");
  REQUIRE(one.status == 0);
  CHECK(split(one.out, '\n').size() == 1 + 12 * 2 * 2);
  CHECK(two.status == one.status);
  CHECK(two.out == one.out);
  CHECK(two.err == one.err);

  std::vector<std::string> lines = {"--thickness-ratio", "0.06:0.14:6", "--thrust-line", "max", "--joints-count", "41"};
  const Run lines_one = with_threads(lines, "1"), lines_two = with_threads(lines, "2");
  REQUIRE(lines_one.status == 0);
  CHECK(lines_two.out == lines_one.out);
}

TEST_CASE("cli: limit names the elastic options it refuses, and its help lists only what it takes") {
  const Run r = limit_cli({"--youngs-modulus", "1"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--youngs-modulus: does not apply to limit (rigid voussoirs have no stiffness") != std::string::npos);
  const Run help = limit_cli({"--help"});
  REQUIRE(help.status == 0);
  for (const char* elastic : {"--youngs-modulus", "--poisson-ratio", "--shear-coefficient", "--plane-strain",
                              "--section", "--support-displacement-ratio", "--left-spread-ratio"}) {
    CAPTURE(elastic);
    CHECK(help.out.find(elastic) == std::string::npos);
  }
  for (const char* own : {"--thickness-ratio", "--point-load", "--fill-density", "--supports", "--joints-count",
                          "--threads"}) {
    CAPTURE(own);
    CHECK(help.out.find(own) != std::string::npos);
  }
}

TEST_CASE("cli: asking for the collapse acceleration changes no other number of limit") {
  // a_c converges on rings of its own: H_min, H_max, t_min and the load factor are the same bytes with
  // --all-columns (which computes it) as without (which does not).
  const std::vector<std::string> scene = {"--eccentricity", "0,0.5", "--thickness-ratio", "0.1,0.14",
                                          "--point-load", "2e4", "--point-load-at", "0.3"};
  std::vector<std::string> plain = scene, all = scene;
  plain.insert(plain.end(), {"--columns", "H_min,H_max,thickness_min_ratio,load_factor,hinges_min,hinges_collapse"});
  all.push_back("--all-columns");
  const Run without = limit_cli(plain), with = limit_cli(all);
  REQUIRE(without.status == 0);
  REQUIRE(with.status == 0);
  for (std::size_t row = 1; row <= 4; ++row) {
    CAPTURE(row);
    CHECK_FALSE(field(with.out, "horizontal_load_factor", row).empty());
    for (const char* name : {"H_min", "H_max", "thickness_min_ratio", "load_factor", "hinges_min", "hinges_collapse"})
      CHECK(field(with.out, name, row) == field(without.out, name, row));
  }
}

TEST_CASE("cli: limit --joints and --weight take lists: a row for each, each the row of its own run") {
  const Run both = limit_cli({"--eccentricity", "0,0.5", "--joints", "radial,vertical", "--weight", "voussoir,axis"});
  REQUIRE(both.status == 0);
  const auto rows = split(both.out, '\n');
  REQUIRE(rows.size() == 1 + 2 * 4);
  CHECK(split(rows[0], ',').at(2) == "joints");  // the lists are inputs that vary
  std::size_t k = 1;
  for (const char* eccentricity : {"0", "0.5"})
    for (const char* joints : {"radial", "vertical"})
      for (const char* weight : {"voussoir", "axis"}) {
        const Run one = limit_cli({"--eccentricity", eccentricity, "--joints", joints, "--weight", weight,
                                   "--all-columns"});
        REQUIRE(one.status == 0);
        CHECK(field(both.out, "joints", k) == joints);
        CHECK(field(both.out, "weight", k) == weight);
        for (const char* name : {"H_min", "H_max", "thickness_min_ratio", "hinges_min"})
          CHECK(field(both.out, name, k) == field(one.out, name));
        ++k;
      }
  CHECK(limit_cli({"--weight", "voussoir,"}).status == 2);
  CHECK(limit_cli({"--joints", "radial,diagonal"}).status == 2);
}

TEST_CASE("cli: --compressive-strength in Pa or with a unit of stress, bad values refused with one line") {
  const std::vector<std::string> scene = {"--curve", "semicircular", "--span", "10", "--density", "2000",
                                          "--columns", "compressive_strength,status,thickness_min_ratio"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = scene;
    args.insert(args.end(), extra.begin(), extra.end());
    return limit_cli(args);
  };
  const Run pa = with({"--compressive-strength", "3924000"}), mpa = with({"--compressive-strength", "3.924MPa"});
  REQUIRE(pa.status == 0);
  CHECK(pa.out == mpa.out);
  CHECK(field(pa.out, "compressive_strength") == "3924000");
  CHECK(field(pa.out, "status") == "success");
  // Not scaled by --units (a stress): the same t_min; the column prints in kPa as the stresses do.
  const Run kn = with({"--compressive-strength", "3.924MPa", "--units", "kN"});
  REQUIRE(kn.status == 0);
  const std::string table = kn.out.substr(kn.out.find('\n') + 1);  // after the '# units: kN' line
  CHECK(field(table, "thickness_min_ratio") == field(pa.out, "thickness_min_ratio"));
  CHECK(field(table, "compressive_strength") == "3924");
  // Without the option: no strength, Heyman's t_min.
  const Run heyman = with({});
  CHECK(field(heyman.out, "compressive_strength").empty());
  CHECK(std::stod(field(heyman.out, "thickness_min_ratio")) < std::stod(field(pa.out, "thickness_min_ratio")));
  for (const char* bad : {"0", "-1", "nan", "inf", "3xPa", "1e400", "3MPa,4MPa"}) {
    CAPTURE(bad);
    const Run r = with({"--compressive-strength", bad});
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find("--compressive-strength") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  // A list names what was given, not its value in Pa.
  const Run list = with({"--compressive-strength", "3MPa,4MPa"});
  CHECK(list.err.find("3MPa,4MPa") != std::string::npos);
  // Too weak for the arch's own weight: an answer (inadmissible), whose message says the joints crush.
  const Run weak = limit_cli({"--curve", "semicircular", "--compressive-strength", "1kPa", "--columns",
                              "status,H_min,message"});
  REQUIRE(weak.status == 0);
  CHECK(field(weak.out, "status") == "inadmissible");
  CHECK(field(weak.out, "H_min").empty());
  CHECK(weak.out.find("crush") != std::string::npos);
}
