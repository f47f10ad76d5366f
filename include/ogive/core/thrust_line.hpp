// The line of thrust of a solved arch, summarised: where the compression's resultant strays furthest
// from the axis, and whether it stays within the kern and within the section (MODEL.md, "What is
// reported"). What a masonry engineer reads first: |e| <= 100 % everywhere means the elastic section is
// nowhere in tension; |e| <= 300 % means the resultant never leaves the masonry.
#pragma once

#include <limits>

#include "ogive/core/solution.hpp"

namespace ogive {

struct ThrustLineSummary {
  // %, the largest |e| along the whole arch (e = 600 M / (N t), in per cent of the kern's half-width
  // t/6); NaN where the normal force is not a compression everywhere (e unbounded or undefined).
  double max_abs_e = std::numeric_limits<double>::quiet_NaN();
  double max_abs_e_at = std::numeric_limits<double>::quiet_NaN();  // m, arc length where it occurs
  bool in_kern = false;     // N < 0 and |e| <= 100 % everywhere
  bool in_section = false;  // N < 0 and |e| <= 300 % everywhere
  bool ok = false;          // false when the solution has no field to summarise
};

// From the solution's field: `stations` equally spaced stations over the whole arch (odd, so that the
// crown is one), then the largest |e| refined by golden-section search between the neighbours of the
// best station, to 1e-9 of the arch's length in position (e is smooth there, so its value is then
// exact to the field's accuracy). Its error is the profile's (profile_difference measures e in units
// of the kern): solve with Options::stations > 0 so that verification covers it.
ThrustLineSummary summarize_thrust_line(const Solution& solution, int stations = 129);

}  // namespace ogive
