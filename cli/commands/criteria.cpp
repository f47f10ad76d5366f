#include "criteria.hpp"

#include <cmath>
#include <limits>
#include <map>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "option_text.hpp"
#include "values.hpp"

namespace ogive::cli {
namespace {

const std::map<std::string, ThrustRequirement> kThrustRequirements = {
    {"none", ThrustRequirement::none}, {"section", ThrustRequirement::section}, {"kern", ThrustRequirement::kern}};

// A required value: > 0 and finite, or "none" (NaN: not required).
double required_value(const std::string& text, const char* flag) {
  if (text == "none") return std::numeric_limits<double>::quiet_NaN();
  const double v = parse_number(text, flag);
  if (!(v > 0)) throw UsageError(fmt::format("{}: must be > 0, or none (not required), got '{}'", flag, shown(text)));
  return v;
}

// The default of a scene option, as its --help shows it.
std::string default_of(const CLI::App& cmd, const char* flag) {
  const CLI::Option* o = cmd.get_option_no_throw(flag);
  return o ? o->get_default_str() : std::string();
}

}  // namespace

void add_criteria_options(CLI::App& cmd, CriteriaText& t) {
  cmd.add_option("--require-geometric-factor", t.geometric_factor,
                 "the least geometric factor of safety t / t_min (Heyman: 2 to 3), > 0, or none")
      ->capture_default_str();
  cmd.add_option("--require-load-factor", t.load_factor,
                 "the least collapse load factor of the point and live loads, > 0, or none (a scene without them "
                 "has none to check)")
      ->capture_default_str();
  cmd.add_option("--require-acceleration", t.acceleration,
                 "the least horizontal acceleration of collapse a_c, a fraction of g, > 0, or none")
      ->capture_default_str();
  cmd.add_option("--require-spread", t.spread,
                 "the least spreading capacity: the span's increase at collapse over the span, both springings "
                 "moving outwards (on walls: the walls leaning about their toes), > 0, or none")
      ->capture_default_str();
  cmd.add_option("--require-thrust", t.thrust,
                 "where the scene's own line of thrust (its --section's) must stay: section (|e| <= 300 % of the "
                 "kern), kern (|e| <= 100 %) or none")
      ->capture_default_str();
}

AssessmentCriteria criteria_of(const CriteriaText& t) {
  AssessmentCriteria c;
  c.geometric_safety_factor = required_value(t.geometric_factor, "--require-geometric-factor");
  c.load_factor = required_value(t.load_factor, "--require-load-factor");
  c.horizontal_load_factor = required_value(t.acceleration, "--require-acceleration");
  c.spread_capacity_ratio = required_value(t.spread, "--require-spread");
  c.thrust = lookup(kThrustRequirements, t.thrust, "--require-thrust");
  return c;
}

std::vector<std::string> default_warnings(const CLI::App& cmd, const std::string& curve) {
  std::vector<std::string> warnings;
  const bool file_span = curve == "points" || curve == "whole-points";
  if (!file_span && !given(cmd, "--span") && !given(cmd, "--radius"))
    warnings.push_back(fmt::format("--span not given: the default span of {} m is used", default_of(cmd, "--span")));
  if (!given(cmd, "--thickness") && !given(cmd, "--thickness-ratio"))
    warnings.push_back(fmt::format("neither --thickness nor --thickness-ratio given: the default t/L of {} is used",
                                   default_of(cmd, "--thickness-ratio")));
  if (!given(cmd, "--density") && !given(cmd, "--unit-weight"))
    warnings.push_back(
        fmt::format("--density not given: the default {} kg/m^3 (travertine, the paper's) is used", default_of(cmd, "--density")));
  return warnings;
}

}  // namespace ogive::cli
