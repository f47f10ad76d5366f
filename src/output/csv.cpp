#include "ogive/output/csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace ogive {

void append_number(std::string& out, double value, int digits) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  if (std::isinf(value)) {
    out += value > 0 ? "inf" : "-inf";
    return;
  }
  if (value == 0.0) value = 0.0;  // no "-0" in the output
  char buf[32];
  if (digits > 0) {
    // Rounded to that many significant digits, then written as the shortest text of the rounded number:
    // 57387.5 at 3 digits prints 57400 (not %g's 5.74e+04), 1.23e-7 stays in scientific notation.
    const auto rounded = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::scientific, digits - 1);
    std::from_chars(buf, rounded.ptr, value);
  }
  // std::to_chars without a format gives the shortest representation that round-trips.
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, result.ptr);
}

CsvRow& CsvRow::add(double value) {
  if (!open_field()) return *this;
  // No number, no digits: an empty field reads as missing in gnuplot, pandas and spreadsheets, and a
  // row can never carry "nan" or "inf" that a script might take for a result.
  if (!std::isfinite(value)) return *this;
  if (divisor_ && index_ <= divisor_->size()) value /= (*divisor_)[index_ - 1];
  // The shortest round-trip text of -x is "-" followed by that of x: a repeated magnitude is copied.
  const double magnitude = std::abs(value);
  if (magnitude != 0)
    for (std::size_t i = 0; i < recent_count_; ++i) {
      const Recent& r = recent_[i];
      if (r.magnitude != magnitude) continue;
      char digits[32];
      line_.copy(digits, r.length, r.offset);
      if (value < 0) line_ += '-';
      line_.append(digits, r.length);
      return *this;
    }
  const std::size_t start = line_.size();
  append_number(line_, value, digits_);
  if (magnitude == 0 || line_.size() - start > 32) return *this;
  const std::size_t digits = start + (value < 0 ? 1 : 0);
  recent_[recent_next_] = {magnitude, static_cast<std::uint32_t>(digits), static_cast<std::uint32_t>(line_.size() - digits)};
  recent_next_ = (recent_next_ + 1) % kRecent;
  recent_count_ = std::max(recent_count_, recent_next_ == 0 ? kRecent : recent_next_);
  return *this;
}

void CsvRow::forget_recent_beyond(std::size_t size) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < recent_count_; ++i)
    if (recent_[i].offset + recent_[i].length <= size) recent_[kept++] = recent_[i];
  if (kept < recent_count_) {
    recent_count_ = kept;
    recent_next_ = kept % kRecent;
  }
}

CsvRow& CsvRow::add(std::int64_t value) {
  if (!open_field()) return *this;
  line_ += std::to_string(value);
  return *this;
}

CsvRow& CsvRow::add(std::string_view text) {
  if (!open_field()) return *this;
  // RFC 4180: a field with a separator, a quote or a line break is quoted, its quotes doubled. Messages
  // carry commas ("must lie in (0, 0.5)"); every other field ogive prints is a bare word or number.
  // (One pass over these short fields: find_first_of scanned them once per special character.)
  if (std::none_of(text.begin(), text.end(), [](char c) { return c == ',' || c == '"' || c == '\r' || c == '\n'; })) {
    line_ += text;
    return *this;
  }
  line_ += '"';
  for (char c : text) {
    if (c == '"') line_ += '"';
    line_ += c;
  }
  line_ += '"';
  return *this;
}

// The fields are formatted in the full order (so that a caller adds them as it computes them) and
// moved into the selection's order once the row is whole.
std::string CsvRow::ordered_line() const {
  std::string out;
  out.reserve(line_.size() + 1);
  for (std::size_t k = 0; k < order_->size(); ++k) {
    const std::size_t f = (*order_)[k];
    if (f >= starts_.size()) continue;  // a row built short of the selection (never, for whole rows)
    const std::size_t begin = starts_[f];
    const std::size_t end = f + 1 < starts_.size() ? starts_[f + 1] - 1 : line_.size();
    if (k > 0) out += ',';
    out.append(line_, begin, end - begin);
  }
  out += '\n';
  return out;
}

std::string CsvRow::take() {
  std::string out;
  if (order_) {
    out = ordered_line();
  } else {
    out = std::move(line_);
    out += '\n';
  }
  line_.clear();
  starts_.clear();
  fields_ = 0;
  index_ = 0;
  mark_ = {};
  recent_count_ = recent_next_ = 0;
  return out;
}

std::string CsvRow::take_to_mark() {
  std::string out = order_ ? ordered_line() : line_ + '\n';
  line_.resize(mark_.size);
  starts_.resize(mark_.starts);
  forget_recent_beyond(mark_.size);
  index_ = mark_.index;
  fields_ = mark_.fields;
  return out;
}

}  // namespace ogive
