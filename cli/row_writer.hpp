// Output: rows are written as they are made, in pieces of whole rows, so that the first row of a long
// sweep arrives at once, memory does not grow with the sweep, and an interrupted run leaves only complete
// rows (each piece goes out whole: a SIGINT, SIGTERM or SIGHUP that arrives meanwhile waits for it,
// interrupt.hpp; a fatal signal would cut a large write to a file at a page). A failed write (disk
// full, a closed stdout) ends the run: OutputError, exit status kExitOutput. A closed pipe raises
// SIGPIPE before any of this, which ends the process quietly, as `| head` expects.
#pragma once

#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <stdexcept>
#include <string>

namespace ogive::cli {

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class RowWriter {
 public:
  explicit RowWriter(std::ostream& out) : out_(out) {}
  // The header and the first row go out at once; then pieces of 64 KiB, or what 0.2 s produced.
  void write(const std::string& rows);
  void flush();

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::size_t kPiece = 1 << 16;
  static constexpr std::chrono::milliseconds kInterval{200};
  std::ostream& out_;
  std::string buffer_;
  int pieces_ = 0;
  Clock::time_point last_ = Clock::now();
};

// All of `text` at once (--columns help), as the rows are written.
void write_all(std::ostream& out, const std::string& text);

}  // namespace ogive::cli
