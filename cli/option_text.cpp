#include "option_text.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <CLI/CLI.hpp>

namespace ogive::cli {

std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> names;
  for (std::size_t pos = 0; pos <= text.size();) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    names.push_back(text.substr(pos, comma - pos));
    pos = comma + 1;
  }
  return names;
}

namespace {

// The library's field names and the options that set them (the lengths and movements are given over
// the span on the command line). A name not here (points, unit_weight) is no option: it stays a word.
constexpr std::pair<std::string_view, std::string_view> kFieldOptions[] = {
    {"thickness", "--thickness-ratio"},
    {"support_displacement", "--support-displacement-ratio"},
    {"left_spread", "--left-spread-ratio"},
    {"right_spread", "--right-spread-ratio"},
    {"left_settlement", "--left-settlement-ratio"},
    {"right_settlement", "--right-settlement-ratio"},
    {"left_rotation", "--left-rotation"},
    {"right_rotation", "--right-rotation"},
    {"span", "--span"},
    {"curve", "--curve"},
    {"eccentricity", "--eccentricity"},
    {"rise_ratio", "--rise-ratio"},
    {"haunch_angle", "--haunch-angle"},
    {"crown_angle", "--crown-angle"},
    {"density", "--density"},
    {"gravity", "--gravity"},
    {"youngs_modulus", "--youngs-modulus"},
    {"poisson_ratio", "--poisson-ratio"},
    {"shear_coefficient", "--shear-coefficient"},
    {"horizontal_acceleration", "--horizontal-acceleration"},
    {"point_load", "--point-load"},
    {"point_load_at", "--point-load-at"},
    {"live_load", "--live-load"},
    {"live_load_from", "--live-load-from"},
    {"live_load_to", "--live-load-to"},
    {"fill_density", "--fill-density"},
    {"fill_height_ratio", "--fill-height-ratio"},
    {"left_wall_height", "--left-wall-height"},
    {"left_wall_thickness", "--left-wall-thickness"},
    {"left_wall_density", "--left-wall-density"},
    {"left_wall_top_load", "--left-wall-top-load"},
    {"left_wall_top_load_at", "--left-wall-top-load-at"},
    {"right_wall_height", "--right-wall-height"},
    {"right_wall_thickness", "--right-wall-thickness"},
    {"right_wall_density", "--right-wall-density"},
    {"right_wall_top_load", "--right-wall-top-load"},
    {"right_wall_top_load_at", "--right-wall-top-load-at"},
    {"joints_count", "--joints-count"},
    {"friction", "--friction"},
    {"friction_model", "--friction-model"},
    {"compressive_strength", "--compressive-strength"},
    {"rtol", "--rtol"},
    {"atol", "--atol"},
    {"segments", "--segments"},
    {"max_steps", "--max-steps"},
    {"stations", "--stations"},
    // Not one field: the options that load the ring (the message restated below, or any other of them).
    {"loads", "--density, --point-load, --live-load, --fill-density and --loads-file"},
};

std::string_view option_of(std::string_view field) {
  for (const auto& [name, option] : kFieldOptions)
    if (name == field) return option;
  return {};
}

bool identifier_char(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; }

// Each known field name in `text` as its option: every one when `all`, else those with an underscore
// (an identifier, never an English word such as "density 0").
std::string options_for_fields(std::string_view text, bool all) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const bool starts = identifier_char(text[i]) && (i == 0 || !(identifier_char(text[i - 1]) || text[i - 1] == '-'));
    if (!starts) {
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && identifier_char(text[end])) ++end;
    const std::string_view word = text.substr(i, end - i);
    const std::string_view option = option_of(word);
    out += !option.empty() && (all || word.find('_') != std::string_view::npos) ? option : word;
    i = end;
  }
  return out;
}

}  // namespace

