// The spreading analysis' public types: their names and the options' rules (spreading.hpp).
#include <cmath>
#include <string>

#include "ogive/limit/spreading.hpp"

namespace ogive {

const char* to_string(SpreadCollapse c) {
  switch (c) {
    case SpreadCollapse::thrust_leaves_arch: return "thrust_leaves_arch";
    case SpreadCollapse::snap_through: return "snap_through";
    case SpreadCollapse::sliding: return "sliding";
    case SpreadCollapse::wall_tips: return "wall_tips";
  }
  return "?";
}

const char* to_string(SpreadStatus s) {
  switch (s) {
    case SpreadStatus::success: return "success";
    case SpreadStatus::inadmissible: return "inadmissible";
    case SpreadStatus::no_mechanism: return "no_mechanism";
    case SpreadStatus::lp_failure: return "lp_failure";
    case SpreadStatus::not_collapsed: return "not_collapsed";
    case SpreadStatus::unsettled: return "unsettled";
    case SpreadStatus::not_converged: return "not_converged";
  }
  return "?";
}

bool SpreadOptions::is_valid(std::string* why) const {
  auto bad = [&](const char* m) {
    if (why) *why = m;
    return false;
  };
  if (!(left_share >= 0) || !std::isfinite(left_share)) return bad("left_share must be finite and >= 0");
  if (!(right_share >= 0) || !std::isfinite(right_share)) return bad("right_share must be finite and >= 0");
  if (!(left_share + right_share > 0)) return bad("left_share + right_share must be > 0 (the span must grow)");
  if (!std::isfinite(left_settlement_share)) return bad("left_settlement_share must be finite");
  if (!std::isfinite(right_settlement_share)) return bad("right_settlement_share must be finite");
  if (!(increment_ratio >= kLeastIncrementRatio && increment_ratio <= 0.1))
    return bad("increment_ratio must lie in [1e-4, 0.1] (finer increments take longer without moving the capacity)");
  if (steps < 1 || steps > 100000) return bad("steps must be in [1, 100000]");
  if (!(stop_ratio >= 0)) return bad("stop_ratio must be >= 0 (infinity: to collapse)");
  return true;
}

}  // namespace ogive
