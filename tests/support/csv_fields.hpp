// One CSV line's fields, for the tests and the fuzz checks (RFC 4180: a quoted field may hold commas
// and doubled quotes; ogive quotes its messages).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ogive::test {

inline std::vector<std::string> csv_fields(std::string_view line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += line[++i];
      else if (c == '"') quoted = false;
      else out.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  return out;
}

}  // namespace ogive::test
