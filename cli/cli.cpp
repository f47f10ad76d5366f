#include "cli.hpp"

#include <algorithm>
#include <exception>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "commands.hpp"
#include "help.hpp"
#include "ogive/version.hpp"
#include "option_text.hpp"
#include "row_writer.hpp"
#include "values.hpp"
#include "warnings.hpp"

namespace ogive::cli {
namespace {

struct Subcommand {
  const char* name;
  const char* description;
  Run (*add_options)(CLI::App& cmd);
};

// In the order `ogive --help` lists them.
constexpr Subcommand kSubcommands[] = {
    {"thrust", "reactions H, V and H/V: one row per scene", add_thrust_options},
    {"profile", "N, V, M, e and the thrust line along the arch", add_profile_options},
    {"check", "every method's H/V against the closed form", add_check_options},
    {"curve", "the generator curve: s, x, y, theta, kappa", add_curve_options},
    {"bench", "median time per solve and true error, per method and rtol", add_bench_options},
    {"draw", "an SVG picture of each scene to scale: arch, thrust line, supports", add_draw_options},
    {"limit", "limit analysis (rigid voussoirs, no tension): H_min, H_max, t_min, collapse load; one row per scene",
     add_limit_options},
    {"report", "one HTML page per scene: drawing, reactions, thrust range, safety, collapse, spreading",
     add_report_options},
    {"spread", "the arch on spreading walls to collapse: elastic thrust, plateau, spreading capacity; one row per scene",
     add_spread_options},
    {"assess", "an assessment: each criterion's value against what it must reach, and a verdict (pass or fail); one row per scene",
     add_assess_options},
};

// The flag of the hidden option (one the command does not take: hide_inapplicable) given on the command
// line, the one given twice first; "" for none.
std::string hidden_option_given(const CLI::App& where, const std::vector<std::string>& args) {
  std::string once;
  for (const CLI::Option* opt : where.get_options()) {
    if (!opt->get_group().empty() || opt->get_lnames().empty()) continue;
    const std::string flag = "--" + opt->get_lnames().front();
    const auto times = std::count_if(args.begin(), args.end(), [&](const std::string& a) {
      return a == flag || a.rfind(flag + "=", 0) == 0;
    });
    if (times > 1) return flag;
    if (times == 1 && once.empty()) once = flag;
  }
  return once;
}

// The parse error in the user's words rather than the parser's: an unknown option or a stray value,
// an option without its value or given twice, a missing subcommand; anything else as the parser says it.
std::string parse_error_words(CLI::App& app, CLI::App* where, const std::vector<std::string>& names,
                              const std::vector<std::string>& args, const CLI::ParseError& e) {
  std::string what = e.what();
  std::replace(what.begin(), what.end(), '\n', ' ');
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const std::string command = where == &app ? std::string() : where->get_name() + ": ";
    const std::vector<std::string> extras = app.remaining(true);
    for (const std::string& word : extras) {
      const std::string name = word.substr(0, word.find('='));
      if (name.rfind("--", 0) == 0 && name != "--help" && name != "--version" &&
          std::find(names.begin(), names.end(), name) == names.end())
        return fmt::format("{}unknown option '{}'", command, name);
    }
    if (!extras.empty()) {
      std::string list;
      for (const std::string& word : extras) list += (list.empty() ? "'" : " '") + word + "'";
      return fmt::format("{}unexpected argument{} {} (a value follows its option, e.g. --span 8)", command,
                         extras.size() > 1 ? "s" : "", list);
    }
  }
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr) {
    std::string option = what.substr(0, what.find(':'));
    // CLI11 names a hidden option (one the command does not take) by "": the hidden option given,
    // the one given twice first.
    if (option.empty()) option = hidden_option_given(*where, args);
    if (what.find("missing") != std::string::npos) return option + ": needs a value (" + option + " VALUE)";
    if (what.find("At Most") != std::string::npos)
      return option + ": given more than once (several values are one list a,b,c or a range start:stop:count)";
  }
  // CLI11: "Could not convert: --plane-strain = maybe" (a flag given a value it cannot read).
  if (const std::string prefix = "Could not convert: ";
      dynamic_cast<const CLI::ConversionError*>(&e) != nullptr && what.rfind(prefix, 0) == 0) {
    const std::string rest = what.substr(prefix.size());
    const std::size_t eq = rest.find(" = ");
    if (eq != std::string::npos) {
      const std::string flag = eq == 0 ? hidden_option_given(*where, args) : rest.substr(0, eq);
      return fmt::format("{}: a flag, given alone or as {}=true / {}=false, not '{}'", flag, flag, flag,
                         rest.substr(eq + 3));
    }
  }
  if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr && where == &app) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    return "a subcommand comes first: " + list;
  }
  return what;
}

