#include "values.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <fmt/compile.h>
#include <fmt/format.h>

namespace ogive::cli {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
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

// A range's values, refused when two neighbours are the same double while its ends differ: its step lies
// below the resolution of doubles there, and the sweep would repeat scenes it was not asked for.
std::vector<double> distinct_range(std::vector<double> values, std::string_view text, std::string_view option) {
  if (values.front() == values.back()) return values;
  for (std::size_t i = 1; i < values.size(); ++i)
    if (values[i] == values[i - 1])
      throw UsageError(fmt::format("{}: range '{}' has a step below the resolution of its values ({} would repeat): "
                                   "give fewer points or ends further apart",
                                   option, shown(text), values[i]));
  return values;
}

// The decimal a double reads as (its shortest round-trip text: the number as typed, or as a range
// computed it), or nullopt beyond as_decimal's reach.
std::optional<Decimal> typed_decimal(double x) {
  if (!std::isfinite(x)) return std::nullopt;
  char text[40];
  // The shortest text that reads back (fmt's Dragonbox: half the instructions of std::to_chars here).
  const char* end = fmt::format_to(text, FMT_COMPILE("{}"), x);
  return as_decimal(std::string_view(text, static_cast<std::size_t>(end - text)));
}

// The double nearest to mantissa 10^exponent. Where both are exact doubles (|mantissa| < 2^53, 10^|e| for
// |e| <= 22) one multiplication or division rounds correctly: the common case, a few nanoseconds (a
// sweep converts a length per scene); else through nearest_double's decimal text.
double decimal_value(Int128 mantissa, int exponent) {
  static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  constexpr Int128 kExact = Int128{1} << 53;
  if (mantissa < kExact && mantissa > -kExact && exponent >= -22 && exponent <= 22) {
    const auto m = static_cast<double>(static_cast<long long>(mantissa));
    return exponent >= 0 ? m * kPowers[exponent] : m / kPowers[-exponent];
  }
  // Up to 34 digits (a product of two 17-digit decimals): two 64-bit halves of 17 digits each, written
  // out for from_chars with one 128-bit division (nearest_double spends two per digit).
  constexpr Int128 kHalf = 100000000000000000, kMost = kHalf * kHalf;
  if (mantissa < kMost && mantissa > -kMost) {
    const Int128 m = mantissa < 0 ? -mantissa : mantissa;
    const auto high = static_cast<std::uint64_t>(m / kHalf), low = static_cast<std::uint64_t>(m % kHalf);
    // "-" high low, each half 17 digits (leading zeros are harmless), then "e" exponent.
    char text[48];
    char* end = text;
    if (mantissa < 0) *end++ = '-';
    for (std::uint64_t half : {high, low}) {
      for (int k = 16; k >= 0; --k, half /= 10) end[k] = static_cast<char>('0' + half % 10);
      end += 17;
    }
    *end++ = 'e';
    end = std::to_chars(end, text + sizeof text, exponent).ptr;
    double value = 0;
    std::from_chars(text, end, value);
    return value;
  }
  return nearest_double(mantissa, 1, exponent);
}

// The last few answers of one conversion on this thread: a sweep converts the same length at the same
// span scene after scene (the axis that varies fastest is seldom a length), and a conversion costs about
// 1500 instructions, half a closed-form scene's.
struct Memo {
  static constexpr int kSize = 4;
  std::uint64_t a[kSize] = {}, b[kSize] = {};
  double result[kSize] = {};
  bool used[kSize] = {};
  int next = 0;
  template <class F>
  double operator()(double x, double y, F convert) {
    const auto bx = std::bit_cast<std::uint64_t>(x), by = std::bit_cast<std::uint64_t>(y);  // -0 is not 0
    for (int i = 0; i < kSize; ++i)
      if (used[i] && a[i] == bx && b[i] == by) return result[i];
    const double r = convert(x, y);
    a[next] = bx;
    b[next] = by;
    result[next] = r;
    used[next] = true;
    next = (next + 1) % kSize;
    return r;
  }
};

double exact_product(double a, double b) {
  const auto da = typed_decimal(a), db = typed_decimal(b);
  // 17 digits each: the product's mantissa holds 34, within 128 bits.
  if (!da || !db || da->mantissa == 0 || db->mantissa == 0 || std::abs(da->exponent + db->exponent) > 280) return a * b;
  return decimal_value(da->mantissa * db->mantissa, da->exponent + db->exponent);
}

double exact_quotient(double a, double b) {
  const auto da = typed_decimal(a), db = typed_decimal(b);
  if (!da || !db || da->mantissa == 0 || db->mantissa == 0 || std::abs(da->exponent - db->exponent) > 280) return a / b;
  Int128 numerator = da->mantissa, denominator = db->mantissa;
  if (denominator < 0) {
    numerator = -numerator;
    denominator = -denominator;
  }
  // A quotient with a short decimal expansion (0.7 / 7): exact as an integer times a power of ten.
  Int128 scaled = numerator;
  for (int shift = 0; shift <= 20; ++shift, scaled *= 10)
    if (scaled % denominator == 0) return decimal_value(scaled / denominator, da->exponent - db->exponent - shift);
  // Else at least 17 digits before the point, so that nearest_double's 24 after it make 41 significant.
  int shift = 0;
  for (const Int128 most = denominator * 100000000000000000; (numerator < 0 ? -numerator : numerator) < most; ++shift)
    numerator *= 10;
  return nearest_double(numerator, denominator, da->exponent - db->exponent - shift);
}

}  // namespace

double decimal_product(double a, double b) {
  thread_local Memo memo;
  return memo(a, b, exact_product);
}

double decimal_quotient(double a, double b) {
  thread_local Memo memo;
  return memo(a, b, exact_quotient);
}

double parse_number(std::string_view text, std::string_view option) {
  const std::string_view t = trim(text);
  double value = 0;
  // from_chars: no locale, no leading '+', no hex unless asked; the whole token must be consumed.
  std::string_view body = t;
  if (!body.empty() && body.front() == '+') body.remove_prefix(1);
  // One sign at most: "+-1" is no number.
  const bool second_sign = t.size() > body.size() && !body.empty() && (body.front() == '-' || body.front() == '+');
  const auto [end, ec] = std::from_chars(body.data(), body.data() + body.size(), value);
  if (body.empty() || second_sign || ec != std::errc() || end != body.data() + body.size())
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
      // A (steps - k) + B k must fit: 18 digits scaled by up to 10^18 do, times a million points may not
      // (found: 999999999999999999:1e-18:1000 wrapped round to negative loads). Then double arithmetic.
      const Int128 most = (Int128{1} << 125) / steps;
      if (A <= most && A >= -most && B <= most && B >= -most) {
        for (std::size_t i = 0; i < n; ++i) {
          const Int128 k = static_cast<Int128>(i);
          out.push_back(i == 0 ? start : i + 1 == n ? stop : nearest_double(A * (steps - k) + B * k, steps, e));
        }
        return distinct_range(std::move(out), text, option);
      }
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
        v = 2 * ((start / 2) * (1 - f) + (stop / 2) * f);
      }
      // Between the ends, where it lies exactly: rounding must not take it past one.
      out.push_back(std::clamp(v, std::min(start, stop), std::max(start, stop)));
    }
    return distinct_range(std::move(out), text, option);
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

std::string shown(std::string_view s) {
  std::string out;
  for (char ch : s.substr(0, 60)) out += (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ? '?' : ch;
  if (s.size() > 60) out += "...";
  return out;
}

}  // namespace ogive::cli
