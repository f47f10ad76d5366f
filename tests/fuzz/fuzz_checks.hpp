// The checks the fuzz targets run on one input, shared with the doctest suite: the targets in this
// directory call them from LLVMFuzzerTestOneInput, and tests/acceptance/fuzz_replay_test.cpp replays the seed
// corpora and every input the fuzzers ever broke through the same functions (no clang needed).
//
// The documented error of each entry point (UsageError, CurveFileError) is expected and its message is
// checked; any other exception, and any broken invariant (thrown as InvariantBroken), escapes. In a
// fuzz target that terminates the process, which libFuzzer reports as a crash and saves the input.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli.hpp"
#include "../support/csv_fields.hpp"
#include "ogive/geometry/curve_families.hpp"
#include "values.hpp"

namespace ogive::fuzz {

struct InvariantBroken : std::logic_error {
  using std::logic_error::logic_error;
};

// The message is formatted only when the check fails: the checks run in the fuzzers' inner loop.
template <class... Args>
void require(bool ok, fmt::format_string<Args...> message, Args&&... args) {
  if (!ok) throw InvariantBroken(fmt::format(message, std::forward<Args>(args)...));
}

// At most this many scenes go through run_cli per input, so that exec/s stays high: a range of
// kMaxValues scenes is parse_values' business, checked without solving it.
inline constexpr std::size_t kMaxCliScenes = 16;
// run_cli builds its whole CLI11 parser per call: about 1.5 ms under ASan and coverage instrumentation,
// 1000 times parse_values. So the fuzz target sends one input in kCliSampling through it (chosen by a
// hash of the bytes, so that an input always gets the same treatment); the regression tests send all.
inline constexpr std::uint32_t kCliSampling = 8;

inline std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t at = text.find(sep, start);
    out.push_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return out;
    start = at + 1;
  }
}

inline bool one_line(std::string_view message) {
  return !message.empty() && message.find('\n') == std::string_view::npos;
}

// ---------------------------------------------------------------------------------------------------
// parse_number / parse_values, then the same text as a scene option through the CLI.

// One command line per case; the value goes in as "--flag=TEXT", so that CLI11 never reads it as an
// option of its own. Only cheap commands: the closed form (about 3 us a scene) and the geometry.
// `ogive curve --stations 3` prints 3 rows per scene, `ogive thrust` one.
struct CliCase {
  std::vector<std::string> args;
  const char* flag;
};

inline const std::vector<CliCase>& cli_cases() {
  static const std::vector<CliCase> cases = {
      {{"thrust", "--method", "closed-form"}, "--eccentricity"},
      {{"thrust", "--method", "closed-form", "--curve", "segmental"}, "--rise-ratio"},
      {{"thrust", "--method", "closed-form", "--curve", "three-centred"}, "--haunch-angle"},
      {{"thrust", "--method", "closed-form", "--curve", "four-centred"}, "--crown-angle"},
      {{"thrust", "--method", "closed-form", "--curve", "four-centred"}, "--rise-ratio"},
      {{"thrust", "--method", "closed-form"}, "--thickness-ratio"},
      {{"thrust", "--method", "closed-form"}, "--support-displacement-ratio"},
      {{"thrust", "--method", "closed-form", "--eccentricity", "0.5"}, "--span"},
      {{"thrust", "--method", "closed-form"}, "--poisson-ratio"},
      {{"thrust", "--method", "closed-form", "--plane-strain"}, "--poisson-ratio"},
      {{"thrust", "--method", "closed-form"}, "--youngs-modulus"},
      {{"thrust", "--method", "closed-form"}, "--density"},
      {{"thrust", "--method", "closed-form"}, "--shear-coefficient"},
      {{"curve", "--stations", "3", "--curve", "elliptical"}, "--rise-ratio"},
      {{"curve", "--stations", "3", "--curve", "parabolic"}, "--rise-ratio"},
      {{"curve", "--stations", "3", "--curve", "catenary"}, "--rise-ratio"},
      {{"curve", "--stations", "3", "--curve", "catenary"}, "--span"},
      {{"curve", "--stations", "3", "--curve", "three-centred"}, "--haunch-angle"},
      // The loads and movements of whole arches (closed form: a live load or fill is not_applicable for it,
      // a row without numbers; the options' rules and Scene::validate still judge every value).
      {{"thrust", "--method", "closed-form"}, "--point-load"},
      {{"thrust", "--method", "closed-form", "--point-load", "1e4"}, "--point-load-at"},
      {{"thrust", "--method", "closed-form", "--live-load", "1e3"}, "--live-load-to"},
      {{"thrust", "--method", "closed-form", "--fill-height-ratio", "0.5"}, "--fill-density"},
      {{"thrust", "--method", "closed-form", "--supports", "pinned"}, "--right-settlement-ratio"},
      {{"thrust", "--method", "closed-form", "--eccentricity", "0.5"}, "--left-rotation"},
      {{"thrust", "--method", "closed-form", "--supports", "pinned"}, "--horizontal-acceleration"},
      // The walls (their resultant down each wall in thrust's columns).
      {{"thrust", "--method", "closed-form", "--wall-thickness", "3"}, "--wall-height"},
      {{"thrust", "--method", "closed-form", "--wall-height", "5"}, "--wall-thickness"},
      {{"thrust", "--method", "closed-form", "--wall-height", "5", "--wall-thickness", "3"}, "--wall-top-load"},
      {{"thrust", "--method", "closed-form", "--wall-height", "5", "--wall-thickness", "3"}, "--wall-lean"},
  };
  return cases;
}

