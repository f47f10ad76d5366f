#include "ogive/model/loads_file.hpp"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace ogive {
namespace {

constexpr std::size_t kMaxLineLength = 4096;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// A finite decimal number (an optional '+' too), or why not.
bool parse_number(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

}  // namespace

Loads parse_loads(std::istream& in, const std::string& name) {
  auto fail = [&](std::size_t line, const std::string& rule) -> void {
    throw std::invalid_argument(line == 0 ? fmt::format("{}: {}", name, rule) : fmt::format("{}:{}: {}", name, line, rule));
  };
  Loads loads;
  std::string line;
  std::size_t line_no = 0, count = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.size() > kMaxLineLength) fail(line_no, fmt::format("line longer than {} characters", kMaxLineLength));
    std::string_view text = line;
    if (line_no == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (trim(text).empty()) continue;
    const std::vector<std::string_view> f = fields_of(text);
    if (!header) {
      if (f.size() != 4 || lower(f[0]) != "kind" || lower(f[1]) != "value" || lower(f[2]) != "a" || lower(f[3]) != "b")
        fail(line_no, "the header must be kind,value,a,b");
      header = true;
      continue;
    }
    if (f.size() != 4) fail(line_no, fmt::format("expected 4 fields kind,value,a,b, got {}", f.size()));
    if (++count > kMaxLoadsInFile) fail(line_no, fmt::format("more than {} loads", kMaxLoadsInFile));
    const std::string kind = lower(f[0]);
    double value = 0, a = 0, b = 0;
    if (!parse_number(f[1], value)) fail(line_no, "value is not a finite number");
    if (!parse_number(f[2], a)) fail(line_no, "a is not a finite number");
    const bool has_b = !f[3].empty();
    if (has_b && !parse_number(f[3], b)) fail(line_no, "b is not a finite number");
    if (kind == "point") {
      if (has_b) fail(line_no, "a point load takes no b (its position is a)");
      if (!(a >= 0 && a <= 1)) fail(line_no, fmt::format("a point load's a = x/L must lie in [0, 1] (within the span), got {}", a));
      loads.points.push_back({value, a});
    } else if (kind == "live") {
      if (!has_b) fail(line_no, "a live load needs b, the end of its stretch (x/L)");
      if (!(a >= 0 && b <= 1 && a < b))
        fail(line_no, fmt::format("a live load's stretch a < b must lie in [0, 1] (within the span), got {} .. {}", a, b));
      loads.live.push_back({value, a, b});
    } else if (kind == "fill") {
      if (has_b) fail(line_no, "a fill takes no b (its level is a)");
      if (!(value >= 0)) fail(line_no, fmt::format("a fill's density must be >= 0, got {}", value));
      if (!(a > 0 && a <= 100))
        fail(line_no, fmt::format("a fill's level a = h_f/L must lie in (0, 100] (above the springing line), got {}", a));
      loads.fills.push_back({value, a});
    } else {
      fail(line_no, "kind must be point, live or fill");
    }
  }
  if (in.bad()) fail(0, "read error");
  if (!header) fail(1, "empty file: expected the header kind,value,a,b");
  return loads;
}

Loads read_loads_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw std::invalid_argument(path + ": cannot be read: it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in.is_open())
    throw std::invalid_argument(fmt::format("{}: cannot be opened ({})", path, errno != 0 ? std::strerror(errno) : "unknown error"));
  return parse_loads(in, path);
}

}  // namespace ogive
