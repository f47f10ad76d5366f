// The CLI's subcommands in-process (thrust, profile, check, bench, curve): a header and one row per scene,
// a failure as a status in its row with exit 3, help on stdout, --version, the help's own examples, and
// deterministic output.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "cli.hpp"
#include "ogive/solve/solve.hpp"
#include "support/cli_run.hpp"
#include "support/files.hpp"
#include "support/tolerances.hpp"

using namespace ogive;
using namespace ogive::test;
using ogive::cli::run_cli;

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

TEST_CASE("trust: profile's failure row - one row per scene - no numbers - exit 3") {
  const Run r = run_command({"profile", "--method", "shooting", "--max-steps", "3", "--eccentricity", "0,0.5", "--stations", "11",
                             "--all-columns"});
  CHECK(r.status == 3);
  REQUIRE(lines(r.out).size() == 3);
  for (std::size_t row : {1, 2}) {
    CHECK(column(r.out, "status", row) == "integrator_failure");
    CHECK(column(r.out, "message", row).find("CV_TOO_MUCH_WORK") != std::string::npos);
    for (const char* name : {"H_over_V", "s", "N", "M", "thrust_eccentricity"}) CHECK(column(r.out, name, row).empty());
  }
}

TEST_CASE("trust: bench and curve print what they promise") {
  const Run b = run_command({"bench", "--eccentricity", "0.5", "--methods", "closed-form,shooting,auto", "--rtols", "1e-6,1e-9",
                     "--repeats", "1"});
  REQUIRE(b.status == 0);
  const auto ls = lines(b.out);
  REQUIRE(ls.size() == 1 + 1 + 2 + 1);  // closed form once, shooting per rtol, auto (closed form) once
  for (std::size_t row = 1; row < ls.size(); ++row) {
    CAPTURE(ls[row]);
    CHECK(fields(ls[row]).size() == fields(ls[0]).size());
    CHECK(column(b.out, "status", row) == "success");
    const double rtol = column(b.out, "rtol", row).empty() ? 1e-14 : std::stod(column(b.out, "rtol", row));
    CHECK(within_tolerance(std::stod(column(b.out, "error_H_over_V", row)), rtol));
    CHECK(within_tolerance(std::stod(column(b.out, "error_profile", row)), rtol));
    CHECK(std::stod(column(b.out, "median_seconds", row)) > 0);
  }
  CHECK(column(b.out, "chosen_method", 4) == "closed-form");
  // On a circular arc under a live load the closed form does not apply: auto is CVODE shooting, one row
  // per rtol, each within its own rtol (not one row, as if auto were the closed form).
  const Run live = run_command({"bench", "--curve", "semicircular", "--live-load", "5e3", "--live-load-to", "0.5",
                                "--methods", "closed-form,auto", "--rtols", "1e-6,1e-10", "--repeats", "1"});
  REQUIRE(live.status == 0);
  REQUIRE(lines(live.out).size() == 1 + 2);  // no closed-form row: not applicable
  for (std::size_t row : {1, 2}) {
    CAPTURE(row);
    CHECK(column(live.out, "method", row) == "auto");
    CHECK(column(live.out, "status", row) == "success");
    const double rtol = std::stod(column(live.out, "rtol", row));
    CHECK(within_tolerance(std::stod(column(live.out, "error_H_over_V", row)), rtol));
    CHECK(within_tolerance(std::stod(column(live.out, "error_profile", row)), rtol));
  }
  const Run c = run_command({"curve", "--curve", "parabolic", "--rise-ratio", "0.25", "--stations", "5"});
  REQUIRE(c.status == 0);
  REQUIRE(lines(c.out).size() == 1 + 5);
  // y = 4 h x (L - x) / L^2 at the stations, and the tangent's angle from its slope.
  for (std::size_t row = 1; row <= 5; ++row) {
    const double x = std::stod(column(c.out, "x", row)), y = std::stod(column(c.out, "y", row));
    CHECK(std::abs(y - 4 * 2.5 * x * (10 - x) / 100) <= kExact * 10);
    CHECK(std::abs(std::tan(std::stod(column(c.out, "theta", row))) - 4 * 2.5 * (10 - 2 * x) / 100) <= 1e-9);
  }
  CHECK(close(std::stod(column(c.out, "x", 5)), 10.0, kExact));
}