// A hash of an input's bytes (FNV-1a): whether it goes through the CLI and which case it meets, so that
// every value meets every option.
inline std::uint32_t input_hash(std::string_view text) {
  std::uint32_t h = 2166136261u;
  for (unsigned char c : text) h = (h ^ c) * 16777619u;
  return h;
}

inline const CliCase& cli_case_for(std::string_view text) {
  return cli_cases()[(input_hash(text) / kCliSampling) % cli_cases().size()];
}

// The column `name` of a CSV header line, or npos.
inline std::size_t column_index(std::string_view header, std::string_view name) {
  const auto names = split(header, ',');
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return i;
  return std::string_view::npos;
}

// run_cli with the value text of one scene option; `values` is what parse_values made of it (empty
// when it threw UsageError).
inline void check_cli_value(std::string_view text, const std::vector<double>& values, bool parsed) {
  const CliCase& c = cli_case_for(text);
  const bool geometry = c.args.front() == "curve";
  std::vector<std::string> args = c.args;
  args.push_back(fmt::format("{}={}", c.flag, text));
  args.push_back("--all-columns");  // the checks read the inputs' columns too
  std::ostringstream out, err;
  const int status = ogive::cli::run_cli(args, out, err);
  const std::string o = out.str(), e = err.str();
  const std::string where = fmt::format("run_cli {} {}=...: ", args.front(), c.flag);
  require(status != ogive::cli::kExitInternal, "{}internal error (exit 1): {}", where, e);
  if (!parsed) require(status == ogive::cli::kExitUsage, "{}parse_values refused the text, the CLI did not", where);
  if (status == ogive::cli::kExitUsage) {
    require(o.empty(), "{}exit 2 with something on stdout", where);
    require(e.size() >= 2 && e.rfind("ogive: ", 0) == 0 && e.back() == '\n' && one_line(e.substr(0, e.size() - 1)),
            "{}exit 2 must print one line 'ogive: ...' on stderr, got: {}", where, e);
    return;
  }
  require(status == ogive::cli::kExitOk || status == ogive::cli::kExitNotConverged,
          "{}unknown exit status {}", where, status);
  // A CSV run prints on stderr only warnings, whole lines "ogive: warning: ..." (cli/warnings.hpp).
  for (const std::string_view line : split(e, '\n'))
    require(line.empty() || line.rfind("ogive: warning: ", 0) == 0, "{}a CSV run printed on stderr: {}", where, e);
  require(e.empty() || e.back() == '\n', "{}stderr's warnings end mid-line: {}", where, e);
  const auto rows = split(o, '\n');
  const std::size_t per_scene = geometry ? 3 : 1;
  // A value that makes no scene with the others (a span outside the curves' range, say) is one row
  // that says so (status invalid_scene, exit 3); every other scene gives per_scene rows.
  const std::size_t status_column = column_index(rows.front(), "status");
  require(status_column != std::string_view::npos, "{}no column status in the CSV", where);
  std::size_t invalid = 0;
  for (std::size_t r = 1; r + 1 < rows.size(); ++r)
    invalid += ogive::test::csv_fields(rows[r]).at(status_column) == "invalid_scene" ? 1 : 0;
  require(invalid <= values.size(), "{}{} invalid scenes of {}", where, invalid, values.size());
  if (invalid > 0) require(status == ogive::cli::kExitNotConverged, "{}an invalid scene with exit {}", where, status);
  // header, rows, and the empty string after the last "\n"
  require(rows.size() == 2 + (values.size() - invalid) * per_scene + invalid && rows.back().empty(),
          "{}{} values ({} invalid) gave {} lines of CSV", where, values.size(), invalid, rows.size() - 1);
  const std::size_t width = split(rows.front(), ',').size();
  const std::size_t status_col = column_index(rows.front(), "status");
  // The CSV prints a number that is not finite as an empty field: the columns that a geometry row, or
  // the row of a solved scene, must fill.
  std::vector<std::size_t> numbers;
  for (const char* name : geometry ? std::vector<const char*>{"span", "rise_ratio", "s", "x", "y", "theta", "kappa"}
                                   : std::vector<const char*>{"span", "rise_ratio", "H", "V", "H_over_V"}) {
    numbers.push_back(column_index(rows.front(), name));
    require(numbers.back() != std::string_view::npos, "{}no column {} in the CSV", where, name);
  }
  for (std::size_t r = 1; r + 1 < rows.size(); ++r) {
    const auto fields = ogive::test::csv_fields(rows[r]);
    require(fields.size() == width, "{}a row's width differs from the header's: {}", where, rows[r]);
    const bool solved = status_col != std::string_view::npos && fields[status_col] == "success";
    if (status == ogive::cli::kExitOk)
      require(solved, "{}exit 0 with a row that is not a success: {}", where, rows[r]);
    if (!solved) continue;
    for (std::size_t col : numbers) {
      const std::string_view f = fields[col];
      double v = 0;
      const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
      require(!f.empty() && ec == std::errc() && end == f.data() + f.size() && std::isfinite(v),
              "{}column {} is not a finite number in {}", where, col, rows[r]);
    }
  }
}

