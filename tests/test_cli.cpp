// The CLI, in-process: CSV on stdout, one line on stderr and exit 2 for bad input, determinism.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "cli_run.hpp"
#include "ogive/solve.hpp"
#include "tolerances.hpp"

using ogive::cli::run_cli;
using namespace ogive::test;

TEST_CASE("cli: thrust prints a header and one row per scene of the cartesian product") {
  const Run r = run_command({"thrust", "--eccentricity", "0:1:11", "--thickness-ratio", "0.06,0.08,0.10"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const auto ls = lines(r.out);
  REQUIRE(ls.size() == 1 + 33);
  for (const char* name : {"H", "V", "H_over_V", "eccentricity", "thickness_ratio", "method", "status"})
    CHECK(std::find(fields(ls[0]).begin(), fields(ls[0]).end(), std::string(name)) != fields(ls[0]).end());
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
  for (const char* name : {"s", "x", "y", "N", "V", "M", "e", "thrust_x", "thrust_y"})
    CHECK(std::find(fields(ls[0]).begin(), fields(ls[0]).end(), std::string(name)) != fields(ls[0]).end());
  CHECK(std::stod(column(r.out, "x", 1)) == 0.0);
  CHECK(ogive::close(std::stod(column(r.out, "x", 7)), 10.0, ogive::kExact));
}

TEST_CASE("cli: check reports every method within tolerance - methods and integrators selectable") {
  const Run r = run_command({"check", "--eccentricity", "0,1", "--rtol", "1e-7", "--integrator", "bdf"});
  REQUIRE(r.status == 0);
  const auto ls = lines(r.out);
  REQUIRE(ls.size() == 1 + 6);
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
      {"nonsense"},
      {},
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
