// `ogive assess`: one row per scene, each criterion's value, required value and outcome, the verdict and
// its governing criterion; the numbers are limit's and thrust's; bad input refused.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "support/cli_run.hpp"

using namespace ogive::test;

namespace {

// A 12 m segmental bridge arch, rise 3 m, filled to 3.8 m, a 100 kN/m line load 3 m from its left
// springing, ring `t` m thick.
std::vector<std::string> bridge(const std::string& command, const std::string& t) {
  return {command, "--curve", "segmental", "--span", "12", "--rise", "3", "--thickness", t, "--fill-density", "2000",
          "--fill-height", "3.8", "--point-load", "1e5", "--point-load-x", "3"};
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("cli: assess fails the thin bridge arch on its load factor and states the thick one's") {
  const Run thin = run_command(bridge("assess", "0.3"));
  REQUIRE(thin.status == 0);  // a failing arch is an answer
  CHECK(thin.err.empty());
  CHECK(column(thin.out, "verdict") == "fail");
  CHECK(column(thin.out, "governing") == "load_factor");
  CHECK(column(thin.out, "load_factor_outcome") == "fail");
  CHECK(column(thin.out, "geometric_safety_factor_outcome") == "fail");
  // The numbers are limit's, to the digit.
  const Run limit = run_command(with(bridge("limit", "0.3"), {"--columns", "load_factor,geometric_safety_factor"}));
  REQUIRE(limit.status == 0);
  CHECK(column(thin.out, "load_factor") == column(limit.out, "load_factor"));
  CHECK(column(thin.out, "geometric_safety_factor") == column(limit.out, "geometric_safety_factor"));
  CHECK(std::stod(column(thin.out, "load_factor")) < 1);
  CHECK(std::stod(column(thin.out, "margin")) == std::stod(column(thin.out, "load_factor")) / 2);
  CHECK(column(thin.out, "warnings").find("below t_min") != std::string::npos);

  // Twice as thick: the load factor passes 2; the geometric factor (about 1.6) fails the default 2 and
  // passes 1.5.
  const Run thick = run_command(bridge("assess", "0.6"));
  REQUIRE(thick.status == 0);
  CHECK(column(thick.out, "load_factor_outcome") == "pass");
  CHECK(column(thick.out, "verdict") == "fail");
  CHECK(column(thick.out, "governing") == "geometric_safety_factor");
  const Run relaxed = run_command(with(bridge("assess", "0.6"), {"--require-geometric-factor", "1.5"}));
  REQUIRE(relaxed.status == 0);
  CHECK(column(relaxed.out, "verdict") == "pass");
  CHECK(column(relaxed.out, "geometric_safety_factor_outcome") == "pass");
  CHECK(std::stod(column(relaxed.out, "margin")) >= 1);
}

TEST_CASE("cli: assess with every criterion off but one, and with none required") {
  const Run r = run_command({"assess", "--thickness-ratio", "0.1", "--require-geometric-factor", "none",
                             "--require-thrust", "section"});
  REQUIRE(r.status == 0);
  CHECK(column(r.out, "governing") == "max_thrust_eccentricity");
  CHECK(column(r.out, "geometric_safety_factor_outcome") == "not_required");
  CHECK(!column(r.out, "geometric_safety_factor").empty());  // printed for the reader all the same
  CHECK(column(r.out, "load_factor_outcome") == "not_applicable");  // required by default, no live load
  // Nothing required: nothing to pass.
  const Run none = run_command({"assess", "--require-geometric-factor", "none", "--require-load-factor", "none"});
  CHECK(none.status == 3);
  CHECK(column(none.out, "verdict") == "not_assessed");
}

TEST_CASE("cli: assess refuses bad input with one line") {
  for (const std::string bad : {"0", "-1", "nan", "inf", "two", ""})
    check_refused({"assess", "--require-geometric-factor", bad});
  check_refused({"assess", "--require-load-factor", "-2"});
  check_refused({"assess", "--require-acceleration", "0"});
  check_refused({"assess", "--require-spread", "-0.01"});
  check_refused({"assess", "--require-thrust", "middle-third"});
  check_refused({"assess", "--support-displacement-ratio", "1e-4"});
  check_refused({"assess", "--joints-count", "4"});
  check_refused({"assess", "--friction", "0"});
  check_refused({"assess", "--friction-model", "associative"});
  check_refused({"assess", "--friction", "0.5", "--friction-model", "dilatant"});
}
