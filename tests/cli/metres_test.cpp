// Scene options in metres and kN beside the ratios: an engineer's session, each metre/ratio pair giving
// the same scene, both of a pair refused, --units kN and --digits.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/cli_run.hpp"
#include "support/tolerances.hpp"

namespace ogive::test {
namespace {

// The rows of a command's output without the '# units' line that --units kN puts first.
std::string without_comment(const std::string& csv) {
  return csv.rfind("#", 0) == 0 ? csv.substr(csv.find('\n') + 1) : csv;
}

Run ok(std::vector<std::string> args) {
  const Run r = run_command(std::move(args));
  REQUIRE_MESSAGE(r.status == 0, r.err);
  return r;
}

double number(const std::string& csv, const std::string& name, std::size_t row = 1) {
  return std::stod(column(without_comment(csv), name, row));
}

// The result columns of thrust and limit that the pair tests compare: everything but the inputs' echo.
const std::string kThrustResults = "method,status,H,V,H_over_V,H_left,V_left,M_left,H_right,V_right,M_right,error_estimate";

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("metres: the engineer's session, an 8 m pointed arch with fill and a point load, in metres and kN") {
  // Span 8 m, thickness 0.8 m, rise 6.93 m, density 2000 kg/m^3, a fill of the same density to the
  // crown's extrados, a 50 kN/m point load 2 m from the left springing; printed in kN.
  const std::vector<std::string> metres = {"--span", "8", "--thickness", "0.8", "--rise", "6.93",
                                           "--density", "2000", "--fill-density", "2000", "--fill-height", "crown",
                                           "--point-load", "50", "--point-load-x", "2", "--units", "kN"};
  const Run kn = ok(with({"thrust"}, with(metres, {"--all-columns"})));
  CHECK(kn.out.rfind("# units: kN", 0) == 0);
  // The echoed inputs as given, and their ratios.
  CHECK(column(without_comment(kn.out), "thickness") == "0.8");
  CHECK(column(without_comment(kn.out), "rise") == "6.93");
  CHECK(column(without_comment(kn.out), "point_load") == "50");
  CHECK(column(without_comment(kn.out), "point_load_x") == "2");
  CHECK(column(without_comment(kn.out), "thickness_ratio") == "0.1");
  CHECK(column(without_comment(kn.out), "point_load_at") == "0.25");
  // The pointed arch of rise h over span L: R = (0.5 + e) L with e = (h/L)^2 - 1/4; the crown's
  // extrados is where the two arcs of radius R + t/2 about (R, 0) and (L - R, 0) meet over x = L/2.
  const double L = 8, t = 0.8, h = 6.93;
  const double e = (h / L) * (h / L) - 0.25, R = (0.5 + e) * L;
  CHECK(close(number(kn.out, "eccentricity"), e, kExact));
  CHECK(close(number(kn.out, "radius"), R, kExact));
  const double crown = std::sqrt((R + t / 2) * (R + t / 2) - (R - L / 2) * (R - L / 2));
  CHECK(close(number(kn.out, "fill_height"), crown, kExact));
  CHECK(crown / L > 0.92);  // the engineer's hand estimate: 0.924 L
  CHECK(crown / L < 0.93);

  // The ratio form of the same scene in N: the same numbers, a thousand times larger.
  const std::string fill_ratio = column(without_comment(kn.out), "fill_height_ratio");
  const std::vector<std::string> ratios = {"--span", "8", "--thickness-ratio", "0.1", "--rise-ratio", "0.86625",
                                           "--density", "2000", "--fill-density", "2000", "--fill-height-ratio",
                                           fill_ratio, "--point-load", "50000", "--point-load-at", "0.25"};
  const Run n = ok(with({"thrust"}, with(ratios, {"--columns", kThrustResults})));
  const Run kn_results = ok(with({"thrust"}, with(metres, {"--columns", kThrustResults})));
  CHECK(column(n.out, "status") == "success");
  for (const char* force : {"H", "V", "H_left", "V_left", "H_right", "V_right", "M_left", "M_right"}) {
    CAPTURE(force);
    CHECK(close(1000 * number(kn_results.out, force), number(n.out, force), kExact));
  }
  CHECK(column(without_comment(kn_results.out), "H_over_V") == column(n.out, "H_over_V"));  // a ratio: no unit
  CHECK(column(without_comment(kn_results.out), "error_estimate") == column(n.out, "error_estimate"));
  // The pushing side: the point load on the left makes the left springing's vertical reaction larger.
  CHECK(number(n.out, "V_left") > number(n.out, "V_right"));

  // Limit analysis of the same arch: its thrust range and the point load's collapse factor.
  const std::string limit_columns = "status,H_min,H_max,V,thickness_min_ratio,load_factor";
  const Run limit_kn = ok(with({"limit"}, with(metres, {"--columns", limit_columns})));
  const Run limit_n = ok(with({"limit"}, with(ratios, {"--columns", limit_columns})));
  CHECK(column(without_comment(limit_kn.out), "status") == "success");
  for (const char* force : {"H_min", "H_max", "V"}) {
    CAPTURE(force);
    CHECK(close(1000 * number(limit_kn.out, force), number(limit_n.out, force), kExact));
  }
  CHECK(column(without_comment(limit_kn.out), "load_factor") == column(limit_n.out, "load_factor"));
  CHECK(number(limit_n.out, "load_factor") > 1);  // it carries the load
}

TEST_CASE("metres: each metre option gives the scene of its ratio, to the last digit") {
  // Span 8 m: every ratio below is the metre value over 8, exactly in binary.
  const std::vector<std::string> span = {"--span", "8"};
  struct Pair {
    std::vector<std::string> metre, ratio;
  };
  const std::vector<Pair> pairs = {
      {{"--thickness", "0.8"}, {"--thickness-ratio", "0.1"}},
      {{"--curve", "segmental", "--rise", "2"}, {"--curve", "segmental", "--rise-ratio", "0.25"}},
      {{"--curve", "catenary", "--rise", "3"}, {"--curve", "catenary", "--rise-ratio", "0.375"}},
      // The pointed arch: rise 6 m, rise ratio 0.75, eccentricity 0.75^2 - 1/4 = 0.3125, radius 6.5 m.
      {{"--rise", "6"}, {"--eccentricity", "0.3125"}},
      {{"--rise-ratio", "0.75"}, {"--eccentricity", "0.3125"}},
      {{"--radius", "6.5"}, {"--eccentricity", "0.3125"}},
      {{"--fill-density", "1800", "--fill-height", "4"}, {"--fill-density", "1800", "--fill-height-ratio", "0.5"}},
      {{"--point-load", "2e4", "--point-load-x", "2"}, {"--point-load", "2e4", "--point-load-at", "0.25"}},
      {{"--live-load", "5e3", "--live-load-from-x", "1", "--live-load-to-x", "6"},
       {"--live-load", "5e3", "--live-load-from", "0.125", "--live-load-to", "0.75"}},
  };
  for (const Pair& p : pairs) {
    CAPTURE(p.metre.at(p.metre.size() - 2));
    for (const std::string& command : {"thrust", "limit"}) {
      const std::string columns = command == "thrust" ? kThrustResults : "status,H_min,H_max,V,thickness_min_ratio";
      const Run metre = ok(with(with({command}, span), with(p.metre, {"--columns", columns})));
      const Run ratio = ok(with(with({command}, span), with(p.ratio, {"--columns", columns})));
      CHECK(metre.out == ratio.out);
    }
  }
}

TEST_CASE("metres: both options of a pair are refused with one line naming both") {
  const std::vector<std::vector<std::string>> both = {
      {"--thickness", "0.8", "--thickness-ratio", "0.1"},
      {"--rise", "6", "--eccentricity", "0.3"},
      {"--rise", "6", "--rise-ratio", "0.75"},
      {"--radius", "6", "--rise", "6"},
      {"--fill-density", "1", "--fill-height", "crown", "--fill-height-ratio", "0.5"},
      {"--point-load", "1", "--point-load-x", "2", "--point-load-at", "0.3"},
      {"--live-load", "1", "--live-load-from-x", "1", "--live-load-from", "0.1"},
      {"--live-load", "1", "--live-load-to-x", "1", "--live-load-to", "0.1"},
  };
  for (const std::vector<std::string>& args : both) {
    const Run r = run_command(with({"thrust"}, args));
    CAPTURE(r.err);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(lines(r.err).size() == 1);
    // Both flags named.
    std::vector<std::string> flags;
    for (const std::string& a : args)
      if (a.rfind("--", 0) == 0 && a != "--fill-density" && a != "--point-load" && a != "--live-load") flags.push_back(a);
    REQUIRE(flags.size() == 2);
    for (const std::string& f : flags) {
      const bool named = r.err.find(f + ":") != std::string::npos || r.err.find(f + " ") != std::string::npos;
      CHECK(named);
    }
  }
  // Metre values outside their rule, with one line each.
  check_refused({"thrust", "--point-load", "1", "--point-load-x", "11"});       // beyond the 10 m span
  check_refused({"thrust", "--live-load", "1", "--live-load-to-x", "10.5"});
  check_refused({"thrust", "--rise", "4"});                                       // a pointed arch below L/2
  check_refused({"thrust", "--radius", "4.9"});
  check_refused({"thrust", "--curve", "semicircular", "--rise", "5"});            // its rise is the span's half
  check_refused({"thrust", "--curve", "segmental", "--radius", "5"});
  check_refused({"thrust", "--thickness", "-1"});
  // A ratio derived from metres keeps the ratio option's rule, and the message names the option given.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"thrust", "--fill-density", "1", "--fill-height", "1e300"},
        {"thrust", "--rise", "25"}, {"thrust", "--rise", "1e300"}, {"thrust", "--thickness", "10"},
        {"thrust", "--curve", "segmental", "--rise", "9"}}) {
    check_refused(args);
    const std::string& flag = args.at(args.size() - 2);
    CHECK(run_command(args).err.rfind("ogive: " + flag + ":", 0) == 0);
  }
  check_refused({"thrust", "--fill-density", "1", "--fill-height", "top"});
  check_refused({"thrust", "--fill-height", "crown"});                            // no fill density
  check_refused({"thrust", "--units", "kNm"});  // kn and KN are kN (engineer_inputs_test.cpp)
  check_refused({"thrust", "--digits", "0"});
  check_refused({"thrust", "--digits", "18"});
  check_refused({"limit", "--digits", "2.5"});
  // curve draws the axis alone: loads, supports, material and the force unit do not apply.
  check_refused({"curve", "--point-load", "1"});
  check_refused({"curve", "--fill-density", "1", "--fill-height", "crown"});
  check_refused({"curve", "--units", "kN"});
  check_refused({"curve", "--youngs-modulus", "1"});
  CHECK(ok({"curve", "--help"}).out.find("--point-load") == std::string::npos);
  CHECK(ok({"curve", "--curve", "segmental", "--rise", "2", "--span", "8", "--stations", "3"}).out ==
        ok({"curve", "--curve", "segmental", "--rise-ratio", "0.25", "--span", "8", "--stations", "3"}).out);
  // A points file sets its own span: --span may repeat it, not change it.
  const std::string file = OGIVE_DATA_DIR "/curves/catenary-survey.csv";
  const Run same = ok({"thrust", "--curve", "points", "--curve-file", file, "--span", "12", "--columns", "H"});
  CHECK(same.out == ok({"thrust", "--curve", "points", "--curve-file", file, "--columns", "H"}).out);
  const Run other = run_command({"thrust", "--curve", "points", "--curve-file", file, "--span", "8"});
  CHECK(other.status == 2);
  CHECK(other.err.find("12 m") != std::string::npos);
}

