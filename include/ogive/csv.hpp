// CSV rows for the CLI: comma-separated (RFC 4180: a text field with a comma, quote or line break is
// quoted), numbers in their shortest round-trip decimal form so that output is exact and deterministic.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace ogive {

// Shortest decimal that reads back to the same double; "nan", "inf", "-inf" for the non-finite.
void append_number(std::string& out, double value);

class CsvRow {
 public:
  CsvRow& add(double value);  // shortest round-trip; an empty field when not finite (no number)
  CsvRow& add(std::int64_t value);
  CsvRow& add(int value) { return add(static_cast<std::int64_t>(value)); }
  CsvRow& add(std::string_view text);  // quoted only where it must be
  // The row with its newline; the row is cleared for reuse.
  std::string take();

 private:
  void separate() {
    if (fields_++ > 0) line_ += ',';
  }
  std::string line_;
  int fields_ = 0;
};

}  // namespace ogive
