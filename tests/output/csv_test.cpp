// The CSV writer (include/ogive/output/csv.hpp): RFC 4180 quoting, column selection and order, and a repeated
// number (copied from earlier in the row) that reads as if formatted anew.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "ogive/output/csv.hpp"

TEST_CASE("csv: RFC 4180 quoting where a field needs it") {
  ogive::CsvRow row;
  row.add("plain").add("a, b").add("say \"x\"").add(1.5);
  CHECK(row.take() == "plain,\"a, b\",\"say \"\"x\"\"\",1.5\n");
  const ogive::FieldSelection keep{{true, false, true}, {}};
  ogive::CsvRow selected(&keep);
  selected.add(1.0).add(2.0).add(3.0);
  CHECK(selected.take() == "1,3\n");
}

TEST_CASE("csv: the kept fields in the selection's order - quoted fields moved whole - a mark's shared fields") {
  const ogive::FieldSelection backwards{{true, true, false, true}, {2, 0, 1}};
  ogive::CsvRow row(&backwards);
  row.add("a, b").add(2.5).add("skipped").add(std::string_view{});
  CHECK(row.take() == ",\"a, b\",2.5\n");
  row.add(1.0);
  row.mark();
  row.add(2.0).add(3.0).add(4.0);
  CHECK(row.take_to_mark() == "4,1,2\n");
  row.add(5.0).add(6.0).add(7.0);
  CHECK(row.take_to_mark() == "7,1,5\n");
}

TEST_CASE("csv: a repeated number (its magnitude copied from earlier in the row) reads as if formatted anew") {
  // Every field against append_number alone, with repeats, signs, zeros, a selection, and the text
  // before and after a rewind to a mark (the entries beyond it are stale).
  auto formatted = [](double x) {
    std::string s;
    ogive::append_number(s, x);
    return s;
  };
  const std::vector<double> values = {57387.507300707, -57387.507300707, 0.1, 1e-300, -0.0, 0.0, 0.1, -0.1,
                                      57387.507300707, 3.0, 4.0, 5.0, 6.0, 0.1, -57387.507300707};
  ogive::CsvRow row;
  std::string expected;
  for (double v : values) {
    row.add(v);
    expected += (expected.empty() ? "" : ",") + formatted(v);
  }
  CHECK(row.take() == expected + "\n");
  ogive::CsvRow marked;
  marked.add(2.5).add(-7.25);
  marked.mark();
  marked.add(123.456).add(-123.456);
  CHECK(marked.take_to_mark() == "2.5,-7.25,123.456,-123.456\n");
  // 123.456's text was beyond the mark: now 9.5 is written where it was, and a repeat must not copy it.
  marked.add(9.5).add(123.456).add(7.25).add(-2.5);
  CHECK(marked.take_to_mark() == "2.5,-7.25,9.5,123.456,7.25,-2.5\n");
  const ogive::FieldSelection keep{{true, false, true}, {}};
  ogive::CsvRow selected(&keep);
  selected.add(1.25).add(8.5).add(8.5);
  CHECK(selected.take() == "1.25,8.5\n");
}
