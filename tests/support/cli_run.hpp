// Running the CLI in-process, and reading its CSV, for the tests.
#pragma once

#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "csv_fields.hpp"

namespace ogive::test {

struct Run {
  int status;
  std::string out, err;
};

inline Run run_command(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int status = cli::run_cli(args, out, err);
  return {status, out.str(), err.str()};
}

inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// One CSV line's fields.
inline std::vector<std::string> fields(const std::string& line) { return csv_fields(line); }

// The value of column `name` in data row `row` (1-based, after the header).
inline std::string column(const std::string& csv, const std::string& name, std::size_t row = 1) {
  const auto ls = lines(csv);
  const auto header = fields(ls.at(0));
  const auto it = std::find(header.begin(), header.end(), name);
  REQUIRE_MESSAGE(it != header.end(), "no column " << name);
  return fields(ls.at(row)).at(static_cast<std::size_t>(it - header.begin()));
}

// Bad input: exit 2, nothing on stdout, one line on stderr starting "ogive: ".
inline void check_refused(const std::vector<std::string>& args) {
  std::string joined;
  for (const auto& a : args) joined += a.substr(0, 40) + " ";
  CAPTURE(joined);
  const Run r = run_command(args);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(lines(r.err).size() == 1);
  CHECK(r.err.rfind("ogive: ", 0) == 0);
}

// The command with --threads 1 and with each of `threads`: the same exit status, stdout and stderr
// (CHECKed); the one-thread run.
inline Run same_with_threads(const std::vector<std::string>& command, const std::vector<std::string>& threads) {
  std::vector<std::string> one = command;
  one.insert(one.end(), {"--threads", "1"});
  const Run reference = run_command(one);
  for (const std::string& n : threads) {
    std::vector<std::string> many = command;
    many.insert(many.end(), {"--threads", n});
    const Run r = run_command(many);
    CAPTURE(n);
    CHECK(r.status == reference.status);
    CHECK(r.out == reference.out);
    CHECK(r.err == reference.err);
  }
  return reference;
}

}  // namespace ogive::test
