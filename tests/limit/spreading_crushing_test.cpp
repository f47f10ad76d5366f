// The spreading path of rigid voussoirs whose joints crush (LimitOptions::compressive_strength): the
// infinite strength's path at a huge f_c, the start at the limit analysis' minimum thrust with the same
// f_c, the program's thrust against the mechanism's virtual work (the blocks turning about the stress
// blocks' inner edges, which dissipate N^2 / (2 f_c) per unit rotation), capacities that converge with
// the joints and fall with the strength to nothing where the arch can no longer stand, and an
// independent program of rigid blocks with crushing hinges (benchmarks/crushing/spread_check.py).
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
// The path's first state is the limit analysis' minimum-thrust state: the same program's optimum, on
// a ring refined next to the same hinges, further (with a finite strength the path's ring is refined
// next to its hinges at d = 0): H_min as the limit analysis converges it, to kLimitTolerance.
constexpr double kSameState = kLimitTolerance;
// The collapse is located to kSpreadTolerance of the span; the thrust there moves with it.
constexpr double kCollapseLocated = 1e-6;
// Two capacities each converged to kSpreadCapacityTolerance of itself (on rings refined differently).
constexpr double kTwoConvergedCapacities = 2 * kSpreadCapacityTolerance;
// benchmarks/crushing/spread_check.py (8001 joints, the hinge kept where it formed: --roll none): its
// capacities on 4001 and 8001 joints differ by up to 1e-3 (where its ring has the hinge), and the two
// programs' joints are not the same: agreement to 2e-3 of the capacity. Its thrust along the path, at a
// span increase of 0.0695 L, on the same hinge joint as ogive's up to its ring's spacing: 2e-4.
constexpr double kScriptCapacity = 2e-3;
constexpr double kScriptThrust = 2e-4;

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
  // With a finite strength the joints next to the hinges at d = 0 are refined too: another ring, the
  // same capacity to the tolerance of each.
  CHECK(close(huge.d_max, heyman.d_max, kTwoConvergedCapacities));
  CHECK(close(huge.path.front().H, heyman.path.front().H, kSameState));
  CHECK(close(huge.path.back().H, heyman.path.back().H, kTwoConvergedCapacities));
}

TEST_CASE("spreading with crushing: converged, starts at H_min, virtual work with dissipation, capacity falls with f_c") {
  const Scene scene = semicircle();
  double last_capacity = std::numeric_limits<double>::infinity();
  for (double f_c : {std::numeric_limits<double>::infinity(), 1e7, 2e6, 1e6, 5e5}) {
    CAPTURE(f_c);
    const LimitOptions o = with_strength(f_c);
    const LimitResult lim = analyse_limit(scene, o);
    const SpreadResult r = analyse_spreading(scene, o, {});
    REQUIRE(r.status == SpreadStatus::success);
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

TEST_CASE("spreading with crushing: the capacity holds from other starting rings") {
  const Scene scene = semicircle();
  for (double f_c : {2e6, 1e6}) {
    CAPTURE(f_c);
    LimitOptions o = with_strength(f_c);
    const SpreadResult r = analyse_spreading(scene, o, {});
    o.joints_count = 801;
    const SpreadResult finer = analyse_spreading(scene, o, {});
    REQUIRE(r.status == SpreadStatus::success);
    REQUIRE(finer.status == SpreadStatus::success);
    CHECK(close(r.d_max, finer.d_max, kTwoConvergedCapacities));
  }
}

TEST_CASE("spreading with crushing: the capacity and the thrust of an independent program of crushing blocks") {
  // benchmarks/crushing/spread_check.py --joints 8001 --fc 2e6,1e6 --roll none: the span's increase at
  // collapse over L, and H / V at a span increase of 0.0695 L.
  struct Reference {
    double f_c, capacity, H_over_V;
  };
  const Scene scene = semicircle();
  for (const Reference& ref : {Reference{2e6, 0.116238, 0.424886}, Reference{1e6, 0.097291, 0.442558}}) {
    CAPTURE(ref.f_c);
    const LimitOptions o = with_strength(ref.f_c);
    const SpreadResult r = analyse_spreading(scene, o, {});
    REQUIRE(r.status == SpreadStatus::success);
    const double capacity = 2 * r.d_max / r.ring.span;  // both springings move out by d_max
    CHECK(close(capacity, ref.capacity, kScriptCapacity));
    SpreadOptions there;
    there.stop_ratio = 0.0695;
    const SpreadResult mid = analyse_spreading(scene, o, there);
    REQUIRE(mid.status == SpreadStatus::success);
    REQUIRE(mid.stopped);
    const double V = mid.path.back().V_left;
    CHECK(close(mid.path.back().H / V, ref.H_over_V, kScriptThrust));
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
