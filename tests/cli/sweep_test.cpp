// The CLI's sweep runner and ordered writer: output streams in whole rows as they are ready, a write
// error ends the run with one line and exit 4, and any number of threads prints the same bytes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "support/cli_run.hpp"

using namespace ogive;
using namespace ogive::test;

namespace {

// A stream buffer that records each piece handed to it at a flush, and fails (as a full disk does)
// once more than `capacity` bytes have been written.
class RecordingBuffer : public std::streambuf {
 public:
  explicit RecordingBuffer(std::size_t capacity = std::numeric_limits<std::size_t>::max()) : capacity_(capacity) {}
  std::vector<std::string> pieces{std::string()};
  std::string all() const {
    std::string s;
    for (const auto& p : pieces) s += p;
    return s;
  }

 protected:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (written_ + static_cast<std::size_t>(n) > capacity_) return 0;
    written_ += static_cast<std::size_t>(n);
    pieces.back().append(s, static_cast<std::size_t>(n));
    return n;
  }
  int overflow(int c) override {
    if (c == traits_type::eof()) return 0;
    const char ch = static_cast<char>(c);
    return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
  }
  int sync() override {
    if (!pieces.back().empty()) pieces.emplace_back();
    return 0;
  }

 private:
  std::size_t capacity_;
  std::size_t written_ = 0;
};

}  // namespace

TEST_CASE("trust: output streams in whole rows - header and first row at once") {
  RecordingBuffer buffer;
  std::ostream out(&buffer);
  std::ostringstream err;
  // One thread: the first row on its own. (With several, the first chunk of scenes, at most 128.)
  REQUIRE(cli::run_cli({"thrust", "--eccentricity", "0:1:3001", "--threads", "1"}, out, err) == 0);
  const auto& pieces = buffer.pieces;
  REQUIRE(pieces.size() >= 4);                      // written in several pieces, not at the end
  CHECK(lines(pieces[0]).size() == 1);              // the header
  CHECK(lines(pieces[1]).size() == 1);              // the first row, on its own
  for (const auto& piece : pieces)
    if (!piece.empty()) CHECK(piece.back() == '\n');  // whole rows only
  CHECK(lines(buffer.all()).size() == 1 + 3001);
  // The same bytes as one string: streaming changes when, not what.
  const Run whole = run_command({"thrust", "--eccentricity", "0:1:3001"});
  CHECK(whole.out == buffer.all());
  // With two threads: whole rows in every piece, the first rows early (one chunk), the same bytes.
  RecordingBuffer threaded;
  std::ostream out2(&threaded);
  REQUIRE(cli::run_cli({"thrust", "--eccentricity", "0:1:3001", "--threads", "2"}, out2, err) == 0);
  REQUIRE(threaded.pieces.size() >= 4);
  CHECK(lines(threaded.pieces[1]).size() <= 128);
  for (const auto& piece : threaded.pieces)
    if (!piece.empty()) CHECK(piece.back() == '\n');
  CHECK(threaded.all() == buffer.all());
}

TEST_CASE("trust: a write error ends the run - one line on stderr - exit 4") {
  for (const char* command : {"thrust", "profile", "curve"}) {
    RecordingBuffer full(3000);  // the header and a few rows fit, then the disk is full
    std::ostream out(&full);
    std::ostringstream err;
    const int status = cli::run_cli({command, "--eccentricity", "0:1:2001"}, out, err);
    CAPTURE(command);
    CHECK(status == cli::kExitOutput);
    CHECK(lines(err.str()).size() == 1);
    CHECK(err.str().find("cannot write the output") != std::string::npos);
    const std::string written = full.all();
    CHECK(!written.empty());
    CHECK(written.back() == '\n');  // what was written is whole rows
  }
}

TEST_CASE("threads: the same bytes with any number of threads - invalid scenes and failures included") {
  const std::vector<std::vector<std::string>> commands = {
      {"thrust", "--curve", "catenary", "--rise-ratio", "0.3:2:40", "--thickness-ratio", "0.4"},
      {"thrust", "--eccentricity", "0:1:30", "--method", "shooting", "--max-steps", "40"},
      {"profile", "--eccentricity", "0:1:9", "--stations", "33"},
      {"check", "--curve", "parabolic", "--rise-ratio", "0.3,0.5,0.7"},
      {"curve", "--curve", "elliptical", "--rise-ratio", "0.2:0.6:5", "--stations", "9"},
  };
  for (const auto& command : commands) {
    CAPTURE(command[0]);
    same_with_threads(command, {"2", "3", "8"});
  }
  check_refused({"thrust", "--threads", "0"});
  check_refused({"thrust", "--threads", "257"});
  check_refused({"thrust", "--threads", "two"});
}

TEST_CASE("threads: a write error with several threads still ends the run cleanly - exit 4") {
  RecordingBuffer full(5000);
  std::ostream out(&full);
  std::ostringstream err;
  const int status = cli::run_cli({"thrust", "--eccentricity", "0:1:3000", "--threads", "4"}, out, err);
  CHECK(status == cli::kExitOutput);
  CHECK(lines(err.str()).size() == 1);
  CHECK(full.all().back() == '\n');
}

TEST_CASE("threads: what waits to be written is bounded by rows, whatever the stations - the same bytes") {
  // The writer's pieces show what was held at once: scenes of many stations go out as they are made
  // (pieces of about 64 KiB), scenes of a few thousand wait in chunks of at most kChunkRows rows.
  const std::vector<std::pair<std::vector<std::string>, std::size_t>> sweeps = {
      {{"curve", "--eccentricity", "0,0.5,1", "--stations", "100000"}, 2 * (std::size_t{1} << 16) + 1000},
      {{"curve", "--eccentricity", "0:1:200", "--stations", "2000"}, (std::size_t{1} << 16) + 4096 * 200},
      {{"profile", "--eccentricity", "0:1:3", "--stations", "10000"}, 2 * (std::size_t{1} << 16) + 4096 * 400}};
  for (const auto& sweep : sweeps) {
    const auto& [command, bound] = sweep;
    CAPTURE(sweep.first[0]);
    CAPTURE(sweep.first[4]);
    std::string one_thread;
    for (const char* threads : {"1", "2"}) {
      std::vector<std::string> args = command;
      args.insert(args.end(), {"--threads", threads});
      RecordingBuffer buffer;
      std::ostream out(&buffer);
      std::ostringstream err;
      REQUIRE(cli::run_cli(args, out, err) == 0);
      std::size_t largest = 0;
      for (const auto& piece : buffer.pieces) largest = std::max(largest, piece.size());
      CAPTURE(threads);
      CHECK(largest <= bound);
      if (one_thread.empty()) one_thread = buffer.all();
      CHECK(buffer.all() == one_thread);
    }
  }
}
