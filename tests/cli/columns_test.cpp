// The CLI's CSV: every command's output read by a strict reader, every column documented with its unit,
// inputs echoed as typed, one spelling for booleans and for "no number", the columns chosen by default
// and by --columns, the thrust line's summary and the section's faces against the profile, and lists of
// solver options.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "support/cli_run.hpp"
#include "support/tolerances.hpp"
#include "values.hpp"

using namespace ogive::test;

namespace {

const std::vector<std::vector<std::string>> kCommands = {
    {"thrust", "--eccentricity", "0:1:11", "--thickness-ratio", "0.06,0.1"},
    {"thrust", "--curve", "catenary", "--rise-ratio", "0.5,2", "--thickness-ratio", "0.5"},  // an invalid scene
    {"thrust", "--method", "shooting", "--max-steps", "3"},                                   // a failed solve
    {"profile", "--eccentricity", "0,0.5", "--stations", "11"},
    {"profile", "--method", "shooting", "--max-steps", "3"},
    {"check", "--curve", "parabolic", "--rise-ratio", "0.2,0.4"},
    {"curve", "--curve", "four-centred", "--rise-ratio", "0.4,0.5", "--stations", "7"},
    {"bench", "--eccentricity", "0.5", "--method", "closed-form,shooting", "--rtol", "1e-6", "--repeats", "1"},
    {"limit", "--eccentricity", "0,0.5", "--thickness-ratio", "0.15", "--joints-count", "101"},
    {"limit", "--thickness-ratio", "0.03", "--joints-count", "101"},  // inadmissible
    {"limit", "--point-load", "2e5", "--point-load-at", "0.25", "--thrust-line", "collapse", "--joints-count", "101"},
};

// The documented columns of a command (with its options: limit's --thrust-line has its own columns):
// `--columns help` as name -> (unit, meaning).
std::map<std::string, std::pair<std::string, std::string>> documented(std::vector<std::string> command) {
  command.insert(command.end(), {"--columns", "help"});
  const Run help = run_command(command);
  REQUIRE(help.status == 0);
  const auto ls = lines(help.out);
  REQUIRE(ls.size() > 1);
  CHECK(ls[0] == "column,unit,meaning");
  std::map<std::string, std::pair<std::string, std::string>> out;
  for (std::size_t i = 1; i < ls.size(); ++i) {
    const auto f = fields(ls[i]);
    REQUIRE(f.size() == 3);
    out[f[0]] = {f[1], f[2]};
  }
  return out;
}

}  // namespace

TEST_CASE("csv: a strict reader reads every command - rectangular - every column documented - no nan or inf") {
  for (const auto& base : kCommands) {
    const auto docs = documented(base);
    for (bool all : {false, true}) {
      std::vector<std::string> args = base;
      if (all) args.push_back("--all-columns");
      const Run r = run_command(args);
      CAPTURE(args[0]);
      CAPTURE(args[1]);
      CAPTURE(all);
      REQUIRE((r.status == 0 || r.status == 3));
      const auto ls = lines(r.out);
      REQUIRE(ls.size() >= 2);
      const auto header = fields(ls[0]);
      CHECK(header.front() == "scene");
      std::set<std::string> unique(header.begin(), header.end());
      CHECK(unique.size() == header.size());  // no name twice
      for (const std::string& name : header) {
        CAPTURE(name);
        REQUIRE(docs.count(name) == 1);
        CHECK(!docs.at(name).second.empty());  // a meaning; the unit is empty only for pure numbers
      }
      for (std::size_t row = 1; row < ls.size(); ++row) {
        const auto f = fields(ls[row]);
        CHECK(f.size() == header.size());
        for (const std::string& v : f) {
          CHECK(v != "nan");
          CHECK(v != "inf");
          CHECK(v != "-inf");
          CHECK(v != "none");
        }
        for (std::size_t c = 0; c < header.size(); ++c)
          if (header[c] == "plane_strain" || header[c].rfind("thrust_in_", 0) == 0 || header[c] == "within_tolerance")
            CHECK((f[c] == "true" || f[c] == "false" || f[c].empty()));
      }
    }
  }
}

