#include "ogive/core/thrust_line.hpp"

#include <algorithm>
#include <cmath>

namespace ogive {

ThrustLineSummary summarize_thrust_line(const Solution& sol, int stations) {
  ThrustLineSummary out;
  if (!sol.field || !sol.model || stations < 3) return out;
  out.ok = true;
  const std::vector<ArchState> profile = sample_stations(sol, stations, 0, stations);
  // A tensile or vanishing normal force anywhere: the eccentricity has no bound, and the line of thrust
  // is neither in the kern nor in the section.
  for (const ArchState& st : profile)
    if (!(st.N < 0)) return out;
  std::size_t best = 0;
  for (std::size_t k = 1; k < profile.size(); ++k)
    if (std::abs(profile[k].e) > std::abs(profile[best].e)) best = k;
  double max_e = std::abs(profile[best].e), at = profile[best].s;
  // Golden-section search for the maximum of |e| between the best station's neighbours. Every value
  // evaluated is a true |e| of the field, so the printed maximum is never above the truth, and a kink
  // (a pointed crown, where N jumps) that breaks unimodality costs only the refinement.
  auto abs_e = [&](double s) {
    const ArchState st = sol.at(s);
    if (!(st.N < 0)) return std::numeric_limits<double>::infinity();
    if (std::abs(st.e) > max_e) {
      max_e = std::abs(st.e);
      at = st.s;
    }
    return std::abs(st.e);
  };
  double lo = profile[best == 0 ? 0 : best - 1].s, hi = profile[std::min(best + 1, profile.size() - 1)].s;
  const double total = profile.back().s, golden = (std::sqrt(5.0) - 1) / 2;
  double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
  double fa = abs_e(a), fb = abs_e(b);
  while (hi - lo > 1e-9 * total && std::isfinite(fa) && std::isfinite(fb)) {
    if (fa > fb) {
      hi = b;
      b = a;
      fb = fa;
      a = hi - golden * (hi - lo);
      fa = abs_e(a);
    } else {
      lo = a;
      a = b;
      fa = fb;
      b = lo + golden * (hi - lo);
      fb = abs_e(b);
    }
  }
  if (!std::isfinite(fa) || !std::isfinite(fb)) return out;  // N reached zero between stations
  out.max_abs_e = max_e;
  out.max_abs_e_at = at;
  out.in_kern = max_e <= 100;
  out.in_section = max_e <= 300;
  return out;
}

}  // namespace ogive