// every_cli: run the CLI part for every input (the regression tests), not one in kCliSampling.
inline void check_values(std::string_view text, bool every_cli = false) {
  using ogive::cli::UsageError;
  constexpr std::string_view kOption = "--value";
  const auto check_message = [&](const UsageError& e) {
    const std::string_view what = e.what();
    require(what.substr(0, kOption.size() + 2) == std::string(kOption) + ": ", "a UsageError must start with the option's name: {}", what);
    require(one_line(what), "a UsageError must be one line: {}", what);
  };

  std::vector<double> values;
  bool parsed = true;
  try {
    values = ogive::cli::parse_values(text, kOption);
  } catch (const UsageError& e) {
    check_message(e);
    parsed = false;
  }
  if (parsed) {
    require(!values.empty(), "parse_values returned no values");
    require(values.size() <= ogive::cli::kMaxValues, "parse_values returned {} values", values.size());
    for (double v : values) require(std::isfinite(v), "parse_values returned {}", v);
    if (text.find(':') != std::string_view::npos) {
      // A range: exactly count values, from start to stop, never going back, never outside the ends.
      const auto parts = split(text, ':');
      require(parts.size() == 3, "parse_values took a range that is not start:stop:count");
      const double start = ogive::cli::parse_number(parts[0], kOption);
      const double stop = ogive::cli::parse_number(parts[1], kOption);
      const double count = ogive::cli::parse_number(parts[2], kOption);
      require(static_cast<double>(values.size()) == count, "range gave {} values, count {}", values.size(), count);
      require(values.front() == start && values.back() == stop,
              "range {}:{} gave ends {} and {}", start, stop, values.front(), values.back());
      const double lo = std::min(start, stop), hi = std::max(start, stop);
      for (std::size_t i = 0; i < values.size(); ++i) {
        require(values[i] >= lo && values[i] <= hi, "range {}:{} gave {} outside its ends", start, stop, values[i]);
        if (i > 0)
          require(start <= stop ? values[i] >= values[i - 1] : values[i] <= values[i - 1],
                  "range {}:{} is not monotonic at {}", start, stop, i);
      }
    } else {
      // A list: one value per item, each what parse_number makes of it.
      const auto items = split(text, ',');
      require(items.size() == values.size(), "{} items gave {} values", items.size(), values.size());
      for (std::size_t i = 0; i < items.size(); ++i)
        require(ogive::cli::parse_number(items[i], kOption) == values[i], "a list item differs from parse_number's value");
    }
  }

  // parse_number on the whole text agrees with parse_values on text that is neither a list nor a range.
  try {
    const double v = ogive::cli::parse_number(text, kOption);
    require(std::isfinite(v), "parse_number returned {}", v);
    require(parsed && values.size() == 1 && values.front() == v, "parse_number took a text that parse_values refused");
  } catch (const UsageError& e) {
    check_message(e);
    require(!parsed || text.find_first_of(",:") != std::string_view::npos,
            "parse_values took a single number that parse_number refused");
  }

  // The CLI, when cheap enough: argv cannot carry a NUL byte.
  const bool sampled = every_cli || input_hash(text) % kCliSampling == 0;
  if (sampled && text.find('\0') == std::string_view::npos && values.size() <= kMaxCliScenes)
    check_cli_value(text, values, parsed);
}

// ---------------------------------------------------------------------------------------------------
// A points file.

