#include "units.hpp"

#include <cctype>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "values.hpp"

namespace ogive::cli {
namespace {

// One unit: its spelling and its power of ten over the option's own unit. Forces are in N and are
// shifted by --units afterwards.
struct Unit {
  const char* name;
  int exponent;
};

struct Dimension {
  const char* what;  // for messages
  std::vector<Unit> units;
  bool force = false;  // relative to --units
};

const Dimension kLength{"a length", {{"m", 0}, {"cm", -2}, {"mm", -3}}};
const Dimension kLineForce{
    "a force per metre of vault width", {{"N", 0}, {"kN", 3}, {"MN", 6}, {"N/m", 0}, {"kN/m", 3}, {"MN/m", 6}}, true};
const Dimension kPressure{"a load per unit area",
                          {{"N/m2", 0}, {"N/m^2", 0}, {"kN/m2", 3}, {"kN/m^2", 3}, {"Pa", 0}, {"kPa", 3}},
                          true};
const Dimension kDensity{"a density", {{"kg/m3", 0}, {"kg/m^3", 0}, {"t/m3", 3}, {"t/m^3", 3}}};
const Dimension kModulus{"a modulus",
                         {{"Pa", 0}, {"kPa", 3}, {"MPa", 6}, {"GPa", 9}, {"N/m2", 0}, {"N/m^2", 0}, {"N/mm2", 6},
                          {"N/mm^2", 6}}};
const Dimension kStress{"a stress",
                        {{"Pa", 0}, {"kPa", 3}, {"MPa", 6}, {"GPa", 9}, {"N/m2", 0}, {"N/m^2", 0}, {"N/mm2", 6},
                         {"N/mm^2", 6}}};
const Dimension kUnitWeight{"a unit weight", {{"N/m3", 0}, {"N/m^3", 0}, {"kN/m3", 3}, {"kN/m^3", 3}}};
const Dimension kAcceleration{"an acceleration", {{"m/s2", 0}, {"m/s^2", 0}}};
// A wall's lean: rad, or its out-of-plumb (the top's displacement over the height, the same number for
// small rotations) in mm per m or per cent.
const Dimension kLean{"a lean", {{"rad", 0}, {"mm/m", -3}, {"%", -2}}};

const std::map<std::string_view, const Dimension*>& dimensions() {
  static const std::map<std::string_view, const Dimension*> of = {
      {"--span", &kLength},           {"--thickness", &kLength},        {"--rise", &kLength},
      {"--radius", &kLength},         {"--fill-height", &kLength},      {"--point-load-x", &kLength},
      {"--live-load-from-x", &kLength}, {"--live-load-to-x", &kLength}, {"--point-load", &kLineForce},
      {"--live-load", &kPressure},    {"--density", &kDensity},         {"--fill-density", &kDensity},
      {"--youngs-modulus", &kModulus}, {"--unit-weight", &kUnitWeight}, {"--gravity", &kAcceleration},
      {"--compressive-strength", &kStress},
      {"--wall-height", &kLength},    {"--left-wall-height", &kLength}, {"--right-wall-height", &kLength},
      {"--wall-thickness", &kLength}, {"--left-wall-thickness", &kLength}, {"--right-wall-thickness", &kLength},
      {"--wall-density", &kDensity},  {"--left-wall-density", &kDensity}, {"--right-wall-density", &kDensity},
      {"--wall-top-load", &kLineForce}, {"--left-wall-top-load", &kLineForce}, {"--right-wall-top-load", &kLineForce},
      {"--wall-lean", &kLean},        {"--left-wall-lean", &kLean},     {"--right-wall-lean", &kLean},
  };
  return of;
}

std::string unit_list(const Dimension& d) {
  std::string list;
  for (const Unit& u : d.units) list += (list.empty() ? "" : ", ") + std::string(u.name);
  return list;
}

// Where a value's unit begins: after its number (digits, sign, point, exponent).
std::size_t unit_start(std::string_view value) {
  std::size_t i = 0;
  while (i < value.size()) {
    const char c = value[i];
    const bool exponent = (c == 'e' || c == 'E') && i + 1 < value.size() &&
                          (std::isdigit(static_cast<unsigned char>(value[i + 1])) || value[i + 1] == '+' ||
                           value[i + 1] == '-');
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' || exponent) {
      i += exponent ? 2 : 1;
      continue;
    }
    break;
  }
  return i;
}

// One value: its unit replaced by the power of ten (relative to --units for forces).
std::string resolved(std::string_view value, std::string_view option, const Dimension* d, int force_exponent) {
  const std::size_t at = unit_start(value);
  std::string_view number = value.substr(0, at), unit = value.substr(at);
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  if (unit.empty() || number.empty()) return std::string(value);  // a bare number, or a word (crown, none)
  if (!d) throw UsageError(fmt::format("{}: takes no unit (a ratio or a count), got '{}'", option, shown(value)));
  for (const Unit& u : d->units) {
    if (unit != u.name) continue;
    int shift = u.exponent - (d->force ? force_exponent : 0);
    // The number's own exponent, moved: "6e2mm" is 6e-1. An exponent beyond what a double holds is left
    // for parse_values to refuse.
    const std::size_t e = number.find_first_of("eE");
    if (e == std::string_view::npos) return shift == 0 ? std::string(number) : fmt::format("{}e{}", number, shift);
    std::string_view digits = number.substr(e + 1);
    const bool negative = !digits.empty() && digits.front() == '-';
    if (!digits.empty() && (digits.front() == '-' || digits.front() == '+')) digits.remove_prefix(1);
    if (digits.empty() || digits.size() > 4 || digits.find_first_not_of("0123456789") != std::string_view::npos)
      return std::string(value);
    const int own = std::stoi(std::string(digits));
    return fmt::format("{}e{}", number.substr(0, e), (negative ? -own : own) + shift);
  }
  throw UsageError(fmt::format("{}: '{}' is not a unit of {} (takes {}; a bare number is in {})", option, shown(unit),
                               d->what, unit_list(*d), d->force ? "--units" : d->units.front().name));
}

}  // namespace

std::string with_units_resolved(std::string_view text, std::string_view option, int force_exponent) {
  const auto it = dimensions().find(option);
  const Dimension* d = it == dimensions().end() ? nullptr : it->second;
  const bool range = text.find(':') != std::string_view::npos;
  std::string out;
  std::size_t start = 0;
  for (int part = 0;; ++part) {
    const std::size_t end = text.find_first_of(range ? ":" : ",", start);
    const std::string_view value = text.substr(start, end == std::string_view::npos ? end : end - start);
    if (range && part == 2 && unit_start(value) != value.size())
      throw UsageError(fmt::format("{}: a range's count takes no unit, got '{}'", option, shown(value)));
    out += range && part == 2 ? std::string(value) : resolved(value, option, d, force_exponent);
    if (end == std::string_view::npos) break;
    out += text[end];
    start = end + 1;
  }
  return out;
}

std::string units_taken(std::string_view option) {
  const auto it = dimensions().find(option);
  return it == dimensions().end() ? std::string() : unit_list(*it->second);
}

}  // namespace ogive::cli
