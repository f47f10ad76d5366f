// The arch model's physical states (include/ogive/model/arch_model.hpp, ArchModel::to_physical): the
// eccentricity is undefined without compression, and the thrust point lies on the section at the
// offset e t / 600 from the axis.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "ogive/model/arch_model.hpp"
#include "ogive/solve/solve.hpp"
#include "support/scenes.hpp"
#include "support/tolerances.hpp"

using namespace ogive;

TEST_CASE("no silent numbers: e is undefined where N = 0 - never an unbounded number") {
  const ArchModel model(paper_scene(0.0));
  StateVector y = StateVector::Zero();
  const ArchState st = model.to_physical(0.3, y);
  CHECK(st.N == 0.0);
  CHECK(std::isnan(st.e));
  CHECK(std::isnan(st.thrust_x));
  y[kFx] = -1.0;  // any compression: e defined
  CHECK(std::isfinite(model.to_physical(0.3, y).e));
}

TEST_CASE("geometry: the thrust point lies on the section at e t / 600 towards the intrados") {
  // e = 600 M / (N t) > 0 puts the resultant on the intrados side (docs/model.md); the point's
  // distance from the axis, signed towards the extrados, is -e t / 600.
  Options o;
  o.stations = 21;
  for (double eps : {0.0, 0.5, 1.0}) {
    const Scene scene = paper_scene(eps, 0.08, 1e-4);
    const Solution sol = solve(scene, o);
    REQUIRE(sol.ok());
    for (const ArchState& st : sol.profile) {
      const double n_x = -std::sin(st.theta), n_y = std::cos(st.theta);
      const double offset = (st.thrust_x - st.x) * n_x + (st.thrust_y - st.y) * n_y;
      const double along = (st.thrust_x - st.x) * n_y - (st.thrust_y - st.y) * n_x;
      CHECK(std::abs(offset + st.e * scene.thickness / 600) <= kExact * std::max(std::abs(offset), scene.thickness));
      CHECK(std::abs(along) <= kExact * std::max(std::abs(offset), scene.thickness));
    }
  }
}
