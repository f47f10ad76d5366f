// Warnings: what the user should know about the input but is no error (a length in metres without
// --span, a load that looks like it was meant in kN). Collected while a command runs and printed by
// run_cli on standard error after it, one line each ("ogive: warning: ..."), whatever the exit status;
// standard output is not touched.
#pragma once

#include <string>
#include <vector>

namespace ogive::cli {

// While one lives (run_cli makes one per call, on its thread), warn() collects into it.
class WarningSink {
 public:
  WarningSink();
  ~WarningSink();
  WarningSink(const WarningSink&) = delete;
  WarningSink& operator=(const WarningSink&) = delete;
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  friend void warn(const std::string& key, const std::string& text);
  std::vector<std::string> keys_, lines_;
  WarningSink* outer_;
};

// The warning `text`, once per `key` (a sweep warns once about an option, not once per scene); nothing
// without a sink. Thread-safe: the sweep's threads may warn at once.
void warn(const std::string& key, const std::string& text);

}  // namespace ogive::cli