// The invariants of curve.hpp, on any curve: a half (to the crown at x = L/2) or a whole arch (to the
// right springing at x = L, y = right_springing_height(); its crown the highest point).
inline void check_curve(const ogive::Curve& curve) {
  const bool whole = curve.extent() == ogive::CurveExtent::whole;
  const double L = curve.span(), S = curve.length();
  require(std::isfinite(L) && L > 0, "span {}", L);
  require(std::isfinite(S) && S > 0, "length {}", S);
  // The curve reaches from x = 0 to x = L/2 (half) or L (whole): it is at least that long (to round-off).
  const double end_x = whole ? L : 0.5 * L;
  require(S >= end_x * (1 - 1e-12), "length {} shorter than its horizontal extent {}", S, end_x);
  const double rise = curve.rise(), crown = curve.crown();
  require(std::isfinite(rise) && rise > 0, "rise {}", rise);
  require(crown >= 0 && crown <= S, "crown {} outside [0, {}]", crown, S);
  const double tol = 1e-12 * S;
  const ogive::CurvePoint p0 = curve.at(0), pS = curve.at(S);
  require(std::abs(p0.x) <= tol && std::abs(p0.y) <= tol, "at(0) = ({}, {})", p0.x, p0.y);
  require(std::abs(pS.x - end_x) <= tol, "at(S).x = {}, expected {}", pS.x, end_x);
  if (whole) {
    const double h = curve.right_springing_height();
    require(std::isfinite(h) && std::abs(pS.y - h) <= tol, "at(S).y = {}, right springing height {}", pS.y, h);
  }
  // Arc length: no chord is longer than the arc between its ends (to the accuracy of at(s)); x never
  // decreases; no point is higher than the crown.
  constexpr int kSamples = 16;
  ogive::CurvePoint previous = p0;
  for (int k = 0; k <= kSamples; ++k) {
    const double s = S * k / kSamples;
    const ogive::CurvePoint p = curve.at(s);
    require(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta) && std::isfinite(p.kappa),
            "at({}) = ({}, {}, {}, {})", s, p.x, p.y, p.theta, p.kappa);
    require(std::abs(p.theta) <= std::numbers::pi, "theta({}) = {}", s, p.theta);
    if (whole) require(p.y <= rise + tol, "y({}) = {} above the crown's {}", s, p.y, rise);
    if (k > 0) {
      const double chord = std::hypot(p.x - previous.x, p.y - previous.y);
      require(chord <= (S / kSamples) * (1 + 1e-9) + tol,
              "chord {} longer than the arc {} before s = {}", chord, S / kSamples, s);
      if (whole) require(p.x >= previous.x, "x decreases before s = {}: {} after {}", s, p.x, previous.x);
    }
    previous = p;
  }
  const std::vector<double> breaks = curve.breakpoints();
  for (std::size_t i = 0; i < breaks.size(); ++i) {
    require(breaks[i] > 0 && breaks[i] < S, "breakpoint {} outside (0, {})", breaks[i], S);
    if (i > 0) require(breaks[i] > breaks[i - 1], "breakpoints not strictly increasing");
  }
  require(std::isfinite(curve.first_moment_x()), "first moment {}", curve.first_moment_x());
}

// Physical lines of a text, as the points reader counts them.
inline std::size_t physical_lines(std::string_view bytes) {
  std::size_t lines = 1;
  for (char c : bytes) lines += c == '\n';
  return lines;
}

// One points file through one parser (half or whole): a CurveFileError FILE:LINE: rule, or a curve of
// that family that keeps the invariants.
template <class Parse>
void check_points_parser(std::string_view bytes, Parse parse, const char* family) {
  const std::string name = "fuzz.csv";
  std::istringstream in{std::string(bytes)};
  std::shared_ptr<const ogive::Curve> curve;
  try {
    curve = parse(in, name);
  } catch (const ogive::CurveFileError& e) {
    const std::string_view what = e.what();
    require(e.file() == name, "CurveFileError names another file: {}", e.file());
    require(e.line() >= 1 && e.line() <= physical_lines(bytes),
            "CurveFileError at line {} of {}: {}", e.line(), physical_lines(bytes), what);
    require(what == fmt::format("{}:{}: {}", name, e.line(), e.rule()), "CurveFileError::what() is not FILE:LINE: rule: {}", what);
    require(one_line(e.rule()), "a CurveFileError must be one line: {}", what);
    return;
  }
  require(curve != nullptr, "the {} parser returned no curve", family);
  require(curve->family() == family, "family {}, expected {}", curve->family(), family);
  require(curve->arcs().empty(), "a points curve has circular arcs");
  check_curve(*curve);
}

// The same bytes as a half file and as a whole file.
inline void check_points_file(std::string_view bytes) {
  check_points_parser(bytes, ogive::parse_points_curve, "points");
  check_points_parser(bytes, ogive::parse_whole_points_curve, "whole-points");
}

}  // namespace ogive::fuzz
