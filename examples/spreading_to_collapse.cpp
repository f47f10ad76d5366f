// The arch on spreading walls, to collapse: the semicircular arch (span 10 m, t = 0.075 L) of rigid
// voussoirs, its weight on the axis, both springings moving apart; then the right springing alone moving
// out and sinking half as far as it moves (each state then the one of least work on the movement).
// Prints, for each movement, the span's increase at collapse over L, H/V at the start and at collapse
// and the hinges there (x / L and face). Exits 0 when both paths reach collapse, the thrust rises along
// the first (the semicircle's, Ochsendorf 2006) and the settling springing collapses sooner; 1 otherwise.
#include <cstdio>

#include "ogive/ogive.hpp"

namespace {

// The path of one movement, printed; the span's increase at collapse over L, or -1 without a path.
double print_path(const char* name, const ogive::Scene& scene, const ogive::SpreadOptions& spread) {
  ogive::LimitOptions limit;
  limit.weight = ogive::WeightModel::axis;
  const ogive::SpreadResult r = ogive::analyse_spreading(scene, limit, spread);
  if (r.status != ogive::SpreadStatus::success) {
    std::printf("%s: status %s: %s\n", name, ogive::to_string(r.status), r.message.c_str());
    return -1;
  }
  const double L = scene.span();
  const ogive::SpreadStep& first = r.path.front();
  const ogive::SpreadStep& last = r.path.back();
  const double capacity = (spread.left_share + spread.right_share) * r.d_max / L;
  std::printf("%s: capacity %.4f, H/V %.4f at d = 0 and %.4f at collapse (%s), hinges", name, capacity,
              first.H / first.V_left, last.H / last.V_left, ogive::to_string(r.collapse));
  for (const ogive::Hinge& h : last.hinges)
    std::printf(" %.3f:%s", h.point.x() / L, ogive::to_string(h.face));
  std::printf("\n");
  return last.H > first.H ? capacity : -1;
}

}  // namespace

int main() {
  ogive::Scene scene;
  scene.curve = ogive::make_pointed(10.0, 0.0);  // eccentricity 0: the semicircle
  scene.thickness = 0.075 * scene.span();

  const double both = print_path("both springings", scene, ogive::SpreadOptions{});
  ogive::SpreadOptions settling;
  settling.left_share = 0;
  settling.right_settlement_share = 0.5;
  const double right = print_path("right springing, sinking", scene, settling);
  return both > 0 && right > 0 && right < both ? 0 : 1;
}
