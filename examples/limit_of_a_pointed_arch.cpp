// Limit analysis (Heyman's rigid, no-tension voussoirs) of the equilateral pointed arch, span 10 m,
// t = 0.15 L: the range of thrusts it can carry (H_min, H_max, as fractions of the half weight V), the
// thinnest arch of the same shape that still stands (t_min) and the hinges of the minimum-thrust state.
// Exits 0 when the analysis succeeded, 1 otherwise.
#include <cstdio>

#include "ogive/ogive.hpp"

int main() {
  ogive::Scene scene;
  scene.curve = ogive::make_pointed(10.0, 0.5);
  scene.thickness = 0.15 * scene.span();

  const ogive::LimitResult r = ogive::analyse_limit(scene, ogive::LimitOptions{});
  if (r.status != ogive::LimitStatus::success) {
    std::printf("status %s: %s\n", ogive::to_string(r.status), r.message.c_str());
    return 1;
  }
  std::printf("H_min/V = %.4f, H_max/V = %.4f, t_min/L = %.5f, geometric safety factor %.3f\n", r.H_min() / r.V,
              r.H_max() / r.V, r.thickness_min / scene.span(), scene.thickness / r.thickness_min);
  std::printf("minimum thrust hinges:");
  for (const ogive::Hinge& h : r.min_state.hinges)
    std::printf(" x/L = %.3f (%s)", h.point.x() / scene.span(), ogive::to_string(h.face));
  std::printf("\n");
  return 0;
}