TEST_CASE("quadrature: --method quadrature in the CLI, no integrator, its estimate, not_applicable said") {
  std::ostringstream out, err;
  REQUIRE(cli::run_cli({"thrust", "--curve", "catenary", "--rise-ratio", "0.5", "--method", "quadrature",
                        "--all-columns"},
                       out, err) == 0);
  const std::string csv = out.str();
  const std::string header = csv.substr(0, csv.find('\n'));
  const std::string row = csv.substr(csv.find('\n') + 1);
  CHECK(header.find(",method,integrator,rtol,status,") != std::string::npos);
  CHECK(row.find(",quadrature,,1e-08,success,") != std::string::npos);  // no integrator: empty
  CHECK(err.str().empty());
  // Told to ignore a survey's breakpoints: not applicable, exit 3, no number where there is none.
  std::ostringstream out2, err2;
  CHECK(cli::run_cli({"thrust", "--curve", "points", "--curve-file", OGIVE_DATA_DIR "/curves/parabola-40.csv",
                      "--method", "quadrature", "--ignore-breakpoints", "--all-columns"},
                     out2, err2) == 3);
  CHECK(out2.str().find(",quadrature,,1e-08,not_applicable,half,,") != std::string::npos);
  CHECK(out2.str().find("nan") == std::string::npos);
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

TEST_CASE("cli: --version names the project version, bare ogive prints the help on stderr with exit 2") {
  const Run v = run_command({"--version"});
  CHECK(v.status == 0);
  CHECK(v.out == std::string("ogive ") + OGIVE_VERSION + "\n");
  const Run bare = run_command({});
  CHECK(bare.status == 2);
  CHECK(bare.out.empty());
  for (const char* sub : {"thrust", "profile", "check", "curve", "bench", "draw", "docs/cli.md", "docs/model.md"})
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

namespace {

// A stream buffer that refuses every byte, as a full disk or a closed descriptor does.
class RefusingBuffer : public std::streambuf {
 protected:
  std::streamsize xsputn(const char*, std::streamsize) override { return 0; }
  int overflow(int) override { return traits_type::eof(); }
};

}  // namespace

TEST_CASE("cli: help and version that cannot be written exit 4 with one line - extra arguments are refused") {
  std::vector<std::vector<std::string>> asks = {{"--version"}, {"--help"}};
  for (const char* sub : {"thrust", "profile", "check", "curve", "bench", "draw", "limit", "spread"})
    asks.push_back({sub, "--help"});
  for (const auto& args : asks) {
    CAPTURE(args.back());
    CAPTURE(args.front());
    RefusingBuffer refusing;
    std::ostream full(&refusing);
    std::ostream closed(nullptr);  // badbit from the start
    for (std::ostream* out : {&full, &closed}) {
      std::ostringstream err;
      CHECK(run_cli(args, *out, err) == cli::kExitOutput);
      CHECK(lines(err.str()).size() == 1);
      CHECK(err.str().find("cannot write the output") != std::string::npos);
    }
  }
  // An argument nobody takes, before or after help or version: refused, and named.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--version", "extra"},
           {"extra", "--version"},
           {"--help", "extra"},
           {"thrust", "--help", "extra"},
           {"thrust", "extra", "--help"},
           {"draw", "--eccentricity", "0.5", "extra", "--version"}}) {
    check_refused(args);
    CHECK(run_command(args).err.find("extra") != std::string::npos);
  }
}

TEST_CASE("cli: bench exits 3 when a row failed - the row says which") {
  // A survey's breakpoints ignored: quadrature is not applicable, its row says so; multiple shooting
  // steps across them, where no error estimate holds: unverified.
  const Run r = run_command({"bench", "--curve", "points", "--curve-file", OGIVE_DATA_DIR "/curves/parabola-40.csv",
                             "--methods", "multiple-shooting,quadrature", "--ignore-breakpoints", "--rtols", "1e-6",
                             "--repeats", "1", "--columns", "method,status"});
  CHECK(r.status == cli::kExitNotConverged);
  CHECK(r.err.empty());
  REQUIRE(lines(r.out).size() == 1 + 2);
  CHECK(column(r.out, "status", 1) == "unverified");
  CHECK(column(r.out, "status", 2) == "not_applicable");
}
