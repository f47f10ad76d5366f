// The text of options: names looked up among the known ones, the library's messages restated in terms
// of the options, suggestions for misspelt names, and CLI11 validators for numeric options.
#pragma once

#include <array>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "values.hpp"

namespace CLI {
class App;
class Validator;
}

namespace ogive::cli {

// The value `text` names in `names`; UsageError listing the known names otherwise.
template <class Enum>
Enum lookup(const std::map<std::string, Enum>& names, const std::string& text, const char* flag) {
  const auto it = names.find(text);
  if (it != names.end()) return it->second;
  std::string known;
  for (const auto& [name, value] : names) known += (known.empty() ? "" : ", ") + name;
  throw UsageError(fmt::format("{}: unknown value '{}' (known: {})", flag, text, known));
}

// Comma-separated names ("a,b"): each one, empty ones included (the lookup refuses them).
std::vector<std::string> split_names(const std::string& text);

// "rise_ratio: rule" from the library becomes "--rise-ratio: rule"; the scene's lengths are given
// as ratios of the span on the command line, so "thickness: ..." names --thickness-ratio.
std::string as_option_message(const std::string& what);

// " (did you mean 'x'?)" for the candidate closest to a misspelt name (edit distance at most 2), else
// for a name cut short (5 characters or more) the one to three candidates it begins
// (" (did you mean 'a' or 'b'?)"), or "".
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

// Whether the option `flag` ("--name", one of cmd's) was given: App::count's answer without its cost,
// which copies every option's names for each option it compares (a one-scene run asks some 80 times).
// CLI::OptionNotFound, as App::count, for a flag that cmd does not have.
bool given(const CLI::App& cmd, std::string_view flag);
// Whether a wall option (--wall-height, --left-wall-height, --right-wall-height) was given.
bool walls_given(const CLI::App& cmd);

// A file or directory option given as "": UsageError naming it (rather than read as not given);
// `what` says what the option takes, e.g. "a file, or - for standard input".
void refuse_empty_name(const CLI::App& cmd, const char* flag, const std::string& value, const char* what);

// Options a command registers with the scene options but cannot use, and why: hide_inapplicable
// leaves them out of the command's --help, refuse_inapplicable refuses any of them that was given
// ("FLAG: does not apply to COMMAND (WHY)").
struct Inapplicable {
  const char* flag;
  const char* why;
};
void hide_inapplicable(CLI::App& cmd, std::span<const Inapplicable> options);
void refuse_inapplicable(const CLI::App& cmd, const char* command, std::span<const Inapplicable> options);

// The scene options that move the springings (a leaning wall moves its springing too), each with the same
// reason: for an analysis that moves them itself (spread, and draw's spreading stage) or takes them as built.
constexpr std::array<Inapplicable, 10> springing_movements(const char* why) {
  return {{{"--support-displacement-ratio", why},
           {"--left-spread-ratio", why},
           {"--right-spread-ratio", why},
           {"--left-settlement-ratio", why},
           {"--right-settlement-ratio", why},
           {"--left-rotation", why},
           {"--right-rotation", why},
           {"--wall-lean", why},
           {"--left-wall-lean", why},
           {"--right-wall-lean", why}}};
}

// CLI11 would read "" as 0 and saturate huge integers: numeric options must be what parse_number
// accepts (the whole text, finite), and counts whole numbers within what an int holds.
const CLI::Validator& finite_number();
const CLI::Validator& whole_count();

}  // namespace ogive::cli