// The one line a parse error prints; for an option nobody knows, the closest option of the subcommand
// (or subcommand name) is suggested.
std::string parse_error_line(CLI::App& app, const std::vector<std::string>& args, const CLI::ParseError& e) {
  std::vector<std::string> names;
  CLI::App* where = &app;
  for (CLI::App* sub : app.get_subcommands({}))
    if (sub->parsed()) where = sub;
  if (where == &app)
    for (CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
  else
    for (const CLI::Option* opt : where->get_options())
      for (const std::string& n : opt->get_lnames()) names.push_back("--" + n);
  std::string hint;
  for (const std::string& word : args)
    if (hint.empty() && std::find(names.begin(), names.end(), word.substr(0, word.find('='))) == names.end() &&
        (word.rfind("--", 0) == 0 || where == &app))
      hint = did_you_mean(word.substr(0, word.find('=')), names);
  return "ogive: " + parse_error_words(app, where, names, args, e) + hint + "\n";
}

// Help or version: refused with status 2 when the command line holds arguments nobody takes (CLI11
// reports those only after help), else printed on out with status 0, or 4 when out cannot be written.
// The options given with it are not checked (CLI11's usual: `thrust --help --span 8` prints the help).
int print_help_or_version(CLI::App& app, const std::vector<std::string>& args, const CLI::ParseError& e,
                          std::ostream& out, std::ostream& err) {
  if (const std::vector<std::string> extras = app.remaining(true); !extras.empty()) {
    err << parse_error_line(app, args, CLI::ExtrasError(extras));
    return kExitUsage;
  }
  std::ostringstream text;
  const int status = app.exit(e, text, err);
  try {
    write_all(out, text.str());
  } catch (const OutputError& failed) {
    err << "ogive: " << failed.what() << "\n";
    return kExitOutput;
  }
  return status;
}

// -1 when the command line parsed, else the exit status.
int parse(CLI::App& app, const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<const char*> argv{"ogive"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::CallForHelp& e) {
    return print_help_or_version(app, args, e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return print_help_or_version(app, args, e, out, err);
  } catch (const CLI::CallForVersion& e) {
    return print_help_or_version(app, args, e, out, err);
  } catch (const CLI::ParseError& e) {
    err << parse_error_line(app, args, e);
    return kExitUsage;
  }
  return -1;
}

// An option given as "--name=" with nothing after the sign: CLI11 would take the next argument as its
// value ("--span= 8" as --span 8). The option's name, or "" when there is none.
std::string empty_assignment(const std::vector<std::string>& args) {
  for (const std::string& word : args) {
    if (word == "--") break;
    if (word.size() > 3 && word.rfind("--", 0) == 0 && word.find('=') == word.size() - 1)
      return word.substr(0, word.size() - 1);
  }
  return {};
}

// The options whose own check refuses an empty name, saying what the name should be.
constexpr std::string_view kNamedFiles[] = {"--curve-file", "--loads-file", "--output", "--output-dir"};

// The option's flag as written on the command line. CLI11's get_name() is empty for a hidden option
// (an inapplicable one: hide_inapplicable), which a refusal must still name.
std::string flag_of(const CLI::Option& opt) {
  if (!opt.get_lnames().empty()) return "--" + opt.get_lnames().front();
  if (!opt.get_snames().empty()) return "-" + opt.get_snames().front();
  return opt.get_name();
}

// What CLI11 takes but a command line must not hold (one line, or ""): an option given twice (a flag
// too: CLI11 counts flags), an empty value (it would be read as the default, or as not given), a value
// left out after '='.
std::string refused_after_parse(const CLI::App& cmd, const std::vector<std::string>& args) {
  if (const std::string option = empty_assignment(args); !option.empty())
    return fmt::format("{}: no value after '=' (write {}=VALUE or {} VALUE)", option, option, option);
  for (const CLI::Option* opt : cmd.get_options()) {
    if (opt->count() == 0) continue;
    const std::string name = flag_of(*opt);
    if (opt->count() > 1) return fmt::format("{}: given more than once (give each option once)", name);
    if (opt->get_items_expected_min() == 0 ||
        std::find(std::begin(kNamedFiles), std::end(kNamedFiles), name) != std::end(kNamedFiles))
      continue;
    for (const std::string& value : opt->results())
      if (value.find_first_not_of(" \t") == std::string::npos)
        return fmt::format("{}: the value must not be empty (omit the option for its default)", name);
  }
  return {};
}

// The subcommand's exit status; its errors as one line on err with theirs.
int run_reporting_errors(const Run& run, std::ostream& out, std::ostream& err) {
  try {
    return run(out);
  } catch (const UsageError& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitUsage;
  } catch (const OutputError& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitOutput;
  } catch (const std::invalid_argument& e) {
    err << "ogive: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::exception& e) {
    err << "ogive: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"ogive: thrust and line of thrust of arches and barrel vaults (CSV on stdout)", "ogive"};
  app.require_subcommand(1);
  // Only the subcommand named first on the command line is built, with its options: CLI11 checks every
  // new option's names against all of its command's others, and building every subcommand's options
  // cost about as much as the rest of a one-scene run. A command line that names none first (help,
  // version, a misspelt or missing subcommand) gets them all, without options, so that `ogive --help`
  // lists them and a misspelt one is named. Once one is named, the others change nothing CLI11 prints:
  // a second subcommand is refused as an unexpected argument either way (require_subcommand(1)).
  const std::string named = args.empty() ? std::string() : args.front();
  const bool names_one = std::any_of(std::begin(kSubcommands), std::end(kSubcommands),
                                     [&](const Subcommand& s) { return s.name == named; });
  Run run;
  for (const Subcommand& s : kSubcommands) {
    if (names_one && s.name != named) continue;
    CLI::App* cmd = app.add_subcommand(s.name, s.description);
    if (names_one) run = s.add_options(*cmd);
  }
  add_help_texts(app);
  app.set_version_flag("--version", std::string("ogive ") + kVersion, "print the version and exit");
  // Bare `ogive`: the help, but on stderr with status 2, since stdout is for CSV only and a script that
  // forgot the subcommand should fail rather than read the help as data.
  if (args.empty()) {
    err << app.help();
    return kExitUsage;
  }
  if (const int status = parse(app, args, out, err); status >= 0) return status;
  for (const CLI::App* sub : app.get_subcommands())
    if (const std::string refused = refused_after_parse(*sub, args); !refused.empty()) {
      err << "ogive: " << refused << "\n";
      return kExitUsage;
    }
  // A parsed command line names its subcommand first (only help and version come before one).
  if (!run) return kExitUsage;
  const WarningSink warnings;
  const int status = run_reporting_errors(run, out, err);
  if (status != kExitUsage)  // bad input is one line
    for (const std::string& w : warnings.lines()) err << "ogive: warning: " << w << "\n";
  return status;
}

}  // namespace ogive::cli
