#include "values.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
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

// 128-bit integers (a GCC and Clang extension) hold a range's decimal arithmetic exactly: 18 digits
// times a million points.
__extension__ using Int128 = __int128;

// A decimal number's text as an exact integer mantissa and a power of ten: value = mantissa 10^exponent.
struct Decimal {
  Int128 mantissa = 0;
  int exponent = 0;
};

// nullopt when the text has more than 18 significant digits or an exponent beyond +-300 (the caller
// then falls back to double arithmetic). The text has already been accepted by parse_number.
std::optional<Decimal> as_decimal(std::string_view t) {
  t = trim(t);
  bool negative = false;
  if (!t.empty() && (t.front() == '+' || t.front() == '-')) {
    negative = t.front() == '-';
    t.remove_prefix(1);
  }
  Decimal d;
  int digits = 0;
  bool point = false, any = false;
  std::size_t i = 0;
  for (; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '.' && !point) {
      point = true;
    } else if (c >= '0' && c <= '9') {
      any = true;
      if (d.mantissa == 0 && c == '0') {
        if (point) --d.exponent;
        continue;
      }
      if (++digits > 18) return std::nullopt;
      d.mantissa = d.mantissa * 10 + (c - '0');
      if (point) --d.exponent;
    } else {
      break;
    }
  }
  if (!any) return std::nullopt;
  if (i < t.size()) {
    if (t[i] != 'e' && t[i] != 'E') return std::nullopt;
    int e = 0;
    const auto [end, ec] = std::from_chars(t.data() + i + 1 + (t[i + 1] == '+' ? 1 : 0), t.data() + t.size(), e);
    if (ec != std::errc() || end != t.data() + t.size() || std::abs(e) > 300) return std::nullopt;
    d.exponent += e;
  }
  if (negative) d.mantissa = -d.mantissa;
  return d;
}

// The double nearest to numerator / denominator * 10^exponent, through a decimal string of 24
// significant digits that from_chars rounds correctly.
double nearest_double(Int128 numerator, Int128 denominator, int exponent) {
  std::string text;
  if (numerator < 0) {
    text += '-';
    numerator = -numerator;
  }
  Int128 whole = numerator / denominator, rest = numerator % denominator;
  std::string digits;
  do {
    digits.insert(digits.begin(), static_cast<char>('0' + static_cast<int>(whole % 10)));
    whole /= 10;
  } while (whole > 0);
  text += digits + '.';
  for (int k = 0; k < 24; ++k) {
    rest *= 10;
    text += static_cast<char>('0' + static_cast<int>(rest / denominator));
    rest %= denominator;
  }
  text += 'e' + std::to_string(exponent);
  double value = 0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
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
    // The points of a decimal range are computed in decimal, exactly, and rounded once: 0:1:11 gives
    // 0.1, 0.2, 0.3 (not 0.30000000000000004) and 0:0.0003:7 gives 5e-05, so that the echoed input
    // reads as typed and a filter such as rise_ratio == 0.2 finds its rows.
    const auto a_dec = as_decimal(text.substr(0, a)), b_dec = as_decimal(text.substr(a + 1, b - a - 1));
    if (a_dec && b_dec && n > 1 && std::abs(a_dec->exponent - b_dec->exponent) <= 18) {
      const int e = std::min(a_dec->exponent, b_dec->exponent);
      auto scaled = [e](const Decimal& d) {
        Int128 m = d.mantissa;
        for (int k = e; k < d.exponent; ++k) m *= 10;
        return m;
      };
      const Int128 A = scaled(*a_dec), B = scaled(*b_dec), steps = static_cast<Int128>(n - 1);
      for (std::size_t i = 0; i < n; ++i) {
        const Int128 k = static_cast<Int128>(i);
        out.push_back(i == 0 ? start : i + 1 == n ? stop : nearest_double(A * (steps - k) + B * k, steps, e));
      }
      return out;
    }
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
