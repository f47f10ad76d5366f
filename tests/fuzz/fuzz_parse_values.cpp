// libFuzzer target: the input is the text of a numeric option ("a", "a,b,c" or "start:stop:count").
// parse_values and parse_number must either return finite values that keep their invariants or throw
// UsageError; the same text as a scene option through run_cli must give exit 0/3 with well-formed CSV or
// exit 2 with one line on stderr. See fuzz_checks.hpp.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ogive::fuzz::check_values(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
