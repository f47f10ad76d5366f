// The cracking arch: the semicircular arch (span 10 m, t = 0.08 L) with a no-tension section whose
// supports spread apart. Each step starts from the previous solution (continuation); the thrust falls
// as the arch cracks, towards the minimum thrust of the limit analysis (same weight on the axis), which
// it never crosses. Prints d/L, H/V and the cracked stations per step, then that floor.
// Exits 0 when every solve succeeded and stayed above the floor, 1 otherwise.
#include <cstdio>
#include <vector>

#include "ogive/ogive.hpp"

int main() {
  ogive::Scene scene;
  scene.curve = ogive::make_pointed(10.0, 0.0);
  scene.thickness = 0.08 * scene.span();
  scene.section = ogive::SectionKind::no_tension;

  ogive::LimitOptions limit_options;
  limit_options.weight = ogive::WeightModel::axis;  // the elastic model's weight: rho g t per axis length
  const ogive::LimitResult limit = ogive::analyse_limit(scene, limit_options);
  if (limit.status != ogive::LimitStatus::success) return 1;
  const double floor = limit.H_min() / limit.V;

  ogive::Options options;
  options.stations = 41;
  ogive::Solution previous;
  bool ok = true;
  for (double d_over_L : {0.0, 1e-5, 1e-4, 1e-3, 1e-2}) {
    scene.set_support_displacement(d_over_L * scene.span());
    const ogive::Solution sol = ogive::solve(scene, options, previous.field ? &previous : nullptr);
    if (!sol.ok()) {
      std::printf("d/L = %g: status %s: %s\n", d_over_L, ogive::to_string(sol.status), sol.message.c_str());
      return 1;
    }
    int cracked = 0;
    for (const ogive::ArchState& st : sol.profile) cracked += st.cracked ? 1 : 0;
    std::printf("d/L = %-6g H/V = %.6f, %2d of %zu stations cracked\n", d_over_L, sol.H_over_V, cracked,
                sol.profile.size());
    ok = ok && sol.H_over_V >= floor;
    previous = sol;
  }
  std::printf("minimum thrust (limit analysis) H_min/V = %.6f: %s\n", floor,
              ok ? "every step above it" : "a step below it");
  return ok ? 0 : 1;
}
