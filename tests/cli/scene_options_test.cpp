// The CLI's scene options: every bad value is one line on stderr naming the option, exit 2 and nothing on
// stdout; curve files (named at their line, CRLF and BOM accepted, standard input), whole-arch files,
// loads files, point loads as an influence line and the sign conventions of support movements.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "ogive/model/scene.hpp"
#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;

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
  // A flag given a value it cannot read: the flag's words, not the parser's.
  const Run flag = run_command({"thrust", "--plane-strain=maybe"});
  CHECK(flag.err == "ogive: --plane-strain: a flag, given alone or as --plane-strain=true / --plane-strain=false, "
                    "not 'maybe'\n");
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

TEST_CASE("help that teaches: a misspelt option or subcommand gets a suggestion - a points file on standard input") {
  const Run r = run_command({"thrust", "--eccentricty", "0.5"});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("did you mean '--eccentricity'?") != std::string::npos);
  CHECK(lines(r.err).size() == 1);
  CHECK(run_command({"thrus"}).err.find("did you mean 'thrust'?") != std::string::npos);
  // A name cut short: the options it begins.
  const Run short_name = run_command({"thrust", "--thicknes", "0.1"});
  CHECK(short_name.status == 2);
  CHECK(short_name.out.empty());
  CHECK(short_name.err.find("did you mean '--thickness'?") != std::string::npos);
  CHECK(run_command({"thrust", "--thickness-rati", "0.1"}).err.find("did you mean '--thickness-ratio'?") !=
        std::string::npos);
  CHECK(run_command({"thrust", "--left-spread", "0"}).err.find("did you mean '--left-spread-ratio'?") !=
        std::string::npos);
  // The parser's errors in the user's words: one line that names the option and what it wants.
  const std::vector<std::pair<std::vector<std::string>, std::string>> worded = {
      {{"thrust", "--thicknes", "0.1"}, "ogive: thrust: unknown option '--thicknes'"},
      {{"thrust", "0.3"}, "ogive: thrust: unexpected argument '0.3' (a value follows its option"},
      {{"thrust", "--span"}, "ogive: --span: needs a value (--span VALUE)"},
      {{"thrust", "--span", "1", "--span", "2"}, "ogive: --span: given more than once"},
      {{"frobnicate"}, "ogive: a subcommand comes first: thrust, profile, check, curve, bench, draw, limit"},
  };
  for (const auto& [args, words] : worded) {
    const Run refused = run_command(args);
    CHECK(refused.status == 2);
    CHECK(refused.out.empty());
    CHECK(lines(refused.err).size() == 1);
    CHECK(refused.err.rfind(words, 0) == 0);
  }
  // --curve-file - reads the points from standard input: the same rows as the file.
  const std::string path = OGIVE_DATA_DIR "/curves/semicircle-24.csv";
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  std::istringstream piped(text.str());
  std::streambuf* saved = std::cin.rdbuf(piped.rdbuf());
  const Run from_stdin = run_command({"thrust", "--curve", "points", "--curve-file", "-"});
  std::cin.rdbuf(saved);
  const Run from_file = run_command({"thrust", "--curve", "points", "--curve-file", path});
  CHECK(from_stdin.status == 0);
  CHECK(from_stdin.out == from_file.out);
}

TEST_CASE("whole arches: bad loads, supports and movements are refused with one line, exit 2") {
  check_refused({"thrust", "--point-load", "1e4", "--point-load-at", "1.2"});      // outside the span
  check_refused({"thrust", "--point-load", "1e4", "--point-load-at", "-0.1"});
  check_refused({"thrust", "--fill-density", "-5", "--fill-height-ratio", "0.5"});  // negative density
  check_refused({"thrust", "--fill-density", "1800", "--fill-height-ratio", "0"});  // at the springing line
  check_refused({"thrust", "--fill-density", "1800", "--fill-height-ratio", "-0.2"});
  check_refused({"thrust", "--fill-density", "1800"});                              // no level
  check_refused({"thrust", "--middle-spread-ratio", "1e-4"});                       // no such side
  check_refused({"thrust", "--supports", "pinned", "--left-rotation", "1e-4"});     // a pinned side turns freely
  check_refused({"thrust", "--left-support", "hinged"});
  check_refused({"thrust", "--point-load-at", "0.3"});
  check_refused({"thrust", "--left-spread-ratio", "1e-4", "--support-displacement-ratio", "1e-4"});
  check_refused({"thrust", "--live-load", "100", "--live-load-from", "0.6", "--live-load-to", "0.4"});
  check_refused({"thrust", "--density", "0"});                                      // no load at all
  check_refused({"thrust", "--loads-file", OGIVE_DATA_DIR "/no-such-file.csv"});
}

