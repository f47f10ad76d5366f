// The spreading path of rigid voussoirs whose joints crush (LimitOptions::compressive_strength): the
// infinite strength's path at a huge f_c, the start at the limit analysis' minimum thrust with the same
// f_c, the program's thrust against the mechanism's virtual work with every hinge at its stress block's
// centre, and a capacity that falls with the strength to nothing where the arch can no longer stand.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ogive/limit/limit.hpp"
#include "ogive/limit/spreading.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

namespace {

// One statically determinate equilibrium computed twice (the program's thrust and the virtual work of
// its hinges' mechanism): equal to round-off.
constexpr double kStaticKinematic = 1e-9;
// The path's first state is the limit analysis' minimum-thrust state: the same program's optimum.
constexpr double kSameState = 1e-9;
// The collapse is located to kSpreadTolerance of the span; the thrust there moves with it.
constexpr double kCollapseLocated = 1e-6;

LimitOptions with_strength(double f_c) {
  LimitOptions o;
  o.weight = WeightModel::voussoir;
  o.compressive_strength = f_c;
  return o;
}

// The paper's travertine arch, semicircular here, t/L 0.10 (L = 10 m: rho g L about 0.23 MPa).
Scene semicircle() { return paper_scene(0.0, 0.10); }

}  // namespace

TEST_CASE("spreading with crushing: a huge strength gives the infinite strength's path") {
  const SpreadResult heyman = analyse_spreading(semicircle(), with_strength(std::numeric_limits<double>::infinity()), {});
  const SpreadResult huge = analyse_spreading(semicircle(), with_strength(1e30), {});
  REQUIRE(heyman.status == SpreadStatus::success);
  REQUIRE(huge.status == SpreadStatus::success);
  CHECK(huge.d_max == heyman.d_max);
  CHECK(close(huge.path.front().H, heyman.path.front().H, kSameState));
  CHECK(close(huge.path.back().H, heyman.path.back().H, kCollapseLocated));
}

TEST_CASE("spreading with crushing: starts at H_min, virtual work with the stress blocks, capacity falls with f_c") {
  const Scene scene = semicircle();
  double last_capacity = std::numeric_limits<double>::infinity();
  for (double f_c : {std::numeric_limits<double>::infinity(), 1e7, 2e6, 1e6, 5e5}) {
    CAPTURE(f_c);
    const LimitOptions o = with_strength(f_c);
    const LimitResult lim = analyse_limit(scene, o);
    const SpreadResult r = analyse_spreading(scene, o, {});
    // With a finite strength a finer ring changes the state at d = 0 and the capacity moves by 2.7e-3 to
    // 0.048 of itself there.
    REQUIRE(r.status == (std::isinf(f_c) ? SpreadStatus::success : SpreadStatus::not_converged));
    CHECK(close(r.path.front().H, lim.H_min(), kSameState));
    for (std::size_t i = 0; i < r.path.size(); ++i) {
      const SpreadStep& s = r.path[i];
      CAPTURE(i);
      CHECK(close(s.H, s.H_work, kStaticKinematic));
      if (i > 0) CHECK(s.potential < r.path[i - 1].potential);
    }
    CHECK(r.d_max < last_capacity);
    last_capacity = r.d_max;
  }
}

TEST_CASE("spreading with crushing: no path where the joints crush under the arch's own weight") {
  const Scene scene = semicircle();
  // Below the strength at which the arch just stands (about 3e5 Pa here, where H_min and H_max meet).
  const LimitOptions o = with_strength(2e5);
  REQUIRE(analyse_limit(scene, o).status == LimitStatus::inadmissible);
  const SpreadResult r = analyse_spreading(scene, o, {});
  CHECK(r.status == SpreadStatus::inadmissible);
  CHECK(!std::isfinite(r.d_max));
}
