#include "limit_text.hpp"

#include <limits>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli.hpp"
#include "option_text.hpp"
#include "units.hpp"
#include "values.hpp"

namespace ogive::cli {

const std::map<std::string, WeightModel>& weight_models() {
  static const std::map<std::string, WeightModel> names = {{"voussoir", WeightModel::voussoir},
                                                           {"axis", WeightModel::axis}};
  return names;
}

const std::map<std::string, JointOrientation>& joint_orientations() {
  static const std::map<std::string, JointOrientation> names = {{"radial", JointOrientation::radial},
                                                                {"vertical", JointOrientation::vertical}};
  return names;
}

void add_compressive_strength_option(CLI::App& cmd, std::string& text, const char* what) {
  cmd.add_option("--compressive-strength", text,
                 fmt::format("the masonry's compressive strength f_c (> 0; Pa, or with a unit: 3.92MPa): {}", what));
}

double compressive_strength_of(const std::string& text, const CLI::App& cmd) {
  if (!given(cmd, "--compressive-strength")) return std::numeric_limits<double>::infinity();
  const std::string in_pa = with_units_resolved(text, "--compressive-strength", 0);  // names a bad unit itself
  double f_c = 0;
  try {
    f_c = parse_number(in_pa, "--compressive-strength");
  } catch (const UsageError&) {  // name what was given, not its value in Pa
    throw UsageError(fmt::format("--compressive-strength: one stress, Pa or with a unit (MPa, kPa, N/mm2), got {}", shown(text)));
  }
  if (!(f_c > 0))
    throw UsageError(fmt::format("--compressive-strength: must be > 0 (Pa; omit it for infinite strength), got {}",
                                 shown(text)));
  return f_c;
}

void add_friction_model_option(CLI::App& cmd, std::string& text) {
  cmd.add_option("--friction-model", text,
                 "with --friction: non-associative (sliding without dilatancy, masonry: Gilbert et al.'s iteration) or "
                 "associative (an upper bound of the non-associative load factor and a_c)")
      ->capture_default_str();
}

FrictionModel friction_model_of(const std::string& text, const CLI::App& cmd) {
  if (given(cmd, "--friction-model") && !given(cmd, "--friction"))
    throw UsageError("--friction-model: applies with --friction only (without it the joints do not slide)");
  static const std::map<std::string, FrictionModel> names = {{"associative", FrictionModel::associative},
                                                             {"non-associative", FrictionModel::non_associative}};
  return lookup(names, text, "--friction-model");
}

std::string friction_model_text(const LimitOptions& o) {
  if (!(o.friction > 0)) return {};
  return o.friction_model == FrictionModel::associative ? "associative" : "non-associative";
}

std::string hinge_text(const std::vector<Hinge>& hinges, double span, const Ring* ring) {
  std::string text;
  for (const Hinge& h : hinges) {
    if (!text.empty()) text += ';';
    if (ring && (h.joint < ring->left_springing() || h.joint > ring->right_springing())) {
      text += fmt::format("{:.6g}:wall-{}@{:.6g}", h.point.x() / span, h.face == Face::extrados ? "outer" : "inner",
                          h.point.y() / span);
      continue;
    }
    text += fmt::format("{:.6g}:{}", h.point.x() / span, to_string(h.face));
  }
  return text;
}

}  // namespace ogive::cli