TEST_CASE("whole arches: the CLI's influence line, loads file and sign conventions") {
  // An influence line in one call: H is the same for a and 1 - a, and vanishes at the springings.
  const test::Run r = run_command({"thrust", "--density", "0", "--point-load", "1e4", "--point-load-at", "0:1:11",
                                   "--columns", "point_load_at,status,H_left,V_left,V_right"});
  REQUIRE(r.status == 0);
  REQUIRE(lines(r.out).size() == 12);
  for (std::size_t k = 1; k <= 11; ++k) {
    const double H = std::stod(column(r.out, "H_left", k)), H_mirror = std::stod(column(r.out, "H_left", 12 - k));
    CHECK(std::abs(H - H_mirror) <= kExact * 1e4);
    CHECK(close(std::stod(column(r.out, "V_left", k)) + std::stod(column(r.out, "V_right", k)), 1e4, kExact));
  }
  CHECK(std::abs(std::stod(column(r.out, "H_left", 1))) <= kExact * 1e4);
  // The loads file: the same numbers as the options.
  const test::Run file = run_command({"thrust", "--loads-file", OGIVE_DATA_DIR "/loads/quarter-point-and-half-live.csv",
                                      "--columns", "H_left,M_right"});
  const test::Run options = run_command({"thrust", "--point-load", "2e4", "--point-load-at", "0.25", "--live-load",
                                         "5000", "--live-load-to", "0.5", "--columns", "H_left,M_right"});
  REQUIRE(file.status == 0);
  CHECK(file.out == options.out);
  // Sign conventions: an outward spread of the left springing lowers H (the arch is let out); a
  // settlement of the left springing moves load to the right one.
  const double H0 = std::stod(column(run_command({"thrust", "--columns", "H_left"}).out, "H_left"));
  const double H_spread =
      std::stod(column(run_command({"thrust", "--left-spread-ratio", "1e-4", "--columns", "H_left"}).out, "H_left"));
  CHECK(H_spread < H0);
  const test::Run settled = run_command({"thrust", "--left-settlement-ratio", "1e-4", "--columns", "V_left,V_right"});
  CHECK(std::stod(column(settled.out, "V_left")) < std::stod(column(settled.out, "V_right")));
}

TEST_CASE("whole arches: a surveyed rampant arch from the CLI, and whole-arch files refused with their line") {
  // The rampant survey: springings at different heights, solved over the whole arch; its reactions
  // balance its weight (w times the axis length) and H_left = H_right.
  const test::Run r = test::run_command({"thrust", "--curve", "whole-points", "--curve-file",
                                         OGIVE_DATA_DIR "/curves/rampant-survey.csv", "--columns",
                                         "status,domain,H_left,H_right,V_left,V_right"});
  REQUIRE(r.status == 0);
  CHECK(test::column(r.out, "domain") == "whole");
  Scene s;
  s.curve = read_whole_points_curve(OGIVE_DATA_DIR "/curves/rampant-survey.csv");
  CHECK(s.curve->right_springing_height() > 1.0);
  s.thickness = 0.08 * s.span();
  const double weight = s.weight_per_length() * s.curve->length();
  const double V = std::stod(test::column(r.out, "V_left")) + std::stod(test::column(r.out, "V_right"));
  CHECK(close(V, weight, 1e-8));  // the rtol asked (auto's default)
  CHECK(close(std::stod(test::column(r.out, "H_left")), std::stod(test::column(r.out, "H_right")), kExact));

  const std::string dir = std::filesystem::temp_directory_path().string();
  auto file = [&](const std::string& name, const std::string& text) {
    const std::string path = dir + "/ogive-test-" + name;
    std::ofstream(path) << text;
    return path;
  };
  // Folds back: x decreases at line 5.
  const std::string folds = file("folds.csv", "x,y\n0,0\n1,2\n2,3\n1.5,3.2\n4,2\n5,0\n");
  const test::Run f = test::run_command({"thrust", "--curve", "whole-points", "--curve-file", folds});
  CHECK(f.status == 2);
  CHECK(f.out.empty());
  CHECK(f.err.find(folds + ":5:") != std::string::npos);
  // Fewer points than the fit needs: named at the last point's line.
  const std::string few = file("few.csv", "x,y\n0,0\n1,1\n2,0\n");
  const test::Run t = test::run_command({"thrust", "--curve", "whole-points", "--curve-file", few});
  CHECK(t.status == 2);
  CHECK(t.err.find(few + ":4:") != std::string::npos);
  test::check_refused({"thrust", "--curve", "whole-points"});  // no file
  test::check_refused({"thrust", "--curve", "whole-points", "--curve-file", folds, "--span", "10"});
}

TEST_CASE("cli: an empty file name is refused naming its option - - reads the file from standard input") {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"thrust", "--loads-file", ""},
           {"limit", "--loads-file", ""},
           {"thrust", "--curve", "points", "--curve-file", ""},
           {"curve", "--curve", "whole-points", "--curve-file", ""},
           {"thrust", "--curve-file", ""}}) {
    check_refused(args);
    const Run r = run_command(args);
    CHECK(r.err.find(args[args.size() - 2] + ": the name must not be empty") != std::string::npos);
  }
  // --loads-file - reads the loads from standard input: the same rows as the file.
  const std::string path = OGIVE_DATA_DIR "/loads/quarter-point-and-half-live.csv";
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  std::istringstream piped(text.str());
  std::streambuf* saved = std::cin.rdbuf(piped.rdbuf());
  const Run from_stdin = run_command({"thrust", "--loads-file", "-"});
  std::cin.rdbuf(saved);
  const Run from_file = run_command({"thrust", "--loads-file", path});
  CHECK(from_stdin.status == 0);
  CHECK(from_stdin.out == from_file.out);
  CHECK(from_stdin.out.find("H_over_V") != std::string::npos);
}
