// The line of thrust of a solved arch, summarised: where the compression's resultant strays furthest
// from the axis, and whether it stays within the kern and within the section (MODEL.md, "What is
// reported"). What a masonry engineer reads first: |e| <= 100 % everywhere means the elastic section is
// nowhere in tension; |e| <= 300 % means the resultant never leaves the masonry.
#pragma once

#include <limits>
#include <vector>

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

// Where the field is not smooth (the domain's ends, the curve's breakpoints, point loads, a hinge, a live
// load's ends, a fill's breaks) it is cut into pieces; on each, e = 600 M / (N t) is smooth, and its
// extrema are the piece's ends (each side's own limit) and the zeros of
//   d(M/N)/ds ~ M' N - M N',  M' = -V,  N' = kappa V + c Fx' + sn Fy'  (the model's equations).
// That slope is bracketed at points at most kScanTurn of tangent turn apart (at least kScanIntervals
// intervals a piece) and each sign change refined to 1e-9 of the arch's length by Brent's method
// (interpolation safeguarded by bisection); so is each fall of N' through zero (the largest N, which
// must be a compression too: between bracketing points e's slope need not change sign where N turns
// tensile). Every value compared is a true |e| of the field, so the printed maximum is never
// above the truth. Over a half model the left half is summarised (the right is its mirror image).
ThrustLineSummary summarize_thrust_line(const Solution& solution);

// The greatest compressive stress along the arch (ArchState::compressive_stress: the elastic section's
// linear stress, the no-tension section's triangular block where it is cracked), found as the largest |e|
// is: on each smooth piece, at its ends and where the stress's slope (from the model's equations) falls
// through zero, bracketed and refined to 1e-9 of the arch's length. Every value compared is a true stress
// of the field, so the printed maximum is never above the truth. NaN where the normal force is not a
// compression everywhere, or the no-tension section's resultant leaves the section.
struct StressSummary {
  double max_compressive_stress = std::numeric_limits<double>::quiet_NaN();     // Pa
  double max_compressive_stress_at = std::numeric_limits<double>::quiet_NaN();  // m, arc length
  bool ok = false;  // false when the solution has no field to summarise
};
StressSummary summarize_compressive_stress(const Solution& solution);

// The states at the scan's bracketing points (the pieces' ends and the points between): a few dozen
// states that show the field's size (its largest force and couple) without sampling it densely.
std::vector<ArchState> field_scan(const Solution& solution);

// The profile's stations a solve is asked for when a summary reads its field without printing it
// (Options::stations with Options::unprinted_profile): the error estimate, and so the status, then covers
// the field the summary reads. `thrust`'s summary columns and the assessment use it.
inline constexpr int kSummaryStations = 65;

// The bracketing points' spacing in tangent turn, and the fewest intervals a piece is cut into.
inline constexpr double kScanTurn = 3.14159265358979323846 / 24;
inline constexpr int kScanIntervals = 4;

}  // namespace ogive