std::string as_option_message(const std::string& what) {
  // Messages that name no option of their own, restated in the options that decide them.
  if (what.starts_with("loads: the ring carries no load"))
    return "--density: 0 leaves the ring without load (no point or live load, and every fill's level lies below "
           "the extrados over the whole span: raise --fill-height-ratio or give a self-weight)";
  if (const std::size_t units = what.find(": must be finite in units of w L^4 / EI, got ");
      units != std::string::npos && what.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == units) {
    const std::string side = what.substr(0, what.find('_'));
    const std::string movement = what.substr(0, units).ends_with("spread") ? "spread" : "settlement";
    return fmt::format("--density, --gravity, --thickness-ratio and --youngs-modulus: the {} springing's {} of {} m "
                       "is beyond the range of a double in units of w L^4 / EI (the weight per length w too small "
                       "for the bending stiffness EI)",
                       side, movement, what.substr(units + std::string_view(": must be finite in units of w L^4 / EI, got ").size()));
  }
  // "field: rule" or "field, field and field: rule": the fields before the colon become options; in the
  // rule, the field names with an underscore.
  const std::size_t colon = what.find(": ");
  if (colon == std::string::npos || what.find_first_not_of("abcdefghijklmnopqrstuvwxyz_, ") < colon)
    return options_for_fields(what, false);
  return options_for_fields(std::string_view(what).substr(0, colon), true) +
         options_for_fields(std::string_view(what).substr(colon), false);
}

bool given(const CLI::App& cmd, std::string_view flag) {
  // CLI11 keeps long names without their dashes.
  if (flag.starts_with("--"))
    for (const CLI::Option* opt : cmd.get_options())
      for (const std::string& name : opt->get_lnames())
        if (name == flag.substr(2)) return opt->count() > 0;
  throw CLI::OptionNotFound(std::string(flag));
}

void refuse_empty_name(const CLI::App& cmd, const char* flag, const std::string& value, const char* what) {
  if (value.empty() && given(cmd, flag))
    throw UsageError(fmt::format("{}: the name must not be empty (give {})", flag, what));
}

void hide_inapplicable(CLI::App& cmd, std::span<const Inapplicable> options) {
  for (const Inapplicable& o : options) cmd.get_option(o.flag)->group("");
}

bool walls_given(const CLI::App& cmd) {
  return given(cmd, "--wall-height") || given(cmd, "--left-wall-height") || given(cmd, "--right-wall-height");
}

void refuse_inapplicable(const CLI::App& cmd, const char* command, std::span<const Inapplicable> options) {
  for (const Inapplicable& o : options)
    if (given(cmd, o.flag)) throw UsageError(fmt::format("{}: does not apply to {} ({})", o.flag, command, o.why));
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  if (name.size() > 100) return "";
  std::size_t best = std::string::npos, best_distance = 3;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    // Levenshtein distance, one row at a time.
    const std::string& c = candidates[i];
    std::vector<std::size_t> row(c.size() + 1);
    for (std::size_t j = 0; j <= c.size(); ++j) row[j] = j;
    for (std::size_t a = 1; a <= name.size(); ++a) {
      std::size_t diagonal = row[0];
      row[0] = a;
      for (std::size_t j = 1; j <= c.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (name[a - 1] == c[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    if (row[c.size()] < best_distance) {
      best_distance = row[c.size()];
      best = i;
    }
  }
  if (best != std::string::npos) return " (did you mean '" + candidates[best] + "'?)";
  // A word cut short ("--thick", "--rise"): the options it begins, up to three of them.
  std::vector<std::string> longer;
  if (name.size() >= 5)
    for (const std::string& c : candidates)
      if (c.size() > name.size() && c.compare(0, name.size(), name) == 0) longer.push_back("'" + c + "'");
  if (longer.empty() || longer.size() > 3) return "";
  std::string list = longer.front();
  for (std::size_t i = 1; i < longer.size(); ++i) list += (i + 1 == longer.size() ? " or " : ", ") + longer[i];
  return " (did you mean " + list + "?)";
}

namespace {

// What is wrong with an option's text as a number (empty if nothing): not what parse_number accepts,
// or, for counts, not a whole number up to 1e9.
std::string number_problem(const std::string& text, bool count) {
  double v = 0;
  try {
    v = parse_number(text, "");
  } catch (const UsageError&) {
    return "'" + text.substr(0, 60) + "' is not a finite number";
  }
  if (count && (v != std::floor(v) || std::abs(v) > 1e9))
    return "'" + text.substr(0, 60) + "' is not a whole number up to 1e9";
  return {};
}

}  // namespace

const CLI::Validator& finite_number() {
  static const CLI::Validator validator([](std::string& text) { return number_problem(text, false); }, "NUMBER");
  return validator;
}

const CLI::Validator& whole_count() {
  static const CLI::Validator validator([](std::string& text) { return number_problem(text, true); }, "COUNT");
  return validator;
}

}  // namespace ogive::cli
