// `ogive spread` (the CLI's spread subcommand): the spreading capacity from zero at the semicircle's
// minimum thickness and growing with it, the mechanism's rising thrust (Ochsendorf), the cracking part
// as thrust --section no-tension prints it, the mechanism's start at limit's H_min, inadmissible arches
// as rows, and the refusal of bad input.
#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using ogive::test::Run;

namespace {

// The path's first mechanism state is the limit analysis' minimum-thrust state solved again with its
// hinges as pins: the same thrust to the LP's round-off.
constexpr double kSameState = 1e-9;
// Two successful solves of one scene at the default rtol (Options::rtol) agree within it.
constexpr double kDefaultRtol = 1e-8;
// Near t_min the mechanism has almost no room to move: its capacity is a small part of a thicker arch's.
constexpr double kNearlyNoCapacity = 0.05;

// The rows of a CSV text as maps from the header's names.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::string at(std::size_t row, const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE_MESSAGE(it != header.end(), "no column " << name);
    return rows.at(row).at(static_cast<std::size_t>(it - header.begin()));
  }
  double number(std::size_t row, const std::string& name) const { return std::stod(at(row, name)); }
};

Table table(const std::string& csv) {
  Table t;
  const auto rows = test::lines(csv);
  REQUIRE(!rows.empty());
  t.header = test::fields(rows[0]);
  for (std::size_t i = 1; i < rows.size(); ++i) t.rows.push_back(test::fields(rows[i]));
  return t;
}

Run run(const std::vector<std::string>& args) { return test::run_command(args); }

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, sep)) out.push_back(item);
  return out;
}

std::vector<std::size_t> rows_of_part(const Table& t, const std::string& part) {
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    if (t.at(i, "part") == part) rows.push_back(i);
  return rows;
}

}  // namespace

TEST_CASE("cli: spread's capacity goes to zero at the semicircle's minimum thickness and grows with it") {
  const double t_min_over_L = 0.1075 / 2;  // Milankovitch's t/R = 0.1075 (true voussoir weight); t/L = t/(2R)
  const std::string thicknesses = fmt::format("{:.17g},0.065,0.075,0.09", 1.0005 * t_min_over_L);
  const Run r = run({"spread", "--weight", "voussoir", "--thickness-ratio", thicknesses});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const Table t = table(r.out);
  REQUIRE(t.rows.size() == 4);
  double previous = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    CAPTURE(i);
    CHECK(t.at(i, "status") == "success");
    const double capacity = t.number(i, "spread_capacity_ratio");
    CHECK(capacity > previous);
    previous = capacity;
    CHECK(split(t.at(i, "hinges"), ';').size() == 3);
    CHECK(t.number(i, "crown_drop_ratio") > 0);
  }
  CHECK(t.number(0, "spread_capacity_ratio") < kNearlyNoCapacity * t.number(2, "spread_capacity_ratio"));
  CHECK(r.out.find("nan") == std::string::npos);
}