TEST_CASE("csv: inputs round-trip as typed - decimal ranges - a scene number per scene") {
  const Run r = run_command({"thrust", "--support-displacement-ratio", "0:0.0003:7", "--eccentricity", "0:1:11"});
  REQUIRE(r.status == 0);
  REQUIRE(lines(r.out).size() == 1 + 77);
  CHECK(column(r.out, "eccentricity", 4) == "0.3");
  CHECK(column(r.out, "support_displacement_ratio", 12) == "5e-05");
  CHECK(column(r.out, "scene", 77) == "77");
  const Run seg = run_command({"thrust", "--curve", "segmental", "--rise-ratio", "0.2", "--all-columns"});
  CHECK(column(seg.out, "rise_ratio") == "0.2");
  CHECK(column(seg.out, "plane_strain") == "false");
  CHECK(column(seg.out, "integrator").empty());  // not applicable to the closed form: empty
  const Run semi = run_command({"thrust", "--curve", "semicircular", "--all-columns"});
  CHECK(column(semi.out, "rise_ratio") == "0.5");  // derived from the geometry, 12 digits
  // Every point of a decimal range is the double nearest the decimal value.
  const std::vector<double> v = ogive::cli::parse_values("0.06:0.2:8", "--thickness-ratio");
  const std::vector<double> expected = {0.06, 0.08, 0.1, 0.12, 0.14, 0.16, 0.18, 0.2};
  CHECK(v == expected);
  const std::vector<double> w = ogive::cli::parse_values("-1e-3:2e-3:4", "--x");
  CHECK(w == std::vector<double>{-1e-3, 0.0, 1e-3, 2e-3});
}

TEST_CASE("csv: by default the inputs that vary and the results - --columns chooses, in its order - --all-columns prints all") {
  const Run r = run_command({"thrust", "--eccentricity", "0,1"});
  const auto header = fields(lines(r.out)[0]);
  CHECK(std::find(header.begin(), header.end(), "eccentricity") != header.end());
  CHECK(std::find(header.begin(), header.end(), "youngs_modulus") == header.end());  // the same in every scene
  for (const char* name : {"H", "V", "H_over_V", "status", "message", "error_estimate"})
    CHECK(std::find(header.begin(), header.end(), name) != header.end());
  CHECK(std::find(header.begin(), header.end(), "max_thrust_eccentricity") == header.end());  // asked by name
  const Run chosen = run_command({"thrust", "--eccentricity", "0,1", "--columns", "H_over_V,eccentricity"});
  CHECK(lines(chosen.out)[0] == "scene,H_over_V,eccentricity");  // scene first, then as given
  CHECK(column(chosen.out, "H_over_V") == column(r.out, "H_over_V"));
  CHECK(column(chosen.out, "eccentricity") == column(r.out, "eccentricity"));
  CHECK(lines(run_command({"thrust", "--columns", "H,scene,H"}).out)[0] == "scene,H");  // once each
  // Every field moves with its name: each row's fields equal those of the full order, by name, in a
  // command with quoted messages (a failed solve), one with a scene's fields shared by its stations
  // (profile) and one without a varying input.
  for (const std::vector<std::string>& command :
       std::vector<std::vector<std::string>>{{"thrust", "--method", "shooting", "--max-steps", "3"},
                                             {"profile", "--eccentricity", "0,0.5", "--stations", "5"},
                                             {"limit", "--joints-count", "101"}}) {
    auto all = command;
    all.push_back("--all-columns");
    const Run full = run_command(all);
    const auto names = fields(lines(full.out)[0]);
    std::vector<std::string> reversed(names.rbegin(), names.rend());
    std::string list;
    for (const std::string& n : reversed) list += (list.empty() ? "" : ",") + n;
    auto chosen_all = command;
    chosen_all.insert(chosen_all.end(), {"--columns", list});
    const Run backwards = run_command(chosen_all);
    REQUIRE(backwards.status == full.status);
    const auto header_back = fields(lines(backwards.out)[0]);
    REQUIRE(header_back.size() == names.size());
    CHECK(header_back[0] == "scene");
    const std::size_t rows = lines(full.out).size();
    REQUIRE(lines(backwards.out).size() == rows);
    for (std::size_t row = 1; row < rows; ++row)
      for (const std::string& n : names) CHECK(column(backwards.out, n, row) == column(full.out, n, row));
  }
  check_refused({"thrust", "--columns", "H_ovr_V"});
  const Run misspelt = run_command({"thrust", "--columns", "H_ovr_V"});
  CHECK(misspelt.err.find("did you mean 'H_over_V'") != std::string::npos);
  check_refused({"profile", "--columns", ""});
  check_refused({"bench", "--columns", "H,"});
}

