#include "warnings.hpp"

#include <algorithm>
#include <mutex>

namespace ogive::cli {
namespace {

// The sink of the run_cli call under way; a sweep's worker threads warn into their caller's.
WarningSink* current = nullptr;
std::mutex guard;

}  // namespace

WarningSink::WarningSink() : outer_(current) { current = this; }
WarningSink::~WarningSink() { current = outer_; }

void warn(const std::string& key, const std::string& text) {
  const std::lock_guard<std::mutex> lock(guard);
  if (!current || std::find(current->keys_.begin(), current->keys_.end(), key) != current->keys_.end()) return;
  current->keys_.push_back(key);
  current->lines_.push_back(text);
}

}  // namespace ogive::cli
