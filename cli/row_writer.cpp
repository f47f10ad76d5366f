#include "row_writer.hpp"

#include <cerrno>
#include <cstring>
#include <ostream>

#include "interrupt.hpp"

namespace ogive::cli {

void RowWriter::write(const std::string& rows) {
  buffer_ += rows;
  if (pieces_ < 2 || buffer_.size() >= kPiece || Clock::now() - last_ >= kInterval) flush();
}

void RowWriter::flush() {
  const WholeWrite whole;  // an interrupting signal waits until the piece is out
  errno = 0;
  if (!buffer_.empty()) out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  out_.flush();
  if (!out_) {
    const int code = errno;
    throw OutputError(code ? std::string("cannot write the output: ") + std::strerror(code)
                           : std::string("cannot write the output"));
  }
  buffer_.clear();
  ++pieces_;
  last_ = Clock::now();
}

void write_all(std::ostream& out, const std::string& text) {
  RowWriter writer(out);
  writer.write(text);
  writer.flush();
}

}  // namespace ogive::cli