TEST_CASE("cli: spread --path: the mechanism starts at limit's H_min and the semicircle's thrust rises (Ochsendorf)") {
  const Run r = run({"spread", "--path", "--thickness-ratio", "0.075", "--steps", "40"});
  REQUIRE(r.status == 0);
  const Table t = table(r.out);
  REQUIRE(rows_of_part(t, "elastic").size() == 1);
  const auto mechanism = rows_of_part(t, "mechanism");
  REQUIRE(mechanism.size() == 41);
  const Run lim = run({"limit", "--weight", "axis", "--thickness-ratio", "0.075", "--columns", "H_min,hinges_min"});
  REQUIRE(lim.status == 0);
  const double H_min = table(lim.out).number(0, "H_min");
  CHECK(t.number(mechanism.front(), "spread_ratio") == 0);
  CHECK(close(t.number(mechanism.front(), "H"), H_min, kSameState));
  CHECK(t.at(mechanism.front(), "hinges") == table(lim.out).at(0, "hinges_min"));  // the semicircle's three
  for (std::size_t k = 1; k < mechanism.size(); ++k) {
    CAPTURE(k);
    CHECK(t.number(mechanism[k], "H") > t.number(mechanism[k - 1], "H"));
    CHECK(t.number(mechanism[k], "spread_ratio") > t.number(mechanism[k - 1], "spread_ratio"));
    CHECK(t.number(mechanism[k], "crown_drop_ratio") > t.number(mechanism[k - 1], "crown_drop_ratio"));
  }
  CHECK(t.at(mechanism.back(), "collapse") != "");
  CHECK(t.at(mechanism.front(), "collapse") == "");
  // The summary's plateau and capacity are the path's ends.
  const Run summary = run({"spread", "--thickness-ratio", "0.075", "--steps", "40"});
  const Table s = table(summary.out);
  CHECK(s.at(0, "H_plateau") == t.at(mechanism.front(), "H"));
  CHECK(s.at(0, "H_collapse") == t.at(mechanism.back(), "H"));
  CHECK(s.at(0, "spread_capacity_ratio") == t.at(mechanism.back(), "spread_ratio"));
  CHECK(s.at(0, "collapse") == t.at(mechanism.back(), "collapse"));
  CHECK(s.at(0, "H_elastic") == t.at(0, "H"));
}

TEST_CASE("cli: spread --path's cracking part is thrust --section no-tension at the same movements, to the byte") {
  const std::string moves = "0,1e-6,3e-6,1e-5,3e-5,1e-4,3e-4,1e-3,3e-3,1e-2";
  struct Case {
    std::string moving;
    std::vector<std::string> thrust_movement;
    double sides;
  };
  for (const Case& c : {Case{"both", {"--support-displacement-ratio", moves}, 2},
                        Case{"left", {"--left-spread-ratio", moves, "--right-spread-ratio", "0"}, 1}}) {
    CAPTURE(c.moving);
    const Run r = run({"spread", "--path", "--thickness-ratio", "0.075", "--moving", c.moving, "--steps", "10"});
    REQUIRE(r.status == 0);
    const Table t = table(r.out);
    const auto cracking = rows_of_part(t, "cracking");
    std::vector<std::string> args = {"thrust", "--section", "no-tension", "--thickness-ratio", "0.075",
                                     "--columns", "status,H,V,H_over_V"};
    args.insert(args.end(), c.thrust_movement.begin(), c.thrust_movement.end());
    const Run th = run(args);
    REQUIRE(th.status == 0);
    const Table u = table(th.out);
    REQUIRE(cracking.size() == u.rows.size());
    const auto each = split(moves, ',');
    for (std::size_t k = 0; k < cracking.size(); ++k) {
      CAPTURE(k);
      for (const char* name : {"status", "H", "V", "H_over_V"}) CHECK(t.at(cracking[k], name) == u.at(k, name));
      CHECK(t.number(cracking[k], "spread_ratio") == c.sides * std::stod(each[k]));
    }
    // The cracking arch falls towards the plateau, the mechanism's start.
    const double plateau = t.number(rows_of_part(t, "mechanism").front(), "H_over_V");
    CHECK(t.number(cracking.back(), "H_over_V") < t.number(cracking.front(), "H_over_V"));
    CHECK(t.number(cracking.back(), "H_over_V") > plateau);
  }
}

