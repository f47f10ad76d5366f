// CSV rows for the CLI: comma-separated (RFC 4180: a text field with a comma, quote or line break is
// quoted), numbers in their shortest round-trip decimal form so that output is exact and deterministic.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ogive {

// Shortest decimal that reads back to the same double; "nan", "inf", "-inf" for the non-finite. With
// digits 1 .. 17: that many significant digits (trailing zeros dropped).
void append_number(std::string& out, double value, int digits = 0);

// Which fields of a command's full order a row prints, and in which order.
struct FieldSelection {
  std::vector<bool> keep;  // keep[i]: whether field i of the full order is printed
  // Empty: the kept fields in the full order. Else order[k] is the rank, among the kept fields in the
  // full order, of the field printed k-th (a permutation of 0 .. kept - 1).
  std::vector<std::size_t> order;
  // Empty: numbers as they are. Else field i's numbers are divided by divisor[i] before printing (a
  // change of unit: 1000 prints N as kN).
  std::vector<double> divisor;
  // Significant digits of every number printed, 1 .. 17; 0: the shortest decimal that reads back to
  // the same double.
  int digits = 0;
};

// A row is built by adding every field of its command in the header's full order; with a selection,
// the fields not selected are skipped unformatted, so that choosing columns costs nothing, and the kept
// ones are printed in the selection's order.
class CsvRow {
 public:
  CsvRow() = default;
  // nullptr: every field, in the full order. Must outlive the row.
  explicit CsvRow(const FieldSelection* selection)
      : keep_(selection ? &selection->keep : nullptr),
        order_(selection && !selection->order.empty() ? &selection->order : nullptr),
        divisor_(selection && !selection->divisor.empty() ? &selection->divisor : nullptr),
        digits_(selection ? selection->digits : 0) {}

  CsvRow& add(double value);  // shortest round-trip; an empty field when not finite (no number)
  CsvRow& add(std::int64_t value);
  CsvRow& add(int value) { return add(static_cast<std::int64_t>(value)); }
  CsvRow& add(std::string_view text);  // quoted only where it must be
  // Booleans have one spelling, true / false (what pandas reads as bool).
  CsvRow& add_bool(bool value) { return add(std::string_view(value ? "true" : "false")); }
  // Whether the next field is printed (and counts it): lets a caller skip computing a skipped field.
  bool wants_next() const { return !keep_ || (index_ < keep_->size() && (*keep_)[index_]); }
  // The row with its newline; the row is cleared for reuse.
  std::string take();
  // Rows that share their first fields (a scene's, on every station of a profile): mark() after
  // adding them, and take_to_mark() returns the row and rewinds to the mark, formatted once.
  void mark() { mark_ = {line_.size(), index_, starts_.size(), fields_}; }
  std::string take_to_mark();

 private:
  // Counts the field; false when it is not selected (nothing is written), else writes the separator.
  bool open_field() {
    const bool keep = wants_next();
    ++index_;
    if (keep && fields_++ > 0) line_ += ',';
    if (keep && order_) starts_.push_back(line_.size());
    return keep;
  }
  // line_ with its fields in order_'s order (order_ set) and a newline.
  std::string ordered_line() const;
  struct Mark {
    std::size_t size = 0, index = 0, starts = 0;
    int fields = 0;
  };
  // The last few numbers formatted into line_ (their magnitude and where its digits are): a row often
  // repeats one (H and H_left, a symmetric arch's right springing mirroring the left), and formatting a
  // double costs more than copying its text. Entries beyond line_'s end or a rewind are dropped.
  struct Recent {
    double magnitude = 0;
    std::uint32_t offset = 0, length = 0;
  };
  static constexpr std::size_t kRecent = 4;
  Recent recent_[kRecent];
  std::size_t recent_count_ = 0, recent_next_ = 0;
  void forget_recent_beyond(std::size_t size);
  const std::vector<bool>* keep_ = nullptr;
  const std::vector<std::size_t>* order_ = nullptr;
  const std::vector<double>* divisor_ = nullptr;
  int digits_ = 0;
  std::vector<std::size_t> starts_;  // with order_: where each kept field's text begins in line_
  std::size_t index_ = 0;
  std::string line_;
  int fields_ = 0;
  Mark mark_;
};

}  // namespace ogive
