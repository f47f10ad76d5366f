// libFuzzer target: the input is a points file (CSV "x,y"), read both as a half file (springing to crown,
// parse_points_curve) and as a whole file (springing to springing, parse_whole_points_curve). Each
// must either throw CurveFileError "FILE:LINE: rule" or return a curve that keeps the invariants of
// curve.hpp (finite, arc-length parameterised, breakpoints inside the curve). See fuzz_checks.hpp.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ogive::fuzz::check_points_file(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