TEST_CASE("csv: the thrust line's summary - largest |e| - where - in kern and in section - against the profile") {
  // The semicircle at t = 0.08 L (paper's Figure 11): |e| peaks at the crown, 282 %; outside the kern,
  // inside the section. The summary's maximum is at least the profile's largest station value.
  const Run t = run_command({"thrust", "--curve", "semicircular", "--all-columns"});
  const Run p = run_command({"profile", "--curve", "semicircular", "--stations", "201"});
  double largest = 0;
  for (std::size_t row = 1; row < lines(p.out).size(); ++row)
    largest = std::max(largest, std::abs(std::stod(column(p.out, "thrust_eccentricity", row))));
  const double summary = std::stod(column(t.out, "max_thrust_eccentricity"));
  CHECK(summary >= largest);
  CHECK(summary <= largest * (1 + 1e-9));  // the crown is a station: the peak is sampled exactly
  CHECK(std::abs(std::stod(column(t.out, "max_thrust_eccentricity_at")) - 0.5 * 3.141592653589793 * 5) <= 1e-5);
  CHECK(column(t.out, "thrust_in_kern") == "false");
  CHECK(column(t.out, "thrust_in_section") == "true");
  // Thick equilateral arch: inside the kern everywhere (largest linear |e| 99 %, docs/model.md, Figure 11).
  const Run thick = run_command({"thrust", "--eccentricity", "0.5", "--thickness-ratio", "0.2", "--columns",
                                 "max_thrust_eccentricity,thrust_in_kern"});
  CHECK(std::stod(column(thick.out, "max_thrust_eccentricity")) < 100);
  CHECK(column(thick.out, "thrust_in_kern") == "true");
  // Where the crown goes into tension (support spreading past d/L = 0.0177 %) there is no bound.
  const Run spread = run_command({"thrust", "--support-displacement-ratio", "0.0003", "--all-columns"});
  CHECK(column(spread.out, "max_thrust_eccentricity").empty());
  CHECK(column(spread.out, "thrust_in_section") == "false");
}

TEST_CASE("csv: the largest compressive stress - against a dense profile - kPa with --units kN") {
  // Pinned, half the span under a live load (given with its unit: the same load with --units kN): the
  // maximum lies inside the arch, between stations.
  const std::vector<std::string> scene = {"--left-support", "pinned", "--right-support", "pinned", "--live-load", "5kN/m2",
                                          "--live-load-to", "0.5"};
  auto with = [&](std::vector<std::string> command, const std::vector<std::string>& more) {
    command.insert(command.begin() + 1, scene.begin(), scene.end());
    command.insert(command.end(), more.begin(), more.end());
    return run_command(command);
  };
  const Run t = with({"thrust"}, {"--columns", "max_compressive_stress,max_compressive_stress_at"});
  const Run p = with({"profile"}, {"--stations", "20001", "--columns", "s,compressive_stress"});
  REQUIRE(t.status == 0);
  REQUIRE(p.status == 0);
  const auto rows = lines(p.out);
  double largest = 0, at = 0;
  for (std::size_t row = 1; row < rows.size(); ++row) {
    const auto f = fields(rows[row]);  // scene, s, compressive_stress
    if (std::stod(f.at(2)) > largest) {
      largest = std::stod(f.at(2));
      at = std::stod(f.at(1));
    }
  }
  const double summary = std::stod(column(t.out, "max_compressive_stress"));
  // The stations sample the same field: the summary, the field's refined maximum, is at least their largest
  // (to round-off) and above it by no more than the stations' spacing leaves at a smooth peak (measured
  // 6.8e-9 at 20001 stations); both place it alike.
  constexpr double kPeakBetweenStations = 1e-7;
  const double length = 3.141592653589793 * 10, spacing = length / 20000;  // the semicircle, span 10 m
  CHECK(summary >= largest * (1 - ogive::kExact));
  CHECK(summary <= largest * (1 + kPeakBetweenStations));
  CHECK(std::abs(std::stod(column(t.out, "max_compressive_stress_at")) - at) <= 2 * spacing);
  // --units kN: forces in kN/m, stresses in kPa (N/m^2 / 1000), and the first line says so.
  const Run kn = with({"thrust"}, {"--columns", "H,max_compressive_stress", "--units", "kN"});
  REQUIRE(kn.status == 0);
  const auto kn_lines = lines(kn.out);
  REQUIRE(kn_lines.size() == 3);
  CHECK(kn_lines[0] == "# units: kN (forces in kN/m and moments in kN m/m per metre of vault width; stresses in kPa)");
  const std::string body = kn.out.substr(kn.out.find('\n') + 1);
  CHECK(ogive::close(std::stod(column(body, "max_compressive_stress")), summary / 1000, ogive::kExact));
  // Without a stress printed the line is the forces' alone; --columns help says kPa for the stresses, and
  // Pa still for Young's modulus, an input given in Pa whatever --units says.
  const Run forces = with({"profile"}, {"--stations", "3", "--columns", "N", "--units", "kN"});
  CHECK(lines(forces.out).at(0) == "# units: kN (forces in kN/m and moments in kN m/m per metre of vault width)");
  const auto help = documented({"profile", "--units", "kN"});
  CHECK(help.at("compressive_stress").first == "kPa");
  CHECK(help.at("youngs_modulus").first == "Pa");
  CHECK(documented({"thrust"}).at("max_compressive_stress").first == "Pa");
}