TEST_CASE("cli: spread --right-settlement-share: the cracking part settles too, within the small movements") {
  // Twice as far down as out: the cracking movements are halved so that no springing moves more than
  // 1e-2 L either way; the settling springing sheds load; the cracking arch falls towards the plateau.
  const Run r = run({"spread", "--path", "--thickness-ratio", "0.075", "--moving", "right", "--right-settlement-share",
                     "2", "--steps", "10", "--all-columns"});
  // A finer ring changes the state at d = 0; joints where its least-work line (not limit's least-thrust
  // one: the settling springing sheds load) grazes the faces there settle it: the mechanism's rows say
  // success (the same capacity from 201 to 1601 starting joints).
  REQUIRE(r.status == 0);
  const Table t = table(r.out);
  const auto cracking = rows_of_part(t, "cracking");
  const auto each = split("0,1e-6,3e-6,1e-5,3e-5,1e-4,3e-4,1e-3,3e-3,1e-2", ',');
  REQUIRE(cracking.size() == each.size());
  for (std::size_t k = 0; k < cracking.size(); ++k) {
    CAPTURE(k);
    CHECK(t.at(cracking[k], "status") == "success");
    CHECK(t.at(cracking[k], "right_settlement_share") == "2");
    CHECK(t.number(cracking[k], "spread_ratio") == std::stod(each[k]) / 2);
    if (k > 0) CHECK(t.number(cracking[k], "V_right") < t.number(cracking[k], "V"));
  }
  // The same last movement by thrust --section no-tension, alone (no continuation): the same answer
  // within the default rtol each solve meets.
  const Run th = run({"thrust", "--section", "no-tension", "--thickness-ratio", "0.075", "--left-spread-ratio", "0",
                      "--right-spread-ratio", "0.005", "--right-settlement-ratio", "0.01", "--columns", "H,V_right"});
  REQUIRE(th.status == 0);
  CHECK(close(t.number(cracking.back(), "H"), table(th.out).number(0, "H"), kDefaultRtol));
  const auto mechanism = rows_of_part(t, "mechanism");
  REQUIRE(!mechanism.empty());
  for (const std::size_t k : mechanism) {
    CHECK(t.at(k, "status") == "success");
    CHECK(t.at(k, "message").empty());
  }
  CHECK(t.number(cracking.back(), "H_over_V") > t.number(mechanism.front(), "H_over_V"));
  CHECK(t.at(mechanism.back(), "collapse") != "");
}

TEST_CASE("cli: spread gives a pointed arch its four hinges and a capacity") {
  // With joints where the least-thrust line grazes the faces at d = 0 the capacity converges.
  const Run r = run({"spread", "--eccentricity", "0.5", "--thickness-ratio", "0.08"});
  CHECK(r.status == 0);
  const Table t = table(r.out);
  CHECK(t.at(0, "status") == "success");
  const std::string hinges = t.at(0, "hinges");
  CHECK(std::count(hinges.begin(), hinges.end(), ';') == 3);
  CHECK(!t.at(0, "spread_capacity_ratio").empty());
  CHECK(t.at(0, "message").empty());
}

TEST_CASE("cli: spread prints a not_converged row's numbers, the message the capacity's last change, exit 3") {
  // The loaded equilateral vault (8 m, t = 0.8 m, fill to the crown, 50 kN/m at 2 m) with the true
  // voussoir weight: a finer ring changes the state at d = 0 and the capacity moves by 3.2e-3 of itself
  // there, joints where the least-thrust line grazes the faces or not. The summary and the --path rows
  // give the coarser ring's path (the same capacity), each saying not_converged and by how much.
  const std::vector<std::string> scene = {"spread", "--span", "8", "--thickness", "0.8", "--eccentricity", "0.5",
                                          "--density", "2000", "--fill-density", "2000", "--fill-height-ratio",
                                          "0.924", "--point-load", "5e4", "--point-load-x", "2", "--weight",
                                          "voussoir"};
  std::vector<std::string> with_path = scene;
  for (const char* more : {"--path", "--steps", "3"}) with_path.push_back(more);
  const Run sum = run(scene);
  const Run path = run(with_path);
  CHECK(sum.status == 3);
  CHECK(path.status == 3);
  CHECK(sum.err.empty());
  const Table s = table(sum.out), p = table(path.out);
  CHECK(s.at(0, "status") == "not_converged");
  const std::string message = s.at(0, "message");
  CHECK(message.rfind("the capacity moved by 0.0032 of itself at the last refinement of the joints", 0) == 0);
  for (const char* column : {"H_over_V_plateau", "spread_capacity_ratio", "H_over_V_collapse", "crown_drop_ratio"})
    CHECK(s.number(0, column) > 0);
  CHECK(s.at(0, "collapse") == "snap_through");
  CHECK(!s.at(0, "hinges_at_collapse").empty());
  const auto mechanism = rows_of_part(p, "mechanism");
  REQUIRE(mechanism.size() == 4);
  for (const std::size_t k : mechanism) {
    CHECK(p.at(k, "status") == "not_converged");
    CHECK(p.at(k, "message") == message);
    CHECK(!p.at(k, "H_over_V").empty());
  }
  CHECK(p.number(mechanism.back(), "spread_ratio") == s.number(0, "spread_capacity_ratio"));
  CHECK(p.at(mechanism.back(), "collapse") == "snap_through");
}