TEST_CASE("metres: --units kN divides every force and moment by 1000, --digits rounds every number") {
  const Run n = ok({"thrust", "--point-load", "2e4", "--all-columns"});
  const Run kn = ok({"thrust", "--point-load", "20", "--units", "kN", "--all-columns"});
  CHECK(kn.out.rfind("# units: kN", 0) == 0);
  CHECK(n.out.rfind("scene,", 0) == 0);  // no comment line in N
  for (const char* force : {"H", "V", "H_left", "V_left", "M_left", "H_right", "V_right", "M_right"}) {
    CAPTURE(force);
    CHECK(close(1000 * number(kn.out, force), number(n.out, force), kExact));
  }
  for (const char* plain : {"H_over_V", "error_estimate", "rise_ratio", "thickness"})
    CHECK(column(without_comment(kn.out), plain) == column(n.out, plain));
  // The column docs say the unit printed.
  const Run help = ok({"thrust", "--units", "kN", "--columns", "help"});
  CHECK(help.out.find("\nM_left,kN m/m,") != std::string::npos);
  CHECK(help.out.find("\nH,kN/m,") != std::string::npos);
  CHECK(ok({"thrust", "--columns", "help"}).out.find("\nH,N/m,") != std::string::npos);
  // Three significant digits: each number is the full one rounded.
  const Run three = ok({"thrust", "--digits", "3", "--columns", "H,M_left,error_estimate"});
  const Run full = ok({"thrust", "--columns", "H,M_left,error_estimate"});
  for (const char* name : {"H", "M_left", "error_estimate"}) {
    CAPTURE(name);
    const double x = number(full.out, name), r = number(three.out, name);
    const double unit = std::pow(10.0, std::floor(std::log10(std::abs(x))) - 2);
    CHECK(std::abs(x - r) <= 0.5 * unit * (1 + kExact));
  }
  CHECK(column(three.out, "H") == "57400");
  // A drawing does not depend on the unit the loads were given in.
  const Run drawn_kn = ok({"report", "--point-load", "50", "--units", "kN", "--output", "-"});
  const Run drawn_n = ok({"report", "--point-load", "50000", "--output", "-"});
  CHECK(drawn_kn.out.find("P 50 kN/m") != std::string::npos);
  // The pages differ only in the inputs as given.
  const auto body = [](const std::string& page) { return page.substr(0, page.find("id=\"inputs\"")); };
  CHECK(body(drawn_kn.out) == body(drawn_n.out));
}

}  // namespace ogive::test