TEST_CASE("csv: --compressive-strength adds the stresses' ratio to f_c - the same with --units kN") {
  const std::vector<std::string> scene = {"--curve", "semicircular", "--live-load", "5kN/m2", "--live-load-to", "0.5"};
  auto with = [&](std::vector<std::string> command, const std::vector<std::string>& more) {
    command.insert(command.begin() + 1, scene.begin(), scene.end());
    command.insert(command.end(), more.begin(), more.end());
    return run_command(command);
  };
  const Run t = with({"thrust"}, {"--compressive-strength", "2.5MPa", "--columns", "max_compressive_stress,max_stress_ratio"});
  REQUIRE(t.status == 0);
  CHECK(ogive::close(std::stod(column(t.out, "max_stress_ratio")), std::stod(column(t.out, "max_compressive_stress")) / 2.5e6,
                     ogive::kExact));
  const Run kn = with({"thrust"}, {"--compressive-strength", "2.5MPa", "--units", "kN", "--columns", "max_stress_ratio"});
  REQUIRE(kn.status == 0);
  CHECK(column(kn.out.substr(kn.out.find('\n') + 1), "max_stress_ratio") == column(t.out, "max_stress_ratio"));
  const Run p = with({"profile"}, {"--stations", "5", "--compressive-strength", "2.5MPa", "--columns", "compressive_stress,stress_ratio"});
  REQUIRE(p.status == 0);
  for (std::size_t row = 1; row <= 5; ++row)
    CHECK(ogive::close(std::stod(column(p.out, "stress_ratio", row)), std::stod(column(p.out, "compressive_stress", row)) / 2.5e6,
                       ogive::kExact));
  // Without the option the ratio is empty; a bad strength is refused.
  CHECK(column(with({"thrust"}, {"--columns", "max_stress_ratio"}).out, "max_stress_ratio").empty());
  CHECK(with({"profile"}, {"--compressive-strength", "-2MPa"}).status == 2);
}

TEST_CASE("csv: profile prints each section's intrados and extrados points - t apart, centred on the axis") {
  const Run r = run_command({"profile", "--eccentricity", "0.5", "--thickness-ratio", "0.2", "--stations", "21"});
  REQUIRE(r.status == 0);
  const double t = 2.0;
  for (std::size_t row = 1; row <= 21; ++row) {
    auto at = [&](const char* name) { return std::stod(column(r.out, name, row)); };
    CHECK(std::abs(std::hypot(at("extrados_x") - at("intrados_x"), at("extrados_y") - at("intrados_y")) - t) <= 1e-12 * t);
    CHECK(std::abs((at("extrados_x") + at("intrados_x")) / 2 - at("x")) <= 1e-12 * 10);
    CHECK(std::abs((at("extrados_y") + at("intrados_y")) / 2 - at("y")) <= 1e-12 * 10);
    // Inside the kern (|e| <= 100 %): the thrust point lies between the faces, within t/6 of the axis.
    CHECK(std::hypot(at("thrust_x") - at("x"), at("thrust_y") - at("y")) <= t / 6 * (1 + 1e-12));
  }
}

TEST_CASE("csv: --method, --integrator and --rtol take lists (and --rtol ranges) like every scene option") {
  const Run r = run_command({"thrust", "--curve", "catenary", "--eccentricity", "0", "--rtol", "1e-6,1e-8",
                             "--integrator", "adams,bdf"});
  CHECK(r.status == 2);  // --eccentricity does not apply to the catenary
  const Run lists = run_command({"thrust", "--curve", "catenary", "--rise-ratio", "0.4,0.5", "--rtol", "1e-6,1e-8",
                                 "--integrator", "adams,bdf", "--method", "shooting"});
  REQUIRE(lists.status == 0);
  REQUIRE(lines(lists.out).size() == 1 + 2 * 4);
  // The solver's options vary fastest, after the scene's; they are printed because they vary.
  CHECK(column(lists.out, "rise_ratio", 4) == "0.4");
  CHECK(column(lists.out, "integrator", 3) == "bdf");
  CHECK(column(lists.out, "rtol", 2) == "1e-08");
  CHECK(column(lists.out, "scene", 5) == "2");
  for (std::size_t row = 1; row <= 8; ++row) CHECK(column(lists.out, "status", row) == "success");
  const Run profile = run_command({"profile", "--rtol", "1e-6:1e-4:3", "--stations", "5", "--method", "shooting"});
  REQUIRE(profile.status == 0);
  CHECK(lines(profile.out).size() == 1 + 3 * 5);
  CHECK(column(profile.out, "rtol", 6) == "5.05e-05");
  check_refused({"thrust", "--rtol", "1e-6,0"});
  check_refused({"thrust", "--rtol", "1e-6,"});
  check_refused({"thrust", "--method", "shooting,"});
  check_refused({"draw", "--rtol", "1e-6,1e-8", "--output", "x.svg"});
}
