// Inputs as engineers give them: values with units (the same bytes as the bare number in the option's
// own unit), units refused where they do not fit, --dimensions intrados (the same bytes as the axis'
// equivalent, and the geometry of circular arcs by hand), --fill-height crown+D, --units kn, and the
// warnings on stderr about a forgotten --span or a load that looks meant in kN.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

using namespace ogive::test;

namespace {

std::vector<std::string> with(std::vector<std::string> head, const std::vector<std::string>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

// Both command lines print the same bytes on stdout and stderr, with exit status 0.
void check_same(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  std::string joined;
  for (const auto& w : a) joined += w + " ";
  CAPTURE(joined);
  const Run ra = run_command(a), rb = run_command(b);
  REQUIRE(ra.status == 0);
  CHECK(rb.status == 0);
  CHECK(ra.out == rb.out);
  CHECK(ra.err == rb.err);
}

}  // namespace

TEST_CASE("cli: a value with a unit is the same bytes as the bare number in the option's unit") {
  const std::vector<std::string> thrust = {"thrust", "--span", "8", "--all-columns"};
  check_same(with(thrust, {"--thickness", "600mm"}), with(thrust, {"--thickness", "0.6"}));
  check_same(with(thrust, {"--thickness", "60cm"}), with(thrust, {"--thickness", "0.6"}));
  check_same(with(thrust, {"--thickness", "0.6m"}), with(thrust, {"--thickness", "0.6"}));
  check_same(with(thrust, {"--thickness", "0.5m:700mm:3"}), with(thrust, {"--thickness", "0.5:0.7:3"}));
  check_same(with(thrust, {"--thickness", "6e2mm,0.7m"}), with(thrust, {"--thickness", "0.6,0.7"}));
  check_same(with(thrust, {"--density", "2.2t/m3"}), with(thrust, {"--density", "2200"}));
  check_same(with(thrust, {"--density", "2200kg/m^3"}), with(thrust, {"--density", "2200"}));
  check_same(with(thrust, {"--youngs-modulus", "15GPa"}), with(thrust, {"--youngs-modulus", "15e9"}));
  check_same(with(thrust, {"--youngs-modulus", "15000N/mm2"}), with(thrust, {"--youngs-modulus", "15e9"}));
  check_same(with(thrust, {"--gravity", "9.81m/s2"}), with(thrust, {"--gravity", "9.81"}));
  check_same(with(thrust, {"--point-load", "100kN", "--point-load-x", "2000mm"}),
             with(thrust, {"--point-load", "1e5", "--point-load-x", "2"}));
  check_same(with(thrust, {"--live-load", "5kN/m2"}), with(thrust, {"--live-load", "5000"}));
  check_same(with(thrust, {"--live-load", "5kPa"}), with(thrust, {"--live-load", "5000"}));
  // Forces with --units kN: a unit is converted to kN, a bare number is kN; kn is kN.
  check_same(with(thrust, {"--units", "kN", "--point-load", "100kN"}), with(thrust, {"--units", "kN", "--point-load", "100"}));
  check_same(with(thrust, {"--units", "kN", "--point-load", "100000N"}),
             with(thrust, {"--units", "kN", "--point-load", "100"}));
  check_same(with(thrust, {"--units", "kn", "--point-load", "100"}), with(thrust, {"--units", "kN", "--point-load", "100"}));
  // limit reads the same values.
  const std::vector<std::string> limit = {"limit", "--span", "8", "--all-columns"};
  check_same(with(limit, {"--thickness", "800mm", "--fill-density", "2t/m3", "--fill-height", "7400mm"}),
             with(limit, {"--thickness", "0.8", "--fill-density", "2000", "--fill-height", "7.4"}));
}

TEST_CASE("cli: a unit that does not fit its option is refused with one line naming the option") {
  // A unit of each kind on an option of every other kind, and any unit on a ratio or a count.
  const std::vector<std::pair<std::string, std::string>> kinds = {
      {"--thickness", "1m"}, {"--point-load", "1kN"}, {"--live-load", "1kPa"}, {"--density", "1kg/m3"},
      {"--youngs-modulus", "1GPa"}, {"--gravity", "1m/s2"}};
  for (const auto& [option, own] : kinds)
    for (const auto& [other, value] : kinds) {
      if (own == value || (option == "--youngs-modulus" && value == "1kPa") || (option == "--live-load" && value == "1GPa"))
        continue;  // Pa is both a pressure's and a modulus' unit (kPa and GPa are each one's only)
      check_refused({"thrust", option, value});
    }
  for (const char* ratio : {"--thickness-ratio", "--rise-ratio", "--point-load-at", "--eccentricity", "--poisson-ratio",
                            "--horizontal-acceleration", "--support-displacement-ratio"})
    check_refused({"thrust", ratio, "0.1m"});
  check_refused({"thrust", "--thickness", "1furlong"});
  check_refused({"thrust", "--thickness", "0.5m:0.7m:3m"});  // a count takes no unit
  check_refused({"thrust", "--fill-density", "2000", "--fill-height", "crown*2"});
  check_refused({"thrust", "--units", "MN"});
}

TEST_CASE("cli: --dimensions intrados is the same bytes as its axis equivalent, and the circle's by hand") {
  for (const std::vector<std::string>& arch :
       {std::vector<std::string>{"--curve", "segmental", "--span", "12", "--rise", "3", "--thickness", "0.6"},
        std::vector<std::string>{"--curve", "pointed", "--span", "8", "--rise", "6.93", "--thickness", "0.8"},
        std::vector<std::string>{"--curve", "semicircular", "--span", "8", "--thickness", "0.8"},
        std::vector<std::string>{"--curve", "parabolic", "--span", "10", "--rise", "4", "--thickness", "0.5"}}) {
    const Run intrados = run_command(with(with({"thrust", "--all-columns", "--dimensions", "intrados"}, arch), {}));
    REQUIRE(intrados.status == 0);
    // The axis the row prints, given as the axis.
    std::vector<std::string> axis = {"thrust", "--all-columns", "--curve", arch[1], "--span", column(intrados.out, "span"),
                                     "--thickness", column(intrados.out, "thickness")};
    if (arch[1] != "semicircular") axis = with(axis, {"--rise", column(intrados.out, "rise")});
    const Run as_axis = run_command(axis);
    REQUIRE(as_axis.status == 0);
    CHECK(as_axis.out == intrados.out);
  }
  // Circular arcs by hand: the intrados has the axis' centres and the radius R - t/2.
  const Run seg = run_command({"thrust", "--curve", "segmental", "--span", "12", "--rise", "3", "--thickness", "0.6",
                               "--dimensions", "intrados", "--all-columns"});
  // The intrados: radius (6^2 + 3^2) / (2 3) = 7.5, sin phi = 0.8; the axis: radius 7.8.
  CHECK(std::abs(std::stod(column(seg.out, "span")) - 2 * 7.8 * 0.8) <= ogive::kExact * 12.48);
  CHECK(std::abs(std::stod(column(seg.out, "rise")) - 7.8 * 0.4) <= ogive::kExact * 3.12);
  const Run semi = run_command({"thrust", "--curve", "semicircular", "--span", "8", "--thickness", "0.8",
                                "--dimensions", "intrados", "--all-columns"});
  CHECK(std::abs(std::stod(column(semi.out, "span")) - 8.8) <= ogive::kExact * 8.8);
  // Pointed: the intrados' arcs (radius R - t/2, centres R from each springing) meet at mid-span at the
  // rise given.
  const Run pointed = run_command({"thrust", "--curve", "pointed", "--span", "8", "--rise", "6.93", "--thickness", "0.8",
                                   "--dimensions", "intrados", "--all-columns"});
  const double L = std::stod(column(pointed.out, "span")), R = std::stod(column(pointed.out, "radius"));
  CHECK(std::abs(L - 8.8) <= ogive::kExact * 8.8);
  CHECK(std::abs(std::sqrt((R - 0.4) * (R - 0.4) - (R - L / 2) * (R - L / 2)) - 6.93) <= ogive::kExact * 6.93);

  check_refused({"thrust", "--dimensions", "intrados", "--thickness-ratio", "0.1"});
  check_refused({"thrust", "--dimensions", "intrados", "--curve", "segmental", "--span", "8", "--thickness", "0.5"});
  check_refused({"thrust", "--dimensions", "intrados", "--span", "8"});
  check_refused({"thrust", "--dimensions", "extrados"});
}

TEST_CASE("cli: --fill-height crown+D puts the fill D m over the extrados' crown") {
  const std::vector<std::string> arch = {"limit", "--span", "8", "--thickness", "0.8", "--rise", "6.93",
                                         "--fill-density", "2000", "--columns", "fill_height"};
  const Run crown = run_command(with(arch, {"--fill-height", "crown"}));
  const Run above = run_command(with(arch, {"--fill-height", "crown+0.5"}));
  const Run above_mm = run_command(with(arch, {"--fill-height", "crown+500mm"}));
  REQUIRE(crown.status == 0);
  REQUIRE(above.status == 0);
  const double h = std::stod(column(crown.out, "fill_height"));
  CHECK(std::abs(std::stod(column(above.out, "fill_height")) - (h + 0.5)) <= ogive::kExact * h);
  CHECK(above_mm.out == above.out);
}

TEST_CASE("cli: warnings on stderr, the output unchanged: metres without --span, a load that looks meant in kN") {
  const Run metres = run_command({"thrust", "--thickness", "0.6", "--columns", "H"});
  REQUIRE(metres.status == 0);
  CHECK(metres.err == "ogive: warning: --thickness is in metres but --span was not given: the default span of 10 m "
                      "is used\n");
  CHECK(run_command({"thrust", "--thickness", "0.6", "--span", "10", "--columns", "H"}).out == metres.out);
  const Run small = run_command({"thrust", "--span", "10", "--point-load", "100", "--columns", "H"});
  REQUIRE(small.status == 0);
  CHECK(small.err.find("ogive: warning: --point-load: 100 N/m is less than 1 % of the arch's own weight") == 0);
  CHECK(lines(small.err).size() == 1);
  // In kN, or as large as meant: no warning; a sweep warns once.
  CHECK(run_command({"thrust", "--span", "10", "--point-load", "100kN", "--columns", "H"}).err.empty());
  CHECK(run_command({"thrust", "--span", "10", "--point-load", "1e5", "--columns", "H"}).err.empty());
  CHECK(lines(run_command({"thrust", "--span", "10", "--point-load", "100,200", "--columns", "H"}).err).size() == 1);
}

TEST_CASE("cli: --unit-weight gives the density gamma / g, and refuses --density beside it") {
  const Run gamma = run_command({"thrust", "--unit-weight", "22kN/m3", "--gravity", "9.81", "--columns",
                                 "density,unit_weight,H"});
  REQUIRE(gamma.status == 0);
  CHECK(column(gamma.out, "unit_weight") == "22000");
  const double rho = std::stod(column(gamma.out, "density"));
  CHECK(std::abs(rho * 9.81 - 22000) <= ogive::kExact * 22000);
  const Run same = run_command({"thrust", "--density", column(gamma.out, "density"), "--columns", "H"});
  REQUIRE(same.status == 0);
  const double H = std::stod(column(gamma.out, "H"));
  CHECK(std::abs(std::stod(column(same.out, "H")) - H) <= ogive::kExact * H);
  check_refused({"thrust", "--unit-weight", "22000", "--density", "2200"});
  check_refused({"thrust", "--unit-weight", "2.2t/m3"});
  check_refused({"curve", "--unit-weight", "22000"});
}