TEST_CASE("cli: spread gives an arch too thin to stand a row of status inadmissible and no curve") {
  for (const bool path : {false, true}) {
    CAPTURE(path);
    std::vector<std::string> args = {"spread", "--thickness-ratio", "0.04"};
    if (path) args.push_back("--path");
    const Run r = run(args);
    REQUIRE(r.status == 0);
    const Table t = table(r.out);
    REQUIRE(t.rows.size() == 1);
    CHECK(t.at(0, "status") == "inadmissible");
    CHECK(t.at(0, "hinges").empty());
  }
  const Table s = table(run({"spread", "--thickness-ratio", "0.04"}).out);
  CHECK(s.at(0, "spread_capacity_ratio").empty());
  CHECK(!s.at(0, "H_elastic").empty());  // the elastic arch has its thrust whatever its thickness
}

TEST_CASE("cli: spread --joints vertical: the mechanism starts at limit's H_min on the same vertical joints") {
  // The equilateral arch, whose vertical joints differ most from its radial ones near the springings.
  const std::vector<std::string> scene = {"--eccentricity", "0.5", "--thickness-ratio", "0.08", "--weight", "axis"};
  double capacity[2] = {0, 0};
  for (const char* joints : {"radial", "vertical"}) {
    CAPTURE(joints);
    std::vector<std::string> spread = {"spread", "--joints", joints, "--columns",
                                       "joints,status,H_plateau,spread_capacity_ratio"};
    spread.insert(spread.end(), scene.begin(), scene.end());
    const Run r = run(spread);
    // Both converge, the path on a ring with joints where the least-thrust line grazes the faces at d = 0
    // (its least thrust above the limit ring's by the square of their distance: 2e-7 of it).
    constexpr double kGrazingJoints = 1e-6;
    REQUIRE(r.status == 0);
    std::vector<std::string> limit = {"limit", "--joints", joints, "--joints-count", "201", "--columns", "H_min"};
    limit.insert(limit.end(), scene.begin(), scene.end());
    const Run lim = run(limit);
    REQUIRE(lim.status == 0);
    const Table t = table(r.out);
    CHECK(t.at(0, "joints") == joints);
    CHECK(t.at(0, "status") == "success");
    CHECK(t.number(0, "H_plateau") >= table(lim.out).number(0, "H_min") * (1 - kSameState));
    CHECK(close(t.number(0, "H_plateau"), table(lim.out).number(0, "H_min"), kGrazingJoints));
    capacity[joints[0] == 'v' ? 1 : 0] = t.number(0, "spread_capacity_ratio");
  }
  CHECK(capacity[0] > 0);
  CHECK(capacity[1] > 0);
  CHECK(capacity[0] != capacity[1]);  // the joints are the question's: another ring, another capacity
}

