#include "values.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

namespace ogive::cli {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Printable form of user text for a message: control bytes become '?', long text is cut.
std::string shown(std::string_view s) {
  std::string out;
  for (char ch : s.substr(0, 60)) out += (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ? '?' : ch;
  if (s.size() > 60) out += "...";
  return out;
}

}  // namespace

double parse_number(std::string_view text, std::string_view option) {
  const std::string_view t = trim(text);
  double value = 0;
  // from_chars: no locale, no leading '+', no hex unless asked; the whole token must be consumed.
  std::string_view body = t;
  if (!body.empty() && body.front() == '+') body.remove_prefix(1);
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (body.empty() || ec != std::errc() || end != body.data() + body.size())
    throw UsageError(fmt::format("{}: '{}' is not a number", option, shown(t)));
  if (!std::isfinite(value))
    throw UsageError(fmt::format("{}: '{}' is not a finite number", option, shown(t)));
  return value;
}

std::vector<double> parse_values(std::string_view text, std::string_view option) {
  if (trim(text).empty()) throw UsageError(fmt::format("{}: needs a value, a list a,b,c or a range start:stop:count", option));
  std::vector<double> out;
  if (text.find(':') != std::string_view::npos) {
    if (text.find(',') != std::string_view::npos)
      throw UsageError(fmt::format("{}: '{}' mixes a list and a range", option, shown(text)));
    const std::size_t a = text.find(':'), b = text.find(':', a + 1);
    if (b == std::string_view::npos || text.find(':', b + 1) != std::string_view::npos)
      throw UsageError(fmt::format("{}: range '{}' must be start:stop:count", option, shown(text)));
    const double start = parse_number(text.substr(0, a), option);
    const double stop = parse_number(text.substr(a + 1, b - a - 1), option);
    const double count = parse_number(text.substr(b + 1), option);
    if (count != std::floor(count) || count < 1)
      throw UsageError(fmt::format("{}: range count '{}' must be a whole number >= 1", option, shown(text.substr(b + 1))));
    if (count > static_cast<double>(kMaxValues))
      throw UsageError(fmt::format("{}: range count {} exceeds the limit of {}", option, count, kMaxValues));
    if (count == 1 && start != stop)
      throw UsageError(fmt::format("{}: a range of one value needs start == stop, got '{}'", option, shown(text)));
    const auto n = static_cast<std::size_t>(count);
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (n == 1 || i + 1 == n) {
        out.push_back(i == 0 ? start : stop);
        continue;
      }
      double v = start + (stop - start) * static_cast<double>(i) / static_cast<double>(n - 1);
      // Near the ends of the double range, stop - start or (stop - start) * i overflows (found by
      // fuzzing: "1:1.7976931348623157e308:5" gave inf, "-1e308:1e308:3" nan). Then interpolate the
      // halves, which cannot overflow, and keep the value between the ends, where it lies exactly.
      if (!std::isfinite(v)) {
        const double f = static_cast<double>(i) / static_cast<double>(n - 1);
        v = std::clamp(2 * ((start / 2) * (1 - f) + (stop / 2) * f), std::min(start, stop), std::max(start, stop));
      }
      out.push_back(v);
    }
    return out;
  }
  std::size_t pos = 0;
  while (true) {
    const std::size_t comma = text.find(',', pos);
    const std::string_view item = text.substr(pos, comma == std::string_view::npos ? std::string_view::npos : comma - pos);
    if (trim(item).empty()) throw UsageError(fmt::format("{}: empty item in list '{}'", option, shown(text)));
    out.push_back(parse_number(item, option));
    if (out.size() > kMaxValues) throw UsageError(fmt::format("{}: more than {} values", option, kMaxValues));
    if (comma == std::string_view::npos) break;
    pos = comma + 1;
  }
  return out;
}

}  // namespace ogive::cli
