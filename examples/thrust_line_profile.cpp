// A profile: the thrust line along the equilateral arch (span 10 m, t = 0.08 L) at 11 stations from
// springing to springing: the axis point, the internal forces and where the resultant crosses the
// section (e in per cent of the kern's half-width t/6: beyond 100 the section would be in tension).
// Then the thrust line's summary: its largest |e|, where, and whether it stays in the kern and the section.
// Exits 0 when the solve succeeded, 1 otherwise.
#include <cstdio>

#include "ogive/ogive.hpp"

int main() {
  ogive::Scene scene;
  scene.curve = ogive::make_pointed(10.0, 0.5);
  scene.thickness = 0.08 * scene.span();

  ogive::Options options;
  options.stations = 11;  // the profile, over the whole arch; verified with the reactions
  const ogive::Solution sol = ogive::solve(scene, options);
  if (!sol.ok()) {
    std::printf("status %s: %s\n", ogive::to_string(sol.status), sol.message.c_str());
    return 1;
  }
  std::printf("%8s %8s %8s %12s %12s %9s %9s %9s\n", "s", "x", "y", "N", "M", "e", "thrust_x", "thrust_y");
  for (const ogive::ArchState& st : sol.profile)
    std::printf("%8.4f %8.4f %8.4f %12.2f %12.2f %9.2f %9.4f %9.4f\n", st.s, st.x, st.y, st.N, st.M, st.e,
                st.thrust_x, st.thrust_y);
  const ogive::ThrustLineSummary summary = ogive::summarize_thrust_line(sol);
  std::printf("largest |e| = %.4g %% at s = %.4g m, in kern: %s, in section: %s\n", summary.max_abs_e,
              summary.max_abs_e_at, summary.in_kern ? "yes" : "no", summary.in_section ? "yes" : "no");
  return summary.ok ? 0 : 1;
}