TEST_CASE("cli: spread refuses bad input with one line naming the option, exit 2, nothing on stdout") {
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"--moving", "up"}, "--moving"},
      {{"--steps", "0"}, "--steps"},
      {{"--weight", "heavy"}, "--weight"},
      {{"--joints", "oblique"}, "--joints"},
      {{"--right-settlement-share", "11"}, "--right-settlement-share"},
      {{"--left-settlement-share", "nan"}, "--left-settlement-share"},
      {{"--left-settlement-share", "0,1"}, "--left-settlement-share"},
      {{"--increment-ratio", "abc"}, "--increment-ratio"},
      {{"--increment-ratio", "1e-7"}, "--increment-ratio"},
      {{"--increment-ratio", "1e-8"}, "--increment-ratio"},
      {{"--increment-ratio", "0.2"}, "--increment-ratio"},
      {{"--joints-count", "4"}, "--joints-count"},
      {{"--support-displacement-ratio", "0.001"}, "--support-displacement-ratio"},
      {{"--left-spread-ratio", "0.001"}, "--left-spread-ratio"},
      {{"--section", "no-tension"}, "--section"},
      {{"--horizontal-acceleration", "0.1"}, "--horizontal-acceleration"},
      {{"--columns", "H_min"}, "--columns"},
  };
  for (const auto& item : bad) {
    const std::vector<std::string>& args = item.first;
    const std::string& flag = item.second;  // not a structured binding: CAPTURE's lambda captures it
    CAPTURE(flag);
    std::vector<std::string> all = {"spread"};
    all.insert(all.end(), args.begin(), args.end());
    const Run r = run(all);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(test::lines(r.err).size() == 1);
    CHECK(r.err.find(flag) != std::string::npos);
  }
}

TEST_CASE("cli: spread --columns help gives every column its unit, and threads change no byte") {
  const Run help = run({"spread", "--columns", "help"});
  REQUIRE(help.status == 0);
  CHECK(help.out.find("spread_capacity_ratio,,") != std::string::npos);
  CHECK(help.out.find("H_plateau,N/m,") != std::string::npos);
  // --units kN divides the forces by 1000 and leaves the ratios alone.
  const Table newtons = table(run({"spread", "--thickness-ratio", "0.075", "--steps", "20"}).out);
  const Run kn = run({"spread", "--thickness-ratio", "0.075", "--steps", "20", "--units", "kN"});
  REQUIRE(kn.out.rfind("# units: kN", 0) == 0);
  const Table kilonewtons = table(kn.out.substr(kn.out.find('\n') + 1));  // after the units line
  CHECK(close(kilonewtons.number(0, "H_plateau") * 1000, newtons.number(0, "H_plateau"), kExact));
  CHECK(kilonewtons.at(0, "spread_capacity_ratio") == newtons.at(0, "spread_capacity_ratio"));
  const Run one = run({"spread", "--thickness-ratio", "0.06:0.09:4", "--span", "8,10", "--threads", "1"});
  const Run two = run({"spread", "--thickness-ratio", "0.06:0.09:4", "--span", "8,10", "--threads", "2"});
  REQUIRE(one.status == 0);
  CHECK(one.out == two.out);
}

TEST_CASE("cli: spread's finest increment gives the capacity of the default one, in bounded time and memory") {
  // The increments are bounded below (kLeastIncrementRatio): at the finest, each of the semicircle's
  // paths takes some 600 increments, and the summary keeps two states of it. The capacity is the
  // default increment's to three significant digits (docs/spreading.md's table).
  constexpr double kThreeDigits = 2.5e-3;
  const std::vector<std::string> scene = {"spread", "--curve", "semicircular", "--thickness-ratio", "0.075",
                                          "--columns", "spread_capacity_ratio"};
  std::vector<std::string> finest = scene;
  finest.insert(finest.end(), {"--increment-ratio", "1e-4"});
  const Run fine = run(finest), standard = run(scene);
  REQUIRE(fine.status == 0);
  REQUIRE(standard.status == 0);
  const double a = table(fine.out).number(0, "spread_capacity_ratio");
  const double b = table(standard.out).number(0, "spread_capacity_ratio");
  CHECK(close(a, b, kThreeDigits));
  const Run refused = run({"spread", "--increment-ratio", "9e-5"});
  CHECK(refused.status == 2);
  CHECK(refused.out.empty());
  CHECK(refused.err.find("--increment-ratio: must lie in [1e-4, 0.1]") != std::string::npos);
}
