#include "option_text.hpp"

#include <algorithm>
#include <cmath>

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

std::string as_option_message(const std::string& what) {
  const std::size_t colon = what.find(':');
  if (colon == std::string::npos || what.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") < colon) return what;
  std::string field = what.substr(0, colon);
  if (field == "thickness" || field == "support_displacement" || field == "left_spread" || field == "right_spread" ||
      field == "left_settlement" || field == "right_settlement")
    field += "_ratio";
  std::string flag = "--" + field;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag + what.substr(colon);
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
